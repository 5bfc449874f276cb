//! `standard ada2010`: each rule at its boundary, through the language: a
//! figure the rule allows holds, one millimetre beyond it fails. Rooms are
//! small and built for one rule at a time; `approach forward` or `side`
//! picks the rules an element is held to.

use reach::report::{RuleCheck, StandardReport, TaskReport};

use crate::body::run;

/// The standard's report of a 6 x 6 m room holding `items`.
fn checked(items: &str, options: &str) -> StandardReport {
    let text = format!(
        "units mm deg\nroom r {{\n  size 6000 x 6000 x 2500\n{items}\n}}\nstandard ada2010 {options}\n"
    );
    let (_, report) = run(&text);
    report
        .tasks
        .into_iter()
        .find_map(|t| match t {
            TaskReport::Standard(s) => Some(*s),
            _ => None,
        })
        .expect("a standard's report")
}

/// The rule of `section` about the first element.
fn rule(report: &StandardReport, section: &str) -> RuleCheck {
    let e = &report.elements[0];
    e.rules
        .iter()
        .find(|r| r.section == section)
        .cloned()
        .unwrap_or_else(|| panic!("no {section} among {:?}", e.rules))
}

fn holds(items: &str, options: &str, section: &str) -> bool {
    rule(&checked(items, options), section).ok
}

#[test]
fn forward_reach_unobstructed_is_380_to_1220_mm() {
    // A switch on the wall x = 0, nothing in front.
    let at = |z: f64| format!("target switch at (0, 3000, {z})");
    let forward = "{ approach forward }";
    assert!(holds(&at(380.0), forward, "308.2.1"));
    assert!(!holds(&at(379.0), forward, "308.2.1"));
    assert!(holds(&at(1220.0), forward, "308.2.1"));
    assert!(!holds(&at(1221.0), forward, "308.2.1"));
}

#[test]
fn forward_reach_over_an_obstruction_is_1220_up_to_510_deep_and_1120_up_to_635() {
    // A table with knee space under it (700 to 850 mm), 900 mm deep along
    // the whole wall x = 0; the element `depth` in from its front edge.
    let table = "box table at (0, 0, 700) size (900, 6000, 150)";
    let at = |depth: f64, z: f64| format!("{table}\ntarget cup at ({}, 3000, {z})", 900.0 - depth);
    let forward = "{ approach forward }";
    assert!(holds(&at(510.0, 1220.0), forward, "308.2.2"));
    assert!(!holds(&at(511.0, 1220.0), forward, "308.2.2"));
    assert!(holds(&at(511.0, 1120.0), forward, "308.2.2"));
    assert!(holds(&at(635.0, 1120.0), forward, "308.2.2"));
    assert!(!holds(&at(636.0, 1120.0), forward, "308.2.2"));
    // The knee space under it holds too.
    assert!(holds(&at(510.0, 1220.0), forward, "306.3"));
}

#[test]
fn knee_clearance_is_685_mm_high_and_280_mm_deep() {
    // A worktop along the whole wall, its underside `bottom` high, `deep`
    // deep; the element 200 mm in from its front edge.
    let at = |bottom: f64, deep: f64| {
        format!(
            "box top at (0, 0, {bottom}) size ({deep}, 6000, 40)\ntarget cup at ({}, 3000, 1000)",
            deep - 200.0
        )
    };
    let forward = "{ approach forward }";
    assert!(holds(&at(685.0, 280.0), forward, "306.3"));
    assert!(!holds(&at(684.0, 280.0), forward, "306.3"));
    assert!(!holds(&at(685.0, 279.0), forward, "306.3"));
}

