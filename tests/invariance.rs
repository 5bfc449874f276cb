//! Answers that do not depend on where the room is: a kitchen island (a
//! counter, a wall cabinet's board over it, now and then a post) in the
//! middle of a large square room, five targets on it, under it and in the
//! cabinet, and one seated person with a fixed base or a wheelchair. The
//! same kitchen moved across the room, or turned by 90 degrees about the
//! room's centre (the room turns onto itself), asks the same questions of
//! the same person.
//!
//! What holds: moved or turned, a person on a fixed base gets the same
//! answers to the report's last digit (verdicts, distances, postures,
//! comfort, causes), since each solve is seeded by where its target is
//! from the person (`scene::seed_in_base_frame`), not by where it is in
//! the room, and a heading along a wall turns exactly; mirrored left to
//! right and asked of the other hand, a two-armed person on a fixed base
//! or a wheelchair gets the same answers with the posture seen in a
//! mirror (`kinematics::mirror`). Moved or turned, a wheelchair user gets
//! the same verdicts; the wheelchair's placements may differ in their last
//! digits (the floor's outlines are worked out in the room's own
//! coordinates).

use proptest::prelude::*;
use reach::plugin::Registry;
use reach::Input;
use serde_json::Value;

/// The side of the square room, and its centre.
const ROOM_MM: f64 = 6000.0;
const CENTRE_MM: f64 = ROOM_MM / 2.0;

/// How the kitchen is placed in the room.
#[derive(Clone, Copy, Debug)]
enum Placed {
    AsDrawn,
    /// Moved across the floor by (x, y) mm.
    Moved(f64, f64),
    /// Turned by 90 degrees about the room's centre, counter-clockwise.
    Turned,
    /// Mirrored left to right (y to the room's side less y), asked of the
    /// other hand.
    Mirrored,
}

impl Placed {
    /// Where the point (x, y) of the drawn kitchen is.
    fn point(self, x: f64, y: f64) -> (f64, f64) {
        match self {
            Placed::AsDrawn => (x, y),
            Placed::Moved(dx, dy) => (x + dx, y + dy),
            Placed::Turned => (2.0 * CENTRE_MM - y, x),
            Placed::Mirrored => (x, ROOM_MM - y),
        }
    }

    /// Where the box at corner (x, y) with sides (sx, sy) is: its corner
    /// and sides.
    fn box_xy(self, x: f64, y: f64, sx: f64, sy: f64) -> (f64, f64, f64, f64) {
        match self {
            Placed::Turned => (2.0 * CENTRE_MM - y - sy, x, sy, sx),
            Placed::Mirrored => (x, ROOM_MM - y - sy, sx, sy),
            _ => {
                let (x, y) = self.point(x, y);
                (x, y, sx, sy)
            }
        }
    }

    fn heading_deg(self, heading_deg: f64) -> f64 {
        match self {
            Placed::Turned => heading_deg + 90.0,
            Placed::Mirrored => -heading_deg,
            _ => heading_deg,
        }
    }
}

/// A target: where on the island (0: on the top, 1: above the top, 2:
/// in the cabinet, 3: low in front), and where along it.
type TargetAt = (u8, f64, f64, f64);

/// The drawn kitchen.
#[derive(Clone, Debug)]
struct Kitchen {
    counter_height_mm: f64,
    counter_depth_mm: f64,
    counter_x_mm: f64,
    board_height_mm: f64,
    post: Option<(f64, f64)>,
    targets: Vec<TargetAt>,
    /// The fixed base's hip point (x, y); none: a wheelchair.
    fixed: Option<(f64, f64)>,
}

