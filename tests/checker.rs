//! Checker tests, table-driven: each bad scenario gives its messages, each
//! pointing at the offending text; good ones give the values they mean.

use reach::bases::FixedSettings;
use reach::plugin::{Registry, Settings};
use reach::scenario::Scenario;
use reach::solvers::IncrementalSettings;
use reach::tasks::ReachSettings;
use reach::Input;

const SCENE: &str = "
room kitchen {
  size 3600 x 2800 x 2500
  target mug at (300, 1200, 960)
}
mannequin arm {
  joint shoulder dh(theta 0, d 0, alpha 90deg, a 0) limits(-90deg, 90deg)
  joint elbow dh(theta 0, d 0, alpha 0, a 300) limits(0deg, 150deg) neutral 30deg
  effector hand at (200, 0, 0)
}
";

fn check(text: &str) -> Result<Scenario, Vec<(String, String)>> {
    let registry = Registry::builtin();
    let (_, result) = reach::check(
        Input::Text {
            name: "test.reach",
            text,
        },
        &registry,
    );
    result.map_err(|d| {
        d.errors
            .iter()
            .map(|e| {
                let span = e.span().expect("every checker error has a place");
                let text = text[span.start as usize..span.end as usize].to_string();
                (e.kind().to_string(), text)
            })
            .collect()
    })
}

fn ok(text: &str) -> Scenario {
    check(text).unwrap_or_else(|e| panic!("{text}\n{e:#?}"))
}

