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

use super::reach::ReachTask;
use crate::error::ErrorKind;
use crate::kinematics::{Body, Chain};
use crate::plugin::{
    Dependence, EffectorNeed, Fit, Options, ParamSpec, Params, Plugin, Registry, Settings,
    SettingsError, Subject, SubjectKind, Task, TaskInput, TaskPlugin, Tries,
};
use crate::report::{AdviceFrame, AdviceReport, PositionAnswer, TaskReport};
use crate::scene::Room;

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
        }
    }
}

impl Plugin for Advise {
    fn name(&self) -> &'static str {
        "advise"
    }

    fn doc(&self) -> &'static str {
        "where along one axis to put the target (and the boxes that carry it) so that the person, or a share of the population, reaches it"
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
        let axis = match s.along.as_str() {
            "x" => 0,
            "y" => 1,
            "z" => 2,
            other => {
                return Err(SettingsError::invalid(
                    "along",
                    format!("`{other}` is not an axis of the room: use `x`, `y` or `z`"),
                ))
            }
        };
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
        let span = s.to_mm - s.from_mm;
        if span < 0.0 {
            return Err(SettingsError::invalid(
                "to",
                format!("`to` ({} mm) is below `from` ({} mm)", s.to_mm, s.from_mm),
            ));
        }
        let steps = span / s.step_mm;
        if (steps - steps.round()).abs() > 1e-6 {
            let last = s.from_mm + steps.floor() * s.step_mm;
            return Err(SettingsError::invalid(
                "to",
                format!(
                    "`to` is not a whole number of steps from `from`: {} mm is (or take another step)",
                    last
                ),
            ));
        }
        // Compared before it is a count: a span of light years is refused,
        // not wrapped round.
        if steps.round() + 1.0 > MAX_POSITIONS as f64 {
            let count = steps.round() + 1.0;
            return Err(SettingsError::invalid(
                "step",
                format!("{count} positions: at most {MAX_POSITIONS} (take a longer step)"),
            ));
        }
        let count = steps.round() as usize + 1;
        Ok(Box::new(AdviseTask {
            reach: ReachTask::new(s.reach, plugins)?,
            carries: s.carries.unwrap_or_default(),
            axis,
            positions_mm: (0..count)
                .map(|k| s.from_mm + k as f64 * s.step_mm)
                .collect(),
            step_mm: s.step_mm,
            serves: s.serves,
            full,
            coarse: s.coarse as usize,
        }))
    }
}

/// A configured advice.
struct AdviseTask {
    reach: ReachTask,
    carries: Vec<String>,
    /// 0, 1, 2: x, y, z.
    axis: usize,
    positions_mm: Vec<f64>,
    step_mm: f64,
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
        let size = room.size_mm[self.axis];
        let outside = (self.positions_mm.iter()).find(|&&at| !(0.0..=size).contains(&at))?;
        let option = if *outside < 0.0 { "from" } else { "to" };
        Some((
            option,
            format!(
                "`{}` at {} {} mm is outside room `{}` (0 to {} mm on that axis)",
                target.name, AXES[self.axis], outside, room.name, size
            ),
        ))
    }

    fn points(&self, _subject: &Subject<'_>) -> u64 {
        self.positions_mm.len() as u64
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
            dependence.points_mm = (self.positions_mm.iter())
                .map(|&at| {
                    let mut p = target.position_mm;
                    p[self.axis] = at;
                    p
                })
                .collect();
        }
        dependence
    }

    /// Each position's floor is another where the element meets the
    /// base: the fit is checked there ([`AdviseTask::answer_at`]).
    fn places_itself(&self) -> bool {
        true
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
        let room = self.moved_room(input.room, &target.name, at)?;
        let floors = Floors::of(input);
        self.answer_at(input, &room, index, true, &floors).verdict
    }

    fn run(&self, input: &TaskInput<'_>) -> TaskReport {
        let Subject::Target(target) = input.subject else {
            unreachable!("the checker gives an advice a target")
        };
        let index = (input.room.targets.iter())
            .position(|t| t.name == target.name)
            .expect("the subject is a target of its room");
        let floors = Floors::of(input);
        let at = |k: usize, explain: bool| {
            let room =
                (self.moved_room(input.room, &target.name, k)).expect("a position of the scan");
            self.answer_at(input, &room, index, explain, &floors)
        };
        // A population's member is asked why afterwards, and only where
        // their population's report shows it (`Task::explain`).
        let explain = !input.verdict_only;
        let (answers, holed) = scan(self.positions_mm.len(), self.full, self.coarse, explain, at);
        let frame = AdviceFrame {
            name: target.name.clone(),
            base: input.person.base.name.clone(),
            carries: self.carries.clone(),
            along: AXES[self.axis],
            target_mm: target.position_mm.coords.into(),
            declared_mm: target.position_mm[self.axis],
            step_mm: self.step_mm,
            serves: self.serves,
            scan: if self.full { "full" } else { "bracketed" },
            rescanned: usize::from(holed),
            positions_mm: self.positions_mm.clone(),
        };
        TaskReport::Advice(Box::new(AdviceReport::person(
            &frame,
            &input.person.name,
            &answers,
        )))
    }
}

impl AdviseTask {
    /// `room` with the element (target `name` and what it carries) at
    /// position `k`: made for each solve and dropped after it (a room's
    /// meshes are copied with it, so rooms for every position are not
    /// kept).
    fn moved_room(&self, room: &Room, name: &str, k: usize) -> Option<Room> {
        let declared = room.targets.iter().find(|t| t.name == name)?.position_mm[self.axis];
        let at = self.positions_mm.get(k)?;
        Some(room.moved(&self.element(name), self.axis, at - declared))
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
        if input.allowance.exhausted() {
            return PositionAnswer {
                reached: false,
                verdict: None,
            };
        }
        let fit = input.base.fit(room, input.allowance);
        floors.charge(input, room);
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
/// worked out afresh.
struct Floors(RefCell<Vec<u64>>);

impl Floors {
    /// None met but the declared room's, of `input`.
    fn of(input: &TaskInput<'_>) -> Self {
        Floors(RefCell::new(
            input.base.floor_key(input.room).into_iter().collect(),
        ))
    }

    /// `room`'s floor (worked out by the fit) charged, where it is one
    /// not met before.
    fn charge(&self, input: &TaskInput<'_>, room: &Room) {
        let Some(key) = input.base.floor_key(room) else {
            return;
        };
        if self.0.borrow().contains(&key) {
            return;
        }
        self.0.borrow_mut().push(key);
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
