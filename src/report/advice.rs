//! An advice (`advise`): an element (a target and the boxes that carry
//! it) moved along one axis of its room, and at each position who reaches
//! it. For a person, the positions they reach; for a population, each
//! position's share with its 95 % interval. The ranges of positions that
//! serve at least the share asked, the position that serves the most, and
//! at each end of a range who drops out there and why, in their own
//! answers' words.

use std::fmt::Write as _;

use serde::Serialize;
use serde_json::Value;

use super::entry_kind::{text, Asks, EntryKind, Tolerance};
use super::population::percent;
use super::Across;
use super::{fixed, mm, wilson95, Answer, Figure, ReportKind, TaskReport};
use crate::scene::Population;

/// One element moved along an axis, for one person or population.
#[derive(Clone, Debug, PartialEq, Serialize, schemars::JsonSchema)]
pub struct AdviceReport {
    /// `advise`.
    pub task: &'static str,
    /// The target moved.
    pub name: String,
    /// The person, or the population.
    pub who: String,
    /// Whether `who` is a population.
    pub population: bool,
    /// How many people: 1 for a person.
    pub people: usize,
    /// The base plugin.
    pub base: String,
    /// The boxes moved with the target.
    pub carries: Vec<String>,
    /// The room's axis the element moves along: `x`, `y` or `z`.
    pub along: &'static str,
    /// Where the file puts the target.
    pub target_mm: [f64; 3],
    /// Where the file puts the target on that axis.
    pub declared_mm: f64,
    pub step_mm: f64,
    /// The share a served range must reach at each of its positions (1
    /// for a person: they reach it).
    pub serves: f64,
    /// `full`: every position solved for every person; `bracketed`: a
    /// coarse scan, then each change between its positions bisected (a
    /// stretch shorter than the coarse step between two solved positions
    /// can be missed).
    pub scan: &'static str,
    /// Of a bracketed scan: how many of the people answered it with more
    /// than one stretch of positions reached (a band with a hole, where the
    /// coarse step may pass others by), and were scanned again in full.
    #[serde(skip_serializing_if = "is_zero")]
    pub rescanned: usize,
    /// For an element moved over a grid: the second axis, and where on it
    /// this line of positions lies (for the grid as a whole, the line that
    /// serves the most: one of `rows`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub across: Option<Across>,
    /// The positions, in order: the target's coordinate on the axis.
    pub points: Vec<AdvicePoint>,
    /// For a population: who reach it at no position, grouped by their
    /// answer (a base that does not fit in the room, or none asked).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub nowhere: Vec<Because>,
    /// The runs of positions that serve at least `serves`, in order.
    pub ranges: Vec<ServedRange>,
    /// The position that serves the most (the middle of the longest run
    /// of positions with the highest share); none where no one reaches
    /// any.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub best: Option<AdvicePoint>,
    /// Whether some position serves at least `serves`.
    pub ok: bool,
    /// Each standard on the room, its rule for the element checked at
    /// each position, beside the served ranges.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub standards: Vec<AdviceStandard>,
    /// For a grid: each line along `along`, in order across, an advice of
    /// its own (its `across` says where it lies; none of them has rows).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub rows: Vec<AdviceReport>,
    /// The share the task asked (a person's `serves` is 1; this is what
    /// their population's advice asks).
    #[serde(skip)]
    #[schemars(skip)]
    pub asked: f64,
}

/// One position of the element.
#[derive(Clone, Debug, PartialEq, Serialize, schemars::JsonSchema)]
pub struct AdvicePoint {
    /// The target's coordinate on the axis.
    pub at_mm: f64,
    /// How many people reach it there.
    pub reached: usize,
    /// `reached / people`.
    pub share: f64,
    /// For a population: the Wilson score interval of the share at 95 %.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub ci95: Option<[f64; 2]>,
    /// For a person who does not reach it there: why, where it was asked
    /// (at the ends of what they reach).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub verdict: Option<String>,
}

/// A run of positions that serve at least the share asked.
#[derive(Clone, Debug, PartialEq, Serialize, schemars::JsonSchema)]
pub struct ServedRange {
    pub from_mm: f64,
    pub to_mm: f64,
    /// What ends it below `from_mm` (none: the scan's first position).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub low_end: Option<RangeEnd>,
    /// What ends it above `to_mm` (none: the scan's last position).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub high_end: Option<RangeEnd>,
}

/// One end of a served range: the first position past it, and who
/// reaches the range's end but not there, grouped by their answer there.
#[derive(Clone, Debug, PartialEq, Serialize, schemars::JsonSchema)]
pub struct RangeEnd {
    /// The first position outside the range.
    pub at_mm: f64,
    /// The share there.
    pub share: f64,
    /// How many reach the range's end but not this position.
    pub dropped: usize,
    /// Their answers at this position, the most common first.
    pub because: Vec<Because>,
}

