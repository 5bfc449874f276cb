//! Advice (`advise`): the bracketed scan answers as a full scan of every
//! position does (as many people reach each position), in a kitchen with
//! a door, manual wheelchair users reaching with either hand; a person's advice is where
//! their own reach answers yes, and over random kitchens it counts the
//! people a population's reach of each position counts (the advice's
//! search passes over placements proved out of reach, the reach's does
//! not); expectations on advice are judged; bad
//! advice options are diagnostics at the option.

use proptest::prelude::*;
use reach::report::{AdviceReport, Report, TaskReport};

use crate::body::run;

/// The start of the kitchen of `examples/advice.reach`: its size, door
/// and counter (the room's block left open).
const KITCHEN: &str = "units mm deg
use std::people
use std::populations
limits { solver_work 2e9 }
room kitchen {
  size 3600 x 3000 x 2500
  door entrance at (3600, 1500) width 900mm
  box counter at (0, 0, 0) size (600, 2400, 900)
";

/// The kitchen of `examples/advice.reach`, its microwave advised by
/// `who` with `options`.
fn kitchen(people: &str, who: &str, options: &str) -> String {
    format!(
        "{KITCHEN}  box microwave       at (0, 2500, 1000) size (400, 500, 300)
  box microwave_shelf at (0, 2500, 980)  size (450, 500, 20)
  target microwave_handle at (420, 2950, 1150)
}}
{people}
advise microwave_handle by {who} {{ carries [microwave, microwave_shelf] {options} }}
"
    )
}

fn advices(report: &Report) -> Vec<&AdviceReport> {
    (report.tasks.iter())
        .map(|t| match t {
            TaskReport::Advice(a) => a.as_ref(),
            other => panic!("not an advice: {other:?}"),
        })
        .collect()
}

const USERS: &str = "population users = manual_wheelchair_users { size 6 seed 5 }";

#[test]
fn a_bracketed_scan_answers_as_a_full_scan_of_every_position() {
    let along = "along z from 700mm to 1700mm step 50mm";
    let (_, bracketed) = run(&kitchen(USERS, "users", &format!("{along} scan bracketed")));
    let (_, full) = run(&kitchen(USERS, "users", &format!("{along} scan full")));
    let (b, f) = (advices(&bracketed), advices(&full));
    let counts = |a: &AdviceReport| a.points.iter().map(|p| p.reached).collect::<Vec<_>>();
    assert_eq!(counts(b[0]), counts(f[0]));
    assert_eq!(b[0].ranges, f[0].ranges);
    // Someone drops out within the scan: the test is of a real edge.
    assert!(counts(f[0]).iter().any(|&c| c < 6), "{:?}", counts(f[0]));
    assert_eq!((b[0].scan, f[0].scan), ("bracketed", "full"));
}

#[test]
fn a_persons_advice_is_where_their_own_reach_answers_yes() {
    let ann = "person ann { mannequin woman_5th_seated base manual_wheelchair }";
    let along = "along z from 900mm to 1700mm step 100mm scan full";
    let (_, report) = run(&kitchen(ann, "ann", along));
    let advice = advices(&report)[0];
    assert_eq!((advice.people, advice.serves), (1, 1.0));
    for point in &advice.points {
        // The same kitchen with the element put there by hand.
        let dz = point.at_mm - 1150.0;
        let text = kitchen(ann, "ann", along)
            .replace(
                "at (0, 2500, 1000) size (400",
                &format!("at (0, 2500, {}) size (400", 1000.0 + dz),
            )
            .replace("at (0, 2500, 980)", &format!("at (0, 2500, {})", 980.0 + dz))
            .replace("(420, 2950, 1150)", &format!("(420, 2950, {})", point.at_mm))
            .replace("advise microwave_handle by ann {", "reach microwave_handle by ann {")
            .replace("carries [microwave, microwave_shelf] along z from 900mm to 1700mm step 100mm scan full", "");
        let (_, alone) = run(&text);
        let TaskReport::Reach(r) = &alone.tasks[0] else {
            panic!()
        };
        assert_eq!(r.ok, point.reached == 1, "at {} mm", point.at_mm);
        if !r.ok && point.verdict.is_some() {
            assert_eq!(point.verdict.as_deref(), Some(r.verdict().as_str()));
        }
    }
    assert!(advice.points.iter().any(|p| p.reached == 0));
    assert!(advice.points.iter().any(|p| p.reached == 1));
}

