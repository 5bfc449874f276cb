//! `scene.glb`: the scene of the 3D page as one binary glTF file, for
//! Blender, a CAD tool or a colleague: each room's boxes, meshes and
//! targets, and for each task its person (capsules, legs, chair or
//! rollator) in the reported posture, its map's cells in the colours of
//! the map pictures (`map_files.rs`), its line of sight and the joints at
//! a limit. One glTF scene per task
//! (the room and that task), the first the default; nodes are named as the
//! report names things. Coordinates are glTF's: metres, y up (the room's
//! z), the room's y towards -z.
//!
//! The JSON is built with serde_json, the file laid out by the `gltf`
//! crate (`Glb`); reading it back with that crate's validation is the
//! test.

mod tessellate;

use nalgebra::{Point3, Vector3};
use serde_json::{json, Value};

use super::colours::{view_cell_colour, MISSED, REACHED, SEEN};
use super::view::{RoomView, SolidView, TaskView, ViewData};
use crate::geometry::Cuboid;
use tessellate::Triangles;

/// Colours as the page draws them (linear RGBA is close enough for a
/// picture).
const BOX: &str = "#d8c8a8";
const MESH: &str = "#c9c1b1";
const TARGET_IDLE: &str = "#8a93a3";
const STRAINED: &str = "#ff2d95";

/// The GLB of `view`.
pub fn glb(view: &ViewData) -> Vec<u8> {
    let mut b = Builder::default();
    let rooms: Vec<usize> = view.rooms.iter().map(|r| b.room(r)).collect();
    let mut scenes = Vec::new();
    for task in &view.tasks {
        let node = b.task(task);
        scenes.push(json!({ "name": task.label, "nodes": [rooms[task.room], node] }));
    }
    if scenes.is_empty() {
        scenes.push(json!({ "name": view.title, "nodes": rooms }));
    }
    b.finish(&view.title, scenes)
}

/// The parts of a glTF file as they are added.
#[derive(Default)]
struct Builder {
    bin: Vec<u8>,
    views: Vec<Value>,
    accessors: Vec<Value>,
    meshes: Vec<Value>,
    nodes: Vec<Value>,
    materials: Vec<(String, f64)>,
}

impl Builder {
    fn room(&mut self, room: &RoomView) -> usize {
        let mut children = Vec::new();
        for b in &room.boxes {
            let t = Triangles::cuboid(&b.cuboid());
            children.push(self.mesh_node(&b.name, &t, BOX, 1.0));
        }
        for m in &room.meshes {
            let t = Triangles {
                vertices: m
                    .positions
                    .chunks_exact(3)
                    .map(|c| Point3::new(c[0], c[1], c[2]))
                    .collect(),
                indices: m.indices.clone(),
            };
            children.push(self.mesh_node(&m.name, &t, MESH, 1.0));
        }
        for target in &room.targets {
            let p = Point3::from(target.at);
            let t = Triangles::capsule(p, p, 25.0);
            children.push(self.mesh_node(&target.name, &t, TARGET_IDLE, 1.0));
        }
        self.group(&room.name, children)
    }

    fn task(&mut self, task: &TaskView) -> usize {
        let mut children = Vec::new();
        for solid in &task.solids {
            let (name, t, colour, opacity) = match solid {
                SolidView::Capsule {
                    name,
                    a,
                    b,
                    r,
                    color,
                    opacity,
                } => (
                    name,
                    Triangles::capsule(Point3::from(*a), Point3::from(*b), *r),
                    color,
                    *opacity,
                ),
                SolidView::Box {
                    name,
                    centre,
                    half,
                    yaw_deg,
                    color,
                    opacity,
                } => (
                    name,
                    Triangles::cuboid(&Cuboid {
                        centre: Point3::from(*centre),
                        half_mm: Vector3::from(*half),
                        yaw_rad: yaw_deg.to_radians(),
                    }),
                    color,
                    *opacity,
                ),
            };
            children.push(self.mesh_node(name, &t, colour, opacity));
        }
        if let Some(at) = task.target {
            let p = Point3::from(at);
            let colour = if task.ok { REACHED } else { MISSED };
            let t = Triangles::capsule(p, p, 30.0);
            children.push(self.mesh_node("target", &t, colour, 1.0));
        }
        for j in &task.strained {
            let p = Point3::from(j.at);
            children.push(self.mesh_node(&j.name, &Triangles::capsule(p, p, 30.0), STRAINED, 1.0));
        }
        if let Some(s) = &task.sight {
            let (eyes, target) = (Point3::from(s.eyes), Point3::from(s.target));
            let colour = if s.ok { SEEN } else { MISSED };
            children.push(self.mesh_node(
                "line of sight",
                &Triangles::capsule(eyes, target, 4.0),
                colour,
                1.0,
            ));
        }
        if let Some(c) = &task.cells {
            let (u, v) = (Vector3::from(c.u), Vector3::from(c.v));
            let normal = u.cross(&v).normalize();
            let mut by_colour: Vec<(String, Triangles)> = Vec::new();
            for p in &c.points {
                let centre = Point3::new(p[0], p[1], p[2]) + 3.0 * normal;
                // The view's fourth number: how far short (0 where reached),
                // or a population's share.
                let colour = view_cell_colour(c.of, p[3]).to_string();
                let square = Triangles::square(centre, u, v, 0.9 * c.step);
                match by_colour.iter_mut().find(|(k, _)| *k == colour) {
                    Some((_, t)) => t.append(&square),
                    None => by_colour.push((colour, square)),
                }
            }
            for (colour, t) in by_colour {
                children.push(self.mesh_node("map cells", &t, &colour, 1.0));
            }
        }
        self.group(&task.label, children)
    }

