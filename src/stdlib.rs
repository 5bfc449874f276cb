//! The standard library's mannequins, checked as a scenario would check
//! them, for programs, tests and benchmarks (the module texts themselves
//! are in `std_modules.rs`, below the loader that reads them).

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