#[test]
fn side_reach_is_1220_up_to_255_deep_and_1170_up_to_610_over_at_most_865() {
    // A counter `top` high, 1000 mm deep against the wall x = 0; the
    // element `depth` in from its front edge.
    let at = |top: f64, depth: f64, z: f64| {
        format!(
            "box counter at (0, 2000, 0) size (1000, 2000, {top})\ntarget jar at ({}, 3000, {z})",
            1000.0 - depth
        )
    };
    let side = "{ approach side }";
    assert!(holds(&at(865.0, 255.0, 1220.0), side, "308.3.1"));
    assert!(!holds(&at(866.0, 255.0, 1220.0), side, "308.3.1"));
    assert!(holds(&at(865.0, 256.0, 1170.0), side, "308.3.2"));
    assert!(!holds(&at(865.0, 256.0, 1171.0), side, "308.3.2"));
    assert!(holds(&at(865.0, 610.0, 1170.0), side, "308.3.2"));
    assert!(!holds(&at(865.0, 611.0, 1170.0), side, "308.3.2"));
    assert!(!holds(&at(866.0, 300.0, 1000.0), side, "308.3.2"));
}

#[test]
fn a_clear_floor_space_is_760_by_1220_mm() {
    // A switch in an alcove `width` wide and 1500 mm deep.
    let at = |width: f64| {
        format!(
            "box left at (0, 0, 0) size (1500, {}, 900)\nbox right at (0, {}, 0) size (1500, {}, 900)\ntarget switch at (0, 3000, 1000)",
            3000.0 - width / 2.0,
            3000.0 + width / 2.0,
            3000.0 - width / 2.0
        )
    };
    let forward = "{ approach forward }";
    assert!(holds(&at(760.0), forward, "305"));
    assert!(!holds(&at(759.0), forward, "305"));
}

#[test]
fn a_turning_space_is_a_1525_mm_circle_or_a_t() {
    // A corridor `width` wide, 4 m long, along the room.
    let corridor = |width: f64| {
        format!(
            "box a at (0, 0, 0) size (6000, 1000, 900)\nbox b at (0, {}, 0) size (6000, {}, 900)\ntarget switch at (3000, 1000, 1000)",
            1000.0 + width,
            5000.0 - width
        )
    };
    let turning = |width: f64| checked(&corridor(width), "").room_rules[0].clone();
    assert!(turning(1525.0).ok);
    let narrow = turning(1524.0);
    assert!(!narrow.ok, "{narrow:?}");
    // A knee-high obstacle leaves the floor under it (304.2).
    let raised = "box a at (0, 0, 0) size (6000, 1000, 900)\nbox b at (0, 2000, 700) size (6000, 4000, 200)\ntarget switch at (3000, 1000, 1000)";
    assert!(checked(raised, "").room_rules[0].ok);
}

/// Floor under a raised obstacle counts as knee and toe clearance only
/// 635 mm deep (306): a room roofed by a table at knee height has no
/// turning space in its middle.
#[test]
fn a_trap_box_against_the_wall_under_a_basin_shortens_the_toe_space() {
    // A basin 550 deep on the wall x = 0, its underside at 720 mm, open
    // below but for a trap box `trap` deep against the wall (floor to 500
    // mm), under the tap, which is 450 mm in from the basin's front edge.
    // The basin is what the hand reaches over, not a shelf over the trap
    // box: the space under it is knee and toe space.
    let basin = |trap: f64| {
        format!(
            "box basin at (0, 2700, 720) size (550, 600, 150)\n\
             box trap_box at (0, 2850, 0) size ({trap}, 300, 500)\n\
             target tap at (100, 3000, 900)"
        )
    };
    let forward = "{ approach forward }";
    // 100 deep: knee space 720 mm high and 450 deep; toe space as deep as
    // the reach.
    let report = checked(&basin(100.0), forward);
    let (knee, toe) = (rule(&report, "306.3"), rule(&report, "306.2"));
    assert!(knee.ok && toe.ok, "{knee:?} {toe:?}");
    assert_eq!(knee.measured, "720 mm high, 450 mm deep down to 230 mm");
    assert_eq!(toe.measured, "450 mm deep at the floor");
    // 150 deep, reaching under the tap: the knees have room (280 mm at
    // 230 mm high is enough), the clear floor space under the tap does
    // not (it was taken for a shelf over the trap box: "none").
    let report = checked(&basin(150.0), forward);
    let (knee, toe) = (rule(&report, "306.3"), rule(&report, "306.2"));
    assert!(knee.ok, "{knee:?}");
    assert_eq!(knee.measured, "720 mm high, 400 mm deep down to 230 mm");
    assert!(!toe.ok, "{toe:?}");
    assert_eq!(toe.measured, "400 mm deep at the floor");
    assert_eq!(rule(&report, "308.2.2").measured, "900 mm high over 450 mm");
}

