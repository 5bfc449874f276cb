//! Property tests of the kinematics and the solvers, on random chains
//! (revolute and prismatic joints, random DH parameters and limits) and
//! random targets.

use nalgebra::{Point3, Vector3};
use proptest::prelude::*;
use reach::collision::{Obstacles, PlacedObstacles};
use reach::kinematics::{Chain, Coupling, Dh, Ellipse, IncrementalFk, Joint, JointKind, Link};
use reach::plugin::{BasePose, IkProblem, IkSolution, Options, Registry, Settings, Solver, Value};
use reach::scene::{Blocker, BoxObstacle, OwnBody, Room};
use reach::solvers::fabrik::{solve_tree, TreeGoal, TreeProblem};
use reach::solvers::FabrikSettings;

use reach::kinematics::SUPPORT_SHARE;

use crate::body_check::{balanced, effector_link_end};

/// A random joint: revolute (limits within +/-pi) or prismatic (0 to 200 mm).
fn joint() -> impl Strategy<Value = Joint> {
    (
        any::<bool>(),
        -3.0..3.0f64,
        -200.0..200.0f64,
        -3.0..3.0f64,
        -200.0..200.0f64,
        0.0..1.0f64,
        0.05..1.0f64,
        0.0..20.0f64,
    )
        .prop_map(
            |(revolute, theta_rad, d_mm, alpha_rad, a_mm, low, span, radius_mm)| {
                let (kind, min, max) = if revolute {
                    let min = -std::f64::consts::PI + low * std::f64::consts::PI;
                    (JointKind::Revolute, min, min + span * std::f64::consts::PI)
                } else {
                    (
                        JointKind::Prismatic,
                        low * 100.0,
                        low * 100.0 + span * 100.0,
                    )
                };
                Joint {
                    name: "j".into(),
                    kind,
                    dh: Dh::new(theta_rad, d_mm, alpha_rad, a_mm),
                    fixed: None,
                    pre: None,
                    min,
                    max,
                    anatomical: None,
                    neutral: (min + max) / 2.0,
                    weight: 1.0,
                    link: Link {
                        name: "link".into(),
                        radius_mm,
                    },
                }
            },
        )
}

fn chain() -> impl Strategy<Value = Chain> {
    (
        prop::collection::vec(joint(), 1..10),
        -100.0..100.0f64,
        0.0..20.0f64,
        prop::option::of((0usize..10, 0usize..10)),
    )
        .prop_map(|(joints, e, radius_mm, couple)| {
            let n = joints.len();
            let mut chain = Chain::new(joints, "tip", Vector3::new(e, e / 2.0, -e / 3.0));
            chain.effector_link.radius_mm = radius_mm;
            // Two joints whose ranges are coupled, as the stdlib trunk's.
            if let Some((a, b)) = couple.filter(|_| n >= 2) {
                let (a, b) = (a % n, (a + 1 + b % (n - 1)) % n);
                chain
                    .couplings
                    .push(Coupling::Ellipse(Ellipse { joints: vec![a, b] }));
            }
            chain
        })
}

/// A posture within the chain's limits, from fractions in [0, 1].
fn posture(chain: &Chain, fractions: &[f64]) -> Vec<f64> {
    chain
        .joints
        .iter()
        .zip(fractions.iter().cycle())
        .map(|(j, f)| j.min + f * j.range())
        .collect()
}

/// Whether a link of `chain` in posture `q`, a capsule of its radius,
/// meets box `b`, by parry (independently of the crate's own geometry):
/// the effector's link `allowance_mm` thinner, or if that leaves nothing,
/// stopping that far (a millimetre at least) short of the effector.
fn links_meet_box(chain: &Chain, q: &[f64], allowance_mm: f64, b: &BoxObstacle) -> bool {
    use parry3d_f64::math::Isometry;
    use parry3d_f64::query::intersection_test;
    use parry3d_f64::shape::{Capsule, Cuboid};
    let half = b.size_mm / 2.0;
    let (sin, cos) = b.yaw_rad.sin_cos();
    let centre = b.corner_mm
        + Vector3::new(
            cos * half.x - sin * half.y,
            sin * half.x + cos * half.y,
            half.z,
        );
    let box_pose = Isometry::new(centre.coords, Vector3::z() * b.yaw_rad);
    let cuboid = Cuboid::new(half);
    let mut radii: Vec<f64> = Vec::new();
    let mut frame_points = vec![Point3::origin()];
    let mut frame = nalgebra::IsometryMatrix3::identity();
    for (joint, &qj) in chain.joints.iter().zip(q) {
        frame *= joint.transform(qj);
        let origin = Point3::from(frame.translation.vector);
        if (origin - frame_points[frame_points.len() - 1]).norm() > 1e-6 {
            frame_points.push(origin);
            radii.push(joint.link.radius_mm);
        }
    }
    let effector = frame * Point3::from(chain.effector_mm);
    let last = frame_points[frame_points.len() - 1];
    let mut links: Vec<(Point3<f64>, Point3<f64>, f64)> = frame_points
        .windows(2)
        .zip(&radii)
        .map(|(w, &r)| (w[0], w[1], r))
        .collect();
    if let Some((end, r)) =
        effector_link_end(last, effector, chain.effector_link.radius_mm, allowance_mm)
    {
        links.push((last, end, r));
    }
    links.iter().any(|&(a, b, r)| {
        let capsule = Capsule::new(a, b, r);
        intersection_test(&Isometry::identity(), &capsule, &box_pose, &cuboid).expect("supported")
    })
}

