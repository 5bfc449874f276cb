//! A plugin's settings as a Rust struct. The struct's `visit` declares
//! each option once, by name, kind, default, bounds and doc, and takes its
//! value in the same expression:
//!
//! ```ignore
//! fn visit(p: &mut Params<'_>) -> Self {
//!     Trolley {
//!         radius_mm: p.length("radius", 450.0, "the circle ...").range(100.0, 2000.0).get(),
//!         headings: p.integer("headings", 16, "directions tried").range(1.0, 360.0).get() as u32,
//!     }
//! }
//! ```
//!
//! Run one way (declaring), `visit` gives the declared parameters that
//! `reach plugins` prints and the checker validates; run the other way
//! (reading), it gives the settings from validated [`Options`]. The name is
//! written once, the field's type must match the kind's (`length` gives an
//! `f64`, `optional_point` an `Option<Vector3>`), and a field misspelt in
//! the code is a compile error. A value missing or of another kind (only
//! options built by hand can have one) is a [`SettingsError`], never a panic.

use std::fmt;
use std::marker::PhantomData;

use nalgebra::Vector3;

use super::{Options, ParamKind, ParamSpec, PluginConfig, PluginKind, Value};

/// A plugin's settings, declared and read by one `visit`.
pub trait Settings: Sized {
    /// Declare every option, in the order `reach plugins` lists them, and
    /// take each one's value.
    fn visit(p: &mut Params<'_>) -> Self;

    /// The declared parameters.
    fn params() -> Vec<ParamSpec> {
        declare::<Self>().0
    }

    /// Every option at its default, and a placeholder (zero, empty, none)
    /// where one must be given.
    fn with_defaults() -> Self {
        declare::<Self>().1
    }

    /// The settings that validated options give.
    fn from_options(options: &Options) -> Result<Self, SettingsError> {
        let mut p = Params {
            reading: Some(options),
            declared: Vec::new(),
            error: None,
        };
        let settings = Self::visit(&mut p);
        match p.error {
            Some(e) => Err(e),
            None => Ok(settings),
        }
    }

    /// Every option at its default (an error if one must be given).
    fn defaults() -> Result<Self, SettingsError> {
        Self::from_options(&Options::defaults(&Self::params()))
    }
}

/// The declaring pass: the parameters, and the settings at their defaults.
fn declare<S: Settings>() -> (Vec<ParamSpec>, S) {
    let mut p = Params {
        reading: None,
        declared: Vec::new(),
        error: None,
    };
    let settings = S::visit(&mut p);
    (p.declared, settings)
}

/// What is wrong with one option of a settings struct.
#[derive(Clone, Debug, PartialEq)]
pub struct SettingsError {
    pub option: &'static str,
    pub problem: SettingsProblem,
}

#[derive(Clone, Debug, PartialEq)]
pub enum SettingsProblem {
    /// No value, and the option has no default.
    Missing,
    /// A value of another kind.
    WrongKind { expected: ParamKind },
    /// A value the plugin cannot use with the others (in words).
    Invalid(String),
}

impl SettingsError {
    pub fn invalid(option: &'static str, why: impl Into<String>) -> Self {
        SettingsError {
            option,
            problem: SettingsProblem::Invalid(why.into()),
        }
    }
}

impl fmt::Display for SettingsError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.problem {
            SettingsProblem::Missing => write!(f, "option `{}` must be given", self.option),
            SettingsProblem::WrongKind { expected } => {
                write!(
                    f,
                    "option `{}` must be {}",
                    self.option,
                    expected.describe()
                )
            }
            SettingsProblem::Invalid(why) => write!(f, "option `{}`: {why}", self.option),
        }
    }
}

impl std::error::Error for SettingsError {}

/// The declaring or reading pass of a [`Settings::visit`].
pub struct Params<'a> {
    reading: Option<&'a Options>,
    declared: Vec<ParamSpec>,
    error: Option<SettingsError>,
}