fn kitchen(wheelchair: bool) -> impl Strategy<Value = Kitchen> {
    (
        prop::sample::select(vec![720.0, 800.0, 860.0, 900.0, 950.0]),
        prop::sample::select(vec![500.0, 600.0, 650.0]),
        -100.0..100.0f64,
        0.0..300.0f64,
        prop::option::of((900.0..1300.0f64, 200.0..800.0f64)),
        prop::collection::vec((0u8..4, 0.0..1.0f64, 0.0..1.0f64, 0.0..1.0f64), 5),
        (250.0..450.0f64, 400.0..1200.0f64),
    )
        .prop_map(
            move |(height, depth, x, board, post, targets, (front, along))| {
                let counter_x_mm = 2000.0 + x;
                Kitchen {
                    counter_height_mm: height,
                    counter_depth_mm: depth,
                    counter_x_mm,
                    board_height_mm: 1300.0 + board,
                    post,
                    targets,
                    fixed: (!wheelchair).then_some((counter_x_mm + depth + front, 2200.0 + along)),
                }
            },
        )
}

impl Kitchen {
    /// The scenario text, the kitchen placed as `placed`, asked of a
    /// one-armed person (std::arm's right arm).
    fn text(&self, placed: Placed) -> String {
        self.text_asking(placed, None)
    }

    /// The scenario text, the kitchen placed as `placed`; `hand`: asked
    /// of that hand of a two-armed person (std::body's upper body), else
    /// as [`Kitchen::text`].
    fn text_asking(&self, placed: Placed, hand: Option<&str>) -> String {
        let (x0, depth, height) = (
            self.counter_x_mm,
            self.counter_depth_mm,
            self.counter_height_mm,
        );
        let mut boxes = vec![
            ("counter", [x0, 2200.0, 0.0], [depth, 1600.0, height]),
            (
                "cabinet",
                [x0, 2200.0, self.board_height_mm],
                [350.0, 1600.0, 20.0],
            ),
        ];
        if let Some((px, py)) = self.post {
            boxes.push(("post", [x0 + px, 2200.0 + py, 0.0], [150.0, 150.0, 2000.0]));
        }
        // Asked of a hand, on whole quarter millimetres, as a drawing is
        // (so that mirroring the room, y to its side less y, is exact).
        let snap = |v: f64| {
            if hand.is_some() {
                (v * 4.0).round() / 4.0
            } else {
                v
            }
        };
        let module = if hand.is_some() { "body" } else { "arm" };
        let mut text = format!(
            "units mm deg\nuse std::{module}\n\nroom r {{\n  size {ROOM_MM} x {ROOM_MM} x 2500\n"
        );
        for (name, [x, y, z], [sx, sy, sz]) in boxes {
            let [x, y, z, sx, sy, sz] = [x, y, z, sx, sy, sz].map(snap);
            let (x, y, sx, sy) = placed.box_xy(x, y, sx, sy);
            text +=
                &format!("  box {name} at ({x:?}, {y:?}, {z:?}) size ({sx:?}, {sy:?}, {sz:?})\n");
        }
        for (k, &(kind, u, v, w)) in self.targets.iter().enumerate() {
            let [x, y, z] = self.target(kind, u, v, w).map(snap);
            let (x, y) = placed.point(x, y);
            text += &format!("  target t{k} at ({x:?}, {y:?}, {z:?})\n");
        }
        let mannequin = if hand.is_some() {
            "upper_body"
        } else {
            "right_arm"
        };
        text += &format!(
            "}}\nperson p {{\n  mannequin {mannequin} {{ limits trunk_flexion (-10deg, 40deg) }}\n"
        );
        match self.fixed {
            Some((x, y)) => {
                let (x, y) = placed.point(snap(x), snap(y));
                let heading = placed.heading_deg(180.0);
                text +=
                    &format!("  base fixed {{ at ({x:?}, {y:?}, 930) heading {heading:?}deg }}\n");
            }
            None => text += "  base wheelchair\n",
        }
        let names: Vec<String> = (0..self.targets.len()).map(|k| format!("t{k}")).collect();
        let options = hand.map_or(String::new(), |h| format!(" {{ hand {h} }}"));
        text + &format!("}}\nreach {} by p{options}\n", names.join(", "))
    }

