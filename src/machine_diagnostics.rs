//! Diagnostics for programs rather than people: JSON (one object per
//! diagnostic and per line, with file, line, column, code, message, labels
//! and help) for editors and scripts, and GitHub Actions workflow commands
//! (`::error file=...,line=...,col=...::message`) so that CI shows each
//! error on its line. Lines and columns are 1-based, columns counted in
//! characters, as the human rendering's header counts them.

use miette::Diagnostic;
use serde::Serialize;

use crate::error::{Diagnostics, Error};
use crate::escape::{escaped, escaped_keeping};
use crate::source::Place;

/// How diagnostics are written.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DiagnosticStyle {
    /// miette's rendering for people, in colour or not.
    Human { colour: bool },
    /// JSON Lines: one object per diagnostic.
    Json,
    /// GitHub Actions `::error` workflow commands.
    Github,
}

impl Diagnostics {
    /// The diagnostics written in `style`.
    pub fn render_in(&self, style: DiagnosticStyle) -> String {
        match style {
            DiagnosticStyle::Human { colour } => self.render(!colour),
            DiagnosticStyle::Json => self.errors.iter().map(json_line).collect(),
            DiagnosticStyle::Github => self.errors.iter().map(github_line).collect(),
        }
    }
}

/// One diagnostic as JSON.
#[derive(Serialize)]
struct JsonDiagnostic {
    severity: &'static str,
    code: String,
    message: String,
    /// Where the error is; absent for an error in no file (a missing
    /// scenario file).
    #[serde(flatten)]
    place: Option<Place>,
    labels: Vec<JsonLabel>,
    help: Option<String>,
}

#[derive(Serialize)]
struct JsonLabel {
    label: String,
    #[serde(flatten)]
    place: Place,
}

fn json_line(e: &Error) -> String {
    let labels: Vec<JsonLabel> = e
        .placed_labels()
        .into_iter()
        .map(|(place, label)| JsonLabel {
            label: escaped(&label).into_owned(),
            place: place.clone(),
        })
        .collect();
    let diagnostic = JsonDiagnostic {
        severity: "error",
        code: e.kind().code().to_string(),
        message: e.to_string(),
        place: labels.first().map(|l| l.place.clone()),
        labels,
        help: e.help().map(|h| h.to_string()),
    };
    let mut line = serde_json::to_string(&diagnostic).expect("a diagnostic is JSON");
    line.push('\n');
    line
}

/// `::error file=F,line=L,col=C,endLine=..,endColumn=..,title=CODE::MESSAGE`,
/// the message followed by the label and the help on lines of their own.
fn github_line(e: &Error) -> String {
    let labels = e.placed_labels();
    let mut message = e.to_string();
    let mut properties = Vec::new();
    if let Some((place, label)) = labels.first() {
        properties.extend([
            format!("file={}", property(&place.file)),
            format!("line={}", place.line),
            format!("col={}", place.column),
            format!("endLine={}", place.end_line),
            format!("endColumn={}", place.end_column),
        ]);
        message.push_str(&format!("\n{}", escaped(label)));
    }
    for (place, label) in labels.iter().skip(1) {
        message.push_str(&format!("\nline {}: {}", place.line, escaped(label)));
    }
    properties.push(format!("title={}", property(e.kind().code())));
    if let Some(help) = e.help() {
        message.push_str(&format!("\nhelp: {help}"));
    }
    format!("::error {}::{}\n", properties.join(","), data(&message))
}

/// A failure that is not about the text of the input: an `expect` not
/// met, a base that fits nowhere under `--strict`; in a file, and on a
/// line of it, where it is written.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Finding {
    pub code: &'static str,
    pub message: String,
    pub file: Option<String>,
    pub line: Option<usize>,
}

impl Finding {
    /// The finding in `style`, one line: `error: MESSAGE (FILE:LINE)` for
    /// people, a JSON object, or an `::error` workflow command.
    pub fn render_in(&self, style: DiagnosticStyle) -> String {
        let message = escaped(&self.message).into_owned();
        match style {
            DiagnosticStyle::Human { .. } => match (&self.file, self.line) {
                (Some(file), Some(line)) => {
                    format!("error: {message} ({}:{line})\n", escaped(file))
                }
                _ => format!("error: {message}\n"),
            },
            DiagnosticStyle::Json => {
                let mut object = serde_json::json!({
                    "severity": "error",
                    "code": self.code,
                    "message": message,
                });
                if let Some(file) = &self.file {
                    object["file"] = file.as_str().into();
                }
                if let Some(line) = self.line {
                    object["line"] = line.into();
                }
                format!("{object}\n")
            }
            DiagnosticStyle::Github => {
                let mut place = String::new();
                if let Some(file) = &self.file {
                    place.push_str(&format!("file={},", property(file)));
                }
                if let Some(line) = self.line {
                    place.push_str(&format!("line={line},"));
                }
                format!(
                    "::error {place}title={}::{}\n",
                    property(self.code),
                    data(&message)
                )
            }
        }
    }
}

/// A workflow command's message, escaped as the Actions runner reads it,
/// and with every other control or invisible character escaped as on a
/// terminal (a log is shown on one).
pub fn data(text: &str) -> String {
    escaped_keeping(text, |c| c == '\n' || c == '\r')
        .replace('%', "%25")
        .replace('\r', "%0D")
        .replace('\n', "%0A")
}

/// A workflow command's property value (a file name, a code): as its
/// message, and `:` and `,`.
pub fn property(text: &str) -> String {
    data(text).replace(':', "%3A").replace(',', "%2C")
}

#[cfg(test)]
mod tests {
    use super::{data, property};

    #[test]
    fn workflow_command_escapes() {
        let cases = [
            ("plain", "plain", "plain"),
            ("50 %", "50 %25", "50 %25"),
            ("a\nb\r", "a%0Ab%0D", "a%0Ab%0D"),
            ("k.reach:3, x", "k.reach:3, x", "k.reach%3A3%2C x"),
            // A file name that would recolour the log: escaped, not sent.
            ("ev\u{1b}il.reach", "ev\\u{1b}il.reach", "ev\\u{1b}il.reach"),
            ("\u{202e}a", "\\u{202e}a", "\\u{202e}a"),
        ];
        for (text, as_data, as_property) in cases {
            assert_eq!(data(text), as_data, "{text:?}");
            assert_eq!(property(text), as_property, "{text:?}");
        }
    }
}
