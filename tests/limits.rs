//! A scenario's own bounds on its run (`limits { ... }`): a file may raise
//! them up to `--max-limits-raise` times the command line's, or lower them.

use crate::cli::{reach, stderr};

/// `examples/flat_12.reach` with `limits` (none where `limits` is empty)
/// written at its top, in a temporary directory; its path.
fn flat_with(limits: &str) -> (tempfile::TempDir, std::path::PathBuf) {
    let dir = tempfile::tempdir().unwrap();
    let text = std::fs::read_to_string("examples/flat_12.reach").unwrap();
    let path = dir.path().join("flat.reach");
    std::fs::write(&path, format!("{limits}\n{text}")).unwrap();
    (dir, path)
}

/// `reach run FILE --max-solver-work 10000000`: flat_12 needs about
/// 38,000,000 units, so the command line's bound alone stops it.
fn run_within_1e7(path: &std::path::Path, also: &[&str]) -> std::process::Output {
    let mut args = vec![
        "run",
        path.to_str().unwrap(),
        "--max-solver-work",
        "10000000",
    ];
    args.extend_from_slice(also);
    reach(&args)
}

#[test]
fn a_file_raises_its_own_bound_on_work_within_ten_times_the_command_lines() {
    let (_d, plain) = flat_with("");
    let o = run_within_1e7(&plain, &[]);
    assert_eq!(o.status.code(), Some(4), "{}", stderr(&o));
    assert!(stderr(&o).contains("solver_work N"), "{}", stderr(&o));
    assert!(
        !stderr(&o).contains("the bound this file sets"),
        "{}",
        stderr(&o)
    );

    let (_d, raised) = flat_with("limits { solver_work 1e8 }");
    let o = run_within_1e7(&raised, &[]);
    assert!(matches!(o.status.code(), Some(0 | 3)), "{}", stderr(&o));

    // Ten times is the most by default; the command line may allow more.
    let (_d, too_far) = flat_with("limits { solver_work 2e8 }");
    let o = run_within_1e7(&too_far, &[]);
    assert_eq!(o.status.code(), Some(1));
    let err = stderr(&o);
    assert!(
        err.contains("above the 100,000,000") && err.contains("--max-solver-work 200000000"),
        "{err}"
    );
    let o = run_within_1e7(&too_far, &["--max-limits-raise", "20"]);
    assert!(matches!(o.status.code(), Some(0 | 3)), "{}", stderr(&o));
}

/// A bound the file lowered stops the run, and the diagnostic points at
/// the line that lowered it.
#[test]
fn a_file_lowers_its_own_bound_below_the_command_lines() {
    let (_d, lowered) = flat_with("limits { solver_work 1000000 }");
    let o = reach(&["run", lowered.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(4));
    let err = stderr(&o);
    assert!(err.contains("limit of 1,000,000 units"), "{err}");
    assert!(err.contains("the bound this file sets"), "{err}");
    assert!(err.contains("1 │ limits { solver_work 1000000 }"), "{err}");
}