/// People who drop out at a range's end for one reason.
#[derive(Clone, Debug, PartialEq, Serialize, schemars::JsonSchema)]
pub struct Because {
    /// Their answer there (`NOT reachable: out of reach`).
    pub verdict: String,
    pub people: usize,
    /// The first few of them (`manual_users#17`), in draw order.
    pub who: Vec<String>,
}

impl Because {
    /// How many, and the first few by name: `7 (manual_users#2,
    /// manual_users#5 and 5 more)`.
    fn named(&self) -> String {
        let more = self.people.saturating_sub(self.who.len());
        let extra = match more {
            0 => String::new(),
            _ => format!(" and {more} more"),
        };
        format!("{} ({}{extra})", self.people, self.who.join(", "))
    }
}

/// A standard's rule for the element, checked at each position.
#[derive(Clone, Debug, PartialEq, Serialize, schemars::JsonSchema)]
pub struct AdviceStandard {
    /// The standard plugin (`ada2010`).
    pub standard: String,
    /// The sections that apply along the scan (`308.3.1`), in the order
    /// met: the approach, or the obstruction, can change as the element
    /// moves.
    pub sections: Vec<String>,
    /// The first section's rule in words.
    pub rule: String,
    /// The runs of positions where the rule holds, `[from, to]`.
    pub ranges: Vec<[f64; 2]>,
    /// The rule's range against the advice's, in words.
    pub compared: String,
}

impl AdviceStandard {
    /// Standard `standard`'s rule (section, words, holds) for `advice`'s
    /// element at each of its positions (none: not an element there).
    pub fn new(
        standard: &str,
        advice: &AdviceReport,
        rules: &[Option<(String, String, bool)>],
    ) -> Self {
        let mut sections: Vec<String> = Vec::new();
        for (section, _, _) in rules.iter().flatten() {
            if !sections.contains(section) {
                sections.push(section.clone());
            }
        }
        let rule = (rules.iter().flatten().next()).map_or_else(String::new, |r| r.1.clone());
        let holds = |k: usize| rules[k].as_ref().is_some_and(|r| r.2);
        let at = |k: usize| advice.points[k].at_mm;
        let ranges: Vec<[f64; 2]> = runs(rules.len(), holds)
            .into_iter()
            .map(|(a, b)| [at(a), at(b)])
            .collect();
        let compared = compared(advice, &ranges);
        AdviceStandard {
            standard: standard.to_string(),
            sections,
            rule,
            ranges,
            compared,
        }
    }
}

/// The rule's ranges `rule` against the advice's served ranges, in words.
fn compared(advice: &AdviceReport, rule: &[[f64; 2]]) -> String {
    let words = |r: &[[f64; 2]]| -> String {
        let each: Vec<String> = r.iter().map(|[a, b]| span_words(*a, *b)).collect();
        each.join(", ")
    };
    let served: Vec<[f64; 2]> = advice.ranges.iter().map(|r| [r.from_mm, r.to_mm]).collect();
    let (whom, reach) = if advice.population {
        (
            format!("{} of {}", percent(advice.serves), advice.who),
            "reach",
        )
    } else {
        (advice.who.clone(), "reaches")
    };
    match (rule.first(), rule.last(), served.first(), served.last()) {
        (None, ..) => format!(
            "holds nowhere in the scan; what serves {whom}: {}",
            advice.ranges_words()
        ),
        (_, _, None, _) => format!(
            "the rule allows {} but no position serves {whom}",
            words(rule)
        ),
        (Some(r0), Some(r1), Some(s0), Some(s1)) => {
            let (lo, hi) = (r0[0], r1[1]);
            let (from, to) = (s0[0], s1[1]);
            let mut parts = Vec::new();
            if hi > to {
                parts.push(format!(
                    "the rule allows up to {hi} mm, {} mm past what serves {whom} ({to} mm)",
                    fixed(hi - to, 1)
                ));
            } else if to > hi {
                parts.push(format!(
                    "{whom} {reach} {} mm past the rule's top ({hi} mm)",
                    fixed(to - hi, 1)
                ));
            }
            if lo < from {
                parts.push(format!(
                    "the rule allows down to {lo} mm, {} mm below what serves {whom} ({from} mm)",
                    fixed(from - lo, 1)
                ));
            } else if from < lo {
                parts.push(format!(
                    "{whom} {reach} {} mm below the rule's bottom ({lo} mm)",
                    fixed(lo - from, 1)
                ));
            }
            if parts.is_empty() {
                parts.push(format!("the rule and the advice agree: {}", words(rule)));
            }
            format!("holds at {}: {}", words(rule), parts.join("; "))
        }
        _ => String::new(),
    }
}

