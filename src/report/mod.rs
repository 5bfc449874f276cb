//! The report of a run: one entry per task, in the order of the file. Its
//! JSON form is a documented, stable schema (docs/report.md): lengths in
//! millimetres and angles in degrees whatever units the file used, every
//! number rounded to a fixed number of decimals so that runs compare byte
//! for byte.
//!
//! Each kind of task report is in its own file and says there, once, what
//! its answer is ([`Answer`]: the verdict in words and the figures that
//! matter); the text output, watch mode's list of changes and comparisons
//! with golden reports read that answer. [`TaskReport`] is the enum serde
//! writes, tagged by kind.

mod advice;
mod advice_grid;
mod advised_together;
mod answer;
mod entry_kind;
mod expectation;
mod gaze;
mod map;
mod not_evaluated;
mod not_placed;
mod parts;
mod population;
mod reach;
mod reach_and_gaze;
mod schema;
mod standard;
mod why;

pub use advice::{
    axis_index, AdviceFrame, AdvicePoint, AdviceReport, AdviceStandard, Because, PositionAnswer,
    RangeEnd, ServedRange,
};
pub use advice_grid::{rows_of, Across};
pub use advised_together::{AdvisedTogether, Span};
pub use answer::{Answer, Figure};
pub use entry_kind::{Asks, EntryKind, Kind, Tolerance};
pub use expectation::ExpectationReport;
pub use gaze::{GazeReport, Sight};
pub use map::{MapCell, MapReport};
pub use not_evaluated::{NotEvaluatedReport, EVALUATING, WORK_LIMIT};
pub use not_placed::NotPlacedReport;
pub use parts::{deg, fixed, mm, Asked, BaseReport, Names, Posture, BALANCE};
pub use population::{
    wilson95, Excluded, MapFrame, MemberOutcome, PopulationReport, ShareCell, ShareGrid,
};
pub use reach::{quoted, ReachReport};
pub use reach_and_gaze::ReachAndGazeReport;
pub use schema::schema_json;
pub use standard::{ElementCheck, FloorShape, PersonAnswer, RuleCheck, StandardReport};
pub use why::{Why, WIDENED_DEG};

use serde::Serialize;

/// Version of the JSON schema; raised when a field changes meaning.
pub const SCHEMA_VERSION: u32 = 1;

/// The whole report of one run of a scenario.
#[derive(Clone, Debug, PartialEq, Serialize, schemars::JsonSchema)]
pub struct Report {
    /// The version of this schema the report follows.
    pub schema: u32,
    /// The scenario file, as it was named to the tool.
    pub file: String,
    /// What a reader should know about every answer: a room without doors
    /// (where a base is placed, the way there is not checked).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub notes: Vec<String>,
    pub tasks: Vec<TaskReport>,
    /// The scenario's `expect`s, each met or not and why (left out when it
    /// has none).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub expectations: Vec<ExpectationReport>,
    /// Where an element is advised for two or more groups: the positions
    /// that serve every one (left out when there is none).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub advised_together: Vec<AdvisedTogether>,
}

impl Report {
    /// This report with its maps [`MapReport::without_cells`].
    pub fn without_cells(&self) -> Report {
        // Every field named, so that a field added is not left out.
        let Report {
            schema,
            file,
            notes,
            tasks,
            expectations,
            advised_together,
        } = self;
        Report {
            schema: *schema,
            file: file.clone(),
            notes: notes.clone(),
            tasks: tasks
                .iter()
                .map(|task| match task {
                    TaskReport::Map(map) => TaskReport::Map(map.without_cells()),
                    other => other.clone(),
                })
                .collect(),
            expectations: expectations.clone(),
            advised_together: advised_together.clone(),
        }
    }

    /// The advices along one line, by target and axis, each group named
    /// after its target (and its axis, where the target is advised along
    /// another axis too: `kettle-x`); grids are [`Report::advice_grids`].
    pub fn advices_by_target(&self) -> Vec<(String, Vec<&AdviceReport>)> {
        advised_together::by_target(&self.tasks)
    }

