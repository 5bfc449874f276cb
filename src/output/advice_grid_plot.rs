//! An advice over a grid as SVG: one cell per position of the element,
//! shaded by the share of the group who reach the target there (a person:
//! reached or not), for a population the cells that serve the share
//! asked outlined in amber, the position that serves the most ringed and where the file puts
//! the target crossed. Height, where it is one of the two axes, runs up
//! the page.

use std::fmt::Write;

use super::advice_plot::page_start;
use super::ticks::nice_step;
use crate::escape::markup;
use crate::report::{axis_index, AdvicePoint, AdviceReport};

const WIDTH: f64 = 760.0;
const HEIGHT: f64 = 520.0;
const LEFT: f64 = 72.0;
const RIGHT: f64 = 210.0;
const TOP: f64 = 48.0;
const BOTTOM: f64 = 60.0;

/// The served cells' outline.
const SERVED: &str = "#f2b53a";

/// One cell of the grid: its position on the page's two axes and what is
/// reached there.
struct Cell<'a> {
    across_mm: f64,
    point: &'a AdvicePoint,
}

/// The picture of `grid` (an advice with rows).
pub fn svg(grid: &AdviceReport) -> String {
    let across = grid.across.as_ref().map_or("", |a| a.axis);
    let across_step = grid.across.as_ref().map_or(grid.step_mm, |a| a.step_mm);
    let cells: Vec<Cell<'_>> = (grid.rows.iter())
        .flat_map(|row| {
            let at = row.across.as_ref().map_or(0.0, |a| a.at_mm);
            (row.points.iter()).map(move |point| Cell {
                across_mm: at,
                point,
            })
        })
        .collect();
    // Height up the page; otherwise the axis along runs across it.
    let along_up = grid.along == "z";
    let page = |c: &Cell<'_>| match along_up {
        true => (c.across_mm, c.point.at_mm),
        false => (c.point.at_mm, c.across_mm),
    };
    let (step_h, step_v) = match along_up {
        true => (across_step, grid.step_mm),
        false => (grid.step_mm, across_step),
    };
    let (name_h, name_v) = match along_up {
        true => (across, grid.along),
        false => (grid.along, across),
    };
    let span = |f: &dyn Fn(&Cell<'_>) -> f64, step: f64| {
        let (lo, hi) = (cells.iter()).fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), c| {
            (lo.min(f(c)), hi.max(f(c)))
        });
        (lo - step / 2.0, hi + step / 2.0)
    };
    let (h0, h1) = span(&|c| page(c).0, step_h);
    let (v0, v1) = span(&|c| page(c).1, step_v);
    let plot_w = WIDTH - LEFT - RIGHT;
    let plot_h = HEIGHT - TOP - BOTTOM;
    // The same scale on both axes, so that the grid's cells are as long
    // as they are wide on the page as in the room.
    let scale = (plot_w / (h1 - h0).max(1e-9)).min(plot_h / (v1 - v0).max(1e-9));
    let x = |mm: f64| LEFT + (mm - h0) * scale;
    let y = |mm: f64| TOP + (v1 - mm) * scale;
    let title = format!(
        "advise {} by {}: who reaches it, by its {name_h} and {name_v} (mm)",
        grid.name, grid.who
    );
    let mut s = page_start((WIDTH, HEIGHT), LEFT, &title);
    // A person's cells are reached or not: no outline says more.
    let serves = |p: &AdvicePoint| grid.population && grid.serves_at(p);
    for cell in &cells {
        let (h, v) = page(cell);
        let p = cell.point;
        let _ = writeln!(
            s,
            r##"<rect x="{:.1}" y="{:.1}" width="{:.1}" height="{:.1}" fill="{}" stroke="#fff" stroke-width="0.5"><title>{name_h} {h} mm, {name_v} {v} mm: {}</title></rect>"##,
            x(h - step_h / 2.0),
            y(v + step_v / 2.0),
            step_h * scale,
            step_v * scale,
            shade(p.share),
            markup(&reached_words(grid, p))
        );
    }
    for cell in cells.iter().filter(|c| serves(c.point)) {
        let (h, v) = page(cell);
        let _ = writeln!(
            s,
            r#"<rect x="{:.1}" y="{:.1}" width="{:.1}" height="{:.1}" fill="none" stroke="{SERVED}" stroke-width="2.5"/>"#,
            x(h - step_h / 2.0) + 1.5,
            y(v + step_v / 2.0) + 1.5,
            (step_h * scale - 3.0).max(0.5),
            (step_v * scale - 3.0).max(0.5),
        );
    }
    axes(&mut s, ((h0, h1), (v0, v1)), (&x, &y), (name_h, name_v));
    marks(&mut s, grid, along_up, (&x, &y));
    legend(&mut s, grid);
    s.push_str("</svg>\n");
    s
}

