//! reach: can this person reach and see the things in this room?
//!
//! The pipeline, from text to report (ARCHITECTURE.md has the map):
//! [`check`] reads the scenario file and everything it `use`s, parses
//! each, resolves names, evaluates expressions with units and
//! validates plugin options against the plugins of a [`plugin::Registry`]
//! and configures them into a [`scenario::Scenario`]; [`run`] runs its
//! tasks into a [`report::Report`], which an output format renders.
//! [`Session`] checks and runs with limits, progress and a number of
//! threads of its own.
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

// Without the `internals` feature, what only the crate's own tests,
// benches and fuzz targets use of its modules (re-exports, helpers) is
// unused.
#![cfg_attr(not(feature = "internals"), allow(dead_code, unused_imports))]

// The run API and the plugin SDK: what a program that uses this crate
// sees. `plugin` is the SDK (the traits, the registry, and the types their
// methods take); `report`, `output`, `suite`, `limits` and `progress` are
// what a run takes and gives (`machine_diagnostics`: its diagnostics as
// JSON Lines or GitHub workflow commands).
pub mod limits;
pub mod machine_diagnostics;
pub mod output;
pub mod plugin;
pub mod progress;
pub mod report;
pub mod suite;
// What an editor asks of a scenario: the language server's library.
pub mod editor;

/// Modules that are the crate's own: private, but public (and hidden from
/// the docs) where the `internals` feature is on, which only the crate's
/// own tests, benches and fuzz targets enable (`[dev-dependencies]`), so
/// that they can test the parts.
macro_rules! internal_modules {
    ($($module:ident)*) => {
        $(
            #[cfg(feature = "internals")]
            #[doc(hidden)]
            pub mod $module;
            #[cfg(not(feature = "internals"))]
            mod $module;
        )*
    };
}

internal_modules! {
    allowance ansur bases builtin cache calibration check collision engine
    error escape excerpt figure floor functional_reach geometry kept kinematics loader
    meshfile meter names once options picture read scenario
    scene solvers source span standards std_modules std_texts stdlib syntax tasks units
    vision
}

pub use cache::{CacheStats, Plan, TaskCache};
pub use error::{Diagnostics, Error, ErrorKind};
pub use escape::escaped;
pub use kept::Memo;
pub use limits::Limits;
pub use loader::Input;
pub use machine_diagnostics::{DiagnosticStyle, Finding};
pub use read::read_root;
pub use scenario::{fingerprint, read_shard, write_shard};
pub use scenario::{PeopleBuilt, Scenario, ShardOf, ShardPart};
pub use source::Sources;
pub use std_modules::listing as stdlib_listing;
pub use stdlib::describe as stdlib_entry;

use std::sync::Arc;

use plugin::Registry;
use report::Report;

/// How scenarios are checked and run: the limits, the directories files
/// may be read from besides each root's own (`--allow-path`; see
/// `read`), what long tasks (maps) tell their progress to, how many
/// threads run the tasks and what the runs keep for each other (floors,
/// routes, capability maps: [`kept::Memo`]). `Session::default()` has the
/// defaults: [`Limits::default`], no other directory, no progress, rayon's
/// global pool, a memo for each run.
///
/// ```no_run
/// let registry = reach::plugin::Registry::builtin();
/// let session = reach::Session::default().threads(2);
/// let (_sources, checked) = session.check(reach::Input::Path("kitchen.reach".as_ref()), &registry);
/// if let Ok(scenario) = checked {
///     let ran = session.run(&scenario).expect("within the bound on solver work");
///     println!("{} answers, {} units of work", ran.report.tasks.len(), ran.work);
/// }
/// ```
#[derive(Clone, Copy)]
pub struct Session<'a> {
    limits: Limits,
    also_allowed: &'a [std::path::PathBuf],
    progress: &'a dyn progress::Progress,
    threads: Option<usize>,
    memo: Option<&'a Arc<kept::Memo>>,
    built: scenario::PeopleBuilt,
}

/// A run's report and the work its solvers did, in the units of
/// the meter: the same on every run and thread count.
#[derive(Clone, Debug)]
pub struct Ran {
    pub report: Report,
    pub work: u64,
    /// Where the bound on work stopped a run of [`Session::run_partly`]
    /// (none where every task was answered): the error to show, at the
    /// first task not evaluated.
    pub stopped: Option<Error>,
}

impl Default for Session<'_> {
    fn default() -> Self {
        Session {
            limits: Limits::default(),
            also_allowed: &[],
            progress: &progress::NoProgress,
            threads: None,
            memo: None,
            built: scenario::PeopleBuilt::Everyone,
        }
    }
}

