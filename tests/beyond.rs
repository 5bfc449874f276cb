//! The proof that a point is out of a person's reach (`collision::OutOfReach`)
//! must never rule out a point that a posture clear of the person's own
//! body reaches. The postures are pushed to the edge of what the body
//! allows, where a proof that cut a corner would show it: from a random
//! posture, joints are moved one at a time as far as the effector goes in
//! a random direction while every solid but the hand stays clear of the
//! person's legs and base; the point a little further on (within the
//! tolerance) is asked of the proof, and of the proofs a map keeps
//! (`engine::KeptProofs`), which look longer at a point asked again.
//! And it must rule out what a seated person plainly cannot reach.

use nalgebra::{Point3, Vector3};
use proptest::prelude::*;
use reach::collision::{OutOfReach, Verdict};
use reach::engine::KeptProofs;
use reach::kinematics::{Chain, Owner};
use reach::plugin::Registry;
use reach::scene::OwnBody;
use reach::Input;

/// Each person of a scenario: the chain of their right hand and their own
/// body and base.
fn people() -> Vec<(String, Chain, OwnBody)> {
    let text = "units mm deg\nuse std::arm\nuse std::people\n\
        room r { size 4000 x 4000 x 2500 }\n\
        person seated { mannequin right_arm { limits trunk_flexion (-10deg, 40deg) } base wheelchair }\n\
        person seated_full { mannequin right_arm base wheelchair }\n\
        person walker { mannequin right_arm base rollator }\n\
        person small { mannequin woman_5th_seated base manual_wheelchair }\n\
        person tall { mannequin man_95th_seated base power_wheelchair }\n\
        person standing { mannequin man_50th base rollator }\n";
    let registry = Registry::builtin();
    let (_, scenario) = reach::check(
        Input::Text {
            name: "people.reach",
            text,
        },
        &registry,
    );
    let scenario = scenario.expect("the scenario checks");
    scenario
        .persons
        .iter()
        .zip(&scenario.bases)
        .map(|(p, base)| {
            let chain = p.body.chain_named(None).expect("a chain");
            (p.name.clone(), chain, base.own_body().clone())
        })
        .collect()
}

/// Whether posture `q` keeps every solid but the hand out of the
/// person's own body and base.
fn clear_of_own_body(chain: &Chain, own: &OwnBody, q: &[f64]) -> bool {
    let v = chain.volumes(q);
    let hand = Owner::Link(chain.joints.len());
    v.capsules
        .iter()
        .zip(&v.owners)
        .all(|(c, &o)| o == hand || own.hit(c).is_none())
}

#[test]
fn the_proof_applies_to_the_standard_people() {
    for (name, chain, own) in people() {
        assert!(OutOfReach::of(&chain, &own).is_some(), "{name}");
    }
}

#[test]
fn the_floor_before_the_footrests_is_out_of_reach_and_the_lap_is_not() {
    for (name, chain, own) in people()
        .into_iter()
        .filter(|(n, ..)| n.starts_with("seated"))
    {
        let proof = OutOfReach::of(&chain, &own).unwrap();
        let hip_mm = own
            .solids
            .iter()
            .map(|s| s.shape.bounds()[0].z)
            .fold(f64::INFINITY, f64::min);
        // Straight ahead, 10 mm above the lowest part of the chair (the
        // floor), 600 mm ahead of the hip: the trunk would have to lean
        // into the thighs.
        let floor = Point3::new(600.0, 0.0, hip_mm + 10.0);
        assert!(proof.proves(&floor, 10.0), "{name}: the floor");
        let lap = Point3::new(350.0, -150.0, 250.0);
        assert!(!proof.proves(&lap, 10.0), "{name}: above the knees");
        let kept = KeptProofs::new(&chain, &own, &reach::allowance::Unbounded);
        assert!(kept.proves(&floor, 10.0), "{name}: the floor, kept");
        assert!(
            (0..64).all(|_| !kept.proves(&lap, 10.0)),
            "{name}: the lap, kept"
        );
    }
}

/// Posture `q` moved, a joint at a time, as far as the effector goes
/// along `towards` while it stays within the limits and `allowed`.
fn pushed_to_the_edge(
    chain: &Chain,
    allowed: &dyn Fn(&[f64]) -> bool,
    mut q: Vec<f64>,
    towards: &Vector3<f64>,
) -> Vec<f64> {
    let gain = |q: &[f64]| chain.effector(q).coords.dot(towards);
    for step_rad in [0.2, 0.05, 0.01, 0.002] {
        for _ in 0..40 {
            let mut moved = false;
            for i in 0..q.len() {
                for sign in [1.0, -1.0] {
                    let mut tried = q.clone();
                    tried[i] = chain.clamp_joint(i, q[i] + sign * step_rad, &q);
                    if gain(&tried) > gain(&q) + 1e-9 && allowed(&tried) {
                        q = tried;
                        moved = true;
                    }
                }
            }
            if !moved {
                break;
            }
        }
    }
    q
}

