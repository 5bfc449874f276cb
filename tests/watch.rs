//! `reach watch` on a temporary scenario that uses another file: edited in
//! place, replaced by rename, deleted and re-created, broken and fixed, and
//! its used file edited. Each step waits (generously) for the new output
//! and checks the process is still alive.

use std::io::{BufRead, BufReader};
use std::path::Path;
use std::process::{Child, Command, Stdio};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

const PARTS: &str = "// Used by watched.reach.\nlet mug_h = 960\n";

fn scenario(extra_mm: u32) -> String {
    format!(
        "use std::arm\nuse \"parts.reach\"\nroom kitchen {{\n  size 3600 x 2800 x 2500\n  box counter at (0, 0, 0) size (600, 2800, 900)\n  target mug at (400, 1150, mug_h + {extra_mm})\n}}\nperson ben {{\n  mannequin right_arm\n  base fixed {{ at (850, 1300, 930) heading 180deg }}\n}}\nreach mug by ben\n"
    )
}

struct Watch {
    child: Child,
    lines: Arc<Mutex<Vec<String>>>,
}

impl Watch {
    fn start(file: &Path) -> Watch {
        Watch::start_with(file, &[])
    }

    fn start_with(file: &Path, more: &[&str]) -> Watch {
        let mut child = Command::new(env!("CARGO_BIN_EXE_reach"))
            .args(["watch", file.to_str().unwrap()])
            .args(more)
            .stdout(Stdio::piped())
            .stderr(Stdio::null())
            .spawn()
            .unwrap();
        let stdout = child.stdout.take().unwrap();
        let lines = Arc::new(Mutex::new(Vec::new()));
        let sink = Arc::clone(&lines);
        std::thread::spawn(move || {
            for line in BufReader::new(stdout).lines().map_while(Result::ok) {
                sink.lock().unwrap().push(line);
            }
        });
        Watch { child, lines }
    }

    fn count(&self, needle: &str) -> usize {
        self.lines
            .lock()
            .unwrap()
            .iter()
            .filter(|l| l.contains(needle))
            .count()
    }

    /// Wait until `needle` has appeared `times` times, and check the process
    /// is alive.
    fn expect(&mut self, needle: &str, times: usize) {
        let started = Instant::now();
        while self.count(needle) < times {
            assert!(
                started.elapsed() < Duration::from_secs(30),
                "waited for {times} x {needle:?}; output:\n{}",
                self.lines.lock().unwrap().join("\n")
            );
            std::thread::sleep(Duration::from_millis(20));
        }
        assert!(
            self.child.try_wait().unwrap().is_none(),
            "reach watch exited"
        );
    }
}

impl Drop for Watch {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// A scenario that uses `parts.reach`, in a directory of its own, watched
/// until its first results are shown.
fn watching() -> (tempfile::TempDir, std::path::PathBuf, Watch) {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("watched.reach");
    std::fs::write(dir.path().join("parts.reach"), PARTS).unwrap();
    std::fs::write(&file, scenario(0)).unwrap();
    let mut w = Watch::start(&file);
    w.expect("first results", 1);
    (dir, file, w)
}

#[test]
fn watch_follows_every_way_of_saving() {
    let (dir, file, mut w) = watching();

    // Written in place.
    std::fs::write(&file, scenario(1500)).unwrap();
    w.expect("mug by ben: reachable -> NOT reachable", 1);

    // Replaced by a rename, as many editors save.
    let tmp = dir.path().join(".watched.reach.tmp");
    std::fs::write(&tmp, scenario(0)).unwrap();
    std::fs::rename(&tmp, &file).unwrap();
    w.expect("mug by ben: NOT reachable: out of reach -> reachable", 1);

    // Deleted and created again.
    std::fs::remove_file(&file).unwrap();
    std::thread::sleep(Duration::from_millis(100));
    std::fs::write(&file, scenario(1500)).unwrap();
    w.expect("mug by ben: reachable -> NOT reachable", 2);

    // Broken, then fixed.
    std::fs::write(&file, scenario(0) + "room {\n").unwrap();
    w.expect("errors found", 1);
    std::fs::write(&file, scenario(0)).unwrap();
    w.expect("mug by ben: NOT reachable: out of reach -> reachable", 2);

    // The used file changes.
    std::fs::write(dir.path().join("parts.reach"), PARTS.replace("960", "2500")).unwrap();
    w.expect("mug by ben: reachable -> NOT reachable", 3);
}

/// Each evaluation says which of the scenario's expectations are not met.
#[test]
fn watch_shows_the_expectations_on_each_evaluation() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("watched.reach");
    std::fs::write(dir.path().join("parts.reach"), PARTS).unwrap();
    let expecting = |extra_mm| scenario(extra_mm) + "expect ben reaches mug\n";
    std::fs::write(&file, expecting(0)).unwrap();
    let mut w = Watch::start(&file);
    w.expect("every expectation met (1)", 1);
    std::fs::write(&file, expecting(1500)).unwrap();
    w.expect("expectations NOT met (1 of 1): ben reaches mug", 1);
    std::fs::write(&file, expecting(0)).unwrap();
    w.expect("every expectation met (1)", 2);
}

