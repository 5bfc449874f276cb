//! The `reach_and_gaze` task, written `reach mug and gaze by ann`: can the
//! person bring their hand to the target while looking at it? The base is
//! placed for the hand, as a reach task places it; from there the hand and
//! the eyes are solved together by FABRIK's tree solve, the hand first
//! (weight 1 in the shared spine's goal) and the eyes after (`gaze_weight`).
//! The report holds a reach report for the hand and a gaze report for the
//! eyes, from the one posture.

use nalgebra::Point3;

use super::common::{chain_of, mix_seed, Common, CommonDecl, Reaching, THOROUGH_RETRY};
use super::gaze::{limit_look, needs_look_link, GazeObstacles, Looked, Looking};
use super::why::{Failed, Found};
use crate::collision::{Obstacles, PlacedObstacles};
use crate::error::ErrorKind;
use crate::kinematics::{Body, Chain};
use crate::plugin::{
    BasePose, Dependence, EffectorNeed, IkSolution, Options, ParamSpec, Params, Placement, Plugin,
    ReachQuery, Registry, Search, Settings, SettingsError, Subject, SubjectKind, Task, TaskInput,
    TaskPlugin, Tries,
};
use crate::report::{Asked, GazeReport, ReachAndGazeReport, ReachReport, TaskReport, Why};
use crate::solvers::fabrik::{solve_tree, TreeGoal, TreeProblem, TreeSolution};
use crate::solvers::FabrikSettings;

/// The plugin `reach_and_gaze`.
pub struct ReachAndGaze;

/// Its settings: the common ones (fabrik as solver), the eyes, their
/// weight, and what they must make out.
struct ReachAndGazeSettings {
    common: Common,
    eyes: String,
    gaze_weight: f64,
    looking: Looking,
}

impl Settings for ReachAndGazeSettings {
    fn visit(p: &mut Params<'_>) -> Self {
        let common = Common::visit(
            p,
            &CommonDecl {
                what: "target",
                seed_doc: "seeds the solver's random starts (mixed with where the target is, never with names)",
                solver: (
                    "fabrik",
                    "fabrik, whose tree solve moves hand and eyes together",
                ),
                effector: None,
                retry: THOROUGH_RETRY,
            },
        );
        let eyes = p
            .name(
                "eyes",
                "eyes",
                "the effector whose chain ends in the look link",
            )
            .get();
        let gaze_weight = p
            .number(
                "gaze_weight",
                0.1,
                "the eyes' priority in the shared joints, against the hand's 1",
            )
            .range(0.0, 100.0)
            .get();
        ReachAndGazeSettings {
            common,
            eyes,
            gaze_weight,
            looking: Looking::visit(p),
        }
    }
}

impl Plugin for ReachAndGaze {
    fn name(&self) -> &'static str {
        "reach_and_gaze"
    }

    fn doc(&self) -> &'static str {
        "`reach T and gaze`: the hand on the target while the eyes see it, one posture (fabrik's tree solve)"
    }

    fn params(&self) -> Vec<ParamSpec> {
        ReachAndGazeSettings::params()
    }
}

impl TaskPlugin for ReachAndGaze {
    fn subject(&self) -> SubjectKind {
        SubjectKind::Target
    }

    fn configure(
        &self,
        options: &Options,
        plugins: &Registry,
    ) -> Result<Box<dyn Task>, SettingsError> {
        let s = ReachAndGazeSettings::from_options(options)?;
        // The tree solve is fabrik's: its settings when fabrik is named
        // (`validate` refuses any other solver).
        let tree =
            if s.common.solver.name == "fabrik" {
                let options = s.common.solver.options.completed(&FabrikSettings::params());
                Some(FabrikSettings::from_options(&options).map_err(|e| {
                    SettingsError::invalid("solver", format!("solver `fabrik`: {e}"))
                })?)
            } else {
                None
            };
        Ok(Box::new(ReachAndGazeTask {
            reaching: Reaching::new(s.common, plugins)?,
            eyes: s.eyes,
            gaze_weight: s.gaze_weight,
            looking: s.looking,
            tree,
        }))
    }
}

