//! reach: can this person reach and see the things in this room?
//!
//! The pipeline, from text to report (ARCHITECTURE.md has the map):
//! [`load`] reads the scenario file and everything it `use`s and parses
//! each; [`check`] resolves names, evaluates expressions with units and
//! validates plugin options into a [`scene::Scenario`]; [`run`] runs its
//! tasks with the plugins of a [`plugin::Registry`] into a
//! [`report::Report`], which an output format renders.
//!
//! ```no_run
//! let registry = reach::plugin::Registry::builtin();
//! let (_sources, checked) = reach::check(reach::Input::Path("kitchen.reach".as_ref()), &registry);
//! match checked {
//!     Ok(scenario) => println!("{:?}", reach::run(&scenario, &registry).tasks),
//!     Err(diagnostics) => eprintln!("{}", diagnostics.render(true)),
//! }
//! ```

pub mod bases;
mod builtin;
pub mod cache;
mod check;
pub mod collision;
pub mod error;
pub mod floor;
pub mod kinematics;
pub mod limits;
mod loader;
mod names;
pub mod options;
pub mod output;
pub mod plugin;
pub mod progress;
pub mod report;
pub mod scene;
pub mod solvers;
pub mod source;
pub mod span;
pub mod std_modules;
pub mod stdlib;
pub mod syntax;
pub mod tasks;
pub mod units;
pub mod vision;

use rayon::prelude::*;

pub use error::{Diagnostics, Error, ErrorKind};
pub use limits::Limits;
pub use loader::Input;

use plugin::{Registry, TaskContext};
use report::Report;
use scene::Scenario;
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
    let (mut sources, loaded) = loader::load(input, limits);
    let result = loaded.and_then(|files| {
        let (data_files, checked) = check::check(&sources, &files, registry, limits);
        sources.add_data_files(data_files);
        checked
    });
    let result = result.map_err(|d| d.attach(&sources));
    (sources, result)
}

/// Run every task of a checked scenario, in parallel; the report lists them
/// in the order of the file whatever the number of threads.
pub fn run(scenario: &Scenario, registry: &Registry) -> Report {
    run_with_progress(scenario, registry, &progress::NoProgress)
}

/// [`run`], telling `progress` how long tasks (maps) advance.
pub fn run_with_progress(
    scenario: &Scenario,
    registry: &Registry,
    progress: &dyn progress::Progress,
) -> Report {
    let tasks = scenario
        .tasks
        .par_iter()
        .map(|task| {
            let plugin = registry
                .task(&task.kind)
                .expect("the checker resolved every task kind");
            plugin.run(&TaskContext {
                scenario,
                task,
                registry,
                progress,
            })
        })
        .collect();
    Report {
        schema: report::SCHEMA_VERSION,
        file: scenario.file.clone(),
        tasks,
    }
}
