//! Files for each map, written with `--out DIR`: the points as CSV and a
//! heat map as SVG, named after the surface and the person (or the
//! population). The SVG shows a horizontal surface in plan (x to the
//! right, y up) and a vertical one in elevation as seen from the room
//! (from the side a hand touches it from, height up), each point's cell
//! graded by how far short it fell (a population's: by the share of its
//! people who reach it), with the room's furniture near it for context
//! (outlines in plan, faces in elevation) and, in plan, where the base
//! stood for the points. Ticks fall on round millimetres, spaced so their
//! labels never meet. Both kinds of map are drawn through one
//! [`Picture`].

use std::fmt::Write;

use nalgebra::{Vector2, Vector3};

use super::colours::{cell_colour, share_colour, MISSED, REACHED, SEEN, SHARES, SHORT, THROUGH};
use super::ticks::nice_step;
use super::view::RoomView;
use crate::escape::markup;
use crate::report::{quoted, MapCell, MapReport, PopulationReport, ShareCell, ShareGrid, BALANCE};

/// File names for a map: `map-SURFACE-PERSON.csv` and `.svg`
/// (`gaze_map-...` for a gaze map), and a map of one effector other than
/// the right hand's `grip` (`hand left`) the effector after them:
/// `map-SURFACE-PERSON-left_grip`.
pub fn file_stem(m: &MapReport) -> String {
    let who = match (m.of, &m.other_hand) {
        ("reach", None) if m.effector != "grip" && !m.effector.is_empty() => {
            format!("{}-{}", m.person, m.effector)
        }
        _ => m.person.clone(),
    };
    stem(m.of, &m.name, &who)
}

/// File names for a population's map: `map-SURFACE-POPULATION`.
pub fn population_stem(p: &PopulationReport, grid: &ShareGrid) -> String {
    stem(grid.of, &p.name, &p.population)
}

fn stem(of: &str, surface: &str, who: &str) -> String {
    let clean = |s: &str| s.replace(|c: char| !c.is_ascii_alphanumeric() && c != '_', "-");
    let kind = if of == "gaze" { "gaze_map" } else { "map" };
    format!("{kind}-{}-{}", clean(surface), clean(who))
}

/// One line per point: where it is, whether it is reachable, the distance
/// left, the comfort, and where the base stood; where the map reaches
/// with either hand, which hand; where the map found why
/// points were not reached (`why true`), why, in a last column.
pub fn csv(m: &MapReport) -> String {
    let with_why = m.cells.iter().any(|c| !c.why().is_empty());
    let with_hand = m.other_hand.is_some();
    let mut out = String::from("column,row,x_mm,y_mm,z_mm,reachable,distance_mm,comfort,base_x_mm,base_y_mm,base_heading_deg");
    out += if with_hand { ",hand" } else { "" };
    out += if with_why { ",why\n" } else { "\n" };
    for c in &m.cells {
        let [x, y, z] = c.point_mm;
        let [bx, by, bh] = c.base_mm_deg;
        let _ = write!(
            out,
            "{},{},{x},{y},{z},{},{},{},{bx},{by},{bh}",
            c.column,
            c.row,
            c.reachable,
            finite(c.distance_mm),
            finite(c.comfort)
        );
        if with_hand {
            let _ = write!(out, ",{}", c.hand.unwrap_or_default());
        }
        if with_why {
            let _ = write!(out, ",{}", csv_field(&c.why_words()));
        }
        out.push('\n');
    }
    out
}

/// A figure for the CSV: empty where there is none (no place to
/// approach the point from, so no posture).
fn finite(value: f64) -> String {
    if value.is_finite() {
        value.to_string()
    } else {
        String::new()
    }
}

/// `text` as one CSV field: quoted, its quotes doubled, where it holds a
/// comma, a quote or a line break.
fn csv_field(text: &str) -> String {
    if text.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", text.replace('"', "\"\""))
    } else {
        text.to_string()
    }
}

