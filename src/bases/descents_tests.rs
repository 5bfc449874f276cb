//! [`Descents`] (`plugin/descents.rs`) tested with a solver of this
//! crate: a descent from the same start to the same target of the base
//! frame is made once, and judged at each base pose as a descent of its
//! own would be, exactly: no answer depends on what was kept.

use std::f64::consts::FRAC_PI_2;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;

use nalgebra::{Point3, Vector3};
use proptest::prelude::*;

use crate::allowance::Unbounded;
use crate::collision::Obstacles;
use crate::kinematics::revolute;
use crate::kinematics::Chain;
use crate::options::Settings;
use crate::plugin::{BasePose, Descents, IkProblem, IkSolution, ReachQuery, Search, Solver};
use crate::scene::{BoxObstacle, OwnBody, Room};
use crate::solvers::{IncrementalSettings, IncrementalSolver};

/// A planar arm of three links (300, 250 and 150 mm) turning about
/// vertical axes.
fn arm() -> Chain {
    Chain::new(
        vec![
            revolute("a", 0.0, 0.0, 0.0, 300.0),
            revolute("b", 0.0, 0.0, 0.0, 250.0),
            revolute("c", 0.0, 0.0, 0.0, 150.0),
        ],
        "tip",
        Vector3::zeros(),
    )
}

/// A room with a thin wall across the way from the second base pose
/// to the target, out of the way of the first.
fn room() -> Room {
    Room {
        name: "r".into(),
        size_mm: Vector3::new(4000.0, 4000.0, 2500.0),
        boxes: vec![BoxObstacle {
            name: "wall".into(),
            corner_mm: Point3::new(1900.0, 1750.0, 0.0),
            size_mm: Vector3::new(200.0, 10.0, 2500.0),
            yaw_rad: 0.0,
        }],
        meshes: Vec::new(),
        targets: Vec::new(),
        surfaces: Vec::new(),
        doors: Vec::new(),
    }
}

/// A query for `target_room_mm` among `obstacles`.
fn query<'a>(
    target_room_mm: Point3<f64>,
    obstacles: &'a Obstacles,
    own: &'a OwnBody,
) -> ReachQuery<'a> {
    ReachQuery {
        target_room_mm,
        tolerance_mm: 10.0,
        seed: 7,
        search: Search::FirstReaching,
        obstacles: Some(obstacles),
        own,
        retry: None,
        proofs: None,
        last_resort: None,
        from_rest: false,
        descents: None,
        allowance: &Unbounded,
        solves: None,
    }
}

/// The base pose at `heading_rad` 400 mm from `target_room_mm`, facing it.
fn pose(target_room_mm: Point3<f64>, heading_rad: f64) -> BasePose {
    let (s, c) = heading_rad.sin_cos();
    BasePose {
        position_mm: target_room_mm - Vector3::new(400.0 * c, 400.0 * s, 0.0),
        heading_rad,
    }
}

/// The same start and target of the base frame at two headings: one
/// descent, judged at each pose as a descent of its own is, so that
/// the wall in the way of the second pose is found there.
#[test]
fn a_descent_is_made_once_and_judged_at_each_pose() {
    let (chain, room) = (arm(), room());
    let obstacles = Obstacles::new(&room, 0.0);
    let own = OwnBody::default();
    let solver = Counted {
        solver: IncrementalSolver::new(
            IncrementalSettings::defaults().expect("defaults are valid"),
        ),
        descents: AtomicUsize::new(0),
        targets_mm: Mutex::new(Vec::new()),
    };
    let target_room_mm = Point3::new(2000.0, 2000.0, 1000.0);
    let query = query(target_room_mm, &obstacles, &own);
    let (east, north) = (pose(target_room_mm, 0.0), pose(target_room_mm, FRAC_PI_2));
    let start = [0.3, 0.4, -0.2];
    let mut descents = Descents::default();
    let first = descents.solve_from_at(&query, &chain, east, &solver, &start);
    let again = descents.solve_from_at(&query, &chain, north, &solver, &start);
    assert_eq!(
        solver.descents.load(Ordering::Relaxed),
        1,
        "the second is not descended"
    );
    let fresh = query.solve_from_at(&chain, north, &solver, start.to_vec());
    assert!(first.solution.reaches(10.0), "{:?}", first.solution);
    assert!(first.solution.collision.is_none());
    for (a, b) in again.solution.q.iter().zip(&fresh.solution.q) {
        assert!(
            (a - b).abs() < 1e-9,
            "{:?} {:?}",
            again.solution,
            fresh.solution
        );
    }
    assert!((again.solution.distance_mm - fresh.solution.distance_mm).abs() < 1e-9);
    assert!(again.solution.collision.is_some(), "the wall is in the way");
    assert_eq!(again.solution.collision, fresh.solution.collision);
    assert_eq!(again.pose, north);
}

/// A solver that counts its descents, and notes the target of each.
struct Counted {
    solver: IncrementalSolver,
    descents: AtomicUsize,
    targets_mm: Mutex<Vec<Point3<f64>>>,
}

impl Counted {
    fn note(&self, problem: &IkProblem<'_>) {
        self.descents.fetch_add(1, Ordering::Relaxed);
        let mut targets_mm = self.targets_mm.lock().expect("not poisoned");
        targets_mm.push(problem.target_mm);
    }
}

