//! The checked scenario: the scene (rooms, persons), each person's base
//! built, and the tasks to run, each configured from its options and
//! resolved: its room, subject, person and effectors are indices, so that a
//! run looks no name up. Spans remain only where a run may still need to
//! point back at the text.

mod advice;
mod estimate;
mod expect;
mod run;
mod shard;
mod shard_file;

pub use estimate::{sample_size, TaskWork, WorkEstimate};
pub use expect::{ExpectCheck, ExpectSpec};
pub use run::{Ran, Stop};
pub use shard::{PeopleBuilt, ShardOf, ShardPart};
pub use shard_file::{fingerprint, read_shard, write_shard};

use std::fmt;
use std::sync::Arc;

use crate::allowance::Unbounded;
use crate::error::{Error, ErrorKind};
use crate::options::Options;
use crate::plugin::{Base, FormatScene, Standard, Subject, Task, TaskInput, TaskPlace};
use crate::progress::Progress;
use crate::scene::{Person, Population, Room, Surface};
use crate::span::Span;
use crate::units::Quantity;

#[derive(Clone)]
pub struct Scenario {
    /// The root file's name as given.
    pub file: String,
    /// Every `let` constant with its value, by name.
    pub constants: Vec<(String, Quantity)>,
    pub rooms: Vec<Room>,
    pub persons: Vec<Person>,
    /// Each person's base, built, in the order of `persons`.
    pub bases: Vec<Arc<dyn Base>>,
    /// The populations the tasks name; their people are among `persons`.
    pub populations: Vec<Population>,
    pub tasks: Vec<TaskSpec>,
    /// Building standards checked on rooms, reported after the tasks.
    pub standards: Vec<StandardSpec>,
    /// What the file expects of the answers.
    pub expectations: Vec<ExpectSpec>,
    /// The most work its run's solvers may do.
    pub work: WorkBound,
}

/// The bound on the solvers' work in one run ([`crate::meter`]), and where
/// a run past it is reported.
#[derive(Clone, Copy, Debug)]
pub struct WorkBound {
    /// In the meter's units.
    pub limit: u64,
    /// The task declaration that may ask the most (by the count of solver
    /// starts, so the same on every run), if there are tasks.
    pub costliest: Option<Span>,
    /// Where the file's `limits` sets the bound, if it does: a run past
    /// it points there too.
    pub set_at: Option<Span>,
}

impl WorkBound {
    /// The error of a run the bound stopped partway (`answered` of
    /// `tasks` answered), `at` the first task not evaluated (its
    /// declaration, and it in words) with `left` units left for it.
    pub fn stopped(
        &self,
        at: (Option<Span>, String),
        answered: usize,
        tasks: usize,
        left: u64,
    ) -> Error {
        let (span, first) = at;
        let kind = ErrorKind::StoppedPartway {
            limit: self.limit,
            answered,
            tasks,
            left,
            first,
        };
        self.noting_where_set(match span {
            Some(span) => Error::new(kind, span),
            None => Error::unplaced(kind),
        })
    }

    /// The error of a run past the bound.
    pub fn exceeded(&self) -> Error {
        let kind = ErrorKind::TooMuchWork { limit: self.limit };
        self.noting_where_set(match self.costliest {
            Some(span) => Error::new(kind, span),
            None => Error::unplaced(kind),
        })
    }

    /// `error` with a note at the file's `limits` where it set the bound
    /// (an error placed nowhere else, there).
    fn noting_where_set(&self, error: Error) -> Error {
        match (self.set_at, error.span()) {
            (Some(set), Some(_)) => error.with_note(set, "the bound this file sets"),
            (Some(set), None) => error.moved_to(set),
            (None, _) => error,
        }
    }
}

/// A building standard to check on one room.
#[derive(Clone)]
pub struct StandardSpec {
    /// The standard plugin's name (`ada2010`).
    pub name: String,
    pub standard: Arc<dyn Standard>,
    pub room: usize,
    /// Targets of the room that are not elements (`except`), by name.
    pub except: Vec<String>,
    /// The validated options it was configured from.
    pub options: Options,
    pub span: Span,
}

impl StandardSpec {
    /// `room` as the standard sees it: without the targets `except` names.
    pub fn room_of_elements<'r>(&self, room: &'r Room) -> std::borrow::Cow<'r, Room> {
        if self.except.is_empty() {
            return std::borrow::Cow::Borrowed(room);
        }
        let mut elements = room.clone();
        elements.targets.retain(|t| !self.except.contains(&t.name));
        std::borrow::Cow::Owned(elements)
    }

    /// The report's note of the targets of `room` left out, if any.
    pub fn except_note(&self, room: &Room) -> Option<String> {
        let names: Vec<String> = (self.except.iter())
            .filter(|n| room.targets.iter().any(|t| &t.name == *n))
            .map(|n| format!("`{n}`"))
            .collect();
        (!names.is_empty()).then(|| format!("not elements (`except`): {}", names.join(", ")))
    }
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
            // The report's entries: the tasks, then the standards (which
            // place no person).
            tasks: self
                .tasks
                .iter()
                .map(|t| TaskPlace {
                    room: t.room,
                    person: t.person,
                })
                .chain(self.standards.iter().map(|s| TaskPlace {
                    room: s.room,
                    person: 0,
                }))
                .collect(),
        }
    }

    /// What a reader of the report should know about every answer: each
    /// room without doors where a task places a base that moves.
    pub fn notes(&self) -> Vec<String> {
        let mut rooms: Vec<usize> = self
            .tasks
            .iter()
            .filter(|t| self.bases[t.person].footprint().is_some())
            .map(|t| t.room)
            .filter(|&r| self.rooms[r].doors.is_empty())
            .collect();
        rooms.sort_unstable();
        rooms.dedup();
        rooms
            .into_iter()
            .map(|r| {
                format!(
                    "room `{}` has no `door`: a base is placed wherever it fits, even where nothing leads to (behind a counter, in a corner closed in by furniture); declare the room's doors to place it only where it can get to",
                    self.rooms[r].name
                )
            })
            .collect()
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
            verdict_only: false,
            touched: None,
            allowance: &Unbounded,
            solves: None,
        }
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

#[cfg(test)]
mod tests {
    use super::WorkBound;
    use crate::span::{FileId, Span};

    /// A run past a bound the file set is placed at the costliest task
    /// (the note at the bound is `tests/limits.rs`'s), or where the file
    /// has no task, at the bound itself, so that it is shown.
    #[test]
    fn a_bound_the_file_set_is_pointed_at() {
        let task = Span::new(FileId(0), 10, 20);
        let limits = Span::new(FileId(0), 30, 40);
        let bound = |costliest, set_at| WorkBound {
            limit: 1,
            costliest,
            set_at,
        };
        assert_eq!(
            bound(Some(task), Some(limits)).exceeded().span(),
            Some(task)
        );
        assert_eq!(bound(None, Some(limits)).exceeded().span(), Some(limits));
        assert_eq!(bound(None, None).exceeded().span(), None);
    }
}