/// The unit vector along `direction` (straight down if it has none).
fn unit_vector(direction: [f64; 3]) -> Vector3<f64> {
    Vector3::from(direction)
        .try_normalize(1e-6)
        .unwrap_or_else(|| -Vector3::z())
}

/// The posture at fractions `unit` of each joint's range, drawn within
/// the couplings of its joints (the stdlib trunk's turn and sideways bend).
fn posture_at(chain: &Chain, unit: &[f64]) -> Vec<f64> {
    let mut q: Vec<f64> = chain
        .joints
        .iter()
        .zip(unit.iter().cycle())
        .map(|(j, u)| j.min + u * j.range())
        .collect();
    chain.pull_in(&mut q);
    q
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn a_point_a_clear_posture_reaches_is_never_ruled_out(
        unit in prop::collection::vec(0.0..1.0f64, 16),
        direction in prop::array::uniform3(-1.0..1.0f64),
    ) {
        let towards = unit_vector(direction);
        for (name, chain, own) in people() {
            let proof = OutOfReach::of(&chain, &own).unwrap();
            let q = posture_at(&chain, &unit);
            if !clear_of_own_body(&chain, &own, &q) {
                continue;
            }
            let clear = |q: &[f64]| clear_of_own_body(&chain, &own, q);
            let q = pushed_to_the_edge(&chain, &clear, q, &towards);
            let target = chain.effector(&q) + towards * 9.9;
            prop_assert!(!proof.proves(&target, 10.0), "{}: {:?} reaches {:?}", name, q, target);
            // Kept for a map and asked again and again, the proof looks
            // longer (up to 64 times as long, between a map's rounds) and
            // for a grid cell round the point: it must not rule the point
            // out either.
            let kept = KeptProofs::new(&chain, &own, &reach::allowance::Unbounded);
            for asked in 1..=64 {
                prop_assert!(!kept.proves(&target, 10.0), "{}: kept, asked {} times: {:?} reaches {:?}", name, asked, q, target);
                kept.settle();
            }
        }
    }

    /// The proof by the limits alone (which lets a map pass over a
    /// placement unsolved) must never rule out a point that some posture
    /// within the joint limits comes within the tolerance of, through the
    /// person's own body or not: postures pushed to the edge of the
    /// limits, the point a little further on.
    #[test]
    fn a_point_any_posture_reaches_is_never_beyond_the_limits(
        unit in prop::collection::vec(0.0..1.0f64, 16),
        direction in prop::array::uniform3(-1.0..1.0f64),
    ) {
        let towards = unit_vector(direction);
        for (name, chain, own) in people() {
            let proof = OutOfReach::of(&chain, &own).unwrap();
            let q = posture_at(&chain, &unit);
            let q = pushed_to_the_edge(&chain, &|_| true, q, &towards);
            let target = chain.effector(&q) + towards * 9.9;
            let verdict = proof.decide_by_limits(&target, 10.0, 1024);
            prop_assert!(verdict != Verdict::Proved, "{}: {:?} reaches {:?}", name, q, target);
            let kept = KeptProofs::new(&chain, &own, &reach::allowance::Unbounded);
            prop_assert!(!kept.beyond_limits(&target, 10.0), "{}: kept: {:?} reaches {:?}", name, q, target);
        }
    }
}

#[test]
fn the_ceiling_is_beyond_the_limits_and_the_floor_only_beyond_the_body() {
    for (name, chain, own) in people()
        .into_iter()
        .filter(|(n, ..)| n.starts_with("seated"))
    {
        let proof = OutOfReach::of(&chain, &own).unwrap();
        let ceiling = Point3::new(300.0, 0.0, 2500.0);
        assert_eq!(
            proof.decide_by_limits(&ceiling, 10.0, 1024),
            Verdict::Proved,
            "{name}: the ceiling"
        );
        // Just ahead of the knees, low: the trunk could bend there if the
        // thighs were not in the way.
        let low = Point3::new(450.0, -150.0, -150.0);
        assert_ne!(
            proof.decide_by_limits(&low, 10.0, 1024),
            Verdict::Proved,
            "{name}: low"
        );
    }
}