/// `reach watch --out DIR` keeps the page current: each evaluation writes
/// a new `report.html` and a new stamp beside it, which the open page polls.
#[test]
fn watch_keeps_the_page_and_its_stamp_current() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("watched.reach");
    let out = dir.path().join("out");
    std::fs::write(dir.path().join("parts.reach"), PARTS).unwrap();
    std::fs::write(&file, scenario(0)).unwrap();
    let mut w = Watch::start_with(&file, &["--out", out.to_str().unwrap()]);
    w.expect("first results", 1);
    let stamp = std::fs::read_to_string(out.join("report-stamp.js")).unwrap();
    let page = std::fs::read_to_string(out.join("report.html")).unwrap();
    assert!(
        page.contains("\"at\":[400.0,1150.0,960.0]"),
        "the mug where it stands"
    );
    std::fs::write(&file, scenario(1500)).unwrap();
    w.expect("mug by ben: reachable -> NOT reachable", 1);
    let new_stamp = std::fs::read_to_string(out.join("report-stamp.js")).unwrap();
    let new_page = std::fs::read_to_string(out.join("report.html")).unwrap();
    assert_ne!(stamp, new_stamp);
    assert!(
        new_page.contains("\"at\":[400.0,1150.0,2460.0]"),
        "the mug moved up"
    );
    assert!(
        new_page.contains(new_stamp.split('"').nth(1).unwrap()),
        "the page holds its stamp"
    );
}

/// An upturned crate as OBJ text, from `min` to `min + size` (mm): a cube
/// without its bottom face, open, so that what it covers is not inside a
/// solid (which a target may not be) but behind its walls.
fn crate_obj(min: [f64; 3], size: f64) -> String {
    let cube = cube_obj(min, size);
    cube.lines()
        .filter(|line| *line != "f 1 3 4 2")
        .map(|line| format!("{line}\n"))
        .collect()
}

/// A closed cube as OBJ text, from `min` to `min + size` (mm).
pub(crate) fn cube_obj(min: [f64; 3], size: f64) -> String {
    let mut text = String::new();
    for i in 0..8 {
        let corner = |axis: usize| min[axis] + if i >> axis & 1 == 1 { size } else { 0.0 };
        text += &format!("v {} {} {}\n", corner(0), corner(1), corner(2));
    }
    // Faces wound outwards; vertex k has x = bit 0, y = bit 1, z = bit 2.
    for face in [
        "1 3 4 2", "5 6 8 7", "1 2 6 5", "3 7 8 4", "1 5 7 3", "2 4 8 6",
    ] {
        text += &format!("f {face}\n");
    }
    text
}

#[test]
fn watch_follows_a_mesh_file_and_a_moved_mesh() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("watched.reach");
    let obj = dir.path().join("crate.obj");
    std::fs::write(dir.path().join("parts.reach"), PARTS).unwrap();
    // A crate over the mug: no arm gets in.
    std::fs::write(&obj, crate_obj([250.0, 1000.0, 920.0], 300.0)).unwrap();
    let scenario = |at_mm: i32| {
        scenario(0).replace(
            "  target mug",
            &format!("  mesh crate from \"crate.obj\" at ({at_mm}, 0, 0)\n  target mug"),
        )
    };
    std::fs::write(&file, scenario(0)).unwrap();
    let mut w = Watch::start(&file);
    w.expect("first results", 1);
    assert_eq!(w.count("NOT reachable"), 1, "{:?}", w.lines.lock().unwrap());

    // The OBJ file is edited: the crate moves away from the mug.
    std::fs::write(&obj, crate_obj([2500.0, 1000.0, 920.0], 300.0)).unwrap();
    w.expect(
        "mug by ben: NOT reachable: blocked by `crate` -> reachable",
        1,
    );

    // The scenario moves the mesh back over the mug.
    std::fs::write(&file, scenario(-2250)).unwrap();
    w.expect("mug by ben: reachable -> NOT reachable", 1);
}

