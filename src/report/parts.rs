//! What the kinds of task report share: where the base stood, the posture,
//! what was asked, and the fixed rounding of every number.

use std::fmt::Write;

use nalgebra::Point3;
use serde::ser::{SerializeMap, Serializer};
use serde::Serialize;

use super::Figure;
use crate::kinematics::{Chain, JointKind};
use crate::scene::{BasePose, Blocker, Collision, OwnBody, Person, Room, Wall};

/// Where the base stood.
#[derive(Clone, Debug, PartialEq, Serialize, schemars::JsonSchema)]
pub struct BaseReport {
    /// The base plugin's name.
    pub kind: String,
    pub x_mm: f64,
    pub y_mm: f64,
    pub z_mm: f64,
    pub heading_deg: f64,
}

impl BaseReport {
    pub fn new(kind: &str, pose: &BasePose) -> Self {
        BaseReport {
            kind: kind.to_string(),
            x_mm: mm(pose.position_mm.x),
            y_mm: mm(pose.position_mm.y),
            z_mm: mm(pose.position_mm.z),
            heading_deg: deg(pose.heading_rad),
        }
    }

    /// The pose it reports (to the report's rounding).
    pub fn pose(&self) -> BasePose {
        BasePose {
            position_mm: nalgebra::Point3::new(self.x_mm, self.y_mm, self.z_mm),
            heading_rad: self.heading_deg.to_radians(),
        }
    }

    /// Where it stood, as figures of an answer.
    pub fn figures(&self) -> [Figure; 3] {
        [
            Figure::new("base x", self.x_mm, "mm", BASE_TOLERANCE_MM),
            Figure::new("base y", self.y_mm, "mm", BASE_TOLERANCE_MM),
            Figure::new("heading", self.heading_deg, "deg", HEADING_TOLERANCE_DEG),
        ]
    }

    /// `\nNAME VERB PERSON (SOLVER): KIND base at (x, y, z) mm, heading h deg`.
    pub fn write_line(&self, out: &mut String, what: [&str; 4]) {
        let [name, verb, person, solver] = what;
        let _ = writeln!(
            out,
            "\n{name} {verb} {person} ({solver}): {} base at ({:.0}, {:.0}, {:.0}) mm, heading {:.0} deg",
            self.kind, self.x_mm, self.y_mm, self.z_mm, self.heading_deg
        );
    }
}

/// How far the base may move, and turn, before an answer counts as changed.
const BASE_TOLERANCE_MM: f64 = 5.0;
const HEADING_TOLERANCE_DEG: f64 = 1.0;
/// How much a distance may move before an answer counts as changed.
pub(super) const DISTANCE_TOLERANCE_MM: f64 = 1.0;
/// How much the comfort criterion may move before an answer counts as
/// changed.
pub(super) const COMFORT_TOLERANCE: f64 = 0.05;

/// Joint values by joint name, in chain order: degrees for revolute joints,
/// millimetres for prismatic ones (the names of those are the second
/// field, for the text report; JSON has the values alone).
#[derive(Clone, Debug, PartialEq)]
pub struct Posture(pub Vec<(String, f64)>, pub Vec<String>);

/// A map from joint name to number (JSON objects keep no order in a
/// schema; the report writes them in chain order).
impl schemars::JsonSchema for Posture {
    fn schema_name() -> std::borrow::Cow<'static, str> {
        "Posture".into()
    }

    fn json_schema(_: &mut schemars::SchemaGenerator) -> schemars::Schema {
        schemars::json_schema!({
            "type": "object",
            "description": "Joint values by joint name, in chain order: degrees for revolute joints, millimetres for prismatic ones.",
            "additionalProperties": { "type": "number" }
        })
    }
}

impl Serialize for Posture {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let mut map = s.serialize_map(Some(self.0.len()))?;
        for (k, v) in &self.0 {
            map.serialize_entry(k, v)?;
        }
        map.end()
    }
}

impl Posture {
    /// Joint values of `chain` in the units a user reads.
    pub fn new(chain: &Chain, q: &[f64]) -> Self {
        let values = chain
            .joints
            .iter()
            .zip(q)
            .map(|(j, &v)| {
                let shown = match j.kind {
                    JointKind::Revolute => deg(v),
                    JointKind::Prismatic => mm(v),
                };
                (j.name.clone(), shown)
            })
            .collect();
        let sliding = chain
            .joints
            .iter()
            .filter(|j| j.kind == JointKind::Prismatic)
            .map(|j| j.name.clone())
            .collect();
        Posture(values, sliding)
    }