#[test]
fn knee_space_narrows_by_1_in_6_from_280_mm_at_230_mm_to_205_mm_at_685() {
    // A counter 700 mm deep, its underside at 760 mm, with a bowl under it
    // whose front is `back` mm behind the counter's front and whose
    // bottom is at `bottom` mm: it needs 280 - (bottom - 230) / 6 mm.
    let at = |back: f64, bottom: f64| {
        format!(
            "box counter at (0, 0, 760) size (700, 6000, 40)\n\
             box bowl at (0, 2500, {bottom}) size ({}, 1000, {})\n\
             target tap at (600, 3000, 900)",
            700.0 - back,
            760.0 - bottom
        )
    };
    let forward = "{ approach forward }";
    // At 640 mm: 211.7 mm needed (ADA's 306.3.4; it was 685 mm high over
    // the front 280, "none: the obstruction comes down to 640 mm").
    assert!(holds(&at(212.0, 640.0), forward, "306.3"));
    assert!(!holds(&at(211.0, 640.0), forward, "306.3"));
    // And the clear floor space reaches under the counter up to the bowl:
    // every rule holds.
    let whole = checked(&at(250.0, 640.0), forward);
    assert!(whole.elements[0].ok, "{:?}", whole.elements[0]);
    // Just under 685 mm, about 205 (204.3 at 684); at 230 mm and below,
    // 280.
    assert!(holds(&at(205.0, 684.0), forward, "306.3"));
    assert!(!holds(&at(204.0, 684.0), forward, "306.3"));
    assert!(holds(&at(280.0, 100.0), forward, "306.3"));
    assert!(!holds(&at(279.0, 100.0), forward, "306.3"));
    // Toe space: 430 mm at the floor (a bowl from 230 mm up leaves it).
    assert!(holds(&at(300.0, 230.0), forward, "306.2"));
    assert!(!holds(&at(429.0, 0.0), forward, "306.2"));
    assert!(holds(&at(430.0, 0.0), forward, "306.2"));
}

#[test]
fn a_switch_on_a_wall_is_approached_from_the_room() {
    // A switch on the middle of the wall y = 6000, and one in the corner.
    let report = checked(
        "target switch at (3000, 6000, 1200)\ntarget corner at (6000, 6000, 1000)",
        "",
    );
    let [switch, corner] = &report.elements[..] else {
        panic!("two elements: {:?}", report.elements);
    };
    // Facing the wall, not along it (the first side tried was +x: it
    // read "forward approach facing 180 deg" with the floor space along
    // the wall).
    assert_eq!(
        (switch.approach.as_str(), switch.facing_deg),
        ("forward", 90.0)
    );
    assert!(switch.ok, "{switch:?}");
    // In a corner, facing either wall.
    assert!([0.0, 90.0].contains(&corner.facing_deg), "{corner:?}");
    // On a partition (a box), 10 mm proud of its face: facing the
    // partition (it read "facing 180 deg", along it).
    let partition = checked(
        "box partition at (0, 3000, 0) size (4000, 100, 2500)\ntarget switch at (2000, 3110, 1000)",
        "",
    );
    let switch = &partition.elements[0];
    assert_eq!(
        (switch.approach.as_str(), switch.facing_deg),
        ("forward", 270.0)
    );
    // Side: beside it, parallel to the wall.
    let side = checked("target switch at (3000, 6000, 1200)", "{ approach side }");
    let switch = &side.elements[0];
    assert_eq!(switch.approach, "side");
    assert!([0.0, 180.0].contains(&switch.facing_deg), "{switch:?}");
    assert!(switch.ok, "{switch:?}");
}

