//! A run's answers against a golden report (the JSON of an earlier run a
//! person signed off): about answers, not bytes. Tasks are matched by what
//! they ask (the task, its target or surface, its person, population or
//! room), so adding a task shifts nothing; for each, what counts as a
//! change, in words:
//!
//! - a verdict that flipped ("kettle: ann reachable -> NOT reachable, now
//!   blocked by `upper_cabinet`"), or an unreached answer whose reason
//!   changed;
//! - where the base stood, moved more than the tolerance (default 1 mm,
//!   0.1 deg), and how far short an unreached answer falls;
//! - a map's points that flipped; a population's share or who it leaves
//!   out; a standard's rules that flipped;
//! - a task the golden report has and the run does not, or the reverse.
//!
//! Postures, comfort and iterations are not compared: the same answer may
//! be found by another posture. A golden report of another schema version
//! is not compared at all: it must be written again (`--update`).

use serde_json::Value;

use crate::report::{Answer, TaskReport, Why, SCHEMA_VERSION};

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

/// How a run compares with its golden report.
#[derive(Clone, Debug, PartialEq)]
pub enum Compared {
    /// The same answers.
    Same,
    /// What changed, in words, one line each.
    Changed(Vec<String>),
    /// Written by a reach of another schema version: not comparable.
    OtherSchema { golden: u64 },
    /// Not a report (not JSON, or no tasks).
    Unreadable(String),
}

/// `new` (the run's entries and their JSON) against `golden` (the text of a
/// golden report).
pub fn compare(golden: &str, new: &[TaskReport], tolerance: Tolerance) -> Compared {
    let golden: Value = match serde_json::from_str(golden) {
        Ok(v) => v,
        Err(e) => return Compared::Unreadable(format!("not JSON: {e}")),
    };
    let schema = golden["schema"].as_u64().unwrap_or(0);
    if schema != u64::from(SCHEMA_VERSION) {
        return Compared::OtherSchema { golden: schema };
    }
    let Some(old_tasks) = golden["tasks"].as_array() else {
        return Compared::Unreadable("no `tasks`".into());
    };
    let new_values: Vec<(Value, Answer)> = new
        .iter()
        .map(|t| (serde_json::to_value(t).unwrap_or(Value::Null), t.answer()))
        .collect();
    let mut changes = Vec::new();
    let mut matched = vec![false; new_values.len()];
    for old in old_tasks {
        let key = key_of(old);
        let found =
            (new_values.iter().enumerate()).find(|(k, (v, _))| !matched[*k] && key_of(v) == key);
        match found {
            Some((k, (v, answer))) => {
                matched[k] = true;
                changes.extend(entry_changes(old, v, answer, tolerance));
            }
            None => changes.push(format!(
                "{}: in the golden report, no longer asked",
                key.words()
            )),
        }
    }
    for (k, (v, _)) in new_values.iter().enumerate() {
        if !matched[k] {
            changes.push(format!(
                "{}: not in the golden report (`reach test --update` signs it off)",
                key_of(v).words()
            ));
        }
    }
    if changes.is_empty() {
        Compared::Same
    } else {
        Compared::Changed(changes)
    }
}

/// What a report entry asks: the task, its subject, and who (or which room).
#[derive(Clone, Debug, PartialEq)]
struct Key {
    task: String,
    subject: String,
    who: String,
}

impl Key {
    fn words(&self) -> String {
        match self.task.as_str() {
            "standard" => format!("standard {} in {}", self.subject, self.who),
            _ => format!("{} {} by {}", self.task, self.subject, self.who),
        }
    }
}

fn text(v: &Value, field: &str) -> String {
    v[field].as_str().unwrap_or_default().to_string()
}

