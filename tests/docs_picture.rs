//! The picture of the body model in docs/language.md (`docs/body.svg`),
//! drawn from the standard library: the seated people in their manual
//! wheelchairs and the standing ones with their rollators, from the side,
//! each in the neutral posture. The test fails when the committed picture
//! is not what the library draws now; `REACH_UPDATE_DOCS=1 cargo test
//! --release --test main docs_picture` writes it again.

use nalgebra::Point3;
use reach::figure;
use reach::picture::{svg, Panel, View};
use reach::plugin::{BasePose, Registry};
use reach::Input;

const PEOPLE: [(&str, &str, &str); 6] = [
    ("woman_5th_seated", "manual_wheelchair", "woman_5th_seated"),
    ("man_50th_seated", "manual_wheelchair", "man_50th_seated"),
    ("man_95th_seated", "manual_wheelchair", "man_95th_seated"),
    ("woman_5th", "rollator", "woman_5th"),
    ("man_50th", "rollator", "man_50th"),
    ("man_95th", "rollator", "man_95th"),
];

fn picture() -> String {
    let mut text = String::from(
        "units mm deg\nuse std::people\nroom r {\n  size 3000 x 3000 x 2500\n  target t at (1500, 1500, 900)\n}\n",
    );
    for (i, (mannequin, base, _)) in PEOPLE.iter().enumerate() {
        text += &format!("person p{i} {{ mannequin {mannequin} base {base} }}\n");
    }
    let registry = Registry::builtin();
    let (_, checked) = reach::check(
        Input::Text {
            name: "body.reach",
            text: &text,
        },
        &registry,
    );
    let scenario = checked.unwrap_or_else(|d| panic!("{}", d.render(false)));
    let panels: Vec<Panel> = PEOPLE
        .iter()
        .enumerate()
        .map(|(i, (_, _, title))| {
            let body = &scenario.persons[i].body;
            let base_of = &scenario.bases[i];
            let hip_mm = base_of
                .hip_height_mm()
                .expect("a moving base knows the hip's height");
            let pose = BasePose {
                position_mm: Point3::new(0.0, 0.0, hip_mm),
                heading_rad: 0.0,
            };
            let neutral: Vec<f64> = body.joints.iter().map(|j| j.neutral).collect();
            Panel {
                title: title.to_string(),
                view: View::Side,
                items: figure::person(body, &neutral, pose, base_of.own_body()),
                levels_mm: vec![(0.0, "floor".into())],
            }
        })
        .collect();
    svg(
        "std::people in manual wheelchairs and with rollators: the solids a posture keeps apart (from the right, neutral posture)",
        &panels,
        0.2,
    )
}

#[test]
fn the_body_picture_in_the_docs_is_what_the_library_draws() {
    let drawn = picture();
    let path = "docs/body.svg";
    if std::env::var_os("REACH_UPDATE_DOCS").is_some() {
        std::fs::write(path, &drawn).unwrap();
    }
    let committed = std::fs::read_to_string(path).unwrap_or_default();
    assert!(
        committed == drawn,
        "{path} is not what the library draws now: run REACH_UPDATE_DOCS=1 cargo test --release --test main docs_picture"
    );
}