#[test]
fn knee_clearance_counts_only_635_mm_deep() {
    // A counter along the wall y = 0, `open` mm of open floor, then a
    // table at knee height `deep` mm deep to the wall y = 6000.
    let under = |deep: f64, open: f64| {
        format!(
            "box counter at (0, 0, 0) size (6000, {}, 900)
box table at (0, {}, 700) size (6000, {deep}, 40)
target switch at (3000, 100, 1000)",
            6000.0 - deep - open,
            6000.0 - deep
        )
    };
    // 1270 mm deep: all of it within 635 mm of an edge, and with 300 mm
    // of open floor a circle fits.
    assert!(checked(&under(1270.0, 300.0), "").room_rules[0].ok);
    // 1600 mm deep: its middle is more than 635 mm from every edge.
    let deep = checked(&under(1600.0, 0.0), "").room_rules[0].clone();
    assert!(!deep.ok, "{deep:?}");
}

/// A turning space behind a passage narrower than a route from the door
/// is not on the route: it does not count.
#[test]
fn a_turning_space_must_be_on_the_route_from_a_door() {
    // A wall across the room at y = 3000 with an 800 mm gap; the door in
    // the wall y = 0 opens into a 1000 mm deep vestibule.
    let room = |gap: f64| {
        format!(
            "box wall_a at (0, 1000, 0) size ({}, 100, 2500)
box wall_b at ({}, 1000, 0) size ({}, 100, 2500)
             target switch at (3000, 6000, 1000)
door hall at (3000, 0) width 900",
            3000.0 - gap / 2.0,
            3000.0 + gap / 2.0,
            3000.0 - gap / 2.0
        )
    };
    let cut_off = checked(&room(800.0), "").room_rules[0].clone();
    assert!(!cut_off.ok, "{cut_off:?}");
    assert!(cut_off.measured.contains("no 915 mm route"), "{cut_off:?}");
    assert!(checked(&room(920.0), "").room_rules[0].ok);
}

/// Boxes at the element's height count only where the hand must pass; an
/// element resting on a shelf over a counter is reached over the counter.
#[test]
fn only_what_the_hand_passes_through_blocks_a_reach() {
    let across = "box cupboard at (3000, 0, 0) size (600, 6000, 2000)
target switch at (0, 3000, 1000)";
    assert!(holds(across, "{ approach forward }", "308.2.1"));
    // A jar on a board 1100 mm up over an 865 mm counter 500 mm deep: a
    // side reach over 350 mm of counter, 1160 mm high.
    let shelf = "box counter at (0, 0, 0) size (500, 6000, 865)
box board at (0, 0, 1100) size (300, 6000, 20)
target jar at (150, 3000, 1160)";
    let r = rule(&checked(shelf, "{ approach side }"), "308.3.2");
    assert!(r.ok, "{r:?}");
    assert!(r.measured.contains("over 350 mm, 865 mm high"), "{r:?}");
}

#[test]
fn a_route_is_at_least_915_mm_and_a_door_815() {
    // From a door in the wall y = 0 through a passage `width` wide between
    // two counters to a switch on the far wall.
    let at = |width: f64, door: f64| {
        format!(
            "box a at (0, 2500, 0) size ({}, 200, 900)\nbox b at ({}, 2500, 0) size ({}, 200, 900)\n\
             target switch at (3000, 6000, 1000)\ndoor hall at (3000, 0) width {door}",
            3000.0 - width / 2.0,
            3000.0 + width / 2.0,
            3000.0 - width / 2.0
        )
    };
    assert!(holds(&at(915.0, 900.0), "", "403.5.1"));
    assert!(!holds(&at(914.0, 900.0), "", "403.5.1"));
    let door = |width: f64| checked(&at(1200.0, width), "").room_rules[1].clone();
    assert!(door(815.0).ok && !door(814.0).ok);
    // A cabinet standing 100 mm into a 900 mm opening, just inside.
    let narrowed = format!(
        "{}\nbox cabinet at (2450, 0, 0) size (200, 400, 900)",
        at(1200.0, 900.0)
    );
    let d = checked(&narrowed, "").room_rules[1].clone();
    assert!(!d.ok, "{d:?}");
    assert_eq!(d.measured, "800 mm of its 900 mm opening clear");
    // Without a door, routes are not checked, and the report says so.
    let open = checked("target switch at (0, 3000, 1000)", "");
    assert!(open.elements[0]
        .rules
        .iter()
        .all(|r| r.section != "403.5.1"));
    assert!(open.notes.iter().any(|n| n.contains("no `door`")));
}

