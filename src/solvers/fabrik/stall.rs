//! When a start has stalled, shared by the chain and the tree solves: a
//! pass that does not bring the distance (for a tree, the weighted sum of
//! distances) down by 0.01 % is a stall; `stall` stalls in a row ask for a
//! kick, up to `kicks` of them, or `BLOCKED_KICKS` when the effectors are on
//! their targets and only a collision is left.

use super::FabrikSettings;

/// Kicks for a posture that reaches the target but passes through an
/// obstacle: moving the bones out has failed, and more kicks rarely help.
pub const BLOCKED_KICKS: u32 = 3;

/// What a start does after seeing where its last pass left it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Next {
    Pass,
    Kick,
    Stop,
}

/// The stall count, best distance since the last kick, and kicks so far.
pub struct Stalls {
    progress: f64,
    stalled: u32,
    kicks: u32,
}

impl Stalls {
    pub fn new() -> Self {
        Stalls {
            progress: f64::INFINITY,
            stalled: 0,
            kicks: 0,
        }
    }

    /// After a pass that left the effectors `distance_mm` from their
    /// targets (`near`: each within tolerance).
    pub fn next(&mut self, s: &FabrikSettings, distance_mm: f64, near: bool) -> Next {
        self.stalled = if distance_mm < self.progress * (1.0 - 1e-4) {
            0
        } else {
            self.stalled + 1
        };
        self.progress = self.progress.min(distance_mm);
        if self.stalled < s.stall {
            return Next::Pass;
        }
        let limit = if near {
            s.kicks.min(BLOCKED_KICKS)
        } else {
            s.kicks
        };
        if self.kicks >= limit {
            return Next::Stop;
        }
        (self.kicks, self.stalled, self.progress) = (self.kicks + 1, 0, f64::INFINITY);
        Next::Kick
    }
}
