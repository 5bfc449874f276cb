//! Solves kept from a task's last run for its next one (watch mode). A
//! solve's answer depends on its problem (the target in the base frame,
//! the base's pose, the tolerance, the seed), its solver, where it starts,
//! the task's chain and own body, and on the room's obstacles only through
//! the questions it puts to them. Each solve of a task's searches (a
//! map's points, a reach, the searches that find why) is kept by a key of
//! all but the obstacles, with the obstacles its questions touched and
//! the work it charged, which the solve's own view of the obstacles
//! (`Obstacles::recording_solve`) and its counted allowance
//! (`allowance::Counted`) record as it runs.
//!
//! The task's next run, after an edit that left its key of all but the
//! obstacles as it was but moved an obstacle it touched (`cache`), takes a
//! kept solve's answer where none of the obstacles that solve touched
//! changed, and each obstacle that changed either stays within its old
//! bounds grown by the margin or, grown by the margin, misses the bounds
//! of all the solve's questions together: every question the solve put
//! then gets the answer it got, so it is the same solve. Its work is
//! charged and its touches marked as the solve would have charged them,
//! so the run's work is a fresh run's, and so is every answer. A changed
//! obstacle that stayed near and meets those bounds may now be within the
//! margin of a question: the solve, kept again, counts it as touched (and
//! so does the task's record), so that it is not taken again once that
//! obstacle moves on.
//!
//! The placements a mobile base samples for a point (from its capability
//! map, each posture checked against the room) are kept the same way: they
//! depend on the point, the face it is on and the obstacles the checks
//! touched, the floor being part of the task's key.
//!
//! A task's searches may differ in their chain, obstacles and own body
//! (finding why searches again with limits widened, without an obstacle
//! or a part of the body): each search asks through [`SolvesFor`], whose
//! variant, a hash of those three, is part of every key.

use std::collections::HashMap;
use std::sync::{Arc, Mutex};

use nalgebra::Point3;

use crate::allowance::{Allowance, Counted};
use crate::collision::{bounds_meet, Obstacles, SolveRecord, Touched, TOUCH_MARGIN_MM};
use crate::kinematics::Chain;
use crate::scene::{BasePose, IkSolution, OwnBody};

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
#[derive(Clone, Debug)]
pub struct KeptSolve {
    found: Arc<Found>,
    /// The work it charged.
    units: u64,
    /// The obstacles its questions touched, by index, in order.
    touched: Box<[u32]>,
    /// The bounds of all its questions together (none: it put none).
    asked_mm: Option<[Point3<f64>; 2]>,
}

/// Kept solves by their key.
pub type SolveMap = HashMap<u64, KeptSolve>;

/// One of the room's obstacles that changed since a task's last run.
#[derive(Clone, Debug)]
pub struct Changed {
    pub index: usize,
    /// Its bounds now, as the collision checks hold them (none: a mesh
    /// with no solid).
    pub bounds_mm: Option<[Point3<f64>; 2]>,
    /// Whether it stays within its old bounds grown by the margin.
    pub near: bool,
}

/// The solves of a task's last run, and the room's obstacles that have
/// changed since.
#[derive(Clone)]
pub struct Earlier {
    solves: Arc<SolveMap>,
    changed: Vec<Changed>,
}

impl Earlier {
    /// `solves`, in a room whose obstacles `changed` since.
    pub fn new(solves: Arc<SolveMap>, changed: Vec<Changed>) -> Self {
        Earlier { solves, changed }
    }

    /// The kept solve of `key` where it holds, with the obstacles it now
    /// counts as touched: none of those it touched changed, and each that
    /// changed misses its questions' bounds or stayed near (then it counts
    /// as touched).
    fn holding(&self, key: u64) -> Option<KeptSolve> {
        let kept = self.solves.get(&key)?;
        let mut near_now = Vec::new();
        for c in &self.changed {
            if kept.touched.contains(&(c.index as u32)) {
                return None;
            }
            let meets = match (&c.bounds_mm, &kept.asked_mm) {
                (_, None) => false,
                (None, Some(_)) => true,
                (Some(b), Some(a)) => bounds_meet(b, a, TOUCH_MARGIN_MM),
            };
            match (meets, c.near) {
                (false, _) => {}
                (true, true) => near_now.push(c.index as u32),
                (true, false) => return None,
            }
        }
        if near_now.is_empty() {
            return Some(kept.clone());
        }
        let mut touched = kept.touched.to_vec();
        touched.extend(near_now);
        touched.sort_unstable();
        touched.dedup();
        Some(KeptSolve {
            touched: touched.into_boxed_slice(),
            ..kept.clone()
        })
    }
}

