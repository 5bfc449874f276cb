//! Fuzz URDF loading: the bytes become a mannequin's chain (root `a`, tip
//! `b`), checked and run within a small bound on solver starts. No input
//! may panic or hang; a chain that loads must give a report.
#![no_main]

use libfuzzer_sys::fuzz_target;
use reach::plugin::Registry;
use reach::{Input, Limits};

const SCENARIO: &str = "units mm deg
mannequin arm from urdf \"fuzz-scratch/m.urdf\" root \"a\" tip \"b\"
room r { size 3000 x 3000 x 2500 target cup at (1300, 1300, 1200) }
person p { mannequin arm base fixed { at (1000, 1500, 930) } }
reach cup by p { solver incremental { starts 2 } blocked_retries 1 }
";

fuzz_target!(|data: &[u8]| {
    std::fs::create_dir_all("fuzz-scratch").unwrap();
    std::fs::write("fuzz-scratch/m.urdf", data).unwrap();
    let registry = Registry::builtin();
    let limits = Limits { solver_starts: 2_000, ..Limits::default() };
    let input = Input::Text { name: "urdf.reach", text: SCENARIO };
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
