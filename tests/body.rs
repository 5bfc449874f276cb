//! The person takes up space: answers that only a body with thickness,
//! legs and a chair or a rollator gives. Seated people's lowest forward
//! reach lies between the lowest published 280 mm and 480 mm; a chair
//! pulls under a sink as far as its knee and toe clearance let it; a
//! rollator puts each person's hip where their legs put it; an arm does not
//! pass through the chest, nor a hand into a slot narrower than itself.

use std::f64::consts::FRAC_1_SQRT_2;

use nalgebra::Point3;
use reach::collision::{Obstacles, PlacedObstacles};
use reach::plugin::{BasePose, Registry};
use reach::report::{ReachReport, Report, TaskReport};
use reach::scene::{Blocker, OwnBody, Room};
use reach::Input;

pub fn run(text: &str) -> (reach::scenario::Scenario, Report) {
    let registry = Registry::builtin();
    let (_, checked) = reach::check(
        Input::Text {
            name: "body.reach",
            text,
        },
        &registry,
    );
    let scenario = checked.unwrap_or_else(|d| panic!("{}", d.render(false)));
    let report = reach::run(&scenario).expect("within the bound on solver work");
    (scenario, report)
}

pub fn reach_of<'r>(report: &'r Report, target: &str, person: &str) -> &'r ReachReport {
    report
        .tasks
        .iter()
        .find_map(|t| match t {
            TaskReport::Reach(r) if r.name == target && r.person == person => Some(r),
            _ => None,
        })
        .unwrap_or_else(|| panic!("no reach of {target} by {person}"))
}

const SEATED: [&str; 3] = ["woman_5th_seated", "man_50th_seated", "man_95th_seated"];

/// Each seated person's lowest forward reach: in an unobstructed forward
/// approach (the chair facing a bare wall, its toes against it), the
/// lowest point of the wall the grip comes to lies between 280 mm, the
/// lowest published, and 480 mm. (ADA 308.2.1's 380 mm is a design figure
/// for a population of wheelchair users, not a reach each percentile
/// person must make: these lowest reaches are about 350, 400 and 440 mm for
/// the 5th-percentile woman and the 50th- and 95th-percentile men, longer
/// legs keeping the larger people farther from the wall;
/// docs/calibration.md.) Targets are asked for every 10 mm from 250 mm: one
/// below 280 mm may be reached within the tolerance, but never with the
/// grip under 280 mm. The chair stands with the reaching (right) shoulder
/// in front of the target: finding that placement unaided is the
/// placement search's work, not the body's (the next test).
#[test]
fn each_seated_persons_lowest_forward_reach_is_between_280_and_480_mm() {
    let heights_mm: Vec<u32> = (250..=480).step_by(10).collect();
    let mut text =
        String::from("units mm deg\nuse std::people\nroom r {\n  size 3000 x 2000 x 2500\n");
    for z in &heights_mm {
        text += &format!("  target at_{z} at (3000, 1000, {z})\n");
    }
    text += "}\n";
    // The hip's y that puts each person's right shoulder at y = 1000 (half
    // their shoulder breadth to the right of it).
    let hip_y = [1170.6, 1207.7, 1221.3];
    for (i, mannequin) in SEATED.iter().enumerate() {
        let (from, to) = (hip_y[i] - 1.0, hip_y[i] + 1.0);
        // One heading: facing +x, the wall.
        text += &format!(
            "person p{i} {{ mannequin {mannequin} base manual_wheelchair {{ headings 1 \
             zone_from (0, {from}, 0) zone_to (3000, {to}, 0) }} }}\n"
        );
    }
    let targets: Vec<String> = heights_mm.iter().map(|z| format!("at_{z}")).collect();
    text += &format!("reach {} by p0, p1, p2\n", targets.join(", "));
    let (_, report) = run(&text);
    for (i, mannequin) in SEATED.iter().enumerate() {
        let person = format!("p{i}");
        let reached: Vec<&ReachReport> = targets
            .iter()
            .map(|t| reach_of(&report, t, &person))
            .filter(|r| r.ok)
            .collect();
        for r in &reached {
            assert_eq!(r.base.heading_deg, 0.0);
            assert!(
                r.effector_mm[2] >= 280.0,
                "{mannequin} brings the hand to {:.1} mm: {r:?}",
                r.effector_mm[2]
            );
        }
        let lowest = reached
            .iter()
            .map(|r| r.effector_mm[2])
            .fold(f64::INFINITY, f64::min);
        assert!(
            (280.0..=480.0).contains(&lowest),
            "{mannequin}'s lowest forward reach: {lowest:.1} mm"
        );
    }
}

