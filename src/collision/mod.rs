//! Obstacles, for the questions the solvers and the gaze task ask: does a
//! solid of the person (a capsule: a link, a limb, the head) overlap an
//! obstacle of the room, a wall, the floor or the ceiling, and what does a
//! line of sight meet first? Boxes are measured exactly (`geometry`),
//! meshes with parry (`parry3d-f64`); all in the room frame, millimetres.
//! `placed.rs` asks it of a whole posture, with the person's own body.

mod beyond;
mod placed;
#[cfg(test)]
mod split_mesh_tests;
mod touched;

pub use beyond::{OutOfReach, Verdict, BOXES};
pub use placed::PlacedObstacles;
pub use touched::{
    bounds_meet, bounds_within, OneRecord, SolveRecord, Touched, TouchedSet, TOUCH_MARGIN_MM,
};

use std::cell::Cell;
use std::sync::Arc;

use nalgebra::{Isometry3, Point3, Vector3};
use parry3d_f64::bounding_volume::BoundingVolume;
use parry3d_f64::query::{self, Ray, RayCast};
use parry3d_f64::shape::{Capsule as ParryCapsule, Shape};

use crate::allowance::{Allowance, Counted};
use crate::geometry::{Capsule, Cuboid};
use crate::meter::capsule_check;
use crate::scene::{Blocker, MeshObstacle, MeshPart, MeshShape, Room, Wall};

/// A mesh obstacle as parry holds it, and its name for reports.
#[derive(Clone)]
struct Mesh {
    /// Its index among the room's obstacles (the boxes, then the meshes).
    index: usize,
    name: String,
    /// Its triangles in parts near each other (one part when closed).
    parts: Vec<MeshPart>,
    /// A mesh whose inside is known (closed, faces outwards): a point in
    /// it is in the obstacle. (A ray cast only finds the surface.)
    closed: bool,
    bounds: [Point3<f64>; 2],
}

/// A box obstacle: its name for reports, its solid and its bounds.
type NamedBox = (String, Cuboid, [Point3<f64>; 2]);

/// The obstacles of one room.
#[derive(Clone, Default)]
pub struct Obstacles {
    boxes: Arc<[NamedBox]>,
    meshes: Arc<[Mesh]>,
    /// The room's size: its walls, floor and ceiling.
    size_mm: Vector3<f64>,
    /// How close a solid may come to an obstacle.
    clearance_mm: f64,
    /// The room's sides that count (all six, but where a search asks what
    /// it would reach without one).
    walls: Vec<Wall>,
    /// Where the obstacles the questions come near are recorded (watch
    /// mode's cache), if anywhere.
    touched: Option<Arc<Touched>>,
    /// The record of the one solve these obstacles are asked by, if one is
    /// being made (`Obstacles::recording_solve`).
    solve: Option<Arc<SolveRecord>>,
    /// The room's boxes and meshes, which a check is charged for
    /// ([`crate::meter`]) whichever of them a search leaves out.
    charged: usize,
    /// Where the triangles a mesh check tests are charged, if anywhere
    /// ([`UNITS_PER_TRIANGLE`]).
    account: Option<Arc<dyn Allowance + Send>>,
}

const WALLS: [Wall; 6] = [
    Wall::Floor,
    Wall::Ceiling,
    Wall::XMin,
    Wall::XMax,
    Wall::YMin,
    Wall::YMax,
];

impl Obstacles {
    /// The room's boxes, meshes and sides; a solid closer than
    /// `clearance_mm` to one counts as touching it. A mesh is solid where
    /// its triangles close and face outwards, else only its surface counts.
    pub fn new(room: &Room, clearance_mm: f64) -> Self {
        let boxes: Vec<_> = room
            .boxes
            .iter()
            .map(|b| {
                let cuboid = b.cuboid();
                (b.name.clone(), cuboid, cuboid.bounds())
            })
            .collect();
        let first_mesh = room.boxes.len();
        let meshes: Vec<Mesh> = room
            .meshes
            .iter()
            .enumerate()
            .filter_map(|(k, m)| {
                let MeshShape { parts, solid } = m.shape()?.clone();
                let bounds = mesh_bounds(m, &parts);
                Some(Mesh {
                    index: first_mesh + k,
                    name: m.name.clone(),
                    parts,
                    closed: solid,
                    bounds,
                })
            })
            .collect();
        Obstacles {
            boxes: boxes.into(),
            meshes: meshes.into(),
            size_mm: room.size_mm,
            clearance_mm,
            walls: WALLS.to_vec(),
            touched: None,
            solve: None,
            charged: room.boxes.len() + room.meshes.len(),
            account: None,
        }
    }

    /// These obstacles, charging `meter` for the triangles of meshes
    /// their checks test: a check is otherwise charged by the obstacles
    /// it is put to, and a mesh counts as one, though a check may test
    /// every one of its triangles (thin ones across the room).
    pub fn charging(self, allowance: &dyn Allowance) -> Self {
        Obstacles {
            account: Some(allowance.shared()),
            ..self
        }
    }

    /// These obstacles, recording in `touched` which of them the questions
    /// put to them come near.
    pub fn recording(self, touched: Option<&Arc<Touched>>) -> Self {
        Obstacles {
            touched: touched.cloned(),
            ..self
        }
    }

