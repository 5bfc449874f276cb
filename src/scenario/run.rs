//! Running a scenario's tasks: each task for its person, or, for a task by
//! a population, for each of its people, whose answers are summed up as
//! the share accommodated. Everything runs in one parallel loop over jobs,
//! and the answers come back in the order the tasks were given, whatever
//! the number of threads.

use std::collections::{BTreeMap, HashMap, HashSet};
use std::sync::Arc;

use rayon::prelude::*;

use super::{Scenario, StandardSpec, TaskSpec};
use crate::collision::{Touched, TouchedSet};
use crate::engine::{Earlier, KeptSolves, SolveMap};
use crate::error::Error;
use crate::kept::Memo;
use crate::meter::{Meter, RunWork};
use crate::plugin::{Fit, TaskInput};
use crate::progress::Progress;
use crate::report::{
    AdvisedTogether, NotEvaluatedReport, NotPlacedReport, PersonAnswer, PopulationReport, Report,
    TaskReport, SCHEMA_VERSION,
};

/// One task's answer, what its questions touched of its room (where it
/// records that) and the work its solvers did.
pub struct Ran {
    pub report: TaskReport,
    pub touched: Option<TouchedSet>,
    pub work: u64,
    /// Its solves, kept for its next run (where it records its touches).
    pub solves: Option<SolveMap>,
}

/// Where the bound stopped a run of tasks ([`Scenario::run_tasks_partly`]):
/// the position of the first task not run, and the work that was left
/// for it (it alone needs more).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Stop {
    pub at: usize,
    pub left: u64,
}

/// A task kind as the text report names it (`reach`, `map`, ...).
fn task_label(kind: &str) -> &'static str {
    match kind {
        "reach_and_gaze" => "reach+gaze",
        "reach" => "reach",
        "gaze" => "gaze",
        "map" => "map",
        "gaze_map" => "gaze_map",
        "advise" => "advise",
        _ => "task",
    }
}

/// That a task's run records what it touched (watch mode), with the
/// solves of its last run that it may take.
#[derive(Clone, Copy)]
pub(super) struct Recording<'e> {
    earlier: Option<&'e Earlier>,
}

/// One piece of parallel work.
enum Job {
    /// The task at this position, for its person.
    Alone(usize),
    /// One person of a population, with every task by that population,
    /// one after another: what the person's base works out once (the
    /// capability map, the floor) is built by the thread that uses it, not
    /// waited for by another.
    Member { population: usize, person: usize },
}

/// Which tasks are charged their person's floor and their base's getting
/// ready ([`Scenario::floor_charges`]).
pub(super) struct FloorCharges {
    first: HashMap<usize, Charges>,
}

/// What a task is charged besides its own work.
#[derive(Clone, Copy)]
pub(super) struct Charges {
    /// Its person's floor in its room ([`Base::floor_work`]).
    floor: bool,
    /// Its base's getting ready for its effectors ([`Base::prepare_work`]).
    prepare: bool,
}

impl FloorCharges {
    /// What `task` is charged (a task not of the scenario: everything).
    pub(super) fn of(&self, task: &TaskSpec) -> Charges {
        let address = std::ptr::from_ref(task) as usize;
        (self.first.get(&address).copied()).unwrap_or(Charges {
            floor: true,
            prepare: true,
        })
    }
}

impl Scenario {
    /// Run `task`: its plugin's answer, or, where the person's base fits
    /// nowhere in the task's room, that answer (and nothing tried); for a
    /// task by a population, the share of its people it accommodates.
    /// An error where its solvers needed more work than the scenario's
    /// bound.
    pub fn run_task(&self, task: &TaskSpec, progress: &dyn Progress) -> Result<TaskReport, Error> {
        let mut ran = self.run_tasks(&[task], progress, &Arc::default())?;
        Ok(ran.pop().expect("one answer per task").report)
    }

