//! IK benchmark on the accessibility paper's 21-DOF chain (`std::paper`),
//! after the protocol used to compare IK solvers in robotics (TRAC-IK):
//! targets are the forward kinematics of random postures within the joint
//! limits (fixed seed), position only, tolerance 0.5 units (5 mm); the time
//! per solve includes failures.
//!
//! `cargo run --release --example bench_ik [-- --json] [--solves N] [--set OPTION=VALUE ...]
//! [--only-incremental | --only-upper-body]`
//!
//! `--set` changes an option of the two `incremental` rows (numbers and
//! true/false; lengths in mm), to try other settings.
//!
//! Prints a markdown table (and with `--json` one JSON object per line):
//! the paper's variants A-F of its table 1 beside the paper's own figures,
//! `incremental` with its defaults (one start, and with restarts), `dls`,
//! and the Jacobian solver of the `k` crate on the same chain and targets.

use std::time::Instant;

use nalgebra::Point3;
use rand_chacha::rand_core::SeedableRng;
use rand_chacha::ChaCha8Rng;
use reach::kinematics::Chain;
use reach::plugin::{IkProblem, Options, ParamKind, Settings, Solver, Value};
use reach::solvers::random_posture;
use reach::solvers::{
    DlsSolver, FabrikSettings, FabrikSolver, IncrementalSettings, IncrementalSolver,
};

/// The paper's tolerance: 0.5 units, taken as centimetres.
const TOLERANCE_MM: f64 = 5.0;
const TARGET_SEED: u64 = 2026;

mod upper_body;

/// One row of results.
struct Row {
    solver: String,
    dof: usize,
    /// How many effectors each solve brings to a target.
    effectors: usize,
    solves: usize,
    success: f64,
    mean_us: f64,
    median_us: f64,
    mean_iterations: Option<f64>,
    /// In the paper's units (cm).
    mean_error: f64,
}

/// The paper's own figures (table 1): mean ms, mean error, mean iterations.
const PAPER: [(&str, f64, f64, f64); 5] = [
    ("paper-A", 42.0, 0.51, 23.2),
    ("paper-B", 34.0, 0.51, 23.2),
    ("paper-C", 7.2, 0.51, 24.2),
    ("paper-D", 6.1, 0.51, 23.2),
    ("paper-F", 8.0, 0.43, 25.5),
];

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let json = args.iter().any(|a| a == "--json");
    let solves = args
        .iter()
        .position(|a| a == "--solves")
        .and_then(|i| args.get(i + 1))
        .map(|n| n.parse().expect("--solves takes a number"))
        .unwrap_or(10_000);

    let overrides: Vec<(String, String)> = args
        .iter()
        .enumerate()
        .filter(|(_, a)| *a == "--set")
        .filter_map(|(i, _)| args.get(i + 1)?.split_once('='))
        .map(|(k, v)| (k.to_string(), v.to_string()))
        .collect();
    let only_ours = args.iter().any(|a| a == "--only-incremental");
    let only_upper = args.iter().any(|a| a == "--only-upper-body");
    if only_upper {
        let upper = upper_body::rows(solves);
        return if json {
            print_json(&upper)
        } else {
            upper_body::print_table(&upper)
        };
    }

    let chain = paper_chain();
    let targets = targets(&chain, solves);
    let mut rows = Vec::new();
    for (name, solver) in our_solvers(&overrides) {
        if only_ours && !name.starts_with("incremental") {
            continue;
        }
        rows.push(measure(&name, &targets, |i, target| {
            let s = solver.solve(&IkProblem {
                chain: &chain,
                target_mm: *target,
                tolerance_mm: TOLERANCE_MM,
                seed: i as u64,
                obstacles: None,
                allowance: &reach::allowance::Unbounded,
            });
            (s.distance_mm, Some(s.iterations as f64))
        }));
    }
    if !only_ours {
        rows.push(k_row("k-default", &chain, &targets, 10, 1));
        rows.push(k_row("k-fair", &chain, &targets, 100, 10));
    }
    let upper = if only_ours {
        Vec::new()
    } else {
        upper_body::rows(solves)
    };
    print_rows(&rows, json, &chain);
    if json {
        print_json(&upper);
    } else if !upper.is_empty() {
        upper_body::print_table(&upper);
    }
}

