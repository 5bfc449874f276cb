//! The `reach` task: can this person bring their hand to this target?

use super::common::{mix_seed, Common, CommonDecl, Reaching, INCREMENTAL, THOROUGH_RETRY};
use super::gaze::refuses_look_link;
use super::hand::{self, hands_of, Hand};
use super::walk_in::reach_walking_in;
use super::why::{Failed, Found};
use crate::engine::KeptProofs;
use crate::error::ErrorKind;
use crate::kinematics::{Body, Chain};
use crate::plugin::{
    Dependence, EffectorNeed, Obstacles, Options, ParamSpec, Params, Plugin, ReachQuery, Registry,
    Search, Settings, SettingsError, Subject, SubjectKind, Task, TaskInput, TaskPlugin, Tries,
};
use crate::report::{ReachReport, TaskReport};
use crate::scene::Target;
use nalgebra::Point3;

/// The plugin `reach`.
pub struct Reach;

/// Its settings: the common ones, and which hand reaches.
pub struct ReachSettings {
    pub common: Common,
    /// `either`, `right` or `left` ([`Hand`]); none: either hand where no
    /// effector is named, else the one named.
    pub hand: Option<String>,
}

impl Settings for ReachSettings {
    fn visit(p: &mut Params<'_>) -> Self {
        ReachSettings {
            common: Common::visit(
                p,
                &CommonDecl {
                    what: "target",
                    seed_doc: "seeds the solver's random starts (mixed with where the target is from where the person stands, never with names or where the room is)",
                    solver: INCREMENTAL,
                    effector: None,
                    retry: THOROUGH_RETRY,
                },
            ),
            hand: Hand::option(p, hand::HAND_DOC),
        }
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
        let settings = ReachSettings::from_options(options)?;
        Ok(Box::new(ReachTask::new(settings, plugins)?))
    }
}

/// A configured reach: with the effector asked for alone, or `either`
/// hand (its twin too, where the mannequin has one).
pub(super) struct ReachTask {
    reaching: Reaching,
    either: bool,
}

impl ReachTask {
    /// The reach `settings` configure, its solvers built from `plugins`.
    pub(super) fn new(settings: ReachSettings, plugins: &Registry) -> Result<Self, SettingsError> {
        let ReachSettings { mut common, hand } = settings;
        let either = Hand::resolve(hand.as_deref(), &mut common)?;
        Ok(ReachTask {
            reaching: Reaching::new(common, plugins)?,
            either,
        })
    }

    /// The reach of `input`'s target, with either hand as configured;
    /// where it fails, why only if `explain` (finding why searches again
    /// without the room, the body and the limits: the most costly part of
    /// a failed reach). Without `explain`, only whether it reaches is to
    /// be read: a failed report's closest placement may be another than
    /// the one an explained reach keeps (`reach_with`).
    pub(super) fn reach(&self, input: &TaskInput<'_>, explain: bool) -> ReachReport {
        let Subject::Target(target) = input.subject else {
            unreachable!("the checker gives a reach a target")
        };
        // The room's obstacles, once for either hand.
        let obstacles = self.reaching.obstacles(input);
        let mut best: Option<ReachReport> = None;
        for effector in self.hands_of(&input.person.body, input.effectors[0]) {
            let report = self.reach_with(input, target, effector, obstacles.as_ref(), explain);
            // For a verdict alone, the first hand that reaches will do.
            let done = report.ok && input.verdict_only;
            best = Some(match best {
                Some(kept) if !better(&report, &kept, &target.position_mm) => kept,
                _ => report,
            });
            if done {
                break;
            }
        }
        best.expect("a reach has at least one hand")
    }
}

impl Task for ReachTask {
    fn effectors(&self) -> Vec<EffectorNeed> {
        vec![self.reaching.effector_need()]
    }

    /// A hand's point: not a line of sight, whose look link would
    /// "reach" whatever is in view.
    fn validate_chain(&self, person: &str, _need: usize, chain: &Chain) -> Option<ErrorKind> {
        refuses_look_link(person, chain)
    }