#[test]
fn errors_point_at_the_offending_text() {
    let person =
        format!("{SCENE}person ann {{ mannequin arm base fixed {{ at (900, 1200, 930) }} }}\n");
    let cases: Vec<(String, Vec<(&str, &str)>)> = vec![
        ("let a = 1m + 2deg".into(), vec![("cannot add a length and an angle", "1m + 2deg")]),
        ("let a = 2deg - 1mm".into(), vec![("cannot subtract an angle and a length", "2deg - 1mm")]),
        ("let a = 1 / (2mm - 2mm)".into(), vec![("division by zero", "(2mm - 2mm)")]),
        ("let a = b\nlet b = a".into(), vec![("`a` is defined in terms of itself", "a")]),
        ("let a = nope".into(), vec![("unknown constant `nope`", "nope")]),
        ("let a = 1\nlet a = 2".into(), vec![("constant `a` is defined twice", "a")]),
        (
            "room k { size 10 x 10 x 10 }\nroom k { size 10 x 10 x 10 }".into(),
            vec![("room `k` is defined twice", "k")],
        ),
        ("room k { size 1deg x 10 x 10 }".into(), vec![("expected a length, found an angle", "1deg")]),
        (
            "room k { size 10 x 10 x 10 size 20 x 20 x 20 }".into(),
            vec![("the room's size is given more than once", "20 x 20 x 20")],
        ),
        (
            "room k { size 10 x 10 x 10\n box b at (0, 0, 0) size (1, 1, 1) rotate 5mm }".into(),
            vec![("expected an angle, found a length", "5mm")],
        ),
        (
            "mannequin m { joint j dh(theta 1mm) limits(0, 1) }".into(),
            vec![("expected an angle, found a length", "1mm")],
        ),
        (
            "mannequin m { joint j dh(theta 0, theta 1) limits(0, 1) }".into(),
            vec![("`theta` is given more than once", "theta")],
        ),
        (
            "mannequin m { joint j prismatic dh(d 10) limits(0deg, 1deg) }".into(),
            vec![
                ("expected a length, found an angle", "0deg"),
                ("expected a length, found an angle", "1deg"),
            ],
        ),
        (
            "mannequin m { joint j dh(a 1) limits(0, 1) limits(0, 2) }".into(),
            vec![("`limits` is given more than once", "limits(0, 2)")],
        ),
        (
            "mannequin m { joint j dh(a 1) limits(0, 1)\n joint k after jj dh(a 1) limits(0, 1)\n effector a at (0,0,0)\n effector a after j at (0,0,0) }".into(),
            vec![
                ("unknown joint declared before this one `jj`", "jj"),
                ("effector `a` is defined twice", "a"),
            ],
        ),
        (
            "mannequin m { joint j dh(a 1) limits(0, 1)\n joint f fixed dh(theta 90deg, d 5, alpha 90deg) limits(0, 1) link x }".into(),
            vec![
                ("joint `f` is fixed: it takes no length (d or a)", "5"),
                ("joint `f` is fixed: it takes no limits", "limits(0, 1)"),
                ("joint `f` is fixed: it takes no link", "x"),
            ],
        ),
        (
            "mannequin m { joint j dh(a 1) limits(0, 1)\n joint f fixed dh(alpha 90deg)\n joint k prismatic dh(d 1) limits(0, 5)\n couple j, f\n rhythm k with j, f from 30deg }".into(),
            vec![
                ("joint `f` is fixed: it takes no coupling", "f"),
                ("joint `f` is fixed: it takes no coupling", "f"),
            ],
        ),
        (
            "mannequin m { joint j dh(a 1) limits(0, 1)\n joint i dh(a 1) limits(0, 1)\n joint k prismatic dh(d 1) limits(0, 5)\n rhythm j with k, i from 30deg\n rhythm k with j, jj from 30deg\n rhythm k with j, i from 180deg\n rhythm k with j, k from 0deg }".into(),
            vec![
                ("a joint that drives a `rhythm` must be a revolute joint, found prismatic `k`", "k"),
                ("unknown joint of this mannequin `jj`", "jj"),
                ("a rhythm's `from` must be from 0deg up to 180deg, found 180deg", "180deg"),
                ("joint `k` in one `rhythm` is given more than once", "k"),
            ],
        ),
        (
            "mannequin f { joint fx fixed dh(theta 90deg)\n effector stub after fx at (200, 0, 0)\n joint sh dh(a 10) limits(0, 1) }".into(),
            vec![("mannequin `f` has no joint that moves before each effector", "f")],
        ),
        (
            "mannequin m { joint j dh(a 1) limits(0, 1)\n joint i dh(a 1) limits(0, 1)\n joint k prismatic dh(d 1) limits(0, 5)\n rhythm k with j, i from 30deg\n rhythm k with i, j from 60deg }".into(),
            vec![("a `rhythm` of `k` is given more than once", "k")],
        ),
        (
            // A bare number is in the file's unit (85 cm); a chest depth
            // that makes std::body's trunk radius negative is shown here.
            "units cm deg\nuse std::people\nperson p { mannequin measured(sitting_height 85, chest_depth -10) base manual_wheelchair }".into(),
            vec![("a radius must be zero or more, found -50mm", "measured")],
        ),
        (
            "use std::people\nperson p { mannequin man_50th_seated { limits shoulder_flexion (-60deg, 200deg) limits elbow_flexion (-20deg, 140deg) } base manual_wheelchair }".into(),
            vec![
                ("the limits of `shoulder_flexion`, -60deg to 200deg, go beyond its anatomical range, -60deg to 180deg", "limits shoulder_flexion (-60deg, 200deg)"),
                ("the limits of `elbow_flexion`, -20deg to 140deg, go beyond its anatomical range, 0deg to 150deg", "limits elbow_flexion (-20deg, 140deg)"),
            ],
        ),
        (
            "mannequin m { joint j dh(a 1) limits(-1, 1) anatomical(-0.5, 2) }".into(),
            vec![("the limits of `j`, -1deg to 1deg, go beyond its anatomical range, -0.5deg to 2deg", "anatomical(-0.5, 2)")],
        ),
        (
            "mannequin f { joint fx fixed dh(theta 90deg) }".into(),
            vec![("mannequin `f` has no joint that moves before each effector", "f")],
        ),
        (
            "mannequin n(a = 1mm, b = 2 * a) { joint j dh(a a) limits(0, 1)\n require b <= 3 * a, \"b too long\" }\nmannequin o = n(a 1mm, b 5mm)".into(),
            vec![("b too long", "b 5mm")],
        ),
        (
            "use std::people\nperson p { mannequin measured(stature 1500mm, forearm_hand 600mm) base manual_wheelchair }".into(),
            vec![(
                "the forearm-hand length is too long for the stature: measured adults have 0.306 of their stature or less (the back of the bent elbow to the middle fingertip)",
                "forearm_hand 600mm",
            )],
        ),
        (
            "mannequin m(l = 1mm) = n(a l)\nmannequin n(a = 1mm) { joint j dh(a a) limits(0, 1) }\nmannequin o = m(l 2mm, q 3mm)".into(),
            vec![("unknown parameter of this mannequin `q`", "q")],
        ),
        (
            format!("{SCENE}person ann {{ mannequin arm {{ neutral elbow 160deg }} base fixed {{ at (0,0,0) }} }}"),
            vec![(
                "the neutral value must be within the joint's limits, 0deg to 150deg, found 160deg",
                "160deg",
            )],
        ),
        (
            format!("{SCENE}person ann {{ mannequin arm mannequin arm base fixed {{ at (0,0,0) }} }}"),
            vec![("`mannequin` is given more than once", "arm")],
        ),
        (
            format!("{SCENE}person ann {{ mannequin arm base fixed {{ at 5 }} }}"),
            vec![("expected a point (x, y, z), found a number", "5")],
        ),
        (
            format!("{SCENE}person ann {{ mannequin arm base fixed {{ at (0,0,0) heading 1mm }} }}"),
            vec![("expected an angle, found a length", "1mm")],
        ),
        (
            format!("{person}reach mug by ann {{ solver incremental {{ starts 0 }} }}"),
            vec![("option `starts` must be between 1 and 1000, found 0", "0")],
        ),
        (
            format!("{person}reach mug by ann {{ solver 5 }}"),
            vec![("expected the name of a solver, found an expression", "5")],
        ),
        (
            format!("{person}reach mug by ann {{ solver fixed }}"),
            vec![("unknown solver `fixed`", "fixed")],
        ),
        (
            format!("{person}reach mug by ann {{ tolerance \"5mm\" }}"),
            vec![("expected a length, found a string", "\"5mm\"")],
        ),
        (
            format!("{person}reach mug, cup by ann, bob"),
            vec![("unknown target `cup`", "cup"), ("unknown person `bob`", "bob")],
        ),
        (
            format!("{person}map kitchen_wall.top by ann"),
            vec![("unknown surface or box `kitchen_wall`", "kitchen_wall.top")],
        ),
        (
            format!("{SCENE}room k2 {{ size 4000 x 4000 x 2500\n box counter at (0,0,0) size (600, 3000, 900) }}\nperson ann {{ mannequin arm base fixed {{ at (900, 1200, 930) }} }}\nmap counter.tpo by ann"),
            vec![("unknown face `tpo`", "counter.tpo")],
        ),
        (
            format!("{SCENE}room k2 {{ size 4000 x 4000 x 2500\n box counter at (0,0,0) size (600, 3000, 900) }}\nperson ann {{ mannequin arm base fixed {{ at (900, 1200, 930) }} }}\nmap counter.top by ann {{ step 1mm }}"),
            vec![("the map of `counter.top` (1800000 points) exceeds the limit of 100000 points: raise `max_points` or the `step`", "counter.top")],
        ),
        (
            "room k { size 10 x 10 x 10\n surface s at (0, 0, 0) size (5, 5, 5) }".into(),
            vec![("a surface's size must be two positive sizes and one zero, found (5, 5, 5) mm", "(5, 5, 5)")],
        ),
    ];
    for (text, expected) in cases {
        let errors = match check(&text) {
            Ok(_) => panic!("{text}\nchecks without error"),
            Err(e) => e,
        };
        let got: Vec<(&str, &str)> = errors
            .iter()
            .map(|(m, t)| (m.as_str(), t.as_str()))
            .collect();
        assert_eq!(got, expected, "\n{text}");
    }
}

