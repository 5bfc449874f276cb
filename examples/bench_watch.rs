//! Watch mode's latency: `reach watch` on a copy of
//! `examples/kitchen_wheelchair.reach`, saved again and again with one
//! edit made and undone, timed from the end of each write to the first
//! answers it shows (the answers kept, printed while the tasks the save
//! runs again are running, or the whole evaluation where it is quicker)
//! and to the summary line of the evaluation it causes (a monotonic clock;
//! the first 25 ms are the wait that batches an editor's burst of events).
//!
//! `cargo build --release && cargo run --release --example bench_watch -- EDIT [SAVES]`,
//! EDIT one of `target` (a target moved 1 mm), `shelf` (shelf_3 up 1 mm),
//! `shelf_side` (shelf_3 along the wall by 1 mm), `tall` (the tall
//! cabinet's top up 1 mm), each undone at the next save;
//! or `shelf_on` (shelf_3 up 1 mm further at every save, never back: a
//! room not seen before at every save). Prints each save's times and
//! summary, then the least, median and greatest of each. EDIT `each_box` moves
//! each box of the kitchen up 1 mm in turn (SAVES saves each, the edit
//! made and undone) and prints each box's medians; `each_box SAVES NAME`
//! moves only box NAME; `each_box_on` moves each box up 1 mm further at
//! every save, never back; `box_on SAVES NAME` moves box NAME up 1 mm
//! further at every save and prints each save.

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
    if edit == "each_box" || edit == "each_box_on" {
        let onward = edit == "each_box_on";
        return each_box(saves, args.get(3).map(String::as_str), onward);
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

/// A save's times from the write: to the first answers shown, and to
/// the evaluation's end.
#[derive(Clone, Copy)]
struct Times {
    first_ms: f64,
    last_ms: f64,
}

/// The least, median and greatest of `times`' first answers and of their
/// ends, printed after `what`.
fn summary(what: &str, times: Vec<Times>) {
    let spread = |mut ms: Vec<f64>| {
        ms.sort_by(f64::total_cmp);
        format!(
            "least {:.0} ms, median {:.0} ms, greatest {:.0} ms",
            ms[0],
            ms[ms.len() / 2],
            ms[ms.len() - 1]
        )
    };
    println!(
        "{what}: first answers {}; whole answer {} (over {} saves)",
        spread(times.iter().map(|t| t.first_ms).collect()),
        spread(times.iter().map(|t| t.last_ms).collect()),
        times.len()
    );
}

/// Each box of the kitchen (or only the box `only`) moved up 1 mm and
/// back (`each_box`) or further at every save (`onward`), `saves` saves
/// each: each box's medians to the first answers and to the whole
/// evaluation, and how many boxes show their first answers within 100 ms.
fn each_box(saves: usize, only: Option<&str>, onward: bool) {
    let original = kitchen();
    let watched = Watched::start(&original);
    let mut within = 0;
    let boxes: Vec<&str> = (original.lines())
        .filter(|line| raised(line).is_some())
        .filter(|line| only.is_none_or(|name| line.split_whitespace().nth(1) == Some(name)))
        .collect();
    let median = |mut ms: Vec<f64>| {
        ms.sort_by(f64::total_cmp);
        ms[ms.len() / 2]
    };
    for line in &boxes {
        let text = |i: usize| match (onward, i % 2) {
            (true, _) => original.replacen(line, &raised_by(line, i + 1).unwrap_or_default(), 1),
            (false, 0) => original.replacen(line, &raised(line).unwrap_or_default(), 1),
            (false, _) => original.clone(),
        };
        let times: Vec<Times> = (0..saves).map(|i| watched.save(&text(i), false)).collect();
        let first = median(times.iter().map(|t| t.first_ms).collect());
        let whole = median(times.iter().map(|t| t.last_ms).collect());
        within += usize::from(first <= 100.0);
        let name = line.split_whitespace().nth(1).unwrap_or("?");
        println!("{name:20} first answers {first:5.0} ms, whole {whole:5.0} ms (medians)");
    }
    println!(
        "{within} of {} boxes show their first answers within 100 ms",
        boxes.len()
    );
}

/// Box `name` raised 1 mm further at every save, never back: a room not
/// seen before at every save.
fn box_on(saves: usize, name: &str) {
    let original = kitchen();
    let line = (original.lines())
        .find(|l| l.trim_start().starts_with(&format!("box {name} ")))
        .expect("a box of the kitchen");
    let watched = Watched::start(&original);
    let times: Vec<Times> = (1..=saves)
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
                let shown = ["first answers", "evaluated", "errors"];
                if shown.iter().any(|start| line.starts_with(start)) {
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

    /// `text` saved: the times to its first answers (the answers kept
    /// shown while the rest run, or the whole evaluation where it is
    /// quick) and to its evaluation's summary, in ms, printed with the
    /// summary where `print`.
    fn save(&self, text: &str, print: bool) -> Times {
        std::thread::sleep(Duration::from_millis(300));
        let start = Instant::now();
        std::fs::write(&self.file, text).unwrap();
        let ms = |end: Instant| (end - start).as_secs_f64() * 1000.0;
        let (first, mut line) = self.evaluations.recv_timeout(WAIT).expect("an evaluation");
        let mut last = first;
        if line.starts_with("first answers") {
            (last, line) = self.evaluations.recv_timeout(WAIT).expect("an evaluation");
        }
        let times = Times {
            first_ms: ms(first),
            last_ms: ms(last),
        };
        if print {
            println!(
                "first {:5.0} ms, last {:5.0} ms  {line}",
                times.first_ms, times.last_ms
            );
        }
        times
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
