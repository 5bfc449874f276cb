//! What an editor asks of a scenario (the language server, `reach lsp`,
//! is its client): the names its files declare and use (`outline.rs`),
//! what may be typed at a place (`complete.rs`) and what a name, an
//! option or a number is (`hover.rs`), which places a rename changes and
//! whether the new name may be (`rename.rs`), and a run's answers at the
//! lines that asked for them (`verdicts.rs`). The protocol itself is the
//! binary's.

mod complete;
mod hover;
mod outline;
mod rename;
mod verdicts;

pub use complete::{completions, Completion, CompletionKind};
pub use hover::hover;
pub use outline::{
    Found, OptionName, OptionOwner, Outline, PluginName, Reference, Symbol, SymbolKind, UseOf,
};
pub use rename::{may_rename_to, renamed_at, written_at, RenameRefused};
pub use verdicts::{unmet, verdicts, Unmet, Verdict};

pub use crate::syntax::ast::UseTarget;

use crate::error::Diagnostics;
use crate::scenario::Scenario;
use crate::source::Sources;

/// One check of a scenario as an editor holds it: its files, the outline
/// of their names (none where a file does not parse) and the scenario
/// checked, or what is wrong with it.
pub struct Analysis {
    pub sources: Sources,
    pub outline: Option<Outline>,
    pub checked: Result<Scenario, Diagnostics>,
}
