//! A reach and a map of the same point should agree: for each map of a
//! top (plan view, of reach) in a scenario, every point of its grid is
//! asked again as a `reach` target by the same person (lifted by the
//! radius of the hand, its effector's link, as the map lifts it), and
//! the points where the two answers differ are counted and listed: "map
//! only" (the map reaches it, the reach does not) and "reach only".
//! Either is a search that missed (docs/language.md, "What an unreached
//! answer means").
//!
//! `cargo run --release --example reach_vs_map -- [FILE.reach]`
//! (`examples/kitchen_wheelchair.reach` by default). The targets are put
//! into the scenario's first room, and its `reach`, `map`, `gaze` and
//! `standard` lines after the people are left out.

use reach::limits::CEILINGS;
use reach::plugin::Registry;
use reach::report::{MapReport, TaskReport};
use reach::scenario::Scenario;
use reach::{Input, Limits};

fn main() {
    let file = std::env::args()
        .nth(1)
        .unwrap_or_else(|| "examples/kitchen_wheelchair.reach".into());
    let text = std::fs::read_to_string(&file).expect("a readable scenario");
    let scenario = checked(&file, &text);
    let report = reach::run(&scenario).expect("within the ceiling on solver work");
    let (mut points, mut map_only, mut reach_only) = (0, 0, 0);
    println!("| map | person | points | map only | reach only |");
    println!("|---|---|---:|---:|---:|");
    for map in report.tasks.iter().filter_map(top_map) {
        let person = scenario.person(&map.person).expect("the map's person");
        let lift_mm = person.body.chain(0).effector_link.radius_mm;
        let targets: Vec<[f64; 3]> = map
            .cells
            .iter()
            .map(|c| [c.point_mm[0], c.point_mm[1], c.point_mm[2] + lift_mm])
            .collect();
        let reached = reaches(&file, &text, &map.person, &targets);
        let differ: Vec<(usize, bool)> = (0..targets.len())
            .filter(|&i| map.cells[i].reachable != reached[i])
            .map(|i| (i, map.cells[i].reachable))
            .collect();
        let only_map = differ.iter().filter(|(_, m)| *m).count();
        let only_reach = differ.len() - only_map;
        println!(
            "| {} | {} | {} | {only_map} | {only_reach} |",
            map.name,
            map.person,
            targets.len()
        );
        for (i, by_map) in differ {
            let who = if by_map { "map only" } else { "reach only" };
            eprintln!("  {} {}: {who} at {:?}", map.name, map.person, targets[i]);
        }
        points += targets.len();
        map_only += only_map;
        reach_only += only_reach;
    }
    println!("| all | | {points} | {map_only} | {reach_only} |");
}

/// A map of a top, of reach.
fn top_map(task: &TaskReport) -> Option<&MapReport> {
    match task {
        TaskReport::Map(m) if m.of == "reach" && m.view == "plan" => Some(m),
        _ => None,
    }
}

/// Whether `person` reaches each of `targets_mm`, put into the first room
/// of scenario `text` (its tasks left out).
fn reaches(file: &str, text: &str, person: &str, targets_mm: &[[f64; 3]]) -> Vec<bool> {
    let room_at = text.find("\nroom ").expect("a room");
    let close = room_at + text[room_at..].find("\n}").expect("the room's end");
    let targets: String = targets_mm
        .iter()
        .enumerate()
        .map(|(i, p)| format!("  target agree_{i} at ({}, {}, {})\n", p[0], p[1], p[2]))
        .collect();
    let people = &text[close..tasks_at(text)];
    let names: Vec<String> = (0..targets_mm.len())
        .map(|i| format!("agree_{i}"))
        .collect();
    let asked = format!(
        "{}\n{targets}{people}\nreach {} by {person}\n",
        &text[..close],
        names.join(", ")
    );
    let report = reach::run(&checked(file, &asked)).expect("within the ceiling on solver work");
    report
        .tasks
        .iter()
        .map(|t| match t {
            TaskReport::Reach(r) => r.ok,
            other => panic!("a reach: {other:?}"),
        })
        .collect()
}

/// Where the scenario's tasks start: its first task line after the rooms
/// and people.
fn tasks_at(text: &str) -> usize {
    [
        "\nreach ",
        "\nmap ",
        "\ngaze ",
        "\ngaze_map ",
        "\nstandard ",
    ]
    .iter()
    .filter_map(|t| text.find(t))
    .min()
    .unwrap_or(text.len())
}

/// Scenario `text` (read as `file`, for its used files), checked with
/// every limit on work at its ceiling: this measures, it does not refuse.
fn checked(file: &str, text: &str) -> Scenario {
    let limits = Limits {
        solver_starts: CEILINGS.solver_starts,
        solver_work: CEILINGS.solver_work,
        ..Limits::default()
    };
    let registry = Registry::builtin();
    let input = Input::Text { name: file, text };
    let (_, checked) = reach::Session::default()
        .limits(limits)
        .check(input, &registry);
    checked.unwrap_or_else(|d| panic!("{}", d.render(false)))
}
