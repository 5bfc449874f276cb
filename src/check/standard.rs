//! `standard NAME [in ROOM] { options }`: a building standard's rules
//! checked on one room, or on every room without `in`: the plugin by name
//! (with the nearest names when it is unknown), its options validated
//! against its declared parameters, the room resolved, and the targets
//! `except` names (not elements) resolved in it.

use std::sync::Arc;

use super::Checker;
use crate::error::{Error, ErrorKind};
use crate::plugin::{PluginKind, Standard};
use crate::scenario::StandardSpec;
use crate::scene::Room;
use crate::syntax::ast::StandardDecl;

impl Checker<'_> {
    pub(super) fn standards(&mut self, rooms: &[Room]) -> Vec<StandardSpec> {
        let decls = std::mem::take(&mut self.decls.standards);
        let mut out = Vec::new();
        for (decl, file) in decls {
            if let Some(specs) = self.in_file(file, |c| c.standard(decl, rooms)) {
                out.extend(specs);
            }
        }
        out
    }

    fn standard(&mut self, decl: &StandardDecl, rooms: &[Room]) -> Option<Vec<StandardSpec>> {
        let name = &decl.name;
        let Some(plugin) = self.cx.registry.standard(&name.value).cloned() else {
            let names = self.cx.registry.names(PluginKind::Standard);
            self.error(Error::new(
                ErrorKind::UnknownPlugin {
                    kind: "standard",
                    name: name.value.clone(),
                    suggestion: self
                        .cx
                        .suggestions
                        .suggest(&name.value, names.iter().copied()),
                    available: names.join(", "),
                },
                name.span,
            ));
            return None;
        };
        let label = format!("standard `{}`", name.value);
        let options = self.options(&label, &plugin.params(), &decl.options, decl.span);
        let checked: Vec<usize> = match &decl.room {
            Some(room) => match rooms.iter().position(|r| r.name == room.value) {
                Some(i) => vec![i],
                None => {
                    let names = rooms.iter().map(|r| r.name.as_str());
                    self.error(self.unknown("room", &room.value, room.span, names));
                    return None;
                }
            },
            None => (0..rooms.len()).collect(),
        };
        let except = self.except(decl, rooms, &checked)?;
        let options = options?;
        let standard: Arc<dyn Standard> = match plugin.configure(&options) {
            Ok(s) => Arc::from(s),
            Err(e) => {
                self.settings_error(&label, &e, &decl.options, decl.span);
                return None;
            }
        };
        if !self.boxes_named(decl, standard.as_ref(), rooms, &checked) {
            return None;
        }
        Some(
            checked
                .into_iter()
                .map(|room| StandardSpec {
                    name: name.value.clone(),
                    standard: Arc::clone(&standard),
                    room,
                    except: except.clone(),
                    options: options.clone(),
                    span: decl.span,
                })
                .collect(),
        )
    }

    /// Whether each box the standard's options name is a box of every
    /// room checked; an error at the option's value where one is not.
    fn boxes_named(
        &mut self,
        decl: &StandardDecl,
        standard: &dyn Standard,
        rooms: &[Room],
        checked: &[usize],
    ) -> bool {
        let mut ok = true;
        let mut seen: Vec<(&'static str, String)> = Vec::new();
        for (option, name) in standard.boxes_named() {
            let span = (decl.options.iter())
                .find(|o| o.name.value == option)
                .map_or(decl.span, |o| o.value_span);
            if let Some((first, _)) = seen.iter().find(|(_, n)| *n == name) {
                let what = format!("box `{name}` as a fixture (by `{first}` and `{option}`)");
                self.error(Error::new(ErrorKind::Repeated { what }, span));
                ok = false;
                continue;
            }
            seen.push((option, name.clone()));
            let Some(&missing) = checked
                .iter()
                .find(|&&r| !rooms[r].boxes.iter().any(|b| b.name == name))
            else {
                continue;
            };
            let elsewhere = (rooms.iter().enumerate())
                .find(|(k, r)| *k != missing && r.boxes.iter().any(|b| b.name == name))
                .map(|(_, r)| r.name.clone());
            if let (Some(home), None) = (&elsewhere, &decl.room) {
                let error = ErrorKind::FixtureNotInEveryRoom {
                    name: name.clone(),
                    room: rooms[missing].name.clone(),
                    home: home.clone(),
                };
                self.error(Error::new(error, span));
                ok = false;
                continue;
            }
            let is = elsewhere.map(|home| format!("a box of room `{home}`"));
            let error = match is
                .or_else(|| what_else(&name, rooms, &[missing]))
                .or_else(|| {
                    (rooms[missing].targets.iter().any(|t| t.name == name))
                        .then(|| "a target".to_string())
                }) {
                // Never "a box": the box is missing from this room.
                Some(is) => Error::new(
                    ErrorKind::NotAFixture {
                        name: name.clone(),
                        is,
                        option,
                    },
                    span,
                ),
                None => {
                    let boxes = rooms[missing].boxes.iter().map(|b| b.name.as_str());
                    self.unknown("box", &name, span, boxes)
                }
            };
            self.error(error);
            ok = false;
        }
        ok
    }

    /// The names of `except`: each a target of a room checked (of one of
    /// them without `in`), named once.
    fn except(
        &mut self,
        decl: &StandardDecl,
        rooms: &[Room],
        checked: &[usize],
    ) -> Option<Vec<String>> {
        let mut names: Vec<String> = Vec::new();
        let mut ok = true;
        for name in &decl.except {
            let targets = || {
                (checked.iter())
                    .flat_map(|&r| rooms[r].targets.iter())
                    .map(|t| t.name.as_str())
            };
            if names.contains(&name.value) {
                let what = format!("`{}` in `except`", name.value);
                self.error(Error::new(ErrorKind::Repeated { what }, name.span));
                ok = false;
            } else if targets().any(|t| t == name.value) {
                names.push(name.value.clone());
            } else {
                let error = match what_else(&name.value, rooms, checked) {
                    Some(is) => Error::new(
                        ErrorKind::NotAnElement {
                            name: name.value.clone(),
                            is,
                        },
                        name.span,
                    ),
                    None => self.unknown("target", &name.value, name.span, targets()),
                };
                self.error(error);
                ok = false;
            }
        }
        ok.then_some(names)
    }
}

/// What `name` is, if not a target of the rooms `checked`: a box, mesh,
/// surface or door of one of them, or a target of another room.
fn what_else(name: &str, rooms: &[Room], checked: &[usize]) -> Option<String> {
    let here = || checked.iter().map(|&r| &rooms[r]);
    let kind = here().find_map(|r| {
        if r.boxes.iter().any(|b| b.name == name) {
            Some("a box")
        } else if r.meshes.iter().any(|m| m.name == name) {
            Some("a mesh")
        } else if r.surfaces.iter().any(|s| s.name == name) {
            Some("a surface")
        } else if r.doors.iter().any(|d| d.name == name) {
            Some("a door")
        } else {
            None
        }
    });
    kind.map(str::to_string).or_else(|| {
        (rooms.iter().enumerate())
            .find(|(k, r)| !checked.contains(k) && r.targets.iter().any(|t| t.name == name))
            .map(|(_, r)| format!("a target of room `{}`", r.name))
    })
}