    /// Run `tasks` in parallel, keeping what they work out in `memo`;
    /// their answers (and the work of each) in the order given, or an
    /// error where their solvers needed more work than the scenario's
    /// bound.
    pub fn run_tasks(
        &self,
        tasks: &[&TaskSpec],
        progress: &dyn Progress,
        memo: &Arc<Memo>,
    ) -> Result<Vec<Ran>, Error> {
        let run = RunWork::keeping(self.work.limit, Arc::clone(memo));
        self.run_jobs(tasks, progress, None, &run)
    }

    /// Run `tasks` in parallel within the scenario's bound: each task's
    /// answer, or where the bound stopped the run, none for the tasks it
    /// stopped (which those are depends on the threads), and whether it
    /// stopped.
    pub fn run_tasks_partly(
        &self,
        tasks: &[&TaskSpec],
        progress: &dyn Progress,
        memo: &Arc<Memo>,
    ) -> (Vec<Option<Ran>>, bool) {
        let run = RunWork::keeping(self.work.limit, Arc::clone(memo));
        let ran = self.run_jobs_partly(tasks, progress, None, &run);
        let stopped = run.exceeded() || ran.iter().any(Option::is_none);
        (ran, stopped)
    }

    /// Run `tasks` (in the order of the file) one at a time, each alone
    /// with what the bound has left, until one does not fit: the answers
    /// of the leading run of tasks whose work together fits within the
    /// bound, none for the rest, and where the bound stopped them, the
    /// position of the first not run with the work that was left for it.
    /// On a scenario nothing has run on yet, the same on every run and
    /// thread count: side by side, what a task is charged depends on which
    /// task worked out a value they share first (the floor of a room
    /// without an obstacle, for two tasks finding why); alone, in order
    /// from the start, it does not.
    pub fn run_tasks_in_order(
        &self,
        tasks: &[&TaskSpec],
        progress: &dyn Progress,
    ) -> (Vec<Option<Ran>>, Option<Stop>) {
        let memo = Arc::new(Memo::default());
        let mut ran: Vec<Option<Ran>> = (0..tasks.len()).map(|_| None).collect();
        let mut spent = 0u64;
        for k in 0..tasks.len() {
            let left = self.work.limit.saturating_sub(spent);
            let alone = RunWork::keeping(left, Arc::clone(&memo));
            let mut one = self.run_jobs_partly(&tasks[k..=k], progress, None, &alone);
            let Some(done) = one.pop().flatten().filter(|_| !alone.exceeded()) else {
                return (ran, Some(Stop { at: k, left }));
            };
            spent += done.work;
            ran[k] = Some(done);
        }
        (ran, None)
    }

    /// The error of a run of every task of the file that the bound
    /// stopped at `stop`.
    pub fn stopped_at(&self, stop: Stop) -> Error {
        let all = self.tasks.len() + self.standards.len();
        let Some(task) = self.tasks.get(stop.at) else {
            return self.stopped_at_standards(self.work.limit.saturating_sub(stop.left));
        };
        let first = self.not_evaluated(task).answer().label();
        self.work
            .stopped((Some(task.span), first), stop.at, all, stop.left)
    }

    /// The error of a run of every task of the file (`spent` units of
    /// work) that the bound stopped at its standards.
    pub fn stopped_at_standards(&self, spent: u64) -> Error {
        let all = self.tasks.len() + self.standards.len();
        let first = self.standards.first();
        let at = (
            first.map(|s| s.span),
            first.map_or_else(String::new, |s| {
                TaskReport::NotEvaluated(self.standard_not_evaluated(s))
                    .answer()
                    .label()
            }),
        );
        let left = self.work.limit.saturating_sub(spent);
        self.work.stopped(at, self.tasks.len(), all, left)
    }

    /// The entry of the standard `spec`, which the bound stopped the run
    /// before.
    fn standard_not_evaluated(&self, spec: &StandardSpec) -> NotEvaluatedReport {
        let room = format!("in {}", self.rooms[spec.room].name);
        NotEvaluatedReport::new("standard", &spec.name, &room)
    }

