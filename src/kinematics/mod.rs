//! Kinematic chains: Denavit-Hartenberg parameters, joints with limits, and
//! forward kinematics, full (`chain.rs`) and incremental (`incremental.rs`).

mod chain;
mod dh;
mod incremental;

pub use chain::{Chain, Joint, JointKind};
pub use dh::Dh;
pub use incremental::{IncrementalFk, Step};