    fn target(&self, kind: u8, u: f64, v: f64, w: f64) -> [f64; 3] {
        let (x0, depth, height) = (
            self.counter_x_mm,
            self.counter_depth_mm,
            self.counter_height_mm,
        );
        let on_top = x0 + 30.0 + u * (depth - 60.0);
        let y = 2300.0 + v * 1400.0;
        match kind {
            0 => [on_top, y, height + 40.0],
            1 => [on_top, y, height + 250.0],
            2 => [
                x0 + 30.0 + u * 290.0,
                y,
                self.board_height_mm + 60.0 + w * 300.0,
            ],
            _ => [x0 + depth + 50.0 + u * 250.0, y, 300.0 + w * 400.0],
        }
    }
}

/// The report's tasks of `text`, run.
pub(super) fn tasks(text: &str) -> Vec<Value> {
    let registry = Registry::builtin();
    let (_, checked) = reach::check(
        Input::Text {
            name: "island.reach",
            text,
        },
        &registry,
    );
    let scenario = checked.unwrap_or_else(|d| panic!("{}\n{text}", d.render(false)));
    let report = reach::run(&scenario).expect("within the bound on solver work");
    let json = registry
        .format("json")
        .unwrap()
        .render(&report, &scenario.format_scene())
        .unwrap();
    let mut value: Value = serde_json::from_str(&json).unwrap();
    value["tasks"].as_array_mut().map(std::mem::take).unwrap()
}

/// Each task's verdict.
fn verdicts(tasks: &[Value]) -> Vec<bool> {
    tasks.iter().map(|t| t["ok"] == Value::Bool(true)).collect()
}

/// A task's answer but for where the base stood and where the hand and
/// the target are in the room.
fn answer(task: &Value) -> Value {
    let mut task = task.clone();
    for room_frame in ["base", "effector_mm", "target_mm"] {
        task.as_object_mut().unwrap().remove(room_frame);
    }
    task
}

/// Where a task's base stood, less `(dx, dy)`.
fn base_less(task: &Value, dx: f64, dy: f64) -> (f64, f64, f64) {
    let base = &task["base"];
    let at = |k: &str| base[k].as_f64().unwrap_or(f64::NAN);
    (at("x_mm") - dx, at("y_mm") - dy, at("heading_deg"))
}

/// Moves of whole quarter millimetres, as a drawing is moved.
fn a_move() -> impl Strategy<Value = (f64, f64)> {
    (-2000i32..2000, -2000i32..2000).prop_map(|(x, y)| (x as f64 / 4.0, y as f64 / 4.0))
}