#[test]
fn the_people_s_answers_stand_beside_the_rules() {
    let text = "units mm deg\nuse std::people\nroom r {\n  size 4000 x 4000 x 2500\n  \
                box counter at (0, 0, 0) size (600, 4000, 900)\n  target cup at (300, 2000, 950)\n}\n\
                person ann { mannequin woman_5th_seated base manual_wheelchair }\n\
                reach cup by ann\nstandard ada2010 in r\n";
    let (_, report) = run(text);
    let TaskReport::Standard(s) = &report.tasks[1] else {
        panic!("the standard after the tasks")
    };
    let people = &s.elements[0].people;
    assert_eq!(people.len(), 1);
    assert_eq!(
        (people[0].person.as_str(), people[0].task.as_str()),
        ("ann", "reach")
    );
    assert_eq!(people[0].ok, report.tasks[0].answer().ok);
}

#[test]
fn a_target_named_in_except_is_not_an_element() {
    // A point on a mirror a gaze looks at, high on the wall, and a switch.
    let items = "target mirror_centre at (0, 3000, 1700)\ntarget switch at (0, 1000, 1100)";
    let all = checked(items, "");
    let names =
        |r: &StandardReport| -> Vec<String> { r.elements.iter().map(|e| e.name.clone()).collect() };
    assert_eq!(names(&all), ["mirror_centre", "switch"]);
    assert!(!all.ok, "the mirror's point is out of reach: {all:?}");
    let except = checked(items, "except mirror_centre");
    assert_eq!(names(&except), ["switch"]);
    assert!(except.ok, "{except:?}");
    assert!(
        except
            .notes
            .iter()
            .any(|n| n == "not elements (`except`): `mirror_centre`"),
        "{:?}",
        except.notes
    );
}

#[test]
fn each_room_notes_only_its_own_targets_left_out() {
    let text = "units mm deg
room bath {
  size 3000 x 3000 x 2500
  target mirror_centre at (0, 1500, 1700)
}
room kitchen {
  size 4000 x 3000 x 2500
  target worktop_spot at (0, 1500, 950)
}
standard ada2010 except mirror_centre, worktop_spot
";
    let (_, report) = run(text);
    let notes: Vec<Vec<String>> = (report.tasks.iter())
        .filter_map(|t| match t {
            TaskReport::Standard(s) => Some(s.notes.clone()),
            _ => None,
        })
        .collect();
    let except = |notes: &[String]| {
        notes
            .iter()
            .find(|n| n.starts_with("not elements"))
            .cloned()
    };
    assert_eq!(
        notes.iter().map(|n| except(n)).collect::<Vec<_>>(),
        [
            Some("not elements (`except`): `mirror_centre`".to_string()),
            Some("not elements (`except`): `worktop_spot`".to_string())
        ]
    );
}

#[test]
fn an_unknown_standard_or_room_or_approach_is_a_diagnostic() {
    let registry = reach::plugin::Registry::builtin();
    for (tail, expected) in [
        ("standard ada2011\n", "did you mean `ada2010`"),
        ("standard ada2010 in kitchn\n", "did you mean `kitchen`"),
        (
            "standard ada2010 { approach diagonal }\n",
            "not an approach",
        ),
        ("standard ada2010 { aproach side }\n", "approach"),
    ] {
        let text = format!("room kitchen {{\n  size 4000 x 4000 x 2500\n}}\n{tail}");
        let (_, checked) = reach::check(
            reach::Input::Text {
                name: "std.reach",
                text: &text,
            },
            &registry,
        );
        let rendered = match checked {
            Ok(_) => panic!("accepted: {tail}"),
            Err(d) => d.render(false),
        };
        assert!(rendered.contains(expected), "{tail}: {rendered}");
    }
}

