//! The `advise` task: where along one axis of the room to put an element
//! (a target and the boxes and targets that carry it, moved as one) so
//! that people reach it. The element is moved to each position of a line
//! (`along z from 700mm to 1400mm step 10mm`), and at each the person
//! reaches for the target as a `reach` does, with either hand; the answer
//! is the positions they reach ([`crate::report::AdviceReport`]), and for
//! a population each position's share.
//!
//! What a person reaches along a line is mostly one stretch. The default
//! `bracketed` scan solves every `coarse`-th position, then bisects each
//! change between two of them, so a person's ends are found with a few
//! solves instead of one per position; a stretch shorter than the coarse
//! step that lies between two solved positions (reached or not, where
//! they answer alike or where the bisection passes it by) can be missed
//! (the `full` scan solves every position). Where a person does not reach a
//! position next to one they reach, why is found as a reach finds it:
//! those are the words of the advice's range ends.

use std::cell::RefCell;

use nalgebra::{Point3, Vector3};

use super::reach::ReachTask;
use crate::error::ErrorKind;
use crate::kinematics::{Body, Chain};
use crate::plugin::{
    Dependence, EffectorNeed, Fit, Options, ParamSpec, Params, Plugin, Registry, Settings,
    SettingsError, Subject, SubjectKind, Task, TaskInput, TaskPlugin, Tries,
};
use crate::report::{axis_index, Across, AdviceFrame, AdviceReport, PositionAnswer, TaskReport};
use crate::scene::{Room, Sweep};

/// The plugin `advise`.
pub struct Advise;

/// The most positions one advice may scan.
pub const MAX_POSITIONS: usize = 1001;

/// Its settings: a reach's, and how the element moves.
pub struct AdviseSettings {
    pub reach: super::ReachSettings,
    /// Boxes and targets moved with the target.
    pub carries: Option<Vec<String>>,
    pub along: String,
    pub from_mm: f64,
    pub to_mm: f64,
    pub step_mm: f64,
    pub serves: f64,
    pub scan: String,
    pub coarse: i64,
    /// A second axis, for a grid.
    pub across: Option<String>,
    pub across_from_mm: Option<f64>,
    pub across_to_mm: Option<f64>,
    pub across_step_mm: Option<f64>,
}

impl Settings for AdviseSettings {
    fn visit(p: &mut Params<'_>) -> Self {
        AdviseSettings {
            reach: super::ReachSettings::visit(p),
            carries: p
                .optional_names(
                    "carries",
                    "boxes and other targets of the room moved with the target, as one element (`carries [oven, turntable]`: a microwave's box with its handle the target; a shelf board under a tin)",
                )
                .get(),
            along: p
                .name(
                    "along",
                    "z",
                    "the room's axis the element moves along: `z` (its height), `x` or `y` (a depth or a distance along a wall)",
                )
                .get(),
            from_mm: p
                .required_length("from", "the target's first position on that axis")
                .get(),
            to_mm: p
                .required_length("to", "the target's last position on that axis")
                .get(),
            step_mm: p
                .length("step", 10.0, "between two positions")
                .range(1.0, 1000.0)
                .get(),
            serves: p
                .number(
                    "serves",
                    0.9,
                    "the share of a population a position must serve to be in the advised range (`90 %`); a person is served where they reach it",
                )
                .range(0.0, 1.0)
                .get(),
            scan: p
                .name(
                    "scan",
                    "bracketed",
                    "`bracketed`: every `coarse`-th position solved, then each change between two bisected (a stretch shorter than the coarse step between two solved positions can be missed); `full`: every position solved",
                )
                .get(),
            coarse: p
                .integer("coarse", 4, "for a bracketed scan: every `coarse`-th position is solved first, then each change between two is bisected")
                .range(2.0, 100.0)
                .get(),
            across: p
                .optional_name(
                    "across",
                    "a second axis of the room, for a grid: at each position across (`across_from` to `across_to`), the element is moved along `along` as without it",
                )
                .get(),
            across_from_mm: p
                .optional_length("across_from", "for a grid: the target's first position across")
                .get(),
            across_to_mm: p
                .optional_length("across_to", "for a grid: the target's last position across")
                .get(),
            across_step_mm: p
                .optional_length("across_step", "for a grid: between two positions across (`step` where left out)")
                .range(1.0, 1000.0)
                .get(),
        }
    }
}

