//! Why a target was not reached, found by searching again without each
//! thing that may have stopped it: a board between the arm and the target
//! is named (and without it the target is reached); a target just past a
//! joint's limit names the joint; a target far away is out of reach, with
//! the closest the bare arm comes. A planar arm of two 300 mm links on a
//! fixed base, so that every answer can be worked out by hand.

use super::body::reach_of;
use reach::report::{Report, Why};

/// The arm at (1000, 1000, 1000) facing +x, turning in the horizontal
/// plane: the shoulder within +-90 deg, the elbow 0-150 deg, so the hand
/// reaches 600 mm out, and only ahead of the shoulder's sideways line.
fn scenario(board: bool) -> String {
    let board = if board {
        // Across the line to `ahead`: the elbow of every posture that
        // reaches it lies at x = 1250 mm, within 166 mm of y = 1000.
        "  box board at (1240, 700, 0) size (20, 600, 3000)\n"
    } else {
        ""
    };
    format!(
        "units mm deg
room r {{
  size 3000 x 3000 x 3000
{board}  target ahead at (1500, 1000, 1000)
  // 500 mm out at 130 deg: the shoulder must turn 96.5 deg (elbow 67 deg).
  target past_limit at (678.6, 1383.0, 1000)
  target far at (2400, 1000, 1000)
}}
mannequin arm {{
  joint shoulder dh(theta 0, d 0, alpha 0, a 300) limits(-90deg, 90deg)
  joint elbow dh(theta 0, d 0, alpha 0, a 0) limits(0deg, 150deg)
  effector hand at (300, 0, 0)
}}
person pat {{
  mannequin arm
  base fixed {{ at (1000, 1000, 1000) }}
}}
reach ahead, past_limit, far by pat
"
    )
}

fn run(text: &str) -> Report {
    super::body::run(text).1
}

#[test]
fn the_board_in_the_way_is_named_and_without_it_the_target_is_reached() {
    let with = run(&scenario(true));
    let ahead = reach_of(&with, "ahead", "pat");
    assert!(!ahead.ok, "{ahead:?}");
    assert_eq!(
        ahead.why,
        [Why::Obstacles {
            names: vec!["board".into()],
            together: false
        }]
    );
    let without = run(&scenario(false));
    let ahead = reach_of(&without, "ahead", "pat");
    assert!(ahead.ok && ahead.why.is_empty(), "{ahead:?}");
}

#[test]
fn a_target_just_past_a_limit_names_the_joint() {
    let report = run(&scenario(false));
    let past = reach_of(&report, "past_limit", "pat");
    assert!(!past.ok, "{past:?}");
    assert_eq!(
        past.why,
        [Why::JointLimits {
            joints: vec!["shoulder".into()],
            coupled: false
        }]
    );
}

#[test]
fn a_far_target_is_out_of_reach_by_its_distance_less_the_arm() {
    let report = run(&scenario(true));
    let far = reach_of(&report, "far", "pat");
    let [Why::OutOfReach { closest_mm, .. }] = far.why.as_slice() else {
        panic!("{far:?}")
    };
    // 1400 mm from the shoulder, 600 mm of arm.
    assert!((closest_mm - 800.0).abs() < 1.0, "{closest_mm}");
}

/// A socket on the wall 1300 mm up behind a counter 800 mm deep: a seated
/// small woman's chair is kept away by the counter (with the counter gone
/// from the floor she reaches it), which "out of reach" would hide; the
/// same chair told to face the kettle (`approach forward`: within 45 deg
/// of straight ahead) in a galley where it can only stand along the
/// counter, and within 200 mm of the kettle along it (its zone), has no
/// place to approach it from, and nothing is tried. (Without the zone it
/// may stand back along the galley with the kettle 45 deg to its right.)
#[test]
fn a_counter_that_keeps_the_chair_away_is_named_and_no_approach_is_said() {
    let text = "units mm deg
use std::people
room kitchen {
  size 3000 x 3000 x 2500
  box counter at (0, 0, 0) size (3000, 800, 900)
  target socket at (1500, 5, 1300)
}
room galley {
  size 4000 x 1300 x 2500
  box counter at (0, 0, 0) size (4000, 600, 900)
  target kettle at (2000, 450, 950)
}
person ann { mannequin woman_5th_seated base manual_wheelchair }
person ann_facing {
  mannequin woman_5th_seated
  base manual_wheelchair { approach forward zone_from (1800, 0, 0) zone_to (2200, 1300, 0) }
}
reach socket by ann
reach kettle by ann_facing
";
    let report = run(text);
    let socket = reach_of(&report, "socket", "ann");
    assert_eq!(
        socket.why,
        [Why::KeptAway {
            names: vec!["counter".into()],
            together: false
        }],
        "{socket:?}"
    );
    let without = run(&text.replace("  box counter at (0, 0, 0) size (3000, 800, 900)\n", ""));
    assert!(reach_of(&without, "socket", "ann").ok);
    let kettle = reach_of(&report, "kettle", "ann_facing");
    assert_eq!(kettle.why, [Why::NoApproach], "{kettle:?}");
    assert!(!kettle.ok && kettle.iterations == 0);
}

