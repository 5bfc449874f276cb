//! Which of a room's obstacles a task's questions came near: the record
//! watch mode keeps beside a task's answer, so that an obstacle moved a
//! little where no question came near it leaves the answer as it was.
//!
//! An obstacle is marked when its bounds, grown by [`TOUCH_MARGIN_MM`] on
//! every side, meet the bounds of a question that is put to it (a solid
//! of the person, a line of sight) before the exact test. An obstacle not
//! marked was, at every question, farther than the margin from it along
//! some axis; moved or resized within its grown bounds it still is, so
//! every question gets the answer it got, and the task's whole run, which
//! depends on the room only through these questions (and the floor,
//! which the cache compares whole), is the same run. A question that
//! stops at the first obstacle it meets marks only those it looked at:
//! the rest could not change its answer. A run that ranks the room's
//! obstacles by their distance (finding why) says so: its answer depends
//! on obstacles however far, which a key of the obstacles within reach
//! does not hold.
//!
//! One solve's own record ([`SolveRecord`]) is kept beside the task's
//! while it runs, by the view of the obstacles that solve is given
//! (`Obstacles::recording_solve`): watch mode keeps the solve's answer
//! with it (`engine::KeptSolves`), for a run of the task after an edit
//! that changed none of the obstacles that solve touched.

use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::{Arc, Mutex};

use nalgebra::Point3;

/// How far beyond an obstacle's bounds a question marks it: an obstacle
/// not marked may move or grow by up to this on every side without
/// changing the run.
pub const TOUCH_MARGIN_MM: f64 = 5.0;

/// The obstacles (by index: the boxes, then the meshes) one task's
/// questions came near, recorded as it runs, from any thread.
#[derive(Debug, Default)]
pub struct Touched {
    words: Vec<AtomicU64>,
    /// Every obstacle counts as touched.
    all: AtomicBool,
    /// The obstacles were ranked by their distance.
    ranked: AtomicBool,
}

/// What a task's run touched, once it has ended.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TouchedSet {
    /// The obstacles touched, by index, as bits (none: every obstacle).
    words: Option<Vec<u64>>,
    /// Whether the run ranked the room's obstacles by their distance.
    ranked: bool,
}

impl Touched {
    /// None touched yet, of a room with `obstacles` obstacles.
    pub fn new(obstacles: usize) -> Self {
        Touched {
            words: (0..obstacles.div_ceil(64))
                .map(|_| AtomicU64::new(0))
                .collect(),
            all: AtomicBool::new(false),
            ranked: AtomicBool::new(false),
        }
    }

    /// Obstacle `index` was touched.
    pub fn mark(&self, index: usize) {
        let bit = 1u64 << (index % 64);
        match self.words.get(index / 64) {
            // Read first: the threads of one task mark the same few
            // obstacles again and again, and a write each time would pass
            // the line between them.
            Some(word) if word.load(Ordering::Relaxed) & bit == 0 => {
                word.fetch_or(bit, Ordering::Relaxed);
            }
            Some(_) => {}
            None => self.mark_all(),
        }
    }

    /// Whether a question must work out whether it comes near obstacle
    /// `index`: the obstacle is not marked yet in the task's record, or in
    /// the record of the solve asking (`solve`), if one is being made.
    pub fn needs(&self, index: usize, solve: Option<&SolveRecord>) -> bool {
        solve.is_some_and(|s| !s.has(index)) || !self.is_marked(index)
    }

    /// Whether obstacle `index` is touched already in the task's record.
    pub fn is_marked(&self, index: usize) -> bool {
        self.all.load(Ordering::Relaxed)
            || self
                .words
                .get(index / 64)
                .is_some_and(|word| word.load(Ordering::Relaxed) & (1u64 << (index % 64)) != 0)
    }

    /// Every obstacle was touched.
    pub fn mark_all(&self) {
        self.all.store(true, Ordering::Relaxed);
    }

    /// The run ranked the room's obstacles by their distance.
    pub fn mark_ranked(&self) {
        self.ranked.store(true, Ordering::Relaxed);
    }

    /// What was touched.
    pub fn set(&self) -> TouchedSet {
        let all = self.all.load(Ordering::Relaxed);
        let words = self.words.iter().map(|w| w.load(Ordering::Relaxed));
        TouchedSet {
            words: (!all).then(|| words.collect()),
            ranked: self.ranked.load(Ordering::Relaxed),
        }
    }
}

impl TouchedSet {
    /// Whether obstacle `index` was touched.
    pub fn contains(&self, index: usize) -> bool {
        self.words.as_ref().is_none_or(|words| {
            words
                .get(index / 64)
                .is_none_or(|w| w & (1u64 << (index % 64)) != 0)
        })
    }

    /// Whether the run ranked the room's obstacles by their distance: its
    /// answer may name an obstacle however far from the task.
    pub fn ranked(&self) -> bool {
        self.ranked
    }

    /// Obstacle `index` counts as touched too.
    pub fn insert(&mut self, index: usize) {
        if let Some(words) = &mut self.words {
            if words.len() <= index / 64 {
                words.resize(index / 64 + 1, 0);
            }
            words[index / 64] |= 1u64 << (index % 64);
        }
    }
}

/// What one solve's questions came to ([`SolveRecord::finish`]).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct OneRecord {
    /// The obstacles they touched, by index, in order.
    pub touched: Vec<u32>,
    /// The bounds of every question put to an obstacle, together (none:
    /// no question was): an obstacle whose bounds grown by the margin miss
    /// them was touched by none of the questions, wherever it is.
    pub asked_mm: Option<[Point3<f64>; 2]>,
}