impl<'a> Params<'a> {
    fn field<T: FromValue>(
        &mut self,
        name: &'static str,
        kind: ParamKind,
        default: Option<Value>,
        doc: &'static str,
    ) -> Field<'_, 'a, T> {
        Field {
            params: self,
            spec: ParamSpec {
                name,
                kind,
                default,
                range: None,
                optional: false,
                doc,
            },
            value: PhantomData,
        }
    }

    /// Millimetres inside; any length unit in the file.
    pub fn length(
        &mut self,
        name: &'static str,
        default_mm: f64,
        doc: &'static str,
    ) -> Field<'_, 'a, f64> {
        self.field(
            name,
            ParamKind::Length,
            Some(Value::Length(default_mm)),
            doc,
        )
    }

    /// Radians inside; any angle unit in the file.
    pub fn angle(
        &mut self,
        name: &'static str,
        default_rad: f64,
        doc: &'static str,
    ) -> Field<'_, 'a, f64> {
        self.field(name, ParamKind::Angle, Some(Value::Angle(default_rad)), doc)
    }

    /// A number without unit.
    pub fn number(
        &mut self,
        name: &'static str,
        default: f64,
        doc: &'static str,
    ) -> Field<'_, 'a, f64> {
        self.field(name, ParamKind::Number, Some(Value::Number(default)), doc)
    }

    pub fn integer(
        &mut self,
        name: &'static str,
        default: i64,
        doc: &'static str,
    ) -> Field<'_, 'a, i64> {
        self.field(name, ParamKind::Integer, Some(Value::Integer(default)), doc)
    }

    pub fn boolean(
        &mut self,
        name: &'static str,
        default: bool,
        doc: &'static str,
    ) -> Field<'_, 'a, bool> {
        self.field(name, ParamKind::Bool, Some(Value::Bool(default)), doc)
    }

    /// A name with a default.
    pub fn name(
        &mut self,
        name: &'static str,
        default: &str,
        doc: &'static str,
    ) -> Field<'_, 'a, String> {
        self.field(
            name,
            ParamKind::Name,
            Some(Value::Name(default.to_string())),
            doc,
        )
    }

    /// A length that must be given.
    pub fn required_length(&mut self, name: &'static str, doc: &'static str) -> Field<'_, 'a, f64> {
        self.field(name, ParamKind::Length, None, doc)
    }

    /// A point `(x, y, z)` of lengths that must be given.
    pub fn point(&mut self, name: &'static str, doc: &'static str) -> Field<'_, 'a, Vector3<f64>> {
        self.field(name, ParamKind::Point, None, doc)
    }

    /// Another plugin, by name, with the named default.
    pub fn plugin(
        &mut self,
        name: &'static str,
        kind: PluginKind,
        default: &str,
        doc: &'static str,
    ) -> Field<'_, 'a, PluginConfig> {
        self.plugin_with(name, kind, default, Vec::new(), doc)
    }

