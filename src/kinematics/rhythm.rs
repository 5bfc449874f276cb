//! A joint that follows the elevation of two others (`rhythm`): the
//! shoulder girdle, which stays down while the arm hangs and rises, in
//! proportion, as the arm is raised past the first 30 degrees (the
//! scapulohumeral rhythm).
//!
//! The drivers are two joints with orthogonal axes that turn one link
//! from its rest direction (shoulder flexion and abduction turn the
//! upper arm from hanging): the link's elevation, the angle between its
//! rest direction and where it points, has the cosine
//! `cos(a) cos(b)`. The follower may take its lower limit and, as the
//! elevation passes `from`, a share of its range that grows in
//! proportion to the elevation, all of it at 180 degrees (straight up).
//! It is an upper bound: the follower may stay lower (the shoulder need
//! not be shrugged).

use std::f64::consts::{PI, TAU};
use std::hash::{Hash, Hasher};

use super::limited::Limited;

/// Slack on the follower's bound, as a share of its range, for values
/// that went through a cosine and back.
const SLACK: f64 = 1e-9;

/// A follower bounded by the elevation its two drivers give, by index
/// in their chain (or body).
#[derive(Clone, Debug, PartialEq)]
pub struct Rhythm {
    pub follower: usize,
    pub drivers: [usize; 2],
    /// The elevation up to which the follower stays at its lower limit.
    pub from_rad: f64,
}

impl Eq for Rhythm {}

impl Hash for Rhythm {
    fn hash<H: Hasher>(&self, h: &mut H) {
        (self.follower, self.drivers, self.from_rad.to_bits()).hash(h);
    }
}

impl Rhythm {
    /// The elevation of the link two orthogonal joints at `a` and `b`
    /// turn from its rest direction.
    pub fn elevation_rad(a: f64, b: f64) -> f64 {
        (a.cos() * b.cos()).clamp(-1.0, 1.0).acos()
    }

    /// The share of its range the follower may take at elevation
    /// `beta_rad`.
    pub fn share(&self, beta_rad: f64) -> f64 {
        let span = PI - self.from_rad;
        if span <= 0.0 {
            return if beta_rad >= PI { 1.0 } else { 0.0 };
        }
        ((beta_rad - self.from_rad) / span).clamp(0.0, 1.0)
    }

    /// The highest value the follower may take with the drivers where `q`
    /// has them.
    pub fn cap(&self, joints: &[impl Limited], q: &[f64]) -> f64 {
        let (min, max) = joints[self.follower].limits();
        let [a, b] = self.drivers;
        min + (max - min) * self.share(Self::elevation_rad(q[a], q[b]))
    }

    fn slack(&self, joints: &[impl Limited]) -> f64 {
        let (min, max) = joints[self.follower].limits();
        SLACK * (max - min).max(1.0)
    }

    /// Whether `q` keeps the follower within what its drivers allow.
    pub fn admits(&self, joints: &[impl Limited], q: &[f64]) -> bool {
        q[self.follower] <= self.cap(joints, q) + self.slack(joints)
    }

    /// Whether some posture within `ranges` keeps the follower within what
    /// its drivers allow: its lowest value within the most the highest
    /// elevation of the box allows (true where a joint is beyond `ranges`).
    pub fn admits_some(&self, joints: &[impl Limited], ranges: &[(f64, f64)]) -> bool {
        let [a, b] = self.drivers;
        let (Some(&(lowest, _)), Some(&ra), Some(&rb)) =
            (ranges.get(self.follower), ranges.get(a), ranges.get(b))
        else {
            return true;
        };
        let (ca, cb) = (cos_range(ra), cos_range(rb));
        let least = [ca.0 * cb.0, ca.0 * cb.1, ca.1 * cb.0, ca.1 * cb.1]
            .into_iter()
            .fold(f64::INFINITY, f64::min);
        let highest = least.clamp(-1.0, 1.0).acos();
        let (min, max) = joints[self.follower].limits();
        lowest <= min + (max - min) * self.share(highest) + self.slack(joints)
    }

