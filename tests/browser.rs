//! `report.html` in a real browser: headless Chromium opens the page from
//! `file://` as a user would, offline. For each example: no error on the
//! page, the picture is not blank, and a click on another task changes it.
//! For the wheelchair kitchen, screenshots of two tasks show the person's
//! colour and each task's target in its result's colour, and differ; a
//! stamp beside the page that no longer matches it is seen (the live
//! reload of `reach watch --out`), one that matches is not.
//!
//! Chromium is found as `REACH_CHROMIUM`, or `chromium`, `chromium-browser`
//! or `google-chrome` on the PATH. Without one each test prints "SKIPPED"
//! in `cargo test`'s output and passes,
//! unless `REACH_REQUIRE_BROWSER` is set, as `.ci/run` sets it (after
//! installing Debian's chromium). `REACH_UPDATE_DOCS=1` writes the
//! screenshots in `docs/` again.

use std::path::{Path, PathBuf};
use std::process::Command;

fn chromium() -> Option<PathBuf> {
    if let Some(path) = std::env::var_os("REACH_CHROMIUM") {
        return Some(PathBuf::from(path));
    }
    let path = std::env::var_os("PATH")?;
    ["chromium", "chromium-browser", "google-chrome"]
        .iter()
        .flat_map(|name| std::env::split_paths(&path).map(move |dir| dir.join(name)))
        .find(|p| p.is_file())
}

/// Chromium, or `None` (with a note) where it may be missing.
fn browser() -> Option<PathBuf> {
    let found = chromium();
    if found.is_none() {
        assert!(
            std::env::var_os("REACH_REQUIRE_BROWSER").is_none(),
            "REACH_REQUIRE_BROWSER is set and no Chromium was found (REACH_CHROMIUM, or chromium on the PATH)"
        );
        // Written past the test harness's capture (which takes only
        // `eprintln!`), so that `cargo test` shows it beside the "ok".
        use std::io::Write;
        let _ = writeln!(
            std::io::stderr(),
            "SKIPPED: no Chromium (install Debian's chromium, or set REACH_CHROMIUM)"
        );
    }
    found
}

/// Headless Chromium as this machine allows it: software WebGL, no network
/// services, a fresh profile.
fn headless(chromium: &Path, profile: &Path) -> Command {
    let mut c = Command::new(chromium);
    c.args([
        "--headless",
        "--no-sandbox",
        "--disable-gpu",
        "--use-angle=swiftshader",
        "--enable-unsafe-swiftshader",
        "--disable-quic",
        "--no-first-run",
        "--disable-background-networking",
        "--disable-component-update",
        "--disable-sync",
        "--window-size=1200,800", // WINDOW
        "--virtual-time-budget=4000",
    ])
    .arg(format!("--user-data-dir={}", profile.display()));
    c
}

/// `reach run --out DIR FILE`.
fn write_report(file: &str, dir: &Path) {
    let o = Command::new(env!("CARGO_BIN_EXE_reach"))
        .args(["run", "--format", "json", "--out"])
        .arg(dir)
        .arg(file)
        .output()
        .unwrap();
    assert!(
        o.status.success(),
        "{file}: {}",
        String::from_utf8_lossy(&o.stderr)
    );
}

fn url(dir: &Path, suffix: &str) -> String {
    format!("file://{}/report.html{suffix}", dir.display())
}

/// The page's `<body>` attributes after it ran, from the DOM Chromium dumps.
fn body_attributes(chromium: &Path, profile: &Path, page: &str) -> String {
    let o = headless(chromium, profile)
        .arg("--dump-dom")
        .arg(page)
        .output()
        .unwrap();
    let dom = String::from_utf8_lossy(&o.stdout).into_owned();
    let start = dom
        .find("<body")
        .unwrap_or_else(|| panic!("no body in {dom}"));
    let end = start + dom[start..].find('>').unwrap();
    dom[start..end].replace("&quot;", "\"")
}

/// The number after `"key":` in `text`.
fn number(text: &str, key: &str) -> f64 {
    let at = text
        .find(&format!("\"{key}\":"))
        .unwrap_or_else(|| panic!("no {key} in {text}"));
    let rest = &text[at + key.len() + 3..];
    let end = rest
        .find(|c: char| !c.is_ascii_digit() && c != '.')
        .unwrap();
    rest[..end].parse().unwrap()
}

