//! The report of a run: one entry per task, in the order of the file. Its
//! JSON form is a documented, stable schema (docs/report.md): lengths in
//! millimetres and angles in degrees whatever units the file used, every
//! number rounded to a fixed number of decimals so that runs compare byte
//! for byte.

use nalgebra::Point3;
use serde::ser::{SerializeMap, Serializer};
use serde::Serialize;

use crate::kinematics::{Chain, JointKind};
use crate::scene::{BasePose, Grid, GridCell, Person, Placement, Room, Surface, TaskSpec};

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
    Gaze(GazeReport),
    #[serde(rename = "reach_and_gaze")]
    ReachAndGaze(Box<ReachAndGazeReport>),
    Map(MapReport),
}

impl TaskReport {
    pub fn kind(&self) -> &'static str {
        match self {
            TaskReport::Reach(_) => "reach",
            TaskReport::Gaze(_) => "gaze",
            TaskReport::ReachAndGaze(_) => "reach_and_gaze",
            TaskReport::Map(_) => "map",
        }
    }

    pub fn name(&self) -> &str {
        match self {
            TaskReport::Reach(r) => &r.name,
            TaskReport::Gaze(g) => &g.name,
            TaskReport::ReachAndGaze(b) => &b.name,
            TaskReport::Map(m) => &m.name,
        }
    }

    pub fn person(&self) -> &str {
        match self {
            TaskReport::Reach(r) => &r.person,
            TaskReport::Gaze(g) => &g.person,
            TaskReport::ReachAndGaze(b) => &b.person,
            TaskReport::Map(m) => &m.person,
        }
    }

    /// Reachable (a map: at least one point is).
    pub fn ok(&self) -> bool {
        match self {
            TaskReport::Reach(r) => r.ok,
            TaskReport::Gaze(g) => g.ok,
            TaskReport::ReachAndGaze(b) => b.ok,
            TaskReport::Map(m) => m.ok,
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
    /// Reached: `distance_mm <= tolerance_mm` and no link through an
    /// obstacle.
    pub ok: bool,
    /// Distance left between effector and target.
    pub distance_mm: f64,
    /// The obstacle a link of the posture passes through (null: none, or
    /// collisions not checked).
    pub collision: Option<String>,
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

/// What a reach-like task asked: by whom, with which chain and solver.
pub struct Asked<'a> {
    pub task: &'a TaskSpec,
    pub person: &'a Person,
    /// The chain of the effector the task names.
    pub chain: &'a Chain,
    pub solver: &'a str,
    pub tolerance_mm: f64,
}

impl ReachReport {
    pub fn new(asked: &Asked<'_>, placement: &Placement, target: Point3<f64>, room: &Room) -> Self {
        let chain = asked.chain;
        let q = &placement.solution.q;
        let effector_room = placement.pose.to_room(&chain.effector(q));
        ReachReport {
            name: asked.task.subject.clone(),
            person: asked.person.name.clone(),
            ok: placement.solution.reaches(asked.tolerance_mm),
            distance_mm: mm(placement.solution.distance_mm),
            collision: placement
                .solution
                .collision
                .map(|i| room.obstacle_name(i).to_string()),
            tolerance_mm: mm(asked.tolerance_mm),
            iterations: placement.solution.iterations,
            comfort: fixed(chain.discomfort(q), 4),
            solver: asked.solver.to_string(),
            effector: chain.effector_name.clone(),
            base: BaseReport::new(&asked.person.base.name, &placement.pose),
            posture: Posture::new(chain, q),
            effector_mm: point(effector_room),
            target_mm: point(target),
        }
    }
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
        Posture(values)
    }
}

/// Whether the person sees a target well enough to use it, and if not,
/// why.
#[derive(Clone, Debug, PartialEq, Serialize)]
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
    pub base: BaseReport,
    pub posture: Posture,
    pub eyes_mm: [f64; 3],
    pub target_mm: [f64; 3],
}

/// `reach T and gaze`: the hand's reach and the eyes' gaze in one posture.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ReachAndGazeReport {
    /// The target.
    pub name: String,
    pub person: String,
    /// Both: the hand reaches and the eyes see.
    pub ok: bool,
    pub reach: ReachReport,
    pub gaze: GazeReport,
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
            name: asked.task.subject.clone(),
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
            base: BaseReport::new(&asked.person.base.name, &placement.pose),
            posture: Posture::new(asked.chain, q),
            eyes_mm: point(sight.eyes_room_mm),
            target_mm: point(target),
        }
    }
}