/// The record being made of one solve: the obstacles its questions
/// touched and where they asked, and the work it charged (counted by the
/// allowances it is given, `allowance::Counted`).
#[derive(Debug, Default)]
pub struct SolveRecord {
    scope: Mutex<Scope>,
    units: Arc<AtomicU64>,
}

impl SolveRecord {
    /// The count the solve's allowances add its work to.
    pub fn units(&self) -> Arc<AtomicU64> {
        Arc::clone(&self.units)
    }

    /// Obstacle `index` touched by the solve.
    pub fn mark(&self, index: usize) {
        self.scope().mark(index);
    }

    /// Whether the solve has touched obstacle `index`.
    pub fn has(&self, index: usize) -> bool {
        self.scope().has(index)
    }

    /// A question whose bounds are `asked_mm` was put to the obstacles.
    pub fn asked(&self, asked_mm: &[Point3<f64>; 2]) {
        self.scope().take_asked(asked_mm);
    }

    /// What the solve's questions came to, and the work it charged.
    pub fn finish(&self) -> (OneRecord, u64) {
        let scope = std::mem::take(&mut *self.scope());
        let touched: Vec<u32> = (scope.words.iter().enumerate())
            .flat_map(|(w, &word)| {
                (0..64u32)
                    .filter(move |b| word & (1u64 << b) != 0)
                    .map(move |b| w as u32 * 64 + b)
            })
            .collect();
        let record = OneRecord {
            touched,
            asked_mm: scope.asked_mm,
        };
        (record, self.units.load(Ordering::Relaxed))
    }

    fn scope(&self) -> std::sync::MutexGuard<'_, Scope> {
        self.scope.lock().unwrap_or_else(|e| e.into_inner())
    }
}

/// One solve's record as it is made.
#[derive(Debug, Default)]
struct Scope {
    words: Vec<u64>,
    asked_mm: Option<[Point3<f64>; 2]>,
}

impl Scope {
    fn mark(&mut self, index: usize) {
        if self.words.len() <= index / 64 {
            self.words.resize(index / 64 + 1, 0);
        }
        self.words[index / 64] |= 1u64 << (index % 64);
    }

    fn has(&self, index: usize) -> bool {
        (self.words.get(index / 64)).is_some_and(|w| w & (1u64 << (index % 64)) != 0)
    }

    fn take_asked(&mut self, asked: &[Point3<f64>; 2]) {
        self.asked_mm = Some(match self.asked_mm {
            Some([lo, hi]) => [lo.inf(&asked[0]), hi.sup(&asked[1])],
            None => *asked,
        });
    }
}

/// Whether the bounds `a` and `b` meet once `a` is grown by `grow_mm` on
/// every side.
pub fn bounds_meet(a: &[Point3<f64>; 2], b: &[Point3<f64>; 2], grow_mm: f64) -> bool {
    (0..3).all(|i| a[0][i] - grow_mm <= b[1][i] && b[0][i] <= a[1][i] + grow_mm)
}

/// Whether `inner` lies within `outer` grown by `grow_mm` on every side.
pub fn bounds_within(inner: &[Point3<f64>; 2], outer: &[Point3<f64>; 2], grow_mm: f64) -> bool {
    (0..3).all(|i| outer[0][i] - grow_mm <= inner[0][i] && inner[1][i] <= outer[1][i] + grow_mm)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn marks_are_kept_by_index_and_all_covers_every_index() {
        let touched = Touched::new(130);
        touched.mark(3);
        touched.mark(129);
        let set = touched.set();
        assert!(set.contains(3) && set.contains(129));
        assert!(!set.contains(4) && !set.contains(64));
        touched.mark_all();
        assert!(touched.set().contains(4));
    }

    #[test]
    fn one_solve_keeps_its_own_record_beside_the_task_s() {
        let touched = Touched::new(200);
        touched.mark(3);
        let at = |x: f64| [Point3::new(x, 0.0, 0.0), Point3::new(x + 1.0, 1.0, 1.0)];
        let solve = SolveRecord::default();
        // Marked for the task already, but not for this solve.
        assert!(touched.needs(3, Some(&solve)));
        assert!(!touched.needs(3, None));
        solve.mark(3);
        assert!(!touched.needs(3, Some(&solve)));
        solve.mark(130);
        solve.asked(&at(0.0));
        solve.asked(&at(10.0));
        solve.units().fetch_add(7, Ordering::Relaxed);
        let (record, units) = solve.finish();
        assert_eq!(record.touched, vec![3, 130]);
        let [lo, hi] = record.asked_mm.unwrap();
        assert_eq!((lo.x, hi.x, units), (0.0, 11.0, 7));
        // The task's record is the obstacles' to mark, not the solve's.
        assert!(touched.needs(130, None));
    }

    #[test]
    fn grown_bounds_meet_and_hold() {
        let b = [Point3::new(0.0, 0.0, 0.0), Point3::new(10.0, 10.0, 10.0)];
        let near = [Point3::new(13.0, 0.0, 0.0), Point3::new(20.0, 5.0, 5.0)];
        assert!(!bounds_meet(&b, &near, 2.0));
        assert!(bounds_meet(&b, &near, 3.0));
        let moved = [Point3::new(1.0, -1.0, 0.0), Point3::new(11.0, 9.0, 10.0)];
        assert!(bounds_within(&moved, &b, 1.0));
        assert!(!bounds_within(&moved, &b, 0.5));
    }
}