/// The room rule of `section` (a fixture's) whose rule names `fixture`.
fn room_rule(report: &StandardReport, section: &str, fixture: &str) -> RuleCheck {
    report
        .room_rules
        .iter()
        .find(|r| r.section == section && r.rule.contains(&format!("`{fixture}`")))
        .cloned()
        .unwrap_or_else(|| panic!("no {section} of {fixture} among {:?}", report.room_rules))
}

/// A water closet against the wall at y = 0, its side wall x = 0, its
/// centreline `centre` from that wall, its seat at `seat`; a side bar
/// from `bar_from` to `bar_to` from the rear wall, its top at `bar_top`,
/// `bar_gap` off its wall; a rear bar from `rear_from` to `rear_to` along
/// x; and what else stands in the room.
struct Toilet {
    centre: f64,
    seat: f64,
    bar_from: f64,
    bar_to: f64,
    bar_top: f64,
    bar_gap: f64,
    rear_from: f64,
    rear_to: f64,
    also: &'static str,
}

const COMPLIANT: Toilet = Toilet {
    centre: 430.0,
    seat: 440.0,
    bar_from: 305.0,
    bar_to: 1370.0,
    bar_top: 878.0,
    bar_gap: 38.0,
    rear_from: 125.0,
    rear_to: 1040.0,
    also: "",
};

fn toilet(t: &Toilet) -> StandardReport {
    let items = format!(
        "box toilet at ({}, 0, 0) size (360, 700, {})\n\
         box side_bar at ({}, {}, {}) size (38, {}, 38)\n\
         box rear_bar at ({}, 38, 860) size ({}, 38, 38)\n{}",
        t.centre - 180.0,
        t.seat,
        t.bar_gap,
        t.bar_from,
        t.bar_top - 38.0,
        t.bar_to - t.bar_from,
        t.rear_from,
        t.rear_to - t.rear_from,
        t.also
    );
    checked(
        &items,
        "{ water_closet toilet side_grab_bar side_bar rear_grab_bar rear_bar }",
    )
}

/// 604.2-604.5 and 609.3-609.4, each at its boundary: the figure the rule
/// allows holds, 5 mm beyond it fails (the rules take 2 mm of rounding).
#[test]
fn a_water_closet_and_its_grab_bars_hold_at_their_figures_and_fail_beyond() {
    let report = toilet(&COMPLIANT);
    for (section, fixture) in [
        ("604.2", "toilet"),
        ("604.3.1", "toilet"),
        ("604.4", "toilet"),
        ("604.5.1", "side_bar"),
        ("604.5.2", "rear_bar"),
        ("609.2", "side_bar"),
        ("609.3", "side_bar"),
        ("609.4", "side_bar"),
    ] {
        let r = room_rule(&report, section, fixture);
        assert!(r.ok, "{section} of the compliant toilet: {r:?}");
    }
    let fails = |t: Toilet, section: &str, fixture: &str| {
        let r = room_rule(&toilet(&t), section, fixture);
        assert!(!r.ok, "{section} of {fixture} should fail: {r:?}");
    };
    fails(
        Toilet {
            centre: 460.0,
            ..COMPLIANT
        },
        "604.2",
        "toilet",
    );
    fails(
        Toilet {
            centre: 400.0,
            ..COMPLIANT
        },
        "604.2",
        "toilet",
    );
    fails(
        Toilet {
            seat: 490.0,
            ..COMPLIANT
        },
        "604.4",
        "toilet",
    );
    fails(
        Toilet {
            seat: 425.0,
            ..COMPLIANT
        },
        "604.4",
        "toilet",
    );
    fails(
        Toilet {
            bar_from: 310.0,
            ..COMPLIANT
        },
        "604.5.1",
        "side_bar",
    );
    fails(
        Toilet {
            bar_to: 1365.0,
            ..COMPLIANT
        },
        "604.5.1",
        "side_bar",
    );
    fails(
        Toilet {
            bar_top: 920.0,
            ..COMPLIANT
        },
        "609.4",
        "side_bar",
    );
    fails(
        Toilet {
            bar_top: 835.0,
            ..COMPLIANT
        },
        "609.4",
        "side_bar",
    );
    fails(
        Toilet {
            bar_gap: 45.0,
            ..COMPLIANT
        },
        "609.3",
        "side_bar",
    );
    fails(
        Toilet {
            rear_from: 130.0,
            ..COMPLIANT
        },
        "604.5.2",
        "rear_bar",
    );
    fails(
        Toilet {
            rear_to: 1035.0,
            ..COMPLIANT
        },
        "604.5.2",
        "rear_bar",
    );
    // A vanity inside the 1525 x 1420 mm clearance, and one just outside.
    let inside = Toilet {
        also: "box vanity at (1520, 0, 0) size (500, 500, 850)",
        ..COMPLIANT
    };
    let r = room_rule(&toilet(&inside), "604.3.1", "toilet");
    assert!(!r.ok && r.measured.contains("`vanity`"), "{r:?}");
    let outside = Toilet {
        also: "box vanity at (1530, 0, 0) size (500, 500, 850)",
        ..COMPLIANT
    };
    assert!(room_rule(&toilet(&outside), "604.3.1", "toilet").ok);
}

