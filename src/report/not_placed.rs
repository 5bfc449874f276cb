//! The answer for a person whose base fits nowhere in the task's room, or
//! cannot get anywhere it fits from the room's doors: no posture was
//! looked for, and the report says so and by how much the base misses (or
//! which doors shut it out), so that "Bob's chair does not fit in this
//! galley" is a finding of the run, beside the other people's answers, not
//! an error that stops it.

use std::fmt::Write as _;

use serde::Serialize;

use super::entry_kind::{text, Asks, EntryKind, Tolerance};
use super::reach::quoted;
use super::{fixed, mm, Answer, Figure, ReportKind};
use crate::floor::{Entry, Misfit, Shut};
use serde_json::Value;

/// A task not tried because the person's base fits nowhere.
#[derive(Clone, Debug, PartialEq, Serialize, schemars::JsonSchema)]
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
    /// fits nowhere within it (or cannot get there).
    pub in_zone: bool,
    /// Whether that zone lies wholly outside the room's floor (a mistake
    /// in the zone, not in the base's size).
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub zone_outside_room: bool,
    /// Where the room has doors and the base fits somewhere but cannot get
    /// there: each door and how the base fares at it.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub doors: Vec<DoorReport>,
}

/// One door of a room that shuts a base out.
#[derive(Clone, Debug, PartialEq, Serialize, schemars::JsonSchema)]
pub struct DoorReport {
    pub name: String,
    pub width_mm: f64,
    /// How wide the base is across the opening.
    pub needs_mm: f64,
    /// `too narrow`, `blocked` (something stands just inside) or
    /// `through` (it comes in, but cannot get to where it would fit).
    pub comes_in: &'static str,
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
            zone_outside_room: misfit.zone_outside,
            doors: Vec::new(),
        }
    }

    /// The report of a base that fits somewhere in the room but cannot
    /// get there from any of its doors.
    pub fn shut(
        task: &'static str,
        name: &str,
        person: &str,
        base: &str,
        room: &str,
        shut: &Shut,
    ) -> Self {
        NotPlacedReport {
            task,
            name: name.to_string(),
            person: person.to_string(),
            base: base.to_string(),
            room: room.to_string(),
            ok: false,
            footprint_mm: shut.footprint_mm.map(mm),
            fits_at: 1.0,
            in_zone: shut.in_zone,
            zone_outside_room: false,
            doors: shut
                .doors
                .iter()
                .map(|d| DoorReport {
                    name: d.name.clone(),
                    width_mm: mm(d.width_mm),
                    needs_mm: mm(d.needs_mm),
                    comes_in: match d.comes_in {
                        Entry::TooNarrow => "too narrow",
                        Entry::Blocked => "blocked",
                        Entry::Through => "through",
                    },
                })
                .collect(),
        }
    }

    /// Whether it comes in by a door (and only cannot get to where it
    /// would fit).
    fn comes_in(&self) -> bool {
        self.doors.iter().any(|d| d.comes_in == "through")
    }

    /// The widest the base could be and fit (its width times `fits_at`).
    fn fitting_width_mm(&self) -> f64 {
        self.footprint_mm[1] * self.fits_at
    }
}

impl ReportKind for NotPlacedReport {
    fn answer(&self) -> Answer {
        let verdict = match (self.doors.is_empty(), self.comes_in()) {
            _ if self.zone_outside_room => "does NOT fit: its zone lies outside the room",
            (true, _) => "does NOT fit in the room",
            (false, false) => "cannot get in: no door lets the base in",
            (false, true) => "cannot get there from a door",
        };
        Answer {
            task: self.task,
            subject: self.name.clone(),
            person: self.person.clone(),
            ok: false,
            verdict: verdict.into(),
            effector: None,
            figures: vec![Figure::new("fits at", self.fits_at * 100.0, "%", 0.5)],
        }
    }

    fn details(&self, out: &mut String) {
        if !self.doors.is_empty() {
            self.door_details(out);
            return;
        }
        if self.zone_outside_room {
            let _ = writeln!(
                out,
                "{} by {}: the {} base is kept to a zone that lies outside room `{}` (check `zone`, or `zone_from` and `zone_to`); no posture was looked for",
                self.name, self.person, self.base, self.room
            );
            return;
        }
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

impl NotPlacedReport {
    /// Which doors shut the base out, and how.
    fn door_details(&self, out: &mut String) {
        let where_to = if self.in_zone {
            "its zone"
        } else {
            "anywhere it fits"
        };
        let _ = writeln!(
            out,
            "{} by {}: the {} base cannot get to {where_to} in room `{}` from a door; no posture was looked for",
            self.name, self.person, self.base, self.room
        );
        for d in &self.doors {
            let how = match d.comes_in {
                "too narrow" => format!(
                    "too narrow: the base needs {:.0} mm, the door is {:.0} mm",
                    d.needs_mm, d.width_mm
                ),
                "blocked" => "something stands just inside it".to_string(),
                _ => format!(
                    "the base comes in ({:.0} of {:.0} mm), but every place it fits{} is cut off from it",
                    d.needs_mm,
                    d.width_mm,
                    if self.in_zone { " in its zone" } else { "" }
                ),
            };
            let _ = writeln!(out, "  door {}: {how}", quoted(&d.name));
        }
    }
}

impl EntryKind for NotPlacedReport {
    fn asks(entry: &Value) -> Asks {
        Asks::by_name(text(entry, "task"), entry, "person")
    }
    fn verdict_words(_: &Value) -> String {
        "does NOT fit (or cannot get in)".into()
    }
    fn changes(old: &Value, new: &Value, answer: &Answer, who: &str, _: Tolerance) -> Vec<String> {
        if old["fits_at"] != new["fits_at"] || old["doors"] != new["doors"] {
            return vec![format!("{who}: {}", answer.verdict)];
        }
        Vec::new()
    }
}
