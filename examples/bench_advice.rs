//! Advice at the size the advice issue asks for: PEOPLE manual wheelchair
//! users (std::populations), reaching with either hand, advising the
//! height of a wall-mounted microwave in a kitchen with a door, at 61
//! heights (700 to 1600 mm in 15 mm steps). Prints the bracketed scan's
//! wall time; with `full`, a full scan's too (a solve at every height for
//! every person), and whether the two agree within one step (as many
//! people reach each height, and the served ranges' ends).
//!
//! `cargo run --release --example bench_advice -- [PEOPLE] [full]`
//! (1000 people, bracketed only, by default).

use std::time::Instant;

use reach::plugin::Registry;
use reach::report::{AdviceReport, TaskReport};
use reach::{Input, Limits};

fn scenario(people: usize, scan: &str) -> String {
    format!(
        "units mm deg
use std::populations
room kitchen {{
  size 3600 x 3000 x 2500
  door entrance at (3600, 1500) width 900mm
  box counter at (0, 0, 0) size (600, 2400, 900)
  box wall_cabinet at (0, 0, 1450) size (350, 2400, 700)
  box microwave       at (0, 2500, 1000) size (400, 500, 300)
  box microwave_shelf at (0, 2500, 980)  size (450, 500, 20)
  target microwave_handle at (420, 2950, 1150)
}}
population users = manual_wheelchair_users {{ size {people} seed 1 }}
advise microwave_handle by users {{
  carries [microwave, microwave_shelf]
  along z from 700mm to 1600mm step 15mm
  scan {scan}
}}
"
    )
}

/// The advice, the run's wall time (s) and its solver work.
fn run(text: &str) -> (AdviceReport, f64, u64) {
    let registry = Registry::builtin();
    let limits = Limits {
        solver_work: 1000 * Limits::default().solver_work,
        solver_starts: 1000 * Limits::default().solver_starts,
        ..Limits::default()
    };
    let session = reach::Session::default().limits(limits);
    let name = "bench_advice.reach";
    let (_, checked) = session.check(Input::Text { name, text }, &registry);
    let scenario = checked.unwrap_or_else(|d| panic!("{}", d.render(false)));
    let start = Instant::now();
    let ran = session
        .run(&scenario)
        .expect("within the bound on solver work");
    let seconds = start.elapsed().as_secs_f64();
    let (report, work) = (ran.report, ran.work);
    let TaskReport::Advice(advice) = &report.tasks[0] else {
        panic!("not an advice: {:?}", report.tasks[0])
    };
    (advice.as_ref().clone(), seconds, work)
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let people: usize = args.iter().find_map(|a| a.parse().ok()).unwrap_or(1000);
    let full = args.iter().any(|a| a == "full");
    let (bracketed, seconds, work) = run(&scenario(people, "bracketed"));
    println!(
        "bracketed: {people} people x {} heights in {seconds:.2} s ({work} units of work); served {}",
        bracketed.points.len(),
        ranges(&bracketed)
    );
    if full {
        let (all, seconds, work) = run(&scenario(people, "full"));
        println!(
            "full: {people} people x {} heights in {seconds:.2} s ({work} units of work); served {}",
            all.points.len(),
            ranges(&all)
        );
        let same_counts = (bracketed.points.iter().zip(&all.points))
            .filter(|(a, b)| a.reached != b.reached)
            .count();
        let ends_within_a_step = bracketed.ranges.len() == all.ranges.len()
            && (bracketed.ranges.iter().zip(&all.ranges)).all(|(a, b)| {
                (a.from_mm - b.from_mm).abs() <= all.step_mm
                    && (a.to_mm - b.to_mm).abs() <= all.step_mm
            });
        println!(
            "agree: {} heights reached by another number of people; ranges' ends within one step: {ends_within_a_step}",
            same_counts
        );
    }
}

fn ranges(a: &AdviceReport) -> String {
    let each: Vec<String> = (a.ranges.iter())
        .map(|r| format!("{}-{} mm", r.from_mm, r.to_mm))
        .collect();
    if each.is_empty() {
        "nowhere".into()
    } else {
        each.join(", ")
    }
}
