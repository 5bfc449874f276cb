//! A placed person as solids in the room, for a picture: every link of the
//! body in a posture (the joints a task moved, the others at neutral), the
//! head, the legs and the base's parts where the base stands.

use crate::geometry::{Capsule, Cuboid, Shape, Solid};
use crate::kinematics::{Body, Owner};
use crate::picture::Painted;
use crate::scene::{BasePose, OwnBody};

/// Colours: skin for the moving body, a darker skin for the legs, grey
/// for the base.
pub const SKIN: &str = "#e8b48a";
pub const LEGS: &str = "#c8906a";
pub const BASE: &str = "#7d8590";

/// The body in posture `q` (a value per joint of `body`, in its order),
/// standing at `pose`, with its legs and base `own`: each solid once, in
/// the room frame.
pub fn person(body: &Body, q: &[f64], pose: BasePose, own: &OwnBody) -> Vec<Painted> {
    let mut items = Vec::new();
    let mut drawn = vec![false; body.joints.len()];
    let paths: Vec<Vec<usize>> = (0..body.effectors.len())
        .map(|index| body.path(body.effectors[index].joint))
        .collect();
    for (index, path) in paths.iter().enumerate() {
        let chain = body.chain(index);
        let chain_q: Vec<f64> = path.iter().map(|&j| q[j]).collect();
        let volumes = chain.volumes(&chain_q);
        let riders = body.riders_on(path);
        for (capsule, &owner) in volumes.capsules.iter().zip(&volumes.owners) {
            let new = match owner {
                Owner::Link(j) if j < path.len() => !std::mem::replace(&mut drawn[path[j]], true),
                Owner::Link(_) => true,
                Owner::Rider(k) => index == drawing_chain(&paths, riders[k].0),
            };
            if new && capsule.radius_mm > 0.0 {
                items.push(Painted {
                    shape: Shape::Capsule(capsule_in_room(capsule, pose)),
                    fill: SKIN.into(),
                    opacity: 0.9,
                    label: chain.volume_name(owner).to_string(),
                });
            }
        }
    }
    let leaning = leaning_legs(body, q, own);
    items.extend(own.solids.iter().map(|solid| {
        Painted {
            shape: shape_in_room(
                &leaning
                    .iter()
                    .find(|leg| leg.name == solid.name)
                    .unwrap_or(solid)
                    .shape,
                pose,
            ),
            fill: if is_leg(solid) { LEGS } else { BASE }.into(),
            // The base's parts let the body behind them show through.
            opacity: if is_leg(solid) { 0.9 } else { 0.45 },
            label: solid.name.clone(),
        }
    }));
    items
}

/// Standing, the legs leaning where the balance of posture `q` puts the
/// feet (none where they stay under the hips, or it is lost).
fn leaning_legs(body: &Body, q: &[f64], own: &OwnBody) -> Vec<Solid> {
    let Some(balance) = own.balance.as_ref() else {
        return Vec::new();
    };
    let Some(first) = body.effectors.first() else {
        return Vec::new();
    };
    let path = body.path(first.joint);
    let chain_q: Vec<f64> = path.iter().map(|&j| q[j]).collect();
    let volumes = body.chain_posed(0, q).volumes(&chain_q);
    match balance.feet_moved_mm(&volumes) {
        Ok(moved) if moved != nalgebra::Vector2::zeros() => {
            balance.legs().standing_feet_moved(moved)
        }
        _ => Vec::new(),
    }
}

/// The chain that draws a carried solid sitting on body joint `joint`:
/// the first whose joints include it (which poses it as the task moved
/// it), else the first (which carries it at neutral, as no task moves it).
fn drawing_chain(paths: &[Vec<usize>], joint: Option<usize>) -> usize {
    joint
        .and_then(|j| paths.iter().position(|path| path.contains(&j)))
        .unwrap_or(0)
}

/// Whether a solid of the person's own body is a part of them (a thigh, a
/// foot) rather than of their base.
fn is_leg(solid: &Solid) -> bool {
    ["thigh", "shank", "foot"]
        .iter()
        .any(|part| solid.name.ends_with(part))
}

fn capsule_in_room(c: &Capsule, pose: BasePose) -> Capsule {
    Capsule::new(pose.to_room(&c.a), pose.to_room(&c.b), c.radius_mm)
}

fn shape_in_room(shape: &Shape, pose: BasePose) -> Shape {
    match shape {
        Shape::Capsule(c) => Shape::Capsule(capsule_in_room(c, pose)),
        Shape::Cuboid(c) => Shape::Cuboid(Cuboid {
            centre: pose.to_room(&c.centre),
            yaw_rad: c.yaw_rad + pose.heading_rad,
            ..*c
        }),
    }
}
