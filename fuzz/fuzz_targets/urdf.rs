//! Fuzz URDF loading: the bytes become a mannequin's chain (root `a`, tip
//! `b`), checked and run within a small bound on solver starts. No input
//! may panic or hang; a chain that loads must give a report.
#![no_main]

use libfuzzer_sys::fuzz_target;

#[path = "data_file.rs"]
mod data_file;

const SCENARIO: &str = "units mm deg
mannequin arm from urdf \"fuzz-scratch/m.urdf\" root \"a\" tip \"b\"
room r { size 3000 x 3000 x 2500 target cup at (1300, 1300, 1200) }
person p { mannequin arm base fixed { at (1000, 1500, 930) } }
reach cup by p { solver incremental { starts 2 } blocked_retries 1 }
";

fuzz_target!(|data: &[u8]| {
    data_file::check_with("m.urdf", data, "urdf.reach", SCENARIO);
});
