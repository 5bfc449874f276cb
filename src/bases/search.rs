//! The search every base shares: the solver is run from each candidate
//! placement in order of promise, and the kept placement is the most
//! comfortable one that reaches, or else the closest. With
//! [`Search::FirstReaching`] (maps) the search stops at the first that
//! reaches.
//!
//! Where the room's obstacles are checked and no placement reaches, the
//! most promising placements where the solver's posture reached the target
//! through something (an obstacle, the person's own body, their chair) are
//! tried again with the query's [`Retry`] solver before the target is
//! called unreachable: a solver that ignores obstacles while it searches
//! can miss postures that go round a board, and an unreachable answer must
//! mean unreachable. The retry starts near the blocked posture (most of
//! the way round is usually a small change of it) and, one start in four,
//! anywhere. A retry that does not reach changes nothing (the answer shows
//! the first search's closest): a placement proved hopeless
//! (`engine::KeptProofs`) is skipped, and the answer must be the same
//! whether or not the proof was made.

use crate::engine::KeptProofs;
use crate::kinematics::Chain;

use crate::plugin::{BasePose, Descents, IkProblem, Placement, ReachQuery, Retry, Search, Solver};
use crate::scene::{Blocked, Preferred};
use crate::solvers::Kicks;

/// A placement to try: the base pose and, where one is known (a
/// capability map's sample), the posture to start from.
#[derive(Clone, Debug)]
pub struct Candidate {
    pub pose: BasePose,
    pub start: Option<Vec<f64>>,
    /// Tried only while no placement before it has reached: a last
    /// resort, not a choice among comfortable placements.
    pub fallback: bool,
}

impl Candidate {
    /// A pose with no known posture: the solver's own starts.
    pub fn at(pose: BasePose) -> Self {
        Candidate {
            pose,
            start: None,
            fallback: false,
        }
    }

    /// A pose tried only if nothing before it reached.
    pub fn fallback(pose: BasePose) -> Self {
        Candidate {
            fallback: true,
            ..Candidate::at(pose)
        }
    }
}

/// The placement kept over `candidates` (none when there are none): from
/// a candidate with a start, one descent of the solver from it; from one
/// without, the solver's own starts. Candidates from which the target is
/// beyond the chain's reach (longer than its links end to end), or that
/// the query's kept proofs put beyond the trunk's joint limits and the
/// arm's length (body or none: no posture comes within the tolerance, so
/// the placement would not even be blocked), are passed over,
/// but if all are, the first is solved, so that the answer still shows the
/// closest the person came. The query's last resort, if it has one, is the
/// last candidate. The candidates are drawn as they are needed: a search
/// that stops at the first placement that reaches works out no more of
/// them.
pub fn search(
    query: &ReachQuery<'_>,
    chain: &Chain,
    candidates: impl IntoIterator<Item = Candidate>,
    solver: &dyn Solver,
) -> Option<Placement> {
    let (mut best, blocked) = first_search(query, chain, candidates, solver);
    if let (false, Some(retry)) = (best.reaches(), query.retry) {
        retry_blocked(query, chain, &blocked, retry, &mut best);
    }
    best.into_kept()
}

/// [`search`] without its retry: the placement kept, and where none
/// reaches, the blocked placements the retry would start from
/// ([`retry`]).
pub fn search_retrying_later(
    query: &ReachQuery<'_>,
    chain: &Chain,
    candidates: impl IntoIterator<Item = Candidate>,
    solver: &dyn Solver,
) -> (Option<Placement>, Vec<Blocked>) {
    let (best, blocked) = first_search(query, chain, candidates, solver);
    if best.reaches() {
        return (best.into_kept(), Vec::new());
    }
    (best.into_kept(), blocked)
}

/// The retry [`search`] makes, from `blocked` (what
/// [`search_retrying_later`] left): the placement that reaches, if one
/// does. None without the query's retry.
pub fn retry(query: &ReachQuery<'_>, chain: &Chain, blocked: &[Blocked]) -> Option<Placement> {
    let retry = query.retry?;
    let mut best = Preferred::new(query.tolerance_mm);
    retry_blocked(query, chain, blocked, retry, &mut best);
    best.into_kept()
}

/// The search before its retry: the placements offered, and the blocked.
fn first_search(
    query: &ReachQuery<'_>,
    chain: &Chain,
    candidates: impl IntoIterator<Item = Candidate>,
    solver: &dyn Solver,
) -> (Preferred<Placement>, Vec<Blocked>) {
    let mut best = Preferred::new(query.tolerance_mm);
    let mut blocked = Vec::new();
    let bound_mm = chain.reach_bound_mm() + query.tolerance_mm;
    let mut first_passed = None;
    let mut any_solved = false;
    let mut own_descents = Descents::default();
    let mut kept = query.descents.map(|d| d.borrow_mut());
    let mut tried = Tried {
        best: &mut best,
        blocked: &mut blocked,
        descents: kept.as_deref_mut().unwrap_or(&mut own_descents),
    };
    let last_resort = query.last_resort.map(|(pose, q)| Candidate {
        pose,
        start: Some(q.to_vec()),
        fallback: true,
    });
    for candidate in candidates.into_iter().chain(last_resort) {
        // Fallbacks come last: once one placement reaches, none is drawn.
        if candidate.fallback && tried.best.reaches() {
            break;
        }
        let target_mm = candidate.pose.to_base(&query.target_room_mm);
        let hopeless = target_mm.coords.norm() > bound_mm
            || query
                .proofs
                .is_some_and(|p| p.beyond_limits(&target_mm, query.tolerance_mm));
        if hopeless {
            if first_passed.is_none() && !any_solved {
                first_passed = Some(candidate);
            }
            continue;
        }
        any_solved = true;
        if try_candidate(query, chain, &candidate, solver, &mut tried) {
            return (best, blocked);
        }
    }
    if let (false, Some(candidate)) = (any_solved, first_passed) {
        try_candidate(query, chain, &candidate, solver, &mut tried);
    }
    (best, blocked)
}