#[test]
fn units_follow_the_file_default_and_explicit_units_win() {
    let s = ok("units cm rad\nroom k { size 360 x 280 x 250\n target t at (30, 120mm, 1m) }");
    let t = &s.rooms[0].targets[0];
    assert_eq!(
        [t.position_mm.x, t.position_mm.y, t.position_mm.z],
        [300.0, 120.0, 1000.0]
    );
    assert_eq!(s.rooms[0].size_mm.x, 3600.0);
}

/// `min` and `max` take the kind of their arguments: a bare number beside
/// a length is a length in the file's unit, and bare numbers stay bare to
/// take the unit of the place they are used.
#[test]
fn min_and_max_of_bare_numbers_and_lengths() {
    let cases = [
        ("units cm\nlet x = min(20, 300mm)", 200.0),
        ("units cm\nlet x = min(300mm, 20)", 200.0),
        ("units cm\nlet x = max(20, 300mm)", 300.0),
        ("units cm\nlet x = max(10, 20)", 200.0),
        ("units cm\nlet x = min(10, 20) + 1mm", 101.0),
        ("units mm\nlet x = min(915, 900mm, 1m)", 900.0),
    ];
    for (lets, x_mm) in cases {
        let s = ok(&format!(
            "{lets}\nroom k {{ size 3m x 3m x 3m\n target t at (x, 0, 0) }}"
        ));
        assert_eq!(s.rooms[0].targets[0].position_mm.x, x_mm, "{lets}");
    }
    let e = check("let x = min(1m, 2deg)").unwrap_err();
    assert!(e[0].0.contains("a length and an angle"), "{e:?}");
}

