//! A run the bound on work stops partway: the answers of the longest
//! leading run of tasks whose work fits within the bound, each the same as
//! a whole run's, the rest not evaluated; the same on every thread count,
//! and more answered under a larger bound, never fewer.

use reach::plugin::Registry;
use reach::{Input, Limits};
use serde_json::Value;

use crate::cli::{reach, stderr};

/// A room with a door, a person in a wheelchair reaching three targets, a
/// population of four reaching one, a map and a standard.
const SCENARIO: &str = "units mm deg
use std::people
use std::populations
room r {
  size 4000 x 3000 x 2500
  box counter at (0, 0, 0) size (4000, 600, 900)
  box shelf at (0, 0, 1400) size (4000, 300, 20)
  door d at (4000, 1500) width 900mm
  target cup at (1000, 400, 950)
  target jar at (2000, 150, 1450)
  target tin at (3000, 500, 950)
  surface front at (500, 100, 900) size (1500, 400, 0)
}
person sam { mannequin man_50th_seated base manual_wheelchair }
population users = manual_wheelchair_users { size 4 seed 3 }
reach cup, jar by sam
reach tin by users
map front by sam { step 250mm }
reach tin by sam
standard ada2010 in r
";

/// The run of [`SCENARIO`] within `limit` units on `threads` threads: its
/// JSON report and whether the bound stopped it.
fn run(limit: u64, threads: usize) -> (Value, bool) {
    let registry = Registry::builtin();
    let limits = Limits {
        solver_work: limit,
        ..Limits::default()
    };
    let session = reach::Session::default().limits(limits).threads(threads);
    let input = Input::Text {
        name: "partial.reach",
        text: SCENARIO,
    };
    let scenario = session
        .check(input, &registry)
        .1
        .expect("the scenario checks");
    let again = || {
        let input = Input::Text {
            name: "partial.reach",
            text: SCENARIO,
        };
        session.check(input, &registry).1.ok()
    };
    let ran = session.run_partly(&scenario, &again);
    let json = serde_json::to_value(&ran.report).expect("a report is JSON");
    (json, ran.stopped.is_some())
}

/// How many entries lead before the first not evaluated.
fn answered(report: &Value) -> usize {
    let tasks = report["tasks"].as_array().expect("tasks");
    (tasks.iter())
        .take_while(|t| t["kind"] != "not_evaluated")
        .count()
}

#[test]
fn a_run_stopped_partway_answers_a_leading_run_of_tasks_as_a_whole_run_does() {
    let (whole, stopped) = run(u64::MAX / 2, 2);
    assert!(!stopped);
    let tasks = whole["tasks"].as_array().expect("tasks").clone();
    assert_eq!(tasks.len(), 6);
    let mut last = 0;
    // Bounds from a twentieth of a whole run's work (about 19 million
    // units) to more than all of it.
    for limit in [1_000_000, 5_000_000, 10_000_000, 15_000_000, 30_000_000] {
        let (one, stopped) = run(limit, 1);
        let (three, _) = run(limit, 3);
        assert_eq!(one, three, "the threads changed the answers at {limit}");
        let k = answered(&one);
        assert_eq!(stopped, k < tasks.len(), "at {limit}");
        assert!(k >= last, "a larger bound answered fewer: {k} < {last}");
        last = k;
        let entries = one["tasks"].as_array().expect("tasks");
        assert_eq!(entries.len(), tasks.len());
        for (i, entry) in entries.iter().enumerate() {
            if i < k {
                assert_eq!(entry, &tasks[i], "task {i} at {limit}");
            } else {
                assert_eq!(entry["kind"], "not_evaluated", "task {i} at {limit}");
                assert_eq!(entry["reason"], "work limit");
                assert_eq!(entry["ok"], false);
            }
        }
    }
    assert_eq!(last, tasks.len(), "the largest bound answers every task");
}

#[test]
fn reach_run_shows_the_answers_before_the_stop_and_exits_4() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("partial.reach");
    std::fs::write(&path, SCENARIO).unwrap();
    let out = dir.path().join("out");
    let o = reach(&[
        "run",
        path.to_str().unwrap(),
        "--max-solver-work",
        "5000000",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(4), "{}", stderr(&o));
    let text = String::from_utf8_lossy(&o.stdout).to_string();
    assert!(text.contains("not evaluated: work limit"), "{text}");
    assert!(
        text.contains("reachable"),
        "the first task's answer is shown: {text}"
    );
    let err = stderr(&o);
    assert!(
        err.contains("1 of 6 tasks answered") && err.contains("units left"),
        "{err}"
    );
    let json = std::fs::read_to_string(out.join("report.json")).expect("report.json written");
    assert!(json.contains("\"not_evaluated\""), "{json}");
}

/// examples/kitchen_wheelchair.reach stopped at 20,000,000 units: run side
/// by side, which tasks fit changed from run to run (a helper saw 12 and
/// 17 of 35), since what a task is charged there depends on which task
/// worked out a shared floor first; found again one task at a time on the
/// file checked afresh, the same every time.
#[test]
fn the_tasks_answered_are_the_same_every_run_and_thread_count() {
    let path = "examples/kitchen_wheelchair.reach";
    let run = |threads: usize| {
        let o = std::process::Command::new(env!("CARGO_BIN_EXE_reach"))
            .args([
                "run",
                path,
                "--format",
                "json",
                "--max-solver-work",
                "20000000",
            ])
            .env("RAYON_NUM_THREADS", threads.to_string())
            .output()
            .expect("reach runs");
        assert_eq!(o.status.code(), Some(4), "{}", stderr(&o));
        let err = stderr(&o);
        (o.stdout, err)
    };
    let first = run(3);
    for threads in [3, 3, 1] {
        assert_eq!(run(threads), first, "{threads} threads");
    }
}
