//! Watch mode's latency: `reach watch` on a copy of
//! `examples/kitchen_wheelchair.reach`, saved again and again with one
//! edit made and undone, timed from the end of each write to the summary
//! line of the evaluation it causes (a monotonic clock; the first 25 ms are
//! the wait that batches an editor's burst of events).
//!
//! `cargo build --release && cargo run --release --example bench_watch -- EDIT [SAVES]`,
//! EDIT one of `target` (a target moved 1 mm), `shelf` (shelf_3 up 1 mm),
//! `shelf_side` (shelf_3 along the wall by 1 mm), `tall` (the tall
//! cabinet's top up 1 mm), each undone at the next save;
//! or `shelf_on` (shelf_3 up 1 mm further at every save, never back: a
//! room not seen before at every save). Prints each save's time and
//! summary, then the least, median and greatest.

use std::io::{BufRead, BufReader};
use std::path::PathBuf;
use std::process::{Command, Stdio};
use std::sync::mpsc;
use std::time::{Duration, Instant};

const EDITS: [(&str, &str, &str); 4] = [
    (
        "target",
        "target counter_front  at (550, 1500, counter_h + 50)",
        "target counter_front  at (551, 1500, counter_h + 50)",
    ),
    (
        "shelf",
        "box shelf_3 at (1500, 2900, 1400)",
        "box shelf_3 at (1500, 2900, 1401)",
    ),
    (
        "shelf_side",
        "box shelf_3 at (1500, 2900, 1400)",
        "box shelf_3 at (1501, 2900, 1400)",
    ),
    (
        "tall",
        "box tall_cabinet_upper at (0, 2600, 1900)",
        "box tall_cabinet_upper at (0, 2600, 1901)",
    ),
];

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let edit = args.get(1).map_or("target", String::as_str);
    let saves: usize = args.get(2).map_or(10, |s| s.parse().expect("a count"));
    let onward = edit == "shelf_on";
    let named = if onward { "shelf" } else { edit };
    let Some(&(_, from, to)) = EDITS.iter().find(|(name, ..)| *name == named) else {
        panic!("EDIT is target, shelf, shelf_side, tall or shelf_on");
    };
    let original = std::fs::read_to_string("examples/kitchen_wheelchair.reach")
        .expect("run from the crate's directory");
    assert!(original.contains(from));
    let dir = tempfile::tempdir().expect("a temporary directory");
    let file = dir.path().join("kitchen.reach");
    std::fs::write(&file, &original).unwrap();
    let mut child = Command::new(reach_binary())
        .arg("watch")
        .arg(&file)
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .expect("target/release/reach runs (cargo build --release)");
    let (tx, rx) = mpsc::channel();
    let stdout = child.stdout.take().unwrap();
    std::thread::spawn(move || {
        for line in BufReader::new(stdout).lines().map_while(Result::ok) {
            if line.starts_with("evaluated") || line.starts_with("errors") {
                let _ = tx.send((Instant::now(), line));
            }
        }
    });
    let wait = Duration::from_secs(120);
    rx.recv_timeout(wait).expect("the first evaluation");
    let mut times = Vec::new();
    for i in 0..saves {
        let text = if onward {
            original.replace(from, &format!("box shelf_3 at (1500, 2900, {})", 1401 + i))
        } else if i % 2 == 0 {
            original.replace(from, to)
        } else {
            original.clone()
        };
        std::thread::sleep(Duration::from_millis(300));
        let start = Instant::now();
        std::fs::write(&file, text).unwrap();
        let (end, line) = rx.recv_timeout(wait).expect("an evaluation");
        let ms = (end - start).as_secs_f64() * 1000.0;
        println!("{ms:5.0} ms  {line}");
        times.push(ms);
    }
    let _ = child.kill();
    let _ = child.wait();
    times.sort_by(f64::total_cmp);
    println!(
        "{edit}: least {:.0} ms, median {:.0} ms, greatest {:.0} ms over {saves} saves",
        times[0],
        times[times.len() / 2],
        times[times.len() - 1]
    );
}

/// The `reach` binary beside this example's directory
/// (`target/release/reach`).
fn reach_binary() -> PathBuf {
    let exe = std::env::current_exe().expect("the example's path");
    let dir = exe
        .parent()
        .and_then(|d| d.parent())
        .expect("target/release");
    dir.join(format!("reach{}", std::env::consts::EXE_SUFFIX))
}