#[test]
fn an_expectation_on_advice_holds_only_where_every_position_serves() {
    let ann = "person ann { mannequin woman_5th_seated base manual_wheelchair }";
    let along = "along z from 900mm to 1700mm step 100mm";
    let text = kitchen(ann, "ann", along)
        + "expect advise microwave_handle serves 100 % between 1000mm and 1200mm\n"
        + "expect advise microwave_handle serves 100 % between 1000mm and 1700mm\n"
        + "expect advise microwave_handle serves 100 % between 600mm and 1000mm\n";
    let (_, report) = run(&text);
    let met: Vec<bool> = report.expectations.iter().map(|e| e.met).collect();
    assert_eq!(met, [true, false, false], "{:?}", report.expectations);
    assert!(report.expectations[1].because.contains("does NOT reach it"));
    assert!(report.expectations[2]
        .because
        .contains("scans 900-1700 mm only"));
}

/// A cart with a cup on it, moved along the wall with the kitchen's door.
const CART: &str = "units mm deg
use std::people
room kitchen {
  size 3600 x 3000 x 2500
  door entrance at (3600, 1500) width 900mm
  box cart at (3150, 200, 0) size (450, 700, 750)
  target cup at (3350, 550, 760)
}
person ann { mannequin woman_5th_seated base manual_wheelchair }
advise cup by ann { carries cart along y from 550mm to 2450mm step 100mm scan full }
";

#[test]
fn a_cart_moved_in_front_of_the_door_shuts_the_chair_out_there_only() {
    // The floor is another at each position where the element meets the
    // chair's footprint: here where the cart stands before the door.
    let (_, report) = run(CART);
    let advice = advices(&report)[0];
    let shut = "the base cannot get in from a door with it there";
    for point in &advice.points {
        // The cart is 700 mm long along y, its cup in the middle; the
        // door spans 1050-1950 mm. Clear of the door, the chair gets in;
        // across its middle, it cannot (between, it depends on the
        // chair's width).
        let (near, far) = (point.at_mm - 350.0, point.at_mm + 350.0);
        if far <= 1050.0 || near >= 1950.0 {
            assert_eq!(point.reached, 1, "at {} mm", point.at_mm);
        }
        if near <= 1500.0 && 1500.0 <= far {
            assert_eq!(point.reached, 0, "at {} mm", point.at_mm);
        }
    }
    let ends: Vec<_> = (advice.ranges.iter())
        .flat_map(|r| [&r.low_end, &r.high_end])
        .flatten()
        .collect();
    assert!(!ends.is_empty());
    for end in ends {
        assert_eq!(end.because[0].verdict, shut, "{end:?}");
    }
}

#[test]
fn the_page_draws_the_element_where_it_serves_the_most() {
    let (scenario, report) = run(CART);
    let advice = advices(&report)[0];
    let best = advice.best.as_ref().expect("ann reaches the cup somewhere");
    let view = reach::output::view::view_data(&report, &scenario.format_scene());
    let task = &view.tasks[0];
    let advised = task
        .advised
        .as_ref()
        .expect("the cup where it serves the most");
    assert_eq!(advised.at, [3350.0, best.at_mm, 760.0]);
    // The cart, moved as the cup is: its centre 350 mm along from its
    // corner, the cup in its middle.
    let [cart] = task.solids.as_slice() else {
        panic!("one box drawn: {}", task.solids.len())
    };
    let json = serde_json::to_value(cart).unwrap();
    assert_eq!(json["centre"][1].as_f64(), Some(best.at_mm));
    assert_eq!(json["half"][1].as_f64(), Some(350.0));
}

#[test]
fn an_element_declared_before_the_door_is_advised_as_one_declared_clear_of_it() {
    // Declared where it shuts the chair out, the cart is still moved to
    // every position, and each answers as before.
    let (_, clear) = run(CART);
    let before_the_door = CART
        .replace("cart at (3150, 200, 0)", "cart at (3150, 1150, 0)")
        .replace("cup at (3350, 550, 760)", "cup at (3350, 1500, 760)");
    let (_, shut) = run(&before_the_door);
    let reached = |r: &Report| -> Vec<(f64, usize)> {
        (advices(r)[0].points.iter())
            .map(|p| (p.at_mm, p.reached))
            .collect()
    };
    assert_eq!(reached(&shut), reached(&clear));
    assert_eq!(advices(&shut)[0].declared_mm, 1500.0);
}

