//! The scene a report answers about, as the data the HTML page and the
//! glTF scene draw: each
//! room's boxes, meshes, surfaces and targets, and for each task the
//! person's solids in the reported posture where the base stood, the
//! target's result, a gaze's line of sight and what blocked it, a map's
//! cells graded by how far short each point fell, and the joints held at
//! a limit. Numbers are rounded (0.1 mm, 0.1 degree) so the page is the
//! same bytes on every run.

use super::{advice_grid_plot, advice_plot};
use nalgebra::{IsometryMatrix3, Point3, Vector3};
use serde::Serialize;

mod simplify;

use super::colours::{SHARES, THROUGH_MARK};
use crate::figure;
use crate::geometry::{Cuboid, Shape};
use crate::kinematics::{Body, JointKind};
use crate::plugin::{FormatScene, TaskPlace};
use crate::report::{
    fixed, AdviceReport, FloorShape, MapReport, PopulationReport, Report, StandardReport,
    TaskReport,
};
use crate::scene::{BasePose, Door, Room, Wall};
use simplify::simplified;

/// Most triangles of all meshes drawn; larger meshes are simplified.
const MESH_TRIANGLE_BUDGET: usize = 150_000;
/// A joint this close to a limit (degrees, or mm if it slides) is marked.
const AT_LIMIT: f64 = 1.0;

#[derive(Serialize)]
pub struct ViewData {
    pub title: String,
    pub rooms: Vec<RoomView>,
    pub tasks: Vec<TaskView>,
    /// How a population's map colours a point by its share: the least
    /// share of each band, its colour and its name, as the SVG maps have
    /// them.
    pub share_bands: Vec<(f64, &'static str, &'static str)>,
    /// The scenario's expectations, met or not and why.
    pub expectations: Vec<crate::report::ExpectationReport>,
}

#[derive(Serialize)]
pub struct RoomView {
    pub name: String,
    pub size: [f64; 3],
    pub boxes: Vec<BoxView>,
    pub meshes: Vec<MeshView>,
    pub surfaces: Vec<SurfaceView>,
    pub targets: Vec<Labelled>,
    /// Each door's opening on the floor: its two ends.
    pub doors: Vec<DoorView>,
}

#[derive(Serialize)]
pub struct DoorView {
    pub name: String,
    pub from: [f64; 2],
    pub to: [f64; 2],
}

#[derive(Serialize)]
pub struct BoxView {
    pub name: String,
    pub corner: [f64; 3],
    pub size: [f64; 3],
    pub yaw_deg: f64,
}

impl BoxView {
    /// The box as a solid, turned about its corner as `BoxObstacle` is.
    pub fn cuboid(&self) -> Cuboid {
        Cuboid::from_corner(
            Point3::from(self.corner),
            Vector3::from(self.size),
            self.yaw_deg.to_radians(),
        )
    }
}

#[derive(Serialize)]
pub struct MeshView {
    pub name: String,
    /// x, y, z per vertex, mm.
    pub positions: Vec<f64>,
    pub indices: Vec<u32>,
    /// The triangles of the mesh itself where it was simplified to draw.
    pub simplified_from: Option<usize>,
}

#[derive(Serialize)]
pub struct SurfaceView {
    pub name: String,
    pub corner: [f64; 3],
    pub u: [f64; 3],
    pub v: [f64; 3],
}

#[derive(Serialize)]
pub struct Labelled {
    pub name: String,
    pub at: [f64; 3],
}

#[derive(Serialize)]
pub struct TaskView {
    /// `reach mug by ann`.
    pub label: String,
    pub room: usize,
    pub ok: bool,
    /// Present and true where the run's work limit stopped it before this
    /// task: nothing was looked for (drawn grey, not as a failure).
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub not_evaluated: bool,
    pub verdict: String,
    /// The text report's lines for this task.
    pub details: String,
    /// The person's solids, where a posture was reported.
    pub solids: Vec<SolidView>,
    /// Joints at a limit: where they are and what they are.
    pub strained: Vec<Labelled>,
    /// What the task asked about: a target's point.
    pub target: Option<[f64; 3]>,
    /// The hand's point the posture reached.
    pub reached: Option<[f64; 3]>,
    /// Where the base put the hip: x, y, z (mm) and heading (degrees).
    pub base: Option<[f64; 4]>,
    pub sight: Option<SightView>,
    /// The obstacle a posture or a line of sight met.
    pub blocked_by: Option<String>,
    pub cells: Option<CellsView>,
    /// An advice's plot (every group's share against the position), SVG.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub plot: Option<String>,
    /// An advice's target where it serves the most (its boxes are drawn
    /// there among `solids`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub advised: Option<Labelled>,
    /// What a standard's rules measured: areas and circles on the floor,
    /// elements, each green where its rule holds and red where not.
    pub marks: Vec<MarkView>,
    /// Where the room has doors: the floor the base's hip point can get to
    /// from one, at the heading it was placed at (polygons' outlines; the
    /// holes as outlines too).
    pub routes: Vec<Vec<[f64; 2]>>,
}

