//! A mesh made smaller to draw: vertices clustered on a grid (each cell's
//! vertices become their mean), triangles whose corners fall in fewer than
//! three cells dropped, the grid coarsened until the triangles fit. Only
//! the picture uses it; every answer is found on the mesh itself.

use std::collections::HashMap;

use nalgebra::Point3;

/// The first cell size tried, and how much each try grows it.
const FIRST_CELL_MM: f64 = 10.0;
const GROWTH: f64 = 1.5;

/// `vertices` and `triangles` with at most `most` triangles.
pub fn simplified(
    vertices: &[Point3<f64>],
    triangles: &[[u32; 3]],
    most: usize,
) -> (Vec<Point3<f64>>, Vec<[u32; 3]>) {
    let mut cell_mm = FIRST_CELL_MM;
    loop {
        let (v, t) = clustered(vertices, triangles, cell_mm);
        if t.len() <= most {
            return (v, t);
        }
        cell_mm *= GROWTH;
    }
}

fn clustered(
    vertices: &[Point3<f64>],
    triangles: &[[u32; 3]],
    cell_mm: f64,
) -> (Vec<Point3<f64>>, Vec<[u32; 3]>) {
    let mut cell_of: HashMap<[i64; 3], u32> = HashMap::new();
    let mut sums: Vec<(Point3<f64>, f64)> = Vec::new();
    let index: Vec<u32> = vertices
        .iter()
        .map(|p| {
            let key = [p.x, p.y, p.z].map(|c| (c / cell_mm).floor() as i64);
            let k = *cell_of.entry(key).or_insert_with(|| {
                sums.push((Point3::origin(), 0.0));
                (sums.len() - 1) as u32
            });
            let (sum, n) = &mut sums[k as usize];
            *sum += p.coords;
            *n += 1.0;
            k
        })
        .collect();
    let merged = sums.into_iter().map(|(sum, n)| sum / n).collect();
    let mut seen = std::collections::HashSet::new();
    let kept = triangles
        .iter()
        .map(|t| t.map(|k| index[k as usize]))
        .filter(|&[a, b, c]| a != b && b != c && a != c)
        .filter(|&[a, b, c]| {
            // One triangle per set of three cells (both windings).
            let mut key = [a, b, c];
            key.sort_unstable();
            seen.insert(key)
        })
        .collect();
    (merged, kept)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_fine_grid_becomes_few_triangles_within_its_bounds() {
        let n = 100u32;
        let vertices: Vec<Point3<f64>> = (0..=n)
            .flat_map(|i| (0..=n).map(move |j| Point3::new(f64::from(i), f64::from(j), 0.0)))
            .collect();
        let at = |i: u32, j: u32| i * (n + 1) + j;
        let triangles: Vec<[u32; 3]> = (0..n)
            .flat_map(|i| {
                (0..n).flat_map(move |j| {
                    [
                        [at(i, j), at(i + 1, j), at(i + 1, j + 1)],
                        [at(i, j), at(i + 1, j + 1), at(i, j + 1)],
                    ]
                })
            })
            .collect();
        let (v, t) = simplified(&vertices, &triangles, 500);
        assert!(t.len() <= 500 && t.len() > 50, "{}", t.len());
        assert!(v
            .iter()
            .all(|p| (0.0..=100.0).contains(&p.x) && (0.0..=100.0).contains(&p.y)));
    }
}
