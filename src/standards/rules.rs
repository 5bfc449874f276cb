//! The rules of a building standard for people on wheels, checked on a
//! room with the figures of a [`Figures`] table (`figures.rs`): turning
//! space, each door's clear width, and for each element (target) a forward
//! or a side approach that meets the reach range, a clear floor space,
//! knee clearance under the obstruction a forward reach goes over, and a
//! route from a door. A standard with these rules is a table; one whose
//! rules differ adds only those.
//!
//! Approaches are tried along the room's axes (a person facing an element
//! from +x, -x, +y or -y, or beside it), each held to every rule; the
//! first that meets them all is reported, else the first that fails
//! fewest. Boxes only: a mesh is not measured, and a reach it may stand in
//! the way of fails saying so (the report notes it); it does take floor.

use geo::{Coord, LineString, Polygon};
use nalgebra::{Point3, Vector2};

use super::clearance::Under;
use super::elements::{approached, crossing_within, wall_distance, Approached};
use super::figures::Figures;
use super::fixtures::{self, Fixtures};
use crate::allowance::Allowance;
use crate::bases::Approach;
use crate::floor::{
    disc_centre, door_clear_width, knee_limited, route_width, t_space, FreeFloor, RouteFloor,
};
use crate::report::{mm, ElementCheck, FloorShape, RuleCheck, StandardReport};
use crate::scene::{BoxObstacle, Door, Room, Target};

/// The steps by which a clear floor space is slid along an element.
const SLIDE_STEP: f64 = 10.0;
/// Less than this counts as nothing to reach over.
const NONE_MM: f64 = 1.0;
/// Figures within this of a rule's meet it (rounding in the geometry).
const EXACT_MM: f64 = 0.01;
/// The longest route measured: wider counts as this wide.
const ROUTE_MOST: f64 = 3000.0;
/// How far inside the room a door's opening is looked at for what
/// narrows it.
const DOOR_REVEAL: f64 = 20.0;

/// What the fixtures' rules leave out, said where fixtures are named.
const FIXTURES_NOTE: &str = "fixtures: checked are 603.3, 604.2, 604.3.1, 604.4, 604.5.1, 604.5.2, 606.3, 609.2-609.4 and 904.4 as named; not checked are 603.2 (the room's turning space is 304), 603.4 coat hooks and shelves, 604.6 flush controls and 604.7 dispensers (targets, where declared, are checked as elements), 604.5.2's exceptions, 604.8 stalls (a partition is not a wall here), 606.2 (the lavatory's targets are elements, with their knee clearance), 606.5 exposed pipes, 609.3's clear space above and below a bar, 609.5-609.8 (surfaces, fittings, strength), 904.3 check-out aisles and 904.5 food service lines";

/// Standard `f`'s rules on `room`, every element usable by `approach`;
/// the floors worked out are charged to `meter`.
pub fn check(
    f: &Figures,
    approach: Approach,
    room: &Room,
    allowance: &dyn Allowance,
    fixtures: &Fixtures,
) -> StandardReport {
    // Floor under an element counts only so deep (306).
    let knees = knee_limited(room, f.knee_high_mm, f.knee_deepest_mm);
    let floor = FreeFloor::new(&knees, f.knee_high_mm, allowance);
    // A route's floor, to the rounded width (as `route` measures).
    let routes = RouteFloor::new(room, f.route_mm - 0.5, f.headroom_mm, allowance);
    let mut notes = Vec::new();
    if room.doors.is_empty() {
        notes.push(format!(
            "the room has no `door`: routes ({}) are not checked",
            f.sections.route
        ));
    }
    if *fixtures != Fixtures::default() {
        notes.push(FIXTURES_NOTE.to_string());
    }
    if !room.meshes.is_empty() {
        notes.push(
            "meshes are not measured as obstructions or knee space (boxes are): a reach a mesh may stand in the way of fails as not measured".to_string(),
        );
    }
    let report = StandardReport {
        standard: f.name.into(),
        room: room.name.clone(),
        ok: true,
        checks: 0,
        failed: 0,
        notes,
        room_rules: std::iter::once(turning_space(f, &knees, routes.as_ref(), allowance))
            .chain(room.doors.iter().map(|d| door_width(f, room, d)))
            .chain(fixtures::check(room, fixtures))
            .collect(),
        elements: {
            let measure = Measure {
                room,
                floor: &floor,
                routes: routes.as_ref(),
                meshes: mesh_bounds(room),
                allowance,
                figures: f,
            };
            room.targets
                .iter()
                .map(|t| element(&measure, t, approach))
                .collect()
        },
    };
    report.counted()
}

