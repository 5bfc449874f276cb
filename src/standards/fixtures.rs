//! The rules of a standard for named fixtures of a room, each a box the
//! standard's options name (`standard ada2010 in bathroom { water_closet
//! toilet side_grab_bar side_bar }`): a water closet's place, clearance
//! and seat (604.2-604.4), its grab bars (604.5, 609.2-609.4), a
//! lavatory's height (606.3), a mirror's bottom edge (603.3) and a sales
//! or service counter's accessible portion (904.4). Boxes are measured by
//! their outline's bounds, square to the room's walls; a fixture's wall is
//! the wall nearest it.

use crate::report::{mm, FloorShape, RuleCheck};
use crate::scene::{BoxObstacle, Room};

/// The boxes a standard's options name as fixtures.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Fixtures {
    pub water_closet: Option<String>,
    /// The water closet's tank, where it is a box of its own: part of the
    /// water closet for its walls and its clearance, not for its seat.
    pub water_closet_tank: Option<String>,
    pub side_grab_bar: Option<String>,
    pub rear_grab_bar: Option<String>,
    pub lavatory: Option<String>,
    pub mirror: Option<String>,
    pub service_counter: Option<String>,
}

impl Fixtures {
    /// Each fixture named, with its option.
    pub fn named(&self) -> Vec<(&'static str, String)> {
        [
            ("water_closet", &self.water_closet),
            ("water_closet_tank", &self.water_closet_tank),
            ("side_grab_bar", &self.side_grab_bar),
            ("rear_grab_bar", &self.rear_grab_bar),
            ("lavatory", &self.lavatory),
            ("mirror", &self.mirror),
            ("service_counter", &self.service_counter),
        ]
        .into_iter()
        .filter_map(|(option, name)| name.clone().map(|n| (option, n)))
        .collect()
    }
}

/// The 2010 ADA Standards' figures for fixtures, mm.
mod ada {
    /// 604.2: the water closet's centreline from the side wall.
    pub const CENTRE_FROM_SIDE: (f64, f64) = (405.0, 455.0);
    /// 604.3.1: its clearance, measured from the side wall and the rear
    /// wall.
    pub const CLEARANCE_WIDE: f64 = 1525.0;
    pub const CLEARANCE_DEEP: f64 = 1420.0;
    /// 604.4: the seat's top.
    pub const SEAT: (f64, f64) = (430.0, 485.0);
    /// 604.5.1: the side wall's bar.
    pub const SIDE_BAR_LONG: f64 = 1065.0;
    pub const SIDE_BAR_FROM_REAR: f64 = 305.0;
    pub const SIDE_BAR_REACHES: f64 = 1370.0;
    /// 604.5.2: the rear wall's bar, from the centreline to the side wall
    /// and to the open side.
    pub const REAR_BAR_LONG: f64 = 915.0;
    pub const REAR_BAR_WALL_SIDE: f64 = 305.0;
    pub const REAR_BAR_OPEN_SIDE: f64 = 610.0;
    /// 609.2: a bar's cross section: round, 1 1/4 to 2 in across
    /// (609.2.1), or another shape 4 to 4.8 in round and at most 2 in
    /// across (609.2.2).
    pub const ROUND: (f64, f64) = (32.0, 51.0);
    pub const PERIMETER: (f64, f64) = (100.0, 122.0);
    /// 609.3: the space between a bar and its wall.
    pub const FROM_WALL: f64 = 38.0;
    /// 604.3.2: a box on a wall, off the floor and at most this deep (a
    /// dispenser, a coat hook, a shelf) may stand in the clearance.
    pub const ACCESSORY_DEEP: f64 = 200.0;
    pub const ACCESSORY_OFF_FLOOR: f64 = 380.0;
    /// A box this close to a wall is on it.
    pub const ON_WALL: f64 = 50.0;
    /// 609.4: the top of the gripping surface.
    pub const BAR_HEIGHT: (f64, f64) = (840.0, 915.0);
    /// 606.3: a lavatory's rim or counter surface, at most.
    pub const LAVATORY_HIGH: f64 = 865.0;
    /// 603.3: a mirror's bottom edge, above a lavatory or counter and
    /// elsewhere.
    pub const MIRROR_OVER_LAVATORY: f64 = 1015.0;
    pub const MIRROR_ELSEWHERE: f64 = 890.0;
    /// 904.4: a service counter's portion: long (parallel approach, and
    /// forward approach), and high at most.
    pub const COUNTER_LONG_PARALLEL: f64 = 915.0;
    pub const COUNTER_LONG_FORWARD: f64 = 760.0;
    pub const COUNTER_HIGH: f64 = 915.0;
    /// 306.3: knee clearance under a forward approach's counter, and
    /// 306.2.3 how deep the toe clearance under it reaches at least.
    pub const KNEE_HIGH: f64 = 685.0;
    pub const TOE_DEEP: f64 = 430.0;
    /// Nothing this low or lower stands in a clearance (a box at 2030 mm
    /// and above is headroom, 307.4).
    pub const HEADROOM: f64 = 2030.0;
}

