//! What users of a well-kept command-line tool expect of it, through the
//! binary: the report's JSON Schema (it validates the examples' reports
//! and rejects a report with a field removed), diagnostics as JSON Lines
//! and GitHub workflow commands, completions and man pages, colour that
//! follows `--color` and NO_COLOR on a real terminal, and `--quiet`.

use std::path::Path;
use std::process::Output;

use serde_json::Value;

use super::cli::{reach, stderr, stdout};
use super::suite::{reach_in, scenario, write, HIGH_MM};

fn schema() -> Value {
    let o = reach(&["schema"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    serde_json::from_str(&stdout(&o)).expect("the schema is JSON")
}

/// Every reason `report` does not follow `schema`.
pub(crate) fn schema_errors(schema: &Value, report: &Value) -> Vec<String> {
    let validator = jsonschema::validator_for(schema).expect("the schema is a JSON Schema");
    validator
        .iter_errors(report)
        .map(|e| format!("{} at {}", e, e.instance_path()))
        .collect()
}

#[test]
fn the_schema_validates_a_report_and_rejects_one_with_a_field_removed() {
    let schema = schema();
    let o = reach(&["run", "examples/kitchen.reach", "--format", "json"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let report: Value = serde_json::from_str(&stdout(&o)).unwrap();
    assert_eq!(schema_errors(&schema, &report), Vec::<String>::new());

    let removed = |path: &[&str]| {
        let mut r = report.clone();
        let (last, parents) = path.split_last().unwrap();
        let mut at = &mut r;
        for p in parents {
            at = match p.parse::<usize>() {
                Ok(i) => &mut at[i],
                Err(_) => &mut at[*p],
            };
        }
        assert!(
            at.as_object_mut().unwrap().remove(*last).is_some(),
            "{path:?}"
        );
        r
    };
    for path in [
        &["tasks"][..],
        &["tasks", "0", "ok"],
        &["tasks", "0", "base"],
        &["tasks", "0", "base", "heading_deg"],
    ] {
        assert!(
            !schema_errors(&schema, &removed(path)).is_empty(),
            "a report without {path:?} passes the schema"
        );
    }
    let mut other_version = report.clone();
    other_version["schema"] = 2.into();
    assert!(!schema_errors(&schema, &other_version).is_empty());
    let mut wrong_kind = report.clone();
    wrong_kind["tasks"][0]["distance_mm"] = "near".into();
    assert!(!schema_errors(&schema, &wrong_kind).is_empty());
}

/// docs/report.md links docs/report.schema.json: it is what the binary
/// prints.
#[test]
fn the_schema_in_docs_is_the_binarys() {
    let o = reach(&["schema"]);
    let docs = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/report.schema.json"),
    )
    .unwrap();
    assert!(
        docs == stdout(&o),
        "docs/report.schema.json is out of date: run `cargo run --release -- schema > docs/report.schema.json`"
    );
}

/// Three errors, each at a known line and column (1-based, in characters:
/// the `é` in the comment before the third counts as one).
const THREE_ERRORS: &str = "units mm deg
room k {
  size 3000 x 3000 x 2500
  target far at (1, 1, 1)
}
person ann { mannequin nobody_here base fixed { at (0, 0, 0) } }
reach kettel by ann
reach /* café */ far by bob
";

const EXPECTED_PLACES: [(usize, usize, &str); 3] =
    [(6, 24, "nobody_here"), (7, 7, "kettel"), (8, 25, "bob")];

#[test]
fn json_diagnostics_parse_and_carry_line_and_column() {
    let dir = tempfile::tempdir().unwrap();
    write(dir.path(), "three.reach", THREE_ERRORS);
    let o = reach_in(
        dir.path(),
        &["check", "three.reach", "--diagnostics", "json"],
    );
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    assert_eq!(stdout(&o), "", "diagnostics go to standard error");
    let objects: Vec<Value> = stderr(&o)
        .lines()
        .map(|l| serde_json::from_str(l).unwrap_or_else(|e| panic!("{e}: {l}")))
        .collect();
    let places: Vec<(usize, usize, String)> = objects
        .iter()
        .map(|d| {
            assert_eq!(d["file"], "three.reach", "{d}");
            assert_eq!(d["severity"], "error", "{d}");
            assert!(d["code"].as_str().unwrap().starts_with("reach::"), "{d}");
            assert!(!d["message"].as_str().unwrap().is_empty(), "{d}");
            assert!(!d["labels"].as_array().unwrap().is_empty(), "{d}");
            let (offset, length) = (d["offset"].as_u64().unwrap(), d["length"].as_u64().unwrap());
            let text = &THREE_ERRORS[offset as usize..(offset + length) as usize];
            (
                d["line"].as_u64().unwrap() as usize,
                d["column"].as_u64().unwrap() as usize,
                text.to_string(),
            )
        })
        .collect();
    let expected: Vec<(usize, usize, String)> = EXPECTED_PLACES
        .iter()
        .map(|&(l, c, t)| (l, c, t.to_string()))
        .collect();
    assert_eq!(places, expected, "{}", stderr(&o));
}

#[test]
fn github_diagnostics_are_workflow_commands_on_their_lines() {
    let dir = tempfile::tempdir().unwrap();
    write(dir.path(), "three.reach", THREE_ERRORS);
    let o = reach_in(
        dir.path(),
        &["check", "three.reach", "--diagnostics", "github"],
    );
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    let lines: Vec<String> = stderr(&o).lines().map(str::to_string).collect();
    assert_eq!(lines.len(), 3, "{lines:?}");
    for (line, (l, c, _)) in lines.iter().zip(EXPECTED_PLACES) {
        let (properties, message) = workflow_command(line, "error");
        assert_eq!(properties["file"], "three.reach", "{line}");
        assert_eq!(properties["line"], l.to_string(), "{line}");
        assert_eq!(properties["col"], c.to_string(), "{line}");
        assert!(properties["title"].starts_with("reach%3A%3A"), "{line}");
        assert!(!message.is_empty() && !message.contains('\n'), "{line}");
    }
}

/// `::NAME k=v,k=v::MESSAGE`, split; panics if `line` is not one.
fn workflow_command(
    line: &str,
    name: &str,
) -> (std::collections::BTreeMap<String, String>, String) {
    let rest = line
        .strip_prefix(&format!("::{name} "))
        .unwrap_or_else(|| panic!("not a ::{name} command: {line}"));
    let (properties, message) = rest.split_once("::").expect("properties::message");
    let properties = properties
        .split(',')
        .map(|p| {
            let (k, v) = p.split_once('=').expect("key=value");
            assert!(
                !v.contains(':') && !v.contains(','),
                "unescaped value in {line}"
            );
            (k.to_string(), v.to_string())
        })
        .collect();
    (properties, message.to_string())
}

/// An expectation not met is annotated on its own line, under `run` and
/// under `test`, and is a JSON object under `run`, on standard error:
/// standard output keeps the report whole (`reach test` leaves JSON to
/// `--junit`).
#[test]
fn expectations_not_met_are_annotated_on_their_line() {
    let dir = tempfile::tempdir().unwrap();
    let text = scenario(HIGH_MM, "expect ann reaches jar");
    let line = text.lines().position(|l| l.starts_with("expect")).unwrap() + 1;
    write(dir.path(), "high.reach", &text);
    for args in [
        &[
            "run",
            "high.reach",
            "--diagnostics",
            "github",
            "--format",
            "json",
        ][..],
        &["test", "high.reach", "--diagnostics", "github"],
    ] {
        let o = reach_in(dir.path(), args);
        assert_ne!(o.status.code(), Some(0), "{args:?}");
        if args[0] == "run" {
            let report: Result<Value, _> = serde_json::from_str(&stdout(&o));
            assert!(report.is_ok(), "the report stays JSON: {}", stdout(&o));
        }
        let annotations: Vec<String> = (stderr(&o).lines())
            .filter(|l| l.starts_with("::"))
            .map(str::to_string)
            .collect();
        assert_eq!(annotations.len(), 1, "{args:?}: {}", stderr(&o));
        let (properties, message) = workflow_command(&annotations[0], "error");
        assert_eq!(properties["file"], "high.reach");
        assert_eq!(properties["line"], line.to_string());
        assert!(
            message.starts_with("expectation NOT met: ann reaches jar: NOT reachable"),
            "{message}"
        );
    }
    let o = reach_in(dir.path(), &["run", "high.reach", "--diagnostics", "json"]);
    assert_eq!(o.status.code(), Some(3));
    let objects: Vec<Value> = (stderr(&o).lines())
        .map(|l| serde_json::from_str(l).unwrap_or_else(|e| panic!("{e}: {l}")))
        .collect();
    assert_eq!(objects.len(), 1, "{}", stderr(&o));
    assert_eq!(objects[0]["code"], "reach::expect");
    assert_eq!(objects[0]["line"], line);
    let o = reach_in(dir.path(), &["test", "high.reach", "--diagnostics", "json"]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("--junit"), "{}", stderr(&o));
}

#[test]
fn completions_generate_for_each_shell() {
    for (shell, marker) in [
        ("bash", "complete -F"),
        ("zsh", "#compdef reach"),
        ("fish", "complete -c reach"),
        ("powershell", "Register-ArgumentCompleter"),
        ("elvish", "edit:completion:arg-completer[reach]"),
    ] {
        let o = reach(&["completions", shell]);
        assert_eq!(o.status.code(), Some(0), "{shell}: {}", stderr(&o));
        let script = stdout(&o);
        assert!(script.contains(marker), "{shell}: no `{marker}`");
        for command in ["run", "watch", "test", "schema", "diagnostics"] {
            assert!(script.contains(command), "{shell}: no `{command}`");
        }
    }
    let o = reach(&["completions", "tcsh"]);
    assert_eq!(o.status.code(), Some(2));
}

/// In bash, after `reach run` (and `watch`, `check`, `test`) a word that
/// is not an option completes to the `.reach` files and directories
/// there, not to the options; an option's value is still clap's.
#[test]
fn bash_completes_scenario_files_after_run() {
    let dir = tempfile::tempdir().unwrap();
    let script = dir.path().join("reach.bash");
    std::fs::write(&script, stdout(&reach(&["completions", "bash"]))).unwrap();
    for name in ["kitchen.reach", "kettle.obj", "keys.txt"] {
        std::fs::write(dir.path().join(name), "").unwrap();
    }
    std::fs::create_dir(dir.path().join("kits")).unwrap();
    let complete = |words: &str| {
        let o = std::process::Command::new("bash")
            .current_dir(dir.path())
            .arg("-c")
            .arg(format!(
                "source reach.bash; COMP_WORDS=({words}); COMP_CWORD=$((${{#COMP_WORDS[@]}}-1)); \
                 _reach_scenarios reach \"${{COMP_WORDS[-1]}}\" \"${{COMP_WORDS[-2]}}\"; \
                 printf '%s\\n' \"${{COMPREPLY[@]}}\" | sort"
            ))
            .output()
            .unwrap();
        String::from_utf8_lossy(&o.stdout).into_owned()
    };
    assert_eq!(complete("reach run k"), "kitchen.reach\nkits\n");
    assert_eq!(complete("reach check a.reach k"), "kitchen.reach\nkits\n");
    assert_eq!(complete("reach run --fo"), "--format\n");
    assert!(!complete("reach run --out k").contains("--format"));
    // A global option's value is clap's too.
    assert_eq!(complete("reach run --color a"), "always\nauto\n");
}

#[test]
fn man_pages_are_roff_for_every_command() {
    let o = reach(&["man"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(stdout(&o).contains(".TH reach 1"), "{}", stdout(&o));
    let dir = tempfile::tempdir().unwrap();
    let o = reach_in(dir.path(), &["man", "--out", "man"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let mut pages: Vec<String> = std::fs::read_dir(dir.path().join("man"))
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    pages.sort();
    for page in ["reach.1", "reach-run.1", "reach-test.1", "reach-watch.1"] {
        assert!(pages.iter().any(|p| p == page), "{page} not in {pages:?}");
    }
    let run = std::fs::read_to_string(dir.path().join("man/reach-run.1")).unwrap();
    assert!(
        run.contains(".TH reach-run 1") && run.contains("quiet"),
        "{run}"
    );
}

/// The binary on a pseudo-terminal, as a user at a terminal runs it: its
/// standard output and error together.
#[cfg(unix)]
fn on_terminal(args: &[&str], no_color: Option<&str>) -> String {
    use std::io::Read;
    use std::os::fd::{FromRawFd, OwnedFd};
    use std::process::{Command, Stdio};
    let (mut leader, mut follower) = (0, 0);
    // SAFETY: openpty writes two descriptors we then own.
    let made = unsafe {
        libc::openpty(
            &mut leader,
            &mut follower,
            std::ptr::null_mut(),
            std::ptr::null(),
            std::ptr::null(),
        )
    };
    assert_eq!(made, 0, "a pseudo-terminal");
    // SAFETY: both descriptors are open and owned by nothing else.
    let (leader, follower) =
        unsafe { (OwnedFd::from_raw_fd(leader), OwnedFd::from_raw_fd(follower)) };
    let mut command = Command::new(env!("CARGO_BIN_EXE_reach"));
    command
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .env_remove("NO_COLOR")
        .stdin(Stdio::null())
        .stdout(Stdio::from(follower.try_clone().unwrap()))
        .stderr(Stdio::from(follower));
    if let Some(v) = no_color {
        command.env("NO_COLOR", v);
    }
    let mut child = command.spawn().expect("the binary runs");
    drop(command);
    let mut out = Vec::new();
    // Reading ends with EIO once the child has closed the terminal.
    let _ = std::fs::File::from(leader).read_to_end(&mut out);
    child.wait().unwrap();
    String::from_utf8_lossy(&out).into_owned()
}

#[cfg(unix)]
#[test]
fn colour_follows_the_terminal_no_color_and_the_flag() {
    let bad = ["check", "tests/errors/units_unknown.reach"];
    let escape = '\u{1b}';
    let coloured = on_terminal(&bad, None);
    assert!(coloured.contains("reach::"), "{coloured}");
    assert!(
        coloured.contains(escape),
        "a terminal gets colour: {coloured:?}"
    );
    for no_color in ["1", "yes"] {
        let plain = on_terminal(&bad, Some(no_color));
        assert!(plain.contains("reach::"), "{plain}");
        assert!(!plain.contains(escape), "NO_COLOR={no_color}: {plain:?}");
    }
    let never = on_terminal(&[&bad[..], &["--color", "never"]].concat(), None);
    assert!(!never.contains(escape), "{never:?}");
    let help = on_terminal(&["--help"], Some("1"));
    assert!(help.contains("Usage") && !help.contains(escape), "{help:?}");
    // Piped: plain unless asked.
    let piped = reach(&bad);
    assert!(!stderr(&piped).contains(escape));
    let asked = reach(&[&bad[..], &["--color=always"]].concat());
    assert!(stderr(&asked).contains(escape), "{}", stderr(&asked));
}

fn quiet(dir: &Path, args: &[&str]) -> Output {
    reach_in(dir, &[args, &["--quiet"]].concat())
}

#[test]
fn quiet_prints_only_failures() {
    let dir = tempfile::tempdir().unwrap();
    write(
        dir.path(),
        "low.reach",
        &scenario(1200, "expect ann reaches jar"),
    );
    write(
        dir.path(),
        "high.reach",
        &scenario(HIGH_MM, "expect ann reaches jar"),
    );
    for args in [
        &["run", "low.reach"][..],
        &["check", "low.reach"],
        &["test", "low.reach"],
    ] {
        let o = quiet(dir.path(), args);
        assert_eq!(o.status.code(), Some(0), "{args:?}: {}", stderr(&o));
        assert_eq!(
            (stdout(&o), stderr(&o)),
            (String::new(), String::new()),
            "{args:?}"
        );
    }
    let o = quiet(dir.path(), &["run", "high.reach"]);
    assert_eq!(o.status.code(), Some(3));
    assert_eq!(stdout(&o), "");
    let err = stderr(&o);
    assert_eq!(err.lines().count(), 2, "{err}");
    assert!(
        err.starts_with("error: expectation NOT met: ann reaches jar: NOT reachable"),
        "{err}"
    );
    assert!(err.contains("(high.reach:"), "{err}");
    let o = quiet(dir.path(), &["test", "."]);
    assert_eq!(o.status.code(), Some(1));
    let out = stdout(&o);
    assert!(
        out.starts_with("FAILED  ./high.reach") || out.starts_with("FAILED  high.reach"),
        "{out}"
    );
    assert!(
        !out.contains("low.reach") && !out.contains("passed"),
        "{out}"
    );
}

/// A file name that is not UTF-8 is a diagnostic, not a panic (the
/// command line is read for `--color` before clap sees it).
#[cfg(unix)]
#[test]
fn a_file_name_that_is_not_utf8_is_a_diagnostic() {
    use std::os::unix::ffi::OsStrExt;
    let name = std::ffi::OsStr::from_bytes(b"bad\xff.reach");
    let o = std::process::Command::new(env!("CARGO_BIN_EXE_reach"))
        .arg("check")
        .arg(name)
        .env("NO_COLOR", "1")
        .output()
        .expect("the binary runs");
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    assert!(stderr(&o).contains("cannot read"), "{}", stderr(&o));
}
