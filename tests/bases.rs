//! Mobile bases: every placement a report gives is admissible, checked
//! independently of the placement search: each part of the footprint at
//! the reported pose lies in the room and overlaps no obstacle at its
//! height.

use geo::{Area, BooleanOps, Coord, LineString, Polygon};
use reach::plugin::Registry;
use reach::report::TaskReport;
use reach::scenario::Scenario;
use reach::scene::BoxObstacle;
use reach::Input;

fn scenario(path: &str) -> Scenario {
    let (_, checked) = reach::check(Input::Path(path.as_ref()), &Registry::builtin());
    checked.unwrap_or_else(|d| panic!("{}", d.render(true)))
}

fn outline(b: &BoxObstacle) -> Polygon<f64> {
    let (s, c) = b.yaw_rad.sin_cos();
    let ring: Vec<Coord<f64>> = [
        (0.0, 0.0),
        (b.size_mm.x, 0.0),
        (b.size_mm.x, b.size_mm.y),
        (0.0, b.size_mm.y),
    ]
    .into_iter()
    .map(|(x, y)| Coord {
        x: b.corner_mm.x + c * x - s * y,
        y: b.corner_mm.y + s * x + c * y,
    })
    .collect();
    Polygon::new(LineString::from(ring), Vec::new())
}

#[test]
fn every_reported_base_pose_is_admissible() {
    let scenario = scenario("examples/kitchen_wheelchair.reach");
    let report = reach::run(&scenario).expect("within the bound on solver work");
    let room = &scenario.rooms[0];
    let mut checked = 0;
    for task in &report.tasks {
        let TaskReport::Reach(r) = task else { continue };
        let index = scenario
            .persons
            .iter()
            .position(|p| p.name == r.person)
            .unwrap();
        let Some(footprint) = scenario.bases[index].footprint() else {
            continue;
        };
        let heading = r.base.heading_deg.to_radians();
        for (k, part) in footprint.parts.iter().enumerate() {
            let shape = footprint.polygon_at(k, r.base.x_mm, r.base.y_mm, heading);
            // Reports round to 0.01 mm; allow that much.
            for c in shape.exterior().coords() {
                let inside = (-0.02..=room.size_mm.x + 0.02).contains(&c.x)
                    && (-0.02..=room.size_mm.y + 0.02).contains(&c.y);
                assert!(
                    inside,
                    "{} by {}: outside the room at {c:?}",
                    r.name, r.person
                );
            }
            // A box counts where its height overlaps the part's: the
            // footrests go under a sink, the seat does not.
            let below = |b: &&BoxObstacle| {
                b.corner_mm.z < part.z_mm[1] && b.corner_mm.z + b.size_mm.z > part.z_mm[0]
            };
            for b in room.boxes.iter().filter(below) {
                let overlap = shape.intersection(&outline(b)).unsigned_area();
                assert!(
                    overlap < 1.0,
                    "{} by {}: part {k} of the footprint overlaps {} by {overlap} mm2",
                    r.name,
                    r.person,
                    b.name
                );
            }
        }
        checked += 1;
    }
    assert!(checked >= 4, "the example places mobile bases");
}

#[test]
fn a_wheelchair_user_cannot_reach_what_a_standing_person_can() {
    let scenario = scenario("examples/kitchen_wheelchair.reach");
    let report = reach::run(&scenario).expect("within the bound on solver work");
    let reach = |target: &str, person: &str| super::body::reach_of(&report, target, person);
    assert!(reach("counter_front", "ann").ok);
    // The wall cabinet's bottom board: within the standing person's reach,
    // not the seated one's (her hand comes to it only through the board);
    // its middle shelf is beyond both, far beyond the seated one's.
    let (ben, ann) = (reach("cabinet_low", "ben"), reach("cabinet_low", "ann"));
    assert!(ben.ok, "{ben:?}");
    assert!(!ann.ok, "{ann:?}");
    let ann = reach("cabinet_high", "ann");
    assert!(ann.distance_mm > 100.0, "{ann:?}");
}
