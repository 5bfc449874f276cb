//! The key of each task's result: a hash, bit for bit, of every value its
//! answer depends on. Of the room, that is its size, the placements the
//! task's base may try for each point (they hold all the floor's obstacles
//! do to the answer: the admissible region is computed over all of them,
//! and only its candidate points are used), and the obstacles within reach
//! of those placements (`reach.rs`).

use std::collections::hash_map::DefaultHasher;
use std::collections::HashMap;
use std::hash::{Hash, Hasher};

use rayon::prelude::*;

use super::reach::{obstacles_within, Tried};
use crate::kinematics::{Body, Chain, Joint};
use crate::plugin::{Dependence, PreparedBase};
use crate::progress::NoProgress;
use crate::scenario::{Scenario, SubjectRef, TaskSpec};
use crate::scene::{BasePose, Person, Room};

/// The keys of the scenario's tasks, in order.
pub(super) fn keys(scenario: &Scenario) -> Vec<u64> {
    let dependences: Vec<Dependence> = scenario
        .tasks
        .par_iter()
        .map(|t| t.task.dependence(&scenario.input(t, &NoProgress)))
        .collect();
    // A base is prepared once per person, room and chain.
    let mut prepared: HashMap<(usize, usize, u64), Box<dyn PreparedBase + '_>> = HashMap::new();
    for (task, dependence) in scenario.tasks.iter().zip(&dependences) {
        let at = (
            task.person,
            task.room,
            hash_of(|h| hash_chain(&dependence.chain, h)),
        );
        prepared.entry(at).or_insert_with(|| {
            scenario.bases[task.person].prepare(&scenario.rooms[task.room], &dependence.chain)
        });
    }
    scenario
        .tasks
        .par_iter()
        .zip(&dependences)
        .map(|(task, dependence)| {
            let at = (
                task.person,
                task.room,
                hash_of(|h| hash_chain(&dependence.chain, h)),
            );
            key(scenario, task, dependence, prepared[&at].as_ref())
        })
        .collect()
}

fn key(
    scenario: &Scenario,
    task: &TaskSpec,
    dependence: &Dependence,
    prepared: &dyn PreparedBase,
) -> u64 {
    let room = &scenario.rooms[task.room];
    hash_of(|h| {
        (&task.kind, &task.options, &task.effectors).hash(h);
        hash_subject(&task.subject, room, h);
        hash_person(&scenario.persons[task.person], h);
        room.name.hash(h);
        hash_bits(room.size_mm.iter(), h);
        let tried: Vec<Tried> = dependence
            .points_mm
            .iter()
            .map(|p| {
                let poses = prepared.candidates(p);
                poses.iter().for_each(|pose| hash_pose(pose, h));
                Tried {
                    point_mm: *p,
                    hips_mm: poses.iter().map(|pose| pose.position_mm).collect(),
                }
            })
            .collect();
        if let Some(reach_mm) = dependence.reach_mm {
            for i in obstacles_within(room, &tried, reach_mm, dependence.sight_lines) {
                hash_obstacle(room, i, h);
            }
        }
    })
}

fn hash_of(f: impl FnOnce(&mut DefaultHasher)) -> u64 {
    let mut h = DefaultHasher::new();
    f(&mut h);
    h.finish()
}

fn hash_bits<'a>(values: impl IntoIterator<Item = &'a f64>, h: &mut DefaultHasher) {
    for v in values {
        v.to_bits().hash(h);
    }
}

fn hash_pose(pose: &BasePose, h: &mut DefaultHasher) {
    hash_bits(pose.position_mm.iter(), h);
    pose.heading_rad.to_bits().hash(h);
}

fn hash_subject(subject: &SubjectRef, room: &Room, h: &mut DefaultHasher) {
    match subject {
        SubjectRef::Target(i) => {
            let t = &room.targets[*i];
            t.name.hash(h);
            hash_bits(t.position_mm.iter(), h);
        }
        SubjectRef::Surface(s) => {
            s.name.hash(h);
            hash_bits(s.corner_mm.iter().chain(s.u_mm.iter()).chain(&s.v_mm), h);
        }
    }
}

fn hash_person(person: &Person, h: &mut DefaultHasher) {
    (&person.name, &person.mannequin, &person.base).hash(h);
    hash_body(&person.body, h);
    let v = &person.vision;
    for o in [v.mar_far_rad, v.mar_near_rad, v.near_point_mm, v.acuity] {
        o.map(f64::to_bits).hash(h);
    }
}

fn hash_body(body: &Body, h: &mut DefaultHasher) {
    body.joints.iter().for_each(|j| hash_joint(j, h));
    body.parents.hash(h);
    for e in &body.effectors {
        (&e.name, e.joint).hash(h);
        hash_bits(e.offset_mm.iter(), h);
    }
}

fn hash_chain(chain: &Chain, h: &mut DefaultHasher) {
    chain.joints.iter().for_each(|j| hash_joint(j, h));
    chain.effector_name.hash(h);
    hash_bits(chain.effector_mm.iter(), h);
}

fn hash_joint(j: &Joint, h: &mut DefaultHasher) {
    (&j.name, j.kind as u8).hash(h);
    let d = &j.dh;
    hash_bits(&[d.theta_rad, d.d_mm, d.alpha_rad, d.a_mm], h);
    if let Some(fixed) = &j.fixed {
        hash_bits(fixed.rotation.matrix().iter(), h);
        hash_bits(fixed.translation.vector.iter(), h);
    }
    hash_bits(&[j.min, j.max, j.neutral, j.weight], h);
}

/// Obstacle `index` of the room (boxes, then meshes), by value.
fn hash_obstacle(room: &Room, index: usize, h: &mut DefaultHasher) {
    index.hash(h);
    match room.boxes.get(index) {
        Some(b) => {
            b.name.hash(h);
            hash_bits(b.corner_mm.iter().chain(b.size_mm.iter()), h);
            b.yaw_rad.to_bits().hash(h);
        }
        None => {
            let m = &room.meshes[index - room.boxes.len()];
            m.name.hash(h);
            m.vertices_mm.iter().for_each(|v| hash_bits(v.iter(), h));
            m.triangles.hash(h);
        }
    }
}
