//! Rooms as designers and scanners give them: one mesh for a whole
//! kitchen. The same L-shaped counter as two boxes, as one closed OBJ and
//! as an open scan in metres (tops and fronts only, with the floor and a
//! wall) gives the same answers and the same base placements; over random
//! rooms, a mesh of boxes blocks the floor exactly as the boxes do where
//! its edges fall on the floor cells, and never less where they do not.

use std::fmt::Write as _;
use std::path::Path;

use geo::{Area, BooleanOps, MultiPolygon};
use proptest::prelude::*;
use reach::floor::{admissible, Footprint, CELL_MM};
use reach::plugin::Registry;
use reach::report::{Report, TaskReport};
use reach::scene::{BoxObstacle, MeshObstacle, Room};
use reach::Input;

const COUNTER_H: f64 = 900.0;

/// A kitchen whose counters are `counters` (a line of the room block), a
/// wheelchair user and three targets: on each run and in the corner.
fn kitchen(counters: &str) -> String {
    format!(
        "units mm deg\nuse std::arm\nroom kitchen {{\n  size 4000 x 3200 x 2500\n{counters}\n  \
         target mug at (1500, 450, 950)\n  target cup at (450, 1800, 950)\n  \
         target corner at (300, 300, 950)\n}}\nperson ann {{\n  mannequin right_arm {{ limits \
         trunk_flexion (-10deg, 40deg) }}\n  base wheelchair\n}}\nreach mug, cup, corner by ann\n"
    )
}

/// The L's outline, counter-clockwise from above.
const L: [(f64, f64); 6] = [
    (0.0, 0.0),
    (3000.0, 0.0),
    (3000.0, 600.0),
    (600.0, 600.0),
    (600.0, 2600.0),
    (0.0, 2600.0),
];

/// Quads (four corners each) as OBJ text, coordinates divided by `unit`.
fn obj(quads: &[[[f64; 3]; 4]], unit: f64) -> String {
    let mut text = String::new();
    for q in quads {
        for p in q {
            writeln!(text, "v {} {} {}", p[0] / unit, p[1] / unit, p[2] / unit).unwrap();
        }
    }
    for k in 0..quads.len() {
        let b = 4 * k + 1;
        writeln!(
            text,
            "f {} {} {}\nf {} {} {}",
            b,
            b + 1,
            b + 2,
            b,
            b + 2,
            b + 3
        )
        .unwrap();
    }
    text
}

/// The L as one closed solid: its top, bottom and six sides.
fn closed_l() -> String {
    let h = COUNTER_H;
    let at = |k: usize, z: f64| [L[k].0, L[k].1, z];
    let mut quads = vec![
        [at(0, h), at(1, h), at(2, h), at(3, h)],
        [at(0, h), at(3, h), at(4, h), at(5, h)],
        [at(0, 0.0), at(3, 0.0), at(2, 0.0), at(1, 0.0)],
        [at(0, 0.0), at(5, 0.0), at(4, 0.0), at(3, 0.0)],
    ];
    for k in 0..L.len() {
        let n = (k + 1) % L.len();
        quads.push([at(k, 0.0), at(n, 0.0), at(n, h), at(k, h)]);
    }
    obj(&quads, 1.0)
}

/// The L as a phone would scan it, in metres: the tops, the fronts and
/// ends the room shows, the floor 4 mm up and the wall behind; no bottom,
/// no back.
fn scanned_l() -> String {
    let h = COUNTER_H;
    let quads = [
        [
            [0.0, 0.0, h],
            [3000.0, 0.0, h],
            [3000.0, 600.0, h],
            [600.0, 600.0, h],
        ],
        [
            [0.0, 0.0, h],
            [600.0, 600.0, h],
            [600.0, 2600.0, h],
            [0.0, 2600.0, h],
        ],
        [
            [3000.0, 600.0, 0.0],
            [600.0, 600.0, 0.0],
            [600.0, 600.0, h],
            [3000.0, 600.0, h],
        ],
        [
            [600.0, 600.0, 0.0],
            [600.0, 2600.0, 0.0],
            [600.0, 2600.0, h],
            [600.0, 600.0, h],
        ],
        [
            [3000.0, 0.0, 0.0],
            [3000.0, 600.0, 0.0],
            [3000.0, 600.0, h],
            [3000.0, 0.0, h],
        ],
        [
            [600.0, 2600.0, 0.0],
            [0.0, 2600.0, 0.0],
            [0.0, 2600.0, h],
            [600.0, 2600.0, h],
        ],
        [
            [0.0, 0.0, 4.0],
            [4000.0, 0.0, 4.0],
            [4000.0, 3200.0, 4.0],
            [0.0, 3200.0, 4.0],
        ],
        [
            [0.0, 0.0, 0.0],
            [0.0, 3200.0, 0.0],
            [0.0, 3200.0, 2500.0],
            [0.0, 0.0, 2500.0],
        ],
    ];
    obj(&quads, 1000.0)
}

