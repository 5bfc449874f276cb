//! A run split across machines: shard K of N (`reach run --shard K/N`)
//! runs the K-th of N equal ranges of each population's people, for every
//! task by that population, and keeps of each person what the population's
//! report needs ([`MemberOutcome`]); the merge (`reach merge`) runs the
//! rest (each task by one person, the standards) and puts the shards'
//! people back in draw order, so that its report is the one a single run
//! writes, byte for byte. A person's answer does not depend on who else
//! is run beside them (shared work is shared exactly: `floor::group`).

use std::ops::Range;
use std::sync::Arc;

use rayon::prelude::*;

use super::{Scenario, TaskSpec};
use crate::error::{Error, ErrorKind};
use crate::kept::Memo;
use crate::meter::RunWork;
use crate::progress::Progress;
use crate::report::{MapFrame, MemberOutcome, PopulationReport, Report, TaskReport};

/// Which shard of how many: `K/N`, K from 1.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ShardOf {
    pub index: usize,
    pub count: usize,
}

impl ShardOf {
    /// `K/N` with 1 <= K <= N, else why not.
    pub fn parse(text: &str) -> Result<Self, String> {
        let (k, n) = text
            .split_once('/')
            .ok_or_else(|| format!("`{text}` is not K/N (as 3/10: the third of ten shards)"))?;
        let number = |s: &str| {
            s.trim()
                .parse::<usize>()
                .map_err(|_| format!("`{s}` is not a whole number"))
        };
        let (index, count) = (number(k)?, number(n)?);
        if count == 0 || index == 0 || index > count {
            return Err(format!("shard {index} of {count}: K must be from 1 to N"));
        }
        Ok(ShardOf { index, count })
    }

    /// Which of the `count` shards of a run are not given (`given` says
    /// whether shard K is), in words: `shard 3/4 is not given`, `shards
    /// 1/4, 3/4 are not given`; none where every one is.
    pub fn missing(count: usize, given: impl Fn(usize) -> bool) -> Option<String> {
        let missing: Vec<String> = (1..=count)
            .filter(|&k| !given(k))
            .map(|index| ShardOf { index, count }.to_string())
            .collect();
        match missing.len() {
            0 => None,
            1 => Some(format!("shard {} is not given", missing[0])),
            _ => Some(format!("shards {} are not given", missing.join(", "))),
        }
    }

    /// Its people of a population of `people`: the K-th of N ranges as
    /// equal as can be, in draw order (0 for the first).
    pub fn people(&self, people: usize) -> Range<usize> {
        let at = |k: usize| k * people / self.count;
        at(self.index - 1)..at(self.index)
    }
}

impl std::fmt::Display for ShardOf {
    /// `K/N`.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}/{}", self.index, self.count)
    }
}

/// Which of each population's people a check builds as persons: everyone
/// (a whole run), a shard's (`reach run --shard`), or only the first (the
/// merge, which runs none of them); at least the first where the range is
/// empty, so that a task by the population is checked against a body.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum PeopleBuilt {
    #[default]
    Everyone,
    Shard(ShardOf),
    First,
}

impl PeopleBuilt {
    /// Those built of a population of `people`, by their index in the
    /// draw.
    pub fn range(self, people: usize) -> Range<usize> {
        let range = match self {
            PeopleBuilt::Everyone => 0..people,
            PeopleBuilt::Shard(shard) => shard.people(people),
            PeopleBuilt::First => 0..0,
        };
        if range.is_empty() {
            0..people.min(1)
        } else {
            range
        }
    }
}

/// What one shard found of one task by a population: how each of its
/// people ended, and the frame of the first map among them.
#[derive(Clone, Debug, PartialEq)]
pub struct ShardPart {
    /// The task's position in the scenario.
    pub task: usize,
    /// The shard's people of the population, in draw order (0 for the
    /// first).
    pub people: Range<usize>,
    pub outcomes: Vec<MemberOutcome>,
    pub frame: Option<MapFrame>,
}