/// 304: a 1525 mm circle, or else a T, on floor a route from a door gets
/// to (where the room has doors).
fn turning_space(
    f: &Figures,
    room: &Room,
    routes: Option<&RouteFloor>,
    allowance: &dyn Allowance,
) -> RuleCheck {
    let limit = format!("a {turning_mm:.0} mm circle, or a T in a {turning_mm:.0} mm square with {turning_arm_mm:.0} mm arms", turning_mm = f.turning_mm, turning_arm_mm = f.turning_arm_mm);
    // Exactly the rule's figures hold.
    let radius = f.turning_mm / 2.0 - EXACT_MM;
    let (square, arm) = (
        f.turning_mm - 2.0 * EXACT_MM,
        f.turning_arm_mm - 2.0 * EXACT_MM,
    );
    if let Some(c) = disc_centre(room, radius, f.knee_high_mm, routes, allowance) {
        return RuleCheck {
            section: f.sections.turning_circle.into(),
            rule: "turning space".into(),
            ok: true,
            measured: format!(
                "a {turning_mm:.0} mm circle fits about ({:.0}, {:.0})",
                c.x(),
                c.y(),
                turning_mm = f.turning_mm
            ),
            limit,
            shape: Some(FloorShape::Circle {
                centre_mm: [mm(c.x()), mm(c.y())],
                radius_mm: f.turning_mm / 2.0,
            }),
        };
    }
    if let Some((c, heading)) = t_space(room, square, arm, f.knee_high_mm, routes, allowance) {
        return RuleCheck {
            section: f.sections.turning_t.into(),
            rule: "turning space".into(),
            ok: true,
            measured: format!(
                "no circle fits; a T fits about ({:.0}, {:.0}), its stem towards {:.0} deg",
                c.x(),
                c.y(),
                heading.to_degrees()
            ),
            limit,
            shape: Some(FloorShape::Polygon {
                points_mm: t_outline(f, [c.x(), c.y()], heading),
            }),
        };
    }
    let cut_off = routes.is_some()
        && (disc_centre(room, radius, f.knee_high_mm, None, allowance).is_some()
            || t_space(room, square, arm, f.knee_high_mm, None, allowance).is_some());
    RuleCheck {
        section: f.sections.turning.into(),
        rule: "turning space".into(),
        ok: false,
        measured: if cut_off {
            format!(
                "one fits only where no {route_mm:.0} mm route from a door gets",
                route_mm = f.route_mm
            )
        } else {
            "neither a circle nor a T fits anywhere".into()
        },
        limit,
        shape: None,
    }
}

/// 404.2.3: a door's clear width: its opening, less what stands in it
/// just inside.
fn door_width(f: &Figures, room: &Room, door: &Door) -> RuleCheck {
    let clear = door_clear_width(room, door, DOOR_REVEAL, f.headroom_mm);
    let narrowed = clear < door.width_mm - EXACT_MM;
    RuleCheck {
        section: f.sections.door.into(),
        rule: format!("door clear width, `{}`", door.name),
        ok: clear >= f.door_mm - EXACT_MM,
        measured: if narrowed {
            format!("{clear:.0} mm of its {:.0} mm opening clear", door.width_mm)
        } else {
            format!("{clear:.0} mm")
        },
        limit: format!("at least {door_mm:.0} mm", door_mm = f.door_mm),
        shape: None,
    }
}