/// The placement search finds each seated person's low forward reach
/// unaided: facing the wall and free to stand anywhere along it, each
/// reaches a point 10 mm above the lowest the previous test's chair, held
/// with the shoulder in front of the target, reaches (360, 410 and 450 mm).
#[test]
fn the_placement_search_finds_the_low_forward_reach_unaided() {
    let heights_mm = [360, 410, 450];
    let mut text =
        String::from("units mm deg\nuse std::people\nroom r {\n  size 3000 x 2000 x 2500\n");
    for (i, z) in heights_mm.iter().enumerate() {
        text += &format!("  target low_{i} at (3000, 1000, {z})\n");
    }
    text += "}\n";
    for (i, mannequin) in SEATED.iter().enumerate() {
        text += &format!(
            "person p{i} {{ mannequin {mannequin} base manual_wheelchair {{ heading 0deg }} }}\n\
             reach low_{i} by p{i}\n"
        );
    }
    let (_, report) = run(&text);
    for (i, mannequin) in SEATED.iter().enumerate() {
        let low = reach_of(&report, &format!("low_{i}"), &format!("p{i}"));
        assert!(
            low.ok,
            "{mannequin} does not reach {} mm: {low:?}",
            heights_mm[i]
        );
    }
}

/// `approach forward` faces the wall and `approach side` runs parallel to
/// it, each to within 45 degrees, wherever the search finds the best
/// placement (a chair parallel to the wall reaching a point a little
/// ahead of it is a side approach, however small the angle from the hip);
/// every seated person reaches 480 mm (the top of the range their lowest
/// forward reaches lie in, above) and ADA 308.3.1's 1,220 mm both ways.
#[test]
fn a_forward_approach_faces_the_wall_and_a_side_approach_runs_along_it() {
    let mut text = String::from(
        "units mm deg\nuse std::people\nroom r {\n  size 3000 x 2000 x 2500\n  \
         target low at (3000, 1000, 480)\n  target high at (3000, 1000, 1220)\n}\n",
    );
    for (i, mannequin) in SEATED.iter().enumerate() {
        for approach in ["forward", "side"] {
            text += &format!(
                "person {approach}{i} {{ mannequin {mannequin} base manual_wheelchair \
                 {{ approach {approach} }} }}\n"
            );
        }
    }
    let people: Vec<String> = (0..SEATED.len())
        .flat_map(|i| [format!("forward{i}"), format!("side{i}")])
        .collect();
    text += &format!("reach low, high by {}\n", people.join(", "));
    let (_, report) = run(&text);
    for person in &people {
        for target in ["low", "high"] {
            let r = reach_of(&report, target, person);
            assert!(r.ok, "{person} does not reach {target}: {r:?}");
            // The wall's inward normal is -x: facing it is heading 0.
            let facing = r.base.heading_deg.to_radians().cos();
            if person.starts_with("forward") {
                assert!(facing > FRAC_1_SQRT_2, "{person} {target}: {:?}", r.base);
            } else {
                assert!(
                    facing.abs() < FRAC_1_SQRT_2,
                    "{person} {target}: {:?}",
                    r.base
                );
            }
        }
    }
}

/// A sink with knee space (ADA 306: knee clearance 685 mm high, toe
/// clearance 230 mm): the counter's front, an apron from 700 to 865 mm,
/// is 600 mm deep; the knee space behind its front edge ends 480 mm in,
/// at the plumbing. The alcove is 1 m wide, so the chair faces the sink:
/// its footrests and the person's knees and toes go under the apron (the
/// chair pulls in), but no further than the plumbing, and the trunk stays
/// in front of the counter.
#[test]
fn a_chair_pulls_in_under_a_sink_as_far_as_the_knee_space_allows() {
    let text = "
units mm deg
use std::people
room alcove {
  size 3000 x 1000 x 2500
  box apron    at (2400, 0, 700) size (600, 1000, 165)
  box plumbing at (2880, 0, 0)   size (120, 1000, 700)
  target tap at (2700, 500, 900)
}
person ann { mannequin man_50th_seated base manual_wheelchair { headings 1 } }
reach tap by ann
";
    let (scenario, report) = run(text);
    let r = reach_of(&report, "tap", "ann");
    assert!(r.ok, "{r:?}");
    let footprint = scenario.bases[0].footprint().expect("a wheelchair moves");
    // The farthest forward of the parts below the apron, and of those at
    // its height or above.
    let ahead = |below: bool| {
        footprint
            .parts
            .iter()
            .filter(|p| (p.z_mm[1] <= 700.0) == below)
            .flat_map(|p| p.outline_mm.iter().map(|v| v.x))
            .fold(f64::NEG_INFINITY, f64::max)
    };
    let (toes, trunk) = (r.base.x_mm + ahead(true), r.base.x_mm + ahead(false));
    assert!(
        toes > 2400.0 + 100.0,
        "the feet stay out of the knee space: {toes}"
    );
    assert!(toes <= 2880.0 + 0.02, "the feet pass the plumbing: {toes}");
    assert!(
        trunk <= 2400.0 + 0.02,
        "the body passes the counter's front: {trunk}"
    );
}

