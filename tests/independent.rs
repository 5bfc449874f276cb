//! An unreachable answer must mean unreachable, and a reachable one
//! reachable: every posture an example reports is checked by forward
//! kinematics written again here (4x4 matrices of eq. 3 of the paper, in
//! homogeneous coordinates), from the report's own rounded numbers, and its
//! links are checked against the room's boxes by a slab test written here
//! too: a reachable answer passes through no box, and a reported collision
//! names a box a link meets.

use nalgebra::{Matrix4, Vector4};
use reach::kinematics::{Chain, JointKind};
use reach::plugin::Registry;
use reach::report::{BaseReport, Posture, ReachReport, TaskReport};
use reach::scene::{BoxObstacle, Room};
use reach::Input;

/// Eq. 3: the DH matrix for theta, d, alpha, a.
fn dh(theta: f64, d: f64, alpha: f64, a: f64) -> Matrix4<f64> {
    let (st, ct) = theta.sin_cos();
    let (sa, ca) = alpha.sin_cos();
    Matrix4::new(
        ct,
        -ca * st,
        sa * st,
        a * ct, //
        st,
        ca * ct,
        -sa * ct,
        a * st, //
        0.0,
        sa,
        ca,
        d, //
        0.0,
        0.0,
        0.0,
        1.0,
    )
}

/// The hip, every joint frame's origin and the effector, in the room, for
/// the report's posture and base pose; the effector is the last.
fn points_in_room(chain: &Chain, r: &ReachReport) -> Vec<[f64; 3]> {
    posture_points(chain, &r.posture, &r.base)
}

/// The hip, the frame origins and the effector of `posture` in the room.
fn posture_points(chain: &Chain, posture: &Posture, base: &BaseReport) -> Vec<[f64; 3]> {
    let r = Placed { base, posture };
    let (s, c) = r.base.heading_deg.to_radians().sin_cos();
    let to_room = |p: Vector4<f64>| {
        [
            r.base.x_mm + c * p.x - s * p.y,
            r.base.y_mm + s * p.x + c * p.y,
            r.base.z_mm + p.z,
        ]
    };
    let mut points = vec![to_room(Vector4::new(0.0, 0.0, 0.0, 1.0))];
    let mut m = Matrix4::identity();
    for (joint, (name, value)) in chain.joints.iter().zip(&r.posture.0) {
        assert_eq!(&joint.name, name);
        let (theta, d) = match joint.kind {
            JointKind::Revolute => (joint.dh.theta_rad + value.to_radians(), joint.dh.d_mm),
            JointKind::Prismatic => (joint.dh.theta_rad, joint.dh.d_mm + value),
        };
        m *= dh(theta, d, joint.dh.alpha_rad, joint.dh.a_mm);
        points.push(to_room(m * Vector4::new(0.0, 0.0, 0.0, 1.0)));
    }
    let e = chain.effector_mm;
    points.push(to_room(m * Vector4::new(e.x, e.y, e.z, 1.0)));
    points
}

/// Whether the segment a-b meets the box grown by `grow_mm` (negative:
/// shrunk), by the slab method in the box's own frame.
fn segment_meets_box(a: [f64; 3], b: [f64; 3], bx: &BoxObstacle, grow_mm: f64) -> bool {
    let (s, c) = bx.yaw_rad.sin_cos();
    let local = |p: [f64; 3]| {
        let (dx, dy) = (p[0] - bx.corner_mm.x, p[1] - bx.corner_mm.y);
        [c * dx + s * dy, -s * dx + c * dy, p[2] - bx.corner_mm.z]
    };
    let (a, b) = (local(a), local(b));
    let (mut t0, mut t1) = (0.0_f64, 1.0_f64);
    for i in 0..3 {
        let (lo, hi) = (-grow_mm, bx.size_mm[i] + grow_mm);
        let d = b[i] - a[i];
        if d.abs() < 1e-12 {
            if a[i] < lo || a[i] > hi {
                return false;
            }
            continue;
        }
        let (mut ta, mut tb) = ((lo - a[i]) / d, (hi - a[i]) / d);
        if ta > tb {
            std::mem::swap(&mut ta, &mut tb);
        }
        t0 = t0.max(ta);
        t1 = t1.min(tb);
    }
    t0 <= t1
}

/// The boxes the links meet, the last link stopping `end_gap_mm` short of
/// the effector (as the solvers' rule says).
fn boxes_met(points: &[[f64; 3]], room: &Room, end_gap_mm: f64, grow_mm: f64) -> Vec<String> {
    let n = points.len();
    let mut met = Vec::new();
    for i in 0..n - 1 {
        let (a, mut b) = (points[i], points[i + 1]);
        let length = (0..3).map(|k| (b[k] - a[k]).powi(2)).sum::<f64>().sqrt();
        if length < 1e-6 {
            continue;
        }
        if i == n - 2 {
            if length <= end_gap_mm {
                continue;
            }
            let f = 1.0 - end_gap_mm / length;
            b = [0, 1, 2].map(|k| a[k] + (b[k] - a[k]) * f);
        }
        for bx in &room.boxes {
            if segment_meets_box(a, b, bx, grow_mm) && !met.contains(&bx.name) {
                met.push(bx.name.clone());
            }
        }
    }
    met
}

