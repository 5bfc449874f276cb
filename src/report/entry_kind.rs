//! How each kind of report entry compares with the same entry of a golden
//! report (`reach test`): what it asks, by which entries are matched; its
//! verdict in a word or two; and what counts as a change between two
//! entries with the same verdict. Each kind says so in its own file
//! ([`EntryKind`]); [`Kind`] is the one list of kinds, read from an
//! entry's `kind` tag, and every match on it is exhaustive, so a kind
//! added to [`super::TaskReport`] and not here does not compile.
//!
//! Golden reports are read as JSON values: a golden file written by a
//! run of this schema (or edited by hand) is compared field by field,
//! without asking it to be a report this build could have written.

use serde::Deserialize;
use serde_json::Value;

use super::{
    AdviceReport, Answer, GazeReport, MapReport, NotEvaluatedReport, NotPlacedReport,
    PopulationReport, ReachAndGazeReport, ReachReport, StandardReport, TaskReport, Why,
};

/// Floats within these count as unchanged.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tolerance {
    pub mm: f64,
    pub deg: f64,
}

impl Default for Tolerance {
    fn default() -> Self {
        Tolerance { mm: 1.0, deg: 0.1 }
    }
}

/// What a report entry asks: the task, its subject, and who (or which
/// room).
#[derive(Clone, Debug, PartialEq)]
pub struct Asks {
    pub task: String,
    pub subject: String,
    pub who: String,
}

impl Asks {
    /// The entry's `task`, its `name` and its `person` (most kinds).
    pub(super) fn by_name(task: impl Into<String>, entry: &Value, who_field: &str) -> Self {
        Asks {
            task: task.into(),
            subject: text(entry, "name"),
            who: text(entry, who_field),
        }
    }

    /// In words: "reach kettle by ann", "standard ada2010 in kitchen".
    pub fn words(&self) -> String {
        match self.task.as_str() {
            "standard" => format!("standard {} in {}", self.subject, self.who),
            _ => format!("{} {} by {}", self.task, self.subject, self.who),
        }
    }
}

/// What one kind of entry says of itself to a golden comparison.
pub trait EntryKind {
    /// What `entry` (of this kind, as JSON) asks.
    fn asks(entry: &Value) -> Asks;
    /// The verdict of `entry` (of this kind) in a word or two.
    fn verdict_words(entry: &Value) -> String;
    /// What changed from `old` to `new`, entries of this kind with the
    /// same verdict (`answer`, the new one's), beyond `tolerance`: one
    /// line each, about `who`.
    fn changes(old: &Value, new: &Value, answer: &Answer, who: &str, tol: Tolerance)
        -> Vec<String>;
}

/// Every kind of entry a report holds, as its `kind` tag names it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Kind {
    Reach,
    Gaze,
    ReachAndGaze,
    Map,
    NotPlaced,
    NotEvaluated,
    Population,
    Standard,
    Advice,
}

impl Kind {
    /// The kind of `entry`, by its tag (none: not a kind this build knows).
    pub fn of(entry: &Value) -> Option<Kind> {
        Kind::deserialize(&entry["kind"]).ok()
    }

    /// The kind of a run's entry.
    pub fn of_report(report: &TaskReport) -> Kind {
        match report {
            TaskReport::Reach(_) => Kind::Reach,
            TaskReport::Gaze(_) => Kind::Gaze,
            TaskReport::ReachAndGaze(_) => Kind::ReachAndGaze,
            TaskReport::Map(_) => Kind::Map,
            TaskReport::NotPlaced(_) => Kind::NotPlaced,
            TaskReport::NotEvaluated(_) => Kind::NotEvaluated,
            TaskReport::Population(_) => Kind::Population,
            TaskReport::Standard(_) => Kind::Standard,
            TaskReport::Advice(_) => Kind::Advice,
        }
    }

    /// [`EntryKind::asks`] of this kind.
    pub fn asks(self, entry: &Value) -> Asks {
        match self {
            Kind::Reach => ReachReport::asks(entry),
            Kind::Gaze => GazeReport::asks(entry),
            Kind::ReachAndGaze => ReachAndGazeReport::asks(entry),
            Kind::Map => MapReport::asks(entry),
            Kind::NotPlaced => NotPlacedReport::asks(entry),
            Kind::NotEvaluated => NotEvaluatedReport::asks(entry),
            Kind::Population => PopulationReport::asks(entry),
            Kind::Standard => StandardReport::asks(entry),
            Kind::Advice => AdviceReport::asks(entry),
        }
    }

    /// [`EntryKind::verdict_words`] of this kind.
    pub fn verdict_words(self, entry: &Value) -> String {
        match self {
            Kind::Reach => ReachReport::verdict_words(entry),
            Kind::Gaze => GazeReport::verdict_words(entry),
            Kind::ReachAndGaze => ReachAndGazeReport::verdict_words(entry),
            Kind::Map => MapReport::verdict_words(entry),
            Kind::NotPlaced => NotPlacedReport::verdict_words(entry),
            Kind::NotEvaluated => NotEvaluatedReport::verdict_words(entry),
            Kind::Population => PopulationReport::verdict_words(entry),
            Kind::Standard => StandardReport::verdict_words(entry),
            Kind::Advice => AdviceReport::verdict_words(entry),
        }
    }

