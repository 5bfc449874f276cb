//! Solves kept from a task's last run for its next one (watch mode). A
//! solve's answer depends on its problem (the target in the base frame,
//! the base's pose, the tolerance, the seed), its solver, where it starts,
//! the task's chain and own body, and on the room's obstacles only through
//! the questions it puts to them. Each solve of a map's run is kept by a
//! key of all but the obstacles, with the obstacles its questions touched
//! (`collision::recording_one`) and the work it charged
//! (`meter::counting_one`).
//!
//! The task's next run, after an edit that left its key of all but the
//! obstacles as it was but moved an obstacle it touched (`cache`), takes a
//! kept solve's answer where none of the obstacles that solve touched
//! changed, and every obstacle that changed stays within its old bounds
//! grown by the margin (the caller gives no earlier solves otherwise):
//! every question the solve put then gets the answer it got, so it is the
//! same solve. Its work is charged and its touches marked as the solve
//! would have charged and marked them, so the run's work and record are a
//! fresh run's, and so is every answer.
//!
//! The solves of one task are of one chain and one own body (a map's),
//! which the key therefore leaves out.

use std::collections::HashMap;
use std::sync::{Arc, Mutex};

use crate::collision::{recording_one, Touched};
use crate::meter::{counting_one, Meter};
use crate::scene::IkSolution;

/// The most solves kept for one task (about 300 bytes each): past it, no
/// more are kept.
const KEPT_MOST: usize = 1 << 17;

/// One solve's answer, with what it touched and charged.
#[derive(Debug)]
pub struct KeptSolve {
    q: Vec<f64>,
    distance_mm: f64,
    iterations: u64,
    /// The work it charged.
    units: u64,
    /// The obstacles its questions touched, by index.
    touched: Box<[u32]>,
}

/// Kept solves by their key.
pub type SolveMap = HashMap<u64, Arc<KeptSolve>>;

/// The solves of a task's last run, and which of the room's obstacles
/// have changed since.
#[derive(Clone)]
pub struct Earlier {
    solves: Arc<SolveMap>,
    /// The obstacles changed, as bits by index.
    changed: Vec<u64>,
}

impl Earlier {
    /// `solves`, in a room whose obstacles `changed` (by index) changed
    /// since, each staying within its old bounds grown by the margin.
    pub fn new(solves: Arc<SolveMap>, changed: impl IntoIterator<Item = usize>) -> Self {
        let mut bits = Vec::new();
        for i in changed {
            if bits.len() <= i / 64 {
                bits.resize(i / 64 + 1, 0u64);
            }
            bits[i / 64] |= 1u64 << (i % 64);
        }
        Earlier {
            solves,
            changed: bits,
        }
    }

    /// The kept solve of `key`, if none of what it touched changed.
    fn holding(&self, key: u64) -> Option<&Arc<KeptSolve>> {
        let kept = self.solves.get(&key)?;
        let changed = |i: u32| {
            let i = i as usize;
            self.changed
                .get(i / 64)
                .is_some_and(|w| w & (1u64 << (i % 64)) != 0)
        };
        (!kept.touched.iter().any(|&i| changed(i))).then_some(kept)
    }
}

/// One task run's solves: those it may take from its last run, and those
/// it makes (or takes), kept for the next.
pub struct KeptSolves {
    earlier: Option<Earlier>,
    /// The task's record of what its questions touched.
    touched: Arc<Touched>,
    now: Mutex<SolveMap>,
}

impl KeptSolves {
    /// None made yet, for a task recording its touches in `touched`,
    /// taking what holds of `earlier`.
    pub fn new(touched: Arc<Touched>, earlier: Option<Earlier>) -> Self {
        KeptSolves {
            earlier,
            touched,
            now: Mutex::default(),
        }
    }

    /// The solves of this run, for the next.
    pub fn into_map(self) -> SolveMap {
        self.now.into_inner().unwrap_or_else(|e| e.into_inner())
    }

    /// The solve of `key`: kept from the last run where it holds (its
    /// work charged to `meter`, its touches marked), else `solve` run
    /// here, recorded, and kept unless the run passed its limit.
    pub fn solve(&self, key: u64, meter: &Meter, solve: impl FnOnce() -> IkSolution) -> IkSolution {
        let held = self.earlier.as_ref().and_then(|e| e.holding(key));
        if let Some(kept) = held.filter(|_| !meter.exceeded()) {
            meter.charge(kept.units);
            for &i in kept.touched.iter() {
                self.touched.mark(i as usize);
            }
            let kept = Arc::clone(kept);
            let solution = IkSolution {
                q: kept.q.clone(),
                distance_mm: kept.distance_mm,
                iterations: kept.iterations,
                collision: None,
            };
            self.keep(key, kept);
            return solution;
        }
        let ((solution, touched), units) = counting_one(|| recording_one(solve));
        if !meter.exceeded() {
            let kept = KeptSolve {
                q: solution.q.clone(),
                distance_mm: solution.distance_mm,
                iterations: solution.iterations,
                units,
                touched: touched.into_boxed_slice(),
            };
            self.keep(key, Arc::new(kept));
        }
        solution
    }

    /// `kept` kept under `key` for the next run, while there is room.
    fn keep(&self, key: u64, kept: Arc<KeptSolve>) {
        let mut now = self.now.lock().unwrap_or_else(|e| e.into_inner());
        if now.len() < KEPT_MOST {
            now.insert(key, kept);
        }
    }
}