impl Scenario {
    /// Shard `shard`'s part of a run: for each task by a population, in
    /// the order of the file, its people of that range, run as a whole run
    /// runs them (in parallel, each person's tasks one after another). An
    /// error where the solvers needed more work than the scenario's bound.
    pub fn run_shard(
        &self,
        shard: ShardOf,
        progress: &dyn Progress,
        memo: &Arc<Memo>,
    ) -> Result<Vec<ShardPart>, Error> {
        if let Some(advice) = self
            .tasks
            .iter()
            .find(|t| t.kind == "advise" && t.population.is_some())
        {
            return Err(Error::new(
                ErrorKind::Unsupported {
                    what: "a run split into shards with an `advise` task by a population".to_string(),
                    help: "run it whole: a shard keeps whether each person reaches, not why at each position an advice's range ends".to_string(),
                },
                advice.span,
            ));
        }
        let run = RunWork::keeping(self.work.limit, Arc::clone(memo));
        let charges = self.floor_charges();
        let by_population = |p: usize| -> Vec<(usize, &TaskSpec)> {
            (self.tasks.iter().enumerate())
                .filter(|(_, t)| t.population == Some(p))
                .collect()
        };
        let mut parts = Vec::new();
        for (p, population) in self.populations.iter().enumerate() {
            let tasks = by_population(p);
            let range = shard.people(population.len());
            let built: Option<Vec<usize>> =
                range.clone().map(|i| population.person_of(i)).collect();
            let Some(members) = built else {
                return Err(not_built(shard, &population.name));
            };
            let answers: Vec<Vec<TaskReport>> = members
                .into_par_iter()
                .map(|person| {
                    let own = tasks.iter().map(|(_, task)| *task);
                    (self
                        .run_member_tasks(own, person, progress, &run, &charges)
                        .into_iter())
                    .map(|(answer, _)| answer)
                    .collect()
                })
                .collect();
            if run.exceeded() {
                return Err(self.work.exceeded());
            }
            for (j, (k, _)) in tasks.iter().enumerate() {
                let reports: Vec<&TaskReport> = answers.iter().map(|each| &each[j]).collect();
                parts.push(ShardPart {
                    task: *k,
                    people: range.clone(),
                    outcomes: reports.iter().map(|r| MemberOutcome::of(r)).collect(),
                    frame: reports.iter().find_map(|r| r.map()).map(MapFrame::of),
                });
            }
        }
        parts.sort_by_key(|part| part.task);
        Ok(parts)
    }

    /// The report of a run whose tasks by populations were run by shards
    /// (`parts`, every shard's, checked whole by the caller): each task by
    /// one person run here, in parallel, then the standards, as a whole
    /// run; with the work done here.
    pub fn run_merged(
        &self,
        parts: &[ShardPart],
        progress: &dyn Progress,
        memo: &Arc<Memo>,
    ) -> Result<(Report, u64), Error> {
        let alone: Vec<&TaskSpec> = self
            .tasks
            .iter()
            .filter(|t| t.population.is_none())
            .collect();
        let ran = self.run_tasks(&alone, progress, memo)?;
        let work: u64 = ran.iter().map(|r| r.work).sum();
        let mut ran = ran.into_iter();
        let tasks = (self.tasks.iter().enumerate())
            .map(|(k, task)| match task.population {
                None => ran.next().expect("an answer per task by a person").report,
                Some(p) => {
                    let mine: Vec<&ShardPart> =
                        parts.iter().filter(|part| part.task == k).collect();
                    let outcomes: Vec<MemberOutcome> = mine
                        .iter()
                        .flat_map(|part| part.outcomes.iter().cloned())
                        .collect();
                    let frame = mine.iter().find_map(|part| part.frame.as_ref());
                    let name = task.subject_name(self);
                    let population = &self.populations[p];
                    let report = PopulationReport::of_outcomes(name, population, &outcomes, frame);
                    TaskReport::Population(Box::new(report))
                }
            })
            .collect();
        let (report, standards) = self.report(tasks, work, memo)?;
        Ok((report, work + standards))
    }
}

/// The error of a shard run on a scenario whose check did not build that
/// shard's people of `population` (`Session::building`).
fn not_built(shard: ShardOf, population: &str) -> Error {
    Error::unplaced(ErrorKind::Unsupported {
        what: format!("shard {shard} of population `{population}`, whose people this scenario's check did not build"),
        help: "check the scenario with this shard's people built (`Session::building` with `PeopleBuilt::Shard`)".to_string(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shards_cover_every_person_once_in_order() {
        for people in [0, 1, 7, 100, 1001] {
            for count in 1..=12 {
                let mut next = 0;
                for index in 1..=count {
                    let range = ShardOf { index, count }.people(people);
                    assert_eq!(range.start, next, "{people} people, {index}/{count}");
                    assert!(range.len() <= people / count + 1);
                    next = range.end;
                }
                assert_eq!(next, people);
            }
        }
    }

    #[test]
    fn the_shards_not_given_are_named() {
        assert_eq!(
            ShardOf::missing(3, |k| k != 2),
            Some("shard 2/3 is not given".into())
        );
        assert_eq!(
            ShardOf::missing(4, |k| k == 2),
            Some("shards 1/4, 3/4, 4/4 are not given".into())
        );
        assert_eq!(ShardOf::missing(2, |_| true), None);
    }

    #[test]
    fn a_shard_is_written_k_of_n() {
        assert_eq!(
            ShardOf::parse("3/10"),
            Ok(ShardOf {
                index: 3,
                count: 10
            })
        );
        for bad in ["0/3", "4/3", "1/0", "3", "a/3", "1/-2"] {
            assert!(ShardOf::parse(bad).is_err(), "{bad}");
        }
    }
}