    fn starts_per_point(&self, placements: Tries) -> u64 {
        self.reaching.starts_per_point(placements)
    }

    /// Either hand: a search with each.
    fn searches(&self, body: &Body, effectors: &[usize]) -> u64 {
        hand::searches(body, effectors, self.either)
    }

    /// Its obstacles are asked about through `Reaching::obstacles` (and
    /// finding why marks those it ranks), its floor through its base.
    fn records_touches(&self) -> bool {
        true
    }

    fn dependence(&self, input: &TaskInput<'_>) -> Dependence {
        // The effector asked for first, then its twin.
        let chains: Vec<_> = (self.hands_of(&input.person.body, input.effectors[0]).iter())
            .map(|&e| input.person.body.chain(e))
            .collect();
        let all: Vec<&_> = chains.iter().collect();
        let points = match input.subject {
            Subject::Target(target) => vec![target.position_mm],
            _ => Vec::new(),
        };
        self.reaching.dependence(&chains[0], &all, points, false)
    }

    fn run(&self, input: &TaskInput<'_>) -> TaskReport {
        TaskReport::Reach(self.reach(input, true))
    }
}

/// Whether `a` is a better answer than `b` for the target at
/// `target_mm`: it reaches where `b` does not; both reaching, with the
/// hand on the target's side where it is well to one side (past a
/// shoulder: a person does not reach across the body for it), else the
/// more comfortable; neither, it comes closer.
fn better(a: &ReachReport, b: &ReachReport, target_mm: &Point3<f64>) -> bool {
    let on_its_side = |r: &ReachReport| hand::on_side_of(&r.effector, &r.base.pose(), target_mm);
    match (a.ok, b.ok) {
        (true, false) => true,
        (false, true) => false,
        (true, true) => hand::rather((on_its_side(a), a.comfort), (on_its_side(b), b.comfort)),
        (false, false) => a.distance_mm < b.distance_mm,
    }
}

impl ReachTask {
    /// The effectors (indices into `body`) this reach tries: `asked`, and
    /// for `either` its twin.
    fn hands_of(&self, body: &Body, asked: usize) -> Vec<usize> {
        hands_of(body, asked, self.either)
    }

    /// The reach of `target` with effector `effector`, kept out of
    /// `obstacles` (none: collisions are not checked), and where it fails,
    /// why (if `explain`).
    fn reach_with(
        &self,
        input: &TaskInput<'_>,
        target: &Target,
        effector: usize,
        obstacles: Option<&Obstacles>,
        explain: bool,
    ) -> ReachReport {
        let reaching = &self.reaching;
        let chain = input.person.body.chain(effector);
        let seed = mix_seed(reaching.common.seed, "reach");
        // Whether any placement reaches does not depend on which is kept:
        // for a verdict alone, the first that reaches will do.
        let search = if input.verdict_only {
            Search::FirstReaching
        } else {
            Search::MostComfortable
        };
        let own = input.base.own_body();
        // Asked for whether it reaches alone (not why), the search passes
        // over the placements a proof puts out of reach: their descents
        // could not reach, so whether any placement does is the same, but
        // the closest of a failed search may be another, so a reach that
        // is explained searches them all.
        let proofs = (!explain).then(|| KeptProofs::new(&chain, own, input.allowance));
        let query = ReachQuery {
            solves: (input.solves).map(|s| s.of(&chain, obstacles, own)),
            proofs: proofs.as_ref(),
            ..reaching.query(
                target.position_mm,
                seed,
                search,
                obstacles,
                own,
                input.allowance,
            )
        };
        let prepared = input.base.prepare(input.room, &chain, input.allowance);
        let solver = reaching.solver.as_ref();
        let mut placement = reach_walking_in(prepared.as_ref(), &query, &chain, solver);
        let mut why = Vec::new();
        if explain && !placement.solution.reaches(reaching.common.tolerance_mm) {
            let failed = Failed {
                reaching,
                input,
                chain: &chain,
                target_mm: target.position_mm,
                seed,
                obstacles,
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
        report
    }
}
