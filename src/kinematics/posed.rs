//! A chain in one posture, kept so that the solids of the posture with one
//! joint moved cost only what that joint moves: the frames and volumes
//! before the joint are kept, those after it made again, and each volume
//! says how it moved ([`Motion`]), so that a check of a posture known to
//! be clear need look only at what moved (a descent that checks each move
//! it makes).

use nalgebra::IsometryMatrix3;

use super::chain::Chain;
use super::volumes::{Volumes, Walk};

/// A chain in one posture, and a scratch posture with one joint moved.
pub struct Posed<'c> {
    chain: &'c Chain,
    locals: Vec<IsometryMatrix3<f64>>,
    walk: Walk,
    current: Volumes,
    /// The last posture tried: which joint moved to what, and its solids.
    trial: Option<(usize, f64)>,
    trial_local: IsometryMatrix3<f64>,
    trial_walk: Walk,
    trial_volumes: Volumes,
}

impl<'c> Posed<'c> {
    pub fn new(chain: &'c Chain, q: &[f64]) -> Self {
        let locals: Vec<IsometryMatrix3<f64>> = chain
            .joints
            .iter()
            .zip(q)
            .map(|(j, &qj)| j.transform(qj))
            .collect();
        let mut walk = Walk::new(chain.joints.len());
        let mut current = Volumes::default();
        chain.walk(&locals, &mut walk, 0, &mut current, None);
        Posed {
            chain,
            locals,
            trial_walk: walk.clone(),
            walk,
            trial_volumes: current.clone(),
            current,
            trial: None,
            trial_local: IsometryMatrix3::identity(),
        }
    }

    /// Joint `i` moved to `value`.
    pub fn set(&mut self, i: usize, value: f64) {
        if self.trial == Some((i, value)) {
            // The posture last tried: its solids are made, and its walk is
            // whole (the prefix copied, the rest walked).
            self.locals[i] = self.trial_local;
            std::mem::swap(&mut self.walk, &mut self.trial_walk);
            std::mem::swap(&mut self.current, &mut self.trial_volumes);
            self.current.all_moved();
            self.trial = None;
            return;
        }
        self.locals[i] = self.chain.joints[i].transform(value);
        let pushed = self.walk.marks[i].pushed;
        self.current.truncate(pushed);
        self.chain
            .walk(&self.locals, &mut self.walk, i, &mut self.current, None);
        self.trial = None;
    }

    /// The solids with joint `i` at `value`, the others as they are; each
    /// says how it moved from the posture as it is.
    pub fn volumes_with(&mut self, i: usize, value: f64) -> &Volumes {
        self.trial_local = self.chain.joints[i].transform(value);
        let local = std::mem::replace(&mut self.locals[i], self.trial_local);
        self.trial_walk.copy_prefix(&self.walk, i);
        let pushed = self.walk.marks[i].pushed;
        self.trial_volumes.copy_still(&self.current, pushed);
        self.chain.walk(
            &self.locals,
            &mut self.trial_walk,
            i,
            &mut self.trial_volumes,
            Some(i),
        );
        self.locals[i] = local;
        self.trial = Some((i, value));
        &self.trial_volumes
    }

    /// The solids as they are, every one to be checked.
    pub fn volumes(&self) -> &Volumes {
        &self.current
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kinematics::volumes::Motion;
    use crate::kinematics::{Joint, Link, Rider};
    use nalgebra::Vector3;
    use rand_chacha::rand_core::{Rng, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    /// A number in [lo, hi).
    fn uniform(rng: &mut ChaCha8Rng, lo: f64, hi: f64) -> f64 {
        lo + (rng.next_u64() >> 11) as f64 / (1u64 << 53) as f64 * (hi - lo)
    }

    /// A 3-D arm with links of zero length between some joints (as a
    /// shoulder's three), a sphere on joint 1 and one on the base.
    fn arm() -> Chain {
        use crate::kinematics::chain::revolute;
        let joint = |name: &str, alpha: f64, a_mm| Joint {
            link: Link {
                name: name.into(),
                radius_mm: 10.0,
            },
            ..revolute(name, 0.0, 0.0, alpha, a_mm)
        };
        let half_pi = std::f64::consts::FRAC_PI_2;
        let mut chain = Chain::new(
            vec![
                joint("a", half_pi, 100.0),
                joint("s1", half_pi, 0.0),
                joint("s2", -half_pi, 0.0),
                joint("b", 0.0, 200.0),
                joint("c", half_pi, 150.0),
                joint("d", 0.0, 80.0),
            ],
            "tip",
            Vector3::new(30.0, 0.0, 0.0),
        );
        for (anchor, z) in [(Some(1), 40.0), (None, 60.0), (Some(4), 10.0)] {
            chain.riders.push(Rider::sphere(
                "ball",
                anchor,
                Vector3::new(0.0, 0.0, z),
                20.0,
            ));
        }
        chain
    }

    /// After any sequence of tried and made moves, the solids with a joint
    /// moved are those made from scratch, a still volume is where it was,
    /// and two rigid volumes keep their distance.
    #[test]
    fn moved_solids_equal_solids_made_from_scratch() {
        let chain = arm();
        let mut rng = ChaCha8Rng::seed_from_u64(7);
        let mut q: Vec<f64> = (0..6).map(|_| uniform(&mut rng, -2.0, 2.0)).collect();
        let mut posed = Posed::new(&chain, &q);
        for step in 0..400 {
            let i = (rng.next_u64() % 6) as usize;
            let value = uniform(&mut rng, -2.0, 2.0);
            let before = posed.volumes().clone();
            let tried = posed.volumes_with(i, value).clone();
            let mut moved_q = q.clone();
            moved_q[i] = value;
            let fresh = chain.volumes(&moved_q);
            assert_eq!(tried.owners, fresh.owners, "step {step} joint {i}");
            for (k, (t, f)) in tried.capsules.iter().zip(&fresh.capsules).enumerate() {
                assert!((t.a - f.a).norm() < 1e-9 && (t.b - f.b).norm() < 1e-9);
                if tried.motion[k] == Motion::Still {
                    assert_eq!(t.a, before.capsules[k].a, "volume {k} moved");
                    assert_eq!(t.b, before.capsules[k].b, "volume {k} moved");
                }
            }
            let rigid: Vec<usize> = (0..tried.motion.len())
                .filter(|&k| tried.motion[k] == Motion::Rigid)
                .collect();
            for &m in &rigid {
                for &n in &rigid {
                    let d = |v: &Volumes| (v.capsules[m].a - v.capsules[n].b).norm();
                    assert!((d(&tried) - d(&before)).abs() < 1e-9);
                }
            }
            // Make the move tried, or another.
            match step % 3 {
                0 => {
                    posed.set(i, value);
                    q = moved_q;
                }
                1 => {
                    let other = (rng.next_u64() % 6) as usize;
                    let v = uniform(&mut rng, -2.0, 2.0);
                    posed.set(other, v);
                    q[other] = v;
                }
                _ => {}
            }
            let now = posed.volumes();
            let fresh = chain.volumes(&q);
            assert!(now.motion.iter().all(|m| *m == Motion::Moved));
            for (t, f) in now.capsules.iter().zip(&fresh.capsules) {
                assert!((t.a - f.a).norm() < 1e-9 && (t.b - f.b).norm() < 1e-9);
            }
        }
    }
}