/// At most this many people are named for each reason.
const NAMED: usize = 5;

/// What one person answered at each position: reached, or not and (where
/// asked) why.
#[derive(Clone, Debug, PartialEq)]
pub struct PositionAnswer {
    pub reached: bool,
    pub verdict: Option<String>,
}

/// How an advice was set: what moves, along which axis, where it was
/// declared, and the share asked.
#[derive(Clone, Debug, PartialEq)]
pub struct AdviceFrame {
    pub name: String,
    pub base: String,
    pub carries: Vec<String>,
    pub along: &'static str,
    pub target_mm: [f64; 3],
    pub declared_mm: f64,
    pub step_mm: f64,
    pub serves: f64,
    pub scan: &'static str,
    /// How many people a bracketed scan solved at every position (their
    /// band had a hole).
    pub rescanned: usize,
    pub positions_mm: Vec<f64>,
    /// For a line of a grid: where across it lies.
    pub across: Option<Across>,
}

impl AdviceReport {
    /// The advice for one person, `who`, whose answer at each position of
    /// `frame` is `answers`.
    pub fn person(frame: &AdviceFrame, who: &str, answers: &[PositionAnswer]) -> Self {
        let members = [(who.to_string(), answers.to_vec())];
        // A person is served where they reach it, whatever share the
        // task asks of a population.
        let reached = AdviceFrame {
            serves: 1.0,
            ..frame.clone()
        };
        let mut report = Self::of_people(&reached, who, false, &members);
        report.asked = frame.serves;
        for (point, answer) in report.points.iter_mut().zip(answers) {
            point.ci95 = None;
            point.verdict = answer.verdict.clone().filter(|_| !answer.reached);
        }
        report
    }

    /// The advice for a population, `who`, whose people (named as the
    /// report names them, in draw order) answered `members`.
    pub fn population(
        frame: &AdviceFrame,
        who: &str,
        members: &[(String, Vec<PositionAnswer>)],
    ) -> Self {
        Self::of_people(frame, who, true, members)
    }

    /// The frame of `population`'s advice, whose people (in draw order)
    /// answered `answers` (their advices, or for one whose base fits
    /// nowhere in the room as declared, that answer at every position),
    /// and each one's name and answer at each position, as
    /// [`AdviceReport::population`] takes them; none where no one's answer
    /// is an advice (no positions are known).
    #[allow(clippy::type_complexity)]
    pub fn members(
        population: &Population,
        answers: &[TaskReport],
    ) -> Option<(AdviceFrame, Vec<(String, Vec<PositionAnswer>)>)> {
        let first = answers.iter().find_map(|a| match a {
            TaskReport::Advice(advice) => Some(advice.as_ref()),
            _ => None,
        })?;
        let members: Vec<(String, Vec<PositionAnswer>)> = (answers.iter().zip(1..))
            .map(|(answer, i)| {
                let name = format!("{}#{i}", population.name);
                let each = match answer {
                    TaskReport::Advice(a) => a.answers(),
                    other => {
                        let verdict = other.answer().verdict;
                        let not = PositionAnswer {
                            reached: false,
                            verdict: Some(verdict),
                        };
                        vec![not; first.points.len()]
                    }
                };
                (name, each)
            })
            .collect();
        let rescanned = (answers.iter())
            .filter(|a| matches!(a, TaskReport::Advice(x) if x.rescanned > 0))
            .count();
        Some((
            AdviceFrame {
                rescanned,
                ..first.frame()
            },
            members,
        ))
    }

    /// Who drops out at each end of each served range: (index into the
    /// members, position index).
    pub fn dropped(&self, members: &[(String, Vec<PositionAnswer>)]) -> Vec<(usize, usize)> {
        let index = |at: f64| self.points.iter().position(|p| p.at_mm == at);
        let mut out = Vec::new();
        for range in &self.ranges {
            let ends = [
                (index(range.from_mm), range.low_end.as_ref()),
                (index(range.to_mm), range.high_end.as_ref()),
            ];
            for (edge, end) in ends {
                let (Some(edge), Some(end)) = (edge, end) else {
                    continue;
                };
                let Some(beyond) = index(end.at_mm) else {
                    continue;
                };
                for (m, (_, answers)) in members.iter().enumerate() {
                    if answers[edge].reached
                        && !answers[beyond].reached
                        && !out.contains(&(m, beyond))
                    {
                        out.push((m, beyond));
                    }
                }
            }
        }
        out
    }

    /// The frame this advice was made in (for a person's: the share asked
    /// of the population they belong to).
    fn frame(&self) -> AdviceFrame {
        AdviceFrame {
            name: self.name.clone(),
            base: self.base.clone(),
            carries: self.carries.clone(),
            along: self.along,
            target_mm: self.target_mm,
            declared_mm: self.declared_mm,
            step_mm: self.step_mm,
            serves: self.asked,
            scan: self.scan,
            rescanned: self.rescanned,
            positions_mm: self.points.iter().map(|p| p.at_mm).collect(),
            across: self.across.clone(),
        }
    }

