//! The JSON Schema of the report, generated from the report's own types
//! (their doc comments become its descriptions), so that it cannot drift
//! from what `--format json` and `--out` write.

use schemars::generate::SchemaSettings;

use super::{Report, SCHEMA_VERSION};

/// The report's schema (JSON Schema 2020-12), pretty-printed, ending with a
/// newline.
pub fn schema_json() -> String {
    let generator = SchemaSettings::draft2020_12()
        .for_serialize()
        .into_generator();
    let mut schema = generator.into_root_schema_for::<Report>();
    schema.insert(
        "title".into(),
        format!("reach report, schema version {SCHEMA_VERSION}").into(),
    );
    // A report of another version is not this schema's.
    if let Some(version) = schema
        .get_mut("properties")
        .and_then(|p| p.get_mut("schema"))
        .and_then(|s| s.as_object_mut())
    {
        version.insert("const".into(), SCHEMA_VERSION.into());
    }
    let mut text = serde_json::to_string_pretty(&schema).expect("a schema is JSON");
    text.push('\n');
    text
}