#[derive(Serialize)]
#[serde(tag = "kind", rename_all = "lowercase")]
pub enum MarkView {
    /// A polygon on the floor (a clear floor space, a T turning space).
    Area {
        label: String,
        ok: bool,
        points: Vec<[f64; 2]>,
    },
    /// A circle on the floor (a round turning space).
    Circle {
        label: String,
        ok: bool,
        centre: [f64; 2],
        radius: f64,
    },
    /// A point in the room (an element the rules are about).
    Point {
        label: String,
        ok: bool,
        at: [f64; 3],
    },
}

#[derive(Serialize)]
#[serde(tag = "kind", rename_all = "lowercase")]
pub enum SolidView {
    Capsule {
        name: String,
        a: [f64; 3],
        b: [f64; 3],
        r: f64,
        color: String,
        opacity: f64,
    },
    Box {
        name: String,
        centre: [f64; 3],
        half: [f64; 3],
        yaw_deg: f64,
        color: String,
        opacity: f64,
    },
}

#[derive(Serialize)]
pub struct SightView {
    pub eyes: [f64; 3],
    pub target: [f64; 3],
    pub ok: bool,
}

#[derive(Serialize)]
pub struct CellsView {
    /// `reach` (graded by how far short), `gaze` (seen or not) or `share`
    /// (a population's: by the share of its people who reach it).
    pub of: &'static str,
    pub step: f64,
    pub u: [f64; 3],
    pub v: [f64; 3],
    /// Each point: x, y, z, and how far short it fell (mm, 0 if reached),
    /// or the share of the population who reach it.
    pub points: Vec<[f64; 4]>,
}

/// The view's data for `report` over `scene`.
pub fn view_data(report: &Report, scene: &FormatScene<'_>) -> ViewData {
    let advices = report.advices_by_target();
    let plot = |task: &TaskReport| match task {
        TaskReport::Advice(a) if !a.rows.is_empty() => Some(advice_grid_plot::svg(a)),
        TaskReport::Advice(a) => (advices.iter())
            .find(|(_, each)| each.iter().any(|e| std::ptr::eq(*e, a.as_ref())))
            .map(|(_, each)| advice_plot::svg(each)),
        _ => None,
    };
    ViewData {
        title: report.file.clone(),
        rooms: room_views(scene.rooms),
        tasks: report
            .tasks
            .iter()
            .zip(&scene.tasks)
            .map(|(task, place)| TaskView {
                plot: plot(task),
                ..task_view(task, place, scene)
            })
            .collect(),
        share_bands: SHARES
            .iter()
            // JSON has no infinity: the last band starts at zero.
            .map(|&(least, colour, name)| (least.max(0.0), colour, name))
            .collect(),
        expectations: report.expectations.clone(),
    }
}

/// The rooms as drawn, their large meshes simplified for the picture.
pub fn room_views(rooms: &[Room]) -> Vec<RoomView> {
    let budget = mesh_budget(rooms);
    rooms.iter().map(|r| room_view(r, budget)).collect()
}

/// Triangles per mesh when all of them would exceed the budget.
fn mesh_budget(rooms: &[Room]) -> Option<usize> {
    let meshes = rooms.iter().flat_map(|r| &r.meshes);
    let total: usize = meshes.clone().map(|m| m.triangles.len()).sum();
    let count = meshes.count().max(1);
    (total > MESH_TRIANGLE_BUDGET).then_some(MESH_TRIANGLE_BUDGET / count)
}