    /// A person's answer at each position.
    fn answers(&self) -> Vec<PositionAnswer> {
        (self.points.iter())
            .map(|p| PositionAnswer {
                reached: p.reached > 0,
                verdict: p.verdict.clone(),
            })
            .collect()
    }

    fn of_people(
        frame: &AdviceFrame,
        who: &str,
        population: bool,
        members: &[(String, Vec<PositionAnswer>)],
    ) -> Self {
        let people = members.len();
        let reached_at = |k: usize| members.iter().filter(|(_, a)| a[k].reached).count();
        let points: Vec<AdvicePoint> = (frame.positions_mm.iter().enumerate())
            .map(|(k, &at)| {
                let reached = reached_at(k);
                AdvicePoint {
                    at_mm: mm(at),
                    reached,
                    share: fixed(reached as f64 / people.max(1) as f64, 4),
                    ci95: Some(wilson95(reached, people).map(|v| fixed(v, 4))),
                    verdict: None,
                }
            })
            .collect();
        let serves = frame.serves;
        let served = |k: usize| serving(points[k].reached, people, serves);
        let ranges = runs(points.len(), served)
            .into_iter()
            .map(|(first, last)| ServedRange {
                from_mm: points[first].at_mm,
                to_mm: points[last].at_mm,
                low_end: (first > 0).then(|| end(&points, members, first, first - 1)),
                high_end: (last + 1 < points.len()).then(|| end(&points, members, last, last + 1)),
            })
            .collect::<Vec<_>>();
        let best = best_point(&points);
        let nowhere = match population {
            true => reached_nowhere(members),
            false => Vec::new(),
        };
        AdviceReport {
            nowhere,
            task: "advise",
            name: frame.name.clone(),
            who: who.to_string(),
            population,
            people,
            base: frame.base.clone(),
            carries: frame.carries.clone(),
            along: frame.along,
            target_mm: frame.target_mm.map(mm),
            declared_mm: mm(frame.declared_mm),
            step_mm: mm(frame.step_mm),
            serves: fixed(serves, 4),
            scan: frame.scan,
            rescanned: frame.rescanned,
            asked: frame.serves,
            standards: Vec::new(),
            across: frame.across.clone(),
            rows: Vec::new(),
            ok: !ranges.is_empty(),
            points,
            ranges,
            best,
        }
    }

    /// Whether every position from `from_mm` to `to_mm` (within half a
    /// step) serves at least `share`, and in words the first that does
    /// not (or the range's least share).
    pub(super) fn line_serves_between(
        &self,
        share: f64,
        from_mm: f64,
        to_mm: f64,
    ) -> (bool, String) {
        let half = self.step_mm / 2.0;
        let inside: Vec<&AdvicePoint> = (self.points.iter())
            .filter(|p| p.at_mm >= from_mm - half && p.at_mm <= to_mm + half)
            .collect();
        let (lo, hi) = (self.points.first(), self.points.last());
        if lo.is_none_or(|p| p.at_mm > from_mm + half) || hi.is_none_or(|p| p.at_mm < to_mm - half)
        {
            return (
                false,
                format!(
                    "{} scans {} only",
                    self.who,
                    lo.zip(hi)
                        .map_or("nothing".into(), |(a, b)| span_words(a.at_mm, b.at_mm))
                ),
            );
        }
        let Some(least) = (inside.iter()).min_by(|a, b| a.share.total_cmp(&b.share)) else {
            return (false, format!("{} has no position there", self.who));
        };
        let ok = least.share >= share - 1e-9;
        let words = format!(
            "{} {} at {} mm",
            self.who,
            if self.population {
                percent(least.share)
            } else if least.reached > 0 {
                "reaches it".into()
            } else {
                "does NOT reach it".into()
            },
            least.at_mm
        );
        (ok, words)
    }

    /// The runs of positions (first, last) at which every one of
    /// `advices` serves: each population at least its share asked, each
    /// person reaching it; positions as the first advice has them.
    pub fn served_together(advices: &[&AdviceReport]) -> Vec<(f64, f64)> {
        let Some(first) = advices.first() else {
            return Vec::new();
        };
        let serves_at =
            |a: &AdviceReport, at: f64| (a.points.iter()).any(|p| p.at_mm == at && a.serves_at(p));
        let points = &first.points;
        runs(points.len(), |k| {
            advices.iter().all(|a| serves_at(a, points[k].at_mm))
        })
        .into_iter()
        .map(|(a, b)| (points[a].at_mm, points[b].at_mm))
        .collect()
    }