    /// These obstacles as one solve asks them, keeping its own record in
    /// `solve` beside the task's (where the task's is kept): what its
    /// questions touched, where they asked, and what the triangles its
    /// checks tested cost. (A solve asks no other solve's questions: a
    /// view of a view keeps only the last record.)
    pub fn recording_solve(&self, solve: &Arc<SolveRecord>) -> Obstacles {
        let account = self.account.as_ref().map(|account| {
            let counted = Counted::new(Arc::clone(account), solve.units());
            Arc::new(counted) as Arc<dyn Allowance + Send>
        });
        Obstacles {
            solve: self.touched.as_ref().map(|_| Arc::clone(solve)),
            account,
            ..self.clone()
        }
    }

    /// Obstacle `index` touched: in the task's record and the solve's.
    fn mark(&self, index: usize) {
        if let Some(touched) = &self.touched {
            touched.mark(index);
            if let Some(solve) = &self.solve {
                solve.mark(index);
            }
        }
    }

    /// Whether a question must work out whether it comes near obstacle
    /// `index` ([`Touched::needs`]).
    fn needs(&self, index: usize) -> bool {
        (self.touched.as_ref()).is_some_and(|t| t.needs(index, self.solve.as_deref()))
    }

    /// Record obstacle `index`, whose bounds are `bounds`, as touched if
    /// the segment `a`-`b`, whose bounds grown by `r_mm` are `asked`, comes
    /// nearer than `r_mm` to them grown by the margin (`touched.rs`): the
    /// obstacle, wherever it moves within them, could meet it. (A line of
    /// sight, which meets what it enters, asks with `r_mm` nought.)
    #[inline]
    fn note(
        &self,
        index: usize,
        bounds: &[Point3<f64>; 2],
        segment: (&Point3<f64>, &Point3<f64>, f64),
        asked: &[Point3<f64>; 2],
    ) {
        if self.touched.is_some() {
            self.note_recorded(index, bounds, segment, asked);
        }
    }

    /// A question whose bounds are `asked` is put to the obstacles (where
    /// the questions are recorded, the record of the solve being made
    /// takes them in: `touched.rs`).
    #[inline]
    fn ask(&self, asked: &[Point3<f64>; 2]) {
        if let Some(solve) = &self.solve {
            solve.asked(asked);
        }
    }

    /// Record mesh `index`, whose bounds are `bounds`, as touched if they,
    /// grown by the margin, meet the question's bounds `asked`: the
    /// triangles a question tests (and is charged for) are those whose
    /// bounds meet its own, so the work, not only the answer, depends on
    /// where a mesh is once its bounds come that near.
    #[inline]
    fn note_mesh(&self, index: usize, bounds: &[Point3<f64>; 2], asked: &[Point3<f64>; 2]) {
        if bounds_meet(bounds, asked, TOUCH_MARGIN_MM) && self.needs(index) {
            self.mark(index);
        }
    }

    /// [`Obstacles::note`] where the questions are recorded.
    fn note_recorded(
        &self,
        index: usize,
        bounds: &[Point3<f64>; 2],
        segment: (&Point3<f64>, &Point3<f64>, f64),
        asked: &[Point3<f64>; 2],
    ) {
        if !bounds_meet(bounds, asked, TOUCH_MARGIN_MM) || !self.needs(index) {
            return;
        }
        let (a, b, r_mm) = segment;
        let grown = Vector3::repeat(TOUCH_MARGIN_MM);
        let [lo, hi] = [bounds[0] - grown, bounds[1] + grown];
        let aabb = Cuboid {
            centre: nalgebra::center(&lo, &hi),
            half_mm: (hi - lo) / 2.0,
            yaw_rad: 0.0,
        };
        // A little more than the exact tests count, to be safe.
        if aabb.distance_to_segment(a, b) < r_mm.max(0.0) + 1e-6 {
            self.mark(index);
        }
    }

    /// These obstacles but for `removed` (the room's obstacles and sides
    /// among them): what a search asks to learn whether one of them is
    /// what stopped it. A removed box keeps its index, with no extent.
    pub fn without(&self, removed: &[Blocker]) -> Obstacles {
        let mut rest = self.clone();
        let mut boxes = rest.boxes.to_vec();
        for (i, (_, _, bounds)) in boxes.iter_mut().enumerate() {
            if removed.contains(&Blocker::Obstacle(i)) {
                *bounds = NO_EXTENT;
            }
        }
        rest.boxes = boxes.into();
        let meshes = rest
            .meshes
            .iter()
            .filter(|m| !removed.contains(&Blocker::Obstacle(m.index)));
        rest.meshes = meshes.cloned().collect();
        rest.walls.retain(|w| !removed.contains(&Blocker::Wall(*w)));
        rest
    }

