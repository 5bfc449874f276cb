//! Inverse kinematics solvers, each a plugin.

mod dls;
pub mod fabrik;
mod incremental;
mod starts;

pub use dls::{Dls, DlsSolver};
pub use fabrik::{Fabrik, FabrikSettings, FabrikSolver};
pub use incremental::{Incremental, IncrementalSettings, IncrementalSolver};
pub use starts::{random_posture, Kicks, Starts};
