//! Starting postures for the solvers: the neutral posture, then postures
//! drawn uniformly within the joint limits from a seeded generator whose
//! stream does not change between versions of the crate. A left hand's
//! chain drawn as its twin's mirror image (`Chain::mirror_of_twin`) draws
//! the mirror image of what the twin draws.

use rand_chacha::rand_core::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

use crate::kinematics::{Chain, Coupling};
use crate::options::Params;

/// The option `neutral_start`, which every solver that draws starts has.
pub fn neutral_start(p: &mut Params<'_>) -> bool {
    p.boolean(
        "neutral_start",
        true,
        "the first start is the neutral posture, the others random",
    )
    .get()
}

/// A posture drawn at random within the joint limits: each joint uniformly
/// within its limits, and a coupled joint within what the joints coupled
/// to it, drawn before it, leave it (those after it at their centres). A
/// rhythm's follower (the shoulder girdle) is drawn after its drivers, so
/// that it rises in the starts where the arm is raised.
pub fn random_posture(chain: &Chain, rng: &mut ChaCha8Rng) -> Vec<f64> {
    let mut q: Vec<f64> = chain
        .joints
        .iter()
        .map(|j| 0.0_f64.clamp(j.min, j.max))
        .collect();
    for i in drawing_order(chain) {
        let (lo, hi) = chain.interval(i, &q);
        let u = unit_interval(rng);
        // Drawn negated (`Chain::mirror_of_twin`): the negation of the
        // twin's draw `-hi + u (hi - lo)` from its interval `(-hi, -lo)`.
        q[i] = if chain.drawn_negated(i) {
            hi - u * (hi - lo)
        } else {
            lo + u * (hi - lo)
        };
    }
    q
}

/// A kick of joint `i` of `chain` by up to `fraction` of its range, from
/// draw `u` in [0, 1): negated for a joint drawn negated, so that a
/// mirrored chain is kicked as its twin is, in the mirror.
pub(crate) fn kick_by(chain: &Chain, i: usize, u: f64, fraction: f64) -> f64 {
    let kick = (2.0 * u - 1.0) * fraction * chain.joints[i].range();
    if chain.drawn_negated(i) {
        -kick
    } else {
        kick
    }
}

/// The rhythms' followers of `chain` (the shoulder girdles), in the
/// order of its couplings. (Asked for each posture drawn, 8,192 a
/// capability map: nothing is allocated.)
fn followers(chain: &Chain) -> impl Iterator<Item = usize> + '_ {
    chain.couplings.iter().filter_map(|c| match c {
        Coupling::Rhythm(r) => Some(r.follower),
        Coupling::Ellipse(_) => None,
    })
}

/// The joints in the order they are drawn: the chain's, the rhythms'
/// followers last.
fn drawing_order(chain: &Chain) -> impl Iterator<Item = usize> + '_ {
    let leaders = (0..chain.dof()).filter(|&i| !followers(chain).any(|f| f == i));
    leaders.chain(followers(chain))
}

/// The starting postures of one solve, in order: the neutral posture first
/// if `neutral_first`, then random ones from `seed`.
pub struct Starts<'a> {
    chain: &'a Chain,
    rng: ChaCha8Rng,
    neutral_first: bool,
    given: u32,
}

impl<'a> Starts<'a> {
    pub fn new(chain: &'a Chain, seed: u64, neutral_first: bool) -> Self {
        Starts {
            chain,
            rng: ChaCha8Rng::seed_from_u64(seed),
            neutral_first,
            given: 0,
        }
    }
}

impl Iterator for Starts<'_> {
    type Item = Vec<f64>;

    fn next(&mut self) -> Option<Vec<f64>> {
        let first = self.given == 0;
        self.given += 1;
        Some(if first && self.neutral_first {
            self.chain.neutral()
        } else {
            random_posture(self.chain, &mut self.rng)
        })
    }
}

/// Starts near a posture that reached its target through something: the
/// posture with each joint moved by up to `spread` of its range (clamped
/// to its limits), and every fourth start drawn uniformly, so that a
/// posture on the far side of the obstacle can still be found.
pub struct Kicks<'a> {
    chain: &'a Chain,
    around: &'a [f64],
    spread: f64,
    rng: ChaCha8Rng,
    given: u32,
}

impl<'a> Kicks<'a> {
    pub fn new(chain: &'a Chain, around: &'a [f64], spread: f64, seed: u64) -> Self {
        Kicks {
            chain,
            around,
            spread,
            rng: ChaCha8Rng::seed_from_u64(seed),
            given: 0,
        }
    }
}

impl Iterator for Kicks<'_> {
    type Item = Vec<f64>;

    fn next(&mut self) -> Option<Vec<f64>> {
        self.given += 1;
        if self.given.is_multiple_of(4) {
            return Some(random_posture(self.chain, &mut self.rng));
        }
        // The followers kicked last, from their lower limits meanwhile, so
        // that a raised girdle does not keep the arm from being kicked down.
        let mut kicked = self.around.to_vec();
        for f in followers(self.chain) {
            kicked[f] = self.chain.joints[f].min;
        }
        for i in drawing_order(self.chain) {
            let kick = kick_by(self.chain, i, unit_interval(&mut self.rng), self.spread);
            kicked[i] = self.chain.clamp_joint(i, self.around[i] + kick, &kicked);
        }
        Some(kicked)
    }
}

/// A uniform draw from [0, 1) with 53 random bits.
pub(crate) fn unit_interval(rng: &mut ChaCha8Rng) -> f64 {
    (rng.next_u64() >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
}
