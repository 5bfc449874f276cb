//! Output formats: a report made into named files (what `--out DIR`
//! writes, every format's files as one set) and, for a format that has
//! one, a text for standard output (`--format NAME`), with the scene it
//! answers about for the formats that draw it.

use std::sync::Arc;

use super::{Base, Plugin};
use crate::report::Report;
use crate::scene::{Person, Room};

pub trait FormatPlugin: Plugin {
    /// The files of `report` in this format, by name, in the order they
    /// are written; `scene` is what the report answers about (the text and
    /// JSON formats read only the report).
    fn files(&self, report: &Report, scene: &FormatScene<'_>) -> Vec<(String, Vec<u8>)>;
    /// `report` in this format as one text for standard output, where the
    /// format has one ([`FormatPlugin::prints`]).
    fn render(&self, report: &Report, scene: &FormatScene<'_>) -> Option<String>;
    /// Whether the format has a text for standard output (`--format`):
    /// not one of a binary file, or of a file for each map.
    fn prints(&self) -> bool {
        true
    }
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