impl<'a> Session<'a> {
    /// Checking and running within `limits`.
    pub fn limits(self, limits: Limits) -> Self {
        Session { limits, ..self }
    }

    /// Reading files from the directories in `also_allowed` as well as
    /// each root's own.
    pub fn allowing(self, also_allowed: &'a [std::path::PathBuf]) -> Self {
        Session {
            also_allowed,
            ..self
        }
    }

    /// Telling `progress` how long tasks advance.
    pub fn progress(self, progress: &'a dyn progress::Progress) -> Self {
        Session { progress, ..self }
    }

    /// Keeping what the runs work out that does not depend on the tasks
    /// (a base's floor, its routes, a person's capability map) in `memo`,
    /// for the runs after (a watch session's): the answers are those of a
    /// memo of the run's own.
    pub fn keeping(self, memo: &'a Arc<kept::Memo>) -> Self {
        Session {
            memo: Some(memo),
            ..self
        }
    }

    /// Building only these of each population's people as persons (a
    /// shard's, for [`Session::run_shard`]; the first, for
    /// [`Session::run_merged`]): a scenario so checked runs only those.
    pub fn building(self, built: scenario::PeopleBuilt) -> Self {
        Session { built, ..self }
    }

    /// Running the tasks on a pool of `threads` threads (at least 1) of
    /// their own; the answers are the same on every number.
    pub fn threads(self, threads: usize) -> Self {
        Session {
            threads: Some(threads.max(1)),
            ..self
        }
    }

    /// Load and check a scenario against `registry`'s plugins. The sources
    /// come back either way, so that a caller can show or watch the files;
    /// the diagnostics are ready to render.
    pub fn check(
        &self,
        input: Input<'_>,
        registry: &Registry,
    ) -> (Sources, Result<Scenario, Diagnostics>) {
        let (sources, _, checked) = self.check_loaded(input, registry);
        (sources, checked)
    }

    /// Check a scenario as [`Session::check`] does, and outline the names
    /// its files declare and use, for an editor.
    pub fn analyse(&self, input: Input<'_>, registry: &Registry) -> editor::Analysis {
        let (sources, files, checked) = self.check_loaded(input, registry);
        let outline = files.map(|files| {
            let asts = files.iter().map(|f| (f.id, &f.ast));
            editor::Outline::of(asts, registry)
        });
        editor::Analysis {
            sources,
            outline,
            checked,
        }
    }

    /// Load and check: the sources, the files parsed (none where one
    /// does not parse) and the check.
    fn check_loaded(
        &self,
        input: Input<'_>,
        registry: &Registry,
    ) -> (
        Sources,
        Option<Vec<loader::LoadedFile>>,
        Result<Scenario, Diagnostics>,
    ) {
        // One budget of did-you-mean suggestions for the whole check.
        let suggestions = names::Suggestions::default();
        let (mut sources, loaded) =
            loader::load(input, &self.limits, self.also_allowed, &suggestions);
        let (files, result) = match loaded {
            Ok(files) => {
                let (data_files, checked) = check::check(
                    &sources,
                    &files,
                    registry,
                    (&self.limits, self.built),
                    &suggestions,
                );
                sources.add_data_files(data_files);
                (Some(files), checked)
            }
            Err(d) => (None, Err(d)),
        };
        let result = result.map_err(|d| d.attach(&sources));
        (sources, files, result)
    }

    /// Run every task of a checked scenario, in parallel; the report lists
    /// them in the order of the file whatever the number of threads. An
    /// error where the solvers needed more work than the scenario's bound
    /// ([`Limits::solver_work`]; no answer is given, since some were cut
    /// short).
    pub fn run(&self, scenario: &Scenario) -> Result<Ran, Error> {
        self.on_pool(|memo| run_on_this_pool(scenario, self.progress, memo))
    }

    /// Run every task of a checked scenario as [`Session::run`] does, as
    /// far as the scenario's bound on work allows: where it stops the run,
    /// the answers of the longest leading run of tasks (in the order of
    /// the file) whose work fits within the bound, each task after them
    /// reported not evaluated ([`report::NotEvaluatedReport`]), and
    /// [`Ran::stopped`] says where and why. The same answers on every run
    /// and thread count: where the bound stops the tasks run in parallel,
    /// they are run again one at a time, in order, on `again`, the same
    /// scenario checked afresh (nothing run on it yet); where that cannot
    /// be had, no task is answered.
    pub fn run_partly(
        &self,
        scenario: &Scenario,
        again: &(dyn Fn() -> Option<Scenario> + Sync),
    ) -> Ran {
        self.on_pool(|memo| run_partly_on_this_pool(scenario, again, self.progress, memo))
    }

