//! A person's capability map: where their hand can be, relative to the hip
//! point, and how comfortably. Postures drawn at random within the joint
//! limits, those that keep the arm out of the person's own body, legs and
//! base, are sorted into horizontal slices of the base frame by the height
//! of the effector, the most comfortable first in each slice. A mobile
//! base reads it backwards: for a target at height z above the hip, each
//! sample near that height, turned by a heading, says where the hip point
//! would put the hand on the target in a posture known to be free of the
//! body (the paper's target minus the admissible region, section 5.3.5,
//! made of samples).
//!
//! Whether a sample keeps the arm out of the body is worked out the first
//! time a search asks for a sample near its height, not when the map is
//! built: a reach looks at a few hundred of the 8,192, and a population of
//! a thousand people builds a thousand maps.
//!
//! Maps are kept in the memo of the run or the watch session, keyed by
//! everything they depend on (the chain and the person's own body), so watch
//! mode and the people of a scenario who share a body share one map.

use std::collections::HashMap;
use std::sync::{Arc, Mutex, OnceLock};

use nalgebra::{Vector2, Vector3};
use rand_chacha::rand_core::SeedableRng;
use rand_chacha::ChaCha8Rng;

use crate::kept::{Memo, Table};
use crate::kinematics::{Chain, Owner};
use crate::scene::OwnBody;
use crate::solvers::random_posture;

/// One posture of the map: where it puts the effector in the base frame,
/// its discomfort and where its joint values are kept
/// ([`Capability::q`]).
#[derive(Debug)]
pub struct Sample {
    pub effector_mm: Vector3<f64>,
    pub discomfort: f64,
    /// The first of its joint values in the map's `qs`.
    at: usize,
    /// Whether it keeps the arm out of the body, once asked.
    clear: OnceLock<bool>,
}

/// The samples by the effector's height above the hip point.
#[derive(Debug)]
pub struct Capability {
    /// The height of the bottom of slice 0.
    bottom_mm: f64,
    slices: Vec<Vec<Sample>>,
    /// Every sample's joint values, one after another.
    qs: Vec<f64>,
    /// What a sample is checked against: the chain and the person's own
    /// body and base.
    chain: Chain,
    own: OwnBody,
    /// Where the hand is on average over the chain's postures, relative to
    /// the hip point, seen from above: where a placement would rather have
    /// a target.
    pub centre_mm: Vector2<f64>,
    /// Where the hand is in the neutral posture, relative to the hip
    /// point: in front of the reaching shoulder.
    pub at_rest_mm: Vector2<f64>,
}

/// How many postures are drawn for one map.
const SAMPLES: usize = 8192;
/// The height of one slice.
const SLICE_MM: f64 = 20.0;

impl Capability {
    /// The map of `chain` for a person whose own body and base are `own`:
    /// `samples` postures drawn from a fixed seed.
    pub fn build(chain: &Chain, own: &OwnBody, samples: usize) -> Self {
        let mut rng = ChaCha8Rng::seed_from_u64(0xcafa_b1e5);
        let mut qs = Vec::with_capacity(samples * chain.dof());
        let kept: Vec<Sample> = (0..samples)
            .map(|_| {
                let q = random_posture(chain, &mut rng);
                let sample = Sample {
                    effector_mm: chain.effector(&q).coords,
                    discomfort: chain.discomfort(&q),
                    at: qs.len(),
                    clear: OnceLock::new(),
                };
                qs.extend(q);
                sample
            })
            .collect();
        let bottom_mm = kept
            .iter()
            .map(|s| s.effector_mm.z)
            .fold(f64::INFINITY, f64::min);
        let mut slices: Vec<Vec<Sample>> = Vec::new();
        for s in kept {
            let k = ((s.effector_mm.z - bottom_mm) / SLICE_MM) as usize;
            if slices.len() <= k {
                slices.resize_with(k + 1, Vec::new);
            }
            slices[k].push(s);
        }
        for slice in &mut slices {
            slice.sort_by(|a, b| a.discomfort.total_cmp(&b.discomfort));
        }
        let at_rest = chain.effector(&chain.neutral());
        Capability {
            bottom_mm,
            slices,
            qs,
            chain: chain.clone(),
            own: own.clone(),
            centre_mm: workspace_centre(chain),
            at_rest_mm: Vector2::new(at_rest.x, at_rest.y),
        }
    }

    /// What building the map of `chain` costs the meter: for each sample,
    /// a posture drawn within the couplings, its effector and its
    /// discomfort, and the sorting, a unit a joint and four more.
    pub fn build_work(chain: &Chain) -> u64 {
        SAMPLES as u64 * (4 + chain.dof() as u64)
    }