/// `CART`'s cup advised over a grid: along the wall with the door, and
/// at three distances from it.
fn cart_grid(scan: &str) -> String {
    CART.replace(
        "along y from 550mm to 2450mm step 100mm scan full",
        &format!(
            "along y from 550mm to 2350mm step 300mm across x across_from 2350mm across_to 3350mm across_step 500mm scan {scan}"
        ),
    )
}

#[test]
fn each_line_of_a_grid_answers_as_a_line_with_the_element_declared_there() {
    let (_, grid) = run(&cart_grid("bracketed"));
    let grid = advices(&grid)[0];
    assert_eq!(grid.rows.len(), 3);
    for row in &grid.rows {
        let across = row.across.as_ref().expect("a line of the grid");
        let dx = across.at_mm - 3350.0;
        let line = CART
            .replace(
                "cart at (3150, 200, 0)",
                &format!("cart at ({}, 200, 0)", 3150.0 + dx),
            )
            .replace(
                "cup at (3350, 550, 760)",
                &format!("cup at ({}, 550, 760)", across.at_mm),
            )
            .replace("step 100mm scan full", "step 300mm")
            .replace("2450mm", "2350mm");
        let (_, alone) = run(&line);
        let alone = advices(&alone)[0];
        let answers = |a: &AdviceReport| -> Vec<(f64, usize, Option<String>)> {
            (a.points.iter())
                .map(|p| (p.at_mm, p.reached, p.verdict.clone()))
                .collect()
        };
        assert_eq!(answers(row), answers(alone), "at x {} mm", across.at_mm);
        assert_eq!(row.ranges, alone.ranges, "at x {} mm", across.at_mm);
    }
    // Away from the wall with the door, the cart no longer shuts the
    // chair out: somewhere the lines differ.
    let reached =
        |k: usize| -> Vec<usize> { grid.rows[k].points.iter().map(|p| p.reached).collect() };
    assert!(
        reached(0) != reached(2),
        "{:?} {:?}",
        reached(0),
        reached(2)
    );
    // The grid is told by its line that serves the most.
    let best = grid.best.as_ref().expect("reached somewhere");
    let most = |r: &AdviceReport| r.points.iter().filter(|p| p.reached > 0).count();
    assert!(grid.rows.iter().all(|r| most(r) <= most(grid)));
    assert!(grid.best_target_mm().is_some_and(|at| at[1] == best.at_mm));
}

#[test]
fn a_population_s_grid_asks_why_at_each_line_s_own_positions() {
    let people = "population users = manual_wheelchair_users { size 4 seed 5 }";
    let grid = "along z from 700mm to 1700mm step 100mm across y across_from 2450mm across_to 2950mm across_step 250mm";
    let text = kitchen(people, "users", grid)
        + "expect advise microwave_handle serves 100 % between 1000mm and 1100mm\n"
        + "expect advise microwave_handle serves 100 % between 700mm and 1700mm\n";
    let (_, report) = run(&text);
    let advice = advices(&report)[0];
    assert_eq!(advice.rows.len(), 3);
    // The last line is the element as declared (y 2950 mm): the same as
    // the advice along one line.
    let (_, line) = run(&kitchen(
        people,
        "users",
        "along z from 700mm to 1700mm step 100mm",
    ));
    let line = advices(&line)[0];
    let row = &advice.rows[2];
    assert_eq!(row.points, line.points);
    assert_eq!(row.ranges, line.ranges);
    assert!(
        line.ranges
            .iter()
            .any(|r| r.low_end.is_some() || r.high_end.is_some()),
        "someone drops out within the scan: the test is of a real end"
    );
    let met: Vec<bool> = report.expectations.iter().map(|e| e.met).collect();
    assert_eq!(met, [true, false], "{:?}", report.expectations);
    assert!(
        report.expectations[1]
            .because
            .starts_with("no line across serves it"),
        "{:?}",
        report.expectations[1]
    );
}