fn solver(name: &str, set: &[(&str, Value)]) -> Box<dyn Solver> {
    let registry = Registry::builtin();
    let plugin = registry.solver(name).unwrap();
    let mut options = Options::defaults(&plugin.params());
    for (k, v) in set {
        let name = plugin.params().iter().find(|p| p.name == *k).unwrap().name;
        options = options.set(name, v.clone());
    }
    plugin.build(&options).expect("the solver builds")
}

fn solve(solver: &dyn Solver, chain: &Chain, target: Point3<f64>, seed: u64) -> IkSolution {
    solver.solve(&IkProblem {
        chain,
        target_mm: target,
        tolerance_mm: 5.0,
        seed,
        obstacles: None,
        allowance: &reach::allowance::Unbounded,
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    #[test]
    fn incremental_fk_agrees_with_the_full_product(
        chain in chain(),
        start in prop::collection::vec(0.0..1.0f64, 10),
        changes in prop::collection::vec((0usize..10, 0.0..1.0f64), 0..30),
        target in prop::array::uniform3(-300.0..300.0f64),
    ) {
        let target = Point3::from(target);
        let mut q = posture(&chain, &start);
        let mut fk = IncrementalFk::new(&chain, q.clone(), target);
        for (i, f) in changes {
            let i = i % chain.dof();
            let qi = chain.joints[i].min + f * chain.joints[i].range();
            let mut moved = q.clone();
            moved[i] = qi;
            let expected = (chain.effector(&moved) - target).norm_squared();
            prop_assert!((fk.distance_sq_with(i, qi) - expected).abs() <= 1e-9 * expected.max(1.0));
            fk.set(i, qi);
            q = moved;
            prop_assert!((fk.effector() - chain.effector(&q)).norm() < 1e-9);
        }
    }

    #[test]
    fn solutions_respect_limits_and_report_their_true_distance(
        chain in chain(),
        goal in prop::collection::vec(0.0..1.0f64, 10),
        seed in any::<u64>(),
        which in 0usize..4,
    ) {
        let target = chain.effector(&posture(&chain, &goal));
        let solver = match which {
            0 => solver("incremental", &[("starts", Value::Integer(2))]),
            1 => solver("incremental", &[("starts", Value::Integer(1)), ("grow", Value::Number(1.0)), ("shrink", Value::Number(1.0))]),
            2 => solver("fabrik", &[("starts", Value::Integer(2))]),
            _ => solver("dls", &[("starts", Value::Integer(2))]),
        };
        let s = solve(solver.as_ref(), &chain, target, seed);
        prop_assert!(chain.within_limits(&s.q), "{:?} outside limits", s.q);
        let fk_distance = (chain.effector(&s.q) - target).norm();
        prop_assert!((s.distance_mm - fk_distance).abs() < 1e-9, "{} vs {}", s.distance_mm, fk_distance);
    }

    #[test]
    fn the_same_seed_gives_the_same_answer(
        chain in chain(),
        goal in prop::collection::vec(0.0..1.0f64, 10),
        seed in any::<u64>(),
    ) {
        let target = chain.effector(&posture(&chain, &goal));
        for name in ["incremental", "dls", "fabrik"] {
            let s = solver(name, &[("starts", Value::Integer(3)), ("neutral_start", Value::Bool(false))]);
            prop_assert_eq!(solve(s.as_ref(), &chain, target, seed), solve(s.as_ref(), &chain, target, seed));
        }
    }

    #[test]
    fn eager_and_lazy_evaluation_choose_alike(
        chain in chain(),
        goal in prop::collection::vec(0.0..1.0f64, 10),
        seed in any::<u64>(),
    ) {
        let target = chain.effector(&posture(&chain, &goal));
        let eager = solver("incremental", &[("eager_pair", Value::Bool(true))]);
        let lazy = solver("incremental", &[("eager_pair", Value::Bool(false))]);
        prop_assert_eq!(solve(eager.as_ref(), &chain, target, seed), solve(lazy.as_ref(), &chain, target, seed));
    }

    #[test]
    fn fabrik_keeps_limits_and_says_truly_whether_links_meet_the_box(
        chain in chain(),
        goal in prop::collection::vec(0.0..1.0f64, 10),
        seed in any::<u64>(),
        corner in prop::array::uniform3(-300.0..300.0f64),
        size in prop::array::uniform3(10.0..300.0f64),
    ) {
        let target = chain.effector(&posture(&chain, &goal));
        // The base stands in the middle of a room 10 m each way (no chain
        // of ten links of 200 mm reaches a wall); the box is around it.
        let middle = Vector3::repeat(5000.0);
        let box_in_base = BoxObstacle { name: "b".into(), corner_mm: Point3::from(corner), size_mm: Vector3::from(size), yaw_rad: 0.3 };
        let room = Room {
            name: "r".into(),
            size_mm: Vector3::repeat(1e4),
            boxes: vec![BoxObstacle { corner_mm: box_in_base.corner_mm + middle, ..box_in_base.clone() }],
            meshes: Vec::new(),
            targets: vec![],
            surfaces: vec![],
            doors: Vec::new(),
        };
        let obstacles = Obstacles::new(&room, 0.0);
        let own = OwnBody::default();
        let placed = PlacedObstacles { obstacles: &obstacles, own: &own, base_pose: BasePose { position_mm: Point3::from(middle), heading_rad: 0.0 } };
        let problem = IkProblem { chain: &chain, target_mm: target, tolerance_mm: 5.0, seed, obstacles: Some(placed), allowance: &reach::allowance::Unbounded };
        let s = solver("fabrik", &[("starts", Value::Integer(2))]).solve(&problem);
        prop_assert!(chain.within_limits(&s.q), "{:?} outside limits", s.q);
        let met = links_meet_box(&chain, &s.q, 5.0, &box_in_base);
        match s.collision.map(|c| c.blocker) {
            // Its links meet each other, which parry is not asked.
            Some(Blocker::Body(_)) => {}
            collision => prop_assert_eq!(met, collision.is_some(), "{:?}", collision),
        }
    }

    #[test]
    fn the_tree_solve_keeps_every_joint_within_limits(
        fractions in prop::collection::vec(0.0..1.0f64, 16),
        seed in any::<u64>(),
    ) {
        let body = reach::stdlib::body("body", "upper_body").unwrap();
        let mut whole = Chain::new(body.joints.clone(), "", Vector3::zeros());
        whole.couplings = body.couplings.clone();
        prop_assert!(!whole.couplings.is_empty(), "the stdlib trunk is coupled");
        let q = posture(&whole, &fractions);
        let targets: Vec<Point3<f64>> = (0..2).map(|e| {
            let path = body.path(body.effectors[e].joint);
            body.chain(e).effector(&path.iter().map(|&j| q[j]).collect::<Vec<_>>())
        }).collect();
        let goals = [
            TreeGoal { effector: 0, target_mm: targets[0], weight: 1.0 },
            TreeGoal { effector: 1, target_mm: targets[1], weight: 0.1 },
        ];
        let settings = FabrikSettings {
            starts: 1, max_iterations: 50, samples: 5, kicks: 3,
            ..FabrikSettings::with_defaults()
        };
        let s = solve_tree(&settings, &TreeProblem { body: &body, goals: &goals, tolerance_mm: 5.0, seed, obstacles: None, allowance: &reach::allowance::Unbounded });
        prop_assert!(whole.within_limits(&s.q));
        for (e, g) in goals.iter().enumerate() {
            let path = body.path(body.effectors[g.effector].joint);
            let fk = body.chain(e).effector(&path.iter().map(|&j| s.q[j]).collect::<Vec<_>>());
            prop_assert!(((fk - g.target_mm).norm() - s.distances_mm[e]).abs() < 1e-6);
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    /// Standing, for random postures of std::people's people, the
    /// balance's answer agrees with a search of the feet's place a
    /// millimetre at a time (`body_check::balanced`): a posture it holds
    /// is held there (with the feet moved no farther than the legs lean),
    /// and one it says tips is not held anywhere within that lean.
    #[test]
    fn the_balance_agrees_with_a_search_of_where_the_feet_may_go(
        person in 0usize..3,
        fractions in prop::collection::vec(0.0..1.0f64, 11),
    ) {
        let name = ["woman_5th", "man_50th", "man_95th"][person];
        let body = reach::stdlib::body("people", name).unwrap();
        let physique = reach::scene::Physique::of(&body);
        let own = OwnBody::default().standing(&physique);
        let balance = own.balance.as_ref().unwrap();
        let chain = body.chain_named(Some("grip")).unwrap();
        let mut q = posture(&chain, &fractions);
        chain.pull_in(&mut q);
        let reported = reach::report::Posture::new(&chain, &q);
        let margin = 0.02;
        match balance.feet_moved_mm(&chain.volumes(&q)) {
            Ok(moved) => {
                prop_assert!(moved.norm() <= balance.feet_shift_max_mm() + 1e-9);
                prop_assert!(balanced(&body, "grip", &reported, SUPPORT_SHARE + margin, false));
            }
            Err(_) => prop_assert!(!balanced(&body, "grip", &reported, SUPPORT_SHARE - margin, false)),
        }
    }
}
