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
//!   element; side: its long side), 306 knee clearance under the
//!   obstruction where a forward reach goes over one (at least 685 mm
//!   high, 280 mm deep and as deep as the reach), and 403.5.1 a route at
//!   least 915 mm wide from a door to the clear floor space (where the room
//!   has doors).
//!
//! Approaches are tried along the room's axes (a person facing an element
//! from +x, -x, +y or -y, or beside it), each held to every rule; the
//! first that meets them all is reported, else the first that fails
//! fewest. Boxes only: a mesh is not measured, and a reach it may stand in
//! the way of fails saying so (the report notes it); it does take floor.

use geo::{Coord, LineString, Polygon};
use nalgebra::{Point3, Vector2};

use super::elements::{approached, crossing_within, knee_depth, Approached};
use crate::bases::Approach;
use crate::floor::{
    disc_centre, door_clear_width, knee_limited, route_width, t_space, FreeFloor, RouteFloor,
};
use crate::meter::Meter;
use crate::plugin::{
    Options, ParamSpec, Params, Plugin, Settings, SettingsError, Standard, StandardPlugin,
};
use crate::report::{mm, ElementCheck, FloorShape, RuleCheck, StandardReport};
use crate::scene::{BoxObstacle, Door, Room, Target};

/// The plugin `ada2010`.
pub struct Ada2010;

/// The standard's figures, mm.
const HIGH: f64 = 1220.0;
const LOW: f64 = 380.0;
const FORWARD_DEEP: f64 = 510.0;
const FORWARD_DEEPEST: f64 = 635.0;
const FORWARD_DEEP_HIGH: f64 = 1120.0;
const SIDE_SHALLOW: f64 = 255.0;
const SIDE_DEEPEST: f64 = 610.0;
const SIDE_DEEP_HIGH: f64 = 1170.0;
const SIDE_OBSTRUCTION_HIGH: f64 = 865.0;
const FLOOR_WIDTH: f64 = 760.0;
const FLOOR_LENGTH: f64 = 1220.0;
const KNEE_HIGH: f64 = 685.0;
const KNEE_DEEP: f64 = 280.0;
/// Knee and toe clearance deeper than this under an element is not
/// floor space (306.2.2, 306.3.2).
const KNEE_DEEPEST: f64 = 635.0;
const TURNING: f64 = 1525.0;
const TURNING_ARM: f64 = 915.0;
const ROUTE: f64 = 915.0;
const DOOR: f64 = 815.0;
/// A route narrows at anything below this (ADA 307.4's headroom): what
/// protrudes into it takes its width.
const HEADROOM: f64 = 2030.0;
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
        "the 2010 ADA Standards: turning space (304), reach ranges (308), clear floor space (305), knee clearance (306), route widths (403.5.1)"
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
    fn check(&self, room: &Room, meter: &Meter) -> StandardReport {
        // Floor under an element counts only so deep (306).
        let knees = knee_limited(room, KNEE_HIGH, KNEE_DEEPEST);
        let floor = FreeFloor::new(&knees, KNEE_HIGH, meter);
        // A route's floor, to a rounded 915 mm (as `route` measures).
        let routes = RouteFloor::new(room, ROUTE - 0.5, HEADROOM, meter);
        let mut notes = Vec::new();
        if room.doors.is_empty() {
            notes.push("the room has no `door`: routes (403.5.1) are not checked".to_string());
        }
        if !room.meshes.is_empty() {
            notes.push(
                "meshes are not measured as obstructions or knee space (boxes are): a reach a mesh may stand in the way of fails as not measured".to_string(),
            );
        }
        let report = StandardReport {
            standard: "ada2010".into(),
            room: room.name.clone(),
            ok: true,
            checks: 0,
            failed: 0,
            notes,
            room_rules: std::iter::once(turning_space(&knees, routes.as_ref(), meter))
                .chain(room.doors.iter().map(|d| door_width(room, d)))
                .collect(),
            elements: {
                let measure = Measure {
                    room,
                    floor: &floor,
                    routes: routes.as_ref(),
                    meshes: mesh_bounds(room),
                    meter,
                };
                room.targets
                    .iter()
                    .map(|t| element(&measure, t, self.0))
                    .collect()
            },
        };
        report.counted()
    }
}

