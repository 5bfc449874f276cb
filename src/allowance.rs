//! What a solver knows of the run it is part of: an [`Allowance`] it tells
//! the work it does to, in units of about the cost of moving one joint
//! once, and that says whether it may go on. How work is bounded, shared
//! between threads and counted per solve is the meter's (`crate::meter`),
//! and what is kept for watch mode the engine's (`crate::engine`), not the
//! solver's.

/// What a computation tells its work to.
pub trait Allowance: Sync {
    /// Add `units`; whether the computation may go on.
    fn spend(&self, units: u64) -> bool;
    /// Whether the computation must stop: the run it is part of has
    /// passed its bound (its answers will be thrown away).
    fn exhausted(&self) -> bool;
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
}

/// Units a solve counts before it tells its allowance (and learns whether
/// it may go on): few enough that a run past its bound stops within a
/// millisecond or so, many enough that threads seldom meet at a shared
/// counter.
const BATCH: u64 = 4_096;

/// The work of one solve, told to its allowance every [`BATCH`] units and
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
