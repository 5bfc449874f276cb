//! The `reach_and_gaze` task, written `reach mug and gaze by ann`: can the
//! person bring their hand to the target while looking at it? The base is
//! placed for the hand, as a reach task places it; from there the hand and
//! the eyes are solved together by FABRIK's tree solve, the hand first
//! (weight 1 in the shared spine's goal) and the eyes after (`gaze_weight`).
//! The report holds a reach report for the hand and a gaze report for the
//! eyes, from the one posture.

use nalgebra::{Point3, Vector2};

use super::common::{mix_seed, Common, CommonDecl, Reaching, THOROUGH_RETRY};
use super::gaze::{
    limit_look, needs_look_link, refuses_look_link, Eyes, GazeObstacles, Looked, Looking,
};
use super::hand::{self, hands_of, Hand};
use super::why::{Failed, Found};
use crate::collision::{Obstacles, PlacedObstacles};
use crate::error::ErrorKind;
use crate::kinematics::{Body, Chain};
use crate::plugin::{
    BasePose, Dependence, EffectorNeed, IkSolution, Options, ParamSpec, Params, Placement, Plugin,
    PreparedBase, ReachQuery, Registry, Search, Settings, SettingsError, Subject, SubjectKind,
    Task, TaskInput, TaskPlugin, Tries,
};
use crate::report::{Asked, GazeReport, ReachAndGazeReport, ReachReport, TaskReport, Why};
use crate::scene::{seed_in_base_frame, Target};
use crate::solvers::fabrik::{solve_tree, TreeGoal, TreeProblem, TreeSolution};
use crate::solvers::FabrikSettings;

/// The plugin `reach_and_gaze`.
pub struct ReachAndGaze;

/// Its settings: the common ones (fabrik as solver), which hand, the
/// eyes, their weight, and what they must make out.
struct ReachAndGazeSettings {
    common: Common,
    /// `either`, `right` or `left` ([`Hand`]); none: either hand where no
    /// effector is named, else the one named.
    hand: Option<String>,
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
                seed_doc: "seeds the solver's random starts (mixed with where the target is from where the person stands, never with names or where the room is)",
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
            hand: Hand::option(p, hand::HAND_DOC_SEEN),
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
        let mut s = ReachAndGazeSettings::from_options(options)?;
        let either = Hand::resolve(s.hand.as_deref(), &mut s.common)?;
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
            either,
            eyes: s.eyes,
            gaze_weight: s.gaze_weight,
            looking: s.looking,
            tree,
        }))
    }
}

/// A configured `reach T and gaze`: with the effector asked for alone, or
/// `either` hand (its twin too, where the mannequin has one).
struct ReachAndGazeTask {
    reaching: Reaching,
    either: bool,
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
        match need {
            0 => refuses_look_link(person, chain),
            _ => needs_look_link(person, chain),
        }
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
        let eyes = self.looking.eyes(Some(&input.person.vision));
        let (body, eyes_index) =
            body_with_look_range(input, eyes.aimed_mm(self.reaching.common.tolerance_mm));
        // The effector asked for first, then its twin, then the eyes.
        let mut chains: Vec<Chain> = (self.hands(input).into_iter())
            .map(|hand| input.person.body.chain(hand))
            .collect();
        chains.push(body.chain(eyes_index));
        let all: Vec<&Chain> = chains.iter().collect();
        let points = match input.subject {
            Subject::Target(t) => vec![t.position_mm],
            Subject::Surface(_) => Vec::new(),
        };
        self.reaching.dependence(&chains[0], &all, points, true)
    }

    fn run(&self, input: &TaskInput<'_>) -> TaskReport {
        let Subject::Target(target) = input.subject else {
            unreachable!("the checker gives a reach and gaze a target")
        };
        // The room's obstacles and the body with its look range, once for
        // either hand.
        let eyes = self.looking.eyes(Some(&input.person.vision));
        let (body, eyes_index) =
            body_with_look_range(input, eyes.aimed_mm(self.reaching.common.tolerance_mm));
        let obstacles = GazeObstacles::new(input, &self.reaching);
        let query = self.reaching.query(
            target.position_mm,
            mix_seed(self.reaching.common.seed, "reach+gaze"),
            Search::MostComfortable,
            obstacles.body.as_ref(),
            input.base.own_body(),
            input.allowance,
        );
        let with = With {
            input,
            target,
            body: &body,
            eyes_index,
            eyes: &eyes,
            obstacles: &obstacles,
            query: &query,
        };
        let mut best: Option<Tried> = None;
        let hands = self.hands(input);
        for (k, &hand) in hands.iter().enumerate() {
            let tried = self.run_with(&with, hand);
            // The first hand that reaches while the eyes see will do,
            // unless the target is on the other hand's side of the body:
            // the other is tried only then or where the first does not (a
            // solve with the eyes costs several reaches, and trying the
            // other hand for comfort everywhere tripled a kitchen's work).
            let pose = tried.alone.pose;
            let effectors = &input.person.body.effectors;
            let twin_side = (hands.get(k + 1)).is_some_and(|&twin| {
                hand::on_side_of(&effectors[twin].name, &pose, &target.position_mm)
            });
            let done = tried.report.ok && !twin_side;
            best = Some(match best {
                Some(kept) if !better(&tried.report, &kept.report, (&pose, target)) => kept,
                _ => tried,
            });
            if done {
                break;
            }
        }
        let Tried {
            mut report,
            hand,
            alone,
        } = best.expect("a reach and gaze has at least one hand");
        // Why, for the hand answered with only (finding why searches again).
        if !report.reach.ok {
            let chain = input.person.body.chain(hand);
            report.reach.why = self.why_not(input, &chain, &alone, &query, obstacles.body.as_ref());
        }
        TaskReport::ReachAndGaze(Box::new(report))
    }
}

