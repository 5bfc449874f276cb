//! A reach: whether the person's effector comes to the target, from where,
//! in which posture.

use std::fmt::Write;

use nalgebra::Point3;
use serde::Serialize;

use super::entry_kind::{ok_words, placed_answer_changes, Asks, EntryKind, Tolerance};
use super::parts::{point, BALANCE, COMFORT_TOLERANCE, DISTANCE_TOLERANCE_MM};
use super::{fixed, mm, Answer, Asked, BaseReport, Figure, Posture, ReportKind, Why};
use crate::scene::Placement;
use serde_json::Value;

#[derive(Clone, Debug, PartialEq, Serialize, schemars::JsonSchema)]
pub struct ReachReport {
    /// The target.
    pub name: String,
    pub person: String,
    /// Reached: `distance_mm <= tolerance_mm` and no link through an
    /// obstacle.
    pub ok: bool,
    /// Distance left between effector and target.
    pub distance_mm: f64,
    /// What a part of the posture passes through: an obstacle of the room,
    /// a wall, or the person's own body or base ("the left thigh"); or,
    /// standing, "their balance (tipping forwards)" where the posture
    /// loses it; null: nothing, or collisions not checked.
    pub collision: Option<String>,
    /// Which part of the person passes through it ("the right forearm";
    /// "the person" where it is their balance).
    pub collision_part: Option<String>,
    pub tolerance_mm: f64,
    /// Sweeps (solver iterations) of the kept solution.
    pub iterations: u64,
    /// The comfort criterion C of the posture: 0 is the neutral posture.
    pub comfort: f64,
    pub solver: String,
    /// The effector brought to the target (`grip`, `fingertip`).
    pub effector: String,
    /// What point of the body that effector is, which `distance_mm` is
    /// measured to ("the centre of a power grasp"), as its mannequin says;
    /// else "the effector `NAME`".
    pub point: String,
    pub base: BaseReport,
    pub posture: Posture,
    pub effector_mm: [f64; 3],
    pub target_mm: [f64; 3],
    /// Why the target was not reached, found by searching again without
    /// what may have stopped it (the room's obstacles; or the person's own
    /// body and the joints' limits, each alone enough; or out of reach);
    /// empty when it was reached.
    pub why: Vec<Why>,
    /// Reached with the target behind the person (more than 110 degrees
    /// round from the way the base faces): the search keeps such a
    /// posture only where no placement facing the target reached it.
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub behind: bool,
    /// Standing: where the feet went to keep the person's balance, moved
    /// from under the hip point (forward, to the left), mm; absent where
    /// they stay under it, where it is not reached, and seated.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub feet_moved_mm: Option<[f64; 2]>,
}

impl ReachReport {
    pub fn new(asked: &Asked<'_>, placement: &Placement, target: Point3<f64>) -> Self {
        let chain = asked.chain;
        let q = &placement.solution.q;
        let effector_room = placement.pose.to_room(&chain.effector(q));
        let collision = placement.solution.collision.map(|c| asked.describe(&c));
        ReachReport {
            name: asked.subject.to_string(),
            person: asked.person.name.clone(),
            ok: placement.solution.reaches(asked.tolerance_mm),
            distance_mm: mm(placement.solution.distance_mm),
            collision_part: collision.as_ref().map(|(part, _)| part.clone()),
            collision: collision.map(|(_, blocker)| blocker),
            tolerance_mm: mm(asked.tolerance_mm),
            iterations: placement.solution.iterations,
            comfort: fixed(chain.discomfort(q), 4),
            solver: asked.solver.to_string(),
            effector: chain.effector_name.clone(),
            point: chain.measured_to(),
            base: BaseReport::new(&asked.person.base.name, &placement.pose),
            posture: Posture::new(chain, q),
            effector_mm: point(effector_room),
            target_mm: point(target),
            why: Vec::new(),
            behind: placement.solution.reaches(asked.tolerance_mm)
                && placement.pose.has_behind(&target),
            feet_moved_mm: feet_moved(asked, placement),
        }
    }

    /// `reachable` or `NOT reachable`.
    pub fn verdict(&self) -> String {
        match (self.why.as_slice(), self.ok) {
            (_, true) if self.behind => "reachable, only facing away".into(),
            (_, true) => "reachable".into(),
            ([], false) => "NOT reachable".into(),
            (why, false) => {
                let short: Vec<String> = why.iter().map(Why::short).collect();
                format!("NOT reachable: {}", short.join("; "))
            }
        }
    }

