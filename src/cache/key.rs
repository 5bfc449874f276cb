//! The key of each task's result: a hash, bit for bit, of every value its
//! answer depends on. Of the room, that is its size, where the task's base
//! may put the hip for each point (`Hips`: poses, and for a base that
//! searches the floor a ball about the point that holds every hip point it
//! may try and the floor that decides whether it fits there), and the
//! obstacles within reach of those (`reach.rs`). Placements are computed again only
//! when the room's obstacles, the person or the points change.

use std::collections::hash_map::DefaultHasher;
use std::collections::HashMap;
use std::hash::{Hash, Hasher};
use std::sync::Arc;

use rayon::prelude::*;

use super::reach::{obstacles_within, Tried};
use super::touched::points_bounds;
use crate::allowance::Unmetered;
use crate::kept::Memo;
use crate::kinematics::{Body, Chain, Joint};
use crate::plugin::Dependence;
use crate::progress::NoProgress;
use crate::scenario::{Scenario, SubjectRef, TaskSpec};
use crate::scene::{hash_bits, BasePose, Person, Room};
use nalgebra::Point3;

/// The placements tried for each point of a task, by what they depend on.
pub(super) type Placements = HashMap<u64, Arc<Vec<Tried>>>;

/// A task's keys.
pub(super) struct TaskKey {
    /// Of everything its answer depends on, the obstacles within its
    /// reach included.
    pub strict: u64,
    /// Of everything but the obstacles, for a task that records what its
    /// questions touch (`touched.rs`); none for one that does not.
    pub loose: Option<u64>,
    /// The bounds of the task's points.
    pub points: Option<[Point3<f64>; 2]>,
}

impl TaskKey {
    /// The keys of a task charged its person's floor and its base's
    /// getting ready as `charges` says (`Scenario::first_charges`).
    pub fn charged(&mut self, charges: (bool, bool)) {
        self.strict = hash_of(|h| (self.strict, charges).hash(h));
        self.loose = (self.loose).map(|loose| hash_of(|h| (loose, charges).hash(h)));
    }

    /// The full key with every obstacle of the task's room (`room`, their
    /// hash by value): what an answer whose why ranked the obstacles is
    /// kept by.
    pub fn whole(&self, room: u64) -> u64 {
        hash_of(|h| (self.strict, room).hash(h))
    }
}

/// The keys of the scenario's tasks, in order; `placements` holds, after,
/// the placements of this scenario's tasks (reused from it where nothing
/// they depend on changed).
pub(super) fn keys(
    scenario: &Scenario,
    placements: &mut Placements,
    memo: &Arc<Memo>,
) -> Vec<TaskKey> {
    let dependences: Vec<Dependence> = scenario
        .tasks
        .par_iter()
        .map(|t| t.task.dependence(&scenario.input(t, &NoProgress)))
        .collect();
    let floor_keys: Vec<u64> = scenario
        .tasks
        .par_iter()
        .zip(&dependences)
        .map(|(t, d)| placements_key(scenario, t, d))
        .collect();
    let mut fresh = Placements::new();
    for ((task, dependence), floor_key) in scenario.tasks.iter().zip(&dependences).zip(&floor_keys)
    {
        if fresh.contains_key(floor_key) {
            continue;
        }
        let tried = match placements.get(floor_key) {
            Some(tried) => Arc::clone(tried),
            None => Arc::new(tried(scenario, task, dependence, memo)),
        };
        fresh.insert(*floor_key, tried);
    }
    *placements = fresh;
    scenario
        .tasks
        .par_iter()
        .zip(&dependences)
        .zip(&floor_keys)
        .map(|((task, dependence), floor_key)| {
            let tried = &placements[floor_key];
            TaskKey {
                strict: key(scenario, task, dependence, tried),
                loose: loose_key(scenario, task, tried),
                points: points_bounds(&dependence.points_mm),
            }
        })
        .collect()
}

/// The key of everything `task`'s answer depends on but the room's
/// obstacles, where the task records what its questions touch and its
/// base reads the room only through the floor: its settings, subject and
/// person, the room's size, the placements its base may try and, for a
/// base that moves, the floor it moves on.
fn loose_key(scenario: &Scenario, task: &TaskSpec, tried: &[Tried]) -> Option<u64> {
    let base = &scenario.bases[task.person];
    let tracked = task.task.records_touches() && base.reads_room_through_floor();
    if task.population.is_some() || !tracked {
        return None;
    }
    let room = &scenario.rooms[task.room];
    Some(hash_of(|h| {
        hash_task(scenario, task, tried, h);
        if base.footprint().is_some() {
            room.hash_floor(&footprint_bands(scenario, task), h);
        }
    }))
}