    /// Another plugin, with the named default and some of its options set
    /// (the others take the plugin's defaults).
    pub fn plugin_with(
        &mut self,
        name: &'static str,
        kind: PluginKind,
        default: &str,
        options: Vec<(&'static str, Value)>,
        doc: &'static str,
    ) -> Field<'_, 'a, PluginConfig> {
        let default = PluginConfig {
            name: default.to_string(),
            options: Options::new(options),
        };
        self.field(
            name,
            ParamKind::Plugin(kind),
            Some(Value::Plugin(default)),
            doc,
        )
    }

    fn optional<T: FromValue>(
        &mut self,
        name: &'static str,
        kind: ParamKind,
        doc: &'static str,
    ) -> Field<'_, 'a, Option<T>> {
        let mut field = self.field(name, kind, None, doc);
        field.spec.optional = true;
        field
    }

    /// A length that may be left out.
    pub fn optional_length(
        &mut self,
        name: &'static str,
        doc: &'static str,
    ) -> Field<'_, 'a, Option<f64>> {
        self.optional(name, ParamKind::Length, doc)
    }

    /// An angle that may be left out.
    pub fn optional_angle(
        &mut self,
        name: &'static str,
        doc: &'static str,
    ) -> Field<'_, 'a, Option<f64>> {
        self.optional(name, ParamKind::Angle, doc)
    }

    /// A number that may be left out.
    pub fn optional_number(
        &mut self,
        name: &'static str,
        doc: &'static str,
    ) -> Field<'_, 'a, Option<f64>> {
        self.optional(name, ParamKind::Number, doc)
    }

    /// A point that may be left out.
    pub fn optional_point(
        &mut self,
        name: &'static str,
        doc: &'static str,
    ) -> Field<'_, 'a, Option<Vector3<f64>>> {
        self.optional(name, ParamKind::Point, doc)
    }

    /// Points (an outline) that may be left out.
    pub fn optional_points(
        &mut self,
        name: &'static str,
        doc: &'static str,
    ) -> Field<'_, 'a, Option<Vec<Vector3<f64>>>> {
        self.optional(name, ParamKind::Points, doc)
    }

    /// Names (one, or a list `[a, b]`) that may be left out.
    pub fn optional_names(
        &mut self,
        name: &'static str,
        doc: &'static str,
    ) -> Field<'_, 'a, Option<Vec<String>>> {
        self.optional(name, ParamKind::Names, doc)
    }

    /// A name that may be left out (the plugin then takes a default of its
    /// own, such as the mannequin's first effector).
    pub fn optional_name(
        &mut self,
        name: &'static str,
        doc: &'static str,
    ) -> Field<'_, 'a, Option<String>> {
        self.optional(name, ParamKind::Name, doc)
    }

    fn fail(&mut self, option: &'static str, problem: SettingsProblem) {
        self.error.get_or_insert(SettingsError { option, problem });
    }
}

/// One option being declared or read; [`Field::get`] ends it.
pub struct Field<'p, 'a, T> {
    params: &'p mut Params<'a>,
    spec: ParamSpec,
    value: PhantomData<T>,
}

impl<T: FromValue> Field<'_, '_, T> {
    /// Inclusive bounds, in internal units (mm, rad), for numeric kinds.
    pub fn range(mut self, min: f64, max: f64) -> Self {
        self.spec.range = Some((min, max));
        self
    }

