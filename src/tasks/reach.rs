//! The `reach` task: can this person bring their hand to this target?

use super::common::{
    chain_of, mix_seed, Common, CommonDecl, Reaching, INCREMENTAL, THOROUGH_RETRY,
};
use super::walk_in::reach_walking_in;
use super::why::{Failed, Found};
use crate::plugin::{
    Dependence, EffectorNeed, Options, ParamSpec, Params, Plugin, ReachQuery, Registry, Search,
    Settings, SettingsError, Subject, SubjectKind, Task, TaskInput, TaskPlugin, Tries,
};
use crate::report::{ReachReport, TaskReport};

/// The plugin `reach`.
pub struct Reach;

/// Its settings: the common ones.
pub struct ReachSettings(pub Common);

impl Settings for ReachSettings {
    fn visit(p: &mut Params<'_>) -> Self {
        ReachSettings(Common::visit(
            p,
            &CommonDecl {
                what: "target",
                seed_doc: "seeds the solver's random starts (mixed with where the target is from where the person stands, never with names or where the room is)",
                solver: INCREMENTAL,
                effector: None,
                retry: THOROUGH_RETRY,
            },
        ))
    }
}

impl Plugin for Reach {
    fn name(&self) -> &'static str {
        "reach"
    }

    fn doc(&self) -> &'static str {
        "can the person's effector reach the target, from where their base lets them be"
    }

    fn params(&self) -> Vec<ParamSpec> {
        ReachSettings::params()
    }
}

impl TaskPlugin for Reach {
    fn subject(&self) -> SubjectKind {
        SubjectKind::Target
    }

    fn configure(
        &self,
        options: &Options,
        plugins: &Registry,
    ) -> Result<Box<dyn Task>, SettingsError> {
        let ReachSettings(common) = ReachSettings::from_options(options)?;
        Ok(Box::new(ReachTask(Reaching::new(common, plugins)?)))
    }
}

/// A configured reach.
struct ReachTask(Reaching);

impl Task for ReachTask {
    fn effectors(&self) -> Vec<EffectorNeed> {
        vec![self.0.effector_need()]
    }

    fn starts_per_point(&self, placements: Tries) -> u64 {
        self.0.starts_per_point(placements)
    }

    /// Its obstacles are asked about through `Reaching::obstacles` (and
    /// finding why marks those it ranks), its floor through its base.
    fn records_touches(&self) -> bool {
        true
    }

    fn dependence(&self, input: &TaskInput<'_>) -> Dependence {
        let chain = chain_of(input, 0);
        let Subject::Target(target) = input.subject else {
            return self.0.dependence(&chain, &[&chain], Vec::new(), false);
        };
        self.0
            .dependence(&chain, &[&chain], vec![target.position_mm], false)
    }

    fn run(&self, input: &TaskInput<'_>) -> TaskReport {
        let reaching = &self.0;
        let Subject::Target(target) = input.subject else {
            unreachable!("the checker gives a reach a target")
        };
        let chain = chain_of(input, 0);
        let obstacles = reaching.obstacles(input);
        let seed = mix_seed(reaching.common.seed, "reach");
        // Whether any placement reaches does not depend on which is kept:
        // for a verdict alone, the first that reaches will do.
        let search = if input.verdict_only {
            Search::FirstReaching
        } else {
            Search::MostComfortable
        };
        let own = input.base.own_body();
        let query = ReachQuery {
            solves: (input.solves).map(|s| s.of(&chain, obstacles.as_ref(), own)),
            ..reaching.query(
                target.position_mm,
                seed,
                search,
                obstacles.as_ref(),
                own,
                input.allowance,
            )
        };
        let prepared = input.base.prepare(input.room, &chain, input.allowance);
        let solver = reaching.solver.as_ref();
        let mut placement = reach_walking_in(prepared.as_ref(), &query, &chain, solver);
        let mut why = Vec::new();
        if !placement.solution.reaches(reaching.common.tolerance_mm) {
            let failed = Failed {
                reaching,
                input,
                chain: &chain,
                target_mm: target.position_mm,
                seed,
                obstacles: obstacles.as_ref(),
                placement: &placement,
            };
            match failed.why() {
                Found::Why(w) => why = w,
                Found::Reached(p) => placement = p,
            }
        }
        let asked = reaching.asked(&target.name, input, &chain, &placement);
        let mut report = ReachReport::new(&asked, &placement, target.position_mm);
        report.why = why;
        TaskReport::Reach(report)
    }
}
