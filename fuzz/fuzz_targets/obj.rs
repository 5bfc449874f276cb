//! Fuzz OBJ loading: the bytes become a mesh in a room that a person
//! reaches into, checked and run within a small bound on solver starts. No
//! input may panic or hang; a mesh that loads must give a report.
#![no_main]

use libfuzzer_sys::fuzz_target;
use reach::plugin::Registry;
use reach::{Input, Limits};

const SCENARIO: &str = "units mm deg
use std::arm
room r {
  size 3000 x 3000 x 2500
  mesh m from \"fuzz-scratch/m.obj\" at (600, 1200, 800) scale 100
  target mug at (700, 1400, 1000)
}
person p { mannequin right_arm base fixed { at (1000, 1500, 930) heading 180deg } }
reach mug by p { solver incremental { starts 2 } blocked_retries 1 }
";

fuzz_target!(|data: &[u8]| {
    // Text input reads files from the working directory and below.
    std::fs::create_dir_all("fuzz-scratch").unwrap();
    std::fs::write("fuzz-scratch/m.obj", data).unwrap();
    let registry = Registry::builtin();
    let limits = Limits { solver_starts: 2_000, ..Limits::default() };
    let input = Input::Text { name: "obj.reach", text: SCENARIO };
    let (_, checked) = reach::check_within(input, &registry, &limits);
    match checked {
        Err(diagnostics) => {
            let _ = diagnostics.render(true);
        }
        Ok(scenario) => {
            let report = reach::run(&scenario);
            assert_eq!(report.tasks.len(), 1);
        }
    }
});
