//! Placing a mobile base: where should the person stand or sit, and facing
//! which way, to reach a target? For each of `headings` directions the
//! preferred hip point is the one that puts the target where the arm works
//! best (the average horizontal position of the effector over the chain's
//! workspace, turned by the heading); the candidate is the admissible point
//! nearest to it. The candidates are searched as every base's are
//! (`search.rs`).
//! This is the paper's idea (section 5.3.5: the target becomes the region of
//! target minus admissible base positions) made discrete, with the heading
//! theta_0 of section 5.3.6 as the outer loop.

use std::collections::HashMap;
use std::sync::{Arc, Mutex, OnceLock};

use geo::{Closest, ClosestPoint, Contains, MultiPolygon, Point};
use nalgebra::{Point3, Rotation2, Vector2};
use rand_chacha::rand_core::SeedableRng;
use rand_chacha::ChaCha8Rng;

use super::search::search;
use crate::floor::{admissible, Footprint, Zone};
use crate::geometry::Solid;
use crate::kinematics::Chain;
use crate::plugin::{Base, BasePose, IkSolution, Placement, PreparedBase, ReachQuery, Solver};
use crate::scene::{column_solid, OwnBody, Physique, Room};
use crate::solvers::random_posture;

/// The admissible region at each heading searched.
type Regions = Vec<(f64, MultiPolygon<f64>)>;

/// A base that moves on the floor: its footprint, the person's own body
/// and the base's parts, and how it is searched.
pub struct Mobile {
    pub footprint: Footprint,
    pub hip_height_mm: f64,
    pub headings: u32,
    pub zone: Option<Zone>,
    pub own: OwnBody,
    /// The regions of each room, by name, worked out once.
    regions: Mutex<HashMap<String, Arc<OnceLock<Regions>>>>,
}

impl Mobile {
    pub fn new(
        footprint: Footprint,
        hip_height_mm: f64,
        headings: u32,
        zone: Option<Zone>,
        own: OwnBody,
    ) -> Self {
        Mobile {
            footprint,
            hip_height_mm,
            headings,
            zone,
            own,
            regions: Mutex::default(),
        }
    }

    /// The base with its parts and the person's legs (`solids`, in the
    /// base frame, the hip point `hip_height_mm` above the floor): the
    /// floor must find room for them and for the upright upper body, and
    /// links must stay out of them (but for the pelvis, `pelvis_mm` about
    /// the hip point).
    pub fn carrying(
        solids: Vec<Solid>,
        person: &Physique,
        pelvis_mm: f64,
        hip_height_mm: f64,
        headings: u32,
        zone: Option<Zone>,
    ) -> Self {
        let column = person.column_mm.map(|c| column_solid("the upper body", c));
        let footprint = Footprint::of_solids(solids.iter().chain(&column), hip_height_mm);
        Mobile::new(
            footprint,
            hip_height_mm,
            headings,
            zone,
            OwnBody::new(solids, pelvis_mm),
        )
    }

    /// The admissible regions, one per heading searched (one for all when
    /// turning does not change the footprint), worked out once per room.
    fn regions(&self, room: &Room) -> Arc<OnceLock<Regions>> {
        let cell = {
            let mut by_room = self.regions.lock().unwrap_or_else(|e| e.into_inner());
            Arc::clone(by_room.entry(room.name.clone()).or_default())
        };
        cell.get_or_init(|| self.compute_regions(room));
        cell
    }

    fn compute_regions(&self, room: &Room) -> Regions {
        let headings: Vec<f64> = (0..self.headings)
            .map(|k| 2.0 * std::f64::consts::PI * f64::from(k) / f64::from(self.headings))
            .collect();
        if !self.footprint.turns() {
            let region = admissible(room, &self.footprint, 0.0, self.zone);
            return headings.into_iter().map(|h| (h, region.clone())).collect();
        }
        headings
            .into_iter()
            .map(|h| (h, admissible(room, &self.footprint, h, self.zone)))
            .collect()
    }

    /// Whether the base fits anywhere in the room.
    pub fn fits(&self, room: &Room) -> bool {
        let regions = self.regions(room);
        regions
            .get()
            .is_some_and(|r| r.iter().any(|(_, r)| !r.0.is_empty()))
    }

