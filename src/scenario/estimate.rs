//! How much work a scenario's run will need, before it is run
//! (`reach check --estimate`): every task by one person is run, and of a
//! task by a population only the first people of its draw (a random
//! sample, since the draw is), whose work is scaled up to the whole
//! population with a 95 % interval from the spread between them. The
//! sample runs within a bound of its own (the most a file may raise its
//! bound to), so that an estimate of a file that needs more than its bound
//! still says how much, and an estimate of a hostile file ends.

use std::fmt::Write as _;
use std::sync::Arc;

use rayon::prelude::*;

use super::{Scenario, TaskSpec};
use crate::error::thousands;
use crate::kept::Memo;
use crate::meter::RunWork;
use crate::progress::Progress;
use crate::span::Span;

/// The work of one task, measured or estimated from a sample.
#[derive(Clone, Debug, PartialEq)]
pub struct TaskWork {
    /// The task in words: `map high_far_half by chair_users`.
    pub label: String,
    /// Its declaration.
    pub span: Span,
    /// The work it needs, in the meter's units (measured, or the sample's
    /// mean times the population's size).
    pub units: u64,
    /// Half the width of the 95 % interval around `units` (0 where it was
    /// measured).
    pub half_width: u64,
    /// For a task by a population: how many of its people were run, and
    /// how many it has.
    pub sampled: Option<(usize, usize)>,
}

/// The work a scenario's run needs, task by task.
#[derive(Clone, Debug, PartialEq)]
pub struct WorkEstimate {
    /// In the order of the file: the tasks estimated before the sample ran
    /// out of the bound (all of them where it did not).
    pub tasks: Vec<TaskWork>,
    /// The standards' work, where the scenario has standards and the
    /// sample reached them.
    pub standards: Option<u64>,
    /// Whether the sample itself needed more than its budget (the tasks
    /// after the last listed were not estimated).
    pub stopped: bool,
    /// The work the sample did.
    pub sample_units: u64,
}

impl WorkEstimate {
    /// The estimated total, and half the width of its interval (the
    /// tasks' half widths added up: the tasks share people, so their
    /// errors are not independent).
    pub fn total(&self) -> (u64, u64) {
        let sum =
            |f: fn(&TaskWork) -> u64| self.tasks.iter().map(f).fold(0u64, u64::saturating_add);
        let units = sum(|t| t.units).saturating_add(self.standards.unwrap_or(0));
        (units, sum(|t| t.half_width))
    }
}

/// How many people of a population of `people` the estimate runs: all of
/// a small one, else the square root of its size, at least
/// [`LEAST_SAMPLE`] (100 people: 10; 1,000: 32; 100,000: 317).
pub fn sample_size(people: usize) -> usize {
    if people <= LEAST_SAMPLE {
        return people;
    }
    (people as f64).sqrt().ceil().max(LEAST_SAMPLE as f64) as usize
}

/// The fewest people of a population the estimate runs (all of them where
/// it has fewer).
const LEAST_SAMPLE: usize = 8;

impl Scenario {
    /// The work a run of this scenario needs, each task run on a memo of
    /// the estimate's own, in the order of the file (a task by a
    /// population by its sample of people, in parallel), the sample within
    /// `budget_units`. The same on every run and thread count.
    pub fn estimate_work(&self, progress: &dyn Progress, budget_units: u64) -> WorkEstimate {
        let run = RunWork::keeping(budget_units, Arc::new(Memo::default()));
        let charges = self.floor_charges();
        let mut tasks = Vec::with_capacity(self.tasks.len());
        for task in &self.tasks {
            let label = self.task_words(task);
            let charged = charges.of(task);
            let work = match task.population {
                None => {
                    let ran = self.run_one(task, progress, false, None, &run, charged);
                    TaskWork {
                        label,
                        span: task.span,
                        units: ran.work,
                        half_width: 0,
                        sampled: None,
                    }
                }
                Some(p) => {
                    let population = &self.populations[p];
                    let sample = sample_size(population.len());
                    // The first people of the draw, those the check built.
                    let people: Vec<usize> = (0..sample)
                        .filter_map(|i| population.person_of(i))
                        .collect();
                    let sample = people.len();
                    let each: Vec<u64> = people
                        .into_par_iter()
                        .map(|person| self.run_member(task, person, progress, &run, charged).1)
                        .collect();
                    let (units, half_width) = scaled(&each, population.len());
                    TaskWork {
                        label,
                        span: task.span,
                        units,
                        half_width,
                        sampled: Some((sample, population.len())),
                    }
                }
            };
            if run.exceeded() {
                return self.estimate_stopped(tasks, &run);
            }
            tasks.push(work);
        }
        let before = run.spent();
        let all: Vec<&TaskSpec> = self.tasks.iter().collect();
        let _ = self.run_standards(&all, &[], &run);
        if run.exceeded() {
            return self.estimate_stopped(tasks, &run);
        }
        WorkEstimate {
            tasks,
            standards: (!self.standards.is_empty()).then(|| run.spent() - before),
            stopped: false,
            sample_units: run.spent(),
        }
    }