/// A task run's kept solves, as one of its searches asks for them: by
/// its chain, obstacles and own body (`variant`).
#[derive(Clone, Copy)]
pub struct SolvesFor<'a> {
    kept: &'a KeptSolves,
    variant: u64,
    /// Whether the placements a mobile base samples are kept too (for the
    /// base as the task prepares it; not where a search prepares it in
    /// another room or without its zone).
    placements: bool,
}

impl SolvesFor<'_> {
    /// The same, but the sampled placements are not kept: the search
    /// prepares the base otherwise than the task.
    pub fn without_placements(self) -> Self {
        SolvesFor {
            placements: false,
            ..self
        }
    }

    /// `KeptSolves::solve` for this variant.
    pub fn solve(
        &self,
        key: u64,
        asked: Asked<'_>,
        solve: impl FnOnce(Asked<'_>) -> IkSolution,
    ) -> IkSolution {
        self.kept.solve(self.key(key), asked, solve)
    }

    /// `KeptSolves::placements` for this variant, where placements are
    /// kept; else sampled here.
    pub fn placements(
        &self,
        key: u64,
        asked: Asked<'_>,
        sample: impl FnOnce(Asked<'_>) -> Vec<(BasePose, Vec<f64>)>,
    ) -> Vec<(BasePose, Vec<f64>)> {
        match self.placements {
            true => self.kept.placements(self.key(key), asked, sample),
            false => sample(asked),
        }
    }

    fn key(&self, key: u64) -> u64 {
        let mut h = std::collections::hash_map::DefaultHasher::new();
        std::hash::Hasher::write_u64(&mut h, key);
        std::hash::Hasher::write_u64(&mut h, self.variant);
        std::hash::Hasher::finish(&h)
    }
}

/// What a kept computation asks its questions of and tells its work to:
/// the obstacles (none: not checked) and the allowance. A computation
/// made to be kept is given its own view of both, which record what it
/// touched and charged.
#[derive(Clone, Copy)]
pub struct Asked<'a> {
    pub obstacles: Option<&'a Obstacles>,
    pub allowance: &'a dyn Allowance,
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

    /// These solves as a search by `chain` among `obstacles` (none: not
    /// checked) with `own` asks for them.
    pub fn of(&self, chain: &Chain, obstacles: Option<&Obstacles>, own: &OwnBody) -> SolvesFor<'_> {
        let variant = fingerprint_of("search", &(chain, obstacles.map(Obstacles::variant), own));
        SolvesFor {
            kept: self,
            variant,
            placements: true,
        }
    }

    /// The solves of this run, for the next.
    pub fn into_map(self) -> SolveMap {
        self.now.into_inner().unwrap_or_else(|e| e.into_inner())
    }

    /// The solve of `key`: kept from the last run where it holds (its
    /// work told to `allowance`, its touches marked), else `solve` run
    /// here, recorded, and kept unless the run passed its limit.
    fn solve(
        &self,
        key: u64,
        asked: Asked<'_>,
        solve: impl FnOnce(Asked<'_>) -> IkSolution,
    ) -> IkSolution {
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
        self.kept_or_made(key, asked, solve, keep, take)
    }

    /// The placements sampled for a point, by `key`: kept from the last
    /// run where they hold, else sampled here by `sample`, as
    /// [`KeptSolves::solve`].
    fn placements(
        &self,
        key: u64,
        asked: Asked<'_>,
        sample: impl FnOnce(Asked<'_>) -> Vec<(BasePose, Vec<f64>)>,
    ) -> Vec<(BasePose, Vec<f64>)> {
        let keep = |p: &Vec<(BasePose, Vec<f64>)>| Found::Placements(p.clone());
        let take = |found: &Found| match found {
            Found::Placements(p) => Some(p.clone()),
            Found::Solve { .. } => None,
        };
        self.kept_or_made(key, asked, sample, keep, take)
    }

    /// What `make` makes, kept under `key` from the last run where that
    /// holds (`take` reading it back), its work told to the allowance
    /// `asked` gives and its touches marked; else made here, asking
    /// through a view of its own that records it, and kept (as `keep`
    /// writes it) unless the run has passed its limit.
    fn kept_or_made<T>(
        &self,
        key: u64,
        asked: Asked<'_>,
        make: impl FnOnce(Asked<'_>) -> T,
        keep: impl FnOnce(&T) -> Found,
        take: impl FnOnce(&Found) -> Option<T>,
    ) -> T {
        let allowance = asked.allowance;
        let held = self.earlier.as_ref().and_then(|e| e.holding(key));
        if let Some(kept) = held.filter(|_| !allowance.exhausted()) {
            if let Some(made) = take(&kept.found) {
                allowance.spend(kept.units);
                for &i in kept.touched.iter() {
                    self.touched.mark(i as usize);
                }
                self.keep(key, kept);
                return made;
            }
        }
        let solve = Arc::new(SolveRecord::default());
        let obstacles = asked.obstacles.map(|o| o.recording_solve(&solve));
        let counted = Counted::new(allowance, solve.units());
        let made = make(Asked {
            obstacles: obstacles.as_ref(),
            allowance: &counted,
        });
        let (record, units) = solve.finish();
        if !allowance.exhausted() {
            let kept = KeptSolve {
                found: Arc::new(keep(&made)),
                units,
                touched: record.touched.into_boxed_slice(),
                asked_mm: record.asked_mm,
            };
            self.keep(key, kept);
        }
        made
    }

    /// `kept` kept under `key` for the next run, while there is room.
    fn keep(&self, key: u64, kept: KeptSolve) {
        let mut now = self.now.lock().unwrap_or_else(|e| e.into_inner());
        if now.len() < KEPT_MOST {
            now.insert(key, kept);
        }
    }
}

/// The fingerprint of a solver of `kind` with `settings`
/// ([`Solver::fingerprint`](crate::plugin::Solver::fingerprint)): a hash of their `Debug` text, which writes
/// every field, each float exactly, so that a setting added later is
/// taken in without being named here.
pub fn fingerprint_of(kind: &str, settings: &impl std::fmt::Debug) -> u64 {
    use std::fmt::Write;
    use std::hash::Hasher;
    /// Text written straight into a hasher.
    struct Hashing(std::collections::hash_map::DefaultHasher);
    impl Write for Hashing {
        fn write_str(&mut self, text: &str) -> std::fmt::Result {
            self.0.write(text.as_bytes());
            Ok(())
        }
    }
    let mut h = Hashing(std::collections::hash_map::DefaultHasher::new());
    // Writing into a hasher cannot fail.
    let _ = write!(h, "{kind}\u{0}{settings:?}");
    h.0.finish()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cube(x: f64) -> [Point3<f64>; 2] {
        [
            Point3::new(x, 0.0, 0.0),
            Point3::new(x + 100.0, 100.0, 100.0),
        ]
    }

    /// A solve that touched obstacle 0 and asked within the cube at 0.
    fn kept() -> Arc<SolveMap> {
        let solve = KeptSolve {
            found: Arc::new(Found::Placements(Vec::new())),
            units: 9,
            touched: vec![0].into_boxed_slice(),
            asked_mm: Some(cube(0.0)),
        };
        Arc::new(HashMap::from([(1, solve)]))
    }

    fn changed(index: usize, x: f64, near: bool) -> Changed {
        Changed {
            index,
            bounds_mm: Some(cube(x)),
            near,
        }
    }

    #[test]
    fn a_solve_holds_while_what_changed_missed_its_questions() {
        let holding = |c: Vec<Changed>| Earlier::new(kept(), c).holding(1).map(|k| k.touched);
        // What it touched changed.
        assert_eq!(holding(vec![changed(0, 0.0, true)]), None);
        // Far from where it asked, however far it moved.
        assert_eq!(
            holding(vec![changed(1, 500.0, false)]),
            Some(vec![0].into())
        );
        // Moved far into where it asked.
        assert_eq!(holding(vec![changed(1, 50.0, false)]), None);
        // Moved a little where it asked: it holds, and counts as touched.
        assert_eq!(
            holding(vec![changed(1, 50.0, true)]),
            Some(vec![0, 1].into())
        );
        // Another key.
        assert!(Earlier::new(kept(), Vec::new()).holding(2).is_none());
    }
}
