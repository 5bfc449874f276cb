//! An unreachable answer must mean unreachable, and a reachable one
//! reachable: every posture an example reports is checked by forward
//! kinematics written again here (4x4 matrices of eq. 3 of the paper, in
//! homogeneous coordinates), from the report's own rounded numbers.

use nalgebra::{Matrix4, Vector4};
use reach::kinematics::{Chain, JointKind};
use reach::plugin::Registry;
use reach::report::{ReachReport, TaskReport};
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

/// The effector in the room for the report's posture and base pose.
fn effector_in_room(chain: &Chain, r: &ReachReport) -> [f64; 3] {
    let mut m = Matrix4::identity();
    for (joint, (name, value)) in chain.joints.iter().zip(&r.posture.0) {
        assert_eq!(&joint.name, name);
        let (theta, d) = match joint.kind {
            JointKind::Revolute => (joint.dh.theta_rad + value.to_radians(), joint.dh.d_mm),
            JointKind::Prismatic => (joint.dh.theta_rad, joint.dh.d_mm + value),
        };
        m *= dh(theta, d, joint.dh.alpha_rad, joint.dh.a_mm);
    }
    let e = chain.effector_mm;
    let p = m * Vector4::new(e.x, e.y, e.z, 1.0);
    let (s, c) = r.base.heading_deg.to_radians().sin_cos();
    [
        r.base.x_mm + c * p.x - s * p.y,
        r.base.y_mm + s * p.x + c * p.y,
        r.base.z_mm + p.z,
    ]
}

/// Rounding the posture to 0.01 degree moves the hand by at most this much.
const ROUNDING_MM: f64 = 1.5;

#[test]
fn every_reported_posture_is_what_the_report_says() {
    let mut checked = 0;
    for example in [
        "examples/kitchen.reach",
        "examples/kitchen_wheelchair.reach",
    ] {
        let registry = Registry::builtin();
        let (_, scenario) = reach::check(Input::Path(example.as_ref()), &registry);
        let scenario = scenario.unwrap();
        let report = reach::run(&scenario, &registry);
        for task in &report.tasks {
            let TaskReport::Reach(r) = task else { continue };
            let chain = &scenario.person(&r.person).unwrap().chain;
            for (joint, (_, value)) in chain.joints.iter().zip(&r.posture.0) {
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
            let e = effector_in_room(chain, r);
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
    assert_eq!(checked, 4 + 16);
}
