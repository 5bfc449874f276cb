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
//! Which points skip the retry then depends on the order the points are
//! asked in (on the threads). The answers do not: the proof is sound, so a
//! retry it skips would not have reached, and a retry that does not reach
//! leaves the answer as it was (`bases::search`).

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
    /// How many times it was asked about.
    asked: usize,
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

    /// Whether no posture brings the effector within `tolerance_mm` of
    /// `target_mm` (in the base frame), by the proof for the point's grid
    /// cell: made now on the first question, and again with a larger
    /// budget as the questions grow fourfold while it is undecided. False
    /// where it cannot tell, or there is no proof for this chain.
    pub fn proves(&self, target_mm: &Point3<f64>, tolerance_mm: f64) -> bool {
        let Some(cut) = &self.cut else {
            return false;
        };
        let cell = target_mm.coords.map(|c| (c / GRID_MM).round());
        let key = (
            [cell.x as i64, cell.y as i64, cell.z as i64],
            tolerance_mm.to_bits(),
        );
        let asked = {
            let mut cells = self.lock();
            let kept = cells.entry(key).or_insert(Kept {
                asked: 0,
                verdict: Verdict::Undecided,
            });
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
        let centre_mm = Point3::from(cell * GRID_MM);
        let verdict = cut.decide(&centre_mm, tolerance_mm + HALF_DIAGONAL_MM, boxes);
        let mut cells = self.lock();
        if let Some(kept) = cells.get_mut(&key) {
            // Another thread's longer look may have decided it meanwhile.
            if kept.verdict == Verdict::Undecided {
                kept.verdict = verdict;
            }
        }
        verdict == Verdict::Proved
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
