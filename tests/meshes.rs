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
         target corner at (350, 350, 950)\n}}\nperson ann {{\n  mannequin right_arm {{ limits \
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
    obj(&closed_l_quads(), 1.0)
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

/// Quads (four corners each, in mm, z up) as triangles: vertices and
/// indices.
fn triangulated(quads: &[[[f64; 3]; 4]]) -> (Vec<[f64; 3]>, Vec<[u32; 3]>) {
    let vertices = quads.iter().flatten().copied().collect();
    let triangles = (0..quads.len() as u32)
        .flat_map(|k| [[4 * k, 4 * k + 1, 4 * k + 2], [4 * k, 4 * k + 2, 4 * k + 3]])
        .collect();
    (vertices, triangles)
}

/// The closed L's quads (as `closed_l` writes them).
fn closed_l_quads() -> Vec<[[f64; 3]; 4]> {
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
    quads
}

/// A binary STL of the quads, in millimetres, z up; `count` overrides the
/// triangle count its header states.
fn binary_stl(quads: &[[[f64; 3]; 4]], count: Option<u32>) -> Vec<u8> {
    let (v, t) = triangulated(quads);
    let mut bytes = vec![b' '; 80];
    bytes.extend(count.unwrap_or(t.len() as u32).to_le_bytes());
    for tri in &t {
        bytes.extend([0f32; 3].iter().flat_map(|x| x.to_le_bytes()));
        for &k in tri {
            bytes.extend(v[k as usize].iter().flat_map(|&x| (x as f32).to_le_bytes()));
        }
        bytes.extend([0u8; 2]);
    }
    bytes
}

/// An ASCII STL of the quads, in centimetres, y up (x, z, -y).
fn ascii_stl_cm_y_up(quads: &[[[f64; 3]; 4]]) -> String {
    let (v, t) = triangulated(quads);
    let mut text = String::from("solid l\n");
    for tri in &t {
        text.push_str("facet normal 0 0 0\nouter loop\n");
        for &k in tri {
            let [x, y, z] = v[k as usize];
            writeln!(text, "vertex {} {} {}", x / 10.0, z / 10.0, -y / 10.0).unwrap();
        }
        text.push_str("endloop\nendfacet\n");
    }
    text.push_str("endsolid l\n");
    text
}

/// A GLB of the quads as glTF has them (metres, y up), its vertices 1 m
/// off in x and put back by its node's translation; `declared` overrides
/// the buffer's stated length.
fn glb(quads: &[[[f64; 3]; 4]], declared: Option<usize>) -> Vec<u8> {
    let (v, t) = triangulated(quads);
    let mut bin = Vec::new();
    for [x, y, z] in &v {
        for c in [x / 1000.0 - 1.0, z / 1000.0, -y / 1000.0] {
            bin.extend((c as f32).to_le_bytes());
        }
    }
    let positions_len = bin.len();
    bin.extend(t.iter().flatten().flat_map(|k| k.to_le_bytes()));
    let (lo, hi) = (-10.0, 10.0);
    let json = format!(
        r#"{{"asset":{{"version":"2.0"}},"scene":0,"scenes":[{{"nodes":[0]}}],
"nodes":[{{"mesh":0,"translation":[1,0,0]}}],
"meshes":[{{"primitives":[{{"attributes":{{"POSITION":0}},"indices":1}}]}}],
"accessors":[{{"bufferView":0,"componentType":5126,"count":{nv},"type":"VEC3","min":[{lo},{lo},{lo}],"max":[{hi},{hi},{hi}]}},
{{"bufferView":1,"componentType":5125,"count":{ni},"type":"SCALAR"}}],
"bufferViews":[{{"buffer":0,"byteOffset":0,"byteLength":{positions_len}}},{{"buffer":0,"byteOffset":{positions_len},"byteLength":{il}}}],
"buffers":[{{"byteLength":{bl}}}]}}"#,
        nv = v.len(),
        ni = 3 * t.len(),
        il = bin.len() - positions_len,
        bl = declared.unwrap_or(bin.len()),
    );
    reach::output::glb::container(json.as_bytes(), &bin)
}

fn run_file(path: &Path) -> Report {
    let (_, checked) = reach::check(Input::Path(path), &Registry::builtin());
    let scenario = checked.unwrap_or_else(|d| panic!("{}", d.render(false)));
    reach::run(&scenario).expect("within the bound on solver work")
}

/// The kitchen with its counters as the mesh file `file` (`props` after
/// its name), written in `dir`.
fn mesh_kitchen(dir: &Path, file: &str, bytes: &[u8], props: &str) -> std::path::PathBuf {
    std::fs::write(dir.join(file), bytes).unwrap();
    let path = dir.join(format!("{file}.reach"));
    let line = format!("  mesh counters from \"{file}\"{props}");
    std::fs::write(&path, kitchen(&line)).unwrap();
    path
}

/// Two reports give the same verdicts with bases within 5 mm.
fn assert_same_answers(expected: &Report, got: &Report, what: &str) {
    assert_eq!(expected.tasks.len(), got.tasks.len());
    for (e, g) in expected.tasks.iter().zip(&got.tasks) {
        let (TaskReport::Reach(e), TaskReport::Reach(g)) = (e, g) else {
            panic!("reach tasks only");
        };
        let what = format!("{} in {what}", e.name);
        assert_eq!(e.ok, g.ok, "{what}");
        let apart = (e.base.x_mm - g.base.x_mm).hypot(e.base.y_mm - g.base.y_mm);
        assert!(apart <= 5.0, "{what}: bases {apart} mm apart");
        assert_eq!(e.base.heading_deg, g.base.heading_deg, "{what}");
    }
}

#[test]
fn an_stl_a_glb_and_an_obj_of_one_room_answer_alike() {
    let dir = tempfile::tempdir().unwrap();
    let quads = closed_l_quads();
    let obj = mesh_kitchen(dir.path(), "l.obj", closed_l().as_bytes(), "");
    let expected = run_file(&obj);
    assert!(expected
        .tasks
        .iter()
        .all(|t| matches!(t, TaskReport::Reach(r) if r.ok)));
    let files = [
        mesh_kitchen(dir.path(), "l.stl", &binary_stl(&quads, None), ""),
        mesh_kitchen(
            dir.path(),
            "l_ascii.stl",
            ascii_stl_cm_y_up(&quads).as_bytes(),
            " unit cm up y",
        ),
        mesh_kitchen(dir.path(), "l.glb", &glb(&quads, None), ""),
    ];
    for path in files {
        assert_same_answers(&expected, &run_file(&path), &path.display().to_string());
    }
}

#[test]
fn a_broken_glb_buffer_and_a_wrong_stl_count_are_diagnostics_at_the_file() {
    let dir = tempfile::tempdir().unwrap();
    let quads = closed_l_quads();
    let n = 2 * quads.len() as u32;
    let cases = [
        (
            "short.glb",
            glb(&quads, Some(1 << 20)),
            "declares 1048576 bytes but holds",
        ),
        (
            "more.stl",
            binary_stl(&quads, Some(n + 1)),
            &*format!("header says {} triangles", n + 1),
        ),
        ("fewer.stl", binary_stl(&quads, Some(n - 1)), "header says"),
    ];
    for (file, bytes, says) in cases {
        let path = mesh_kitchen(dir.path(), file, &bytes, "");
        let o = std::process::Command::new(env!("CARGO_BIN_EXE_reach"))
            .arg("check")
            .arg(&path)
            .env("NO_COLOR", "1")
            .output()
            .unwrap();
        let err = String::from_utf8_lossy(&o.stderr);
        // The message as one line, as miette wraps it to the terminal.
        let err = err
            .replace('│', " ")
            .split_whitespace()
            .collect::<Vec<_>>()
            .join(" ");
        assert_eq!(o.status.code(), Some(1), "{file}: {err}");
        assert!(err.contains(says), "{file}: {err}");
        assert!(
            err.contains(&format!("\"{file}\"")),
            "{file}: the label is on the name: {err}"
        );
    }
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
        doors: Vec::new(),
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

/// A closed box as a mesh: its eight corners and twelve triangles, faces
/// outwards.
fn box_mesh(corner: [f64; 3], size: [f64; 3]) -> MeshObstacle {
    let vertices = (0..8)
        .map(|k| {
            let pick =
                |axis: usize| corner[axis] + if k >> axis & 1 == 1 { size[axis] } else { 0.0 };
            nalgebra::Point3::new(pick(0), pick(1), pick(2))
        })
        .collect();
    // Corner k has x from bit 0, y from bit 1, z from bit 2.
    let triangles = [
        [0, 2, 1],
        [1, 2, 3], // z = 0, down
        [4, 5, 6],
        [5, 7, 6], // z = top, up
        [0, 1, 4],
        [1, 5, 4], // y = 0
        [2, 6, 3],
        [3, 6, 7], // y = top
        [0, 4, 2],
        [2, 4, 6], // x = 0
        [1, 3, 5],
        [3, 7, 5], // x = top
    ];
    MeshObstacle::new("board".into(), vertices, &triangles)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, rng_seed: proptest::test_runner::RngSeed::Fixed(57), .. ProptestConfig::default() })]

    /// Solids are solid: a point is strictly inside a closed mesh exactly
    /// where it is strictly inside the box the mesh closes (the checker
    /// refuses a target there, as in a box), whatever the box and the
    /// point, boards 1 mm from their surface included.
    #[test]
    fn a_point_is_inside_a_closed_mesh_where_inside_its_box(
        corner in prop::array::uniform3(-500.0..500.0f64),
        size in prop::array::uniform3(5.0..800.0f64),
        at in prop::array::uniform3(-0.2..1.2f64),
    ) {
        let mesh = box_mesh(corner, size);
        prop_assert!(mesh.encloses());
        let p = nalgebra::Point3::new(
            corner[0] + at[0] * size[0],
            corner[1] + at[1] * size[1],
            corner[2] + at[2] * size[2],
        );
        let depth = (0..3)
            .map(|i| (p[i] - corner[i]).min(corner[i] + size[i] - p[i]))
            .fold(f64::INFINITY, f64::min);
        // Within a micrometre of the surface either answer is allowed.
        if depth.abs() > 2e-3 {
            prop_assert_eq!(mesh.holds_strictly(&p), depth > 0.0, "depth {}", depth);
        }
    }
}