    /// The advices over a grid, in the order of the file.
    pub fn advice_grids(&self) -> impl Iterator<Item = &AdviceReport> {
        self.tasks.iter().filter_map(|t| match t {
            TaskReport::Advice(a) if !a.rows.is_empty() => Some(a.as_ref()),
            _ => None,
        })
    }

    /// Whether every expectation is met.
    pub fn expectations_met(&self) -> bool {
        self.expectations.iter().all(|e| e.met)
    }
}

impl Report {
    /// The answers, one per task, in the order of the file.
    pub fn answers(&self) -> Vec<Answer> {
        self.tasks.iter().map(TaskReport::answer).collect()
    }
}

/// One task's result, tagged by task kind.
#[derive(Clone, Debug, PartialEq, Serialize, schemars::JsonSchema)]
#[serde(tag = "kind", rename_all = "lowercase")]
pub enum TaskReport {
    Reach(ReachReport),
    Gaze(GazeReport),
    #[serde(rename = "reach_and_gaze")]
    ReachAndGaze(Box<ReachAndGazeReport>),
    Map(MapReport),
    /// The person's base fits nowhere in the task's room.
    #[serde(rename = "not_placed")]
    NotPlaced(NotPlacedReport),
    /// A task the run's work limit stopped it before.
    #[serde(rename = "not_evaluated")]
    NotEvaluated(NotEvaluatedReport),
    /// A task by a population: the share it accommodates.
    Population(Box<PopulationReport>),
    /// A room checked against a building standard's rules.
    Standard(Box<StandardReport>),
    /// An element moved along an axis: where it serves whom.
    Advice(Box<AdviceReport>),
}

/// What every kind of task report says of itself.
pub trait ReportKind {
    /// The answer: by whom, of what, the verdict and the figures.
    fn answer(&self) -> Answer;
    /// The lines the text report prints after its table.
    fn details(&self, out: &mut String);
    /// The answer `expect ... reaches` measures (`sees`: `expect ...
    /// sees`): the entry's own, or a part of it.
    fn answer_of(&self, sees: bool) -> Answer {
        let _ = sees;
        self.answer()
    }
    /// How much of its points the entry covers (0 to 1), in words, for
    /// `expect ... covers`: none where it has no points.
    fn coverage(&self) -> Option<(f64, String)> {
        None
    }
    /// The share of a population it accommodates, for `expect ... share`.
    fn share(&self) -> Option<f64> {
        None
    }
    /// Whether every rule holds, and in words which fail, for `expect ...
    /// meets`: none where it checks no rules.
    fn rules_met(&self) -> Option<(bool, String)> {
        None
    }
}

impl TaskReport {
    fn kind_report(&self) -> &dyn ReportKind {
        match self {
            TaskReport::Reach(r) => r,
            TaskReport::Gaze(g) => g,
            TaskReport::ReachAndGaze(b) => b.as_ref(),
            TaskReport::Map(m) => m,
            TaskReport::NotPlaced(n) => n,
            TaskReport::NotEvaluated(n) => n,
            TaskReport::Population(p) => p.as_ref(),
            TaskReport::Standard(s) => s.as_ref(),
            TaskReport::Advice(a) => a.as_ref(),
        }
    }

    pub fn answer(&self) -> Answer {
        self.kind_report().answer()
    }

    pub fn details(&self, out: &mut String) {
        self.kind_report().details(out)
    }

    /// [`ReportKind::answer_of`].
    pub fn answer_of(&self, sees: bool) -> Answer {
        self.kind_report().answer_of(sees)
    }

    /// [`ReportKind::coverage`].
    pub fn coverage(&self) -> Option<(f64, String)> {
        self.kind_report().coverage()
    }

    /// [`ReportKind::share`].
    pub fn share(&self) -> Option<f64> {
        self.kind_report().share()
    }

    /// [`ReportKind::rules_met`].
    pub fn rules_met(&self) -> Option<(bool, String)> {
        self.kind_report().rules_met()
    }

    /// The map, for a map or a gaze map (its points have files of their own).
    pub fn map(&self) -> Option<&MapReport> {
        match self {
            TaskReport::Map(m) => Some(m),
            _ => None,
        }
    }
}
