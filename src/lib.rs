//! reach: can this person reach and see the things in this room?
//!
//! The pipeline, from text to report (ARCHITECTURE.md has the map):
//! [`load`] reads the scenario file and everything it `use`s and parses
//! each; [`check`] resolves names, evaluates expressions with units and
//! validates plugin options against the plugins of a [`plugin::Registry`]
//! and configures them into a [`scenario::Scenario`]; [`run`] runs its
//! tasks into a [`report::Report`], which an output format renders.
//!
//! ```no_run
//! let registry = reach::plugin::Registry::builtin();
//! let (_sources, checked) = reach::check(reach::Input::Path("kitchen.reach".as_ref()), &registry);
//! match checked.map(|scenario| reach::run(&scenario)) {
//!     Ok(Ok(report)) => println!("{:?}", report.tasks),
//!     // A run whose solvers worked past the bound (`Limits::solver_work`).
//!     Ok(Err(error)) => eprintln!("{error}"),
//!     Err(diagnostics) => eprintln!("{}", diagnostics.render(true)),
//! }
//! ```

pub mod allowance;
pub mod ansur;
pub mod bases;
mod builtin;
pub mod cache;
pub mod calibration;
mod check;
pub mod collision;
pub mod engine;
pub mod error;
pub mod escape;
mod excerpt;
pub mod figure;
pub mod floor;
pub mod geometry;
pub mod kept;
pub mod kinematics;
pub mod limits;
mod loader;
pub mod machine_diagnostics;
pub mod meshfile;
pub mod meter;
mod names;
pub mod options;
pub mod output;
pub mod picture;
pub mod plugin;
pub mod progress;
pub mod read;
pub mod report;
pub mod scenario;
pub mod scene;
pub mod solvers;
pub mod source;
pub mod span;
pub mod standards;
pub mod std_modules;
pub mod stdlib;
pub mod suite;
pub mod syntax;
pub mod tasks;
pub mod units;
pub mod vision;

pub use error::{Diagnostics, Error, ErrorKind};
pub use limits::Limits;
pub use loader::Input;
pub use machine_diagnostics::DiagnosticStyle;

use plugin::Registry;
use report::Report;
use scenario::Scenario;
use source::Sources;

/// Load and check a scenario within the default [`Limits`]. The sources
/// come back either way, so that a
/// caller can show or watch the files; the diagnostics are ready to render.
pub fn check(input: Input<'_>, registry: &Registry) -> (Sources, Result<Scenario, Diagnostics>) {
    check_within(input, registry, &Limits::default())
}

/// [`check`] against `limits` instead of the default ones.
pub fn check_within(
    input: Input<'_>,
    registry: &Registry,
    limits: &Limits,
) -> (Sources, Result<Scenario, Diagnostics>) {
    check_allowing(input, registry, limits, &[])
}

/// [`check_within`], reading files from the directories in `also_allowed`
/// as well as the root's own (`--allow-path`; see [`read`]).
pub fn check_allowing(
    input: Input<'_>,
    registry: &Registry,
    limits: &Limits,
    also_allowed: &[std::path::PathBuf],
) -> (Sources, Result<Scenario, Diagnostics>) {
    let _suggestions = names::fresh_budget();
    let (mut sources, loaded) = loader::load(input, limits, also_allowed);
    let result = loaded.and_then(|files| {
        let (data_files, checked) = check::check(&sources, &files, registry, limits);
        sources.add_data_files(data_files);
        checked
    });
    let result = result.map_err(|d| d.attach(&sources));
    (sources, result)
}

/// Run every task of a checked scenario, in parallel; the report lists them
/// in the order of the file whatever the number of threads. An error where
/// the solvers needed more work than the scenario's bound
/// ([`Limits::solver_work`]; no answer is given, since some were cut short).
pub fn run(scenario: &Scenario) -> Result<Report, Error> {
    run_with_progress(scenario, &progress::NoProgress)
}

/// [`run`], telling `progress` how long tasks (maps) advance.
pub fn run_with_progress(
    scenario: &Scenario,
    progress: &dyn progress::Progress,
) -> Result<Report, Error> {
    run_counting(scenario, progress).map(|(report, _)| report)
}

/// [`run_with_progress`], and the work its solvers did, in the units of
/// [`meter`]: the same on every run and thread count.
pub fn run_counting(
    scenario: &Scenario,
    progress: &dyn progress::Progress,
) -> Result<(Report, u64), Error> {
    let all: Vec<&scenario::TaskSpec> = scenario.tasks.iter().collect();
    let ran = scenario.run_tasks(&all, progress)?;
    let work: u64 = ran.iter().map(|r| r.work).sum();
    let tasks = ran.into_iter().map(|r| r.report).collect();
    let (report, standards) = scenario.report(tasks, work)?;
    Ok((report, work + standards))
}
