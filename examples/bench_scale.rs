//! Rooms at real scale: how long a run takes and how much memory it
//! holds as the room grows. Each row is generated (boxes in shelving
//! units; a scanned kitchen as one open mesh of small triangles; a map of
//! a counter's front; posts in a hall entered by a door, so that the
//! routes from the door cross the whole hall) and written to files by
//! this program, then checked and run in a child process of it, which
//! reports its time and its peak resident memory (Linux: `VmHWM`, in MiB),
//! so the generating does not count towards the run's memory. Prints one table row per size and the growth exponent
//! between the two largest sizes of each kind.
//!
//! `cargo run --release --example bench_scale` (all rows), or with a kind
//! (`boxes`, `mesh`, `map`, `doors`, `far_boxes`, `far_mesh`: clutter
//! beyond every reach) to run only those; `--tiny` makes
//! each size a hundredth (CI runs it so, to see every row run).

use std::fmt::Write as _;
use std::path::Path;
use std::process::Command;
use std::time::Instant;

use reach::plugin::Registry;
use reach::Input;

/// The sizes of each kind: boxes, triangles, map points, posts.
const ROWS: [(&str, [usize; 2]); 6] = [
    ("boxes", [200, 2_000]),
    ("mesh", [100_000, 1_000_000]),
    ("map", [10_000, 100_000]),
    ("doors", [200, 2_000]),
    ("far_boxes", [200, 2_000]),
    ("far_mesh", [100_000, 1_000_000]),
];

fn main() {
    let args: Vec<String> = std::env::args().collect();
    if args.len() == 3 && args[1] == "--child" {
        child(Path::new(&args[2]));
        return;
    }
    // `--tiny`: each size a hundredth, to see that every row runs.
    let tiny = args.iter().any(|a| a == "--tiny");
    let only = args.iter().skip(1).find(|a| *a != "--tiny").cloned();
    println!("| work | size | time (s) | peak memory (MiB) |\n|---|---|---|---|");
    for (kind, sizes) in ROWS {
        if only.as_deref().is_some_and(|o| o != kind) {
            continue;
        }
        let mut figures = Vec::new();
        for size in sizes {
            let size = if tiny { (size / 100).max(2) } else { size };
            let dir = tempfile::tempdir().expect("a temporary directory");
            let path = write_room(kind, size, dir.path());
            let out = Command::new(&args[0])
                .arg("--child")
                .arg(&path)
                .output()
                .expect("the child runs");
            assert!(
                out.status.success(),
                "the run of {kind} at {size} failed: {}",
                String::from_utf8_lossy(&out.stderr)
            );
            let text = String::from_utf8_lossy(&out.stdout);
            let mut it = text
                .split_whitespace()
                .map(|x| x.parse::<f64>().unwrap_or(f64::NAN));
            let (seconds, mb) = (it.next().unwrap_or(f64::NAN), it.next().unwrap_or(f64::NAN));
            println!("| {} | {size} | {seconds:.2} | {mb:.0} |", describe(kind));
            figures.push((size as f64, seconds));
        }
        let [(n0, t0), (n1, t1)] = [figures[0], figures[1]];
        println!(
            "| {} | growth | time x{:.1} for size x{:.0} (exponent {:.2}) | |",
            describe(kind),
            t1 / t0,
            n1 / n0,
            (t1 / t0).ln() / (n1 / n0).ln()
        );
    }
}

fn describe(kind: &str) -> &'static str {
    match kind {
        "boxes" => "box obstacles, wheelchair, 20 targets",
        "mesh" => "one scanned mesh (triangles), wheelchair, 20 targets",
        "doors" => "posts 1 m apart in a hall with a door, manual wheelchair, 1 target",
        "far_boxes" => "small boxes strewn in 3D through the far half of a 10 m room, wheelchair, 20 targets on a counter at the other end",
        "far_mesh" => "one mesh of small cubes (triangles) strewn through the far half of a 10 m room, wheelchair, 20 targets on a counter at the other end",
        _ => "map points, wheelchair, JSON report",
    }
}

