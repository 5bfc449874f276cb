//! Which hand a reach or a map uses: the effector asked for, its twin on
//! the other hand (`left_` and its name), or either, the default where
//! the task names no effector.

use nalgebra::Point3;

use super::common::Common;
use crate::kinematics::{hand_side, Body, LEFT_PREFIX as LEFT};
use crate::plugin::{BasePose, Params, SettingsError};

/// The option `hand`'s documentation, for a task that searches with each
/// hand (a reach).
pub const HAND_DOC: &str = "`either` (the effector and its twin on the other hand, `left_` and its name, where the mannequin has both: the hand that reaches; where both do, the hand on the target's side when the target is more than 150 mm to one side, else the more comfortable; the default where no effector is named), `right` or `left`";

/// The option `hand`'s documentation, for a task that tries the twin only
/// where the effector asked for does not do (a map's point).
pub const HAND_DOC_FIRST: &str = "`either` (the effector and its twin on the other hand, `left_` and its name, where the mannequin has both: the effector where it does, else its twin; the default where no effector is named), `right` or `left`";

/// The option `hand`'s documentation for a reach and gaze: the twin is
/// tried where the first does not do or the target is on its side.
pub const HAND_DOC_SEEN: &str = "`either` (the effector and its twin on the other hand, `left_` and its name, where the mannequin has both: the effector where it reaches while the eyes see, the twin too where it does not or the target is more than 150 mm to the twin's side, and then the hand on the target's side; the default where no effector is named), `right` or `left`";

/// Which hand a task uses.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Hand {
    /// The effector asked for and its twin on the other hand, where the
    /// mannequin has one.
    Either,
    /// The effector asked for, on the right hand (its name without
    /// `left_`).
    Right,
    /// Its twin on the left hand (`left_` and its name).
    Left,
}

impl Hand {
    fn parse(word: &str) -> Result<Self, SettingsError> {
        match word {
            "either" => Ok(Hand::Either),
            "right" => Ok(Hand::Right),
            "left" => Ok(Hand::Left),
            other => Err(SettingsError::invalid(
                "hand",
                format!("`{other}` is not a hand: use `either`, `right` or `left`"),
            )),
        }
    }

    /// The option `hand`, read by a task's settings, with its
    /// documentation (`HAND_DOC`, `HAND_DOC_FIRST` or `HAND_DOC_SEEN`).
    pub fn option(p: &mut Params<'_>, doc: &'static str) -> Option<String> {
        p.optional_name("hand", doc).get()
    }

    /// The hand `word` asks for (none: either where `common` names no
    /// effector, else the one it names), with `common`'s effector set to
    /// that hand's; whether the task reaches with either hand.
    pub fn resolve(word: Option<&str>, common: &mut Common) -> Result<bool, SettingsError> {
        let hand = match word {
            Some(word) => Some(Hand::parse(word)?),
            // An effector named is the one asked for.
            None => common.effector.is_none().then_some(Hand::Either),
        };
        // An effector named on the other hand than the one named: which
        // the user meant cannot be told.
        if let (Some(side @ (Hand::Right | Hand::Left)), Some(named)) = (hand, &common.effector) {
            let on_left = named.starts_with(LEFT);
            if on_left != (side == Hand::Left) {
                let word = if side == Hand::Left { "left" } else { "right" };
                let named_is = if on_left {
                    "a left-hand effector (`left_`)"
                } else {
                    "not a left-hand effector (no `left_`)"
                };
                return Err(SettingsError::invalid(
                    "hand",
                    format!(
                        "`hand {word}` and `effector {named}`, {named_is}, disagree: name the effector of the hand meant, or leave one out"
                    ),
                ));
            }
        }
        // A hand named: the effector on that hand, which the checker finds
        // (the mannequin's `grip` where no effector is named).
        let named = common.effector.clone().unwrap_or_else(|| "grip".into());
        let on_right = named.strip_prefix(LEFT).unwrap_or(&named).to_string();
        match hand {
            None | Some(Hand::Either) => {}
            Some(Hand::Right) => common.effector = Some(on_right),
            Some(Hand::Left) => common.effector = Some(format!("{LEFT}{on_right}")),
        }
        Ok(hand == Some(Hand::Either))
    }
}