/// One line per point of a population's map: where it is, the share of
/// the people who reach (or see) it, how many do, and of how many.
pub fn population_csv(p: &PopulationReport, cells: &[ShareCell]) -> String {
    let mut out = String::from("column,row,x_mm,y_mm,z_mm,share,reached,people\n");
    for c in cells {
        let [x, y, z] = c.point_mm;
        let _ = writeln!(
            out,
            "{},{},{x},{y},{z},{},{},{}",
            c.column, c.row, c.share, c.reached, p.people
        );
    }
    out
}

/// How much room around the map the picture shows, for context.
const CONTEXT_MM: f64 = 400.0;
/// The drawing's largest side, and the margins for axes and the legend.
const DRAWING_PX: f64 = 640.0;
const MARGIN: f64 = 70.0;
const LEGEND_PX: f64 = 190.0;
/// Least space between two tick labels.
const TICK_GAP_PX: f64 = 55.0;
const FURNITURE: &str = "#e9dfcc";
const FURNITURE_EDGE: &str = "#9c8b6c";
const BASE: &str = "#4b5563";
const NOTE: &str = "#555d6b";

/// A map as its SVG shows it, whoever's it is.
pub struct Picture {
    title: String,
    view: &'static str,
    step_mm: f64,
    /// The surface's unit normal on the side it is used from.
    seen_from: Vector3<f64>,
    cells: Vec<PictureCell>,
    /// Where the base stood for the points, in plan (a person's map).
    bases: Option<Vec<[f64; 3]>>,
    /// The colours of the cells and what they mean.
    legend: Vec<(&'static str, String)>,
}

struct PictureCell {
    point_mm: [f64; 3],
    fill: &'static str,
    /// What the cell's tooltip says of it.
    words: String,
}

/// What a point not reached says: how far short it fell, or what it was
/// reached only through, and why where the map found out.
fn missed_words(c: &MapCell) -> String {
    let missed = match c.through() {
        Some(what) if what.starts_with(BALANCE) => format!("reached only losing {what}"),
        Some(what) => format!("reached only through {}", quoted(what)),
        None => format!("{} mm short", c.distance_mm),
    };
    match c.why_words() {
        why if why.is_empty() => missed,
        why => format!("{missed}: {why}"),
    }
}

/// A map's hand in its title: " with either hand", " with `left_grip`"
/// (one effector other than the right hand's grip), or nothing.
fn with_hand(m: &MapReport) -> String {
    match (&m.other_hand, m.of) {
        (Some(_), _) => " with either hand".into(),
        (None, "reach") if m.effector != "grip" && !m.effector.is_empty() => {
            format!(" with `{}`", m.effector)
        }
        _ => String::new(),
    }
}

impl Picture {
    /// One person's map: each point reached, or how far short it fell.
    pub fn of_map(m: &MapReport) -> Self {
        let cells = m
            .cells
            .iter()
            .map(|c| PictureCell {
                point_mm: c.point_mm,
                fill: match c.through() {
                    Some(_) => THROUGH.0,
                    None => cell_colour(m.of, c.reachable, c.distance_mm),
                },
                words: match (c.reachable, m.of) {
                    (true, _) => match c.hand {
                        Some(hand) => format!("{} with the {hand} hand", m.words()[1]),
                        None => m.words()[1].to_string(),
                    },
                    (false, _) if c.hand.is_some() && c.distance_mm.is_finite() => {
                        let hand = c.hand.unwrap_or_default();
                        format!("{} (the {hand} hand came closest)", missed_words(c))
                    }
                    (false, "gaze") => "not seen".to_string(),
                    (false, _) if !c.distance_mm.is_finite() => {
                        "no place to approach it from".into()
                    }
                    (false, _) => missed_words(c),
                },
            })
            .collect();
        let legend = if m.of == "gaze" {
            vec![
                (SEEN, m.words()[1].to_string()),
                (MISSED, format!("not {}", m.words()[1])),
            ]
        } else {
            let short = SHORT.iter().map(|(c, t)| (*c, (*t).to_string()));
            let through = m
                .cells
                .iter()
                .any(|c| c.through().is_some())
                .then(|| (THROUGH.0, THROUGH.1.to_string()));
            std::iter::once((REACHED, m.words()[1].to_string()))
                .chain(short)
                .chain(through)
                .collect()
        };
        Picture {
            title: format!(
                "{} {} by {}{} ({} base): {:.1} % of {} points",
                m.name,
                m.words()[0],
                m.person,
                with_hand(m),
                m.base,
                m.fraction * 100.0,
                m.points
            ),
            view: m.view,
            step_mm: m.step_mm,
            seen_from: Vector3::from(m.seen_from()),
            cells,
            bases: (m.view == "plan").then(|| m.cells.iter().map(|c| c.base_mm_deg).collect()),
            legend,
        }
    }

