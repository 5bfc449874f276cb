//! Forward kinematics that follows one joint change at a time (section
//! 5.3.2 of the accessibility paper, eq. 6-8), specialised to what the
//! incremental solver asks: how far is the effector from a target if joint
//! i takes value q?
//!
//! Where the paper keeps `DH_0,i-1` and `DH_i+1,n` and multiplies three
//! matrices per change (eq. 7), this keeps two chains of points for the
//! current posture: the effector in every frame (`e_k = T_k e_k+1`) and the
//! target in every frame (`t_k+1 = T_k^-1 t_k`).
//!
//! With joint i moved, the effector in frame i is `Rz(theta_i) w_i + d_i z`,
//! where `w_i = Tx(a) Rx(alpha) e_i+1` does not depend on joint i, so a trial
//! costs one rotation about z and a squared distance in frame i (rotations
//! keep distances). Changing joint i invalidates the targets after i and
//! the effectors up to i; both are refreshed lazily, so a sweep from the
//! base outwards refreshes each point once.
//!
//! A joint with a fixed pose (URDF) moves as `motion(q) F`, the same form
//! with `F` in place of `Tx(a) Rx(alpha)` and theta and d zero, so such
//! chains are followed the same way (a 1,000-joint URDF chain costs what
//! the same DH chain does, not a product of 1,000 matrices per trial). A
//! joint's `pre` frame (a mannequin's `fixed` joint) is carried by the
//! joint before it, whose `F` it follows; the first joint's, by the base.

use nalgebra::{IsometryMatrix3, Point3, Vector3};

use super::{Chain, JointKind};

/// What follows a joint's motion about (or along) z: a DH joint's
/// `Tx(a) Rx(alpha)`, or a fixed pose.
#[derive(Clone, Copy, Debug)]
enum Rest {
    Dh {
        a_mm: f64,
        cos_alpha: f64,
        sin_alpha: f64,
    },
    Fixed(IsometryMatrix3<f64>),
}

impl Rest {
    /// This rest followed by `pre`, as one fixed pose.
    fn then(&self, pre: &IsometryMatrix3<f64>) -> Rest {
        let own = match self {
            Rest::Dh {
                a_mm,
                cos_alpha,
                sin_alpha,
            } => IsometryMatrix3::from_parts(
                nalgebra::Translation3::new(*a_mm, 0.0, 0.0),
                nalgebra::Rotation3::from_matrix_unchecked(nalgebra::Matrix3::new(
                    1.0, 0.0, 0.0, 0.0, *cos_alpha, -sin_alpha, 0.0, *sin_alpha, *cos_alpha,
                )),
            ),
            Rest::Fixed(pose) => *pose,
        };
        Rest::Fixed(own * pre)
    }

    /// `F p`: a point of frame k+1 in joint k's frame before its motion.
    #[inline]
    fn apply(&self, p: &Vector3<f64>) -> Vector3<f64> {
        match self {
            Rest::Dh {
                a_mm,
                cos_alpha,
                sin_alpha,
            } => Vector3::new(
                p.x + a_mm,
                cos_alpha * p.y - sin_alpha * p.z,
                sin_alpha * p.y + cos_alpha * p.z,
            ),
            Rest::Fixed(pose) => pose.rotation * p + pose.translation.vector,
        }
    }

    /// `F^-1 p`.
    #[inline]
    fn unapply(&self, p: &Vector3<f64>) -> Vector3<f64> {
        match self {
            Rest::Dh {
                a_mm,
                cos_alpha,
                sin_alpha,
            } => {
                let (x, y, z) = (p.x - a_mm, p.y, p.z);
                Vector3::new(
                    x,
                    cos_alpha * y + sin_alpha * z,
                    -sin_alpha * y + cos_alpha * z,
                )
            }
            Rest::Fixed(pose) => pose.rotation.transpose() * (p - pose.translation.vector),
        }
    }
}

