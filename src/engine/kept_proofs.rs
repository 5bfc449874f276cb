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
//! four, sixteen and sixty-four times the budget, once its cell has been
//! asked about four, sixteen and sixty-four times: a cell that comes again
//! and again earns a longer look, and the looks never cost more than a
//! third more than looking once each time. The longer looks are made
//! between the map's rounds ([`KeptProofs::settle`]), never while one is
//! solved: within a round every question gets the verdict of the first
//! look (the same whoever asks first) or of a longer look made before the
//! round, so which retries are skipped, and the work the map does, is the
//! same whatever the order the threads ask in. The answers would not
//! depend on it either way: the proof is sound, so a retry it skips would
//! not have reached, and a retry that does not reach leaves the answer as
//! it was (`bases::search`).

use std::collections::HashMap;
use std::sync::Mutex;

use nalgebra::Point3;
use rayon::prelude::*;

use crate::allowance::Allowance;
use crate::collision::{OutOfReach, Verdict, BOXES};
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
    /// The verdict of the first look that keeps out of the body
    /// ([`BOXES`] boxes), once a question asked for it: the same whoever
    /// asked.
    first: Option<Verdict>,
    /// The verdict of the longest look made between rounds (or of the
    /// limits), and the boxes it was given.
    settled: Verdict,
    looked: usize,
}

/// The proofs made for one chain and one own body.
pub struct KeptProofs<'a> {
    cut: Option<OutOfReach<'a>>,
    cells: Mutex<HashMap<Key, Kept>>,
    /// What each look is told to: the looks kept (one per cell and
    /// budget, whoever made it), so that the work is the same whatever
    /// the threads.
    allowance: &'a dyn Allowance,
}

/// What looking at one box of trunk postures costs, in the meter's units
/// (`crate::meter`; about half a microsecond).
const BOX_UNITS: u64 = 6;

impl<'a> KeptProofs<'a> {
    /// None made yet, for `chain` in a person whose own body and base are
    /// `own`, the looks' work told to `meter`.
    pub fn new(chain: &'a Chain, own: &'a OwnBody, allowance: &'a dyn Allowance) -> Self {
        KeptProofs {
            cut: OutOfReach::of(chain, own),
            cells: Mutex::new(HashMap::new()),
            allowance,
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
    /// frame), by the proof for the point's grid cell: the first look, or
    /// the longest made before this round ([`KeptProofs::settle`]). False
    /// where it cannot tell, or there is no proof for this chain. Only a
    /// retry, which changes nothing where it fails, may be skipped by it.
    pub fn proves(&self, target_mm: &Point3<f64>, tolerance_mm: f64) -> bool {
        let Some((key, _)) = self.cell(target_mm, tolerance_mm) else {
            return false;
        };
        let first = {
            let mut cells = self.lock();
            let Some(kept) = cells.get_mut(&key) else {
                return false;
            };
            kept.asked += 1;
            match kept.settled {
                Verdict::Proved => return true,
                Verdict::Cannot => return false,
                Verdict::Undecided => kept.first,
            }
        };
        let first = first.unwrap_or_else(|| {
            let (verdict, looked) = self.look(&key, BOXES, OutOfReach::decide_looking);
            let mut cells = self.lock();
            match cells.get_mut(&key) {
                Some(Kept {
                    first: Some(kept), ..
                }) => *kept,
                Some(kept) => {
                    self.charge(looked);
                    *kept.first.insert(verdict)
                }
                None => verdict,
            }
        });
        first == Verdict::Proved
    }

    /// Between two rounds of a map: each cell still undecided whose
    /// questions have grown to four, sixteen or sixty-four is looked at
    /// again with so many times `BOXES` (in parallel), and the verdict
    /// answers its questions from the next round on.
    pub fn settle(&self) {
        if self.allowance.exhausted() {
            // The run is thrown away: no longer look is worth making.
            return;
        }
        let longer: Vec<(Key, usize)> = self
            .lock()
            .iter()
            .filter(|(_, kept)| {
                kept.settled == Verdict::Undecided && kept.first == Some(Verdict::Undecided)
            })
            .filter_map(|(key, kept)| {
                let boxes = longest_look(kept.asked);
                (boxes > kept.looked.max(BOXES)).then_some((*key, boxes))
            })
            .collect();
        let verdicts: Vec<(Key, usize, (Verdict, usize))> = longer
            .into_par_iter()
            .map(|(key, boxes)| {
                (
                    key,
                    boxes,
                    self.look(&key, boxes, OutOfReach::decide_looking),
                )
            })
            .collect();
        let mut cells = self.lock();
        for (key, boxes, (verdict, looked)) in verdicts {
            self.charge(looked);
            if let Some(kept) = cells.get_mut(&key) {
                kept.settled = verdict;
                kept.looked = boxes;
            }
        }
    }

    /// The point's grid cell and what is known of it, looked at by the
    /// limits alone if it was not before; none where there is no proof for
    /// this chain.
    fn cell(&self, target_mm: &Point3<f64>, tolerance_mm: f64) -> Option<(Key, Kept)> {
        self.cut.as_ref()?;
        if self.allowance.exhausted() {
            // The run is thrown away: no proof is worth making.
            return None;
        }
        let cell = target_mm.coords.map(|c| (c / GRID_MM).round());
        let key = (
            [cell.x as i64, cell.y as i64, cell.z as i64],
            tolerance_mm.to_bits(),
        );
        if let Some(&kept) = self.lock().get(&key) {
            return Some((key, kept));
        }
        let (verdict, looked) = self.look(&key, BOXES, OutOfReach::decide_by_limits_looking);
        let beyond_limits = verdict == Verdict::Proved;
        let kept = *self.lock().entry(key).or_insert_with(|| {
            self.charge(looked);
            Kept {
                beyond_limits,
                asked: 0,
                first: None,
                // Beyond the limits is beyond them clear of the body too.
                settled: if beyond_limits {
                    Verdict::Proved
                } else {
                    Verdict::Undecided
                },
                looked: 0,
            }
        });
        Some((key, kept))
    }

    /// The proof `decide` for grid cell `key`, looking at up to `boxes`
    /// boxes.
    fn look(
        &self,
        key: &Key,
        boxes: usize,
        decide: fn(&OutOfReach<'a>, &Point3<f64>, f64, usize) -> (Verdict, usize),
    ) -> (Verdict, usize) {
        let Some(cut) = &self.cut else {
            return (Verdict::Undecided, 0);
        };
        let ([x, y, z], tolerance_bits) = *key;
        let centre_mm = Point3::new(x as f64, y as f64, z as f64) * GRID_MM;
        let tolerance_mm = f64::from_bits(tolerance_bits) + HALF_DIAGONAL_MM;
        decide(cut, &centre_mm, tolerance_mm, boxes)
    }

    /// Tell the meter of a look kept that looked at `boxes` boxes.
    fn charge(&self, boxes: usize) {
        self.allowance.spend(boxes as u64 * BOX_UNITS);
    }

    fn lock(&self) -> std::sync::MutexGuard<'_, HashMap<Key, Kept>> {
        // A thread that panicked while holding it left whole entries.
        self.cells.lock().unwrap_or_else(|e| e.into_inner())
    }
}

/// The boxes of the longest look a cell asked about `asked` times has
/// earned: [`BOXES`] times the largest power of four not above `asked`,
/// at most [`MOST_BOXES`].
fn longest_look(asked: usize) -> usize {
    let mut times = 1;
    while times * 4 <= asked && BOXES * times * 4 <= MOST_BOXES {
        times *= 4;
    }
    BOXES * times
}