/// What both keys hold: the task's settings, subject and person, its
/// room's name and size, and where its base may put the hip for each
/// point.
fn hash_task(scenario: &Scenario, task: &TaskSpec, tried: &[Tried], h: &mut DefaultHasher) {
    let room = &scenario.rooms[task.room];
    (&task.kind, &task.options, &task.effectors).hash(h);
    hash_subject(&task.subject, room, h);
    hash_person(&scenario.persons[task.person], h);
    room.name.hash(h);
    hash_bits(room.size_mm.iter(), h);
    hash_tried(tried, h);
    // What a check costs the meter: a kept answer's work is a fresh run's.
    crate::meter::capsule_check(room.boxes.len() + room.meshes.len()).hash(h);
}

/// Where the base may put the hip for each point.
fn hash_tried(tried: &[Tried], h: &mut DefaultHasher) {
    for t in tried {
        t.hips.poses.iter().for_each(|pose| hash_pose(pose, h));
        if let Some((centre, radius_mm)) = &t.hips.around {
            hash_bits(centre.iter().chain([radius_mm]), h);
        }
    }
}

/// The placements a task's base may try for each of its points.
fn tried(
    scenario: &Scenario,
    task: &TaskSpec,
    dependence: &Dependence,
    memo: &Arc<Memo>,
) -> Vec<Tried> {
    let room = &scenario.rooms[task.room];
    // Worked out before the run, not metered; kept with the session's.
    let unmetered = Unmetered(Arc::clone(memo));
    let prepared = scenario.bases[task.person].prepare(room, &dependence.chain, &unmetered);
    dependence
        .points_mm
        .par_iter()
        .map(|p| Tried {
            point_mm: *p,
            hips: prepared.hips(p, dependence.tolerance_mm),
        })
        .collect()
}

/// What a task's placements depend on: the person's base, the chain, the
/// points, and the room's floor as the base meets it (its size, the doors,
/// every obstacle's outline on the floor and whether it comes within the
/// heights of the base's footprint).
fn placements_key(scenario: &Scenario, task: &TaskSpec, dependence: &Dependence) -> u64 {
    let room = &scenario.rooms[task.room];
    let bands = footprint_bands(scenario, task);
    hash_of(|h| {
        (task.person, &scenario.persons[task.person].base).hash(h);
        hash_chain(&dependence.chain, h);
        dependence
            .points_mm
            .iter()
            .for_each(|p| hash_bits(p.iter(), h));
        room.hash_floor(&bands, h);
    })
}

/// The heights the parts of the task's base's footprint stand at (none
/// for a base that does not move).
fn footprint_bands(scenario: &Scenario, task: &TaskSpec) -> Vec<[f64; 2]> {
    scenario.bases[task.person]
        .footprint()
        .map(|f| f.bands_mm())
        .unwrap_or_default()
}

fn key(scenario: &Scenario, task: &TaskSpec, dependence: &Dependence, tried: &[Tried]) -> u64 {
    let room = &scenario.rooms[task.room];
    hash_of(|h| {
        hash_task(scenario, task, tried, h);
        // Where the room has doors, whether a base that moves can get to a
        // place depends on the doors and on the floor of the whole room.
        let routed = !room.doors.is_empty() && tried.iter().any(|t| t.hips.around.is_some());
        // A population's people differ from its first in their bodies,
        // bases and placements: each is in the key, and every obstacle.
        if let Some(population) = task.population {
            let members = scenario.populations[population].members.clone();
            for person in &scenario.persons[members] {
                hash_person(person, h);
                person.base.hash(h);
            }
            room.hash_obstacles(h);
            if routed {
                room.doors.iter().for_each(|d| d.hash_into(h));
            }
        } else {
            // The floor's hash holds the doors.
            if routed {
                room.hash_floor(&footprint_bands(scenario, task), h);
            }
            if let Some(reach_mm) = dependence.reach_mm {
                for i in obstacles_within(room, tried, reach_mm, dependence.sight_lines) {
                    room.hash_obstacle(i, h);
                }
            }
        }
    })
}

fn hash_of(f: impl FnOnce(&mut DefaultHasher)) -> u64 {
    let mut h = DefaultHasher::new();
    f(&mut h);
    h.finish()
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
    body.couplings.hash(h);
    for e in &body.effectors {
        (&e.name, e.joint).hash(h);
        hash_bits(e.offset_mm.iter(), h);
    }
}

fn hash_chain(chain: &Chain, h: &mut DefaultHasher) {
    chain.joints.iter().for_each(|j| hash_joint(j, h));
    chain.effector_name.hash(h);
    chain.couplings.hash(h);
    hash_bits(chain.effector_mm.iter(), h);
}

fn hash_joint(j: &Joint, h: &mut DefaultHasher) {
    (&j.name, j.kind as u8).hash(h);
    let d = &j.dh;
    hash_bits(&[d.theta_rad, d.d_mm, d.alpha_rad(), d.a_mm], h);
    (j.fixed.is_some(), j.pre.is_some()).hash(h);
    for pose in [&j.fixed, &j.pre].into_iter().flatten() {
        hash_bits(pose.rotation.matrix().iter(), h);
        hash_bits(pose.translation.vector.iter(), h);
    }
    hash_bits(&[j.min, j.max, j.neutral, j.weight], h);
}