/// One joint's link constants, its current angle and the two cached
/// points on either side of it, kept together so a visit touches one record.
#[derive(Clone, Copy, Debug)]
struct JointState {
    revolute: bool,
    theta_rad: f64,
    d_mm: f64,
    rest: Rest,
    /// Cosine and sine of the total theta, and the total d.
    cos: f64,
    sin: f64,
    d_total: f64,
    /// The target in this joint's frame (frame k for joint k).
    target_in: Vector3<f64>,
    /// The effector in the next frame (k + 1).
    effector_out: Vector3<f64>,
}

impl JointState {
    /// `T_k p`: a point of frame k+1 in frame k.
    fn forward(&self, p: &Vector3<f64>) -> Vector3<f64> {
        let r = self.rest.apply(p);
        Vector3::new(
            self.cos * r.x - self.sin * r.y,
            self.sin * r.x + self.cos * r.y,
            r.z + self.d_total,
        )
    }

    /// `T_k^-1 p`: a point of frame k in frame k+1.
    fn backward(&self, p: &Vector3<f64>) -> Vector3<f64> {
        let unturned = Vector3::new(
            self.cos * p.x + self.sin * p.y,
            -self.sin * p.x + self.cos * p.y,
            p.z - self.d_total,
        );
        self.rest.unapply(&unturned)
    }

    fn store(&mut self, qi: f64) {
        let theta = if self.revolute {
            self.theta_rad + qi
        } else {
            self.theta_rad
        };
        (self.sin, self.cos) = theta.sin_cos();
        self.d_total = if self.revolute {
            self.d_mm
        } else {
            self.d_mm + qi
        };
    }
}

/// A posture of a chain, a target, and the cached points between them.
pub struct IncrementalFk {
    q: Vec<f64>,
    joints: Vec<JointState>,
    /// The first joint's `pre` frame, between the base and its motion.
    base_pre: Option<IsometryMatrix3<f64>>,
    target: Point3<f64>,
    /// `effector_out` of joints `k >= suffix_valid` is current (the last
    /// joint's never changes).
    suffix_valid: usize,
    /// `target_in` of joints `k <= target_valid` is current.
    target_valid: usize,
}