/// A share as a shade: white for no one, deep blue for everyone.
fn shade(share: f64) -> String {
    let t = share.clamp(0.0, 1.0);
    let mix = |from: f64, to: f64| (from + (to - from) * t).round() as u8;
    format!(
        "#{:02x}{:02x}{:02x}",
        mix(247.0, 8.0),
        mix(251.0, 69.0),
        mix(255.0, 148.0)
    )
}

/// `40 % reach it` (a person: `reached`, `not reached`).
fn reached_words(grid: &AdviceReport, p: &AdvicePoint) -> String {
    match (grid.population, p.reached > 0) {
        (true, _) => format!("{:.0} % reach it", p.share * 100.0),
        (false, true) => "reached".into(),
        (false, false) => "not reached".into(),
    }
}

/// The frame and round ticks on both axes.
fn axes(
    s: &mut String,
    ((h0, h1), (v0, v1)): ((f64, f64), (f64, f64)),
    (x, y): (&dyn Fn(f64) -> f64, &dyn Fn(f64) -> f64),
    (name_h, name_v): (&str, &str),
) {
    let (left, right, top, bottom) = (x(h0), x(h1), y(v1), y(v0));
    let _ = writeln!(
        s,
        r#"<rect x="{left:.1}" y="{top:.1}" width="{:.1}" height="{:.1}" fill="none" stroke="black"/>"#,
        right - left,
        bottom - top
    );
    let per_px = (h1 - h0) / (right - left).max(1e-9);
    for tick in ticks(h0, h1, nice_step(60.0 * per_px)) {
        let _ = writeln!(
            s,
            r##"<line x1="{0:.1}" x2="{0:.1}" y1="{1:.1}" y2="{2:.1}" stroke="black"/><text x="{0:.1}" y="{3:.1}" text-anchor="middle">{4}</text>"##,
            x(tick),
            bottom,
            bottom + 5.0,
            bottom + 19.0,
            tick
        );
    }
    for tick in ticks(v0, v1, nice_step(40.0 * per_px)) {
        let _ = writeln!(
            s,
            r##"<line x1="{0:.1}" x2="{1:.1}" y1="{2:.1}" y2="{2:.1}" stroke="black"/><text x="{3:.1}" y="{4:.1}" text-anchor="end">{5}</text>"##,
            left - 5.0,
            left,
            y(tick),
            left - 8.0,
            y(tick) + 4.0,
            tick
        );
    }
    let _ = writeln!(
        s,
        r#"<text x="{:.1}" y="{:.1}" text-anchor="middle">{name_h} of the target (mm)</text>"#,
        (left + right) / 2.0,
        bottom + 40.0
    );
    let _ = writeln!(
        s,
        r#"<text x="{0:.1}" y="{1:.1}" text-anchor="middle" transform="rotate(-90 {0:.1} {1:.1})">{name_v} of the target (mm)</text>"#,
        LEFT - 50.0,
        (top + bottom) / 2.0
    );
}