    /// A population's map: each point by the share of its people who
    /// reach (or see) it.
    pub fn of_population(p: &PopulationReport, grid: &ShareGrid, cells: &[ShareCell]) -> Self {
        let (verb, participle) = if grid.of == "gaze" {
            ("see", "seen")
        } else {
            ("reach", "reached")
        };
        let everyone = cells.iter().filter(|c| c.reached == p.people).count();
        Picture {
            title: format!(
                "{} {participle} by {} ({} people, {} base): {everyone} of {} points by everyone",
                p.name,
                p.population,
                p.people,
                grid.base,
                cells.len()
            ),
            view: grid.view,
            step_mm: grid.step_mm,
            seen_from: Vector3::from(grid.seen_from),
            cells: cells
                .iter()
                .map(|c| PictureCell {
                    point_mm: c.point_mm,
                    fill: share_colour(c.share),
                    words: format!("{} of {} {verb} it", c.reached, p.people),
                })
                .collect(),
            bases: None,
            legend: SHARES
                .iter()
                .map(|(_, colour, label)| (*colour, format!("{participle} by {label}")))
                .collect(),
        }
    }
}

/// How the map is seen: two unit directions in the room for the
/// picture's right and up.
struct Frame {
    right: Vector3<f64>,
    up: Vector3<f64>,
}

impl Frame {
    fn of(m: &Picture) -> Frame {
        if m.view == "plan" {
            return Frame {
                right: Vector3::x(),
                up: Vector3::y(),
            };
        }
        // An elevation, seen from the room: looking along -normal, the
        // right hand points along (-normal) x z.
        let right = (-m.seen_from).cross(&Vector3::z());
        Frame {
            right: right.try_normalize(1e-9).unwrap_or_else(Vector3::x),
            up: Vector3::z(),
        }
    }