/// Within this, two figures are one (the geometry's rounding; a bar drawn
/// 1 mm off its wall).
const ROUNDING_MM: f64 = 2.0;

/// A box's outline from above, as bounds square to the room.
#[derive(Clone, Copy, Debug)]
struct Plan {
    min: [f64; 2],
    max: [f64; 2],
    bottom: f64,
    top: f64,
}

fn plan(b: &BoxObstacle) -> Plan {
    let (w, d) = (b.size_mm.x, b.size_mm.y);
    let mut p = Plan {
        min: [f64::INFINITY; 2],
        max: [f64::NEG_INFINITY; 2],
        bottom: b.corner_mm.z,
        top: b.corner_mm.z + b.size_mm.z,
    };
    for (x, y) in [(0.0, 0.0), (w, 0.0), (0.0, d), (w, d)] {
        let corner = b.floor_point(nalgebra::Vector2::new(x, y));
        for k in 0..2 {
            p.min[k] = p.min[k].min(corner[k]);
            p.max[k] = p.max[k].max(corner[k]);
        }
    }
    p
}

impl Plan {
    /// The part of this outline within `deep` of its edge across `axis`
    /// (`far`: the edge away from the origin), not clamped to it.
    fn strip(mut self, axis: usize, far: bool, deep: f64) -> Plan {
        match far {
            false => self.max[axis] = self.min[axis] + deep,
            true => self.min[axis] = self.max[axis] - deep,
        }
        self
    }
}

/// The bounds of two outlines together.
fn union(a: Plan, b: Plan) -> Plan {
    Plan {
        min: [a.min[0].min(b.min[0]), a.min[1].min(b.min[1])],
        max: [a.max[0].max(b.max[0]), a.max[1].max(b.max[1])],
        bottom: a.bottom.min(b.bottom),
        top: a.top.max(b.top),
    }
}

/// How far the box is turned off the room's walls, degrees (0 to 45).
fn off_square_deg(b: &BoxObstacle) -> f64 {
    let quarter = std::f64::consts::FRAC_PI_2;
    let off = b.yaw_rad.rem_euclid(quarter);
    off.min(quarter - off).to_degrees()
}

/// A box turned more than this off the walls is not square to them.
const SQUARE_DEG: f64 = 1.0;

/// Whether two outlines overlap on the floor (by more than the rounding).
fn overlap(a: &Plan, b: &Plan) -> bool {
    (0..2).all(|k| a.min[k] < b.max[k] - ROUNDING_MM && b.min[k] + ROUNDING_MM < a.max[k])
}

/// A wall of the room: `axis` 0 is a wall across x (at x = 0 or at the
/// room's far x), 1 across y; `far` the one away from the origin.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Wall {
    axis: usize,
    far: bool,
}

impl Wall {
    /// How far the box is from this wall.
    fn gap(self, room: &Room, p: &Plan) -> f64 {
        self.span(room, p).0
    }