    /// Which of the room's obstacles and sides these are, hashed (not
    /// where they are: what a kept solve depends on of them is recorded
    /// as it asks, `touched.rs`): the room's all, or some left out
    /// ([`Obstacles::without`], [`Obstacles::none_of`]), and the
    /// clearance asked.
    pub fn variant(&self) -> u64 {
        use std::hash::{Hash, Hasher};
        let mut h = std::collections::hash_map::DefaultHasher::new();
        let removed = (self.boxes.iter().enumerate()).filter(|(_, (_, _, b))| !has_extent(b));
        removed.for_each(|(i, _)| i.hash(&mut h));
        self.boxes.len().hash(&mut h);
        self.meshes.iter().for_each(|m| m.index.hash(&mut h));
        self.meshes.len().hash(&mut h);
        self.walls.hash(&mut h);
        self.clearance_mm.to_bits().hash(&mut h);
        h.finish()
    }

    /// None of the room's obstacles or sides, in a room of this size.
    pub fn none_of(&self) -> Obstacles {
        Obstacles {
            size_mm: self.size_mm,
            clearance_mm: self.clearance_mm,
            charged: self.charged,
            ..Obstacles::default()
        }
    }

    /// How many boxes and meshes a check is charged for: the room's,
    /// whichever of them a search leaves out, so that a task's work
    /// depends on the room only through their number.
    pub fn count(&self) -> usize {
        self.charged
    }

    /// The name of the room's obstacle `index` (as the hits give it): an
    /// obstacle whose name is asked for counts as touched.
    pub fn name(&self, index: usize) -> &str {
        self.mark(index);
        match self.boxes.get(index) {
            Some((name, ..)) => name,
            None => self
                .meshes
                .iter()
                .find(|m| m.index == index)
                .map_or("", |m| m.name.as_str()),
        }
    }

    /// The first obstacle (boxes, then meshes, then the room's sides) that
    /// `capsule` (in the room frame) overlaps.
    pub fn capsule_hit(&self, capsule: &Capsule) -> Option<Blocker> {
        // `capsule_hits(capsule).next()`, written out: the hottest check
        // of every solve, whose speed should not hang on whether the
        // compiler inlines the iterator's closures (a build that did not
        // ran the kitchen example 10 % slower).
        let r = capsule.radius_mm + self.clearance_mm;
        let [clo, chi] = capsule.bounds();
        let grown = Vector3::repeat(self.clearance_mm);
        let asked = [clo - grown, chi + grown];
        let segment = (&capsule.a, &capsule.b, r);
        let reach = |[lo, hi]: &[Point3<f64>; 2]| {
            (0..3)
                .all(|i| chi[i] + self.clearance_mm >= lo[i] && clo[i] - self.clearance_mm <= hi[i])
        };
        let touches = |d: f64| d < r.max(1e-9);
        self.ask(&asked);
        for (i, (_, cuboid, bounds)) in self.boxes.iter().enumerate() {
            self.note(i, bounds, segment, &asked);
            if reach(bounds)
                && segment_meets_box(&capsule.a, &capsule.b, bounds, r)
                && touches(cuboid.distance_to_segment(&capsule.a, &capsule.b))
            {
                return Some(Blocker::Obstacle(i));
            }
        }
        for m in self.meshes.iter() {
            self.note_mesh(m.index, &m.bounds, &asked);
            if reach(&m.bounds) && self.mesh_touches(m, capsule, r.max(1e-9), reach) {
                return Some(Blocker::Obstacle(m.index));
            }
        }
        self.walls_hit(capsule, r).next()
    }

    /// Every obstacle `capsule` overlaps, in that order (lazily: the first
    /// costs what it costs to find).
    pub fn capsule_hits<'a>(&'a self, capsule: &'a Capsule) -> impl Iterator<Item = Blocker> + 'a {
        let r = capsule.radius_mm + self.clearance_mm;
        let [clo, chi] = capsule.bounds();
        let grown = Vector3::repeat(self.clearance_mm);
        let asked = [clo - grown, chi + grown];
        let segment = (&capsule.a, &capsule.b, r);
        let reach = move |[lo, hi]: &[Point3<f64>; 2]| {
            (0..3)
                .all(|i| chi[i] + self.clearance_mm >= lo[i] && clo[i] - self.clearance_mm <= hi[i])
        };
        let touches = move |d: f64| d < r.max(1e-9);
        self.ask(&asked);
        let boxes = self
            .boxes
            .iter()
            .enumerate()
            .filter_map(move |(i, (_, cuboid, bounds))| {
                self.note(i, bounds, segment, &asked);
                (reach(bounds)
                    && segment_meets_box(&capsule.a, &capsule.b, bounds, r)
                    && touches(cuboid.distance_to_segment(&capsule.a, &capsule.b)))
                .then_some(Blocker::Obstacle(i))
            });
        let meshes = self.meshes.iter().filter_map(move |m| {
            self.note_mesh(m.index, &m.bounds, &asked);
            (reach(&m.bounds) && self.mesh_touches(m, capsule, r.max(1e-9), reach))
                .then_some(Blocker::Obstacle(m.index))
        });
        boxes.chain(meshes).chain(self.walls_hit(capsule, r))
    }

    /// The first of the room's sides the capsule's points come within `r`
    /// of, or pass beyond.
    fn wall_hit(&self, c: &Capsule, r: f64) -> Option<Blocker> {
        self.walls_hit(c, r).next()
    }

