//! Fuzz the parser and checker, and run what checks (reach tasks only, with
//! maps left out so that one input cannot take minutes): no input may panic,
//! and every diagnostic's span must lie inside the text.
#![no_main]

use libfuzzer_sys::fuzz_target;
use reach::plugin::Registry;
use reach::Input;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else { return };
    let registry = Registry::builtin();
    let (sources, checked) = reach::check(Input::Text { name: "fuzz.reach", text }, &registry);
    match checked {
        Err(diagnostics) => {
            for e in &diagnostics.errors {
                if let Some(span) = e.span() {
                    let file = sources.get(span.file);
                    assert!(span.start <= span.end && span.end as usize <= file.text.len(), "span outside the text");
                }
            }
            let _ = diagnostics.render(true);
        }
        Ok(mut scenario) => {
            scenario.tasks.retain(|t| t.kind != "map");
            scenario.tasks.truncate(8);
            let _ = reach::run(&scenario, &registry);
        }
    }
});