fn run_file(path: &Path) -> Report {
    let (_, checked) = reach::check(Input::Path(path), &Registry::builtin());
    let scenario = checked.unwrap_or_else(|d| panic!("{}", d.render(false)));
    reach::run(&scenario)
}

#[test]
fn an_l_kitchen_as_one_mesh_answers_as_its_boxes() {
    let dir = tempfile::tempdir().unwrap();
    let write = |name: &str, text: &str| {
        let path = dir.path().join(name);
        std::fs::write(&path, text).unwrap();
        path
    };
    write("l_closed.obj", &closed_l());
    write("l_scan.obj", &scanned_l());
    let boxes = write(
        "boxes.reach",
        &kitchen(
            "  box left_counter at (0, 0, 0) size (3000, 600, 900)\n  \
             box back_counter at (0, 600, 0) size (600, 2000, 900)",
        ),
    );
    let closed = write(
        "closed.reach",
        &kitchen("  mesh counters from \"l_closed.obj\""),
    );
    let scan = write(
        "scan.reach",
        &kitchen("  mesh counters from \"l_scan.obj\" scale 1000"),
    );
    let expected = run_file(&boxes);
    for path in [closed, scan] {
        let got = run_file(&path);
        for (e, g) in expected.tasks.iter().zip(&got.tasks) {
            let (TaskReport::Reach(e), TaskReport::Reach(g)) = (e, g) else {
                panic!("reach tasks only");
            };
            let what = format!("{} in {}", e.name, path.display());
            assert!(e.ok, "{what}: the boxes' kitchen reaches it");
            assert_eq!(e.ok, g.ok, "{what}");
            let apart = (e.base.x_mm - g.base.x_mm).hypot(e.base.y_mm - g.base.y_mm);
            assert!(apart <= 5.0, "{what}: bases {apart} mm apart");
            assert_eq!(e.base.heading_deg, g.base.heading_deg, "{what}");
        }
    }
}

/// A wheelchair user's footprint: the chair's and the legs' parts.
fn wheelchair() -> Footprint {
    let text = "units mm\nuse std::arm\nroom r { size 4000 x 4000 x 2500\n target t at (2000, 2000, 900) }\n\
                person p { mannequin right_arm  base wheelchair }\nreach t by p\n";
    let (_, checked) = reach::check(
        Input::Text {
            name: "w.reach",
            text,
        },
        &Registry::builtin(),
    );
    let scenario = checked.unwrap_or_else(|d| panic!("{}", d.render(false)));
    scenario.bases[0].footprint().unwrap().clone()
}

/// Axis-aligned boxes `[x, y, z, w, d, h]` as one mesh: closed, or open
/// as a scan sees them (no bottoms under what stands on the floor).
fn as_mesh(boxes: &[[f64; 6]], closed: bool) -> MeshObstacle {
    let mut vertices = Vec::new();
    let mut triangles = Vec::new();
    for &[x, y, z, w, d, h] in boxes {
        let base = vertices.len() as u32;
        for k in 0..8 {
            let (dx, dy, dz) = (k & 1, (k >> 1) & 1, (k >> 2) & 1);
            vertices.push(nalgebra::Point3::new(
                x + w * dx as f64,
                y + d * dy as f64,
                z + h * dz as f64,
            ));
        }
        // Faces wound outwards: bottom, top, then the four sides.
        let faces: [[u32; 4]; 6] = [
            [0, 2, 3, 1],
            [4, 5, 7, 6],
            [0, 1, 5, 4],
            [1, 3, 7, 5],
            [3, 2, 6, 7],
            [2, 0, 4, 6],
        ];
        for (k, f) in faces.iter().enumerate() {
            if k == 0 && !closed && z == 0.0 {
                continue;
            }
            triangles.push([base + f[0], base + f[1], base + f[2]]);
            triangles.push([base + f[0], base + f[2], base + f[3]]);
        }
    }
    MeshObstacle::new("m".into(), vertices, &triangles)
}