    /// Each of the room's sides the capsule's points come within `r` of,
    /// or pass beyond.
    fn walls_hit<'a>(&'a self, c: &'a Capsule, r: f64) -> impl Iterator<Item = Blocker> + 'a {
        let size = self.size_mm;
        self.walls.iter().filter_map(move |&wall| {
            let gap = |p: &Point3<f64>| match wall {
                Wall::Floor => p.z,
                Wall::Ceiling => size.z - p.z,
                Wall::XMin => p.x,
                Wall::XMax => size.x - p.x,
                Wall::YMin => p.y,
                Wall::YMax => size.y - p.y,
            };
            (gap(&c.a).min(gap(&c.b)) < r.max(1e-9)).then_some(Blocker::Wall(wall))
        })
    }

    /// What the line of sight from `eye` to `target` meets first, and
    /// where along it (0 at the eye, 1 at the target; 0 for a box that holds
    /// the eye). The last `end_gap_mm` before the target is not checked, so
    /// that an object resting on a shelf is not hidden by the shelf.
    /// Charged as a solid's check is (`capsule_check`), and the
    /// triangles of meshes tested besides; once the run is past its limit,
    /// nothing is looked at (the answers are thrown away).
    pub fn first_on_sight_line(
        &self,
        eye: &Point3<f64>,
        target: &Point3<f64>,
        end_gap_mm: f64,
    ) -> Option<(Blocker, f64)> {
        if let Some(account) = &self.account {
            // Past the limit, the answers are thrown away.
            if account.exhausted() {
                return None;
            }
            account.spend(capsule_check(self.charged));
        }
        let length = (target - eye).norm();
        if length <= end_gap_mm {
            return None;
        }
        let max = 1.0 - end_gap_mm / length;
        let end = eye + (target - eye) * max;
        let asked = [eye.inf(&end), eye.sup(&end)];
        self.ask(&asked);
        // A segment whose bounds miss an obstacle's cannot meet it.
        let near = |i: usize, bounds: &[Point3<f64>; 2]| {
            self.note(i, bounds, (eye, &end, 0.0), &asked);
            bounds_meet(bounds, &asked, 0.0)
        };
        let boxes = self
            .boxes
            .iter()
            .enumerate()
            // A removed box has no extent (`without`).
            .filter(|(_, (_, _, bounds))| has_extent(bounds))
            .filter(|(i, (_, _, bounds))| near(*i, bounds))
            .filter_map(|(i, (_, cuboid, _))| {
                entry_along(cuboid, eye, &end).map(|t| (Blocker::Obstacle(i), t * max))
            });
        let ray = Ray::new(*eye, target - eye);
        let at = Isometry3::identity();
        let meshes = self
            .meshes
            .iter()
            .filter(|m| {
                self.note_mesh(m.index, &m.bounds, &asked);
                bounds_meet(&m.bounds, &asked, 0.0)
            })
            .filter_map(|m| {
                let toi = if m.closed && m.parts[0].shape.contains_point(&at, eye) {
                    Some(0.0)
                } else {
                    self.mesh_ray(m, &ray, max)
                };
                toi.map(|t| (Blocker::Obstacle(m.index), t))
            });
        let outside = self
            .wall_hit(&Capsule::sphere(*eye, 0.0), 0.0)
            .map(|wall| (wall, 0.0));
        boxes
            .chain(meshes)
            .chain(outside)
            .min_by(|a, b| a.1.total_cmp(&b.1).then(rank(&a.0).cmp(&rank(&b.0))))
    }

    /// Whether the capsule's segment comes within `r` of mesh `m` (or lies
    /// in it, when it is closed): each part whose bounds it `reach`es, the
    /// triangles whose bounds meet the capsule's (by the part's tree)
    /// tested until one meets it, as parry's test of a capsule and a mesh
    /// does. The triangles tested are charged ([`UNITS_PER_TRIANGLE`]);
    /// once the run is past its limit, none is tested and the mesh counts
    /// as touched.
    fn mesh_touches(
        &self,
        m: &Mesh,
        c: &Capsule,
        r: f64,
        reach: impl Fn(&[Point3<f64>; 2]) -> bool,
    ) -> bool {
        // Past the limit, the answers are thrown away: a check that could
        // test thousands of triangles is not made.
        if self.account.as_ref().is_some_and(|a| a.exhausted()) {
            return true;
        }
        let at = Isometry3::identity();
        if m.closed {
            let whole = &m.parts[0].shape;
            if whole.contains_point(&at, &c.a) || whole.contains_point(&at, &c.b) {
                return true;
            }
        }
        let swept = ParryCapsule::new(c.a, c.b, r);
        let mut tested = 0;
        let touches = (m.parts.iter())
            .filter(|p| reach(&p.bounds))
            .any(|p| part_touches(p, &swept, &mut tested));
        if let (Some(account), 1..) = (&self.account, tested) {
            account.spend(tested.saturating_mul(UNITS_PER_TRIANGLE));
        }
        touches
    }