#[test]
fn a_grid_has_a_picture_and_a_table_of_its_own() {
    let (scenario, report) = run(&cart_grid("bracketed"));
    let grid = advices(&report)[0];
    let registry = reach::plugin::Registry::builtin();
    let format = registry.format("advice").expect("the advice format");
    let files = format.files(&report, &scenario.format_scene());
    let names: Vec<&str> = files.iter().map(|(n, _)| n.as_str()).collect();
    assert_eq!(
        names,
        ["advice-grid-cup-yx-ann.svg", "advice-grid-cup-yx-ann.csv"]
    );
    let csv = String::from_utf8(files[1].1.clone()).unwrap();
    let lines: Vec<&str> = csv.lines().collect();
    assert_eq!(lines[0], "x_mm,y_mm,reached,share");
    // A line per position: 3 across, 7 along.
    assert_eq!(lines.len(), 1 + 3 * 7);
    let reached = (grid.rows.iter().flat_map(|r| &r.points)).filter(|p| p.reached > 0);
    let listed = lines[1..].iter().filter(|l| l.ends_with(",1,1"));
    assert_eq!(reached.count(), listed.count());
    let svg = String::from_utf8(files[0].1.clone()).unwrap();
    // A cell per position, each saying who reaches it there.
    assert_eq!(svg.matches("<title>y ").count(), 3 * 7, "{svg}");
    assert!(svg.contains("serves the most: y "), "{svg}");
}

#[test]
fn an_advice_in_a_room_the_chair_fits_nowhere_in_says_so() {
    // Too narrow for the chair with or without the shelf: the room, not
    // where the shelf goes, keeps it out, and the answer says so.
    let text = "units mm deg
use std::people
room hall {
  size 700 x 1000 x 2500
  box shelf at (0, 100, 1000) size (300, 400, 20)
  target jar at (250, 300, 1060)
}
person bob { mannequin man_50th_seated base manual_wheelchair }
advise jar by bob { carries shelf along x from 100mm to 400mm step 150mm }
";
    let (_, report) = run(text);
    let TaskReport::NotPlaced(not) = &report.tasks[0] else {
        panic!("not placed: {:?}", report.tasks[0])
    };
    assert!(!not.ok);
    assert!(
        report.tasks[0].answer().verdict.contains("NOT fit"),
        "{:?}",
        report.tasks[0].answer()
    );
}

proptest! {
    #![proptest_config(ProptestConfig {
        cases: 10,
        rng_seed: proptest::test_runner::RngSeed::Fixed(61),
        ..ProptestConfig::default()
    })]

    /// An advice asks at each position whether people reach, without why,
    /// and its search passes over placements a proof puts out of reach;
    /// a population's reach asks each member why, and searches them all.
    /// Both must count the same people at a point of a random kitchen.
    #[test]
    fn an_advice_counts_the_people_a_reach_of_each_position_counts(
        x_mm in 100.0..3400.0f64,
        y_mm in 100.0..2900.0f64,
        z_mm in 950.0..1750.0f64,
        seed in 0u64..1000,
    ) {
        let (x_mm, y_mm, z_mm) = (x_mm.round(), y_mm.round(), z_mm.round());
        let above_mm = z_mm + 150.0;
        let room = format!(
            "{KITCHEN}  box island at (1500, 900, 0) size (900, 1000, 900)
  target low at ({x_mm}, {y_mm}, {z_mm})
  target high at ({x_mm}, {y_mm}, {above_mm})
}}
population users = manual_wheelchair_users {{ size 3 seed {seed} }}
"
        );
        let advice = format!(
            "{room}advise low by users {{ along z from {z_mm}mm to {above_mm}mm step 150mm scan full }}\n"
        );
        let (_, advised) = run(&advice);
        let (_, reached) = run(&format!("{room}reach low, high by users\n"));
        let counts: Vec<usize> = (reached.tasks.iter())
            .map(|t| match t {
                TaskReport::Population(p) => p.accommodated,
                other => panic!("not a population's reach: {other:?}"),
            })
            .collect();
        let points: Vec<usize> = advices(&advised)[0].points.iter().map(|p| p.reached).collect();
        prop_assert_eq!(points, counts, "at ({}, {}, {}) and 150 mm above", x_mm, y_mm, z_mm);
    }
}
