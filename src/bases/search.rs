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

/// The placement kept over `poses` (none when there are no poses).
pub fn search(
    query: &ReachQuery<'_>,
    chain: &Chain,
    poses: &[BasePose],
    solver: &dyn Solver,
) -> Option<Placement> {
    let mut best = Best::new(chain, query.tolerance_mm);
    let mut blocked = Vec::new();
    for &pose in poses {
        let placement = query.solve_at(chain, pose, solver);
        if placement.solution.collision.is_some()
            && placement.solution.distance_mm <= query.tolerance_mm
        {
            blocked.push(pose);
        }
        best.offer(placement);
        if best.reaches() && query.search == Search::FirstReaching {
            return best.kept();
        }
    }
    if let (false, Some(retry)) = (best.reaches(), query.retry) {
        retry_blocked(query, chain, &blocked, retry, &mut best);
    }
    best.kept()
}

/// Try again from the first `retry.placements` of the `blocked` poses (the
/// solver's posture there reached the target through an obstacle), until
/// one reaches.
fn retry_blocked(
    query: &ReachQuery<'_>,
    chain: &Chain,
    blocked: &[BasePose],
    retry: Retry<'_>,
    best: &mut Best<'_>,
) {
    for &pose in blocked.iter().take(retry.placements) {
        let mut placement = query.retried().solve_at(chain, pose, retry.solver);
        placement.retried = true;
        best.offer(placement);
        if best.reaches() {
            return;
        }
    }
}

/// The best placement so far and its discomfort.
struct Best<'a> {
    chain: &'a Chain,
    tolerance_mm: f64,
    kept: Option<(Placement, f64)>,
}

impl<'a> Best<'a> {
    fn new(chain: &'a Chain, tolerance_mm: f64) -> Self {
        Best {
            chain,
            tolerance_mm,
            kept: None,
        }
    }

    fn offer(&mut self, placement: Placement) {
        let comfort = self.chain.discomfort(&placement.solution.q);
        let better = self.kept.as_ref().is_none_or(|(kept, kept_comfort)| {
            placement.solution.preferred_to(
                comfort,
                &kept.solution,
                *kept_comfort,
                self.tolerance_mm,
            )
        });
        if better {
            self.kept = Some((placement, comfort));
        }
    }

    fn reaches(&self) -> bool {
        self.kept
            .as_ref()
            .is_some_and(|(kept, _)| kept.solution.reaches(self.tolerance_mm))
    }

    fn kept(self) -> Option<Placement> {
        self.kept.map(|(placement, _)| placement)
    }
}
