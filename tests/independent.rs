//! An unreachable answer must mean unreachable, and a reachable one
//! reachable: every posture an example reports is checked by forward
//! kinematics written again here (4x4 matrices of eq. 3 of the paper, in
//! homogeneous coordinates), from the report's own rounded numbers, and its
//! solids (`body_check.rs`) against the room's boxes, walls, floor and
//! ceiling, the person's legs and base and the person's other parts: a
//! reachable answer passes through nothing, and a reported collision names
//! something a part meets.

use nalgebra::{Matrix4, Vector4};
use reach::kinematics::{Body, Chain, JointKind, SUPPORT_SHARE};
use reach::plugin::Registry;
use reach::report::{BaseReport, Posture, ReachReport, TaskReport};
use reach::scene::{OwnBody, Room};
use reach::Input;

use super::body_check::{balanced, dh, everything_met, legs_meet_boxes, parts, parts_with, Part};
use super::gaze::RIGHT_SHELVES;

/// The hip, every joint frame's origin and the effector, in the room, for
/// the report's posture and base pose; the effector is the last.
fn points_in_room(chain: &Chain, r: &ReachReport) -> Vec<[f64; 3]> {
    posture_points(chain, &r.posture, &r.base)
}

/// The hip, the frame origins and the effector of `posture` in the room.
fn posture_points(chain: &Chain, posture: &Posture, base: &BaseReport) -> Vec<[f64; 3]> {
    let r = Placed { base, posture };
    let (s, c) = r.base.heading_deg.to_radians().sin_cos();
    let to_room = |p: Vector4<f64>| {
        [
            r.base.x_mm + c * p.x - s * p.y,
            r.base.y_mm + s * p.x + c * p.y,
            r.base.z_mm + p.z,
        ]
    };
    let mut points = vec![to_room(Vector4::new(0.0, 0.0, 0.0, 1.0))];
    let mut m = Matrix4::identity();
    for (joint, (name, value)) in chain.joints.iter().zip(&r.posture.0) {
        assert_eq!(&joint.name, name);
        let (theta, d) = match joint.kind {
            JointKind::Revolute => (joint.dh.theta_rad + value.to_radians(), joint.dh.d_mm),
            JointKind::Prismatic => (joint.dh.theta_rad, joint.dh.d_mm + value),
        };
        m *= joint
            .pre
            .map_or(Matrix4::identity(), |p| p.to_homogeneous());
        m *= dh(theta, d, joint.dh.alpha_rad(), joint.dh.a_mm);
        points.push(to_room(m * Vector4::new(0.0, 0.0, 0.0, 1.0)));
    }
    let e = chain.effector_mm;
    points.push(to_room(m * Vector4::new(e.x, e.y, e.z, 1.0)));
    points
}

/// Rounding the posture to 0.01 degree moves the hand by at most this much.
/// (Reports round to 0.1 degree in text, 0.01 in JSON; the check reads the
/// report structure, at 0.01.)
const ROUNDING_MM: f64 = 1.5;

#[test]
fn every_reported_posture_is_what_the_report_says() {
    let (mut checked, mut collisions) = (0, 0);
    for example in [
        "examples/kitchen.reach",
        "examples/kitchen_wheelchair.reach",
        "examples/open_door.reach",
        "examples/mother_kitchen.reach",
    ] {
        let (reaches, met) = reaches_checked(Input::Path(example.as_ref()), example);
        checked += reaches;
        collisions += met;
    }
    assert_eq!(checked, 4 + 16 + 6 + 10);
    assert!(collisions > 0, "the examples have postures that meet a box");
}

