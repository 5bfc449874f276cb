//! A reported posture's solids, built again from the report's numbers, and
//! what they meet, by parry's intersection tests rather than the crate's
//! own geometry: each link a capsule of its joint's radius (the effector's
//! link ending its radius short of the effector and as much thinner as the
//! tolerance), the head and neck where their anchor frame puts them;
//! against the room's boxes, its walls,
//! floor and ceiling, the person's legs and base (but for the pelvis, the
//! trunk's part within `pelvis_mm` of the hip point), and the person's other
//! moving parts (links two apart may not overlap; a neighbour may not run
//! its axis through a link's core beyond their joint's reach).

use nalgebra::{Isometry3, Matrix4, Point3, Vector3, Vector4};
use parry3d_f64::query::details::distance_segment_segment;
use parry3d_f64::query::intersection_test;
use parry3d_f64::shape::{Capsule as PCapsule, Cuboid as PCuboid};
use reach::geometry::Shape;
use reach::kinematics::{Body, JointKind};
use reach::report::{BaseReport, Posture};
use reach::scene::{OwnBody, Room};

/// Eq. 3 of the accessibility paper: the DH matrix for theta, d, alpha, a.
pub fn dh(theta: f64, d: f64, alpha: f64, a: f64) -> Matrix4<f64> {
    let (st, ct) = theta.sin_cos();
    let (sa, ca) = alpha.sin_cos();
    #[rustfmt::skip]
    let m = Matrix4::new(
        ct, -ca * st, sa * st, a * ct,
        st, ca * ct, -sa * ct, a * st,
        0.0, sa, ca, d,
        0.0, 0.0, 0.0, 1.0,
    );
    m
}

/// One solid of the posture, in the room: a segment and a radius, its
/// place along the chain (a link's count from the base; a solid the chain
/// carries, the head or the neck, its anchor link's), and its name.
#[derive(Clone, Debug)]
pub struct Part {
    pub a: Point3<f64>,
    pub b: Point3<f64>,
    pub radius_mm: f64,
    pub order: i64,
    pub carried: bool,
    pub name: String,
}

/// Where the base stands, from the report.
fn to_room(base: &BaseReport, p: &Point3<f64>) -> Point3<f64> {
    let (s, c) = base.heading_deg.to_radians().sin_cos();
    Point3::new(
        base.x_mm + c * p.x - s * p.y,
        base.y_mm + s * p.x + c * p.y,
        base.z_mm + p.z,
    )
}

/// The effector's link from `last` (the last joint's origin) toward
/// `effector`, of radius `radius_mm`, as it is checked: ending its radius
/// (or `allowance_mm`, a millimetre at least) short of the effector, and
/// `allowance_mm` thinner, so that the hand may touch what it reaches with
/// its end. Its end and radius, or none if nothing is left.
pub fn effector_link_end(
    last: Point3<f64>,
    effector: Point3<f64>,
    radius_mm: f64,
    allowance_mm: f64,
) -> Option<(Point3<f64>, f64)> {
    let gap = radius_mm.max(allowance_mm).max(1.0);
    let length = (effector - last).norm();
    (length > gap).then(|| {
        let b = last + (effector - last) * (1.0 - gap / length);
        (b, (radius_mm - allowance_mm).max(0.0))
    })
}

/// The posture's solids, the effector's link ending its radius (or
/// `allowance_mm`, a millimetre at least) short and `allowance_mm` thinner
/// (none if nothing is left). Built from the whole body, not from the
/// chain the solver saw: the joints off the effector's path at their
/// neutral values, and with the path's links and the effector's, the
/// spheres (the head) and the links that hold them to the path (the
/// neck). The other branches (the other arm) are not modelled.
pub fn parts(
    body: &Body,
    effector: &str,
    posture: &Posture,
    base: &BaseReport,
    allowance_mm: f64,
) -> Vec<Part> {
    parts_with(body, effector, posture, None, base, allowance_mm)
}

