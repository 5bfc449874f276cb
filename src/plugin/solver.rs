//! Solvers: an inverse kinematics problem and the trait of a configured
//! solver.

use nalgebra::Point3;

use super::{Options, Plugin, SettingsError};
use crate::collision::PlacedObstacles;
use crate::kinematics::Chain;
use crate::scene::IkSolution;

/// An inverse kinematics problem: bring the chain's effector to a point
/// given in the chain's base frame.
#[derive(Clone, Copy)]
pub struct IkProblem<'a> {
    pub chain: &'a Chain,
    pub target_mm: Point3<f64>,
    pub tolerance_mm: f64,
    /// Seeds every random choice the solver makes.
    pub seed: u64,
    /// The room's obstacles, when links must stay out of them.
    pub obstacles: Option<PlacedObstacles<'a>>,
}

impl IkProblem<'_> {
    /// The first obstacle a link of posture `q` passes through (none when
    /// obstacles are not checked).
    pub fn collision(&self, q: &[f64]) -> Option<usize> {
        let obstacles = self.obstacles.as_ref()?;
        // The effector may rest on the target's surface: the last link
        // stops a tolerance (at least a millimetre) short of it.
        let gap_mm = self.tolerance_mm.max(1.0);
        obstacles.polyline_hit(&self.chain.link_points(q), gap_mm)
    }
}

/// A solver built from its settings.
pub trait Solver: Send + Sync {
    fn solve(&self, problem: &IkProblem<'_>) -> IkSolution;
    /// How many starts one solve runs at most (what the limit on solver
    /// starts counts).
    fn starts(&self) -> u64 {
        1
    }
}

pub trait SolverPlugin: Plugin {
    /// The solver that validated `options` configure.
    fn build(&self, options: &Options) -> Result<Box<dyn Solver>, SettingsError>;
}