    fn estimate_stopped(&self, tasks: Vec<TaskWork>, run: &RunWork) -> WorkEstimate {
        WorkEstimate {
            tasks,
            standards: None,
            stopped: true,
            sample_units: run.spent(),
        }
    }
}

/// The most tasks the text lists one by one (the rest are summed up).
const LISTED: usize = 10;

impl WorkEstimate {
    /// The estimate in words, against the run's bound `limit_units`; a
    /// file may raise its bound to at most `file_ceiling_units` (the
    /// sample's budget).
    pub fn text(&self, limit_units: u64, file_ceiling_units: u64) -> String {
        let (total, half) = self.total();
        let mut out = String::new();
        let range = if half > 0 {
            format!(
                " ({} to {})",
                thousands(total.saturating_sub(half)),
                thousands(total.saturating_add(half))
            )
        } else {
            String::new()
        };
        let _ = writeln!(
            out,
            "work {}: {}{} units{range}, {} the bound of {} units",
            if self.stopped {
                "of the tasks estimated"
            } else {
                "estimated"
            },
            if half > 0 { "about " } else { "" },
            thousands(total),
            share_words(total, limit_units),
            thousands(limit_units),
        );
        self.rows(&mut out, total);
        out.push_str(&self.verdict(limit_units, file_ceiling_units));
        out
    }

    /// The costliest tasks, a line each, the rest summed up, and the
    /// standards.
    fn rows(&self, out: &mut String, total: u64) {
        let mut order: Vec<&TaskWork> = self.tasks.iter().collect();
        order.sort_by_key(|t| std::cmp::Reverse(t.units));
        let width = thousands(order.first().map_or(0, |t| t.units)).len().max(5);
        let _ = writeln!(out, "  {:>width$}  share  task", "units");
        for task in order.iter().take(LISTED) {
            let sampled = match task.sampled {
                Some((run, of)) if run < of => format!(
                    " (from {run} of its {of} people, within {} units at 95 %)",
                    thousands(task.half_width)
                ),
                _ => String::new(),
            };
            let share = percent(task.units, total);
            let units = thousands(task.units);
            let _ = writeln!(
                out,
                "  {units:>width$}  {share:>3} %  {}{sampled}",
                task.label
            );
        }
        let rest = &order[order.len().min(LISTED)..];
        if !rest.is_empty() {
            let units: u64 = rest.iter().map(|t| t.units).sum();
            let (share, n) = (percent(units, total), rest.len());
            let _ = writeln!(
                out,
                "  {:>width$}  {share:>3} %  {n} more tasks",
                thousands(units)
            );
        }
        if let Some(units) = self.standards {
            let share = percent(units, total);
            let _ = writeln!(
                out,
                "  {:>width$}  {share:>3} %  the standards",
                thousands(units)
            );
        }
    }

    /// Whether the run fits within its bound, and if not, what to raise
    /// it to.
    fn verdict(&self, limit_units: u64, file_ceiling_units: u64) -> String {
        let (total, half) = self.total();
        let sample = thousands(self.sample_units);
        if self.stopped {
            return format!(
                "the sample itself ({sample} units) passed the most a file may raise its bound to ({} units) after {} task{}: a run stops partway; raise --max-solver-work or --max-limits-raise to estimate the rest\n",
                thousands(file_ceiling_units),
                self.tasks.len(),
                if self.tasks.len() == 1 { "" } else { "s" }
            );
        }
        let measured = format!("measured by running each task by one person and a sample of each population's people ({sample} units)\n");
        let upper = total.saturating_add(half);
        if upper <= limit_units {
            return format!("within the bound; {measured}");
        }
        let raise_to = round_up(upper.saturating_add(upper / 10));
        let how = if raise_to <= file_ceiling_units {
            format!(
                "`limits {{ solver_work {} }}` in the file, or --max-solver-work {}",
                sci(raise_to),
                sci(raise_to)
            )
        } else {
            format!(
                "--max-solver-work {} (more than a file may raise its own bound to, {} units, under --max-limits-raise)",
                sci(raise_to),
                thousands(file_ceiling_units)
            )
        };
        let stops = if total > limit_units {
            "a run stops partway"
        } else {
            "a run may stop partway"
        };
        format!(
            "{stops}: raise the bound to about {} units with {how}; {measured}",
            thousands(raise_to)
        )
    }
}