    /// The range joint `i` may take with the others of `q` where they are:
    /// the follower up to what the drivers allow; a driver where, with the
    /// other driver where it is, the elevation still allows the follower's
    /// value (the part of that set that holds `q[i]`; `q[i]` alone where
    /// `q` breaks the rhythm).
    pub fn interval(&self, joints: &[impl Limited], q: &[f64], i: usize) -> (f64, f64) {
        let (min, max) = joints[i].limits();
        let [a, b] = self.drivers;
        if i == self.follower {
            return (min, self.cap(joints, q).max(min));
        }
        let other = match i {
            _ if i == a => b,
            _ if i == b => a,
            _ => return (min, max),
        };
        let (f_min, f_max) = joints[self.follower].limits();
        let need = if f_max > f_min {
            (q[self.follower] - f_min) / (f_max - f_min) - SLACK
        } else {
            0.0
        };
        if need <= 0.0 {
            return (min, max);
        }
        // The elevation the follower's value needs: cos(x) cos(other) may
        // be at most its cosine.
        let needed_rad = (self.from_rad + need * (PI - self.from_rad)).min(PI);
        let bound = needed_rad.cos() + SLACK;
        let c_other = q[other].cos();
        let feasible = |x: f64| x.cos() * c_other <= bound;
        holding(
            min,
            max,
            q[i],
            feasible,
            crossings(min, max, bound, c_other),
        )
    }

    /// `q` with the follower lowered to what its drivers allow.
    pub fn pull_in(&self, joints: &[impl Limited], q: &mut [f64]) {
        let cap = self.cap(joints, q);
        if q[self.follower] > cap {
            q[self.follower] = cap;
        }
    }

    /// This rhythm on a subset of the joints, renumbered by `index`;
    /// `None` unless all three joints are in it.
    pub fn renumbered(&self, index: impl Fn(usize) -> Option<usize>) -> Option<Rhythm> {
        Some(Rhythm {
            follower: index(self.follower)?,
            drivers: [index(self.drivers[0])?, index(self.drivers[1])?],
            from_rad: self.from_rad,
        })
    }
}

/// The least and greatest cosine over `[lo, hi]`.
fn cos_range((lo, hi): (f64, f64)) -> (f64, f64) {
    if hi - lo >= TAU {
        return (-1.0, 1.0);
    }
    let (cl, ch) = (lo.cos(), hi.cos());
    let holds = |at: f64| {
        let k = ((lo - at) / TAU).ceil();
        at + k * TAU <= hi
    };
    let least = if holds(PI) { -1.0 } else { cl.min(ch) };
    let greatest = if holds(0.0) { 1.0 } else { cl.max(ch) };
    (least, greatest)
}

/// The values within `[lo, hi]` where `cos(x) * c_other` equals `bound`,
/// in order.
fn crossings(lo: f64, hi: f64, bound: f64, c_other: f64) -> Vec<f64> {
    if c_other.abs() < 1e-12 {
        return Vec::new();
    }
    let ratio = bound / c_other;
    if !(-1.0..=1.0).contains(&ratio) {
        return Vec::new();
    }
    let root = ratio.acos();
    let first = (lo / TAU).floor() as i64 - 1;
    let last = (hi / TAU).ceil() as i64 + 1;
    let mut at: Vec<f64> = (first..=last)
        .flat_map(|k| [k as f64 * TAU - root, k as f64 * TAU + root])
        .filter(|x| *x > lo && *x < hi)
        .collect();
    at.sort_by(f64::total_cmp);
    at.dedup();
    at
}

/// The part of `[lo, hi]` where `feasible` holds that holds `x` (the
/// pieces between the `cuts`, each judged at its middle, joined where
/// neighbours both hold); `(x, x)` where the piece `x` is in does not.
fn holding(lo: f64, hi: f64, x: f64, feasible: impl Fn(f64) -> bool, cuts: Vec<f64>) -> (f64, f64) {
    let x = x.clamp(lo, hi);
    let mut ends = Vec::with_capacity(cuts.len() + 2);
    ends.push(lo);
    ends.extend(cuts);
    ends.push(hi);
    let pieces: Vec<(f64, f64, bool)> = ends
        .windows(2)
        .map(|w| (w[0], w[1], feasible(0.5 * (w[0] + w[1]))))
        .collect();
    let Some(at) = pieces.iter().position(|&(l, h, _)| l <= x && x <= h) else {
        return (x, x);
    };
    if !pieces[at].2 {
        return (x, x);
    }
    let mut first = at;
    while first > 0 && pieces[first - 1].2 {
        first -= 1;
    }
    let mut last = at;
    while last + 1 < pieces.len() && pieces[last + 1].2 {
        last += 1;
    }
    (pieces[first].0, pieces[last].1)
}

