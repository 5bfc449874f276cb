//! Golden files: every `examples/*.reach` is run, its JSON report
//! validated against the report's JSON Schema and compared with
//! `tests/snapshots/golden__report@NAME.snap`; every
//! `tests/errors/*.reach` is checked and its rendered diagnostics (no
//! colour, fixed width) compared with `golden__diagnostics@NAME.snap`.
//!
//! After an intended change, update the expected files with
//! `INSTA_UPDATE=always cargo test --release --test main golden` and review
//! the diff.

use std::path::Path;

use reach::plugin::Registry;
use reach::Input;

/// The path relative to the crate root, so snapshots name files the same
/// on every machine.
fn relative(path: &Path) -> &Path {
    path.strip_prefix(env!("CARGO_MANIFEST_DIR"))
        .unwrap_or(path)
}

fn json_report(path: &Path) -> String {
    let registry = Registry::builtin();
    let (_, checked) = reach::check(Input::Path(relative(path)), &registry);
    let scenario = match checked {
        Ok(s) => s,
        Err(d) => panic!("{} does not check:\n{}", path.display(), d.render(true)),
    };
    let report = reach::run(&scenario).expect("within the bound on solver work");
    registry
        .format("json")
        .unwrap()
        .render(&report, &scenario.format_scene())
        .expect("json prints")
}

fn diagnostics(path: &Path) -> String {
    let registry = Registry::builtin();
    let (_, checked) = reach::check(Input::Path(relative(path)), &registry);
    match checked {
        Ok(_) => panic!(
            "{} checks without error, but is under tests/errors",
            path.display()
        ),
        Err(d) => d.render(true),
    }
}

/// Snapshots named `golden__NAME@FILE.snap`, as when this file was a test
/// binary of its own (the module path no longer prefixes them).
fn golden_names() -> insta::Settings {
    let mut settings = insta::Settings::clone_current();
    settings.set_prepend_module_to_snapshot(false);
    settings
}

/// Each example's report is also validated against the JSON Schema the
/// binary prints (`reach schema`), so the schema cannot drift from the
/// output.
#[test]
fn example_reports() {
    let printed = super::cli::reach(&["schema"]);
    let schema: serde_json::Value = serde_json::from_slice(&printed.stdout).expect("a schema");
    golden_names().bind(|| {
        insta::glob!("../examples", "*.reach", |path| {
            let json = json_report(path);
            let report: serde_json::Value = serde_json::from_str(&json).expect("JSON");
            let errors = super::ecosystem::schema_errors(&schema, &report);
            assert!(
                errors.is_empty(),
                "{}'s report does not follow `reach schema`:\n{}",
                path.display(),
                errors.join("\n")
            );
            insta::assert_snapshot!("golden__report", json);
        });
    });
}

#[test]
fn error_diagnostics() {
    golden_names().bind(|| {
        insta::glob!("errors", "*.reach", |path| {
            insta::assert_snapshot!("golden__diagnostics", diagnostics(path));
        });
    });
}
