//! The descents a search has made, kept for a solver blind to the room
//! ([`Solver::blind_to_room`]): a descent's posture then depends only on
//! where it starts and on the target in the base frame, so a descent from
//! the same start to the same target is made once and judged at each base
//! pose (its distance from that pose's target, and what it runs into
//! there), as a descent of its own would be.
//!
//! The target in the base frame comes again and again: a capability
//! map's sample turned by each heading puts the hand on the target the
//! same way, and along a map's row the base stands in the same place
//! relative to each point (the same approach to the same counter). One
//! search keeps its own; a map's run of points, solved one after another
//! by one thread, keeps one for the whole run ([`ReachQuery::descents`]),
//! so what is kept never depends on the threads.

use std::collections::HashMap;

use nalgebra::Point3;

use super::{BasePose, IkSolution, Placement, ReachQuery, Solver};
use crate::kinematics::Chain;

/// The grid targets of the base frame are rounded to: a target turned
/// into a heading's frame and back differs from itself by about 1e-12 mm.
/// Two targets in one cell of it are one.
const SAME_TARGET_MM: f64 = 1e-6;

/// The most descents kept: past it, what is kept is let go and kept
/// afresh (about 200 bytes each).
const KEPT: usize = 4096;

/// A cell of the [`SAME_TARGET_MM`] grid.
type TargetKey = [i64; 3];

/// A descent made: where from (none: the solver's own start), and the
/// posture it ended at.
struct Made {
    start: Option<Vec<f64>>,
    q: Vec<f64>,
    iterations: u64,
}

/// Descents made, by their target in the base frame.
#[derive(Default)]
pub struct Descents {
    made: HashMap<TargetKey, Vec<Made>>,
    count: usize,
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
        self.kept_or(query, chain, pose, Some(start), || {
            query.solve_from_at(chain, pose, solver, start.to_vec())
        })
    }

    /// A solve of `solver` from its own starts at `pose` (as
    /// [`ReachQuery::solve_at`]), kept where those starts do not depend on
    /// the seed ([`Solver::seeded`]).
    pub fn solve_at(
        &mut self,
        query: &ReachQuery<'_>,
        chain: &Chain,
        pose: BasePose,
        solver: &dyn Solver,
    ) -> Placement {
        if !solver.blind_to_room() || solver.seeded() {
            return query.solve_at(chain, pose, solver);
        }
        self.kept_or(query, chain, pose, None, || {
            query.solve_at(chain, pose, solver)
        })
    }

    /// The kept descent from `start` to `pose`'s target judged at `pose`,
    /// or `solve`'s, kept.
    fn kept_or(
        &mut self,
        query: &ReachQuery<'_>,
        chain: &Chain,
        pose: BasePose,
        start: Option<&[f64]>,
        solve: impl FnOnce() -> Placement,
    ) -> Placement {
        let key = target_key(&pose.to_base(&query.target_room_mm));
        let known = self
            .made
            .get(&key)
            .and_then(|made| made.iter().find(|m| m.start.as_deref() == start));
        if let Some(made) = known {
            return judged(query, chain, pose, made);
        }
        let placement = solve();
        if self.count == KEPT {
            self.made.clear();
            self.count = 0;
        }
        self.count += 1;
        self.made.entry(key).or_default().push(Made {
            start: start.map(<[f64]>::to_vec),
            q: placement.solution.q.clone(),
            iterations: placement.solution.iterations,
        });
        placement
    }
}

/// `target_mm`'s cell of the [`SAME_TARGET_MM`] grid.
fn target_key(target_mm: &Point3<f64>) -> TargetKey {
    let cell = |c: f64| (c / SAME_TARGET_MM).round() as i64;
    [cell(target_mm.x), cell(target_mm.y), cell(target_mm.z)]
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