    /// How far the outline's nearest and farthest edges are from this
    /// wall.
    fn span(self, room: &Room, p: &Plan) -> (f64, f64) {
        let (a, b) = (
            self.from(room, p.min[self.axis]),
            self.from(room, p.max[self.axis]),
        );
        (a.min(b), a.max(b))
    }

    /// How far a coordinate along this wall's normal is from it.
    fn from(self, room: &Room, at: f64) -> f64 {
        match self.far {
            false => at,
            true => room.size_mm[self.axis] - at,
        }
    }

    fn name(self) -> &'static str {
        match (self.axis, self.far) {
            (0, false) => "the wall at x = 0",
            (0, true) => "the far wall across x",
            (_, false) => "the wall at y = 0",
            (_, true) => "the far wall across y",
        }
    }
}

const WALLS: [Wall; 4] = [
    Wall {
        axis: 0,
        far: false,
    },
    Wall { axis: 0, far: true },
    Wall {
        axis: 1,
        far: false,
    },
    Wall { axis: 1, far: true },
];

/// The wall nearest the box.
fn nearest_wall(room: &Room, p: &Plan) -> Wall {
    WALLS
        .into_iter()
        .min_by(|a, b| a.gap(room, p).total_cmp(&b.gap(room, p)))
        .unwrap_or(WALLS[0])
}

/// A rule's answer: `ok`, what was measured, what it allows.
fn rule(section: &str, rule: &str, ok: bool, measured: String, limit: String) -> RuleCheck {
    RuleCheck {
        section: section.into(),
        rule: rule.into(),
        ok,
        measured,
        limit,
        shape: None,
    }
}

fn within((low, high): (f64, f64), value: f64) -> bool {
    value >= low - ROUNDING_MM && value <= high + ROUNDING_MM
}

/// The box named `name` in the room (the checker made sure it is one).
fn named<'r>(room: &'r Room, name: &Option<String>) -> Option<&'r BoxObstacle> {
    let name = name.as_deref()?;
    room.boxes.iter().find(|b| b.name == name)
}

/// Every fixture rule that applies to the fixtures named, in the order of
/// the sections.
pub fn check(room: &Room, fixtures: &Fixtures) -> Vec<RuleCheck> {
    let mut rules = Vec::new();
    if let Some(mirror) = named(room, &fixtures.mirror) {
        rules.push(mirror_rule(room, mirror, named(room, &fixtures.lavatory)));
    }
    if let Some(wc) = named(room, &fixtures.water_closet) {
        rules.extend(water_closet(room, wc, fixtures));
    }
    if let Some(lavatory) = named(room, &fixtures.lavatory) {
        let top = plan(lavatory).top;
        rules.push(rule(
            "606.3",
            &format!("lavatory height, `{}`", lavatory.name),
            top <= ada::LAVATORY_HIGH + ROUNDING_MM,
            format!("its rim at {top:.0} mm"),
            format!("at most {:.0} mm", ada::LAVATORY_HIGH),
        ));
    }
    for bar in [&fixtures.side_grab_bar, &fixtures.rear_grab_bar] {
        if let Some(bar) = named(room, bar) {
            rules.extend(grab_bar(room, bar));
        }
    }
    if let Some(counter) = named(room, &fixtures.service_counter) {
        rules.push(service_counter(room, counter));
    }
    rules
}

/// 603.3: a mirror's bottom edge (the box's underside), over a lavatory
/// (their spans along the mirror's wall overlap) or not.
fn mirror_rule(room: &Room, mirror: &BoxObstacle, lavatory: Option<&BoxObstacle>) -> RuleCheck {
    let m = plan(mirror);
    let wall = nearest_wall(room, &m);
    let along = 1 - wall.axis;
    let over = lavatory.is_some_and(|l| {
        let l = plan(l);
        nearest_wall(room, &l) == wall
            && l.min[along] < m.max[along]
            && m.min[along] < l.max[along]
            && l.top <= m.bottom
    });
    let (high, where_) = match over {
        true => (ada::MIRROR_OVER_LAVATORY, "over the lavatory"),
        false => (ada::MIRROR_ELSEWHERE, "not over a lavatory"),
    };
    rule(
        "603.3",
        &format!("mirror's bottom edge, `{}`", mirror.name),
        m.bottom <= high + ROUNDING_MM,
        format!("{:.0} mm above the floor, {where_}", m.bottom),
        format!("at most {high:.0} mm"),
    )
}