    /// Where along `ray` (within `max`) it first meets mesh `m`'s surface:
    /// the first of each part's hits, as parry casts a ray on a mesh. The
    /// triangles tested are charged ([`UNITS_PER_RAY_TRIANGLE`]).
    fn mesh_ray(&self, m: &Mesh, ray: &Ray, max: f64) -> Option<f64> {
        let tested = Cell::new(0_u64);
        let toi = (m.parts.iter())
            .filter_map(|p| part_ray(p, ray, max, &tested))
            .min_by(f64::total_cmp);
        if let (Some(account), 1..) = (&self.account, tested.get()) {
            account.spend(tested.get().saturating_mul(UNITS_PER_RAY_TRIANGLE));
        }
        toi
    }
}

/// Where `ray` first meets a triangle of part `p` within `max`, `tested`
/// counting the triangles tested: parry's ray cast on a mesh, written out.
fn part_ray(p: &MeshPart, ray: &Ray, max: f64, tested: &Cell<u64>) -> Option<f64> {
    let at = Isometry3::identity();
    let Some(mesh) = p.shape.as_trimesh() else {
        return p.shape.cast_ray(&at, ray, max, true);
    };
    let hit = mesh.bvh().cast_ray(ray, max, |leaf, best_so_far| {
        tested.set(tested.get() + 1);
        mesh.triangle(leaf).cast_local_ray(ray, best_so_far, true)
    })?;
    (hit.1 < max).then_some(hit.1)
}

/// What testing a ray against one of a mesh's triangles costs, in units
/// of the meter: parry's ray and triangle test, a few tens of
/// nanoseconds, with its tree's walk.
const UNITS_PER_RAY_TRIANGLE: u64 = 1;

/// What testing a capsule against one of a mesh's triangles costs, in
/// units of the meter ([`Obstacles::charging`]): parry's test (GJK) takes
/// about 0.37 microseconds. Measured where it is nearly all the work: a
/// map by a person standing among 200,000 slivers, each across the room,
/// whose every check tests them all. At a unit a triangle it did 5,400
/// units a millisecond on two cores (stopped after 47 s); at six, about
/// 32,000, as the solvers do.
const UNITS_PER_TRIANGLE: u64 = 6;

/// Whether `swept` meets a triangle of part `p`, `tested` counting the
/// triangles tested: parry's test of a shape and a mesh, written out.
fn part_touches(p: &MeshPart, swept: &ParryCapsule, tested: &mut u64) -> bool {
    let at = Isometry3::identity();
    let Some(mesh) = p.shape.as_trimesh() else {
        return query::intersection_test(&at, swept, &at, p.shape.as_ref()).unwrap_or(true);
    };
    let aabb = swept.compute_aabb(&at);
    let mut leaves = mesh.bvh().leaves(|node| node.aabb().intersects(&aabb));
    leaves.any(|leaf| {
        *tested += 1;
        query::intersection_test(&at, &mesh.triangle(leaf), &at, swept) == Ok(true)
    })
}

/// Bounds that hold nothing: a box left out (`Obstacles::without`), or
/// where bounds are gathered from none.
const NO_EXTENT: [Point3<f64>; 2] = [
    Point3::new(f64::INFINITY, f64::INFINITY, f64::INFINITY),
    Point3::new(f64::NEG_INFINITY, f64::NEG_INFINITY, f64::NEG_INFINITY),
];

/// Whether `bounds` hold anything (not [`NO_EXTENT`], nor gathered from
/// nothing).
fn has_extent([lo, hi]: &[Point3<f64>; 2]) -> bool {
    lo.x <= hi.x
}

/// The bounds that hold a mesh's parts.
fn parts_bounds(parts: &[MeshPart]) -> [Point3<f64>; 2] {
    (parts.iter()).fold(NO_EXTENT, |[lo, hi], p| {
        [lo.inf(&p.bounds[0]), hi.sup(&p.bounds[1])]
    })
}

/// The bounds of a mesh: of its solid's `parts` and of every vertex it
/// lists (a triangle without area is left out of the solid, but a search
/// for why measures the mesh by its vertices).
fn mesh_bounds(m: &MeshObstacle, parts: &[MeshPart]) -> [Point3<f64>; 2] {
    let [lo, hi] = parts_bounds(parts);
    match m.vertex_bounds() {
        Some([vlo, vhi]) => [lo.inf(&vlo), hi.sup(&vhi)],
        None => [lo, hi],
    }
}

/// The bounds of each of the room's obstacles (the boxes, then the
/// meshes) as [`Obstacles`] holds them (a mesh's hold its vertices too):
/// none for a mesh with neither solid nor vertices.
pub fn obstacle_bounds(room: &Room) -> Vec<Option<[Point3<f64>; 2]>> {
    let boxes = room.boxes.iter().map(|b| Some(b.cuboid().bounds()));
    let meshes = (room.meshes.iter()).map(|m| {
        let parts = m.shape().map_or(&[][..], |s| &s.parts[..]);
        let bounds = mesh_bounds(m, parts);
        has_extent(&bounds).then_some(bounds)
    });
    boxes.chain(meshes).collect()
}

