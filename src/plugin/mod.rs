//! Plugins: solvers, bases, tasks, output formats and building standards. Each implements
//! [`Plugin`] (a name, a one-line doc and declared parameters) and the trait
//! of its kind; all are registered by name in one [`Registry`]. A plugin
//! declares its options as a settings struct ([`Settings`]) and is built
//! from validated options once, by the checker: what runs holds its
//! settings, typed, and looks nothing up by name.

mod base;
mod descents;
mod format;
mod registry;
mod solver;
mod standard;
mod task;

pub use base::{
    Base, BaseError, BasePlugin, Fit, Hips, PreparedBase, ReachQuery, Retry, Search, Tries,
};
pub use descents::Descents;
pub use format::{FormatPlugin, FormatScene, TaskPlace};
pub use registry::Registry;
// What a solve tells its work to (`crate::allowance`).
pub use crate::allowance::{Allowance, Tally, Unbounded};
pub use solver::{work_ratio, IkProblem, Solver, SolverPlugin};
// A solver's fingerprint, by which watch mode keeps its solves.
pub use crate::engine::fingerprint_of;
pub use standard::{Standard, StandardPlugin};
pub use task::{Dependence, EffectorNeed, Subject, SubjectKind, Task, TaskInput, TaskPlugin};
// The data the traits speak of, so that a plugin needs one `use`.
pub use crate::options::{
    Options, ParamKind, ParamSpec, Params, PluginConfig, PluginKind, Settings, SettingsError, Value,
};
pub use crate::scene::{BasePose, IkSolution, Placement};
// The types the traits' questions carry: the chain a solver works on, the
// room, person and own body a base places, the obstacles a posture is
// checked against, what a task and a format answer with.
pub use crate::collision::{Obstacles, PlacedObstacles, Touched};
pub use crate::engine::{Asked, KeptProofs, KeptSolves, SolvesFor};
pub use crate::kinematics::{Body, Chain, Joint};
pub use crate::report::{Names, Report, StandardReport, TaskReport};
pub use crate::scene::{OwnBody, Person, Room};

/// What every plugin declares.
pub trait Plugin: Send + Sync {
    fn name(&self) -> &'static str;
    /// One line for `reach plugins`.
    fn doc(&self) -> &'static str;
    /// The options its block accepts (its settings' declared parameters).
    fn params(&self) -> Vec<ParamSpec>;
}
