//! Advice (`advise`): the bracketed scan answers as a full scan of every
//! position does (as many people reach each position), in a kitchen with
//! a door, manual wheelchair users reaching with either hand; a person's advice is where
//! their own reach answers yes; expectations on advice are judged; bad
//! advice options are diagnostics at the option.

use reach::report::{AdviceReport, Report, TaskReport};

use crate::body::run;

/// The kitchen of `examples/advice.reach`, its microwave advised by
/// `who` with `options`.
fn kitchen(people: &str, who: &str, options: &str) -> String {
    format!(
        "units mm deg
use std::people
use std::populations
limits {{ solver_work 2e9 }}
room kitchen {{
  size 3600 x 3000 x 2500
  door entrance at (3600, 1500) width 900mm
  box counter at (0, 0, 0) size (600, 2400, 900)
  box microwave       at (0, 2500, 1000) size (400, 500, 300)
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