fn key_of(v: &Value) -> Key {
    let kind = text(v, "kind");
    match kind.as_str() {
        "standard" => Key {
            task: kind,
            subject: text(v, "standard"),
            who: text(v, "room"),
        },
        "population" => Key {
            task: text(v, "task"),
            subject: text(v, "name"),
            who: text(v, "population"),
        },
        "not_placed" => Key {
            task: text(v, "task"),
            subject: text(v, "name"),
            who: text(v, "person"),
        },
        "map" if text(v, "of") == "gaze" => Key {
            task: "gaze_map".into(),
            subject: text(v, "name"),
            who: text(v, "person"),
        },
        _ => Key {
            task: kind,
            subject: text(v, "name"),
            who: text(v, "person"),
        },
    }
}

/// What changed between one entry of the golden report and the run's.
fn entry_changes(old: &Value, new: &Value, answer: &Answer, tol: Tolerance) -> Vec<String> {
    let key = key_of(new);
    let who = format!("{}: {}", key.subject, key.who);
    let mut changes = Vec::new();
    let old_ok = old["ok"].as_bool().unwrap_or(false);
    if old_ok != answer.ok || text(old, "kind") != text(new, "kind") {
        changes.push(format!("{who} {} -> {}", old_words(old), answer.verdict));
        return changes;
    }
    match text(new, "kind").as_str() {
        "reach" | "gaze" => {
            changes.extend(why_changed(&who, old, new, answer));
            changes.extend(placed(&who, old, new, answer.ok, tol));
        }
        "reach_and_gaze" => {
            for part in ["reach", "gaze"] {
                changes.extend(why_changed(&who, &old[part], &new[part], answer));
                changes.extend(placed(&who, &old[part], &new[part], answer.ok, tol));
            }
        }
        "map" => changes.extend(map_changes(&who, old, new)),
        "population" => changes.extend(population_changes(&who, old, new)),
        "standard" => changes.extend(standard_changes(&who, old, new)),
        _ => {
            if old["fits_at"] != new["fits_at"] || old["doors"] != new["doors"] {
                changes.push(format!("{who}: {}", answer.verdict));
            }
        }
    }
    changes
}

/// The golden entry's verdict, in a word or two.
fn old_words(old: &Value) -> String {
    let ok = old["ok"].as_bool().unwrap_or(false);
    let not = if ok { "" } else { "NOT " };
    match text(old, "kind").as_str() {
        "reach" => format!("{not}reachable"),
        "gaze" => format!("{not}visible"),
        "reach_and_gaze" => format!("{not}reachable and visible"),
        "not_placed" => "does NOT fit (or cannot get in)".into(),
        "standard" => if ok { "every rule holds" } else { "rules FAIL" }.into(),
        "population" => format!("{:.1} %", old["share"].as_f64().unwrap_or(0.0) * 100.0),
        "map" => format!("{:.1} %", old["fraction"].as_f64().unwrap_or(0.0) * 100.0),
        _ => if ok { "ok" } else { "NOT ok" }.into(),
    }
}

