//! The standard library: `.reach` modules under `stdlib/`, embedded in the
//! binary and loaded with `use std::NAME`.

/// Every module, by name, in the order `reach stdlib` lists them.
pub const MODULES: &[(&str, &str)] = &[
    ("arm", include_str!("../stdlib/arm.reach")),
    ("paper", include_str!("../stdlib/paper.reach")),
];

/// The text of module `name`, if there is one.
pub fn module(name: &str) -> Option<&'static str> {
    MODULES
        .iter()
        .find(|(n, _)| *n == name)
        .map(|(_, text)| *text)
}
