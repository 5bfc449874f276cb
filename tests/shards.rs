//! A run split into shards (`reach run --shard K/N`) and merged (`reach
//! merge`) gives the report one run gives, byte for byte, in every format
//! and for every number of shards (more shards than people included); a
//! merge refuses shards that are missing, repeated, of another scenario or
//! not a shard's file, saying which.

use std::path::Path;

use crate::cli::{reach, stderr, stdout};

/// A room with a door and a knee-height counter; a person reaching two
/// targets; two populations, one reaching a target and one mapping the
/// counter; a standard; an expectation about a population.
const SCENARIO: &str = "units mm deg
use std::people
use std::populations
room r {
  size 4000 x 3000 x 2500
  box counter at (0, 0, 0) size (2000, 600, 900)
  box low_top at (2000, 0, 720) size (1200, 600, 40)
  box shelf at (0, 0, 1400) size (4000, 300, 20)
  door d at (4000, 1500) width 900mm
  target cup at (1000, 400, 950)
  target jar at (2500, 150, 1450)
  surface low at (2000, 100, 760) size (1200, 500, 0)
}
person sam { mannequin man_50th_seated base manual_wheelchair }
population users = manual_wheelchair_users { size 7 seed 3 }
population walkers = adults_65_85 { size 5 seed 4 }
reach cup, jar by sam
reach jar by users, walkers
map low by users { step 300mm }
standard ada2010 in r
expect share(users, jar) >= 50 %
";

/// The scenario written in `dir`, its path.
fn written(dir: &Path) -> String {
    let file = dir.join("study.reach");
    std::fs::write(&file, SCENARIO).expect("written");
    file.to_str().expect("a UTF-8 path").to_string()
}

/// Shards 1..=count of the scenario at `file`, written beside it: their
/// paths, last first (a merge takes them in any order).
fn shards(file: &str, count: usize) -> Vec<String> {
    let dir = Path::new(file).parent().expect("a directory");
    let mut paths = Vec::new();
    for k in 1..=count {
        let o = reach(&["run", file, "--shard", &format!("{k}/{count}")]);
        assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
        let path = dir.join(format!("shard-{k}-of-{count}.json"));
        std::fs::write(&path, &o.stdout).expect("written");
        paths.push(path.to_str().expect("UTF-8").to_string());
    }
    paths.reverse();
    paths
}

fn merged(file: &str, shards: &[String], format: &str) -> std::process::Output {
    let mut args = vec!["merge", file, "--format", format];
    args.extend(shards.iter().map(String::as_str));
    reach(&args)
}

#[test]
fn merged_shards_give_the_report_one_run_gives_byte_for_byte() {
    let dir = tempfile::tempdir().expect("a temporary directory");
    let file = written(dir.path());
    let whole: Vec<_> = ["json", "text", "html"]
        .iter()
        .map(|format| reach(&["run", &file, "--format", format]))
        .collect();
    // 3 where the expectation is not met: the merge must exit the same.
    for o in &whole {
        assert!(matches!(o.status.code(), Some(0 | 3)), "{}", stderr(o));
    }
    // More shards than either population has people: some shards hold no
    // one of a population.
    for count in [1, 2, 3, 8] {
        let paths = shards(&file, count);
        for (format, whole) in ["json", "text", "html"].iter().zip(&whole) {
            let o = merged(&file, &paths, format);
            assert_eq!(o.status.code(), whole.status.code(), "{}", stderr(&o));
            assert!(
                o.stdout == whole.stdout,
                "{count} shards, {format}: the merge differs from the run"
            );
        }
    }
    let json = stdout(&whole[0]);
    assert!(json.contains("\"population\": \"users\""), "{json}");
    assert!(
        json.contains("\"cells\""),
        "the map by a population: {json}"
    );
}

