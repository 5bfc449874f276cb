//! The one registry of plugins, by kind and name, in registration order.

use std::sync::Arc;

use super::{
    BasePlugin, FormatPlugin, ParamSpec, Plugin, PluginConfig, PluginKind, SettingsError, Solver,
    SolverPlugin, StandardPlugin, TaskPlugin,
};

/// Every plugin a run can use. [`Registry::builtin`] (`builtin.rs`, above
/// the plugins it names) has the built-in ones; a program using the
/// library can register its own.
#[derive(Clone, Default)]
pub struct Registry {
    solvers: Vec<Arc<dyn SolverPlugin>>,
    bases: Vec<Arc<dyn BasePlugin>>,
    tasks: Vec<Arc<dyn TaskPlugin>>,
    formats: Vec<Arc<dyn FormatPlugin>>,
    standards: Vec<Arc<dyn StandardPlugin>>,
}

/// Put `plugin` into `list`, replacing one of the same name.
fn insert<T: ?Sized + Plugin>(list: &mut Vec<Arc<T>>, plugin: Arc<T>) {
    match list.iter().position(|p| p.name() == plugin.name()) {
        Some(i) => list[i] = plugin,
        None => list.push(plugin),
    }
}

fn find<'a, T: ?Sized + Plugin>(list: &'a [Arc<T>], name: &str) -> Option<&'a Arc<T>> {
    list.iter().find(|p| p.name() == name)
}

impl Registry {
    pub fn register_solver(&mut self, p: impl SolverPlugin + 'static) {
        insert(&mut self.solvers, Arc::new(p) as Arc<dyn SolverPlugin>);
    }

    pub fn register_base(&mut self, p: impl BasePlugin + 'static) {
        insert(&mut self.bases, Arc::new(p) as Arc<dyn BasePlugin>);
    }

    pub fn register_task(&mut self, p: impl TaskPlugin + 'static) {
        insert(&mut self.tasks, Arc::new(p) as Arc<dyn TaskPlugin>);
    }

    pub fn register_format(&mut self, p: impl FormatPlugin + 'static) {
        insert(&mut self.formats, Arc::new(p) as Arc<dyn FormatPlugin>);
    }

    pub fn register_standard(&mut self, p: impl StandardPlugin + 'static) {
        insert(&mut self.standards, Arc::new(p) as Arc<dyn StandardPlugin>);
    }

    pub fn standard(&self, name: &str) -> Option<&Arc<dyn StandardPlugin>> {
        find(&self.standards, name)
    }

    pub fn solver(&self, name: &str) -> Option<&Arc<dyn SolverPlugin>> {
        find(&self.solvers, name)
    }

    pub fn base(&self, name: &str) -> Option<&Arc<dyn BasePlugin>> {
        find(&self.bases, name)
    }

    pub fn task(&self, name: &str) -> Option<&Arc<dyn TaskPlugin>> {
        find(&self.tasks, name)
    }

    pub fn format(&self, name: &str) -> Option<&Arc<dyn FormatPlugin>> {
        find(&self.formats, name)
    }

    /// Every format, in registration order: what `--out` writes.
    pub fn formats(&self) -> &[Arc<dyn FormatPlugin>] {
        &self.formats
    }

    /// The solver `config` names, built from its options (those it leaves
    /// out at their defaults); `option` is the option that names it (where
    /// an error points).
    pub fn build_solver(
        &self,
        option: &'static str,
        config: &PluginConfig,
    ) -> Result<Box<dyn Solver>, SettingsError> {
        let plugin = self.solver(&config.name).ok_or_else(|| {
            SettingsError::invalid(option, format!("there is no solver `{}`", config.name))
        })?;
        plugin
            .build(&config.options.completed(&plugin.params()))
            .map_err(|e| SettingsError::invalid(option, format!("solver `{}`: {e}", config.name)))
    }

    /// The plugins of one kind, in registration order, as plain plugins.
    pub fn of_kind(&self, kind: PluginKind) -> Vec<&dyn Plugin> {
        match kind {
            PluginKind::Solver => self
                .solvers
                .iter()
                .map(|p| p.as_ref() as &dyn Plugin)
                .collect(),
            PluginKind::Base => self
                .bases
                .iter()
                .map(|p| p.as_ref() as &dyn Plugin)
                .collect(),
            PluginKind::Task => self
                .tasks
                .iter()
                .map(|p| p.as_ref() as &dyn Plugin)
                .collect(),
            PluginKind::Format => self
                .formats
                .iter()
                .map(|p| p.as_ref() as &dyn Plugin)
                .collect(),
            PluginKind::Standard => self
                .standards
                .iter()
                .map(|p| p.as_ref() as &dyn Plugin)
                .collect(),
        }
    }

    /// The declared parameters of plugin `name` of `kind`.
    pub fn params(&self, kind: PluginKind, name: &str) -> Option<Vec<ParamSpec>> {
        self.of_kind(kind)
            .into_iter()
            .find(|p| p.name() == name)
            .map(|p| p.params())
    }

    pub fn names(&self, kind: PluginKind) -> Vec<&'static str> {
        self.of_kind(kind).into_iter().map(|p| p.name()).collect()
    }

    /// Every plugin as a row of a Markdown table (kind, name, what it
    /// does, its options with their defaults), from the plugins' own
    /// declarations: the table of docs/language.md.
    pub fn markdown_table(&self) -> String {
        let mut out = String::from("| kind | name | what | options |\n|---|---|---|---|\n");
        for kind in PluginKind::ALL {
            for p in self.of_kind(kind) {
                let options: Vec<String> = p.params().iter().map(option_words).collect();
                let options = match options.is_empty() {
                    true => "none".to_string(),
                    false => options.join(", "),
                };
                let doc = p.doc().replace('|', "\\|");
                out.push_str(&format!(
                    "| {} | `{}` | {doc} | {options} |\n",
                    kind.noun(),
                    p.name()
                ));
            }
        }
        out
    }
}

/// An option in a table's words: `` `tolerance` 10mm ``, `` `at` (required) ``.
fn option_words(param: &ParamSpec) -> String {
    let value = match &param.default {
        Some(v) => v.display(),
        None if param.optional => "(optional)".to_string(),
        None => "(required)".to_string(),
    };
    format!("`{}` {}", param.name, value.replace('|', "\\|"))
}
