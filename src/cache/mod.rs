//! Task results kept between evaluations (watch mode), each under a key
//! made of the values its answer depends on (`key.rs`): the task's kind,
//! options and effectors, its subject, the person (body, base, vision),
//! the room's size, the placements its base may try for each point, and
//! the obstacles within reach of one of those placements (`reach.rs`).
//! Spans are not part of the key, so editing one line leaves the other
//! tasks' results in place, and an obstacle moved out of a task's reach
//! leaves that task's result in place too. A task that records which
//! obstacles its questions came near keeps its result, too, while the
//! obstacles it touched stay as they were and the others move only a
//! little (`touched.rs`): a shelf raised by a millimetre re-runs only the
//! tasks whose arms came near it. A task run again keeps, one by one, the
//! solves of its last run that the change did not touch
//! (`engine::KeptSolves`). The results of the last few runs are kept by
//! their full key too, so that an edit undone (a shelf tried higher, then
//! put back) takes the answers from before it.

mod key;
mod reach;
mod touched;

use std::collections::{HashMap, VecDeque};
use std::sync::Arc;

use crate::engine::Earlier;
use crate::error::Error;
use crate::kept::Memo;
use crate::progress::Progress;
use crate::report::{Report, TaskReport};
use crate::scenario::{Scenario, TaskSpec};

/// Results of earlier runs, by key.
#[derive(Default)]
pub struct TaskCache {
    /// The last run's results.
    last: Generation,
    /// The results of the runs before the last, newest first (at most
    /// [`GENERATIONS`]).
    older: VecDeque<Generation>,
    /// The placements each task's base may try, kept while the room and
    /// the person stay as they are.
    placements: key::Placements,
    /// Those of the runs before the last, newest first (at most
    /// [`GENERATIONS`]): an edit undone finds them again.
    older_placements: VecDeque<key::Placements>,
    /// What the runs work out and keep (floors, routes, capability maps),
    /// kept across the session's runs.
    memo: Arc<Memo>,
}

/// The results of one run.
#[derive(Default)]
struct Generation {
    /// Results by their full key; those whose run ranked the room's
    /// obstacles by distance (finding why), which may name an obstacle
    /// beyond the reach the key holds, by their full key and all of the
    /// room's obstacles (`TaskKey::whole`).
    results: HashMap<u64, (TaskReport, u64)>,
    /// Results by the key of all but the obstacles, with what their
    /// questions touched and their solves.
    kept: HashMap<u64, Arc<touched::Kept>>,
}

/// A result kept, and its entry by the key of all but the obstacles (of
/// the run that found it).
type Held = ((TaskReport, u64), Option<Arc<touched::Kept>>);

/// How many runs before the last keep their results by full key: an edit
/// undone after up to this many saves takes its answers from before it.
const GENERATIONS: usize = 3;

/// Which tasks of a scenario keep an earlier answer ([`TaskCache::plan`]),
/// to be finished by [`TaskCache::finish`].
pub struct Plan {
    keys: Vec<key::TaskKey>,
    /// Each room's obstacles, as the keys of what a task touched see them.
    seen: Vec<Vec<touched::Seen>>,
    /// Each task's key with all of its room's obstacles.
    whole: Vec<u64>,
    /// Each task's answer kept from an earlier run, if any.
    held: Vec<Option<Held>>,
}

impl Plan {
    /// The tasks that must run, by their position in the scenario.
    pub fn to_run(&self) -> Vec<usize> {
        (0..self.held.len())
            .filter(|&i| self.held[i].is_none())
            .collect()
    }

    /// The report to show while the tasks that must run are running: the
    /// answers kept, and each other task (and every standard, which looks
    /// at the tasks' answers) marked as being evaluated; `None` where
    /// every task keeps its answer, or none does.
    pub fn first_report(&self, scenario: &Scenario) -> Option<Report> {
        let kept = self.held.iter().filter(|h| h.is_some()).count();
        if kept == 0 || kept == self.held.len() {
            return None;
        }
        let tasks = (scenario.tasks.iter().zip(&self.held))
            .map(|(task, held)| match held {
                Some(((answer, _), _)) => answer.clone(),
                None => scenario.evaluating(task),
            })
            .collect();
        Some(scenario.report_evaluating(tasks))
    }
}

