//! Output formats: a report rendered as text.

use super::Plugin;
use crate::report::Report;

pub trait FormatPlugin: Plugin {
    fn render(&self, report: &Report) -> String;
    /// The file extension when written with `--out`.
    fn extension(&self) -> &'static str;
}
