//! The `dls` solver: damped least squares on the position Jacobian, a
//! classic control for the incremental solver. Each iteration moves the
//! joints by `dq = J^T (J J^T + lambda^2 I)^-1 e`, with the error `e` cut to
//! `max_step`, then clamps them into their limits. Further starts (seeded
//! random postures) are tried only until one reaches the target.

use nalgebra::{Matrix3, Point3, Vector3};

use super::starts::{neutral_start, Starts};
use crate::kinematics::{Chain, JointKind};
use crate::plugin::{
    fingerprint_of, work_ratio, IkProblem, IkSolution, Options, ParamSpec, Params, Plugin,
    Settings, SettingsError, Solver, SolverPlugin, Tally,
};

/// The plugin `dls`.
pub struct Dls;

/// The configured solver, its settings from its option block.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DlsSolver {
    pub damping_mm: f64,
    pub max_step_mm: f64,
    pub max_iterations: u64,
    pub starts: u32,
    pub neutral_start: bool,
}

impl Settings for DlsSolver {
    fn visit(p: &mut Params<'_>) -> Self {
        DlsSolver {
            damping_mm: p
                .length(
                    "damping",
                    20.0,
                    "the damping lambda: larger is steadier near singularities",
                )
                .range(1e-6, 1e6)
                .get(),
            max_step_mm: p
                .length(
                    "max_step",
                    100.0,
                    "the error followed in one iteration is cut to this length",
                )
                .range(1e-3, 1e6)
                .get(),
            max_iterations: p
                .integer("max_iterations", 200, "iterations per start")
                .range(1.0, 1e4)
                .get() as u64,
            starts: p
                .integer("starts", 1, "starting postures tried until one reaches")
                .range(1.0, 1000.0)
                .get() as u32,
            neutral_start: neutral_start(p),
        }
    }
}

impl Plugin for Dls {
    fn name(&self) -> &'static str {
        "dls"
    }

    fn doc(&self) -> &'static str {
        "damped least squares on the position Jacobian, joint limits by clamping"
    }

    fn params(&self) -> Vec<ParamSpec> {
        DlsSolver::params()
    }
}

impl SolverPlugin for Dls {
    fn build(&self, options: &Options) -> Result<Box<dyn Solver>, SettingsError> {
        Ok(Box::new(DlsSolver::from_options(options)?))
    }
}

impl Solver for DlsSolver {
    fn fingerprint(&self) -> Option<u64> {
        Some(fingerprint_of("dls", self))
    }

    fn solve(&self, problem: &IkProblem<'_>) -> IkSolution {
        let starts = Starts::new(problem.chain, problem.seed, self.neutral_start);
        let mut best: Option<IkSolution> = None;
        for start in starts.take(self.starts as usize) {
            let solution = self.descend(problem, start);
            let reached = solution.distance_mm <= problem.tolerance_mm;
            if best
                .as_ref()
                .is_none_or(|b| solution.distance_mm < b.distance_mm)
            {
                best = Some(solution);
            }
            if reached {
                break;
            }
        }
        best.unwrap_or_else(|| IkSolution::unsolved(problem.chain))
    }

    fn solve_from(&self, problem: &IkProblem<'_>, mut start: Vec<f64>) -> IkSolution {
        problem.chain.pull_in(&mut start);
        self.descend(problem, start)
    }

    fn starts(&self) -> u64 {
        u64::from(self.starts.max(1))
    }

    fn work_per_start(&self) -> u64 {
        work_ratio(&[(self.max_iterations as f64, 200.0)])
    }

    /// Its steps look at the target alone; the room only judges the end.
    fn blind_to_room(&self) -> bool {
        true
    }
}

impl DlsSolver {
    fn descend(&self, problem: &IkProblem<'_>, mut q: Vec<f64>) -> IkSolution {
        let chain = problem.chain;
        let mut columns = vec![Vector3::zeros(); chain.dof()];
        let mut iterations = 0;
        let mut p = effector_and_jacobian(chain, &q, &mut columns);
        let mut tally = Tally::new(problem.allowance);
        // An iteration moves every joint and works out its column.
        let per_iteration = 3 * chain.dof() as u64;
        while (problem.target_mm - p).norm() > problem.tolerance_mm
            && iterations < self.max_iterations
            && tally.add(per_iteration)
        {
            iterations += 1;
            let mut e = problem.target_mm - p;
            let len = e.norm();
            if len > self.max_step_mm {
                e *= self.max_step_mm / len;
            }
            let mut jjt = Matrix3::identity() * (self.damping_mm * self.damping_mm);
            for c in &columns {
                jjt += c * c.transpose();
            }
            // J J^T + lambda^2 I is symmetric positive definite.
            let y = jjt
                .cholesky()
                .expect("damped J J^T is positive definite")
                .solve(&e);
            for (i, c) in columns.iter().enumerate() {
                q[i] = chain.clamp_joint(i, q[i] + c.dot(&y), &q);
            }
            p = effector_and_jacobian(chain, &q, &mut columns);
        }
        tally.count(problem.check_units());
        IkSolution {
            distance_mm: (problem.target_mm - p).norm(),
            collision: problem.collision(&q),
            q,
            iterations,
        }
    }
}

/// The effector of posture `q` in the base frame; `columns` receives the
/// position Jacobian, one column per joint.
fn effector_and_jacobian(chain: &Chain, q: &[f64], columns: &mut [Vector3<f64>]) -> Point3<f64> {
    let mut frame = nalgebra::IsometryMatrix3::identity();
    let mut axes = Vec::with_capacity(chain.dof());
    for (joint, &qi) in chain.joints.iter().zip(q) {
        let moving = frame * joint.axis_frame();
        axes.push((moving.translation.vector, moving.rotation * Vector3::z()));
        frame *= joint.transform(qi);
    }
    let p = frame * Point3::from(chain.effector_mm);
    for ((column, (origin, axis)), joint) in columns.iter_mut().zip(axes).zip(&chain.joints) {
        *column = match joint.kind {
            JointKind::Revolute => axis.cross(&(p.coords - origin)),
            JointKind::Prismatic => axis,
        };
    }
    p
}