    /// Declaring: record the parameter and give its default. Reading: the
    /// option's value.
    pub fn get(self) -> T {
        let Field { params, spec, .. } = self;
        let Some(options) = params.reading else {
            let value = spec.default.as_ref().and_then(T::from_value);
            params.declared.push(spec);
            return value.unwrap_or_else(T::placeholder);
        };
        match options.get(spec.name) {
            Some(value) if value.is(spec.kind) => T::from_value(value).unwrap_or_else(|| {
                params.fail(
                    spec.name,
                    SettingsProblem::WrongKind {
                        expected: spec.kind,
                    },
                );
                T::placeholder()
            }),
            Some(_) => {
                params.fail(
                    spec.name,
                    SettingsProblem::WrongKind {
                        expected: spec.kind,
                    },
                );
                T::placeholder()
            }
            None if spec.optional => T::placeholder(),
            None => {
                params.fail(spec.name, SettingsProblem::Missing);
                T::placeholder()
            }
        }
    }
}

/// A Rust type an option's value is read as.
pub trait FromValue: Sized {
    fn from_value(value: &Value) -> Option<Self>;
    /// What a declaring pass gives where there is no default, and an
    /// optional option left out (`None`).
    fn placeholder() -> Self;
}

impl FromValue for f64 {
    fn from_value(value: &Value) -> Option<Self> {
        match value {
            Value::Length(v) | Value::Angle(v) | Value::Number(v) => Some(*v),
            _ => None,
        }
    }
    fn placeholder() -> Self {
        0.0
    }
}

impl FromValue for i64 {
    fn from_value(value: &Value) -> Option<Self> {
        match value {
            Value::Integer(v) => Some(*v),
            _ => None,
        }
    }
    fn placeholder() -> Self {
        0
    }
}

impl FromValue for bool {
    fn from_value(value: &Value) -> Option<Self> {
        match value {
            Value::Bool(v) => Some(*v),
            _ => None,
        }
    }
    fn placeholder() -> Self {
        false
    }
}

impl FromValue for String {
    fn from_value(value: &Value) -> Option<Self> {
        match value {
            Value::Name(v) => Some(v.clone()),
            _ => None,
        }
    }
    fn placeholder() -> Self {
        String::new()
    }
}

impl FromValue for Vec<String> {
    fn from_value(value: &Value) -> Option<Self> {
        match value {
            Value::Names(v) => Some(v.clone()),
            _ => None,
        }
    }
    fn placeholder() -> Self {
        Vec::new()
    }
}

impl FromValue for Vector3<f64> {
    fn from_value(value: &Value) -> Option<Self> {
        match value {
            Value::Point(v) => Some(*v),
            _ => None,
        }
    }
    fn placeholder() -> Self {
        Vector3::zeros()
    }
}

impl FromValue for Vec<Vector3<f64>> {
    fn from_value(value: &Value) -> Option<Self> {
        match value {
            Value::Points(v) => Some(v.clone()),
            _ => None,
        }
    }
    fn placeholder() -> Self {
        Vec::new()
    }
}

impl FromValue for PluginConfig {
    fn from_value(value: &Value) -> Option<Self> {
        match value {
            Value::Plugin(v) => Some(v.clone()),
            _ => None,
        }
    }
    fn placeholder() -> Self {
        PluginConfig::default()
    }
}

impl<T: FromValue> FromValue for Option<T> {
    fn from_value(value: &Value) -> Option<Self> {
        T::from_value(value).map(Some)
    }
    fn placeholder() -> Self {
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[derive(Debug, PartialEq)]
    struct Example {
        radius_mm: f64,
        turns: i64,
        zone: Option<Vector3<f64>>,
        at: Vector3<f64>,
    }

    impl Settings for Example {
        fn visit(p: &mut Params<'_>) -> Self {
            Example {
                radius_mm: p.length("radius", 450.0, "r").range(1.0, 900.0).get(),
                turns: p.integer("turns", 4, "t").get(),
                zone: p.optional_point("zone", "z").get(),
                at: p.point("at", "a").get(),
            }
        }
    }

    #[test]
    fn one_visit_declares_in_order_and_reads() {
        let params = Example::params();
        let names: Vec<&str> = params.iter().map(|p| p.name).collect();
        assert_eq!(names, ["radius", "turns", "zone", "at"]);
        assert_eq!(params[0].range, Some((1.0, 900.0)));
        assert!(params[2].optional && params[3].default.is_none());
        let options = Options::defaults(&params).set("at", Value::Point(Vector3::x()));
        let read = Example::from_options(&options).unwrap();
        assert_eq!(
            read,
            Example {
                radius_mm: 450.0,
                turns: 4,
                zone: None,
                at: Vector3::x()
            }
        );
    }

    #[test]
    fn a_missing_or_mistyped_value_is_an_error_not_a_panic() {
        let missing = Example::defaults().unwrap_err();
        assert_eq!(missing.option, "at");
        assert_eq!(missing.problem, SettingsProblem::Missing);
        let options = Options::defaults(&Example::params())
            .set("at", Value::Point(Vector3::x()))
            .set("radius", Value::Angle(1.0));
        let wrong = Example::from_options(&options).unwrap_err();
        assert_eq!(wrong.to_string(), "option `radius` must be a length");
    }
}
