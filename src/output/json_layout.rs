//! JSON laid out for people and for line-by-line diffs of golden files:
//! objects over several lines, but an array of numbers on one line, and in
//! other arrays each string (a row of a map's grid) or object whose values
//! are all plain (a map's cell) on a line of its own.

use serde_json::Value;

use crate::report::MapCell;

/// `value` as text, indented by two spaces a level.
pub fn to_string(value: &Value) -> String {
    let mut out = String::new();
    write(&mut out, value, 0);
    out.push('\n');
    out
}

/// A report's value `head`, made with its maps' cells left out, laid out
/// as [`to_string`] lays out the whole report: each map's cells (`cells`
/// of task k, the last key of its object) serialized and written one at a
/// time.
pub fn report_to_string(head: &Value, cells: &[Option<&[MapCell]>]) -> String {
    let Value::Object(map) = head else {
        return to_string(head);
    };
    let mut out = String::from("{");
    for (i, (key, item)) in map.iter().enumerate() {
        entry(&mut out, i, 1);
        write_key(&mut out, key);
        match item {
            Value::Array(tasks) if key == "tasks" && !tasks.is_empty() => {
                write_tasks(&mut out, tasks, cells);
            }
            _ => write(&mut out, item, 1),
        }
    }
    close(&mut out, 0, '}');
    out.push('\n');
    out
}

/// The report's tasks at level 1, each map with its cells.
fn write_tasks(out: &mut String, tasks: &[Value], cells: &[Option<&[MapCell]>]) {
    out.push('[');
    for (k, task) in tasks.iter().enumerate() {
        entry(out, k, 2);
        match (cells.get(k).copied().flatten(), task) {
            (Some(points), Value::Object(fields)) if !points.is_empty() => {
                write_map(out, fields, points);
            }
            (Some(_), Value::Object(fields)) => {
                let mut whole = fields.clone();
                whole.insert("cells".into(), Value::Array(Vec::new()));
                write_item(out, &Value::Object(whole), 2);
            }
            _ => write_item(out, task, 2),
        }
    }
    close(out, 1, ']');
}

/// An array's item at `level`, as [`write`] lays it out.
fn write_item(out: &mut String, item: &Value, level: usize) {
    if is_flat(item) {
        write_inline(out, item);
    } else {
        write(out, item, level);
    }
}

/// A map's object at level 2 (not flat: its cells are objects), then its
/// cells, each a flat object on a line of its own.
fn write_map(out: &mut String, fields: &serde_json::Map<String, Value>, points: &[MapCell]) {
    out.push('{');
    for (i, (key, item)) in fields.iter().enumerate() {
        entry(out, i, 3);
        write_key(out, key);
        write(out, item, 3);
    }
    entry(out, fields.len(), 3);
    write_key(out, "cells");
    out.push('[');
    for (j, cell) in points.iter().enumerate() {
        entry(out, j, 4);
        write_cell(out, cell);
    }
    close(out, 3, ']');
    close(out, 2, '}');
}

/// A map's cell at level 4: a cell with no reasons why it was not
/// reached is flat, and is written straight from its fields on one line
/// as [`write_inline`] writes its value; one with reasons is laid out
/// from its value.
fn write_cell(out: &mut String, cell: &MapCell) {
    if !cell.why().is_empty() {
        let value = serde_json::to_value(cell).expect("cells serialize");
        write_item(out, &value, 4);
        return;
    }
    let mut bytes = Vec::with_capacity(160);
    let mut line = serde_json::Serializer::with_formatter(&mut bytes, Inline);
    serde::Serialize::serialize(cell, &mut line).expect("cells serialize");
    out.push_str(std::str::from_utf8(&bytes).expect("JSON is UTF-8"));
}

/// Flat values on one line, as [`write_inline`] lays them out: a comma
/// and a space between items, a colon and a space after a key.
struct Inline;

impl serde_json::ser::Formatter for Inline {
    fn begin_array_value<W: ?Sized + std::io::Write>(
        &mut self,
        writer: &mut W,
        first: bool,
    ) -> std::io::Result<()> {
        separate(writer, first)
    }

