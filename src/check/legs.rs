//! A mannequin's `legs(...)`: its leg dimensions, every one given, each a
//! length; the standing heights of hip, knee and ankle in that order.

use super::eval::fmt_num;
use super::Checker;
use crate::error::{Error, ErrorKind};
use crate::kinematics::Legs;
use crate::syntax::ast::MannequinDecl;

/// The dimensions `legs(...)` takes, in the order of [`Legs`]'s fields.
const LEG_PARAMS: [&str; 10] = [
    "hip_height",
    "knee_height",
    "ankle_height",
    "foot",
    "hip_width",
    "thigh_radius",
    "shank_radius",
    "foot_radius",
    "hip_above_seat",
    "pelvis",
];

impl Checker<'_> {
    /// The legs `decl` declares: `Some(None)` if none, `None` on errors.
    pub(super) fn legs(&mut self, decl: &MannequinDecl) -> Option<Option<Legs>> {
        self.repeated(decl.legs.iter().skip(1).map(|l| l.span), "`legs`");
        let Some(legs) = decl.legs.first() else {
            return Some(None);
        };
        let mut values: [Option<f64>; 10] = [None; 10];
        let mut ok = true;
        for (name, expr) in &legs.args {
            let Some(i) = LEG_PARAMS.iter().position(|p| *p == name.value) else {
                self.error(self.unknown("leg dimension", &name.value, name.span, LEG_PARAMS));
                ok = false;
                continue;
            };
            if values[i].is_some() {
                self.repeated(std::iter::once(name.span), &format!("`{}`", name.value));
                continue;
            }
            let v = self.length(expr);
            if let Some(v) = v.filter(|v| *v < 0.0) {
                let shown = format!("{}mm", fmt_num(v));
                self.out_of_range(expr.span, "a leg dimension", "zero or more", &shown);
                ok = false;
                continue;
            }
            ok &= v.is_some();
            values[i] = v;
        }
        for (i, name) in LEG_PARAMS.iter().enumerate() {
            if values[i].is_none() && ok && !legs.args.iter().any(|(n, _)| n.value == *name) {
                self.error(Error::new(
                    ErrorKind::Missing {
                        owner: "`legs`".into(),
                        what: name,
                    },
                    legs.span,
                ));
                ok = false;
            }
        }
        if !ok {
            return None;
        }
        let [hip, knee, ankle, foot, width, thigh_r, shank_r, foot_r, above_seat, pelvis] =
            values.map(|v| v.unwrap_or_default());
        if !(hip > knee && knee > ankle) {
            let shown = format!(
                "hip {}mm, knee {}mm, ankle {}mm",
                fmt_num(hip),
                fmt_num(knee),
                fmt_num(ankle)
            );
            self.out_of_range(
                legs.span,
                "the standing heights",
                "hip above knee above ankle",
                &shown,
            );
            return None;
        }
        Some(Some(Legs {
            hip_height_mm: hip,
            knee_height_mm: knee,
            ankle_height_mm: ankle,
            foot_mm: foot,
            hip_width_mm: width,
            thigh_radius_mm: thigh_r,
            shank_radius_mm: shank_r,
            foot_radius_mm: foot_r,
            hip_above_seat_mm: above_seat,
            pelvis_mm: pelvis,
        }))
    }
}
