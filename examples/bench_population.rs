//! Populations at the size the populations issue asks for: PEOPLE manual
//! wheelchair users (std::populations) against a kitchen counter with 20
//! targets (each reach with the chair's placement), and the same people
//! mapping a 100-point counter front. Prints each row's wall time; run it
//! under `/usr/bin/time -v` for the peak memory.
//!
//! `cargo run --release --example bench_population -- [reach|map] [PEOPLE]`
//! (both rows and 1000 people by default).

use std::time::Instant;

use reach::plugin::Registry;
use reach::Input;

const ROOM: &str = "units mm deg
use std::populations
room kitchen {
  size 4000 x 3000 x 2500
  box counter at (0, 0, 0) size (600, 3000, 900)
  surface counter_front at (600, 500, 300) size (0, 2000, 500)
";

/// 20 targets on and over the counter and on its front.
fn targets() -> String {
    let mut out = String::new();
    for (k, y) in [500, 1000, 1500, 2000, 2500].into_iter().enumerate() {
        for (row, (x, z)) in [(300, 950), (300, 1250), (100, 950), (620, 400)]
            .into_iter()
            .enumerate()
        {
            out.push_str(&format!(
                "  target t{} at ({x}, {y}, {z})\n",
                row * 5 + k + 1
            ));
        }
    }
    out
}

fn scenario(kind: &str, people: usize) -> String {
    let population =
        format!("population users = manual_wheelchair_users {{ size {people} seed 1 }}\n");
    let task = match kind {
        "map" => "map counter_front by users { step 100mm }\n".to_string(),
        _ => {
            let names: Vec<String> = (1..=20).map(|k| format!("t{k}")).collect();
            format!("reach {} by users\n", names.join(", "))
        }
    };
    format!("{ROOM}{}}}\n{population}{task}", targets())
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let kinds: Vec<&str> = match args.first().map(String::as_str) {
        Some(k @ ("reach" | "map")) => vec![k],
        _ => vec!["reach", "map"],
    };
    let people: usize = args.iter().find_map(|a| a.parse().ok()).unwrap_or(1000);
    let registry = Registry::builtin();
    for kind in kinds {
        let text = scenario(kind, people);
        let start = Instant::now();
        // Ten times the default bound on solver work: 1,000 people with 20
        // targets each need more than the default allows (the searches of
        // those who do not reach a target cost the most).
        let limits = reach::Limits {
            solver_work: 10 * reach::Limits::default().solver_work,
            ..reach::Limits::default()
        };
        let input = Input::Text {
            name: "bench_population.reach",
            text: &text,
        };
        let (_, checked) = reach::Session::default()
            .limits(limits)
            .check(input, &registry);
        let scenario = match checked {
            Ok(s) => s,
            Err(d) => {
                eprintln!("{}", d.render(false));
                std::process::exit(1);
            }
        };
        let checked_s = start.elapsed().as_secs_f64();
        let report = reach::run(&scenario).expect("within the bound on solver work");
        let total_s = start.elapsed().as_secs_f64();
        let answers = report.answers();
        let shares: Vec<String> = answers.iter().map(|a| a.verdict.clone()).collect();
        println!(
            "{kind}: {people} people, {} tasks: check {checked_s:.2} s, total {total_s:.2} s; first answer {}",
            answers.len(),
            shares.first().map_or("-", String::as_str)
        );
    }
}