    /// The entry of `task`, which the bound stopped the run before.
    pub fn not_evaluated(&self, task: &TaskSpec) -> TaskReport {
        let label = task_label(&task.kind);
        TaskReport::NotEvaluated(NotEvaluatedReport::new(
            label,
            task.subject_name(self),
            self.who(task),
        ))
    }

    /// The entry of `task` while it runs (watch mode's first answers).
    pub fn evaluating(&self, task: &TaskSpec) -> TaskReport {
        let label = task_label(&task.kind);
        let (name, who) = (task.subject_name(self), self.who(task));
        TaskReport::NotEvaluated(NotEvaluatedReport::evaluating(label, name, who))
    }

    /// The report to show while some of `tasks` (every task of the file,
    /// in order) are still being evaluated ([`Scenario::evaluating`]):
    /// every standard is too (it looks at the tasks' answers), and only
    /// the expectations about the answers already found are judged.
    pub fn report_evaluating(&self, mut tasks: Vec<TaskReport>) -> Report {
        let standards = self.standards.iter().map(|spec| {
            let room = format!("in {}", self.rooms[spec.room].name);
            TaskReport::NotEvaluated(NotEvaluatedReport::evaluating(
                "standard", &spec.name, &room,
            ))
        });
        tasks.extend(standards);
        let answered = |k: &usize| !matches!(tasks.get(*k), Some(TaskReport::NotEvaluated(_)));
        let expectations = (self.expectations.iter())
            .filter(|e| e.check.entries().iter().all(answered))
            .map(|e| e.judge(&tasks))
            .collect();
        Report {
            schema: SCHEMA_VERSION,
            file: self.file.clone(),
            notes: self.notes(),
            expectations,
            advised_together: AdvisedTogether::of(&tasks),
            tasks,
        }
    }

    /// `task` in words: `map high_far_half by chair_users`.
    pub fn task_words(&self, task: &TaskSpec) -> String {
        let label = task_label(&task.kind);
        format!("{label} {} by {}", task.subject_name(self), self.who(task))
    }

    /// Who `task` is by: its population's name or its person's.
    fn who(&self, task: &TaskSpec) -> &str {
        match task.population {
            Some(p) => &self.populations[p].name,
            None => &self.persons[task.person].name,
        }
    }

    /// As [`Scenario::run_tasks`], with what each task's questions touched
    /// of its room where it records that (`Task::records_touches`; never
    /// for a population's task), and the work each did; the work of the
    /// tasks not run (`also_spent`, kept from before) is counted against
    /// the bound as well, so that a run that reuses answers stops where a
    /// fresh run would.
    /// Each task may take the solves of its last run that hold
    /// (`earlier`, by position; `engine::KeptSolves`).
    pub fn run_tasks_recording(
        &self,
        tasks: &[&TaskSpec],
        progress: &dyn Progress,
        also_spent: u64,
        earlier: &[Option<Earlier>],
        memo: &Arc<Memo>,
    ) -> Result<Vec<Ran>, Error> {
        let run = RunWork::keeping(self.work.limit, Arc::clone(memo));
        if !run.charge(also_spent) {
            return Err(self.work.exceeded());
        }
        self.run_jobs(tasks, progress, Some(earlier), &run)
    }

    /// `tasks` run in parallel, recording what they touch where `record`
    /// holds the solves of their last runs (by position), their work told
    /// to `run`: every answer, or an error where the run passed its bound.
    fn run_jobs(
        &self,
        tasks: &[&TaskSpec],
        progress: &dyn Progress,
        record: Option<&[Option<Earlier>]>,
        run: &Arc<RunWork>,
    ) -> Result<Vec<Ran>, Error> {
        let ran = self.run_jobs_partly(tasks, progress, record, run);
        match ran.into_iter().collect::<Option<Vec<Ran>>>() {
            Some(ran) if !run.exceeded() => Ok(ran),
            _ => Err(self.work.exceeded()),
        }
    }