/// The 95th-percentile seated man, his chair held in place, reaching for
/// points in the 65 mm slot between his seat and its right wheel, 280 to
/// 400 mm above the floor: a forearm 111 mm thick does not fit. Every
/// answer is checked against his solids rebuilt here. Before only the
/// trunk's part near the hip point was let into the seat and thighs (the
/// pelvis), an arm passing within 285 mm of the hip point was let in too:
/// five points were "reachable" with the forearm 19-34 mm into the seat
/// and the wheel (a helper's find).
#[test]
fn an_arm_beside_the_hip_stays_out_of_the_seat_and_the_wheel() {
    let mut text =
        String::from("units mm deg\nuse std::people\nroom r {\n  size 4000 x 4000 x 2500\n");
    let mut names = Vec::new();
    for x in [1900, 1950, 2000, 2050] {
        for z in [280, 310, 340, 370, 400] {
            text += &format!("  target g{x}_{z} at ({x}, 1738, {z})\n");
            names.push(format!("g{x}_{z}"));
        }
    }
    text += "}\nperson m95 { mannequin man_95th_seated base manual_wheelchair { \
             zone_from (2000, 2000, 0) zone_to (2000, 2000, 0) heading 0deg heading_within 0deg } }\n";
    text += &format!("reach {} by m95\n", names.join(", "));
    let input = Input::Text {
        name: "slot.reach",
        text: &text,
    };
    let (checked, _) = reaches_checked(input, "slot.reach");
    assert_eq!(checked, names.len());
}

/// A seated man reaching over a screen to a point behind it leans his
/// head over it: his neck (off the arm's chain, as the head is) must stay
/// out of the screen. Before the chain carried the neck, his posture for
/// the near point ran it 39 mm into the screen (a helper's find).
#[test]
fn a_reach_over_a_screen_keeps_the_neck_out_of_it() {
    let text = "units mm deg
use std::people
room r {
  size 4000 x 3500 x 2500
  box table   at (0, 500, 0)    size (700, 800, 740)
  box screen  at (650, 500, 740) size (20, 800, 500)
  target behind_screen_near at (600, 900, 800)
  target behind_screen_far  at (300, 900, 800)
  box desk    at (0, 1800, 0)    size (700, 900, 740)
  box hutch_top at (0, 1800, 1100) size (300, 900, 20)
  box hutch_bot at (0, 1800, 740) size (300, 900, 20)
  box hutch_front at (290, 1800, 760) size (10, 900, 200)
  target hutch_in at (150, 2250, 800)
  box lip_shelf at (0, 2900, 1000) size (350, 600, 20)
  box lip       at (330, 2900, 1020) size (20, 600, 150)
  target behind_lip at (150, 3200, 1060)
  box partition at (1500, 0, 0) size (20, 1200, 2000)
  target behind_partition at (1450, 600, 1000)
}
person wf { mannequin woman_5th_seated base manual_wheelchair }
person wm { mannequin man_50th_seated base manual_wheelchair }
person rb { mannequin man_95th base rollator }
person rf { mannequin woman_5th base rollator }
reach behind_screen_near, behind_screen_far, hutch_in, behind_lip, behind_partition by wf, wm, rb, rf
";
    let input = Input::Text {
        name: "behind.reach",
        text,
    };
    let (checked, _) = reaches_checked(input, "behind.reach");
    assert_eq!(checked, 20);
}

