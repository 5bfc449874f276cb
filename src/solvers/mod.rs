//! Inverse kinematics solvers, each a plugin.

mod dls;
mod incremental;

pub use dls::{Dls, DlsSolver};
pub use incremental::{random_posture, Incremental, IncrementalSettings, IncrementalSolver};