/// What a search has found so far: the placement it keeps, the blocked
/// ones, and the descents it made.
struct Tried<'s> {
    best: &'s mut Preferred<Placement>,
    blocked: &'s mut Vec<Blocked>,
    descents: &'s mut Descents,
}

/// Solve from `candidate`, offer the placement to `best` and note it in
/// `blocked` if it reached through something; whether the search may stop
/// there (it reaches, and the first that reaches will do).
fn try_candidate(
    query: &ReachQuery<'_>,
    chain: &Chain,
    candidate: &Candidate,
    solver: &dyn Solver,
    tried: &mut Tried<'_>,
) -> bool {
    let pose = candidate.pose;
    let placement = match &candidate.start {
        Some(start) => tried
            .descents
            .solve_from_at(query, chain, pose, solver, start),
        None => tried.descents.solve_at(query, chain, pose, solver),
    };
    let solution = &placement.solution;
    if solution.collision.is_some() && solution.distance_mm <= query.tolerance_mm {
        tried.blocked.push(Blocked {
            pose,
            q: solution.q.clone(),
        });
    }
    let rank = rank(query, chain, &placement);
    tried.best.offer(placement, rank);
    tried.best.reaches() && query.search == Search::FirstReaching
}

/// How a placement that reaches ranks among those that do (lower is
/// better): its discomfort, and [`BEHIND_RANK`] more where the target is
/// behind the person, so that a posture reaching back behind the hips is
/// kept only where no placement facing the target reaches it.
fn rank(query: &ReachQuery<'_>, chain: &Chain, placement: &Placement) -> f64 {
    let behind = placement.pose.has_behind(&query.target_room_mm);
    chain.discomfort(&placement.solution.q) + if behind { BEHIND_RANK } else { 0.0 }
}

/// Far more than any posture's discomfort (a sum of squared, weighted
/// distances from neutral: tens at the joints' ends).
const BEHIND_RANK: f64 = 1e6;

/// The first of up to `draws` starts that is clear of obstacles and of
/// the person's own body (a solver that steers clear stays clear from it),
/// or the last drawn if none is.
fn clear_start(problem: &IkProblem<'_>, kicks: &mut Kicks<'_>, draws: usize) -> Vec<f64> {
    let mut start = Vec::new();
    for _ in 0..draws {
        start = kicks.next().unwrap_or_default();
        if problem.collision_charged(&start).is_none() {
            break;
        }
    }
    start
}

/// How many starts are drawn at most for one that is clear, for a solver
/// that steers clear (a check costs a microsecond or two, a descent tens).
const CLEAR_DRAWS: usize = 16;

/// Try again from the first `retry.placements` of the `blocked`
/// placements, until one reaches: from each, one descent of the retry
/// solver per start it has, the starts drawn around the blocked posture.
fn retry_blocked(
    query: &ReachQuery<'_>,
    chain: &Chain,
    blocked: &[Blocked],
    retry: Retry<'_>,
    best: &mut Preferred<Placement>,
) {
    let starts = retry.solver.starts() as usize;
    let made_here;
    let proofs = match query.proofs {
        Some(kept) => kept,
        None => {
            made_here = KeptProofs::new(chain, query.own, query.allowance);
            &made_here
        }
    };
    for (k, placement) in blocked.iter().take(retry.placements).enumerate() {
        let target_mm = placement.pose.to_base(&query.target_room_mm);
        if proofs.proves(&target_mm, query.tolerance_mm) {
            continue;
        }
        let problem = query.problem(chain, placement.pose);
        // The problem's seed holds where the target is from this placement.
        let seed = problem.seed ^ 0x7e72_1ed5_0000_0001 ^ ((k as u64) << 32);
        let mut kicks = Kicks::new(chain, &placement.q, retry.spread, seed);
        let draws = if retry.solver.steers_clear() {
            CLEAR_DRAWS
        } else {
            1
        };
        for _ in 0..starts {
            let start = clear_start(&problem, &mut kicks, draws);
            let mut tried = query.solve_from_at(chain, placement.pose, retry.solver, start);
            if !tried.solution.reaches(query.tolerance_mm) {
                // Nearer or not, the answer stays the first search's: a
                // retry skipped (proved hopeless) must change nothing.
                continue;
            }
            tried.retried = true;
            let rank = rank(query, chain, &tried);
            best.offer(tried, rank);
            if query.search == Search::FirstReaching {
                return;
            }
        }
        if best.reaches() {
            return;
        }
    }
}
