//! What the reach-like tasks share: their common options (solver,
//! tolerance, seed, effector, collisions and the retry where obstacles
//! block), those options with their solvers built ([`Reaching`]), the
//! queries they ask a base, what their answers depend on, and seeds that
//! depend on names rather than on the order of tasks.

use nalgebra::Point3;

use crate::allowance::Allowance;
use crate::collision::Obstacles;
use crate::kinematics::Chain;
use crate::plugin::{
    Dependence, EffectorNeed, Params, Placement, PluginConfig, PluginKind, ReachQuery, Registry,
    Retry, Search, SettingsError, Solver, TaskInput, Tries, Value,
};
use crate::report::Asked;
use crate::scene::OwnBody;

/// How a task declares its common options: what one of its subjects is
/// called in the docs, the seed's doc, the default solver, and the
/// effector option.
pub struct CommonDecl {
    /// `target` or `point`.
    pub what: &'static str,
    pub seed_doc: &'static str,
    /// The default solver and the option's doc.
    pub solver: (&'static str, &'static str),
    /// `None`: the effector may be left out (the mannequin's first);
    /// `Some((default, doc))`: a named default.
    pub effector: Option<(&'static str, &'static str)>,
    /// The default retry solver's starts, and whether it steers clear of
    /// obstacles: one target can afford 32 guarded descents per blocked
    /// placement; a map of thousands of points retries with 8 (four times
    /// faster, and finds a little less). Plain descents would be faster
    /// still, but miss half of what the guarded ones reach between boards
    /// (docs/benchmarks.md).
    pub retry: (i64, bool),
}

/// The retry of one target: 32 starts per blocked placement, steering
/// clear.
pub const THOROUGH_RETRY: (i64, bool) = (32, true);
/// The retry of each point of a map: 8 starts, steering clear.
pub const MAP_RETRY: (i64, bool) = (8, true);

/// The solver a reach-like task uses unless told otherwise, and its doc.
pub const INCREMENTAL: (&str, &str) = ("incremental", "the IK solver and its options");

/// The options every reach-like task has.
#[derive(Clone, Debug, PartialEq)]
pub struct Common {
    pub solver: PluginConfig,
    pub tolerance_mm: f64,
    pub seed: u64,
    /// The effector's name (`None`: the mannequin's first).
    pub effector: Option<String>,
    pub collisions: bool,
    pub clearance_mm: f64,
    pub blocked_solver: PluginConfig,
    pub blocked_retries: u32,
    pub blocked_spread: f64,
}

impl Common {
    /// Declare and read the common options, as `decl` says.
    pub fn visit(p: &mut Params<'_>, decl: &CommonDecl) -> Self {
        let tolerance_doc = match decl.what {
            "point" => "a point counts as reached within this distance",
            _ => "the target counts as reached within this distance",
        };
        let (solver, solver_doc) = decl.solver;
        Common {
            solver: p.plugin("solver", PluginKind::Solver, solver, solver_doc).get(),
            tolerance_mm: p
                .length("tolerance", 10.0, tolerance_doc)
                .range(0.001, 1000.0)
                .get(),
            seed: p
                .integer("seed", 1, decl.seed_doc)
                .range(0.0, 9_007_199_254_740_992.0)
                .get() as u64,
            effector: match decl.effector {
                None => p
                    .optional_name(
                        "effector",
                        "which of the mannequin's effectors (default: its first)",
                    )
                    .get(),
                Some((default, doc)) => Some(p.name("effector", default, doc).get()),
            },
            collisions: p
                .boolean(
                    "collisions",
                    true,
                    "links must stay out of the room's obstacles (links are segments between joints)",
                )
                .get(),
            clearance_mm: p
                .length(
                    "clearance",
                    0.0,
                    "with collisions: how close a link may come to an obstacle",
                )
                .range(0.0, 500.0)
                .get(),
            blocked_solver: p
                .plugin_with(
                    "blocked_solver",
                    PluginKind::Solver,
                    "incremental",
                    vec![
                        ("starts", Value::Integer(decl.retry.0)),
                        ("steer_clear", Value::Bool(decl.retry.1)),
                    ],
                    "with collisions, where the solver reaches from no placement: the solver that tries again, one descent per start from starts near the blocked posture",
                )
                .get(),
            blocked_retries: p
                .integer(
                    "blocked_retries",
                    4,
                    "how many of the most promising placements `blocked_solver` tries (0: none)",
                )
                .range(0.0, 360.0)
                .get() as u32,
            blocked_spread: p
                .number(
                    "blocked_spread",
                    0.2,
                    "how far the retry's starts stray from the blocked posture, as a fraction of each joint's range",
                )
                .range(0.0, 1.0)
                .get(),
        }
    }
}

/// A reach-like task's common options with its solvers built.
pub struct Reaching {
    pub common: Common,
    pub solver: Box<dyn Solver>,
    pub blocked_solver: Box<dyn Solver>,
}

impl Reaching {
    /// Build the solvers `common` names.
    pub fn new(common: Common, plugins: &Registry) -> Result<Self, SettingsError> {
        Ok(Reaching {
            solver: plugins.build_solver("solver", &common.solver)?,
            blocked_solver: plugins.build_solver("blocked_solver", &common.blocked_solver)?,
            common,
        })
    }

