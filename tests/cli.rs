//! The `reach` binary as a user meets it: exit codes, output, --out, and
//! determinism across runs and thread counts.

use std::path::Path;
use std::process::{Command, Output};

pub(crate) fn reach(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_reach"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .env("NO_COLOR", "1")
        .output()
        .expect("the binary runs")
}

pub(crate) fn stdout(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

pub(crate) fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

#[test]
fn run_prints_a_table_and_exits_0_even_when_a_target_is_unreachable() {
    let o = reach(&["run", "examples/kitchen.reach"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let out = stdout(&o);
    assert!(out.contains("NOT reachable"), "{out}");
    assert!(out.contains("reachable"), "{out}");
    assert!(
        out.lines()
            .any(|l| l.starts_with("task") && l.contains("distance")),
        "{out}"
    );
}

/// A limit's count is read written out or in scientific notation (as
/// `reach check --estimate` suggests it), and anything else, or a count
/// beyond its ceiling, is a usage error naming the flag.
#[test]
fn limits_take_counts_written_out_or_in_scientific_notation() {
    for count in ["250000000", "2.5e8", "25E7"] {
        let o = reach(&[
            "check",
            "--max-solver-work",
            count,
            "examples/kitchen.reach",
        ]);
        assert_eq!(o.status.code(), Some(0), "{count}: {}", stderr(&o));
    }
    for count in ["1.5", "2.55e0", "0", "-3", "1e30", "lots"] {
        let flag = format!("--max-solver-work={count}");
        let o = reach(&["check", &flag, "examples/kitchen.reach"]);
        assert_eq!(o.status.code(), Some(2), "{count}: {}", stderr(&o));
        let said = stderr(&o);
        assert!(
            said.contains(&format!(
                "`{count}` for --max-solver-work is not a whole number from 1 to"
            )),
            "{said}"
        );
    }
}

/// A person whose chair fits nowhere in the room is an answer: the other
/// person's answers are given, the run exits 0, and `--strict` makes it
/// exit 3 (not 1, which says the input is wrong) after the same report.
#[test]
fn a_chair_that_fits_nowhere_is_an_answer_and_strict_exits_3() {
    let o = reach(&["run", "examples/galley.reach"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let out = stdout(&o);
    let row = |target: &str, person: &str| {
        out.lines()
            .find(|l| {
                let words: Vec<&str> = l.split_whitespace().collect();
                words.get(1) == Some(&target) && words.get(2) == Some(&person)
            })
            .unwrap_or_else(|| panic!("no row for {target} by {person}:\n{out}"))
            .to_string()
    };
    assert!(row("kettle", "ann").contains(" reachable"), "{out}");
    assert!(row("kettle", "bob").contains("does NOT fit"), "{out}");
    assert!(
        out.contains("would fit only at 98.5 % of its size (about 699 mm wide)"),
        "{out}"
    );
    let strict = reach(&["run", "--strict", "examples/galley.reach"]);
    assert_eq!(strict.status.code(), Some(3), "{}", stderr(&strict));
    assert_eq!(stdout(&strict), out, "the same report, then the exit code");
    assert!(stderr(&strict).contains("--strict"), "{}", stderr(&strict));
    let json = stdout(&reach(&[
        "run",
        "--format",
        "json",
        "examples/galley.reach",
    ]));
    let report: serde_json::Value = serde_json::from_str(&json).unwrap();
    let bob = &report["tasks"][1];
    assert_eq!(bob["kind"], "not_placed", "{bob}");
    assert_eq!(bob["footprint_mm"][1], 710.0, "{bob}");
    assert_eq!(bob["ok"], false);
    // Without a person who does not fit, --strict changes nothing.
    let fine = reach(&["run", "--strict", "examples/kitchen.reach"]);
    assert_eq!(fine.status.code(), Some(0), "{}", stderr(&fine));
}

#[test]
fn json_report_has_the_documented_fields() {
    let o = reach(&["run", "examples/kitchen.reach", "--format", "json"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).expect("valid JSON");
    assert_eq!(v["file"], "examples/kitchen.reach");
    let task = &v["tasks"][0];
    for field in [
        "kind",
        "name",
        "person",
        "ok",
        "distance_mm",
        "iterations",
        "posture",
        "comfort",
        "base",
    ] {
        assert!(!task[field].is_null(), "missing {field} in {task}");
    }
    assert_eq!(task["kind"], "reach");
}

/// One test per example, so that each is short and they run beside the
/// others: `example` on one thread and on four gives the same JSON, and
/// the same as its golden report.
macro_rules! identical_across_threads {
    ($($test:ident: $file:literal,)*) => {
        $(
            #[test]
            fn $test() {
                identical_across_threads(concat!("examples/", $file));
            }
        )*

        /// Every example has its test above.
        #[test]
        fn json_is_byte_identical_across_runs_and_thread_counts_for_every_example() {
            let listed = [$($file),*];
            let mut examples: Vec<String> =
                std::fs::read_dir(concat!(env!("CARGO_MANIFEST_DIR"), "/examples"))
                    .unwrap()
                    .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
                    .filter(|name| name.ends_with(".reach"))
                    .collect();
            examples.sort();
            assert_eq!(examples, listed, "an example without its test above, or the reverse");
        }
    };
}

identical_across_threads! {
    identical_json_advice: "advice.reach",
    identical_json_bathroom: "bathroom.reach",
    identical_json_client_kitchen: "client_kitchen.reach",
    identical_json_flat_12: "flat_12.reach",
    identical_json_galley: "galley.reach",
    identical_json_gaze_shelf: "gaze_shelf.reach",
    identical_json_kitchen: "kitchen.reach",
    identical_json_kitchen_wheelchair: "kitchen_wheelchair.reach",
    identical_json_map_10k: "map_10k.reach",
    identical_json_mother_kitchen: "mother_kitchen.reach",
    identical_json_open_door: "open_door.reach",
    identical_json_pocket: "pocket.reach",
    identical_json_population: "population.reach",
    identical_json_why_map: "why_map.reach",
}

/// `example` run twice, at once, on one thread and on four: both runs'
/// JSON the same bytes, and the same as its golden report
/// (`tests/golden.rs`, made by another run, on the test's own pool), so
/// three runs on three thread counts agree. Against the golden report only
/// where it is not being rewritten (`INSTA_UPDATE`).
fn identical_across_threads(example: &str) {
    let runs: Vec<std::process::Child> = ["1", "4"]
        .iter()
        .map(|threads| {
            Command::new(env!("CARGO_BIN_EXE_reach"))
                .args(["run", example, "--format", "json"])
                .current_dir(env!("CARGO_MANIFEST_DIR"))
                .env("RAYON_NUM_THREADS", threads)
                .stdout(std::process::Stdio::piped())
                .stderr(std::process::Stdio::null())
                .spawn()
                .unwrap()
        })
        .collect();
    let outputs: Vec<std::process::Output> = runs
        .into_iter()
        .map(|run| run.wait_with_output().unwrap())
        .collect();
    for (threads, o) in ["1", "4"].iter().zip(&outputs) {
        assert_eq!(o.status.code(), Some(0), "{example} on {threads} threads");
    }
    assert!(
        outputs[1].stdout == outputs[0].stdout,
        "{example}: the JSON on 4 threads differs from the JSON on 1"
    );
    if std::env::var_os("INSTA_UPDATE").is_some() {
        return;
    }
    let name = Path::new(example).file_name().unwrap().to_string_lossy();
    let snap = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/snapshots")
        .join(format!("golden__report@{name}.snap"));
    let golden = std::fs::read_to_string(&snap).unwrap();
    let body = golden
        .splitn(3, "---\n")
        .nth(2)
        .expect("a snapshot's header");
    let json = String::from_utf8_lossy(&outputs[0].stdout);
    assert!(
        json.trim_end() == body.trim_end(),
        "{example}: the JSON differs from its golden report {} (another run)",
        snap.display()
    );
}

/// Every file of an `--out` set (the page, the glTF scene, the maps' SVG
/// and CSV) is the same bytes on one thread and on four.
#[test]
fn out_sets_are_byte_identical_across_thread_counts() {
    let set = |threads: &str| {
        let dir = tempfile::tempdir().unwrap();
        let o = Command::new(env!("CARGO_BIN_EXE_reach"))
            .args(["run", "examples/kitchen_wheelchair.reach", "--out"])
            .arg(dir.path())
            .current_dir(env!("CARGO_MANIFEST_DIR"))
            .env("RAYON_NUM_THREADS", threads)
            .output()
            .unwrap();
        assert_eq!(o.status.code(), Some(0));
        let mut files: Vec<(String, Vec<u8>)> = std::fs::read_dir(dir.path())
            .unwrap()
            .map(|e| e.unwrap())
            .map(|e| {
                (
                    e.file_name().to_string_lossy().into_owned(),
                    std::fs::read(e.path()).unwrap(),
                )
            })
            .collect();
        files.sort();
        files
    };
    let (one, four) = (set("1"), set("4"));
    assert_eq!(one.len(), four.len());
    for ((name, a), (_, b)) in one.iter().zip(&four) {
        assert!(a == b, "{name} differs between 1 and 4 threads");
    }
}

#[test]
fn out_dir_gets_report_json_and_nothing_half_written() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("results");
    let o = reach(&[
        "run",
        "examples/kitchen.reach",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let written = std::fs::read_to_string(out.join("report.json")).unwrap();
    let json = reach(&["run", "examples/kitchen.reach", "--format", "json"]);
    assert_eq!(written, stdout(&json));
    let mut names: Vec<_> = std::fs::read_dir(&out)
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    names.sort();
    assert_eq!(
        names,
        [
            ".reach-set",
            "report-stamp.js",
            "report.html",
            "report.json",
            "report.txt",
            "scene.glb"
        ],
        "no temporary file is left behind"
    );
    let text = std::fs::read(out.join("report.txt")).unwrap();
    let printed = reach(&["run", "examples/kitchen.reach", "--format", "text"]);
    assert_eq!(text, printed.stdout, "the text written is the text printed");
    let html = std::fs::read_to_string(out.join("report.html")).unwrap();
    let page = reach(&["run", "examples/kitchen.reach", "--format", "html"]);
    assert!(html.starts_with("<!DOCTYPE html>") && html.contains("\"live\":true"));
    assert_eq!(
        html.replace("\"live\":true", "\"live\":false"),
        stdout(&page),
        "the page written is the page printed, but for its reload"
    );
}

/// A temporary directory holding `reach run FILE --out DIR`'s set.
fn out_dir_of(file: &str) -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    let o = reach(&["run", file, "--out", dir.path().to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    dir
}

#[test]
fn out_dir_gets_a_csv_and_an_svg_per_map() {
    let dir = out_dir_of("examples/kitchen_wheelchair.reach");
    let csv = std::fs::read_to_string(dir.path().join("map-tall_cabinet-front-ann.csv")).unwrap();
    assert!(csv.starts_with("column,row,x_mm,y_mm,z_mm,reachable"));
    assert_eq!(csv.lines().count(), 1 + 6 * 14);
    let svg = std::fs::read_to_string(dir.path().join("map-tall_cabinet-front-ann.svg")).unwrap();
    assert!(svg.starts_with("<svg") && svg.contains("tall_cabinet.front reached by ann"));
    assert!(svg.contains("reachable") && svg.contains("height z (mm)"));
    // The lowest points are there only through the thighs: purple, said
    // so in the legend and the tooltip, not "short".
    assert!(svg.contains("there only through something"));
    assert!(svg.contains("reached only through the right thigh"));
    let files = std::fs::read_dir(dir.path()).unwrap().count();
    assert_eq!(
        files,
        6 + 2 * 18,
        "report.txt, report.json, report.html, its stamp, scene.glb, the list of the set and two files for each of eighteen maps"
    );
}

#[test]
fn a_scenario_with_errors_writes_no_report() {
    let dir = tempfile::tempdir().unwrap();
    let o = reach(&[
        "run",
        "tests/errors/several_errors.reach",
        "--out",
        dir.path().to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(1));
    assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 0);
}

#[test]
fn check_reports_ok() {
    let o = reach(&["check", "examples/kitchen.reach"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(stdout(&o).contains("ok (4 tasks)"), "{}", stdout(&o));
    // Its standard counted as `run` counts it (34 were said).
    let o = reach(&["check", "examples/kitchen_wheelchair.reach"]);
    assert!(stdout(&o).contains("ok (35 tasks)"), "{}", stdout(&o));
}

/// `reach check` takes several files, says each one's result, and exits
/// with the worst.
#[test]
fn check_takes_several_files() {
    let o = reach(&[
        "check",
        "examples/kitchen.reach",
        "tests/errors/syntax_brace_left_open.reach",
        "examples/galley.reach",
    ]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    assert!(
        stdout(&o).contains("examples/kitchen.reach: ok"),
        "{}",
        stdout(&o)
    );
    assert!(
        stdout(&o).contains("examples/galley.reach: ok"),
        "{}",
        stdout(&o)
    );
    assert!(
        stderr(&o).contains("syntax_brace_left_open.reach"),
        "{}",
        stderr(&o)
    );
    let o = reach(&["check", "examples/kitchen.reach", "examples/galley.reach"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
}

#[test]
fn every_error_file_exits_1_with_a_located_diagnostic() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/errors");
    let mut files: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "reach"))
        .collect();
    files.sort();
    assert!(files.len() >= 30, "only {} error files", files.len());
    for path in files {
        let rel = format!(
            "tests/errors/{}",
            path.file_name().unwrap().to_str().unwrap()
        );
        for command in ["check", "run"] {
            let o = reach(&[command, &rel]);
            let err = stderr(&o);
            assert_eq!(o.status.code(), Some(1), "{command} {rel}: {err}");
            assert!(o.stdout.is_empty(), "{command} {rel} printed a report");
            assert!(
                err.contains("tests/errors/"),
                "{rel}: no file named in\n{err}"
            );
            assert!(!err.contains("panicked"), "{rel}: {err}");
        }
    }
}

#[test]
fn usage_errors_exit_2() {
    assert_eq!(reach(&["run"]).status.code(), Some(2));
    assert_eq!(reach(&["frobnicate"]).status.code(), Some(2));
    let o = reach(&["run", "examples/kitchen.reach", "--format", "yaml"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("text, json"), "{}", stderr(&o));
}

#[test]
fn a_missing_file_is_a_diagnostic() {
    let o = reach(&["run", "no/such/file.reach"]);
    assert_eq!(o.status.code(), Some(1));
    assert!(
        stderr(&o).contains("cannot read `no/such/file.reach`"),
        "{}",
        stderr(&o)
    );
}

#[test]
fn help_and_version() {
    let help = reach(&["--help"]);
    assert_eq!(help.status.code(), Some(0));
    for command in ["run", "check", "plugins"] {
        assert!(stdout(&help).contains(command));
    }
    let version = reach(&["--version"]);
    assert_eq!(version.status.code(), Some(0));
    assert!(stdout(&version).starts_with("reach "));
}

#[test]
fn plugins_lists_every_plugin_with_its_parameters() {
    let o = reach(&["plugins"]);
    assert_eq!(o.status.code(), Some(0));
    let out = stdout(&o);
    for name in [
        "incremental",
        "fixed",
        "reach",
        "text",
        "json",
        "rate",
        "gamma",
        "tolerance",
        "heading",
    ] {
        assert!(out.contains(name), "{name} missing from\n{out}");
    }
}

#[test]
fn hostile_sizes_give_diagnostics_not_crashes() {
    let dir = tempfile::tempdir().unwrap();
    let n = 100_000;
    let cases = [
        (
            "deep",
            format!("let a = {}1{}", "(".repeat(n), ")".repeat(n)),
        ),
        ("negations", format!("let a = {}1", "-".repeat(n))),
        ("sum", format!("let a = 1{}", " + 1".repeat(n))),
        (
            "lets",
            (0..n)
                .map(|i| format!("let a{i} = a{} + 1\n", i + 1))
                .collect::<String>()
                + &format!("let a{n} = 1\n"),
        ),
        (
            "braces",
            format!("reach m by p {{ solver {}", "a { ".repeat(n)),
        ),
    ];
    for (name, text) in cases {
        let path = dir.path().join(format!("{name}.reach"));
        std::fs::write(&path, text).unwrap();
        let o = reach(&["check", path.to_str().unwrap()]);
        let err = stderr(&o);
        assert_eq!(
            o.status.code(),
            Some(1),
            "{name}: {}",
            &err[..err.len().min(500)]
        );
        assert!(
            err.contains("exceeds the limit"),
            "{name}: {}",
            &err[..err.len().min(500)]
        );
    }
}

#[test]
fn stdlib_lists_people_chairs_and_visions() {
    let o = reach(&["stdlib"]);
    assert_eq!(o.status.code(), Some(0));
    let out = stdout(&o);
    for expected in [
        "std::people",
        "woman_5th_seated",
        "older_adult",
        "manual_wheelchair (wheelchair)",
        "reduced_acuity",
        "upper_body(stature",
    ] {
        assert!(out.contains(expected), "{expected} missing from\n{out}");
    }
}

/// The README's first example prints what the README shows.
#[test]
fn the_readmes_first_table_is_what_the_kitchen_prints() {
    let readme = std::fs::read_to_string("README.md").unwrap();
    let out = stdout(&reach(&["run", "examples/kitchen.reach"]));
    let table: Vec<&str> = out
        .lines()
        .take_while(|l| !l.starts_with("mug by"))
        .collect();
    let table = table.join("\n");
    assert!(
        readme.contains(table.trim_end()),
        "README.md's table is not what `reach run examples/kitchen.reach` prints:\n{table}"
    );
}

/// `reach stdlib NAME` shows where a name is declared, the comment naming
/// its sources, the declaration and, for a mannequin, the body it builds;
/// a base preset's other options at their defaults; a name it does not
/// declare is an error with the closest one.
#[test]
fn stdlib_shows_one_entry_with_its_sources_and_body() {
    let o = reach(&["stdlib", "woman_5th_seated"]);
    assert_eq!(o.status.code(), Some(0));
    let out = stdout(&o);
    for expected in [
        "mannequin woman_5th_seated: std::people (`use std::people`)",
        "mannequin woman_5th_seated = woman_5th seated",
        "Built from `woman_5th`, then `measured`, then `upper_body`",
        "posture: seated",
        "shoulder_flexion",
        "effectors: grip (67.6 past wrist_deviation), eyes",
    ] {
        assert!(out.contains(expected), "{expected} missing from\n{out}");
    }
    // The upper arm of the 5th-percentile woman: shorter than the man's.
    let upper_arm = |text: &str| -> f64 {
        let row = text
            .lines()
            .find(|l| l.trim_start().starts_with("shoulder_rotation "))
            .unwrap();
        let after = row.split("upper arm ").nth(1).unwrap();
        after.split_whitespace().next().unwrap().parse().unwrap()
    };
    assert!(out.contains("lateral; - medial rotation"), "{out}");
    let man = stdout(&reach(&["stdlib", "man_50th"]));
    assert!(upper_arm(&out) + 20.0 < upper_arm(&man), "{out}\n{man}");

    let base = stdout(&reach(&["stdlib", "power_wheelchair"]));
    assert!(base.contains("IDeA Center"), "{base}");
    assert!(base.contains("seat_height 538mm"), "{base}");
    assert!(base.contains("  width                  660mm"), "{base}");

    let module = stdout(&reach(&["stdlib", "std::arm"]));
    assert!(
        module.starts_with("std::arm\n") && module.contains("right_arm"),
        "{module}"
    );

    let o = reach(&["stdlib", "woman_5"]);
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("did you mean `woman_5th`"), "{err}");
}

/// Input nested exactly as deep as each limit's ceiling is taken (the
/// command line's stack holds it); one level more is refused by name.
#[test]
fn every_limit_holds_at_its_ceiling_and_refuses_beyond() {
    use reach::limits::CEILINGS;
    type Make = fn(&std::path::Path, usize) -> String;
    let cases: [(&str, usize, Make); 9] = [
        ("--max-nesting", CEILINGS.nesting, |_, n| {
            format!("let a = {}1{}\n", "(".repeat(n), ")".repeat(n))
        }),
        (
            "--max-expression-terms",
            CEILINGS.expression_terms,
            |_, n| format!("let a = {}1\n", "-".repeat(n - 1)),
        ),
        // Unary minus inside nested parentheses: every term counts, the
        // parentheses' as well, since each is a step of the recursion.
        (
            "--max-expression-terms",
            CEILINGS.expression_terms,
            |_, n| {
                let levels = reach::limits::DEFAULTS.nesting - 1;
                let minus = (n - 1 - levels) / levels;
                let last = n - 1 - levels - minus * (levels - 1);
                let open = format!("{}(", "-".repeat(minus)).repeat(levels - 1);
                let close = ")".repeat(levels - 1);
                format!("let a = {open}{}(1){close}\n", "-".repeat(last))
            },
        ),
        ("--max-constant-chain", CEILINGS.constant_chain, |_, n| {
            (0..n - 1)
                .map(|i| format!("let a{i} = a{} + 1\n", i + 1))
                .collect::<String>()
                + &format!("let a{} = 1\n", n - 1)
        }),
        ("--max-alias-chain", CEILINGS.alias_chain, |_, n| {
            let aliases: String = (0..n)
                .map(|i| format!("mannequin m{i} = m{}\n", i + 1))
                .collect();
            format!("use std::arm\n{aliases}mannequin m{n} = right_arm\n")
        }),
        ("--max-use-chain", CEILINGS.use_chain, |dir, n| {
            for i in 1..n {
                let next = if i + 1 < n {
                    format!("use \"f{}.reach\"\n", i + 1)
                } else {
                    String::new()
                };
                std::fs::write(
                    dir.join(format!("f{i}.reach")),
                    format!("{next}let c{i} = 1\n"),
                )
                .unwrap();
            }
            "use \"f1.reach\"\n".to_string()
        }),
        ("--max-file-bytes", 1 << 20, |_, n| {
            format!("let a = 1\n{}", " ".repeat(n - 10))
        }),
        ("--max-scenario-bytes", 1 << 20, |_, n| {
            format!("let a = 1\n{}", " ".repeat(n - 10))
        }),
        // Not the ceiling (a million boxes is a 40 MB file): the limit
        // holds at the value given.
        ("--max-boxes", 2_000, |_, n| {
            let boxes: String = (0..n)
                .map(|i| {
                    format!(
                        "  box b{i} at ({}, {}, 0) size (10, 10, 10)\n",
                        20 * (i % 100),
                        20 * (i / 100)
                    )
                })
                .collect();
            format!("room r {{\n  size 4000 x 4000 x 2500\n{boxes}}}\n")
        }),
    ];
    for (flag, ceiling, make) in cases {
        for (n, refused) in [(ceiling, false), (ceiling + 1, true)] {
            let dir = tempfile::tempdir().unwrap();
            let path = dir.path().join("root.reach");
            std::fs::write(&path, make(dir.path(), n)).unwrap();
            let limit = ceiling.to_string();
            let o = reach(&["check", path.to_str().unwrap(), flag, &limit]);
            let err = stderr(&o);
            let shown: String = err.chars().take(600).collect();
            assert_eq!(
                o.status.code(),
                Some(if refused { 1 } else { 0 }),
                "{flag} {n}: {shown}"
            );
            // The message may wrap anywhere, even inside the flag's name.
            let joined: String = err
                .chars()
                .filter(|c| !c.is_whitespace() && *c != '│')
                .collect();
            assert_eq!(joined.contains(flag), refused, "{flag} {n}: {shown}");
        }
    }
}

#[test]
fn solver_starts_are_bounded_before_anything_runs() {
    let file = "examples/kitchen_wheelchair.reach";
    // 73,216 at worst: 16 reaches of 16 placements of 6 starts, 16
    // seeded descents, 16 placements from rest of 6 starts and 4 retried
    // placements of 32; 1,060 map points of 16 placements of 1 start, 16
    // seeded descents and 4 retried placements of 8.
    let o = reach(&["run", file, "--max-solver-starts", "73215"]);
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert!(err.contains("up to 73,216 solver starts"), "{err}");
    assert!(stdout(&o).is_empty());
    let o = reach(&["check", file, "--max-solver-starts", "73216"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
}

/// `scene.glb` under `--out`: valid glTF (the `gltf` crate's validation),
/// one scene per task named as the report names it, and its default scene,
/// read back as a mesh, lies in the room (metres, y up) and holds the
/// person as well as the furniture.
#[test]
fn out_dir_gets_a_gltf_scene_per_task() {
    let dir = out_dir_of("examples/kitchen_wheelchair.reach");
    let bytes = std::fs::read(dir.path().join("scene.glb")).unwrap();
    let gltf = gltf::Gltf::from_slice(&bytes).expect("valid glTF");
    let report: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.path().join("report.json")).unwrap())
            .unwrap();
    let tasks = report["tasks"].as_array().unwrap();
    assert_eq!(gltf.scenes().count(), tasks.len());
    let first = gltf.scenes().next().unwrap();
    assert_eq!(first.name(), Some("reach counter_front by ben"));
    let names: Vec<&str> = gltf.nodes().filter_map(|n| n.name()).collect();
    for part in [
        "back_counter",
        "the head",
        "the wheelchair's seat",
        "target",
    ] {
        assert!(names.contains(&part), "no node {part} in {names:?}");
    }
    let mut none = |_: &str| Err("none".to_string());
    let mesh = reach::meshfile::parse(
        reach::meshfile::MeshFormat::Gltf,
        &bytes,
        1 << 24,
        &mut none,
    )
    .expect("our own reader reads it");
    // Back in the room's frame (mm, z up): within the room's 4 x 3.2 x
    // 2.5 m.
    let room = [4000.0, 3200.0, 2500.0];
    for v in &mesh.vertices {
        let p = reach::meshfile::UpAxis::Y.to_z_up(*v) * 1000.0;
        for k in 0..3 {
            assert!(p[k] > -1.0 && p[k] < room[k] + 1.0, "{p:?}");
        }
    }
}

/// A map's SVG shows the furniture near it and, in plan, where the base
/// stood; its tick labels are round numbers far enough apart never to meet.
#[test]
fn map_pictures_show_context_and_readable_ticks() {
    let dir = out_dir_of("examples/kitchen_wheelchair.reach");
    let plan = std::fs::read_to_string(dir.path().join("map-back_counter-top-ann.svg")).unwrap();
    assert!(
        plan.contains("<title>left_counter</title>"),
        "the furniture is drawn"
    );
    assert!(plan.contains("<title>base at ("), "the bases are drawn");
    assert!(
        plan.contains("short by up to 75 mm"),
        "graded colours have a legend"
    );
    for svg in [
        plan,
        std::fs::read_to_string(dir.path().join("map-tall_cabinet-front-ann.svg")).unwrap(),
    ] {
        // The labels under the x axis: `text-anchor="middle">NUMBER<`.
        let xs: Vec<(f64, f64)> = svg
            .lines()
            .filter(|l| l.starts_with("<line") && l.contains(r#"text-anchor="middle">"#))
            .map(|l| {
                let x = l.split("x1=\"").nth(1).unwrap().split('"').next().unwrap();
                let label = l
                    .split(r#"text-anchor="middle">"#)
                    .nth(1)
                    .unwrap()
                    .split('<')
                    .next()
                    .unwrap();
                (x.parse().unwrap(), label.parse().unwrap())
            })
            .collect();
        assert!(xs.len() >= 3, "{xs:?}");
        for pair in xs.windows(2) {
            assert!(pair[1].0 - pair[0].0 >= 55.0, "labels too close: {xs:?}");
            let step = pair[1].1 - pair[0].1;
            assert!(
                [1.0, 2.0, 5.0]
                    .iter()
                    .any(|k| (step / k).log10().fract().abs() < 1e-9),
                "{step}"
            );
        }
    }
}

/// A format with no text for standard output (`glb`, `maps`) is a usage
/// error under `--format`, naming the formats that print, before any run.
#[test]
fn a_format_of_files_only_is_refused_for_standard_output() {
    for format in ["glb", "maps"] {
        let o = reach(&["run", "examples/kitchen.reach", "--format", format]);
        assert_eq!(o.status.code(), Some(2), "{format}");
        let err = stderr(&o);
        assert!(
            err.contains("writes files only") && err.contains("text, json, html"),
            "{err}"
        );
        assert!(o.stdout.is_empty());
    }
}