/// The outline of the T turning space about `centre`, its stem along
/// `heading`.
fn t_outline(f: &Figures, centre: [f64; 2], heading: f64) -> Vec<[f64; 2]> {
    let (h, a) = (f.turning_mm / 2.0, f.turning_arm_mm / 2.0);
    let bar = -h + f.turning_arm_mm;
    let corners = [
        (-h, -h),
        (bar, -h),
        (bar, -a),
        (h, -a),
        (h, a),
        (bar, a),
        (bar, h),
        (-h, h),
    ];
    let (s, c) = heading.sin_cos();
    corners
        .iter()
        .map(|&(x, y)| [mm(centre[0] + c * x - s * y), mm(centre[1] + s * x + c * y)])
        .collect()
}

/// One way of using an element: approached from a side, forward or
/// beside it, with its rules.
struct Usage {
    forward: bool,
    facing_deg: f64,
    rules: Vec<RuleCheck>,
    /// Its clear floor space, for the route to it.
    space: Polygon<f64>,
}

impl Usage {
    fn failed(&self) -> usize {
        self.rules.iter().filter(|r| !r.ok).count()
    }
}

/// What an element's rules are measured on: the room, its free floor
/// (knee clearance only so deep), the floor a route from a door gets to,
/// and each mesh's bounds (not measured: a reach one may stand in the way
/// of fails).
struct Measure<'r> {
    room: &'r Room,
    floor: &'r FreeFloor<'r>,
    routes: Option<&'r RouteFloor<'r>>,
    meshes: Vec<BoxObstacle>,
    /// What the floors worked out are charged to.
    allowance: &'r dyn Allowance,
    /// The standard's figures.
    figures: &'r Figures,
}

/// Each mesh's bounding box, named as the mesh.
fn mesh_bounds(room: &Room) -> Vec<BoxObstacle> {
    (room.meshes.iter())
        .filter_map(|m| {
            let [lo, hi] = m.vertex_bounds()?;
            Some(BoxObstacle {
                name: m.name.clone(),
                corner_mm: lo,
                size_mm: hi - lo,
                yaw_rad: 0.0,
            })
        })
        .collect()
}

/// The element `t`'s rules, by the approach that meets them (or fails
/// fewest, the first tried of those).
fn element(m: &Measure<'_>, t: &Target, approach: Approach) -> ElementCheck {
    let at = t.position_mm;
    let mut usages: Vec<Usage> = Vec::new();
    let sides = approach_sides(m.room, &at);
    let ways: Vec<Approached> = sides.iter().map(|&t| approached(m.room, &at, t)).collect();
    // A way whose obstruction runs to the wall leaves the person nowhere
    // to stand (outside the room), unless every way does.
    let inside =
        |a: &Approached| wall_distance(m.room, at.xy().coords, a.toward) > a.depth_mm + 1.0;
    let any_inside = ways.iter().any(inside);
    for a in ways.iter().filter(|a| !any_inside || inside(a)) {
        if approach != Approach::Side {
            usages.push(forward(m, &at, a));
        }
        if approach != Approach::Forward {
            usages.push(side(m, &at, a));
        }
    }
    if let Some(routes) = m.routes {
        for usage in &mut usages {
            usage
                .rules
                .push(route_reaches(m.figures, routes, &usage.space));
        }
    }
    let chosen = (0..usages.len())
        .min_by_key(|&k| usages[k].failed())
        .unwrap_or(0);
    let mut usage = usages.swap_remove(chosen);
    // The chosen approach's route, measured.
    if m.routes.is_some() {
        usage.rules.pop();
        usage
            .rules
            .push(route(m.figures, m.room, &usage.space, m.allowance));
    }
    ElementCheck {
        name: t.name.clone(),
        at_mm: [at.x, at.y, at.z],
        ok: usage.failed() == 0,
        approach: if usage.forward { "forward" } else { "side" }.into(),
        facing_deg: usage.facing_deg,
        rules: usage.rules,
        people: Vec::new(),
    }
}

