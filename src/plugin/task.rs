//! Tasks: what a scenario asks of a person. A task plugin is configured
//! once, by the checker, from its validated options (the solvers they name
//! built then); the checker also resolves the task's subject, person and
//! effectors, and a run hands them to the configured task, which looks no
//! name up.

use std::sync::Arc;

use nalgebra::Point3;

use super::{Base, Options, Plugin, Registry, SettingsError, Tries};
use crate::allowance::Allowance;
use crate::collision::Touched;
use crate::engine::KeptSolves;
use crate::error::ErrorKind;
use crate::kinematics::{Body, Chain};
use crate::progress::Progress;
use crate::report::{Names, TaskReport};
use crate::scene::{Person, Room, Surface, Sweep, Target};

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SubjectKind {
    /// A named target of a room.
    Target,
    /// A surface: a `surface` of a room or a face of a box (`counter.top`).
    Surface,
}

/// What a task is about, resolved.
#[derive(Clone, Copy, Debug)]
pub enum Subject<'a> {
    Target(&'a Target),
    Surface(&'a Surface),
}

impl Subject<'_> {
    /// As the file names it: `mug`, `counter.top`.
    pub fn name(&self) -> &str {
        match self {
            Subject::Target(t) => &t.name,
            Subject::Surface(s) => &s.name,
        }
    }
}

/// An effector a task's options name (`None`: the mannequin's first),
/// which the checker resolves for each person.
#[derive(Clone, Debug, PartialEq)]
pub struct EffectorNeed {
    /// The option that names it, where a diagnostic points.
    pub option: &'static str,
    pub name: Option<String>,
}

/// Everything a configured task runs on, resolved by the checker.
pub struct TaskInput<'a> {
    pub room: &'a Room,
    pub subject: Subject<'a>,
    pub person: &'a Person,
    /// The person's base, built.
    pub base: &'a dyn Base,
    /// The effectors of [`Task::effectors`], in that order, as indices into
    /// the person's body.
    pub effectors: &'a [usize],
    /// Where a long task reports its progress.
    pub progress: &'a dyn Progress,
    /// Whether only the verdict matters (the task runs for one member of a
    /// population, whose report keeps only whether the answer holds and,
    /// where it does not, why): a search may stop at the first placement
    /// that holds instead of looking on for the most comfortable one.
    pub verdict_only: bool,
    /// Where the obstacles the task's questions come near are recorded
    /// (watch mode's cache), if anywhere: only a task that
    /// [`Task::records_touches`] is given one.
    pub touched: Option<&'a Arc<Touched>>,
    /// What the task's solves tell their work to (`Allowance`):
    /// a task whose run passes its bound is thrown away with the run.
    pub allowance: &'a dyn Allowance,
    /// Where a map's solves are kept for the task's next run, and taken
    /// from its last (watch mode's cache): given with [`TaskInput::touched`].
    pub solves: Option<&'a KeptSolves>,
}