impl IncrementalFk {
    pub fn new(chain: &Chain, q: Vec<f64>, target: Point3<f64>) -> Self {
        let n = chain.dof();
        assert_eq!(q.len(), n, "one value per joint");
        assert!(n > 0, "a chain has joints");
        let base_pre = chain.joints[0].pre;
        let target_in =
            base_pre.map_or(target.coords, |p| p.inverse_transform_point(&target).coords);
        let mut joints: Vec<JointState> = chain
            .joints
            .iter()
            .zip(&q)
            .map(|(j, &qi)| {
                let (sin_alpha, cos_alpha) = j.dh.alpha_sin_cos();
                let (theta_rad, d_mm, rest) = match &j.fixed {
                    Some(pose) => (0.0, 0.0, Rest::Fixed(*pose)),
                    None => (
                        j.dh.theta_rad,
                        j.dh.d_mm,
                        Rest::Dh {
                            a_mm: j.dh.a_mm,
                            cos_alpha,
                            sin_alpha,
                        },
                    ),
                };
                let mut state = JointState {
                    revolute: j.kind == JointKind::Revolute,
                    theta_rad,
                    d_mm,
                    rest,
                    cos: 1.0,
                    sin: 0.0,
                    d_total: 0.0,
                    target_in,
                    effector_out: chain.effector_mm,
                };
                state.store(qi);
                state
            })
            .collect();
        for (k, next) in chain.joints.iter().enumerate().skip(1) {
            if let Some(pre) = &next.pre {
                joints[k - 1].rest = joints[k - 1].rest.then(pre);
            }
        }
        IncrementalFk {
            q,
            joints,
            base_pre,
            target,
            suffix_valid: n - 1,
            target_valid: 0,
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
        let first = &self.joints[0];
        let p = Point3::from(first.forward(&first.effector_out));
        match &self.base_pre {
            Some(pre) => pre * p,
            None => p,
        }
    }

    /// The squared distance from effector to target, current posture.
    pub fn distance_sq(&mut self) -> f64 {
        (self.effector() - self.target).norm_squared()
    }

    /// The squared distance from effector to target if joint `i` had value
    /// `qi`, the others unchanged.
    pub fn distance_sq_with(&mut self, i: usize, qi: f64) -> f64 {
        let w = self.lever(i);
        let j = &self.joints[i];
        let (c, s, d) = if j.revolute {
            let (s, c) = (j.theta_rad + qi).sin_cos();
            (c, s, j.d_mm)
        } else {
            (j.cos, j.sin, j.d_mm + qi)
        };
        squared_distance(c, s, d, &w, &j.target_in)
    }

    /// `w_i`: the effector in frame i before joint i's rotation about z and
    /// without joint i's d. It changes only when joints after i change, so a
    /// caller trying several values of joint i computes it once.
    pub fn lever(&mut self, i: usize) -> Vector3<f64> {
        self.refresh_target(i);
        self.refresh_suffix(i);
        let j = &self.joints[i];
        j.rest.apply(&j.effector_out)
    }

    /// The squared distance if joint `i` moved by `dir * step.delta` from
    /// its current value, without evaluating a sine or cosine: the moved
    /// angle's cosine and sine come from the angle-addition formulas. Also
    /// returns them, for [`Self::set_moved`]. `w` is [`Self::lever`]`(i)`.
    #[inline]
    pub fn distance_sq_moved(
        &self,
        i: usize,
        step: &Step,
        dir: f64,
        w: &Vector3<f64>,
    ) -> (f64, (f64, f64)) {
        let j = &self.joints[i];
        let (c, s, d) = if j.revolute {
            let sd = dir * step.sin;
            (
                j.cos * step.cos - j.sin * sd,
                j.sin * step.cos + j.cos * sd,
                j.d_total,
            )
        } else {
            (j.cos, j.sin, j.d_total + dir * step.delta)
        };
        (squared_distance(c, s, d, w, &j.target_in), (c, s))
    }

    /// Give joint `i` the value `qi`.
    pub fn set(&mut self, i: usize, qi: f64) {
        self.q[i] = qi;
        self.joints[i].store(qi);
        self.invalidate(i);
    }

    /// Give joint `i` the value `qi`, whose theta's cosine and sine (for a
    /// revolute joint) [`Self::distance_sq_moved`] returned.
    pub fn set_moved(&mut self, i: usize, qi: f64, cos_sin: (f64, f64)) {
        self.q[i] = qi;
        let j = &mut self.joints[i];
        if j.revolute {
            (j.cos, j.sin) = cos_sin;
        } else {
            j.d_total = j.d_mm + qi;
        }
        self.invalidate(i);
    }

    fn invalidate(&mut self, i: usize) {
        self.target_valid = self.target_valid.min(i);
        self.suffix_valid = self.suffix_valid.max(i);
    }

    fn refresh_target(&mut self, upto: usize) {
        while self.target_valid < upto {
            let k = self.target_valid;
            let next = self.joints[k].backward(&self.joints[k].target_in);
            self.joints[k + 1].target_in = next;
            self.target_valid += 1;
        }
    }

    fn refresh_suffix(&mut self, from: usize) {
        while self.suffix_valid > from {
            let k = self.suffix_valid;
            let previous = self.joints[k].forward(&self.joints[k].effector_out);
            self.joints[k - 1].effector_out = previous;
            self.suffix_valid -= 1;
        }
    }
}

/// `|Rz(theta) w + (0, 0, d) - t|^2` with `theta` given by its cosine and sine.
#[inline]
fn squared_distance(c: f64, s: f64, d: f64, w: &Vector3<f64>, t: &Vector3<f64>) -> f64 {
    let dx = c * w.x - s * w.y - t.x;
    let dy = s * w.x + c * w.y - t.y;
    let dz = w.z + d - t.z;
    dx * dx + dy * dy + dz * dz
}

/// A joint increment with its cosine and sine, kept up to date as it is
/// scaled: doubling and halving (exact in floating point) use the double-
/// and half-angle formulas, other factors evaluate them afresh.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Step {
    pub delta: f64,
    pub cos: f64,
    pub sin: f64,
}

