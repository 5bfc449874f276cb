//! The standard library: `.reach` modules under `stdlib/`, embedded in the
//! binary and loaded with `use std::NAME`.

/// Every module, by name, in the order `reach stdlib` lists them.
pub const MODULES: &[(&str, &str)] = &[
    ("arm", include_str!("../stdlib/arm.reach")),
    ("body", include_str!("../stdlib/body.reach")),
    ("paper", include_str!("../stdlib/paper.reach")),
];

/// The text of module `name`, if there is one.
pub fn module(name: &str) -> Option<&'static str> {
    MODULES
        .iter()
        .find(|(n, _)| *n == name)
        .map(|(_, text)| *text)
}

/// The body of mannequin `name` of module `std::module`, checked as a
/// scenario would check it (for programs, tests and benchmarks).
pub fn body(module: &str, name: &str) -> Result<crate::kinematics::Body, crate::Diagnostics> {
    let text =
        format!("use std::{module}\nperson p {{ mannequin {name} base fixed {{ at (0, 0, 0) }} }}");
    let input = crate::Input::Text {
        name: "stdlib.reach",
        text: &text,
    };
    let (_, checked) = crate::check(input, &crate::plugin::Registry::builtin());
    checked.map(|scenario| scenario.persons[0].body.clone())
}

/// The chain to the first effector of mannequin `name` of `std::module`.
pub fn chain(module: &str, name: &str) -> Result<crate::kinematics::Chain, crate::Diagnostics> {
    body(module, name).map(|b| b.chain(0))
}