#[test]
fn a_merge_refuses_shards_missing_repeated_foreign_or_not_shards() {
    let dir = tempfile::tempdir().expect("a temporary directory");
    let file = written(dir.path());
    let paths = shards(&file, 3);
    let other_dir = tempfile::tempdir().expect("a temporary directory");
    let other = other_dir.path().join("other.reach");
    std::fs::write(&other, SCENARIO.replace("size 7 seed 3", "size 7 seed 5")).expect("written");
    let other = other.to_str().expect("UTF-8");
    let foreign = shards(other, 3);
    let not_a_shard = dir.path().join("report.json");
    std::fs::write(
        &not_a_shard,
        stdout(&reach(&["run", &file, "--format", "json"])),
    )
    .expect("written");
    let not_a_shard = not_a_shard.to_str().expect("UTF-8").to_string();
    let cases: [(Vec<String>, &str); 4] = [
        (paths[..2].to_vec(), "shard 1/3 is not given (of its run)"),
        (
            vec![
                paths[0].clone(),
                paths[1].clone(),
                paths[2].clone(),
                paths[1].clone(),
            ],
            "it is shard 2/3, as",
        ),
        (
            vec![paths[0].clone(), paths[1].clone(), foreign[2].clone()],
            "it was run on other scenario files",
        ),
        (vec![not_a_shard], "not a shard file of reach"),
    ];
    for (given, why) in cases {
        let o = merged(&file, &given, "json");
        assert_eq!(o.status.code(), Some(1), "{given:?}");
        assert!(o.stdout.is_empty(), "{given:?}: no report");
        let err = stderr(&o);
        assert!(err.contains(why), "{given:?}: {err}");
        assert!(err.contains("reach::file"), "{err}");
    }
}

#[test]
fn a_shard_is_k_of_n_and_writes_no_set() {
    let dir = tempfile::tempdir().expect("a temporary directory");
    let file = written(dir.path());
    for bad in ["0/3", "4/3", "3", "x/y"] {
        let o = reach(&["run", &file, "--shard", bad]);
        assert_eq!(o.status.code(), Some(2), "{bad}");
        assert!(stderr(&o).contains("--shard"), "{}", stderr(&o));
    }
    let out = dir.path().join("out");
    let o = reach(&[
        "run",
        &file,
        "--shard",
        "1/2",
        "--out",
        out.to_str().expect("UTF-8"),
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert!(!out.exists());
}

#[test]
fn a_suite_tested_in_shards_and_merged_writes_the_junit_file_one_run_writes() {
    use crate::suite::{scenario, HIGH_MM};
    let dir = tempfile::tempdir().expect("a temporary directory");
    let expects = "expect ann reaches cup\nexpect ann reaches jar\n";
    let files = [
        ("a_high.reach", scenario(HIGH_MM, expects)),
        ("b_low.reach", scenario(1200, expects)),
        ("c_broken.reach", "room {".to_string()),
        ("d_low.reach", scenario(1300, "expect ann reaches cup\n")),
    ];
    for (name, text) in &files {
        std::fs::write(dir.path().join(name), text).expect("written");
    }
    let suite = dir.path().to_str().expect("UTF-8");
    let xml = |name: &str| dir.path().join(name).to_str().expect("UTF-8").to_string();
    let whole = xml("whole.xml");
    let o = reach(&["test", suite, "--junit", &whole]);
    assert_eq!(o.status.code(), Some(1), "one fails: {}", stdout(&o));
    let whole = std::fs::read(&whole).expect("written");
    // More shards than scenarios: some shards test none.
    for count in [2, 3, 6] {
        let mut parts = Vec::new();
        for k in (1..=count).rev() {
            let part = xml(&format!("part-{k}-of-{count}.xml"));
            let o = reach(&[
                "test",
                suite,
                "--shard",
                &format!("{k}/{count}"),
                "--junit",
                &part,
            ]);
            assert!(matches!(o.status.code(), Some(0 | 1)), "{}", stderr(&o));
            parts.push(part);
        }
        let merged = xml("merged.xml");
        let mut args = vec!["merge", "--junit", &merged];
        args.extend(parts.iter().map(String::as_str));
        let o = reach(&args);
        assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
        assert!(
            std::fs::read(&merged).expect("written") == whole,
            "{count} shards: the merged JUnit file differs from one run's"
        );
        // A shard left out is named.
        let mut args = vec!["merge", "--junit", &merged];
        args.extend(parts[1..].iter().map(String::as_str));
        let o = reach(&args);
        assert_eq!(o.status.code(), Some(1));
        assert!(
            stderr(&o).contains(&format!("shard {count}/{count}")),
            "{}",
            stderr(&o)
        );
    }
}