    /// Whether `point`, one of this advice's, serves the share asked.
    pub fn serves_at(&self, point: &AdvicePoint) -> bool {
        serving(point.reached, self.people, self.serves)
    }

    /// The served ranges in words: `800-1120 mm`, `nowhere`.
    pub(super) fn ranges_words(&self) -> String {
        if self.ranges.is_empty() {
            return "nowhere".into();
        }
        let each: Vec<String> = (self.ranges.iter())
            .map(|r| span_words(r.from_mm, r.to_mm))
            .collect();
        each.join(", ")
    }
}

fn is_zero(n: &usize) -> bool {
    *n == 0
}

/// Whether `reached` of `people` is at least the share `serves` (none of
/// no one).
fn serving(reached: usize, people: usize, serves: f64) -> bool {
    people > 0 && reached as f64 >= serves * people as f64 - 1e-9
}

/// 0, 1, 2 for the room's axis `x`, `y`, `z`.
pub fn axis_index(axis: &str) -> Option<usize> {
    ["x", "y", "z"].iter().position(|a| *a == axis)
}

/// `800-1120 mm`, or `800 mm` for one position.
pub(super) fn span_words(from_mm: f64, to_mm: f64) -> String {
    if from_mm == to_mm {
        format!("{from_mm} mm")
    } else {
        format!("{from_mm}-{to_mm} mm")
    }
}

/// The runs of consecutive indices below `n` where `inside` holds, as
/// (first, last).
pub(super) fn runs(n: usize, inside: impl Fn(usize) -> bool) -> Vec<(usize, usize)> {
    let mut out: Vec<(usize, usize)> = Vec::new();
    for k in (0..n).filter(|&k| inside(k)) {
        match out.last_mut() {
            Some((_, last)) if *last + 1 == k => *last = k,
            _ => out.push((k, k)),
        }
    }
    out
}

/// Who of `members` reach it at no position, by their answer (the first
/// one given; where none was asked, that they reach it nowhere).
fn reached_nowhere(members: &[(String, Vec<PositionAnswer>)]) -> Vec<Because> {
    let mut because: Vec<Because> = Vec::new();
    for (name, answers) in members.iter().filter(|(_, a)| !a.iter().any(|x| x.reached)) {
        let verdict = (answers.iter().find_map(|a| a.verdict.clone()))
            .unwrap_or_else(|| "NOT reached at any position scanned".into());
        tally(&mut because, verdict, name);
    }
    because.sort_by_key(|b| std::cmp::Reverse(b.people));
    because
}

/// `name` counted under `verdict` (named among the first few).
fn tally(because: &mut Vec<Because>, verdict: String, name: &str) {
    match because.iter_mut().find(|b| b.verdict == verdict) {
        Some(b) => {
            b.people += 1;
            if b.who.len() < NAMED {
                b.who.push(name.to_string());
            }
        }
        None => because.push(Because {
            verdict,
            people: 1,
            who: vec![name.to_string()],
        }),
    }
}

/// The end of a range at `edge` (its last position that serves), whose
/// next position outside is `beyond`: who reaches `edge` but not `beyond`,
/// by their answer there.
fn end(
    points: &[AdvicePoint],
    members: &[(String, Vec<PositionAnswer>)],
    edge: usize,
    beyond: usize,
) -> RangeEnd {
    let mut because: Vec<Because> = Vec::new();
    let mut dropped = 0;
    for (name, answers) in members {
        if !answers[edge].reached || answers[beyond].reached {
            continue;
        }
        dropped += 1;
        let verdict = (answers[beyond].verdict.clone()).unwrap_or_else(|| "NOT reachable".into());
        tally(&mut because, verdict, name);
    }
    // The most common first; equal counts in the order first met.
    because.sort_by_key(|b| std::cmp::Reverse(b.people));
    RangeEnd {
        at_mm: points[beyond].at_mm,
        share: points[beyond].share,
        dropped,
        because,
    }
}

/// The middle of the longest run of positions with the highest share
/// (the first such run where two are as long); none where no one reaches
/// any position.
fn best_point(points: &[AdvicePoint]) -> Option<AdvicePoint> {
    let most = points.iter().map(|p| p.reached).max().filter(|&m| m > 0)?;
    let longest = runs(points.len(), |k| points[k].reached == most)
        .into_iter()
        .fold(None::<(usize, usize)>, |kept, run| match kept {
            Some(k) if k.1 - k.0 >= run.1 - run.0 => Some(k),
            _ => Some(run),
        })?;
    let mut best = points[(longest.0 + longest.1) / 2].clone();
    best.verdict = None;
    Some(best)
}