/// Whether the segment `a`-`b` passes through the box `bounds` grown by
/// `r_mm` on every side (a slab test): where it does not, it comes no
/// nearer than `r_mm` to anything inside `bounds`, and a capsule of radius
/// `r_mm` about it touches none of it. The exact distance is measured only
/// where it does: a long link (the eyes' look, metres long) has bounds
/// that take in thousands of small boxes it passes far from.
fn segment_meets_box(
    a: &Point3<f64>,
    b: &Point3<f64>,
    bounds: &[Point3<f64>; 2],
    r_mm: f64,
) -> bool {
    let (mut t0, mut t1) = (0.0_f64, 1.0_f64);
    for i in 0..3 {
        let grown = r_mm + SLAB_MARGIN_MM;
        let (lo, hi) = (bounds[0][i] - grown, bounds[1][i] + grown);
        let d = b[i] - a[i];
        if d == 0.0 {
            if a[i] < lo || a[i] > hi {
                return false;
            }
            continue;
        }
        let (ta, tb) = ((lo - a[i]) / d, (hi - a[i]) / d);
        t0 = t0.max(ta.min(tb));
        t1 = t1.min(ta.max(tb));
        if t0 > t1 {
            return false;
        }
    }
    true
}

/// How much more than the radius the slab test grows a box by: far more
/// than the rounding of the test, far less than anything measured.
const SLAB_MARGIN_MM: f64 = 1e-6;

/// Obstacles before walls, and by index, where two are met at once.
fn rank(b: &Blocker) -> (u8, usize) {
    match b {
        Blocker::Obstacle(i) => (0, *i),
        _ => (1, 0),
    }
}

/// Where along the segment `a`-`b` (0 to 1) it first enters `cuboid`.
fn entry_along(cuboid: &Cuboid, a: &Point3<f64>, b: &Point3<f64>) -> Option<f64> {
    if cuboid.distance_to_segment(a, b) > 0.0 {
        return None;
    }
    if cuboid.contains(a) {
        return Some(0.0);
    }
    // The entry is where the distance from the start first reaches zero:
    // the distance from a to the part of the segment up to t falls with t.
    let (mut lo, mut hi) = (0.0, 1.0);
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if cuboid.distance_to_segment(a, &(a + (b - a) * mid)) > 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Some(hi)
}

#[cfg(test)]
mod tests {
    use super::*;

    proptest::proptest! {
        /// The slab test passes over no box a capsule touches: wherever the
        /// segment comes within the radius of a box, it passes through
        /// the box grown by the radius.
        #[test]
        fn the_slab_test_keeps_every_box_a_capsule_touches(
            a in proptest::array::uniform3(-500.0..500.0f64),
            b in proptest::array::uniform3(-500.0..500.0f64),
            half in proptest::array::uniform3(1.0..200.0f64),
            r_mm in 0.0..100.0f64,
        ) {
            let cuboid = Cuboid {
                centre: Point3::origin(),
                half_mm: Vector3::from(half),
                yaw_rad: 0.0,
            };
            let (a, b) = (Point3::from(a), Point3::from(b));
            if cuboid.distance_to_segment(&a, &b) < r_mm {
                proptest::prop_assert!(segment_meets_box(&a, &b, &cuboid.bounds(), r_mm));
            }
        }
    }
    use crate::scene::BoxObstacle;

    /// The obstacle a line (a capsule of no radius) meets, by index; the
    /// walls left out.
    fn line_hit(o: &Obstacles, a: [f64; 3], b: [f64; 3]) -> Option<usize> {
        match o.capsule_hit(&Capsule::new(Point3::from(a), Point3::from(b), 0.0)) {
            Some(Blocker::Obstacle(i)) => Some(i),
            _ => None,
        }
    }

    #[test]
    fn a_capsule_meets_what_is_within_its_radius_and_the_room_sides() {
        let o = Obstacles::new(
            &room_with(vec![block("b", [1000.0, 1000.0, 0.0], [100.0; 3], 0.0)]),
            0.0,
        );
        let arm = |y: f64, r: f64| {
            o.capsule_hit(&Capsule::new(
                Point3::new(900.0, y, 50.0),
                Point3::new(1200.0, y, 50.0),
                r,
            ))
        };
        assert_eq!(
            arm(1130.0, 40.0),
            Some(Blocker::Obstacle(0)),
            "30 mm away, radius 40"
        );
        assert_eq!(arm(1150.0, 40.0), None, "50 mm away");
        let low = o.capsule_hit(&Capsule::new(
            Point3::new(2000.0, 2000.0, 30.0),
            Point3::new(2100.0, 2000.0, 500.0),
            40.0,
        ));
        assert_eq!(low, Some(Blocker::Wall(Wall::Floor)));
        let clear = o.capsule_hit(&Capsule::new(
            Point3::new(2000.0, 2000.0, 50.0),
            Point3::new(2100.0, 2000.0, 500.0),
            40.0,
        ));
        assert_eq!(clear, None);
    }

    fn room_with(boxes: Vec<BoxObstacle>) -> Room {
        Room {
            name: "r".into(),
            size_mm: Vector3::new(4000.0, 4000.0, 2500.0),
            boxes,
            meshes: Vec::new(),
            targets: vec![],
            surfaces: vec![],
            doors: Vec::new(),
        }
    }

    fn block(name: &str, corner: [f64; 3], size: [f64; 3], yaw_rad: f64) -> BoxObstacle {
        BoxObstacle {
            name: name.into(),
            corner_mm: Point3::from(corner),
            size_mm: Vector3::from(size),
            yaw_rad,
        }
    }

