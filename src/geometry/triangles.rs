//! A triangle mesh as files give it, made fit for collision: triangles
//! with a repeated vertex or no area are dropped (they have no inside and
//! no normal, and a solid built with them would block everything), and
//! each closed piece is wound outwards (a closed mesh wound inwards is the
//! same solid as one wound outwards; a collision library would take it as
//! everything outside).

use std::collections::HashMap;

use nalgebra::Point3;

/// The triangles of `triangles` that have an area (and corners within
/// `vertices`), each closed piece (every edge shared by exactly two of its
/// triangles, once in each direction) turned to face outwards; and whether
/// they enclose solids: every piece closed. A single sheet (one triangle,
/// an open box) does not: only its surface is an obstacle.
pub fn cleaned(vertices: &[Point3<f64>], triangles: &[[u32; 3]]) -> (Vec<[u32; 3]>, bool) {
    let mut kept: Vec<[u32; 3]> = triangles
        .iter()
        .copied()
        .filter(|t| has_area(vertices, t))
        .collect();
    // Counted once for all pieces: triangles sharing an edge are one piece,
    // so an edge's count is its piece's.
    let mut directed: HashMap<(u32, u32), u32> = HashMap::new();
    for t in &kept {
        for edge in edges(t) {
            *directed.entry(edge).or_default() += 1;
        }
    }
    let closed_edge =
        |(a, b): (u32, u32)| directed[&(a, b)] == 1 && directed.get(&(b, a)) == Some(&1);
    let mut every_piece_closed = true;
    for piece in pieces(&kept) {
        let closed = piece
            .iter()
            .all(|&i| edges(&kept[i]).into_iter().all(closed_edge));
        every_piece_closed &= closed;
        if closed && signed_volume(vertices, &kept, &piece) < 0.0 {
            for &i in &piece {
                kept[i].swap(1, 2);
            }
        }
    }
    let encloses = every_piece_closed && !kept.is_empty();
    // Kept for the mesh's life: no spare capacity from the filter's growth.
    kept.shrink_to_fit();
    (kept, encloses)
}

/// Whether a triangle has three distinct corners that do not lie on one
/// line (relative to its size, so that millimetres and metres agree).
fn has_area(vertices: &[Point3<f64>], [a, b, c]: &[u32; 3]) -> bool {
    let within = |i: &u32| (*i as usize) < vertices.len();
    if a == b || b == c || a == c || !(within(a) && within(b) && within(c)) {
        return false;
    }
    let (a, b, c) = (
        vertices[*a as usize],
        vertices[*b as usize],
        vertices[*c as usize],
    );
    let (ab, ac) = (b - a, c - a);
    let longest_sq = ab
        .norm_squared()
        .max(ac.norm_squared())
        .max((c - b).norm_squared());
    let twice_area = ab.cross(&ac).norm();
    twice_area > 1e-9 * longest_sq
}

/// The triangles in groups that share edges (connected pieces), each in
/// ascending order, the pieces by their first triangle.
fn pieces(triangles: &[[u32; 3]]) -> Vec<Vec<usize>> {
    let mut parent: Vec<usize> = (0..triangles.len()).collect();
    fn root(parent: &mut [usize], mut i: usize) -> usize {
        while parent[i] != i {
            parent[i] = parent[parent[i]];
            i = parent[i];
        }
        i
    }
    let mut first_with_edge: HashMap<(u32, u32), usize> = HashMap::new();
    for (i, t) in triangles.iter().enumerate() {
        for (a, b) in edges(t) {
            let key = (a.min(b), a.max(b));
            match first_with_edge.get(&key) {
                Some(&j) => {
                    let (ri, rj) = (root(&mut parent, i), root(&mut parent, j));
                    parent[ri.max(rj)] = ri.min(rj);
                }
                None => {
                    first_with_edge.insert(key, i);
                }
            }
        }
    }
    let mut groups: Vec<Vec<usize>> = Vec::new();
    let mut group_of_root: HashMap<usize, usize> = HashMap::new();
    for i in 0..triangles.len() {
        let r = root(&mut parent, i);
        let g = *group_of_root.entry(r).or_insert_with(|| {
            groups.push(Vec::new());
            groups.len() - 1
        });
        groups[g].push(i);
    }
    groups
}

fn edges([a, b, c]: &[u32; 3]) -> [(u32, u32); 3] {
    [(*a, *b), (*b, *c), (*c, *a)]
}

/// Six times the volume the piece's triangles enclose, positive when they
/// face outwards.
fn signed_volume(vertices: &[Point3<f64>], triangles: &[[u32; 3]], piece: &[usize]) -> f64 {
    // About the piece's first corner, so that a solid far from the origin
    // keeps its precision.
    let origin = vertices[triangles[piece[0]][0] as usize];
    piece
        .iter()
        .map(|&i| {
            let [a, b, c] = triangles[i].map(|k| vertices[k as usize] - origin);
            a.dot(&b.cross(&c))
        })
        .sum()
}

/// A unit cube's corners and its twelve triangles, wound outwards (for
/// tests here and of the standards).
#[cfg(test)]
pub(crate) fn unit_cube() -> (Vec<Point3<f64>>, Vec<[u32; 3]>) {
    let v = (0..8)
        .map(|i| Point3::new(f64::from(i & 1), f64::from((i >> 1) & 1), f64::from(i >> 2)))
        .collect();
    let t = vec![
        [0, 2, 1],
        [1, 2, 3],
        [4, 5, 6],
        [5, 7, 6],
        [0, 1, 4],
        [1, 5, 4],
        [2, 6, 3],
        [3, 6, 7],
        [0, 4, 2],
        [2, 4, 6],
        [1, 3, 5],
        [3, 7, 5],
    ];
    (v, t)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_outward_cube_stays_and_an_inward_one_turns() {
        let (v, t) = unit_cube();
        assert!(signed_volume(&v, &t, &(0..12).collect::<Vec<_>>()) > 0.0);
        assert_eq!(cleaned(&v, &t), (t.clone(), true));
        let inward: Vec<[u32; 3]> = t.iter().map(|&[a, b, c]| [a, c, b]).collect();
        assert_eq!(cleaned(&v, &inward), (t, true));
    }

    #[test]
    fn degenerate_triangles_go_and_open_pieces_keep_their_winding() {
        let (mut v, mut t) = unit_cube();
        assert!(!cleaned(&v, &t[..11]).1 && !cleaned(&v, &t[..1]).1);
        v.push(Point3::new(0.5, 0.5, 0.0));
        t.extend([[0, 0, 1], [0, 1, 3], [0, 3, 8]]);
        let (kept, encloses) = cleaned(&v, &t);
        assert!(!encloses);
        // [0, 1, 3] has an area; it opens the cube, so nothing is turned.
        assert_eq!(kept.len(), 13);
        assert!(kept.contains(&[0, 1, 3]));
        let open: Vec<[u32; 3]> = t[..11].iter().map(|&[a, b, c]| [a, c, b]).collect();
        assert_eq!(cleaned(&v, &open), (open, false));
    }
}