fn room(boxes: &[[f64; 6]], mesh: Option<MeshObstacle>) -> Room {
    Room {
        name: "r".into(),
        size_mm: nalgebra::Vector3::new(4000.0, 3200.0, 2500.0),
        boxes: match mesh {
            Some(_) => Vec::new(),
            None => boxes
                .iter()
                .enumerate()
                .map(|(k, &[x, y, z, w, d, h])| BoxObstacle {
                    name: format!("b{k}"),
                    corner_mm: nalgebra::Point3::new(x, y, z),
                    size_mm: nalgebra::Vector3::new(w, d, h),
                    yaw_rad: 0.0,
                })
                .collect(),
        },
        meshes: mesh.into_iter().collect(),
        targets: Vec::new(),
        surfaces: Vec::new(),
    }
}

/// A box on the floor or raised (a wall cabinet, a table top), in
/// millimetres, each coordinate a multiple of `grain_mm`.
fn a_box(grain_mm: f64) -> impl Strategy<Value = [f64; 6]> {
    let n = move |lo: u32, hi: u32| (lo..hi).prop_map(move |k| f64::from(k) * grain_mm);
    let cells = |mm: u32| (mm as f64 / grain_mm) as u32;
    (
        n(0, cells(3500)),
        n(0, cells(2700)),
        prop_oneof![Just(0.0), n(cells(300), cells(1500))],
        n(cells(50), cells(1200)),
        n(cells(50), cells(1200)),
        n(cells(20), cells(900)),
    )
        .prop_map(|(x, y, z, w, d, h)| [x, y, z, w, d, h])
}

/// The floor region of a chair (or, if not `chair`, a low robot that fits
/// in the hollow of a box) among `boxes`, as boxes and as one mesh.
fn regions(
    boxes: &[[f64; 6]],
    closed: bool,
    chair: bool,
    heading: f64,
) -> (MultiPolygon<f64>, MultiPolygon<f64>) {
    let footprint = if chair {
        wheelchair()
    } else {
        Footprint::circle(250.0, 300.0)
    };
    let mesh = Some(as_mesh(boxes, closed));
    (
        admissible(&room(boxes, None), &footprint, heading, None),
        admissible(&room(boxes, mesh), &footprint, heading, None),
    )
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]

    #[test]
    fn a_mesh_on_the_cells_blocks_the_floor_as_its_boxes_do(
        boxes in prop::collection::vec(a_box(CELL_MM), 1..4),
        closed in any::<bool>(),
        chair in any::<bool>(),
        heading in 0.0..std::f64::consts::TAU,
    ) {
        let (expected, got) = regions(&boxes, closed, chair, heading);
        let differ = expected.xor(&got).unsigned_area();
        prop_assert!(differ < 1.0, "{differ} mm2 differ");
    }

    #[test]
    fn a_mesh_off_the_cells_never_blocks_less_than_its_boxes(
        boxes in prop::collection::vec(a_box(1.0), 1..4),
        closed in any::<bool>(),
        chair in any::<bool>(),
        heading in 0.0..std::f64::consts::TAU,
    ) {
        let (expected, got) = regions(&boxes, closed, chair, heading);
        let extra = got.difference(&expected).unsigned_area();
        prop_assert!(extra < 1.0, "the mesh frees {extra} mm2 the boxes block");
        // And at most two cells' width more along every edge the boxes'
        // floor region has.
        let lost = expected.difference(&got).unsigned_area();
        let edges: f64 = expected.0.iter().map(|p| {
            use geo::{Euclidean, Length};
            Euclidean.length(p.exterior())
                + p.interiors().iter().map(|r| Euclidean.length(r)).sum::<f64>()
        }).sum();
        prop_assert!(lost <= edges * 2.0 * CELL_MM + 1.0, "{lost} mm2 lost along {edges} mm");
    }
}