    /// [`EntryKind::changes`] of this kind.
    pub fn changes(
        self,
        (old, new): (&Value, &Value),
        answer: &Answer,
        who: &str,
        tol: Tolerance,
    ) -> Vec<String> {
        let changes = match self {
            Kind::Reach => ReachReport::changes,
            Kind::Gaze => GazeReport::changes,
            Kind::ReachAndGaze => ReachAndGazeReport::changes,
            Kind::Map => MapReport::changes,
            Kind::NotPlaced => NotPlacedReport::changes,
            Kind::NotEvaluated => NotEvaluatedReport::changes,
            Kind::Population => PopulationReport::changes,
            Kind::Standard => StandardReport::changes,
            Kind::Advice => AdviceReport::changes,
        };
        changes(old, new, answer, who, tol)
    }
}

/// `entry`'s text field `field` ("" where it has none).
pub(super) fn text(entry: &Value, field: &str) -> String {
    entry[field].as_str().unwrap_or_default().to_string()
}

/// "reachable" or "NOT reachable", as `entry`'s `ok` says.
pub(super) fn ok_words(entry: &Value, word: &str) -> String {
    let ok = entry["ok"].as_bool().unwrap_or(false);
    format!("{}{word}", if ok { "" } else { "NOT " })
}

/// The answer of a reach or a gaze (or the part of a reach and gaze):
/// why it was not reached, where its base stood, how far short it fell.
pub(super) fn placed_answer_changes(
    (old, new): (&Value, &Value),
    answer: &Answer,
    who: &str,
    old_words: &str,
    tol: Tolerance,
) -> Vec<String> {
    let mut changes: Vec<String> = why_changed(who, old, new, answer, old_words)
        .into_iter()
        .collect();
    changes.extend(placed(who, old, new, answer.ok, tol));
    changes
}

/// An unreached answer whose reason changed: "still NOT reachable, now
/// blocked by `a` (was: blocked by `b`)". Where the report says why (the
/// `why` found by searching again), that is the reason; what the closest
/// posture happened to meet (`collision`) counts only where it does not.
fn why_changed(
    who: &str,
    old: &Value,
    new: &Value,
    answer: &Answer,
    old_words: &str,
) -> Option<String> {
    let reasons = |v: &Value| {
        let said = v["why"].as_array().is_some_and(|w| !w.is_empty());
        (
            v["why"].clone(),
            v["occluded_by"].clone(),
            v["reason"].clone(),
            if said {
                Value::Null
            } else {
                v["collision"].clone()
            },
        )
    };
    if answer.ok || reasons(old) == reasons(new) {
        return None;
    }
    let now = answer
        .verdict
        .split_once(": ")
        .map_or("for another reason", |(_, why)| why);
    Some(format!(
        "{who} still {old_words}, now {now} (was: {})",
        old_reason(old)
    ))
}

/// Why the golden entry's target was not reached or seen, in a few words.
fn old_reason(old: &Value) -> String {
    if let Some(why) = old.get("why").filter(|w| w.is_array()) {
        let why: Vec<Why> = serde_json::from_value(why.clone()).unwrap_or_default();
        if !why.is_empty() {
            return why.iter().map(Why::short).collect::<Vec<_>>().join("; ");
        }
    }
    match (old["reason"].as_str(), old["occluded_by"].as_str()) {
        (Some("occluded"), Some(by)) => format!("behind {by}"),
        (Some(reason), _) => reason.to_string(),
        _ => "no reason recorded".into(),
    }
}

/// Where the base stood, and how far short an unreached answer falls,
/// beyond the tolerance.
fn placed(who: &str, old: &Value, new: &Value, ok: bool, tol: Tolerance) -> Vec<String> {
    let f = |v: &Value, field: &str| v[field].as_f64().unwrap_or(f64::NAN);
    let (ob, nb) = (&old["base"], &new["base"]);
    let moved = (f(ob, "x_mm") - f(nb, "x_mm")).hypot(f(ob, "y_mm") - f(nb, "y_mm"));
    let turned = angle_apart(f(ob, "heading_deg"), f(nb, "heading_deg"));
    let mut changes = Vec::new();
    if moved > tol.mm || turned > tol.deg {
        changes.push(format!(
            "{who}'s base moved from ({:.0}, {:.0}) heading {:.1} deg to ({:.0}, {:.0}) heading {:.1} deg",
            f(ob, "x_mm"),
            f(ob, "y_mm"),
            f(ob, "heading_deg"),
            f(nb, "x_mm"),
            f(nb, "y_mm"),
            f(nb, "heading_deg")
        ));
    }
    let (od, nd) = (f(old, "distance_mm"), f(new, "distance_mm"));
    if !ok && (od - nd).abs() > tol.mm {
        changes.push(format!("{who} falls {nd:.1} mm short (was {od:.1} mm)"));
    }
    changes
}

/// How far apart two headings are, degrees (0 to 180).
fn angle_apart(a: f64, b: f64) -> f64 {
    let d = (a - b).rem_euclid(360.0);
    d.min(360.0 - d)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every tag the report's schema gives a task entry is a [`Kind`]: a
    /// kind added to the report and not to this list is caught here as
    /// well as by the compiler.
    #[test]
    fn every_tag_of_the_reports_schema_is_a_kind() {
        let schema: Value = serde_json::from_str(&super::super::schema_json()).unwrap();
        let tags: Vec<String> = schema["$defs"]["TaskReport"]["oneOf"]
            .as_array()
            .expect("one schema per kind")
            .iter()
            .map(|k| text(&k["properties"]["kind"], "const"))
            .collect();
        assert_eq!(tags.len(), 9, "{tags:?}");
        for tag in tags {
            let entry = serde_json::json!({ "kind": tag });
            assert!(Kind::of(&entry).is_some(), "`{tag}` is not a Kind");
        }
        assert_eq!(Kind::of(&serde_json::json!({ "kind": "teleport" })), None);
    }
}