#[test]
fn constants_may_be_used_before_they_are_defined() {
    let s = ok(
        "room k { size w x w x h\n target t at (w / 2, 0, h - 10cm) }\nlet w = 2 * h\nlet h = 1m",
    );
    assert_eq!(s.rooms[0].size_mm.x, 2000.0);
    assert_eq!(s.rooms[0].targets[0].position_mm.x, 1000.0);
    assert_eq!(s.rooms[0].targets[0].position_mm.z, 900.0);
}

#[test]
fn a_person_gets_the_mannequin_with_their_own_limits() {
    let text = format!(
        "{SCENE}person ann {{\n mannequin arm {{ limits elbow (10deg, 90deg) weight elbow 3 }}\n base fixed {{ at (900, 1200, 930) heading 90deg }}\n}}"
    );
    let s = ok(&text);
    let elbow = &s.persons[0].body.chain(0).joints[1];
    assert!((elbow.min.to_degrees() - 10.0).abs() < 1e-9);
    assert!((elbow.max.to_degrees() - 90.0).abs() < 1e-9);
    assert_eq!(elbow.weight, 3.0);
    assert!((elbow.neutral.to_degrees() - 30.0).abs() < 1e-9);
    assert_eq!(s.persons[0].base.name, "fixed");
    let base = FixedSettings::from_options(&s.persons[0].base.options).unwrap();
    assert!((base.heading_rad.to_degrees() - 90.0).abs() < 1e-9);
}

