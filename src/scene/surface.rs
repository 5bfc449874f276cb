//! Surfaces for maps: a rectangle in the room, given as a corner and two
//! edges. A `surface` item of a room, or a face of a box: `top`, `bottom`,
//! `front` (the side face turned most towards the middle of the room),
//! `back`, or by its side of the box's own axes: `x_min`, `x_max`, `y_min`,
//! `y_max`.

use nalgebra::{Point3, Vector2, Vector3};

use super::{BoxObstacle, Room};

/// The faces of a box a map can name.
pub const FACES: [&str; 8] = [
    "top", "bottom", "front", "back", "x_min", "x_max", "y_min", "y_max",
];

#[derive(Clone, Debug, PartialEq)]
pub struct Surface {
    /// As the task names it: `counter.top` or `shelf`.
    pub name: String,
    pub corner_mm: Point3<f64>,
    /// The first edge: along it run the columns of the map's grid.
    pub u_mm: Vector3<f64>,
    /// The second edge: along it run the rows.
    pub v_mm: Vector3<f64>,
    /// Unit, the side a hand touches it from: out of a box's face, up from
    /// a level `surface`, towards the middle of the room from an upright
    /// one.
    pub normal: Vector3<f64>,
}

impl Surface {
    /// Horizontal surfaces are drawn in plan, vertical ones in elevation.
    pub fn is_horizontal(&self) -> bool {
        self.u_mm.z.abs() < 1e-9 && self.v_mm.z.abs() < 1e-9
    }

    /// A grid of cells about `step_mm` wide, each sampled at its centre,
    /// row by row.
    pub fn grid(&self, step_mm: f64) -> Grid {
        let (columns, rows) = self.grid_size(step_mm);
        let mut cells = Vec::with_capacity(columns * rows);
        for row in 0..rows {
            for column in 0..columns {
                let a = (column as f64 + 0.5) / columns as f64;
                let b = (row as f64 + 0.5) / rows as f64;
                let point_mm = self.corner_mm + self.u_mm * a + self.v_mm * b;
                cells.push(GridCell {
                    column,
                    row,
                    point_mm,
                });
            }
        }
        Grid {
            columns,
            rows,
            cells,
        }
    }

    /// Columns and rows of the grid for `step_mm`, at least one each.
    pub fn grid_size(&self, step_mm: f64) -> (usize, usize) {
        let n = |len: f64| ((len / step_mm).round() as usize).max(1);
        (n(self.u_mm.norm()), n(self.v_mm.norm()))
    }
}

/// The sampled cells of a surface.
#[derive(Clone, Debug, PartialEq)]
pub struct Grid {
    pub columns: usize,
    pub rows: usize,
    pub cells: Vec<GridCell>,
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GridCell {
    pub column: usize,
    pub row: usize,
    pub point_mm: Point3<f64>,
}

impl Room {
    /// The surface a dotted subject names (`counter.top`, `splashback`).
    pub fn surface_named(&self, subject: &str) -> Option<Surface> {
        let path: Vec<String> = subject.split('.').map(str::to_string).collect();
        self.surface(&path)
    }

    /// Whether a task's subject, a target or a surface, is in this room.
    pub fn holds(&self, subject: &str) -> bool {
        self.targets.iter().any(|t| t.name == subject) || self.surface_named(subject).is_some()
    }

    /// The surface `path` names in this room: `[surface]` or `[box, face]`.
    pub fn surface(&self, path: &[String]) -> Option<Surface> {
        match path {
            [name] => self.surfaces.iter().find(|s| &s.name == name).cloned(),
            [box_name, face] => {
                let b = self.boxes.iter().find(|b| &b.name == box_name)?;
                box_face(b, face, self).map(|(corner_mm, u_mm, v_mm, normal)| Surface {
                    name: format!("{box_name}.{face}"),
                    corner_mm,
                    u_mm,
                    v_mm,
                    normal,
                })
            }
            _ => None,
        }
    }
}

/// A face's corner, its two edges, and its outward normal.
type Face = (Point3<f64>, Vector3<f64>, Vector3<f64>, Vector3<f64>);

fn box_face(b: &BoxObstacle, face: &str, room: &Room) -> Option<Face> {
    let axes = b.rotation();
    let (x, y) = (axes * Vector2::x(), axes * Vector2::y());
    let ex = Vector3::new(x.x, x.y, 0.0) * b.size_mm.x;
    let ey = Vector3::new(y.x, y.y, 0.0) * b.size_mm.y;
    let ez = Vector3::new(0.0, 0.0, b.size_mm.z);
    let o = b.corner_mm;
    let unit = |v: Vector3<f64>| v.try_normalize(0.0).unwrap_or_else(Vector3::z);
    Some(match face {
        "top" => (o + ez, ex, ey, Vector3::z()),
        "bottom" => (o, ex, ey, -Vector3::z()),
        "x_min" => (o, ey, ez, -unit(ex)),
        "x_max" => (o + ex, ey, ez, unit(ex)),
        "y_min" => (o, ex, ez, -unit(ey)),
        "y_max" => (o + ey, ex, ez, unit(ey)),
        "front" | "back" => {
            let towards = facing_centre(b, room, &[ex, ey]);
            let chosen = if face == "front" {
                towards
            } else {
                opposite(towards)
            };
            return box_face(b, chosen, room);
        }
        _ => return None,
    })
}

/// The side face whose outward normal points most towards the room's middle.
fn facing_centre(b: &BoxObstacle, room: &Room, axes: &[Vector3<f64>; 2]) -> &'static str {
    let centre_box = b.corner_mm + (axes[0] + axes[1]) * 0.5;
    let to_middle = Vector3::new(
        room.size_mm.x / 2.0 - centre_box.x,
        room.size_mm.y / 2.0 - centre_box.y,
        0.0,
    );
    let sides = [
        ("x_max", axes[0].normalize()),
        ("x_min", -axes[0].normalize()),
        ("y_max", axes[1].normalize()),
        ("y_min", -axes[1].normalize()),
    ];
    sides
        .into_iter()
        .max_by(|a, b| a.1.dot(&to_middle).total_cmp(&b.1.dot(&to_middle)))
        .map(|(name, _)| name)
        .unwrap_or("x_max")
}

fn opposite(face: &str) -> &'static str {
    match face {
        "x_max" => "x_min",
        "x_min" => "x_max",
        "y_max" => "y_min",
        _ => "y_max",
    }
}
