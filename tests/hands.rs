//! Either hand: a reach that names no effector is made with the right
//! hand and the left, and answers with the hand that reaches; `hand left`
//! and `hand right` ask for one; every row names the effector.

use reach::plugin::Registry;
use reach::report::TaskReport;
use reach::Input;

/// A man standing at a fixed place facing +x, a cup 300 mm ahead and
/// `side_mm` to his left (negative: right), at chest height; the reach
/// with `options`.
fn cup_reach(side_mm: f64, options: &str) -> Result<(bool, String), String> {
    cup_task(side_mm, "reach cup", options)
}

/// The task `task` (`reach cup`, `reach cup and gaze`) of the man and cup
/// of [`cup_reach`], with `options`: whether the hand (and the eyes) do,
/// and the hand's effector.
fn cup_task(side_mm: f64, task: &str, options: &str) -> Result<(bool, String), String> {
    cup_task_at([300.0, side_mm, 1300.0], task, options)
}

/// [`cup_task`] with the cup `[ahead, to the left, high]` of the man's hip
/// point (mm; his hip point is 930 mm above the floor).
fn cup_task_at(at_mm: [f64; 3], task: &str, options: &str) -> Result<(bool, String), String> {
    let text = format!(
        "units mm deg\nuse std::people\nroom r {{\n  size 4000 x 4000 x 2500\n  \
         target cup at ({}, {}, {})\n}}\n\
         person p {{ mannequin man_50th base fixed {{ at (1000, 2000, 930) heading 0deg }} }}\n\
         {task} by p {{ {options} }}\n",
        1000.0 + at_mm[0],
        2000.0 + at_mm[1],
        at_mm[2]
    );
    let registry = Registry::builtin();
    let (_, checked) = reach::check(
        Input::Text {
            name: "hands.reach",
            text: &text,
        },
        &registry,
    );
    let scenario = checked.map_err(|d| d.render(false))?;
    let report = reach::run(&scenario).map_err(|e| e.to_string())?;
    match &report.tasks[0] {
        TaskReport::Reach(r) => Ok((r.ok, r.effector.clone())),
        TaskReport::ReachAndGaze(r) => Ok((r.ok, r.reach.effector.clone())),
        other => Err(format!("not a reach: {other:?}")),
    }
}

#[test]
fn a_reach_and_gaze_far_to_the_left_is_made_with_the_left_hand_and_named() {
    let task = "reach cup and gaze";
    let (ok, effector) = cup_task(900.0, task, "size 10mm").unwrap();
    assert!(ok && effector == "left_grip", "{ok} {effector}");
    let (ok, effector) = cup_task(900.0, task, "size 10mm hand right").unwrap();
    assert!(!ok && effector == "grip", "{ok} {effector}");
    // Mirrored: the right hand, by default too.
    let (ok, effector) = cup_task(-900.0, task, "size 10mm").unwrap();
    assert!(ok && effector == "grip", "{ok} {effector}");
    // An effector named is used alone.
    let (ok, effector) = cup_task(900.0, task, "size 10mm effector grip").unwrap();
    assert!(!ok && effector == "grip", "{ok} {effector}");
}

#[test]
fn a_cup_far_to_the_left_is_reached_by_the_left_hand_and_named() {
    // 900 mm to his left: beyond the right hand across the body.
    let (ok, effector) = cup_reach(900.0, "").unwrap();
    assert!(ok && effector == "left_grip", "{ok} {effector}");
    let (ok, effector) = cup_reach(900.0, "hand right").unwrap();
    assert!(!ok && effector == "grip", "{ok} {effector}");
    let (ok, effector) = cup_reach(900.0, "hand left").unwrap();
    assert!(ok && effector == "left_grip", "{ok} {effector}");
    // Mirrored: the right hand, by default too.
    let (ok, effector) = cup_reach(-900.0, "").unwrap();
    assert!(ok && effector == "grip", "{ok} {effector}");
    // An effector named is used alone.
    let (ok, effector) = cup_reach(900.0, "effector grip").unwrap();
    assert!(!ok && effector == "grip", "{ok} {effector}");
}

