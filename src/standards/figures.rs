//! A building standard's figures as one table: the numbers and section
//! names that `rules.rs` reads. A second standard with the same rules is
//! a second table.

/// A standard's figures, mm, and the sections that set them.
#[derive(Clone, Copy, Debug)]
pub struct Figures {
    /// The standard's name in reports.
    pub name: &'static str,
    /// The highest a forward or side reach may be, unobstructed.
    pub high_mm: f64,
    /// The lowest any reach may be.
    pub low_mm: f64,
    /// A forward reach over an obstruction up to this deep may reach
    /// [`Figures::high_mm`] ...
    pub forward_deep_mm: f64,
    /// ... and over one up to this deep, at most this high
    /// ([`Figures::forward_deep_high_mm`]); deeper, not at all.
    pub forward_deepest_mm: f64,
    pub forward_deep_high_mm: f64,
    /// A side reach over an obstruction up to this deep reaches the
    /// unobstructed range ...
    pub side_shallow_mm: f64,
    /// ... and over one up to this deep, at most this high
    /// ([`Figures::side_deep_high_mm`]); deeper, not at all.
    pub side_deepest_mm: f64,
    pub side_deep_high_mm: f64,
    /// The highest an obstruction a side reach goes over may be.
    pub side_obstruction_high_mm: f64,
    /// The clear floor space: its short side and its long side.
    pub floor_width_mm: f64,
    pub floor_length_mm: f64,
    /// Knee clearance: at least this high ...
    pub knee_high_mm: f64,
    /// ... this deep at that height ...
    pub knee_front_deep_mm: f64,
    /// ... and this deep at [`Figures::toe_high_mm`], narrowing between
    /// the two by 1 in [`Figures::knee_slope`] of height ...
    pub knee_deep_mm: f64,
    pub knee_slope: f64,
    /// ... and counted as floor space only so deep.
    pub knee_deepest_mm: f64,
    /// Toe clearance: the space up to this high, at least this deep under
    /// the element (and as deep as the reach over it).
    pub toe_high_mm: f64,
    pub toe_deep_mm: f64,
    /// The turning circle's diameter, and the T's square.
    pub turning_mm: f64,
    /// The width of the T's arms.
    pub turning_arm_mm: f64,
    /// The narrowest route from a door.
    pub route_mm: f64,
    /// The narrowest clear width of a door.
    pub door_mm: f64,
    /// A route narrows at anything below this: what protrudes into it
    /// takes its width.
    pub headroom_mm: f64,
    pub sections: Sections,
}

/// The standard's section of each rule, as reports name it.
#[derive(Clone, Copy, Debug)]
pub struct Sections {
    pub turning: &'static str,
    pub turning_circle: &'static str,
    pub turning_t: &'static str,
    pub door: &'static str,
    pub route: &'static str,
    pub forward_reach: &'static str,
    pub forward_unobstructed: &'static str,
    pub forward_over: &'static str,
    pub knee: &'static str,
    pub toe: &'static str,
    pub side_reach: &'static str,
    pub side_shallow: &'static str,
    pub side_deep: &'static str,
    pub clear_floor: &'static str,
}

/// The 2010 ADA Standards for Accessible Design (304, 305, 306, 307.4,
/// 308, 403.5.1, 404.2.3).
pub const ADA2010: Figures = Figures {
    name: "ada2010",
    high_mm: 1220.0,
    low_mm: 380.0,
    forward_deep_mm: 510.0,
    forward_deepest_mm: 635.0,
    forward_deep_high_mm: 1120.0,
    side_shallow_mm: 255.0,
    side_deepest_mm: 610.0,
    side_deep_high_mm: 1170.0,
    side_obstruction_high_mm: 865.0,
    floor_width_mm: 760.0,
    floor_length_mm: 1220.0,
    knee_high_mm: 685.0,
    knee_front_deep_mm: 205.0,
    knee_deep_mm: 280.0,
    knee_slope: 6.0,
    toe_high_mm: 230.0,
    toe_deep_mm: 430.0,
    knee_deepest_mm: 635.0,
    turning_mm: 1525.0,
    turning_arm_mm: 915.0,
    route_mm: 915.0,
    door_mm: 815.0,
    headroom_mm: 2030.0,
    sections: Sections {
        turning: "304.3",
        turning_circle: "304.3.1",
        turning_t: "304.3.2",
        door: "404.2.3",
        route: "403.5.1",
        forward_reach: "308.2",
        forward_unobstructed: "308.2.1",
        forward_over: "308.2.2",
        knee: "306.3",
        toe: "306.2",
        side_reach: "308.3",
        side_shallow: "308.3.1",
        side_deep: "308.3.2",
        clear_floor: "305",
    },
};