/// An unreached answer whose reason changed: "still NOT reachable, now
/// blocked by `a` (was: blocked by `b`)". Where the report says why (the
/// `why` found by searching again), that is the reason; what the closest
/// posture happened to meet (`collision`) counts only where it does not.
fn why_changed(who: &str, old: &Value, new: &Value, answer: &Answer) -> Option<String> {
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
        "{who} still {}, now {now} (was: {})",
        old_words(old),
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

/// A map's points that flipped.
fn map_changes(who: &str, old: &Value, new: &Value) -> Vec<String> {
    let cells = |v: &Value| -> Vec<(String, bool)> {
        v["cells"]
            .as_array()
            .map(|cells| {
                cells
                    .iter()
                    .map(|c| {
                        (
                            point_words(&c["point_mm"]),
                            c["reachable"].as_bool() == Some(true),
                        )
                    })
                    .collect()
            })
            .unwrap_or_default()
    };
    let (was, now) = (cells(old), cells(new));
    if was.len() != now.len() {
        return vec![format!(
            "{who}: the map has {} points, was {}",
            now.len(),
            was.len()
        )];
    }
    let lost: Vec<&str> = (was.iter().zip(&now))
        .filter(|(w, n)| w.1 && !n.1)
        .map(|(w, _)| w.0.as_str())
        .collect();
    let gained: Vec<&str> = (was.iter().zip(&now))
        .filter(|(w, n)| !w.1 && n.1)
        .map(|(w, _)| w.0.as_str())
        .collect();
    let mut changes = Vec::new();
    for (points, word) in [(&lost, "no longer reached"), (&gained, "newly reached")] {
        if !points.is_empty() {
            changes.push(format!(
                "{who}: {} {word}: {}{}",
                match points.len() {
                    1 => "1 point".to_string(),
                    n => format!("{n} points"),
                },
                points
                    .iter()
                    .take(4)
                    .cloned()
                    .collect::<Vec<_>>()
                    .join(", "),
                if points.len() > 4 { ", ..." } else { "" }
            ));
        }
    }
    changes
}

/// A map point's JSON `[x, y, z]` as "(x, y, z) mm".
fn point_words(point: &Value) -> String {
    let xyz: Vec<String> = (point.as_array().into_iter().flatten())
        .map(|c| format!("{:.0}", c.as_f64().unwrap_or(f64::NAN)))
        .collect();
    format!("({}) mm", xyz.join(", "))
}

/// A population's share, its map's shares, and who it leaves out.
fn population_changes(who: &str, old: &Value, new: &Value) -> Vec<String> {
    let mut changes = Vec::new();
    if old["accommodated"] != new["accommodated"] || old["people"] != new["people"] {
        changes.push(format!(
            "{who}: accommodates {} of {} (was {} of {})",
            new["accommodated"], new["people"], old["accommodated"], old["people"]
        ));
    }
    let out = |v: &Value| -> Vec<String> {
        v["excluded"]
            .as_array()
            .map(|e| e.iter().map(|x| text(x, "person")).collect())
            .unwrap_or_default()
    };
    if changes.is_empty() && out(old) != out(new) {
        changes.push(format!("{who}: leaves out other people"));
    }
    let shares = |v: &Value| -> Vec<Value> {
        v["cells"]
            .as_array()
            .map(|c| c.iter().map(|x| x["reached"].clone()).collect())
            .unwrap_or_default()
    };
    let (was, now) = (shares(old), shares(new));
    let flipped = was.iter().zip(&now).filter(|(a, b)| a != b).count();
    if flipped > 0 || was.len() != now.len() {
        changes.push(format!(
            "{who}: {flipped} of the map's points reached by another number of people"
        ));
    }
    changes
}

/// A standard's rules that flipped.
fn standard_changes(who: &str, old: &Value, new: &Value) -> Vec<String> {
    let rules = |v: &Value| -> Vec<(String, bool)> {
        let room = v["room_rules"].as_array().cloned().unwrap_or_default();
        let elements = v["elements"].as_array().cloned().unwrap_or_default();
        let of_elements = elements.iter().flat_map(|e| {
            let name = text(e, "name");
            e["rules"]
                .as_array()
                .cloned()
                .unwrap_or_default()
                .into_iter()
                .map(move |r| {
                    (
                        format!("{} at `{name}`", text(&r, "section")),
                        r["ok"] == true,
                    )
                })
        });
        room.iter()
            .map(|r| {
                (
                    format!("{} {}", text(r, "section"), text(r, "rule")),
                    r["ok"] == true,
                )
            })
            .chain(of_elements)
            .collect()
    };
    let (was, now) = (rules(old), rules(new));
    let mut changes = Vec::new();
    for (rule, ok) in &now {
        match was.iter().find(|(r, _)| r == rule) {
            Some((_, was_ok)) if was_ok != ok => changes.push(format!(
                "{who}: {rule} {} -> {}",
                if *was_ok { "holds" } else { "FAILS" },
                if *ok { "holds" } else { "FAILS" }
            )),
            None => changes.push(format!("{who}: {rule} newly checked")),
            _ => {}
        }
    }
    changes
}
