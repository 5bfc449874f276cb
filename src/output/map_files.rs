//! Files for each map, written with `--out DIR`: the points as CSV and a
//! heat map as SVG (plan view for a horizontal surface, elevation for a
//! vertical one), named after the surface and the person.

use std::fmt::Write;

use crate::report::MapReport;

/// File names for a map: `map-SURFACE-PERSON.csv` and `.svg`
/// (`gaze_map-...` for a gaze map).
pub fn file_stem(m: &MapReport) -> String {
    let clean = |s: &str| s.replace(|c: char| !c.is_ascii_alphanumeric() && c != '_', "-");
    let kind = if m.of == "gaze" { "gaze_map" } else { "map" };
    format!("{kind}-{}-{}", clean(&m.name), clean(&m.person))
}

/// One line per point: where it is, whether it is reachable, the distance
/// left, the comfort, and where the base stood.
pub fn csv(m: &MapReport) -> String {
    let mut out = String::from("column,row,x_mm,y_mm,z_mm,reachable,distance_mm,comfort,base_x_mm,base_y_mm,base_heading_deg\n");
    for c in &m.cells {
        let [x, y, z] = c.point_mm;
        let [bx, by, bh] = c.base_mm_deg;
        let _ = writeln!(
            out,
            "{},{},{x},{y},{z},{},{},{},{bx},{by},{bh}",
            c.column, c.row, c.reachable, c.distance_mm, c.comfort
        );
    }
    out
}

const CELL_PX: f64 = 12.0;
const MARGIN: f64 = 70.0;
const REACHABLE: &str = "#2e8b57";
const UNREACHABLE: &str = "#e8b4b0";

/// The heat map: a cell per point, axes in millimetres along the
/// surface's two edges, a legend, and the surface and person in the title.
pub fn svg(m: &MapReport) -> String {
    let (w, h) = (m.columns as f64 * CELL_PX, m.rows as f64 * CELL_PX);
    let title = format!(
        "{} {} by {} ({} base): {:.1} % of {} points",
        m.name,
        m.words()[0],
        m.person,
        m.base,
        m.fraction * 100.0,
        m.points
    );
    // Wide enough for the grid and legend, and for the title (about 9 px
    // a character at 15 px bold).
    let width = (w + 2.0 * MARGIN + 160.0).max(9.0 * title.len() as f64 + 2.0 * MARGIN);
    let height = h + 2.0 * MARGIN;
    let mut s = String::new();
    let _ = writeln!(
        s,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" viewBox="0 0 {width} {height}" font-family="sans-serif" font-size="12">"#
    );
    let _ = writeln!(s, r#"<rect width="100%" height="100%" fill="white"/>"#);
    let _ = writeln!(
        s,
        r#"<text x="{MARGIN}" y="24" font-size="15" font-weight="bold">{}</text>"#,
        escape(&title)
    );
    // Row 0 at the bottom, like the surface's second edge pointing up.
    for c in &m.cells {
        let x = MARGIN + c.column as f64 * CELL_PX;
        let y = MARGIN + h - (c.row as f64 + 1.0) * CELL_PX;
        let fill = if c.reachable { REACHABLE } else { UNREACHABLE };
        let _ = writeln!(
            s,
            r#"<rect x="{x}" y="{y}" width="{CELL_PX}" height="{CELL_PX}" fill="{fill}" stroke="white" stroke-width="0.5"><title>({}, {}, {}) mm: {}</title></rect>"#,
            c.point_mm[0],
            c.point_mm[1],
            c.point_mm[2],
            match (c.reachable, m.of) {
                (true, _) => m.words()[1].to_string(),
                (false, "gaze") => "not seen".to_string(),
                (false, _) => format!("{} mm short", c.distance_mm),
            }
        );
    }
    axes(&mut s, m, w, h);
    legend(&mut s, w, m.words()[1]);
    s.push_str("</svg>\n");
    s
}

/// Ticks every few cells, labelled with millimetres along each edge.
fn axes(s: &mut String, m: &MapReport, w: f64, h: f64) {
    let len = |v: [f64; 3]| (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    let (u_len, v_len) = (len(m.u_mm), len(m.v_mm));
    let (u_name, v_name) = (axis_name(m.u_mm), axis_name(m.v_mm));
    let _ = writeln!(
        s,
        r#"<rect x="{MARGIN}" y="{MARGIN}" width="{w}" height="{h}" fill="none" stroke="black"/>"#
    );
    for k in 0..=4 {
        let f = k as f64 / 4.0;
        let x = MARGIN + f * w;
        let u_mm = m.corner_mm[axis(m.u_mm)] + f * u_len * sign(m.u_mm);
        let _ = writeln!(
            s,
            r#"<text x="{x}" y="{}" text-anchor="middle">{u_mm:.0}</text>"#,
            MARGIN + h + 18.0
        );
        let y = MARGIN + h - f * h;
        let v_mm = m.corner_mm[axis(m.v_mm)] + f * v_len * sign(m.v_mm);
        let _ = writeln!(
            s,
            r#"<text x="{}" y="{}" text-anchor="end">{v_mm:.0}</text>"#,
            MARGIN - 6.0,
            y + 4.0
        );
    }
    let _ = writeln!(
        s,
        r#"<text x="{}" y="{}" text-anchor="middle">{u_name} (mm)</text>"#,
        MARGIN + w / 2.0,
        MARGIN + h + 40.0
    );
    let _ = writeln!(
        s,
        r#"<text x="18" y="{}" text-anchor="middle" transform="rotate(-90 18 {})">{v_name} (mm)</text>"#,
        MARGIN + h / 2.0,
        MARGIN + h / 2.0
    );
}

fn legend(s: &mut String, w: f64, yes: &str) {
    let x = MARGIN + w + 24.0;
    let no = format!("not {yes}");
    for (k, (fill, label)) in [(REACHABLE, yes), (UNREACHABLE, no.as_str())]
        .into_iter()
        .enumerate()
    {
        let y = MARGIN + k as f64 * 22.0;
        let _ = writeln!(
            s,
            r#"<rect x="{x}" y="{y}" width="14" height="14" fill="{fill}"/>"#
        );
        let _ = writeln!(
            s,
            r#"<text x="{}" y="{}">{label}</text>"#,
            x + 20.0,
            y + 11.0
        );
    }
}

/// The room axis an edge runs along (edges of maps run along one axis,
/// except faces of turned boxes, named by their largest part).
fn axis(v: [f64; 3]) -> usize {
    (0..3)
        .max_by(|&a, &b| v[a].abs().total_cmp(&v[b].abs()))
        .unwrap_or(0)
}

fn axis_name(v: [f64; 3]) -> &'static str {
    ["x", "y", "height z"][axis(v)]
}

fn sign(v: [f64; 3]) -> f64 {
    v[axis(v)].signum()
}

fn escape(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}
