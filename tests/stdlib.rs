//! The standard library's mannequins against positions worked out by hand
//! from their sources (stature 1755 mm; the joint-centre fractions of
//! std::body, docs/calibration.md).

use nalgebra::Point3;

const H: f64 = 1755.0;
/// std::arm's lengths as fractions of stature: hip point to the shoulder's
/// centre, mid-trunk to the shoulder, upper arm, forearm, hand; the grip
/// 40 % along the hand; the girdle's rise.
const TRUNK: f64 = 0.2466;
const SHOULDER: f64 = 0.1183;
const ARM_TO_GRIP: f64 = 0.1629 + 0.1590 + 0.4 * 0.1101;
const RISE: f64 = 0.0757;

fn right_arm() -> reach::kinematics::Chain {
    reach::stdlib::chain("arm", "right_arm").expect("std::arm checks")
}

#[test]
fn right_arm_hangs_beside_the_hip_at_rest() {
    let chain = right_arm();
    assert_eq!(chain.dof(), 11);
    let q = vec![0.0; 11];
    let expected = Point3::new(0.0, -SHOULDER * H, (TRUNK - ARM_TO_GRIP) * H);
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
    let at = |moved: &[(&str, f64)]| {
        let mut q = vec![0.0; 11];
        for (joint, value) in moved {
            q[index(joint)] = *value;
        }
        (chain.effector(&q), chain.within_limits(&q))
    };
    let deg = f64::to_radians;
    let (rest, _) = at(&[]);
    // Shoulder flexion 90 deg: the straight arm points forward at shoulder height.
    let (p, _) = at(&[("shoulder_flexion", deg(90.0))]);
    assert!(
        (p - Point3::new(ARM_TO_GRIP * H, rest.y, TRUNK * H)).norm() < 1e-9,
        "{p}"
    );
    // Elbow flexion moves the hand forward and up; abduction moves it out to the right.
    assert!(at(&[("elbow_flexion", deg(90.0))]).0.x > 300.0);
    assert!(at(&[("shoulder_abduction", deg(30.0))]).0.y < rest.y);
    // Trunk flexion carries the shoulder forward (the hanging hand, below the hip, goes back).
    assert!(at(&[("trunk_flexion", deg(30.0))]).0.z > rest.z);
    // The girdle slides the shoulder up the trunk, all its range with the
    // arm straight up, none with it hanging (its rhythm).
    let rise = RISE * H;
    let (up, within) = at(&[
        ("shoulder_flexion", deg(180.0)),
        ("shoulder_elevation", rise),
    ]);
    assert!(within);
    let top = Point3::new(0.0, -SHOULDER * H, (TRUNK + ARM_TO_GRIP + RISE) * H);
    assert!((up - top).norm() < 1e-6, "{up}");
    assert!(!at(&[("shoulder_elevation", 1.0)]).1);
    let half = (105.0 - 30.0) / 150.0 * rise;
    assert!(
        at(&[
            ("shoulder_flexion", deg(105.0)),
            ("shoulder_elevation", half)
        ])
        .1
    );
    assert!(
        !at(&[
            ("shoulder_flexion", deg(105.0)),
            ("shoulder_elevation", half + 1.0)
        ])
        .1
    );
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

/// Standing or seated, the eyes are as high above the hip point as
/// ANSUR II's sitting eye height (by their sex's median proportion to
/// stature: 699.6, 804.6 and 857.3 mm above the seat) less the hip
/// point's 100 mm above the seat.
#[test]
fn people_scale_with_stature_and_see_from_the_measured_sitting_eye_height() {
    for (name, above_seat) in [
        ("woman_5th", 699.6),
        ("man_50th", 804.6),
        ("man_95th", 857.3),
        ("woman_5th_seated", 699.6),
        ("man_50th_seated", 804.6),
        ("man_95th_seated", 857.3),
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

/// How FABRIK reads std::arm's chain as bones: the trunk; the girdle's
/// slide; the shoulder's offset (turned by the trunk alone); the upper arm
/// by flexion and abduction; the forearm by the humerus's rotation and the
/// elbow; the hand by the forearm and wrist.
#[test]
fn fabrik_reads_the_arm_as_trunk_shoulder_upper_arm_forearm_and_hand() {
    use reach::solvers::fabrik::{bones, End};
    let b = bones(&right_arm());
    let groups: Vec<_> = b.iter().map(|b| b.joints.clone()).collect();
    assert_eq!(groups, [0..3, 3..4, 4..4, 4..6, 6..8, 8..11]);
    assert_eq!(b[5].end, End::Effector);
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