impl ReportKind for AdviceReport {
    fn answer(&self) -> Answer {
        let verdict = if self.population {
            let best = self.best.as_ref().map_or_else(
                || "no one reaches it anywhere".to_string(),
                |b| format!("at most {} at {} mm", percent(b.share), b.at_mm),
            );
            format!(
                "{} serves {}: {}; {best}",
                self.ranges_words(),
                percent(self.serves),
                self.along_words()
            )
        } else if self.ok {
            format!(
                "reached at {} ({})",
                self.ranges_words(),
                self.along_words()
            )
        } else {
            format!("NOT reached anywhere ({})", self.along_words())
        };
        let figure = |name: &'static str, value: f64| Figure::new(name, value, "mm", 1.0);
        let mut figures = Vec::new();
        if let (Some(first), Some(last)) = (self.ranges.first(), self.ranges.last()) {
            figures.push(figure("from", first.from_mm));
            figures.push(figure("to", last.to_mm));
        }
        Answer {
            task: "advise",
            subject: self.name.clone(),
            person: self.who.clone(),
            ok: self.ok,
            verdict,
            effector: None,
            figures,
        }
    }

    fn details(&self, out: &mut String) {
        let grid = match &self.across {
            Some(across) if !self.rows.is_empty() => format!(
                " and across {} in steps of {} mm",
                across.axis, across.step_mm
            ),
            _ => String::new(),
        };
        let _ = writeln!(
            out,
            "\nadvise {} by {}: moved along {} in steps of {} mm{grid} ({} scan), carrying {}",
            self.name,
            self.who,
            self.along,
            self.step_mm,
            self.scan,
            if self.carries.is_empty() {
                "nothing else".to_string()
            } else {
                self.carries.join(", ")
            }
        );
        if !self.rows.is_empty() {
            self.rows_lines(out);
        }
        self.line_details(out);
    }

    fn share(&self) -> Option<f64> {
        self.best.as_ref().map(|b| b.share)
    }
}

impl AdviceReport {
    /// The lines of `details` about one line of positions: each
    /// position's share, the served ranges and their ends, the standards
    /// and the best.
    fn line_details(&self, out: &mut String) {
        let _ = writeln!(out, "  {}", self.series());
        for b in &self.nowhere {
            let _ = writeln!(out, "  reached nowhere by {}: {}", b.named(), b.verdict);
        }
        if self.rescanned > 0 {
            let whom = match self.population {
                true => format!("{} of {} people", self.rescanned, self.people),
                false => self.who.clone(),
            };
            let _ = writeln!(
                out,
                "  {whom}: more than one stretch reached, so every position solved (a hole the coarse step passes by is found)"
            );
        }
        for range in &self.ranges {
            let _ = writeln!(
                out,
                "  {} serves {}",
                span_words(range.from_mm, range.to_mm),
                if self.population {
                    format!("at least {}", percent(self.serves))
                } else {
                    format!("{}: reached", self.who)
                }
            );
            for (side, end) in [("below", &range.low_end), ("above", &range.high_end)] {
                if let Some(end) = end {
                    self.end_lines(out, side, range, end);
                }
            }
        }
        for s in &self.standards {
            let _ = writeln!(
                out,
                "  {} {} ({}) {}",
                s.standard,
                s.sections.join(", "),
                s.rule,
                s.compared
            );
        }
        if let Some(best) = &self.best {
            if self.population {
                let [lo, hi] = best.ci95.unwrap_or([0.0, 1.0]);
                let _ = writeln!(
                    out,
                    "  most served at {} mm: {} ({} to {} at 95 %)",
                    best.at_mm,
                    percent(best.share),
                    percent(lo),
                    percent(hi)
                );
            }
        }
    }

    /// The target moved to the position that serves the most (on a grid,
    /// across too).
    pub fn best_target_mm(&self) -> Option<[f64; 3]> {
        let best = self.best.as_ref()?;
        let mut at = self.target_mm;
        at[axis_index(self.along)?] = best.at_mm;
        if let Some(across) = &self.across {
            at[axis_index(across.axis)?] = across.at_mm;
        }
        Some(at)
    }

    /// Where the target serves the most, in words: `at 950 mm` (on a
    /// grid: `at z 950 mm, x 300 mm`); none where no one reaches it.
    pub fn best_words(&self) -> Option<String> {
        let best = self.best.as_ref()?;
        Some(match &self.across {
            Some(a) => format!(
                "at {} {} mm, {} {} mm",
                self.along, best.at_mm, a.axis, a.at_mm
            ),
            None => format!("at {} mm", best.at_mm),
        })
    }

    /// `the target's z, declared at 950 mm` (on a grid: `the target's z
    /// at x 300 mm, declared at 950 mm`).
    fn along_words(&self) -> String {
        let across = (self.across.as_ref())
            .map_or(String::new(), |a| format!(" at {} {} mm", a.axis, a.at_mm));
        format!(
            "{}'s {}{across}, declared at {} mm",
            self.name, self.along, self.declared_mm
        )
    }