impl Solver for Counted {
    fn solve(&self, problem: &IkProblem<'_>) -> IkSolution {
        self.note(problem);
        self.solver.solve(problem)
    }

    fn solve_until_reached(&self, problem: &IkProblem<'_>) -> IkSolution {
        self.note(problem);
        self.solver.solve_until_reached(problem)
    }

    fn solve_from(&self, problem: &IkProblem<'_>, start: Vec<f64>) -> IkSolution {
        self.note(problem);
        self.solver.solve_from(problem, start)
    }

    fn blind_to_room(&self) -> bool {
        self.solver.blind_to_room()
    }

    fn seeded(&self) -> bool {
        self.solver.seeded()
    }
}

/// A solve from the solver's own starts is kept only where they do not
/// depend on the seed: one start, the neutral posture.
#[test]
fn a_solve_from_its_own_starts_is_kept_only_where_no_seed_is_drawn() {
    let (chain, room) = (arm(), room());
    let obstacles = Obstacles::new(&room, 0.0);
    let own = OwnBody::default();
    let target_room_mm = Point3::new(2000.0, 2000.0, 1000.0);
    for (starts, solves) in [(1, 1), (6, 2)] {
        let defaults = IncrementalSettings::defaults().expect("defaults are valid");
        let solver = Counted {
            solver: IncrementalSolver::new(IncrementalSettings { starts, ..defaults }),
            descents: AtomicUsize::new(0),
            targets_mm: Mutex::new(Vec::new()),
        };
        let query = query(target_room_mm, &obstacles, &own);
        let mut descents = Descents::default();
        let east = pose(target_room_mm, 0.0);
        descents.solve_at(&query, &chain, pose(target_room_mm, FRAC_PI_2), &solver);
        let again = descents.solve_at(&query, &chain, east, &solver);
        let made = solver.descents.load(Ordering::Relaxed);
        assert_eq!(made, solves, "{starts} starts");
        let fresh = query.solve_at(&chain, east, &solver);
        for (a, b) in again.solution.q.iter().zip(&fresh.solution.q) {
            assert!((a - b).abs() < 1e-9, "{again:?} {fresh:?}");
        }
        assert_eq!(again.solution.collision, fresh.solution.collision);
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    /// What is kept is exactly what a new descent gives: a descent made at
    /// one heading and judged at another equals, bit for bit, the one a
    /// search that kept nothing makes there (the target turned into each
    /// heading's frame differs by about 1e-12 mm, enough for a descent to
    /// end elsewhere were it made to the target itself).
    #[test]
    fn a_kept_descent_is_the_descent_a_new_one_would_be(
        x in 1500.0..2500.0f64,
        y in 1500.0..2500.0f64,
        first_rad in 0.0..6.3f64,
        turns in 1..12u32,
        ahead_mm in 150.0..650.0f64,
        aside_mm in -300.0..300.0f64,
        start in proptest::collection::vec(-2.0..2.0f64, 3),
        from_own_starts in any::<bool>(),
    ) {
        let (chain, room) = (arm(), room());
        let obstacles = Obstacles::new(&room, 0.0);
        let own = OwnBody::default();
        let solver = Counted {
            solver: IncrementalSolver::new(IncrementalSettings {
                starts: 1,
                ..IncrementalSettings::defaults().expect("defaults are valid")
            }),
            descents: AtomicUsize::new(0),
            targets_mm: Mutex::new(Vec::new()),
        };
        let target_room_mm = Point3::new(x, y, 1000.0);
        let query = query(target_room_mm, &obstacles, &own);
        // The target `ahead_mm` ahead of the base and `aside_mm` to its
        // left at both headings.
        let at = |heading_rad: f64| {
            let (s, c) = heading_rad.sin_cos();
            let base_to_target = Vector3::new(ahead_mm * c - aside_mm * s, ahead_mm * s + aside_mm * c, 0.0);
            BasePose { position_mm: target_room_mm - base_to_target, heading_rad }
        };
        let (first, second) = (at(first_rad), at(first_rad + f64::from(turns) * 0.5));
        let solve = |descents: &mut Descents, at: BasePose| {
            if from_own_starts {
                descents.solve_at(&query, &chain, at, &solver)
            } else {
                descents.solve_from_at(&query, &chain, at, &solver, &start)
            }
        };
        let mut kept = Descents::default();
        solve(&mut kept, first);
        let again = solve(&mut kept, second);
        let fresh = solve(&mut Descents::default(), second);
        // The descent kept and the new one were made to one target.
        let targets_mm = solver.targets_mm.lock().expect("not poisoned").clone();
        prop_assert_eq!(targets_mm.len(), 2);
        prop_assert_eq!(targets_mm[0], targets_mm[1]);
        prop_assert_eq!(&again.solution.q, &fresh.solution.q);
        prop_assert_eq!(again.solution.distance_mm.to_bits(), fresh.solution.distance_mm.to_bits());
        prop_assert_eq!(again.solution.collision, fresh.solution.collision);
        prop_assert_eq!(again.solution.iterations, fresh.solution.iterations);
    }
}