/// The gaps hostile users found: a root that is a symbolic link whose
/// target is edited, a used file's directory removed and made again, and a
/// used file swapped for a FIFO (which must not block the watcher).
#[cfg(unix)]
#[test]
fn watch_follows_links_remade_directories_and_is_not_held_by_a_fifo() {
    let dir = tempfile::tempdir().unwrap();
    let real = dir.path().join("real");
    let sub = real.join("sub");
    std::fs::create_dir_all(&sub).unwrap();
    std::fs::write(sub.join("parts.reach"), PARTS).unwrap();
    let target = real.join("target.reach");
    let text = |extra_mm| scenario(extra_mm).replace("\"parts.reach\"", "\"real/sub/parts.reach\"");
    std::fs::write(&target, text(0)).unwrap();
    let link = dir.path().join("link.reach");
    std::os::unix::fs::symlink(&target, &link).unwrap();
    let mut w = Watch::start(&link);
    w.expect("first results", 1);

    // The link's target is edited.
    std::fs::write(&target, text(1500)).unwrap();
    w.expect("mug by ben: reachable -> NOT reachable", 1);
    std::fs::write(&target, text(0)).unwrap();
    w.expect("mug by ben: NOT reachable: out of reach -> reachable", 1);

    // The used file's directory goes, then comes back with another file.
    std::fs::remove_dir_all(&sub).unwrap();
    w.expect("errors found", 1);
    std::fs::create_dir(&sub).unwrap();
    std::thread::sleep(Duration::from_millis(200));
    std::fs::write(sub.join("parts.reach"), PARTS.replace("960", "2500")).unwrap();
    w.expect("mug by ben: reachable -> NOT reachable", 2);

    // The used file becomes a FIFO: refused at once, and the watcher goes
    // on to see it become a file again.
    std::fs::remove_file(sub.join("parts.reach")).unwrap();
    let made = Command::new("mkfifo")
        .arg(sub.join("parts.reach"))
        .status()
        .unwrap();
    assert!(made.success());
    // (The directory made again, still empty, was no change to show.)
    w.expect("errors found", 2);
    std::fs::remove_file(sub.join("parts.reach")).unwrap();
    std::fs::write(sub.join("parts.reach"), PARTS).unwrap();
    w.expect("mug by ben: NOT reachable: out of reach -> reachable", 2);
}

/// A save that leaves every file as it was (an editor's rename whose
/// write was already seen, a file saved unchanged) shows nothing again;
/// the next real change is shown.
#[test]
fn watch_does_not_evaluate_again_what_a_save_left_unchanged() {
    let (dir, file, mut w) = watching();
    // The first evaluation found the used file: the files it read are
    // known from the second on.
    std::fs::write(&file, scenario(1)).unwrap();
    w.expect("=== evaluation 2", 1);
    // The same bytes, written in place and by a rename.
    std::fs::write(&file, scenario(1)).unwrap();
    let tmp = dir.path().join(".watched.reach.tmp");
    std::fs::write(&tmp, scenario(1)).unwrap();
    std::fs::rename(&tmp, &file).unwrap();
    std::fs::write(dir.path().join("parts.reach"), PARTS).unwrap();
    std::thread::sleep(Duration::from_millis(600));
    assert_eq!(
        w.count("=== evaluation"),
        2,
        "{}",
        w.lines.lock().unwrap().join("\n")
    );
    std::fs::write(&file, scenario(1500)).unwrap();
    w.expect("mug by ben: reachable -> NOT reachable", 1);
    assert_eq!(w.count("=== evaluation"), 3);
}

