//! FABRIK on a tree: several effectors of one body (a hand and the eyes)
//! with a target each, sharing the joints of their common root (the
//! spine). After Aristidou and Lasenby's multiple end effectors: each
//! effector's chain makes its backward pass from its target to the
//! sub-base (the end of the shared bones); the sub-base's goal is the
//! average of theirs, weighted by each effector's priority; from there
//! the backward pass goes on to the base. The forward pass turns the
//! shared groups towards those goals, then each branch its own.

use nalgebra::Point3;
use rand_chacha::rand_core::SeedableRng;
use rand_chacha::ChaCha8Rng;

use super::bones::{bones, Bone};
use super::pass::{kick, Pass};
use super::stall::{Next, Stalls};
use super::FabrikSettings;
use crate::collision::PlacedObstacles;
use crate::kinematics::{Body, Chain};
use crate::plugin::{Allowance, IkProblem, Tally};
use crate::solvers::starts::Starts;

/// One effector's target and priority.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TreeGoal {
    /// Index into the body's effectors.
    pub effector: usize,
    /// In the body's base frame.
    pub target_mm: Point3<f64>,
    /// Its weight in the sub-base's goal: the larger, the more the shared
    /// joints serve this effector.
    pub weight: f64,
}

/// A tree problem: the body, its goals, and what a chain problem has.
#[derive(Clone, Copy)]
pub struct TreeProblem<'a> {
    pub body: &'a Body,
    pub goals: &'a [TreeGoal],
    pub tolerance_mm: f64,
    pub seed: u64,
    pub obstacles: Option<PlacedObstacles<'a>>,
    /// What the solve's work is told to (`IkProblem::allowance`).
    pub allowance: &'a dyn Allowance,
}

/// The posture found, in the body's joint order, and each goal's distance.
#[derive(Clone, Debug, PartialEq)]
pub struct TreeSolution {
    pub q: Vec<f64>,
    pub distances_mm: Vec<f64>,
    pub iterations: u64,
    /// The first thing a part of some branch runs into, when obstacles
    /// are checked.
    pub collision: Option<crate::scene::Collision>,
}

impl TreeSolution {
    /// Every effector within tolerance, and no link through an obstacle.
    pub fn reaches(&self, tolerance_mm: f64) -> bool {
        self.distances_mm.iter().all(|&d| d <= tolerance_mm) && self.collision.is_none()
    }

    /// Whether this posture is preferred to `kept`: one that reaches every
    /// goal before one that does not; of two that do, the more comfortable
    /// (`discomfort`, of the joints the goals move), as a chain's solve
    /// prefers; of two that do not, the smaller weighted distance.
    fn preferred_to(
        &self,
        discomfort: f64,
        kept: &TreeSolution,
        kept_discomfort: f64,
        goals: &[TreeGoal],
        tolerance_mm: f64,
    ) -> bool {
        match (self.reaches(tolerance_mm), kept.reaches(tolerance_mm)) {
            (true, false) => true,
            (false, true) => false,
            (true, true) => discomfort < kept_discomfort,
            (false, false) => self.weighted_mm(goals) < kept.weighted_mm(goals),
        }
    }

    /// Within one start's run: reaching first, then the weighted distance.
    fn score(&self, goals: &[TreeGoal], tolerance_mm: f64) -> (bool, f64) {
        (self.reaches(tolerance_mm), -self.weighted_mm(goals))
    }

    fn weighted_mm(&self, goals: &[TreeGoal]) -> f64 {
        goals
            .iter()
            .zip(&self.distances_mm)
            .map(|(g, d)| g.weight * d)
            .sum()
    }
}

/// One effector's chain, as the chain solver sees it.
struct Branch {
    chain: Chain,
    /// Body index of each chain joint.
    path: Vec<usize>,
    bones: Vec<Bone>,
}