/// On a rollator the hip is where the person's legs put it (0.530 of
/// stature): 806 mm for the 5th-percentile woman, 991 mm for the
/// 95th-percentile man. The handle of a pull cord at 2 m, in the middle of
/// the room, is within the tall man's reach and far beyond the small
/// woman's (with everyone's hip at 930 mm, as before the legs, she was
/// reported 125 mm taller than she is).
#[test]
fn a_rollator_stands_each_person_at_their_own_hip_height() {
    let text = "
units mm deg
use std::people
room hall {
  size 4000 x 3000 x 2600
  target cord at (2000, 1500, 2000)
}
person small { mannequin woman_5th base rollator }
person tall  { mannequin man_95th base rollator }
reach cord by small, tall
";
    let (_, report) = run(text);
    let (small, tall) = (
        reach_of(&report, "cord", "small"),
        reach_of(&report, "cord", "tall"),
    );
    assert!((small.base.z_mm - 0.530 * 1520.0).abs() < 0.01, "{small:?}");
    assert!((tall.base.z_mm - 0.530 * 1870.0).abs() < 0.01, "{tall:?}");
    assert!(tall.ok, "{tall:?}");
    assert!(!small.ok && small.distance_mm > 100.0, "{small:?}");
}

/// std::arm with the arm forward, the elbow folded and the upper arm turned
/// in: the forearm would pass through the chest. The posture is refused,
/// naming the parts.
#[test]
fn an_arm_through_the_chest_is_refused() {
    let body = reach::stdlib::body("arm", "right_arm").unwrap();
    let chain = body.chain(0);
    let d = f64::to_radians;
    // The arm forward, the elbow bent fully, the humerus turned in (the
    // forearm across the chest) or not.
    let bent = |rotation: f64| {
        let mut q = [0.0; 11];
        (q[4], q[6], q[7]) = (d(90.0), d(rotation), d(150.0));
        q
    };
    let (through, beside) = (bent(-70.0), bent(0.0));
    let room = Room {
        name: "r".into(),
        size_mm: nalgebra::Vector3::repeat(4000.0),
        boxes: vec![],
        meshes: vec![],
        targets: vec![],
        surfaces: vec![],
        doors: Vec::new(),
    };
    let obstacles = Obstacles::new(&room, 0.0);
    let own = OwnBody::default();
    let placed = PlacedObstacles {
        obstacles: &obstacles,
        own: &own,
        base_pose: BasePose {
            position_mm: Point3::new(2000.0, 2000.0, 930.0),
            heading_rad: 0.0,
        },
    };
    let hit = placed.posture_hit(&chain, &through, 10.0).expect("refused");
    let Blocker::Body(other) = hit.blocker else {
        panic!("{hit:?}")
    };
    assert_eq!(chain.volume_name(hit.part), "the right forearm");
    assert_eq!(chain.volume_name(other), "the trunk");
    assert_eq!(placed.posture_hit(&chain, &beside, 10.0), None);
}

/// Two boards 11 mm apart, and a target 60 mm into the slot between them:
/// a hand (56 mm thick) does not go in, so the target is not reachable,
/// though the same target with the upper board gone is.
#[test]
fn a_hand_does_not_go_into_an_11_mm_slot() {
    let room = |upper: bool| {
        format!(
            "
units mm deg
use std::arm
room kitchen {{
  size 4000 x 3000 x 2500
  box lower at (0, 1000, 1000) size (400, 800, 20)
  {}
  target card at (340, 1400, 1025)
}}
person ben {{ mannequin right_arm base fixed {{ at (800, 1400, 930) heading 180deg }} }}
reach card by ben
",
            if upper {
                "box upper at (0, 1000, 1031) size (400, 800, 20)"
            } else {
                ""
            }
        )
    };
    let (_, slot) = run(&room(true));
    let r = reach_of(&slot, "card", "ben");
    assert!(!r.ok, "{r:?}");
    let (_, open) = run(&room(false));
    let r = reach_of(&open, "card", "ben");
    assert!(r.ok, "{r:?}");
}
