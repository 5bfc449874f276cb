//! What the retry where obstacles block buys, and what it costs: the maps
//! of `examples/kitchen_wheelchair.reach` (one start per placement, so
//! that boards block often) run with no retry, with the retry by
//! `incremental` at several numbers of starts, by `fabrik`, and with
//! collisions off (an upper bound: what the arm reaches if boards were
//! not there). Prints a Markdown table: points reached over all maps, the
//! seated user's `shelf_3.top` and `wall_cab_bottom.top`, and the time.
//!
//! `cargo run --release --example bench_retry`; `-- --tiny` runs the
//! first two rows and the last (CI runs it so, to see it run).

use std::time::Instant;

use std::sync::Arc;

use reach::plugin::{Options, ParamSpec, PluginConfig, Registry, Value};
use reach::report::TaskReport;
use reach::scenario::Scenario;
use reach::{Input, Limits};

/// One row: a label, the retries and the retry solver with its starts and
/// whether it steers clear (`None`: collisions off).
type Setting = (&'static str, i64, Option<(&'static str, i64, bool)>);

const SETTINGS: [Setting; 10] = [
    ("no retry", 0, Some(("incremental", 1, false))),
    (
        "incremental { starts 8 }, 4 placements",
        4,
        Some(("incremental", 8, false)),
    ),
    (
        "incremental { starts 32 }, 4 placements",
        4,
        Some(("incremental", 32, false)),
    ),
    (
        "incremental { starts 64 }, 4 placements",
        4,
        Some(("incremental", 64, false)),
    ),
    (
        "incremental { starts 8 steer_clear true }, 4 placements (default)",
        4,
        Some(("incremental", 8, true)),
    ),
    (
        "incremental { starts 16 steer_clear true }, 4 placements",
        4,
        Some(("incremental", 16, true)),
    ),
    (
        "incremental { starts 32 steer_clear true }, 4 placements",
        4,
        Some(("incremental", 32, true)),
    ),
    (
        "incremental { starts 64 steer_clear true }, 16 placements",
        16,
        Some(("incremental", 64, true)),
    ),
    (
        "fabrik (defaults: 4 starts), 4 placements",
        4,
        Some(("fabrik", 4, false)),
    ),
    ("collisions off (upper bound)", 0, None),
];

fn main() {
    let registry = Registry::builtin();
    // The hardest rows search far more than a run may by default.
    let limits = Limits {
        solver_work: 20 * Limits::default().solver_work,
        ..Limits::default()
    };
    let (_, checked) = reach::Session::default().limits(limits).check(
        Input::Path("examples/kitchen_wheelchair.reach".as_ref()),
        &registry,
    );
    let mut scenario = checked.expect("the example checks");
    scenario.tasks.retain(|t| t.kind == "map");
    println!("Maps of examples/kitchen_wheelchair.reach ({} maps), `solver incremental {{ starts 1 }}`\n", scenario.tasks.len());
    println!("| retry | points reached | ann shelf_3.top | ann wall_cab_bottom.top | time s |");
    println!("|---|---:|---:|---:|---:|");
    let tiny = std::env::args().any(|a| a == "--tiny");
    let rows = SETTINGS
        .iter()
        .enumerate()
        .filter(|&(i, _)| !tiny || i < 2 || i == SETTINGS.len() - 1);
    for (_, &(label, retries, solver)) in rows {
        let variant = with_retry(&scenario, &registry, retries, solver);
        let start = Instant::now();
        let report = reach::run(&variant).expect("within the bound on solver work");
        let seconds = start.elapsed().as_secs_f64();
        let maps: Vec<_> = report
            .tasks
            .iter()
            .filter_map(|t| match t {
                TaskReport::Map(m) => Some(m),
                _ => None,
            })
            .collect();
        let total: usize = maps.iter().map(|m| m.reachable).sum();
        let points: usize = maps.iter().map(|m| m.points).sum();
        let of = |surface: &str| {
            maps.iter()
                .find(|m| m.name == surface && m.person == "ann")
                .map(|m| format!("{} of {}", m.reachable, m.points))
                .unwrap_or_default()
        };
        println!(
            "| {label} | {total} of {points} | {} | {} | {seconds:.2} |",
            of("shelf_3.top"),
            of("wall_cab_bottom.top")
        );
    }
}

/// The scenario with every task's retry set (or collisions off): each map
/// configured again from its options so changed.
fn with_retry(
    scenario: &Scenario,
    registry: &Registry,
    retries: i64,
    solver: Option<(&str, i64, bool)>,
) -> Scenario {
    let map = registry.task("map").expect("built in");
    let params = map.params();
    let mut variant = scenario.clone();
    for task in &mut variant.tasks {
        let mut options = task.options.clone();
        match solver {
            Some((name, starts, steer)) => {
                let plugin = registry.solver(name).expect("built in");
                let solver_params = plugin.params();
                let mut solver_options = Options::defaults(&solver_params)
                    .set(option(&solver_params, "starts"), Value::Integer(starts));
                if steer {
                    solver_options = solver_options
                        .set(option(&solver_params, "steer_clear"), Value::Bool(true));
                }
                let config = PluginConfig {
                    name: name.to_string(),
                    options: solver_options,
                };
                options = options
                    .set(option(&params, "blocked_solver"), Value::Plugin(config))
                    .set(option(&params, "blocked_retries"), Value::Integer(retries));
            }
            None => options = options.set(option(&params, "collisions"), Value::Bool(false)),
        }
        task.task = Arc::from(map.configure(&options, registry).expect("valid options"));
        task.options = options;
    }
    variant
}

/// The declared name of parameter `name`.
fn option(params: &[ParamSpec], name: &str) -> &'static str {
    params
        .iter()
        .find(|p| p.name == name)
        .map(|p| p.name)
        .expect("a declared option")
}
