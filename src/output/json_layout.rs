//! JSON laid out for people and for line-by-line diffs of golden files:
//! objects over several lines, but an array of numbers on one line, and in
//! other arrays each string (a row of a map's grid) or object whose values
//! are all plain (a map's cell) on a line of its own.

use serde_json::Value;

/// `value` as text, indented by two spaces a level.
pub fn to_string(value: &Value) -> String {
    let mut out = String::new();
    write(&mut out, value, 0);
    out.push('\n');
    out
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
