//! `reach T and gaze`: the hand's reach and the eyes' gaze in one posture.

use serde::Serialize;

use super::entry_kind::{ok_words, placed_answer_changes, Asks, EntryKind, Tolerance};
use super::{Answer, GazeReport, ReachReport, ReportKind};
use serde_json::Value;

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
            effector: Some(self.reach.effector.clone()),
            figures: self.reach.figures(),
        }
    }

    fn details(&self, out: &mut String) {
        self.reach.details(out);
        self.gaze.details(out);
    }

    fn answer_of(&self, sees: bool) -> Answer {
        match sees {
            true => self.gaze.answer(),
            false => self.reach.answer(),
        }
    }
}

impl EntryKind for ReachAndGazeReport {
    fn asks(entry: &Value) -> Asks {
        Asks::by_name("reach_and_gaze", entry, "person")
    }
    fn verdict_words(entry: &Value) -> String {
        ok_words(entry, "reachable and visible")
    }
    /// Each part (the reach, the gaze) as a reach or a gaze compares,
    /// its own verdict in the words "ok" or "NOT ok".
    fn changes(
        old: &Value,
        new: &Value,
        answer: &Answer,
        who: &str,
        tol: Tolerance,
    ) -> Vec<String> {
        let mut changes = Vec::new();
        for part in ["reach", "gaze"] {
            let (old, new) = (&old[part], &new[part]);
            let words = ok_words(old, "ok");
            changes.extend(placed_answer_changes((old, new), answer, who, &words, tol));
        }
        changes
    }
}
