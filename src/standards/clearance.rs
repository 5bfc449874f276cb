//! ADA 306: the knee and toe clearance under an obstruction that a forward
//! reach goes over. Knee clearance (306.3): the obstruction's underside at
//! least 685 mm high over its front 205 mm, and the space under it at
//! least 205 mm deep at 685 mm high and 280 mm deep at 230 mm, narrowing
//! between the two by 1 in 6 of height (306.3.3, 306.3.4): a bowl that
//! hangs lower further back, or a trap box, may stand in it where the
//! profile leaves room. Toe clearance (306.2): at least 430 mm deep under
//! the element up to 230 mm high (306.2.3), and as deep as the reach over
//! the obstruction (308.2.2: the clear floor space extends beneath the
//! element so far).

use nalgebra::Point3;

use super::elements::{knee_height, narrowings, Approached, Narrowing};
use super::figures::Figures;
use crate::report::RuleCheck;
use crate::scene::Room;

/// The space under an obstruction a forward reach goes over, measured
/// once for its rules and its clear floor space.
pub(super) struct Under {
    /// The obstruction's underside over its front.
    height_mm: f64,
    /// Where the space narrows below the knee clearance's height, the
    /// wall included (none where there is no knee space).
    narrowings: Vec<Narrowing>,
}

impl Under {
    /// The space under the obstruction `a` at `at`.
    pub(super) fn of(f: &Figures, room: &Room, at: &Point3<f64>, a: &Approached) -> Self {
        let height_mm = knee_height(room, at, a, f.knee_front_deep_mm);
        let narrowings = if height_mm >= f.knee_high_mm {
            narrowings(room, at, a.toward, a.depth_mm, f.knee_high_mm)
        } else {
            Vec::new()
        };
        Under {
            height_mm,
            narrowings,
        }
    }

    /// Whether there is knee space at the front: the underside there at
    /// least as high as the knee clearance.
    pub(super) fn has_knee_space(&self, f: &Figures) -> bool {
        self.height_mm >= f.knee_high_mm
    }

    /// How far back the space is free of anything below `below_mm`.
    fn free_depth(&self, below_mm: f64) -> f64 {
        (self.narrowings.iter())
            .filter(|n| n.bottom_mm < below_mm)
            .map(|n| n.depth_mm)
            .fold(f64::INFINITY, f64::min)
    }

    /// How far back nothing comes down into the knee space: the floor
    /// there is wholly clear floor space.
    pub(super) fn open_depth(&self, f: &Figures) -> f64 {
        self.free_depth(f.knee_high_mm)
    }

    /// 306.3: knee clearance.
    pub(super) fn knee(&self, f: &Figures) -> RuleCheck {
        let height = self.height_mm;
        let limit = format!(
            "at least {:.0} mm high, {:.0} mm deep at that height and {:.0} mm at {:.0} mm (narrowing by 1 in {:.0} between)",
            f.knee_high_mm, f.knee_front_deep_mm, f.knee_deep_mm, f.toe_high_mm, f.knee_slope
        );
        let rule = |ok: bool, measured: String| RuleCheck {
            section: f.sections.knee.into(),
            rule: "knee clearance under the obstruction".into(),
            ok,
            measured,
            limit: limit.clone(),
            shape: None,
        };
        if !self.has_knee_space(f) {
            return rule(
                false,
                format!("none: the obstruction comes down to {height:.0} mm"),
            );
        }
        // The narrowing that leaves least room beyond what its height needs.
        let worst = self.narrowings.iter().min_by(|m, n| {
            let margin = |x: &Narrowing| x.depth_mm - needed_at(f, x.bottom_mm);
            margin(m).total_cmp(&margin(n))
        });
        match worst {
            Some(n) => {
                let low = n.bottom_mm.max(f.toe_high_mm);
                let measured = format!(
                    "{height:.0} mm high, {:.0} mm deep down to {low:.0} mm",
                    n.depth_mm
                );
                rule(n.depth_mm >= needed_at(f, n.bottom_mm), measured)
            }
            None => rule(true, format!("{height:.0} mm high, open behind")),
        }
    }

    /// 306.2 and 308.2.2: toe clearance, as deep as the reach over the
    /// obstruction (`reach_depth_mm`).
    pub(super) fn toe(&self, f: &Figures, reach_depth_mm: f64) -> RuleCheck {
        let depth = self.free_depth(f.toe_high_mm);
        let needed = f.toe_deep_mm.max(reach_depth_mm);
        RuleCheck {
            section: f.sections.toe.into(),
            rule: "toe clearance under the obstruction".into(),
            ok: depth >= needed,
            measured: format!("{depth:.0} mm deep at the floor"),
            limit: format!(
                "at least {needed:.0} mm deep ({:.0} mm, and as deep as the reach)",
                f.toe_deep_mm
            ),
            shape: None,
        }
    }
}

/// How deep the knee space must be at its lowest point, `bottom_mm` (at
/// most 685 mm): 280 mm at 230 mm and below, narrowing to 205 mm at 685.
fn needed_at(f: &Figures, bottom_mm: f64) -> f64 {
    let z = bottom_mm.clamp(f.toe_high_mm, f.knee_high_mm);
    f.knee_deep_mm - (z - f.toe_high_mm) / f.knee_slope
}