impl Plugin for Advise {
    fn name(&self) -> &'static str {
        "advise"
    }

    fn doc(&self) -> &'static str {
        "where along one axis, or over a grid of two, to put the target (and the boxes that carry it) so that the person, or a share of the population, reaches it"
    }

    fn params(&self) -> Vec<ParamSpec> {
        AdviseSettings::params()
    }
}

impl TaskPlugin for Advise {
    fn subject(&self) -> SubjectKind {
        SubjectKind::Target
    }

    fn configure(
        &self,
        options: &Options,
        plugins: &Registry,
    ) -> Result<Box<dyn Task>, SettingsError> {
        let s = AdviseSettings::from_options(options)?;
        let full = match s.scan.as_str() {
            "full" => true,
            "bracketed" => false,
            other => {
                return Err(SettingsError::invalid(
                    "scan",
                    format!("`{other}` is not a scan: use `bracketed` or `full`"),
                ))
            }
        };
        let along = Line::new(&s.along, s.from_mm, s.to_mm, s.step_mm, ALONG, 1)?;
        let across = match (&s.across, s.across_from_mm, s.across_to_mm) {
            (None, None, None) if s.across_step_mm.is_some() => {
                return Err(SettingsError::invalid(
                    "across_step",
                    "a step across is for a grid: give it `across x` (or `y`, `z`), `across_from` and `across_to`",
                ))
            }
            (None, None, None) => None,
            (Some(axis), Some(from), Some(to)) => {
                let step = s.across_step_mm.unwrap_or(s.step_mm);
                let line = Line::new(axis, from, to, step, ACROSS, along.positions_mm.len())?;
                if line.axis == along.axis {
                    return Err(SettingsError::invalid(
                        "across",
                        format!("`{axis}` is the axis `along` moves the element on: take another"),
                    ));
                }
                Some(line)
            }
            (None, ..) => {
                let option = if s.across_from_mm.is_some() { "across_from" } else { "across_to" };
                return Err(SettingsError::invalid(
                    option,
                    "a grid needs its second axis: `across x` (or `y`, `z`)",
                ));
            }
            (Some(_), None, _) => {
                return Err(SettingsError::invalid(
                    "across",
                    "a grid needs `across_from` and `across_to`: where its lines across begin and end",
                ))
            }
            (Some(_), _, None) => {
                return Err(SettingsError::invalid(
                    "across",
                    "a grid needs `across_to`: where its lines across end",
                ))
            }
        };
        Ok(Box::new(AdviseTask {
            reach: ReachTask::new(s.reach, plugins)?,
            carries: s.carries.unwrap_or_default(),
            along,
            across,
            serves: s.serves,
            full,
            coarse: s.coarse as usize,
        }))
    }
}

/// The options that set one line of positions.
struct LineOptions {
    axis: &'static str,
    to: &'static str,
    step: &'static str,
}

const ALONG: LineOptions = LineOptions {
    axis: "along",
    to: "to",
    step: "step",
};

const ACROSS: LineOptions = LineOptions {
    axis: "across",
    to: "across_to",
    step: "across_step",
};

/// The positions of the element on one axis of the room.
struct Line {
    /// 0, 1, 2: x, y, z.
    axis: usize,
    positions_mm: Vec<f64>,
    step_mm: f64,
}

