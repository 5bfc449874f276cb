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
//! - for the fixtures its options name (each a box): 603.3 a mirror's
//!   bottom edge, 604.2 a water closet's centreline from the side wall,
//!   604.3.1 its clearance, 604.4 its seat, 604.5.1 and 604.5.2 its grab
//!   bars' places, 606.3 a lavatory's rim, 609.2-609.4 each grab bar's
//!   cross section, space from the wall and height, 904.4 a sales or
//!   service counter's accessible portion (`fixtures.rs`).
//!
//! The figures are [`ADA2010`] (`figures.rs`), the rules `rules.rs`'s and
//! `fixtures.rs`'s.

use super::figures::ADA2010;
use super::fixtures::Fixtures;
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
    fixtures: Fixtures,
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
            fixtures: Fixtures {
                water_closet: p
                    .optional_name(
                        "water_closet",
                        "the box that is the water closet (604.2-604.4: its centreline from the side wall, clearance, seat height)",
                    )
                    .get(),
                water_closet_tank: p
                    .optional_name(
                        "water_closet_tank",
                        "the box that is the water closet's tank, where it is a box of its own (part of the water closet for its walls and clearance)",
                    )
                    .get(),
                side_grab_bar: p
                    .optional_name(
                        "side_grab_bar",
                        "the box that is the side wall's grab bar (604.5.1, 609.2-609.4)",
                    )
                    .get(),
                rear_grab_bar: p
                    .optional_name(
                        "rear_grab_bar",
                        "the box that is the rear wall's grab bar (604.5.2, 609.2-609.4)",
                    )
                    .get(),
                lavatory: p
                    .optional_name(
                        "lavatory",
                        "the box that is the lavatory or sink (606.3: its rim's height)",
                    )
                    .get(),
                mirror: p
                    .optional_name(
                        "mirror",
                        "the box that is the mirror's reflecting surface (603.3: its bottom edge)",
                    )
                    .get(),
                service_counter: p
                    .optional_name(
                        "service_counter",
                        "the box that is the accessible portion of a sales or service counter (904.4)",
                    )
                    .get(),
            },
        }
    }
}

impl Plugin for Ada2010 {
    fn name(&self) -> &'static str {
        "ada2010"
    }

    fn doc(&self) -> &'static str {
        "the 2010 ADA Standards: turning space (304), reach ranges (308), clear floor space (305), knee clearance (306), route widths (403.5.1), door widths (404.2.3); for the fixtures named: mirrors (603.3), water closets (604.2-604.5), lavatories (606.3), grab bars (609.2-609.4), service counters (904.4)"
    }

    fn params(&self) -> Vec<ParamSpec> {
        Ada2010Settings::params()
    }
}

impl StandardPlugin for Ada2010 {
    fn configure(&self, options: &Options) -> Result<Box<dyn Standard>, SettingsError> {
        let settings = Ada2010Settings::from_options(options)?;
        Ok(Box::new(Checked {
            approach: Approach::parse(&settings.approach)?,
            fixtures: settings.fixtures,
        }))
    }
}

/// The configured standard: the approaches it may use, and the room's
/// fixtures its options name.
struct Checked {
    approach: Approach,
    fixtures: Fixtures,
}

impl Standard for Checked {
    fn check(&self, room: &Room, allowance: &dyn Allowance) -> StandardReport {
        rules::check(&ADA2010, self.approach, room, allowance, &self.fixtures)
    }

    fn boxes_named(&self) -> Vec<(&'static str, String)> {
        self.fixtures.named()
    }
}