    #[test]
    fn a_segment_through_a_box_hits_it_and_one_beside_it_does_not() {
        let o = Obstacles::new(
            &room_with(vec![block("b", [0.0, 0.0, 0.0], [100.0; 3], 0.0)]),
            0.0,
        );
        let hit = |a: [f64; 3], b: [f64; 3]| line_hit(&o, a, b);
        assert_eq!(hit([-50.0, 50.0, 50.0], [150.0, 50.0, 50.0]), Some(0));
        assert_eq!(
            hit([50.0, 50.0, 50.0], [60.0, 60.0, 60.0]),
            Some(0),
            "inside"
        );
        assert_eq!(hit([-50.0, 50.0, 150.0], [150.0, 50.0, 150.0]), None);
        assert_eq!(
            hit([-50.0, 50.0, 50.0], [-10.0, 50.0, 50.0]),
            None,
            "stops short"
        );
    }

    #[test]
    fn questions_mark_the_obstacles_they_come_within_the_margin_of() {
        let boxes = vec![
            block("near", [500.0, 500.0, 500.0], [100.0; 3], 0.0),
            block("far", [1500.0, 500.0, 500.0], [100.0; 3], 0.0),
            block("named", [2500.0, 500.0, 500.0], [100.0; 3], 0.0),
        ];
        let touched = Arc::new(Touched::new(boxes.len()));
        let o = Obstacles::new(&room_with(boxes), 0.0).recording(Some(&touched));
        // A capsule 3 mm clear of `near`'s side: no hit, but within the
        // margin; `far` is not near it.
        let c = Capsule::new(
            Point3::new(487.0, 550.0, 550.0),
            Point3::new(487.0, 550.0, 580.0),
            10.0,
        );
        assert_eq!(o.capsule_hit(&c), None);
        o.name(2);
        let set = touched.set();
        assert!(set.contains(0) && set.contains(2));
        assert!(!set.contains(1));
        // Farther than the margin: not marked.
        let quiet = Arc::new(Touched::new(3));
        let o = o.recording(Some(&quiet));
        let away = Capsule::new(
            Point3::new(470.0, 550.0, 550.0),
            Point3::new(470.0, 550.0, 580.0),
            10.0,
        );
        assert_eq!(o.capsule_hit(&away), None);
        assert!(!quiet.set().contains(0));
    }

    /// A closed cube of side 100 mm at the origin, faces outwards.
    fn cube_mesh() -> crate::scene::MeshObstacle {
        let v: Vec<Point3<f64>> = (0..8)
            .map(|i| {
                Point3::new(
                    f64::from(i >> 2) * 100.0,
                    f64::from((i >> 1) & 1) * 100.0,
                    f64::from(i & 1) * 100.0,
                )
            })
            .collect();
        let quads = [
            [0, 2, 6, 4],
            [1, 5, 7, 3],
            [0, 4, 5, 1],
            [2, 3, 7, 6],
            [0, 1, 3, 2],
            [4, 6, 7, 5],
        ];
        let triangles: Vec<[u32; 3]> = quads
            .iter()
            .flat_map(|q| [[q[0], q[1], q[2]], [q[0], q[2], q[3]]])
            .collect();
        crate::scene::MeshObstacle::new("cube".into(), v, &triangles)
    }

    /// `n` thin horizontal triangles, one above another, along the
    /// diagonal of a 2 m square: each one's bounds take in the square.
    fn slivers(n: u32) -> crate::scene::MeshObstacle {
        let mut v = Vec::new();
        let mut triangles = Vec::new();
        for k in 0..n {
            let z = 100.0 + 10.0 * f64::from(k);
            v.extend([
                Point3::new(0.0, 0.0, z),
                Point3::new(2000.0, 2000.0, z),
                Point3::new(2000.0, 2001.0, z),
            ]);
            triangles.push([3 * k, 3 * k + 1, 3 * k + 2]);
        }
        crate::scene::MeshObstacle::new("slivers".into(), v, &triangles)
    }

    #[test]
    fn a_check_is_charged_for_each_triangle_of_a_mesh_it_tests() {
        let mut room = room_with(Vec::new());
        room.meshes.push(slivers(100));
        let run = crate::meter::RunWork::new(u64::MAX);
        let allowance = crate::meter::Meter::of(&run);
        let o = Obstacles::new(&room, 0.0).charging(&allowance);
        // Beside every sliver's bounds' diagonal, 700 mm from each.
        let upright = Capsule::new(
            Point3::new(1500.0, 500.0, 50.0),
            Point3::new(1500.0, 500.0, 1200.0),
            40.0,
        );
        assert_eq!(o.capsule_hit(&upright), None);
        assert_eq!(allowance.spent(), 100 * UNITS_PER_TRIANGLE);
        assert_eq!(run.spent(), 100 * UNITS_PER_TRIANGLE);
        // Far from their bounds: none tested, nothing charged.
        let aside = Capsule::sphere(Point3::new(3000.0, 3000.0, 500.0), 40.0);
        assert_eq!(o.capsule_hit(&aside), None);
        assert_eq!(allowance.spent(), 100 * UNITS_PER_TRIANGLE);
        // Uncharged obstacles charge nothing.
        assert_eq!(Obstacles::new(&room, 0.0).capsule_hit(&upright), None);
        assert_eq!(allowance.spent(), 100 * UNITS_PER_TRIANGLE);
    }