/// How many tasks a cached run reused and how many it ran, and the work
/// of all of them (the solver work a fresh run would count).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CacheStats {
    pub reused: usize,
    pub ran: usize,
    pub work: u64,
    /// The tasks run (not reused), by their position in the scenario.
    pub ran_tasks: Vec<usize>,
}

impl TaskCache {
    /// What its runs keep (floors, routes, capability maps): through it,
    /// a run in flight is cancelled ([`Memo::cancel`]).
    pub fn memo(&self) -> Arc<Memo> {
        Arc::clone(&self.memo)
    }

    /// Run the scenario, reusing the results of tasks whose inputs have not
    /// changed; afterwards the cache holds this run's results, and by full
    /// key those of the `GENERATIONS` runs before it. The
    /// work of the results reused counts against the scenario's bound as
    /// if they had run: an error where a fresh run would stop too.
    pub fn run(
        &mut self,
        scenario: &Scenario,
        progress: &dyn Progress,
    ) -> Result<(Report, CacheStats), Error> {
        let plan = self.plan(scenario);
        self.finish(plan, scenario, progress)
    }

    /// Which of the scenario's tasks keep an answer of an earlier run
    /// and which must run: the first half of [`TaskCache::run`], quick
    /// (its keys and look-ups), so that watch mode can show the answers
    /// kept before the rest are found.
    pub fn plan(&mut self, scenario: &Scenario) -> Plan {
        let mut known = self.placements.clone();
        for older in &self.older_placements {
            for (k, tried) in older {
                known.entry(*k).or_insert_with(|| Arc::clone(tried));
            }
        }
        let mut keys = key::keys(scenario, &mut known, &self.memo);
        // A task's work holds its person's floor where it is the first to
        // place them (`Scenario::first_charges`): so does its key.
        for (k, charges) in keys.iter_mut().zip(scenario.first_charges()) {
            k.charged(charges);
        }
        let previous = std::mem::replace(&mut self.placements, known);
        self.older_placements.push_front(previous);
        self.older_placements.truncate(GENERATIONS);
        let seen: Vec<Vec<touched::Seen>> = scenario.rooms.iter().map(touched::seen).collect();
        let rooms: Vec<u64> = seen.iter().map(|s| touched::hash_seen(s)).collect();
        let whole: Vec<u64> = (scenario.tasks.iter().zip(&keys))
            .map(|(task, k)| k.whole(rooms[task.room]))
            .collect();
        let held: Vec<Option<Held>> = (scenario.tasks.iter().zip(&keys).zip(&whole))
            .map(|((task, k), &whole)| self.held(k, whole, &seen[task.room]))
            .collect();
        Plan {
            keys,
            seen,
            whole,
            held,
        }
    }