    /// Run shard `shard` of a run of a checked scenario: the shard's people
    /// of each population, for every task by it ([`Scenario::run_shard`]).
    pub fn run_shard(
        &self,
        scenario: &Scenario,
        shard: scenario::ShardOf,
    ) -> Result<Vec<scenario::ShardPart>, Error> {
        self.on_pool(|memo| scenario.run_shard(shard, self.progress, memo))
    }

    /// The run of a checked scenario whose populations' people were run by
    /// shards (`parts`, every shard's): the report a whole run gives
    /// ([`Scenario::run_merged`]).
    pub fn run_merged(
        &self,
        scenario: &Scenario,
        parts: &[scenario::ShardPart],
    ) -> Result<Ran, Error> {
        self.on_pool(|memo| {
            let (report, work) = scenario.run_merged(parts, self.progress, memo)?;
            Ok(Ran {
                report,
                work,
                stopped: None,
            })
        })
    }

    /// `run` on the session's pool of threads (or rayon's global one),
    /// with the session's memo (or one of its own).
    fn on_pool<T: Send>(&self, run: impl FnOnce(&Arc<kept::Memo>) -> T + Send) -> T {
        let pool = self
            .threads
            .and_then(|n| rayon::ThreadPoolBuilder::new().num_threads(n).build().ok());
        let own = Arc::default();
        let memo = self.memo.unwrap_or(&own);
        match pool {
            Some(pool) => pool.install(|| run(memo)),
            // Without a pool of its own (none asked for, or the system
            // gave none), on rayon's global one: the same answers.
            None => run(memo),
        }
    }
}

/// Load and check a scenario with `registry`'s plugins and the defaults
/// ([`Session`] for other limits and directories).
pub fn check(input: Input<'_>, registry: &Registry) -> (Sources, Result<Scenario, Diagnostics>) {
    Session::default().check(input, registry)
}

/// Run every task of a checked scenario with the defaults ([`Session::run`]).
pub fn run(scenario: &Scenario) -> Result<Report, Error> {
    Session::default().run(scenario).map(|ran| ran.report)
}

fn run_on_this_pool(
    scenario: &Scenario,
    progress: &dyn progress::Progress,
    memo: &Arc<kept::Memo>,
) -> Result<Ran, Error> {
    let all: Vec<&scenario::TaskSpec> = scenario.tasks.iter().collect();
    let ran = scenario.run_tasks(&all, progress, memo)?;
    let work: u64 = ran.iter().map(|r| r.work).sum();
    let tasks = ran.into_iter().map(|r| r.report).collect();
    let (report, standards) = scenario.report(tasks, work, memo)?;
    Ok(Ran {
        report,
        work: work + standards,
        stopped: None,
    })
}

fn run_partly_on_this_pool(
    scenario: &Scenario,
    again: &(dyn Fn() -> Option<Scenario> + Sync),
    progress: &dyn progress::Progress,
    memo: &Arc<kept::Memo>,
) -> Ran {
    let all: Vec<&scenario::TaskSpec> = scenario.tasks.iter().collect();
    let (ran, stopped) = scenario.run_tasks_partly(&all, progress, memo);
    if !stopped {
        return partly_reported(scenario, ran, None, memo);
    }
    match again() {
        Some(fresh) => {
            let all: Vec<&scenario::TaskSpec> = fresh.tasks.iter().collect();
            let (ran, stop) = fresh.run_tasks_in_order(&all, progress);
            partly_reported(&fresh, ran, stop, memo)
        }
        None => {
            let none = all.iter().map(|_| None).collect();
            let stop = scenario::Stop {
                at: 0,
                left: scenario.work.limit,
            };
            partly_reported(scenario, none, Some(stop), memo)
        }
    }
}

/// The report of `ran` (each task's answer, none where it was not
/// evaluated), stopped at `stop` where the bound stopped it.
fn partly_reported(
    scenario: &Scenario,
    ran: Vec<Option<scenario::Ran>>,
    stop: Option<scenario::Stop>,
    memo: &Arc<kept::Memo>,
) -> Ran {
    let work: u64 = ran.iter().flatten().map(|r| r.work).sum();
    let tasks = (ran.into_iter().zip(&scenario.tasks))
        .map(|(ran, task)| ran.map_or_else(|| scenario.not_evaluated(task), |r| r.report))
        .collect();
    let (report, standards, checked) = scenario.report_partly(tasks, work, stop.is_some(), memo);
    let stopped = match stop {
        Some(stop) => Some(scenario.stopped_at(stop)),
        None if !checked => Some(scenario.stopped_at_standards(work)),
        None => None,
    };
    Ran {
        report,
        work: work + standards,
        stopped,
    }
}