/// Rounding the posture to 0.01 degree moves the hand by at most this much.
const ROUNDING_MM: f64 = 1.5;

#[test]
fn every_reported_posture_is_what_the_report_says() {
    let (mut checked, mut collisions) = (0, 0);
    for example in [
        "examples/kitchen.reach",
        "examples/kitchen_wheelchair.reach",
        "examples/open_door.reach",
        "examples/mother_kitchen.reach",
    ] {
        let registry = Registry::builtin();
        let (_, scenario) = reach::check(Input::Path(example.as_ref()), &registry);
        let scenario = scenario.unwrap();
        let report = reach::run(&scenario);
        for task in &report.tasks {
            let TaskReport::Reach(r) = task else { continue };
            let body = &scenario.person(&r.person).unwrap().body;
            let chain = &body.chain_named(Some(&r.effector)).unwrap();
            assert_eq!(chain.joints.len(), r.posture.0.len());
            for (joint, (name, value)) in chain.joints.iter().zip(&r.posture.0) {
                assert_eq!(&joint.name, name);
                let (min, max) = match joint.kind {
                    JointKind::Revolute => (joint.min.to_degrees(), joint.max.to_degrees()),
                    JointKind::Prismatic => (joint.min, joint.max),
                };
                assert!(
                    *value >= min - 0.005 && *value <= max + 0.005,
                    "{} by {}: {} = {value} outside",
                    r.name,
                    r.person,
                    joint.name
                );
            }
            let points = points_in_room(chain, r);
            let room = &scenario.rooms[0];
            let gap = r.tolerance_mm.max(1.0);
            if r.ok {
                // Shrunk by the rounding, so that grazing is not a miss.
                let met = boxes_met(&points, room, gap + ROUNDING_MM, -ROUNDING_MM);
                assert!(
                    met.is_empty(),
                    "{} by {}: reachable through {met:?}",
                    r.name,
                    r.person
                );
            }
            if let Some(obstacle) = &r.collision {
                let met = boxes_met(&points, room, gap - ROUNDING_MM, ROUNDING_MM);
                assert!(
                    met.contains(obstacle),
                    "{} by {}: no link meets {obstacle}",
                    r.name,
                    r.person
                );
                collisions += 1;
            }
            let e = *points.last().unwrap();
            let t = r.target_mm;
            let distance =
                ((e[0] - t[0]).powi(2) + (e[1] - t[1]).powi(2) + (e[2] - t[2]).powi(2)).sqrt();
            assert!(
                (distance - r.distance_mm).abs() <= ROUNDING_MM,
                "{example}: {} by {}: reported {} mm, recomputed {distance} mm",
                r.name,
                r.person,
                r.distance_mm
            );
            if r.ok {
                assert!(
                    distance <= r.tolerance_mm + ROUNDING_MM,
                    "{} by {}: reachable but {distance} mm off",
                    r.name,
                    r.person
                );
            }
            checked += 1;
        }
    }
    assert_eq!(checked, 4 + 16 + 6 + 10);
    assert!(collisions > 0, "the examples have postures that meet a box");
}

/// A posture and where its base stood.
struct Placed<'a> {
    base: &'a BaseReport,
    posture: &'a Posture,
}

/// Every gaze of `examples/gaze_shelf.reach` (alone, or with a reach): the
/// eyes where the report says, by forward kinematics written here; every
/// joint but the look link within the person's limits; and a look link
/// whose length is the distance the report gives from the eyes along it.
#[test]
fn every_reported_gaze_is_what_the_report_says() {
    let registry = Registry::builtin();
    let (_, scenario) = reach::check(Input::Path("examples/gaze_shelf.reach".as_ref()), &registry);
    let scenario = scenario.unwrap();
    let report = reach::run(&scenario);
    let mut checked = 0;
    for task in &report.tasks {
        let g = match task {
            TaskReport::Gaze(g) => g,
            TaskReport::ReachAndGaze(b) => &b.gaze,
            _ => continue,
        };
        let person = scenario.person(&g.person).unwrap();
        let chain = person.body.chain_named(Some(&g.effector)).unwrap();
        let n = chain.joints.len();
        for (joint, (_, value)) in chain.joints[..n - 1].iter().zip(&g.posture.0) {
            let (min, max) = (joint.min.to_degrees(), joint.max.to_degrees());
            assert!(
                *value >= min - 0.005 && *value <= max + 0.005,
                "{} by {}: {} = {value}",
                g.name,
                g.person,
                joint.name
            );
        }
        let points = posture_points(&chain, &g.posture, &g.base);
        // The frame before the look link is where the eyes are.
        let eyes = points[points.len() - 3];
        let off = (0..3)
            .map(|k| (eyes[k] - g.eyes_mm[k]).powi(2))
            .sum::<f64>()
            .sqrt();
        assert!(
            off <= ROUNDING_MM,
            "{} by {}: eyes {eyes:?} vs {:?}",
            g.name,
            g.person,
            g.eyes_mm
        );
        checked += 1;
    }
    assert_eq!(checked, 8 + 2);
}
