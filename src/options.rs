//! Declared parameters of plugins and the validated values of an option
//! block. Every plugin declares its parameters the same way, so the checker
//! validates every option block the same way. Plain data, below the scene
//! that holds option values and the plugin traits that declare parameters.

use nalgebra::Vector3;

/// The four kinds of plugin.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum PluginKind {
    Solver,
    Base,
    Task,
    Format,
}

impl PluginKind {
    pub const ALL: [PluginKind; 4] = [
        PluginKind::Solver,
        PluginKind::Base,
        PluginKind::Task,
        PluginKind::Format,
    ];

    pub fn noun(self) -> &'static str {
        match self {
            PluginKind::Solver => "solver",
            PluginKind::Base => "base",
            PluginKind::Task => "task",
            PluginKind::Format => "format",
        }
    }
}

/// What kind of value a parameter takes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ParamKind {
    /// Millimetres inside; any length unit in the file.
    Length,
    /// Radians inside; any angle unit in the file.
    Angle,
    /// A number without unit.
    Number,
    /// A whole number.
    Integer,
    Bool,
    /// A point `(x, y, z)` of lengths.
    Point,
    /// A name the task resolves itself, such as an effector (`effector eyes`).
    Name,
    /// Another plugin, by name, with its own option block.
    Plugin(PluginKind),
}

impl ParamKind {
    /// With an article, for messages: "a length".
    pub fn describe(self) -> String {
        match self {
            ParamKind::Length => "a length".into(),
            ParamKind::Angle => "an angle".into(),
            ParamKind::Number => "a number without unit".into(),
            ParamKind::Integer => "a whole number".into(),
            ParamKind::Bool => "true or false".into(),
            ParamKind::Point => "a point (x, y, z)".into(),
            ParamKind::Name => "a name".into(),
            ParamKind::Plugin(k) => format!("the name of a {}", k.noun()),
        }
    }

    /// Short form for `reach plugins`.
    pub fn short(self) -> &'static str {
        match self {
            ParamKind::Length => "length",
            ParamKind::Angle => "angle",
            ParamKind::Number => "number",
            ParamKind::Integer => "integer",
            ParamKind::Bool => "bool",
            ParamKind::Point => "point",
            ParamKind::Name => "name",
            ParamKind::Plugin(PluginKind::Solver) => "solver",
            ParamKind::Plugin(PluginKind::Base) => "base",
            ParamKind::Plugin(PluginKind::Task) => "task",
            ParamKind::Plugin(PluginKind::Format) => "format",
        }
    }
}

/// A validated option value, in internal units.
#[derive(Clone, Debug, PartialEq)]
pub enum Value {
    Length(f64),
    Angle(f64),
    Number(f64),
    Integer(i64),
    Bool(bool),
    Point(Vector3<f64>),
    Name(String),
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
            Value::Point(p) => format!("({}, {}, {})", trim(p.x), trim(p.y), trim(p.z)),
            Value::Name(n) => n.clone(),
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
}

fn trim(v: f64) -> String {
    let s = format!("{v:.6}");
    s.trim_end_matches('0').trim_end_matches('.').to_string()
}

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
    fn new(name: &'static str, kind: ParamKind, default: Option<Value>, doc: &'static str) -> Self {
        ParamSpec {
            name,
            kind,
            default,
            range: None,
            optional: false,
            doc,
        }
    }

    pub fn length(name: &'static str, default_mm: f64, doc: &'static str) -> Self {
        Self::new(
            name,
            ParamKind::Length,
            Some(Value::Length(default_mm)),
            doc,
        )
    }

    pub fn angle(name: &'static str, default_rad: f64, doc: &'static str) -> Self {
        Self::new(name, ParamKind::Angle, Some(Value::Angle(default_rad)), doc)
    }

    pub fn number(name: &'static str, default: f64, doc: &'static str) -> Self {
        Self::new(name, ParamKind::Number, Some(Value::Number(default)), doc)
    }

    pub fn integer(name: &'static str, default: i64, doc: &'static str) -> Self {
        Self::new(name, ParamKind::Integer, Some(Value::Integer(default)), doc)
    }

    pub fn boolean(name: &'static str, default: bool, doc: &'static str) -> Self {
        Self::new(name, ParamKind::Bool, Some(Value::Bool(default)), doc)
    }

    /// A name that may be left out (the plugin then takes a default of its
    /// own, such as the mannequin's first effector).
    pub fn optional_name(name: &'static str, doc: &'static str) -> Self {
        ParamSpec {
            optional: true,
            ..Self::new(name, ParamKind::Name, None, doc)
        }
    }

    /// A name with a default.
    pub fn name(name: &'static str, default: &str, doc: &'static str) -> Self {
        Self::new(
            name,
            ParamKind::Name,
            Some(Value::Name(default.to_string())),
            doc,
        )
    }

    /// An optional length: `None` when the file left it out.
    pub fn optional_length(name: &'static str, doc: &'static str) -> Self {
        ParamSpec {
            optional: true,
            ..Self::new(name, ParamKind::Length, None, doc)
        }
    }

    /// An optional number: `None` when the file left it out.
    pub fn optional_number(name: &'static str, doc: &'static str) -> Self {
        ParamSpec {
            optional: true,
            ..Self::new(name, ParamKind::Number, None, doc)
        }
    }

    /// An optional angle: `None` when the file left it out.
    pub fn optional_angle(name: &'static str, doc: &'static str) -> Self {
        ParamSpec {
            optional: true,
            ..Self::new(name, ParamKind::Angle, None, doc)
        }
    }

    /// A point that must be given.
    pub fn point(name: &'static str, doc: &'static str) -> Self {
        Self::new(name, ParamKind::Point, None, doc)
    }

    /// A point that may be left out.
    pub fn optional_point(name: &'static str, doc: &'static str) -> Self {
        ParamSpec {
            optional: true,
            ..Self::new(name, ParamKind::Point, None, doc)
        }
    }

    /// Another plugin, with the named default.
    pub fn plugin(name: &'static str, kind: PluginKind, default: &str, doc: &'static str) -> Self {
        let default = PluginConfig {
            name: default.to_string(),
            options: Options::default(),
        };
        Self::new(
            name,
            ParamKind::Plugin(kind),
            Some(Value::Plugin(default)),
            doc,
        )
    }

    /// Another plugin, with the named default and some of its options set
    /// (the others take the plugin's defaults).
    pub fn plugin_with(
        name: &'static str,
        kind: PluginKind,
        default: &str,
        options: Vec<(&'static str, Value)>,
        doc: &'static str,
    ) -> Self {
        let mut spec = Self::plugin(name, kind, default, doc);
        if let Some(Value::Plugin(config)) = &mut spec.default {
            config.options = Options::new(options);
        }
        spec
    }

    /// Bounds, inclusive, in internal units (mm, rad).
    pub fn range(mut self, min: f64, max: f64) -> Self {
        self.range = Some((min, max));
        self
    }
}