/// The directions an element is approached from (from the element
/// towards the person, on the floor): from the room for an element on a
/// wall, or on the side of a box that stands at its height (a partition,
/// a cabinet's front), within [`ON_WALL_MM`] (in a corner, from either),
/// else from each of the four sides. A forward approach along a wall
/// would face past a switch on it, and a side approach along it would
/// stand facing the wall beside the switch: neither is how the standard
/// approaches it.
fn approach_sides(room: &Room, at: &Point3<f64>) -> Vec<Vector2<f64>> {
    let sides = [Vector2::x(), -Vector2::x(), Vector2::y(), -Vector2::y()];
    let walls = [at.x, room.size_mm.x - at.x, at.y, room.size_mm.y - at.y];
    let on: Vec<Vector2<f64>> = (sides.iter().zip(walls))
        .filter(|&(&out, wall_mm)| {
            wall_mm <= ON_WALL_MM || room.boxes.iter().any(|b| on_box_side(b, at, out))
        })
        .map(|(&out, _)| out)
        .collect();
    if on.is_empty() {
        sides.to_vec()
    } else {
        on
    }
}

/// Whether `at` is on the side of box `b` that faces `out` (a unit vector
/// along the room's axes): within [`ON_WALL_MM`] in front of that side,
/// between its ends and between the box's bottom and top. A box turned off
/// the room's axes has no such side.
fn on_box_side(b: &crate::scene::BoxObstacle, at: &Point3<f64>, out: Vector2<f64>) -> bool {
    if b.yaw_rad != 0.0 {
        return false;
    }
    let (lo, hi) = (b.corner_mm, b.corner_mm + b.size_mm);
    let within = |v: f64, a: f64, c: f64| (a..=c).contains(&v);
    let height = within(at.z, lo.z, hi.z);
    let in_front = |v: f64, face: f64, sign: f64| within(sign * (v - face), 0.0, ON_WALL_MM);
    height
        && if out.x != 0.0 {
            let face = if out.x > 0.0 { hi.x } else { lo.x };
            in_front(at.x, face, out.x) && within(at.y, lo.y, hi.y)
        } else {
            let face = if out.y > 0.0 { hi.y } else { lo.y };
            in_front(at.y, face, out.y) && within(at.x, lo.x, hi.x)
        }
}

/// An element at most this far from a wall is on it: a switch, a socket,
/// a dispenser's button.
const ON_WALL_MM: f64 = 50.0;

/// 403.5.1 for an approach not (yet) chosen: whether a 915 mm route gets
/// to its clear floor space.
fn route_reaches(f: &Figures, routes: &RouteFloor, space: &Polygon<f64>) -> RuleCheck {
    let ok = routes.reaches(space);
    RuleCheck {
        section: f.sections.route.into(),
        rule: "route width".into(),
        ok,
        measured: if ok {
            format!("a {route_mm:.0} mm route gets there", route_mm = f.route_mm)
        } else {
            format!(
                "no {route_mm:.0} mm route from a door",
                route_mm = f.route_mm
            )
        },
        limit: format!("at least {route_mm:.0} mm", route_mm = f.route_mm),
        shape: None,
    }
}

/// The reach rule when something stands where the hand must pass: a box
/// at the element's height, or a mesh (not measured) anywhere between the
/// element and the person.
fn in_the_way(
    m: &Measure<'_>,
    at: &Point3<f64>,
    a: &Approached,
    person_mm: f64,
    section: &str,
    rule: &str,
) -> Option<RuleCheck> {
    let measured = if let Some(i) = a.blocked_by(m.room, person_mm, m.figures.knee_high_mm) {
        format!("through `{}` at the element's height", m.room.boxes[i].name)
    } else {
        let mesh = m.meshes.iter().find(|b| {
            b.corner_mm.z < at.z + NONE_MM
                && crossing_within(b, at, a.toward, a.depth_mm + person_mm)
        })?;
        format!(
            "not measured: mesh `{}` may stand in the way (meshes are not measured)",
            mesh.name
        )
    };
    Some(RuleCheck {
        section: section.into(),
        rule: rule.into(),
        ok: false,
        measured,
        limit: "nothing in the way at its height".into(),
        shape: None,
    })
}