    /// `tasks` run in parallel as [`Scenario::run_jobs`] runs them: each
    /// task's answer where it was finished before the run passed its bound
    /// (a population's task: by every one of its people), none where the
    /// bound stopped it first. Which tasks those are depends on the order
    /// the threads took them in.
    fn run_jobs_partly(
        &self,
        tasks: &[&TaskSpec],
        progress: &dyn Progress,
        record: Option<&[Option<Earlier>]>,
        run: &Arc<RunWork>,
    ) -> Vec<Option<Ran>> {
        // The positions of the tasks by each population.
        let mut by_population: BTreeMap<usize, Vec<usize>> = BTreeMap::new();
        let mut jobs = Vec::new();
        for (k, task) in tasks.iter().enumerate() {
            match task.population {
                Some(p) => by_population.entry(p).or_default().push(k),
                None => jobs.push(Job::Alone(k)),
            }
        }
        for (&population, positions) in &by_population {
            for &k in positions {
                if self.one_point(tasks[k]) {
                    progress.add_work(self.populations[population].len() as u64);
                }
            }
            let members = self.populations[population].members.clone();
            jobs.extend(members.map(|person| Job::Member { population, person }));
        }
        // Each mesh's collision shape is built here, before the tasks fan
        // out, on the thread that loaded the mesh: it reuses the memory
        // the loading freed, where a worker thread's allocator would take
        // fresh memory (a 1,000,000-triangle scan: 291 MB peak before, 240 after).
        for room in &self.rooms {
            for mesh in &room.meshes {
                let _ = mesh.shape();
            }
        }
        let floor_charges = self.floor_charges();
        // Each job's answers (a task's alone, or a member's in the order
        // of their population's tasks) and the work of each; none where
        // the run passed its bound before the job ended (no job starts
        // then, and one under way stops early: its answers are not
        // whole). The bound, once passed, stays passed: a job that ends
        // with the run within it was never cut short.
        type Found = (
            Vec<(TaskReport, u64)>,
            Option<(TouchedSet, Option<SolveMap>)>,
        );
        let found: Vec<Option<Found>> = jobs
            .par_iter()
            .map(|job| {
                if run.exceeded() {
                    return None;
                }
                let found = match *job {
                    Job::Alone(k) => {
                        let charges = floor_charges.of(tasks[k]);
                        let recording = record.map(|earlier| Recording {
                            earlier: earlier.get(k).and_then(Option::as_ref),
                        });
                        let ran = self.run_one(tasks[k], progress, false, recording, run, charges);
                        let touched = ran.touched.map(|t| (t, ran.solves));
                        (vec![(ran.report, ran.work)], touched)
                    }
                    Job::Member { population, person } => {
                        let own = by_population[&population].iter().map(|&k| tasks[k]);
                        let each =
                            self.run_member_tasks(own, person, progress, run, &floor_charges);
                        (each, None)
                    }
                };
                (!run.exceeded()).then_some(found)
            })
            .collect();
        let mut touched: Vec<Option<(TouchedSet, Option<SolveMap>)>> =
            (0..tasks.len()).map(|_| None).collect();
        let mut work = vec![0u64; tasks.len()];
        let mut whole = vec![true; tasks.len()];
        let mut answers = Vec::with_capacity(found.len());
        for (job, found) in jobs.iter().zip(found) {
            let Some((each, set)) = found else {
                match job {
                    Job::Alone(k) => whole[*k] = false,
                    Job::Member { population, .. } => {
                        by_population[population]
                            .iter()
                            .for_each(|&k| whole[k] = false);
                    }
                }
                answers.push(None);
                continue;
            };
            match job {
                Job::Alone(k) => (touched[*k], work[*k]) = (set, each[0].1),
                Job::Member { population, .. } => {
                    for (&k, (_, w)) in by_population[population].iter().zip(&each) {
                        work[k] += w;
                    }
                }
            }
            answers.push(Some(each.into_iter().map(|(report, _)| report).collect()));
        }
        let asking = (progress, run, work.as_mut_slice());
        let reports = self.gather(tasks, &by_population, &jobs, answers, &whole, asking);
        reports
            .into_iter()
            .zip(touched)
            .zip(work)
            .map(|((report, touched), work)| {
                let (touched, solves) = touched.unzip();
                report.map(|report| Ran {
                    report,
                    touched,
                    work,
                    solves: solves.flatten(),
                })
            })
            .collect()
    }