/// A plugin chosen by name with its validated options.
#[derive(Clone, Debug, PartialEq)]
pub struct PluginConfig {
    pub name: String,
    pub options: Options,
}

/// The validated values of an option block: every declared parameter, the
/// given value or its default, in declaration order.
#[derive(Clone, Debug, PartialEq, Default)]
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

    /// These options with declared option `name` set to `value` (for
    /// programs that configure plugins without a scenario file).
    pub fn with(mut self, name: &str, value: Value) -> Self {
        let slot = self
            .values
            .iter_mut()
            .find(|(n, _)| *n == name)
            .unwrap_or_else(|| panic!("no declared option `{name}` to set"));
        slot.1 = value;
        self
    }

    /// These options with `name` set to `value`, added if absent.
    pub fn set(mut self, name: &'static str, value: Value) -> Self {
        match self.values.iter_mut().find(|(n, _)| *n == name) {
            Some(slot) => slot.1 = value,
            None => self.values.push((name, value)),
        }
        self
    }

    pub fn iter(&self) -> impl Iterator<Item = &(&'static str, Value)> {
        self.values.iter()
    }

    pub fn get(&self, name: &str) -> Option<&Value> {
        self.values.iter().find(|(n, _)| *n == name).map(|(_, v)| v)
    }

    /// The value of a declared parameter. The checker has filled in every
    /// declared parameter, so a miss is a bug in the plugin, not bad input.
    fn expect(&self, name: &str) -> &Value {
        self.get(name)
            .unwrap_or_else(|| panic!("plugin asked for undeclared option `{name}`"))
    }

    pub fn length_mm(&self, name: &str) -> f64 {
        match self.expect(name) {
            Value::Length(v) => *v,
            v => panic!("option `{name}` is not a length: {v:?}"),
        }
    }

    pub fn angle_rad(&self, name: &str) -> f64 {
        match self.expect(name) {
            Value::Angle(v) => *v,
            v => panic!("option `{name}` is not an angle: {v:?}"),
        }
    }

    pub fn number(&self, name: &str) -> f64 {
        match self.expect(name) {
            Value::Number(v) => *v,
            v => panic!("option `{name}` is not a number: {v:?}"),
        }
    }

    pub fn integer(&self, name: &str) -> i64 {
        match self.expect(name) {
            Value::Integer(v) => *v,
            v => panic!("option `{name}` is not an integer: {v:?}"),
        }
    }

    pub fn boolean(&self, name: &str) -> bool {
        match self.expect(name) {
            Value::Bool(v) => *v,
            v => panic!("option `{name}` is not a bool: {v:?}"),
        }
    }

    /// An optional name: `None` when the file left it out.
    pub fn name_opt(&self, name: &str) -> Option<&str> {
        match self.get(name)? {
            Value::Name(n) => Some(n),
            v => panic!("option `{name}` is not a name: {v:?}"),
        }
    }

    /// An optional length or angle: `None` when the file left it out.
    pub fn number_opt(&self, name: &str) -> Option<f64> {
        match self.get(name)? {
            Value::Length(v) | Value::Angle(v) | Value::Number(v) => Some(*v),
            v => panic!("option `{name}` is not a number: {v:?}"),
        }
    }

    /// An optional point: `None` when the file left it out.
    pub fn point_mm_opt(&self, name: &str) -> Option<Vector3<f64>> {
        match self.get(name)? {
            Value::Point(v) => Some(*v),
            v => panic!("option `{name}` is not a point: {v:?}"),
        }
    }

    pub fn point_mm(&self, name: &str) -> Vector3<f64> {
        match self.expect(name) {
            Value::Point(v) => *v,
            v => panic!("option `{name}` is not a point: {v:?}"),
        }
    }

    pub fn plugin(&self, name: &str) -> &PluginConfig {
        match self.expect(name) {
            Value::Plugin(c) => c,
            v => panic!("option `{name}` is not a plugin: {v:?}"),
        }
    }
}
