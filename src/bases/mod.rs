//! Bases: where the person stands or sits, each a plugin.

mod fixed;

pub use fixed::Fixed;