/// The paper's chain from the standard library.
fn paper_chain() -> Chain {
    reach::stdlib::chain("paper", "paper21").expect("std::paper checks")
}

/// Effector positions of random postures within the limits.
fn targets(chain: &Chain, n: usize) -> Vec<Point3<f64>> {
    let mut rng = ChaCha8Rng::seed_from_u64(TARGET_SEED);
    (0..n)
        .map(|_| chain.effector(&random_posture(chain, &mut rng)))
        .collect()
}

/// The variants of the paper's table 1 and our solvers, by row name.
fn our_solvers(overrides: &[(String, String)]) -> Vec<(String, Box<dyn Solver>)> {
    let defaults = incremental_with(overrides);
    // The paper's algorithm and cost model: one random start, fixed
    // increments, the second direction tried only after the first.
    let paper = IncrementalSettings {
        starts: 1,
        neutral_start: false,
        grow: 1.0,
        shrink: 1.0,
        eager_pair: false,
        ..defaults
    };
    // Variants A-D: constant rate 0.015, stop when a sweep no longer improves.
    let constant = IncrementalSettings {
        rate: 0.015,
        gamma: 1.0,
        threshold_mm: 0.0,
        stall: 1,
        stall_ratio: 0.0,
        ..paper
    };
    let variant = |sign_memory: bool, incremental_fk: bool| IncrementalSettings {
        sign_memory,
        incremental_fk,
        ..constant
    };
    // Variant F: rate 0.5, divided by 3 when a sweep improves less than 0.1 units.
    let f = IncrementalSettings {
        rate: 0.5,
        gamma: 3.0,
        threshold_mm: 1.0,
        stall: 1_000_000,
        ..paper
    };
    let incremental = |settings| Box::new(IncrementalSolver::new(settings)) as Box<dyn Solver>;
    vec![
        ("A", variant(false, false)),
        ("B", variant(true, false)),
        ("C", variant(false, true)),
        ("D", variant(true, true)),
        ("F", f),
        (
            "incremental",
            IncrementalSettings {
                starts: 1,
                ..defaults
            },
        ),
        ("incremental-restarts", defaults),
    ]
    .into_iter()
    .map(|(name, settings)| (name.to_string(), incremental(settings)))
    .chain(std::iter::once((
        "dls".to_string(),
        Box::new(DlsSolver::with_defaults()) as Box<dyn Solver>,
    )))
    .chain(fabrik_rows())
    .collect()
}

/// `incremental`'s defaults with the `--set OPTION=VALUE` overrides, read
/// through its declared parameters as a scenario's would be.
fn incremental_with(overrides: &[(String, String)]) -> IncrementalSettings {
    let params = IncrementalSettings::params();
    let mut options = Options::defaults(&params);
    for (name, text) in overrides {
        let Some(spec) = params.iter().find(|p| p.name == name) else {
            panic!("--set {name}: incremental has no such option");
        };
        let value = match spec.kind {
            ParamKind::Number => Value::Number(text.parse().expect("a number")),
            ParamKind::Length => Value::Length(text.parse().expect("a length in mm")),
            ParamKind::Integer => Value::Integer(text.parse().expect("a whole number")),
            ParamKind::Bool => Value::Bool(text.parse().expect("true or false")),
            _ => panic!("--set {name}: not a number or bool option of incremental"),
        };
        options = options.set(spec.name, value);
    }
    IncrementalSettings::from_options(&options).expect("the overrides are valid")
}