    #[test]
    fn a_sight_line_is_charged_for_the_triangles_it_is_tested_against() {
        let mut room = room_with(Vec::new());
        room.meshes.push(slivers(100));
        let run = crate::meter::RunWork::new(1_000);
        let allowance = crate::meter::Meter::of(&run);
        let o = Obstacles::new(&room, 0.0).charging(&allowance);
        // Up through every sliver's bounds, 700 mm from each sliver.
        let (eye, target) = (
            Point3::new(1500.0, 500.0, 50.0),
            Point3::new(1500.0, 500.0, 1200.0),
        );
        assert_eq!(o.first_on_sight_line(&eye, &target, 0.0), None);
        let line = capsule_check(1);
        assert_eq!(allowance.spent(), line + 100 * UNITS_PER_RAY_TRIANGLE);
        // Up through the slivers themselves: met at the first, as uncharged.
        let (low, high) = (
            Point3::new(1000.0, 1000.2, 50.0),
            Point3::new(1000.0, 1000.2, 1200.0),
        );
        let uncharged = Obstacles::new(&room, 0.0).first_on_sight_line(&low, &high, 0.0);
        assert!(uncharged.is_some());
        assert_eq!(o.first_on_sight_line(&low, &high, 0.0), uncharged);
        // Past the limit, nothing is looked at or charged.
        run.charge(10_000);
        let spent = allowance.spent();
        assert_eq!(o.first_on_sight_line(&low, &high, 0.0), None);
        assert_eq!(allowance.spent(), spent);
    }

    #[test]
    fn a_mesh_is_hit_through_and_within() {
        let mut room = room_with(vec![block("b", [1000.0; 3], [10.0; 3], 0.0)]);
        room.meshes.push(cube_mesh());
        let o = Obstacles::new(&room, 0.0);
        let hit = |a: [f64; 3], b: [f64; 3]| line_hit(&o, a, b);
        assert_eq!(
            hit([-50.0, 50.0, 50.0], [150.0, 50.0, 50.0]),
            Some(1),
            "through"
        );
        assert_eq!(
            hit([40.0, 50.0, 50.0], [60.0, 50.0, 50.0]),
            Some(1),
            "inside"
        );
        assert_eq!(
            hit([-50.0, 50.0, 150.0], [150.0, 50.0, 150.0]),
            None,
            "above"
        );
        assert_eq!(o.name(1), "cube");
    }

    #[test]
    fn a_turned_box_is_turned_about_its_corner() {
        // Turned 90 degrees, the box spans x from -100 to 0.
        let b = block(
            "b",
            [0.0, 0.0, 0.0],
            [100.0, 10.0, 100.0],
            std::f64::consts::FRAC_PI_2,
        );
        let o = Obstacles::new(&room_with(vec![b]), 0.0);
        let at = |x: f64, y: f64| line_hit(&o, [x, y, 1.0], [x, y, 50.0]);
        assert_eq!(at(-5.0, 50.0), Some(0));
        assert_eq!(at(5.0, 50.0), None);
    }

    #[test]
    fn the_sight_line_names_the_nearest_blocker_and_spares_the_shelf_under_the_target() {
        // Along x at y = 1000, z = 50, from x = 1000.
        let room = room_with(vec![
            block("far", [1200.0, 950.0, 0.0], [10.0, 100.0, 100.0], 0.0),
            block("near", [1100.0, 950.0, 0.0], [10.0, 100.0, 100.0], 0.0),
            block("shelf", [1300.0, 950.0, 0.0], [100.0, 100.0, 50.0], 0.0),
        ]);
        let o = Obstacles::new(&room, 0.0);
        let eye = Point3::new(1000.0, 1000.0, 50.0);
        let (blocker, at) = o
            .first_on_sight_line(&eye, &Point3::new(1350.0, 1000.0, 50.0), 10.0)
            .unwrap();
        assert_eq!(blocker, Blocker::Obstacle(1), "near");
        assert!((at - 100.0 / 350.0).abs() < 1e-6, "{at}");
        let above_shelf = Point3::new(1350.0, 1000.0, 55.0);
        let from_above = Point3::new(1350.0, 1000.0, 500.0);
        assert_eq!(o.first_on_sight_line(&from_above, &above_shelf, 10.0), None);
        let inside = Point3::new(1105.0, 1000.0, 50.0);
        let seen = o.first_on_sight_line(&inside, &Point3::new(1000.0, 1000.0, 50.0), 10.0);
        assert_eq!(
            seen,
            Some((Blocker::Obstacle(1), 0.0)),
            "an eye inside a box sees nothing"
        );
        let outside = Point3::new(-5.0, 1000.0, 50.0);
        let seen = o.first_on_sight_line(&outside, &eye, 10.0);
        assert_eq!(
            seen,
            Some((Blocker::Wall(Wall::XMin), 0.0)),
            "nor one beyond a wall"
        );
    }
}