/// [`parts`], the joints off the effector's path at `others`' values
/// where it names them (the eyes' posture of a reach and gaze, which
/// turns the head), else at neutral.
pub fn parts_with(
    body: &Body,
    effector: &str,
    posture: &Posture,
    others: Option<&Posture>,
    base: &BaseReport,
    allowance_mm: f64,
) -> Vec<Part> {
    let e = body
        .effector_index(effector)
        .expect("the report's effector");
    let path = body.path(body.effectors[e].joint);
    assert_eq!(path.len(), posture.0.len());
    let frames = body_frames(body, &path, posture, others);
    let origin =
        |j: Option<usize>| j.map_or(Point3::origin(), |j| point(&frames[j], &Vector3::zeros()));
    let mut parts = Vec::new();
    let mut last = Point3::origin();
    let mut links = 0;
    // The place along the path of the link ending at each path joint.
    let mut order_at = vec![-1; body.joints.len()];
    for &j in &path {
        let joint = &body.joints[j];
        let end = origin(Some(j));
        if (end - last).norm() > 1e-6 {
            parts.push(Part {
                a: last,
                b: end,
                radius_mm: joint.link.radius_mm,
                order: links,
                carried: false,
                name: joint.link.name.clone(),
            });
            // A bare segment (the girdle's slide) is no solid: the solids
            // either side of it are neighbours.
            if joint.link.radius_mm > 0.0 {
                links += 1;
            }
            last = end;
        }
        order_at[j] = links - 1;
    }
    let hand = &body.effectors[e];
    let effector_at = hand.joint.map_or(Point3::from(hand.offset_mm), |j| {
        point(&frames[j], &hand.offset_mm)
    });
    if let Some((b, radius_mm)) =
        effector_link_end(last, effector_at, hand.link.radius_mm, allowance_mm)
    {
        parts.push(Part {
            a: last,
            b,
            radius_mm,
            order: links,
            carried: false,
            name: hand.link.name.clone(),
        });
    }
    // A carried solid takes the place of the last path joint it hangs from.
    let place = |mut at: Option<usize>| loop {
        match at {
            None => break -1,
            Some(j) if path.contains(&j) => break order_at[j],
            Some(j) => at = body.parents[j],
        }
    };
    for s in &body.spheres {
        let centre = s.joint.map_or(Point3::from(s.centre_mm), |j| {
            point(&frames[j], &s.centre_mm)
        });
        parts.push(Part {
            a: centre,
            b: centre,
            radius_mm: s.radius_mm,
            order: place(s.joint),
            carried: true,
            name: s.name.clone(),
        });
    }
    let mut holding: Vec<usize> = body
        .spheres
        .iter()
        .flat_map(|s| body.path(s.joint))
        .filter(|j| !path.contains(j))
        .collect();
    holding.sort_unstable();
    holding.dedup();
    for j in holding {
        let (a, b) = (origin(body.parents[j]), origin(Some(j)));
        let link = &body.joints[j].link;
        if link.radius_mm > 0.0 && (b - a).norm() > 1e-6 {
            parts.push(Part {
                a,
                b,
                radius_mm: link.radius_mm,
                order: place(body.parents[j]),
                carried: true,
                name: link.name.clone(),
            });
        }
    }
    for p in &mut parts {
        p.a = to_room(base, &p.a);
        p.b = to_room(base, &p.b);
    }
    parts
}

/// Every joint's frame in the base frame, by eq. 3's matrices: the path's
/// joints at the posture's values, the others at `others`' where it names
/// them, else at neutral.
fn body_frames(
    body: &Body,
    path: &[usize],
    posture: &Posture,
    others: Option<&Posture>,
) -> Vec<Matrix4<f64>> {
    let mut frames: Vec<Matrix4<f64>> = Vec::with_capacity(body.joints.len());
    for (j, joint) in body.joints.iter().enumerate() {
        let named = |p: &Posture| p.0.iter().find(|(n, _)| n == &joint.name).map(|(_, v)| *v);
        let reported = match path.iter().position(|&p| p == j) {
            Some(k) => {
                assert_eq!(joint.name, posture.0[k].0);
                Some(posture.0[k].1)
            }
            None => others.and_then(named),
        };
        let value = match (reported, joint.kind) {
            (Some(v), JointKind::Revolute) => v.to_radians(),
            (Some(v), JointKind::Prismatic) => v,
            (None, _) => joint.neutral,
        };
        let (theta, d) = match joint.kind {
            JointKind::Revolute => (joint.dh.theta_rad + value, joint.dh.d_mm),
            JointKind::Prismatic => (joint.dh.theta_rad, joint.dh.d_mm + value),
        };
        let parent = body.parents[j].map_or(Matrix4::identity(), |p| frames[p]);
        let pre = joint
            .pre
            .map_or(Matrix4::identity(), |p| p.to_homogeneous());
        frames.push(parent * pre * dh(theta, d, joint.dh.alpha_rad(), joint.dh.a_mm));
    }
    frames
}