/// How far past the body's midline (the hip point, across the base) a
/// target is on one hand's side: about where that hand's shoulder is.
/// Beyond it, either hand reaches with that side's hand where both do.
pub const SIDE_MM: f64 = 150.0;

/// Whether the point `target_mm` is on the side of the hand of `effector`
/// seen from a base at `pose`: more than [`SIDE_MM`] that way of the
/// midline (the base frame's y, to the left).
pub fn on_side_of(effector: &str, pose: &BasePose, target_mm: &Point3<f64>) -> bool {
    let across_mm = pose.to_base(target_mm).y;
    match hand_side(effector) {
        "left" => across_mm > SIDE_MM,
        _ => across_mm < -SIDE_MM,
    }
}

/// Of two hands that both do, whether the first (`(on the target's side,
/// comfort)`, [`on_side_of`]) is taken rather than the second: the one on
/// the target's side where only one is, else the more comfortable.
pub fn rather((a_side, a_comfort): (bool, f64), (b_side, b_comfort): (bool, f64)) -> bool {
    match (a_side, b_side) {
        (true, false) => true,
        (false, true) => false,
        _ => a_comfort < b_comfort,
    }
}

/// The effectors (indices into `body`) a task tries: `asked`, the one the
/// checker resolved, and with `either` its twin on the other hand where
/// the body has one.
pub fn hands_of(body: &Body, asked: usize, either: bool) -> Vec<usize> {
    let twin = either.then(|| body.twin_of(asked)).flatten();
    std::iter::once(asked).chain(twin).collect()
}

/// How many searches a task makes of its point: one per hand it tries
/// (`effectors`, the checker's, first; one where it names none).
pub fn searches(body: &Body, effectors: &[usize], either: bool) -> u64 {
    effectors
        .first()
        .map_or(1, |&asked| hands_of(body, asked, either).len() as u64)
}

#[cfg(test)]
mod tests {
    use crate::kinematics::{hand_side, twin_name};

    #[test]
    fn a_point_past_a_shoulder_is_on_that_hands_side() {
        use super::on_side_of;
        use crate::plugin::BasePose;
        use nalgebra::Point3;
        let target = Point3::new(1000.0, 1300.0, 1200.0);
        let at = |x: f64, y: f64, heading_rad: f64| BasePose {
            position_mm: Point3::new(x, y, 930.0),
            heading_rad,
        };
        // Facing +x from (700, 1500): the point is 200 mm to the right.
        let pose = at(700.0, 1500.0, 0.0);
        assert!((pose.to_base(&target).y + 200.0).abs() < 1e-9);
        assert!(on_side_of("grip", &pose, &target) && !on_side_of("left_grip", &pose, &target));
        // Facing +y from (700, 1000): 300 mm ahead and 300 mm to the right.
        let turned = at(700.0, 1000.0, std::f64::consts::FRAC_PI_2);
        let across = turned.to_base(&target).y;
        assert!((across + 300.0).abs() < 1e-9, "{across}");
        // 100 mm to the left: on neither hand's side.
        let near = at(900.0, 1200.0, 0.0);
        assert!(!on_side_of("grip", &near, &target) && !on_side_of("left_grip", &near, &target));
    }

    #[test]
    fn the_twin_of_an_effector_is_on_the_other_hand() {
        assert_eq!(twin_name("grip"), "left_grip");
        assert_eq!(twin_name("left_grip"), "grip");
        assert_eq!(hand_side("left_grip"), "left");
        assert_eq!(hand_side("grip"), "right");
    }
}