#[cfg(test)]
mod tests {
    use super::super::limited::Range;
    use super::*;

    /// A girdle of 0-120 mm, flexion -60..180 deg, abduction -30..180 deg.
    fn joints() -> Vec<Range> {
        vec![
            Range(0.0, 120.0),
            Range(-PI / 3.0, PI),
            Range(-PI / 6.0, PI),
        ]
    }

    fn rhythm() -> Rhythm {
        Rhythm {
            follower: 0,
            drivers: [1, 2],
            from_rad: PI / 6.0,
        }
    }

    #[test]
    fn the_girdle_rises_with_the_elevation_past_30_deg() {
        let (j, r) = (joints(), rhythm());
        assert_eq!(r.cap(&j, &[0.0, 0.0, 0.0]), 0.0);
        assert_eq!(r.cap(&j, &[0.0, PI / 6.0, 0.0]), 0.0);
        // 105 deg: half way from 30 to 180.
        let half = r.cap(&j, &[0.0, 105f64.to_radians(), 0.0]);
        assert!((half - 60.0).abs() < 1e-9, "{half}");
        assert!((r.cap(&j, &[0.0, PI, 0.0]) - 120.0).abs() < 1e-9);
        // The elevation of flexion 45 and abduction 45 is 60 deg.
        let e = Rhythm::elevation_rad(PI / 4.0, PI / 4.0);
        assert!((e - PI / 3.0).abs() < 1e-12);
        assert!(r.admits(&j, &[20.0, PI / 4.0, PI / 4.0]));
        assert!(!r.admits(&j, &[30.0, PI / 4.0, PI / 4.0]));
    }

    #[test]
    fn a_raised_girdle_keeps_the_arm_up_and_pulling_in_lowers_it() {
        let (j, r) = (joints(), rhythm());
        // The girdle at 60 mm needs 105 deg of elevation: with abduction
        // at zero, flexion from 105 deg up (or down to -105, beyond its
        // limit).
        let q = [60.0, 2.5, 0.0];
        let (lo, hi) = r.interval(&j, &q, 1);
        assert!((lo - 105f64.to_radians()).abs() < 1e-6, "{lo}");
        assert!((hi - PI).abs() < 1e-12);
        // The girdle may go up to what flexion 2.5 rad allows.
        let (_, cap) = r.interval(&j, &q, 0);
        assert!((cap - r.cap(&j, &q)).abs() < 1e-12);
        let mut low = [100.0, 1.0, 0.0];
        r.pull_in(&j, &mut low);
        assert!((low[0] - r.cap(&j, &[0.0, 1.0, 0.0])).abs() < 1e-12);
        assert!(r.admits(&j, &low));
    }

    #[test]
    fn each_driver_keeps_to_the_piece_of_its_range_it_is_in() {
        let j = vec![Range(0.0, 120.0), Range(-PI, PI), Range(-PI / 6.0, PI)];
        let r = rhythm();
        // Flexion beyond 105 deg either way raises the arm enough.
        let (lo, hi) = r.interval(&j, &[60.0, -2.5, 0.0], 1);
        assert!((lo + PI).abs() < 1e-12);
        assert!((hi + 105f64.to_radians()).abs() < 1e-6, "{hi}");
        // With the arm down, the girdle breaks the rhythm: flexion stays.
        assert_eq!(r.interval(&j, &[60.0, 0.2, 0.0], 1), (0.2, 0.2));
    }

    #[test]
    fn a_box_admits_what_its_highest_elevation_allows() {
        let (j, r) = (joints(), rhythm());
        let arm_down = [(50.0, 120.0), (-0.1, 0.2), (-0.1, 0.1)];
        assert!(!r.admits_some(&j, &arm_down));
        let arm_up = [(50.0, 120.0), (2.0, 3.0), (-0.1, 0.1)];
        assert!(r.admits_some(&j, &arm_up));
        // The follower beyond the ranges given: not looked at.
        assert!(r.admits_some(&j, &arm_down[..2]));
        assert_eq!(cos_range((-0.5, 0.5)).1, 1.0);
        assert_eq!(cos_range((3.0, 3.5)).0, -1.0);
    }
}