/// The water closet's walls: the rear (nearest) and the side (the nearer
/// of the two across it).
fn wc_walls(room: &Room, p: &Plan) -> (Wall, Wall) {
    let rear = nearest_wall(room, p);
    let across = 1 - rear.axis;
    let side = [false, true]
        .map(|far| Wall { axis: across, far })
        .into_iter()
        .min_by(|a, b| a.gap(room, p).total_cmp(&b.gap(room, p)))
        .unwrap_or(Wall {
            axis: across,
            far: false,
        });
    (rear, side)
}

/// 604.2 the centreline from the side wall, 604.3.1 the clearance and
/// 604.4 the seat height; 604.5 the grab bars' places where named.
fn water_closet(room: &Room, wc: &BoxObstacle, fixtures: &Fixtures) -> Vec<RuleCheck> {
    let p = plan(wc);
    let whole = named(room, &fixtures.water_closet_tank).map_or(p, |t| union(p, plan(t)));
    let (rear, side) = wc_walls(room, &whole);
    let centre = 0.5 * (p.min[side.axis] + p.max[side.axis]);
    let from_side = side.from(room, centre);
    let mut rules = vec![
        rule(
            "604.2",
            &format!(
                "water closet's centreline from the side wall, `{}`",
                wc.name
            ),
            within(ada::CENTRE_FROM_SIDE, from_side),
            format!("{from_side:.0} mm from {}", side.name()),
            format!(
                "{:.0} to {:.0} mm",
                ada::CENTRE_FROM_SIDE.0,
                ada::CENTRE_FROM_SIDE.1
            ),
        ),
        clearance(room, wc, (rear, side), fixtures),
        rule(
            "604.4",
            &format!("water closet's seat height, `{}`", wc.name),
            within(ada::SEAT, p.top),
            format!("its top at {:.0} mm", p.top),
            format!("{:.0} to {:.0} mm", ada::SEAT.0, ada::SEAT.1),
        ),
    ];
    if let Some(bar) = named(room, &fixtures.side_grab_bar) {
        rules.push(side_bar_place(room, bar, rear, side));
    }
    if let Some(bar) = named(room, &fixtures.rear_grab_bar) {
        rules.push(rear_bar_place(room, bar, (rear, side), from_side));
    }
    rules
}

