//! Joints whose ranges are not independent (`couple`): two or more joints
//! kept within an ellipse through their single-plane limits. Each
//! joint's value, as a fraction of its range on that side (from zero, or
//! the end of the range nearest zero), is squared; the squares sum to at
//! most one. A joint alone still goes to its limit, but two at once do
//! not both go to theirs (a trunk turned its full range can hardly bend
//! sideways as well).

use super::limited::Limited;

/// Slack on the sum of squares for values that went through a square root
/// and back.
const SLACK: f64 = 1e-9;

/// Coupled joints, by index in their chain (or body).
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Ellipse {
    pub joints: Vec<usize>,
}

impl Ellipse {
    /// How far into its range joint `joint` is at `q`: 0 at its centre
    /// (zero, if the range holds it), 1 at either limit.
    fn fraction(joint: &impl Limited, q: f64) -> f64 {
        let (min, max) = joint.limits();
        let centre = 0.0_f64.clamp(min, max);
        let side = if q >= centre { max } else { min } - centre;
        if side == 0.0 {
            // A range that ends at its centre: nothing on that side.
            return if q == centre { 0.0 } else { f64::INFINITY };
        }
        (q - centre) / side
    }

    /// The sum of the squared fractions of the coupled joints of `q`,
    /// leaving out joint `skip`.
    fn load_without(&self, joints: &[impl Limited], q: &[f64], skip: Option<usize>) -> f64 {
        self.joints
            .iter()
            .filter(|&&j| Some(j) != skip)
            .map(|&j| Self::fraction(&joints[j], q[j]).powi(2))
            .sum()
    }

    /// Whether `q` keeps these joints within the ellipse.
    pub fn admits(&self, joints: &[impl Limited], q: &[f64]) -> bool {
        self.load_without(joints, q, None) <= 1.0 + SLACK
    }

    /// Whether some posture with each joint `j` within `ranges[j]` keeps
    /// these joints within the ellipse (a coupling on joints beyond
    /// `ranges` is not looked at: true).
    pub fn admits_some(&self, joints: &[impl Limited], ranges: &[(f64, f64)]) -> bool {
        let mut least = 0.0;
        for &j in &self.joints {
            let Some(&(lo, hi)) = ranges.get(j) else {
                return true;
            };
            let (min, max) = joints[j].limits();
            let centre = 0.0_f64.clamp(min, max);
            let nearest = centre.clamp(lo, hi);
            least += Self::fraction(&joints[j], nearest).powi(2);
        }
        least <= 1.0 + SLACK
    }

    /// The range joint `i` may take with the others of `q` where they are
    /// (within its own limits; its centre at least).
    pub fn interval(&self, joints: &[impl Limited], q: &[f64], i: usize) -> (f64, f64) {
        let (min, max) = joints[i].limits();
        if !self.joints.contains(&i) {
            return (min, max);
        }
        let left = (1.0 - self.load_without(joints, q, Some(i)))
            .max(0.0)
            .sqrt();
        let centre = 0.0_f64.clamp(min, max);
        (
            centre + left * (min - centre),
            centre + left * (max - centre),
        )
    }

    /// `q` with these joints drawn in towards their centres, all by the
    /// same share, until they lie on the ellipse (unchanged if within).
    pub fn pull_in(&self, joints: &[impl Limited], q: &mut [f64]) {
        let load = self.load_without(joints, q, None);
        if load <= 1.0 {
            return;
        }
        let share = 1.0 / load.sqrt();
        for &j in &self.joints {
            let (min, max) = joints[j].limits();
            let centre = 0.0_f64.clamp(min, max);
            q[j] = centre + (q[j] - centre) * share;
        }
    }

    /// This coupling on a subset of the joints, renumbered by `index`
    /// (`None`: the joint is not in the subset); `None` unless every
    /// coupled joint is in it.
    pub fn renumbered(&self, index: impl Fn(usize) -> Option<usize>) -> Option<Ellipse> {
        let joints: Option<Vec<usize>> = self.joints.iter().map(|&j| index(j)).collect();
        joints.map(|joints| Ellipse { joints })
    }
}

#[cfg(test)]
mod tests {
    use super::super::limited::Range;
    use super::*;

    fn joints() -> Vec<Range> {
        vec![Range(-0.5, 0.5), Range(-0.6, 0.3)]
    }

    #[test]
    fn one_joint_alone_reaches_its_limit_and_two_together_do_not() {
        let (j, c) = (joints(), Ellipse { joints: vec![0, 1] });
        assert!(c.admits(&j, &[0.5, 0.0]));
        assert!(c.admits(&j, &[0.0, -0.6]));
        assert!(!c.admits(&j, &[0.5, 0.3]));
        // On the ellipse: half of each range squared is a quarter.
        let (lo, hi) = c.interval(&j, &[0.5 * 0.5_f64.sqrt(), 0.0], 1);
        assert!((lo + 0.6 * 0.5_f64.sqrt()).abs() < 1e-12);
        assert!((hi - 0.3 * 0.5_f64.sqrt()).abs() < 1e-12);
    }

    #[test]
    fn a_box_outside_the_ellipse_admits_nothing() {
        let (j, c) = (joints(), Ellipse { joints: vec![0, 1] });
        assert!(c.admits_some(&j, &[(-0.1, 0.5), (0.2, 0.3)]));
        // Both at least 90 % of the way to their limits.
        assert!(!c.admits_some(&j, &[(0.45, 0.5), (-0.6, -0.54)]));
        // A coupling beyond the ranges given is not looked at.
        assert!(c.admits_some(&j, &[(0.45, 0.5)]));
    }

    #[test]
    fn pulling_in_lands_on_the_ellipse_and_keeps_the_signs() {
        let (j, c) = (joints(), Ellipse { joints: vec![0, 1] });
        let mut q = [0.5, -0.6];
        c.pull_in(&j, &mut q);
        assert!(q[0] > 0.0 && q[1] < 0.0);
        assert!((c.load_without(&j, &q, None) - 1.0).abs() < 1e-12);
        let mut inside = [0.1, 0.1];
        c.pull_in(&j, &mut inside);
        assert_eq!(inside, [0.1, 0.1]);
    }

    #[test]
    fn a_range_that_ends_at_zero_has_no_room_on_the_other_side() {
        let mut j = joints();
        j[1].0 = 0.0;
        let c = Ellipse { joints: vec![0, 1] };
        assert!(!c.admits(&j, &[0.0, -0.1]));
        assert_eq!(c.interval(&j, &[0.5, 0.0], 1), (0.0, 0.0));
    }
}
