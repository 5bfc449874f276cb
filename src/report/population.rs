//! A task by a population: the share of its people it accommodates (who
//! reach or see the target, or, for a map, each point's share), with a 95 %
//! confidence interval for the sample's size, and who is not accommodated
//! and why (their sex, age, stature, profiles and drawn values, and their
//! own answer's verdict).

use std::fmt::Write as _;

use serde::Serialize;

use super::entry_kind::{text, Asks, EntryKind, Tolerance};
use super::{fixed, mm, Answer, Figure, MapReport, ReportKind, TaskReport};
use crate::scene::{Drawn, Population};
use serde_json::Value;

/// One task by a population.
#[derive(Clone, Debug, PartialEq, Serialize, schemars::JsonSchema)]
pub struct PopulationReport {
    /// The task as the text report names it (`reach`, `gaze`, `map`, ...).
    pub task: &'static str,
    /// The target or surface.
    pub name: String,
    pub population: String,
    pub seed: u64,
    pub people: usize,
    /// Those the answer holds for (reach or see the target; for a map,
    /// reach at least one point); those whose base fits nowhere are not.
    pub accommodated: usize,
    /// `accommodated / people`.
    pub share: f64,
    /// The Wilson score interval of the share at 95 %.
    pub ci95: [f64; 2],
    /// Of those not accommodated, how many fit nowhere in the room.
    pub not_placed: usize,
    /// Whether everyone is accommodated.
    pub ok: bool,
    /// Everyone not accommodated, in draw order.
    pub excluded: Vec<Excluded>,
    /// For a map: the grid the shares are on, as the members' maps have
    /// it.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub grid: Option<ShareGrid>,
    /// For a map: each point's share of the people who reach it, in the
    /// map's order (row by row).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub cells: Option<Vec<ShareCell>>,
}

/// The grid of a population's map: the surface and its cells as each
/// member's map gives them.
#[derive(Clone, Debug, PartialEq, Serialize, schemars::JsonSchema)]
pub struct ShareGrid {
    /// What a point asks: `reach` (reached) or `gaze` (seen).
    pub of: &'static str,
    /// The base plugin.
    pub base: String,
    /// `plan` for a horizontal surface, `elevation` for a vertical one.
    pub view: &'static str,
    pub step_mm: f64,
    /// The surface's corner and its two edges: columns run along the
    /// first, rows along the second.
    pub corner_mm: [f64; 3],
    pub u_mm: [f64; 3],
    pub v_mm: [f64; 3],
    pub columns: usize,
    pub rows: usize,
    /// The surface's unit normal on the side it is used from.
    pub seen_from: [f64; 3],
}

/// A person the task does not accommodate.
#[derive(Clone, Debug, PartialEq, Serialize, schemars::JsonSchema)]
pub struct Excluded {
    /// `manual_users#17`.
    pub person: String,
    /// Their row of ANSUR II (`stdlib/data/ansur2.csv`, 1 for the first
    /// after the header).
    pub survey_row: usize,
    pub sex: &'static str,
    pub age_years: f64,
    pub stature_mm: f64,
    pub profiles: Vec<String>,
    /// The `draw`s' values, by name (lengths in mm, angles in radians).
    #[serde(serialize_with = "by_name")]
    #[schemars(with = "std::collections::BTreeMap<String, f64>")]
    pub drawn: Vec<(String, f64)>,
    /// Their own answer: `NOT reachable: blocked by shelf`, `does NOT fit
    /// in the room`.
    pub verdict: String,
}

/// One point of a population's map.
#[derive(Clone, Debug, PartialEq, Serialize, schemars::JsonSchema)]
pub struct ShareCell {
    pub column: usize,
    pub row: usize,
    pub point_mm: [f64; 3],
    /// The share of the people who reach it.
    pub share: f64,
    /// How many of them reach it.
    pub reached: usize,
}

/// Pairs as a JSON object, in their order.
fn by_name<S: serde::Serializer>(pairs: &[(String, f64)], s: S) -> Result<S::Ok, S::Error> {
    use serde::ser::SerializeMap;
    let mut map = s.serialize_map(Some(pairs.len()))?;
    for (name, value) in pairs {
        map.serialize_entry(name, value)?;
    }
    map.end()
}

