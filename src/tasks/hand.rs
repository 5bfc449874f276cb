//! Which hand a reach or a map uses: the effector asked for, its twin on
//! the other hand (`left_` and its name), or either, the default where
//! the task names no effector.

use super::common::Common;
use crate::kinematics::{Body, LEFT_PREFIX as LEFT};
use crate::plugin::{Params, SettingsError};

/// The option `hand`'s documentation, for a task that takes the more
/// comfortable hand where both do (a reach).
pub const HAND_DOC: &str = "`either` (the effector and its twin on the other hand, `left_` and its name, where the mannequin has both: the hand that reaches, the more comfortable where both do; the default where no effector is named), `right` or `left`";

/// The option `hand`'s documentation, for a task that tries the twin only
/// where the effector asked for does not do (a map's point, a reach and
/// gaze).
pub const HAND_DOC_FIRST: &str = "`either` (the effector and its twin on the other hand, `left_` and its name, where the mannequin has both: the effector where it does, else its twin; the default where no effector is named), `right` or `left`";

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
    /// documentation (`HAND_DOC` or `HAND_DOC_FIRST`).
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
                let other = if on_left { "left" } else { "right" };
                return Err(SettingsError::invalid(
                    "hand",
                    format!(
                        "`hand {word}` and `effector {named}`, an effector of the {other} hand, disagree: name the effector of the hand meant, or leave one out"
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
    effectors.first().map_or(1, |&asked| hands_of(body, asked, either).len() as u64)
}

#[cfg(test)]
mod tests {
    use crate::kinematics::{hand_side, twin_name};

    #[test]
    fn the_twin_of_an_effector_is_on_the_other_hand() {
        assert_eq!(twin_name("grip"), "left_grip");
        assert_eq!(twin_name("left_grip"), "grip");
        assert_eq!(hand_side("left_grip"), "left");
        assert_eq!(hand_side("grip"), "right");
    }
}
