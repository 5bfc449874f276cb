//! Inverse kinematics solvers, each a plugin.

mod dls;
mod incremental;
mod starts;

pub use dls::{Dls, DlsSolver};
pub use incremental::{Incremental, IncrementalSettings, IncrementalSolver};
pub use starts::{random_posture, Starts};