proptest! {
    #![proptest_config(ProptestConfig {
        cases: 12,
        rng_seed: proptest::test_runner::RngSeed::Fixed(57),
        ..ProptestConfig::default()
    })]

    /// Moved, a person on a fixed base gets the same answers, to the last
    /// digit, from the same place.
    #[test]
    fn a_fixed_base_moved_answers_the_same(k in kitchen(false), (dx, dy) in a_move()) {
        let drawn = tasks(&k.text(Placed::AsDrawn));
        let moved = tasks(&k.text(Placed::Moved(dx, dy)));
        for (a, b) in drawn.iter().zip(&moved) {
            prop_assert_eq!(answer(a), answer(b));
            let (xa, ya, ha) = base_less(a, 0.0, 0.0);
            let (xb, yb, hb) = base_less(b, dx, dy);
            prop_assert!((xa - xb).abs() < 0.011 && (ya - yb).abs() < 0.011 && ha == hb);
        }
    }

    /// Turned by 90 degrees, a person on a fixed base gets the same
    /// answers, to the report's last digit (a heading along a wall turns
    /// exactly: `BasePose::rotation`).
    #[test]
    fn a_fixed_base_turned_answers_the_same(k in kitchen(false)) {
        let drawn = tasks(&k.text(Placed::AsDrawn));
        let turned = tasks(&k.text(Placed::Turned));
        for (a, b) in drawn.iter().zip(&turned) {
            prop_assert_eq!(answer(a), answer(b));
        }
    }

    /// Mirrored, a two-armed person on a fixed base asked of the other
    /// hand gets the same answers: verdicts, shortfalls, comfort and the
    /// posture seen in a mirror, to the report's last digit (the left hand
    /// draws its starts, kicks and first steps as the right's mirror
    /// image, `kinematics::mirror`, and a step that leaves the distance as
    /// it was is taken, not left to rounding). Fails on c280014:
    /// shortfalls differed by up to 12 mm, postures in most tasks.
    #[test]
    fn a_fixed_base_mirrored_answers_the_same_with_the_other_hand(k in kitchen(false)) {
        let drawn = tasks(&k.text_asking(Placed::AsDrawn, Some("right")));
        let mirrored = tasks(&k.text_asking(Placed::Mirrored, Some("left")));
        for (a, b) in drawn.iter().zip(&mirrored) {
            prop_assert_eq!(&a["effector"], "grip");
            prop_assert_eq!(&b["effector"], "left_grip");
            for same in ["ok", "distance_mm", "comfort", "iterations"] {
                prop_assert_eq!(&a[same], &b[same], "{}", same);
            }
            // The causes, naming the other arm's joints.
            prop_assert_eq!(a["why"].to_string(), b["why"].to_string().replace("left_", ""));
            prop_assert_eq!(mirrored_posture(&a["posture"]), sorted_posture(&b["posture"]));
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig {
        cases: 4,
        rng_seed: proptest::test_runner::RngSeed::Fixed(57),
        ..ProptestConfig::default()
    })]

    /// Moved or turned, a wheelchair user gets the same verdicts; mirrored
    /// and asked of the other hand, the same answers (verdicts, shortfalls,
    /// comfort, the posture seen in a mirror).
    #[test]
    fn a_wheelchair_moved_turned_or_mirrored_answers_the_same(
        k in kitchen(true),
        (dx, dy) in a_move(),
    ) {
        let drawn = verdicts(&tasks(&k.text(Placed::AsDrawn)));
        prop_assert_eq!(&drawn, &verdicts(&tasks(&k.text(Placed::Moved(dx, dy)))));
        prop_assert_eq!(&drawn, &verdicts(&tasks(&k.text(Placed::Turned))));
        let right = tasks(&k.text_asking(Placed::AsDrawn, Some("right")));
        let left = tasks(&k.text_asking(Placed::Mirrored, Some("left")));
        for (a, b) in right.iter().zip(&left) {
            for same in ["ok", "distance_mm", "comfort"] {
                prop_assert_eq!(&a[same], &b[same], "{}", same);
            }
            prop_assert_eq!(mirrored_posture(&a["posture"]), sorted_posture(&b["posture"]));
        }
    }
}

/// A two-armed person's posture, named by joint, with the left and right
/// arms' names swapped and the joints that turn about an axis in the
/// body's midplane (bending and turning sideways) negated: the posture
/// seen in a mirror.
fn mirrored_posture(posture: &Value) -> Vec<(String, f64)> {
    let mut joints: Vec<(String, f64)> = posture
        .as_object()
        .unwrap()
        .iter()
        .map(|(name, value)| {
            let value = value.as_f64().unwrap();
            let swapped = match name.strip_prefix("left_") {
                Some(right) => right.to_string(),
                None => format!("left_{name}"),
            };
            let sideways = ["trunk_rotation", "trunk_lateral"].contains(&name.as_str());
            match name.as_str() {
                _ if sideways => (name.clone(), -value),
                n if n.starts_with("trunk_") => (name.clone(), value),
                _ => (swapped, value),
            }
        })
        .collect();
    joints.sort_by(|a, b| a.0.cmp(&b.0));
    joints
}

fn sorted_posture(posture: &Value) -> Vec<(String, f64)> {
    let mut joints: Vec<(String, f64)> = (posture.as_object().unwrap().iter())
        .map(|(name, value)| (name.clone(), value.as_f64().unwrap()))
        .collect();
    joints.sort_by(|a, b| a.0.cmp(&b.0));
    joints
}