/// Runs a scenario and checks every reach: its joints within their limits,
/// a reachable posture through nothing, a reported collision real, and
/// the distance what the report says. How many reaches were checked, and
/// how many reported a collision.
fn reaches_checked(input: Input, name: &str) -> (usize, usize) {
    let (mut checked, mut collisions) = (0, 0);
    let registry = Registry::builtin();
    let (_, scenario) = reach::check(input, &registry);
    let scenario = scenario.unwrap();
    let report = reach::run(&scenario).expect("within the bound on solver work");
    for task in &report.tasks {
        let TaskReport::Reach(r) = task else { continue };
        let body = &scenario.person(&r.person).unwrap().body;
        let chain = &body.chain_named(Some(&r.effector)).unwrap();
        assert_eq!(chain.joints.len(), r.posture.0.len());
        for (joint, (name, value)) in chain.joints.iter().zip(&r.posture.0) {
            assert_eq!(&joint.name, name);
            let (min, max) = match joint.kind {
                JointKind::Revolute => (joint.min.to_degrees(), joint.max.to_degrees()),
                JointKind::Prismatic => (joint.min, joint.max),
            };
            assert!(
                *value >= min - 0.005 && *value <= max + 0.005,
                "{} by {}: {} = {value} outside",
                r.name,
                r.person,
                joint.name
            );
        }
        let points = points_in_room(chain, r);
        let room = &scenario.rooms[0];
        let index = scenario
            .persons
            .iter()
            .position(|p| p.name == r.person)
            .unwrap();
        let own = scenario.bases[index].own_body();
        let solids = parts(body, &r.effector, &r.posture, &r.base, r.tolerance_mm);
        if let Some(wrong) = solids_disagree(&solids, room, own, r) {
            panic!("{name}: {wrong}");
        }
        if let Some(wrong) = balance_disagrees(body, room, own, r) {
            panic!("{name}: {wrong}");
        }
        collisions += usize::from(r.collision.is_some());
        let e = *points.last().unwrap();
        let t = r.target_mm;
        let distance =
            ((e[0] - t[0]).powi(2) + (e[1] - t[1]).powi(2) + (e[2] - t[2]).powi(2)).sqrt();
        assert!(
            (distance - r.distance_mm).abs() <= ROUNDING_MM,
            "{name}: {} by {}: reported {} mm, recomputed {distance} mm",
            r.name,
            r.person,
            r.distance_mm
        );
        if r.ok {
            assert!(
                distance <= r.tolerance_mm + ROUNDING_MM,
                "{name}: {} by {}: reachable but {distance} mm off",
                r.name,
                r.person
            );
        }
        checked += 1;
    }
    (checked, collisions)
}

/// The standing woman at the right-hand shelves, reaching for tins on the
/// top shelves while looking at them: her hand's solids, checked again
/// here with her head and neck where her eyes' joints turned them (the
/// hand's chain used to carry them at the neck's neutral posture, and a
/// helper's run had one reach refused through a head that was not
/// there; this room alone does not bring that case back), pass through
/// nothing when reachable, and meet what they are said to be blocked by.
#[test]
fn a_reach_and_gaze_checks_the_head_where_the_eyes_turned_it() {
    let text = format!(
        "units mm deg
use std::people
room r {{
  size 4000 x 3200 x 2500
{RIGHT_SHELVES}  box counter at (0, 0, 0) size (600, 3200, 900)
  box wc_bottom at (0, 800, 1400) size (350, 1400, 20)
  box wc_shelf  at (0, 800, 1720) size (350, 1400, 20)
  door d at (4000, 1600) width 900mm
  target a4 at (2100, 3050, 1980)
  target a5 at (1900, 3150, 1480)
}}
person rf {{ mannequin woman_5th base rollator }}
reach a4, a5 and gaze by rf {{ size 10mm seed 2 }}
"
    );
    let registry = Registry::builtin();
    let (_, scenario) = reach::check(
        Input::Text {
            name: "shelves.reach",
            text: &text,
        },
        &registry,
    );
    let scenario = scenario.unwrap();
    let report = reach::run(&scenario).expect("within the bound on solver work");
    let mut checked = 0;
    for task in &report.tasks {
        let TaskReport::ReachAndGaze(both) = task else {
            continue;
        };
        let r = &both.reach;
        let index = scenario
            .persons
            .iter()
            .position(|p| p.name == r.person)
            .unwrap();
        let body = &scenario.persons[index].body;
        let own = scenario.bases[index].own_body();
        let eyes = Some(&both.gaze.posture);
        let solids = parts_with(body, &r.effector, &r.posture, eyes, &r.base, r.tolerance_mm);
        if let Some(wrong) = solids_disagree(&solids, &scenario.rooms[0], own, r) {
            panic!("{wrong}");
        }
        checked += 1;
    }
    assert_eq!(checked, 2);
}

