//! The `reach` task: can this person bring their hand to this target?

use crate::plugin::{
    ParamSpec, Plugin, PluginKind, ReachQuery, Search, SubjectKind, TaskContext, TaskPlugin,
};
use crate::report::{ReachReport, TaskReport};

/// The plugin `reach`.
pub struct Reach;

impl Plugin for Reach {
    fn name(&self) -> &'static str {
        "reach"
    }

    fn doc(&self) -> &'static str {
        "can the person's effector reach the target, from where their base lets them be"
    }

    fn params(&self) -> Vec<ParamSpec> {
        vec![
            ParamSpec::plugin(
                "solver",
                PluginKind::Solver,
                "incremental",
                "the IK solver and its options",
            ),
            ParamSpec::length(
                "tolerance",
                10.0,
                "the target counts as reached within this distance",
            )
            .range(0.001, 1000.0),
            ParamSpec::integer(
                "seed",
                1,
                "seeds the solver's random starts (mixed with target and person)",
            )
            .range(0.0, 9_007_199_254_740_992.0),
        ]
    }
}

impl TaskPlugin for Reach {
    fn subject(&self) -> SubjectKind {
        SubjectKind::Target
    }

    fn run(&self, ctx: &TaskContext<'_>) -> TaskReport {
        let task = ctx.task;
        let person = ctx.scenario.person(&task.person).expect("checked person");
        let (room, target) = ctx.scenario.target(&task.subject).expect("checked target");
        let solver_cfg = task.options.plugin("solver");
        let solver = ctx
            .registry
            .solver(&solver_cfg.name)
            .expect("checked solver")
            .build(&solver_cfg.options);
        let base = ctx
            .registry
            .base(&person.base.name)
            .expect("checked base")
            .build(&person.base.options);
        let tolerance_mm = task.options.length_mm("tolerance");
        let seed = mix_seed(
            task.options.integer("seed") as u64,
            &[&task.subject, &person.name],
        );
        let query = ReachQuery {
            target_room_mm: target.position_mm,
            tolerance_mm,
            seed,
            search: Search::MostComfortable,
        };
        let placement = base
            .prepare(room, &person.chain)
            .reach(&query, solver.as_ref());
        TaskReport::Reach(ReachReport::new(
            task,
            person,
            &solver_cfg.name,
            &placement,
            target.position_mm,
            tolerance_mm,
        ))
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