/// z for a two-sided 95 % interval.
const Z95: f64 = 1.959_963_984_540_054;

/// The Wilson score interval at 95 % of `successes` in `n` trials.
pub fn wilson95(successes: usize, n: usize) -> [f64; 2] {
    if n == 0 {
        return [0.0, 1.0];
    }
    let (k, n) = (successes as f64, n as f64);
    let p = k / n;
    let z2 = Z95 * Z95;
    let centre = (p + z2 / (2.0 * n)) / (1.0 + z2 / n);
    let half = Z95 / (1.0 + z2 / n) * (p * (1.0 - p) / n + z2 / (4.0 * n * n)).sqrt();
    [(centre - half).max(0.0), (centre + half).min(1.0)]
}

impl PopulationReport {
    /// The report of a task whose answers, one per person of `population`
    /// in draw order, are `answers`; `name` is the subject's.
    pub fn new(name: &str, population: &Population, answers: &[TaskReport]) -> Self {
        let outcomes: Vec<MemberOutcome> = answers.iter().map(MemberOutcome::of).collect();
        let frame = answers.iter().find_map(TaskReport::map).map(MapFrame::of);
        PopulationReport::of_outcomes(name, population, &outcomes, frame.as_ref())
    }

    /// The report of a task whose people (every one of `population`, in
    /// draw order) ended as `outcomes`, the first map among them framed as
    /// `frame`.
    pub fn of_outcomes(
        name: &str,
        population: &Population,
        outcomes: &[MemberOutcome],
        frame: Option<&MapFrame>,
    ) -> Self {
        let people = outcomes.len();
        let task = outcomes.first().map_or("task", |o| o.task);
        let mut excluded = Vec::new();
        let mut not_placed = 0;
        for ((outcome, drawn), i) in outcomes.iter().zip(&population.drawn).zip(1..) {
            if outcome.ok {
                continue;
            }
            not_placed += usize::from(outcome.not_placed);
            excluded.push(Excluded::new(
                &population.name,
                i,
                drawn,
                outcome.verdict.clone(),
            ));
        }
        let accommodated = people - excluded.len();
        let share_of = |k: usize| fixed(k as f64 / people.max(1) as f64, 4);
        PopulationReport {
            task,
            name: name.to_string(),
            population: population.name.clone(),
            seed: population.seed,
            people,
            accommodated,
            share: share_of(accommodated),
            ci95: wilson95(accommodated, people).map(|v| fixed(v, 4)),
            not_placed,
            ok: accommodated == people,
            excluded,
            grid: frame.map(|f| f.grid.clone()),
            cells: frame.map(|f| map_shares(f, outcomes)),
        }
    }
}

/// How one person of a population ended, as much as the population's
/// report needs: what a shard of a run (`reach run --shard`) keeps of each
/// of its people for the merge.
#[derive(Clone, Debug, PartialEq)]
pub struct MemberOutcome {
    /// The task as their answer names it (`reach`, `map`, ...).
    pub task: &'static str,
    /// Whether the answer holds for them.
    pub ok: bool,
    /// Whether their base fits nowhere in the room.
    pub not_placed: bool,
    /// Their answer's verdict.
    pub verdict: String,
    /// For a map: whether they reach each point, in the map's order.
    pub reached: Option<Vec<bool>>,
}

impl MemberOutcome {
    /// How the person whose answer is `report` ended.
    pub fn of(report: &TaskReport) -> Self {
        let answer = report.answer();
        MemberOutcome {
            task: answer.task,
            ok: answer.ok,
            not_placed: matches!(report, TaskReport::NotPlaced(_)),
            verdict: answer.verdict,
            reached: report
                .map()
                .map(|m| m.cells.iter().map(|c| c.reachable).collect()),
        }
    }
}

/// The grid of a population's map and its points, from the first of its
/// people whose map there is (the shares not yet counted).
#[derive(Clone, Debug, PartialEq)]
pub struct MapFrame {
    pub grid: ShareGrid,
    /// Each point, its share and count 0.
    pub cells: Vec<ShareCell>,
}

