//! What the reach-like tasks share: their common options (solver,
//! tolerance, seed, collisions and the retry where obstacles block), the
//! setup that builds the person's solvers and base and asks its queries,
//! and seeds that depend on names rather than on the order of tasks.

use crate::collision::Obstacles;
use crate::kinematics::Chain;
use nalgebra::Point3;

use crate::plugin::{
    Base, ParamSpec, Placement, PluginConfig, PluginKind, ReachQuery, Retry, Search, Solver,
    TaskContext, Value,
};
use crate::scene::{Person, Room};

/// `solver`, `tolerance` and `seed`, with `what` in the docs ("target",
/// "point").
pub fn common_params(what: &'static str, seed_doc: &'static str) -> Vec<ParamSpec> {
    let tolerance_doc = match what {
        "point" => "a point counts as reached within this distance",
        _ => "the target counts as reached within this distance",
    };
    vec![
        ParamSpec::plugin(
            "solver",
            PluginKind::Solver,
            "incremental",
            "the IK solver and its options",
        ),
        ParamSpec::length("tolerance", 10.0, tolerance_doc).range(0.001, 1000.0),
        ParamSpec::integer("seed", 1, seed_doc).range(0.0, 9_007_199_254_740_992.0),
        ParamSpec::optional_name(
            "effector",
            "which of the mannequin's effectors (default: its first)",
        ),
        ParamSpec::boolean(
            "collisions",
            true,
            "links must stay out of the room's obstacles (links are segments between joints)",
        ),
        ParamSpec::length(
            "clearance",
            0.0,
            "with collisions: how close a link may come to an obstacle",
        )
        .range(0.0, 500.0),
        ParamSpec::plugin_with(
            "blocked_solver",
            PluginKind::Solver,
            "incremental",
            vec![("starts", Value::Integer(64))],
            "with collisions, where the solver reaches from no placement: the solver that tries again",
        ),
        ParamSpec::integer(
            "blocked_retries",
            4,
            "how many of the most promising placements `blocked_solver` tries (0: none)",
        )
        .range(0.0, 360.0),
    ]
}

/// The person of a task with their solver and base built from the task's
/// and the person's options (checked, so every name resolves).
pub struct Setup<'a> {
    pub person: &'a Person,
    /// The chain to the effector the task names.
    pub chain: Chain,
    pub solver_name: &'a str,
    pub solver: Box<dyn Solver>,
    pub blocked_solver_name: &'a str,
    pub blocked_solver: Box<dyn Solver>,
    pub blocked_retries: usize,
    pub base: Box<dyn Base>,
    pub tolerance_mm: f64,
    pub seed: u64,
    pub collisions: bool,
    pub clearance_mm: f64,
}

impl<'a> Setup<'a> {
    pub fn new(ctx: &TaskContext<'a>) -> Self {
        let task = ctx.task;
        let person = ctx.scenario.person(&task.person).expect("checked person");
        let solver_cfg = task.options.plugin("solver");
        let blocked_cfg = task.options.plugin("blocked_solver");
        let build = |cfg: &PluginConfig| {
            ctx.registry
                .solver(&cfg.name)
                .expect("checked solver")
                .build(&cfg.options)
        };
        let base = ctx
            .registry
            .base(&person.base.name)
            .expect("checked base")
            .build(&person.base.options);
        let chain = person
            .chain_for(task.options.name_opt("effector"))
            .expect("checked effector");
        Setup {
            person,
            chain,
            solver_name: &solver_cfg.name,
            solver: build(solver_cfg),
            blocked_solver_name: &blocked_cfg.name,
            blocked_solver: build(blocked_cfg),
            blocked_retries: task.options.integer("blocked_retries") as usize,
            base,
            tolerance_mm: task.options.length_mm("tolerance"),
            seed: task.options.integer("seed") as u64,
            collisions: task.options.boolean("collisions"),
            clearance_mm: task.options.length_mm("clearance"),
        }
    }

    /// The room's obstacles when the task checks collisions.
    pub fn obstacles(&self, room: &Room) -> Option<Obstacles> {
        self.collisions
            .then(|| Obstacles::new(room, self.clearance_mm))
    }

    /// A reach of `target_room_mm` keeping links out of `obstacles`, with
    /// the task's tolerance and, where obstacles are checked, its retry.
    pub fn query<'q>(
        &'q self,
        target_room_mm: Point3<f64>,
        seed: u64,
        search: Search,
        obstacles: Option<&'q Obstacles>,
    ) -> ReachQuery<'q> {
        let retry = (obstacles.is_some() && self.blocked_retries > 0).then(|| Retry {
            solver: self.blocked_solver.as_ref(),
            placements: self.blocked_retries,
        });
        ReachQuery {
            target_room_mm,
            tolerance_mm: self.tolerance_mm,
            seed,
            search,
            obstacles,
            retry,
        }
    }

    /// The name of the solver that found `placement`'s posture.
    pub fn solver_of(&self, placement: &Placement) -> &'a str {
        if placement.retried {
            self.blocked_solver_name
        } else {
            self.solver_name
        }
    }
}

/// A seed that depends on the task's seed and on names, never on the order
/// of tasks in the file: adding a task leaves the others' answers alone.
pub fn mix_seed(seed: u64, names: &[&str]) -> u64 {
    // FNV-1a: small, and stable across Rust versions (unlike std's hasher).
    let mut h: u64 = 0xcbf2_9ce4_8422_2325 ^ seed;
    for name in names {
        for b in name.bytes().chain(std::iter::once(0xff)) {
            h ^= u64::from(b);
            h = h.wrapping_mul(0x0100_0000_01b3);
        }
    }
    h
}
