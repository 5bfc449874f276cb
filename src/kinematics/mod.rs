//! Kinematic chains: Denavit-Hartenberg parameters, joints with limits, and
//! forward kinematics, full (`chain.rs`) and incremental (`incremental.rs`);
//! bodies (`body.rs`): joints as a tree with several effectors.

mod body;
mod chain;
mod dh;
mod incremental;
mod urdf;

pub use body::{Body, Effector};
pub use chain::{Chain, Joint, JointKind};
pub use dh::Dh;
pub use incremental::{IncrementalFk, Step};
pub use urdf::{chain_from_urdf, UrdfError};
