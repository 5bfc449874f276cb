//! One declared parameter of a plugin: its name, kind, default, bounds
//! and doc, as `reach plugins` lists it and the checker validates it.
//! Plugins declare them through their settings (`settings.rs`).

use super::{ParamKind, Value};

/// One declared parameter.
#[derive(Clone, Debug)]
pub struct ParamSpec {
    pub name: &'static str,
    pub kind: ParamKind,
    /// `None`: the option must be given.
    pub default: Option<Value>,
    /// Inclusive bounds in internal units, for numeric kinds.
    pub range: Option<(f64, f64)>,
    /// May be left out, with no default: the plugin then does without.
    pub optional: bool,
    pub doc: &'static str,
}

impl ParamSpec {
    /// `default 0.05`, `optional` or `required`: what `reach plugins` and
    /// an editor say of the option's default.
    pub fn default_words(&self) -> String {
        match &self.default {
            Some(v) => format!("default {}", v.display()),
            None if self.optional => "optional".to_string(),
            None => "required".to_string(),
        }
    }
}
