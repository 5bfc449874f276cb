//! Plugin options: the kinds of plugin and of value (`kind.rs`), declared
//! parameters (`spec.rs`), validated values (`value.rs`), and the typed
//! settings a plugin declares and reads them through (`settings.rs`).
//! Plain data, below the scene that holds option values and the plugin
//! traits that declare parameters.

mod kind;
mod settings;
mod spec;
mod value;

pub use kind::{ParamKind, PluginKind};
pub use settings::{Field, FromValue, Params, Settings, SettingsError, SettingsProblem};
pub use spec::ParamSpec;
pub use value::{Options, PluginConfig, Value};