impl Line {
    /// From `from_mm` to `to_mm` in steps of `step_mm` on `axis`, set by
    /// `options`; refused where, with `times` positions for each of its
    /// own (the lines along, for the positions across), the scan would
    /// pass [`MAX_POSITIONS`].
    fn new(
        axis: &str,
        from_mm: f64,
        to_mm: f64,
        step_mm: f64,
        options: LineOptions,
        times: usize,
    ) -> Result<Line, SettingsError> {
        let Some(index) = axis_index(axis) else {
            return Err(SettingsError::invalid(
                options.axis,
                format!("`{axis}` is not an axis of the room: use `x`, `y` or `z`"),
            ));
        };
        let span = to_mm - from_mm;
        if span < 0.0 {
            return Err(SettingsError::invalid(
                options.to,
                format!(
                    "`{}` ({to_mm} mm) is below its start ({from_mm} mm)",
                    options.to
                ),
            ));
        }
        let steps = span / step_mm;
        if (steps - steps.round()).abs() > 1e-6 {
            let last = from_mm + steps.floor() * step_mm;
            return Err(SettingsError::invalid(
                options.to,
                format!(
                    "`{}` is not a whole number of steps from its start: {} mm is (or take another step)",
                    options.to, last
                ),
            ));
        }
        // Compared before it is a count: a span of light years is refused,
        // not wrapped round.
        let count = (steps.round() + 1.0) * times as f64;
        if count > MAX_POSITIONS as f64 {
            let grid = if times > 1 { " over the grid" } else { "" };
            return Err(SettingsError::invalid(
                options.step,
                format!("{count} positions{grid}: at most {MAX_POSITIONS} (take a longer step)"),
            ));
        }
        Ok(Line {
            axis: index,
            positions_mm: (0..=steps.round() as usize)
                .map(|k| from_mm + k as f64 * step_mm)
                .collect(),
            step_mm,
        })
    }
}

/// A configured advice.
struct AdviseTask {
    reach: ReachTask,
    carries: Vec<String>,
    along: Line,
    /// For a grid: the positions across, a line along at each.
    across: Option<Line>,
    serves: f64,
    full: bool,
    coarse: usize,
}

const AXES: [&str; 3] = ["x", "y", "z"];

impl Task for AdviseTask {
    fn effectors(&self) -> Vec<EffectorNeed> {
        self.reach.effectors()
    }

    fn validate_chain(&self, person: &str, need: usize, chain: &Chain) -> Option<ErrorKind> {
        self.reach.validate_chain(person, need, chain)
    }

    fn carried(&self) -> Vec<String> {
        self.carries.clone()
    }

    /// Every position of the target within the room.
    fn validate_in(&self, subject: &Subject<'_>, room: &Room) -> Option<(&'static str, String)> {
        let Subject::Target(target) = subject else {
            return None;
        };
        let lines = std::iter::once((&self.along, ["from", "to"]))
            .chain((self.across.iter()).map(|a| (a, ["across_from", "across_to"])));
        for (line, [below, above]) in lines {
            let size = room.size_mm[line.axis];
            let Some(outside) = (line.positions_mm.iter()).find(|&&at| !(0.0..=size).contains(&at))
            else {
                continue;
            };
            let option = if *outside < 0.0 { below } else { above };
            return Some((
                option,
                format!(
                    "`{}` at {} {} mm is outside room `{}` (0 to {} mm on that axis)",
                    target.name, AXES[line.axis], outside, room.name, size
                ),
            ));
        }
        None
    }

    fn points(&self, _subject: &Subject<'_>) -> u64 {
        (self.along.positions_mm.len() * self.lines()) as u64
    }

    fn starts_per_point(&self, placements: Tries) -> u64 {
        self.reach.starts_per_point(placements)
    }

    fn searches(&self, body: &Body, effectors: &[usize]) -> u64 {
        self.reach.searches(body, effectors)
    }

    fn dependence(&self, input: &TaskInput<'_>) -> Dependence {
        let mut dependence = self.reach.dependence(input);
        if let Subject::Target(target) = input.subject {
            let n = self.along.positions_mm.len() * self.lines();
            dependence.points_mm = (0..n)
                .filter_map(|k| self.position_mm(&target.position_mm, k))
                .collect();
        }
        dependence
    }

    /// Each position's floor is another where the element meets the
    /// base: the fit is checked there ([`AdviseTask::answer_at`]).
    fn places_itself(&self) -> bool {
        true
    }

    fn sweep(&self, room: &Room, subject: &Subject<'_>) -> Option<Sweep> {
        let Subject::Target(target) = subject else {
            return None;
        };
        self.element_sweep(room, &target.name)
    }

    fn explain(&self, input: &TaskInput<'_>, at: usize) -> Option<String> {
        let Subject::Target(target) = input.subject else {
            return None;
        };
        let index = input
            .room
            .targets
            .iter()
            .position(|t| t.name == target.name)?;
        let floors = Floors::of(input, self.element_sweep(input.room, &target.name));
        let room = self.moved_room(input.room, &target.name, at, floors.sweep.as_ref())?;
        self.answer_at(input, &room, index, true, &floors).verdict
    }