/// `reach ... and gaze` says why too: where the hand alone does not reach
/// the target, the same cause a reach gives (a point high across the
/// room: out of reach); where it does, the reach part is reached or says
/// it is not while looking.
#[test]
fn a_reach_while_looking_says_why_its_hand_does_not_reach() {
    let text = "units mm deg
use std::body
room kitchen {
  size 4000 x 3000 x 2500
  box counter at (0, 0, 0) size (600, 3000, 900)
  target far at (100, 2900, 2400)
  target side at (900, 2200, 1000)
}
person ann { mannequin upper_body base fixed { at (900, 1500, 930) heading 180deg } }
reach far, side and gaze by ann { size 10mm }
reach far, side by ann
";
    let report = run(text);
    let both: Vec<&reach::report::ReachAndGazeReport> = report
        .tasks
        .iter()
        .filter_map(|t| match t {
            reach::report::TaskReport::ReachAndGaze(r) => Some(r.as_ref()),
            _ => None,
        })
        .collect();
    assert_eq!(both.len(), 2);
    for r in both {
        let alone = reach_of(&report, &r.name, "ann");
        match (r.reach.ok, alone.ok) {
            (true, _) => assert!(r.reach.why.is_empty(), "{r:?}"),
            (false, false) => {
                let causes = |w: &[Why]| w.iter().map(std::mem::discriminant).collect::<Vec<_>>();
                assert_eq!(causes(&r.reach.why), causes(&alone.why), "{}", r.name);
            }
            (false, true) => assert_eq!(r.reach.why, [Why::WhileLooking], "{}", r.name),
        }
    }
    let far = reach_of(&report, "far", "ann");
    assert!(matches!(far.why[..], [Why::OutOfReach { .. }]), "{far:?}");
}

/// A stick of two coupled joints (turn and bend, each +-90 deg alone) does
/// not reach a point 75 deg round and 75 deg up, which the same stick
/// uncoupled reaches: the coupled limits are named, with both joints.
#[test]
fn a_reach_left_short_by_a_coupling_names_the_coupled_joints() {
    let text = "units mm deg
room r {
  size 3000 x 3000 x 2500
  target both_far at (1250, 1567, 1866)
}
mannequin stick {
  joint turn dh(alpha 90deg) limits(-90deg, 90deg)
  joint bend dh(a 1000) limits(-90deg, 90deg)
  couple turn, bend
  effector hand at (0, 0, 0)
}
person p { mannequin stick base fixed { at (1500, 1500, 900) heading 90deg } }
reach both_far by p
";
    let report = run(text);
    let far = reach_of(&report, "both_far", "p");
    assert_eq!(
        far.why,
        [Why::JointLimits {
            joints: vec!["turn".into(), "bend".into()],
            coupled: true
        }],
        "{far:?}"
    );
    let free = run(&text.replace("  couple turn, bend\n", ""));
    assert!(reach_of(&free, "both_far", "p").ok);
}

/// A chair kept to an L of floor whose missing corner is the one place a
/// table can be reached from: kept to its zone, where the chair kept to
/// the L's bounding square reaches it; a zone wholly outside the room is
/// a mistake in the file, refused at the person's task with a line (it
/// was an answer, "does NOT fit", with exit 0), not a chair too large.
#[test]
fn a_zone_that_keeps_the_chair_away_is_named() {
    let zone_l = "zone ((500, 500, 0), (3000, 500, 0), (3000, 1500, 0), (1500, 1500, 0), (1500, 3000, 0), (500, 3000, 0))";
    let text = |zone: &str| {
        format!(
            "units mm deg
use std::people
room den {{
  size 4000 x 4000 x 2500
  box table at (2600, 2600, 0) size (400, 400, 750)
  target on_table at (2800, 2800, 800)
}}
person p {{ mannequin man_50th_seated base manual_wheelchair {{ headings 8 {zone} }} }}
reach on_table by p
"
        )
    };
    let report = run(&text(zone_l));
    let kept = reach_of(&report, "on_table", "p");
    assert_eq!(kept.why, [Why::Zone], "{kept:?}");
    let square = run(&text("zone_from (500, 500, 0) zone_to (3000, 3000, 0)"));
    assert!(reach_of(&square, "on_table", "p").ok);
    let outside = text("zone_from (5000, 5000, 0) zone_to (6000, 6000, 0)");
    let registry = reach::plugin::Registry::builtin();
    let input = reach::Input::Text {
        name: "den.reach",
        text: &outside,
    };
    let Err(diagnostics) = reach::check(input, &registry).1 else {
        panic!("a zone outside the room checks")
    };
    let rendered = diagnostics.render(false);
    assert!(
        rendered.contains("base of `p` is kept to a zone outside room `den`"),
        "{rendered}"
    );
}

