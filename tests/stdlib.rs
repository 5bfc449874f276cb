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

/// The grip's neutral position of a std::people mannequin, and where its
/// eyes look from.
fn neutral_grip_and_eyes(name: &str) -> (Point3<f64>, Point3<f64>) {
    let body = reach::stdlib::body("people", name).expect("std::people checks");
    let grip = body.chain(0);
    let eyes = body.chain_named(Some("eyes")).unwrap();
    let mut q = eyes.neutral();
    q.pop();
    let eye_frame = eyes.joints[..q.len()]
        .iter()
        .zip(&q)
        .fold(nalgebra::IsometryMatrix3::identity(), |f, (j, &v)| {
            f * j.transform(v)
        });
    (
        grip.effector(&grip.neutral()),
        Point3::from(eye_frame.translation.vector),
    )
}

#[test]
fn people_scale_with_stature_and_sit_by_the_seated_table() {
    let eye_above_hip = |h: f64| (0.936 - 0.530) * h;
    for (name, h) in [
        ("woman_5th", 1520.0),
        ("man_50th", 1755.0),
        ("man_95th", 1870.0),
    ] {
        let (_, eyes) = neutral_grip_and_eyes(name);
        assert!((eyes.z - eye_above_hip(h)).abs() < 1e-6, "{name}: {eyes}");
    }
    // Seated: the eyes as high above the seat as ANSUR II's sitting eye
    // height (698, 804 and 860 mm), with the hip 100 mm above the seat.
    for (name, above_seat) in [
        ("woman_5th_seated", 698.0),
        ("man_50th_seated", 804.0),
        ("man_95th_seated", 860.0),
    ] {
        let (_, eyes) = neutral_grip_and_eyes(name);
        assert!(
            (eyes.z - (above_seat - 100.0)).abs() < 1e-6,
            "{name}: {eyes}"
        );
    }
    let (small, _) = neutral_grip_and_eyes("woman_5th");
    let (tall, _) = neutral_grip_and_eyes("man_95th");
    assert!(
        small.z > tall.z,
        "the longer arm hangs lower: {small} {tall}"
    );
}

#[test]
fn std_people_presets_apply() {
    let text = "use std::people
room r { size 4000mm x 4000mm x 2500mm }
person mum {
  mannequin woman_5th_seated { profile older_adult profile shoulder_to_90 }
  base power_wheelchair { headings 4 }
  vision low_vision
}";
    let registry = reach::plugin::Registry::builtin();
    let (_, checked) = reach::check(
        reach::Input::Text {
            name: "mum.reach",
            text,
        },
        &registry,
    );
    let scenario = checked.expect("checks");
    let mum = &scenario.persons[0];
    let flexion = mum
        .body
        .joints
        .iter()
        .find(|j| j.name == "shoulder_flexion")
        .unwrap();
    // older_adult's extension, then shoulder_to_90's flexion over it.
    assert_eq!(
        (
            flexion.min.to_degrees().round(),
            flexion.max.to_degrees().round()
        ),
        (-60.0, 90.0)
    );
    let elbow = mum
        .body
        .joints
        .iter()
        .find(|j| j.name == "elbow_flexion")
        .unwrap();
    assert!((elbow.max.to_degrees() - 143.0).abs() < 1e-9);
    assert_eq!(mum.base.name, "wheelchair");
    use reach::plugin::Settings;
    let chair = reach::bases::WheelchairSettings::from_options(&mum.base.options).unwrap();
    assert_eq!(chair.seat_height_mm, 538.0);
    assert_eq!(chair.placing.headings, 4);
    let mar = mum
        .vision
        .mar_far_rad
        .expect("low_vision gives it")
        .to_degrees()
        * 60.0;
    assert!((mar - 6.0).abs() < 1e-9);
}

/// The left arm is the right one mirrored in the body's midplane: with the
/// trunk upright, the same arm angles put the left grip where the right
/// one is with y (left) negated, whatever the angles.
#[test]
fn the_left_arm_mirrors_the_right() {
    use rand_chacha::rand_core::{Rng, SeedableRng};
    let body = reach::stdlib::body("body", "upper_body").expect("std::body checks");
    let right = body.chain_named(Some("grip")).unwrap();
    let left = body.chain_named(Some("left_grip")).unwrap();
    assert_eq!(left.dof(), right.dof());
    let trunk = 3;
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(7);
    for _ in 0..200 {
        let mut q: Vec<f64> = right
            .joints
            .iter()
            .map(|j| j.min + (rng.next_u64() as f64 / u64::MAX as f64) * j.range())
            .collect();
        q[..trunk].fill(0.0);
        let (r, l) = (right.effector(&q), left.effector(&q));
        let mirrored = Point3::new(r.x, -r.y, r.z);
        assert!((l - mirrored).norm() < 1e-9, "{q:?}: right {r}, left {l}");
        for (jr, jl) in right.joints.iter().zip(&left.joints).skip(trunk) {
            assert_eq!((jl.min, jl.max, jl.neutral), (jr.min, jr.max, jr.neutral));
        }
    }
    // At rest the left hand hangs on the left (y > 0).
    assert!(left.effector(&left.neutral()).y > 100.0);
}

/// How FABRIK reads std::arm's chain as bones: the trunk; the shoulder's
/// offset (turned by the trunk alone); the upper arm by flexion and
/// abduction; the forearm by the humerus's rotation and the elbow; the hand
/// by the forearm and wrist.
#[test]
fn fabrik_reads_the_arm_as_trunk_shoulder_upper_arm_forearm_and_hand() {
    use reach::solvers::fabrik::{bones, End};
    let b = bones(&right_arm());
    let groups: Vec<_> = b.iter().map(|b| b.joints.clone()).collect();
    assert_eq!(groups, [0..3, 3..3, 3..5, 5..7, 7..10]);
    assert_eq!(b[4].end, End::Effector);
}

/// The eyes' look link is a bone of varying length for FABRIK.
#[test]
fn fabrik_reads_the_look_link_as_a_bone_of_varying_length() {
    let body = reach::stdlib::body("body", "upper_body").expect("std::body checks");
    let eyes = body.chain_named(Some("eyes")).unwrap();
    let b = reach::solvers::fabrik::bones(&eyes);
    let look = b.last().unwrap();
    assert_eq!(look.joints, 6..9, "eye pitch, eye yaw and the look link");
    assert_eq!(look.length_mm, [0.0, 30_000.0]);
}