    /// The report of a run whose tasks, all of them in the order of the
    /// file, answered `tasks` (`spent` units of work, counted against the
    /// bound with the standards'): those answers, then the standards
    /// (checked again each time: they read the whole room), and what the
    /// file expects of them; with the standards' work. An error where the
    /// standards would take the run past its bound.
    pub fn report(
        &self,
        tasks: Vec<TaskReport>,
        spent: u64,
        memo: &Arc<Memo>,
    ) -> Result<(Report, u64), Error> {
        match self.report_partly(tasks, spent, false, memo) {
            (report, work, true) => Ok((report, work)),
            _ => Err(self.work.exceeded()),
        }
    }

    /// The report of a run of every task of the file (`tasks`, `spent`
    /// units of work) that the bound may have stopped (`stopped`: some
    /// tasks are not evaluated): the standards are checked where every
    /// task was answered and they fit within what is left of the bound,
    /// and are each not evaluated otherwise; with the standards' work,
    /// and whether they were checked.
    pub fn report_partly(
        &self,
        mut tasks: Vec<TaskReport>,
        spent: u64,
        stopped: bool,
        memo: &Arc<Memo>,
    ) -> (Report, u64, bool) {
        let all: Vec<&TaskSpec> = self.tasks.iter().collect();
        let run = RunWork::keeping(self.work.limit, Arc::clone(memo));
        run.charge(spent);
        let mut standards = if stopped {
            Vec::new()
        } else {
            self.advise_beside_standards(&mut tasks, &run);
            self.run_standards(&all, &tasks, &run)
        };
        let checked = !stopped && !run.exceeded();
        if !checked {
            standards = (self.standards.iter())
                .map(|spec| TaskReport::NotEvaluated(self.standard_not_evaluated(spec)))
                .collect();
        }
        tasks.extend(standards);
        let report = Report {
            schema: SCHEMA_VERSION,
            file: self.file.clone(),
            notes: self.notes(),
            expectations: self.judge(&tasks),
            advised_together: AdvisedTogether::of(&tasks),
            tasks,
        };
        let work = if checked { run.spent() - spent } else { 0 };
        (report, work, checked)
    }

    /// Each standard checked on its room, in parallel, in the order given,
    /// its work told to `run`; beside each element, what the tasks
    /// (`tasks`, whose answers are `answers`) in that room about it
    /// answered.
    pub(super) fn run_standards(
        &self,
        tasks: &[&TaskSpec],
        answers: &[TaskReport],
        run: &Arc<RunWork>,
    ) -> Vec<TaskReport> {
        self.standards
            .par_iter()
            .map(|spec| {
                let meter = Meter::of(run);
                let room = spec.room_of_elements(&self.rooms[spec.room]);
                let mut report = spec.standard.check(&room, &meter);
                report
                    .notes
                    .extend(spec.except_note(&self.rooms[spec.room]));
                for element in &mut report.elements {
                    let about = tasks.iter().zip(answers).filter(|(t, _)| {
                        t.room == spec.room && t.subject_name(self) == element.name
                    });
                    element.people = about
                        .map(|(_, r)| {
                            let a = r.answer();
                            PersonAnswer {
                                task: a.task.to_string(),
                                person: a.person,
                                ok: a.ok,
                                verdict: a.verdict,
                            }
                        })
                        .collect();
                }
                TaskReport::Standard(Box::new(report))
            })
            .collect()
    }

