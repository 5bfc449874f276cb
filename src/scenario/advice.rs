//! Advice beside the standards: for each `advise` in a room a `standard`
//! checks, the standard's rule for the element (its reach rule, for the
//! approach the standard chose) checked with the element at each of the
//! advice's positions, and the positions where it holds set beside the
//! advised range.

use std::sync::Arc;

use nalgebra::Vector3;
use rayon::prelude::*;

use super::{Scenario, TaskSpec};
use crate::meter::{Meter, RunWork};
use crate::plugin::TaskInput;
use crate::progress::Progress;
use crate::report::{
    axis_index, rows_of, AdviceFrame, AdviceReport, AdviceStandard, PositionAnswer, TaskReport,
};

impl Scenario {
    /// The advice of population task `task`, whose people (in draw order)
    /// answered `answers`, line by line where it is a grid; with the work
    /// asking why took ([`Scenario::population_advice`]); none where no
    /// one's answer is an advice.
    pub(super) fn population_advice_of(
        &self,
        task: &TaskSpec,
        answers: &[TaskReport],
        progress: &dyn Progress,
        run: &Arc<RunWork>,
    ) -> Option<(AdviceReport, u64)> {
        let population = &self.populations[task.population.expect("a population task")];
        let Some(lines) = rows_of(answers) else {
            let (frame, members) = AdviceReport::members(population, answers)?;
            return Some(self.population_advice(task, (&frame, members), 0, progress, run));
        };
        let mut rows = Vec::new();
        let mut spent = 0;
        for (row, line) in lines.iter().enumerate() {
            let (frame, members) = AdviceReport::members(population, line)?;
            let first = row * frame.positions_mm.len();
            let (advice, work) =
                self.population_advice(task, (&frame, members), first, progress, run);
            rows.push(advice);
            spent += work;
        }
        Some((AdviceReport::grid(rows), spent))
    }

    /// The advice of population task `task` on one line of positions (the
    /// first of which is the task's position `first_position`), whose people
    /// answered `members` in `frame`: the served ranges, and why each
    /// person who drops out at a range's end does not reach it there
    /// (asked now, of them alone: [`crate::plugin::Task::explain`]); with
    /// the work that asking took, told to `run`.
    fn population_advice(
        &self,
        task: &TaskSpec,
        (frame, mut members): (&AdviceFrame, Vec<(String, Vec<PositionAnswer>)>),
        first_position: usize,
        progress: &dyn Progress,
        run: &Arc<RunWork>,
    ) -> (AdviceReport, u64) {
        let population = &self.populations[task.population.expect("a population task")];
        let unexplained = AdviceReport::population(frame, &population.name, &members);
        let asked = unexplained.dropped(&members);
        let people: Vec<usize> = population.members.clone().collect();
        let found: Vec<(Option<String>, u64)> = (asked.par_iter())
            .map(|&(m, at)| {
                let meter = Meter::of(run);
                let spec = TaskSpec {
                    person: people[m],
                    population: None,
                    ..task.clone()
                };
                let input = TaskInput {
                    verdict_only: true,
                    allowance: &meter,
                    ..self.input(&spec, progress)
                };
                let why = task.task.explain(&input, first_position + at);
                (why, meter.spent())
            })
            .collect();
        let mut spent = 0;
        for (&(m, at), (why, work)) in asked.iter().zip(found) {
            members[m].1[at].verdict = why;
            spent += work;
        }
        (
            AdviceReport::population(frame, &population.name, &members),
            spent,
        )
    }

    /// Each advice of `tasks` (the tasks' answers, in the order of the
    /// file) given each standard on its room, its work told to `run`.
    pub(super) fn advise_beside_standards(&self, tasks: &mut [TaskReport], run: &Arc<RunWork>) {
        for (spec, task) in self.tasks.iter().zip(tasks.iter_mut()) {
            let TaskReport::Advice(advice) = task else {
                continue;
            };
            let beside = |line: &AdviceReport| -> Vec<AdviceStandard> {
                (self.standards.iter())
                    .filter(|s| s.room == spec.room)
                    .filter_map(|s| self.standard_beside(s, spec.room, line, run))
                    .collect()
            };
            if advice.rows.is_empty() {
                advice.standards = beside(advice);
                continue;
            }
            let mut rows = std::mem::take(&mut advice.rows);
            for row in &mut rows {
                row.standards = beside(row);
            }
            **advice = AdviceReport::grid(rows);
        }
    }

    /// Standard `spec`'s rule for the advice's element at each position,
    /// and where it holds: none where the standard does not take the
    /// target for an element (`except`).
    fn standard_beside(
        &self,
        spec: &super::StandardSpec,
        room: usize,
        advice: &AdviceReport,
        run: &Arc<RunWork>,
    ) -> Option<AdviceStandard> {
        if spec.except.contains(&advice.name) {
            return None;
        }
        let room = &self.rooms[room];
        let along = axis_index(advice.along)?;
        let mut across_mm = Vector3::zeros();
        if let Some(across) = &advice.across {
            let k = axis_index(across.axis)?;
            across_mm[k] = across.at_mm - advice.target_mm[k];
        }
        let mut names: Vec<&str> = vec![advice.name.as_str()];
        names.extend(advice.carries.iter().map(String::as_str));
        let rules: Vec<Option<(String, String, bool)>> = (advice.points.par_iter())
            .map(|point| {
                let mut by_mm = across_mm;
                by_mm[along] = point.at_mm - advice.declared_mm;
                let moved = room.moved(&names, by_mm);
                let meter = Meter::of(run);
                let report = spec.standard.check(&spec.room_of_elements(&moved), &meter);
                let element = report
                    .elements
                    .into_iter()
                    .find(|e| e.name == advice.name)?;
                let rule = element.rules.into_iter().next()?;
                Some((rule.section, rule.rule, rule.ok))
            })
            .collect();
        Some(AdviceStandard::new(&spec.name, advice, &rules))
    }
}
