//! `reach check --estimate`: the work a run will need. Where every person
//! is run (tasks by one person, populations no larger than the sample) it
//! is the run's work to the unit; where a population is sampled, the same
//! on every thread count; and a file given the bound it suggests runs to
//! the end.

use reach::plugin::Registry;
use reach::progress::NoProgress;
use reach::{Input, Limits, Scenario};

use crate::cli::{reach, stderr, stdout};

/// A room with a door; a person in a wheelchair reaching two targets and
/// mapping a counter; a population of `PEOPLE` reaching one; a standard.
fn scenario(people: usize) -> String {
    format!(
        "units mm deg
use std::people
use std::populations
room r {{
  size 4000 x 3000 x 2500
  box counter at (0, 0, 0) size (4000, 600, 900)
  box shelf at (0, 0, 1400) size (4000, 300, 20)
  door d at (4000, 1500) width 900mm
  target cup at (1000, 400, 950)
  target jar at (2000, 150, 1450)
  surface front at (500, 100, 900) size (1500, 400, 0)
}}
person sam {{ mannequin man_50th_seated base manual_wheelchair }}
population users = manual_wheelchair_users {{ size {people} seed 3 }}
reach cup, jar by sam
reach jar by users
map front by sam {{ step 250mm }}
standard ada2010 in r
"
    )
}

fn checked(text: &str, threads: usize) -> Scenario {
    let session = reach::Session::default()
        .limits(Limits::default())
        .threads(threads);
    let input = Input::Text {
        name: "estimate.reach",
        text,
    };
    session
        .check(input, &Registry::builtin())
        .1
        .expect("the scenario checks")
}

#[test]
fn where_everyone_is_run_the_estimate_is_the_runs_work() {
    // A population of 6 is run whole (the sample is at least 8 people).
    let text = scenario(6);
    let estimate = checked(&text, 2).estimate_work(&NoProgress, u64::MAX);
    assert!(!estimate.stopped);
    assert!(estimate.tasks.iter().all(|t| t.half_width == 0));
    let scenario = checked(&text, 2);
    let ran = reach::Session::default().run(&scenario).expect("it runs");
    assert_eq!(estimate.total(), (ran.work, 0));
    let people: Vec<_> = estimate.tasks.iter().filter_map(|t| t.sampled).collect();
    assert_eq!(people, [(6, 6)]);
}

#[test]
fn a_sampled_estimate_is_the_same_on_every_thread_count() {
    let text = scenario(30);
    let on = |threads| {
        let scenario = checked(&text, threads);
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .expect("a pool");
        pool.install(|| scenario.estimate_work(&NoProgress, u64::MAX))
    };
    let one = on(1);
    let sampled = one.tasks.iter().find_map(|t| t.sampled);
    assert_eq!(sampled, Some((8, 30)));
    assert!(one.tasks.iter().any(|t| t.half_width > 0), "{one:?}");
    assert_eq!(one, on(2));
    assert_eq!(one, on(3));
}

#[test]
fn reach_check_estimate_says_what_to_raise_the_bound_to_and_that_bound_runs_to_the_end() {
    let dir = tempfile::tempdir().expect("a temporary directory");
    let file = dir.path().join("estimate.reach");
    std::fs::write(&file, scenario(4)).expect("written");
    let file = file.to_str().expect("a UTF-8 path");
    let bound = "20000000";
    let o = reach(&["check", "--estimate", "--max-solver-work", bound, file]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let out = stdout(&o);
    assert!(out.contains("a run stops partway"), "{out}");
    assert!(out.contains("the bound of 20,000,000 units"), "{out}");
    // The costliest task first: the population's.
    let rows: Vec<&str> = out
        .lines()
        .skip_while(|l| !l.contains("share  task"))
        .collect();
    assert!(rows[1].ends_with("reach jar by users"), "{out}");
    assert!(out.contains("the standards"), "its standard: {out}");
    let raise = out
        .split("`limits { solver_work ")
        .nth(1)
        .and_then(|rest| rest.split(' ').next())
        .unwrap_or_else(|| panic!("no bound suggested: {out}"));
    // As written, the run stops partway (exit 4); with the bound it
    // suggests, it runs to the end.
    assert_eq!(
        reach(&["run", "-q", "--max-solver-work", bound, file])
            .status
            .code(),
        Some(4)
    );
    // The flag it names takes the same text (`1.2e9`).
    let flag = out
        .split(", or --max-solver-work ")
        .nth(1)
        .and_then(|rest| rest.split([' ', ';']).next())
        .unwrap_or_else(|| panic!("no flag suggested: {out}"));
    assert_eq!(flag, raise, "{out}");
    let o = reach(&["run", "-q", "--max-solver-work", flag, file]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let raised = format!("{}limits {{ solver_work {raise} }}\n", scenario(4));
    std::fs::write(file, raised).expect("written");
    let o = reach(&["run", "-q", "--max-solver-work", bound, file]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let o = reach(&["check", "--estimate", "--max-solver-work", bound, file]);
    assert!(stdout(&o).contains("within the bound"), "{}", stdout(&o));
}

#[test]
fn an_estimate_stops_at_the_bound_and_says_so() {
    let dir = tempfile::tempdir().expect("a temporary directory");
    let file = dir.path().join("estimate.reach");
    std::fs::write(&file, scenario(4)).expect("written");
    let file = file.to_str().expect("a UTF-8 path");
    let o = reach(&["check", "--estimate", "--max-solver-work", "1000", file]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let out = stdout(&o);
    assert!(out.contains("work of the tasks estimated"), "{out}");
    assert!(out.contains("(10,000 units) after 0 tasks"), "{out}");
}
