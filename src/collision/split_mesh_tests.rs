//! A surface mesh held in parts answers as the whole mesh does: the same
//! capsules touch it and rays meet it at the same place, for random
//! capsules and rays about a bumpy sheet of more triangles than one part
//! holds.

use std::sync::OnceLock;

use nalgebra::{Isometry3, Point3, Vector3};
use parry3d_f64::query::{self, Ray};
use parry3d_f64::shape::{Capsule as ParryCapsule, SharedShape};
use proptest::prelude::*;

use super::Obstacles;
use crate::geometry::Capsule;
use crate::scene::{Blocker, MeshObstacle, Room, PART_TRIANGLES};

/// Grid points a side: 2 x 129 x 129 = 33,282 triangles, two parts.
const SIDE: u32 = 130;
const STEP_MM: f64 = 20.0;

fn sheet() -> &'static (MeshObstacle, SharedShape) {
    static SHEET: OnceLock<(MeshObstacle, SharedShape)> = OnceLock::new();
    SHEET.get_or_init(|| {
        let mut vertices = Vec::new();
        for j in 0..SIDE {
            for i in 0..SIDE {
                let (x, y) = (f64::from(i) * STEP_MM, f64::from(j) * STEP_MM);
                let z = 900.0 + 40.0 * (x / 150.0).sin() * (y / 230.0).cos();
                vertices.push(Point3::new(500.0 + x, 500.0 + y, z));
            }
        }
        let mut triangles = Vec::new();
        for j in 0..SIDE - 1 {
            for i in 0..SIDE - 1 {
                let v = j * SIDE + i;
                triangles.push([v, v + 1, v + SIDE + 1]);
                triangles.push([v, v + SIDE + 1, v + SIDE]);
            }
        }
        assert!(triangles.len() > PART_TRIANGLES);
        let whole = SharedShape::trimesh(vertices.clone(), triangles.clone()).unwrap();
        (
            MeshObstacle::new("sheet".into(), vertices, &triangles),
            whole,
        )
    })
}

fn obstacles() -> &'static Obstacles {
    static OBSTACLES: OnceLock<Obstacles> = OnceLock::new();
    OBSTACLES.get_or_init(|| {
        let (mesh, _) = sheet();
        assert!(mesh.shape().unwrap().parts.len() >= 2);
        let room = Room {
            name: "r".into(),
            size_mm: Vector3::new(4000.0, 4000.0, 2500.0),
            boxes: Vec::new(),
            meshes: vec![mesh.clone()],
            targets: vec![],
            surfaces: vec![],
            doors: Vec::new(),
        };
        Obstacles::new(&room, 0.0)
    })
}

fn point_about_the_sheet() -> impl Strategy<Value = Point3<f64>> {
    (400.0..3200.0f64, 400.0..3200.0f64, 700.0..1100.0f64)
        .prop_map(|(x, y, z)| Point3::new(x, y, z))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(512))]

    #[test]
    fn a_capsule_touches_the_parts_where_it_touches_the_whole(
        a in point_about_the_sheet(),
        b in point_about_the_sheet(),
        r in 0.0..60.0f64,
    ) {
        let at = Isometry3::identity();
        let whole = query::intersection_test(&at, &ParryCapsule::new(a, b, r.max(1e-9)), &at, sheet().1.as_ref()).unwrap();
        let parts = obstacles().capsule_hits(&Capsule::new(a, b, r)).any(|h| h == Blocker::Obstacle(0));
        prop_assert_eq!(parts, whole);
    }

    #[test]
    fn a_ray_meets_the_parts_where_it_meets_the_whole(
        eye in point_about_the_sheet(),
        target in point_about_the_sheet(),
    ) {
        let at = Isometry3::identity();
        let whole = sheet().1.cast_ray(&at, &Ray::new(eye, target - eye), 1.0, true);
        let parts = obstacles().first_on_sight_line(&eye, &target, 0.0).and_then(|(b, t)| (b == Blocker::Obstacle(0)).then_some(t));
        match (whole, parts) {
            (Some(w), Some(p)) => prop_assert!((w - p).abs() < 1e-9, "{} vs {}", w, p),
            (w, p) => prop_assert_eq!(w.is_some(), p.is_some(), "{:?} vs {:?}", w, p),
        }
    }
}