/// Where a reach's solids (built again in `body_check.rs`) disagree with
/// its answer, how: a reachable posture passes through something (its
/// solids shrunk by the rounding, so that grazing is not a miss), or
/// nothing of it meets what it is said to be blocked by (grown by it).
fn solids_disagree(solids: &[Part], room: &Room, own: &OwnBody, r: &ReachReport) -> Option<String> {
    if r.ok {
        let met = everything_met(solids, room, own, &r.base, -ROUNDING_MM);
        if !met.is_empty() {
            return Some(format!(
                "{} by {}: reachable through {met:?}",
                r.name, r.person
            ));
        }
    }
    let blocker = r.collision.as_ref()?;
    if blocker.contains("balance") {
        return None;
    }
    let met = everything_met(solids, room, own, &r.base, ROUNDING_MM);
    let wall = ["the wall", "the floor", "the ceiling"]
        .iter()
        .any(|w| blocker.starts_with(w));
    let named = met.iter().any(|m| m.contains(blocker.as_str()))
        || wall && met.iter().any(|m| m == "a wall");
    (!named).then(|| {
        format!(
            "{} by {}: nothing meets {blocker} ({:?}): {met:?}",
            r.name, r.person, r.collision_part
        )
    })
}

/// Standing, where the report and the balance worked out here disagree
/// (a margin of 0.02 of the support either way, for the effector's link,
/// whose end the report rounds): a posture reported reached must be
/// balanced; one reported to tip must not be, and one whose feet had no
/// room must not be with the feet left under the hips, or there the legs
/// meet a box.
fn balance_disagrees(body: &Body, room: &Room, own: &OwnBody, r: &ReachReport) -> Option<String> {
    own.balance.as_ref()?;
    let share = SUPPORT_SHARE;
    let said = r.collision.as_deref().unwrap_or("");
    let wrong = if r.ok {
        !balanced(body, &r.effector, &r.posture, share + 0.02, false)
    } else if said.contains("balance (tipping") {
        balanced(body, &r.effector, &r.posture, share - 0.02, false)
    } else if said.contains("balance (no room for the feet") {
        balanced(body, &r.effector, &r.posture, share - 0.02, true)
            && !legs_meet_boxes(body, room, &r.base)
    } else {
        false
    };
    wrong.then(|| {
        format!(
            "{} by {}: reported {:?}, the balance worked out here disagrees",
            r.name, r.person, r.collision
        )
    })
}

/// A posture and where its base stood.
struct Placed<'a> {
    base: &'a BaseReport,
    posture: &'a Posture,
}

/// Every gaze of `examples/gaze_shelf.reach` (alone, or with a reach): the
/// eyes where the report says, by forward kinematics written here; every
/// joint but the look link within the person's limits; and a look link
/// whose length is the distance the report gives from the eyes along it.
#[test]
fn every_reported_gaze_is_what_the_report_says() {
    let registry = Registry::builtin();
    let (_, scenario) = reach::check(Input::Path("examples/gaze_shelf.reach".as_ref()), &registry);
    let scenario = scenario.unwrap();
    let report = reach::run(&scenario).expect("within the bound on solver work");
    let mut checked = 0;
    for task in &report.tasks {
        let g = match task {
            TaskReport::Gaze(g) => g,
            TaskReport::ReachAndGaze(b) => &b.gaze,
            _ => continue,
        };
        let person = scenario.person(&g.person).unwrap();
        let chain = person.body.chain_named(Some(&g.effector)).unwrap();
        let n = chain.joints.len();
        for (joint, (_, value)) in chain.joints[..n - 1].iter().zip(&g.posture.0) {
            let (min, max) = (joint.min.to_degrees(), joint.max.to_degrees());
            assert!(
                *value >= min - 0.005 && *value <= max + 0.005,
                "{} by {}: {} = {value}",
                g.name,
                g.person,
                joint.name
            );
        }
        let points = posture_points(&chain, &g.posture, &g.base);
        // The frame before the look link is where the eyes are.
        let eyes = points[points.len() - 3];
        let off = (0..3)
            .map(|k| (eyes[k] - g.eyes_mm[k]).powi(2))
            .sum::<f64>()
            .sqrt();
        assert!(
            off <= ROUNDING_MM,
            "{} by {}: eyes {eyes:?} vs {:?}",
            g.name,
            g.person,
            g.eyes_mm
        );
        checked += 1;
    }
    assert_eq!(checked, 8 + 2);
}