/// A configured `reach T and gaze`.
struct ReachAndGazeTask {
    reaching: Reaching,
    eyes: String,
    gaze_weight: f64,
    looking: Looking,
    /// Fabrik's settings for the tree solve (`None`: another solver was
    /// named, which `validate` refuses).
    tree: Option<FabrikSettings>,
}

impl Task for ReachAndGazeTask {
    fn effectors(&self) -> Vec<EffectorNeed> {
        vec![
            self.reaching.effector_need(),
            EffectorNeed {
                option: "eyes",
                name: Some(self.eyes.clone()),
            },
        ]
    }

    fn validate(&self, _subject: &Subject<'_>) -> Option<ErrorKind> {
        let solver = &self.reaching.common.solver.name;
        if self.tree.is_none() {
            return Some(ErrorKind::Unsupported {
                what: format!("`reach ... and gaze` with solver `{solver}`"),
                help: "hand and eyes are solved together by the tree solve of `fabrik`: leave `solver` out or name fabrik".into(),
            });
        }
        self.looking.eyes(None).illegible()
    }

    fn validate_chain(&self, person: &str, need: usize, chain: &Chain) -> Option<ErrorKind> {
        (need == 1)
            .then(|| needs_look_link(person, chain))
            .flatten()
    }

    fn starts_per_point(&self, placements: Tries) -> u64 {
        self.reaching.starts_per_point(placements)
    }

    /// Its obstacles are asked about through `Reaching::obstacles` (and
    /// finding why marks those it ranks), its floor through its base.
    fn records_touches(&self) -> bool {
        true
    }

    fn dependence(&self, input: &TaskInput<'_>) -> Dependence {
        let eyes = self.looking.eyes(Some(&input.person.vision));
        let (body, _, eyes_index) =
            body_with_look_range(input, eyes.aimed_mm(self.reaching.common.tolerance_mm));
        let hand_chain = chain_of(input, 0);
        let eyes_chain = body.chain(eyes_index);
        let points = match input.subject {
            Subject::Target(t) => vec![t.position_mm],
            Subject::Surface(_) => Vec::new(),
        };
        self.reaching
            .dependence(&hand_chain, &[&hand_chain, &eyes_chain], points, true)
    }

