//! Solids drawn as an SVG picture: each shape projected along one of the
//! room's axes (a side view, a front view or a plan), the far ones first,
//! in panels side by side at one scale. What `docs/` shows of the body
//! model, and what a posture looks like when its joint angles say little.

use std::fmt::Write;

use nalgebra::{Point2, Point3, Vector2, Vector3};

use crate::escape::markup;
use crate::geometry::Shape;

/// Which way a panel looks.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum View {
    /// From the right (looking along +y): x to the right, z up.
    Side,
    /// From the front (looking along -x): y (the person's left) to the
    /// right, z up.
    Front,
    /// From above: x to the right, y up.
    Plan,
}

impl View {
    /// A point on the page (before scaling; y up) and its depth (larger
    /// is nearer the viewer).
    fn project(self, p: &Point3<f64>) -> (Point2<f64>, f64) {
        match self {
            View::Side => (Point2::new(p.x, p.z), -p.y),
            View::Front => (Point2::new(p.y, p.z), p.x),
            View::Plan => (Point2::new(p.x, p.y), p.z),
        }
    }
}

/// A shape and how it is painted.
#[derive(Clone, Debug, PartialEq)]
pub struct Painted {
    pub shape: Shape,
    /// An SVG colour.
    pub fill: String,
    /// How much of what lies behind it is hidden: 1 opaque, 0 invisible.
    pub opacity: f64,
    /// Shown when the pointer rests on it.
    pub label: String,
}

/// One panel: a title and what it shows.
#[derive(Clone, Debug, PartialEq)]
pub struct Panel {
    pub title: String,
    pub view: View,
    pub items: Vec<Painted>,
    /// Horizontal lines across the panel (the floor, a seat height), with
    /// their labels, in millimetres up the page.
    pub levels_mm: Vec<(f64, String)>,
}

const MARGIN_PX: f64 = 30.0;
const TITLE_PX: f64 = 28.0;
const GAP_PX: f64 = 20.0;

