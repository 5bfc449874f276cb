//! Building standards: rules about a room (reach ranges of its elements,
//! clear floor space, turning space, knee clearance, route widths),
//! checked beside the simulated people's own answers. A standard is a
//! plugin (`standard ada2010`), so that another code (ISO 21542, a
//! national one) is added the same way.

use super::{Options, Plugin, SettingsError};
use crate::allowance::Allowance;
use crate::report::StandardReport;
use crate::scene::Room;

pub trait StandardPlugin: Plugin {
    /// The standard that validated `options` configure.
    fn configure(&self, options: &Options) -> Result<Box<dyn Standard>, SettingsError>;
}

/// A configured standard.
pub trait Standard: Send + Sync {
    /// `room` checked against the standard's rules: each with what was
    /// measured, what the rule allows and whether it holds. What working
    /// out its floor costs is spent from `allowance`; once that is
    /// exhausted the check may stop short (the run then gives no answer).
    fn check(&self, room: &Room, allowance: &dyn Allowance) -> StandardReport;

    /// The boxes its options name (a water closet, a grab bar), each with
    /// its option: the checker makes sure each is a box of every room
    /// checked.
    fn boxes_named(&self) -> Vec<(&'static str, String)> {
        Vec::new()
    }
}