    /// The map of `chain` and `own`, built once for the run or watch
    /// session whose `memo` this is (two threads asking for it at once
    /// build it once).
    pub fn of(chain: &Chain, own: &OwnBody, memo: &Memo) -> Arc<Capability> {
        let maps = MAPS.get_or(memo, 0, Arc::default);
        let key = format!("{chain:?}{own:?}");
        let cell = {
            let mut maps = maps.lock().unwrap_or_else(|e| e.into_inner());
            let bytes = Capability::bytes(chain);
            if maps.built.len() >= MAPS_KEPT || maps.bytes + bytes > MAPS_KEPT_BYTES {
                *maps = Maps::default();
            }
            if !maps.built.contains_key(&key) {
                maps.bytes += bytes;
            }
            Arc::clone(maps.built.entry(key).or_default())
        };
        Arc::clone(cell.get_or_init(|| Arc::new(Capability::build(chain, own, SAMPLES))))
    }

    /// About the memory a map of `chain` takes: its samples and their
    /// joint values.
    fn bytes(chain: &Chain) -> usize {
        SAMPLES * (std::mem::size_of::<Sample>() + chain.dof() * std::mem::size_of::<f64>())
    }

    /// The samples whose effector is between `below_mm` under height
    /// `z_mm` and `above_mm` over it, the most comfortable first, whether
    /// or not they are clear of the body ([`Capability::clear`]).
    pub fn near_height(&self, z_mm: f64, below_mm: f64, above_mm: f64) -> Vec<&Sample> {
        let slice = |z: f64| ((z - self.bottom_mm) / SLICE_MM).floor();
        let first = slice(z_mm - below_mm).max(0.0) as usize;
        let last = slice(z_mm + above_mm);
        if last < 0.0 {
            return Vec::new();
        }
        let last = (last as usize).min(self.slices.len().saturating_sub(1));
        let mut near: Vec<&Sample> = self
            .slices
            .get(first..=last)
            .into_iter()
            .flatten()
            .flatten()
            .filter(|s| (-below_mm..=above_mm).contains(&(s.effector_mm.z - z_mm)))
            .collect();
        near.sort_by(|a, b| a.discomfort.total_cmp(&b.discomfort));
        near
    }

    /// The joint values of `sample`.
    pub fn q(&self, sample: &Sample) -> &[f64] {
        &self.qs[sample.at..sample.at + self.chain.dof()]
    }

    /// Whether `sample` keeps the arm out of the person's own body and
    /// base and out of itself (worked out once).
    pub fn clear(&self, sample: &Sample) -> bool {
        *sample
            .clear
            .get_or_init(|| clear_of_body(&self.chain, &self.own, self.q(sample)))
    }

    /// Whether at least `count` of `samples` are clear, looking no further
    /// than it must.
    pub fn clear_at_least(&self, samples: &[&Sample], count: usize) -> bool {
        samples.iter().filter(|s| self.clear(s)).take(count).count() == count
    }
}

/// The maps built, by what they depend on, each built once, and about the
/// memory they take.
#[derive(Default)]
struct Maps {
    built: HashMap<String, Arc<OnceLock<Arc<Capability>>>>,
    bytes: usize,
}

/// The maps a run or a watch session keeps, as one entry (key 0) of its
/// memo, bounded by their count and their memory together.
const MAPS: Table<Arc<Mutex<Maps>>> = Table::new("capability maps", 1);

/// How many maps a memo keeps before it starts again (about 1 MB
/// each): enough for the people of a scenario and their effectors; the
/// members of a population each have their own, used by one thread while
/// it runs that person's tasks.
const MAPS_KEPT: usize = 64;

/// The most memory the maps kept may take before the memo starts
/// again: a chain of 700 joints makes a map of 46 MB, and 64 of them
/// took 3 GB.
const MAPS_KEPT_BYTES: usize = 256 << 20;

/// Whether posture `q` keeps the chain out of the person's own body and
/// base and out of itself (the hand, which may rest on what it reaches, is
/// checked as the rest are: a sample is a start, not an answer).
fn clear_of_body(chain: &Chain, own: &OwnBody, q: &[f64]) -> bool {
    let v = chain.volumes(q);
    let end = Owner::Link(chain.joints.len());
    let into_own = v
        .capsules
        .iter()
        .zip(&v.owners)
        .any(|(c, &owner)| owner != end && own.hit(c).is_some());
    !into_own && v.self_hit().is_none()
}

/// Where the hand is on average over 64 postures drawn within the
/// chain's limits, seen from above.
fn workspace_centre(chain: &Chain) -> Vector2<f64> {
    let mut rng = ChaCha8Rng::seed_from_u64(0x5eed);
    let n = 64;
    let sum = (0..n).fold(Vector2::zeros(), |acc, _| {
        let p = chain.effector(&random_posture(chain, &mut rng));
        acc + Vector2::new(p.x, p.y)
    });
    sum / f64::from(n)
}
