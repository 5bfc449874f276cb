//! The descents one search has made, for a solver blind to the room
//! ([`Solver::blind_to_room`]): a capability map's sample turned by each
//! heading puts the hand on the target the same way, so the target is
//! the same point of the base frame at every heading, and a descent from
//! the sample's posture ends at the same posture. It is made once and
//! judged at each base pose (its distance to that pose's target, and what
//! it runs into there), as a descent of its own would be.

use nalgebra::Point3;

use crate::kinematics::Chain;
use crate::plugin::{BasePose, IkSolution, Placement, ReachQuery, Solver};

/// Two targets of the base frame closer than this are one: a target
/// turned into a heading's frame and back differs from itself by about
/// 1e-12 mm.
const SAME_TARGET_MM: f64 = 1e-6;

/// The most descents kept: a search seeds at most `placement::SEEDED`.
const KEPT: usize = 32;

/// A descent made: from where, to which target of the base frame, and
/// the posture it ended at.
struct Made {
    start: Vec<f64>,
    target_mm: Point3<f64>,
    q: Vec<f64>,
    iterations: u64,
}

/// The descents of one search.
#[derive(Default)]
pub(super) struct Descents {
    made: Vec<Made>,
}

impl Descents {
    /// One descent of `solver` from `start` at `pose`, or the posture a
    /// descent from the same start to the same target already ended at,
    /// judged at `pose`.
    pub fn solve_from_at(
        &mut self,
        query: &ReachQuery<'_>,
        chain: &Chain,
        pose: BasePose,
        solver: &dyn Solver,
        start: &[f64],
    ) -> Placement {
        if !solver.blind_to_room() {
            return query.solve_from_at(chain, pose, solver, start.to_vec());
        }
        let target_mm = pose.to_base(&query.target_room_mm);
        let known = self
            .made
            .iter()
            .find(|m| m.start == start && (m.target_mm - target_mm).norm() <= SAME_TARGET_MM);
        if let Some(made) = known {
            return judged(query, chain, pose, made);
        }
        let placement = query.solve_from_at(chain, pose, solver, start.to_vec());
        if self.made.len() < KEPT {
            self.made.push(Made {
                start: start.to_vec(),
                target_mm,
                q: placement.solution.q.clone(),
                iterations: placement.solution.iterations,
            });
        }
        placement
    }
}

/// `made`'s posture at `pose`: its distance from the target there, and
/// its collision checked as `ReachQuery::solve_from_at` checks it.
fn judged(query: &ReachQuery<'_>, chain: &Chain, pose: BasePose, made: &Made) -> Placement {
    let problem = query.problem(chain, pose);
    let q = made.q.clone();
    let solution = IkSolution {
        distance_mm: (chain.effector(&q) - problem.target_mm).norm(),
        collision: problem.collision_charged(&q),
        q,
        iterations: made.iterations,
    };
    Placement {
        pose,
        solution,
        retried: false,
    }
}

#[cfg(test)]
mod tests {
    use nalgebra::{Point3, Vector3};

    use super::*;
    use crate::collision::Obstacles;
    use crate::kinematics::{Dh, Joint, JointKind, Link};
    use crate::meter::Meter;
    use crate::options::Settings;
    use crate::plugin::Search;
    use crate::scene::{BoxObstacle, OwnBody, Room};
    use crate::solvers::{IncrementalSettings, IncrementalSolver};

    /// A planar arm of three links (300, 250 and 150 mm) turning about
    /// vertical axes.
    fn arm() -> Chain {
        let joint = |name: &str, a_mm: f64| Joint {
            name: name.into(),
            kind: JointKind::Revolute,
            dh: Dh::new(0.0, 0.0, 0.0, a_mm),
            fixed: None,
            min: -3.0,
            max: 3.0,
            neutral: 0.0,
            weight: 1.0,
            link: Link::named(name),
        };
        Chain::new(
            vec![joint("a", 300.0), joint("b", 250.0), joint("c", 150.0)],
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

    /// The same start and target of the base frame at two headings: one
    /// descent, judged at each pose as a descent of its own is, so that
    /// the wall in the way of the second pose is found there.
    #[test]
    fn a_descent_is_made_once_and_judged_at_each_pose() {
        let (chain, room) = (arm(), room());
        let obstacles = Obstacles::new(&room, 0.0);
        let own = OwnBody::default();
        let solver = IncrementalSolver {
            settings: IncrementalSettings::defaults().expect("defaults are valid"),
        };
        let target_room_mm = Point3::new(2000.0, 2000.0, 1000.0);
        let query = ReachQuery {
            target_room_mm,
            tolerance_mm: 10.0,
            seed: 7,
            search: Search::FirstReaching,
            obstacles: Some(&obstacles),
            own: &own,
            retry: None,
            proofs: None,
            last_resort: None,
            from_rest: false,
            meter: Meter::unmetered(),
        };
        let pose = |heading_rad: f64| {
            let (s, c) = heading_rad.sin_cos();
            BasePose {
                position_mm: target_room_mm - Vector3::new(400.0 * c, 400.0 * s, 0.0),
                heading_rad,
            }
        };
        let (east, north) = (pose(0.0), pose(std::f64::consts::FRAC_PI_2));
        let start = [0.3, 0.4, -0.2];
        let mut descents = Descents::default();
        let first = descents.solve_from_at(&query, &chain, east, &solver, &start);
        let again = descents.solve_from_at(&query, &chain, north, &solver, &start);
        assert_eq!(descents.made.len(), 1, "the second is not descended");
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
}
