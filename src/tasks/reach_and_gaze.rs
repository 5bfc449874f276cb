//! The `reach_and_gaze` task, written `reach mug and gaze by ann`: can the
//! person bring their hand to the target while looking at it? The base is
//! placed for the hand, as a reach task places it; from there the hand and
//! the eyes are solved together by FABRIK's tree solve, the hand first
//! (weight 1 in the shared spine's goal) and the eyes after (`gaze_weight`).
//! The report holds a reach report for the hand and a gaze report for the
//! eyes, from the one posture.

use nalgebra::Point3;

use super::common::{common_params, mix_seed, Setup};
use super::gaze::{
    effective_vision, illegible, legible_mm, limit_look, needs_look_link, see, vision_params,
    GazeObstacles,
};
use crate::collision::PlacedObstacles;
use crate::error::ErrorKind;
use crate::kinematics::{Body, Chain};
use crate::plugin::{
    BasePose, IkSolution, Options, ParamSpec, Placement, Plugin, PluginKind, Search, SubjectKind,
    TaskContext, TaskPlugin,
};
use crate::report::{Asked, GazeReport, ReachAndGazeReport, ReachReport, TaskReport};
use crate::scene::Room;
use crate::solvers::fabrik::{solve_tree, TreeGoal, TreeProblem, TreeSolution};
use crate::solvers::FabrikSettings;

/// The plugin `reach_and_gaze`.
pub struct ReachAndGaze;

impl Plugin for ReachAndGaze {
    fn name(&self) -> &'static str {
        "reach_and_gaze"
    }

    fn doc(&self) -> &'static str {
        "`reach T and gaze`: the hand on the target while the eyes see it, one posture (fabrik's tree solve)"
    }

    fn params(&self) -> Vec<ParamSpec> {
        let mut params = common_params(
            "target",
            "seeds the solver's random starts (mixed with target and person)",
        );
        for p in &mut params {
            if p.name == "solver" {
                *p = ParamSpec::plugin(
                    "solver",
                    PluginKind::Solver,
                    "fabrik",
                    "fabrik, whose tree solve moves hand and eyes together",
                );
            }
        }
        params.extend([
            ParamSpec::name(
                "eyes",
                "eyes",
                "the effector whose chain ends in the look link",
            ),
            ParamSpec::number(
                "gaze_weight",
                0.1,
                "the eyes' priority in the shared joints, against the hand's 1",
            )
            .range(0.0, 100.0),
        ]);
        params.extend(vision_params());
        params
    }
}

impl TaskPlugin for ReachAndGaze {
    fn subject(&self) -> SubjectKind {
        SubjectKind::Target
    }

    fn validate(&self, _room: &Room, _subject: &str, options: &Options) -> Option<ErrorKind> {
        let solver = &options.plugin("solver").name;
        if solver != "fabrik" {
            return Some(ErrorKind::Unsupported {
                what: format!("`reach ... and gaze` with solver `{solver}`"),
                help: "hand and eyes are solved together by the tree solve of `fabrik`: leave `solver` out or name fabrik".into(),
            });
        }
        illegible(&effective_vision(options, None))
    }

    fn effector_options(&self) -> &'static [&'static str] {
        &["effector", "eyes"]
    }

    fn validate_chain(
        &self,
        person: &str,
        option: &str,
        chain: &Chain,
        _: &Options,
    ) -> Option<ErrorKind> {
        (option == "eyes")
            .then(|| needs_look_link(person, chain))
            .flatten()
    }

    fn run(&self, ctx: &TaskContext<'_>) -> TaskReport {
        let task = ctx.task;
        let setup = Setup::new(ctx);
        let (room, target) = ctx.scenario.target(&task.subject).expect("checked target");
        let options = &effective_vision(&task.options, Some(&setup.person.vision));
        let (body, hand, eyes) = body_with_look_range(&setup, options);
        let obstacles = GazeObstacles::new(room, &setup);
        let query = setup.query(
            target.position_mm,
            mix_seed(
                setup.seed,
                &[&task.subject, &setup.person.name, "reach+gaze"],
            ),
            Search::MostComfortable,
            obstacles.body.as_ref(),
        );
        let pose = setup
            .base
            .prepare(room, &setup.chain)
            .reach(&query, setup.solver.as_ref())
            .pose;
        let goal = pose.to_base(&target.position_mm);
        let goals = [
            TreeGoal {
                effector: hand,
                target_mm: goal,
                weight: 1.0,
            },
            TreeGoal {
                effector: eyes,
                target_mm: goal,
                weight: options.number("gaze_weight"),
            },
        ];
        let tree = solve_tree(
            &FabrikSettings::from_options(&options.plugin("solver").options),
            &TreeProblem {
                body: &body,
                goals: &goals,
                tolerance_mm: setup.tolerance_mm,
                seed: query.seed,
                obstacles: obstacles.body.as_ref().map(|o| PlacedObstacles {
                    obstacles: o,
                    base_pose: pose,
                }),
            },
        );
        let asked = |chain| Asked {
            task,
            person: setup.person,
            chain,
            solver: setup.solver_name,
            tolerance_mm: setup.tolerance_mm,
        };
        let hand_chain = body.chain(hand);
        let mut hand_placement = placed(&body, hand, &hand_chain, &tree, pose, target.position_mm);
        hand_placement.solution.collision = query
            .problem(&hand_chain, pose)
            .collision(&hand_placement.solution.q);
        let reach = ReachReport::new(
            &asked(&hand_chain),
            &hand_placement,
            target.position_mm,
            room,
        );
        let eyes_chain = body.chain(eyes);
        let eyes_placement = placed(&body, eyes, &eyes_chain, &tree, pose, target.position_mm);
        let sight = see(
            &eyes_chain,
            &eyes_placement,
            target.position_mm,
            &obstacles,
            &setup,
            options,
        );
        let gaze = GazeReport::new(
            &asked(&eyes_chain),
            &eyes_placement,
            target.position_mm,
            sight,
        );
        TaskReport::ReachAndGaze(Box::new(ReachAndGazeReport {
            name: task.subject.clone(),
            person: setup.person.name.clone(),
            ok: reach.ok && gaze.ok,
            reach,
            gaze,
        }))
    }
}

/// The person's body with the eyes' look link kept to the legible range,
/// and the indices of the hand and eye effectors.
fn body_with_look_range(setup: &Setup<'_>, options: &Options) -> (Body, usize, usize) {
    let mut body = setup.person.body.clone();
    let index = |name: Option<&str>| {
        name.map_or(Some(0), |n| body.effector_index(n))
            .expect("checked effector")
    };
    let hand = index(options.name_opt("effector"));
    let eyes = index(options.name_opt("eyes"));
    let look = body.effectors[eyes].joint.expect("checked look link");
    limit_look(&mut body.joints[look], legible_mm(options));
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
