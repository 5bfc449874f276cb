//! Tasks: `KIND subjects by persons { options }`, one task per subject and
//! person, each configured by its task plugin and resolved: its room,
//! subject, person and effectors by index.

use std::sync::Arc;

use super::Checker;
use crate::error::{Error, ErrorKind};
use crate::plugin::{Base, PluginKind, Subject, SubjectKind, Task};
use crate::scenario::{SubjectRef, TaskSpec};
use crate::scene::{Person, Population, Room, FACES};
use crate::span::{Span, Spanned};
use crate::syntax::ast::TaskDecl;

/// A task's subject resolved: its room and the subject there.
type Resolved = (usize, SubjectRef);

/// Who a task may be by: the persons with their bases, and the
/// populations (whose people are among the persons).
struct People<'s> {
    persons: &'s [Person],
    bases: &'s [Arc<dyn Base>],
    populations: &'s [Population],
}

/// Whom a task is by: a person, or a population (and its first person).
struct Who {
    person: usize,
    population: Option<usize>,
}

impl Checker<'_> {
    pub(super) fn tasks(
        &mut self,
        rooms: &[Room],
        persons: &[Person],
        bases: &[Arc<dyn Base>],
        populations: &[Population],
    ) -> Vec<TaskSpec> {
        let decls = std::mem::take(&mut self.decls.tasks);
        self.built.target_index = rooms
            .iter()
            .enumerate()
            .flat_map(|(r, room)| {
                room.targets
                    .iter()
                    .enumerate()
                    .map(move |(t, target)| (target.name.clone(), (r, t)))
            })
            .collect();
        let mut out = Vec::new();
        for (decl, file) in decls {
            let by = People {
                persons,
                bases,
                populations,
            };
            if let Some(tasks) = self.in_file(file, |c| c.task(decl, rooms, &by)) {
                out.extend(tasks);
            }
        }
        out
    }

    fn task(&mut self, decl: &TaskDecl, rooms: &[Room], by: &People) -> Option<Vec<TaskSpec>> {
        let (persons, bases) = (by.persons, by.bases);
        let kind = &decl.kind;
        let Some(plugin) = self.cx.registry.task(&kind.value).cloned() else {
            let names = self.cx.registry.names(PluginKind::Task);
            self.error(Error::new(
                ErrorKind::UnknownPlugin {
                    kind: "task",
                    name: kind.value.clone(),
                    suggestion: self
                        .cx
                        .suggestions
                        .suggest(&kind.value, names.iter().copied()),
                    available: names.join(", "),
                },
                kind.span,
            ));
            return None;
        };
        let label = format!("task `{}`", kind.value);
        let options = self.options(&label, &plugin.params(), &decl.options, decl.span);
        let subjects: Vec<Option<Resolved>> = decl
            .subjects
            .iter()
            .map(|s| self.subject(plugin.subject(), s, rooms))
            .collect();
        let who: Vec<Option<Who>> = decl
            .persons
            .iter()
            .map(|p| self.person_ref(p, persons, by.populations))
            .collect();
        let options = options?;
        let subjects: Vec<Resolved> = subjects.into_iter().collect::<Option<_>>()?;
        let who: Vec<Who> = who.into_iter().collect::<Option<_>>()?;
        // A population's first person stands for all of them here: they
        // share a body's shape and a base.
        let people: Vec<usize> = who.iter().map(|w| w.person).collect();
        let task: Arc<dyn Task> = match plugin.configure(&options, self.cx.registry) {
            Ok(task) => Arc::from(task),
            Err(e) => {
                self.settings_error(&label, &e, &decl.options, decl.span);
                return None;
            }
        };
        self.check_bases_fit(decl, &subjects, &people, rooms, persons, bases);
        let effectors = self.task_effectors(task.as_ref(), decl, &people, persons);
        for ((room, subject), at) in subjects.iter().zip(&decl.subjects) {
            let spec = subject.in_room(&rooms[*room]);
            if let Some(kind) = task.validate(&spec) {
                self.error(Error::new(kind, at.span));
            }
            if let Some((option, message)) = task.validate_in(&spec, &rooms[*room]) {
                let span = option_span(decl, option);
                let plugin = label.clone();
                self.error(Error::new(ErrorKind::BadOption { plugin, message }, span));
            }
            self.carried(task.as_ref(), decl, &spec, &rooms[*room]);
        }
        let mut tasks = Vec::new();
        for (room, subject) in &subjects {
            for (who, effectors) in who.iter().zip(&effectors) {
                let Some(effectors) = effectors else { continue };
                tasks.push(TaskSpec {
                    kind: kind.value.clone(),
                    task: Arc::clone(&task),
                    room: *room,
                    subject: subject.clone(),
                    person: who.person,
                    population: who.population,
                    effectors: effectors.clone(),
                    options: options.clone(),
                    span: decl.span,
                });
            }
        }
        Some(tasks)
    }

    /// Whether each box or target the task carries with its subject is
    /// one of the subject's room, other than the subject; an error at the
    /// option's value where one is not.
    fn carried(&mut self, task: &dyn Task, decl: &TaskDecl, subject: &Subject<'_>, room: &Room) {
        let span = option_span(decl, "carries");
        for (k, name) in task.carried().iter().enumerate() {
            let is_box = room.boxes.iter().any(|b| &b.name == name);
            let is_target = room.targets.iter().any(|t| &t.name == name);
            let message = if name == subject.name() {
                format!("`{name}` is the target moved: `carries` names what moves with it")
            } else if task.carried()[..k].contains(name) {
                format!("`{name}` is carried twice")
            } else if room.meshes.iter().any(|m| &m.name == name) {
                format!("`{name}` is a mesh: only boxes and targets are carried")
            } else if is_box || is_target {
                continue;
            } else {
                let names = (room.boxes.iter().map(|b| b.name.as_str()))
                    .chain(room.targets.iter().map(|t| t.name.as_str()));
                let error = self.unknown("box or target", name, span, names);
                self.error(error);
                continue;
            };
            let plugin = format!("task `{}`", decl.kind.value);
            self.error(Error::new(ErrorKind::BadOption { plugin, message }, span));
        }
    }

    /// Each effector the task names, for each person: an index into the
    /// person's body, and a chain the task accepts. `None` for a person
    /// whose body lacks one (the error is reported).
    fn task_effectors(
        &mut self,
        task: &dyn Task,
        decl: &TaskDecl,
        people: &[usize],
        persons: &[Person],
    ) -> Vec<Option<Vec<usize>>> {
        let mut found: Vec<Option<Vec<usize>>> = vec![Some(Vec::new()); people.len()];
        for (need_index, need) in task.effectors().iter().enumerate() {
            let at = decl.options.iter().find(|o| o.name.value == need.option);
            for ((&person, name), slot) in people.iter().zip(&decl.persons).zip(&mut found) {
                let person = &persons[person];
                let index = match &need.name {
                    None => Some(0),
                    Some(effector) => person.body.effector_index(effector),
                };
                let Some(index) = index else {
                    // Where the file names the effector, or else at the person.
                    let span = at.map_or(name.span, |o| o.value_span);
                    self.no_effector(person, need.name.as_deref().unwrap_or_default(), span);
                    *slot = None;
                    continue;
                };
                let chain = person.body.chain(index);
                if let Some(kind) = task.validate_chain(&person.name, need_index, &chain) {
                    self.error(Error::new(kind, name.span));
                }
                if let Some(indices) = slot {
                    indices.push(index);
                }
            }
        }
        found
    }

    fn no_effector(&mut self, person: &Person, effector: &str, span: Span) {
        let names: Vec<&str> = person
            .body
            .effectors
            .iter()
            .map(|e| e.name.as_str())
            .collect();
        self.error(Error::new(
            ErrorKind::NoEffector {
                person: person.name.clone(),
                mannequin: person.mannequin.clone(),
                effector: effector.to_string(),
                available: names.join(", "),
            },
            span,
        ));
    }

    /// Each person's base must be placed inside the room of each subject
    /// (a mobile base that fits nowhere is an answer of the run, not a
    /// mistake in the input).
    fn check_bases_fit(
        &mut self,
        decl: &TaskDecl,
        subjects: &[Resolved],
        people: &[usize],
        rooms: &[Room],
        persons: &[Person],
        bases: &[Arc<dyn Base>],
    ) {
        for (&person, name_decl) in people.iter().zip(&decl.persons) {
            let mut checked: Vec<usize> = Vec::new();
            for (room, _) in subjects {
                if checked.contains(room) {
                    continue;
                }
                checked.push(*room);
                if bases[person].outside(&rooms[*room]) {
                    self.error(Error::new(
                        ErrorKind::BaseOutsideRoom {
                            person: persons[person].name.clone(),
                            base: persons[person].base.name.clone(),
                            room: rooms[*room].name.clone(),
                        },
                        name_decl.span,
                    ));
                }
            }
        }
    }

    fn subject(
        &mut self,
        kind: SubjectKind,
        s: &Spanned<Vec<String>>,
        rooms: &[Room],
    ) -> Option<Resolved> {
        match kind {
            SubjectKind::Target => self.target_subject(s, rooms),
            SubjectKind::Surface => self.surface_subject(s, rooms),
        }
    }

    fn target_subject(&mut self, s: &Spanned<Vec<String>>, rooms: &[Room]) -> Option<Resolved> {
        let name = s.value.join(".");
        if let Some(&(r, t)) = self.built.target_index.get(&name) {
            return Some((r, SubjectRef::Target(t)));
        }
        let targets = rooms
            .iter()
            .flat_map(|r| r.targets.iter().map(|t| t.name.as_str()));
        // A target whose room failed to check has reported its own errors.
        let declared = self
            .decls
            .rooms
            .iter()
            .flat_map(|(_, d, _)| d.items.iter())
            .any(|i| matches!(i, crate::syntax::ast::RoomItem::Target(t) if t.name.value == name));
        if !declared {
            self.error(self.unknown("target", &name, s.span, targets));
        }
        None
    }

    /// `surface` or `box.face`.
    /// A name in two rooms is ambiguous: `room.surface` or `room.box.face`
    /// picks one.
    fn surface_subject(&mut self, s: &Spanned<Vec<String>>, rooms: &[Room]) -> Option<Resolved> {
        let in_named_room = match s.value.split_first() {
            Some((room, rest)) if !rest.is_empty() => rooms
                .iter()
                .position(|r| &r.name == room)
                .and_then(|r| Some((r, SubjectRef::Surface(rooms[r].surface(rest)?)))),
            _ => None,
        };
        if in_named_room.is_some() {
            return in_named_room;
        }
        let found: Vec<(usize, SubjectRef)> = rooms
            .iter()
            .enumerate()
            .filter_map(|(r, room)| Some((r, SubjectRef::Surface(room.surface(&s.value)?))))
            .collect();
        match found.as_slice() {
            [one] => return Some(one.clone()),
            [_, _, ..] => {
                let names: Vec<String> =
                    found.iter().map(|(r, _)| rooms[*r].name.clone()).collect();
                self.error(Error::new(
                    ErrorKind::AmbiguousSurface {
                        name: s.value.join("."),
                        rooms: names,
                    },
                    s.span,
                ));
                return None;
            }
            [] => {}
        }
        if s.value
            .iter()
            .any(|part| self.failed_face_holder(part, rooms))
        {
            // Its declaration has reported its own error.
            return None;
        }
        let is_box = |name: &String| {
            rooms
                .iter()
                .any(|r| r.boxes.iter().any(|b| &b.name == name))
        };
        let (what, wrong, candidates): (&'static str, &str, Vec<String>) = match s.value.as_slice()
        {
            [box_name, face] if is_box(box_name) => (
                "face",
                face.as_str(),
                FACES.iter().map(|f| f.to_string()).collect(),
            ),
            [first, ..] => {
                let surfaces = rooms
                    .iter()
                    .flat_map(|r| r.surfaces.iter().map(|s| s.name.clone()));
                let boxes = rooms
                    .iter()
                    .flat_map(|r| r.boxes.iter().map(|b| b.name.clone()));
                (
                    "surface or box",
                    first.as_str(),
                    surfaces.chain(boxes).collect(),
                )
            }
            [] => return None,
        };
        self.error(self.unknown(what, wrong, s.span, candidates.iter().map(String::as_str)));
        None
    }

    fn person_ref(
        &mut self,
        name: &crate::span::Name,
        persons: &[Person],
        populations: &[Population],
    ) -> Option<Who> {
        if let Some(i) = persons.iter().position(|p| p.name == name.value) {
            return Some(Who {
                person: i,
                population: None,
            });
        }
        if let Some(i) = populations.iter().position(|p| p.name == name.value) {
            return Some(Who {
                person: populations[i].members.start,
                population: Some(i),
            });
        }
        // A population that failed to build has reported its own errors.
        let declared = self.decls.persons.get(&name.value).is_some()
            || self.decls.populations.get(&name.value).is_some();
        if declared {
            return None;
        }
        if self.decls.populations.names().next().is_none() {
            if let Err(e) = self.decls.persons.resolve(name, self.cx.suggestions) {
                self.error(e);
            }
            return None;
        }
        let known = self
            .decls
            .persons
            .names()
            .chain(self.decls.populations.names());
        self.error(self.unknown("person or population", &name.value, name.span, known));
        None
    }

    /// Whether `name` is a surface, box or mesh some room declares that was
    /// not built (its declaration failed, and said why).
    fn failed_face_holder(&self, name: &str, rooms: &[Room]) -> bool {
        use crate::syntax::ast::RoomItem;
        let built = rooms.iter().any(|r| {
            r.surfaces.iter().any(|s| s.name == name)
                || r.boxes.iter().any(|b| b.name == name)
                || r.meshes.iter().any(|m| m.name == name)
        });
        let declared = (self.decls.rooms.iter())
            .flat_map(|(_, d, _)| d.items.iter())
            .any(|i| match i {
                RoomItem::Surface(s) => s.name.value == name,
                RoomItem::Box(b) => b.name.value == name,
                RoomItem::Mesh(m) => m.name.value == name,
                _ => false,
            });
        declared && !built
    }
}

/// Where option `name` of `decl` is written: its value, or the task where
/// it is not given.
fn option_span(decl: &TaskDecl, name: &str) -> Span {
    (decl.options.iter())
        .find(|o| o.name.value == name)
        .map_or(decl.span, |o| o.value_span)
}
