//! Solvers: an inverse kinematics problem and the trait of a configured
//! solver.

use nalgebra::Point3;

use super::{Options, Plugin, SettingsError};
use crate::allowance::Allowance;
use crate::collision::PlacedObstacles;
use crate::engine::Asked;
use crate::kinematics::{Chain, Volumes};
use crate::scene::{Collision, IkSolution};

/// An inverse kinematics problem: bring the chain's effector to a point
/// given in the chain's base frame.
#[derive(Clone, Copy)]
pub struct IkProblem<'a> {
    pub chain: &'a Chain,
    pub target_mm: Point3<f64>,
    pub tolerance_mm: f64,
    /// Seeds every random choice the solver makes.
    pub seed: u64,
    /// The room's obstacles and the person's own body, when the posture
    /// must stay out of them.
    pub obstacles: Option<PlacedObstacles<'a>>,
    /// What the solve's work is told to: a solve counts its steps and its
    /// checks against the room ([`Allowance`]) and stops early once
    /// the allowance is exhausted (its answer is then thrown away).
    pub allowance: &'a dyn Allowance,
}

impl<'a> IkProblem<'a> {
    /// What this problem asks its questions of and tells its work to.
    pub fn asked(&self) -> Asked<'a> {
        Asked {
            obstacles: self.obstacles.map(|placed| placed.obstacles),
            allowance: self.allowance,
        }
    }

    /// This problem asking `asked` instead (a kept solve's own view of
    /// the same obstacles and allowance, which record it).
    pub fn asking<'b>(&self, asked: Asked<'b>) -> IkProblem<'b>
    where
        'a: 'b,
    {
        let placed = self.obstacles.zip(asked.obstacles);
        IkProblem {
            obstacles: placed.map(|(placed, obstacles)| PlacedObstacles {
                obstacles,
                ..placed
            }),
            allowance: asked.allowance,
            ..*self
        }
    }

    /// The first thing a part of posture `q` runs into (none when
    /// obstacles are not checked). The hand may press into what it reaches
    /// by up to the tolerance.
    pub fn collision(&self, q: &[f64]) -> Option<Collision> {
        let obstacles = self.obstacles.as_ref()?;
        obstacles.posture_hit(self.chain, q, self.tolerance_mm)
    }

    /// What one check of a posture costs ([`Allowance`]'s units):
    /// nothing where obstacles are not checked.
    pub fn check_units(&self) -> u64 {
        self.obstacles
            .as_ref()
            .map_or(0, |o| o.check_units(self.chain))
    }

    /// [`IkProblem::collision`], the check told to the allowance at once (for
    /// a check outside a solve's tally: a placement's, a start's).
    pub fn collision_charged(&self, q: &[f64]) -> Option<Collision> {
        self.allowance.spend(self.check_units());
        self.collision(q)
    }

    /// The first thing the chain's solids `v` (of some posture) run into,
    /// as [`IkProblem::collision`] finds it.
    pub fn collision_of(&self, v: &Volumes) -> Option<Collision> {
        let obstacles = self.obstacles.as_ref()?;
        obstacles.volumes_hit(self.chain, v, self.tolerance_mm)
    }

    /// [`IkProblem::collision_of`], the check told to the allowance at once, as
    /// [`IkProblem::collision_charged`] tells it: for the solids of one
    /// posture checked at several base poses.
    pub fn collision_of_charged(&self, v: &Volumes) -> Option<Collision> {
        self.allowance.spend(self.check_units());
        self.collision_of(v)
    }
}

/// A solver built from its settings. It asks about the room only through
/// the problem it is given ([`IkProblem::collision`], or the problem's
/// obstacles' questions) and keeps nothing from one solve to the next:
/// watch mode keeps a task's answer by what those questions came near
/// (`collision::Touched`). It tells the problem's allowance the work it
/// does (`allowance::Tally`: a unit a joint moved, [`IkProblem::check_units`]
/// a posture checked) and stops once the allowance is exhausted; the work
/// must not depend on anything but the problem.
pub trait Solver: Send + Sync {
    fn solve(&self, problem: &IkProblem<'_>) -> IkSolution;
    /// A solve that may stop at the first start whose posture reaches the
    /// target clear of obstacles, where only whether it can matters (a
    /// map's point), not which of such postures is the most comfortable.
    fn solve_until_reached(&self, problem: &IkProblem<'_>) -> IkSolution {
        self.solve(problem)
    }
    /// One solve from posture `start` (a neighbour's, on a map), for
    /// solvers that can take one; the others solve as usual.
    fn solve_from(&self, problem: &IkProblem<'_>, start: Vec<f64>) -> IkSolution {
        let _ = start;
        self.solve(problem)
    }
    /// How many starts one solve runs at most (what the limit on solver
    /// starts counts).
    fn starts(&self) -> u64 {
        1
    }
    /// How many default starts one start may cost: its iteration options
    /// over their defaults (at least 1), so that the limit on solver
    /// starts bounds the work, not only the count.
    fn work_per_start(&self) -> u64 {
        1
    }
    /// Whether a descent from a clear posture stays clear (so that it pays
    /// to start it from one).
    fn steers_clear(&self) -> bool {
        false
    }
    /// Whether [`Solver::solve_from`]'s posture depends only on the chain,
    /// the start, the target in the base frame and the tolerance: not on
    /// the room's obstacles, the person's own body or the seed. A search
    /// may then reuse a posture found from the same start for the same
    /// target at another base pose, judged again there.
    fn blind_to_room(&self) -> bool {
        false
    }
    /// Whether [`Solver::solve`]'s starts depend on the problem's seed:
    /// where they do not, a solve from the solver's own starts is, like a
    /// [`Solver::solve_from`], the same for the same target in the base
    /// frame.
    fn seeded(&self) -> bool {
        true
    }
    /// A hash of everything that decides this solver's answers besides
    /// the problem (its kind and settings), where it has one: watch mode
    /// keeps the solves of such a solver for the task's next run
    /// (`engine::KeptSolves`). None: its solves are not kept.
    fn fingerprint(&self) -> Option<u64> {
        None
    }
}

pub trait SolverPlugin: Plugin {
    /// The solver that validated `options` configure.
    fn build(&self, options: &Options) -> Result<Box<dyn Solver>, SettingsError>;
}

/// The work of one start with these options, in default starts: the
/// product of each `(value, default)` ratio, rounded up, at least 1.
pub fn work_ratio(options: &[(f64, f64)]) -> u64 {
    let ratio: f64 = options
        .iter()
        .map(|(value, default)| value / default)
        .product();
    // At most 1e12: the ceiling of the limit itself.
    ratio.ceil().clamp(1.0, 1e12) as u64
}
