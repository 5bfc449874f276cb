//! The meter of solver work: what a run's solvers spend, in units of
//! about the cost of moving one joint once (one step of a descent, one
//! bone of a FABRIK pass), with a solid checked against the room and the
//! body counted by the obstacles it is checked against
//! ([`capsule_check`]; a posture is [`POSTURE_CAPSULES`] solids). The count checked
//! before a run (`--max-solver-starts`) bounds how many solves may run;
//! the meter bounds what they cost, iterations and checks included, so
//! that a scenario asking for the costliest solves the count admits stops
//! with the limit named rather than running for hours. The routes from a
//! room's doors, a floor's costliest part, are counted in the same units
//! (`floor/region.rs`, `UNITS_PER_CORNER`), charged to the first task of
//! the scenario that places the person in the room.
//!
//! Every solve does the same work whatever thread runs it and whatever
//! ran before it, so the work of a whole run is a sum that does not
//! depend on the threads: a run either stays within the limit on every
//! machine and thread count, or passes it on each (a sum that only grows
//! passes a limit whatever order its terms come in). Once past, solves
//! stop early and the run's answers are thrown away.
//!
//! What one solve charges is counted by the allowances it is given
//! (`allowance::Counted`), so that a solve watch mode keeps from an
//! earlier run is charged what it cost when it ran (`engine::KeptSolves`).

use std::collections::{BTreeMap, BTreeSet};
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::{Arc, LazyLock, Mutex};

pub use crate::allowance::Allowance;
use crate::kept::Memo;

/// How many solids a posture check counts (an arm's links and hand).
pub const POSTURE_CAPSULES: u64 = 8;

/// How many of a room's obstacles a solid is checked against in the time
/// of one unit (each is looked at: its bounds, then, where they meet, a
/// slab test and its distance). Measured where the checks are nearly all
/// the work (gazes among 4,990 small boxes hung in a 12 m hall: 1.5 ns a
/// box): 128 a unit ran at 5,200 units a millisecond, and a gaze map there
/// went on for minutes within the bound; at 24, about 28,000, as the
/// solvers do. A kitchen's checks (fewer than 24 boxes) cost 1 unit as
/// before.
const OBSTACLES_PER_UNIT: u64 = 24;

/// What checking one solid against a room of `obstacles` obstacles (and
/// the person's own body) costs, in units.
pub fn capsule_check(obstacles: usize) -> u64 {
    1 + obstacles as u64 / OBSTACLES_PER_UNIT
}

/// What checking a posture of a chain of at most `solids` solids (its
/// links and the spheres it carries) against a room of `obstacles`
/// obstacles and against itself costs. Up to [`PLAIN_SOLIDS`] solids (every
/// person of the stdlib: the rate of the meter was measured on them) it is
/// [`POSTURE_CAPSULES`] solids' checks; beyond, each solid is checked
/// against the room, and each pair of solids against each other (a chain
/// of 600 joints has 180,000 pairs: without them it took minutes for the
/// work of seconds).
pub fn posture_check(obstacles: usize, solids: usize) -> u64 {
    if solids <= PLAIN_SOLIDS {
        return POSTURE_CAPSULES * capsule_check(obstacles);
    }
    let solids = solids as u64;
    let pairs = solids * (solids - 1) / 2;
    solids * capsule_check(obstacles) + pairs / SELF_PAIRS_PER_UNIT
}

/// The most solids a chain may have for a check of its posture to cost
/// [`POSTURE_CAPSULES`] solids' checks: the longest chain of the stdlib's
/// people (a spine, a shoulder and an arm, 24 at most). 32 until stop 51:
/// a population of bodies of 32 solids was counted as of 8, and ran 19 s
/// before the bound stopped it.
pub const PLAIN_SOLIDS: usize = 24;

/// How many pairs of a chain's own solids are checked against each other
/// in the time of one unit (most are told apart by their bounds). 32
/// until stop 51, when a helper measured pairs to take about 2.5 times as
/// long (chains of 30,000 joints ran 21 s before the bound stopped them).
const SELF_PAIRS_PER_UNIT: u64 = 12;

/// The work a whole run has spent, against its limit, and the work of
/// what is being worked out for it now and charged once done
/// ([`crate::allowance::Flight`]).
#[derive(Debug)]
pub struct RunWork {
    spent: AtomicU64,
    limit: u64,
    /// The computations in flight and those landed.
    flights: Mutex<Flights>,
    /// Set where a flight was cut short: the run is past its limit.
    stopped: AtomicBool,
    /// The values the run keeps, which a watch session may keep across
    /// its runs.
    memo: Arc<Memo>,
}

impl RunWork {
    /// Nothing spent yet, of `limit` units, keeping values in a memo of
    /// its own.
    pub fn new(limit: u64) -> Arc<Self> {
        RunWork::keeping(limit, Arc::default())
    }

    /// Nothing spent yet, of `limit` units, keeping values in `memo`.
    pub fn keeping(limit: u64, memo: Arc<Memo>) -> Arc<Self> {
        Arc::new(RunWork {
            spent: AtomicU64::new(0),
            limit,
            flights: Mutex::default(),
            stopped: AtomicBool::new(false),
            memo,
        })
    }

