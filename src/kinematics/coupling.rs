//! Joints whose ranges are not independent: a coupling narrows what each
//! of its joints may take given where the others are. Two kinds: an
//! ellipse through the single-plane limits (`couple`, `ellipse.rs`: a
//! trunk turned to its limit cannot also bend sideways to its own), and
//! a joint that follows the elevation of two others (`rhythm`,
//! `rhythm.rs`: the shoulder girdle rises only as the arm is raised).
//! Every solver keeps a posture within its chain's couplings through
//! these four questions: is `q` admitted, may some posture of a box of
//! ranges be, what interval may one joint take, and `q` pulled in.

pub use super::ellipse::Ellipse;
pub use super::limited::Limited;
pub use super::rhythm::Rhythm;

/// Joints whose ranges are not independent, by index in their chain (or
/// body).
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum Coupling {
    Ellipse(Ellipse),
    Rhythm(Rhythm),
}

impl Coupling {
    /// The joints it couples.
    pub fn joints(&self) -> Vec<usize> {
        match self {
            Coupling::Ellipse(e) => e.joints.clone(),
            Coupling::Rhythm(r) => vec![r.follower, r.drivers[0], r.drivers[1]],
        }
    }

    /// Whether `q` keeps these joints within the coupling.
    pub fn admits(&self, joints: &[impl Limited], q: &[f64]) -> bool {
        match self {
            Coupling::Ellipse(e) => e.admits(joints, q),
            Coupling::Rhythm(r) => r.admits(joints, q),
        }
    }

    /// Whether some posture with each joint `j` within `ranges[j]` keeps
    /// these joints within the coupling (a coupling on joints beyond
    /// `ranges` is not looked at: true).
    pub fn admits_some(&self, joints: &[impl Limited], ranges: &[(f64, f64)]) -> bool {
        match self {
            Coupling::Ellipse(e) => e.admits_some(joints, ranges),
            Coupling::Rhythm(r) => r.admits_some(joints, ranges),
        }
    }

    /// The range joint `i` may take with the others of `q` where they are
    /// (within its own limits).
    pub fn interval(&self, joints: &[impl Limited], q: &[f64], i: usize) -> (f64, f64) {
        match self {
            Coupling::Ellipse(e) => e.interval(joints, q, i),
            Coupling::Rhythm(r) => r.interval(joints, q, i),
        }
    }

    /// `q` moved within the coupling (unchanged if within).
    pub fn pull_in(&self, joints: &[impl Limited], q: &mut [f64]) {
        match self {
            Coupling::Ellipse(e) => e.pull_in(joints, q),
            Coupling::Rhythm(r) => r.pull_in(joints, q),
        }
    }

    /// This coupling on a subset of the joints, renumbered by `index`
    /// (`None`: the joint is not in the subset); `None` unless every
    /// coupled joint is in it.
    pub fn renumbered(&self, index: impl Fn(usize) -> Option<usize>) -> Option<Coupling> {
        match self {
            Coupling::Ellipse(e) => e.renumbered(index).map(Coupling::Ellipse),
            Coupling::Rhythm(r) => r.renumbered(index).map(Coupling::Rhythm),
        }
    }
}
