//! The structure of the accessibility paper's table 2: the same targets
//! reached with a point base, a circular base (a trolley) and a rectangular
//! base (a wheelchair) that also turns. Targets are 1,000 seeded random
//! points on the counter top, the tall cabinet's front and the island top
//! of `examples/kitchen_wheelchair.reach`; the chain is `std::arm`; each
//! reach is placed as a map places it (first reaching placement).
//!
//! `cargo run --release --example bench_bases [-- --targets N]`

use std::time::Instant;

use nalgebra::Point3;
use rand_chacha::rand_core::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use reach::bases::{Mobile, Placing};
use reach::floor::Footprint;
use reach::plugin::{PreparedBase, ReachQuery, Registry, Search, Settings};
use reach::scene::{OwnBody, Room};
use reach::solvers::{IncrementalSettings, IncrementalSolver};
use reach::Input;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let n = args
        .iter()
        .position(|a| a == "--targets")
        .and_then(|i| args.get(i + 1))
        .map(|v| v.parse().expect("--targets takes a number"))
        .unwrap_or(1000);
    let registry = Registry::builtin();
    let (_, checked) = reach::check(
        Input::Path("examples/kitchen_wheelchair.reach".as_ref()),
        &registry,
    );
    let scenario = checked.expect("the example checks");
    let room = &scenario.rooms[0];
    let chain = reach::stdlib::chain("arm", "right_arm").expect("std::arm");
    let targets = targets(room, n);
    let solver = IncrementalSolver::new(IncrementalSettings {
        starts: 1,
        ..IncrementalSettings::with_defaults()
    });

    // The paper's bases are outlines on the floor as tall as the person
    // (1.4 m seated, 2 m standing), with no body of their own.
    let mobile = |footprint, hip_height_mm| {
        Mobile::new(
            footprint,
            hip_height_mm,
            Placing::all_round(16),
            OwnBody::default(),
        )
    };
    let bases = [
        ("point base", mobile(Footprint::circle(1.0, 2000.0), 930.0)),
        (
            "circular base (trolley, r 450 mm)",
            mobile(Footprint::circle(450.0, 2000.0), 930.0),
        ),
        (
            "rectangular base (wheelchair, turning)",
            mobile(Footprint::rectangle(650.0, 565.0, 660.0, 1400.0), 595.0),
        ),
    ];
    println!("Reach with a moving base, std::arm, {n} targets on kitchen surfaces, tolerance 10 mm, one start per placement\n");
    println!("| base | success | mean µs | median µs | mean sweeps | paper (P4 3.4 GHz) |");
    println!("|---|---:|---:|---:|---:|---|");
    let paper = [
        "1.25 ms, 1.47 sweeps",
        "1.34 ms, 1.02 sweeps",
        "2.9 ms, 1.49 sweeps",
    ];
    let own = OwnBody::default();
    for ((name, base), paper) in bases.iter().zip(paper) {
        let prepared = base.prepare(room, &chain, &reach::allowance::Unbounded);
        let (mut ok, mut sweeps) = (0usize, 0u64);
        let mut times = Vec::with_capacity(n);
        for (i, t) in targets.iter().enumerate() {
            let query = ReachQuery {
                target_room_mm: *t,
                tolerance_mm: 10.0,
                seed: i as u64,
                search: Search::FirstReaching,
                obstacles: None,
                own: &own,
                retry: None,
                proofs: None,
                last_resort: None,
                from_rest: true,
                descents: None,
                allowance: &reach::allowance::Unbounded,
                solves: None,
            };
            let start = Instant::now();
            let placement = prepared.reach(&query, &solver);
            times.push(start.elapsed().as_secs_f64() * 1e6);
            ok += usize::from(placement.solution.distance_mm <= 10.0);
            sweeps += placement.solution.iterations;
        }
        let mean = times.iter().sum::<f64>() / n as f64;
        times.sort_by(f64::total_cmp);
        println!(
            "| {name} | {:.1} % | {mean:.1} | {:.1} | {:.2} | {paper} |",
            100.0 * ok as f64 / n as f64,
            times[n / 2],
            sweeps as f64 / n as f64,
        );
    }
}

/// Seeded random points on three surfaces of the kitchen.
fn targets(room: &Room, n: usize) -> Vec<Point3<f64>> {
    let surfaces: Vec<_> = ["back_counter.top", "tall_cabinet.front", "island.top"]
        .iter()
        .map(|s| {
            room.surface(&s.split('.').map(str::to_string).collect::<Vec<_>>())
                .expect("surface")
        })
        .collect();
    let mut rng = ChaCha8Rng::seed_from_u64(2);
    let mut unit = || (rng.next_u64() >> 11) as f64 / (1u64 << 53) as f64;
    (0..n)
        .map(|i| {
            let s = &surfaces[i % surfaces.len()];
            s.corner_mm + s.u_mm * unit() + s.v_mm * unit()
        })
        .collect()
}