    /// Units spent so far.
    pub fn spent(&self) -> u64 {
        self.spent.load(Ordering::Relaxed)
    }

    /// Whether the run has spent more than its limit (or a flight found
    /// that it will), or was cancelled ([`Memo::cancel`]).
    pub fn exceeded(&self) -> bool {
        self.spent() > self.limit || self.stopped.load(Ordering::Relaxed) || self.memo.cancelled()
    }

    fn flights(&self) -> std::sync::MutexGuard<'_, Flights> {
        self.flights.lock().unwrap_or_else(|e| e.into_inner())
    }

    /// Add `units`; whether the run is still within its limit.
    pub fn charge(&self, units: u64) -> bool {
        let before = self.spent.fetch_add(units, Ordering::Relaxed);
        before.saturating_add(units) <= self.limit
    }
}

/// By key, the most work any computation of that key has done so far
/// while it is in flight, and the keys whose computation landed.
#[derive(Debug, Default)]
struct Flights {
    flying: BTreeMap<u64, u64>,
    landed: BTreeSet<u64>,
}

/// The meter of one task (one person's): what it spent, added to its
/// run's work as well.
#[derive(Debug)]
pub struct Meter {
    own: Arc<AtomicU64>,
    run: Option<Arc<RunWork>>,
    /// The pieces of floor this task has been charged for working out
    /// (by the key a memo keeps them by): looked at again, they are
    /// charged for looking alone (`floor/tiles.rs`).
    pieces: Mutex<BTreeSet<u64>>,
}

impl Allowance for Meter {
    fn spend(&self, units: u64) -> bool {
        self.charge(units)
    }
    fn exhausted(&self) -> bool {
        self.exceeded()
    }
    fn would_stay_within(&self, units: u64) -> bool {
        self.run
            .as_ref()
            .is_none_or(|run| run.spent().saturating_add(units) <= run.limit)
    }
    fn first_look(&self, key: u64) -> bool {
        if self.run.is_none() {
            return true;
        }
        let mut pieces = self.pieces.lock().unwrap_or_else(|e| e.into_inner());
        pieces.insert(key)
    }
    fn flight_within(&self, key: u64, units: u64) -> bool {
        let Some(run) = &self.run else {
            return true;
        };
        let flying: u64 = {
            let mut flights = run.flights();
            // A computation of a key that landed is worked out again by a
            // thread that started before it landed; its work is charged
            // once, where the first landed, so it counts no more.
            if !flights.landed.contains(&key) {
                let mine = flights.flying.entry(key).or_default();
                *mine = (*mine).max(units);
            }
            (flights.flying.values()).fold(0, |sum, &w| sum.saturating_add(w))
        };
        let within = run.spent().saturating_add(flying) <= run.limit;
        if !within {
            run.stopped.store(true, Ordering::Relaxed);
        }
        within
    }
    fn flight_landed(&self, key: u64) {
        if let Some(run) = &self.run {
            let mut flights = run.flights();
            flights.flying.remove(&key);
            flights.landed.insert(key);
        }
    }
    fn memo(&self) -> Arc<Memo> {
        memo_of(self.run.as_ref())
    }
    fn shared(&self) -> Arc<dyn Allowance + Send> {
        Arc::new(self.account())
    }
}

/// A meter of no run, which never stops a solve.
static UNMETERED: LazyLock<Meter> = LazyLock::new(|| Meter {
    own: Arc::default(),
    run: None,
    pieces: Mutex::new(BTreeSet::new()),
});

impl Meter {
    /// A meter of a task of the run `run`.
    pub fn of(run: &Arc<RunWork>) -> Self {
        Meter {
            own: Arc::default(),
            run: Some(Arc::clone(run)),
            pieces: Mutex::default(),
        }
    }

    /// A meter that never stops anything (benchmarks of one solver, tests
    /// of one solve).
    pub fn unmetered() -> &'static Meter {
        &UNMETERED
    }

    /// Add `units`; whether the run is still within its limit.
    pub fn charge(&self, units: u64) -> bool {
        self.own.fetch_add(units, Ordering::Relaxed);
        self.run.as_ref().is_none_or(|run| run.charge(units))
    }

    /// What may charge this meter from where it cannot be lent (the
    /// obstacles a task's checks are put to, [`Account`]).
    pub fn account(&self) -> Account {
        Account {
            own: Arc::clone(&self.own),
            run: self.run.clone(),
        }
    }

    /// Whether the run has spent more than its limit (a solve stops).
    pub fn exceeded(&self) -> bool {
        self.run.as_ref().is_some_and(|run| run.exceeded())
    }

    /// Units this task has spent.
    pub fn spent(&self) -> u64 {
        self.own.load(Ordering::Relaxed)
    }
}

/// The memo of `run`; one that keeps nothing where there is no run.
fn memo_of(run: Option<&Arc<RunWork>>) -> Arc<Memo> {
    run.map_or_else(|| Arc::new(Memo::forgetting()), |run| Arc::clone(&run.memo))
}