/// Writes the scenario of `size` of `kind` (and its mesh) into `dir`;
/// the scenario's path.
fn write_room(kind: &str, size: usize, dir: &Path) -> std::path::PathBuf {
    let text = match kind {
        "boxes" => boxes(size),
        "mesh" => {
            std::fs::write(dir.join("scan.obj"), scan(size)).expect("written");
            mesh_room()
        }
        "doors" => hall(size),
        "far_boxes" => far_room(&strewn_boxes(size), size),
        "far_mesh" => {
            std::fs::write(dir.join("clutter.obj"), strewn_cubes(size)).expect("written");
            far_room("  mesh clutter from \"clutter.obj\"\n", size)
        }
        _ => map(size),
    };
    let path = dir.join("scale.reach");
    std::fs::write(&path, text).expect("written");
    path
}

/// Checks and runs the scenario at `path`, prints seconds and peak MiB.
fn child(path: &Path) {
    let start = Instant::now();
    let json = run(path);
    let seconds = start.elapsed().as_secs_f64();
    assert!(json.len() > 100);
    println!("{seconds} {}", peak_mb());
}

fn run(path: &Path) -> String {
    let registry = Registry::builtin();
    let limits = reach::limits::Limits::default();
    let (_, checked) = reach::Session::default()
        .limits(limits)
        .check(Input::Path(path), &registry);
    let scenario = checked.unwrap_or_else(|d| panic!("{}", d.render(false)));
    let report = reach::run(&scenario).expect("within the bound on solver work");
    let json = registry.format("json").expect("the json format");
    json.render(&report, &scenario.format_scene())
        .expect("json prints")
}

/// Peak resident memory of this process, in MiB (Linux), or NaN.
fn peak_mb() -> f64 {
    let status = std::fs::read_to_string("/proc/self/status").unwrap_or_default();
    status
        .lines()
        .find_map(|l| l.strip_prefix("VmHWM:"))
        .and_then(|v| v.trim().trim_end_matches("kB").trim().parse::<f64>().ok())
        .map_or(f64::NAN, |kb| kb / 1024.0)
}

const PERSON: &str =
    "person ann {\n  mannequin right_arm { limits trunk_flexion (-10deg, 40deg) }\n  \
                      base wheelchair\n}\n";

/// `n` boxes as shelving units of ten boards, 2 m apart, 20 targets on
/// their shelves.
fn boxes(n: usize) -> String {
    let units = (n / 10).max(1);
    let cols = (units as f64).sqrt().ceil() as usize;
    let side = cols * 2000 + 1000;
    let mut t = format!("units mm deg\nuse std::arm\nroom k {{\n  size {side} x {side} x 2500\n");
    for u in 0..units {
        let (x, y) = (500 + 2000 * (u % cols), 500 + 2000 * (u / cols));
        writeln!(t, "  box s{u}a at ({x}, {y}, 0) size (20, 400, 1800)").unwrap();
        writeln!(
            t,
            "  box s{u}b at ({}, {y}, 0) size (20, 400, 1800)",
            x + 780
        )
        .unwrap();
        for s in 0..8 {
            let z = 100 + 220 * s;
            writeln!(
                t,
                "  box s{u}_{s} at ({}, {y}, {z}) size (760, 400, 20)",
                x + 20
            )
            .unwrap();
        }
    }
    let mut names = Vec::new();
    for k in 0..20 {
        let u = (k * 7) % units;
        let (x, y) = (500 + 2000 * (u % cols) + 400, 500 + 2000 * (u / cols) + 300);
        let z = 100 + 220 * (2 + k % 3) + 60;
        writeln!(t, "  target t{k} at ({x}, {y}, {z})").unwrap();
        names.push(format!("t{k}"));
    }
    t + "}\n" + PERSON + &format!("reach {} by ann\n", names.join(", "))
}

