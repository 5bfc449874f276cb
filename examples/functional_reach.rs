//! Standing forward reach against measured people (docs/calibration.md,
//! "Standing forward reach"): Duncan et al.'s *functional reach* (1990)
//! taken on std::people's standing people as `src/functional_reach.rs`
//! takes it, beside the measured means.
//!
//! `cargo run --release --example functional_reach` (a few seconds).

use reach::functional_reach::functional_reach;
use reach::stdlib;

const PEOPLE: [(&str, &str); 3] = [
    ("woman_5th", "women 372 (57) | women 350 (55)"),
    ("man_50th", "men 425 (49) | men 379 (56)"),
    ("man_95th", "men 425 (49) | men 379 (56)"),
];

fn main() {
    println!("| person | arm forward (mm ahead of the ankles) | farthest reached | functional reach | measured, aged 20-40: mean (SD) | aged 41-69 |");
    println!("|---|---:|---:|---:|---:|---:|");
    for (name, measured) in PEOPLE {
        let body = stdlib::body("people", name).unwrap_or_else(|d| panic!("{}", d.render(false)));
        let r = functional_reach(name, &body).unwrap_or_else(|e| panic!("{name}: {e:?}"));
        println!(
            "| {name} | {:.0} | {:.0} | **{:.0}** | {measured} |",
            r.arm_forward_mm,
            r.farthest_mm,
            r.reach_mm()
        );
    }
}