/// 604.3.1: 1525 mm from the side wall by 1420 mm from the rear wall,
/// within the room and clear of every box below the headroom but the
/// water closet and its grab bars (604.3.2 lets those overlap).
fn clearance(room: &Room, wc: &BoxObstacle, (rear, side): (Wall, Wall), f: &Fixtures) -> RuleCheck {
    let whole = Plan {
        min: [0.0; 2],
        max: [room.size_mm.x, room.size_mm.y],
        bottom: 0.0,
        top: ada::HEADROOM,
    };
    let area = whole.strip(side.axis, side.far, ada::CLEARANCE_WIDE).strip(
        rear.axis,
        rear.far,
        ada::CLEARANCE_DEEP,
    );
    let (lo, hi) = (area.min, area.max);
    let allowed = [
        Some(&wc.name),
        f.water_closet_tank.as_ref(),
        f.side_grab_bar.as_ref(),
        f.rear_grab_bar.as_ref(),
    ];
    let inside = (0..2).all(|a| lo[a] >= -ROUNDING_MM && hi[a] <= room.size_mm[a] + ROUNDING_MM);
    let mut standing: Vec<&BoxObstacle> = room
        .boxes
        .iter()
        .filter(|b| !allowed.contains(&Some(&b.name)) && !accessory(room, b))
        .filter(|b| plan(b).bottom < ada::HEADROOM && overlap(&plan(b), &area))
        .collect();
    standing.sort_unstable_by(|a, b| a.name.cmp(&b.name));
    let names: Vec<&str> = standing.iter().map(|b| b.name.as_str()).collect();
    let measured = match (inside, names.len()) {
        (false, _) => format!(
            "the room is {:.0} mm from the side wall by {:.0} mm from the rear wall",
            room.size_mm[side.axis], room.size_mm[rear.axis]
        ),
        (true, 0) => "clear (wall-mounted accessories allowed, 604.3.2)".to_string(),
        (true, 1) => format!("`{}` stands in it", names[0]),
        (true, _) => format!("`{}` stand in it", names.join("`, `")),
    };
    // A bar-like box not named as one: say how to name it.
    let hint = match standing.iter().any(|b| bar_like(b)) {
        true => " (a grab bar is named by `side_grab_bar` or `rear_grab_bar`)",
        false => "",
    };
    let measured = format!("{measured}{hint}");
    RuleCheck {
        shape: Some(FloorShape::Polygon {
            points_mm: vec![
                [mm(lo[0]), mm(lo[1])],
                [mm(hi[0]), mm(lo[1])],
                [mm(hi[0]), mm(hi[1])],
                [mm(lo[0]), mm(hi[1])],
            ],
        }),
        ..rule(
            "604.3.1",
            &format!("water closet's clearance, `{}`", wc.name),
            inside && standing.is_empty(),
            measured,
            format!(
                "{:.0} mm from the side wall by {:.0} mm from the rear wall, nothing in it but the water closet and its grab bars",
                ada::CLEARANCE_WIDE,
                ada::CLEARANCE_DEEP
            ),
        )
    }
}

/// 604.3.2: a box on a wall, off the floor and shallow (a dispenser, a
/// coat hook, a shelf), which the clearance may overlap.
fn accessory(room: &Room, b: &BoxObstacle) -> bool {
    let p = plan(b);
    against_wall(room, &p).is_some_and(|wall| {
        p.bottom >= ada::ACCESSORY_OFF_FLOOR
            && p.max[wall.axis] - p.min[wall.axis] <= ada::ACCESSORY_DEEP
    })
}

/// The wall the outline stands against (within [`ada::ON_WALL`]), if any.
fn against_wall(room: &Room, p: &Plan) -> Option<Wall> {
    let wall = nearest_wall(room, p);
    (wall.gap(room, p) <= ada::ON_WALL).then_some(wall)
}

/// Whether a box is shaped like a grab bar: long, and at most 51 mm
/// across both ways.
fn bar_like(b: &BoxObstacle) -> bool {
    let [_, across, long] = sizes(b);
    across <= ada::ROUND.1 + ROUNDING_MM && long >= 300.0
}

/// A box's three sizes, smallest first (a bar's cross section, then its
/// length).
fn sizes(b: &BoxObstacle) -> [f64; 3] {
    let mut sizes = [b.size_mm.x, b.size_mm.y, b.size_mm.z];
    sizes.sort_by(f64::total_cmp);
    sizes
}