/// A reach and gaze with one hand: its report (without why), the hand, and
/// where the hand alone came (searched as a reach).
struct Tried {
    report: ReachAndGazeReport,
    hand: usize,
    alone: Placement,
}

/// Whether `a` is a better answer than `b`, the target's side seen from
/// `a`'s placement (`pose`): hand and eyes both do where in `b` they do
/// not; both doing, with the hand on the target's side where it is well
/// to one side, else the more comfortable hand; neither, the hand reaches
/// where in `b` it does not, else comes closer.
fn better(
    a: &ReachAndGazeReport,
    b: &ReachAndGazeReport,
    (pose, target): (&BasePose, &Target),
) -> bool {
    let on_its_side =
        |r: &ReachAndGazeReport| hand::on_side_of(&r.reach.effector, pose, &target.position_mm);
    match (a.ok, b.ok) {
        (true, false) => true,
        (false, true) => false,
        (true, true) => hand::rather(
            (on_its_side(a), a.reach.comfort),
            (on_its_side(b), b.reach.comfort),
        ),
        (false, false) => match (a.reach.ok, b.reach.ok) {
            (true, false) => true,
            (false, true) => false,
            _ => a.reach.distance_mm < b.reach.distance_mm,
        },
    }
}

/// What a reach and gaze with each hand shares: the task's input and
/// target, the body with its look range, the eyes and the obstacles.
struct With<'w, 'a> {
    input: &'w TaskInput<'a>,
    target: &'w Target,
    body: &'w Body,
    eyes_index: usize,
    eyes: &'w Eyes,
    obstacles: &'w GazeObstacles<'a>,
    /// The hand's reach, searched as a `reach` searches it.
    query: &'w ReachQuery<'w>,
}

impl ReachAndGazeTask {
    /// The hands (effector indices) this reach and gaze tries: the one
    /// asked for, and for `either` its twin.
    fn hands(&self, input: &TaskInput<'_>) -> Vec<usize> {
        let asked = input.effectors.first().copied().unwrap_or(0);
        hands_of(&input.person.body, asked, self.either)
    }

