//! A room's values fed to a hasher bit for bit: what keys a result kept
//! across runs (watch mode's task results, a base's floor) on the room it
//! was worked out in.

use std::hash::{Hash, Hasher};

use super::{Door, Room};

/// Each value's bits, in order.
pub fn hash_bits<'a>(values: impl IntoIterator<Item = &'a f64>, h: &mut impl Hasher) {
    for v in values {
        v.to_bits().hash(h);
    }
}

impl Room {
    /// Obstacle `index` (boxes, then meshes), by value.
    pub fn hash_obstacle(&self, index: usize, h: &mut impl Hasher) {
        index.hash(h);
        match self.boxes.get(index) {
            Some(b) => {
                b.name.hash(h);
                hash_bits(b.corner_mm.iter().chain(b.size_mm.iter()), h);
                b.yaw_rad.to_bits().hash(h);
            }
            None => {
                let m = &self.meshes[index - self.boxes.len()];
                m.name.hash(h);
                m.vertices_mm.iter().for_each(|v| hash_bits(v.iter(), h));
                m.triangles.hash(h);
            }
        }
    }

    /// Every obstacle, in order, by value.
    pub fn hash_obstacles(&self, h: &mut impl Hasher) {
        (0..self.boxes.len() + self.meshes.len()).for_each(|i| self.hash_obstacle(i, h));
    }

    /// Everything the floor of a base whose footprint's parts stand at the
    /// heights `bands_mm` depends on: the size, the doors, each box's turn
    /// (the routes from a door follow the sides of turned boxes) and, for
    /// each band, whether the box comes within it, and the name and
    /// outline on the floor of each box that comes within one (how high it
    /// is otherwise does not matter: a shelf raised within a band leaves
    /// the floor as it was, and a wall cabinet above every band may move
    /// anywhere), every mesh by value.
    pub fn hash_floor(&self, bands_mm: &[[f64; 2]], h: &mut impl Hasher) {
        hash_bits(self.size_mm.iter(), h);
        (self.boxes.len(), self.meshes.len()).hash(h);
        for b in &self.boxes {
            let meets: Vec<bool> = bands_mm.iter().map(|&band| b.meets_band(band)).collect();
            meets.hash(h);
            b.yaw_rad.to_bits().hash(h);
            if meets.contains(&true) {
                b.name.hash(h);
                let (c, s) = (&b.corner_mm, &b.size_mm);
                hash_bits(&[c.x, c.y, s.x, s.y], h);
            }
        }
        let meshes = self.boxes.len()..self.boxes.len() + self.meshes.len();
        meshes.for_each(|i| self.hash_obstacle(i, h));
        self.doors.len().hash(h);
        self.doors.iter().for_each(|d| d.hash_into(h));
    }
}

impl Door {
    /// The door by value.
    pub fn hash_into(&self, h: &mut impl Hasher) {
        (&self.name, self.wall as u8).hash(h);
        hash_bits(&[self.along_mm, self.width_mm], h);
    }
}