/// A meter's counts, shared: work charged where it is done, by what has
/// no meter to hand (a mesh check, by the triangles it tested). What a
/// task's account is charged is the task's, whichever thread does it.
#[derive(Clone, Debug)]
pub struct Account {
    own: Arc<AtomicU64>,
    run: Option<Arc<RunWork>>,
}

impl Account {
    /// Whether the task's run has passed its limit (its answers will be
    /// thrown away).
    pub fn exceeded(&self) -> bool {
        self.run.as_ref().is_some_and(|run| run.exceeded())
    }

    /// Add `units` to the task's work and its run's.
    pub fn charge(&self, units: u64) {
        self.own.fetch_add(units, Ordering::Relaxed);
        if let Some(run) = &self.run {
            run.charge(units);
        }
    }
}

impl Allowance for Account {
    fn spend(&self, units: u64) -> bool {
        self.charge(units);
        !self.exceeded()
    }
    fn exhausted(&self) -> bool {
        self.exceeded()
    }
    fn memo(&self) -> Arc<Memo> {
        memo_of(self.run.as_ref())
    }
    fn shared(&self) -> Arc<dyn Allowance + Send> {
        Arc::new(self.clone())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::allowance::{Counted, Tally};

    #[test]
    fn a_counted_allowance_counts_what_is_spent_through_it_and_its_shares() {
        let run = RunWork::new(u64::MAX);
        let meter = Meter::of(&run);
        meter.charge(5);
        let units = Arc::new(AtomicU64::new(0));
        let counted = Counted::new(&meter as &dyn Allowance, Arc::clone(&units));
        counted.spend(3);
        counted.shared().spend(7);
        let mut tally = Tally::new(&counted);
        tally.add(11);
        drop(tally);
        assert_eq!(
            units.load(Ordering::Relaxed),
            21,
            "its own, its share's and the tally's, told when dropped"
        );
        assert_eq!(meter.spent(), 26);
        // What is charged past it is not its count.
        meter.charge(2);
        assert_eq!(units.load(Ordering::Relaxed), 21);
    }

    #[test]
    fn work_in_flight_counts_with_what_is_spent_and_once_for_each_key() {
        let run = RunWork::new(100);
        let (a, b) = (Meter::of(&run), Meter::of(&run));
        let (a, b): (&dyn Allowance, &dyn Allowance) = (&a, &b);
        assert!(a.spend(20));
        let floor = a.flight(1);
        assert!(floor.within(50));
        // The same floor worked out by another thread counts once.
        let again = b.flight(1);
        assert!(again.within(60));
        drop(again);
        // Another person's floor: 20 spent, 50 and 30 in flight.
        let other = b.flight(2);
        assert!(other.within(30));
        assert!(!run.exceeded());
        drop(floor);
        assert!(other.within(70), "a flight done leaves the count");
        // Worked out again by a thread that started before it landed:
        // charged once, where it landed, it counts no more.
        let late = a.flight(1);
        assert!(late.within(1_000));
        drop(late);
        assert!(!other.within(81));
        assert!(run.exceeded(), "a flight past the limit stops the run");
        let unmetered: &dyn Allowance = Meter::unmetered();
        assert!(unmetered.flight(1).within(u64::MAX));
    }

    #[test]
    fn a_run_past_its_limit_stops_every_task_and_each_task_keeps_its_own_sum() {
        let run = RunWork::new(10_000);
        let (a, b) = (Meter::of(&run), Meter::of(&run));
        {
            let mut tally = Tally::new(&a);
            assert!(tally.add(6_000));
        }
        assert!(b.charge(4_000));
        assert!(!run.exceeded());
        assert!(!b.charge(1));
        assert!(run.exceeded() && a.exceeded());
        assert_eq!((a.spent(), b.spent(), run.spent()), (6_000, 4_001, 10_001));
        assert!(!Tally::new(&a).within());
    }

    #[test]
    fn a_posture_check_counts_eight_solids_up_to_the_stdlib_and_every_pair_beyond() {
        for obstacles in [0, 100, 5_000] {
            for solids in [1, 8, 24, PLAIN_SOLIDS] {
                assert_eq!(
                    posture_check(obstacles, solids),
                    POSTURE_CAPSULES * capsule_check(obstacles)
                );
            }
            // A chain of 600 links: each against the room, and its 179,700
            // pairs against each other.
            let long = posture_check(obstacles, 600);
            assert!(long >= 600 * capsule_check(obstacles) + 179_700 / SELF_PAIRS_PER_UNIT);
            assert!(
                posture_check(obstacles, PLAIN_SOLIDS + 1) > posture_check(obstacles, PLAIN_SOLIDS)
            );
            // The pairs' part: square in the solids.
            let pairs = |solids: usize| {
                posture_check(obstacles, solids) - solids as u64 * capsule_check(obstacles)
            };
            assert!(pairs(1_200) > 3 * pairs(600), "square in the solids");
        }
    }

    #[test]
    fn the_unmetered_meter_never_stops() {
        assert!(Meter::unmetered().charge(u64::MAX));
        assert!(Tally::new(Meter::unmetered()).add(u64::MAX));
    }
}
