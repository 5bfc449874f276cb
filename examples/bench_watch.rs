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
//! summary, then the least, median and greatest. EDIT `each_box` moves
//! each box of the kitchen up 1 mm in turn (SAVES saves each, the edit
//! made and undone) and prints each box's median; `each_box SAVES NAME`
//! moves only box NAME; `box_on SAVES NAME` moves box NAME up 1 mm
//! further at every save.

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
    if edit == "each_box" {
        return each_box(saves, args.get(3).map(String::as_str));
    }
    if edit == "box_on" {
        return box_on(saves, args.get(3).expect("box_on SAVES NAME"));
    }
    let onward = edit == "shelf_on";
    let named = if onward { "shelf" } else { edit };
    let Some(&(_, from, to)) = EDITS.iter().find(|(name, ..)| *name == named) else {
        panic!("EDIT is target, shelf, shelf_side, tall or shelf_on");
    };
    let original = kitchen();
    assert!(original.contains(from));
    let watched = Watched::start(&original);
    let mut times = Vec::new();
    for i in 0..saves {
        let text = if onward {
            original.replace(from, &format!("box shelf_3 at (1500, 2900, {})", 1401 + i))
        } else if i % 2 == 0 {
            original.replace(from, to)
        } else {
            original.clone()
        };
        times.push(watched.save(&text, true));
    }
    summary(edit, times);
}

/// The least, median and greatest of `times` (ms), printed after `what`.
fn summary(what: &str, mut times: Vec<f64>) {
    times.sort_by(f64::total_cmp);
    println!(
        "{what}: least {:.0} ms, median {:.0} ms, greatest {:.0} ms over {} saves",
        times[0],
        times[times.len() / 2],
        times[times.len() - 1],
        times.len()
    );
}

/// Each box of the kitchen (or only the box `only`) moved up 1 mm and
/// back, `saves` saves each: each box's median, and how many boxes are
/// within 100 ms.
fn each_box(saves: usize, only: Option<&str>) {
    let original = kitchen();
    let watched = Watched::start(&original);
    let mut within = 0;
    let boxes: Vec<(String, String)> = original
        .lines()
        .filter_map(|line| raised(line).map(|up| (line.to_string(), up)))
        .filter(|(line, _)| only.is_none_or(|name| line.split_whitespace().nth(1) == Some(name)))
        .collect();
    for (line, up) in &boxes {
        let moved = original.replacen(line.as_str(), up, 1);
        let mut times: Vec<f64> = (0..saves)
            .map(|i| watched.save(if i % 2 == 0 { &moved } else { &original }, false))
            .collect();
        times.sort_by(f64::total_cmp);
        let median = times[times.len() / 2];
        within += usize::from(median <= 100.0);
        let name = line.split_whitespace().nth(1).unwrap_or("?");
        println!("{name:20} median {median:5.0} ms  (least {:.0})", times[0]);
    }
    println!("{within} of {} boxes within 100 ms", boxes.len());
}

/// Box `name` raised 1 mm further at every save, never back: a room not
/// seen before at every save.
fn box_on(saves: usize, name: &str) {
    let original = kitchen();
    let line = (original.lines())
        .find(|l| l.trim_start().starts_with(&format!("box {name} ")))
        .expect("a box of the kitchen");
    let watched = Watched::start(&original);
    let times: Vec<f64> = (1..=saves)
        .map(|i| {
            let up = raised_by(line, i).expect("a box line");
            watched.save(&original.replacen(line, &up, 1), true)
        })
        .collect();
    summary(&format!("{name} on"), times);
}

/// A `box NAME at (x, y, z) ...` line with its z raised by 1 mm.
fn raised(line: &str) -> Option<String> {
    raised_by(line, 1)
}

/// A `box NAME at (x, y, z) ...` line with its z raised by `mm`.
fn raised_by(line: &str, mm: usize) -> Option<String> {
    let trimmed = line.trim_start();
    if !trimmed.starts_with("box ") {
        return None;
    }
    let at = line.find(" at (")? + " at (".len();
    let close = at + line[at..].find(')')?;
    Some(format!("{} + {mm}{}", &line[..close], &line[close..]))
}

/// The example this benchmark edits.
fn kitchen() -> String {
    std::fs::read_to_string("examples/kitchen_wheelchair.reach")
        .expect("run from the crate's directory")
}

/// `reach watch` on a copy of the kitchen in a temporary directory.
struct Watched {
    _dir: tempfile::TempDir,
    file: PathBuf,
    child: std::process::Child,
    evaluations: mpsc::Receiver<(Instant, String)>,
}

impl Watched {
    /// Started on `text`, once its first evaluation is shown.
    fn start(text: &str) -> Self {
        let dir = tempfile::tempdir().expect("a temporary directory");
        let file = dir.path().join("kitchen.reach");
        std::fs::write(&file, text).unwrap();
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
        rx.recv_timeout(WAIT).expect("the first evaluation");
        Watched {
            _dir: dir,
            file,
            child,
            evaluations: rx,
        }
    }

    /// `text` saved: the time to its evaluation's summary, in ms, printed
    /// with the summary where `print`.
    fn save(&self, text: &str, print: bool) -> f64 {
        std::thread::sleep(Duration::from_millis(300));
        let start = Instant::now();
        std::fs::write(&self.file, text).unwrap();
        let (end, line) = self.evaluations.recv_timeout(WAIT).expect("an evaluation");
        let ms = (end - start).as_secs_f64() * 1000.0;
        if print {
            println!("{ms:5.0} ms  {line}");
        }
        ms
    }
}

impl Drop for Watched {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// The longest wait for an evaluation.
const WAIT: Duration = Duration::from_secs(120);

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
