//! The standard library's mannequins against positions worked out by hand
//! from their sources (stature 1755 mm and Drillis & Contini's fractions).

use nalgebra::Point3;

const H: f64 = 1755.0;

fn right_arm() -> reach::kinematics::Chain {
    reach::stdlib::chain("arm", "right_arm").expect("std::arm checks")
}

#[test]
fn right_arm_hangs_beside_the_hip_at_rest() {
    let chain = right_arm();
    assert_eq!(chain.dof(), 10);
    let q = vec![0.0; 10];
    let shoulder_offset = 0.259 / 2.0 * H;
    let trunk = (0.818 - 0.530) * H;
    let arm = (0.186 + 0.146 + 0.6 * 0.108) * H;
    let expected = Point3::new(0.0, -shoulder_offset, trunk - arm);
    assert!(
        (chain.effector(&q) - expected).norm() < 1e-9,
        "{}",
        chain.effector(&q)
    );
}

#[test]
fn right_arm_joints_move_the_hand_the_anatomical_way() {
    let chain = right_arm();
    let index = |name: &str| chain.joints.iter().position(|j| j.name == name).unwrap();
    let at = |joint: &str, deg: f64| {
        let mut q = vec![0.0; 10];
        q[index(joint)] = deg.to_radians();
        chain.effector(&q)
    };
    let rest = at("elbow_flexion", 0.0);
    // Shoulder flexion 90 deg: the straight arm points forward at shoulder height.
    let reach_forward = (0.186 + 0.146 + 0.6 * 0.108) * H;
    let p = at("shoulder_flexion", 90.0);
    assert!(
        (p - Point3::new(reach_forward, rest.y, (0.818 - 0.530) * H)).norm() < 1e-9,
        "{p}"
    );
    // Elbow flexion moves the hand forward and up; abduction moves it out to the right.
    assert!(at("elbow_flexion", 90.0).x > 300.0);
    assert!(at("shoulder_abduction", 30.0).y < rest.y);
    // Trunk flexion carries the shoulder forward (the hanging hand, below the hip, goes back).
    assert!(at("trunk_flexion", 30.0).z > rest.z);
}
