//! `reach test` over SCENARIOS files (100 by default): variants of
//! examples/flat_12.reach (its wall cabinet and kettle moved a little in
//! each; its counter map left out, so that a file is a kitchen's reaches
//! and sights), in a temporary directory. Prints the time to write their
//! golden reports (`--update`), then to test them against those reports
//! on one thread and on every core.
//!
//! `cargo run --release --example bench_suite -- [SCENARIOS]`

use std::path::PathBuf;
use std::time::Instant;

use reach::plugin::Registry;
use reach::suite::{discover, run_suite, Outcome, SuiteOptions};

/// Scenario `k`: the cabinet `k` mm lower and the kettle `k` mm along.
fn variant(flat_12: &str, k: usize) -> String {
    flat_12
        .replace(
            "box wall_cabinet at (0, 0, 1500)",
            &format!("box wall_cabinet at (0, 0, {})", 1500 - k),
        )
        .replace(
            "target kettle      at (300, 1000, 960)",
            &format!("target kettle      at (300, {}, 960)", 1000 + 3 * k),
        )
        .lines()
        .filter(|l| !l.starts_with("map ") && !l.contains(" covers "))
        .collect::<Vec<_>>()
        .join("\n")
}

fn timed(
    label: &str,
    threads: usize,
    roots: &[PathBuf],
    options: &SuiteOptions,
    registry: &Registry,
) -> Vec<Outcome> {
    let scenarios = discover(roots).expect("the scenarios are there");
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .expect("a thread pool");
    let start = Instant::now();
    let outcomes = pool.install(|| run_suite(&scenarios, roots, options, registry));
    let seconds = start.elapsed().as_secs_f64();
    let passed = outcomes.iter().filter(|o| o.passed()).count();
    println!(
        "{label:<24} {threads} thread(s): {seconds:6.2} s  ({passed} of {} passed)",
        outcomes.len()
    );
    outcomes
}

fn main() {
    let count: usize = std::env::args()
        .nth(1)
        .and_then(|a| a.parse().ok())
        .unwrap_or(100);
    let flat_12 = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/examples/flat_12.reach"
    ))
    .expect("examples/flat_12.reach");
    let dir = tempfile::tempdir().expect("a temporary directory");
    for k in 0..count {
        let path = dir.path().join(format!("flat_{k:03}.reach"));
        std::fs::write(path, variant(&flat_12, k)).expect("written");
    }
    let registry = Registry::builtin();
    let roots = vec![dir.path().to_path_buf()];
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    let update = SuiteOptions {
        update: true,
        ..SuiteOptions::default()
    };
    let outcomes = timed("update (write goldens)", cores, &roots, &update, &registry);
    let answers: usize = outcomes.iter().map(|o| o.answers).sum();
    let expectations: usize = outcomes.iter().map(|o| o.expectations.len()).sum();
    println!("{count} scenarios, {answers} answers, {expectations} expectations");
    let test = SuiteOptions::default();
    timed("test", 1, &roots, &test, &registry);
    timed("test", cores, &roots, &test, &registry);
}
