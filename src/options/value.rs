//! Validated option values: one value per declared parameter of a plugin,
//! in internal units (mm, rad), as the checker produced them. Plugins do
//! not read them by name: they read their settings (`settings.rs`).
//! Values hash by their bits, so that a cache can key on them.

use std::hash::{Hash, Hasher};

use nalgebra::Vector3;

use super::{ParamKind, ParamSpec};

/// A validated option value, in internal units.
#[derive(Clone, Debug, PartialEq)]
pub enum Value {
    Length(f64),
    Angle(f64),
    Number(f64),
    Integer(i64),
    Bool(bool),
    Point(Vector3<f64>),
    Points(Vec<Vector3<f64>>),
    Name(String),
    Names(Vec<String>),
    Plugin(PluginConfig),
}

impl Value {
    /// How `reach plugins` shows a default: in mm and degrees.
    pub fn display(&self) -> String {
        match self {
            Value::Length(v) => format!("{}mm", trim(*v)),
            Value::Angle(v) => format!("{}deg", trim(v.to_degrees())),
            Value::Number(v) => trim(*v),
            Value::Integer(v) => v.to_string(),
            Value::Bool(v) => v.to_string(),
            Value::Point(p) => point(p),
            Value::Points(ps) => {
                let points: Vec<String> = ps.iter().map(point).collect();
                format!("({})", points.join(", "))
            }
            Value::Name(n) => n.clone(),
            Value::Names(ns) => format!("[{}]", ns.join(", ")),
            Value::Plugin(c) if c.options.values.is_empty() => c.name.clone(),
            Value::Plugin(c) => {
                let options: Vec<String> = c
                    .options
                    .iter()
                    .map(|(name, value)| format!("{name} {}", value.display()))
                    .collect();
                format!("{} {{ {} }}", c.name, options.join(" "))
            }
        }
    }

    /// Whether the value is of `kind` (a plugin of any kind for a plugin).
    pub fn is(&self, kind: ParamKind) -> bool {
        matches!(
            (kind, self),
            (ParamKind::Length, Value::Length(_))
                | (ParamKind::Angle, Value::Angle(_))
                | (ParamKind::Number, Value::Number(_))
                | (ParamKind::Integer, Value::Integer(_))
                | (ParamKind::Bool, Value::Bool(_))
                | (ParamKind::Point, Value::Point(_))
                | (ParamKind::Points, Value::Points(_))
                | (ParamKind::Name, Value::Name(_))
                | (ParamKind::Names, Value::Names(_))
                | (ParamKind::Plugin(_), Value::Plugin(_))
        )
    }
}

impl Hash for Value {
    fn hash<H: Hasher>(&self, h: &mut H) {
        std::mem::discriminant(self).hash(h);
        match self {
            Value::Length(v) | Value::Angle(v) | Value::Number(v) => v.to_bits().hash(h),
            Value::Integer(v) => v.hash(h),
            Value::Bool(v) => v.hash(h),
            Value::Point(p) => p.iter().for_each(|c| c.to_bits().hash(h)),
            Value::Points(ps) => ps.iter().flatten().for_each(|c| c.to_bits().hash(h)),
            Value::Name(n) => n.hash(h),
            Value::Names(ns) => ns.hash(h),
            Value::Plugin(c) => c.hash(h),
        }
    }
}

fn point(p: &Vector3<f64>) -> String {
    format!("({}, {}, {})", trim(p.x), trim(p.y), trim(p.z))
}

fn trim(v: f64) -> String {
    let s = format!("{v:.6}");
    s.trim_end_matches('0').trim_end_matches('.').to_string()
}

/// A plugin chosen by name with its validated options.
#[derive(Clone, Debug, PartialEq, Hash, Default)]
pub struct PluginConfig {
    pub name: String,
    pub options: Options,
}

/// The validated values of an option block: every declared parameter, the
/// given value or its default, in declaration order (optional parameters
/// the file left out are absent).
#[derive(Clone, Debug, PartialEq, Default, Hash)]
pub struct Options {
    values: Vec<(&'static str, Value)>,
}

impl Options {
    pub fn new(values: Vec<(&'static str, Value)>) -> Self {
        Options { values }
    }

    /// Options with every parameter at its default (parameters without a
    /// default are left out).
    pub fn defaults(params: &[ParamSpec]) -> Self {
        Options {
            values: params
                .iter()
                .filter_map(|p| p.default.clone().map(|d| (p.name, d)))
                .collect(),
        }
    }

    /// These options with `name` set to `value`, added if absent (a
    /// person's own base options over a preset's, say).
    pub fn set(mut self, name: &'static str, value: Value) -> Self {
        match self.values.iter_mut().find(|(n, _)| *n == name) {
            Some(slot) => slot.1 = value,
            None => self.values.push((name, value)),
        }
        self
    }

    /// These options, and the defaults of `params` for those left out.
    pub fn completed(&self, params: &[ParamSpec]) -> Self {
        self.iter()
            .fold(Options::defaults(params), |o, (name, value)| {
                o.set(name, value.clone())
            })
    }

    pub fn iter(&self) -> impl Iterator<Item = &(&'static str, Value)> {
        self.values.iter()
    }

    /// The value of option `name`: for the checker and the settings
    /// reader; plugins read their settings instead.
    pub(crate) fn get(&self, name: &str) -> Option<&Value> {
        self.values.iter().find(|(n, _)| *n == name).map(|(_, v)| v)
    }
}