fn room_view(room: &Room, budget: Option<usize>) -> RoomView {
    RoomView {
        name: room.name.clone(),
        size: v3(&room.size_mm),
        boxes: room
            .boxes
            .iter()
            .map(|b| BoxView {
                name: b.name.clone(),
                corner: p3(&b.corner_mm),
                size: v3(&b.size_mm),
                yaw_deg: deg(b.yaw_rad),
            })
            .collect(),
        meshes: room
            .meshes
            .iter()
            .map(|m| {
                let (vertices, indices, from) = match budget {
                    Some(most) if m.triangles.len() > most => {
                        let (v, t) = simplified(&m.vertices_mm, &m.triangles, most);
                        (v, t, Some(m.triangles.len()))
                    }
                    _ => (m.vertices_mm.clone(), m.triangles.clone(), None),
                };
                MeshView {
                    name: m.name.clone(),
                    positions: vertices.iter().flat_map(p3).collect(),
                    indices: indices.into_iter().flatten().collect(),
                    simplified_from: from,
                }
            })
            .collect(),
        surfaces: room
            .surfaces
            .iter()
            .map(|s| SurfaceView {
                name: s.name.clone(),
                corner: p3(&s.corner_mm),
                u: v3(&s.u_mm),
                v: v3(&s.v_mm),
            })
            .collect(),
        targets: room
            .targets
            .iter()
            .map(|t| Labelled {
                name: t.name.clone(),
                at: p3(&t.position_mm),
            })
            .collect(),
        doors: room.doors.iter().map(|d| door_view(d, room)).collect(),
    }
}

/// A door's opening: its ends on the floor.
fn door_view(d: &Door, room: &Room) -> DoorView {
    let [lo, hi] = d.span_mm().map(mm);
    let (sx, sy) = (mm(room.size_mm.x), mm(room.size_mm.y));
    let (from, to) = match d.wall {
        Wall::XMin => ([0.0, lo], [0.0, hi]),
        Wall::XMax => ([sx, lo], [sx, hi]),
        Wall::YMin => ([lo, 0.0], [hi, 0.0]),
        _ => ([lo, sy], [hi, sy]),
    };
    DoorView {
        name: d.name.clone(),
        from,
        to,
    }
}

fn task_view(task: &TaskReport, place: &TaskPlace, scene: &FormatScene<'_>) -> TaskView {
    let answer = task.answer();
    let mut details = String::new();
    task.details(&mut details);
    let label = match answer.task {
        // `standard ada2010 in kitchen`
        "standard" => format!("{} {} {}", answer.task, answer.subject, answer.person),
        _ => format!("{} {} by {}", answer.task, answer.subject, answer.person),
    };
    let mut view = TaskView {
        label,
        room: place.room,
        ok: answer.ok,
        not_evaluated: matches!(task, TaskReport::NotEvaluated(_)),
        verdict: answer.verdict.clone(),
        details: details.trim().to_string(),
        solids: Vec::new(),
        strained: Vec::new(),
        target: None,
        reached: None,
        base: None,
        sight: None,
        blocked_by: None,
        cells: None,
        plot: None,
        advised: None,
        marks: Vec::new(),
        routes: Vec::new(),
    };
    let mut postures = Vec::new();
    match task {
        TaskReport::Reach(r) => {
            view.target = Some(r.target_mm);
            view.reached = Some(r.effector_mm);
            view.blocked_by.clone_from(&r.collision);
            postures.push((&r.base, &r.posture));
        }
        TaskReport::Gaze(g) => {
            view.target = Some(g.target_mm);
            view.sight = Some(SightView {
                eyes: g.eyes_mm,
                target: g.target_mm,
                ok: g.ok,
            });
            view.blocked_by = g.occluded_by.clone().or_else(|| g.collision.clone());
            postures.push((&g.base, &g.posture));
        }
        TaskReport::ReachAndGaze(rg) => {
            view.target = Some(rg.reach.target_mm);
            view.reached = Some(rg.reach.effector_mm);
            view.sight = Some(SightView {
                eyes: rg.gaze.eyes_mm,
                target: rg.gaze.target_mm,
                ok: rg.gaze.ok,
            });
            view.blocked_by = (rg.reach.collision.clone())
                .or_else(|| rg.gaze.occluded_by.clone())
                .or_else(|| rg.gaze.collision.clone());
            postures.push((&rg.reach.base, &rg.reach.posture));
            postures.push((&rg.gaze.base, &rg.gaze.posture));
        }
        TaskReport::Map(m) => view.cells = Some(cells(m)),
        // No person is placed: the room and the words say it.
        TaskReport::NotPlaced(_) => {}
        // Nothing was looked for: the words say so.
        TaskReport::NotEvaluated(_) => {}
        // Many people: the words say the share, and a map's cells show
        // each point's.
        TaskReport::Population(p) => view.cells = share_cells(p),
        TaskReport::Standard(s) => view.marks = standard_marks(s),
        // The element where it serves the most.
        TaskReport::Advice(a) => {
            let room = &scene.rooms[place.room];
            view.target = a.best_target_mm();
            view.solids = advised_boxes(a, room);
            view.advised = (a.best_target_mm())
                .zip(a.best_words())
                .map(|(at, words)| Labelled {
                    name: format!("{} {words}: the advised position", a.name),
                    at,
                });
        }
    }
    if let Some(&(base, _)) = postures.first() {
        let person = place.person;
        let body = &scene.persons[person].body;
        let mut q: Vec<f64> = body.joints.iter().map(|j| j.neutral).collect();
        for (_, posture) in &postures {
            set_posture(body, &mut q, &posture.0);
        }
        let pose = base.pose();
        view.base = Some([base.x_mm, base.y_mm, base.z_mm, base.heading_deg]);
        let room = &scene.rooms[place.room];
        if let Some(floor) = scene.bases[person].reached_floor(room, pose.heading_rad) {
            view.routes = outlines(&floor);
        }
        let own = scene.bases[person].own_body();
        view.solids = figure::person(body, &q, pose, own)
            .into_iter()
            .map(|item| solid_view(item.shape, item.label, item.fill, item.opacity))
            .collect();
        let moved: Vec<&str> = postures
            .iter()
            .flat_map(|(_, p)| p.0.iter().map(|(name, _)| name.as_str()))
            .collect();
        view.strained = strained(body, &q, pose, &moved);
    }
    view
}

