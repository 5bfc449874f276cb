//! The kinds of plugin, and the kinds of value an option takes.

/// The five kinds of plugin.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum PluginKind {
    Solver,
    Base,
    Task,
    Format,
    /// A building standard's rules (`standard ada2010`).
    Standard,
}

impl PluginKind {
    pub const ALL: [PluginKind; 5] = [
        PluginKind::Solver,
        PluginKind::Base,
        PluginKind::Task,
        PluginKind::Format,
        PluginKind::Standard,
    ];

    pub fn noun(self) -> &'static str {
        match self {
            PluginKind::Solver => "solver",
            PluginKind::Base => "base",
            PluginKind::Task => "task",
            PluginKind::Format => "format",
            PluginKind::Standard => "standard",
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
    /// Points `((x, y, z), (x, y, z), ...)`, two or more: an outline.
    Points,
    /// A name the task resolves itself, such as an effector (`effector eyes`).
    Name,
    /// Names, one (`carries shelf`) or several (`carries [shelf, tin]`),
    /// which the checker resolves for the plugin.
    Names,
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
            ParamKind::Points => "a list of points ((x, y, z), ...)".into(),
            ParamKind::Name => "a name".into(),
            ParamKind::Names => "a name or a list of names [a, b]".into(),
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
            ParamKind::Points => "points",
            ParamKind::Name => "name",
            ParamKind::Names => "names",
            ParamKind::Plugin(PluginKind::Solver) => "solver",
            ParamKind::Plugin(PluginKind::Base) => "base",
            ParamKind::Plugin(PluginKind::Task) => "task",
            ParamKind::Plugin(PluginKind::Format) => "format",
            ParamKind::Plugin(PluginKind::Standard) => "standard",
        }
    }
}