    /// Distance left, sweeps, comfort and where the base stood.
    pub fn figures(&self) -> Vec<Figure> {
        let mut figures = vec![
            Figure::new("distance", self.distance_mm, "mm", DISTANCE_TOLERANCE_MM),
            Figure::new("sweeps", self.iterations as f64, "", f64::INFINITY),
            Figure::new("comfort", self.comfort, "", COMFORT_TOLERANCE),
        ];
        figures.extend(self.base.figures());
        figures
    }
}

/// Standing, where the feet of the placement's posture go to keep the
/// balance, where it reaches and they leave the hip point's vertical.
fn feet_moved(asked: &Asked<'_>, placement: &Placement) -> Option<[f64; 2]> {
    let balance = asked.own.balance.as_ref()?;
    let solution = &placement.solution;
    if !solution.reaches(asked.tolerance_mm) {
        return None;
    }
    let moved = balance
        .feet_moved_mm(&asked.chain.volumes(&solution.q))
        .ok()?;
    let [x, y] = [mm(moved.x), mm(moved.y)];
    (x != 0.0 || y != 0.0).then_some([x, y])
}

/// "the feet 62 mm ahead of and 10 mm to the left of the hip point, for
/// balance".
fn feet_words([forward, left]: [f64; 2]) -> String {
    let mut ways = Vec::new();
    if forward != 0.0 {
        let way = if forward > 0.0 { "ahead of" } else { "behind" };
        ways.push(format!("{:.0} mm {way}", forward.abs()));
    }
    if left != 0.0 {
        let way = if left > 0.0 {
            "to the left of"
        } else {
            "to the right of"
        };
        ways.push(format!("{:.0} mm {way}", left.abs()));
    }
    format!("the feet {} the hip point, for balance", ways.join(" and "))
}

impl ReportKind for ReachReport {
    fn answer(&self) -> Answer {
        Answer {
            task: "reach",
            subject: self.name.clone(),
            person: self.person.clone(),
            ok: self.ok,
            verdict: self.verdict(),
            effector: Some(self.effector.clone()),
            figures: self.figures(),
        }
    }

    fn details(&self, out: &mut String) {
        let what = [
            self.name.as_str(),
            "by",
            self.person.as_str(),
            self.solver.as_str(),
        ];
        if self.distance_mm.is_finite() {
            self.base.write_line(out, what);
            self.posture.write_line(out);
            let _ = writeln!(out, "  distance to {} (`{}`)", self.point, self.effector);
            if let Some(feet) = self.feet_moved_mm {
                let _ = writeln!(out, "  {}", feet_words(feet));
            }
            if self.behind {
                let _ = writeln!(
                    out,
                    "  the target is behind the person (more than 110 deg round from the way the base faces): no placement facing it reached it"
                );
            }
        } else {
            // No place to approach the target from: no base was placed and
            // no posture looked for.
            let [name, verb, person, _] = what;
            let _ = writeln!(out, "\n{name} {verb} {person}: the base was not placed");
        }
        if let (Some(part), Some(what)) = (&self.collision_part, &self.collision) {
            if what.starts_with(BALANCE) {
                let _ = writeln!(out, "  {part} loses {what}");
            } else {
                let _ = writeln!(out, "  {part} passes through {}", quoted(what));
            }
        }
        for why in &self.why {
            let _ = writeln!(out, "  why: {}", why.sentence());
        }
    }
}

/// A room's obstacle in backquotes; the person's own parts and the room's
/// sides ("the left thigh", "the floor") as they are.
pub fn quoted(what: &str) -> String {
    if what.starts_with("the ") {
        what.to_string()
    } else {
        format!("`{what}`")
    }
}

impl EntryKind for ReachReport {
    fn asks(entry: &Value) -> Asks {
        Asks::by_name("reach", entry, "person")
    }
    fn verdict_words(entry: &Value) -> String {
        ok_words(entry, "reachable")
    }
    fn changes(
        old: &Value,
        new: &Value,
        answer: &Answer,
        who: &str,
        tol: Tolerance,
    ) -> Vec<String> {
        let words = Self::verdict_words(old);
        placed_answer_changes((old, new), answer, who, &words, tol)
    }
}
