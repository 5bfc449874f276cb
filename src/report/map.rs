//! A map: which points of a surface the person reaches (or, a gaze map,
//! sees), on a grid.

use std::fmt::Write;

use nalgebra::Vector3;
use serde::Serialize;

use super::entry_kind::{text, Asks, EntryKind, Tolerance};
use super::parts::point;
use super::{deg, fixed, mm, Answer, Figure, ReportKind, Why};
use crate::kinematics::{hand_side, Chain};
use crate::scene::{Grid, GridCell, Person, Placement, Surface};
use serde_json::Value;

/// How much a map's share may move (percentage points) before its answer
/// counts as changed.
const SHARE_TOLERANCE_PERCENT: f64 = 0.5;

/// One map: which points of a surface the person reaches.
#[derive(Clone, Debug, PartialEq, Serialize, schemars::JsonSchema)]
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
    /// The effector whose distance to each point counts (`grip`, `eyes`).
    pub effector: String,
    /// Its twin on the other hand (`left_grip`), where the map reaches
    /// with either hand: each cell's `hand` says which reached it.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub other_hand: Option<String>,
    /// What point of the body that effector is ("the centre of a power
    /// grasp"), as its mannequin says; else "the effector `NAME`".
    pub point: String,
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
    /// Every point, row by row. (Left out where there are none: the JSON
    /// writer serializes a map [`MapReport::without_cells`] and writes
    /// its cells apart.)
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub cells: Vec<MapCell>,
}

impl MapReport {
    /// This map without its cells: what the JSON writer serializes in one
    /// go, writing the cells one at a time, so that a map of 100,000
    /// points is never held as one tree of values.
    pub fn without_cells(&self) -> MapReport {
        // Every field named, so that a field added is not left out.
        let MapReport {
            name,
            person,
            of,
            ok,
            points,
            reachable,
            fraction,
            reachable_heights_mm,
            step_mm,
            tolerance_mm,
            solver,
            effector,
            other_hand,
            point,
            retried,
            base,
            view,
            corner_mm,
            u_mm,
            v_mm,
            columns,
            rows,
            grid,
            cells: _,
        } = self;
        MapReport {
            name: name.clone(),
            person: person.clone(),
            of,
            ok: *ok,
            points: *points,
            reachable: *reachable,
            fraction: *fraction,
            reachable_heights_mm: *reachable_heights_mm,
            step_mm: *step_mm,
            tolerance_mm: *tolerance_mm,
            solver: solver.clone(),
            effector: effector.clone(),
            other_hand: other_hand.clone(),
            point: point.clone(),
            retried: *retried,
            base: base.clone(),
            view,
            corner_mm: *corner_mm,
            u_mm: *u_mm,
            v_mm: *v_mm,
            columns: *columns,
            rows: *rows,
            grid: grid.clone(),
            cells: Vec::new(),
        }
    }
}

/// One point of a map.
#[derive(Clone, Debug, PartialEq, Serialize, schemars::JsonSchema)]
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
    /// Which hand reached the point (`right` or `left`), or came closest,
    /// where the map reaches with either (`other_hand`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub hand: Option<&'static str>,
    /// Reached only thanks to the task's `blocked_solver` (counted in the
    /// map's `retried`).
    #[serde(skip)]
    pub retried: bool,
    /// What more a point not reached says, where it says more (boxed: a
    /// map of 100,000 points keeps its cells twice over while it ends).
    #[serde(flatten)]
    missed: Option<Box<Missed>>,
}

