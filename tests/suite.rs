//! `expect` and `reach test` through the binary, in temporary directories:
//! expectations met and not met (and the exit codes that tell a broken
//! file from a broken design), golden reports compared as answers (a
//! flipped verdict in words, floats within the tolerance ignored),
//! `--update` writing only what changed, JUnit XML, and a suite that goes
//! on past a broken scenario.

use std::path::Path;
use std::process::{Command, Output};

use super::cli::{stderr, stdout};

/// A standing arm in front of a shelf: `cup` on the counter is reached,
/// `jar` on the shelf is reached when the shelf is low and not when it
/// is high; `expects` are appended.
pub(crate) fn scenario(shelf_z_mm: u32, expects: &str) -> String {
    format!(
        "units mm deg
use std::arm

room kitchen {{
  size 2000 x 2000 x 2500
  box counter at (0, 0, 0) size (600, 2000, 900)
  box shelf at (0, 0, {shelf_z_mm}) size (300, 2000, 20)
  target cup at (450, 1000, 960)
  target jar at (150, 1000, {jar_z})
}}

person ann {{
  mannequin right_arm
  base fixed {{ at (850, 1000, 930) heading 180deg }}
}}

reach cup, jar by ann
{expects}
",
        jar_z = shelf_z_mm + 60
    )
}

const LOW_MM: u32 = 1200;
pub(crate) const HIGH_MM: u32 = 2100;

pub(crate) fn reach_in(dir: &Path, args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_reach"))
        .args(args)
        .current_dir(dir)
        .env("NO_COLOR", "1")
        .output()
        .expect("the binary runs")
}

pub(crate) fn write(dir: &Path, name: &str, text: &str) {
    std::fs::write(dir.join(name), text).expect("written");
}

#[test]
fn the_scenario_reaches_the_low_jar_and_not_the_high_one() {
    // The premise of the tests below, checked once.
    let dir = tempfile::tempdir().unwrap();
    write(dir.path(), "low.reach", &scenario(LOW_MM, ""));
    write(dir.path(), "high.reach", &scenario(HIGH_MM, ""));
    let low = stdout(&reach_in(dir.path(), &["run", "low.reach"]));
    let high = stdout(&reach_in(dir.path(), &["run", "high.reach"]));
    let row = |out: &str, target: &str| {
        out.lines()
            .find(|l| l.split_whitespace().nth(1) == Some(target))
            .unwrap_or_else(|| panic!("no {target} row:\n{out}"))
            .to_string()
    };
    assert!(row(&low, "jar").contains(" reachable"), "{low}");
    assert!(row(&high, "jar").contains("NOT reachable"), "{high}");
    assert!(row(&high, "cup").contains(" reachable"), "{high}");
}

