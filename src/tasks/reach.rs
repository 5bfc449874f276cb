//! The `reach` task: can this person bring their hand to this target?

use super::common::{common_params, mix_seed, Setup};
use crate::plugin::{ParamSpec, Plugin, Search, SubjectKind, TaskContext, TaskPlugin};
use crate::report::{Asked, ReachReport, TaskReport};

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
        common_params(
            "target",
            "seeds the solver's random starts (mixed with target and person)",
        )
    }
}

impl TaskPlugin for Reach {
    fn subject(&self) -> SubjectKind {
        SubjectKind::Target
    }

    fn run(&self, ctx: &TaskContext<'_>) -> TaskReport {
        let task = ctx.task;
        let setup = Setup::new(ctx);
        let (room, target) = ctx.scenario.target(&task.subject).expect("checked target");
        let obstacles = setup.obstacles(room);
        let query = setup.query(
            target.position_mm,
            mix_seed(setup.seed, &[&task.subject, &setup.person.name]),
            Search::MostComfortable,
            obstacles.as_ref(),
        );
        let placement = setup
            .base
            .prepare(room, &setup.chain)
            .reach(&query, setup.solver.as_ref());
        let asked = Asked {
            task,
            person: setup.person,
            chain: &setup.chain,
            solver: setup.solver_of(&placement),
            tolerance_mm: setup.tolerance_mm,
        };
        TaskReport::Reach(ReachReport::new(
            &asked,
            &placement,
            target.position_mm,
            room,
        ))
    }
}
