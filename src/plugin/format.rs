//! Output formats: a report rendered as text, with the scene it answers
//! about for the formats that draw it.

use std::sync::Arc;

use super::{Base, Plugin};
use crate::report::Report;
use crate::scene::{Person, Room};

pub trait FormatPlugin: Plugin {
    /// `report` in this format; `scene` is what the report answers about
    /// (the text and JSON formats read only the report).
    fn render(&self, report: &Report, scene: &FormatScene<'_>) -> String;
    /// The file extension when written with `--out`.
    fn extension(&self) -> &'static str;
}

/// The scene a report answers about: its rooms, its people with their
/// built bases, and each task's room and person, in the report's order.
pub struct FormatScene<'a> {
    pub rooms: &'a [Room],
    pub persons: &'a [Person],
    /// Each person's base, in the order of `persons`.
    pub bases: &'a [Arc<dyn Base>],
    pub tasks: Vec<TaskPlace>,
}

impl FormatScene<'_> {
    /// No scene: for a report rendered by a format that reads only the
    /// report, or one with no tasks (a format that draws draws an empty
    /// room).
    pub fn empty() -> Self {
        FormatScene {
            rooms: &[],
            persons: &[],
            bases: &[],
            tasks: Vec::new(),
        }
    }
}

/// Where one task ran: its room and person, by index.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct TaskPlace {
    pub room: usize,
    pub person: usize,
}
