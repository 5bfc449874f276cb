//! The `fabrik` solver: FABRIK (Aristidou and Lasenby) on DH chains, with
//! joint limits and obstacle avoidance after the visibility paper. The
//! chain is read as bones (`bones.rs`); one solve alternates backward and
//! forward passes (`pass.rs`), moving bones out of obstacles on the way
//! (`avoid.rs`), kicking a start that stalls (`stall.rs`). Like `incremental`, it runs from several starts and keeps
//! the most comfortable posture that reaches. `tree.rs` solves several
//! effectors of one body at once (a hand and the eyes).

mod avoid;
mod bones;
mod pass;
mod stall;
mod tree;

pub use bones::{bones, Bone, End};
pub use tree::{solve_tree, TreeGoal, TreeProblem, TreeSolution};

use rand_chacha::rand_core::SeedableRng;
use rand_chacha::ChaCha8Rng;

use crate::plugin::{
    fingerprint_of, work_ratio, IkProblem, IkSolution, Options, ParamSpec, Params, Plugin,
    Settings, SettingsError, Solver, SolverPlugin,
};
use crate::scene::Preferred;
use crate::solvers::starts::{neutral_start, Starts};

/// The plugin `fabrik`.
pub struct Fabrik;

/// The solver's settings, from its option block.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FabrikSettings {
    pub starts: u32,
    pub neutral_start: bool,
    pub max_iterations: u32,
    pub stall: u32,
    pub sweeps: u32,
    pub samples: u32,
    pub avoid_obstacles: bool,
    pub kicks: u32,
    pub kick: f64,
    pub ccd: bool,
}

impl Settings for FabrikSettings {
    fn visit(p: &mut Params<'_>) -> Self {
        // Read in the order `reach plugins` lists them; the struct's fields
        // are in another.
        let starts = p
            .integer(
                "starts",
                4,
                "starting postures; the most comfortable that reaches is kept",
            )
            .range(1.0, 1000.0)
            .get() as u32;
        let neutral_start = neutral_start(p);
        let max_iterations = p
            .integer(
                "max_iterations",
                400,
                "backward and forward passes per start, at most",
            )
            .range(1.0, 1e4)
            .get() as u32;
        let stall = p
            .integer(
                "stall",
                4,
                "stop after this many passes in a row that did not bring the effector closer",
            )
            .range(1.0, 1e4)
            .get() as u32;
        let sweeps = p
            .integer("sweeps", 2, "turns of each group's joints per forward pass")
            .range(1.0, 20.0)
            .get() as u32;
        let samples = p
            .integer(
                "samples",
                7,
                "values per joint when a bone must be moved out of an obstacle",
            )
            .range(2.0, 20.0)
            .get() as u32;
        let kicks = p
            .integer("kicks", 40, "when a start stalls short of the target, kick the posture and go on, this many times")
            .range(0.0, 1000.0)
            .get() as u32;
        let kick = p
            .number(
                "kick",
                0.3,
                "a kick moves each joint by up to this fraction of its range",
            )
            .range(0.0, 1.0)
            .get();
        let ccd = p
            .boolean(
                "ccd",
                true,
                "after each pass, a sweep of groups turning the effector itself towards the target",
            )
            .get();
        let avoid_obstacles = p
            .boolean(
                "avoid_obstacles",
                true,
                "move bones out of obstacles, and prefer clear postures among starts",
            )
            .get();
        FabrikSettings {
            starts,
            neutral_start,
            max_iterations,
            stall,
            sweeps,
            samples,
            avoid_obstacles,
            kicks,
            kick,
            ccd,
        }
    }
}

impl Plugin for Fabrik {
    fn name(&self) -> &'static str {
        "fabrik"
    }

    fn doc(&self) -> &'static str {
        "FABRIK with joint limits and obstacle avoidance (visibility paper)"
    }

    fn params(&self) -> Vec<ParamSpec> {
        FabrikSettings::params()
    }
}

impl SolverPlugin for Fabrik {
    fn build(&self, options: &Options) -> Result<Box<dyn Solver>, SettingsError> {
        Ok(Box::new(FabrikSolver {
            settings: FabrikSettings::from_options(options)?,
        }))
    }
}

/// The configured solver.
pub struct FabrikSolver {
    pub settings: FabrikSettings,
}

impl Solver for FabrikSolver {
    fn fingerprint(&self) -> Option<u64> {
        Some(fingerprint_of("fabrik", &self.settings))
    }

    fn solve(&self, problem: &IkProblem<'_>) -> IkSolution {
        let bones = bones(problem.chain);
        let starts = Starts::new(problem.chain, problem.seed, self.settings.neutral_start);
        // Kicks draw from their own stream, so a start's posture does not
        // depend on how many kicks the starts before it took.
        let mut rng = ChaCha8Rng::seed_from_u64(problem.seed ^ 0x6b69_636b);
        let mut best = Preferred::new(problem.tolerance_mm);
        let mut iterations = 0;
        for start in starts.take(self.settings.starts as usize) {
            let solution = pass::Pass::new(&self.settings, problem, &bones, start).run(&mut rng);
            iterations += solution.iterations;
            let comfort = problem.chain.discomfort(&solution.q);
            best.offer(solution, comfort);
        }
        let mut solution = best
            .into_kept()
            .unwrap_or_else(|| IkSolution::unsolved(problem.chain));
        solution.iterations = iterations;
        solution
    }

    fn solve_from(&self, problem: &IkProblem<'_>, mut start: Vec<f64>) -> IkSolution {
        problem.chain.pull_in(&mut start);
        let bones = bones(problem.chain);
        let mut rng = ChaCha8Rng::seed_from_u64(problem.seed ^ 0x6b69_636b);
        pass::Pass::new(&self.settings, problem, &bones, start).run(&mut rng)
    }

    fn starts(&self) -> u64 {
        u64::from(self.settings.starts.max(1))
    }

    fn work_per_start(&self) -> u64 {
        let s = &self.settings;
        // Moving a bone out of an obstacle tries samples in each of three
        // groups of joints: measured, a start's time grows as the cube of
        // `samples` (10: 0.14 s, 20: 1.1 s, 30: 4.1 s).
        let samples = f64::from(s.samples) / 7.0;
        work_ratio(&[
            (f64::from(s.max_iterations), 400.0),
            (f64::from(s.sweeps), 2.0),
            (samples * samples * samples, 1.0),
        ])
    }
}