/// `z` in words.
fn high(z: f64) -> String {
    format!("{z:.0} mm high")
}

/// The direction a person faces, degrees in [0, 360).
fn facing(direction: Vector2<f64>) -> f64 {
    direction
        .y
        .atan2(direction.x)
        .to_degrees()
        .rem_euclid(360.0)
        .round()
        // Not -0.
        + 0.0
}

/// A forward approach from `a.toward`: facing the element.
fn forward(m: &Measure<'_>, at: &Point3<f64>, a: &Approached) -> Usage {
    let f = m.figures;
    let z = at.z;
    let mut rules = Vec::new();
    // Where the knee rule holds: how far back under the obstruction the
    // floor is open.
    let mut open_mm = None;
    let blocked = in_the_way(
        m,
        at,
        a,
        f.floor_length_mm,
        f.sections.forward_reach,
        "forward reach",
    );
    let reach = if let Some(blocked) = blocked {
        blocked
    } else if a.depth_mm < NONE_MM {
        RuleCheck {
            section: f.sections.forward_unobstructed.into(),
            rule: "forward reach, unobstructed".into(),
            ok: (f.low_mm..=f.high_mm).contains(&z),
            measured: high(z),
            limit: format!(
                "{low_mm:.0} to {high_mm:.0} mm high",
                low_mm = f.low_mm,
                high_mm = f.high_mm
            ),
            shape: None,
        }
    } else {
        let top = if a.depth_mm <= f.forward_deep_mm {
            f.high_mm
        } else {
            f.forward_deep_high_mm
        };
        let under = Under::of(f, m.room, at, a);
        let knee = under.knee(f);
        open_mm = knee.ok.then(|| under.open_depth(f));
        rules.push(knee);
        // Toe space is asked of a space the knees have: where the
        // obstruction comes down in front, the knee rule has said so.
        if under.has_knee_space(f) {
            rules.push(under.toe(f, a.depth_mm));
        }
        RuleCheck {
            section: f.sections.forward_over.into(),
            rule: "forward reach over an obstruction".into(),
            ok: a.depth_mm <= f.forward_deepest_mm && (f.low_mm..=top).contains(&z),
            measured: format!("{} over {:.0} mm", high(z), a.depth_mm),
            limit: format!(
                "at most {high_mm:.0} mm high up to {forward_deep_mm:.0} mm deep, {forward_deep_high_mm:.0} mm up to {forward_deepest_mm:.0} mm; at least {low_mm:.0} mm", high_mm = f.high_mm, forward_deep_mm = f.forward_deep_mm, forward_deep_high_mm = f.forward_deep_high_mm, forward_deepest_mm = f.forward_deepest_mm, low_mm = f.low_mm),
            shape: None,
        }
    };
    rules.insert(0, reach);
    // With knee space, the clear floor space reaches under the obstruction
    // up to the first thing that comes down into the knee space (to the
    // element at most); without, it stops at the obstruction's edge.
    let near = match open_mm {
        Some(open) => (a.depth_mm - open).max(0.0) + NONE_MM,
        None => a.depth_mm + NONE_MM,
    };
    let space = clear_floor(
        f,
        m.floor,
        at,
        a.toward,
        near,
        f.floor_width_mm,
        f.floor_length_mm,
        "forward",
    );
    Usage {
        forward: true,
        facing_deg: facing(-a.toward),
        space: space.1,
        rules: [rules, vec![space.0]].concat(),
    }
}

