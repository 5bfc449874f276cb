//! [`Descents`] (`plugin/descents.rs`) tested with a solver of this
//! crate: a descent from the same start to the same target of the base
//! frame is made once, and judged at each base pose as a descent of its
//! own would be.

use std::f64::consts::FRAC_PI_2;
use std::sync::atomic::{AtomicUsize, Ordering};

use nalgebra::{Point3, Vector3};

use crate::collision::Obstacles;
use crate::kinematics::revolute;
use crate::kinematics::Chain;
use crate::meter::Meter;
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
        meter: Meter::unmetered(),
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
        solver: IncrementalSolver {
            settings: IncrementalSettings::defaults().expect("defaults are valid"),
        },
        descents: AtomicUsize::new(0),
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

/// A solver that counts its descents from a given start.
struct Counted {
    solver: IncrementalSolver,
    descents: AtomicUsize,
}

impl Solver for Counted {
    fn solve(&self, problem: &IkProblem<'_>) -> IkSolution {
        self.descents.fetch_add(1, Ordering::Relaxed);
        self.solver.solve(problem)
    }

    fn solve_until_reached(&self, problem: &IkProblem<'_>) -> IkSolution {
        self.descents.fetch_add(1, Ordering::Relaxed);
        self.solver.solve_until_reached(problem)
    }

    fn solve_from(&self, problem: &IkProblem<'_>, start: Vec<f64>) -> IkSolution {
        self.descents.fetch_add(1, Ordering::Relaxed);
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
            solver: IncrementalSolver {
                settings: IncrementalSettings { starts, ..defaults },
            },
            descents: AtomicUsize::new(0),
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