/// `n` posts of 100 mm on a 1 m grid in a square hall with a door in
/// its wall x = 0, and one target on a post: a seated man in the stdlib's
/// manual wheelchair (its twelve parts) must be able to get there.
fn hall(n: usize) -> String {
    let k = (n as f64).sqrt().ceil() as usize;
    let side = 1000 * (k + 1);
    let mut t =
        format!("units mm deg\nuse std::people\nroom hall {{\n  size {side} x {side} x 2500\n");
    for i in 0..n {
        let (x, y) = (1000 * (1 + i / k), 1000 * (1 + i % k));
        writeln!(t, "  box p{i} at ({x}, {y}, 0) size (100, 100, 900)").unwrap();
    }
    writeln!(t, "  target t at (1050, 1050, 960)").unwrap();
    writeln!(t, "  door d at (0, {}) width 1000mm\n}}", side / 2).unwrap();
    t + "person ann {\n  mannequin man_50th_seated\n  base manual_wheelchair\n}\nreach t by ann\n"
}

/// A kitchen scanned as one mesh of about `n` triangles: an L-shaped
/// counter's tops and fronts, the floor 4 mm up, two walls, a wall
/// cabinet's underside and front; in metres, as scans are.
fn scan(n: usize) -> String {
    type Quad = ([f64; 3], [f64; 3], [f64; 3]);
    let quads: [Quad; 9] = [
        ([0.0, 0.0, 900.0], [3000.0, 0.0, 0.0], [0.0, 600.0, 0.0]),
        ([0.0, 600.0, 900.0], [600.0, 0.0, 0.0], [0.0, 2000.0, 0.0]),
        ([600.0, 600.0, 0.0], [2400.0, 0.0, 0.0], [0.0, 0.0, 900.0]),
        ([600.0, 600.0, 0.0], [0.0, 2000.0, 0.0], [0.0, 0.0, 900.0]),
        ([0.0, 0.0, 4.0], [4000.0, 0.0, 0.0], [0.0, 3200.0, 0.0]),
        ([0.0, 0.0, 0.0], [0.0, 3200.0, 0.0], [0.0, 0.0, 2500.0]),
        ([0.0, 0.0, 0.0], [4000.0, 0.0, 0.0], [0.0, 0.0, 2500.0]),
        ([0.0, 0.0, 1450.0], [350.0, 0.0, 0.0], [0.0, 3200.0, 0.0]),
        ([350.0, 0.0, 1450.0], [0.0, 3200.0, 0.0], [0.0, 0.0, 700.0]),
    ];
    let norm = |v: &[f64; 3]| v.iter().map(|c| c.abs()).sum::<f64>();
    let total: f64 = quads.iter().map(|(_, u, v)| norm(u) * norm(v)).sum();
    let (mut vertices, mut faces) = (String::new(), String::new());
    let mut next = 1;
    for (o, u, v) in quads {
        let cells = ((n as f64 / 2.0) * norm(&u) * norm(&v) / total).max(1.0);
        let rows = cells.sqrt().floor().max(1.0) as usize;
        let cols = (cells / rows as f64).floor().max(1.0) as usize;
        for i in 0..=rows {
            for j in 0..=cols {
                let (a, b) = (i as f64 / rows as f64, j as f64 / cols as f64);
                let p: Vec<f64> = (0..3)
                    .map(|k| (o[k] + u[k] * a + v[k] * b) / 1000.0)
                    .collect();
                writeln!(vertices, "v {:.5} {:.5} {:.5}", p[0], p[1], p[2]).unwrap();
            }
        }
        for i in 0..rows {
            for j in 0..cols {
                let a = next + i * (cols + 1) + j;
                let b = a + cols + 1;
                writeln!(faces, "f {a} {b} {}\nf {a} {} {}", b + 1, b + 1, a + 1).unwrap();
            }
        }
        next += (rows + 1) * (cols + 1);
    }
    vertices + &faces
}

fn mesh_room() -> String {
    let mut t = String::from(
        "units mm deg\nuse std::arm\nroom kitchen {\n  size 4000 x 3200 x 2500\n  \
         mesh scan from \"scan.obj\" scale 1000\n",
    );
    let mut names = Vec::new();
    for k in 0..20 {
        writeln!(t, "  target t{k} at ({}, 450, 950)", 700 + 110 * k).unwrap();
        names.push(format!("t{k}"));
    }
    t + "}\n" + PERSON + &format!("reach {} by ann\n", names.join(", "))
}

