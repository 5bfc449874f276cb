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
        out.push_str(if i == 0 { "\n" } else { ",\n" });
        indent(&mut out, 1);
        out.push_str(&Value::String(key.clone()).to_string());
        out.push_str(": ");
        match item {
            Value::Array(tasks) if key == "tasks" && !tasks.is_empty() => {
                write_tasks(&mut out, tasks, cells);
            }
            _ => write(&mut out, item, 1),
        }
    }
    out.push_str("\n}\n");
    out
}

/// The report's tasks at level 1, each map with its cells.
fn write_tasks(out: &mut String, tasks: &[Value], cells: &[Option<&[MapCell]>]) {
    out.push('[');
    for (k, task) in tasks.iter().enumerate() {
        out.push_str(if k == 0 { "\n" } else { ",\n" });
        indent(out, 2);
        match (cells.get(k).copied().flatten(), task) {
            (Some(points), Value::Object(fields)) if !points.is_empty() => {
                write_map(out, fields, points);
            }
            (Some(_), Value::Object(fields)) => {
                let mut whole = fields.clone();
                whole.insert("cells".into(), Value::Array(Vec::new()));
                let whole = Value::Object(whole);
                write_item(out, &whole, 2);
            }
            _ => write_item(out, task, 2),
        }
    }
    out.push('\n');
    indent(out, 1);
    out.push(']');
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
    for (key, item) in fields {
        out.push('\n');
        indent(out, 3);
        out.push_str(&Value::String(key.clone()).to_string());
        out.push_str(": ");
        write(out, item, 3);
        out.push(',');
    }
    out.push('\n');
    indent(out, 3);
    out.push_str("\"cells\": [");
    for (j, cell) in points.iter().enumerate() {
        out.push_str(if j == 0 { "\n" } else { ",\n" });
        indent(out, 4);
        let value = serde_json::to_value(cell).expect("cells serialize");
        write_item(out, &value, 4);
    }
    out.push('\n');
    indent(out, 3);
    out.push_str("]\n");
    indent(out, 2);
    out.push('}');
}

fn write(out: &mut String, value: &Value, level: usize) {
    match value {
        Value::Array(items) if items.iter().all(|v| is_scalar(v) && !v.is_string()) => {
            write_inline(out, value);
        }
        Value::Array(items) => {
            out.push('[');
            for (i, item) in items.iter().enumerate() {
                out.push_str(if i == 0 { "\n" } else { ",\n" });
                indent(out, level + 1);
                if is_flat(item) {
                    write_inline(out, item);
                } else {
                    write(out, item, level + 1);
                }
            }
            out.push('\n');
            indent(out, level);
            out.push(']');
        }
        Value::Object(map) if !map.is_empty() => {
            out.push('{');
            for (i, (key, item)) in map.iter().enumerate() {
                out.push_str(if i == 0 { "\n" } else { ",\n" });
                indent(out, level + 1);
                out.push_str(&Value::String(key.clone()).to_string());
                out.push_str(": ");
                write(out, item, level + 1);
            }
            out.push('\n');
            indent(out, level);
            out.push('}');
        }
        scalar => out.push_str(&scalar.to_string()),
    }
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