/// 304: a 1525 mm circle, or else a T, on floor a route from a door gets
/// to (where the room has doors).
fn turning_space(room: &Room, routes: Option<&RouteFloor>, meter: &Meter) -> RuleCheck {
    let limit = format!("a {TURNING:.0} mm circle, or a T in a {TURNING:.0} mm square with {TURNING_ARM:.0} mm arms");
    // Exactly the rule's figures hold.
    let radius = TURNING / 2.0 - EXACT_MM;
    let (square, arm) = (TURNING - 2.0 * EXACT_MM, TURNING_ARM - 2.0 * EXACT_MM);
    if let Some(c) = disc_centre(room, radius, KNEE_HIGH, routes, meter) {
        return RuleCheck {
            section: "304.3.1".into(),
            rule: "turning space".into(),
            ok: true,
            measured: format!(
                "a {TURNING:.0} mm circle fits about ({:.0}, {:.0})",
                c.x(),
                c.y()
            ),
            limit,
            shape: Some(FloorShape::Circle {
                centre_mm: [mm(c.x()), mm(c.y())],
                radius_mm: TURNING / 2.0,
            }),
        };
    }
    if let Some((c, heading)) = t_space(room, square, arm, KNEE_HIGH, routes, meter) {
        return RuleCheck {
            section: "304.3.2".into(),
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
                points_mm: t_outline([c.x(), c.y()], heading),
            }),
        };
    }
    let cut_off = routes.is_some()
        && (disc_centre(room, radius, KNEE_HIGH, None, meter).is_some()
            || t_space(room, square, arm, KNEE_HIGH, None, meter).is_some());
    RuleCheck {
        section: "304.3".into(),
        rule: "turning space".into(),
        ok: false,
        measured: if cut_off {
            format!("one fits only where no {ROUTE:.0} mm route from a door gets")
        } else {
            "neither a circle nor a T fits anywhere".into()
        },
        limit,
        shape: None,
    }
}

/// 404.2.3: a door's clear width: its opening, less what stands in it
/// just inside.
fn door_width(room: &Room, door: &Door) -> RuleCheck {
    let clear = door_clear_width(room, door, DOOR_REVEAL, HEADROOM);
    let narrowed = clear < door.width_mm - EXACT_MM;
    RuleCheck {
        section: "404.2.3".into(),
        rule: format!("door clear width, `{}`", door.name),
        ok: clear >= DOOR - EXACT_MM,
        measured: if narrowed {
            format!("{clear:.0} mm of its {:.0} mm opening clear", door.width_mm)
        } else {
            format!("{clear:.0} mm")
        },
        limit: format!("at least {DOOR:.0} mm"),
        shape: None,
    }
}