    fn at(&self, p: Vector3<f64>) -> Vector2<f64> {
        Vector2::new(p.dot(&self.right), p.dot(&self.up))
    }
}

/// Millimetres of the picture to pixels.
struct Scale {
    lo: Vector2<f64>,
    hi: Vector2<f64>,
    px_per_mm: f64,
}

impl Scale {
    fn x(&self, mm: f64) -> f64 {
        MARGIN + (mm - self.lo.x) * self.px_per_mm
    }
    fn y(&self, mm: f64) -> f64 {
        MARGIN + (self.hi.y - mm) * self.px_per_mm
    }
    fn size(&self) -> Vector2<f64> {
        (self.hi - self.lo) * self.px_per_mm
    }
}

/// The heat map of `m`, with `room`'s furniture around it.
pub fn svg(m: &MapReport, room: Option<&RoomView>) -> String {
    picture_svg(&Picture::of_map(m), room)
}

/// The heat map of `m`, with `room`'s furniture around it.
pub fn picture_svg(m: &Picture, room: Option<&RoomView>) -> String {
    let frame = Frame::of(m);
    let scale = scale(m, &frame, room);
    let title = &m.title;
    let size = scale.size();
    // Wide enough for the drawing and legend, and for the title (about
    // 9 px a character at 15 px bold).
    let width = (size.x + 2.0 * MARGIN + LEGEND_PX).max(9.0 * title.len() as f64 + 2.0 * MARGIN);
    let height = (size.y + 2.0 * MARGIN).max(MARGIN + 7.0 * 22.0 + 40.0);
    let mut s = String::new();
    let _ = writeln!(
        s,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{width:.0}" height="{height:.0}" viewBox="0 0 {width:.0} {height:.0}" font-family="sans-serif" font-size="12">"#
    );
    let _ = writeln!(s, r#"<rect width="100%" height="100%" fill="white"/>"#);
    let _ = writeln!(
        s,
        r#"<text x="{MARGIN}" y="24" font-size="15" font-weight="bold">{}</text>"#,
        markup(title)
    );
    let _ = writeln!(
        s,
        r#"<text x="{MARGIN}" y="44" fill="{NOTE}">{}</text>"#,
        if m.view == "plan" {
            "plan, from above"
        } else {
            "elevation, as seen from the room"
        }
    );
    let _ = writeln!(
        s,
        r#"<svg x="{MARGIN}" y="{MARGIN}" width="{:.1}" height="{:.1}" viewBox="{MARGIN} {MARGIN} {:.1} {:.1}" overflow="hidden">"#,
        size.x, size.y, size.x, size.y
    );
    if let Some(room) = room {
        furniture(&mut s, m, room, &frame, &scale);
    }
    cells(&mut s, m, &frame, &scale);
    if let Some(bases_mm_deg) = &m.bases {
        bases(&mut s, bases_mm_deg, &scale);
    }
    s.push_str("</svg>\n");
    axes(&mut s, m, &scale);
    legend(&mut s, m, MARGIN + size.x + 24.0, room.is_some());
    s.push_str("</svg>\n");
    s
}

/// The picture's extent: the cells, and in plan the bases, with room
/// around them; and the scale that fits it in the drawing.
fn scale(m: &Picture, frame: &Frame, room: Option<&RoomView>) -> Scale {
    let half = m.step_mm / 2.0;
    let mut lo = Vector2::repeat(f64::INFINITY);
    let mut hi = Vector2::repeat(f64::NEG_INFINITY);
    let mut grow = |p: Vector2<f64>, by: f64| {
        lo = lo.inf(&(p - Vector2::repeat(by)));
        hi = hi.sup(&(p + Vector2::repeat(by)));
    };
    for (k, c) in m.cells.iter().enumerate() {
        grow(frame.at(Vector3::from(c.point_mm)), half + CONTEXT_MM);
        if let Some([x, y, _]) = m.bases.as_ref().map(|b| b[k]) {
            if x.is_finite() && y.is_finite() {
                grow(Vector2::new(x, y), 150.0);
            }
        }
    }
    if !lo.x.is_finite() {
        (lo, hi) = (Vector2::zeros(), Vector2::repeat(1000.0));
    }
    // Nothing outside the room to see: below its floor, or in plan beyond
    // its walls.
    let (inf, none) = (f64::INFINITY, f64::NEG_INFINITY);
    let (lo_bound, hi_bound) = match (room, m.view) {
        (Some(r), "plan") => (Vector2::zeros(), Vector2::new(r.size[0], r.size[1])),
        (None, "plan") => (Vector2::repeat(none), Vector2::repeat(inf)),
        _ => (Vector2::new(none, 0.0), Vector2::repeat(inf)),
    };
    lo = lo.sup(&lo_bound).inf(&(hi - Vector2::repeat(1.0)));
    hi = hi.inf(&hi_bound).sup(&(lo + Vector2::repeat(1.0)));
    let extent = hi - lo;
    let px_per_mm = DRAWING_PX / extent.x.max(extent.y).max(1.0);
    Scale { lo, hi, px_per_mm }
}

fn cells(s: &mut String, m: &Picture, frame: &Frame, scale: &Scale) {
    let side = m.step_mm * scale.px_per_mm;
    for c in &m.cells {
        let p = frame.at(Vector3::from(c.point_mm));
        let (x, y) = (scale.x(p.x) - side / 2.0, scale.y(p.y) - side / 2.0);
        let _ = writeln!(
            s,
            r#"<rect x="{x:.1}" y="{y:.1}" width="{side:.1}" height="{side:.1}" fill="{}" stroke="white" stroke-width="0.5"><title>({}, {}, {}) mm: {}</title></rect>"#,
            c.fill,
            c.point_mm[0],
            c.point_mm[1],
            c.point_mm[2],
            markup(&c.words),
        );
    }
}

/// The room's boxes near the map: footprints in plan; in elevation, the
/// faces of boxes between the surface and the room, as seen from it.
fn furniture(s: &mut String, m: &Picture, room: &RoomView, frame: &Frame, scale: &Scale) {
    let viewer = frame.right.cross(&frame.up);
    let plane = m.cells.first().map(|c| Vector3::from(c.point_mm));
    for b in &room.boxes {
        let cuboid = b.cuboid();
        let corners: Vec<Vector3<f64>> = (0..8).map(|k| cuboid.corner(k).coords).collect();
        if m.view != "plan" {
            // Only what stands in front of (or in) the surface, not behind
            // it or across the room.
            if let Some(p) = plane {
                let depth: Vec<f64> = corners.iter().map(|c| (c - p).dot(&viewer)).collect();
                let (near, far) = depth
                    .iter()
                    .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &d| {
                        (a.min(d), b.max(d))
                    });
                if far < -m.step_mm || near > 1200.0 {
                    continue;
                }
            }
        }
        let shown: Vec<Vector2<f64>> = corners.iter().map(|c| frame.at(*c)).collect();
        let outline = if m.view == "plan" {
            // The bottom's corners in order round it.
            [0, 1, 3, 2].map(|k| shown[k]).to_vec()
        } else {
            let (lo, hi) = shown.iter().fold(
                (
                    Vector2::repeat(f64::INFINITY),
                    Vector2::repeat(f64::NEG_INFINITY),
                ),
                |(lo, hi), p| (lo.inf(p), hi.sup(p)),
            );
            vec![lo, Vector2::new(hi.x, lo.y), hi, Vector2::new(lo.x, hi.y)]
        };
        let points: Vec<String> = outline
            .iter()
            .map(|p| format!("{:.1},{:.1}", scale.x(p.x), scale.y(p.y)))
            .collect();
        let _ = writeln!(
            s,
            r#"<polygon points="{}" fill="{FURNITURE}" stroke="{FURNITURE_EDGE}" stroke-width="1" fill-opacity="0.8"><title>{}</title></polygon>"#,
            points.join(" "),
            markup(&b.name)
        );
    }
}

/// Where the base stood for the points, each place once: a dot and a
/// tick along its heading.
fn bases(s: &mut String, bases_mm_deg: &[[f64; 3]], scale: &Scale) {
    let mut drawn: Vec<[i64; 3]> = Vec::new();
    for &[x, y, heading] in bases_mm_deg {
        if !(x.is_finite() && y.is_finite() && heading.is_finite()) {
            continue;
        }
        let key = [
            (x / 10.0).round() as i64,
            (y / 10.0).round() as i64,
            heading.round() as i64,
        ];
        if drawn.contains(&key) {
            continue;
        }
        drawn.push(key);
        let (px, py) = (scale.x(x), scale.y(y));
        let (sin, cos) = heading.to_radians().sin_cos();
        let _ = writeln!(
            s,
            r#"<g stroke="{BASE}" fill="{BASE}"><circle cx="{px:.1}" cy="{py:.1}" r="3"/><line x1="{px:.1}" y1="{py:.1}" x2="{:.1}" y2="{:.1}" stroke-width="1.5"/><title>base at ({x}, {y}) mm, heading {heading} deg</title></g>"#,
            px + 12.0 * cos,
            py - 12.0 * sin
        );
    }
}

/// The drawing's frame and round ticks along both sides.
fn axes(s: &mut String, m: &Picture, scale: &Scale) {
    let size = scale.size();
    let _ = writeln!(
        s,
        r#"<rect x="{MARGIN}" y="{MARGIN}" width="{:.1}" height="{:.1}" fill="none" stroke="black"/>"#,
        size.x, size.y
    );
    let step = nice_step(TICK_GAP_PX / scale.px_per_mm);
    let (bottom, left) = (MARGIN + size.y, MARGIN);
    // The picture runs along -x or -y where the room's coordinate
    // decreases to the right: label the room's coordinate.
    let sign = if m.view == "plan" || increasing(&Frame::of(m)) {
        1.0
    } else {
        -1.0
    };
    let mut x_mm = (scale.lo.x / step).ceil() * step;
    while x_mm <= scale.hi.x {
        let x = scale.x(x_mm);
        let _ = writeln!(
            s,
            r#"<line x1="{x:.1}" y1="{bottom:.1}" x2="{x:.1}" y2="{:.1}" stroke="black"/><text x="{x:.1}" y="{:.1}" text-anchor="middle">{x_mm:.0}</text>"#,
            bottom + 5.0,
            bottom + 18.0,
            x_mm = sign * x_mm + 0.0, // no "-0"
        );
        x_mm += step;
    }
    let mut y_mm = (scale.lo.y / step).ceil() * step;
    while y_mm <= scale.hi.y {
        let y = scale.y(y_mm);
        let _ = writeln!(
            s,
            r#"<line x1="{:.1}" y1="{y:.1}" x2="{left:.1}" y2="{y:.1}" stroke="black"/><text x="{:.1}" y="{:.1}" text-anchor="end">{y_mm:.0}</text>"#,
            left - 5.0,
            left - 8.0,
            y + 4.0,
            y_mm = y_mm + 0.0,
        );
        y_mm += step;
    }
    let (right_name, up_name) = if m.view == "plan" {
        ("x (mm)", "y")
    } else {
        (along_name(m), "height z")
    };
    let _ = writeln!(
        s,
        r#"<text x="{:.1}" y="{:.1}" text-anchor="middle">{right_name}</text>"#,
        MARGIN + size.x / 2.0,
        bottom + 40.0
    );
    let mid = MARGIN + size.y / 2.0;
    let _ = writeln!(
        s,
        r#"<text x="18" y="{mid:.1}" text-anchor="middle" transform="rotate(-90 18 {mid:.1})">{up_name} (mm)</text>"#
    );
}

/// An elevation's horizontal axis: along the room's x or y, whichever the
/// picture's right runs along, with its sign.
fn along_name(m: &Picture) -> &'static str {
    let frame = Frame::of(m);
    match (
        frame.right.x.abs() >= frame.right.y.abs(),
        increasing(&frame),
    ) {
        (true, true) => "x (mm)",
        (true, false) => "x (mm, decreasing to the right)",
        (false, true) => "y (mm)",
        (false, false) => "y (mm, decreasing to the right)",
    }
}