    /// The reach and gaze with effector `hand`: the base placed for the
    /// hand, then hand and eyes solved together.
    fn run_with(&self, with: &With<'_, '_>, hand: usize) -> Tried {
        let reaching = &self.reaching;
        let With {
            input,
            target,
            body,
            eyes_index,
            eyes,
            obstacles,
            query,
        } = *with;
        let hand_chain = input.person.body.chain(hand);
        // Not walked in (`walk_in.rs`): searched with the eyes' chain, a
        // seated person's reach and gaze at a shelf took 160 M units, and
        // walked in 830 M, past the bound on solver work.
        let prepared = input.base.prepare(input.room, &hand_chain, input.allowance);
        let alone = prepared.reach(query, reaching.solver.as_ref());
        let solving = Solving {
            task: self,
            input,
            body,
            hand,
            eyes_index,
            eyes,
            obstacles,
            query,
            target,
        };
        // Where the hand alone reaches, first the eyes with the hand held
        // in the reach's own posture (the most comfortable it found: the
        // person reaches as they would and turns the head to look), then
        // hand and eyes together by the tree, which may bend the trunk
        // where the head cannot see from there; then the tree from other
        // starts and with the base moved, before the answer is no.
        let hand_reaches = alone.solution.reaches(reaching.common.tolerance_mm);
        let held = hand_reaches
            .then(|| solving.eyes_after_hand(alone.pose, &alone.solution.q, query.seed))
            .filter(Seen::ok)
            .or_else(|| {
                let looked = hand_reaches.then(|| solving.hand_after_eyes(alone.pose, query.seed));
                looked.filter(Seen::ok)
            });
        let mut seen = held.unwrap_or_else(|| solving.attempt(alone.pose, query.seed));
        if !seen.ok() && hand_reaches {
            let poses = again_from(alone.pose, target.position_mm, prepared.as_ref());
            let tries = poses.into_iter().enumerate().map(|(k, pose)| {
                solving.attempt(pose, mix_seed(query.seed, &format!("reach+gaze again {k}")))
            });
            if let Some(found) = tries.into_iter().find(Seen::ok) {
                seen = found;
            }
        }
        let Seen { reach, gaze } = seen;
        let report = ReachAndGazeReport {
            name: target.name.clone(),
            person: input.person.name.clone(),
            ok: reach.ok && gaze.ok,
            reach,
            gaze,
        };
        Tried {
            report,
            hand,
            alone,
        }
    }
}

/// How many more times the tree is solved from the hand's placement, from
/// other starts, where the hand alone reaches but the first solve did not
/// see it there.
const TREE_TRIES: usize = 4;
/// Then from the placement moved along the floor by these distances, in
/// eight directions (away from the target first).
const MOVED_MM: [f64; 2] = [100.0, 200.0];

/// The placements a reach and gaze is solved again from: `pose` (the
/// hand's) [`TREE_TRIES`] times, then `pose` moved by each of
/// [`MOVED_MM`] away from the target, to its sides, then the other
/// directions, where the base may stand and reach from.
fn again_from(pose: BasePose, target_mm: Point3<f64>, base: &dyn PreparedBase) -> Vec<BasePose> {
    let away = (pose.position_mm - target_mm).xy();
    let away = if away.norm() > 1e-9 {
        away.normalize()
    } else {
        Vector2::x()
    };
    let turned = |deg: f64| nalgebra::Rotation2::new(deg.to_radians()) * away;
    let directions = [0.0, 90.0, -90.0, 45.0, -45.0, 135.0, -135.0, 180.0].map(turned);
    let moved = MOVED_MM
        .iter()
        .flat_map(|&d| directions.iter().map(move |u| u * d));
    let moved = moved
        .filter_map(|by| base.moved(&pose, by))
        .filter(|p| base.admits(p, &target_mm));
    std::iter::repeat_n(pose, TREE_TRIES).chain(moved).collect()
}

/// What one tree solve needs: the task, its person's body with the look
/// link kept to the legible range, the effectors, the eyes and the
/// obstacles.
struct Solving<'s, 'a> {
    task: &'s ReachAndGazeTask,
    input: &'s TaskInput<'a>,
    body: &'s Body,
    hand: usize,
    eyes_index: usize,
    eyes: &'s Eyes,
    obstacles: &'s GazeObstacles<'a>,
    query: &'s ReachQuery<'s>,
    target: &'s Target,
}

/// One tree solve's answer: the hand's and the eyes' reports.
struct Seen {
    reach: ReachReport,
    gaze: GazeReport,
}

impl Seen {
    fn ok(&self) -> bool {
        self.reach.ok && self.gaze.ok
    }
}

impl Solving<'_, '_> {
    /// Hand and eyes solved together by the tree from the base at `pose`,
    /// its starts drawn from `seed`, and what the posture reaches and sees.
    fn attempt(&self, pose: BasePose, seed: u64) -> Seen {
        let goals = [
            self.goal(self.hand, pose, 1.0),
            self.goal(self.eyes_index, pose, self.task.gaze_weight),
        ];
        let tree = self.solve(self.body, &goals, pose, seed);
        self.judge(pose, &tree)
    }

    /// The hand kept where the hand alone reached (`hand_q`, a value for
    /// each joint of its chain) and only the eyes solved, every joint on
    /// the hand's path held: where the hand's own posture leaves the head
    /// free to look.
    fn eyes_after_hand(&self, pose: BasePose, hand_q: &[f64], seed: u64) -> Seen {
        self.held_then(pose, (self.hand, hand_q), self.eyes_index, seed)
    }

