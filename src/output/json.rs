//! The `json` format: the report as pretty-printed JSON (docs/report.md).

use crate::plugin::{FormatPlugin, FormatScene, ParamSpec, Plugin};
use crate::report::{MapCell, Report};

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
    fn files(&self, report: &Report, scene: &FormatScene<'_>) -> Vec<(String, Vec<u8>)> {
        let json = self.render(report, scene).unwrap_or_default();
        vec![("report.json".into(), json.into_bytes())]
    }

    fn render(&self, report: &Report, _: &FormatScene<'_>) -> Option<String> {
        let head = serde_json::to_value(report.without_cells()).expect("reports serialize");
        let cells: Vec<Option<&[MapCell]>> = report
            .tasks
            .iter()
            .map(|t| t.map().map(|m| m.cells.as_slice()))
            .collect();
        Some(super::json_layout::report_to_string(&head, &cells))
    }
}