/// Solve from the settings' starts; the best posture (all reaching, then
/// the most comfortable; else the least weighted distance) is kept.
pub fn solve_tree(settings: &FabrikSettings, problem: &TreeProblem<'_>) -> TreeSolution {
    let body = problem.body;
    let paths: Vec<Vec<usize>> = problem
        .goals
        .iter()
        .map(|g| body.path(body.effectors[g.effector].joint))
        .collect();
    let branches: Vec<Branch> = problem
        .goals
        .iter()
        .zip(&paths)
        .enumerate()
        .map(|(b, (g, path))| {
            let mut chain = body.chain(g.effector);
            // A solid another branch moves (the head, which the eyes'
            // branch turns) is that branch's to check, where it is: this
            // one would carry it at neutral.
            let others = |j: usize| (0..paths.len()).any(|o| o != b && paths[o].contains(&j));
            chain.riders = body
                .riders_on(path)
                .into_iter()
                .filter(|(on, _)| !on.is_some_and(others))
                .map(|(_, rider)| rider)
                .collect();
            Branch {
                path: path.clone(),
                bones: bones(&chain),
                chain,
            }
        })
        .collect();
    let chain_problems: Vec<IkProblem<'_>> = branches
        .iter()
        .zip(problem.goals)
        .map(|(b, g)| IkProblem {
            chain: &b.chain,
            target_mm: g.target_mm,
            tolerance_mm: problem.tolerance_mm,
            seed: problem.seed,
            obstacles: problem.obstacles,
            allowance: problem.allowance,
        })
        .collect();
    let shared = shared_bones(&branches);
    // Only the joints on the goals' paths move (an arm no goal needs stays
    // at its neutral posture and draws nothing from the random streams).
    let effectors: Vec<usize> = problem.goals.iter().map(|g| g.effector).collect();
    let used = Used::new(problem.body, &effectors);
    let mut rng = ChaCha8Rng::seed_from_u64(problem.seed ^ 0x7472_6565);
    let mut best: Option<(TreeSolution, f64)> = None;
    let mut iterations = 0;
    let starts = Starts::new(&used.chain, problem.seed, settings.neutral_start);
    for start in starts.take(settings.starts as usize) {
        let start = used.scatter(
            problem.body.joints.iter().map(|j| j.neutral).collect(),
            &start,
        );
        let mut tree = Tree {
            settings,
            problem,
            branches: &branches,
            passes: branches
                .iter()
                .zip(&chain_problems)
                .map(|(b, p)| {
                    Pass::new(
                        settings,
                        p,
                        &b.bones,
                        b.path.iter().map(|&j| start[j]).collect(),
                    )
                })
                .collect(),
            q: start,
            shared,
        };
        let solution = tree.run(&used, &mut rng);
        iterations += solution.iterations;
        let discomfort = used.chain.discomfort(&used.gather(&solution.q));
        let better = best.as_ref().is_none_or(|(kept, kept_discomfort)| {
            solution.preferred_to(
                discomfort,
                kept,
                *kept_discomfort,
                problem.goals,
                problem.tolerance_mm,
            )
        });
        if better {
            best = Some((solution, discomfort));
        }
    }
    let (mut solution, _) = best.expect("at least one start");
    solution.iterations = iterations;
    solution
}

/// How many leading bones every branch has in common (same body joints).
fn shared_bones(branches: &[Branch]) -> usize {
    let first = &branches[0];
    let same = |k: usize, b: &Branch| {
        b.bones.get(k).is_some_and(|bone| {
            let mine = &first.bones[k];
            bone.end == mine.end
                && bone.joints == mine.joints
                && b.path.get(..depends_on(bone)) == first.path.get(..depends_on(mine))
        })
    };
    (0..first.bones.len())
        .take_while(|&k| branches.iter().all(|b| same(k, b)))
        .count()
}

/// How many chain joints, from the root, a bone's end depends on.
fn depends_on(bone: &Bone) -> usize {
    match bone.end {
        super::bones::End::Frame(j) => (j + 1).max(bone.joints.end),
        super::bones::End::Effector => bone.joints.end,
    }
}

/// The body's joints that lie on some goal's path, in body order, and
/// their chain (for drawing starts and kicks).
struct Used {
    joints: Vec<usize>,
    chain: Chain,
}

impl Used {
    fn new(body: &Body, effectors: &[usize]) -> Self {
        let joints = body.joints_to(effectors);
        let mut chain = Chain::new(
            joints.iter().map(|&j| body.joints[j].clone()).collect(),
            "",
            nalgebra::Vector3::zeros(),
        );
        chain.couplings = body.couplings_on(&joints);
        Used { joints, chain }
    }

    /// The used joints' values of body posture `q`.
    fn gather(&self, q: &[f64]) -> Vec<f64> {
        self.joints.iter().map(|&j| q[j]).collect()
    }