#[test]
fn every_example_report_opens_draws_and_changes_on_a_click() {
    let Some(chromium) = browser() else { return };
    let examples = [
        "examples/kitchen.reach",
        "examples/kitchen_wheelchair.reach",
        "examples/mother_kitchen.reach",
        "examples/gaze_shelf.reach",
        "examples/open_door.reach",
    ];
    for file in examples {
        let dir = tempfile::tempdir().unwrap();
        write_report(file, dir.path());
        let body = body_attributes(
            &chromium,
            &dir.path().join("profile"),
            &url(dir.path(), "?selftest"),
        );
        assert!(
            !body.contains("data-errors"),
            "{file}: errors on the page: {body}"
        );
        assert!(
            body.contains("data-ready=\"1\""),
            "{file}: the page never got ready: {body}"
        );
        let pixels = number(&body, "pixels");
        assert!(
            number(&body, "notWhite") > 0.2 * pixels,
            "{file}: the picture is nearly blank: {body}"
        );
        if number(&body, "tasks") > 1.0 {
            assert!(
                number(&body, "changedByClick") > 0.005 * pixels,
                "{file}: a click on the second task did not change the picture: {body}"
            );
        }
    }
}

/// The window's size, and the part of it the 3D view takes: right of the
/// task list (300 px), less the legend in its lower right corner.
const WINDOW: (usize, usize) = (1200, 800);
fn in_view(x: usize, y: usize) -> bool {
    x >= 310 && !(x >= WINDOW.0 - 300 && y >= WINDOW.1 - 220)
}

/// RGB pixels of a PNG, each with its place.
fn pixels(path: &Path) -> Vec<(usize, usize, [u8; 3])> {
    let decoder = png::Decoder::new(std::io::BufReader::new(std::fs::File::open(path).unwrap()));
    let mut reader = decoder.read_info().unwrap();
    let mut buf = vec![0; reader.output_buffer_size().unwrap()];
    let info = reader.next_frame(&mut buf).unwrap();
    let step = info.color_type.samples();
    let width = info.width as usize;
    buf[..info.buffer_size()]
        .chunks_exact(step)
        .enumerate()
        .map(|(k, p)| (k % width, k / width, [p[0], p[1], p[2]]))
        .collect()
}

/// The RGB pixels of a PNG that fall in the 3D view.
fn view_pixels(path: &Path) -> Vec<[u8; 3]> {
    pixels(path)
        .into_iter()
        .filter(|&(x, y, _)| in_view(x, y))
        .map(|(_, _, rgb)| rgb)
        .collect()
}

/// Pixels near the person's skin (`figure::SKIN`, #e8b48a, as lit).
fn skin(p: &[u8; 3]) -> bool {
    let [r, g, b] = p.map(i32::from);
    r > 150 && r - g > 25 && g - b > 20 && r - b > 60 && r - g < 90
}

/// Pixels of a target reached (#2e9e4f) or not (#d64545), drawn unlit.
fn near(p: &[u8; 3], rgb: [i32; 3]) -> bool {
    p.iter()
        .zip(rgb)
        .all(|(&c, want)| (i32::from(c) - want).abs() <= 12)
}

#[test]
fn screenshots_show_the_person_and_each_targets_result() {
    let Some(chromium) = browser() else { return };
    let dir = tempfile::tempdir().unwrap();
    write_report("examples/kitchen_wheelchair.reach", dir.path());
    let profile = dir.path().join("profile");
    // Task 0: ben reaches counter_front; task 7: ann does NOT reach
    // cabinet_low.
    let mut shots = Vec::new();
    for (task, colour) in [(0, [0x2e, 0x9e, 0x4f]), (7, [0xd6, 0x45, 0x45])] {
        let png = dir.path().join(format!("task{task}.png"));
        let o = headless(&chromium, &profile)
            .arg(format!("--screenshot={}", png.display()))
            .arg(url(dir.path(), &format!("#task={task}")))
            .output()
            .unwrap();
        assert!(
            png.is_file(),
            "no screenshot: {}",
            String::from_utf8_lossy(&o.stderr)
        );
        let p = view_pixels(&png);
        let skin_share = p.iter().filter(|q| skin(q)).count() as f64 / p.len() as f64;
        assert!(
            skin_share > 0.01,
            "task {task}: the person hardly shows ({skin_share})"
        );
        let target = p.iter().filter(|q| near(q, colour)).count();
        eprintln!("task {task}: {target} pixels of the target's colour");
        assert!(
            target > 100,
            "task {task}: the target's colour shows in {target} pixels"
        );
        if std::env::var_os("REACH_UPDATE_DOCS").is_some() {
            std::fs::copy(&png, format!("docs/report-task{task}.png")).unwrap();
        }
        shots.push(p);
    }
    let differ = shots[0]
        .iter()
        .zip(&shots[1])
        .filter(|(a, b)| a != b)
        .count();
    assert!(
        differ > shots[0].len() / 20,
        "two tasks, nearly one picture ({differ} pixels differ)"
    );
}