    /// Each position's share, compressed into runs of equal shares:
    /// `700-770 mm 0 %, 780 mm 40 %, 790-1100 mm 100 %`.
    fn series(&self) -> String {
        let mut parts: Vec<String> = Vec::new();
        let mut k = 0;
        while k < self.points.len() {
            let mut last = k;
            while last + 1 < self.points.len()
                && self.points[last + 1].reached == self.points[k].reached
            {
                last += 1;
            }
            let (a, b) = (self.points[k].at_mm, self.points[last].at_mm);
            let what = if self.population {
                percent(self.points[k].share)
            } else if self.points[k].reached > 0 {
                "reached".into()
            } else {
                "not reached".into()
            };
            parts.push(format!("{} {what}", span_words(a, b)));
            k = last + 1;
        }
        parts.join(", ")
    }

    /// Who drops out past one end of `range`, and why.
    fn end_lines(&self, out: &mut String, side: &str, range: &ServedRange, end: &RangeEnd) {
        let edge = if side == "below" {
            range.from_mm
        } else {
            range.to_mm
        };
        let what = if self.population {
            format!(
                "{} mm ({}): {} of those who reach it at {edge} mm do not",
                end.at_mm,
                percent(end.share),
                end.dropped
            )
        } else {
            format!("{} mm", end.at_mm)
        };
        let _ = writeln!(out, "    {side} it, at {what}");
        for b in &end.because {
            let names = match self.population {
                true => format!("{}: ", b.named()),
                false => String::new(),
            };
            let _ = writeln!(out, "      {names}{}", b.verdict);
        }
    }
}

impl EntryKind for AdviceReport {
    fn asks(entry: &Value) -> Asks {
        Asks::by_name("advise", entry, "who")
    }
    fn verdict_words(entry: &Value) -> String {
        let ranges: Vec<String> = (entry["ranges"].as_array().into_iter().flatten())
            .map(|r| format!("{}-{} mm", r["from_mm"], r["to_mm"]))
            .collect();
        if ranges.is_empty() {
            "served nowhere".into()
        } else {
            format!("served {}", ranges.join(", "))
        }
    }
    /// Its ranges' ends beyond the tolerance, and positions reached by
    /// another number of people.
    fn changes(old: &Value, new: &Value, _: &Answer, who: &str, tol: Tolerance) -> Vec<String> {
        let mut changes = Vec::new();
        let ends = |v: &Value| -> Vec<(f64, f64)> {
            (v["ranges"].as_array().into_iter().flatten())
                .map(|r| (num(&r["from_mm"]), num(&r["to_mm"])))
                .collect()
        };
        let (was, now) = (ends(old), ends(new));
        let moved = was.len() != now.len()
            || was
                .iter()
                .zip(&now)
                .any(|(a, b)| (a.0 - b.0).abs() > tol.mm || (a.1 - b.1).abs() > tol.mm);
        if moved {
            changes.push(format!(
                "{who}: {} (was {})",
                Self::verdict_words(new),
                Self::verdict_words(old)
            ));
        }
        let counts = |v: &Value| -> Vec<Value> {
            (v["points"].as_array().into_iter().flatten())
                .map(|p| p["reached"].clone())
                .collect()
        };
        let (was, now) = (counts(old), counts(new));
        let flipped = was.iter().zip(&now).filter(|(a, b)| a != b).count();
        if flipped > 0 || was.len() != now.len() {
            changes.push(format!(
                "{who}: {flipped} of {} positions reached by another number of people",
                now.len()
            ));
        }
        if text(old, "scan") != text(new, "scan") {
            changes.push(format!(
                "{who}: scanned {} (was {})",
                text(new, "scan"),
                text(old, "scan")
            ));
        }
        changes
    }
}

fn num(v: &Value) -> f64 {
    v.as_f64().unwrap_or(f64::NAN)
}

#[cfg(test)]
pub(super) mod tests {
    use super::*;

    /// A microwave's frame at `positions`, serving `serves` (the other
    /// report tests' too).
    pub(in crate::report) fn frame(positions: &[f64], serves: f64) -> AdviceFrame {
        AdviceFrame {
            name: "microwave".into(),
            base: "wheelchair".into(),
            carries: vec!["oven".into()],
            along: "z",
            target_mm: [300.0, 500.0, 900.0],
            declared_mm: 900.0,
            step_mm: 100.0,
            serves,
            scan: "full",
            rescanned: 0,
            positions_mm: positions.to_vec(),
            across: None,
        }
    }

