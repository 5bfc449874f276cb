//! Populations at the size the populations issue asks for: PEOPLE manual
//! wheelchair users (std::populations) against a kitchen counter with 20
//! targets (each reach with the chair's placement), and the same people
//! mapping a 100-point counter front. Prints each row's wall time; run it
//! under `/usr/bin/time -v` for the peak memory. The `door` row: the same
//! people reaching 20 targets in a kitchen of 30 boxes, with a door and
//! without, and what the door costs a member and target (in work and in
//! time).
//!
//! `cargo run --release --example bench_population -- [reach|map|door] [PEOPLE]`
//! (the three rows and 1000 people by default).

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

/// A 5 x 4 m kitchen of 30 boxes (counters and wall cabinets along two
/// walls, an island, a table with chairs, a fridge, a tall cabinet, a bin
/// and a plant), its door in the far wall where `door`, and 20 targets on
/// the long counter and above it.
fn kitchen(door: bool, people: usize) -> String {
    let mut text = String::from(
        "units mm deg\nuse std::populations\nroom kitchen {\n  size 5000 x 4000 x 2500\n",
    );
    let mut boxes = Vec::new();
    for k in 0..6 {
        let y = 600.0 * f64::from(k);
        boxes.push(([0.0, y, 0.0], [600.0, 600.0, 900.0]));
        boxes.push(([0.0, y, 1400.0], [350.0, 600.0, 700.0]));
    }
    for k in 0..4 {
        let x = 1000.0 + 600.0 * f64::from(k);
        boxes.push(([x, 0.0, 0.0], [600.0, 600.0, 900.0]));
        boxes.push(([x, 0.0, 1400.0], [600.0, 350.0, 700.0]));
    }
    boxes.push(([2000.0, 1700.0, 0.0], [1200.0, 800.0, 900.0]));
    boxes.push(([3600.0, 2600.0, 720.0], [1000.0, 800.0, 40.0]));
    for (x, y) in [
        (3500.0, 2450.0),
        (4250.0, 2450.0),
        (3500.0, 3250.0),
        (4250.0, 3250.0),
    ] {
        boxes.push(([x, y, 0.0], [400.0, 400.0, 450.0]));
    }
    boxes.push(([0.0, 3600.0, 0.0], [700.0, 400.0, 1800.0]));
    boxes.push(([4600.0, 0.0, 0.0], [400.0, 600.0, 2100.0]));
    boxes.push(([1000.0, 700.0, 0.0], [300.0, 300.0, 600.0]));
    boxes.push(([4600.0, 3600.0, 0.0], [400.0, 400.0, 1200.0]));
    for (k, (at, size)) in boxes.iter().enumerate() {
        text.push_str(&format!(
            "  box b{k} at ({}, {}, {}) size ({}, {}, {})\n",
            at[0], at[1], at[2], size[0], size[1], size[2]
        ));
    }
    assert_eq!(boxes.len(), 30);
    for (k, y) in [500, 1100, 1700, 2300, 2900].into_iter().enumerate() {
        for (row, (x, z)) in [(300, 950), (300, 1250), (100, 950), (550, 1000)]
            .into_iter()
            .enumerate()
        {
            text.push_str(&format!(
                "  target t{} at ({x}, {y}, {z})\n",
                row * 5 + k + 1
            ));
        }
    }
    if door {
        text.push_str("  door hall at (2500, 4000) width 900mm\n");
    }
    let names: Vec<String> = (1..=20).map(|k| format!("t{k}")).collect();
    text.push_str(&format!(
        "}}\npopulation users = manual_wheelchair_users {{ size {people} seed 1 }}\nreach {} by users\n",
        names.join(", ")
    ));
    text
}

/// `text` checked and run within a hundred times the default bound on solver
/// work (1,000 people with 20 targets each need more than the default
/// allows: the searches of those who do not reach a target cost the
/// most): its report, its work and its wall time from the start of the
/// check.
fn run(name: &str, text: &str) -> (reach::report::Report, u64, f64, f64) {
    let registry = Registry::builtin();
    let start = Instant::now();
    let limits = reach::Limits {
        solver_work: 100 * reach::Limits::default().solver_work,
        ..reach::Limits::default()
    };
    let session = reach::Session::default().limits(limits);
    let (_, checked) = session.check(Input::Text { name, text }, &registry);
    let scenario = match checked {
        Ok(s) => s,
        Err(d) => {
            eprintln!("{}", d.render(false));
            std::process::exit(1);
        }
    };
    let checked_s = start.elapsed().as_secs_f64();
    let ran = session
        .run(&scenario)
        .expect("within the bound on solver work");
    (
        ran.report,
        ran.work,
        checked_s,
        start.elapsed().as_secs_f64(),
    )
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let kinds: Vec<&str> = match args.first().map(String::as_str) {
        Some(k @ ("reach" | "map" | "door")) => vec![k],
        _ => vec!["reach", "map", "door"],
    };
    let people: usize = args.iter().find_map(|a| a.parse().ok()).unwrap_or(1000);
    for kind in kinds {
        if kind == "door" {
            door_row(people);
            continue;
        }
        let text = scenario(kind, people);
        let (report, _, checked_s, total_s) = run("bench_population.reach", &text);
        let answers = report.answers();
        let shares: Vec<String> = answers.iter().map(|a| a.verdict.clone()).collect();
        println!(
            "{kind}: {people} people, {} tasks: check {checked_s:.2} s, total {total_s:.2} s; first answer {}",
            answers.len(),
            shares.first().map_or("-", String::as_str)
        );
    }
}

/// The kitchen of 30 boxes without its door, then with it: each run's
/// time and work, a member and target's, and the door's cost as the ratio.
fn door_row(people: usize) {
    let mut figures = Vec::new();
    for door in [false, true] {
        let (report, work, _, total_s) = run("bench_population_door.reach", &kitchen(door, people));
        let each = (people * 20) as f64;
        let reached: Vec<String> = report
            .answers()
            .iter()
            .take(3)
            .map(|a| a.verdict.clone())
            .collect();
        println!(
            "door {}: {people} people x 20 targets in a kitchen of 30 boxes: total {total_s:.2} s, {work} units; a member and target {:.3} ms, {:.0} units; first answers {}",
            if door { "yes" } else { "no" },
            1000.0 * total_s / each,
            work as f64 / each,
            reached.join("; ")
        );
        figures.push((total_s, work as f64));
    }
    println!(
        "the door costs {:.2}x the time and {:.2}x the work",
        figures[1].0 / figures[0].0,
        figures[1].1 / figures[0].1
    );
}