    /// Run the tasks `plan` found no answer for, and report every task:
    /// the second half of [`TaskCache::run`].
    pub fn finish(
        &mut self,
        plan: Plan,
        scenario: &Scenario,
        progress: &dyn Progress,
    ) -> Result<(Report, CacheStats), Error> {
        let ran_tasks = plan.to_run();
        let Plan {
            keys,
            seen,
            whole,
            held,
        } = plan;
        let stale: Vec<(&TaskSpec, &key::TaskKey)> = (scenario.tasks.iter().zip(&keys).zip(&held))
            .filter(|(_, h)| h.is_none())
            .map(|(task_key, _)| task_key)
            .collect();
        let earlier: Vec<Option<Earlier>> = stale
            .iter()
            .map(|(task, k)| self.earlier(k, &seen[task.room]))
            .collect();
        let stale: Vec<&TaskSpec> = stale.into_iter().map(|(task, _)| task).collect();
        let reused_work = held.iter().flatten().map(|((_, w), _)| *w).sum();
        let mut ran_now = scenario
            .run_tasks_recording(&stale, progress, reused_work, &earlier, &self.memo)?
            .into_iter();
        let mut kept = HashMap::new();
        let mut results = HashMap::new();
        let mut tasks = Vec::with_capacity(keys.len());
        let mut work = 0;
        for (((task, k), held), &whole) in scenario.tasks.iter().zip(&keys).zip(held).zip(&whole) {
            let (answer, by_strict_key) = match held {
                Some((answer, entry)) => {
                    let ranked = entry.as_ref().is_some_and(|e| e.ranked());
                    if let (Some(l), Some(entry)) = (k.loose, entry) {
                        kept.insert(l, entry);
                    }
                    (answer, !ranked)
                }
                None => {
                    let ran = ran_now.next().expect("an answer per task run");
                    let answer = (ran.report, ran.work);
                    let ranked = ran.touched.as_ref().is_some_and(|s| s.ranked());
                    if let (Some(l), Some(set)) = (k.loose, ran.touched) {
                        let room = seen[task.room].clone();
                        let solves = Arc::new(ran.solves.unwrap_or_default());
                        let entry = touched::Kept::new(answer.clone(), set, room, k.points, solves);
                        kept.insert(l, Arc::new(entry));
                    }
                    (answer, !ranked)
                }
            };
            let key = if by_strict_key { k.strict } else { whole };
            results.insert(key, answer.clone());
            work += answer.1;
            tasks.push(answer.0);
        }
        let ran = stale.len();
        self.keep_last(Generation { results, kept });
        let (report, standards) = scenario.report(tasks, work, &self.memo)?;
        let stats = CacheStats {
            reused: keys.len() - ran,
            ran,
            work: work + standards,
            ran_tasks,
        };
        Ok((report, stats))
    }

    /// `next` kept as the last run's results, the last before it kept as
    /// an older run's: its entries without their solves, but for those
    /// `next` took over.
    fn keep_last(&mut self, next: Generation) {
        let mut last = std::mem::replace(&mut self.last, next);
        for entry in last.kept.values_mut() {
            if let Some(entry) = Arc::get_mut(entry) {
                entry.drop_solves();
            }
        }
        if !last.results.is_empty() || !last.kept.is_empty() {
            self.older.push_front(last);
            self.older.truncate(GENERATIONS);
        }
    }

    /// The solves kept from the last run of a task of keys `k` (its key of
    /// all but the obstacles the same) that its run in a room whose
    /// obstacles are `seen` may take (`engine::KeptSolves`).
    fn earlier(&self, k: &key::TaskKey, seen: &[touched::Seen]) -> Option<Earlier> {
        self.last.kept.get(&k.loose?)?.earlier(seen)
    }

    /// The result kept for a task of keys `k` in a room whose obstacles
    /// are `seen`, and its work, with its entry by the key of all but the
    /// obstacles: under its full key (or that and the whole room's
    /// obstacles, `whole`) in the last run or one before it (with that
    /// run's entry), or under the key of all but the obstacles where those
    /// it touched are as they were.
    fn held(&self, k: &key::TaskKey, whole: u64, seen: &[touched::Seen]) -> Option<Held> {
        for generation in std::iter::once(&self.last).chain(&self.older) {
            let found =
                (generation.results.get(&k.strict)).or_else(|| generation.results.get(&whole));
            if let Some(answer) = found {
                let entry = k.loose.and_then(|l| generation.kept.get(&l).cloned());
                return Some((answer.clone(), entry));
            }
        }
        let kept = self.last.kept.get(&k.loose?)?;
        let answer = || (kept.report.clone(), kept.work);
        kept.holds(seen).then(|| (answer(), Some(Arc::clone(kept))))
    }
}