/// The round values from `lo` to `hi` in steps of `step`.
fn ticks(lo: f64, hi: f64, step: f64) -> Vec<f64> {
    let first = (lo / step).ceil() as i64;
    let last = (hi / step).floor() as i64;
    (first..=last).map(|k| k as f64 * step).collect()
}

/// The best position ringed, where the file puts the target crossed.
fn marks(
    s: &mut String,
    grid: &AdviceReport,
    along_up: bool,
    (x, y): (&dyn Fn(f64) -> f64, &dyn Fn(f64) -> f64),
) {
    let k = (grid.across.as_ref()).and_then(|a| axis_index(a.axis));
    let declared_across = k.map_or(0.0, |k| grid.target_mm[k]);
    let on_page = |along_mm: f64, across_mm: f64| match along_up {
        true => (x(across_mm), y(along_mm)),
        false => (x(along_mm), y(across_mm)),
    };
    let (cx, cy) = on_page(grid.declared_mm, declared_across);
    let _ = writeln!(
        s,
        r##"<path d="M{0:.1} {1:.1}l10 10m0 -10l-10 10" transform="translate(-5 -5)" stroke="#d9591c" stroke-width="2.5"><title>as declared</title></path>"##,
        cx, cy
    );
    if let (Some(best), Some(a)) = (&grid.best, &grid.across) {
        let (bx, by) = on_page(best.at_mm, a.at_mm);
        let _ = writeln!(
            s,
            r##"<circle cx="{bx:.1}" cy="{by:.1}" r="6" fill="white" stroke="#111" stroke-width="2.5"><title>serves the most: {} {} mm, {} {} mm</title></circle>"##,
            grid.along, best.at_mm, a.axis, a.at_mm
        );
    }
}

/// The shades' key and the marks'.
fn legend(s: &mut String, grid: &AdviceReport) {
    let left = WIDTH - RIGHT + 20.0;
    let top = TOP + 6.0;
    let who = match grid.population {
        true => format!("{} ({} people)", grid.who, grid.people),
        false => grid.who.clone(),
    };
    let _ = writeln!(s, r#"<text x="{left}" y="{top}">{}</text>"#, markup(&who));
    let shades: Vec<(f64, String)> = match grid.population {
        true => (0..=4)
            .map(|k| (f64::from(k) / 4.0, format!("{} % reach it", k * 25)))
            .collect(),
        false => vec![(0.0, "not reached".into()), (1.0, "reached".into())],
    };
    for (k, (share, words)) in shades.iter().enumerate() {
        let y = top + 14.0 + k as f64 * 18.0;
        let _ = writeln!(
            s,
            r##"<rect x="{left}" y="{y:.1}" width="22" height="14" fill="{}" stroke="#999" stroke-width="0.5"/><text x="{:.1}" y="{:.1}">{words}</text>"##,
            shade(*share),
            left + 28.0,
            y + 11.0,
        );
    }
    let mut y = top + 14.0 + shades.len() as f64 * 18.0 + 8.0;
    if grid.population {
        let served = format!("serves {:.0} % or more", grid.serves * 100.0);
        let _ = writeln!(
            s,
            r##"<rect x="{left}" y="{y:.1}" width="22" height="14" fill="none" stroke="{SERVED}" stroke-width="2"/><text x="{:.1}" y="{:.1}">{served}</text>"##,
            left + 28.0,
            y + 11.0
        );
        y += 22.0;
    }
    let _ = writeln!(
        s,
        r##"<circle cx="{:.1}" cy="{:.1}" r="6" fill="white" stroke="#111" stroke-width="2.5"/><text x="{:.1}" y="{:.1}">serves the most</text>"##,
        left + 11.0,
        y + 10.0,
        left + 28.0,
        y + 14.0
    );
    let _ = writeln!(
        s,
        r##"<path d="M{:.1} {:.1}l10 10m0 -10l-10 10" stroke="#d9591c" stroke-width="2.5"/><text x="{:.1}" y="{:.1}">as declared</text>"##,
        left + 6.0,
        y + 27.0,
        left + 28.0,
        y + 36.0
    );
}
