//! Rooms of many small boxes for the floor's tests.

use nalgebra::{Point3, Vector3};

use crate::scene::BoxObstacle;

/// 100 boxes 900 mm high in rows of 10, `pitch_mm` apart from `origin_mm`,
/// box `k` of `size(k)` (x, y) mm.
pub fn grid_of_boxes(
    origin_mm: [f64; 2],
    pitch_mm: f64,
    size: &dyn Fn(usize) -> [f64; 2],
) -> Vec<BoxObstacle> {
    (0..100)
        .map(|k| {
            let [w, d] = size(k);
            BoxObstacle {
                name: format!("b{k}"),
                corner_mm: Point3::new(
                    origin_mm[0] + pitch_mm * (k % 10) as f64,
                    origin_mm[1] + pitch_mm * (k / 10) as f64,
                    0.0,
                ),
                size_mm: Vector3::new(w, d, 900.0),
                yaw_rad: 0.0,
            }
        })
        .collect()
}
