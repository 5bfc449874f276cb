//! Answers kept by what their questions touched. A task that records
//! which obstacles its questions came near (`collision::Touched`) keeps
//! its answer under a key of everything but the obstacles (its settings,
//! subject, person, placements and the floor), beside the room's
//! obstacles as they were. A later room with the same key takes the
//! answer when each obstacle is as it was, or was not touched and still
//! lies within its old bounds grown by the margin: every question then
//! gets the answer it got, so the run would be the same run. An obstacle
//! near the task's points counts as touched whatever the record says: a
//! mobile base measures an approach against the face a target is on.

use std::collections::hash_map::DefaultHasher;
use std::hash::Hasher;
use std::sync::Arc;

use nalgebra::Point3;

use crate::bases::ON_FACE_MM;
use crate::collision::{bounds_meet, bounds_within, obstacle_bounds, TouchedSet, TOUCH_MARGIN_MM};
use crate::engine::{Changed, Earlier, SolveMap};
use crate::report::TaskReport;
use crate::scene::Room;

/// One of the room's obstacles as a kept answer saw it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Seen {
    /// Its bounds as the collision checks hold them (none: a mesh with
    /// no solid, which they leave out).
    bounds: Option<[Point3<f64>; 2]>,
    /// A hash of it by value, name included.
    value: u64,
}

/// A hash of the room's obstacles as `seen`, each by value, names
/// included.
pub(super) fn hash_seen(seen: &[Seen]) -> u64 {
    let mut h = DefaultHasher::new();
    for s in seen {
        h.write_u64(s.value);
    }
    h.write_usize(seen.len());
    h.finish()
}

/// The room's obstacles (the boxes, then the meshes) as seen now.
pub(super) fn seen(room: &Room) -> Vec<Seen> {
    obstacle_bounds(room)
        .into_iter()
        .enumerate()
        .map(|(i, bounds)| {
            let mut h = DefaultHasher::new();
            room.hash_obstacle(i, &mut h);
            Seen {
                bounds,
                value: h.finish(),
            }
        })
        .collect()
}

/// An answer kept with what it depended on of the room's obstacles.
#[derive(Clone)]
pub(super) struct Kept {
    pub report: TaskReport,
    /// The work its solvers did ([`crate::meter`]).
    pub work: u64,
    /// What its questions touched, and the obstacles near its points.
    touched: TouchedSet,
    /// The room's obstacles as they were when it was found.
    seen: Vec<Seen>,
    /// Its run's solves, for a run of the task after an edit
    /// (`engine::KeptSolves`).
    solves: Arc<SolveMap>,
}

impl Kept {
    /// `report` and its work, found in a room whose obstacles were `seen`, its
    /// questions having touched `touched`; the task's points lie within
    /// `points_bounds`.
    pub fn new(
        (report, work): (TaskReport, u64),
        mut touched: TouchedSet,
        seen: Vec<Seen>,
        points_bounds: Option<[Point3<f64>; 2]>,
        solves: Arc<SolveMap>,
    ) -> Self {
        // A box within this of a point may hold the face an approach is
        // measured against (a hand's lift from a map's surface included).
        let face_mm = ON_FACE_MM + 2.0 * TOUCH_MARGIN_MM + 100.0;
        for (i, s) in seen.iter().enumerate() {
            let near = match (s.bounds, points_bounds) {
                (Some(b), Some(p)) => bounds_meet(&b, &p, face_mm),
                _ => true,
            };
            if near {
                touched.insert(i);
            }
        }
        Kept {
            report,
            work,
            touched,
            seen,
            solves,
        }
    }

    /// Its run's solves let go (it is kept only for an edit undone, whose
    /// next run then solves afresh): only the last run's entries hold
    /// theirs, so that the memory stays that of one run's solves.
    pub fn drop_solves(&mut self) {
        self.solves = Arc::default();
    }

    /// Whether its run ranked the room's obstacles by distance.
    pub fn ranked(&self) -> bool {
        self.touched.ranked()
    }

    /// Whether the answer holds in a room (of the same key) whose
    /// obstacles are `now`.
    pub fn holds(&self, now: &[Seen]) -> bool {
        self.seen.len() == now.len()
            && (self.seen.iter().zip(now).enumerate()).all(|(i, (was, is))| {
                was.value == is.value || (!self.touched.contains(i) && stays_near(was, is))
            })
    }

    /// The solves of its run that a run of the task in a room (of the
    /// same key) whose obstacles are `now` may take, with the obstacles
    /// changed since (`engine::KeptSolves` works out which solves hold).
    /// None where obstacles were added or taken away.
    pub fn earlier(&self, now: &[Seen]) -> Option<Earlier> {
        if self.seen.len() != now.len() || self.solves.is_empty() {
            return None;
        }
        let changed = (self.seen.iter().zip(now).enumerate())
            .filter(|(_, (was, is))| was.value != is.value)
            .map(|(index, (was, is))| Changed {
                index,
                bounds_mm: is.bounds,
                near: stays_near(was, is),
            })
            .collect();
        Some(Earlier::new(Arc::clone(&self.solves), changed))
    }
}

/// Whether an obstacle that was as `was` is now within those bounds
/// grown by the margin.
fn stays_near(was: &Seen, is: &Seen) -> bool {
    match (was.bounds, is.bounds) {
        (Some(a), Some(b)) => bounds_within(&b, &a, TOUCH_MARGIN_MM),
        (None, None) => true,
        _ => false,
    }
}

/// The bounds of `points`, none if there are none.
pub(super) fn points_bounds(points: &[Point3<f64>]) -> Option<[Point3<f64>; 2]> {
    let first = *points.first()?;
    Some(
        points
            .iter()
            .fold([first, first], |[lo, hi], p| [lo.inf(p), hi.sup(p)]),
    )
}