/// 606.3 a lavatory's rim at most 865 mm; 603.3 a mirror's bottom edge at
/// most 1015 mm over it, 890 mm elsewhere; 904.4 a counter's portion at
/// most 915 mm high and 915 mm long (760 mm with knee space under it).
#[test]
fn a_lavatory_a_mirror_and_a_service_counter_hold_at_their_figures() {
    let room = |rim: f64, mirror_x: f64, mirror_bottom: f64| {
        checked(
            &format!(
                "box basin at (1000, 0, {}) size (550, 450, 70)\n\
                 box mirror at ({mirror_x}, 0, {mirror_bottom}) size (450, 10, 800)",
                rim - 70.0
            ),
            "{ lavatory basin mirror mirror }",
        )
    };
    assert!(room_rule(&room(865.0, 1050.0, 1015.0), "606.3", "basin").ok);
    assert!(!room_rule(&room(870.0, 1050.0, 1015.0), "606.3", "basin").ok);
    assert!(room_rule(&room(865.0, 1050.0, 1015.0), "603.3", "mirror").ok);
    assert!(!room_rule(&room(865.0, 1050.0, 1020.0), "603.3", "mirror").ok);
    // Away from the lavatory, 890 mm.
    assert!(!room_rule(&room(865.0, 3000.0, 900.0), "603.3", "mirror").ok);
    assert!(room_rule(&room(865.0, 3000.0, 890.0), "603.3", "mirror").ok);

    let counter = |items: &str| {
        room_rule(
            &checked(items, "{ service_counter low_part }"),
            "904.4",
            "low_part",
        )
    };
    let counter_ok = |items: &str| {
        let r = checked(items, "{ service_counter low_part }");
        let rule = r
            .room_rules
            .iter()
            .find(|r| r.rule.contains("`low_part`"))
            .cloned()
            .unwrap();
        rule
    };
    // Parallel: 915 long, 915 high.
    assert!(counter_ok("box low_part at (0, 2000, 0) size (600, 915, 915)").ok);
    assert!(!counter_ok("box low_part at (0, 2000, 0) size (600, 915, 920)").ok);
    assert!(!counter("box low_part at (0, 2000, 0) size (600, 905, 915)").ok);
    // Forward: 760 long with knee space under a top at 685 mm and up.
    let top = "box low_part at (0, 2000, 685) size (600, 760, 40)";
    assert!(counter_ok(top).ok);
    // A cupboard under its whole depth takes the knee space; so does a
    // panel 100 mm behind its front (the edge away from its wall).
    let under = format!("{top}\nbox cupboard at (0, 2000, 0) size (600, 300, 600)");
    assert!(!counter(&under).ok);
    let behind_front = format!("{top}\nbox panel at (450, 2000, 0) size (50, 760, 685)");
    assert!(!counter(&behind_front).ok);
    // Free-standing (a reception's lowered top), either long edge may be
    // the front: a panel 450 mm behind one leaves knee space; panels
    // within 430 mm of both do not.
    let free = "box low_part at (1000, 2000, 685) size (600, 760, 40)";
    let panel = format!("{free}\nbox panel at (1450, 2000, 0) size (50, 760, 685)");
    assert!(counter_ok(&panel).ok);
    let both = format!("{free}\nbox panel at (1300, 2000, 0) size (50, 760, 685)\nbox panel_2 at (1120, 2000, 0) size (50, 760, 685)");
    assert!(!counter(&both).ok);
}

