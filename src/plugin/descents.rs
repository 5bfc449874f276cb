//! The descents a search has made, kept for a solver blind to the room
//! ([`Solver::blind_to_room`]): a descent's posture then depends only on
//! where it starts and on the target in the base frame, so a descent from
//! the same start to the same target is made once and judged at each base
//! pose (its distance from that pose's target, and what it runs into
//! there), as a descent of its own would be. Every descent is made to the
//! target rounded to a 1e-6 mm grid, so that what is kept is exactly what
//! a new descent would give: no answer depends on what was kept.
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

use super::{BasePose, IkProblem, IkSolution, Placement, ReachQuery, Solver};
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
        self.kept_or_solved(query, chain, pose, solver, Some(start))
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
        self.kept_or_solved(query, chain, pose, solver, None)
    }

    /// The kept descent from `start` to `pose`'s target, or a new one,
    /// kept; judged at `pose`. Every descent is made to its target's cell
    /// of the [`SAME_TARGET_MM`] grid rather than the target itself, so a
    /// kept descent is exactly the descent a new one would be: a descent
    /// can end elsewhere when its target moves by the 1e-12 mm that
    /// turning it into a heading's frame and back moves it, and a kept
    /// posture must never stand for a different answer.
    fn kept_or_solved(
        &mut self,
        query: &ReachQuery<'_>,
        chain: &Chain,
        pose: BasePose,
        solver: &dyn Solver,
        start: Option<&[f64]>,
    ) -> Placement {
        let key = target_key(&pose.to_base(&query.target_room_mm));
        let known = self
            .made
            .get(&key)
            .and_then(|made| made.iter().find(|m| m.start.as_deref() == start));
        if let Some(made) = known {
            return judged(query, chain, pose, made);
        }
        let problem = IkProblem {
            target_mm: key_point(key),
            ..query.problem(chain, pose)
        };
        let placement = query.solve_problem(&problem, pose, solver, start.map(<[f64]>::to_vec));
        if self.count == KEPT {
            self.made.clear();
            self.count = 0;
        }
        self.count += 1;
        let made = Made {
            start: start.map(<[f64]>::to_vec),
            q: placement.solution.q,
            iterations: placement.solution.iterations,
        };
        let placement = judged(query, chain, pose, &made);
        self.made.entry(key).or_default().push(made);
        placement
    }
}

/// `target_mm`'s cell of the [`SAME_TARGET_MM`] grid.
fn target_key(target_mm: &Point3<f64>) -> TargetKey {
    let cell = |c: f64| (c / SAME_TARGET_MM).round() as i64;
    [cell(target_mm.x), cell(target_mm.y), cell(target_mm.z)]
}

/// The point cell `key` stands for: inside the cell, off its middle by
/// a different fraction on each axis, so that a target on a plane of the
/// arm's symmetry (its side offset 0 in the base frame) stays off it by
/// about 3e-7 mm as it was off it by 1e-12 mm, rather than landing on it
/// exactly, where a descent can stall (descents made to the middles of
/// the cells lost 86 reached points of 280,000 on 160 random maps, and
/// gained 52).
fn key_point(key: TargetKey) -> Point3<f64> {
    // Fractions chosen only to differ (0.318 is not meant as 1/pi).
    #[allow(clippy::approx_constant)]
    const OFF: [f64; 3] = [0.318, 0.271, 0.229];
    let at = |axis: usize| (key[axis] as f64 + OFF[axis]) * SAME_TARGET_MM;
    Point3::new(at(0), at(1), at(2))
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
