//! Forward kinematics that follows one joint change at a time (section
//! 5.3.2 of the accessibility paper, eq. 6-8).
//!
//! Instead of the paper's inverse matrix (eq. 7-8), it caches, for the
//! current posture, the pose of every frame in the base (`prefix`) and the
//! effector in every frame (`suffix`). The effector with joint i moved is
//! then `prefix[i] * T_i(q_i') * suffix[i+1]`: one link transform and two
//! point transforms, whatever the chain's length. Changing a joint
//! invalidates the prefixes after it and the suffixes up to it; they are
//! recomputed lazily, so a sweep over the joints from the base outwards costs
//! one frame product per kept change and one point transform per joint to
//! refresh the suffixes.

use nalgebra::{IsometryMatrix3, Point3, Vector3};

use super::Chain;

/// A posture of `chain` with cached partial products.
pub struct IncrementalFk<'a> {
    chain: &'a Chain,
    q: Vec<f64>,
    /// `prefix[k]`: the pose of frame k (after k joints) in the base frame.
    prefix: Vec<IsometryMatrix3<f64>>,
    /// `suffix[k]`: the effector in frame k.
    suffix: Vec<Vector3<f64>>,
    /// `prefix[0..=prefix_valid]` are up to date.
    prefix_valid: usize,
    /// `suffix[suffix_valid..]` are up to date.
    suffix_valid: usize,
}

impl<'a> IncrementalFk<'a> {
    pub fn new(chain: &'a Chain, q: Vec<f64>) -> Self {
        let n = chain.dof();
        assert_eq!(q.len(), n, "one value per joint");
        let mut suffix = vec![Vector3::zeros(); n + 1];
        suffix[n] = chain.effector_mm;
        IncrementalFk {
            chain,
            q,
            prefix: vec![IsometryMatrix3::identity(); n + 1],
            suffix,
            prefix_valid: 0,
            suffix_valid: n,
        }
    }

    pub fn q(&self) -> &[f64] {
        &self.q
    }

    pub fn into_q(self) -> Vec<f64> {
        self.q
    }

    /// The effector in the base frame for the current posture.
    pub fn effector(&mut self) -> Point3<f64> {
        self.refresh_suffix(0);
        Point3::from(self.suffix[0])
    }

    /// The effector in the base frame if joint `i` had value `qi`, the others
    /// unchanged.
    pub fn effector_with(&mut self, i: usize, qi: f64) -> Point3<f64> {
        self.refresh_prefix(i);
        self.refresh_suffix(i + 1);
        let in_frame_i = self.chain.joints[i].transform(qi) * Point3::from(self.suffix[i + 1]);
        self.prefix[i] * in_frame_i
    }

    /// Give joint `i` the value `qi`.
    pub fn set(&mut self, i: usize, qi: f64) {
        self.q[i] = qi;
        self.prefix_valid = self.prefix_valid.min(i);
        self.suffix_valid = self.suffix_valid.max(i + 1);
    }

    fn refresh_prefix(&mut self, upto: usize) {
        while self.prefix_valid < upto {
            let k = self.prefix_valid;
            self.prefix[k + 1] = self.prefix[k] * self.chain.joints[k].transform(self.q[k]);
            self.prefix_valid += 1;
        }
    }

    fn refresh_suffix(&mut self, from: usize) {
        while self.suffix_valid > from {
            let k = self.suffix_valid - 1;
            let p = self.chain.joints[k].transform(self.q[k]) * Point3::from(self.suffix[k + 1]);
            self.suffix[k] = p.coords;
            self.suffix_valid -= 1;
        }
    }
}