fn point(m: &Matrix4<f64>, v: &Vector3<f64>) -> Point3<f64> {
    let p = m * Vector4::new(v.x, v.y, v.z, 1.0);
    Point3::new(p.x, p.y, p.z)
}

fn capsule(a: &Point3<f64>, b: &Point3<f64>, radius_mm: f64) -> PCapsule {
    PCapsule::new(*a, *b, radius_mm.max(1e-9))
}

/// Whether two capsules overlap: their segments closer than the sum of
/// their radii, by parry's exact segment-segment distance. (parry's
/// `intersection_test` on two capsules goes through GJK, which misses some
/// deep overlaps: a trunk 14 mm into a thigh came out apart when grown by
/// 1.5 mm and overlapping when grown by 1.4 or 2.)
fn capsules_meet(a: &PCapsule, b: &PCapsule) -> bool {
    distance_segment_segment(&Isometry3::identity(), &a.segment, &b.segment) <= a.radius + b.radius
}

fn meets_cuboid(
    part: &Part,
    grow_mm: f64,
    centre: Point3<f64>,
    half: Vector3<f64>,
    yaw: f64,
) -> bool {
    let pose = Isometry3::new(centre.coords, Vector3::z() * yaw);
    let c = capsule(&part.a, &part.b, part.radius_mm + grow_mm);
    intersection_test(&Isometry3::identity(), &c, &pose, &PCuboid::new(half)).unwrap()
}

/// The room's boxes that `part`, grown by `grow_mm`, meets.
pub fn boxes_met(part: &Part, room: &Room, grow_mm: f64) -> Vec<String> {
    room.boxes
        .iter()
        .filter(|b| {
            let (s, c) = b.yaw_rad.sin_cos();
            let h = b.size_mm / 2.0;
            let centre = b.corner_mm + Vector3::new(c * h.x - s * h.y, s * h.x + c * h.y, h.z);
            meets_cuboid(part, grow_mm, centre, h, b.yaw_rad)
        })
        .map(|b| b.name.clone())
        .collect()
}

/// Whether `part`, grown by `grow_mm`, leaves the room (through a wall, the
/// floor or the ceiling).
pub fn leaves_room(part: &Part, room: &Room, grow_mm: f64) -> bool {
    let r = part.radius_mm + grow_mm;
    (0..3).any(|i| {
        let lo = part.a[i].min(part.b[i]) - r;
        let hi = part.a[i].max(part.b[i]) + r;
        lo < 0.0 || hi > room.size_mm[i]
    })
}

/// `part` without what lies within `radius_mm` of `centre` (as the crate
/// exempts the pelvis): none if both ends are inside, the part from where
/// it leaves the ball if one is, the whole part if neither is.
fn outside_ball(part: &Part, centre: &Point3<f64>, radius_mm: f64) -> Option<Part> {
    let inside = |p: &Point3<f64>| (p - centre).norm() < radius_mm;
    let (a_in, b_in) = (inside(&part.a), inside(&part.b));
    if !a_in && !b_in {
        return Some(part.clone());
    }
    if a_in && b_in {
        return None;
    }
    // Bisect for the crossing (written differently from the crate's
    // quadratic on purpose).
    let (mut t_in, mut t_out) = if a_in { (0.0, 1.0) } else { (1.0, 0.0) };
    let at = |t: f64| part.a + (part.b - part.a) * t;
    for _ in 0..60 {
        let mid = 0.5 * (t_in + t_out);
        if inside(&at(mid)) {
            t_in = mid;
        } else {
            t_out = mid;
        }
    }
    let cut = at(t_out);
    let mut kept = part.clone();
    if a_in {
        kept.a = cut;
    } else {
        kept.b = cut;
    }
    Some(kept)
}

/// The person's own legs and base solids (in the base frame) that
/// `part`, grown by `grow_mm`, meets outside the pelvis.
pub fn own_met(part: &Part, own: &OwnBody, base: &BaseReport, grow_mm: f64) -> Vec<String> {
    let hip = to_room(base, &Point3::origin());
    // Only a part that starts within the pelvis (the trunk, from the hip
    // point) may press into the seat and thighs there.
    let starts_inside = (part.a - hip).norm() < own.pelvis_mm;
    let Some(part) = (if starts_inside {
        outside_ball(part, &hip, own.pelvis_mm)
    } else {
        Some(part.clone())
    }) else {
        return Vec::new();
    };
    let heading = base.heading_deg.to_radians();
    own.solids
        .iter()
        .filter(|solid| match &solid.shape {
            Shape::Cuboid(c) => meets_cuboid(
                &part,
                grow_mm,
                to_room(base, &c.centre),
                c.half_mm,
                c.yaw_rad + heading,
            ),
            Shape::Capsule(c) => {
                let mine = capsule(&part.a, &part.b, (part.radius_mm + grow_mm).max(1e-9));
                let theirs = capsule(&to_room(base, &c.a), &to_room(base, &c.b), c.radius_mm);
                capsules_meet(&mine, &theirs)
            }
        })
        .map(|s| s.name.clone())
        .collect()
}