/// The panels side by side at `px_per_mm`, under `caption`.
pub fn svg(caption: &str, panels: &[Panel], px_per_mm: f64) -> String {
    let frames: Vec<Frame> = panels.iter().map(|p| Frame::of(p, px_per_mm)).collect();
    let height = frames.iter().map(|f| f.height_px).fold(0.0, f64::max);
    let width: f64 = frames.iter().map(|f| f.width_px + GAP_PX).sum::<f64>() - GAP_PX;
    let (page_w, page_h) = (
        width + 2.0 * MARGIN_PX,
        height + 2.0 * MARGIN_PX + 2.0 * TITLE_PX,
    );
    let mut s = String::new();
    let _ = writeln!(
        s,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{page_w:.0}" height="{page_h:.0}" viewBox="0 0 {page_w:.0} {page_h:.0}" font-family="sans-serif" font-size="13">"#
    );
    let _ = writeln!(s, r#"<rect width="100%" height="100%" fill="white"/>"#);
    let _ = writeln!(
        s,
        r#"<text x="{MARGIN_PX}" y="{:.1}" font-size="15" font-weight="bold">{}</text>"#,
        MARGIN_PX,
        markup(caption)
    );
    let mut left = MARGIN_PX;
    for (panel, frame) in panels.iter().zip(&frames) {
        let top = MARGIN_PX + TITLE_PX + (height - frame.height_px);
        draw_panel(&mut s, panel, frame, left, top);
        left += frame.width_px + GAP_PX;
    }
    s.push_str("</svg>\n");
    s
}

/// Where a panel's drawing goes: its bounds in millimetres and its size.
struct Frame {
    min: Point2<f64>,
    max: Point2<f64>,
    px_per_mm: f64,
    width_px: f64,
    height_px: f64,
}

impl Frame {
    fn of(panel: &Panel, px_per_mm: f64) -> Self {
        let mut min = Point2::new(f64::INFINITY, f64::INFINITY);
        let mut max = -min;
        for item in &panel.items {
            for p in outline(&item.shape, panel.view).0 {
                min = min.inf(&p);
                max = max.sup(&p);
            }
        }
        for (z, _) in &panel.levels_mm {
            min.y = min.y.min(*z);
            max.y = max.y.max(*z);
        }
        if min.x > max.x {
            (min, max) = (Point2::origin(), Point2::new(1.0, 1.0));
        }
        let pad = 40.0;
        let (min, max) = (min - Vector2::repeat(pad), max + Vector2::repeat(pad));
        Frame {
            width_px: (max.x - min.x) * px_per_mm,
            height_px: (max.y - min.y) * px_per_mm + TITLE_PX,
            min,
            max,
            px_per_mm,
        }
    }

    /// A point in millimetres on the page, the panel's top-left at
    /// (`left`, `top`).
    fn page(&self, p: &Point2<f64>, left: f64, top: f64) -> (f64, f64) {
        (
            left + (p.x - self.min.x) * self.px_per_mm,
            top + TITLE_PX + (self.max.y - p.y) * self.px_per_mm,
        )
    }
}

fn draw_panel(s: &mut String, panel: &Panel, frame: &Frame, left: f64, top: f64) {
    let _ = writeln!(
        s,
        r#"<text x="{left:.1}" y="{:.1}" font-weight="bold">{}</text>"#,
        top + 16.0,
        markup(&panel.title)
    );
    for (z, label) in &panel.levels_mm {
        let (x0, y) = frame.page(&Point2::new(frame.min.x, *z), left, top);
        let (x1, _) = frame.page(&Point2::new(frame.max.x, *z), left, top);
        let _ = writeln!(
            s,
            r##"<line x1="{x0:.1}" y1="{y:.1}" x2="{x1:.1}" y2="{y:.1}" stroke="#999" stroke-dasharray="4 3"/><text x="{:.1}" y="{:.1}" fill="#666" font-size="11" text-anchor="end">{}</text>"##,
            x1,
            y - 3.0,
            markup(label)
        );
    }
    let mut shapes: Vec<(f64, Vec<Point2<f64>>, &Painted)> = panel
        .items
        .iter()
        .map(|item| {
            let (points, depth) = outline(&item.shape, panel.view);
            (depth, points, item)
        })
        .collect();
    shapes.sort_by(|a, b| a.0.total_cmp(&b.0));
    for (_, points, item) in shapes {
        let path: Vec<String> = points
            .iter()
            .map(|p| {
                let (x, y) = frame.page(p, left, top);
                format!("{x:.1},{y:.1}")
            })
            .collect();
        let _ = writeln!(
            s,
            r##"<polygon points="{}" fill="{}" fill-opacity="{:.2}" stroke="#333" stroke-width="0.8"><title>{}</title></polygon>"##,
            path.join(" "),
            item.fill,
            item.opacity,
            markup(&item.label)
        );
    }
}

/// The outline of a shape seen in `view` (a convex polygon, on the page
/// in millimetres) and its depth (of its centre).
fn outline(shape: &Shape, view: View) -> (Vec<Point2<f64>>, f64) {
    match shape {
        Shape::Capsule(c) => {
            let (a, da) = view.project(&c.a);
            let (b, db) = view.project(&c.b);
            let steps = 24;
            let ring = |centre: Point2<f64>| {
                (0..steps).map(move |k| {
                    let t = std::f64::consts::TAU * f64::from(k) / f64::from(steps);
                    centre + Vector2::new(t.cos(), t.sin()) * c.radius_mm.max(1.0)
                })
            };
            (hull(ring(a).chain(ring(b)).collect()), (da + db) / 2.0)
        }
        Shape::Cuboid(c) => {
            let [lo, hi] = [-c.half_mm, c.half_mm];
            let turn = nalgebra::Rotation3::from_axis_angle(&Vector3::z_axis(), c.yaw_rad);
            let corners: Vec<Point2<f64>> = (0..8)
                .map(|k| {
                    let pick = |bit: usize, i: usize| if k & bit == 0 { lo[i] } else { hi[i] };
                    let local = Vector3::new(pick(1, 0), pick(2, 1), pick(4, 2));
                    view.project(&(c.centre + turn * local)).0
                })
                .collect();
            (hull(corners), view.project(&c.centre).1)
        }
    }
}

/// The convex hull of `points`, counter-clockwise (Andrew's monotone
/// chain).
fn hull(mut points: Vec<Point2<f64>>) -> Vec<Point2<f64>> {
    points.sort_by(|a, b| a.x.total_cmp(&b.x).then(a.y.total_cmp(&b.y)));
    points.dedup();
    if points.len() < 3 {
        return points;
    }
    let cross = |o: &Point2<f64>, a: &Point2<f64>, b: &Point2<f64>| {
        (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x)
    };
    let mut lower: Vec<Point2<f64>> = Vec::new();
    for p in &points {
        while lower.len() >= 2 && cross(&lower[lower.len() - 2], &lower[lower.len() - 1], p) <= 0.0
        {
            lower.pop();
        }
        lower.push(*p);
    }
    let mut upper: Vec<Point2<f64>> = Vec::new();
    for p in points.iter().rev() {
        while upper.len() >= 2 && cross(&upper[upper.len() - 2], &upper[upper.len() - 1], p) <= 0.0
        {
            upper.pop();
        }
        upper.push(*p);
    }
    lower.pop();
    upper.pop();
    lower.extend(upper);
    lower
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::{Capsule, Cuboid};

    #[test]
    fn a_box_seen_from_the_side_is_its_x_z_rectangle() {
        let b = Cuboid::between(Point3::new(0.0, 0.0, 0.0), Point3::new(100.0, 50.0, 20.0));
        let (points, _) = outline(&Shape::Cuboid(b), View::Side);
        assert_eq!(points.len(), 4);
        let xs: Vec<f64> = points.iter().map(|p| p.x).collect();
        assert!(xs
            .iter()
            .all(|&x| x.abs() < 1e-9 || (x - 100.0).abs() < 1e-9));
        assert!(points
            .iter()
            .all(|p| p.y.abs() < 1e-9 || (p.y - 20.0).abs() < 1e-9));
    }

    #[test]
    fn the_nearer_solid_is_painted_last() {
        let capsule = |y: f64, fill: &str| Painted {
            shape: Shape::Capsule(Capsule::new(
                Point3::new(0.0, y, 0.0),
                Point3::new(0.0, y, 100.0),
                10.0,
            )),
            fill: fill.into(),
            opacity: 1.0,
            label: fill.into(),
        };
        // Seen from the side (from -y), the solid at y = -50 is nearer.
        let panel = Panel {
            title: "t".into(),
            view: View::Side,
            items: vec![capsule(-50.0, "near"), capsule(50.0, "far")],
            levels_mm: vec![(0.0, "floor".into())],
        };
        let out = svg("c", &[panel], 1.0);
        assert!(out.find("far").unwrap() < out.find("near").unwrap());
        assert!(out.contains("floor"));
    }
}