/// A target 1 mm inside a closed mesh board is refused; 1 mm in front of
/// it, and in an open sheet, it is not.
#[test]
fn a_target_a_millimetre_inside_a_closed_board_is_refused() {
    let board = box_mesh([0.0, 1000.0, 1200.0], [600.0, 300.0, 20.0]);
    assert!(board.holds_strictly(&nalgebra::Point3::new(300.0, 1150.0, 1219.0)));
    assert!(!board.holds_strictly(&nalgebra::Point3::new(300.0, 1150.0, 1221.0)));
    // The board's top alone: open, no inside.
    let sheet = MeshObstacle::new(
        "sheet".into(),
        vec![
            nalgebra::Point3::new(0.0, 1000.0, 1220.0),
            nalgebra::Point3::new(600.0, 1000.0, 1220.0),
            nalgebra::Point3::new(0.0, 1300.0, 1220.0),
            nalgebra::Point3::new(600.0, 1300.0, 1220.0),
        ],
        &[[0, 1, 2], [1, 3, 2]],
    );
    assert!(!sheet.encloses());
    assert!(!sheet.holds_strictly(&nalgebra::Point3::new(300.0, 1150.0, 1219.0)));
}

/// The bytes this thread has read through system calls so far (Linux).
#[cfg(target_os = "linux")]
fn bytes_read_by_this_thread() -> u64 {
    let io = std::fs::read_to_string("/proc/thread-self/io").expect("/proc/thread-self/io");
    io.lines()
        .find_map(|l| l.strip_prefix("rchar: "))
        .and_then(|n| n.trim().parse().ok())
        .expect("an rchar line")
}

