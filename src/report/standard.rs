//! A room checked against a building standard: each rule, where it applies
//! (the room, or one of its elements: a target), with what was measured,
//! what the rule allows and whether it holds; and beside each element what
//! the simulated people answered about it, so that "the standard says"
//! and "this person can" are read together.

use std::fmt::Write as _;

use serde::Serialize;

use super::entry_kind::{text, Asks, EntryKind, Tolerance};
use super::reach::quoted;
use super::{Answer, Figure, ReportKind};
use serde_json::Value;

/// A room checked against a standard.
#[derive(Clone, Debug, PartialEq, Serialize, schemars::JsonSchema)]
pub struct StandardReport {
    /// The standard plugin (`ada2010`).
    pub standard: String,
    pub room: String,
    /// Every rule checked holds.
    pub ok: bool,
    /// How many rules were checked, and how many do not hold.
    pub checks: usize,
    pub failed: usize,
    /// What was not checked, and why (a room without doors: its routes).
    pub notes: Vec<String>,
    /// Rules about the room as a whole (its turning space).
    pub room_rules: Vec<RuleCheck>,
    pub elements: Vec<ElementCheck>,
}

/// One rule, checked once.
#[derive(Clone, Debug, PartialEq, Serialize, schemars::JsonSchema)]
pub struct RuleCheck {
    /// The standard's section (`308.3.2`).
    pub section: String,
    /// What it asks, in words (`side reach over an obstruction`).
    pub rule: String,
    pub ok: bool,
    /// What was measured (`1400 mm high over 240 mm`).
    pub measured: String,
    /// What the rule allows (`at most 1170 mm high`).
    pub limit: String,
    /// Where on the floor it was measured, for pictures.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub shape: Option<FloorShape>,
}

/// A shape on the floor, in millimetres.
#[derive(Clone, Debug, PartialEq, Serialize, schemars::JsonSchema)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum FloorShape {
    /// A polygon (a clear floor space, a T-shaped turning space).
    Polygon { points_mm: Vec<[f64; 2]> },
    /// A circle (a round turning space; a route's narrowest width about
    /// where it is measured).
    Circle { centre_mm: [f64; 2], radius_mm: f64 },
}

/// One element (a target) and the rules about it.
#[derive(Clone, Debug, PartialEq, Serialize, schemars::JsonSchema)]
pub struct ElementCheck {
    pub name: String,
    pub at_mm: [f64; 3],
    /// Some approach meets every rule about it.
    pub ok: bool,
    /// The approach whose rules are given: the first that holds, else the
    /// one that comes closest (`forward` or `side`).
    pub approach: String,
    /// Which way a person faces for it, degrees (0 along the room's x).
    pub facing_deg: f64,
    pub rules: Vec<RuleCheck>,
    /// What the people's own tasks about this element answered.
    pub people: Vec<PersonAnswer>,
}

/// A simulated person's answer about an element, from their own task.
#[derive(Clone, Debug, PartialEq, Serialize, schemars::JsonSchema)]
pub struct PersonAnswer {
    pub task: String,
    pub person: String,
    pub ok: bool,
    pub verdict: String,
}

impl StandardReport {
    /// Counts the rules checked and failed, and sets `ok`.
    pub fn counted(mut self) -> Self {
        let all = self
            .room_rules
            .iter()
            .chain(self.elements.iter().flat_map(|e| &e.rules));
        let (checks, failed) = all.fold((0, 0), |(n, f), r| (n + 1, f + usize::from(!r.ok)));
        self.checks = checks;
        self.failed = failed;
        self.ok = failed == 0;
        self
    }
}

impl RuleCheck {
    fn line(&self) -> String {
        let verdict = if self.ok { "holds" } else { "FAILS" };
        format!(
            "{} {}: {}; {}: {verdict}",
            self.section, self.rule, self.measured, self.limit
        )
    }
}

impl ReportKind for StandardReport {
    fn answer(&self) -> Answer {
        let verdict = if self.ok {
            format!("every rule holds ({} checked)", self.checks)
        } else {
            format!("{} of {} checks FAIL", self.failed, self.checks)
        };
        Answer {
            task: "standard",
            subject: self.standard.clone(),
            person: format!("in {}", self.room),
            ok: self.ok,
            verdict,
            effector: None,
            figures: vec![Figure::new("failed", self.failed as f64, "", 0.0)],
        }
    }

    fn details(&self, out: &mut String) {
        let _ = writeln!(
            out,
            "\n{} in room {}: {} of {} checks fail",
            self.standard,
            quoted(&self.room),
            self.failed,
            self.checks
        );
        for note in &self.notes {
            let _ = writeln!(out, "  note: {note}");
        }
        for r in &self.room_rules {
            let _ = writeln!(out, "  {}", r.line());
        }
        for e in &self.elements {
            let [x, y, z] = e.at_mm;
            let _ = writeln!(
                out,
                "  {} at ({x:.0}, {y:.0}, {z:.0}) mm, {} approach facing {:.0} deg: {}",
                quoted(&e.name),
                e.approach,
                e.facing_deg,
                if e.ok { "holds" } else { "FAILS" }
            );
            for r in &e.rules {
                let _ = writeln!(out, "    {}", r.line());
            }
            for p in &e.people {
                let _ = writeln!(out, "    {} ({}): {}", p.person, p.task, p.verdict);
            }
        }
    }

    /// The first three failing rules, and how many more.
    fn rules_met(&self) -> Option<(bool, String)> {
        if self.ok {
            return Some((true, self.answer().verdict));
        }
        let failing: Vec<String> = (self.room_rules.iter().map(|r| (r, None)))
            .chain(
                (self.elements.iter())
                    .flat_map(|e| e.rules.iter().map(move |r| (r, Some(e.name.as_str())))),
            )
            .filter(|(r, _)| !r.ok)
            .map(|(r, element)| match element {
                Some(e) => format!("{} {} at `{e}`", r.section, r.rule),
                None => format!("{} {}", r.section, r.rule),
            })
            .collect();
        let shown = failing
            .iter()
            .take(3)
            .cloned()
            .collect::<Vec<_>>()
            .join("; ");
        let more = match failing.len() {
            n if n > 3 => format!("; and {} more", n - 3),
            _ => String::new(),
        };
        let words = format!(
            "{} of {} checks FAIL: {shown}{more}",
            self.failed, self.checks
        );
        Some((false, words))
    }
}

impl EntryKind for StandardReport {
    fn asks(entry: &Value) -> Asks {
        Asks {
            task: "standard".into(),
            subject: text(entry, "standard"),
            who: text(entry, "room"),
        }
    }
    fn verdict_words(entry: &Value) -> String {
        let ok = entry["ok"].as_bool().unwrap_or(false);
        if ok { "every rule holds" } else { "rules FAIL" }.into()
    }
    /// The rules that flipped, and those newly checked.
    fn changes(old: &Value, new: &Value, _: &Answer, who: &str, _: Tolerance) -> Vec<String> {
        let (was, now) = (rules_of(old), rules_of(new));
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
}

/// A standard entry's rules in words, each with whether it holds.
fn rules_of(entry: &Value) -> Vec<(String, bool)> {
    let room = entry["room_rules"].as_array().cloned().unwrap_or_default();
    let elements = entry["elements"].as_array().cloned().unwrap_or_default();
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
}
