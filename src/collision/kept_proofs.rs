//! Proofs that a point is out of reach ([`OutOfReach`]), kept for a whole
//! map. Along a row of a map the base stands in the same place relative to
//! each point (the same approach to the same counter), so the point in the
//! base frame, and the proof, come again and again.
//!
//! Points in the base frame are rounded to a grid of [`GRID_MM`], and a
//! proof is made for the centre of a grid cell with the tolerance widened
//! by the cell's half-diagonal: no posture within it of the centre means
//! none within the tolerance of any point of the cell.
//!
//! A proof the budget of [`BOXES`] did not decide is made again, with
//! four times the budget, when its cell has been asked about four times as
//! often: a cell that comes again and again earns a longer look, and the
//! looks never cost more than a third more than looking once each time.
//!
//! Whether a cell is beyond the trunk's limits and the arm's length (the
//! body left out) is the same whoever asks first, so a placement it rules
//! out is not solved at all: no posture comes within the tolerance there,
//! so it would not even be blocked and retried, and the search shows the
//! closest of the others. Which retries the longer looks skip depends
//! on the order the points are asked in (on the threads); the answers do
//! not: the proof is sound, so a retry it skips would not have reached,
//! and a retry that does not reach leaves the answer as it was
//! (`bases::search`).

use std::collections::HashMap;
use std::sync::Mutex;

use nalgebra::Point3;

use super::beyond::{Verdict, BOXES};
use super::OutOfReach;
use crate::kinematics::Chain;
use crate::scene::OwnBody;

/// The side of the grid cells points are rounded to.
pub const GRID_MM: f64 = 1.0;

/// Half the diagonal of a grid cell: the farthest a point is from its
/// cell's centre.
const HALF_DIAGONAL_MM: f64 = GRID_MM * 0.866_025_403_784_438_7;

/// The largest budget a kept proof is given (about 30 ms).
const MOST_BOXES: usize = 64 * BOXES;

/// A grid cell, and the tolerance's bits.
type Key = ([i64; 3], u64);

/// What is known of one grid cell.
#[derive(Clone, Copy)]
struct Kept {
    /// Whether it is beyond the trunk's limits and the arm's length, body
    /// or none ([`OutOfReach::decide_by_limits`], [`BOXES`] boxes): the
    /// same whoever asks, whenever.
    beyond_limits: bool,
    /// How many times the retry asked about it.
    asked: usize,
    /// The verdict of the longest look so far that kept out of the body.
    verdict: Verdict,
}

/// The proofs made for one chain and one own body.
pub struct KeptProofs<'a> {
    cut: Option<OutOfReach<'a>>,
    cells: Mutex<HashMap<Key, Kept>>,
}

impl<'a> KeptProofs<'a> {
    /// None made yet, for `chain` in a person whose own body and base are
    /// `own`.
    pub fn new(chain: &'a Chain, own: &'a OwnBody) -> Self {
        KeptProofs {
            cut: OutOfReach::of(chain, own),
            cells: Mutex::new(HashMap::new()),
        }
    }

    /// Whether no posture within the trunk's limits, body or none, brings
    /// the effector within `tolerance_mm` of any point of `target_mm`'s
    /// grid cell (in the base frame). The same verdict, whatever was asked
    /// before and by which thread: what is solved may depend on it.
    pub fn beyond_limits(&self, target_mm: &Point3<f64>, tolerance_mm: f64) -> bool {
        self.cell(target_mm, tolerance_mm)
            .is_some_and(|(_, kept)| kept.beyond_limits)
    }

    /// Whether no posture that keeps out of the person's own body brings
    /// the effector within `tolerance_mm` of `target_mm` (in the base
    /// frame), by the proof for the point's grid cell: looked at on the
    /// retry's first question, and again with a larger budget as its
    /// questions grow fourfold while it is undecided. False where it
    /// cannot tell, or there is no proof for this chain. Which answer a
    /// question gets depends on the questions before it: only a retry,
    /// which changes nothing where it fails, may be skipped by it.
    pub fn proves(&self, target_mm: &Point3<f64>, tolerance_mm: f64) -> bool {
        let Some((key, _)) = self.cell(target_mm, tolerance_mm) else {
            return false;
        };
        let asked = {
            let mut cells = self.lock();
            let Some(kept) = cells.get_mut(&key) else {
                return false;
            };
            kept.asked += 1;
            match kept.verdict {
                Verdict::Proved => return true,
                Verdict::Cannot => return false,
                Verdict::Undecided => kept.asked,
            }
        };
        let boxes = BOXES.saturating_mul(asked);
        if !is_power_of_four(asked) || boxes > MOST_BOXES {
            return false;
        }
        let verdict = self.look(&key, boxes, OutOfReach::decide);
        let mut cells = self.lock();
        if let Some(kept) = cells.get_mut(&key) {
            // Another thread's longer look may have decided it meanwhile.
            if kept.verdict == Verdict::Undecided {
                kept.verdict = verdict;
            }
        }
        verdict == Verdict::Proved
    }

    /// The point's grid cell and what is known of it, looked at by the
    /// limits alone if it was not before; none where there is no proof for
    /// this chain.
    fn cell(&self, target_mm: &Point3<f64>, tolerance_mm: f64) -> Option<(Key, Kept)> {
        self.cut.as_ref()?;
        let cell = target_mm.coords.map(|c| (c / GRID_MM).round());
        let key = (
            [cell.x as i64, cell.y as i64, cell.z as i64],
            tolerance_mm.to_bits(),
        );
        if let Some(&kept) = self.lock().get(&key) {
            return Some((key, kept));
        }
        let beyond_limits = self.look(&key, BOXES, OutOfReach::decide_by_limits) == Verdict::Proved;
        let kept = *self.lock().entry(key).or_insert(Kept {
            beyond_limits,
            asked: 0,
            // Beyond the limits is beyond them clear of the body too.
            verdict: if beyond_limits {
                Verdict::Proved
            } else {
                Verdict::Undecided
            },
        });
        Some((key, kept))
    }

    /// The proof `decide` for grid cell `key`, looking at up to `boxes`
    /// boxes.
    fn look(
        &self,
        key: &Key,
        boxes: usize,
        decide: fn(&OutOfReach<'a>, &Point3<f64>, f64, usize) -> Verdict,
    ) -> Verdict {
        let Some(cut) = &self.cut else {
            return Verdict::Undecided;
        };
        let ([x, y, z], tolerance_bits) = *key;
        let centre_mm = Point3::new(x as f64, y as f64, z as f64) * GRID_MM;
        let tolerance_mm = f64::from_bits(tolerance_bits) + HALF_DIAGONAL_MM;
        decide(cut, &centre_mm, tolerance_mm, boxes)
    }

    fn lock(&self) -> std::sync::MutexGuard<'_, HashMap<Key, Kept>> {
        // A thread that panicked while holding it left whole entries.
        self.cells.lock().unwrap_or_else(|e| e.into_inner())
    }
}

/// Whether `n` is 1, 4, 16, 64...
fn is_power_of_four(n: usize) -> bool {
    n.is_power_of_two() && n.trailing_zeros().is_multiple_of(2)
}
