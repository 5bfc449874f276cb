//! Tasks: `KIND subjects by persons { options }`, one task per subject and
//! person, each validated against its task plugin.

use super::Checker;
use crate::error::{Error, ErrorKind};
use crate::names::suggest;
use crate::plugin::{Options, PluginKind, SubjectKind, TaskPlugin, Value};
use crate::scene::{Person, Room, TaskSpec, FACES};
use crate::span::Spanned;
use crate::syntax::ast::TaskDecl;

impl Checker<'_> {
    pub(super) fn tasks(&mut self, rooms: &[Room], persons: &[Person]) -> Vec<TaskSpec> {
        let decls = std::mem::take(&mut self.tasks);
        let mut out = Vec::new();
        for (decl, file) in decls {
            if let Some(tasks) = self.in_file(file, |c| c.task(decl, rooms, persons)) {
                out.extend(tasks);
            }
        }
        out
    }

    fn task(
        &mut self,
        decl: &TaskDecl,
        rooms: &[Room],
        persons: &[Person],
    ) -> Option<Vec<TaskSpec>> {
        let kind = &decl.kind;
        let Some(plugin) = self.registry.task(&kind.value).cloned() else {
            let names = self.registry.names(PluginKind::Task);
            self.error(Error::new(
                ErrorKind::UnknownPlugin {
                    kind: "task",
                    name: kind.value.clone(),
                    suggestion: suggest(&kind.value, names.iter().copied()),
                    available: names.join(", "),
                },
                kind.span,
            ));
            return None;
        };
        let label = format!("task `{}`", kind.value);
        let options = self.options(&label, &plugin.params(), &decl.options, decl.span);
        let subjects: Vec<Option<String>> = decl
            .subjects
            .iter()
            .map(|s| self.subject(plugin.subject(), s, rooms))
            .collect();
        let people: Vec<Option<String>> = decl
            .persons
            .iter()
            .map(|p| self.person_ref(p, persons))
            .collect();
        let options = options?;
        let subjects: Vec<String> = subjects.into_iter().collect::<Option<_>>()?;
        let people: Vec<String> = people.into_iter().collect::<Option<_>>()?;
        self.check_bases_fit(decl, &subjects, &people, rooms, persons);
        self.check_effector(plugin.as_ref(), decl, &options, &people, persons);
        for (subject, at) in subjects.iter().zip(&decl.subjects) {
            let room = rooms.iter().find(|r| r.holds(subject));
            if let Some(kind) = room.and_then(|r| plugin.validate(r, subject, &options)) {
                self.error(Error::new(kind, at.span));
            }
        }
        let mut tasks = Vec::new();
        for subject in &subjects {
            for person in &people {
                tasks.push(TaskSpec {
                    kind: kind.value.clone(),
                    subject: subject.clone(),
                    person: person.clone(),
                    options: options.clone(),
                    span: decl.span,
                });
            }
        }
        Some(tasks)
    }

    /// Each option naming an effector must name one of every person's
    /// body, and the task must accept each person's chain to it.
    fn check_effector(
        &mut self,
        plugin: &dyn TaskPlugin,
        decl: &TaskDecl,
        options: &Options,
        people: &[String],
        persons: &[Person],
    ) {
        for option in plugin.effector_options() {
            let effector = match options.get(option) {
                Some(Value::Name(e)) => Some(e.as_str()),
                _ => None,
            };
            let at = decl.options.iter().find(|o| o.name.value == *option);
            for (person, name) in people.iter().zip(&decl.persons) {
                let Some(person) = persons.iter().find(|p| &p.name == person) else {
                    continue;
                };
                let Some(chain) = person.chain_for(effector) else {
                    // Where the file names the effector, or else at the person.
                    let span = at.map_or(name.span, |o| o.value_span);
                    self.no_effector(person, effector.unwrap_or_default(), span);
                    continue;
                };
                if let Some(kind) = plugin.validate_chain(&person.name, option, &chain, options) {
                    self.error(Error::new(kind, name.span));
                }
            }
        }
    }

    fn no_effector(&mut self, person: &Person, effector: &str, span: crate::span::Span) {
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

    /// Each person's base must fit somewhere in the room of each target.
    fn check_bases_fit(
        &mut self,
        decl: &TaskDecl,
        subjects: &[String],
        people: &[String],
        rooms: &[Room],
        persons: &[Person],
    ) {
        for (name, name_decl) in people.iter().zip(&decl.persons) {
            let Some(person) = persons.iter().find(|p| &p.name == name) else {
                continue;
            };
            let Some(plugin) = self.registry.base(&person.base.name).cloned() else {
                continue;
            };
            let base = plugin.build(&person.base.options);
            let mut checked: Vec<&str> = Vec::new();
            for subject in subjects {
                let Some(room) = rooms.iter().find(|r| r.holds(subject)) else {
                    continue;
                };
                if checked.contains(&room.name.as_str()) {
                    continue;
                }
                checked.push(&room.name);
                if !base.fits(room) {
                    self.error(Error::new(
                        ErrorKind::FitsNowhere {
                            person: name.clone(),
                            base: person.base.name.clone(),
                            room: room.name.clone(),
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
    ) -> Option<String> {
        match kind {
            SubjectKind::Target => self.target_subject(s, rooms),
            SubjectKind::Surface => self.surface_subject(s, rooms),
        }
    }

    fn target_subject(&mut self, s: &Spanned<Vec<String>>, rooms: &[Room]) -> Option<String> {
        let name = s.value.join(".");
        let targets = || {
            rooms
                .iter()
                .flat_map(|r| r.targets.iter().map(|t| t.name.as_str()))
        };
        if targets().any(|t| t == name) {
            return Some(name);
        }
        // A target whose room failed to check has reported its own errors.
        let declared =
            self.rooms.iter().flat_map(|(_, d, _)| d.items.iter()).any(
                |i| matches!(i, crate::syntax::ast::RoomItem::Target(t) if t.name.value == name),
            );
        if !declared {
            self.error(Error::new(
                ErrorKind::UnknownName {
                    what: "target",
                    name: name.clone(),
                    suggestion: suggest(&name, targets()),
                },
                s.span,
            ));
        }
        None
    }

    /// `surface` or `box.face`.
    fn surface_subject(&mut self, s: &Spanned<Vec<String>>, rooms: &[Room]) -> Option<String> {
        if rooms.iter().any(|r| r.surface(&s.value).is_some()) {
            return Some(s.value.join("."));
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
        self.error(Error::new(
            ErrorKind::UnknownName {
                what,
                name: wrong.to_string(),
                suggestion: suggest(wrong, candidates.iter().map(String::as_str)),
            },
            s.span,
        ));
        None
    }

    fn person_ref(&mut self, name: &crate::span::Name, persons: &[Person]) -> Option<String> {
        if persons.iter().any(|p| p.name == name.value) {
            return Some(name.value.clone());
        }
        if self.persons.get(&name.value).is_none() {
            if let Err(e) = self.persons.resolve(name) {
                self.error(e);
            }
        }
        None
    }
}
