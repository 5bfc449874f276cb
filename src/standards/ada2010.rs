//! The 2010 ADA Standards for Accessible Design, checked on a room:
//!
//! - 304 turning space: a 1525 mm circle (304.3.1) or a T within a 1525 mm
//!   square with 915 mm arms (304.3.2), on floor a route from a door gets
//!   to, knee and toe clearance allowed (304.2: floor under obstacles from
//!   685 mm up counts, 635 mm deep from their edges, 306);
//! - 404.2.3 each door's clear width, at least 815 mm (its opening less
//!   what stands in it just inside);
//! - for each element (target), a forward or a side approach that meets:
//!   308 reach range (308.2.1 forward unobstructed 380-1220 mm; 308.2.2
//!   forward over an obstruction 1220 mm up to 510 mm deep, 1120 mm up to
//!   635 mm deep; 308.3.1 side 380-1220 mm, over an obstruction at most
//!   255 mm deep and 865 mm high; 308.3.2 side over an obstruction 255-610
//!   mm deep and at most 865 mm high, 1170 mm; never below 380 mm), 305 a
//!   760 x 1220 mm clear floor space (forward: its short side at the
//!   element; side: its long side), 306.3 knee clearance under the
//!   obstruction where a forward reach goes over one (at least 685 mm
//!   high, 205 mm deep there and 280 mm at 230 mm, 1 in 6 between) and
//!   306.2 toe clearance (430 mm, and as deep as the reach; see
//!   `clearance.rs`), and 403.5.1 a route at
//!   least 915 mm wide from a door to the clear floor space (where the room
//!   has doors).
//!
//! The figures are [`ADA2010`] (`figures.rs`), the rules `rules.rs`'s.

use super::figures::ADA2010;
use super::rules;
use crate::allowance::Allowance;
use crate::bases::Approach;
use crate::plugin::{
    Options, ParamSpec, Params, Plugin, Settings, SettingsError, Standard, StandardPlugin,
};
use crate::report::StandardReport;
use crate::scene::Room;

/// The plugin `ada2010`.
pub struct Ada2010;

/// Its settings.
#[derive(Clone, Debug, PartialEq)]
struct Ada2010Settings {
    approach: String,
}

impl Settings for Ada2010Settings {
    fn visit(p: &mut Params<'_>) -> Self {
        Ada2010Settings {
            approach: p
                .name(
                    "approach",
                    "any",
                    "`forward` or `side`: every element must be usable so, with that approach's rules (`any`: either)",
                )
                .get(),
        }
    }
}

impl Plugin for Ada2010 {
    fn name(&self) -> &'static str {
        "ada2010"
    }

    fn doc(&self) -> &'static str {
        "the 2010 ADA Standards: turning space (304), reach ranges (308), clear floor space (305), knee clearance (306), route widths (403.5.1), door widths (404.2.3)"
    }

    fn params(&self) -> Vec<ParamSpec> {
        Ada2010Settings::params()
    }
}

impl StandardPlugin for Ada2010 {
    fn configure(&self, options: &Options) -> Result<Box<dyn Standard>, SettingsError> {
        let settings = Ada2010Settings::from_options(options)?;
        Ok(Box::new(Checked(Approach::parse(&settings.approach)?)))
    }
}

/// The configured standard: the approaches it may use.
struct Checked(Approach);

impl Standard for Checked {
    fn check(&self, room: &Room, allowance: &dyn Allowance) -> StandardReport {
        rules::check(&ADA2010, self.0, room, allowance)
    }
}
