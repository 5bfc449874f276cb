//! A program that uses reach as a library and registers its own solver.
//!
//! The solver here, `sampling`, draws random postures within the joint
//! limits and keeps the one whose hand lands closest to the target: a
//! baseline, far slower than `incremental`, but a complete solver. Once
//! registered, a scenario names it like any built-in one, with an option
//! block that its declared parameters validate.
//!
//! Run it with `cargo run --example custom_solver`.

use rand_chacha::rand_core::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use reach::plugin::{
    IkProblem, IkSolution, Options, ParamSpec, Params, Plugin, Registry, Settings, SettingsError,
    Solver, SolverPlugin,
};
use reach::report::Report;
use reach::Input;
use reach::Scenario;

/// The plugin: its name, its doc line and its parameters.
pub struct Sampling;

/// The solver's settings: each option declared once, in `visit`, which
/// gives both the parameters `reach plugins` lists and the values read
/// from a validated option block.
struct SamplingSolver {
    samples: u64,
}

impl Settings for SamplingSolver {
    fn visit(p: &mut Params<'_>) -> Self {
        SamplingSolver {
            samples: p
                .integer("samples", 5000, "postures to try")
                .range(1.0, 1e7)
                .get() as u64,
        }
    }
}

impl Plugin for Sampling {
    fn name(&self) -> &'static str {
        "sampling"
    }

    fn doc(&self) -> &'static str {
        "random postures within the limits; keeps the closest that is clear (a baseline)"
    }

    fn params(&self) -> Vec<ParamSpec> {
        SamplingSolver::params()
    }
}

impl SolverPlugin for Sampling {
    fn build(&self, options: &Options) -> Result<Box<dyn Solver>, SettingsError> {
        Ok(Box::new(SamplingSolver::from_options(options)?))
    }
}

impl Solver for SamplingSolver {
    fn solve(&self, problem: &IkProblem<'_>) -> IkSolution {
        let mut rng = ChaCha8Rng::seed_from_u64(problem.seed);
        let mut best = IkSolution {
            q: problem.chain.neutral(),
            distance_mm: f64::INFINITY,
            iterations: 0,
            collision: None,
        };
        for i in 1..=self.samples {
            let q: Vec<f64> = problem
                .chain
                .joints
                .iter()
                .map(|j| j.min + (rng.next_u64() >> 11) as f64 / (1u64 << 53) as f64 * j.range())
                .collect();
            let distance_mm = (problem.chain.effector(&q) - problem.target_mm).norm();
            // A posture through an obstacle, the person's own legs or
            // trunk does not count (checked only for a closer one, as
            // the check costs more than the distance).
            if distance_mm < best.distance_mm && problem.collision(&q).is_none() {
                best = IkSolution {
                    q,
                    distance_mm,
                    iterations: i,
                    collision: None,
                };
            }
        }
        // The base checks the final posture again whatever a solver says.
        best.collision = problem.collision(&best.q);
        best
    }
}

/// A scenario that uses the new solver beside the built-in one.
pub const SCENARIO: &str = r#"
use std::arm
room kitchen {
  size 3600 x 2800 x 2500
  target mug at (400, 1150, 960)
}
person ben {
  mannequin right_arm
  base fixed { at (850, 1300, 930) heading 180deg }
}
reach mug by ben { solver sampling { samples 100000 } tolerance 60mm }
reach mug by ben { solver incremental tolerance 60mm }
"#;

/// Check and run `SCENARIO` with the built-in plugins plus `sampling`.
pub fn run_scenario() -> Report {
    run_checked().1
}

/// The scenario checked with the built-in plugins plus `sampling`, and its
/// report.
fn run_checked() -> (Scenario, Report) {
    let mut registry = Registry::builtin();
    registry.register_solver(Sampling);
    let (_, checked) = reach::check(
        Input::Text {
            name: "custom_solver.reach",
            text: SCENARIO,
        },
        &registry,
    );
    match checked {
        Ok(scenario) => {
            let report = reach::run(&scenario).expect("within the bound on solver work");
            (scenario, report)
        }
        Err(d) => panic!("{}", d.render(true)),
    }
}

#[allow(dead_code)]
fn main() {
    let (scenario, report) = run_checked();
    let text = Registry::builtin()
        .format("text")
        .expect("built in")
        .render(&report, &scenario.format_scene())
        .expect("the text format prints");
    print!("{text}");
}