#[test]
fn a_hand_the_mannequin_lacks_is_a_diagnostic_and_a_word_not_a_hand_too() {
    let one_arm = "units mm deg\nuse std::arm\nroom r { size 4000 x 4000 x 2500\n target cup at (1450, 2000, 1300) }\n\
        person p { mannequin right_arm base fixed { at (1000, 2000, 930) heading 0deg } }\n\
        reach cup by p { hand left }\n";
    let registry = Registry::builtin();
    let (_, checked) = reach::check(
        Input::Text {
            name: "one_arm.reach",
            text: one_arm,
        },
        &registry,
    );
    let Err(diagnostics) = checked else {
        panic!("a right arm alone has no left hand")
    };
    let rendered = diagnostics.render(false);
    assert!(rendered.contains("left_grip"), "{rendered}");
    let err = cup_reach(0.0, "hand both").unwrap_err();
    assert!(err.contains("`both` is not a hand"), "{err}");
    // A hand and an effector of the other hand: which was meant cannot be
    // told (it mapped `grip` without a word).
    let err = cup_reach(0.0, "hand right effector left_grip").unwrap_err();
    assert!(err.contains("disagree"), "{err}");
    let err = cup_reach(0.0, "hand left effector grip").unwrap_err();
    assert!(err.contains("disagree"), "{err}");
}

/// The text report's table names the effector of each row.
#[test]
fn each_row_of_the_text_report_names_its_effector() {
    let o = crate::cli::reach(&["run", "examples/mother_kitchen.reach"]);
    let out = crate::cli::stdout(&o);
    let header = out.lines().find(|l| l.starts_with("task ")).unwrap();
    assert!(header.contains(" effector "), "{header}");
    assert!(
        out.lines()
            .any(|l| l.starts_with("reach ") && l.contains(" left_grip ")),
        "{out}"
    );
}

/// The solver starts counted before a run count a search with each hand.
#[test]
fn the_starts_counted_before_the_run_count_each_hand() {
    let starts = |hand: &str| {
        let text = format!(
            "units mm deg\nuse std::people\nroom r {{\n  size 4000 x 4000 x 2500\n  \
             target cup at (1300, 2000, 1300)\n}}\n\
             person p {{ mannequin man_50th base fixed {{ at (1000, 2000, 930) heading 0deg }} }}\n\
             reach cup by p {{ {hand} }}\n"
        );
        let limits = reach::Limits {
            solver_starts: 1,
            ..reach::Limits::default()
        };
        let session = reach::Session::default().limits(limits);
        let registry = Registry::builtin();
        let (_, checked) = session.check(
            Input::Text {
                name: "starts.reach",
                text: &text,
            },
            &registry,
        );
        let Err(d) = checked else {
            panic!("one start is too few")
        };
        let words = d.render(false);
        let after = words.split("up to ").nth(1).unwrap_or_default();
        let number: String = after
            .chars()
            .take_while(|c| c.is_ascii_digit() || *c == ',')
            .collect();
        number
            .replace(',', "")
            .parse::<u64>()
            .unwrap_or_else(|_| panic!("{words}"))
    };
    assert_eq!(starts(""), 2 * starts("hand right"));
    assert_eq!(starts("hand left"), starts("hand right"));
}

/// A man standing at a fixed place facing +x before a wall shelf 400 mm
/// deep spanning 2 m across him: the map of its top with `options`.
fn shelf_map(options: &str) -> reach::report::MapReport {
    let text = format!(
        "units mm deg\nuse std::people\nroom r {{\n  size 4000 x 4000 x 2500\n  \
         box shelf at (1250, 1000, 1100) size (400, 2000, 20)\n}}\n\
         person p {{ mannequin man_50th base fixed {{ at (1000, 2000, 930) heading 0deg }} }}\n\
         map shelf.top by p {{ step 100mm {options} }}\n"
    );
    let registry = Registry::builtin();
    let (_, checked) = reach::check(
        Input::Text {
            name: "shelf.reach",
            text: &text,
        },
        &registry,
    );
    let scenario = checked.map_err(|d| d.render(false)).unwrap();
    let report = reach::run(&scenario).unwrap();
    match &report.tasks[0] {
        TaskReport::Map(m) => m.clone(),
        other => panic!("not a map: {other:?}"),
    }
}

/// A map with either hand (the default) is the right hand's map where it
/// reaches, and the left hand's where it does not: each cell names the
/// hand, the cells only the left reaches lie on the left, and the file
/// of a one-hand map is named after the hand.
#[test]
fn a_map_with_either_hand_reaches_what_each_hand_reaches_and_names_it() {
    let right = shelf_map("hand right");
    let either = shelf_map("");
    assert_eq!(right.other_hand, None);
    assert_eq!(either.other_hand.as_deref(), Some("left_grip"));
    let mut left_only = 0;
    for (r, e) in right.cells.iter().zip(&either.cells) {
        if r.reachable {
            // The right hand's answer is kept as it was.
            assert!(e.reachable && e.hand == Some("right"), "{e:?}");
            assert_eq!((r.base_mm_deg, r.comfort), (e.base_mm_deg, e.comfort));
        } else if e.reachable {
            assert_eq!(e.hand, Some("left"), "{e:?}");
            // Facing +x, the left is +y.
            assert!(e.point_mm[1] > 2000.0, "{e:?}");
            left_only += 1;
        }
    }
    assert!(
        left_only > 0,
        "the left hand reaches further left: {:?}",
        either.grid
    );
    assert_eq!(either.reachable, right.reachable + left_only);
    let named = |m: &reach::report::MapReport| m.cells.iter().filter(|c| c.hand.is_some()).count();
    assert_eq!(named(&either), either.points);
    assert_eq!(named(&right), 0);
}