/// A map that asks `why` gives each point it does not reach the cause a
/// reach would: the planar arm's plane of points (lifted a hand's radius,
/// 30 mm, to the arm's height) behind the board is blocked by it, and
/// points farther than the arm's 600 mm are out of reach. A reached point
/// has no cause, a map that does not ask gives none, and asking never
/// loses a point (its searches can only find one reached after all).
#[test]
fn a_map_that_asks_why_names_the_board_and_the_points_out_of_reach() {
    let map = |why: &str| {
        scenario(true).replace(
            "reach ahead, past_limit, far by pat\n",
            &format!("map plane by pat {{ step 50mm {why} }}\n"),
        )
    };
    let add_plane = |text: String| {
        text.replace(
            "  target far at",
            "  surface plane at (1000, 700, 970) size (800, 600, 0)\n  target far at",
        )
    };
    let asked = run(&add_plane(map("why true")));
    let plain = run(&add_plane(map("")));
    let cells = |report: &Report| match &report.tasks[0] {
        reach::report::TaskReport::Map(m) => m.cells.clone(),
        other => panic!("not a map: {other:?}"),
    };
    let (asked, plain) = (cells(&asked), cells(&plain));
    let (mut blocked, mut far) = (0, 0);
    for (a, p) in asked.iter().zip(&plain) {
        assert!(a.reachable || !p.reachable, "lost with why: {a:?}");
        assert!(p.why().is_empty(), "{p:?}");
        assert_eq!(a.why().is_empty(), a.reachable, "{a:?}");
        let [x, y, _] = a.point_mm;
        let from_shoulder = ((x - 1000.0).powi(2) + (y - 1000.0).powi(2)).sqrt();
        if from_shoulder > 620.0 {
            assert!(
                matches!(a.why(), [Why::OutOfReach { closest_mm, .. }] if *closest_mm > 0.0),
                "{a:?}"
            );
            far += 1;
        } else if x > 1270.0 && from_shoulder < 580.0 && (800.0..1200.0).contains(&y) {
            let board = Why::Obstacles {
                names: vec!["board".into()],
                together: false,
            };
            assert_eq!(a.why(), [board], "{a:?}");
            blocked += 1;
        }
    }
    assert!(blocked > 10 && far > 10, "{blocked} blocked, {far} far");
}

/// What keeps the base away is looked for on the floor, not only among
/// the obstacles nearest the target: a knob on a wall cabinet's door,
/// above a 600 mm counter and beside an open shelf unit whose boards and
/// sides are nearer the knob than the counter's body is. A small woman
/// in her chair does not reach it; without the counter she does, so the
/// counter is named (the wall cabinet and the shelves, nearest the knob,
/// were named instead, "together", from a new user's try).
#[test]
fn the_counter_that_keeps_the_chair_back_is_named_among_nearer_shelves() {
    let text = "units mm deg
use std::people
room kitchen {
  size 3000 x 3000 x 2500
  box counter      at (0, 0, 0)    size (600, 1600, 900)
  box wall_cabinet at (0, 0, 1400) size (350, 1600, 700)
  box shelf_4 at (0, 2000, 1500) size (300, 800, 20)
  box side_a  at (0, 1980, 0)    size (300, 20, 2000)
  target knob at (380, 1450, 1600)
}
person pat { mannequin woman_5th_seated base manual_wheelchair }
reach knob by pat
";
    let knob = run(text);
    let knob = reach_of(&knob, "knob", "pat");
    assert!(
        matches!(&knob.why[..], [Why::KeptAway { names, together: false }]
            if names.contains(&"counter".to_string())),
        "{knob:?}"
    );
    let without = text.replace(
        "  box counter      at (0, 0, 0)    size (600, 1600, 900)\n",
        "",
    );
    assert!(reach_of(&run(&without), "knob", "pat").ok);
}

