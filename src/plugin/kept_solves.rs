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
//! The placements a mobile base samples for a point (from its capability
//! map, each posture checked against the room) are kept the same way: they
//! depend on the point, the face it is on and the obstacles the checks
//! touched, the floor being part of the task's key.
//!
//! The solves of one task are of one chain and one own body (a map's),
//! which the key therefore leaves out.

use std::collections::HashMap;
use std::sync::{Arc, Mutex};

use crate::collision::{recording_one, Touched};
use crate::meter::{counting_one, Meter};
use crate::scene::{BasePose, IkSolution};

/// The most solves kept for one task (about 300 bytes each): past it, no
/// more are kept.
const KEPT_MOST: usize = 1 << 17;

/// What a kept computation found.
#[derive(Debug)]
enum Found {
    /// A solve's posture (its collision is checked again where it is used).
    Solve {
        q: Vec<f64>,
        distance_mm: f64,
        iterations: u64,
    },
    /// The placements sampled for a point, each with its posture.
    Placements(Vec<(BasePose, Vec<f64>)>),
}

/// One solve's answer (or one point's sampled placements), with what it
/// touched and charged.
#[derive(Debug)]
pub struct KeptSolve {
    found: Found,
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
        let keep = |s: &IkSolution| Found::Solve {
            q: s.q.clone(),
            distance_mm: s.distance_mm,
            iterations: s.iterations,
        };
        let take = |found: &Found| match found {
            Found::Solve {
                q,
                distance_mm,
                iterations,
            } => Some(IkSolution {
                q: q.clone(),
                distance_mm: *distance_mm,
                iterations: *iterations,
                collision: None,
            }),
            Found::Placements(_) => None,
        };
        self.kept_or_made(key, meter, solve, keep, take)
    }

    /// The placements sampled for a point, by `key`: kept from the last
    /// run where they hold, else sampled here by `sample`, as
    /// [`KeptSolves::solve`].
    pub fn placements(
        &self,
        key: u64,
        meter: &Meter,
        sample: impl FnOnce() -> Vec<(BasePose, Vec<f64>)>,
    ) -> Vec<(BasePose, Vec<f64>)> {
        let keep = |p: &Vec<(BasePose, Vec<f64>)>| Found::Placements(p.clone());
        let take = |found: &Found| match found {
            Found::Placements(p) => Some(p.clone()),
            Found::Solve { .. } => None,
        };
        self.kept_or_made(key, meter, sample, keep, take)
    }

    /// What `make` makes, kept under `key` from the last run where that
    /// holds (`take` reading it back), its work charged to `meter` and its
    /// touches marked; else made here and kept (as `keep` writes it)
    /// unless the run has passed its limit.
    fn kept_or_made<T>(
        &self,
        key: u64,
        meter: &Meter,
        make: impl FnOnce() -> T,
        keep: impl FnOnce(&T) -> Found,
        take: impl FnOnce(&Found) -> Option<T>,
    ) -> T {
        let held = self.earlier.as_ref().and_then(|e| e.holding(key));
        if let Some(kept) = held.filter(|_| !meter.exceeded()) {
            if let Some(made) = take(&kept.found) {
                meter.charge(kept.units);
                for &i in kept.touched.iter() {
                    self.touched.mark(i as usize);
                }
                self.keep(key, Arc::clone(kept));
                return made;
            }
        }
        let ((made, touched), units) = counting_one(|| recording_one(make));
        if !meter.exceeded() {
            let kept = KeptSolve {
                found: keep(&made),
                units,
                touched: touched.into_boxed_slice(),
            };
            self.keep(key, Arc::new(kept));
        }
        made
    }

    /// `kept` kept under `key` for the next run, while there is room.
    fn keep(&self, key: u64, kept: Arc<KeptSolve>) {
        let mut now = self.now.lock().unwrap_or_else(|e| e.into_inner());
        if now.len() < KEPT_MOST {
            now.insert(key, kept);
        }
    }
}