mod random_rooms {
    //! The same check over random rooms: boards and blocks at random
    //! around people of the standard library on their bases, and targets
    //! at random. Whatever the search finds, no posture it calls reachable
    //! passes through anything, and a collision it reports is real.

    use proptest::prelude::*;
    use reach::plugin::Registry;
    use reach::report::TaskReport;
    use reach::Input;

    use super::super::body_check::parts;
    use super::solids_disagree;

    thread_local! {
        /// Cases run (low 32 bits) and refused by the checker (high).
        static RUN: std::cell::Cell<u64> = const { std::cell::Cell::new(0) };
        /// Targets reached.
        static REACHED: std::cell::Cell<u64> = const { std::cell::Cell::new(0) };
    }

    const PEOPLE: [(&str, &str); 4] = [
        ("woman_5th_seated", "manual_wheelchair"),
        ("man_95th_seated", "wheelchair { armrests true }"),
        ("woman_5th", "rollator"),
        ("man_95th", "rollator"),
    ];

    /// A box: corner and size in a 3 m x 3 m x 2.5 m room.
    fn boxes() -> impl Strategy<Value = Vec<[f64; 6]>> {
        let one = (
            0.0..2600.0f64,
            0.0..2600.0f64,
            0.0..2200.0f64,
            20.0..800.0f64,
            20.0..800.0f64,
            20.0..600.0f64,
        )
            .prop_map(|(x, y, z, w, d, h)| {
                [
                    x,
                    y,
                    z,
                    w.min(3000.0 - x),
                    d.min(3000.0 - y),
                    h.min(2500.0 - z),
                ]
            });
        prop::collection::vec(one, 1..5)
    }

    fn scenario(person: usize, boxes: &[[f64; 6]], targets: &[[f64; 3]]) -> String {
        let (mannequin, base) = PEOPLE[person];
        let mut text =
            String::from("units mm deg\nuse std::people\nroom r {\n  size 3000 x 3000 x 2500\n");
        for (i, b) in boxes.iter().enumerate() {
            text += &format!(
                "  box b{i} at ({:.0}, {:.0}, {:.0}) size ({:.0}, {:.0}, {:.0})\n",
                b[0], b[1], b[2], b[3], b[4], b[5]
            );
        }
        for (i, t) in targets.iter().enumerate() {
            text += &format!("  target t{i} at ({:.0}, {:.0}, {:.0})\n", t[0], t[1], t[2]);
        }
        text += &format!("}}\nperson p {{\n  mannequin {mannequin}\n  base {base}\n}}\n");
        let names: Vec<String> = (0..targets.len()).map(|i| format!("t{i}")).collect();
        text += &format!(
            "reach {} by p {{ blocked_solver incremental {{ starts 8 steer_clear true }} }}\n",
            names.join(", ")
        );
        text
    }

