//! The checked scenario: the scene (rooms, persons), each person's base
//! built, and the tasks to run, each configured from its options and
//! resolved: its room, subject, person and effectors are indices, so that a
//! run looks no name up. Spans remain only where a run may still need to
//! point back at the text.

use std::fmt;
use std::sync::Arc;

use crate::options::Options;
use crate::plugin::{Base, Fit, FormatScene, Subject, Task, TaskInput, TaskPlace};
use crate::progress::Progress;
use crate::report::{NotPlacedReport, PopulationReport, TaskReport};
use crate::scene::{Person, Population, Room, Surface};
use crate::span::Span;

#[derive(Clone)]
pub struct Scenario {
    /// The root file's name as given.
    pub file: String,
    pub rooms: Vec<Room>,
    pub persons: Vec<Person>,
    /// Each person's base, built, in the order of `persons`.
    pub bases: Vec<Arc<dyn Base>>,
    /// The populations the tasks name; their people are among `persons`.
    pub populations: Vec<Population>,
    pub tasks: Vec<TaskSpec>,
}

/// A task's subject, resolved in its room.
#[derive(Clone, Debug, PartialEq)]
pub enum SubjectRef {
    /// The room's target of this index.
    Target(usize),
    /// A surface of the room (a `surface`, or a box's face).
    Surface(Surface),
}

/// One task to run: a configured task plugin on one subject by one person.
#[derive(Clone)]
pub struct TaskSpec {
    /// The task plugin's name (`reach`).
    pub kind: String,
    pub task: Arc<dyn Task>,
    /// Its room, subject and person, by index.
    pub room: usize,
    pub subject: SubjectRef,
    /// The person; for a population's task, its first person (whose body
    /// every other shares in shape).
    pub person: usize,
    /// The population the task is by, if it is by one: it runs for each
    /// of its people.
    pub population: Option<usize>,
    /// The effectors the task names, resolved for the person: indices
    /// into the person's body, in the order of [`Task::effectors`].
    pub effectors: Vec<usize>,
    /// The validated options it was configured from (what a cache keys on).
    pub options: Options,
    pub span: Span,
}

impl fmt::Debug for Scenario {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Scenario")
            .field("file", &self.file)
            .field("rooms", &self.rooms)
            .field("persons", &self.persons)
            .field("tasks", &self.tasks)
            .finish_non_exhaustive()
    }
}

impl fmt::Debug for TaskSpec {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("TaskSpec")
            .field("kind", &self.kind)
            .field("room", &self.room)
            .field("subject", &self.subject)
            .field("person", &self.person)
            .field("population", &self.population)
            .field("effectors", &self.effectors)
            .field("options", &self.options)
            .finish_non_exhaustive()
    }
}

impl Scenario {
    /// What a format may draw of this scenario besides its report.
    pub fn format_scene(&self) -> FormatScene<'_> {
        FormatScene {
            rooms: &self.rooms,
            persons: &self.persons,
            bases: &self.bases,
            tasks: self
                .tasks
                .iter()
                .map(|t| TaskPlace {
                    room: t.room,
                    person: t.person,
                })
                .collect(),
        }
    }

    pub fn person(&self, name: &str) -> Option<&Person> {
        self.persons.iter().find(|p| p.name == name)
    }

    /// What `task` runs on.
    pub fn input<'a>(&'a self, task: &'a TaskSpec, progress: &'a dyn Progress) -> TaskInput<'a> {
        let room = &self.rooms[task.room];
        TaskInput {
            room,
            subject: task.subject_in(room),
            person: &self.persons[task.person],
            base: self.bases[task.person].as_ref(),
            effectors: &task.effectors,
            progress,
        }
    }
}

impl Scenario {
    /// Run `task`: its plugin's answer, or, where the person's base fits
    /// nowhere in the task's room, that answer (and nothing tried).
    pub fn run_task(&self, task: &TaskSpec, progress: &dyn Progress) -> TaskReport {
        if let Some(population) = task.population {
            return self.run_population(task, population, progress);
        }
        let input = self.input(task, progress);
        let Fit::Nowhere(misfit) = input.base.fit(input.room) else {
            return task.task.run(&input);
        };
        let label = match task.kind.as_str() {
            "reach_and_gaze" => "reach+gaze",
            "reach" => "reach",
            "gaze" => "gaze",
            "map" => "map",
            "gaze_map" => "gaze_map",
            _ => "task",
        };
        TaskReport::NotPlaced(NotPlacedReport::new(
            label,
            input.subject.name(),
            &input.person.name,
            &input.person.base.name,
            &input.room.name,
            &misfit,
        ))
    }
}

impl Scenario {
    /// Run `task` for each person of population `index`, in parallel, and
    /// report the share it accommodates. The answers are collected in
    /// draw order, so the report is the same on any number of threads.
    fn run_population(&self, task: &TaskSpec, index: usize, progress: &dyn Progress) -> TaskReport {
        use rayon::prelude::*;
        let population = &self.populations[index];
        let one_point = task.task.points(&task.subject_in(&self.rooms[task.room])) <= 1;
        if one_point {
            progress.add_work(population.len() as u64);
        }
        let answers: Vec<TaskReport> = population
            .members
            .clone()
            .into_par_iter()
            .map(|person| {
                let spec = TaskSpec {
                    person,
                    population: None,
                    ..task.clone()
                };
                let answer = self.run_task(&spec, progress);
                if one_point {
                    progress.advance(1);
                }
                answer
            })
            .collect();
        let name = task.subject_name(self);
        TaskReport::Population(Box::new(PopulationReport::new(name, population, &answers)))
    }
}

impl SubjectRef {
    /// The subject in `room` (the task's own room).
    pub fn in_room<'a>(&'a self, room: &'a Room) -> Subject<'a> {
        match self {
            SubjectRef::Target(i) => Subject::Target(&room.targets[*i]),
            SubjectRef::Surface(s) => Subject::Surface(s),
        }
    }
}

impl TaskSpec {
    /// The subject in `room` (the task's own room).
    pub fn subject_in<'a>(&'a self, room: &'a Room) -> Subject<'a> {
        self.subject.in_room(room)
    }

    /// The subject's name as the file wrote it.
    pub fn subject_name<'a>(&'a self, scenario: &'a Scenario) -> &'a str {
        match &self.subject {
            SubjectRef::Target(i) => &scenario.rooms[self.room].targets[*i].name,
            SubjectRef::Surface(s) => &s.name,
        }
    }
}