/// 604.5.1: the side wall's bar, at least 1065 mm long, from at most
/// 305 mm from the rear wall to at least 1370 mm from it, on the side wall.
fn side_bar_place(room: &Room, bar: &BoxObstacle, rear: Wall, side: Wall) -> RuleCheck {
    let p = plan(bar);
    let on_side = nearest_wall(room, &p) == side;
    let turned = off_square_deg(bar);
    let (near, far) = rear.span(room, &p);
    let long = far - near;
    let ok = on_side
        && turned <= SQUARE_DEG
        && long >= ada::SIDE_BAR_LONG - ROUNDING_MM
        && near <= ada::SIDE_BAR_FROM_REAR + ROUNDING_MM
        && far >= ada::SIDE_BAR_REACHES - ROUNDING_MM;
    let measured = match (on_side, turned <= SQUARE_DEG) {
        (true, true) => {
            format!("{long:.0} mm long, from {near:.0} to {far:.0} mm from the rear wall")
        }
        (true, false) => format!("turned {turned:.0} deg off the side wall"),
        (false, _) => format!("on {}, not the side wall", nearest_wall(room, &p).name()),
    };
    rule(
        "604.5.1",
        &format!("side wall grab bar, `{}`", bar.name),
        ok,
        measured,
        format!(
            "on the side wall, at least {:.0} mm long, from at most {:.0} to at least {:.0} mm from the rear wall",
            ada::SIDE_BAR_LONG,
            ada::SIDE_BAR_FROM_REAR,
            ada::SIDE_BAR_REACHES
        ),
    )
}

/// 604.5.2: the rear wall's bar, at least 915 mm long, reaching 305 mm
/// from the water closet's centreline towards the side wall and 610 mm
/// towards the open side.
fn rear_bar_place(
    room: &Room,
    bar: &BoxObstacle,
    (rear, side): (Wall, Wall),
    centre_from_side: f64,
) -> RuleCheck {
    let p = plan(bar);
    let wall = nearest_wall(room, &p);
    let turned = off_square_deg(bar);
    let (near, far) = side.span(room, &p);
    let wall_side = centre_from_side - near;
    let open_side = far - centre_from_side;
    let long = far - near;
    let ok = wall == rear
        && turned <= SQUARE_DEG
        && long >= ada::REAR_BAR_LONG - ROUNDING_MM
        && wall_side >= ada::REAR_BAR_WALL_SIDE - ROUNDING_MM
        && open_side >= ada::REAR_BAR_OPEN_SIDE - ROUNDING_MM;
    let measured = match (wall == rear, turned <= SQUARE_DEG) {
        (false, _) => format!("on {}, not the rear wall", wall.name()),
        (true, false) => format!("turned {turned:.0} deg off the rear wall"),
        (true, true) => format!(
            "{long:.0} mm long, {wall_side:.0} mm to the side wall's side of the centreline and {open_side:.0} mm to the open side"
        ),
    };
    rule(
        "604.5.2",
        &format!("rear wall grab bar, `{}`", bar.name),
        ok,
        measured,
        format!(
            "on the rear wall, at least {:.0} mm long, at least {:.0} mm to the wall's side and {:.0} mm to the open side",
            ada::REAR_BAR_LONG,
            ada::REAR_BAR_WALL_SIDE,
            ada::REAR_BAR_OPEN_SIDE
        ),
    )
}

/// 609.2 the bar's cross section (its two smaller sizes), 609.3 its
/// space from its wall, 609.4 the height of its top.
fn grab_bar(room: &Room, bar: &BoxObstacle) -> Vec<RuleCheck> {
    let p = plan(bar);
    let wall = nearest_wall(room, &p);
    let [a, b, _] = sizes(bar);
    let round = (a - b).abs() <= ROUNDING_MM && within(ada::ROUND, a) && within(ada::ROUND, b);
    let perimeter = 2.0 * (a + b);
    let shaped = within(ada::PERIMETER, perimeter) && b <= ada::ROUND.1 + ROUNDING_MM;
    let gap = wall.gap(room, &p);
    let turned = off_square_deg(bar);
    let spaced = turned <= SQUARE_DEG && (gap - ada::FROM_WALL).abs() <= ROUNDING_MM;
    let space = match turned <= SQUARE_DEG {
        true => format!("{gap:.0} mm from {}", wall.name()),
        false => format!(
            "turned {turned:.0} deg off {}: its space from it varies",
            wall.name()
        ),
    };
    vec![
        rule(
            "609.2",
            &format!("grab bar's cross section, `{}`", bar.name),
            round || shaped,
            format!("{a:.0} by {b:.0} mm, its perimeter {perimeter:.0} mm"),
            format!(
                "{:.0} to {:.0} mm across (round), or a perimeter of {:.0} to {:.0} mm and at most {:.0} mm across",
                ada::ROUND.0,
                ada::ROUND.1,
                ada::PERIMETER.0,
                ada::PERIMETER.1,
                ada::ROUND.1
            ),
        ),
        rule(
            "609.3",
            &format!("grab bar's space from the wall, `{}`", bar.name),
            spaced,
            space,
            format!("{:.0} mm (within {ROUNDING_MM:.0} mm)", ada::FROM_WALL),
        ),
        rule(
            "609.4",
            &format!("grab bar's height, `{}`", bar.name),
            within(ada::BAR_HEIGHT, p.top),
            format!("its top at {:.0} mm", p.top),
            format!("{:.0} to {:.0} mm", ada::BAR_HEIGHT.0, ada::BAR_HEIGHT.1),
        ),
    ]
}

