//! A posture against everything it may not pass through: the room's
//! obstacles and sides (`Obstacles`), the parts of the person and their
//! base that no joint moves (`OwnBody`: legs, the chair), and the person's
//! other moving parts (the hand through the trunk). The chain's solids come
//! in the base frame and are carried into the room by the base pose.

use nalgebra::Vector2;

use crate::geometry::{Capsule, Shape};
use crate::kinematics::{Chain, Motion, Owner, Tipping, Volumes};
use crate::scene::{BasePose, Blocker, Collision, OwnBody};

use super::Obstacles;

/// Obstacles seen from a placed person.
#[derive(Clone, Copy)]
pub struct PlacedObstacles<'a> {
    pub obstacles: &'a Obstacles,
    /// The person's legs and their base's parts (none: the stick figure of
    /// a scenario that does not check them).
    pub own: &'a OwnBody,
    pub base_pose: BasePose,
}

impl PlacedObstacles<'_> {
    /// What one check of a posture of `chain` against these (and against
    /// itself) costs, in units of the meter (`crate::meter`).
    pub fn check_units(&self, chain: &Chain) -> u64 {
        crate::meter::posture_check(self.obstacles.count(), chain.solids_at_most())
    }

    /// What checking one solid against the room costs, in the same units.
    pub fn capsule_units(&self) -> u64 {
        crate::meter::capsule_check(self.obstacles.count())
    }

    /// What one solid of the person, in the base frame, overlaps first:
    /// their own legs or base, then the room.
    pub fn capsule_hit(&self, capsule: &Capsule) -> Option<Blocker> {
        if let Some(i) = self.own.hit(capsule) {
            return Some(Blocker::Own(i));
        }
        self.obstacles.capsule_hit(&self.in_room(capsule))
    }

    /// A solid of the person, in the base frame, carried into the room.
    fn in_room(&self, capsule: &Capsule) -> Capsule {
        Capsule::new(
            self.base_pose.to_room(&capsule.a),
            self.base_pose.to_room(&capsule.b),
            capsule.radius_mm,
        )
    }

    /// The first collision of `chain` in posture `q`: each solid of the
    /// chain, from the base out, against the person's own legs and base and
    /// the room; then the solids of the chain against each other. The
    /// effector's link may touch what the effector reaches: it is checked
    /// ending its radius short of the effector and `end_allowance_mm`
    /// thinner.
    pub fn posture_hit(
        &self,
        chain: &Chain,
        q: &[f64],
        end_allowance_mm: f64,
    ) -> Option<Collision> {
        self.volumes_hit(chain, &chain.volumes(q), end_allowance_mm)
    }

    /// The first collision of `chain`'s solids `v` in some posture, as
    /// [`PlacedObstacles::posture_hit`] finds it; solids that did not move
    /// since a posture known to be clear (`Motion::Still`), and pairs
    /// that did not move apart, are not looked at again.
    pub fn volumes_hit(
        &self,
        chain: &Chain,
        v: &Volumes,
        end_allowance_mm: f64,
    ) -> Option<Collision> {
        for (tested, part, motion) in checked(chain, v, end_allowance_mm) {
            if motion == Motion::Still {
                continue;
            }
            if let Some(blocker) = self.capsule_hit(&tested) {
                return Some(Collision { part, blocker });
            }
        }
        if let Some((i, j)) = v.self_hit() {
            return Some(Collision {
                part: v.owners[j],
                blocker: Blocker::Body(v.owners[i]),
            });
        }
        self.balance_hit(chain, v, end_allowance_mm)
    }

    /// Standing, whether the posture of `v` loses the balance: no lean of
    /// the legs puts the feet under its centre of mass, or the feet, where
    /// the least lean puts them, meet the room (where a moving base did
    /// not already place them) or the moving body.
    fn balance_hit(&self, chain: &Chain, v: &Volumes, end_allowance_mm: f64) -> Option<Collision> {
        let balance = self.own.balance.as_ref()?;
        let lost = |t| {
            Some(Collision {
                part: Owner::Link(chain.joints.len()),
                blocker: Blocker::Balance(t),
            })
        };
        let feet_mm = match balance.feet_moved_mm(v) {
            Ok(feet_mm) => feet_mm,
            Err(t) => return lost(t),
        };
        let moved = feet_mm != Vector2::zeros();
        if !moved && self.own.feet_placed {
            return None;
        }
        let upright = balance.upright_legs();
        let moved_legs = moved.then(|| balance.legs().standing_feet_moved(feet_mm));
        let standing = moved_legs.as_deref().unwrap_or(upright);
        for (up, now) in upright.iter().zip(standing) {
            let (Shape::Capsule(up), Shape::Capsule(now)) = (&up.shape, &now.shape) else {
                continue;
            };
            if let Some(b) = self.obstacles.capsule_hit(&self.in_room(now)) {
                let placed_so = self.own.feet_placed
                    && self
                        .obstacles
                        .capsule_hits(&self.in_room(up))
                        .any(|u| u == b);
                if !placed_so {
                    return lost(Tipping::NoFooting);
                }
            }
        }
        let legs = OwnBody::new(moved_legs?, self.own.pelvis_mm);
        let upright = OwnBody::new(upright.to_vec(), self.own.pelvis_mm);
        let in_the_way = checked(chain, v, end_allowance_mm)
            .any(|(tested, _, _)| legs.hit(&tested).is_some() && upright.hit(&tested).is_none());
        if in_the_way {
            lost(Tipping::NoFooting)
        } else {
            None
        }
    }
}

