//! What a solver, a base or a standard knows of the run it is part of: an
//! [`Allowance`] it tells the work it does to, in units of about the cost
//! of moving one joint once, and that says whether it may go on. How work is bounded, shared
//! between threads and counted per solve is the meter's (`crate::meter`),
//! and what is kept for watch mode the engine's (`crate::engine`), not the
//! solver's.

use std::ops::Deref;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::Arc;

use crate::kept::Memo;

/// What a computation tells its work to. A solver needs only
/// [`Allowance::spend`] and [`Allowance::exhausted`]; the rest is for the
/// long computations of bases and standards (a room's floor), whose
/// defaults are those of an allowance that never runs out.
pub trait Allowance: Sync {
    /// Add `units`; whether the computation may go on.
    fn spend(&self, units: u64) -> bool;
    /// Whether the computation must stop: the run it is part of has
    /// passed its bound (its answers will be thrown away).
    fn exhausted(&self) -> bool;
    /// Whether the run would still be within its bound were `units` more
    /// spent (nothing is spent).
    fn would_stay_within(&self, _units: u64) -> bool {
        true
    }
    /// Whether this task looks at the piece of work `key` (a piece of
    /// floor) for the first time: it is paid for in full only then.
    fn first_look(&self, _key: u64) -> bool {
        true
    }
    /// Whether the run stays within its bound with the computation `key`
    /// at `units` and every other in flight at what it has done
    /// (`Flight`). Where it does not, the run is stopped.
    fn flight_within(&self, _key: u64, _units: u64) -> bool {
        true
    }
    /// The computation `key` is done (or given up): it no longer counts
    /// as in flight.
    fn flight_landed(&self, _key: u64) {}
    /// The values the run keeps (a room's floor, its routes), which
    /// outlive the computation: by default none are kept.
    fn memo(&self) -> Arc<Memo> {
        Arc::new(Memo::forgetting())
    }
    /// The same allowance, to be kept by what cannot borrow it (the
    /// obstacles a task's checks are put to, which charge the triangles
    /// of meshes they test).
    fn shared(&self) -> Arc<dyn Allowance + Send>;
}

impl dyn Allowance + '_ {
    /// A computation of `key` the run will be charged for once it is
    /// done (a person's floor), whose work so far counts against the
    /// bound with every other in flight.
    pub fn flight(&self, key: u64) -> Flight<'_> {
        Flight {
            allowance: self,
            key,
        }
    }
}

/// A computation the run will be charged for once it is done, by a key
/// that names what it works out (two threads working out the same thing
/// count once), landed when dropped. Work charged only once done would
/// let several such computations at once each run up to the whole bound,
/// as if alone (ten people's floors in a cluttered room, two at a time:
/// twice the time before the run stopped). Counting what each has done so
/// far with what the run has spent stops it as soon as the sum passes the
/// bound, and that stop is the answer every thread count gives: each
/// flight's work is charged in full once done, so the run's sum would
/// pass the bound anyway. A flight dropped leaves the count (its work
/// then charged, or the run stopped).
pub struct Flight<'a> {
    allowance: &'a dyn Allowance,
    key: u64,
}

impl Flight<'_> {
    /// Whether the run stays within its bound with this computation at
    /// `units`; where it does not, the caller cuts its work short.
    pub fn within(&self, units: u64) -> bool {
        self.allowance.flight_within(self.key, units)
    }
}

impl Drop for Flight<'_> {
    fn drop(&mut self) {
        self.allowance.flight_landed(self.key);
    }
}

/// An allowance that never runs out and keeps no count (benchmarks of one
/// solver, tests of one solve).
pub struct Unbounded;

impl Allowance for Unbounded {
    fn spend(&self, _units: u64) -> bool {
        true
    }
    fn exhausted(&self) -> bool {
        false
    }
    fn shared(&self) -> Arc<dyn Allowance + Send> {
        Arc::new(Unbounded)
    }
}

/// An allowance that never runs out and keeps the values it is asked for
/// in a run's memo: what a base works out unmetered for a run (what the
/// run's metered search already paid for, asked again).
pub struct Unmetered(pub Arc<Memo>);

impl Allowance for Unmetered {
    fn spend(&self, _units: u64) -> bool {
        true
    }
    fn exhausted(&self) -> bool {
        false
    }
    fn memo(&self) -> Arc<Memo> {
        Arc::clone(&self.0)
    }
    fn shared(&self) -> Arc<dyn Allowance + Send> {
        Arc::new(Unmetered(Arc::clone(&self.0)))
    }
}

/// An allowance that adds what is spent through it to a count of its
/// own as well: one solve's work, which watch mode keeps with the solve
/// (`engine::KeptSolves`). Everything else is the inner allowance's.
pub struct Counted<A> {
    inner: A,
    units: Arc<AtomicU64>,
}

impl<A> Counted<A> {
    /// `inner`, counting what is spent through it into `units`.
    pub fn new(inner: A, units: Arc<AtomicU64>) -> Self {
        Counted { inner, units }
    }
}

impl<A> Allowance for Counted<A>
where
    A: Deref + Sync,
    A::Target: Allowance,
{
    fn spend(&self, units: u64) -> bool {
        self.units.fetch_add(units, Ordering::Relaxed);
        self.inner.spend(units)
    }
    fn exhausted(&self) -> bool {
        self.inner.exhausted()
    }
    fn would_stay_within(&self, units: u64) -> bool {
        self.inner.would_stay_within(units)
    }
    fn first_look(&self, key: u64) -> bool {
        self.inner.first_look(key)
    }
    fn flight_within(&self, key: u64, units: u64) -> bool {
        self.inner.flight_within(key, units)
    }
    fn flight_landed(&self, key: u64) {
        self.inner.flight_landed(key)
    }
    fn memo(&self) -> Arc<Memo> {
        self.inner.memo()
    }
    fn shared(&self) -> Arc<dyn Allowance + Send> {
        Arc::new(Counted::new(self.inner.shared(), Arc::clone(&self.units)))
    }
}

/// Units a solve counts before it tells its allowance (and learns whether
/// it may go on): few enough that a run past its bound stops within a
/// millisecond or so, many enough that threads seldom meet at a shared
/// counter.
const BATCH: u64 = 4_096;

/// The work of one solve, told to its allowance every `BATCH` units and
/// when it is dropped.
pub struct Tally<'a> {
    allowance: &'a dyn Allowance,
    pending: u64,
    within: bool,
}

impl<'a> Tally<'a> {
    /// A tally of a solve that spends from `allowance`.
    pub fn new(allowance: &'a dyn Allowance) -> Self {
        Tally {
            allowance,
            pending: 0,
            within: !allowance.exhausted(),
        }
    }

    /// Add `units`, telling the allowance once a batch is full.
    #[inline]
    pub fn count(&mut self, units: u64) {
        self.pending = self.pending.saturating_add(units);
        if self.pending >= BATCH {
            self.within = self.allowance.spend(std::mem::take(&mut self.pending));
        }
    }

    /// Add `units`; whether the solve may go on ([`Tally::within`]).
    pub fn add(&mut self, units: u64) -> bool {
        self.count(units);
        self.within()
    }

    /// Whether the solve may go on: within the bound as far as the last
    /// batch told, and the run not stopped since (work told to the
    /// allowance by others may have passed it).
    pub fn within(&self) -> bool {
        self.within && !self.allowance.exhausted()
    }
}

impl Drop for Tally<'_> {
    fn drop(&mut self) {
        if self.pending > 0 {
            self.allowance.spend(self.pending);
        }
    }
}
