//! Rooms: size, box obstacles and targets.

use std::collections::HashMap;

use nalgebra::{Point3, Vector3};
use rstar::primitives::{GeomWithData, Rectangle};
use rstar::RTree;

use super::eval::fmt_num;
use super::Checker;
use crate::error::{thousands, Error, ErrorKind};
use crate::scene::{BoxObstacle, Door, MeshObstacle, Room, Surface, Target, Wall};
use crate::span::Span;
use crate::syntax::ast::{BoxDecl, DoorDecl, RoomDecl, RoomItem, SurfaceDecl, Vec3Expr};

impl Checker<'_> {
    pub(super) fn rooms(&mut self) -> Vec<Room> {
        let decls: Vec<_> = self.decls.rooms.iter().map(|(_, d, f)| (d, f)).collect();
        let mut rooms = Vec::new();
        // Names to where they were first declared: one lookup per name.
        let mut target_names: HashMap<&str, Span> = HashMap::new();
        for (decl, file) in decls {
            for item in &decl.items {
                if let RoomItem::Target(t) = item {
                    match target_names.get(t.name.value.as_str()) {
                        Some(&first) => self.error(Error::duplicate("target", &t.name, first)),
                        None => {
                            target_names.insert(&t.name.value, t.name.span);
                        }
                    }
                }
            }
            if let Some(room) = self.in_file(file, |c| c.room(decl)) {
                rooms.push(room);
            }
        }
        rooms
    }

    /// Boxes and surfaces of one room share a namespace (a map names them).
    fn check_room_names(&mut self, decl: &RoomDecl) {
        let mut seen: HashMap<&str, Span> = HashMap::new();
        for item in &decl.items {
            let name = match item {
                RoomItem::Box(b) => &b.name,
                RoomItem::Mesh(m) => &m.name,
                RoomItem::Surface(s) => &s.name,
                RoomItem::Door(d) => &d.name,
                _ => continue,
            };
            match seen.get(name.value.as_str()) {
                Some(&first) => {
                    self.error(Error::duplicate("box, mesh, surface or door", name, first))
                }
                None => {
                    seen.insert(&name.value, name.span);
                }
            }
        }
    }

    fn room(&mut self, decl: &RoomDecl) -> Option<Room> {
        self.check_room_names(decl);
        // Every check against the room looks at each box and each mesh.
        let box_count = decl
            .items
            .iter()
            .filter(|i| matches!(i, RoomItem::Box(_) | RoomItem::Mesh(_)))
            .count();
        if box_count > self.cx.limits.boxes {
            self.error(Error::new(
                ErrorKind::TooLarge {
                    what: format!(
                        "room `{}`, with {} boxes and meshes,",
                        decl.name.value,
                        thousands(box_count as u64)
                    ),
                    limit: format!(
                        "{} boxes and meshes in one room (--max-boxes)",
                        thousands(self.cx.limits.boxes as u64)
                    ),
                },
                decl.name.span,
            ));
            return None;
        }
        let sizes: Vec<_> = decl
            .items
            .iter()
            .filter_map(|i| match i {
                RoomItem::Size(s) => Some(s),
                _ => None,
            })
            .collect();
        let size = match sizes.as_slice() {
            [] => {
                self.error(Error::new(
                    ErrorKind::Missing {
                        owner: format!("room `{}`", decl.name.value),
                        what: "size",
                    },
                    decl.name.span,
                ));
                None
            }
            [s, rest @ ..] => {
                for r in rest {
                    self.error(Error::new(
                        ErrorKind::Repeated {
                            what: "the room's size".into(),
                        },
                        r.span,
                    ));
                }
                self.size(s, "a room's size")
                    .and_then(|size| self.within_largest_room(s, size))
            }
        };
        let mut boxes = Vec::new();
        let mut targets = Vec::new();
        let mut surfaces = Vec::new();
        let mut target_spans = Vec::new();
        let mut meshes = Vec::new();
        let mut doors = Vec::new();
        for item in &decl.items {
            match item {
                RoomItem::Size(_) => {}
                RoomItem::Door(d) => doors.extend(self.door(d, size)),
                RoomItem::Box(b) => boxes.extend(self.box_obstacle(b)),
                RoomItem::Mesh(m) => meshes.extend(self.mesh(m)),
                RoomItem::Surface(d) => surfaces.extend(self.surface(d, size)),
                RoomItem::Target(t) => {
                    let Some(p) = self.point(&t.at) else { continue };
                    let position_mm = Point3::from(p);
                    if let Some(size) = size {
                        self.check_inside(
                            &decl.name.value,
                            &t.name.value,
                            &position_mm,
                            size,
                            t.at.span,
                        );
                    }
                    targets.push(Target {
                        name: t.name.value.clone(),
                        position_mm,
                    });
                    target_spans.push(t.at.span);
                }
            }
        }
        self.check_not_in_boxes(&targets, &target_spans, &boxes);
        self.check_not_in_meshes(&targets, &target_spans, &meshes);
        Some(Room {
            name: decl.name.value.clone(),
            size_mm: size?,
            boxes,
            meshes,
            targets,
            surfaces,
            doors,
        })
    }

    /// A `door`: its middle on one of the room's walls (within half a
    /// millimetre), its opening within the wall, its width positive.
    fn door(&mut self, d: &DoorDecl, room_size: Option<Vector3<f64>>) -> Option<Door> {
        let [x, y] = &d.at.parts;
        let (x, y, width) = (self.length(x), self.length(y), self.length(&d.width));
        let (x, y, width) = (x?, y?, width?);
        if width <= 0.0 {
            self.out_of_range(
                d.width.span,
                "a door's width",
                "more than 0",
                &fmt_num(width),
            );
            return None;
        }
        let size = room_size?;
        const ON_WALL_MM: f64 = 0.5;
        let walls = [
            (Wall::XMin, x.abs(), y, size.y),
            (Wall::XMax, (x - size.x).abs(), y, size.y),
            (Wall::YMin, y.abs(), x, size.x),
            (Wall::YMax, (y - size.y).abs(), x, size.x),
        ];
        let Some(&(wall, _, along_mm, length_mm)) = walls
            .iter()
            .filter(|(_, off, along, length)| *off <= ON_WALL_MM && (0.0..=*length).contains(along))
            .min_by(|a, b| a.1.total_cmp(&b.1))
        else {
            let value = format!("({}, {}) mm", fmt_num(x), fmt_num(y));
            let bound = format!(
                "on a wall: x = 0 or {}, or y = 0 or {}",
                fmt_num(size.x),
                fmt_num(size.y)
            );
            self.out_of_range(d.at.span, "a door's middle", &bound, &value);
            return None;
        };
        let door = Door {
            name: d.name.value.clone(),
            wall,
            along_mm,
            width_mm: width,
        };
        let [lo, hi] = door.span_mm();
        if lo < 0.0 || hi > length_mm {
            let value = format!("{} to {} mm along it", fmt_num(lo), fmt_num(hi));
            let bound = format!("within the wall, 0 to {} mm", fmt_num(length_mm));
            self.out_of_range(d.width.span, "a door's opening", &bound, &value);
            return None;
        }
        Some(door)
    }

    /// A `surface` item: a rectangle parallel to the room's axes with exactly
    /// one size zero.
    fn surface(&mut self, d: &SurfaceDecl, room_size: Option<Vector3<f64>>) -> Option<Surface> {
        let corner = self.point(&d.at);
        let size = self.point(&d.size)?;
        let zeros = (0..3).filter(|&i| size[i] == 0.0).count();
        let negative = (0..3).find(|&i| size[i] < 0.0);
        if zeros != 1 || negative.is_some() {
            let value = format!(
                "({}, {}, {}) mm",
                fmt_num(size.x),
                fmt_num(size.y),
                fmt_num(size.z)
            );
            self.out_of_range(
                d.size.span,
                "a surface's size",
                "two positive sizes and one zero",
                &value,
            );
            return None;
        }
        let axis = |i: usize| {
            let mut v = Vector3::zeros();
            v[i] = size[i];
            v
        };
        let edges: Vec<Vector3<f64>> = (0..3).filter(|&i| size[i] != 0.0).map(axis).collect();
        let corner_mm = Point3::from(corner?);
        // Touched from above if level; if upright, from the room's middle.
        let flat = (0..3).find(|&i| size[i] == 0.0).unwrap_or(2);
        let mut normal = Vector3::zeros();
        normal[flat] = match room_size {
            Some(room) if flat < 2 && corner_mm[flat] > room[flat] / 2.0 => -1.0,
            _ => 1.0,
        };
        Some(Surface {
            name: d.name.value.clone(),
            corner_mm,
            u_mm: edges[0],
            v_mm: edges[1],
            normal,
        })
    }

    fn check_inside(
        &mut self,
        room: &str,
        target: &str,
        p: &Point3<f64>,
        size: Vector3<f64>,
        span: crate::span::Span,
    ) {
        let inside = (0..3).all(|i| p[i] >= 0.0 && p[i] <= size[i]);
        if !inside {
            self.error(Error::new(
                ErrorKind::TargetOutsideRoom {
                    name: target.to_string(),
                    room: room.to_string(),
                    bounds: format!(
                        "(0, 0, 0) to ({}, {}, {}) mm",
                        fmt_num(size.x),
                        fmt_num(size.y),
                        fmt_num(size.z)
                    ),
                },
                span,
            ));
        }
    }

    /// A target strictly inside a box cannot be reached or seen: the box
    /// is closed. (On its surface is fine: a mug on a counter.)
    fn check_not_in_boxes(
        &mut self,
        targets: &[Target],
        spans: &[crate::span::Span],
        boxes: &[BoxObstacle],
    ) {
        // Each target asks an R-tree of the boxes' bounds for the boxes
        // that may hold it: targets times boxes compared pairwise took
        // 23 s for 50,000 of each.
        let entries = boxes.iter().enumerate().map(|(i, b)| {
            let [lo, hi] = b.cuboid().bounds();
            GeomWithData::new(Rectangle::from_corners(lo.into(), hi.into()), i)
        });
        let tree = RTree::bulk_load(entries.collect());
        for (t, span) in targets.iter().zip(spans) {
            let p: [f64; 3] = t.position_mm.into();
            let holder = tree
                .locate_all_at_point(&p)
                .map(|entry| entry.data)
                .filter(|&i| boxes[i].holds_strictly(&t.position_mm))
                .min();
            if let Some(b) = holder.map(|i| &boxes[i]) {
                self.error(Error::new(
                    ErrorKind::TargetInsideBox {
                        name: t.name.clone(),
                        obstacle: b.name.clone(),
                    },
                    *span,
                ));
            }
        }
    }

    /// Each target inside a closed mesh (and not on its surface) is an
    /// error, as one inside a box is.
    fn check_not_in_meshes(
        &mut self,
        targets: &[Target],
        spans: &[crate::span::Span],
        meshes: &[MeshObstacle],
    ) {
        for (t, span) in targets.iter().zip(spans) {
            if let Some(m) = meshes.iter().find(|m| m.holds_strictly(&t.position_mm)) {
                self.error(Error::new(
                    ErrorKind::TargetInsideMesh {
                        name: t.name.clone(),
                        obstacle: m.name.clone(),
                    },
                    *span,
                ));
            }
        }
    }

    fn box_obstacle(&mut self, b: &BoxDecl) -> Option<BoxObstacle> {
        let corner = self.point(&b.at);
        let size = self.size(&b.size, "a box's size");
        let yaw = match &b.rotate {
            Some(e) => self.angle(e),
            None => Some(0.0),
        };
        Some(BoxObstacle {
            name: b.name.value.clone(),
            corner_mm: Point3::from(corner?),
            size_mm: size?,
            yaw_rad: yaw?,
        })
    }
}

/// The longest side a room may have: 1 km. The floor's regions are worked
/// out in integer coordinates scaled to the room (`geo`'s boolean
/// operations): at 1 km they are 0.5 micrometres apart, and beyond a few
/// thousand kilometres more than a millimetre, where the answers
/// contradict each other (a route 3 m wide whose turning space fails).
pub const LARGEST_ROOM_MM: f64 = 1_000_000.0;

impl Checker<'_> {
    /// `size`, where no side of it is longer than [`LARGEST_ROOM_MM`].
    fn within_largest_room(&mut self, s: &Vec3Expr, size: Vector3<f64>) -> Option<Vector3<f64>> {
        let bound = ("a room's side", "at most 1,000,000 mm (1 km)");
        self.each_part(s, size, bound, |mm| mm <= LARGEST_ROOM_MM)
    }
}
