//! The bound on total work: how many solver starts the tasks may need,
//! counted at their worst (every point of a map, every placement of the
//! base, every start of the solver, every retry where obstacles block),
//! against [`Limits::solver_starts`](crate::limits::Limits). A scenario
//! beyond it is refused before it runs, at the task declaration that asks
//! the most. What a reach does only once its search has failed (walking a
//! blocked target in, `tasks/walk_in.rs`; searching for why, `tasks/why.rs`)
//! is not counted here: the bound on solver work, counted as the solvers
//! work (`crate::meter`), bounds it. The points the tasks answer, whose
//! answers the report and its files hold in memory, are bounded too
//! ([`Limits::map_points`](crate::limits::Limits)).

use std::collections::HashMap;
use std::sync::Arc;

use super::Checker;
use crate::error::{thousands, Error, ErrorKind};
use crate::plugin::Base;
use crate::scenario::TaskSpec;
use crate::scene::{Person, Population, Room};
use crate::span::{FileId, Span};

impl Checker<'_> {
    /// Refuse the tasks if together they may need more solver starts than
    /// the limit; the task declaration that may ask the most (where a run
    /// past the limit on solver work is reported), if any.
    pub(super) fn check_budget(
        &mut self,
        tasks: &[TaskSpec],
        rooms: &[Room],
        bases: &[Arc<dyn Base>],
        populations: &[Population],
        persons: &[Person],
    ) -> Option<Span> {
        let by_decl = by_declaration(tasks, |task| {
            let people = task.population.map_or(1, |p| populations[p].len() as u64);
            let body = &persons[task.person].body;
            let searches = task.task.searches(body, &task.effectors);
            (task_starts(task, rooms, bases).saturating_mul(searches)).saturating_mul(people)
        });
        self.check_points(tasks, rooms);
        let total = by_decl
            .iter()
            .fold(0u64, |sum, (_, s)| sum.saturating_add(*s));
        // The first of those that ask the most.
        let &(span, decl_starts) = by_decl.iter().rev().max_by_key(|(_, s)| *s)?;
        if total <= self.cx.limits.solver_starts {
            return Some(span);
        }
        self.error(Error::new(
            ErrorKind::TooManyStarts {
                total,
                limit: self.cx.limits.solver_starts,
                decl_starts,
            },
            span,
        ));
        Some(span)
    }
}

impl Checker<'_> {
    /// Refuse the tasks if together they answer more points than the
    /// limit, at the declaration that asks the most.
    fn check_points(&mut self, tasks: &[TaskSpec], rooms: &[Room]) {
        let by_decl = by_declaration(tasks, |task| {
            task.task.points(&task.subject_in(&rooms[task.room]))
        });
        let total = by_decl
            .iter()
            .fold(0u64, |sum, (_, n)| sum.saturating_add(*n));
        let limit = self.cx.limits.map_points;
        let Some(&(span, _)) = by_decl.iter().rev().max_by_key(|(_, n)| *n) else {
            return;
        };
        if total > limit {
            self.error(Error::new(
                ErrorKind::TooLarge {
                    what: format!(
                        "the points these tasks answer ({} in all, each map's once for each person)",
                        thousands(total)
                    ),
                    limit: format!("{} points (--max-map-points)", thousands(limit)),
                },
                span,
            ));
        }
    }
}

/// `count` of each task summed by the declaration it comes from (one
/// declaration gives a task per subject and person), in the order the
/// declarations come.
fn by_declaration(tasks: &[TaskSpec], count: impl Fn(&TaskSpec) -> u64) -> Vec<(Span, u64)> {
    let mut by_decl: Vec<(Span, u64)> = Vec::new();
    let mut index: HashMap<(FileId, u32), usize> = HashMap::new();
    for task in tasks {
        let n = count(task);
        let key = (task.span.file, task.span.start);
        match index.get(&key) {
            Some(&i) => by_decl[i].1 = by_decl[i].1.saturating_add(n),
            None => {
                index.insert(key, by_decl.len());
                by_decl.push((task.span, n));
            }
        }
    }
    by_decl
}

/// The most solver starts `task` may need.
fn task_starts(task: &TaskSpec, rooms: &[Room], bases: &[Arc<dyn Base>]) -> u64 {
    let placements = bases[task.person].placements();
    let subject = task.subject_in(&rooms[task.room]);
    task.task
        .points(&subject)
        .saturating_mul(task.task.starts_per_point(placements))
}
