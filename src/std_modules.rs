//! The standard library's texts: the `.reach` modules under `stdlib/`,
//! embedded in the binary and loaded with `use std::NAME`, and the listing
//! `reach stdlib` prints. (`stdlib.rs`, above the checker, gives their
//! mannequins checked.)

pub use crate::std_texts::{module, MODULES};

/// What `reach stdlib` prints: each module with the first line of its
/// comment and, by kind, the names it declares (mannequins with their
/// parameters, the plugin a base preset configures).
pub fn listing() -> String {
    MODULES
        .iter()
        .map(|(name, text)| format!("{}\n", entry(name, text)))
        .collect()
}

/// Module `name`'s part of the listing: its name, the first line of its
/// comment, and the names it declares by kind.
pub fn entry(name: &str, text: &str) -> String {
    use crate::syntax::ast::Item;
    let mut out = format!("std::{name}\n  {}\n", summary(name, text));
    let Ok(file) = crate::syntax::parse_file(crate::span::FileId::default(), text) else {
        return out;
    };
    let mut kinds: Vec<(&str, Vec<String>)> =
        ["mannequins", "profiles", "bases", "visions", "populations"]
            .into_iter()
            .map(|k| (k, Vec::new()))
            .collect();
    for item in &file.items {
        let (k, entry) = match item {
            Item::Mannequin(m) => (0, mannequin_entry(m)),
            Item::Profile(p) => (1, p.name.value.clone()),
            Item::BasePreset(b) => (2, format!("{} ({})", b.name.value, b.plugin.name.value)),
            Item::VisionPreset(v) => (3, v.name.value.clone()),
            Item::Population(p) => (4, p.name.value.clone()),
            _ => continue,
        };
        kinds[k].1.push(entry);
    }
    for (kind, names) in kinds.iter().filter(|(_, n)| !n.is_empty()) {
        out.push_str(&format!("  {kind}: {}\n", names.join(", ")));
    }
    out
}

/// The start of the module's opening comment, up to its first colon or
/// full stop, without the module's name.
fn summary(name: &str, text: &str) -> String {
    let comment: Vec<&str> = text
        .lines()
        .map_while(|l| l.strip_prefix("//"))
        .map(str::trim)
        .collect();
    let joined = comment.join(" ");
    let joined = joined
        .strip_prefix(&format!("std::{name}:"))
        .unwrap_or(&joined)
        .trim();
    // Up to the first colon or full stop.
    let end = [joined.find(':'), joined.find(". ").map(|i| i + 1)]
        .into_iter()
        .flatten()
        .min()
        .unwrap_or(joined.len());
    joined[..end].trim_end_matches('.').to_string()
}

/// `name`, `name(p1, p2)` or `name = other(args)`.
fn mannequin_entry(m: &crate::syntax::ast::MannequinDecl) -> String {
    let name = &m.name.value;
    let params: Vec<&str> = m.params.iter().map(|(n, _)| n.value.as_str()).collect();
    if let (Some(alias), false) = (&m.alias, params.is_empty()) {
        // Its own parameters are what a user gives.
        return format!(
            "{name}({}) (= {}(...))",
            params.join(", "),
            alias.name.value
        );
    }
    if let Some(alias) = &m.alias {
        let args: Vec<&str> = alias.args.iter().map(|(n, _)| n.value.as_str()).collect();
        return format!("{name} (= {}({}))", alias.name.value, args.join(", "));
    }
    if params.is_empty() {
        return name.clone();
    }
    format!("{name}({})", params.join(", "))
}
