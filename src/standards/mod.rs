//! Building standards, each a plugin whose rules are checked on a room
//! beside the simulated people's answers: `ada2010` (the 2010 ADA
//! Standards). A standard is a table of figures (`figures.rs`) that the
//! rules (`rules.rs`) read; `elements.rs` measures what stands between the
//! floor and an element, for any standard's reach rules.

mod ada2010;
mod clearance;
mod elements;
mod figures;
mod fixtures;
mod rules;

pub use ada2010::Ada2010;
