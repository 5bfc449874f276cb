//! The bound on total work: how many solver starts the tasks may need,
//! counted at their worst (every point of a map, every placement of the
//! base, every start of the solver, every retry where obstacles block),
//! against [`Limits::solver_starts`](crate::limits::Limits). A scenario
//! beyond it is refused before it runs, at the task declaration that asks
//! the most.

use super::Checker;
use crate::error::{Error, ErrorKind};
use crate::plugin::{Options, Value};
use crate::scene::{Person, Room, TaskSpec};
use crate::span::Span;

impl Checker<'_> {
    /// Refuse the tasks if together they may need more solver starts than
    /// the limit.
    pub(super) fn check_budget(&mut self, tasks: &[TaskSpec], rooms: &[Room], persons: &[Person]) {
        // Per declaration (one declaration gives a task per subject and person).
        let mut by_decl: Vec<(Span, u64)> = Vec::new();
        for task in tasks {
            let starts = self.task_starts(task, rooms, persons);
            let same = |span: &Span| (span.file, span.start) == (task.span.file, task.span.start);
            match by_decl.iter_mut().find(|(span, _)| same(span)) {
                Some((_, sum)) => *sum = sum.saturating_add(starts),
                None => by_decl.push((task.span, starts)),
            }
        }
        let total = by_decl
            .iter()
            .fold(0u64, |sum, (_, s)| sum.saturating_add(*s));
        if total <= self.limits.solver_starts {
            return;
        }
        let Some(&(span, decl_starts)) = by_decl.iter().max_by_key(|(_, s)| *s) else {
            return;
        };
        self.error(Error::new(
            ErrorKind::TooManyStarts {
                total,
                limit: self.limits.solver_starts,
                decl_starts,
            },
            span,
        ));
    }

    /// The most solver starts `task` may need.
    fn task_starts(&self, task: &TaskSpec, rooms: &[Room], persons: &[Person]) -> u64 {
        let (Some(plugin), Some(room), Some(person)) = (
            self.registry.task(&task.kind),
            rooms.iter().find(|r| r.holds(&task.subject)),
            persons.iter().find(|p| p.name == task.person),
        ) else {
            return 0;
        };
        let placements = self
            .registry
            .base(&person.base.name)
            .map_or(1, |b| b.build(&person.base.options).placements());
        let points = plugin.points(room, &task.subject, &task.options);
        let per_placement = self.starts_of(&task.options, "solver");
        let retries = match (
            task.options.get("blocked_retries"),
            task.options.get("collisions"),
        ) {
            (Some(Value::Integer(n)), Some(Value::Bool(true))) => (*n as u64).min(placements),
            _ => 0,
        };
        let per_point = placements.saturating_mul(per_placement).saturating_add(
            retries.saturating_mul(self.starts_of(&task.options, "blocked_solver")),
        );
        points.saturating_mul(per_point)
    }

    /// The starts of the solver that option `option` names (1 without one).
    fn starts_of(&self, options: &Options, option: &str) -> u64 {
        match options.get(option) {
            Some(Value::Plugin(config)) => self
                .registry
                .solver(&config.name)
                .map_or(1, |s| s.starts(&config.options)),
            _ => 1,
        }
    }
}