/// A file named by many `mesh` lines, and a glTF whose buffers all name
/// one file, are each read once: 20 lines naming one 4 MB OBJ read 80 MB,
/// and 30 buffers naming one 4 MB file 120 MB.
#[cfg(target_os = "linux")]
#[test]
fn a_file_named_many_times_is_read_once() {
    let dir = tempfile::tempdir().unwrap();
    let padding = format!("# {}\n", "x".repeat(1000)).repeat(4000);
    let board = [[
        [0.0, 0.0, 900.0],
        [600.0, 0.0, 900.0],
        [600.0, 600.0, 900.0],
        [0.0, 600.0, 900.0],
    ]];
    std::fs::write(dir.path().join("board.obj"), obj(&board, 1.0) + &padding).unwrap();
    // The glTF's positions and indices at the start of `big.bin`, padded.
    let (v, t) = triangulated(&board);
    let mut bin: Vec<u8> = v
        .iter()
        .flatten()
        .flat_map(|c| ((c / 1000.0) as f32).to_le_bytes())
        .collect();
    let positions_len = bin.len();
    bin.extend(t.iter().flatten().flat_map(|k| k.to_le_bytes()));
    let indices_len = bin.len() - positions_len;
    bin.resize(4_000_000, 0);
    std::fs::write(dir.path().join("big.bin"), &bin).unwrap();
    let buffers = vec![format!(r#"{{"byteLength":{},"uri":"big.bin"}}"#, bin.len()); 30];
    let gltf = format!(
        r#"{{"asset":{{"version":"2.0"}},"scene":0,"scenes":[{{"nodes":[0]}}],"nodes":[{{"mesh":0}}],
"meshes":[{{"primitives":[{{"attributes":{{"POSITION":0}},"indices":1}}]}}],
"accessors":[{{"bufferView":0,"componentType":5126,"count":{nv},"type":"VEC3","min":[0,0,0],"max":[1,1,1]}},
{{"bufferView":1,"componentType":5125,"count":{ni},"type":"SCALAR"}}],
"bufferViews":[{{"buffer":29,"byteOffset":0,"byteLength":{positions_len}}},{{"buffer":29,"byteOffset":{positions_len},"byteLength":{indices_len}}}],
"buffers":[{}]}}"#,
        buffers.join(","),
        nv = v.len(),
        ni = 3 * t.len(),
    );
    std::fs::write(dir.path().join("board.gltf"), gltf).unwrap();
    let mut rooms = String::new();
    for k in 0..20 {
        writeln!(
            rooms,
            "  mesh board_{k} from \"board.obj\" at (0, {}, 0)",
            700 * k
        )
        .unwrap();
    }
    let text = format!(
        "units mm deg\nroom r {{\n  size 3000 x 20000 x 2500\n{rooms}  mesh scan from \"board.gltf\" at (2000, 0, 0) unit mm\n}}\n"
    );
    let path = dir.path().join("boards.reach");
    std::fs::write(&path, text).unwrap();
    let before = bytes_read_by_this_thread();
    let (_, checked) = reach::check(Input::Path(&path), &Registry::builtin());
    let read = bytes_read_by_this_thread() - before;
    let scenario = checked.unwrap_or_else(|d| panic!("{}", d.render(false)));
    assert_eq!(scenario.rooms[0].meshes.len(), 21);
    assert!(read < 20_000_000, "{read} bytes read");
}

