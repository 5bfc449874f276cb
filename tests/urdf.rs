//! Mannequins from URDF: the chain read from `tests/data/human_arm.urdf`
//! (fixed joints folded, axes not along the frame axes, a continuous
//! joint) agrees with the `k` crate loading the same file, to 1e-9 mm, on
//! random configurations; and the file's mistakes are diagnostics.

use proptest::prelude::*;
use reach::plugin::Registry;
use reach::Input;

const SCENARIO: &str = "units mm
mannequin arm from urdf \"tests/data/human_arm.urdf\" root \"pelvis\" tip \"grip\"
room r { size 3000 x 3000 x 2500 target cup at (1300, 1300, 1200) }
person p { mannequin arm base fixed { at (1000, 1500, 930) } }
reach cup by p
";

/// The chain of the person of scenario `text`.
fn chain_of(text: &str) -> reach::kinematics::Chain {
    let registry = Registry::builtin();
    let (_, checked) = reach::check(
        Input::Text {
            name: "urdf.reach",
            text,
        },
        &registry,
    );
    checked.expect("the scenario checks").persons[0]
        .body
        .chain(0)
}

fn our_chain() -> reach::kinematics::Chain {
    chain_of(SCENARIO)
}

fn k_serial() -> k::SerialChain<f64> {
    let tree = k::Chain::<f64>::from_urdf_file("tests/data/human_arm.urdf").unwrap();
    let end = tree.find_link("grip").unwrap().clone();
    k::SerialChain::from_end(&end)
}

#[test]
fn the_chain_has_the_moving_joints_from_root_to_tip() {
    let chain = our_chain();
    let names: Vec<&str> = chain.joints.iter().map(|j| j.name.as_str()).collect();
    assert_eq!(
        names,
        [
            "waist",
            "shoulder_flexion",
            "shoulder_abduction",
            "shoulder_rotation",
            "elbow_flexion",
            "forearm_rotation",
            "wrist_flexion",
            "wrist_deviation"
        ]
    );
    assert_eq!(chain.effector_name, "grip");
    let elbow = &chain.joints[4];
    assert_eq!((elbow.min, elbow.max), (0.0, 2.6));
    let twist = &chain.joints[3];
    assert!(
        (twist.max - std::f64::consts::PI).abs() < 1e-12,
        "continuous: a full turn"
    );
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    #[test]
    fn forward_kinematics_agrees_with_the_k_crate(fractions in prop::collection::vec(0.0..1.0f64, 8)) {
        let chain = our_chain();
        let q: Vec<f64> = chain.joints.iter().zip(&fractions).map(|(j, f)| j.min + f * j.range()).collect();
        let ours = chain.effector(&q);
        let arm = k_serial();
        let by_name: Vec<f64> = arm
            .iter_joints()
            .map(|kj| q[chain.joints.iter().position(|j| j.name == kj.name).unwrap()])
            .collect();
        arm.set_joint_positions(&by_name).unwrap();
        let t = arm.end_transform().translation.vector * 1000.0;
        prop_assert!((ours.x - t.x).abs() < 1e-9 && (ours.y - t.y).abs() < 1e-9 && (ours.z - t.z).abs() < 1e-9,
            "ours {ours} k {t}");
    }
}

/// From the torso, the first axis (the shoulder's) is not the base's z: a
/// locked joint carries the base frame to it. The torso is 50 mm above the
/// pelvis when the waist is at 0.
#[test]
fn a_chain_whose_first_axis_is_turned_starts_with_a_locked_joint() {
    let chain = chain_of(&SCENARIO.replace("root \"pelvis\"", "root \"torso\""));
    assert_eq!(chain.joints[0].name, "shoulder_flexion_base");
    assert_eq!((chain.joints[0].min, chain.joints[0].max), (0.0, 0.0));
    let arm = k_serial();
    for f in [0.1, 0.5, 0.9] {
        let q: Vec<f64> = chain.joints.iter().map(|j| j.min + f * j.range()).collect();
        let by_name: Vec<f64> = arm
            .iter_joints()
            .map(|kj| {
                chain
                    .joints
                    .iter()
                    .position(|j| j.name == kj.name)
                    .map_or(0.0, |i| q[i])
            })
            .collect();
        arm.set_joint_positions(&by_name).unwrap();
        let t = arm.end_transform().translation.vector * 1000.0;
        let ours = chain.effector(&q);
        let diff = (ours.coords + nalgebra::Vector3::new(0.0, 0.0, 50.0)
            - nalgebra::Vector3::new(t.x, t.y, t.z))
        .norm();
        assert!(diff < 1e-9, "{ours} vs {t}");
    }
}

#[test]
fn a_urdf_mannequin_reaches() {
    let registry = Registry::builtin();
    let (_, checked) = reach::check(
        Input::Text {
            name: "urdf.reach",
            text: SCENARIO,
        },
        &registry,
    );
    let report = reach::run(&checked.unwrap()).expect("within the bound on solver work");
    assert!(report.tasks[0].answer().ok, "{:?}", report.tasks[0]);
}

#[test]
fn mistakes_in_the_urdf_are_diagnostics_at_the_reach_text() {
    let cases = [
        (
            SCENARIO.replace("\"grip\"", "\"gripp\""),
            "it has no link `gripp`",
            "\"gripp\"",
        ),
        (
            SCENARIO.replace("human_arm.urdf", "no_such.urdf"),
            "cannot use the URDF",
            "\"tests/data/no_such.urdf\"",
        ),
        (
            SCENARIO.replace("root \"pelvis\"", "root \"head\""),
            "no chain of joints leads from `head` to `grip`",
            "\"grip\"",
        ),
    ];
    let registry = Registry::builtin();
    for (text, message, at) in cases {
        let (sources, checked) = reach::check(
            Input::Text {
                name: "urdf.reach",
                text: &text,
            },
            &registry,
        );
        let errors = checked.expect_err("refused");
        let e = &errors.errors[0];
        let shown = e.to_string();
        assert!(shown.contains(message), "{shown}");
        let span = e.span().expect("a span");
        let source = sources.get(span.file);
        assert_eq!(&source.text[span.start as usize..span.end as usize], at);
    }
}

/// A URDF of more elements than any body has is refused before it is
/// parsed: the arm with 100,000 empty links added parsed (2,000,000 of
/// them in 45 MB took 2.4 GB and 8.5 s).
#[test]
fn a_urdf_of_too_many_elements_is_refused_before_it_is_parsed() {
    let dir = tempfile::tempdir().unwrap();
    let arm = std::fs::read_to_string("tests/data/human_arm.urdf").unwrap();
    let links: String = (0..100_000)
        .map(|k| format!("<link name=\"extra_{k}\"/>"))
        .collect();
    let padded = arm.replacen("</robot>", &format!("{links}</robot>"), 1);
    std::fs::write(dir.path().join("padded.urdf"), padded).unwrap();
    let path = dir.path().join("padded.reach");
    std::fs::write(
        &path,
        SCENARIO.replace("tests/data/human_arm.urdf", "padded.urdf"),
    )
    .unwrap();
    let (_, checked) = reach::check(Input::Path(&path), &Registry::builtin());
    let shown = checked.expect_err("refused").errors[0].to_string();
    assert!(
        shown.contains("it holds more than 100,000 elements"),
        "{shown}"
    );
}