    /// The eyes solved alone first (the most comfortable look the tree
    /// finds), then the hand with every joint on the eyes' path held
    /// there: where the hand's own posture brings the eyes inside the near
    /// point (the thing held too close to read), the person stands as
    /// they look and reaches with the arm.
    fn hand_after_eyes(&self, pose: BasePose, seed: u64) -> Seen {
        let eyes_chain = self.body.chain(self.eyes_index);
        let problem = self.query.problem(&eyes_chain, pose);
        let look = self.task.reaching.solver.solve(&problem);
        self.held_then(pose, (self.eyes_index, &look.q), self.hand, seed)
    }

    /// The joints on `held`'s effector's path kept at its values (one per
    /// joint of its path), and `free`'s effector solved alone by the tree.
    fn held_then(&self, pose: BasePose, held: (usize, &[f64]), free: usize, seed: u64) -> Seen {
        let (held_effector, values) = held;
        let mut body = self.body.clone();
        let path = body.path(body.effectors[held_effector].joint);
        for (&j, &value) in path.iter().zip(values) {
            let joint = &mut body.joints[j];
            (joint.min, joint.max, joint.neutral) = (value, value, value);
        }
        // The held values keep the couplings (the posture they come from did).
        body.couplings
            .retain(|c| !c.joints().iter().any(|j| path.contains(j)));
        let goals = [self.goal(free, pose, 1.0)];
        let mut tree = self.solve(&body, &goals, pose, seed);
        for (&j, &value) in path.iter().zip(values) {
            tree.q[j] = value;
        }
        self.judge(pose, &tree)
    }

    /// The goal of `effector`: the target, in the base frame at `pose`.
    fn goal(&self, effector: usize, pose: BasePose, weight: f64) -> TreeGoal {
        TreeGoal {
            effector,
            target_mm: pose.to_base(&self.target.position_mm),
            weight,
        }
    }

    /// `body`'s tree solve for `goals` from the base at `pose`.
    fn solve(&self, body: &Body, goals: &[TreeGoal], pose: BasePose, seed: u64) -> TreeSolution {
        let own = self.input.base.own_body();
        let seed = seed_in_base_frame(seed, &pose.to_base(&self.target.position_mm));
        solve_tree(
            &self.task.tree.unwrap_or_else(FabrikSettings::with_defaults),
            &TreeProblem {
                body,
                goals,
                tolerance_mm: self.task.reaching.common.tolerance_mm,
                seed,
                obstacles: self.obstacles.body.as_ref().map(|o| PlacedObstacles {
                    obstacles: o,
                    own,
                    base_pose: pose,
                }),
                allowance: self.input.allowance,
            },
        )
    }

    /// What the posture `tree` reaches and sees from the base at `pose`.
    fn judge(&self, pose: BasePose, tree: &TreeSolution) -> Seen {
        let reaching = &self.task.reaching;
        let target = self.target;
        let own = self.input.base.own_body();
        let asked = |chain| Asked {
            subject: &target.name,
            person: self.input.person,
            chain,
            solver: &reaching.common.solver.name,
            tolerance_mm: reaching.common.tolerance_mm,
            room: self.input.room,
            own,
        };
        let body = self.body;
        // The head and neck where the eyes' joints turned them.
        let hand_chain = body.chain_posed(self.hand, &tree.q);
        let mut hand_placement =
            placed(body, self.hand, &hand_chain, tree, pose, target.position_mm);
        hand_placement.solution.collision = self
            .query
            .problem(&hand_chain, pose)
            .collision(&hand_placement.solution.q);
        let reach = ReachReport::new(&asked(&hand_chain), &hand_placement, target.position_mm);
        let eyes_chain = body.chain(self.eyes_index);
        let eyes_placement = placed(
            body,
            self.eyes_index,
            &eyes_chain,
            tree,
            pose,
            target.position_mm,
        );
        let looked = Looked {
            chain: &eyes_chain,
            placement: &eyes_placement,
            target: target.position_mm,
        };
        let sight = looked.see(self.obstacles, reaching.common.tolerance_mm, self.eyes);
        let gaze = GazeReport::new(
            &asked(&eyes_chain),
            &eyes_placement,
            target.position_mm,
            sight,
        );
        Seen { reach, gaze }
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
/// and the index of the eyes' effector.
fn body_with_look_range(input: &TaskInput<'_>, legible_mm: [f64; 2]) -> (Body, usize) {
    let mut body = input.person.body.clone();
    let eyes = input.effectors.get(1).copied().unwrap_or(0);
    if let Some(look) = body.effectors[eyes].joint {
        limit_look(&mut body.joints[look], legible_mm);
    }
    (body, eyes)
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