/// `fabrik` with one start and with its default restarts.
fn fabrik_rows() -> Vec<(String, Box<dyn Solver>)> {
    let defaults = FabrikSettings::with_defaults();
    let fabrik = |settings| Box::new(FabrikSolver { settings }) as Box<dyn Solver>;
    vec![
        (
            "fabrik".to_string(),
            fabrik(FabrikSettings {
                starts: 1,
                ..defaults
            }),
        ),
        ("fabrik-restarts".to_string(), fabrik(defaults)),
    ]
}

/// Time `solve` on every target; it returns the distance left (mm) and the
/// iterations, if the solver reports them.
fn measure(
    name: &str,
    targets: &[Point3<f64>],
    mut solve: impl FnMut(usize, &Point3<f64>) -> (f64, Option<f64>),
) -> Row {
    let mut times_us = Vec::with_capacity(targets.len());
    let (mut ok, mut error_sum, mut iterations_sum) = (0usize, 0.0, Some(0.0));
    for (i, target) in targets.iter().enumerate() {
        let start = Instant::now();
        let (distance_mm, iterations) = solve(i, target);
        times_us.push(start.elapsed().as_secs_f64() * 1e6);
        ok += usize::from(distance_mm <= TOLERANCE_MM);
        error_sum += distance_mm / 10.0;
        iterations_sum = iterations_sum.zip(iterations).map(|(s, n)| s + n);
    }
    let n = targets.len() as f64;
    times_us.sort_by(f64::total_cmp);
    Row {
        solver: name.to_string(),
        dof: 21,
        effectors: 1,
        solves: targets.len(),
        success: ok as f64 / n,
        mean_us: times_us.iter().sum::<f64>() / n,
        median_us: times_us[times_us.len() / 2],
        mean_iterations: iterations_sum.map(|s| s / n),
        mean_error: error_sum / n,
    }
}

/// The `k` crate's Jacobian solver: `tries` iterations per solve, and up to
/// `starts` starts (the neutral posture, then seeded random ones).
fn k_row(name: &str, chain: &Chain, targets: &[Point3<f64>], tries: usize, starts: usize) -> Row {
    use k::InverseKinematicsSolver;
    let arm = k_chain(chain);
    let solver = k::JacobianIkSolver::new(TOLERANCE_MM, f64::MAX, 0.5, tries);
    let constraints = k::Constraints {
        rotation_x: false,
        rotation_y: false,
        rotation_z: false,
        ..Default::default()
    };
    measure(name, targets, |i, target| {
        let mut rng = ChaCha8Rng::seed_from_u64(i as u64);
        let goal = k::Isometry3::translation(target.x, target.y, target.z);
        for s in 0..starts {
            let start = if s == 0 {
                chain.neutral()
            } else {
                random_posture(chain, &mut rng)
            };
            arm.set_joint_positions_clamped(&start);
            if solver
                .solve_with_constraints(&arm, &goal, &constraints)
                .is_ok()
            {
                break;
            }
        }
        let q = arm.joint_positions();
        ((chain.effector(&q) - target).norm(), None)
    })
}

/// The chain as `k` nodes: joint i turns about its z axis after the fixed
/// part of link i-1 (`Tz(d) Tx(a) Rx(alpha)`) and its own theta offset; the
/// effector is a fixed node at the end.
fn k_chain(chain: &Chain) -> k::SerialChain<f64> {
    use k::nalgebra as kna;
    let fixed_part = |dh: &reach::kinematics::Dh| {
        kna::Isometry3::from_parts(
            kna::Translation3::new(dh.a_mm, 0.0, dh.d_mm),
            kna::UnitQuaternion::from_axis_angle(&kna::Vector3::x_axis(), dh.alpha_rad()),
        )
    };
    let mut previous = kna::Isometry3::identity();
    let mut nodes: Vec<k::Node<f64>> = Vec::new();
    for joint in &chain.joints {
        assert_eq!(
            joint.kind,
            reach::kinematics::JointKind::Revolute,
            "the paper's chain is revolute"
        );
        let offset =
            kna::UnitQuaternion::from_axis_angle(&kna::Vector3::z_axis(), joint.dh.theta_rad);
        let node = k::NodeBuilder::new()
            .name(&joint.name)
            .joint_type(k::JointType::Rotational {
                axis: kna::Vector3::z_axis(),
            })
            .limits(Some(k::joint::Range::new(joint.min, joint.max)))
            .origin(previous * kna::Isometry3::from_parts(kna::Translation3::identity(), offset))
            .into_node();
        if let Some(parent) = nodes.last() {
            node.set_parent(parent);
        }
        nodes.push(node);
        previous = fixed_part(&joint.dh);
    }
    let e = chain.effector_mm;
    let end = k::NodeBuilder::new()
        .name("effector")
        .origin(previous * kna::Isometry3::translation(e.x, e.y, e.z))
        .into_node();
    end.set_parent(nodes.last().expect("a chain has joints"));
    k::SerialChain::from_end(&end)
}