/// `q` with the reported values (degrees, or mm for a sliding joint) of
/// the joints named.
fn set_posture(body: &Body, q: &mut [f64], values: &[(String, f64)]) {
    for (name, value) in values {
        if let Some(j) = body.joints.iter().position(|j| &j.name == name) {
            q[j] = match body.joints[j].kind {
                JointKind::Revolute => value.to_radians(),
                JointKind::Prismatic => *value,
            };
        }
    }
}

/// The joints of `body` within [`AT_LIMIT`] of a limit in posture `q`, at
/// their place in the room.
fn strained(body: &Body, q: &[f64], pose: BasePose, moved: &[&str]) -> Vec<Labelled> {
    let mut marks = Vec::new();
    let mut marked = vec![false; body.joints.len()];
    for index in 0..body.effectors.len() {
        let path = body.path(body.effectors[index].joint);
        let mut frame = IsometryMatrix3::identity();
        for &j in &path {
            let joint = &body.joints[j];
            let shown = |x: f64| match joint.kind {
                JointKind::Revolute => x.to_degrees(),
                JointKind::Prismatic => x,
            };
            let margin = shown(q[j] - joint.min).min(shown(joint.max - q[j]));
            let at = pose.to_room(&Point3::from(frame.translation.vector));
            let strains = margin <= AT_LIMIT && moved.contains(&joint.name.as_str());
            if strains && !std::mem::replace(&mut marked[j], true) {
                let which = if shown(q[j] - joint.min) <= AT_LIMIT {
                    "least"
                } else {
                    "most"
                };
                marks.push(Labelled {
                    name: format!("{} at its {which}", joint.name),
                    at: p3(&at),
                });
            }
            frame *= joint.transform(q[j]);
        }
    }
    marks
}

/// The boxes advice `a` moves with its target, where they stand with the
/// target at its best position: see-through green over the room's own.
fn advised_boxes(a: &AdviceReport, room: &Room) -> Vec<SolidView> {
    let (Some(best_mm), Some(words)) = (a.best_target_mm(), a.best_words()) else {
        return Vec::new();
    };
    let by_mm = Vector3::from(best_mm) - Vector3::from(a.target_mm);
    (room.boxes.iter())
        .filter(|b| a.carries.contains(&b.name))
        .map(|b| {
            let mut cuboid = b.cuboid();
            cuboid.centre += by_mm;
            let name = format!("{} with the target {words}", b.name);
            solid_view(Shape::Cuboid(cuboid), name, ADVISED_COLOUR.into(), 0.45)
        })
        .collect()
}