/// A `fixed` frame turns the axes of the joint after it as a joint held
/// at zero would, and is no joint of the body; an alias with parameters
/// of its own gives the mannequin it names values made of them; a
/// `rhythm` couples its follower to its drivers by their body indices.
#[test]
fn fixed_frames_rhythms_and_aliases_with_parameters_build_the_body_meant() {
    let mannequins = "
mannequin held(arm = 300mm) {
  joint up dh(alpha 90deg) limits(-90deg, 90deg)
  joint turn dh(theta 90deg, alpha 90deg) limits(0deg, 0deg)
  joint slide prismatic dh(d 0) limits(0, 50)
  joint elbow dh(a arm) limits(0deg, 150deg)
  effector hand at (200, 0, 0)
}
mannequin framed(arm = 300mm) {
  joint up dh(alpha 90deg) limits(-90deg, 90deg)
  joint turn fixed dh(theta 90deg, alpha 90deg)
  joint slide prismatic dh(d 0) limits(0, 50)
  joint elbow dh(a arm) limits(0deg, 150deg)
  effector hand at (200, 0, 0)
  rhythm slide with up, elbow from 30deg
}
mannequin long(forearm = 100mm) = framed(arm forearm + 250mm)
";
    let text = format!(
        "{SCENE}{mannequins}person a {{ mannequin held base fixed {{ at (0, 0, 0) }} }}\n\
         person b {{ mannequin long(forearm 50mm) base fixed {{ at (0, 0, 0) }} }}\n"
    );
    let s = ok(&text);
    let (held, framed) = (s.persons[0].body.chain(0), s.persons[1].body.chain(0));
    assert_eq!(framed.joints.len(), 3, "the fixed frame is no joint");
    assert!(framed.joints[1].pre.is_some());
    for (up, slide, elbow) in [(0.0, 0.0, 0.0), (0.5, 20.0, 1.0), (-1.2, 45.0, 0.3)] {
        let want = held.effector(&[up, 0.0, slide, elbow]);
        let got = framed.effector(&[up, slide, elbow]);
        assert!((want - got).norm() < 1e-9, "{want} {got}");
    }
    assert!((framed.joints[2].dh.a_mm - 300.0).abs() < 1e-9);
    match &framed.couplings[..] {
        [reach::kinematics::Coupling::Rhythm(r)] => {
            assert_eq!((r.follower, r.drivers), (1, [0, 2]));
            assert!((r.from_rad.to_degrees() - 30.0).abs() < 1e-9);
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn plugin_options_take_their_declared_defaults() {
    let text = format!(
        "{SCENE}person ann {{ mannequin arm base fixed {{ at (900, 1200, 930) }} }}\nreach mug by ann {{ solver incremental {{ rate 0.2 }} }}"
    );
    let s = ok(&text);
    let ReachSettings { common: task, hand } =
        ReachSettings::from_options(&s.tasks[0].options).unwrap();
    assert_eq!(hand, None);
    assert_eq!(task.tolerance_mm, 10.0);
    assert_eq!(task.solver.name, "incremental");
    let solver = IncrementalSettings::from_options(&task.solver.options).unwrap();
    assert_eq!(solver.rate, 0.2);
    assert_eq!(solver.gamma, 3.0);
    assert_eq!(solver.stall, 10);
    assert_eq!(solver.starts, 6);
}

#[test]
fn a_default_plugin_gets_its_own_default_options() {
    let text = format!("{SCENE}person ann {{ mannequin arm base fixed {{ at (900, 1200, 930) }} }}\nreach mug by ann");
    let s = ok(&text);
    let ReachSettings { common: task, hand } =
        ReachSettings::from_options(&s.tasks[0].options).unwrap();
    assert_eq!(hand, None);
    assert_eq!(task.solver.name, "incremental");
    let solver = IncrementalSettings::from_options(&task.solver.options).unwrap();
    assert_eq!(solver.rate, 0.05);
    assert!(solver.incremental_fk);
}

#[test]
fn one_task_per_subject_and_person_in_order() {
    let text = format!(
        "{SCENE}person ann {{ mannequin arm base fixed {{ at (900, 1200, 930) }} }}\nperson bob {{ mannequin arm base fixed {{ at (900, 1000, 930) }} }}\nroom hall {{ size 3000 x 3000 x 2500\n target hook at (1, 1, 1) }}\nreach mug, hook by ann, bob"
    );
    let s = ok(&text);
    let order: Vec<(&str, &str)> = s
        .tasks
        .iter()
        .map(|t| (t.subject_name(&s), s.persons[t.person].name.as_str()))
        .collect();
    assert_eq!(
        order,
        [
            ("mug", "ann"),
            ("mug", "bob"),
            ("hook", "ann"),
            ("hook", "bob")
        ]
    );
}

/// Which box a target is inside, asked of the boxes' bounds in an R-tree:
/// a turned box holds what its own axes hold (not what its bounding
/// rectangle does), a point on a face is outside, and of two boxes that
/// hold a target the first declared is named.
#[test]
fn a_target_inside_a_box_names_the_first_box_that_holds_it() {
    let rooms = [
        // A box turned 45 degrees about its corner (100, 0): its bounds
        // hold (160, 10, 50), the box does not; it holds (100, 70, 50).
        ("box b at (100, 0, 0) size (100, 100, 100) rotate 45deg", "(160, 10, 50)", None),
        ("box b at (100, 0, 0) size (100, 100, 100) rotate 45deg", "(100, 70, 50)", Some("b")),
        // On the top face: a mug on a counter.
        ("box b at (0, 0, 0) size (100, 100, 100)", "(50, 50, 100)", None),
        (
            "box late at (40, 40, 0) size (20, 20, 20)\n box early at (0, 0, 0) size (100, 100, 100)",
            "(50, 50, 10)",
            Some("late"),
        ),
        (
            "box a at (0, 0, 0) size (100, 100, 100)\n box b at (40, 40, 0) size (20, 20, 20)",
            "(50, 50, 10)",
            Some("a"),
        ),
    ];
    for (boxes, at, holder) in rooms {
        let text = format!("room k {{ size 1000 x 1000 x 1000\n {boxes}\n target t at {at} }}");
        let found = match check(&text) {
            Ok(_) => None,
            Err(errors) => {
                assert_eq!(errors.len(), 1, "{text}: {errors:?}");
                assert_eq!(errors[0].1, at, "{text}");
                Some(errors[0].0.clone())
            }
        };
        let expected = holder.map(|b| format!("target `t` is inside box `{b}`"));
        assert_eq!(found, expected, "{text}");
    }
}