impl MapFrame {
    /// The frame of the map `m`.
    pub fn of(m: &MapReport) -> Self {
        let grid = ShareGrid {
            of: m.of,
            base: m.base.clone(),
            view: m.view,
            step_mm: m.step_mm,
            corner_mm: m.corner_mm,
            u_mm: m.u_mm,
            v_mm: m.v_mm,
            columns: m.columns,
            rows: m.rows,
            seen_from: m.seen_from().map(|x| fixed(x, 4)),
        };
        let cells = (m.cells.iter())
            .map(|cell| ShareCell {
                column: cell.column,
                row: cell.row,
                point_mm: cell.point_mm,
                share: 0.0,
                reached: 0,
            })
            .collect();
        MapFrame { grid, cells }
    }
}

/// For maps: each point's share of the people who reach it (a person
/// whose base fits nowhere reaches none).
fn map_shares(frame: &MapFrame, outcomes: &[MemberOutcome]) -> Vec<ShareCell> {
    let people = outcomes.len().max(1) as f64;
    (frame.cells.iter().enumerate())
        .map(|(k, cell)| {
            let reached = (outcomes.iter())
                .filter(|o| o.reached.as_ref().is_some_and(|r| r.get(k) == Some(&true)))
                .count();
            ShareCell {
                share: fixed(reached as f64 / people, 4),
                reached,
                ..cell.clone()
            }
        })
        .collect()
}

impl Excluded {
    fn new(population: &str, number: usize, drawn: &Drawn, verdict: String) -> Self {
        Excluded {
            person: format!("{population}#{number}"),
            survey_row: drawn.row + 1,
            sex: if drawn.female { "female" } else { "male" },
            age_years: drawn.age_years,
            stature_mm: mm(drawn.stature_mm),
            profiles: drawn.profiles.clone(),
            drawn: drawn
                .values
                .iter()
                .map(|(n, v)| (n.clone(), fixed(*v, 2)))
                .collect(),
            verdict,
        }
    }

    /// `#17 (woman, 34 y, 1523 mm, older_adult): NOT reachable`.
    fn line(&self) -> String {
        let sex = if self.sex == "female" { "woman" } else { "man" };
        let mut who = format!("{sex}, {:.0} y, {:.0} mm", self.age_years, self.stature_mm);
        for p in &self.profiles {
            let _ = write!(who, ", {p}");
        }
        format!("{} ({who}): {}", self.person, self.verdict)
    }
}

/// `92 %` with one decimal where it matters.
pub(super) fn percent(share: f64) -> String {
    let p = share * 100.0;
    if (p - p.round()).abs() < 0.05 {
        format!("{p:.0} %")
    } else {
        format!("{p:.1} %")
    }
}

impl PopulationReport {
    /// A map's points reached by everyone, and the mean of its points'
    /// shares.
    fn map_summary(&self) -> Option<(usize, usize, f64)> {
        let cells = self.cells.as_ref()?;
        let everyone = cells.iter().filter(|c| c.reached == self.people).count();
        let mean = cells.iter().map(|c| c.share).sum::<f64>() / cells.len().max(1) as f64;
        Some((everyone, cells.len(), mean))
    }
}

impl ReportKind for PopulationReport {
    fn answer(&self) -> Answer {
        let [lo, hi] = self.ci95;
        let verdict = match self.map_summary() {
            // A map: which points everyone reaches says more than who
            // reaches some point.
            Some((everyone, points, mean)) => format!(
                "{everyone} of {points} points by all {} (a point by {} on average)",
                self.people,
                percent(mean)
            ),
            None => format!(
                "{} of {} (95 % CI {}-{})",
                percent(self.share),
                self.people,
                percent(lo).trim_end_matches(" %"),
                percent(hi)
            ),
        };
        Answer {
            task: self.task,
            subject: self.name.clone(),
            person: self.population.clone(),
            ok: self.ok,
            verdict,
            effector: None,
            figures: vec![Figure::new("share", self.share * 100.0, "%", 0.05)],
        }
    }