/// One map: which points of a surface the person reaches.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct MapReport {
    /// The surface (`counter.top`).
    pub name: String,
    pub person: String,
    /// What a point asks: `reach` (reached) or `gaze` (seen).
    pub of: &'static str,
    /// At least one point is reachable.
    pub ok: bool,
    pub points: usize,
    pub reachable: usize,
    /// `reachable / points`, four decimals.
    pub fraction: f64,
    /// Lowest and highest reachable point, if any.
    pub reachable_heights_mm: Option<[f64; 2]>,
    pub step_mm: f64,
    pub tolerance_mm: f64,
    pub solver: String,
    /// Points that count only thanks to the task's `blocked_solver` (the
    /// solver reached them from no placement without going through an
    /// obstacle).
    pub retried: usize,
    /// The base plugin.
    pub base: String,
    /// `plan` for a horizontal surface, `elevation` for a vertical one.
    pub view: &'static str,
    /// The surface's corner and its two edges: columns run along the first,
    /// rows along the second.
    pub corner_mm: [f64; 3],
    pub u_mm: [f64; 3],
    pub v_mm: [f64; 3],
    pub columns: usize,
    pub rows: usize,
    /// One string per row, the last row first: `#` reachable, `.` not.
    pub grid: Vec<String>,
    /// Every point, row by row.
    pub cells: Vec<MapCell>,
}

/// One point of a map.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct MapCell {
    pub column: usize,
    pub row: usize,
    pub point_mm: [f64; 3],
    pub reachable: bool,
    /// Distance left in the best posture found (null if the base fits
    /// nowhere).
    pub distance_mm: f64,
    pub comfort: f64,
    /// Where the base stood: x, y and heading in degrees.
    pub base_mm_deg: [f64; 3],
}

impl MapCell {
    /// The cell of `placement`, `reachable` as the task judged it.
    pub fn new(cell: &GridCell, placement: &Placement, chain: &Chain, reachable: bool) -> Self {
        let pose = &placement.pose;
        MapCell {
            column: cell.column,
            row: cell.row,
            point_mm: point(cell.point_mm),
            reachable,
            distance_mm: mm(placement.solution.distance_mm),
            comfort: fixed(chain.discomfort(&placement.solution.q), 4),
            base_mm_deg: [
                mm(pose.position_mm.x),
                mm(pose.position_mm.y),
                deg(pose.heading_rad),
            ],
        }
    }
}

impl MapReport {
    /// How a point that counts is described: `reached`/`reachable`, or
    /// `seen`/`visible` for a gaze map.
    pub fn words(&self) -> [&'static str; 2] {
        if self.of == "gaze" {
            ["seen", "visible"]
        } else {
            ["reached", "reachable"]
        }
    }

    pub fn new(
        surface: &Surface,
        person: &Person,
        solver: &str,
        step_mm: f64,
        tolerance_mm: f64,
        grid: &Grid,
        cells: Vec<MapCell>,
    ) -> Self {
        let reachable = cells.iter().filter(|c| c.reachable).count();
        let heights: Vec<f64> = cells
            .iter()
            .filter(|c| c.reachable)
            .map(|c| c.point_mm[2])
            .collect();
        let band = (!heights.is_empty()).then(|| {
            let lo = heights.iter().copied().fold(f64::INFINITY, f64::min);
            let hi = heights.iter().copied().fold(f64::NEG_INFINITY, f64::max);
            [lo, hi]
        });
        let rows: Vec<String> = (0..grid.rows)
            .rev()
            .map(|r| {
                cells[r * grid.columns..(r + 1) * grid.columns]
                    .iter()
                    .map(|c| if c.reachable { '#' } else { '.' })
                    .collect()
            })
            .collect();
        let v3 = |v: nalgebra::Vector3<f64>| [mm(v.x), mm(v.y), mm(v.z)];
        MapReport {
            name: surface.name.clone(),
            person: person.name.clone(),
            of: "reach",
            ok: reachable > 0,
            points: cells.len(),
            reachable,
            fraction: fixed(reachable as f64 / cells.len().max(1) as f64, 4),
            reachable_heights_mm: band,
            step_mm: mm(step_mm),
            tolerance_mm: mm(tolerance_mm),
            solver: solver.to_string(),
            retried: 0,
            base: person.base.name.clone(),
            view: if surface.is_horizontal() {
                "plan"
            } else {
                "elevation"
            },
            corner_mm: point(surface.corner_mm),
            u_mm: v3(surface.u_mm),
            v_mm: v3(surface.v_mm),
            columns: grid.columns,
            rows: grid.rows,
            grid: rows,
            cells,
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