    fn run(&self, input: &TaskInput<'_>) -> TaskReport {
        let Subject::Target(target) = input.subject else {
            unreachable!("the checker gives an advice a target")
        };
        let index = (input.room.targets.iter())
            .position(|t| t.name == target.name)
            .expect("the subject is a target of its room");
        let floors = Floors::of(input, self.element_sweep(input.room, &target.name));
        let at = |k: usize, explain: bool| {
            let room = (self.moved_room(input.room, &target.name, k, floors.sweep.as_ref()))
                .expect("a position of the scan");
            self.answer_at(input, &room, index, explain, &floors)
        };
        // A population's member is asked why afterwards, and only where
        // their population's report shows it (`Task::explain`).
        let explain = !input.verdict_only;
        let n = self.along.positions_mm.len();
        let line = |row: usize| {
            let (answers, holed) = scan(n, self.full, self.coarse, explain, |k, why| {
                at(row * n + k, why)
            });
            let frame = AdviceFrame {
                name: target.name.clone(),
                base: input.person.base.name.clone(),
                carries: self.carries.clone(),
                along: AXES[self.along.axis],
                target_mm: target.position_mm.coords.into(),
                declared_mm: target.position_mm[self.along.axis],
                step_mm: self.along.step_mm,
                serves: self.serves,
                scan: if self.full { "full" } else { "bracketed" },
                rescanned: usize::from(holed),
                positions_mm: self.along.positions_mm.clone(),
                across: (self.across.as_ref()).map(|a| Across {
                    axis: AXES[a.axis],
                    at_mm: a.positions_mm[row],
                    step_mm: a.step_mm,
                }),
            };
            AdviceReport::person(&frame, &input.person.name, &answers)
        };
        let advice = match &self.across {
            None => line(0),
            Some(_) => AdviceReport::grid((0..self.lines()).map(line).collect()),
        };
        TaskReport::Advice(Box::new(advice))
    }
}

impl AdviseTask {
    /// How many lines along the element is moved on: 1, or one for each
    /// position across of a grid.
    fn lines(&self) -> usize {
        self.across.as_ref().map_or(1, |a| a.positions_mm.len())
    }

    /// Where position `k` puts the target declared at `declared_mm`: on a
    /// grid, position `k % n` of line `k / n` (`n` positions along); none
    /// past the last.
    fn position_mm(&self, declared_mm: &Point3<f64>, k: usize) -> Option<Point3<f64>> {
        let n = self.along.positions_mm.len();
        let mut at = *declared_mm;
        at[self.along.axis] = *self.along.positions_mm.get(k % n)?;
        match &self.across {
            Some(across) => at[across.axis] = *across.positions_mm.get(k / n)?,
            None if k >= n => return None,
            None => {}
        }
        Some(at)
    }

    /// `room` with the element (target `name` and what it carries) at
    /// position `k` ([`AdviseTask::position_mm`]), named for the `sweep`
    /// that bounds it where there is one ([`Sweep::named`]): made for
    /// each solve and dropped after it (a room's meshes are copied with
    /// it, so rooms for every position are not kept).
    fn moved_room(&self, room: &Room, name: &str, k: usize, sweep: Option<&Sweep>) -> Option<Room> {
        let declared = room.targets.iter().find(|t| t.name == name)?.position_mm;
        let at = self.position_mm(&declared, k)?;
        let moved = room.moved(&self.element(name), at - declared);
        Some(match sweep {
            Some(sweep) => sweep.named(moved),
            None => moved,
        })
    }

    /// The bounds of the rooms the element (target `name` and what it
    /// carries) makes at every position, and of `room` as declared
    /// ([`Sweep`]).
    fn element_sweep(&self, room: &Room, name: &str) -> Option<Sweep> {
        let declared = room.targets.iter().find(|t| t.name == name)?.position_mm;
        let n = self.along.positions_mm.len() * self.lines();
        let moves: Vec<Vector3<f64>> = (0..n)
            .filter_map(|k| self.position_mm(&declared, k))
            .map(|at| at - declared)
            .chain([Vector3::zeros()])
            .collect();
        Sweep::of(room, &self.element(name), &moves)
    }

    /// The names moved as one: target `name` and what it carries.
    fn element<'a>(&'a self, name: &'a str) -> Vec<&'a str> {
        std::iter::once(name)
            .chain(self.carries.iter().map(String::as_str))
            .collect()
    }