    /// Body posture `q` with the used joints set to `values`.
    fn scatter(&self, mut q: Vec<f64>, values: &[f64]) -> Vec<f64> {
        for (&j, &v) in self.joints.iter().zip(values) {
            q[j] = v;
        }
        q
    }
}

/// The state of one start.
struct Tree<'a> {
    settings: &'a FabrikSettings,
    problem: &'a TreeProblem<'a>,
    branches: &'a [Branch],
    passes: Vec<Pass<'a>>,
    /// The body's posture.
    q: Vec<f64>,
    shared: usize,
}

impl Tree<'_> {
    fn run(&mut self, used: &Used, rng: &mut ChaCha8Rng) -> TreeSolution {
        let s = self.settings;
        let mut best = self.solution(0);
        let mut stalls = Stalls::new();
        let mut iterations = 0;
        let mut tally = Tally::new(self.problem.allowance);
        // Each look at the posture checks every branch.
        let checks = (self.problem.obstacles)
            .filter(|_| s.avoid_obstacles)
            .map_or(0, |o| {
                (self.passes.iter())
                    .map(|p| o.check_units(p.problem.chain))
                    .sum::<u64>()
            });
        while iterations < s.max_iterations {
            let work: u64 = self
                .passes
                .iter_mut()
                .map(|p| std::mem::take(&mut p.work))
                .sum();
            if !tally.add(work + checks) {
                break;
            }
            let now = self.solution(iterations);
            let (reaches, score) = now.score(self.problem.goals, self.problem.tolerance_mm);
            let near = now
                .distances_mm
                .iter()
                .all(|&d| d <= self.problem.tolerance_mm);
            if (reaches, score) > best.score(self.problem.goals, self.problem.tolerance_mm) {
                best = now;
            }
            if reaches {
                break;
            }
            match stalls.next(s, -score, near) {
                Next::Stop => break,
                Next::Kick => {
                    let mut values = used.gather(&self.q);
                    kick(&mut values, &used.chain, s.kick, rng);
                    self.q = used.scatter(std::mem::take(&mut self.q), &values);
                    self.load();
                }
                Next::Pass => {
                    self.iterate();
                    iterations += 1;
                }
            }
        }
        best.iterations = u64::from(iterations);
        best
    }

    /// One backward and forward pass over the whole tree.
    fn iterate(&mut self) {
        let avoiding = self.settings.avoid_obstacles && self.problem.obstacles.is_some();
        let k = self.shared;
        let mut sum = nalgebra::Vector3::zeros();
        let mut weights = 0.0;
        for (pass, goal) in self.passes.iter_mut().zip(self.problem.goals) {
            pass.backward_from(pass.bones.len(), goal.target_mm);
            sum += pass.goals[k].coords * goal.weight;
            weights += goal.weight;
        }
        let sub_base = Point3::from(sum / weights.max(1e-12));
        let (first, rest) = self.passes.split_first_mut().expect("at least one goal");
        first.backward_from(k, sub_base);
        first.forward_bones(0..k, true, avoiding);
        let shared_joints = if k == 0 {
            0
        } else {
            first.bones[k - 1].joints.end
        };
        for pass in rest {
            pass.q[..shared_joints].copy_from_slice(&first.q[..shared_joints]);
        }
        for pass in &mut self.passes {
            let m = pass.bones.len();
            pass.forward_bones(k..m, true, avoiding);
            if self.settings.ccd {
                pass.ccd_sweep_from(k);
            }
        }
        self.store();
    }

    /// The body posture from the branches' postures.
    fn store(&mut self) {
        for (pass, branch) in self.passes.iter().zip(self.branches) {
            for (i, &j) in branch.path.iter().enumerate() {
                self.q[j] = pass.q[i];
            }
        }
    }

    /// The branches' postures from the body posture.
    fn load(&mut self) {
        for (pass, branch) in self.passes.iter_mut().zip(self.branches) {
            for (i, &j) in branch.path.iter().enumerate() {
                pass.q[i] = self.q[j];
            }
            pass.forward_with(false, false);
        }
    }

    fn solution(&self, iterations: u32) -> TreeSolution {
        let checking = self.settings.avoid_obstacles;
        TreeSolution {
            q: self.q.clone(),
            distances_mm: self.passes.iter().map(|p| p.effector_distance()).collect(),
            iterations: u64::from(iterations),
            collision: self
                .passes
                .iter()
                .filter(|_| checking)
                .find_map(|p| p.problem.collision(&p.q)),
        }
    }
}