#[test]
fn a_page_opened_from_disk_sees_a_new_stamp_beside_it() {
    let Some(chromium) = browser() else { return };
    let dir = tempfile::tempdir().unwrap();
    write_report("examples/kitchen.reach", dir.path());
    let profile = dir.path().join("profile");
    let page = url(dir.path(), "?selftest");
    let body = body_attributes(&chromium, &profile, &page);
    assert!(
        !body.contains("data-stale"),
        "the stamp it was written with is not new: {body}"
    );
    std::fs::write(
        dir.path().join("report-stamp.js"),
        "window.reachStamp && window.reachStamp(\"0000000000000000\");\n",
    )
    .unwrap();
    let body = body_attributes(&chromium, &profile, &page);
    assert!(
        body.contains("data-stale=\"1\""),
        "a new stamp went unseen: {body}"
    );
}

/// The page's selftest record (`data-selftest`), from its `<body>`.
fn selftest(chromium: &Path, profile: &Path, page: &str) -> serde_json::Value {
    let body = body_attributes(chromium, profile, page);
    assert!(!body.contains("data-errors"), "errors on the page: {body}");
    let start = body
        .find("data-selftest=\"")
        .unwrap_or_else(|| panic!("no selftest in {body}"))
        + "data-selftest=\"".len();
    let end = start + body[start..].find("}\"").unwrap() + 1;
    serde_json::from_str(&body[start..end]).unwrap()
}

/// Opened without a task in its address, the page shows the whole room
/// from above a corner, with the two walls on the camera's side cut away
/// and the other two drawn; `#task=N` opens close on task N (chosen in the
/// list); `&view=plan` opens on the plan, every wall seen edge on, a
/// picture unlike the room's; the pointer over a target names it.
/// `REACH_UPDATE_DOCS=1` writes the whole
/// room's screenshot as docs/report-room.png (the README shows it).
#[test]
fn the_page_opens_on_the_room_its_walls_cut_away_and_honours_its_address() {
    let Some(chromium) = browser() else { return };
    let dir = tempfile::tempdir().unwrap();
    write_report("examples/kitchen_wheelchair.reach", dir.path());
    let profile = dir.path().join("profile");

    let room = selftest(&chromium, &profile, &url(dir.path(), "?selftest"));
    assert_eq!(room["view"], "room", "{room}");
    assert_eq!(room["selected"], 0, "{room}");
    // The pointer over the first target names it.
    assert_eq!(room["tip"], "counter_front", "{room}");
    let walls: Vec<i64> = serde_json::from_value(room["walls"].clone()).unwrap();
    assert_eq!(walls.iter().sum::<i64>(), 2, "two walls cut away: {room}");

    let task = selftest(&chromium, &profile, &url(dir.path(), "?selftest#task=7"));
    assert_eq!(task["view"], "task", "{task}");
    assert_eq!(task["selected"], 7, "{task}");

    let plan = selftest(
        &chromium,
        &profile,
        &url(dir.path(), "?selftest#task=7&view=plan"),
    );
    assert_eq!(plan["view"], "plan", "{plan}");
    assert_eq!(plan["selected"], 7, "{plan}");
    assert_eq!(plan["walls"], serde_json::json!([1, 1, 1, 1]), "{plan}");

    let shot = |suffix: &str, name: &str| {
        let png = dir.path().join(name);
        headless(&chromium, &profile)
            .arg(format!("--screenshot={}", png.display()))
            .arg(url(dir.path(), suffix))
            .output()
            .unwrap();
        assert!(png.is_file(), "no screenshot {name}");
        png
    };
    let room_png = shot("#task=7&view=room", "room.png");
    let plan_png = shot("#task=7&view=plan", "plan.png");
    let (a, b) = (view_pixels(&room_png), view_pixels(&plan_png));
    let differ = a.iter().zip(&b).filter(|(p, q)| p != q).count();
    assert!(
        differ > a.len() / 5,
        "the plan looks like the room ({differ} of {} pixels differ)",
        a.len()
    );
    // The room's walls show in the whole room's picture: light grey
    // (#e3e6eb, lit), neither white nor the furniture's colour.
    let wall = a
        .iter()
        .filter(|p| {
            let [r, g, b] = p.map(i32::from);
            (150..235).contains(&r) && (g - r).abs() < 8 && (b - g) >= 0 && (b - g) < 14
        })
        .count();
    assert!(
        wall > a.len() / 20,
        "the walls hardly show ({wall} of {} pixels)",
        a.len()
    );
    if std::env::var_os("REACH_UPDATE_DOCS").is_some() {
        std::fs::copy(shot("", "whole.png"), "docs/report-room.png").unwrap();
    }
}