    /// The effector option, for the checker to resolve.
    pub fn effector_need(&self) -> EffectorNeed {
        EffectorNeed {
            option: "effector",
            name: self.common.effector.clone(),
        }
    }

    /// The most solver starts one point needs from `placements` candidate
    /// placements: each runs the solver, and where obstacles block, the
    /// retry runs `blocked_solver` from some of them.
    pub fn starts_per_point(&self, placements: Tries) -> u64 {
        let solved = placements.solved.saturating_add(placements.from_rest);
        let tried = solved.saturating_add(placements.seeded);
        let retries = if self.common.collisions {
            u64::from(self.common.blocked_retries).min(tried)
        } else {
            0
        };
        let work = |solver: &dyn Solver| solver.starts().saturating_mul(solver.work_per_start());
        solved
            .saturating_mul(work(self.solver.as_ref()))
            .saturating_add(
                placements
                    .seeded
                    .saturating_mul(self.solver.work_per_start()),
            )
            .saturating_add(retries.saturating_mul(work(self.blocked_solver.as_ref())))
    }

    /// The room's obstacles when the task checks collisions, recording
    /// what the questions touch where `input` asks for that, charging the
    /// task's meter for the triangles of meshes tested.
    pub fn obstacles(&self, input: &TaskInput<'_>) -> Option<Obstacles> {
        self.common.collisions.then(|| {
            Obstacles::new(input.room, self.common.clearance_mm)
                .recording(input.touched)
                .charging(input.allowance)
        })
    }

    /// A reach of `target_room_mm` keeping the person out of `obstacles`
    /// and their own body and base `own`, with the task's tolerance and,
    /// where obstacles are checked, its retry.
    pub fn query<'q>(
        &'q self,
        target_room_mm: Point3<f64>,
        seed: u64,
        search: Search,
        obstacles: Option<&'q Obstacles>,
        own: &'q OwnBody,
        allowance: &'q dyn Allowance,
    ) -> ReachQuery<'q> {
        let retry = (obstacles.is_some() && self.common.blocked_retries > 0).then(|| Retry {
            solver: self.blocked_solver.as_ref(),
            placements: self.common.blocked_retries as usize,
            spread: self.common.blocked_spread,
        });
        ReachQuery {
            target_room_mm,
            tolerance_mm: self.common.tolerance_mm,
            seed,
            search,
            obstacles,
            own,
            retry,
            proofs: None,
            last_resort: None,
            from_rest: true,
            descents: None,
            allowance,
            solves: None,
        }
    }

    /// What a report of `placement` (for `subject`, by `chain`) says was
    /// asked: who, where, with which solver (the retry's if it found the
    /// posture) and tolerance.
    pub fn asked<'a>(
        &'a self,
        subject: &'a str,
        input: &TaskInput<'a>,
        chain: &'a Chain,
        placement: &Placement,
    ) -> Asked<'a> {
        let solver = if placement.retried {
            &self.common.blocked_solver.name
        } else {
            &self.common.solver.name
        };
        Asked {
            subject,
            person: input.person,
            chain,
            solver,
            tolerance_mm: self.common.tolerance_mm,
            room: input.room,
            own: input.base.own_body(),
        }
    }

    /// What the answer depends on when `chain` reaches for `points_mm`:
    /// the obstacles within the reach of `chains` (grown by the
    /// clearance) from a placement, when collisions are checked, and
    /// (`sight_lines`) those between the eyes and each point.
    pub fn dependence(
        &self,
        chain: &Chain,
        chains: &[&Chain],
        points_mm: Vec<Point3<f64>>,
        sight_lines: bool,
    ) -> Dependence {
        // How far a solid of the chain reaches from the hip: its links'
        // lengths and the thickest radius.
        let reach_mm = chains
            .iter()
            .map(|c| c.reach_bound_mm() + c.thickest_mm())
            .fold(0.0, f64::max);
        let looked_at = self.common.collisions || sight_lines;
        let clearance_mm = if self.common.collisions {
            self.common.clearance_mm
        } else {
            0.0
        };
        Dependence {
            chain: chain.clone(),
            points_mm,
            reach_mm: looked_at.then_some(reach_mm + clearance_mm),
            sight_lines,
            tolerance_mm: self.common.tolerance_mm,
        }
    }
}

/// The chain to the first effector a task names, for the person of
/// `input`.
pub fn chain_of(input: &TaskInput<'_>, need: usize) -> Chain {
    let index = input.effectors.get(need).copied().unwrap_or(0);
    input.person.body.chain(index)
}

/// A seed that depends on the task's seed and on what is asked (`kind`),
/// never on names, the order of tasks in the file or where the room is:
/// adding a task, or renaming a target, a surface or a person, leaves
/// every answer alone (and a member of a population gets the answers the
/// same body alone gets). Each solve mixes in where its target is from
/// where the person stands (`scene::seed_in_base_frame`), so that moving
/// the whole scenario leaves every answer alone too.
pub fn mix_seed(seed: u64, kind: &str) -> u64 {
    crate::scene::fnv1a(seed, kind.bytes().chain([0xff]))
}