/// Whether the room's coordinate the picture's right mostly runs along
/// grows to the right.
fn increasing(frame: &Frame) -> bool {
    let r = frame.right;
    if r.x.abs() >= r.y.abs() {
        r.x >= 0.0
    } else {
        r.y >= 0.0
    }
}

fn legend(s: &mut String, m: &Picture, x: f64, furniture: bool) {
    let mut rows = m.legend.clone();
    if furniture {
        rows.push((FURNITURE, "furniture".to_string()));
    }
    if m.bases.is_some() {
        rows.push((BASE, "where the base stood".to_string()));
    }
    for (k, (fill, label)) in rows.iter().enumerate() {
        let y = MARGIN + k as f64 * 22.0;
        let _ = writeln!(
            s,
            r#"<rect x="{x:.1}" y="{y:.1}" width="14" height="14" fill="{fill}" stroke="{NOTE}" stroke-width="0.5"/><text x="{:.1}" y="{:.1}">{}</text>"#,
            x + 20.0,
            y + 11.0,
            markup(label)
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ticks_are_round_and_at_least_as_far_apart_as_asked() {
        for (min, step) in [
            (0.7, 1.0),
            (55.0, 100.0),
            (120.0, 200.0),
            (260.0, 500.0),
            (1000.0, 1000.0),
        ] {
            assert_eq!(nice_step(min), step, "{min}");
        }
    }

    /// A cell's tooltip names what the hand passed through (an obstacle's
    /// name, a URDF link's): markup in it is text, not markup.
    #[test]
    fn a_cells_tooltip_is_escaped() {
        let hostile = "reached only through `</title><script>alert(1)</script><title>`";
        let picture = Picture {
            title: "t".into(),
            view: "plan",
            step_mm: 100.0,
            seen_from: Vector3::z(),
            cells: vec![PictureCell {
                point_mm: [0.0; 3],
                fill: REACHED,
                words: hostile.into(),
            }],
            bases: None,
            legend: Vec::new(),
        };
        let svg = picture_svg(&picture, None);
        assert!(!svg.contains("<script>"), "{svg}");
        assert!(svg.contains("&lt;/title&gt;&lt;script&gt;"), "{svg}");
    }
}