/// One JSON line, fields in the documented order.
#[derive(serde::Serialize)]
struct JsonRow<'a> {
    solver: &'a str,
    dof: usize,
    effectors: usize,
    solves: usize,
    success: Option<f64>,
    mean_us: f64,
    median_us: Option<f64>,
    mean_iterations: Option<f64>,
    mean_error: f64,
    #[serde(skip_serializing_if = "Option::is_none")]
    source: Option<&'static str>,
}

/// One JSON object per line for each row.
fn print_json(rows: &[Row]) {
    for r in rows {
        let row = JsonRow {
            solver: &r.solver,
            dof: r.dof,
            effectors: r.effectors,
            solves: r.solves,
            success: Some(r.success),
            mean_us: r.mean_us,
            median_us: Some(r.median_us),
            mean_iterations: r.mean_iterations,
            mean_error: r.mean_error,
            source: None,
        };
        println!("{}", serde_json::to_string(&row).expect("plain numbers"));
    }
}

fn print_rows(rows: &[Row], json: bool, chain: &Chain) {
    if json {
        print_json(rows);
        for (name, ms, error, iterations) in PAPER {
            let row = JsonRow {
                solver: name,
                dof: chain.dof(),
                effectors: 1,
                solves: 10_000,
                success: None,
                mean_us: ms * 1000.0,
                median_us: None,
                mean_iterations: Some(iterations),
                mean_error: error,
                source: Some("the paper's table 1, Pentium 4 3.4 GHz"),
            };
            println!("{}", serde_json::to_string(&row).expect("plain numbers"));
        }
        return;
    }
    println!(
        "IK on the paper's {}-DOF chain; {} targets; tolerance 0.5 units (5 mm); {}",
        chain.dof(),
        rows[0].solves,
        machine()
    );
    println!();
    println!("| solver | success | mean µs | median µs | mean sweeps | mean error (units) | paper: mean µs, sweeps, error |");
    println!("|---|---:|---:|---:|---:|---:|---|");
    for r in rows {
        let paper = PAPER
            .iter()
            .find(|(name, ..)| name.strip_prefix("paper-") == Some(r.solver.as_str()))
            .map(|(_, ms, error, it)| format!("{:.0}, {it}, {error}", ms * 1000.0))
            .unwrap_or_default();
        let iterations = r
            .mean_iterations
            .map(|m| format!("{m:.1}"))
            .unwrap_or_else(|| "-".into());
        println!(
            "| {} | {:.2} % | {:.2} | {:.2} | {} | {:.3} | {} |",
            r.solver,
            r.success * 100.0,
            r.mean_us,
            r.median_us,
            iterations,
            r.mean_error,
            paper
        );
    }
}

/// The processor, for the record.
fn machine() -> String {
    let cpu = std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with("model name"))
                .map(|l| l.split(':').nth(1).unwrap_or("").trim().to_string())
        })
        .unwrap_or_else(|| "unknown processor".into());
    let cores = std::thread::available_parallelism()
        .map(|n| n.get())
        .unwrap_or(1);
    format!("{cpu}, {cores} cores, one thread")
}
