//! Fuzz OBJ loading: the bytes become a mesh in a room that a person
//! reaches into, checked and run within a small bound on solver starts. No
//! input may panic or hang; a mesh that loads must give a report.
#![no_main]

use libfuzzer_sys::fuzz_target;

#[path = "data_file.rs"]
mod data_file;

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
    data_file::check_with("m.obj", data, "obj.reach", SCENARIO);
});
