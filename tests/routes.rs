//! Doors and routes through the language and the binary: a wheelchair gets
//! past a gap a millimetre wider than itself and not one a millimetre
//! narrower; a person shut out by the doors is an answer (exit 0, 3 with
//! `--strict`); a target reachable only from a closed-in pocket is "cannot
//! get there" with the furniture named.

use reach::report::TaskReport;

use crate::body::run;
use crate::cli::{reach, stderr, stdout};

/// A 4 x 6 m room divided at y = 3000 by two counters with `gap` between
/// them; the door in the near wall, the target on a shelf beyond.
fn divided(gap: f64) -> String {
    let left = (4000.0 - gap) / 2.0;
    format!(
        "units mm deg\nuse std::people\nroom r {{\n  size 4000 x 6000 x 2500\n  \
         box left at (0, 2900, 0) size ({left}, 200, 900)\n  \
         box right at ({}, 2900, 0) size ({}, 200, 900)\n  \
         box shelf at (1500, 5700, 800) size (1000, 300, 20)\n  \
         target jar at (2000, 5850, 850)\n  door hall at (2000, 0) width 900mm\n}}\n\
         person ann {{ mannequin woman_5th_seated base manual_wheelchair }}\nreach jar by ann\n",
        left + gap,
        4000.0 - left - gap
    )
}

#[test]
fn a_gap_a_millimetre_narrower_than_the_chair_closes_the_way_and_one_wider_opens_it() {
    let (scenario, _) = run(&divided(2000.0));
    let width = scenario.bases[0].footprint().expect("a chair").size_mm()[1];
    let verdict = |gap: f64| {
        let (_, report) = run(&divided(gap));
        report.tasks[0].answer()
    };
    let wider = verdict(width + 1.0);
    assert!(wider.ok, "{width} + 1 mm: {}", wider.verdict);
    let narrower = verdict(width - 1.0);
    assert!(!narrower.ok);
    assert!(
        narrower.verdict.contains("cannot get there"),
        "{width} - 1 mm: {}",
        narrower.verdict
    );
}

/// An 11 x 10 m room cut across by two counters with a gap exactly as
/// wide as the chair (660 mm) between them: with no room to spare there is
/// no way through, wherever the tiles the floor is worked out in cut the
/// gap (found by a helper comparing routes before and after the tiles:
/// here the tiles' rounding had left a channel of no width open).
#[test]
fn a_gap_exactly_as_wide_as_the_chair_is_no_way() {
    let text = "units mm deg\nuse std::people\nroom r {\n  size 11408 x 10071 x 2500\n  \
         box left at (0, 6977, 0) size (6127.2, 549, 900)\n  \
         box right at (6787.2, 6977, 0) size (4620.4, 549, 900)\n  \
         door door1 at (4889, 0) width 938mm\n  \
         target t1 at (6270, 8210, 645)\n  target t3 at (4202, 8659, 926)\n}\n\
         person ann { mannequin woman_5th_seated base manual_wheelchair }\nreach t1, t3 by ann\n";
    let (scenario, report) = run(text);
    let width = scenario.bases[0].footprint().expect("a chair").size_mm()[1];
    assert!((width - 660.0).abs() < 1e-9, "the chair is {width} mm wide");
    for task in &report.tasks {
        let answer = task.answer();
        assert!(
            !answer.ok && answer.verdict.contains("cannot get there"),
            "{}",
            answer.verdict
        );
    }
}

#[test]
fn a_person_the_doors_shut_out_is_an_answer_and_strict_exits_3() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("narrow.reach");
    let text = divided(2000.0).replace("width 900mm", "width 600mm");
    std::fs::write(&path, text).unwrap();
    let path = path.to_str().unwrap();
    let o = reach(&["run", path]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let out = stdout(&o);
    assert!(
        out.contains("cannot get in: no door lets the base in"),
        "{out}"
    );
    assert!(
        out.contains("too narrow: the base needs 660 mm, the door is 600 mm"),
        "{out}"
    );
    let strict = reach(&["run", "--strict", path]);
    assert_eq!(strict.status.code(), Some(3), "{}", stderr(&strict));
}

#[test]
fn a_target_reached_only_from_a_closed_in_pocket_cannot_be_got_to() {
    let o = reach(&["run", "--format", "json", "examples/pocket.reach"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let report: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let kettle = &report["tasks"][0];
    assert_eq!(kettle["ok"], false, "{kettle}");
    assert_eq!(kettle["why"][0]["cause"], "cannot_get_there", "{kettle}");
    let names = kettle["why"][0]["names"].as_array().unwrap();
    for name in ["island", "cupboard_n", "cupboard_s", "counter"] {
        assert!(names.iter().any(|n| n == name), "{name} in {names:?}");
    }
    assert_eq!(
        report["tasks"][1]["ok"], true,
        "the mug, from the open floor"
    );
    // Without the door, the pocket is floor like any other.
    let text = std::fs::read_to_string("examples/pocket.reach").unwrap();
    let (_, open) = run(&text.replace("  door hall at (3200, 0) width 900mm\n", ""));
    let TaskReport::Reach(kettle) = &open.tasks[0] else {
        panic!("a reach")
    };
    assert!(kettle.ok);
    assert!(open.notes.iter().any(|n| n.contains("no `door`")));
}