/// The element at its advised position (the page's "reached" green).
const ADVISED_COLOUR: &str = "#2e9e4f";

fn solid_view(shape: Shape, name: String, color: String, opacity: f64) -> SolidView {
    match shape {
        Shape::Capsule(c) => SolidView::Capsule {
            name,
            a: p3(&c.a),
            b: p3(&c.b),
            r: mm(c.radius_mm),
            color,
            opacity,
        },
        Shape::Cuboid(c) => SolidView::Box {
            name,
            centre: p3(&c.centre),
            half: v3(&c.half_mm),
            yaw_deg: deg(c.yaw_rad),
            color,
            opacity,
        },
    }
}

fn cells(m: &MapReport) -> CellsView {
    CellsView {
        of: m.of,
        step: m.step_mm,
        u: m.u_mm,
        v: m.v_mm,
        points: m
            .cells
            .iter()
            .map(|c| {
                // A point not seen is not short by a distance: any
                // positive value marks it; one there only through
                // something, -1.
                let short = match (c.reachable, m.of) {
                    (true, _) => 0.0,
                    (false, "gaze") => 1.0,
                    (false, _) if c.through().is_some() => THROUGH_MARK,
                    (false, _) => mm(c.distance_mm).max(0.1),
                };
                [c.point_mm[0], c.point_mm[1], c.point_mm[2], short]
            })
            .collect(),
    }
}

/// What a standard's rules measured, as marks: each rule's shape on the
/// floor and each element, coloured by whether it holds.
fn standard_marks(s: &StandardReport) -> Vec<MarkView> {
    // Each rule with the element it is about, if one.
    let rules = (s.room_rules.iter().map(|r| (None, r))).chain(
        s.elements
            .iter()
            .flat_map(|e| e.rules.iter().map(move |r| (Some(&e.name), r))),
    );
    let mut marks: Vec<MarkView> = rules
        .filter_map(|(element, r)| {
            let of = element.map_or(String::new(), |name| format!("`{name}`: "));
            let label = format!("{of}{} {}: {}", r.section, r.rule, r.measured);
            match r.shape.as_ref()? {
                FloorShape::Polygon { points_mm } => Some(MarkView::Area {
                    label,
                    ok: r.ok,
                    points: points_mm.iter().map(|p| p.map(mm)).collect(),
                }),
                FloorShape::Circle {
                    centre_mm,
                    radius_mm,
                } => Some(MarkView::Circle {
                    label,
                    ok: r.ok,
                    centre: centre_mm.map(mm),
                    radius: mm(*radius_mm),
                }),
            }
        })
        .collect();
    marks.extend(s.elements.iter().map(|e| MarkView::Point {
        label: e.name.clone(),
        ok: e.ok,
        at: e.at_mm.map(mm),
    }));
    marks
}

/// Every ring (outlines and holes) of `region`, rounded.
fn outlines(region: &geo::MultiPolygon<f64>) -> Vec<Vec<[f64; 2]>> {
    region
        .0
        .iter()
        .flat_map(|p| std::iter::once(p.exterior()).chain(p.interiors()))
        .map(|ring| ring.coords().map(|c| [mm(c.x), mm(c.y)]).collect())
        .collect()
}

/// A population map's cells, each by its share.
fn share_cells(p: &PopulationReport) -> Option<CellsView> {
    let (grid, cells) = (p.grid.as_ref()?, p.cells.as_ref()?);
    Some(CellsView {
        of: "share",
        step: grid.step_mm,
        u: grid.u_mm,
        v: grid.v_mm,
        points: cells
            .iter()
            .map(|c| [c.point_mm[0], c.point_mm[1], c.point_mm[2], c.share])
            .collect(),
    })
}

/// Decimals the view keeps: 0.1 mm and 0.1 degree.
const DECIMALS: i32 = 1;

fn mm(x: f64) -> f64 {
    fixed(x, DECIMALS)
}

fn deg(rad: f64) -> f64 {
    mm(rad.to_degrees())
}

fn p3(p: &Point3<f64>) -> [f64; 3] {
    [mm(p.x), mm(p.y), mm(p.z)]
}

fn v3(v: &Vector3<f64>) -> [f64; 3] {
    [mm(v.x), mm(v.y), mm(v.z)]
}