    fn group(&mut self, name: &str, children: Vec<usize>) -> usize {
        self.nodes
            .push(json!({ "name": name, "children": children }));
        self.nodes.len() - 1
    }

    /// A node holding one mesh of one material.
    fn mesh_node(&mut self, name: &str, t: &Triangles, colour: &str, opacity: f64) -> usize {
        let positions = self.positions(&t.vertices);
        let indices = self.indices(&t.indices);
        let material = self.material(colour, opacity);
        self.meshes.push(json!({
            "name": name,
            "primitives": [{ "attributes": { "POSITION": positions }, "indices": indices, "material": material }]
        }));
        self.nodes
            .push(json!({ "name": name, "mesh": self.meshes.len() - 1 }));
        self.nodes.len() - 1
    }

    fn material(&mut self, colour: &str, opacity: f64) -> usize {
        let key = (colour.to_string(), opacity);
        match self.materials.iter().position(|m| *m == key) {
            Some(k) => k,
            None => {
                self.materials.push(key);
                self.materials.len() - 1
            }
        }
    }

    /// Vertices in glTF's frame (metres, y up) as an accessor.
    fn positions(&mut self, vertices: &[Point3<f64>]) -> usize {
        let gltf: Vec<[f32; 3]> = vertices
            .iter()
            .map(|p| [p.x, p.z, -p.y].map(|c| (c / 1000.0) as f32))
            .collect();
        let (mut lo, mut hi) = ([f32::MAX; 3], [f32::MIN; 3]);
        for p in &gltf {
            for k in 0..3 {
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k]);
            }
        }
        let bytes: Vec<u8> = gltf
            .iter()
            .flatten()
            .flat_map(|c| c.to_le_bytes())
            .collect();
        let view = self.view(&bytes, 34962);
        self.accessors.push(json!({
            "bufferView": view, "componentType": 5126, "count": gltf.len(), "type": "VEC3",
            "min": lo, "max": hi
        }));
        self.accessors.len() - 1
    }

    fn indices(&mut self, indices: &[u32]) -> usize {
        let bytes: Vec<u8> = indices.iter().flat_map(|k| k.to_le_bytes()).collect();
        let view = self.view(&bytes, 34963);
        self.accessors.push(json!({
            "bufferView": view, "componentType": 5125, "count": indices.len(), "type": "SCALAR"
        }));
        self.accessors.len() - 1
    }

    /// A buffer view of `bytes`, 4-byte aligned in the binary chunk.
    fn view(&mut self, bytes: &[u8], target: u32) -> usize {
        let offset = self.bin.len();
        self.bin.extend(bytes);
        while !self.bin.len().is_multiple_of(4) {
            self.bin.push(0);
        }
        self.views.push(json!({
            "buffer": 0, "byteOffset": offset, "byteLength": bytes.len(), "target": target
        }));
        self.views.len() - 1
    }

    fn finish(self, title: &str, scenes: Vec<Value>) -> Vec<u8> {
        let materials: Vec<Value> = self
            .materials
            .iter()
            .map(|(colour, opacity)| {
                let [r, g, b] = rgb(colour);
                let mut m = json!({
                    "name": colour,
                    "doubleSided": true,
                    "pbrMetallicRoughness": {
                        "baseColorFactor": [r, g, b, *opacity],
                        "metallicFactor": 0.0,
                        "roughnessFactor": 0.9
                    }
                });
                if *opacity < 1.0 {
                    m["alphaMode"] = "BLEND".into();
                }
                m
            })
            .collect();
        let document = json!({
            "asset": { "version": "2.0", "generator": concat!("reach ", env!("CARGO_PKG_VERSION")) },
            "extras": { "file": title },
            "scene": 0,
            "scenes": scenes,
            "nodes": self.nodes,
            "meshes": self.meshes,
            "materials": materials,
            "accessors": self.accessors,
            "bufferViews": self.views,
            "buffers": [{ "byteLength": self.bin.len() }]
        });
        container(
            &serde_json::to_vec(&document).expect("plain data"),
            &self.bin,
        )
    }
}

/// A GLB file of a glTF document's JSON and its binary buffer, laid out
/// (header, chunks padded to four bytes) by the `gltf` crate.
pub fn container(json: &[u8], bin: &[u8]) -> Vec<u8> {
    let glb = gltf::Glb {
        // The length is worked out as the file is written.
        header: gltf::binary::Header {
            magic: *b"glTF",
            version: 2,
            length: 0,
        },
        json: json.into(),
        bin: Some(bin.into()),
    };
    glb.to_vec().expect("written to memory")
}

/// `#rrggbb` as fractions.
fn rgb(colour: &str) -> [f64; 3] {
    let hex = colour.trim_start_matches('#');
    let at = |k: usize| {
        hex.get(k..k + 2)
            .and_then(|h| u8::from_str_radix(h, 16).ok())
            .map_or(0.5, |v| f64::from(v) / 255.0)
    };
    [at(0), at(2), at(4)]
}