    fn begin_object_key<W: ?Sized + std::io::Write>(
        &mut self,
        writer: &mut W,
        first: bool,
    ) -> std::io::Result<()> {
        separate(writer, first)
    }

    fn begin_object_value<W: ?Sized + std::io::Write>(
        &mut self,
        writer: &mut W,
    ) -> std::io::Result<()> {
        writer.write_all(b": ")
    }
}

/// Before an item or a key: nothing before the first, a comma and a space
/// before the others.
fn separate<W: ?Sized + std::io::Write>(writer: &mut W, first: bool) -> std::io::Result<()> {
    if first {
        Ok(())
    } else {
        writer.write_all(b", ")
    }
}

fn write(out: &mut String, value: &Value, level: usize) {
    match value {
        Value::Array(items) if items.iter().all(|v| is_scalar(v) && !v.is_string()) => {
            write_inline(out, value);
        }
        Value::Array(items) => {
            out.push('[');
            for (i, item) in items.iter().enumerate() {
                entry(out, i, level + 1);
                write_item(out, item, level + 1);
            }
            close(out, level, ']');
        }
        Value::Object(map) if !map.is_empty() => {
            out.push('{');
            for (i, (key, item)) in map.iter().enumerate() {
                entry(out, i, level + 1);
                write_key(out, key);
                write(out, item, level + 1);
            }
            close(out, level, '}');
        }
        scalar => out.push_str(&scalar.to_string()),
    }
}

/// Before the `i`th entry of an array or object: a comma after the one
/// before it, a new line, the indent of `level`.
fn entry(out: &mut String, i: usize, level: usize) {
    out.push_str(if i == 0 { "\n" } else { ",\n" });
    indent(out, level);
}

fn write_key(out: &mut String, key: &str) {
    out.push_str(&Value::String(key.to_string()).to_string());
    out.push_str(": ");
}

/// The end of an array or object opened at `level`.
fn close(out: &mut String, level: usize, bracket: char) {
    out.push('\n');
    indent(out, level);
    out.push(bracket);
}

fn indent(out: &mut String, level: usize) {
    for _ in 0..level {
        out.push_str("  ");
    }
}

/// On one line: plain values, arrays of them, objects of them.
fn is_flat(value: &Value) -> bool {
    match value {
        Value::Array(items) => items.iter().all(is_scalar),
        Value::Object(map) => map
            .values()
            .all(|v| is_scalar(v) || matches!(v, Value::Array(a) if a.iter().all(is_scalar))),
        v => is_scalar(v),
    }
}

fn is_scalar(value: &Value) -> bool {
    !matches!(value, Value::Array(_) | Value::Object(_))
}

fn write_inline(out: &mut String, value: &Value) {
    match value {
        Value::Object(map) => {
            out.push('{');
            for (i, (key, item)) in map.iter().enumerate() {
                if i > 0 {
                    out.push_str(", ");
                }
                out.push_str(&Value::String(key.clone()).to_string());
                out.push_str(": ");
                write_inline(out, item);
            }
            out.push('}');
        }
        Value::Array(items) => {
            out.push('[');
            for (i, item) in items.iter().enumerate() {
                if i > 0 {
                    out.push_str(", ");
                }
                write_inline(out, item);
            }
            out.push(']');
        }
        scalar => out.push_str(&scalar.to_string()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn flat_things_stay_on_one_line_and_parse_back() {
        let v: Value = serde_json::from_str(
            r#"{"a": 1, "b": [1.5, 2], "c": [{"x": 1, "y": [0, 1]}, {"x": 2, "y": [3, 4]}], "d": {"e": "f"}}"#,
        )
        .unwrap();
        let text = to_string(&v);
        let expected = [
            "{",
            r#"  "a": 1,"#,
            r#"  "b": [1.5, 2],"#,
            r#"  "c": ["#,
            r#"    {"x": 1, "y": [0, 1]},"#,
            r#"    {"x": 2, "y": [3, 4]}"#,
            "  ],",
            r#"  "d": {"#,
            r#"    "e": "f""#,
            "  }",
            "}",
            "",
        ]
        .join("\n");
        assert_eq!(text, expected);
        assert_eq!(serde_json::from_str::<Value>(&text).unwrap(), v);
    }
}