impl PlacedObstacles<'_> {
    /// Everything the solids of `chain` in posture `q` overlap, each once,
    /// from the base out: the person's own parts, the room's obstacles
    /// and sides, and the chain's own solids that another passes through
    /// (what a failed search met, to be tried without).
    pub fn posture_hits(&self, chain: &Chain, q: &[f64], end_allowance_mm: f64) -> Vec<Blocker> {
        let v = chain.volumes(q);
        let mut met: Vec<Blocker> = Vec::new();
        let mut add = |b: Blocker| {
            if !met.contains(&b) {
                met.push(b);
            }
        };
        for (tested, _, _) in checked(chain, &v, end_allowance_mm) {
            self.own.hits(&tested).for_each(|i| add(Blocker::Own(i)));
            let room = self.in_room(&tested);
            self.obstacles.capsule_hits(&room).for_each(&mut add);
        }
        if let Some((i, _)) = v.self_hit() {
            add(Blocker::Body(v.owners[i]));
        }
        if let Some(c) = self.balance_hit(chain, &v, end_allowance_mm) {
            // What keeps the feet from where the balance needs them (a
            // plinth; the floor, where a fixed base's hips are too low).
            if c.blocker == Blocker::Balance(Tipping::NoFooting) {
                self.footing_hits(&v).into_iter().for_each(&mut add);
            }
            add(c.blocker);
        }
        met
    }

    /// Standing, the room's obstacles and sides the legs meet where the
    /// balance of `v` puts them (but those a moving base placed them
    /// against as they are).
    fn footing_hits(&self, v: &Volumes) -> Vec<Blocker> {
        let Some(balance) = self.own.balance.as_ref() else {
            return Vec::new();
        };
        let Ok(feet_mm) = balance.feet_moved_mm(v) else {
            return Vec::new();
        };
        let upright = balance.upright_legs();
        let moved =
            (feet_mm != Vector2::zeros()).then(|| balance.legs().standing_feet_moved(feet_mm));
        let mut met = Vec::new();
        for (up, now) in upright.iter().zip(moved.as_deref().unwrap_or(upright)) {
            let (Shape::Capsule(up), Shape::Capsule(now)) = (&up.shape, &now.shape) else {
                continue;
            };
            for b in self.obstacles.capsule_hits(&self.in_room(now)) {
                let placed_so = self.own.feet_placed
                    && (self.obstacles.capsule_hits(&self.in_room(up))).any(|u| u == b);
                if !placed_so && !met.contains(&b) {
                    met.push(b);
                }
            }
        }
        met
    }
}

/// Each of `v`'s solids as it is checked, with its part and how it moved:
/// the effector's link [`shortened`] (and left out if nothing is left),
/// the others as they are.
fn checked<'v>(
    chain: &Chain,
    v: &'v Volumes,
    end_allowance_mm: f64,
) -> impl Iterator<Item = (Capsule, Owner, Motion)> + 'v {
    let end = Owner::Link(chain.joints.len());
    let parts = v.capsules.iter().zip(&v.owners).zip(&v.motion);
    parts.filter_map(move |((capsule, &part), &motion)| {
        let tested = if part == end {
            shortened(capsule, end_allowance_mm)?
        } else {
            *capsule
        };
        Some((tested, part, motion))
    })
}

/// The effector's link as it is checked: ending its radius short of the
/// effector, and `allowance_mm` (the tolerance) thinner. The hand may so
/// touch what it reaches with its end (fingers on a switch on a wall), or
/// lie on it (a hand on a shelf, its centre a hand's radius above the
/// board) within the tolerance, but not pass into it. A link without a
/// radius stops `allowance_mm` (a millimetre at least) short. None if
/// nothing is left.
fn shortened(c: &Capsule, allowance_mm: f64) -> Option<Capsule> {
    let gap_mm = c.radius_mm.max(allowance_mm).max(1.0);
    let radius_mm = (c.radius_mm - allowance_mm).max(0.0);
    let link = c.b - c.a;
    let length = link.norm();
    (length > gap_mm).then(|| Capsule::new(c.a, c.a + link * (1.0 - gap_mm / length), radius_mm))
}