    fn details(&self, out: &mut String) {
        let [lo, hi] = self.ci95;
        let interval = format!(
            "95 % CI {}-{}",
            percent(lo).trim_end_matches(" %"),
            percent(hi)
        );
        let (people, seed) = (self.people, self.seed);
        match self.map_summary() {
            Some((everyone, points, mean)) => {
                let _ = writeln!(
                    out,
                    "{} by {} ({people} people, seed {seed}): points reached by everyone: {everyone} of {points}; on average a point is reached by {}",
                    self.name,
                    self.population,
                    percent(mean)
                );
                let _ = writeln!(
                    out,
                    "  {} reach at least one point ({interval})",
                    percent(self.share)
                );
            }
            None => {
                let _ = writeln!(
                    out,
                    "{}: {} of {} ({interval}; {people} people, seed {seed})",
                    self.name,
                    percent(self.share),
                    self.population,
                );
            }
        }
        const SHOWN: usize = 8;
        if !self.excluded.is_empty() {
            let _ = writeln!(
                out,
                "  not accommodated: {} ({} fit nowhere in the room or cannot get in)",
                self.excluded.len(),
                self.not_placed
            );
        }
        for e in self.excluded.iter().take(SHOWN) {
            let _ = writeln!(out, "    {}", e.line());
        }
        if self.excluded.len() > SHOWN {
            let _ = writeln!(
                out,
                "    and {} more (the JSON report lists everyone)",
                self.excluded.len() - SHOWN
            );
        }
    }

    /// The mean of its map's points' shares (none: 0).
    fn coverage(&self) -> Option<(f64, String)> {
        let cells = self.cells.as_deref().unwrap_or_default();
        let mean = cells.iter().map(|c| c.share).sum::<f64>() / cells.len().max(1) as f64;
        let mean = fixed(mean, 4);
        let words = format!(
            "covers {:.1} % (the mean of its points' shares)",
            mean * 100.0
        );
        Some((mean, words))
    }

    fn share(&self) -> Option<f64> {
        Some(self.share)
    }
}

impl EntryKind for PopulationReport {
    fn asks(entry: &Value) -> Asks {
        Asks::by_name(text(entry, "task"), entry, "population")
    }
    fn verdict_words(entry: &Value) -> String {
        format!("{:.1} %", entry["share"].as_f64().unwrap_or(0.0) * 100.0)
    }
    /// Its share, its map's shares, and who it leaves out.
    fn changes(old: &Value, new: &Value, _: &Answer, who: &str, _: Tolerance) -> Vec<String> {
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
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand_chacha::rand_core::SeedableRng;
    use rand_chacha::ChaCha8Rng;
    use rand_distr::{Binomial, Distribution};

    #[test]
    fn wilson_intervals_cover_the_true_share_95_times_in_100() {
        // Samples of 200 people from populations whose true shares are
        // known: the interval must hold the true share in about 95 % of
        // them (Wilson's coverage is close to nominal, a little under it
        // at some shares).
        let mut rng = ChaCha8Rng::seed_from_u64(17);
        for &p in &[0.5, 0.8, 0.92, 0.97] {
            let trials = 4000;
            let covered = (0..trials)
                .filter(|_| {
                    let k = Binomial::new(200, p).unwrap().sample(&mut rng) as usize;
                    let [lo, hi] = wilson95(k, 200);
                    lo <= p && p <= hi
                })
                .count();
            let coverage = covered as f64 / trials as f64;
            assert!(
                (0.925..=0.975).contains(&coverage),
                "share {p}: coverage {coverage}"
            );
        }
    }

    #[test]
    fn wilson_of_all_or_none_stays_inside_zero_and_one() {
        let [lo, hi] = wilson95(50, 50);
        assert!(lo > 0.9 && lo < 1.0 && hi == 1.0);
        let [lo, hi] = wilson95(0, 50);
        assert!(lo == 0.0 && hi > 0.0 && hi < 0.1);
        assert_eq!(wilson95(0, 0), [0.0, 1.0]);
    }
}
