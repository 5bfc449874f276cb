//! A gaze: whether the person sees the target well enough to use it, and
//! if not, why.

use std::fmt::Write;

use nalgebra::Point3;
use serde::Serialize;

use super::entry_kind::{ok_words, placed_answer_changes, Asks, EntryKind, Tolerance};
use super::parts::{point, COMFORT_TOLERANCE, DISTANCE_TOLERANCE_MM};
use super::{deg, fixed, mm, Answer, Asked, BaseReport, Figure, Posture, ReportKind};
use crate::scene::Placement;
use serde_json::Value;

/// Whether the person sees a target well enough to use it, and if not,
/// why.
#[derive(Clone, Debug, PartialEq, Serialize, schemars::JsonSchema)]
pub struct GazeReport {
    /// The target.
    pub name: String,
    pub person: String,
    /// Visible: within the legible range, on the line of sight (acuity at
    /// least the threshold), and not occluded.
    pub ok: bool,
    /// Why not, the first that applies: `too near`, `too far`, `beyond the
    /// neck and eye limits`, `too peripheral`, `occluded`, `the head or
    /// trunk passes through an obstacle`; null if visible.
    pub reason: Option<&'static str>,
    /// The obstacle the line of sight meets first, if any.
    pub occluded_by: Option<String>,
    /// The obstacle a link of the body (not the line of sight) passes
    /// through, if collisions are checked.
    pub collision: Option<String>,
    /// From the eyes to the target.
    pub distance_mm: f64,
    /// The legible range for the object's size (eq. 1-2).
    pub legible_mm: [f64; 2],
    /// Angle between the line of sight and the eyes-to-target direction.
    pub off_axis_deg: f64,
    /// `e^(-7 |angle|)` (eq. 3) and the least the task accepts.
    pub acuity: f64,
    pub acuity_threshold: f64,
    pub size_mm: f64,
    pub comfort: f64,
    pub solver: String,
    pub effector: String,
    /// What point of the body that effector is ("the eyes"), as its
    /// mannequin says; else "the effector `NAME`".
    pub point: String,
    pub base: BaseReport,
    pub posture: Posture,
    pub eyes_mm: [f64; 3],
    pub target_mm: [f64; 3],
}

/// What a gaze found, in internal units, for [`GazeReport::new`].
pub struct Sight {
    pub reason: Option<&'static str>,
    pub occluded_by: Option<String>,
    pub body_collision: Option<String>,
    pub distance_mm: f64,
    pub legible_mm: [f64; 2],
    pub off_axis_rad: f64,
    pub acuity_threshold: f64,
    pub size_mm: f64,
    pub eyes_room_mm: Point3<f64>,
}

impl GazeReport {
    pub fn new(
        asked: &Asked<'_>,
        placement: &Placement,
        target: Point3<f64>,
        sight: Sight,
    ) -> Self {
        let q = &placement.solution.q;
        GazeReport {
            name: asked.subject.to_string(),
            person: asked.person.name.clone(),
            ok: sight.reason.is_none(),
            reason: sight.reason,
            occluded_by: sight.occluded_by,
            collision: sight.body_collision,
            distance_mm: mm(sight.distance_mm),
            legible_mm: sight.legible_mm.map(mm),
            off_axis_deg: deg(sight.off_axis_rad),
            acuity: fixed(crate::vision::acuity(sight.off_axis_rad), 4),
            acuity_threshold: fixed(sight.acuity_threshold, 4),
            size_mm: mm(sight.size_mm),
            comfort: fixed(asked.chain.discomfort(q), 4),
            solver: asked.solver.to_string(),
            effector: asked.chain.effector_name.clone(),
            point: asked.chain.measured_to(),
            base: BaseReport::new(&asked.person.base.name, &placement.pose),
            posture: Posture::new(asked.chain, q),
            eyes_mm: point(sight.eyes_room_mm),
            target_mm: point(target),
        }
    }

    /// `visible`, or why not.
    pub fn verdict(&self) -> String {
        match self.reason {
            None => "visible".into(),
            Some("occluded") => format!(
                "NOT visible: behind {}",
                self.occluded_by.as_deref().unwrap_or("?")
            ),
            Some(reason) => format!("NOT visible: {reason}"),
        }
    }

    /// The eyes' distance, comfort and where the base stood.
    fn figures(&self) -> Vec<Figure> {
        let mut figures = vec![
            Figure::new("distance", self.distance_mm, "mm", DISTANCE_TOLERANCE_MM),
            Figure::new("comfort", self.comfort, "", COMFORT_TOLERANCE),
        ];
        figures.extend(self.base.figures());
        figures
    }
}

impl ReportKind for GazeReport {
    fn answer(&self) -> Answer {
        Answer {
            task: "gaze",
            subject: self.name.clone(),
            person: self.person.clone(),
            ok: self.ok,
            verdict: self.verdict(),
            effector: None,
            figures: self.figures(),
        }
    }

    fn details(&self, out: &mut String) {
        let what = [
            self.name.as_str(),
            "seen by",
            self.person.as_str(),
            self.solver.as_str(),
        ];
        self.base.write_line(out, what);
        let _ = writeln!(
            out,
            "  eyes at ({:.0}, {:.0}, {:.0}) mm, {:.0} mm from the target (legible for {:.0} mm from {:.0} to {:.0} mm), {:.1} deg off the line of sight (acuity {:.2}, needs {:.2})",
            self.eyes_mm[0],
            self.eyes_mm[1],
            self.eyes_mm[2],
            self.distance_mm,
            self.size_mm,
            self.legible_mm[0],
            self.legible_mm[1],
            self.off_axis_deg,
            self.acuity,
            self.acuity_threshold
        );
        if let Some(obstacle) = &self.occluded_by {
            let _ = writeln!(out, "  the line of sight meets `{obstacle}`");
        }
        self.posture.write_line(out);
    }
}

impl EntryKind for GazeReport {
    fn asks(entry: &Value) -> Asks {
        Asks::by_name("gaze", entry, "person")
    }
    fn verdict_words(entry: &Value) -> String {
        ok_words(entry, "visible")
    }
    fn changes(
        old: &Value,
        new: &Value,
        answer: &Answer,
        who: &str,
        tol: Tolerance,
    ) -> Vec<String> {
        let words = Self::verdict_words(old);
        placed_answer_changes((old, new), answer, who, &words, tol)
    }
}
