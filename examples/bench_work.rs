//! The meter of solver work (`reach::meter`) against the clock: for each
//! scenario file given (the examples by default), the work its run did,
//! the wall time, and the work per millisecond. The bound on solver work
//! (`--max-solver-work`) is chosen from the slowest rate this prints, so
//! that what the default admits finishes in about 10 s on this machine
//! (docs/benchmarks.md, "Solver work"). Beside it, what `reach check
//! --estimate` says the run needs, and how long the estimate took.
//!
//! `cargo run --release --example bench_work -- [FILE.reach ...]`

use std::path::PathBuf;
use std::time::Instant;

use reach::limits::CEILINGS;
use reach::plugin::Registry;
use reach::{Input, Limits};

fn main() {
    let mut files: Vec<PathBuf> = std::env::args().skip(1).map(PathBuf::from).collect();
    if files.is_empty() {
        let mut examples: Vec<PathBuf> = std::fs::read_dir("examples")
            .expect("run from the crate's directory")
            .filter_map(|e| e.ok().map(|e| e.path()))
            .filter(|p| p.extension().is_some_and(|x| x == "reach"))
            .collect();
        examples.sort();
        files = examples;
    }
    let registry = Registry::builtin();
    // Every limit at its ceiling: this measures, it does not refuse.
    let limits = Limits {
        solver_starts: CEILINGS.solver_starts,
        solver_work: CEILINGS.solver_work,
        ..Limits::default()
    };
    println!("| scenario | work (units) | seconds | units per ms | estimated (95 %) | estimate's seconds |");
    println!("|---|---|---|---|---|---|");
    for file in files {
        let check = || {
            let (_, checked) = reach::Session::default()
                .limits(limits)
                .check(Input::Path(&file), &registry);
            checked.ok()
        };
        let Some(scenario) = check() else {
            println!("| {} | does not check | | | | |", file.display());
            continue;
        };
        // On a scenario of its own: a base keeps what it works out.
        let started = Instant::now();
        let estimated =
            check().map(|s| s.estimate_work(&reach::progress::NoProgress, CEILINGS.solver_work));
        let estimate_seconds = started.elapsed().as_secs_f64();
        let (units, half) = estimated.map(|e| e.total()).unwrap_or_default();
        let started = Instant::now();
        let ran = reach::Session::default()
            .run(&scenario)
            .map(|ran| (ran.report, ran.work));
        let seconds = started.elapsed().as_secs_f64();
        let work = ran.map(|(_, w)| w).unwrap_or_default();
        println!(
            "| {} | {work} | {seconds:.3} | {:.0} | {units} ± {half} | {estimate_seconds:.3} |",
            file.display(),
            work as f64 / (seconds * 1000.0)
        );
    }
}