/// The outline of the T turning space about `centre`, its stem along
/// `heading`.
fn t_outline(centre: [f64; 2], heading: f64) -> Vec<[f64; 2]> {
    let (h, a) = (TURNING / 2.0, TURNING_ARM / 2.0);
    let bar = -h + TURNING_ARM;
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
    meter: &'r Meter,
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
    let sides = [Vector2::x(), -Vector2::x(), Vector2::y(), -Vector2::y()];
    let mut usages: Vec<Usage> = Vec::new();
    for toward in sides {
        let a = approached(m.room, &at, toward);
        if approach != Approach::Side {
            usages.push(forward(m, &at, &a));
        }
        if approach != Approach::Forward {
            usages.push(side(m, &at, &a));
        }
    }
    if let Some(routes) = m.routes {
        for usage in &mut usages {
            usage.rules.push(route_reaches(routes, &usage.space));
        }
    }
    let chosen = (0..usages.len())
        .min_by_key(|&k| usages[k].failed())
        .unwrap_or(0);
    let mut usage = usages.swap_remove(chosen);
    // The chosen approach's route, measured.
    if m.routes.is_some() {
        usage.rules.pop();
        usage.rules.push(route(m.room, &usage.space, m.meter));
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

/// 403.5.1 for an approach not (yet) chosen: whether a 915 mm route gets
/// to its clear floor space.
fn route_reaches(routes: &RouteFloor, space: &Polygon<f64>) -> RuleCheck {
    let ok = routes.reaches(space);
    RuleCheck {
        section: "403.5.1".into(),
        rule: "route width".into(),
        ok,
        measured: if ok {
            format!("a {ROUTE:.0} mm route gets there")
        } else {
            format!("no {ROUTE:.0} mm route from a door")
        },
        limit: format!("at least {ROUTE:.0} mm"),
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
    let measured = if let Some(i) = a.blocked_by(m.room, person_mm, KNEE_HIGH) {
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
    let z = at.z;
    let mut rules = Vec::new();
    let mut knee_ok = false;
    let blocked = in_the_way(m, at, a, FLOOR_LENGTH, "308.2", "forward reach");
    let reach = if let Some(blocked) = blocked {
        blocked
    } else if a.depth_mm < NONE_MM {
        RuleCheck {
            section: "308.2.1".into(),
            rule: "forward reach, unobstructed".into(),
            ok: (LOW..=HIGH).contains(&z),
            measured: high(z),
            limit: format!("{LOW:.0} to {HIGH:.0} mm high"),
            shape: None,
        }
    } else {
        let top = if a.depth_mm <= FORWARD_DEEP {
            HIGH
        } else {
            FORWARD_DEEP_HIGH
        };
        let knee = knee(m.room, at, a);
        knee_ok = knee.ok;
        rules.push(knee);
        RuleCheck {
            section: "308.2.2".into(),
            rule: "forward reach over an obstruction".into(),
            ok: a.depth_mm <= FORWARD_DEEPEST && (LOW..=top).contains(&z),
            measured: format!("{} over {:.0} mm", high(z), a.depth_mm),
            limit: format!(
                "at most {HIGH:.0} mm high up to {FORWARD_DEEP:.0} mm deep, {FORWARD_DEEP_HIGH:.0} mm up to {FORWARD_DEEPEST:.0} mm; at least {LOW:.0} mm"
            ),
            shape: None,
        }
    };
    rules.insert(0, reach);
    // With knee space, the clear floor space reaches under the element;
    // without, it stops at the obstruction's edge.
    let near = if knee_ok {
        NONE_MM
    } else {
        a.depth_mm + NONE_MM
    };
    let space = clear_floor(
        m.floor,
        at,
        a.toward,
        near,
        FLOOR_WIDTH,
        FLOOR_LENGTH,
        "forward",
    );
    Usage {
        forward: true,
        facing_deg: facing(-a.toward),
        space: space.1,
        rules: [rules, vec![space.0]].concat(),
    }
}

/// 306: the knee space under the obstruction a forward reach goes over.
fn knee(room: &Room, at: &Point3<f64>, a: &Approached) -> RuleCheck {
    let height = a
        .under
        .iter()
        .map(|&i| room.boxes[i].corner_mm.z)
        .fold(f64::INFINITY, f64::min);
    let depth = if height >= KNEE_HIGH {
        knee_depth(room, at, a.toward, a.depth_mm, KNEE_HIGH)
    } else {
        0.0
    };
    let needed = KNEE_DEEP.max(a.depth_mm);
    RuleCheck {
        section: "306.3".into(),
        rule: "knee clearance under the obstruction".into(),
        ok: height >= KNEE_HIGH && depth >= needed,
        measured: if height >= KNEE_HIGH {
            format!("{height:.0} mm high, {depth:.0} mm deep")
        } else {
            format!("none: the obstruction comes down to {height:.0} mm")
        },
        limit: format!(
            "at least {KNEE_HIGH:.0} mm high and {needed:.0} mm deep ({KNEE_DEEP:.0} mm, and as deep as the reach)"
        ),
        shape: None,
    }
}

/// A side (parallel) approach beside the element, from `a.toward`.
fn side(m: &Measure<'_>, at: &Point3<f64>, a: &Approached) -> Usage {
    let z = at.z;
    let (depth, top) = (a.depth_mm, a.height_mm);
    let blocked = in_the_way(m, at, a, FLOOR_WIDTH, "308.3", "side reach");
    let reach = if let Some(blocked) = blocked {
        blocked
    } else if depth <= SIDE_SHALLOW {
        let obstructed = depth >= NONE_MM;
        RuleCheck {
            section: "308.3.1".into(),
            rule: "side reach, unobstructed".into(),
            ok: (LOW..=HIGH).contains(&z) && (!obstructed || top <= SIDE_OBSTRUCTION_HIGH),
            measured: if obstructed {
                format!("{} over {depth:.0} mm, {top:.0} mm high", high(z))
            } else {
                high(z)
            },
            limit: format!(
                "{LOW:.0} to {HIGH:.0} mm high; over at most {SIDE_SHALLOW:.0} mm, {SIDE_OBSTRUCTION_HIGH:.0} mm high"
            ),
            shape: None,
        }
    } else {
        RuleCheck {
            section: "308.3.2".into(),
            rule: "side reach over an obstruction".into(),
            ok: depth <= SIDE_DEEPEST
                && top <= SIDE_OBSTRUCTION_HIGH
                && (LOW..=SIDE_DEEP_HIGH).contains(&z),
            measured: format!("{} over {depth:.0} mm, {top:.0} mm high", high(z)),
            limit: format!(
                "at most {SIDE_DEEP_HIGH:.0} mm high, over at most {SIDE_DEEPEST:.0} mm and {SIDE_OBSTRUCTION_HIGH:.0} mm high; at least {LOW:.0} mm"
            ),
            shape: None,
        }
    };
    let space = clear_floor(
        m.floor,
        at,
        a.toward,
        depth + NONE_MM,
        FLOOR_LENGTH,
        FLOOR_WIDTH,
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
        section: "305".into(),
        rule: format!("clear floor space, {approach}"),
        ok,
        measured: if ok {
            format!("{across:.0} x {deep:.0} mm free")
        } else {
            format!("no free {across:.0} x {deep:.0} mm at the element")
        },
        limit: format!("{FLOOR_WIDTH:.0} x {FLOOR_LENGTH:.0} mm"),
        shape: Some(FloorShape::Polygon { points_mm }),
    };
    (rule, space)
}

/// 403.5.1: the widest way from a door to `space`.
fn route(room: &Room, space: &Polygon<f64>, meter: &Meter) -> RuleCheck {
    let (width, door) = room
        .doors
        .iter()
        .map(|d| {
            (
                route_width(room, d, space, HEADROOM, ROUTE_MOST, meter),
                d.name.as_str(),
            )
        })
        .fold((0.0, ""), |best, w| if w.0 > best.0 { w } else { best });
    RuleCheck {
        section: "403.5.1".into(),
        rule: "route width".into(),
        ok: width >= ROUTE,
        measured: if width >= ROUTE_MOST {
            format!("at least {width:.0} mm, from door `{door}`")
        } else if width > 0.0 {
            format!("{width:.0} mm at its narrowest, from door `{door}`")
        } else {
            "no way from a door".into()
        },
        limit: format!("at least {ROUTE:.0} mm"),
        shape: None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::MeshObstacle;
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
            let meter = Meter::unmetered();
            let floor = FreeFloor::new(room, KNEE_HIGH, meter);
            let m = Measure {
                room,
                floor: &floor,
                routes: None,
                meshes: mesh_bounds(room),
                meter,
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