    /// Whether the person of `input` reaches target `index` of `room` (the
    /// element at one position), and where not and `explain`, why; the
    /// base's floor there charged to the run where `floors` has not met
    /// it yet. Once the run is past its work, nothing is looked for (the
    /// run stops, and this answer is not kept).
    fn answer_at(
        &self,
        input: &TaskInput<'_>,
        room: &Room,
        index: usize,
        explain: bool,
        floors: &Floors,
    ) -> PositionAnswer {
        let not = |verdict: &str| PositionAnswer {
            reached: false,
            verdict: Some(verdict.to_string()),
        };
        // Once the run is past its work it stops: nothing more is worked
        // out for this answer, which is not kept.
        let stopped = PositionAnswer {
            reached: false,
            verdict: None,
        };
        if input.allowance.exhausted() {
            return stopped;
        }
        let fit = match &floors.sweep {
            Some(sweep) => input.base.fit_in_sweep(room, sweep, input.allowance),
            None => input.base.fit(room, input.allowance),
        };
        floors.charge(input, room);
        if input.allowance.exhausted() {
            return stopped;
        }
        match fit {
            Fit::Nowhere(_) => return not("the base fits nowhere in the room with it there"),
            Fit::Shut(_) => return not("the base cannot get in from a door with it there"),
            Fit::Fits | Fit::Outside => {}
        }
        let moved = TaskInput {
            room,
            subject: Subject::Target(&room.targets[index]),
            // The element moves the room: nothing is recorded or kept by
            // the room as declared.
            touched: None,
            solves: None,
            verdict_only: true,
            ..*input
        };
        let report = self.reach.reach(&moved, explain);
        PositionAnswer {
            reached: report.ok,
            verdict: (!report.ok && explain).then(|| report.verdict()),
        }
    }
}

/// The floors an advice's positions have met, each charged to the run
/// once (the declared room's is the task's own, which the run charges):
/// where the element meets the base's footprint, its floor is another,
/// worked out afresh, its routes from the doors bounded by those of the
/// rooms of the element's `sweep`.
struct Floors {
    met: RefCell<Vec<u64>>,
    sweep: Option<Sweep>,
}

impl Floors {
    /// None met but the declared room's, of `input`.
    fn of(input: &TaskInput<'_>, sweep: Option<Sweep>) -> Self {
        Floors {
            met: RefCell::new(input.base.floor_key(input.room).into_iter().collect()),
            sweep,
        }
    }

    /// `room`'s floor (worked out by the fit) charged, where it is one
    /// not met before.
    fn charge(&self, input: &TaskInput<'_>, room: &Room) {
        let Some(key) = input.base.floor_key(room) else {
            return;
        };
        if self.met.borrow().contains(&key) {
            return;
        }
        self.met.borrow_mut().push(key);
        input.allowance.spend(input.base.floor_work(room));
    }
}