/// Whether the strip under the counter along its edge across `across`
/// (`far`: the one away from the origin), as deep as toe clearance must be
/// (306.2.3: 430 mm, or the counter's depth), holds no box below 685 mm.
fn knee_strip_free(
    room: &Room,
    counter: &BoxObstacle,
    p: &Plan,
    (across, far): (usize, bool),
) -> bool {
    let deep = ada::TOE_DEEP.min(p.max[across] - p.min[across]);
    let strip = p.strip(across, far, deep);
    !room.boxes.iter().any(|b| {
        let q = plan(b);
        b.name != counter.name && q.bottom < ada::KNEE_HIGH && overlap(&q, &strip)
    })
}

/// 904.4: the counter's portion (the named box) at most 915 mm high and
/// either 915 mm long (a parallel approach, 904.4.1) or 760 mm long with
/// knee clearance under it (a forward approach, 904.4.2: its underside at
/// 685 mm or higher, and no box below that within 430 mm of one of its
/// long edges).
fn service_counter(room: &Room, counter: &BoxObstacle) -> RuleCheck {
    let p = plan(counter);
    // Its front: along its wall where it stands against one (the edge
    // away from it), else its longer side (either edge).
    let (across, fronts) = match against_wall(room, &p) {
        Some(wall) => (wall.axis, vec![!wall.far]),
        None => (
            usize::from(p.max[0] - p.min[0] > p.max[1] - p.min[1]),
            vec![false, true],
        ),
    };
    let long = p.max[1 - across] - p.min[1 - across];
    let low = p.top <= ada::COUNTER_HIGH + ROUNDING_MM;
    let knees_free = p.bottom >= ada::KNEE_HIGH - ROUNDING_MM
        && fronts
            .into_iter()
            .any(|far| knee_strip_free(room, counter, &p, (across, far)));
    let parallel = low && long >= ada::COUNTER_LONG_PARALLEL - ROUNDING_MM;
    let forward = low && knees_free && long >= ada::COUNTER_LONG_FORWARD - ROUNDING_MM;
    let (section, measured) = match (parallel, forward) {
        (true, _) => (
            "904.4.1",
            format!("{long:.0} mm long, its top at {:.0} mm", p.top),
        ),
        (false, true) => (
            "904.4.2",
            format!(
                "{long:.0} mm long with knee space under it, its top at {:.0} mm",
                p.top
            ),
        ),
        (false, false) => (
            "904.4",
            format!(
                "{long:.0} mm long, its top at {:.0} mm, {} knee space under it",
                p.top,
                if knees_free { "with" } else { "no" }
            ),
        ),
    };
    rule(
        section,
        &format!("sales and service counter, `{}`", counter.name),
        parallel || forward,
        measured,
        format!(
            "at most {:.0} mm high and {:.0} mm long (parallel approach), or {:.0} mm long with knee space (forward approach)",
            ada::COUNTER_HIGH,
            ada::COUNTER_LONG_PARALLEL,
            ada::COUNTER_LONG_FORWARD
        ),
    )
}
