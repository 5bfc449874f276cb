//! Why a target was not reached, found rather than guessed: the search is
//! run again without each thing that may have stopped it (the room's
//! obstacles it met, the person's own body and chair, the joints' limits
//! widened by 10 degrees), and the answer names what, once removed, lets
//! the hand reach; "out of reach" only when nothing removed helps.

use serde::{Deserialize, Serialize};

use super::mm;
use super::reach::quoted;

/// How far each joint's limits are widened to learn whether they are what
/// stopped a reach.
pub const WIDENED_DEG: f64 = 10.0;

/// What stopped a reach.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(tag = "cause", rename_all = "snake_case")]
pub enum Why {
    /// The room's obstacles (or sides) named: without any one of them the
    /// hand reaches (`together`: only without all of them).
    Obstacles { names: Vec<String>, together: bool },
    /// The person's own body or chair (the parts named): with the room's
    /// obstacles gone the hand still does not reach, without these too it
    /// does.
    Body { names: Vec<String> },
    /// The joints' limits: each widened by 10 degrees (and coupled joints
    /// freed of their coupling), the hand reaches, these joints going
    /// beyond their limits (`coupled`: some only beyond the range their
    /// coupling leaves them together).
    JointLimits {
        joints: Vec<String>,
        #[serde(default, skip_serializing_if = "is_false")]
        coupled: bool,
    },
    /// The base's zone: outside it (anywhere else the base fits), the hand
    /// reaches.
    Zone,
    /// The room's furniture keeps the base too far away: with the named
    /// obstacles gone from the floor (and the arm's way), the hand reaches
    /// (`together`: only with all of them gone).
    KeptAway { names: Vec<String>, together: bool },
    /// No place where the base fits lets it approach the target as its
    /// options ask (`approach`, `heading`): nothing was tried.
    NoApproach,
    /// The base fits where the hand would reach, but that floor is cut
    /// off from every door of the room: closed in by the obstacles named.
    CannotGetThere { names: Vec<String> },
    /// Out of the arm's reach with nothing in the way: with the room's
    /// obstacles and the person's own body gone, the hand comes this close
    /// at best. `below_the_knees`: the person stands and the target is
    /// lower than their knees, where a real person squats or kneels, which
    /// the model does not.
    OutOfReach {
        closest_mm: f64,
        #[serde(default, skip_serializing_if = "is_false")]
        below_the_knees: bool,
    },
    /// `reach ... and gaze`: the hand reaches the target alone (searched
    /// as a `reach`), but no posture found brings it there while the eyes
    /// look at it from within the legible range.
    WhileLooking,
}

fn is_false(b: &bool) -> bool {
    !b
}

impl Why {
    pub fn out_of_reach(closest_mm: f64) -> Self {
        Why::OutOfReach {
            closest_mm: mm(closest_mm),
            below_the_knees: false,
        }
    }

    /// In a few words, for the text report's verdict.
    pub fn short(&self) -> String {
        match self {
            Why::Obstacles { names, together } => {
                let names: Vec<String> = names.iter().map(|n| quoted(n)).collect();
                let and = if *together { " together" } else { "" };
                format!(
                    "blocked by {}{and}",
                    names.join(if *together { " and " } else { " or " })
                )
            }
            Why::Body { names } => format!("blocked by {}", names.join(" and ")),
            Why::JointLimits { coupled: false, .. } => "at the joints' limits".into(),
            Why::JointLimits { coupled: true, .. } => "at the joints' coupled limits".into(),
            Why::Zone => "kept to its zone".into(),
            Why::OutOfReach { .. } => "out of reach".into(),
            Why::NoApproach => "no place to approach it from".into(),
            Why::WhileLooking => "not while looking at it".into(),
            Why::CannotGetThere { names } => {
                let names: Vec<String> = names.iter().map(|n| quoted(n)).collect();
                format!("cannot get there: closed in by {}", names.join(", "))
            }
            Why::KeptAway { names, together } => {
                let names: Vec<String> = names.iter().map(|n| quoted(n)).collect();
                let (join, and) = if *together {
                    (" and ", " together")
                } else {
                    (" or ", "")
                };
                format!("the base is kept away by {}{and}", names.join(join))
            }
        }
    }

    /// The same cause with the names it gives in alphabetical order (the
    /// order they were found in says which was met first; two answers
    /// naming the same things are one cause).
    pub fn sorted(&self) -> Why {
        let mut why = self.clone();
        match &mut why {
            Why::Obstacles { names, .. }
            | Why::Body { names }
            | Why::KeptAway { names, .. }
            | Why::CannotGetThere { names } => names.sort(),
            Why::JointLimits { joints, .. } => joints.sort(),
            Why::Zone | Why::NoApproach | Why::OutOfReach { .. } | Why::WhileLooking => {}
        }
        why
    }

    /// In a sentence, for the text report's details.
    pub fn sentence(&self) -> String {
        match self {
            Why::Obstacles {
                together: false,
                names,
            } if names.len() > 1 => {
                format!("{}: without any one of them, the hand reaches", self.short())
            }
            Why::Obstacles { together: false, .. } | Why::Body { .. } => {
                format!("{}: without it, the hand reaches", self.short())
            }
            Why::Obstacles { together: true, .. } => {
                format!("{}: without all of them (not without one), the hand reaches", self.short())
            }
            Why::JointLimits {
                joints,
                coupled: false,
            } => format!(
                "at the joints' limits: with each widened {WIDENED_DEG} deg the hand reaches, with {} beyond their limits",
                joints.join(", ")
            ),
            Why::JointLimits {
                joints,
                coupled: true,
            } => format!(
                "at the joints' coupled limits: with each widened {WIDENED_DEG} deg and coupled joints freed of their coupling (`couple`, `rhythm`) the hand reaches, with {} beyond the range they have together",
                joints.join(", ")
            ),
            Why::Zone => "kept to its zone: the base stays in its `zone` (or between `zone_from` and `zone_to`); anywhere else it fits, the hand reaches".into(),
            Why::KeptAway {
                together: false,
                names,
            } if names.len() > 1 => format!(
                "{}: without any one of them on the floor (and in the arm's way), the base comes close enough and the hand reaches",
                self.short()
            ),
            Why::KeptAway { together: false, .. } => format!(
                "{}: without it on the floor (and in the arm's way), the base comes close enough and the hand reaches",
                self.short()
            ),
            Why::KeptAway { together: true, .. } => format!(
                "{}: only without all of them on the floor (and in the arm's way) does the base come close enough for the hand to reach",
                self.short()
            ),
            Why::CannotGetThere { .. } => format!(
                "{}: the base fits where the hand would reach it, but that floor is cut off from every door of the room (without the doors' routes, the hand reaches)",
                self.short()
            ),
            Why::WhileLooking => "not while looking at it: the hand reaches it alone, but no posture found brings it there while the eyes look at it from within the legible range (the neck's and eyes' limits, the line of sight)".into(),
            Why::NoApproach => "no place to approach it from: wherever the base fits, its `approach` or `heading` options do not let it face the target so; no posture was looked for".into(),
            Why::OutOfReach {
                closest_mm,
                below_the_knees,
            } => format!(
                "out of reach: even with the room empty (no furniture on the floor or in the arm's way) and without the person's own body in the way, the hand comes no closer than {closest_mm:.1} mm{}",
                if *below_the_knees {
                    " (the target is below the knees: a real person squats or kneels for it, which the model does not)"
                } else {
                    ""
                }
            ),
        }
    }
}