/// What more a map point not reached says.
#[derive(Clone, Debug, Default, PartialEq, Serialize, schemars::JsonSchema)]
struct Missed {
    /// Where the closest posture found came within the tolerance but
    /// passed through something: what (`counter`, "the right thigh").
    #[serde(skip_serializing_if = "Option::is_none")]
    through: Option<String>,
    /// Why it was not reached, found as a reach's is (only where the map
    /// asks, `why true`).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    why: Vec<Why>,
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
            hand: None,
            retried: reachable && placement.retried,
            missed: None,
        }
    }

    /// What the closest posture of a point not reached passed through,
    /// where it came within the tolerance.
    pub fn through(&self) -> Option<&str> {
        self.missed.as_ref()?.through.as_deref()
    }

    /// Why it was not reached (empty where the map did not ask).
    pub fn why(&self) -> &[Why] {
        self.missed.as_ref().map_or(&[], |m| &m.why)
    }

    pub fn set_through(&mut self, through: Option<String>) {
        if through.is_some() || self.missed.is_some() {
            self.missed.get_or_insert_with(Box::default).through = through;
        }
    }

    pub fn set_why(&mut self, why: Vec<Why>) {
        if !why.is_empty() || self.missed.is_some() {
            self.missed.get_or_insert_with(Box::default).why = why;
        }
    }

    /// Why it was not reached, each cause in a few words (empty where the
    /// map did not ask, or it was reached).
    pub fn why_words(&self) -> String {
        let words: Vec<String> = self.why().iter().map(Why::short).collect();
        words.join(", ")
    }
}

impl MapReport {
    /// The surface's unit normal on the side it is used from: the side
    /// where the base stood for most of its points (a hand touches a
    /// cabinet's front from the room, not from inside the cabinet; the
    /// base for a point at its corner may stand beside it).
    pub fn seen_from(&self) -> [f64; 3] {
        let (u, v) = (Vector3::from(self.u_mm), Vector3::from(self.v_mm));
        let normal = u.cross(&v).try_normalize(1e-12).unwrap_or_else(Vector3::z);
        let votes: i64 = (self.cells.iter())
            .map(|c| {
                let base = Vector3::new(c.base_mm_deg[0], c.base_mm_deg[1], c.point_mm[2]);
                let side = normal.dot(&(base - Vector3::from(c.point_mm)));
                i64::from(side > 0.0) - i64::from(side < 0.0)
            })
            .sum();
        if votes < 0 {
            (-normal).into()
        } else {
            normal.into()
        }
    }

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
        let v3 = |v: nalgebra::Vector3<f64>| [mm(v.x), mm(v.y), mm(v.z)];
        let mut report = MapReport {
            name: surface.name.clone(),
            person: person.name.clone(),
            of: "reach",
            ok: false,
            points: cells.len(),
            reachable: 0,
            fraction: 0.0,
            reachable_heights_mm: None,
            step_mm: mm(step_mm),
            tolerance_mm: mm(tolerance_mm),
            solver: solver.to_string(),
            effector: String::new(),
            other_hand: None,
            point: String::new(),
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
            grid: Vec::new(),
            cells,
        };
        report.summarize();
        report
    }

    /// The figures that follow from the cells: how many are reachable,
    /// their share and heights, the rows of `#` and `.`, how many only on
    /// the retry.
    fn summarize(&mut self) {
        let cells = &self.cells;
        let reachable = cells.iter().filter(|c| c.reachable).count();
        let heights: Vec<f64> = cells
            .iter()
            .filter(|c| c.reachable)
            .map(|c| c.point_mm[2])
            .collect();
        self.reachable_heights_mm = (!heights.is_empty()).then(|| {
            let lo = heights.iter().copied().fold(f64::INFINITY, f64::min);
            let hi = heights.iter().copied().fold(f64::NEG_INFINITY, f64::max);
            [lo, hi]
        });
        let columns = self.columns;
        self.grid = (0..self.rows)
            .rev()
            .map(|r| {
                cells[r * columns..(r + 1) * columns]
                    .iter()
                    .map(|c| if c.reachable { '#' } else { '.' })
                    .collect()
            })
            .collect();
        self.ok = reachable > 0;
        self.reachable = reachable;
        self.fraction = fixed(reachable as f64 / cells.len().max(1) as f64, 4);
        self.retried = cells.iter().filter(|c| c.retried).count();
    }

    /// This map (of one hand) together with `other`, the same surface's
    /// map with the other hand, made where this one did not reach: each
    /// point as the hand that reached it, or where neither did, the one
    /// that came closer, and which hand in its `hand`.
    pub fn with_other_hand(mut self, other: MapReport) -> MapReport {
        let sides = [hand_side(&self.effector), hand_side(&other.effector)];
        for (cell, theirs) in self.cells.iter_mut().zip(other.cells) {
            let take =
                !cell.reachable && (theirs.reachable || theirs.distance_mm < cell.distance_mm);
            if take {
                *cell = theirs;
                cell.hand = Some(sides[1]);
            } else {
                cell.hand = Some(sides[0]);
            }
        }
        self.other_hand = Some(other.effector);
        self.summarize();
        self
    }
}