/// `part` as a whole per cent of `whole`.
fn percent(part: u64, whole: u64) -> u64 {
    if whole == 0 {
        return 0;
    }
    ((part as f64 / whole as f64) * 100.0).round() as u64
}

/// `units` against the bound: `38 %`, `3.9 times`.
fn share_words(units: u64, limit_units: u64) -> String {
    if units <= limit_units || limit_units == 0 {
        return format!("{} % of", percent(units, limit_units));
    }
    format!("{:.1} times", units as f64 / limit_units as f64)
}

/// `units` rounded up to two significant figures.
fn round_up(units: u64) -> u64 {
    let mut scale = 1u64;
    while units / scale >= 100 {
        scale *= 10;
    }
    units.div_ceil(scale).saturating_mul(scale)
}

/// A round number as the language writes it: `1.2e9`, `450000`.
fn sci(units: u64) -> String {
    if units < 1_000_000 {
        return units.to_string();
    }
    let exponent = units.ilog10();
    let mantissa = units as f64 / 10f64.powi(exponent as i32);
    let digits = format!("{mantissa:.1}");
    let digits = digits.trim_end_matches('0').trim_end_matches('.');
    format!("{digits}e{exponent}")
}

/// The work of `people` people from the work of a sample of them
/// (`each`): the sample's mean times their number, and half the width of
/// its 95 % interval (Student's t, with the correction for a sample drawn
/// from a finite population: none where everyone was run).
fn scaled(each: &[u64], people: usize) -> (u64, u64) {
    let k = each.len();
    if k == 0 {
        return (0, 0);
    }
    let mean = each.iter().map(|&w| w as f64).sum::<f64>() / k as f64;
    let total = mean * people as f64;
    if k < 2 || k >= people {
        return (total.round() as u64, 0);
    }
    let variance = each.iter().map(|&w| (w as f64 - mean).powi(2)).sum::<f64>() / (k - 1) as f64;
    let finite = (1.0 - k as f64 / people as f64).sqrt();
    let half = t95(k - 1) * people as f64 * (variance / k as f64).sqrt() * finite;
    (total.round() as u64, half.round() as u64)
}

/// Student's t for a two-sided 95 % interval with `df` degrees of freedom.
fn t95(df: usize) -> f64 {
    const TABLE: [f64; 30] = [
        12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228, 2.201, 2.179, 2.160,
        2.145, 2.131, 2.120, 2.110, 2.101, 2.093, 2.086, 2.080, 2.074, 2.069, 2.064, 2.060, 2.056,
        2.052, 2.048, 2.045, 2.042,
    ];
    match df {
        0 => f64::INFINITY,
        1..=30 => TABLE[df - 1],
        31..=60 => 2.0,
        _ => 1.96,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_sample_is_all_of_a_small_population_and_the_root_of_a_large_one() {
        let table = [
            (1, 1),
            (8, 8),
            (9, 8),
            (64, 8),
            (100, 10),
            (1000, 32),
            (100_000, 317),
        ];
        for (people, sample) in table {
            assert_eq!(sample_size(people), sample, "{people} people");
        }
    }

    #[test]
    fn everyone_run_is_measured_not_estimated() {
        assert_eq!(scaled(&[10, 30], 2), (40, 0));
    }

    #[test]
    fn a_sample_scales_with_an_interval_that_narrows_as_it_grows() {
        let (units, half) = scaled(&[10, 30, 20, 20], 100);
        assert_eq!(units, 2000);
        // sd 8.165, t(3) 3.182, sqrt(1 - 4/100) 0.9798: 100 * 3.182 * 8.165 / 2 * 0.9798
        assert_eq!(half, 1273);
        let (_, wider) = scaled(&[10, 30, 20, 20], 1000);
        assert!(wider > 10 * half, "{wider}");
        assert_eq!(scaled(&[7, 7, 7], 30), (210, 0));
    }

    #[test]
    fn a_bound_to_raise_to_is_rounded_up_and_written_as_the_language_reads_it() {
        let table = [
            (1, 1, "1"),
            (99, 99, "99"),
            (101, 110, "110"),
            (968_920_123, 970_000_000, "9.7e8"),
            (1_000_000_000, 1_000_000_000, "1e9"),
            (1_210_000_001, 1_300_000_000, "1.3e9"),
        ];
        for (units, up, written) in table {
            assert_eq!(round_up(units), up, "{units}");
            assert_eq!(sci(up), written, "{up}");
        }
    }
}