impl Step {
    pub fn new(delta: f64) -> Self {
        let (sin, cos) = delta.sin_cos();
        Step { delta, cos, sin }
    }

    /// This step times `factor`.
    #[inline]
    pub fn scaled(&self, factor: f64) -> Step {
        let delta = self.delta * factor;
        if factor == 2.0 {
            Step {
                delta,
                cos: self.cos * self.cos - self.sin * self.sin,
                sin: 2.0 * self.sin * self.cos,
            }
        } else if factor == 0.5 && self.delta.abs() <= std::f64::consts::FRAC_PI_2 {
            let cos = ((1.0 + self.cos) * 0.5).sqrt();
            Step {
                delta,
                cos,
                sin: self.sin / (2.0 * cos),
            }
        } else {
            Step::new(delta)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kinematics::{Dh, Joint};

    /// Moves joint `i` by `step` in direction `dir`, checking the distance
    /// predicted before the move and the effector after it against the
    /// full forward kinematics.
    fn move_and_check(
        fk: &mut IncrementalFk,
        chain: &Chain,
        q: &mut [f64],
        i: usize,
        step: &Step,
        dir: f64,
        target: &Point3<f64>,
    ) {
        let w = fk.lever(i);
        let (d_sq, cos_sin) = fk.distance_sq_moved(i, step, dir, &w);
        q[i] += dir * step.delta;
        assert!((d_sq - (chain.effector(q) - target).norm_squared()).abs() < 1e-9);
        fk.set_moved(i, q[i], cos_sin);
        assert!((fk.effector() - chain.effector(q)).norm() < 1e-9);
    }

    fn chain() -> Chain {
        let joint = |name: &str, kind, theta, d, alpha, a| Joint {
            name: name.into(),
            kind,
            dh: Dh::new(theta, d, alpha, a),
            fixed: None,
            pre: None,
            min: -2.0,
            max: 2.0,
            anatomical: None,
            neutral: 0.0,
            weight: 1.0,
            link: crate::kinematics::Link::named(name),
        };
        Chain::new(
            vec![
                joint("a", JointKind::Revolute, 0.3, 10.0, 1.2, 40.0),
                joint("b", JointKind::Prismatic, -0.7, 25.0, -0.4, 5.0),
                joint("c", JointKind::Revolute, 1.1, 0.0, 0.9, 30.0),
                joint("d", JointKind::Revolute, 0.0, 12.0, 0.0, 0.0),
            ],
            "tip",
            Vector3::new(20.0, 3.0, -4.0),
        )
    }

    fn moved(q: &[f64], i: usize, qi: f64) -> Vec<f64> {
        let mut q = q.to_vec();
        q[i] = qi;
        q
    }

    #[test]
    fn agrees_with_the_full_product_after_single_changes() {
        let chain = chain();
        let target = Point3::new(30.0, -20.0, 50.0);
        let mut q = vec![0.1, 4.0, -0.5, 1.0];
        let mut fk = IncrementalFk::new(&chain, q.clone(), target);
        for (i, qi) in [(2, 0.7), (0, -1.1), (1, -3.0), (3, 0.2), (2, 1.9), (1, 0.5)] {
            let expected = (chain.effector(&moved(&q, i, qi)) - target).norm_squared();
            assert!((fk.distance_sq_with(i, qi) - expected).abs() < 1e-9);
            fk.set(i, qi);
            q[i] = qi;
            assert!((fk.effector() - chain.effector(&q)).norm() < 1e-9);
        }
    }

    #[test]
    fn moves_by_steps_agree_with_the_full_product() {
        let chain = chain();
        let target = Point3::new(-10.0, 25.0, 5.0);
        let mut q = vec![0.4, -1.0, 0.2, -0.6];
        let mut fk = IncrementalFk::new(&chain, q.clone(), target);
        let mut step = Step::new(0.3);
        for (k, i) in [0, 2, 1, 3, 2, 0, 3, 1].into_iter().enumerate() {
            step = step.scaled(if k % 3 == 0 { 2.0 } else { 0.5 });
            let dir = if k % 2 == 0 { 1.0 } else { -1.0 };
            move_and_check(&mut fk, &chain, &mut q, i, &step, dir, &target);
        }
    }

    /// The DH chain with two joints given fixed poses instead, as URDF
    /// joints are.
    fn chain_with_fixed_poses() -> Chain {
        let mut chain = chain();
        let pose = |x, y, z, roll, pitch, yaw| {
            IsometryMatrix3::from_parts(
                nalgebra::Translation3::new(x, y, z),
                nalgebra::Rotation3::from_euler_angles(roll, pitch, yaw),
            )
        };
        chain.joints[1].fixed = Some(pose(12.0, -7.0, 30.0, 0.4, -1.1, 0.3));
        chain.joints[3].fixed = Some(pose(0.0, 5.0, 18.0, -0.2, 0.0, 2.0));
        chain
    }

    #[test]
    fn fixed_pose_joints_agree_with_the_full_product() {
        let chain = chain_with_fixed_poses();
        let target = Point3::new(30.0, -20.0, 50.0);
        let mut q = vec![0.1, 4.0, -0.5, 1.0];
        let mut fk = IncrementalFk::new(&chain, q.clone(), target);
        let mut step = Step::new(0.3);
        for (k, (i, qi)) in [(2, 0.7), (0, -1.1), (1, -3.0), (3, 0.2), (1, 0.5)]
            .into_iter()
            .enumerate()
        {
            let expected = (chain.effector(&moved(&q, i, qi)) - target).norm_squared();
            assert!((fk.distance_sq_with(i, qi) - expected).abs() < 1e-9);
            fk.set(i, qi);
            q[i] = qi;
            let dir = if k % 2 == 0 { 1.0 } else { -1.0 };
            move_and_check(&mut fk, &chain, &mut q, i, &step, dir, &target);
            step = step.scaled(0.5);
        }
    }

    /// Turned frames before the first joint's motion and a later one's
    /// (a mannequin's `fixed` joints), on the DH chain and on one with
    /// fixed poses.
    #[test]
    fn pre_frames_agree_with_the_full_product() {
        let turn = |roll, pitch, yaw| {
            IsometryMatrix3::from_parts(
                nalgebra::Translation3::identity(),
                nalgebra::Rotation3::from_euler_angles(roll, pitch, yaw),
            )
        };
        for mut chain in [chain(), chain_with_fixed_poses()] {
            chain.joints[0].pre = Some(turn(0.3, -0.8, 1.2));
            chain.joints[2].pre = Some(turn(-1.1, 0.2, 0.5));
            let target = Point3::new(-10.0, 25.0, 5.0);
            let mut q = vec![0.4, -1.0, 0.2, -0.6];
            let mut fk = IncrementalFk::new(&chain, q.clone(), target);
            assert!((fk.effector() - chain.effector(&q)).norm() < 1e-9);
            let mut step = Step::new(0.3);
            for (k, i) in [0, 2, 1, 3, 2, 0, 3, 1].into_iter().enumerate() {
                let qi = q[i] + 0.37;
                let expected = (chain.effector(&moved(&q, i, qi)) - target).norm_squared();
                assert!((fk.distance_sq_with(i, qi) - expected).abs() < 1e-9);
                step = step.scaled(if k % 3 == 0 { 2.0 } else { 0.5 });
                let dir = if k % 2 == 0 { 1.0 } else { -1.0 };
                move_and_check(&mut fk, &chain, &mut q, i, &step, dir, &target);
            }
        }
    }

    #[test]
    fn scaled_steps_keep_their_cosine_and_sine() {
        let mut step = Step::new(1.3);
        for factor in [
            0.5, 0.5, 2.0, 0.5, 0.5, 0.5, 2.0, 2.0, 1.5, 0.5, 0.2, 0.5, 2.0, 4.0,
        ] {
            step = step.scaled(factor);
            assert!((step.cos - step.delta.cos()).abs() < 1e-14, "{step:?}");
            assert!((step.sin - step.delta.sin()).abs() < 1e-14, "{step:?}");
        }
    }
}
