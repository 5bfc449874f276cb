//! Inverse kinematics solvers, each a plugin.

mod incremental;

pub use incremental::{Incremental, IncrementalSettings, IncrementalSolver};
