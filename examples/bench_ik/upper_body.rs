//! FABRIK rows on the upper body of `std::body` with two effectors, the
//! grip and the eyes, each with a target: the effector positions of the
//! same random posture (so every problem has a solution), the look link
//! kept between 250 mm and 3 m. With a box obstacle (a shelf board across
//! the space in front of the chest), targets come from postures whose
//! links all miss the board, and the solver must keep them so. The grip
//! has priority: weight 1 against 0.1 for the eyes in the sub-base's goal
//! (equal weights: 93 % instead of 95 %, and slower).

use nalgebra::{Point3, Vector3};
use rand_chacha::rand_core::SeedableRng;
use rand_chacha::ChaCha8Rng;
use reach::collision::{Obstacles, PlacedObstacles};
use reach::kinematics::{Body, Chain};
use reach::plugin::{BasePose, Settings};
use reach::scene::{BoxObstacle, OwnBody, Room};
use reach::solvers::fabrik::{solve_tree, TreeGoal, TreeProblem};
use reach::solvers::{random_posture, FabrikSettings};

use super::{measure, Row, TOLERANCE_MM};

const SEED: u64 = 7;

/// The body with its look link between 250 mm and 3 m.
fn body() -> Body {
    let mut body = reach::stdlib::body("body", "upper_body").expect("std::body checks");
    let look = body
        .joints
        .iter_mut()
        .find(|j| j.name == "look")
        .expect("a look link");
    (look.min, look.max, look.neutral) = (250.0, 3000.0, 250.0);
    body
}

/// Where the body's base stands in the room: its middle, far from the
/// floor (an obstacle), the walls and the ceiling.
const BASE_MM: [f64; 3] = [5e4, 5e4, 5e4];

/// The most random postures drawn for each target pair asked: a bench
/// whose postures all hit something stops with a message, not a hang.
const TRIES_PER_TARGET: usize = 10_000;

/// A room holding the body's base at [`BASE_MM`], with a board in front
/// of the chest when `board`.
fn room(board: bool) -> Room {
    Room {
        name: "bench".into(),
        size_mm: Vector3::new(1e5, 1e5, 1e5),
        boxes: board
            .then(|| BoxObstacle {
                name: "board".into(),
                corner_mm: Point3::from(BASE_MM) + Vector3::new(250.0, -400.0, 300.0),
                size_mm: Vector3::new(300.0, 800.0, 20.0),
                yaw_rad: 0.0,
            })
            .into_iter()
            .collect(),
        meshes: Vec::new(),
        targets: vec![],
        surfaces: vec![],
        doors: Vec::new(),
    }
}

/// Grip and eye targets of random postures whose links miss the obstacles
/// (and each other).
fn targets(body: &Body, placed: Option<&PlacedObstacles<'_>>, n: usize) -> Vec<[Point3<f64>; 2]> {
    // The grip's and the eyes' joints (not the left arm).
    let used = body.joints_to(&[0, 1]);
    let whole = Chain::new(
        used.iter().map(|&j| body.joints[j].clone()).collect(),
        "",
        Vector3::zeros(),
    );
    let chains = [body.chain(0), body.chain(1)];
    let paths = [0, 1].map(|e| body.path(body.effectors[e].joint));
    let mut rng = ChaCha8Rng::seed_from_u64(SEED);
    let mut out = Vec::with_capacity(n);
    for _ in 0..n * TRIES_PER_TARGET {
        if out.len() == n {
            break;
        }
        let mut q = vec![0.0; body.joints.len()];
        for (&j, v) in used.iter().zip(random_posture(&whole, &mut rng)) {
            q[j] = v;
        }
        let qs = paths
            .clone()
            .map(|p| p.iter().map(|&j| q[j]).collect::<Vec<_>>());
        let clear =
            placed.is_none_or(|o| (0..2).all(|e| o.posture_hit(&chains[e], &qs[e], 0.0).is_none()));
        if clear {
            out.push([0, 1].map(|e| chains[e].effector(&qs[e])));
        }
    }
    assert_eq!(
        out.len(),
        n,
        "{TRIES_PER_TARGET} random postures per target and still too few miss the room and the body"
    );
    out
}

fn settings() -> FabrikSettings {
    FabrikSettings {
        starts: 1,
        ..FabrikSettings::with_defaults()
    }
}

/// The two rows: without and with the board.
pub fn rows(solves: usize) -> Vec<Row> {
    let body = body();
    let settings = settings();
    [
        ("fabrik-upper-body", false),
        ("fabrik-upper-body-box", true),
    ]
    .into_iter()
    .map(|(name, board)| {
        let obstacles = Obstacles::new(&room(board), 0.0);
        let own = OwnBody::default();
        let placed = board.then_some(PlacedObstacles {
            obstacles: &obstacles,
            own: &own,
            base_pose: BasePose {
                position_mm: Point3::from(BASE_MM),
                heading_rad: 0.0,
            },
        });
        let targets = targets(&body, placed.as_ref(), solves);
        let mut row = measure(name, &vec![Point3::origin(); solves], |i, _| {
            let [grip, eyes] = targets[i];
            let goals = [
                TreeGoal {
                    effector: 0,
                    target_mm: grip,
                    weight: 1.0,
                },
                TreeGoal {
                    effector: 1,
                    target_mm: eyes,
                    weight: 0.1,
                },
            ];
            let s = solve_tree(
                &settings,
                &TreeProblem {
                    body: &body,
                    goals: &goals,
                    tolerance_mm: TOLERANCE_MM,
                    seed: i as u64,
                    obstacles: placed,
                    allowance: &reach::allowance::Unbounded,
                },
            );
            // A solve counts when both effectors reach and no link
            // passes through the board: a collision counts as missing
            // by the tolerance more than the farther effector does.
            let farther = s.distances_mm.iter().copied().fold(0.0, f64::max);
            let distance = farther
                + if s.collision.is_some() {
                    TOLERANCE_MM
                } else {
                    0.0
                };
            (distance, Some(s.iterations as f64))
        });
        row.dof = body.joints_to(&[0, 1]).len();
        row.effectors = 2;
        row
    })
    .collect()
}

/// A markdown table of the rows.
pub fn print_table(rows: &[Row]) {
    println!();
    println!(
        "FABRIK on std::body's upper body ({} joints), two effectors (grip and eyes) with a target each; tolerance 5 mm",
        rows[0].dof
    );
    println!();
    println!("| solver | success | mean µs | median µs | mean passes |");
    println!("|---|---:|---:|---:|---:|");
    for r in rows {
        println!(
            "| {} | {:.2} % | {:.2} | {:.2} | {:.1} |",
            r.solver,
            r.success * 100.0,
            r.mean_us,
            r.median_us,
            r.mean_iterations.unwrap_or(0.0)
        );
    }
}
