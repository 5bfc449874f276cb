//! The report of a run: one entry per task, in the order of the file. Its
//! JSON form is a documented, stable schema (docs/report.md): lengths in
//! millimetres and angles in degrees whatever units the file used, every
//! number rounded to a fixed number of decimals so that runs compare byte
//! for byte.

use nalgebra::Point3;
use serde::ser::{SerializeMap, Serializer};
use serde::Serialize;

use crate::kinematics::JointKind;
use crate::plugin::Placement;
use crate::scene::{Person, TaskSpec};

/// Version of the JSON schema; raised when a field changes meaning.
pub const SCHEMA_VERSION: u32 = 1;

#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Report {
    pub schema: u32,
    pub file: String,
    pub tasks: Vec<TaskReport>,
}

/// One task's result, tagged by task kind.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "lowercase")]
pub enum TaskReport {
    Reach(ReachReport),
}

impl TaskReport {
    pub fn kind(&self) -> &'static str {
        match self {
            TaskReport::Reach(_) => "reach",
        }
    }

    pub fn name(&self) -> &str {
        match self {
            TaskReport::Reach(r) => &r.name,
        }
    }

    pub fn person(&self) -> &str {
        match self {
            TaskReport::Reach(r) => &r.person,
        }
    }

    pub fn ok(&self) -> bool {
        match self {
            TaskReport::Reach(r) => r.ok,
        }
    }
}

/// Where the base stood.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct BaseReport {
    /// The base plugin's name.
    pub kind: String,
    pub x_mm: f64,
    pub y_mm: f64,
    pub z_mm: f64,
    pub heading_deg: f64,
}

/// Joint values by joint name, in chain order: degrees for revolute joints,
/// millimetres for prismatic ones.
#[derive(Clone, Debug, PartialEq)]
pub struct Posture(pub Vec<(String, f64)>);

impl Serialize for Posture {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let mut map = s.serialize_map(Some(self.0.len()))?;
        for (k, v) in &self.0 {
            map.serialize_entry(k, v)?;
        }
        map.end()
    }
}

#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ReachReport {
    /// The target.
    pub name: String,
    pub person: String,
    /// Reached: `distance_mm <= tolerance_mm`.
    pub ok: bool,
    /// Distance left between effector and target.
    pub distance_mm: f64,
    pub tolerance_mm: f64,
    /// Sweeps (solver iterations) of the kept solution.
    pub iterations: u64,
    /// The comfort criterion C of the posture: 0 is the neutral posture.
    pub comfort: f64,
    pub solver: String,
    pub effector: String,
    pub base: BaseReport,
    pub posture: Posture,
    pub effector_mm: [f64; 3],
    pub target_mm: [f64; 3],
}

impl ReachReport {
    pub fn new(
        task: &TaskSpec,
        person: &Person,
        solver: &str,
        placement: &Placement,
        target: Point3<f64>,
        tolerance_mm: f64,
    ) -> Self {
        let chain = &person.chain;
        let q = &placement.solution.q;
        let effector_room = placement.pose.to_room(&chain.effector(q));
        let posture = chain
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
        let pose = &placement.pose;
        ReachReport {
            name: task.subject.clone(),
            person: person.name.clone(),
            ok: placement.solution.distance_mm <= tolerance_mm,
            distance_mm: mm(placement.solution.distance_mm),
            tolerance_mm: mm(tolerance_mm),
            iterations: placement.solution.iterations,
            comfort: fixed(chain.discomfort(q), 4),
            solver: solver.to_string(),
            effector: chain.effector_name.clone(),
            base: BaseReport {
                kind: person.base.name.clone(),
                x_mm: mm(pose.position_mm.x),
                y_mm: mm(pose.position_mm.y),
                z_mm: mm(pose.position_mm.z),
                heading_deg: deg(pose.heading_rad),
            },
            posture: Posture(posture),
            effector_mm: point(effector_room),
            target_mm: point(target),
        }
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

fn point(p: Point3<f64>) -> [f64; 3] {
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
