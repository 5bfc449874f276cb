//! How far a base is from fitting in a room where it fits nowhere: the
//! size of its footprint, and the largest fraction of that size (the
//! outline shrunk about the hip point, its heights kept) that would fit at
//! one of its headings. "A 660 x 1150 mm footprint that would fit at 97 %
//! of its size" says that the narrowest place it needs is about 3 % too
//! small, in the base's own terms, whatever shape the room has.

use std::sync::Arc;

use super::region::Zone;
use super::work::{unbounded, CutShort, Work};
use super::{FloorObstacles, FloorPart, Footprint, Region};
use crate::kept::Memo;
use crate::scene::Room;

/// Why a base fits nowhere, in figures.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Misfit {
    /// The footprint's length (along its heading) and width, on the floor.
    pub size_mm: [f64; 2],
    /// The largest fraction of its size at which it would fit, to within
    /// `PRECISION` (0 when not even `SMALLEST` of it would).
    pub fits_at: f64,
    /// Whether the base was kept to a zone of the floor.
    pub in_zone: bool,
    /// Whether that zone lies wholly outside the room's floor.
    pub zone_outside: bool,
}

/// The smallest fraction of the size tried, and how closely the fraction
/// that fits is found.
const SMALLEST: f64 = 0.05;
const PRECISION: f64 = 0.005;

impl Misfit {
    /// The misfit of `footprint` at `headings` in `room` (within `zone`).
    pub fn of(room: &Room, footprint: &Footprint, headings: &[f64], zone: Option<&Zone>) -> Self {
        let mut work = Work::new(&unbounded);
        let memo = Arc::new(Memo::forgetting());
        Misfit::counted(room, footprint, headings, zone, &mut work, &memo)
            .unwrap_or_else(|_| unreachable!("nothing cuts short a misfit allowed any work"))
    }

    /// Like `of`, its work (the floor its smaller footprints are tried on)
    /// added to `work`, cut short where that would pass what it allows.
    pub fn counted(
        room: &Room,
        footprint: &Footprint,
        headings: &[f64],
        zone: Option<&Zone>,
        work: &mut Work<'_>,
        memo: &Arc<Memo>,
    ) -> Result<Self, CutShort> {
        let mut fits = |scale: f64| -> Result<bool, CutShort> {
            let scaled = footprint.scaled(scale);
            let allows = |units: u64| work.allows(units);
            let obstacles = FloorObstacles::with(room, &scaled, &[], &allows)
                .map_err(|cut| work.cut_short_with(cut.work))?;
            let obstacles = Arc::new(obstacles);
            work.add(obstacles.work())?;
            for &h in headings {
                let region = Region::new(room, &scaled, h, zone, Arc::clone(&obstacles), memo);
                if !region.emptiness(work)? {
                    return Ok(true);
                }
            }
            Ok(false)
        };
        let fits_at = if fits(SMALLEST)? {
            // fits(lo) and not fits(hi), as the base fits nowhere.
            let (mut lo, mut hi) = (SMALLEST, 1.0);
            while hi - lo > PRECISION {
                let mid = (lo + hi) / 2.0;
                if fits(mid)? {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            lo
        } else {
            0.0
        };
        let (x, y) = (room.size_mm.x, room.size_mm.y);
        Ok(Misfit {
            size_mm: footprint.size_mm(),
            fits_at,
            in_zone: zone.is_some(),
            zone_outside: zone.is_some_and(|z| z.outside((x, y))),
        })
    }
}

impl Footprint {
    /// Every outline shrunk (or grown) by `scale` about the hip point, the
    /// heights kept.
    pub fn scaled(&self, scale: f64) -> Footprint {
        Footprint {
            parts: self
                .parts
                .iter()
                .map(|p| FloorPart {
                    outline_mm: p.outline_mm.iter().map(|c| c * scale).collect(),
                    z_mm: p.z_mm,
                })
                .collect(),
        }
    }

    /// The length (along x, the heading) and width (along y) of all the
    /// outlines together.
    pub fn size_mm(&self) -> [f64; 2] {
        let corners = || self.parts.iter().flat_map(|p| &p.outline_mm);
        let span = |k: usize| {
            let lo = corners().map(|c| c[k]).fold(f64::INFINITY, f64::min);
            let hi = corners().map(|c| c[k]).fold(f64::NEG_INFINITY, f64::max);
            if hi >= lo {
                hi - lo
            } else {
                0.0
            }
        };
        [span(0), span(1)]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::BoxObstacle;
    use nalgebra::{Point3, Vector3};

    /// Two counters 1 m deep along x, `gap_mm` apart.
    fn galley(gap_mm: f64) -> Room {
        let counter = |name: &str, y_mm: f64| BoxObstacle {
            name: name.into(),
            corner_mm: Point3::new(0.0, y_mm, 0.0),
            size_mm: Vector3::new(3000.0, 1000.0, 900.0),
            yaw_rad: 0.0,
        };
        Room {
            name: "galley".into(),
            size_mm: Vector3::new(3000.0, 2000.0 + gap_mm, 2400.0),
            boxes: vec![counter("left", 0.0), counter("right", 1000.0 + gap_mm)],
            meshes: Vec::new(),
            targets: Vec::new(),
            surfaces: Vec::new(),
            doors: Vec::new(),
        }
    }

    /// A gap a millimetre narrower than a 700 mm chair keeps it out at
    /// every heading; a millimetre wider lets it in (along the galley).
    #[test]
    fn a_millimetre_decides_whether_a_chair_fits_between_two_counters() {
        let chair = Footprint::rectangle(600.0, 500.0, 700.0, 1200.0);
        let fits = |gap_mm: f64| {
            let room = galley(gap_mm);
            let obstacles = Arc::new(FloorObstacles::new(&room, &chair));
            let memo = Arc::new(Memo::forgetting());
            (0..16).any(|k| {
                let heading = f64::from(k) * std::f64::consts::PI / 8.0;
                !Region::new(&room, &chair, heading, None, Arc::clone(&obstacles), &memo).is_empty()
            })
        };
        assert!(!fits(699.0));
        assert!(fits(701.0));
    }

    /// A 700 mm wide chair (a rectangle to the floor) in a galley 640 mm
    /// wide, along it or across: it would fit at 640 / 700 of its size.
    #[test]
    fn a_chair_too_wide_for_a_galley_would_fit_at_the_gap_over_its_width() {
        let chair = Footprint::rectangle(600.0, 500.0, 700.0, 1200.0);
        let headings: Vec<f64> = (0..8)
            .map(|k| f64::from(k) * std::f64::consts::FRAC_PI_4)
            .collect();
        let misfit = Misfit::of(&galley(640.0), &chair, &headings, None);
        assert_eq!(misfit.size_mm, [1100.0, 700.0]);
        let expected = 640.0 / 700.0;
        assert!(
            misfit.fits_at <= expected && misfit.fits_at > expected - 2.0 * PRECISION,
            "{misfit:?}, expected {expected}"
        );
    }
}