    /// The answers of `found` (one per job of `jobs`, none where it was
    /// not finished) as one report per task, in the order of `tasks`: none
    /// for a task not `whole` (a population's task some of whose people
    /// were not run).
    fn gather(
        &self,
        tasks: &[&TaskSpec],
        by_population: &BTreeMap<usize, Vec<usize>>,
        jobs: &[Job],
        found: Vec<Option<Vec<TaskReport>>>,
        whole: &[bool],
        asking: (&dyn Progress, &Arc<RunWork>, &mut [u64]),
    ) -> Vec<Option<TaskReport>> {
        let (progress, run, work) = asking;
        let mut reports: Vec<Option<TaskReport>> = vec![None; tasks.len()];
        // Each population task's answers, person by person in draw order.
        let mut answers: BTreeMap<usize, Vec<TaskReport>> = BTreeMap::new();
        for (job, each) in jobs.iter().zip(found) {
            let Some(each) = each else { continue };
            match job {
                Job::Alone(k) => reports[*k] = each.into_iter().next(),
                Job::Member { population, .. } => {
                    for (&k, report) in by_population[population].iter().zip(each) {
                        answers.entry(k).or_default().push(report);
                    }
                }
            }
        }
        for (k, answers) in answers {
            if !whole[k] {
                continue;
            }
            let task = tasks[k];
            let population = &self.populations[task.population.expect("a population task")];
            let name = task.subject_name(self);
            reports[k] = Some(
                match self.population_advice_of(task, &answers, progress, run) {
                    Some((advice, spent)) => {
                        work[k] += spent;
                        TaskReport::Advice(Box::new(advice))
                    }
                    None => TaskReport::Population(Box::new(PopulationReport::new(
                        name, population, &answers,
                    ))),
                },
            );
        }
        reports
    }

    /// Whether `task` asks about one point (its progress then counts
    /// people, where a map's counts its points).
    fn one_point(&self, task: &TaskSpec) -> bool {
        task.task.points(&task.subject_in(&self.rooms[task.room])) <= 1
    }