/// A map of about `n` points on the plane of a 5 m counter's front.
fn map(n: usize) -> String {
    let step = (5000.0 * 2000.0 / n as f64).sqrt();
    format!(
        "units mm deg\nuse std::arm\nroom kitchen {{\n  size 3500 x 6000 x 2600\n  \
         box counter at (0, 0, 0) size (600, 5000, 900)\n  \
         box wall_cabinet at (0, 0, 1450) size (350, 5000, 700)\n  \
         surface front at (600, 0, 0) size (0, 5000, 2000)\n}}\n{PERSON}\
         map front by ann {{\n  step {step:.3}mm\n  solver incremental {{ starts 1 }}\n}}\n"
    )
}

/// A 10 m room: a counter at one end with 20 targets along it, and
/// `clutter` (box or mesh lines) in its far half, out of every reach.
fn far_room(clutter: &str, _size: usize) -> String {
    let mut t = String::from(
        "units mm deg\nuse std::arm\nroom hall {\n  size 10000 x 4000 x 2700\n  \
         box counter at (0, 0, 0) size (3000, 600, 900)\n",
    );
    t.push_str(clutter);
    let mut names = Vec::new();
    for k in 0..20 {
        writeln!(t, "  target t{k} at ({}, 400, 950)", 300 + 120 * k).unwrap();
        names.push(format!("t{k}"));
    }
    t + "}\n" + PERSON + &format!("reach {} by ann\n", names.join(", "))
}

/// Where the `k`-th thing strewn through the far half goes: x from 5 m to
/// 9.9 m, y across the room, z from the floor to 2.6 m (a fixed
/// sequence, the same every run).
fn strewn(k: usize) -> [f64; 3] {
    let mut h = (k as u64).wrapping_mul(0x9E37_79B9_7F4A_7C15) ^ 0xD1B5_4A32_D192_ED03;
    let mut next = || {
        h ^= h >> 33;
        h = h.wrapping_mul(0xFF51_AFD7_ED55_8CCD);
        h ^= h >> 33;
        (h % 1_000_000) as f64 / 1_000_000.0
    };
    [5000.0 + 4900.0 * next(), 3900.0 * next(), 2600.0 * next()]
}

/// `n` boxes of 100 mm strewn through the far half.
fn strewn_boxes(n: usize) -> String {
    let mut t = String::new();
    for k in 0..n {
        let [x, y, z] = strewn(k);
        writeln!(
            t,
            "  box c{k} at ({x:.0}, {y:.0}, {z:.0}) size (100, 100, 100)"
        )
        .unwrap();
    }
    t
}

/// An OBJ (mm) of 50 mm cubes strewn through the far half, about `n`
/// triangles (12 a cube).
fn strewn_cubes(n: usize) -> String {
    let (mut vertices, mut faces) = (String::new(), String::new());
    const FACES: [[usize; 4]; 6] = [
        [0, 1, 3, 2],
        [4, 6, 7, 5],
        [0, 4, 5, 1],
        [2, 3, 7, 6],
        [0, 2, 6, 4],
        [1, 5, 7, 3],
    ];
    for k in 0..n.div_ceil(12) {
        let [x, y, z] = strewn(k);
        for c in 0..8 {
            let (dx, dy, dz) = ((c >> 2) & 1, (c >> 1) & 1, c & 1);
            let p = [
                x + 50.0 * dx as f64,
                y + 50.0 * dy as f64,
                z + 50.0 * dz as f64,
            ];
            writeln!(vertices, "v {:.1} {:.1} {:.1}", p[0], p[1], p[2]).unwrap();
        }
        let base = 1 + 8 * k;
        for [a, b, c, d] in FACES {
            let [a, b, c, d] = [a + base, b + base, c + base, d + base];
            writeln!(faces, "f {a} {b} {c}\nf {a} {c} {d}").unwrap();
        }
    }
    vertices + &faces
}