#[test]
fn met_expectations_exit_0_and_one_not_met_exits_3_with_its_reason() {
    let dir = tempfile::tempdir().unwrap();
    let expects = "expect ann reaches cup\nexpect ann reaches jar\n";
    write(dir.path(), "low.reach", &scenario(LOW_MM, expects));
    write(dir.path(), "high.reach", &scenario(HIGH_MM, expects));

    let o = reach_in(dir.path(), &["run", "low.reach"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(stdout(&o).contains("expectations: 2 met, 0 NOT met"));

    let o = reach_in(dir.path(), &["run", "high.reach"]);
    assert_eq!(o.status.code(), Some(3), "{}", stderr(&o));
    let out = stdout(&o);
    let line = out
        .lines()
        .find(|l| l.contains("NOT met") && l.contains("ann reaches jar"))
        .unwrap_or_else(|| panic!("no unmet expectation:\n{out}"));
    // The reason, and where the expectation is written.
    assert!(line.contains("NOT reachable"), "{line}");
    assert!(
        line.contains("mm away") || line.contains("out of reach"),
        "{line}"
    );
    assert!(line.ends_with("(high.reach:19)"), "{line}");
    assert!(stderr(&o).contains("1 of the scenario's expectations not met"));

    let o = reach_in(dir.path(), &["run", "--no-expect", "high.reach"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(stdout(&o).contains("NOT met"));
}

#[test]
fn an_expectation_naming_an_unknown_target_is_a_diagnostic_exit_1() {
    let dir = tempfile::tempdir().unwrap();
    write(
        dir.path(),
        "typo.reach",
        &scenario(LOW_MM, "expect ann reaches jra\n"),
    );
    for args in [&["run", "typo.reach"][..], &["test", "typo.reach"]] {
        let o = reach_in(dir.path(), args);
        assert_eq!(o.status.code(), Some(1), "{args:?}");
        let text = format!("{}{}", stdout(&o), stderr(&o));
        assert!(text.contains("unknown target or surface `jra`"), "{text}");
        assert!(text.contains("did you mean `jar`?"), "{text}");
        assert!(text.contains("typo.reach:18"), "{text}");
    }
}

#[test]
fn a_flipped_verdict_is_reported_in_words() {
    let dir = tempfile::tempdir().unwrap();
    write(dir.path(), "kitchen.reach", &scenario(LOW_MM, ""));
    let o = reach_in(dir.path(), &["test", "--update"]);
    assert_eq!(o.status.code(), Some(0), "{}", stdout(&o));
    assert!(dir.path().join("kitchen.golden.json").exists());

    let o = reach_in(dir.path(), &["test"]);
    assert_eq!(o.status.code(), Some(0), "{}", stdout(&o));
    assert!(stdout(&o).contains("as in the golden report"));

    // The shelf goes up: the jar flips.
    write(dir.path(), "kitchen.reach", &scenario(HIGH_MM, ""));
    let o = reach_in(dir.path(), &["test"]);
    assert_eq!(o.status.code(), Some(1), "{}", stdout(&o));
    let out = stdout(&o);
    assert!(out.contains("FAILED  ./kitchen.reach"), "{out}");
    assert!(
        out.lines().any(|l| l
            .trim_start()
            .starts_with("jar: ann reachable -> NOT reachable")),
        "{out}"
    );
    assert!(out.contains("0 passed, 1 failed"), "{out}");
    assert!(!out.contains("cup: ann"), "the cup did not change:\n{out}");
}

/// The golden report with the entry of target `name` edited by `edit`.
fn edited(golden: &str, name: &str, edit: impl Fn(&mut serde_json::Value)) -> String {
    let mut v: serde_json::Value = serde_json::from_str(golden).unwrap();
    let tasks = v["tasks"].as_array_mut().unwrap();
    edit(tasks.iter_mut().find(|t| t["name"] == name).unwrap());
    serde_json::to_string_pretty(&v).unwrap()
}

/// The golden report with the cup's base moved along x by `dx_mm`.
fn nudged(golden: &str, dx_mm: f64) -> String {
    edited(golden, "cup", |cup| {
        let x = cup["base"]["x_mm"].as_f64().unwrap();
        cup["base"]["x_mm"] = serde_json::json!(x + dx_mm);
    })
}

/// A directory holding the kitchen with its shelf at `shelf_z_mm` and the
/// golden report `reach test --update` wrote: the directory, the golden
/// report's path and its text.
fn with_golden(shelf_z_mm: u32) -> (tempfile::TempDir, std::path::PathBuf, String) {
    let dir = tempfile::tempdir().unwrap();
    write(dir.path(), "kitchen.reach", &scenario(shelf_z_mm, ""));
    reach_in(dir.path(), &["test", "--update"]);
    let golden_path = dir.path().join("kitchen.golden.json");
    let golden = std::fs::read_to_string(&golden_path).unwrap();
    (dir, golden_path, golden)
}

/// An unreached target whose reason (its `why`) is the same is not a
/// change because its closest posture met something else; a different
/// reason is, in words that differ.
#[test]
fn an_unreached_answer_changes_with_its_reason_not_its_closest_posture() {
    let (dir, golden_path, golden) = with_golden(HIGH_MM);
    let jar: serde_json::Value = serde_json::from_str::<serde_json::Value>(&golden).unwrap()
        ["tasks"]
        .as_array()
        .unwrap()
        .iter()
        .find(|t| t["name"] == "jar")
        .cloned()
        .unwrap();
    assert!(!jar["why"].as_array().unwrap().is_empty(), "{jar}");

    let met_else = edited(&golden, "jar", |j| j["collision"] = "`counter`".into());
    std::fs::write(&golden_path, met_else).unwrap();
    let o = reach_in(dir.path(), &["test"]);
    assert_eq!(o.status.code(), Some(0), "{}", stdout(&o));

    let other_why = edited(
        &golden,
        "jar",
        |j| {
            j["why"] =
                serde_json::json!([{"cause": "obstacles", "names": ["counter"], "together": false}])
        },
    );
    std::fs::write(&golden_path, other_why).unwrap();
    let o = reach_in(dir.path(), &["test"]);
    assert_eq!(o.status.code(), Some(1), "{}", stdout(&o));
    let line = stdout(&o)
        .lines()
        .find(|l| l.contains("jar: ann still NOT reachable"))
        .map(str::to_string)
        .unwrap_or_else(|| panic!("{}", stdout(&o)));
    let (now, was) = line.split_once(" (was: ").unwrap();
    assert!(was.contains("counter"), "{line}");
    assert!(!now.contains("`counter`"), "{line}");
}

#[test]
fn a_float_change_inside_the_tolerance_is_ignored_and_outside_reported() {
    let (dir, golden_path, golden) = with_golden(LOW_MM);

    std::fs::write(&golden_path, nudged(&golden, 0.6)).unwrap();
    let o = reach_in(dir.path(), &["test"]);
    assert_eq!(o.status.code(), Some(0), "{}", stdout(&o));

    std::fs::write(&golden_path, nudged(&golden, 5.0)).unwrap();
    let o = reach_in(dir.path(), &["test"]);
    assert_eq!(o.status.code(), Some(1), "{}", stdout(&o));
    assert!(
        stdout(&o).contains("cup: ann's base moved from"),
        "{}",
        stdout(&o)
    );

    // A wider tolerance takes it.
    let o = reach_in(dir.path(), &["test", "--tolerance-mm", "10"]);
    assert_eq!(o.status.code(), Some(0), "{}", stdout(&o));
}

#[test]
fn update_rewrites_only_the_golden_reports_that_changed() {
    let dir = tempfile::tempdir().unwrap();
    write(dir.path(), "a.reach", &scenario(LOW_MM, ""));
    write(dir.path(), "b.reach", &scenario(LOW_MM, ""));
    let o = reach_in(dir.path(), &["test", "--update", "."]);
    assert!(
        stdout(&o).contains("wrote ./a.golden.json (new)"),
        "{}",
        stdout(&o)
    );
    assert!(
        stdout(&o).contains("wrote ./b.golden.json (new)"),
        "{}",
        stdout(&o)
    );
    let modified = |name: &str| {
        std::fs::metadata(dir.path().join(name))
            .unwrap()
            .modified()
            .unwrap()
    };
    let b_before = (
        modified("b.golden.json"),
        std::fs::read(dir.path().join("b.golden.json")).unwrap(),
    );
    std::thread::sleep(std::time::Duration::from_millis(20));

    write(dir.path(), "a.reach", &scenario(HIGH_MM, ""));
    let o = reach_in(dir.path(), &["test", "--update", "."]);
    assert_eq!(o.status.code(), Some(0), "{}", stdout(&o));
    let out = stdout(&o);
    assert!(out.contains("rewrote ./a.golden.json"), "{out}");
    assert!(!out.contains("b.golden.json"), "{out}");
    let b_after = (
        modified("b.golden.json"),
        std::fs::read(dir.path().join("b.golden.json")).unwrap(),
    );
    assert_eq!(b_before, b_after, "b's golden report was left alone");
    let a = std::fs::read_to_string(dir.path().join("a.golden.json")).unwrap();
    assert!(
        a.contains("\"ok\": false"),
        "a's golden now has the jar unreached"
    );
    // Nothing half-written is left beside them.
    let mut names: Vec<String> = std::fs::read_dir(dir.path())
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    assert_eq!(
        names,
        ["a.golden.json", "a.reach", "b.golden.json", "b.reach"]
    );
}

#[test]
fn junit_output_parses_with_the_right_counts() {
    let dir = tempfile::tempdir().unwrap();
    let expects = "expect ann reaches cup\nexpect ann reaches jar\n";
    write(dir.path(), "high.reach", &scenario(HIGH_MM, expects));
    write(dir.path(), "low.reach", &scenario(LOW_MM, expects));
    reach_in(dir.path(), &["test", "--update", "low.reach"]);
    write(dir.path(), "broken.reach", "room {");
    let o = reach_in(dir.path(), &["test", "--junit", "out/results.xml"]);
    assert_eq!(o.status.code(), Some(1), "{}", stdout(&o));
    let xml = std::fs::read_to_string(dir.path().join("out/results.xml")).unwrap();
    let report = quick_junit::Report::deserialize_from_str(&xml).expect("JUnit XML");
    let suites: Vec<(String, usize, usize)> = report
        .test_suites
        .iter()
        .map(|s| (s.name.to_string(), s.test_cases.len(), s.failures))
        .collect();
    assert_eq!(
        suites,
        [
            // The check, failed.
            ("./broken.reach".to_string(), 1, 1),
            // Two expectations, one not met; no golden report.
            ("./high.reach".to_string(), 2, 1),
            // Two expectations met, and the golden comparison.
            ("./low.reach".to_string(), 3, 0),
        ]
    );
    assert_eq!(report.tests, 6);
    assert_eq!(report.failures, 2);
}

#[test]
fn a_broken_scenario_reports_its_diagnostic_and_the_rest_run() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::create_dir(dir.path().join("flats")).unwrap();
    write(
        dir.path(),
        "flats/a_broken.reach",
        "room kitchen {\n  size 1 x\n",
    );
    write(
        dir.path(),
        "flats/b_good.reach",
        &scenario(LOW_MM, "expect ann reaches jar\n"),
    );
    let o = reach_in(dir.path(), &["test", "flats"]);
    assert_eq!(o.status.code(), Some(1), "{}", stdout(&o));
    let out = stdout(&o);
    assert!(
        out.contains("FAILED  flats/a_broken.reach  (does not check)"),
        "{out}"
    );
    assert!(out.contains("ok      flats/b_good.reach"), "{out}");
    assert!(
        out.contains("flats/a_broken.reach:2"),
        "the diagnostic:\n{out}"
    );
    assert!(out.contains("1 passed, 1 failed"), "{out}");
}

#[test]
fn a_golden_report_of_another_schema_fails_naming_update() {
    let dir = tempfile::tempdir().unwrap();
    write(dir.path(), "kitchen.reach", &scenario(LOW_MM, ""));
    reach_in(dir.path(), &["test", "--update"]);
    let path = dir.path().join("kitchen.golden.json");
    let golden = std::fs::read_to_string(&path).unwrap();
    std::fs::write(&path, golden.replacen("\"schema\": 1", "\"schema\": 0", 1)).unwrap();
    let o = reach_in(dir.path(), &["test"]);
    assert_eq!(o.status.code(), Some(1), "{}", stdout(&o));
    let out = stdout(&o);
    assert!(out.contains("written by schema 0"), "{out}");
    assert!(out.contains("reach test --update"), "{out}");
}

#[test]
fn a_golden_report_that_gains_fields_still_passes() {
    // A later reach may add fields to its reports: answers are compared,
    // not bytes.
    let dir = tempfile::tempdir().unwrap();
    write(dir.path(), "kitchen.reach", &scenario(LOW_MM, ""));
    reach_in(dir.path(), &["test", "--update"]);
    let path = dir.path().join("kitchen.golden.json");
    let mut v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&path).unwrap()).unwrap();
    v["tasks"][0]["a_later_field"] = serde_json::json!(42);
    v["generator"] = serde_json::json!("a later reach");
    std::fs::write(&path, serde_json::to_string(&v).unwrap()).unwrap();
    let o = reach_in(dir.path(), &["test"]);
    assert_eq!(o.status.code(), Some(0), "{}", stdout(&o));
}

#[test]
fn a_file_another_scenario_uses_is_not_run_as_a_scenario() {
    let dir = tempfile::tempdir().unwrap();
    write(
        dir.path(),
        "people.reach",
        "person ann {\n  mannequin right_arm\n  base fixed { at (850, 1000, 930) heading 180deg }\n}\n",
    );
    let main = scenario(LOW_MM, "").replace(
        "person ann {\n  mannequin right_arm\n  base fixed { at (850, 1000, 930) heading 180deg }\n}\n",
        "use \"people.reach\"\n",
    );
    write(dir.path(), "kitchen.reach", &main);
    let o = reach_in(dir.path(), &["test"]);
    assert_eq!(o.status.code(), Some(0), "{}{}", stdout(&o), stderr(&o));
    let out = stdout(&o);
    assert!(out.contains("./kitchen.reach"), "{out}");
    assert!(!out.contains("people.reach"), "{out}");
    assert!(out.contains("1 passed, 0 failed"), "{out}");
}

/// A golden report that exists but cannot be read (a directory, a FIFO)
/// fails the test in words, at once: it was taken as no golden report,
/// and the test passed (a FIFO was waited on for ever).
#[test]
fn a_golden_report_that_cannot_be_read_fails_the_test() {
    let (dir, golden_path, _) = with_golden(HIGH_MM);
    std::fs::remove_file(&golden_path).unwrap();
    std::fs::create_dir(&golden_path).unwrap();
    let o = reach_in(dir.path(), &["test"]);
    assert_eq!(o.status.code(), Some(1), "{}{}", stdout(&o), stderr(&o));
    assert!(
        stdout(&o).contains("cannot be read: it is a directory"),
        "{}",
        stdout(&o)
    );
    std::fs::remove_dir(&golden_path).unwrap();
    let made = Command::new("mkfifo").arg(&golden_path).status();
    if made.is_ok_and(|s| s.success()) {
        let o = reach_in(dir.path(), &["test"]);
        assert_eq!(o.status.code(), Some(1), "{}{}", stdout(&o), stderr(&o));
        assert!(stdout(&o).contains("cannot be read"), "{}", stdout(&o));
    }
}

#[test]
fn two_scenarios_whose_golden_reports_would_collide_are_refused_not_overwritten() {
    // `one/x.reach` and `two/x.reach` given as two roots: under
    // `--golden-dir` both would be `goldens/x.golden.json` (it was written
    // twice, "(new)" both times, the second over the first).
    let dir = tempfile::tempdir().unwrap();
    for sub in ["one", "two", "goldens"] {
        std::fs::create_dir(dir.path().join(sub)).unwrap();
    }
    write(&dir.path().join("one"), "x.reach", &scenario(LOW_MM, ""));
    write(&dir.path().join("two"), "x.reach", &scenario(HIGH_MM, ""));
    let args = ["test", "--update", "--golden-dir", "goldens", "one", "two"];
    let o = reach_in(dir.path(), &args);
    assert_eq!(o.status.code(), Some(1), "{}", stdout(&o));
    let out = stdout(&o);
    assert!(
        out.contains("would also be that of two/x.reach") && out.contains("that of one/x.reach"),
        "{out}"
    );
    assert_eq!(
        std::fs::read_dir(dir.path().join("goldens"))
            .unwrap()
            .count(),
        0
    );
    // Named by the folder that holds both, each keeps its own.
    let o = reach_in(
        dir.path(),
        &["test", "--update", "--golden-dir", "goldens", "."],
    );
    assert_eq!(o.status.code(), Some(0), "{}", stdout(&o));
    for each in ["goldens/one/x.golden.json", "goldens/two/x.golden.json"] {
        assert!(dir.path().join(each).is_file(), "{each}: {}", stdout(&o));
    }
}