    fn run(&self, input: &TaskInput<'_>) -> TaskReport {
        let reaching = &self.reaching;
        let Subject::Target(target) = input.subject else {
            unreachable!("the checker gives a reach and gaze a target")
        };
        let eyes = self.looking.eyes(Some(&input.person.vision));
        let (body, hand, eyes_index) =
            body_with_look_range(input, eyes.aimed_mm(self.reaching.common.tolerance_mm));
        let hand_chain = chain_of(input, 0);
        let own = input.base.own_body();
        let obstacles = GazeObstacles::new(input, reaching);
        let query = reaching.query(
            target.position_mm,
            mix_seed(reaching.common.seed, "reach+gaze", &target.position_mm),
            Search::MostComfortable,
            obstacles.body.as_ref(),
            own,
            input.meter,
        );
        // Not walked in (`walk_in.rs`): searched with the eyes' chain, a
        // seated person's reach and gaze at a shelf took 160 M units, and
        // walked in 830 M, past the bound on solver work.
        let alone = input
            .base
            .prepare(input.room, &hand_chain)
            .reach(&query, reaching.solver.as_ref());
        let pose = alone.pose;
        let goal = pose.to_base(&target.position_mm);
        let goals = [
            TreeGoal {
                effector: hand,
                target_mm: goal,
                weight: 1.0,
            },
            TreeGoal {
                effector: eyes_index,
                target_mm: goal,
                weight: self.gaze_weight,
            },
        ];
        let tree = solve_tree(
            &self.tree.unwrap_or_else(FabrikSettings::with_defaults),
            &TreeProblem {
                body: &body,
                goals: &goals,
                tolerance_mm: reaching.common.tolerance_mm,
                seed: query.seed,
                obstacles: obstacles.body.as_ref().map(|o| PlacedObstacles {
                    obstacles: o,
                    own,
                    base_pose: pose,
                }),
                meter: input.meter,
            },
        );
        let asked = |chain| Asked {
            subject: &target.name,
            person: input.person,
            chain,
            solver: &reaching.common.solver.name,
            tolerance_mm: reaching.common.tolerance_mm,
            room: input.room,
            own,
        };
        let hand_chain = body.chain(hand);
        let mut hand_placement = placed(&body, hand, &hand_chain, &tree, pose, target.position_mm);
        hand_placement.solution.collision = query
            .problem(&hand_chain, pose)
            .collision(&hand_placement.solution.q);
        let mut reach = ReachReport::new(&asked(&hand_chain), &hand_placement, target.position_mm);
        if !reach.ok {
            reach.why = self.why_not(input, &hand_chain, &alone, &query, obstacles.body.as_ref());
        }
        let eyes_chain = body.chain(eyes_index);
        let eyes_placement = placed(
            &body,
            eyes_index,
            &eyes_chain,
            &tree,
            pose,
            target.position_mm,
        );
        let looked = Looked {
            chain: &eyes_chain,
            placement: &eyes_placement,
            target: target.position_mm,
        };
        let sight = looked.see(&obstacles, reaching.common.tolerance_mm, &eyes);
        let gaze = GazeReport::new(
            &asked(&eyes_chain),
            &eyes_placement,
            target.position_mm,
            sight,
        );
        TaskReport::ReachAndGaze(Box::new(ReachAndGazeReport {
            name: target.name.clone(),
            person: input.person.name.clone(),
            ok: reach.ok && gaze.ok,
            reach,
            gaze,
        }))
    }
}

impl ReachAndGazeTask {
    /// Why the hand did not reach while the eyes looked: where the hand
    /// alone reaches (`alone`, searched as a `reach`), that it does not
    /// while looking; else why the hand alone does not, found as a reach's
    /// cause is (`why.rs`).
    fn why_not(
        &self,
        input: &TaskInput<'_>,
        hand_chain: &Chain,
        alone: &Placement,
        query: &ReachQuery<'_>,
        obstacles: Option<&Obstacles>,
    ) -> Vec<Why> {
        if alone.solution.reaches(self.reaching.common.tolerance_mm) {
            return vec![Why::WhileLooking];
        }
        let failed = Failed {
            reaching: &self.reaching,
            input,
            chain: hand_chain,
            target_mm: query.target_room_mm,
            seed: query.seed,
            obstacles,
            placement: alone,
        };
        match failed.why() {
            Found::Why(why) => why,
            Found::Reached(_) => vec![Why::WhileLooking],
        }
    }
}

/// The person's body with the eyes' look link kept to the legible range,
/// and the indices of the hand and eye effectors.
fn body_with_look_range(input: &TaskInput<'_>, legible_mm: [f64; 2]) -> (Body, usize, usize) {
    let mut body = input.person.body.clone();
    let hand = input.effectors.first().copied().unwrap_or(0);
    let eyes = input.effectors.get(1).copied().unwrap_or(0);
    if let Some(look) = body.effectors[eyes].joint {
        limit_look(&mut body.joints[look], legible_mm);
    }
    (body, hand, eyes)
}

/// Effector `effector`'s share of the tree's posture (`chain` is its
/// chain), as a placement.
fn placed(
    body: &Body,
    effector: usize,
    chain: &Chain,
    tree: &TreeSolution,
    pose: BasePose,
    target_room: Point3<f64>,
) -> Placement {
    let q: Vec<f64> = body
        .path(body.effectors[effector].joint)
        .iter()
        .map(|&j| tree.q[j])
        .collect();
    Placement {
        pose,
        solution: IkSolution {
            distance_mm: (pose.to_room(&chain.effector(&q)) - target_room).norm(),
            q,
            iterations: tree.iterations,
            collision: None,
        },
        retried: false,
    }
}