/// A save is said at once, with the file that changed, before its
/// evaluation; the summary names the tasks run again where others were
/// kept, and lists each changed answer on a line of its own, last.
#[test]
fn watch_says_at_once_what_changed_and_which_tasks_it_runs_again() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("two.reach");
    let text = |far_y: u32| {
        format!(
            "use std::arm\nroom kitchen {{\n  size 6000 x 6000 x 2500\n  \
             target mug at (400, 1150, 960)\n  target far at (5000, {far_y}, 960)\n}}\n\
             person ben {{\n  mannequin right_arm\n  base fixed {{ at (850, 1300, 930) heading 180deg }}\n}}\n\
             reach mug, far by ben\n"
        )
    };
    std::fs::write(&file, text(5000)).unwrap();
    let mut w = Watch::start(&file);
    w.expect("first results", 1);
    std::fs::write(&file, text(5001)).unwrap();
    w.expect("=== evaluation 2", 1);
    w.expect("run again: far by ben", 1);
    let lines = w.lines.lock().unwrap().clone();
    let said = lines
        .iter()
        .position(|l| l.starts_with("--- two.reach changed: evaluating"));
    let shown = lines.iter().position(|l| l.starts_with("=== evaluation 2"));
    assert!(said.is_some() && said < shown, "{}", lines.join("\n"));
}

/// `watch -q` shows the summary (and the answers that changed), not the
/// report.
#[test]
fn watch_quiet_shows_only_what_changed() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("watched.reach");
    std::fs::write(dir.path().join("parts.reach"), PARTS).unwrap();
    std::fs::write(&file, scenario(0)).unwrap();
    let mut w = Watch::start_with(&file, &["-q"]);
    w.expect("first results", 1);
    std::fs::write(&file, scenario(1500)).unwrap();
    w.expect("  changed: mug by ben: reachable -> NOT reachable", 1);
    let lines = w.lines.lock().unwrap().clone();
    assert!(
        !lines.iter().any(|l| l.starts_with("task ")),
        "{}",
        lines.join("\n")
    );
}

/// Where a save's tasks take a while (a map whose board moved), the
/// answers kept are shown first, the others marked as being evaluated and
/// named, with only the expectations about answers already found; the
/// whole evaluation follows.
#[test]
fn watch_shows_the_answers_kept_while_the_rest_run() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("desk.reach");
    let text = |desk_z: u32| {
        format!(
            "use std::arm\nroom kitchen {{\n  size 4000 x 4000 x 2500\n  \
             box counter at (0, 0, 0) size (600, 2800, 900)\n  target mug at (400, 1150, 960)\n  \
             box desk at (3000, 0, {desk_z}) size (1000, 4000, 20)\n}}\n\
             person ben {{\n  mannequin right_arm\n  base fixed {{ at (850, 1300, 930) heading 180deg }}\n}}\n\
             person ann {{\n  mannequin right_arm\n  base wheelchair\n}}\n\
             reach mug by ben\nmap desk.top by ann {{ step 50mm }}\n\
             expect ben reaches mug\nexpect ann covers desk.top >= 10 %\n"
        )
    };
    std::fs::write(&file, text(700)).unwrap();
    let mut w = Watch::start(&file);
    w.expect("first results", 1);
    std::fs::write(&file, text(701)).unwrap();
    w.expect("=== evaluation 2", 1);
    w.expect("evaluated in", 2);
    let lines = w.lines.lock().unwrap().clone();
    let at = |start: &str| lines.iter().position(|l| l.starts_with(start));
    let all = lines.join("\n");
    let (first, whole) = (
        at("=== first answers, evaluation 2 ===").expect(&all),
        at("=== evaluation 2").expect(&all),
    );
    assert!(first < whole, "{all}");
    let shown = &lines[first..whole];
    let has = |needle: &str| shown.iter().any(|l| l.contains(needle));
    assert!(has("2 tasks, 1 ok, 1 evaluating"), "{all}");
    assert!(has("desk.top by ann: evaluating ..."), "{all}");
    assert!(has("met      ben reaches mug"), "{all}");
    assert!(!has("ann covers desk.top"), "{all}");
    assert!(has("(1 kept); evaluating desk.top by ann"), "{all}");
    assert!(
        lines[whole..]
            .iter()
            .any(|l| l.contains("met      ann covers desk.top")),
        "{all}"
    );
}