/// A side (parallel) approach beside the element, from `a.toward`.
fn side(m: &Measure<'_>, at: &Point3<f64>, a: &Approached) -> Usage {
    let f = m.figures;
    let z = at.z;
    let (depth, top) = (a.depth_mm, a.height_mm);
    let blocked = in_the_way(
        m,
        at,
        a,
        f.floor_width_mm,
        f.sections.side_reach,
        "side reach",
    );
    let reach = if let Some(blocked) = blocked {
        blocked
    } else if depth <= f.side_shallow_mm {
        let obstructed = depth >= NONE_MM;
        RuleCheck {
            section: f.sections.side_shallow.into(),
            rule: if obstructed {
                "side reach over a shallow obstruction"
            } else {
                "side reach, unobstructed"
            }
            .into(),
            ok: (f.low_mm..=f.high_mm).contains(&z) && (!obstructed || top <= f.side_obstruction_high_mm),
            measured: if obstructed {
                format!("{} over {depth:.0} mm, {top:.0} mm high", high(z))
            } else {
                high(z)
            },
            limit: format!(
                "{low_mm:.0} to {high_mm:.0} mm high; over at most {side_shallow_mm:.0} mm, {side_obstruction_high_mm:.0} mm high", low_mm = f.low_mm, high_mm = f.high_mm, side_shallow_mm = f.side_shallow_mm, side_obstruction_high_mm = f.side_obstruction_high_mm),
            shape: None,
        }
    } else {
        RuleCheck {
            section: f.sections.side_deep.into(),
            rule: "side reach over an obstruction".into(),
            ok: depth <= f.side_deepest_mm
                && top <= f.side_obstruction_high_mm
                && (f.low_mm..=f.side_deep_high_mm).contains(&z),
            measured: format!("{} over {depth:.0} mm, {top:.0} mm high", high(z)),
            limit: format!(
                "at most {side_deep_high_mm:.0} mm high, over at most {side_deepest_mm:.0} mm and {side_obstruction_high_mm:.0} mm high; at least {low_mm:.0} mm", side_deep_high_mm = f.side_deep_high_mm, side_deepest_mm = f.side_deepest_mm, side_obstruction_high_mm = f.side_obstruction_high_mm, low_mm = f.low_mm),
            shape: None,
        }
    };
    let space = clear_floor(
        f,
        m.floor,
        at,
        a.toward,
        depth + NONE_MM,
        f.floor_length_mm,
        f.floor_width_mm,
        "parallel",
    );
    let along = Vector2::new(-a.toward.y, a.toward.x);
    Usage {
        forward: false,
        facing_deg: facing(along),
        space: space.1,
        rules: vec![reach, space.0],
    }
}

/// 305: a clear floor space `across` wide (across `toward`) and `deep`
/// along it, its near edge `near_mm` from the element, slid along the
/// element (which stays within its width) until it is free floor; the
/// rule and the space (the one found, else the one centred on the
/// element).
#[allow(clippy::too_many_arguments)]
fn clear_floor(
    f: &Figures,
    floor: &FreeFloor<'_>,
    at: &Point3<f64>,
    toward: Vector2<f64>,
    near_mm: f64,
    across: f64,
    deep: f64,
    approach: &str,
) -> (RuleCheck, Polygon<f64>) {
    let along = Vector2::new(-toward.y, toward.x);
    // Tested a hundredth of a millimetre in from each side, so that a
    // space exactly as wide as the rule asks holds.
    let (half, inset) = (across / 2.0 - EXACT_MM, EXACT_MM);
    let rect = |slide: f64| {
        let base = at.xy().coords + toward * (near_mm + inset) + along * slide;
        let far = toward * (deep - 2.0 * inset);
        let corners = [
            base - along * half,
            base + along * half,
            base + along * half + far,
            base - along * half + far,
        ];
        Polygon::new(
            LineString::from(
                corners
                    .iter()
                    .map(|c| Coord { x: c.x, y: c.y })
                    .collect::<Vec<_>>(),
            ),
            Vec::new(),
        )
    };
    let steps = (across / 2.0 / SLIDE_STEP).floor() as i64;
    let slides = (0..=steps).flat_map(|k| {
        let s = k as f64 * SLIDE_STEP;
        if k == 0 {
            vec![0.0]
        } else {
            vec![s, -s]
        }
    });
    let found = slides.map(rect).find(|r| floor.holds(r));
    let ok = found.is_some();
    let space = found.unwrap_or_else(|| rect(0.0));
    let points_mm = (space.exterior().points())
        .map(|p| [mm(p.x()), mm(p.y())])
        .collect();
    let rule = RuleCheck {
        section: f.sections.clear_floor.into(),
        rule: format!("clear floor space, {approach}"),
        ok,
        measured: if ok {
            format!("{across:.0} x {deep:.0} mm free")
        } else {
            format!("no free {across:.0} x {deep:.0} mm at the element")
        },
        limit: format!(
            "{floor_width_mm:.0} x {floor_length_mm:.0} mm",
            floor_width_mm = f.floor_width_mm,
            floor_length_mm = f.floor_length_mm
        ),
        shape: Some(FloorShape::Polygon { points_mm }),
    };
    (rule, space)
}