impl ReportKind for MapReport {
    fn answer(&self) -> Answer {
        let [verb, _] = self.words();
        Answer {
            task: if self.of == "gaze" { "gaze_map" } else { "map" },
            subject: self.name.clone(),
            person: self.person.clone(),
            ok: self.ok,
            verdict: format!("{:.1} % of {} {verb}", self.fraction * 100.0, self.points),
            effector: (self.of == "reach").then(|| match &self.other_hand {
                Some(other) => format!("{} or {other}", self.effector),
                None => self.effector.clone(),
            }),
            figures: vec![
                Figure::new(
                    "share",
                    fixed(self.fraction * 100.0, 2),
                    "%",
                    SHARE_TOLERANCE_PERCENT,
                ),
                Figure::new("points", self.points as f64, "", 0.0),
            ],
        }
    }

    fn details(&self, out: &mut String) {
        let heights = match self.reachable_heights_mm {
            Some([lo, hi]) if self.of == "gaze" => format!("seen at heights {lo:.0} to {hi:.0} mm"),
            Some([lo, hi]) => format!("reachable heights {lo:.0} to {hi:.0} mm"),
            None if self.of == "gaze" => "nothing seen".to_string(),
            None => "nothing reachable".to_string(),
        };
        let retried = match self.retried {
            0 => String::new(),
            n => format!("; {n} only on the retry where obstacles blocked"),
        };
        let _ = writeln!(
            out,
            "\n{} by {} ({} base): {} of {} points {} ({:.1} %{}), {}; {} view, {} x {} cells of {:.0} mm",
            self.name,
            self.person,
            self.base,
            self.reachable,
            self.points,
            if self.of == "gaze" { "seen" } else { "reachable" },
            self.fraction * 100.0,
            retried,
            heights,
            self.view,
            self.columns,
            self.rows,
            self.step_mm
        );
        match (&self.other_hand, self.point.is_empty()) {
            (_, true) => {}
            (None, false) => {
                let _ = writeln!(out, "  distance to {} (`{}`)", self.point, self.effector);
            }
            (Some(other), false) => {
                let _ = writeln!(
                    out,
                    "  distance to {} (`{}`), or the same of the other hand (`{other}`)",
                    self.point, self.effector
                );
            }
        }
        if let Some(other) = &self.other_hand {
            let with_other = (self.cells.iter())
                .filter(|c| c.reachable && c.hand == Some(hand_side(other)))
                .count();
            let _ = writeln!(
                out,
                "  with either hand: {} reached only with `{other}` (`hand` in the JSON and CSV)",
                points(with_other)
            );
        }
        let through = self.cells.iter().filter(|c| c.through().is_some()).count();
        if through > 0 {
            let _ = writeln!(
                out,
                "  {} not reached came within the tolerance only through something (`through` in the JSON)",
                points(through)
            );
        }
        let causes = self.causes();
        if !causes.is_empty() {
            let listed: Vec<String> = causes
                .iter()
                .map(|(why, n)| format!("{why} ({})", points(*n)))
                .collect();
            let _ = writeln!(out, "  not reached: {}", listed.join("; "));
        }
    }