/// Pairs of the posture's own parts that meet as they may not, grown by
/// `grow_mm`: by name, the earlier first.
pub fn self_met(parts: &[Part], grow_mm: f64) -> Vec<(String, String)> {
    let mut met = Vec::new();
    for (i, p) in parts.iter().enumerate() {
        for q in &parts[i + 1..] {
            if p.radius_mm <= 0.0 || q.radius_mm <= 0.0 || (p.carried && q.carried) {
                continue;
            }
            let apart = (p.order - q.order).abs();
            let meets = if !p.carried && !q.carried && apart == 1 {
                // q starts at their joint, where p ends.
                let reach = p.radius_mm + q.radius_mm;
                let axis = Part {
                    radius_mm: 0.0,
                    ..q.clone()
                };
                outside_ball(&axis, &q.a, reach).is_some_and(|beyond| {
                    let core = capsule(&p.a, &p.b, p.radius_mm / 2.0 + grow_mm);
                    let line = capsule(&beyond.a, &beyond.b, 1e-9);
                    capsules_meet(&line, &core)
                })
            } else if apart >= 2 {
                let a = capsule(&p.a, &p.b, p.radius_mm + grow_mm / 2.0);
                let b = capsule(&q.a, &q.b, q.radius_mm + grow_mm / 2.0);
                capsules_meet(&a, &b)
            } else {
                false
            };
            if meets {
                met.push((p.name.clone(), q.name.clone()));
            }
        }
    }
    met
}

/// Everything the posture's parts meet, grown by `grow_mm` (negative:
/// shrunk, so that grazing within the report's rounding does not count):
/// the names of boxes, own solids, parts, and "a wall".
pub fn everything_met(
    parts: &[Part],
    room: &Room,
    own: &OwnBody,
    base: &BaseReport,
    grow_mm: f64,
) -> Vec<String> {
    let mut met = Vec::new();
    for part in parts {
        met.extend(boxes_met(part, room, grow_mm));
        met.extend(own_met(part, own, base, grow_mm));
        if leaves_room(part, room, grow_mm) {
            met.push("a wall".into());
        }
    }
    for (a, b) in self_met(parts, grow_mm) {
        met.push(format!("{a} and {b}"));
    }
    met
}

/// Whether a standing `body` in `posture` (the reach's effector
/// `effector`'s path; the other joints at neutral) keeps its balance with
/// the centre of mass within `share` of the way from the ankles to the
/// feet's edges, worked out here: every solid of the upper body (each
/// link a capsule between its frame origins, the effector's link whole,
/// the spheres) weighed by its volume, the legs by theirs, the upper body
/// taken sideways from where it is at rest; the feet's place tried a
/// millimetre at a time within the legs' lean, not solved for. With
/// `feet_under`, the feet are kept under the hips.
pub fn balanced(
    body: &Body,
    effector: &str,
    posture: &Posture,
    share: f64,
    feet_under: bool,
) -> bool {
    use reach::kinematics::LEGS_MASS_SHARE;
    let legs = body.legs.as_ref().expect("a standing body has legs");
    let upper = upper_centre(body, effector, Some(posture));
    let rest_left = upper_centre(body, effector, None).y;
    let leg_solids = |s: nalgebra::Vector2<f64>| -> Vec<(f64, Point3<f64>)> {
        legs.standing_feet_moved(s)
            .iter()
            .map(|solid| match &solid.shape {
                Shape::Capsule(c) => (
                    volume(&c.a, &c.b, c.radius_mm),
                    nalgebra::center(&c.a, &c.b),
                ),
                _ => panic!("legs are capsules"),
            })
            .collect()
    };
    let reach_mm = (legs.hip_height_mm - legs.ankle_height_mm) * 10f64.to_radians().sin();
    let side = share * (legs.hip_width_mm / 2.0 + legs.foot_radius_mm);
    let toe = share * 0.8 * legs.foot_mm;
    let heel = share * 0.2 * legs.foot_mm;
    let steps = if feet_under {
        0
    } else {
        reach_mm.floor() as i64
    };
    // The centre over the feet moved `s`, as (x, y) less the move.
    let over = |s: nalgebra::Vector2<f64>| {
        let legs_at = weighted(&leg_solids(s));
        let x = (1.0 - LEGS_MASS_SHARE) * upper.x + LEGS_MASS_SHARE * legs_at.x;
        let y = (1.0 - LEGS_MASS_SHARE) * (upper.y - rest_left) + LEGS_MASS_SHARE * legs_at.y;
        (x - s.x, y - s.y)
    };
    // Each way apart (the legs' centre follows the feet alike either
    // way), then the two moves found together within the lean.
    let least = |holds: &dyn Fn(i64) -> bool| {
        (0..=steps)
            .flat_map(|k| [k, -k])
            .find(|&k| holds(k))
            .map(|k| k as f64)
    };
    let v2 = nalgebra::Vector2::new;
    let forward = least(&|k| {
        let (x, _) = over(v2(k as f64, 0.0));
        x <= toe && x >= -heel
    });
    let sideways = least(&|k| over(v2(0.0, k as f64)).1.abs() <= side);
    match (forward, sideways) {
        (Some(x), Some(y)) => {
            let (cx, cy) = over(v2(x, y));
            v2(x, y).norm() <= reach_mm + 1.5 && cx <= toe && cx >= -heel && cy.abs() <= side
        }
        _ => false,
    }
}