/// A glTF of millions of empty nodes (`{}`, three bytes each: within the
/// byte limit) is refused before it is built: 5,000,000 of them in 15 MB
/// took 1.1 GB.
#[test]
fn a_gltf_of_millions_of_empty_nodes_is_refused_before_it_is_built() {
    let dir = tempfile::tempdir().unwrap();
    let board = [[
        [0.0, 0.0, 900.0],
        [600.0, 0.0, 900.0],
        [600.0, 600.0, 900.0],
        [0.0, 600.0, 900.0],
    ]];
    let glb = glb(&board, None);
    // The GLB's JSON with 1,100,000 empty nodes after its one.
    let json_len = u32::from_le_bytes(glb[12..16].try_into().unwrap()) as usize;
    let json = std::str::from_utf8(&glb[20..20 + json_len])
        .unwrap()
        .trim_end();
    let bin_chunk = &glb[20 + json_len..];
    let nodes = format!("{}{{}}", "{},".repeat(1_099_999));
    let json = json.replacen(
        r#""translation":[1,0,0]}]"#,
        &format!(r#""translation":[1,0,0]}},{nodes}]"#),
        1,
    );
    let gltf = json.replacen(r#""buffers":[{"#, r#""buffers":[{"uri":"board.bin","#, 1);
    std::fs::write(dir.path().join("board.bin"), &bin_chunk[8..]).unwrap();
    let path = mesh_kitchen(dir.path(), "board.gltf", gltf.as_bytes(), "");
    let (_, checked) = reach::check(Input::Path(&path), &Registry::builtin());
    let rendered = match checked {
        Ok(_) => panic!("1,100,000 nodes were built"),
        Err(d) => d.render(false),
    };
    assert!(
        rendered.contains("not a valid glTF file") && rendered.contains("1000000 objects"),
        "{rendered}"
    );
}