    /// Each of `tasks` (by one population, in order) for its member
    /// `person`, one after another, and the work of each.
    pub(super) fn run_member_tasks<'a>(
        &self,
        tasks: impl Iterator<Item = &'a TaskSpec>,
        person: usize,
        progress: &dyn Progress,
        run: &Arc<RunWork>,
        charges: &FloorCharges,
    ) -> Vec<(TaskReport, u64)> {
        tasks
            .map(|task| self.run_member(task, person, progress, run, charges.of(task)))
            .collect()
    }

    /// `task` (by a population) for its member `person`, and its work.
    pub(super) fn run_member(
        &self,
        task: &TaskSpec,
        person: usize,
        progress: &dyn Progress,
        run: &Arc<RunWork>,
        charges: Charges,
    ) -> (TaskReport, u64) {
        let spec = TaskSpec {
            person,
            population: None,
            ..task.clone()
        };
        let ran = self.run_one(&spec, progress, true, None, run, charges);
        let (answer, work) = (ran.report, ran.work);
        if self.one_point(task) {
            progress.advance(1);
        }
        (answer, work)
    }

    /// For each task of the scenario (by its address), whether it is
    /// charged the work of its person's floor in its room
    /// ([`Base::floor_work`](crate::plugin::Base::floor_work)): the first task of the scenario in that room
    /// by the same person (or population), and for a task that moves
    /// things about it, the first with its sweep (`Task::sweep`),
    /// whichever runs first and
    /// whichever answers a watch reuses, so that every task's work is the
    /// same on every run; and whether it is charged its base's getting
    /// ready for its effectors ([`Base::prepare_work`](crate::plugin::Base::prepare_work)): the first task by
    /// the same person (or population) with those effectors, in any room.
    /// A task not of the scenario is charged both.
    /// For each task, in order, whether it is charged its person's floor
    /// and its base's getting ready (`Scenario::floor_charges`): part of
    /// its work, so part of the key watch mode keeps its answer by (a task
    /// added or taken away before it moves them).
    pub fn first_charges(&self) -> Vec<(bool, bool)> {
        let charges = self.floor_charges();
        (self.tasks.iter())
            .map(|t| {
                let c = charges.of(t);
                (c.floor, c.prepare)
            })
            .collect()
    }

    pub(super) fn floor_charges(&self) -> FloorCharges {
        let (mut floors, mut prepared) = (HashSet::new(), HashSet::new());
        let first = (self.tasks.iter())
            .map(|t| {
                let person = t.population.is_none().then_some(t.person);
                // A task bounded by a sweep has a floor of the sweep's own
                // in the room as declared (`Sweep::named`).
                let room = &self.rooms[t.room];
                let sweep = t.task.sweep(room, &t.subject_in(room)).map(|s| s.key);
                let charges = Charges {
                    floor: floors.insert((t.room, t.population, person, sweep)),
                    prepare: prepared.insert((t.population, person, t.effectors.clone())),
                };
                (std::ptr::from_ref(t) as usize, charges)
            })
            .collect();
        FloorCharges { first }
    }

    /// Run `task` for its one person (`verdict_only`: as a member of a
    /// population, of whom only the verdict is kept), its work told to
    /// `run`: its answer, what its questions touched of the room (if
    /// `record` and it records that) and its work.
    pub(super) fn run_one(
        &self,
        task: &TaskSpec,
        progress: &dyn Progress,
        verdict_only: bool,
        record: Option<Recording<'_>>,
        run: &Arc<RunWork>,
        charges: Charges,
    ) -> Ran {
        let room = &self.rooms[task.room];
        let recording = record.filter(|_| task.task.records_touches());
        let touched =
            recording.map(|_| Arc::new(Touched::new(room.boxes.len() + room.meshes.len())));
        let solves = recording
            .zip(touched.as_ref())
            .map(|(r, touched)| KeptSolves::new(Arc::clone(touched), r.earlier.cloned()));
        let meter = Meter::of(run);
        let input = TaskInput {
            verdict_only,
            touched: touched.as_ref(),
            allowance: &meter,
            solves: solves.as_ref(),
            ..self.input(task, progress)
        };
        let label = task_label(&task.kind);
        let (subject, person) = (input.subject.name(), &input.person.name);
        let (base, room) = (&input.person.base.name, &input.room.name);
        // A task that moves things about the room has the room as declared
        // bounded by its sweep, under a name of the sweep's own.
        let sweep = task.task.sweep(input.room, &input.subject);
        let named = sweep.as_ref().map(|s| s.named(input.room.clone()));
        let fitted = named.as_ref().unwrap_or(input.room);
        let mut fit = match &sweep {
            Some(sweep) => input.base.fit_in_sweep(fitted, sweep, &meter),
            None => input.base.fit(fitted, &meter),
        };
        if charges.floor {
            meter.charge(input.base.floor_work(fitted));
        }
        // A task that moves what its subject carries checks each
        // arrangement of its room itself, unless the base is kept out
        // with the element gone too (the room is the cause, not where the
        // element is).
        let mut places_itself = task.task.places_itself();
        if places_itself && matches!(fit, Fit::Nowhere(_) | Fit::Shut(_)) {
            let mut element = task.task.carried();
            element.push(subject.to_string());
            let bare = input.room.without_boxes(&element);
            let bare_fit = input.base.fit(&bare, &meter);
            meter.charge(input.base.floor_work(&bare));
            if matches!(bare_fit, Fit::Nowhere(_) | Fit::Shut(_)) {
                (fit, places_itself) = (bare_fit, false);
            }
        }
        let report = match fit {
            Fit::Nowhere(_) | Fit::Shut(_) if places_itself => task.task.run(&input),
            Fit::Nowhere(misfit) => TaskReport::NotPlaced(NotPlacedReport::new(
                label, subject, person, base, room, &misfit,
            )),
            Fit::Shut(shut) => TaskReport::NotPlaced(NotPlacedReport::shut(
                label, subject, person, base, room, &shut,
            )),
            Fit::Fits | Fit::Outside => {
                if charges.prepare {
                    let body = &input.person.body;
                    (input.effectors.iter())
                        .for_each(|&e| _ = meter.charge(input.base.prepare_work(&body.chain(e))));
                }
                task.task.run(&input)
            }
        };
        Ran {
            report,
            touched: touched.map(|t| t.set()),
            work: meter.spent(),
            solves: solves.map(KeptSolves::into_map),
        }
    }
}
