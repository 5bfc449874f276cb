//! Task results kept between evaluations (watch mode), keyed by everything
//! a task depends on: its kind, subject, person and options, the person's
//! chain and base, and of its room the size, the obstacles (boxes and
//! meshes) and its own target or surface. Spans are not part of the key,
//! so editing one line leaves the other tasks' results in place.

use std::collections::hash_map::DefaultHasher;
use std::collections::HashMap;
use std::hash::{Hash, Hasher};

use rayon::prelude::*;

use crate::plugin::{Registry, TaskContext};
use crate::progress::Progress;
use crate::report::{Report, TaskReport, SCHEMA_VERSION};
use crate::scene::{MeshObstacle, Scenario, TaskSpec};

/// Results of earlier runs, by key.
#[derive(Default)]
pub struct TaskCache {
    results: HashMap<u64, TaskReport>,
}

/// How many tasks a cached run reused and how many it ran.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct CacheStats {
    pub reused: usize,
    pub ran: usize,
}

impl TaskCache {
    /// Run the scenario, reusing the results of tasks whose inputs have not
    /// changed; afterwards the cache holds exactly this run's results.
    pub fn run(
        &mut self,
        scenario: &Scenario,
        registry: &Registry,
        progress: &dyn Progress,
    ) -> (Report, CacheStats) {
        let keys: Vec<u64> = scenario.tasks.iter().map(|t| key(scenario, t)).collect();
        let fresh: Vec<Option<TaskReport>> = scenario
            .tasks
            .par_iter()
            .zip(&keys)
            .map(|(task, k)| {
                if self.results.contains_key(k) {
                    return None;
                }
                let plugin = registry
                    .task(&task.kind)
                    .expect("the checker resolved every task kind");
                Some(plugin.run(&TaskContext {
                    scenario,
                    task,
                    registry,
                    progress,
                }))
            })
            .collect();
        let ran = fresh.iter().filter(|r| r.is_some()).count();
        let tasks: Vec<TaskReport> = fresh
            .into_iter()
            .zip(&keys)
            .map(|(r, k)| r.unwrap_or_else(|| self.results[k].clone()))
            .collect();
        self.results = keys.iter().copied().zip(tasks.iter().cloned()).collect();
        let report = Report {
            schema: SCHEMA_VERSION,
            file: scenario.file.clone(),
            tasks,
        };
        (
            report,
            CacheStats {
                reused: keys.len() - ran,
                ran,
            },
        )
    }
}

/// A hash of what the task's result depends on (the Debug forms hold every
/// value; none of these types holds a span).
fn key(scenario: &Scenario, task: &TaskSpec) -> u64 {
    let mut h = DefaultHasher::new();
    (
        &task.kind,
        &task.subject,
        &task.person,
        format!("{:?}", task.options),
    )
        .hash(&mut h);
    if let Some(person) = scenario.person(&task.person) {
        format!("{person:?}").hash(&mut h);
    }
    // Of the room: its size, its obstacles (where bases fit), and the task's
    // own target or surface; not the other targets and surfaces.
    for room in scenario.rooms.iter().filter(|r| r.holds(&task.subject)) {
        let target = room.targets.iter().find(|t| t.name == task.subject);
        let surface = room.surface_named(&task.subject);
        format!("{:?}{:?}{target:?}{surface:?}", room.size_mm, room.boxes).hash(&mut h);
        hash_meshes(&room.meshes, &mut h);
    }
    h.finish()
}

/// The meshes' names, vertices (bit for bit) and triangles: a mesh moved in
/// the scenario or edited in its OBJ file changes the key.
fn hash_meshes(meshes: &[MeshObstacle], h: &mut DefaultHasher) {
    for mesh in meshes {
        mesh.name.hash(h);
        for v in &mesh.vertices_mm {
            (v.x.to_bits(), v.y.to_bits(), v.z.to_bits()).hash(h);
        }
        mesh.triangles.hash(h);
    }
}
