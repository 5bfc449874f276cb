//! The `json` format: the report as pretty-printed JSON (docs/report.md).

use crate::plugin::{FormatPlugin, FormatScene, ParamSpec, Plugin};
use crate::report::Report;

pub struct Json;

impl Plugin for Json {
    fn name(&self) -> &'static str {
        "json"
    }

    fn doc(&self) -> &'static str {
        "the report as JSON, for tools and golden files (schema: docs/report.md)"
    }

    fn params(&self) -> Vec<ParamSpec> {
        Vec::new()
    }
}

impl FormatPlugin for Json {
    fn render(&self, report: &Report, _: &FormatScene<'_>) -> String {
        let value = serde_json::to_value(report).expect("reports serialize");
        super::json_layout::to_string(&value)
    }

    fn extension(&self) -> &'static str {
        "json"
    }
}
