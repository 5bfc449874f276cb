//! The search every base shares: the solver is run from each candidate
//! placement in order of promise, and the kept placement is the most
//! comfortable one that reaches, or else the closest. With
//! [`Search::FirstReaching`] (maps) the search stops at the first that
//! reaches.
//!
//! Where the room's obstacles are checked and no placement reaches, the
//! most promising placements where the solver's posture reached the target
//! through an obstacle are tried again with the query's [`Retry`] solver
//! (by default `incremental` with 64 starts) before the target is called
//! unreachable: a solver that ignores obstacles while it searches can miss
//! postures that go round a board, and an unreachable answer must mean
//! unreachable.

use crate::kinematics::Chain;
use crate::plugin::{BasePose, Placement, ReachQuery, Retry, Search, Solver};
use crate::scene::Preferred;

/// The placement kept over `poses` (none when there are no poses).
pub fn search(
    query: &ReachQuery<'_>,
    chain: &Chain,
    poses: &[BasePose],
    solver: &dyn Solver,
) -> Option<Placement> {
    let mut best = Preferred::new(query.tolerance_mm);
    let mut blocked = Vec::new();
    for &pose in poses {
        let placement = query.solve_at(chain, pose, solver);
        if placement.solution.collision.is_some()
            && placement.solution.distance_mm <= query.tolerance_mm
        {
            blocked.push(pose);
        }
        let comfort = chain.discomfort(&placement.solution.q);
        best.offer(placement, comfort);
        if best.reaches() && query.search == Search::FirstReaching {
            return best.into_kept();
        }
    }
    if let (false, Some(retry)) = (best.reaches(), query.retry) {
        retry_blocked(query, chain, &blocked, retry, &mut best);
    }
    best.into_kept()
}

/// Try again from the first `retry.placements` of the `blocked` poses (the
/// solver's posture there reached the target through an obstacle), until
/// one reaches.
fn retry_blocked(
    query: &ReachQuery<'_>,
    chain: &Chain,
    blocked: &[BasePose],
    retry: Retry<'_>,
    best: &mut Preferred<Placement>,
) {
    for &pose in blocked.iter().take(retry.placements) {
        let mut placement = query.retried().solve_at(chain, pose, retry.solver);
        placement.retried = true;
        let comfort = chain.discomfort(&placement.solution.q);
        best.offer(placement, comfort);
        if best.reaches() {
            return;
        }
    }
}