/// 403.5.1: the widest way from a door to `space`.
fn route(f: &Figures, room: &Room, space: &Polygon<f64>, allowance: &dyn Allowance) -> RuleCheck {
    let (width, door) = room
        .doors
        .iter()
        .map(|d| {
            (
                route_width(room, d, space, f.headroom_mm, ROUTE_MOST, allowance),
                d.name.as_str(),
            )
        })
        .fold((0.0, ""), |best, w| if w.0 > best.0 { w } else { best });
    RuleCheck {
        section: f.sections.route.into(),
        rule: "route width".into(),
        ok: width >= f.route_mm,
        measured: if width >= ROUTE_MOST {
            format!("at least {width:.0} mm, from door `{door}`")
        } else if width > 0.0 {
            format!("{width:.0} mm at its narrowest, from door `{door}`")
        } else {
            "no way from a door".into()
        },
        limit: format!("at least {route_mm:.0} mm", route_mm = f.route_mm),
        shape: None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::allowance::Unbounded;
    use crate::scene::MeshObstacle;
    use crate::standards::figures::ADA2010;
    use nalgebra::Vector3;

    /// A cube of `size` mm from `corner`, as a mesh.
    fn cube(corner: [f64; 3], size: f64) -> MeshObstacle {
        let (unit, triangles) = crate::geometry::unit_cube();
        let vertices = unit
            .iter()
            .map(|p| Point3::from(corner) + p.coords * size)
            .collect();
        MeshObstacle::new("crate".into(), vertices, &triangles)
    }

    #[test]
    fn a_mesh_where_the_hand_passes_is_not_measured_and_fails() {
        let mut room = Room {
            name: "r".into(),
            size_mm: Vector3::new(4000.0, 4000.0, 2500.0),
            boxes: Vec::new(),
            meshes: Vec::new(),
            targets: Vec::new(),
            surfaces: Vec::new(),
            doors: Vec::new(),
        };
        let switch = Point3::new(0.0, 2000.0, 1000.0);
        let reach_from_the_room = |room: &Room| {
            let allowance = &Unbounded;
            let floor = FreeFloor::new(room, ADA2010.knee_high_mm, allowance);
            let m = Measure {
                room,
                floor: &floor,
                routes: None,
                meshes: mesh_bounds(room),
                allowance,
                figures: &ADA2010,
            };
            forward(&m, &switch, &approached(room, &switch, Vector2::x())).rules[0].clone()
        };
        assert!(reach_from_the_room(&room).ok);
        // A crate on the floor in front of the switch: the rule fails,
        // saying the mesh is not measured.
        room.meshes.push(cube([400.0, 1700.0, 0.0], 600.0));
        let reach = reach_from_the_room(&room);
        assert!(!reach.ok, "{reach:?}");
        assert!(reach.measured.contains("mesh `crate`"), "{reach:?}");
        // One across the room is not in the way.
        room.meshes[0] = cube([3000.0, 1700.0, 0.0], 600.0);
        assert!(reach_from_the_room(&room).ok);
    }
}
