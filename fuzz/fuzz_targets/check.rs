//! Fuzz the parser and checker, and run what checks, maps and gaze maps
//! included, within a small bound on solver starts (so that one input
//! cannot take minutes; beyond it the input is refused, which exercises the
//! bound): no input may panic, and every diagnostic's span must lie inside
//! the text.
#![no_main]

use libfuzzer_sys::fuzz_target;
use reach::plugin::Registry;
use reach::{Input, Limits};

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else { return };
    let registry = Registry::builtin();
    let limits = Limits { solver_starts: 2_000, ..Limits::default() };
    let input = Input::Text { name: "fuzz.reach", text };
    let (sources, checked) = reach::Session::default().limits(limits).check(input, &registry);
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
        Ok(scenario) => {
            let _ = reach::run(&scenario);
        }
    }
});