    /// `  posture (deg): joint value, ..., slide 12.0 mm`: a sliding
    /// joint's value in millimetres, said so.
    pub fn write_line(&self, out: &mut String) {
        let values: Vec<String> = self
            .0
            .iter()
            .map(|(j, v)| match self.1.contains(j) {
                true => format!("{j} {v:.1} mm"),
                false => format!("{j} {v:.1}"),
            })
            .collect();
        let _ = writeln!(out, "  posture (deg): {}", values.join(", "));
    }
}

/// What a reach-like task asked: of what, by whom, with which chain and
/// solver, in which room.
pub struct Asked<'a> {
    /// The target.
    pub subject: &'a str,
    pub person: &'a Person,
    /// The chain of the effector the task names.
    pub chain: &'a Chain,
    pub solver: &'a str,
    pub tolerance_mm: f64,
    pub room: &'a Room,
    /// The person's legs and base.
    pub own: &'a OwnBody,
}

impl Asked<'_> {
    /// A collision in words: the part of the person ("the right forearm"),
    /// and what it runs into (`shelf_3`, "the left thigh", "the floor").
    pub fn describe(&self, c: &Collision) -> (String, String) {
        let names = Names {
            room: self.room,
            own: self.own,
            chain: self.chain,
        };
        (names.part(c), names.blocker(c.blocker))
    }
}

/// What a standing person's balance is called where a posture loses it
/// (`Blocker::Balance`): "the person loses their balance (tipping
/// forwards)".
pub const BALANCE: &str = "their balance";

/// What the parts of a person and the things they meet are called.
pub struct Names<'a> {
    pub room: &'a Room,
    pub own: &'a OwnBody,
    pub chain: &'a Chain,
}

impl Names<'_> {
    pub fn part(&self, c: &Collision) -> String {
        match c.blocker {
            Blocker::Balance(_) => "the person".into(),
            _ => self.chain.volume_name(c.part).to_string(),
        }
    }

    pub fn blocker(&self, b: Blocker) -> String {
        match b {
            Blocker::Obstacle(i) => self.room.obstacle_name(i).to_string(),
            Blocker::Wall(wall) => wall_name(wall, self.room),
            Blocker::Own(i) => self
                .own
                .solids
                .get(i)
                .map_or_else(String::new, |s| s.name.clone()),
            Blocker::Body(owner) => self.chain.volume_name(owner).to_string(),
            Blocker::Balance(t) => format!("{BALANCE} ({})", t.words()),
        }
    }
}

/// How a report names one of the room's sides.
fn wall_name(wall: Wall, room: &Room) -> String {
    let s = room.size_mm;
    match wall {
        Wall::Floor => "the floor".into(),
        Wall::Ceiling => "the ceiling".into(),
        Wall::XMin => "the wall at x = 0".into(),
        Wall::XMax => format!("the wall at x = {} mm", mm(s.x)),
        Wall::YMin => "the wall at y = 0".into(),
        Wall::YMax => format!("the wall at y = {} mm", mm(s.y)),
    }
}

/// `v` rounded to `decimals` places, without negative zero.
pub fn fixed(v: f64, decimals: i32) -> f64 {
    let scale = 10f64.powi(decimals);
    let r = (v * scale).round() / scale;
    if r == 0.0 {
        0.0
    } else {
        r
    }
}

/// A length for the report: millimetres, two decimals.
pub fn mm(v: f64) -> f64 {
    fixed(v, 2)
}

/// An angle for the report: radians in, degrees out, two decimals.
pub fn deg(rad: f64) -> f64 {
    fixed(rad.to_degrees(), 2)
}

pub(super) fn point(p: Point3<f64>) -> [f64; 3] {
    [mm(p.x), mm(p.y), mm(p.z)]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rounding_is_fixed_and_has_no_negative_zero() {
        assert_eq!(mm(12.3456), 12.35);
        assert_eq!(mm(-0.001), 0.0);
        assert!(mm(-0.001).is_sign_positive());
        assert_eq!(deg(std::f64::consts::FRAC_PI_2), 90.0);
    }
}