/// The volume-weighted centre of the upper body in `posture` (none: at
/// rest, every joint at neutral), in the base frame.
fn upper_centre(body: &Body, effector: &str, posture: Option<&Posture>) -> Point3<f64> {
    let e = body
        .effector_index(effector)
        .expect("the report's effector");
    let frames = match posture {
        Some(p) => body_frames(body, &body.path(body.effectors[e].joint), p, None),
        None => body_frames(body, &[], &Posture(Vec::new(), Vec::new()), None),
    };
    let origin =
        |j: Option<usize>| j.map_or(Point3::origin(), |j| point(&frames[j], &Vector3::zeros()));
    let mut solids = Vec::new();
    for (j, joint) in body.joints.iter().enumerate() {
        let (a, b) = (origin(body.parents[j]), origin(Some(j)));
        if joint.link.radius_mm > 0.0 && (b - a).norm() > 1e-6 {
            solids.push((
                volume(&a, &b, joint.link.radius_mm),
                nalgebra::center(&a, &b),
            ));
        }
    }
    let hand = &body.effectors[e];
    let end = hand.joint.map_or(Point3::from(hand.offset_mm), |j| {
        point(&frames[j], &hand.offset_mm)
    });
    let last = origin(hand.joint);
    solids.push((
        volume(&last, &end, hand.link.radius_mm),
        nalgebra::center(&last, &end),
    ));
    for s in &body.spheres {
        let c = s.joint.map_or(Point3::from(s.centre_mm), |j| {
            point(&frames[j], &s.centre_mm)
        });
        solids.push((volume(&c, &c, s.radius_mm), c));
    }
    weighted(&solids)
}

fn volume(a: &Point3<f64>, b: &Point3<f64>, r: f64) -> f64 {
    std::f64::consts::PI * r * r * ((b - a).norm() + 4.0 / 3.0 * r)
}

fn weighted(solids: &[(f64, Point3<f64>)]) -> Point3<f64> {
    let total: f64 = solids.iter().map(|(v, _)| v).sum();
    let sum = solids
        .iter()
        .fold(Vector3::zeros(), |s, (v, p)| s + p.coords * *v);
    Point3::from(sum / total)
}

/// Whether `body`'s legs, standing straight under the hips where the base
/// stood, meet one of the room's boxes (by parry, as the posture's solids
/// are checked here).
pub fn legs_meet_boxes(body: &Body, room: &Room, base: &BaseReport) -> bool {
    let Some(legs) = body.legs.as_ref() else {
        return false;
    };
    legs.standing().iter().any(|solid| {
        let Shape::Capsule(c) = &solid.shape else {
            return false;
        };
        let part = Part {
            a: to_room(base, &c.a),
            b: to_room(base, &c.b),
            radius_mm: c.radius_mm,
            order: -1,
            carried: false,
            name: solid.name.clone(),
        };
        !boxes_met(&part, room, ROUNDING_GROW_MM).is_empty()
    })
}

/// How far a solid is grown where whether it meets a box is asked of a
/// rounded report.
const ROUNDING_GROW_MM: f64 = 0.01;