#[test]
fn a_map_of_one_hand_is_written_to_files_named_after_the_hand() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("shelf.reach");
    std::fs::write(
        &path,
        "units mm deg\nuse std::people\nroom r {\n  size 4000 x 4000 x 2500\n  \
         box shelf at (1250, 1500, 1100) size (400, 1000, 20)\n}\n\
         person p { mannequin man_50th base fixed { at (1000, 2000, 930) heading 0deg } }\n\
         map shelf.top by p { step 200mm hand left }\nmap shelf.top by p { step 200mm }\n",
    )
    .unwrap();
    let out = dir.path().join("out");
    let o = crate::cli::reach(&[
        "run",
        path.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", crate::cli::stderr(&o));
    for name in ["map-shelf-top-p-left_grip.svg", "map-shelf-top-p.svg"] {
        assert!(out.join(name).is_file(), "{name}");
    }
    let csv = std::fs::read_to_string(out.join("map-shelf-top-p.csv")).unwrap();
    assert!(csv.lines().next().unwrap().ends_with(",hand"), "{csv}");
    assert!(
        csv.lines()
            .skip(1)
            .all(|l| l.ends_with(",right") || l.ends_with(",left")),
        "{csv}"
    );
}

/// A cup 300 mm to one side (past that shoulder) that both hands reach is
/// reached with the hand on its side, by a reach and by a reach and gaze:
/// a person does not reach across the body for it. (A reach took the left
/// hand for a cup 300 mm to the right, a little more comfortable by the
/// criterion; a reach and gaze took the right hand for one on the left.)
#[test]
fn a_cup_well_to_one_side_is_reached_with_that_sides_hand() {
    for task in ["reach cup", "reach cup and gaze"] {
        let options = if task == "reach cup" { "" } else { "size 10mm" };
        let (ok, effector) = cup_task(300.0, task, options).unwrap();
        assert!(
            ok && effector == "left_grip",
            "{task} left: {ok} {effector}"
        );
        let (ok, effector) = cup_task(-300.0, task, options).unwrap();
        assert!(ok && effector == "grip", "{task} right: {ok} {effector}");
        // 400 mm ahead, 300 mm to the right, at 1400 mm: the left hand
        // was the more comfortable by the criterion.
        let (ok, effector) = cup_task_at([400.0, -300.0, 1400.0], task, options).unwrap();
        assert!(
            ok && effector == "grip",
            "{task} ahead right: {ok} {effector}"
        );
    }
}

/// std::body's left hand is drawn as the right's mirror image: its chain
/// negates exactly the trunk's turning and sideways bending, and every
/// posture so mirrored puts the left grip where the right grip's mirror
/// image is.
#[test]
fn the_left_arm_is_the_right_arms_mirror_image() {
    let body = reach::stdlib::body("body", "upper_body").unwrap();
    let grip = body.effector_index("grip").unwrap();
    let left = body.chain(body.effector_index("left_grip").unwrap());
    let right = body.chain(grip);
    assert!(right.mirror_of_twin.is_empty());
    let negated: Vec<&str> = (left.joints.iter().zip(&left.mirror_of_twin))
        .filter(|(_, &n)| n)
        .map(|(j, _)| j.name.as_str())
        .collect();
    assert_eq!(negated, ["trunk_rotation", "trunk_lateral"]);
    let mut worst_mm: f64 = 0.0;
    for k in 0..200 {
        let q: Vec<f64> = right
            .joints
            .iter()
            .enumerate()
            .map(|(i, j)| j.min + (j.max - j.min) * (((k * 7 + i * 13) % 17) as f64 / 16.0))
            .collect();
        let q_left: Vec<f64> = q
            .iter()
            .enumerate()
            .map(|(i, &v)| if left.drawn_negated(i) { -v } else { v })
            .collect();
        let r = right.effector(&q);
        let l = left.effector(&q_left);
        worst_mm = worst_mm.max((reach::kinematics::mirrored(&r) - l).norm());
    }
    assert!(worst_mm < 1e-9, "{worst_mm}");
}