    fn coverage(&self) -> Option<(f64, String)> {
        let words = format!(
            "covers {:.1} % ({} of {} points)",
            self.fraction * 100.0,
            self.reachable,
            self.points
        );
        Some((self.fraction, words))
    }
}

impl MapReport {
    /// How many points not reached each cause (in a few words) stopped,
    /// the most first, as found where the map asked why.
    pub fn causes(&self) -> Vec<(String, usize)> {
        let mut counted: std::collections::BTreeMap<String, usize> = Default::default();
        for cell in self.cells.iter().filter(|c| !c.why().is_empty()) {
            let words: Vec<String> = cell.why().iter().map(|w| w.sorted().short()).collect();
            *counted.entry(words.join(", ")).or_default() += 1;
        }
        let mut causes: Vec<(String, usize)> = counted.into_iter().collect();
        causes.sort_by(|a, b| b.1.cmp(&a.1).then_with(|| a.0.cmp(&b.0)));
        causes
    }
}

/// `1 point`, `12 points`.
fn points(n: usize) -> String {
    if n == 1 {
        "1 point".into()
    } else {
        format!("{n} points")
    }
}

impl EntryKind for MapReport {
    /// A gaze map's task is `gaze_map`.
    fn asks(entry: &Value) -> Asks {
        let task = if text(entry, "of") == "gaze" {
            "gaze_map"
        } else {
            "map"
        };
        Asks::by_name(task, entry, "person")
    }
    fn verdict_words(entry: &Value) -> String {
        format!("{:.1} %", entry["fraction"].as_f64().unwrap_or(0.0) * 100.0)
    }
    /// The points that flipped.
    fn changes(old: &Value, new: &Value, _: &Answer, who: &str, _: Tolerance) -> Vec<String> {
        let (was, now) = (reached_cells(old), reached_cells(new));
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
}

/// A map entry's points in words, each with whether it was reached.
fn reached_cells(entry: &Value) -> Vec<(String, bool)> {
    entry["cells"]
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
}

/// A map point's JSON `[x, y, z]` as "(x, y, z) mm".
fn point_words(point: &Value) -> String {
    let xyz: Vec<String> = (point.as_array().into_iter().flatten())
        .map(|c| format!("{:.0}", c.as_f64().unwrap_or(f64::NAN)))
        .collect();
    format!("({}) mm", xyz.join(", "))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_map_without_its_cells_is_the_same_map_less_the_cells() {
        let cell = MapCell {
            column: 0,
            row: 0,
            point_mm: [1.0, 2.0, 3.0],
            reachable: true,
            distance_mm: 0.5,
            comfort: 2.0,
            base_mm_deg: [0.0, 0.0, 90.0],
            hand: Some("left"),
            retried: false,
            missed: None,
        };
        let map = MapReport {
            name: "counter.top".into(),
            person: "ann".into(),
            of: "reach",
            ok: true,
            points: 1,
            reachable: 1,
            fraction: 1.0,
            reachable_heights_mm: Some([3.0, 3.0]),
            step_mm: 100.0,
            tolerance_mm: 10.0,
            solver: "incremental".into(),
            effector: "grip".into(),
            other_hand: Some("left_grip".into()),
            point: "the grip".into(),
            retried: 0,
            base: "wheelchair".into(),
            view: "plan",
            corner_mm: [0.0; 3],
            u_mm: [1.0, 0.0, 0.0],
            v_mm: [0.0, 1.0, 0.0],
            columns: 1,
            rows: 1,
            grid: vec!["#".into()],
            cells: vec![cell],
        };
        let head = map.without_cells();
        assert!(head.cells.is_empty());
        assert_eq!(
            MapReport {
                cells: map.cells.clone(),
                ..head.clone()
            },
            map
        );
        let whole = serde_json::to_value(&map).unwrap();
        let written = serde_json::to_value(&head).unwrap();
        assert!(whole.get("cells").is_some() && written.get("cells").is_none());
    }
}