    #[test]
    fn most_random_rooms_are_run_not_refused() {
        no_reported_posture_passes_through_anything();
        let (run, refused) = RUN.with(|r| (r.get() & 0xffff_ffff, r.get() >> 32));
        let reached = REACHED.with(|c| c.get());
        eprintln!("{run} run, {refused} refused, {reached} targets reached");
        assert!(
            run >= 100 && refused <= run / 4,
            "{run} run, {refused} refused"
        );
        assert!(reached >= run, "{reached} reached of {run} rooms' targets");
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(128))]

        fn no_reported_posture_passes_through_anything(
            person in 0usize..PEOPLE.len(),
            boxes in boxes(),
            targets in prop::collection::vec(prop::array::uniform3(100.0..2400.0f64), 3),
        ) {
            let inside = |t: &[f64; 3]| boxes.iter().any(|b| (0..3).all(|i| t[i] >= b[i] && t[i] <= b[i] + b[i + 3]));
            let targets: Vec<[f64; 3]> = targets.into_iter().filter(|t| !inside(t)).collect();
            prop_assume!(!targets.is_empty());
            let text = scenario(person, &boxes, &targets);
            let Some(reached) = postures_checked(&text)? else {
                RUN.with(|r| r.set(r.get() + (1 << 32)));
                return Ok(());
            };
            RUN.with(|r| r.set(r.get() + 1));
            REACHED.with(|c| c.set(c.get() + reached));
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(48))]

        /// Targets on a shelf under another board, where a reach walks in
        /// from the open side (`tasks/walk_in.rs`): whatever it finds
        /// passes through nothing.
        #[test]
        fn no_posture_walked_into_a_shelf_passes_through_anything(
            person in 0usize..PEOPLE.len(),
            (low_mm, gap_mm, depth_mm) in (300.0..1600.0f64, 150.0..350.0f64, 250.0..450.0f64),
            (y_mm, width_mm) in (300.0..1500.0f64, 500.0..1200.0f64),
            depths in prop::collection::vec(0.5..0.95f64, 3),
        ) {
            // An open cabinet against the wall x = 0: two boards and
            // the two side panels between them.
            let boards = [
                [0.0, y_mm, low_mm, depth_mm, width_mm, 20.0],
                [0.0, y_mm, low_mm + gap_mm, depth_mm, width_mm, 20.0],
                [0.0, y_mm - 20.0, low_mm, depth_mm, 20.0, gap_mm + 20.0],
                [0.0, y_mm + width_mm, low_mm, depth_mm, 20.0, gap_mm + 20.0],
            ];
            let on_top = low_mm + 20.0 + 28.0;
            let targets: Vec<[f64; 3]> = depths
                .iter()
                .enumerate()
                .map(|(k, f)| [f * depth_mm, y_mm + width_mm * (k as f64 + 0.5) / 3.0, on_top])
                .collect();
            let text = scenario(person, &boards, &targets);
            postures_checked(&text)?;
        }
    }

    /// Runs scenario `text` and checks every reach's posture: a reachable
    /// one passes through nothing, and a collision it reports is real.
    /// None where the checker refuses it (a target inside a box); else
    /// how many targets were reached.
    fn postures_checked(text: &str) -> Result<Option<u64>, TestCaseError> {
        let registry = Registry::builtin();
        let (_, checked) = reach::check(
            Input::Text {
                name: "random.reach",
                text,
            },
            &registry,
        );
        // A target inside a box is refused by the checker, and a room
        // the base fits nowhere in answers "does not fit" (no posture):
        // not this test's business.
        let Ok(scenario) = checked else {
            return Ok(None);
        };
        let report = reach::run(&scenario).expect("within the bound on solver work");
        let own = scenario.bases[0].own_body();
        let body = &scenario.persons[0].body;
        let mut reached = 0;
        for task in &report.tasks {
            let TaskReport::Reach(r) = task else { continue };
            let solids = parts(body, &r.effector, &r.posture, &r.base, r.tolerance_mm);
            let room = &scenario.rooms[0];
            reached += u64::from(r.ok);
            if let Some(wrong) = solids_disagree(&solids, room, own, r) {
                prop_assert!(false, "{wrong}\n{text}");
            }
        }
        Ok(Some(reached))
    }
}