    /// Ready for reaches in `room`: the regions and the workspace centre
    /// are computed once.
    pub fn prepare<'a>(&'a self, room: &'a Room, chain: &'a Chain) -> PreparedMobile<'a> {
        let regions = self.regions(room);
        let regions = regions
            .get()
            .map(|r| r.iter().filter(|(_, r)| !r.0.is_empty()).cloned().collect())
            .unwrap_or_default();
        PreparedMobile {
            mobile: self,
            room,
            chain,
            regions,
            hint: workspace_centre(chain),
        }
    }
}

impl Base for Mobile {
    fn own_body(&self) -> &OwnBody {
        &self.own
    }

    fn hip_height_mm(&self) -> Option<f64> {
        Some(self.hip_height_mm)
    }

    fn fits(&self, room: &Room) -> bool {
        Mobile::fits(self, room)
    }

    fn prepare<'a>(&'a self, room: &'a Room, chain: &'a Chain) -> Box<dyn PreparedBase + 'a> {
        Box::new(Mobile::prepare(self, room, chain))
    }

    fn placements(&self) -> u64 {
        u64::from(self.headings)
    }

    fn footprint(&self) -> Option<&Footprint> {
        Some(&self.footprint)
    }
}

/// A mobile base ready for one room and chain.
pub struct PreparedMobile<'a> {
    mobile: &'a Mobile,
    room: &'a Room,
    chain: &'a Chain,
    regions: Vec<(f64, MultiPolygon<f64>)>,
    hint: Vector2<f64>,
}

impl PreparedMobile<'_> {
    /// Candidate poses for reaching `target`, the most promising first (the
    /// hip nearest to where it would rather be), each with that distance.
    pub fn candidates(&self, target: &Point3<f64>) -> Vec<BasePose> {
        let mut scored: Vec<(f64, BasePose)> = self
            .regions
            .iter()
            .filter_map(|(heading, region)| {
                let offset = Rotation2::new(*heading) * self.hint;
                let preferred = Point::new(target.x - offset.x, target.y - offset.y);
                let p = nearest(region, preferred)?;
                let pose = BasePose {
                    position_mm: Point3::new(p.x(), p.y(), self.mobile.hip_height_mm),
                    heading_rad: *heading,
                };
                Some(((p.x() - preferred.x()).hypot(p.y() - preferred.y()), pose))
            })
            .collect();
        scored.sort_by(|a, b| a.0.total_cmp(&b.0));
        scored.into_iter().map(|(_, pose)| pose).collect()
    }
}

impl PreparedBase for PreparedMobile<'_> {
    fn reach(&self, query: &ReachQuery<'_>, solver: &dyn Solver) -> Placement {
        let poses = self.candidates(&query.target_room_mm);
        search(query, self.chain, &poses, solver).unwrap_or_else(|| nowhere(self.room, self.chain))
    }

    fn candidates(&self, target_room_mm: &Point3<f64>) -> Vec<BasePose> {
        PreparedMobile::candidates(self, target_room_mm)
    }
}

/// The admissible point nearest to `p` (itself if admissible).
fn nearest(region: &MultiPolygon<f64>, p: Point<f64>) -> Option<Point<f64>> {
    if region.0.is_empty() {
        return None;
    }
    if region.contains(&p) {
        return Some(p);
    }
    match region.closest_point(&p) {
        Closest::Intersection(q) | Closest::SinglePoint(q) => Some(q),
        Closest::Indeterminate => region
            .0
            .first()
            .and_then(|poly| poly.exterior().0.first())
            .map(|c| Point::new(c.x, c.y)),
    }
}

/// The average horizontal position of the effector over 64 fixed random
/// postures: where, relative to the hip, the arm works best.
fn workspace_centre(chain: &Chain) -> Vector2<f64> {
    let mut rng = ChaCha8Rng::seed_from_u64(0x5eed);
    let n = 64;
    let sum = (0..n).fold(Vector2::zeros(), |acc, _| {
        let p = chain.effector(&random_posture(chain, &mut rng));
        acc + Vector2::new(p.x, p.y)
    });
    sum / f64::from(n)
}

/// What is reported when the base fits nowhere (the checker refuses such
/// scenarios, so this is a last resort): no distance, the neutral posture.
fn nowhere(room: &Room, chain: &Chain) -> Placement {
    Placement {
        pose: BasePose {
            position_mm: Point3::new(room.size_mm.x / 2.0, room.size_mm.y / 2.0, 0.0),
            heading_rad: 0.0,
        },
        solution: IkSolution::unsolved(chain),
        retried: false,
    }
}