/// What a designer's bathrooms showed wrong once: a rear bar on the wall
/// facing the toilet, a bar turned off its wall, a 140 mm round bar, a
/// mirror across the room from the lavatory, a dispenser in the
/// clearance, a toilet's tank as a box of its own, a counter whose depth
/// is longer than its front.
/// The fixture rule fails, and its measure says `words`.
fn fails_saying(report: &StandardReport, section: &str, fixture: &str, words: &str) {
    let r = room_rule(report, section, fixture);
    assert!(!r.ok && r.measured.contains(words), "{r:?}");
}

#[test]
fn fixtures_are_held_to_their_own_walls_and_shapes() {
    let with = |also: &'static str| Toilet { also, ..COMPLIANT };
    // The rear bar on the far wall, facing the toilet.
    let far = checked(
        "box toilet at (250, 0, 0) size (360, 700, 440)\n\
         box rear_bar at (125, 5924, 860) size (950, 38, 38)",
        "{ water_closet toilet rear_grab_bar rear_bar }",
    );
    fails_saying(&far, "604.5.2", "rear_bar", "not the rear wall");
    // A side bar turned 5 deg off its wall.
    let turned = checked(
        "box toilet at (250, 0, 0) size (360, 700, 440)\n\
         box side_bar at (38, 290, 840) size (38, 1090, 38) rotate -5deg",
        "{ water_closet toilet side_grab_bar side_bar }",
    );
    for section in ["604.5.1", "609.3"] {
        fails_saying(&turned, section, "side_bar", "turned 5 deg");
    }
    // 30 by 40 mm: 140 mm round, more than 609.2.2's 122 mm.
    let flat = checked(
        "box side_bar at (38, 300, 840) size (30, 1070, 40)",
        "{ side_grab_bar side_bar }",
    );
    assert!(!room_rule(&flat, "609.2", "side_bar").ok);
    // A mirror on the wall across from the lavatory: 890 mm.
    let across = checked(
        "box basin at (1650, 0, 780) size (550, 450, 70)\n\
         box mirror at (1700, 5990, 1000) size (450, 10, 800)",
        "{ lavatory basin mirror mirror }",
    );
    fails_saying(&across, "603.3", "mirror", "not over a lavatory");
    // A paper dispenser on the side wall, off the floor: allowed in the
    // clearance (604.3.2); a cabinet on the floor there is not.
    let dispenser = toilet(&with("box paper at (0, 900, 600) size (120, 150, 150)"));
    assert!(room_rule(&dispenser, "604.3.1", "toilet").ok);
    let cabinet = toilet(&with("box cabinet at (0, 900, 0) size (120, 150, 600)"));
    assert!(!room_rule(&cabinet, "604.3.1", "toilet").ok);
    // The bowl 250 mm off the rear wall, its tank behind it.
    let bowl = checked(
        "box toilet at (240, 250, 0) size (380, 450, 440)\n\
         box tank at (230, 0, 0) size (400, 250, 760)",
        "{ water_closet toilet water_closet_tank tank }",
    );
    for section in ["604.2", "604.3.1", "604.4"] {
        let r = room_rule(&bowl, section, "toilet");
        assert!(r.ok, "{section}: {r:?}");
    }
    // Against the wall at y = 0, 600 mm of front and 950 mm deep: too
    // short for either approach.
    let deep = checked(
        "box counter at (1000, 0, 0) size (600, 950, 900)",
        "{ service_counter counter }",
    );
    fails_saying(&deep, "904.4", "counter", "600 mm long");
}
