//! Kinematic chains: Denavit-Hartenberg parameters, joints with limits, and
//! forward kinematics, full (`chain.rs`) and incremental (`incremental.rs`);
//! joints whose ranges are coupled (`coupling.rs`: an ellipse through
//! their limits, `ellipse.rs`, or one following two others' elevation,
//! `rhythm.rs`);
//! bodies (`body.rs`): joints as a tree with several effectors; the legs
//! no joint moves (`legs.rs`), and a standing body's balance over them
//! (`balance.rs`); a left hand's chain as its right twin's mirror image
//! (`mirror.rs`).

mod balance;
mod body;
mod chain;
mod coupling;
mod dh;
mod ellipse;
mod frames;
mod incremental;
mod legs;
mod limited;
mod mirror;
mod posed;
mod rhythm;
mod urdf;
mod volumes;

pub use balance::{upper_centre_mm, Balance, Tipping, LEGS_MASS_SHARE, SUPPORT_SHARE};
pub use body::{hand_side, twin_name, Body, Effector, Sphere, LEFT_PREFIX};
#[cfg(test)]
pub(crate) use chain::revolute;
pub use chain::{Chain, Joint, JointKind, Link, Rider};
pub use coupling::{Coupling, Ellipse, Rhythm};
pub use dh::Dh;
pub use frames::{Declared, Folded};
pub use incremental::{IncrementalFk, Step};
pub use legs::{Legs, Stance};
pub use mirror::{flips_of_twin, mirrored, seed_point_mm};
pub use posed::Posed;
pub use urdf::{chain_from_urdf, UrdfError};
pub use volumes::{Contact, Motion, Owner, Volumes};
