//! Plausible postures first: a reach keeps a posture with the target
//! behind the person (more than 110 degrees round from the way the base
//! faces) only where no placement facing it reaches, and says so.

use proptest::prelude::*;
use reach::plugin::Registry;
use reach::report::{ReachReport, TaskReport};
use reach::Input;

/// The reach of the first task of `text`.
fn reach_of(text: &str) -> ReachReport {
    let registry = Registry::builtin();
    let (_, checked) = reach::check(
        Input::Text {
            name: "facing.reach",
            text,
        },
        &registry,
    );
    let scenario = checked.map_err(|d| d.render(false)).unwrap();
    let report = reach::run(&scenario).unwrap();
    match &report.tasks[0] {
        TaskReport::Reach(r) => r.clone(),
        other => panic!("not a reach: {other:?}"),
    }
}

/// How far round from the way the base faces the target is, in degrees.
fn bearing_deg(r: &ReachReport) -> f64 {
    let b = &r.base;
    let (dx, dy) = (r.target_mm[0] - b.x_mm, r.target_mm[1] - b.y_mm);
    let off = dy.atan2(dx).to_degrees() - b.heading_deg;
    (off + 540.0).rem_euclid(360.0) - 180.0
}

/// The reception desk of `../shared/cases/reception.reach`: the man in a
/// manual wheelchair was shown reaching the sign-in tablet with his back
/// to the counter, the arm stretched back behind him.
#[test]
fn a_wheelchair_user_reaches_the_tablet_facing_the_counter() {
    let r = reach_of(
        "units mm deg\nuse std::people\nroom reception {\n  size 5000 x 4000 x 2700\n  \
         box low_top at (2400, 2100, 720) size (600, 900, 40)\n  \
         box low_panel at (2950, 2100, 0) size (50, 900, 720)\n  \
         box high_counter at (2400, 1000, 0) size (600, 1100, 1070)\n  \
         target tablet at (2480, 2550, 780)\n}\n\
         person sam { mannequin man_50th_seated base manual_wheelchair }\n\
         reach tablet by sam\n",
    );
    assert!(r.ok, "{r:?}");
    assert!(
        !r.behind && bearing_deg(&r).abs() <= 110.0,
        "{:?} {}",
        r.base,
        bearing_deg(&r)
    );
}

/// A person whose base may not turn, with the target behind: where the
/// target is reached, the answer says it was reached facing away.
#[test]
fn a_target_reached_only_behind_says_so() {
    let r = reach_of(
        "units mm deg\nuse std::people\nroom r {\n  size 4000 x 4000 x 2500\n  \
         target cup at (1750, 2000, 1200)\n}\n\
         person p { mannequin man_50th base fixed { at (2000, 2000, 930) heading 0deg } }\n\
         reach cup by p\n",
    );
    assert!(r.ok, "{r:?}");
    assert!(r.behind, "{r:?}");
    assert_eq!(r.verdict(), "reachable, only facing away");
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 8, ..ProptestConfig::default() })]

    /// In an open room a wheelchair may face any target: what is reached
    /// is never reached behind the person.
    #[test]
    fn in_an_open_room_no_target_is_reached_behind(
        angle_deg in 0.0f64..360.0,
        out_mm in 300.0f64..700.0,
        height_mm in 500.0f64..1300.0,
    ) {
        let (x, y) = (
            2000.0 + out_mm * angle_deg.to_radians().cos(),
            2000.0 + out_mm * angle_deg.to_radians().sin(),
        );
        let r = reach_of(&format!(
            "units mm deg\nuse std::people\nroom r {{\n  size 4000 x 4000 x 2500\n  \
             target t at ({x:.1}, {y:.1}, {height_mm:.1})\n}}\n\
             person p {{ mannequin woman_5th_seated base manual_wheelchair }}\n\
             reach t by p\n"
        ));
        prop_assert!(!r.behind, "{:?} bearing {}", r.base, bearing_deg(&r));
    }
}
