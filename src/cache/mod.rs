//! Task results kept between evaluations (watch mode), each under a key
//! made of the values its answer depends on (`key.rs`): the task's kind,
//! options and effectors, its subject, the person (body, base, vision),
//! the room's size, the placements its base may try for each point, and
//! the obstacles within reach of one of those placements (`reach.rs`).
//! Spans are not part of the key, so editing one line leaves the other
//! tasks' results in place, and an obstacle moved out of a task's reach
//! leaves that task's result in place too.

mod key;
mod reach;

use std::collections::HashMap;

use crate::progress::Progress;
use crate::report::{Report, TaskReport, SCHEMA_VERSION};
use crate::scenario::{Scenario, TaskSpec};

/// Results of earlier runs, by key.
#[derive(Default)]
pub struct TaskCache {
    results: HashMap<u64, TaskReport>,
    /// The placements each task's base may try, kept while the room and
    /// the person stay as they are.
    placements: key::Placements,
}

/// How many tasks a cached run reused and how many it ran.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct CacheStats {
    pub reused: usize,
    pub ran: usize,
}

impl TaskCache {
    /// Run the scenario, reusing the results of tasks whose inputs have not
    /// changed; afterwards the cache holds exactly this run's results.
    pub fn run(&mut self, scenario: &Scenario, progress: &dyn Progress) -> (Report, CacheStats) {
        let keys = key::keys(scenario, &mut self.placements);
        let stale: Vec<&TaskSpec> = scenario
            .tasks
            .iter()
            .zip(&keys)
            .filter(|(_, k)| !self.results.contains_key(k))
            .map(|(task, _)| task)
            .collect();
        let mut ran_now = scenario.run_tasks(&stale, progress).into_iter();
        let fresh: Vec<Option<TaskReport>> = keys
            .iter()
            .map(|k| {
                if self.results.contains_key(k) {
                    None
                } else {
                    ran_now.next()
                }
            })
            .collect();
        let ran = fresh.iter().filter(|r| r.is_some()).count();
        let tasks: Vec<TaskReport> = fresh
            .into_iter()
            .zip(&keys)
            .map(|(r, k)| r.unwrap_or_else(|| self.results[k].clone()))
            .collect();
        self.results = keys.iter().copied().zip(tasks.iter().cloned()).collect();
        // Standards are checked again every time: they read the whole room.
        let all: Vec<&TaskSpec> = scenario.tasks.iter().collect();
        let mut tasks = tasks;
        let standards = scenario.run_standards(&all, &tasks);
        tasks.extend(standards);
        let report = Report {
            schema: SCHEMA_VERSION,
            file: scenario.file.clone(),
            notes: scenario.notes(),
            expectations: scenario.judge(&tasks),
            tasks,
        };
        (
            report,
            CacheStats {
                reused: keys.len() - ran,
                ran,
            },
        )
    }
}
