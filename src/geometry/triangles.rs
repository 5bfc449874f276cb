//! A triangle mesh as files give it, made fit for collision: triangles
//! with a repeated vertex or no area are dropped (they have no inside and
//! no normal, and a solid built with them would block everything), and
//! each closed piece is wound outwards (a closed mesh wound inwards is the
//! same solid as one wound outwards; a collision library would take it as
//! everything outside).

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
    let (pieces, open) = pieces_and_open_edges(&kept);
    let mut every_piece_closed = true;
    for piece in pieces {
        let closed = piece.iter().all(|&i| !open[i]);
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
/// ascending order, the pieces by their first triangle; and for each
/// triangle whether one of its edges is open: not shared by exactly two
/// triangles, once in each direction. Found from every edge sorted by its
/// corners (no hashing: a million-triangle scan has three million edges).
fn pieces_and_open_edges(triangles: &[[u32; 3]]) -> (Vec<Vec<usize>>, Vec<bool>) {
    // Each edge as its corners in ascending order, whether it runs the
    // other way, and its triangle.
    let mut sides: Vec<(u64, bool, u32)> = Vec::with_capacity(triangles.len() * 3);
    for (i, t) in triangles.iter().enumerate() {
        for (a, b) in edges(t) {
            let undirected = (u64::from(a.min(b)) << 32) | u64::from(a.max(b));
            sides.push((undirected, a > b, i as u32));
        }
    }
    sides.sort_unstable();
    let mut parent: Vec<usize> = (0..triangles.len()).collect();
    fn root(parent: &mut [usize], mut i: usize) -> usize {
        while parent[i] != i {
            parent[i] = parent[parent[i]];
            i = parent[i];
        }
        i
    }
    let mut open = vec![false; triangles.len()];
    for same in sides.chunk_by(|x, y| x.0 == y.0) {
        let closed = matches!(same, [(_, false, _), (_, true, _)]);
        for &(_, _, i) in same {
            open[i as usize] |= !closed;
            let (ri, rj) = (
                root(&mut parent, i as usize),
                root(&mut parent, same[0].2 as usize),
            );
            parent[ri.max(rj)] = ri.min(rj);
        }
    }
    let mut groups: Vec<Vec<usize>> = Vec::new();
    let mut group_of_root: Vec<usize> = vec![usize::MAX; triangles.len()];
    for i in 0..triangles.len() {
        let r = root(&mut parent, i);
        if group_of_root[r] == usize::MAX {
            group_of_root[r] = groups.len();
            groups.push(Vec::new());
        }
        groups[group_of_root[r]].push(i);
    }
    (groups, open)
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
    use proptest::prelude::*;
    use std::collections::HashMap;

    /// The pieces and open edges counted the plain way: edges in hash
    /// maps, pieces joined through the first triangle with each edge.
    fn counted(triangles: &[[u32; 3]]) -> (Vec<Vec<usize>>, Vec<bool>) {
        let mut directed: HashMap<(u32, u32), u32> = HashMap::new();
        for t in triangles {
            for edge in edges(t) {
                *directed.entry(edge).or_default() += 1;
            }
        }
        let closed =
            |(a, b): (u32, u32)| directed[&(a, b)] == 1 && directed.get(&(b, a)) == Some(&1);
        let open = triangles
            .iter()
            .map(|t| !edges(t).into_iter().all(closed))
            .collect();
        let mut piece_of: Vec<usize> = (0..triangles.len()).collect();
        // Joined until nothing changes: every triangle takes the least
        // piece of a triangle it shares an edge with.
        loop {
            let mut changed = false;
            for i in 0..triangles.len() {
                for j in 0..triangles.len() {
                    let shares = edges(&triangles[i]).iter().any(|&(a, b)| {
                        edges(&triangles[j])
                            .iter()
                            .any(|&(c, d)| (a, b) == (c, d) || (a, b) == (d, c))
                    });
                    if shares && piece_of[j] < piece_of[i] {
                        piece_of[i] = piece_of[j];
                        changed = true;
                    }
                }
            }
            if !changed {
                break;
            }
        }
        let mut pieces: Vec<Vec<usize>> = Vec::new();
        for i in 0..triangles.len() {
            match pieces.iter_mut().find(|p| piece_of[p[0]] == piece_of[i]) {
                Some(p) => p.push(i),
                None => pieces.push(vec![i]),
            }
        }
        (pieces, open)
    }

    proptest! {
        /// Triangles over a few corners, so that edges come again in
        /// either direction, twice and more: the sorted edges find the
        /// pieces and open edges the plain count finds.
        #[test]
        fn sorted_edges_find_what_counting_finds(
            triangles in prop::collection::vec((0u32..7, 0u32..7, 0u32..7), 0..24)
        ) {
            let triangles: Vec<[u32; 3]> = triangles
                .into_iter()
                .filter(|(a, b, c)| a != b && b != c && a != c)
                .map(|(a, b, c)| [a, b, c])
                .collect();
            prop_assert_eq!(pieces_and_open_edges(&triangles), counted(&triangles));
        }
    }

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