/// Each of `n` positions answered by `at(k, explain)`: every one (`full`),
/// or every `coarse`-th and the last, then each change between two of
/// them bisected, and where that finds more than one stretch reached (a
/// band with a hole: where there is one, the coarse step may have passed
/// others by), every position; then, where `explain`, each position not
/// reached next to one reached answered again with why. With whether a
/// bracketed scan fell back to solving every position.
fn scan(
    n: usize,
    full: bool,
    coarse: usize,
    explain: bool,
    at: impl Fn(usize, bool) -> PositionAnswer,
) -> (Vec<PositionAnswer>, bool) {
    let mut answers: Vec<Option<PositionAnswer>> = vec![None; n];
    let stride = if full { 1 } else { coarse.max(1) };
    let mut solved: Vec<usize> = (0..n).step_by(stride).collect();
    if solved.last() != Some(&(n - 1)) {
        solved.push(n - 1);
    }
    // Which positions were solved (the others are filled in as their
    // neighbours answer).
    let mut asked = vec![false; n];
    for &k in &solved {
        answers[k] = Some(at(k, false));
        asked[k] = true;
    }
    let reached = |a: &[Option<PositionAnswer>], k: usize| a[k].as_ref().is_some_and(|x| x.reached);
    for pair in solved.windows(2) {
        let (mut lo, mut hi) = (pair[0], pair[1]);
        let low = reached(&answers, lo);
        if low != reached(&answers, hi) {
            while hi - lo > 1 {
                let mid = (lo + hi) / 2;
                let answer = at(mid, false);
                let same = answer.reached == low;
                answers[mid] = Some(answer);
                asked[mid] = true;
                if same {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
        }
        // Between two positions that answer alike (or on either side of
        // the change), as they answer.
        for k in pair[0] + 1..pair[1] {
            if answers[k].is_none() {
                let like = if k < hi { pair[0] } else { pair[1] };
                answers[k] = Some(PositionAnswer {
                    reached: reached(&answers, like),
                    verdict: None,
                });
            }
        }
    }
    let stretches = (0..n)
        .filter(|&k| reached(&answers, k) && (k == 0 || !reached(&answers, k - 1)))
        .count();
    let holed = !full && stretches > 1;
    for k in (0..n).filter(|&k| holed && !asked[k]) {
        answers[k] = Some(at(k, false));
    }
    let mut answers: Vec<PositionAnswer> = answers
        .into_iter()
        .map(|a| a.expect("every position answered"))
        .collect();
    // Why, at each edge of what is reached.
    for k in (0..n).filter(|_| explain) {
        let edge = !answers[k].reached
            && ((k > 0 && answers[k - 1].reached) || (k + 1 < n && answers[k + 1].reached));
        if edge {
            answers[k] = at(k, true);
        }
    }
    (answers, holed)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::cell::Cell;

    /// `bits`' answers, counting the solves.
    fn scanned(bits: &str, full: bool, coarse: usize) -> (String, usize) {
        let (got, solves, _) = scanned_holed(bits, full, coarse);
        (got, solves)
    }

    /// `scanned`, and whether the scan fell back to every position.
    fn scanned_holed(bits: &str, full: bool, coarse: usize) -> (String, usize, bool) {
        let solves = Cell::new(0);
        let b: Vec<bool> = bits.chars().map(|c| c == '1').collect();
        let (answers, holed) = scan(b.len(), full, coarse, true, |k, _| {
            solves.set(solves.get() + 1);
            PositionAnswer {
                reached: b[k],
                verdict: None,
            }
        });
        let got = answers
            .iter()
            .map(|a| if a.reached { '1' } else { '0' })
            .collect();
        (got, solves.get(), holed)
    }

    #[test]
    fn a_bracketed_scan_finds_one_stretchs_ends_with_fewer_solves() {
        let band = format!("{}{}{}", "0".repeat(17), "1".repeat(30), "0".repeat(14));
        let (got, solves) = scanned(&band, false, 4);
        assert_eq!(got, band);
        let (full, all) = scanned(&band, true, 4);
        assert_eq!(full, band);
        // 61 solves and 2 more for why at the edges, against 17 and 2
        // bisections of 2 each and the 2 edges.
        assert_eq!(all, 61 + 2);
        assert!(solves < 30, "{solves}");
    }

    #[test]
    fn a_hole_shorter_than_the_coarse_step_is_missed_and_a_full_scan_finds_it() {
        let holed = "1111101111111";
        assert_eq!(scanned(holed, true, 4).0, holed);
        assert_eq!(scanned(holed, false, 4).0, "1111111111111");
        // Ends on the coarse grid or between: found exactly.
        for band in [
            "0001111000000",
            "0000000000001",
            "1000000000000",
            "0111111111110",
        ] {
            assert_eq!(scanned(band, false, 4).0, band);
        }
    }

    #[test]
    fn a_hole_the_coarse_step_sees_makes_the_scan_solve_every_position() {
        // The hole at 8-9 is seen between coarse positions 4 and 12; the
        // one at 3 lies between two that answer alike, and only the full
        // scan it falls back to finds it: 13 solves, and 3 for why at the
        // positions not reached next to one reached.
        let holed = "1110111100111";
        assert_eq!(
            scanned_holed(holed, false, 4),
            (holed.to_string(), 13 + 3, true)
        );
        // One stretch: no fallback.
        let (band, _, fell_back) = scanned_holed("0001111000000", false, 4);
        assert_eq!((band.as_str(), fell_back), ("0001111000000", false));
        assert!(
            !scanned_holed(holed, true, 4).2,
            "a full scan does not fall back"
        );
    }
}