/// The cause a designer can act on: a seated man reaching for a cabinet's
/// front just over the end of a counter, the counter keeping his chair
/// away. Searched without his body he reaches by leaning back through the
/// chair's backrest, which is not why he misses: with the furniture off
/// the floor, his chair comes close enough for the hand to reach, backrest
/// and all, so the counter keeping the chair away is named (it was "the
/// wheelchair's backrest; the joints' coupled limits").
#[test]
fn a_chair_kept_away_by_a_counter_is_kept_away_not_blocked_by_its_backrest() {
    let text = "units mm deg\nuse std::people\nroom kitchen {\n  size 3000 x 3000 x 2500\n  \
        box counter      at (0, 0, 0)    size (600, 2000, 900)\n  \
        box wall_cabinet at (0, 0, 1400) size (350, 2000, 700)\n  \
        target front at (350, 50, 1550)\n}\n\
        person ann {\n  mannequin man_50th_seated\n  base manual_wheelchair { approach side }\n}\n\
        reach front by ann { hand right }\n";
    let registry = reach::plugin::Registry::builtin();
    let (_, checked) = reach::check(
        reach::Input::Text {
            name: "corner.reach",
            text,
        },
        &registry,
    );
    let Ok(scenario) = checked else {
        panic!("the corner checks")
    };
    let report = reach::run(&scenario).unwrap();
    let reach::report::TaskReport::Reach(r) = &report.tasks[0] else {
        panic!("a reach")
    };
    assert!(!r.ok, "{r:?}");
    let why = format!("{:?}", r.why);
    assert!(why.contains("KeptAway") && why.contains("counter"), "{why}");
    assert!(!why.contains("backrest"), "{why}");
}

/// A standing person's target on the floor, out of reach, says that a
/// real person squats or kneels for it (the model does neither); one at
/// the same distance but high above the head does not.
#[test]
fn a_standing_persons_target_below_the_knees_says_the_model_does_not_squat() {
    let report = run("units mm deg
use std::people
room r {
  size 3000 x 3000 x 2500
  target on_floor at (1250, 1500, 60)
  target up_high at (1250, 1500, 2400)
}
person ann { mannequin woman_5th base fixed { at (1000, 1500, 806) heading 0 } }
reach on_floor, up_high by ann
");
    let below_knees = |target: &str| match reach_of(&report, target, "ann").why[..] {
        [Why::OutOfReach {
            below_the_knees, ..
        }] => below_the_knees,
        ref other => panic!("{target}: {other:?}"),
    };
    assert!(below_knees("on_floor"));
    assert!(!below_knees("up_high"));
    let low = reach_of(&report, "on_floor", "ann");
    assert!(low.why[0].sentence().contains("squats or kneels"));
}

/// A person on a fixed base is never "kept away" by the furniture: the
/// base stands where it is told. A seated woman reaching low on a
/// counter's front, between her knees and the counter: the search without
/// the room or her body happened to reach where the search again, "with
/// the furniture taken off the floor", is the same search for a fixed
/// base; the cause read "the base is kept away by `counter` and `cabinet`
/// together".
#[test]
fn a_fixed_base_is_never_kept_away() {
    let text = "units mm deg
use std::people
room r {
  size 4000 x 4000 x 2500
  box counter at (0, 1000, 0) size (600, 2000, 720)
  box cabinet at (0, 1000, 1300) size (350, 2000, 20)
  target t1 at (600, 1809, 260)
  target t2 at (600, 1809, 280)
}
person w {
  mannequin woman_5th_seated
  base fixed { at (1129, 1832, 500) heading 180deg }
}
reach t1, t2 by w
";
    let report = run(text);
    for target in ["t1", "t2"] {
        let r = reach_of(&report, target, "w");
        assert!(!r.ok, "{r:?}");
        let kept_away = r.why.iter().any(|w| matches!(w, Why::KeptAway { .. }));
        assert!(!kept_away && !r.why.is_empty(), "{target}: {:?}", r.why);
    }
}

/// A standing person on a fixed base whose hip point is put lower than
/// their standing hip height (930 mm for `upper_body`) has their feet in
/// the floor: every posture loses its balance "no room for the feet", and
/// the why names what the feet meet, the floor (it named nothing: "blocked
/// by " and no name). At their hip height the same cup is reached.
#[test]
fn feet_put_into_the_floor_by_a_fixed_base_name_the_floor() {
    let text = |hip_mm: f64| {
        format!(
            "units mm
use std::people
use std::body
room kitchen {{
  size 3000 x 3000 x 2500
  target cup at (1200, 700, 1300)
}}
person ann {{ mannequin upper_body base fixed {{ at (800, 700, {hip_mm}) }} }}
reach cup by ann
"
        )
    };
    let low = run(&text(900.0));
    let cup = reach_of(&low, "cup", "ann");
    assert!(!cup.ok, "{cup:?}");
    assert_eq!(
        cup.why,
        [Why::Obstacles {
            names: vec!["the floor".into()],
            together: false
        }]
    );
    assert_eq!(cup.why[0].short(), "blocked by the floor");
    let at_hip_height = run(&text(930.0));
    let cup = reach_of(&at_hip_height, "cup", "ann");
    assert!(cup.ok && cup.why.is_empty(), "{cup:?}");
}
