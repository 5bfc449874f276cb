//! The answer for a person whose base fits nowhere in the task's room: no
//! posture was looked for, and the report says so and by how much the base
//! misses, so that "Bob's chair does not fit in this galley" is a finding
//! of the run, beside the other people's answers, not an error that stops
//! it.

use std::fmt::Write as _;

use serde::Serialize;

use super::{fixed, mm, Answer, Figure, ReportKind};
use crate::floor::Misfit;

/// A task not tried because the person's base fits nowhere.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct NotPlacedReport {
    /// The task as the text report names it (`reach`, `map`, ...).
    pub task: &'static str,
    /// The target or surface.
    pub name: String,
    pub person: String,
    /// The base plugin (`manual_wheelchair` is the `wheelchair` plugin).
    pub base: String,
    pub room: String,
    /// Always false.
    pub ok: bool,
    /// The footprint's length (along its heading) and width on the floor,
    /// with the person's legs and upright trunk.
    pub footprint_mm: [f64; 2],
    /// The largest fraction of the footprint's size (outline shrunk about
    /// the hip point) that would fit somewhere in the room at one of the
    /// headings allowed, to within 0.005; 0 when not even 5 % would.
    pub fits_at: f64,
    /// Whether the base was kept to a zone (`zone_from`, `zone_to`): it
    /// fits nowhere within it.
    pub in_zone: bool,
}

impl NotPlacedReport {
    pub fn new(
        task: &'static str,
        name: &str,
        person: &str,
        base: &str,
        room: &str,
        misfit: &Misfit,
    ) -> Self {
        NotPlacedReport {
            task,
            name: name.to_string(),
            person: person.to_string(),
            base: base.to_string(),
            room: room.to_string(),
            ok: false,
            footprint_mm: misfit.size_mm.map(mm),
            fits_at: fixed(misfit.fits_at, 3),
            in_zone: misfit.in_zone,
        }
    }

    /// The widest the base could be and fit (its width times `fits_at`).
    fn fitting_width_mm(&self) -> f64 {
        self.footprint_mm[1] * self.fits_at
    }
}

impl ReportKind for NotPlacedReport {
    fn answer(&self) -> Answer {
        Answer {
            task: self.task,
            subject: self.name.clone(),
            person: self.person.clone(),
            ok: false,
            verdict: "does NOT fit in the room".into(),
            figures: vec![Figure::new("fits at", self.fits_at * 100.0, "%", 0.5)],
        }
    }

    fn details(&self, out: &mut String) {
        let [length, width] = self.footprint_mm;
        let _ = write!(
            out,
            "{} by {}: the {} base fits nowhere in room `{}`{}: its footprint, {length:.0} x {width:.0} mm with the person's legs, ",
            self.name,
            self.person,
            self.base,
            self.room,
            if self.in_zone { " within its zone" } else { "" }
        );
        let _ = if self.fits_at > 0.0 {
            writeln!(
                out,
                "would fit only at {:.1} % of its size (about {:.0} mm wide); no posture was looked for",
                self.fits_at * 100.0,
                self.fitting_width_mm()
            )
        } else {
            writeln!(
                out,
                "would not fit at 5 % of its size; no posture was looked for"
            )
        };
    }
}