    fn answers(bits: &str) -> Vec<PositionAnswer> {
        bits.chars()
            .map(|c| PositionAnswer {
                reached: c == '1',
                verdict: (c == '0').then(|| "NOT reachable: out of reach".to_string()),
            })
            .collect()
    }

    #[test]
    fn a_range_ends_where_the_share_falls_below_the_share_asked_and_names_who_drops_out() {
        let at = [600.0, 700.0, 800.0, 900.0, 1000.0];
        let members: Vec<(String, Vec<PositionAnswer>)> = ["01111", "01110", "00110", "11111"]
            .iter()
            .enumerate()
            .map(|(k, b)| (format!("p#{}", k + 1), answers(b)))
            .collect();
        let report = AdviceReport::population(&frame(&at, 0.75), "p", &members);
        let shares: Vec<f64> = report.points.iter().map(|p| p.share).collect();
        assert_eq!(shares, [0.25, 0.75, 1.0, 1.0, 0.5]);
        assert_eq!(report.ranges.len(), 1);
        let range = &report.ranges[0];
        assert_eq!((range.from_mm, range.to_mm), (700.0, 900.0));
        let low = range.low_end.as_ref().unwrap();
        assert_eq!((low.at_mm, low.dropped), (600.0, 2));
        assert_eq!(low.because[0].who, ["p#1", "p#2"]);
        let high = range.high_end.as_ref().unwrap();
        assert_eq!((high.at_mm, high.dropped), (1000.0, 2));
        // The best: the middle of the run at 100 %.
        assert_eq!(report.best.as_ref().unwrap().at_mm, 800.0);
        assert!(report.serves_between(0.75, 700.0, 900.0).0);
        assert!(!report.serves_between(0.75, 700.0, 1000.0).0);
        // Past the scan: not met, whatever the shares.
        assert!(!report.serves_between(0.0, 500.0, 900.0).0);
    }

    #[test]
    fn who_reach_it_nowhere_are_named_with_their_answer() {
        let at = [600.0, 700.0];
        let shut = |name: &str| {
            let not = PositionAnswer {
                reached: false,
                verdict: Some("does NOT fit in the room".into()),
            };
            (name.to_string(), vec![not.clone(), not])
        };
        let members = vec![
            ("p#1".to_string(), answers("11")),
            shut("p#2"),
            ("p#3".to_string(), answers("00")),
            shut("p#4"),
        ];
        let report = AdviceReport::population(&frame(&at, 0.25), "p", &members);
        let nowhere: Vec<(&str, usize, &[String])> = (report.nowhere.iter())
            .map(|b| (b.verdict.as_str(), b.people, b.who.as_slice()))
            .collect();
        assert_eq!(
            nowhere,
            [
                (
                    "does NOT fit in the room",
                    2,
                    &["p#2".to_string(), "p#4".to_string()][..]
                ),
                ("NOT reachable: out of reach", 1, &["p#3".to_string()][..]),
            ]
        );
        let mut out = String::new();
        report.details(&mut out);
        assert!(
            out.contains("reached nowhere by 2 (p#2, p#4): does NOT fit in the room"),
            "{out}"
        );
        // A person's own answer says so: no group of one.
        let alone = AdviceReport::person(&frame(&at, 0.9), "ann", &answers("00"));
        assert!(alone.nowhere.is_empty());
    }

    #[test]
    fn a_person_is_served_where_they_reach_it() {
        let at = [600.0, 700.0, 800.0];
        let report = AdviceReport::person(&frame(&at, 0.9), "ann", &answers("011"));
        assert_eq!(report.serves, 1.0);
        assert_eq!(report.ranges[0].from_mm, 700.0);
        assert!(report.ranges[0].high_end.is_none());
        assert_eq!(
            report.points[0].verdict.as_deref(),
            Some("NOT reachable: out of reach")
        );
        assert!(report.points[0].ci95.is_none());
        let none = AdviceReport::person(&frame(&at, 0.9), "ann", &answers("000"));
        assert!(!none.ok && none.best.is_none());
    }

    #[test]
    fn a_person_scanned_again_in_full_is_said_so() {
        let at = [600.0, 700.0, 800.0];
        let holed = AdviceFrame {
            scan: "bracketed",
            rescanned: 1,
            ..frame(&at, 0.9)
        };
        let mut out = String::new();
        AdviceReport::person(&holed, "ann", &answers("101")).details(&mut out);
        assert!(
            out.contains("ann: more than one stretch reached, so every position solved"),
            "{out}"
        );
        let json =
            serde_json::to_value(AdviceReport::person(&holed, "ann", &answers("101"))).unwrap();
        assert_eq!(json["rescanned"], 1);
        let one = AdviceReport::person(&frame(&at, 0.9), "ann", &answers("110"));
        assert!(serde_json::to_value(one)
            .unwrap()
            .get("rescanned")
            .is_none());
    }
}