impl<'a> TaskInput<'a> {
    /// The names of what `chain`, the task's person's, may run into: the
    /// room's obstacles and sides, the person's own body and base, the
    /// chain's own parts.
    pub fn names(&self, chain: &'a Chain) -> Names<'a> {
        Names {
            room: self.room,
            own: self.base.own_body(),
            chain,
        }
    }
}

/// What a task's answer depends on in its room beyond its own settings,
/// subject and person, for the cache of watch mode: the placements its
/// base may try for each point (through `chain`), and the obstacles within
/// `reach_mm` of one of them.
pub struct Dependence {
    /// The chain whose placements the base searches.
    pub chain: Chain,
    /// The points the task reaches for, in the room.
    pub points_mm: Vec<Point3<f64>>,
    /// How far from the hip a link (grown by the clearance) or a line of
    /// sight may go; `None`: no obstacle is looked at.
    pub reach_mm: Option<f64>,
    /// Lines of sight run from the eyes (within `reach_mm` of the hip) to
    /// each point, so obstacles between count too.
    pub sight_lines: bool,
    /// How close to a point counts as reaching it.
    pub tolerance_mm: f64,
}

pub trait TaskPlugin: Plugin {
    /// Whether the task's subjects are targets (reach, gaze) or surfaces
    /// (map); the checker resolves them accordingly.
    fn subject(&self) -> SubjectKind;
    /// The task that validated `options` configure; the plugins its options
    /// name are built from `plugins`.
    fn configure(
        &self,
        options: &Options,
        plugins: &Registry,
    ) -> Result<Box<dyn Task>, SettingsError>;
}

/// A task configured from its settings.
pub trait Task: Send + Sync {
    /// The effectors its options name, which the checker resolves for each
    /// person.
    fn effectors(&self) -> Vec<EffectorNeed>;
    /// A check of the task on its resolved subject beyond its options (a
    /// map too large, say); the checker reports it at the subject.
    fn validate(&self, _subject: &Subject<'_>) -> Option<ErrorKind> {
        None
    }
    /// The other boxes and targets of the subject's room its options name
    /// (an advice's element, moved with its target): the checker makes
    /// sure each is one.
    fn carried(&self) -> Vec<String> {
        Vec::new()
    }
    /// A check of the task on its subject in its room (an advice's
    /// positions inside it): the option the problem is about, and the
    /// problem, which the checker reports at that option.
    fn validate_in(&self, _subject: &Subject<'_>, _room: &Room) -> Option<(&'static str, String)> {
        None
    }
    /// A check of one person's chain to effector `need` (an index into
    /// [`Task::effectors`]): a gaze needs a look link. Reported at the
    /// person's name.
    fn validate_chain(&self, _person: &str, _need: usize, _chain: &Chain) -> Option<ErrorKind> {
        None
    }
    /// How many reaches the task asks of `subject` (a map: its points).
    fn points(&self, _subject: &Subject<'_>) -> u64 {
        1
    }
    /// The most solver starts one point may need from `placements`
    /// candidate placements (what the limit on solver starts counts).
    fn starts_per_point(&self, placements: Tries) -> u64;
    /// How many searches one point asks of a person of `body`, the task's
    /// effectors resolved to `effectors`: one, but a reach with either
    /// hand searches with each hand the body has.
    fn searches(&self, _body: &Body, _effectors: &[usize]) -> u64 {
        1
    }
    /// What the answer depends on in the room (for the cache).
    fn dependence(&self, input: &TaskInput<'_>) -> Dependence;
    /// Whether the task asks about the room's obstacles only through
    /// `collision::Obstacles` made with [`TaskInput::touched`] (or marks
    /// every obstacle touched where it looks at them otherwise), and about
    /// the floor only through its base: then watch mode may keep its
    /// answer when an obstacle its questions did not come near moves a
    /// little. False (the default) keeps the answer only while every
    /// obstacle within the task's reach stays as it was.
    fn records_touches(&self) -> bool {
        false
    }
    /// Whether the task moves things about its room and checks where the
    /// base fits at each arrangement itself (an advice): then where the
    /// base fits nowhere in the room as declared, it still runs.
    fn places_itself(&self) -> bool {
        false
    }
    /// Where the task moves things about its room: the bounds of every
    /// arrangement it makes of `room` with `subject`, the room as declared
    /// among them (`scene::Sweep`), for the base's floor in each to be bounded
    /// by (`Base::fit_in_sweep`; the answers are the same).
    fn sweep(&self, _room: &Room, _subject: &Subject<'_>) -> Option<Sweep> {
        None
    }
    fn run(&self, input: &TaskInput<'_>) -> TaskReport;
    /// Why the person of `input` does not reach point `at` of the task
    /// (an advice's position), in the words of a reach's verdict: asked
    /// after a population's run of only the people whose answer there a
    /// report shows (those who drop out at an advised range's end). None
    /// for a task with no such points.
    fn explain(&self, _input: &TaskInput<'_>, _at: usize) -> Option<String> {
        None
    }
}
