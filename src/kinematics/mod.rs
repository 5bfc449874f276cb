//! Kinematic chains: Denavit-Hartenberg parameters, joints with limits, and
//! forward kinematics.

mod chain;
mod dh;

pub use chain::{Chain, Joint, JointKind};
pub use dh::Dh;
