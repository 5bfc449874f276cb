//! `reach T and gaze`: the hand's reach and the eyes' gaze in one posture.

use serde::Serialize;

use super::{Answer, GazeReport, ReachReport, ReportKind};

/// `reach T and gaze`: the hand's reach and the eyes' gaze in one posture.
#[derive(Clone, Debug, PartialEq, Serialize, schemars::JsonSchema)]
pub struct ReachAndGazeReport {
    /// The target.
    pub name: String,
    pub person: String,
    /// Both: the hand reaches and the eyes see.
    pub ok: bool,
    pub reach: ReachReport,
    pub gaze: GazeReport,
}

impl ReportKind for ReachAndGazeReport {
    /// The reach's figures; the verdict says both.
    fn answer(&self) -> Answer {
        Answer {
            task: "reach+gaze",
            subject: self.name.clone(),
            person: self.person.clone(),
            ok: self.ok,
            verdict: format!("{}, {}", self.reach.verdict(), self.gaze.verdict()),
            figures: self.reach.figures(),
        }
    }

    fn details(&self, out: &mut String) {
        self.reach.details(out);
        self.gaze.details(out);
    }
}
