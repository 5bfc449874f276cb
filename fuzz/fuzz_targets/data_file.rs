//! What the `obj` and `urdf` targets share: the fuzzed bytes written as the
//! data file a fixed scenario reads, then checked and run within a small
//! bound on solver starts. No input may panic or hang; a file that loads
//! must give the scenario's one report.

use reach::plugin::Registry;
use reach::{Input, Limits};

/// Writes `data` to `fuzz-scratch/{file}` (text input reads files from the
/// working directory and below), then checks and runs `scenario`.
pub fn check_with(file: &str, data: &[u8], name: &str, scenario: &str) {
    std::fs::create_dir_all("fuzz-scratch").unwrap();
    std::fs::write(format!("fuzz-scratch/{file}"), data).unwrap();
    let registry = Registry::builtin();
    let limits = Limits {
        solver_starts: 2_000,
        solver_work: 20_000_000,
        ..Limits::default()
    };
    let input = Input::Text { name, text: scenario };
    let (_, checked) = reach::Session::default().limits(limits).check(input, &registry);
    match checked {
        Err(diagnostics) => {
            let _ = diagnostics.render(true);
        }
        // Past the bound on solver work, a run is an error with the
        // limit named, never a panic.
        Ok(scenario) => match reach::run(&scenario) {
            Ok(report) => assert_eq!(report.tasks.len(), 1),
            Err(e) => assert!(e.to_string().contains("limit"), "{e}"),
        },
    }
}
