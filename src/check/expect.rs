//! `expect` statements: each resolved to the report entries it is about
//! (the tasks by that person or population about that target or surface,
//! or the standard on that room), with names checked like every other
//! statement's (did-you-mean), and an expectation nothing answers refused
//! with the task to add.

use super::Checker;
use crate::error::{Error, ErrorKind};
use crate::scenario::{ExpectCheck, ExpectSpec, StandardSpec, TaskSpec};
use crate::scene::{Person, Population, Room};
use crate::span::{Name, Spanned};
use crate::syntax::ast::{Bound, Claim, Comparison, ExpectDecl, Expr, Verb};

/// What an expectation is checked against.
pub(super) struct Answered<'s> {
    pub rooms: &'s [Room],
    pub persons: &'s [Person],
    pub populations: &'s [Population],
    pub tasks: &'s [TaskSpec],
    pub standards: &'s [StandardSpec],
}

impl Checker<'_> {
    pub(super) fn expectations(&mut self, answered: &Answered<'_>) -> Vec<ExpectSpec> {
        let decls = std::mem::take(&mut self.decls.expects);
        let mut out = Vec::new();
        for (decl, file) in decls {
            if let Some(spec) = self.in_file(file, |c| c.expectation(decl, answered)) {
                out.push(spec);
            }
        }
        out
    }

    fn expectation(&mut self, decl: &ExpectDecl, a: &Answered<'_>) -> Option<ExpectSpec> {
        let check = match &decl.claim {
            Claim::Person {
                who,
                negated,
                verb,
                subject,
                bound,
            } => self.person_claim(decl, who, *negated, verb, subject, bound.as_ref(), a)?,
            Claim::Share {
                population,
                subject,
                task,
                bound,
            } => self.share_claim(decl, population, subject, task.as_ref(), bound, a)?,
            Claim::Meets { room, standard } => self.meets_claim(decl, room, standard, a)?,
            Claim::Advice {
                subject,
                share,
                from,
                to,
            } => self.advice_claim(decl, subject, share, [from, to], a)?,
        };
        let source = self.cx.sources.get(decl.span.file);
        let line = source
            .line_starts()
            .partition_point(|&start| start <= decl.span.start as usize);
        Some(ExpectSpec {
            text: decl.text.clone(),
            at: format!("{}:{line}", source.name),
            check,
            span: decl.span,
        })
    }

    #[allow(clippy::too_many_arguments)]
    fn person_claim(
        &mut self,
        decl: &ExpectDecl,
        who: &Name,
        negated: bool,
        verb: &Spanned<Verb>,
        subject: &Spanned<Vec<String>>,
        bound: Option<&Bound>,
        a: &Answered<'_>,
    ) -> Option<ExpectCheck> {
        let population = a.populations.iter().position(|p| p.name == who.value);
        let person = a
            .persons
            .iter()
            .position(|p| p.name == who.value && population.is_none());
        // A person or population that failed to check has reported its
        // own errors.
        let declared = self.decls.persons.get(&who.value).is_some()
            || self.decls.populations.get(&who.value).is_some();
        if person.is_none() && population.is_none() && declared {
            return None;
        }
        if person.is_none() && population.is_none() {
            let names = a
                .persons
                .iter()
                .map(|p| p.name.as_str())
                .chain(a.populations.iter().map(|p| p.name.as_str()));
            self.error(self.unknown("person or population", &who.value, who.span, names));
            return None;
        }
        self.known_subject(subject, a)?;
        let name = subject.value.join(".");
        if population.is_some() && verb.value != Verb::Covers {
            self.error(Error::new(
                ErrorKind::BadExpectation {
                    what: format!("`{}` is a population: a share is expected of it, not whether it reaches or sees", who.value),
                    help: format!("write `expect share({}, {name}) >= 90 %`", who.value),
                },
                who.span,
            ));
            return None;
        }
        if let (true, Some(bound)) = (negated, bound) {
            self.not_with_bound(decl, bound.comparison.value);
            return None;
        }
        let kinds: &[&str] = match verb.value {
            Verb::Reaches => &["reach", "reach_and_gaze"],
            Verb::Sees => &["gaze", "reach_and_gaze"],
            Verb::Covers => &["map", "gaze_map"],
        };
        let entries: Vec<usize> = (a.tasks.iter().enumerate())
            .filter(|(_, t)| kinds.contains(&t.kind.as_str()))
            .filter(|(_, t)| match population {
                Some(p) => t.population == Some(p),
                None => t.population.is_none() && a.persons[t.person].name == who.value,
            })
            .filter(|(_, t)| t.subject_in(&a.rooms[t.room]).name() == name)
            .map(|(k, _)| k)
            .collect();
        if entries.is_empty() {
            let task = match verb.value {
                Verb::Reaches => "reach",
                Verb::Sees => "gaze",
                Verb::Covers => "map",
            };
            self.nothing_answers(decl, &format!("add `{task} {name} by {}`", who.value));
            return None;
        }
        match (verb.value, bound) {
            (Verb::Covers, Some(bound)) => {
                let (comparison, bound) = self.bound(bound)?;
                Some(ExpectCheck::Covers {
                    entries,
                    comparison,
                    bound,
                })
            }
            (Verb::Covers, None) => {
                self.error(Error::new(
                    ErrorKind::BadExpectation {
                        what: "how much a map must cover is not given".into(),
                        help: format!("write `expect {} covers {name} >= 80 %`", who.value),
                    },
                    verb.span,
                ));
                None
            }
            (_, Some(bound)) => {
                self.error(Error::new(
                    ErrorKind::BadExpectation {
                        what: "a bound is for `covers` and `share`".into(),
                        help: "a reach or a sight holds or not: leave the bound out".into(),
                    },
                    bound.comparison.span.to(bound.value.span),
                ));
                None
            }
            (verb, None) => Some(ExpectCheck::Answers {
                entries,
                sees: verb == Verb::Sees,
                wanted: !negated,
            }),
        }
    }

    fn share_claim(
        &mut self,
        decl: &ExpectDecl,
        population: &Name,
        subject: &Spanned<Vec<String>>,
        task: Option<&Name>,
        bound: &Bound,
        a: &Answered<'_>,
    ) -> Option<ExpectCheck> {
        let Some(p) = a
            .populations
            .iter()
            .position(|x| x.name == population.value)
        else {
            if self.decls.populations.get(&population.value).is_some() {
                return None;
            }
            if a.persons.iter().any(|x| x.name == population.value) {
                self.error(Error::new(
                    ErrorKind::BadExpectation {
                        what: format!(
                            "`{}` is a person: a share is of a population",
                            population.value
                        ),
                        help: format!(
                            "write `expect {} reaches {}`",
                            population.value,
                            subject.value.join(".")
                        ),
                    },
                    population.span,
                ));
                return None;
            }
            let names = a.populations.iter().map(|x| x.name.as_str());
            self.error(self.unknown("population", &population.value, population.span, names));
            return None;
        };
        self.known_subject(subject, a)?;
        let (comparison, bound) = self.bound(bound)?;
        let name = subject.value.join(".");
        let about: Vec<(usize, &TaskSpec)> = (a.tasks.iter().enumerate())
            .filter(|(_, t)| t.population == Some(p))
            .filter(|(_, t)| t.subject_in(&a.rooms[t.room]).name() == name)
            .collect();
        let mut kinds: Vec<&str> = about.iter().map(|(_, t)| t.kind.as_str()).collect();
        kinds.sort_unstable();
        kinds.dedup();
        let entries: Vec<usize> = match task {
            Some(kind) => about
                .iter()
                .filter(|(_, t)| t.kind == kind.value)
                .map(|&(k, _)| k)
                .collect(),
            None if kinds.len() > 1 => {
                self.error(Error::new(
                    ErrorKind::BadExpectation {
                        what: format!(
                            "`{}` has {} tasks about `{name}`: which share?",
                            population.value,
                            kinds.join(" and ")
                        ),
                        help: format!(
                            "name the task: `expect share({}, {name}, {}) ...`",
                            population.value, kinds[0]
                        ),
                    },
                    subject.span,
                ));
                return None;
            }
            None => about.iter().map(|&(k, _)| k).collect(),
        };
        if entries.is_empty() {
            let kind = task.map_or("reach", |t| t.value.as_str());
            self.nothing_answers(
                decl,
                &format!("add `{kind} {name} by {}`", population.value),
            );
            return None;
        }
        Some(ExpectCheck::Share {
            entries,
            comparison,
            bound,
        })
    }

    /// Every advice about the subject, by whomever.
    fn advice_claim(
        &mut self,
        decl: &ExpectDecl,
        subject: &Spanned<Vec<String>>,
        share: &Expr,
        [from, to]: [&Expr; 2],
        a: &Answered<'_>,
    ) -> Option<ExpectCheck> {
        self.known_subject(subject, a)?;
        let share = self.share(share, "an advice's share");
        let (from_mm, to_mm) = (self.length(from), self.length(to));
        let (share, from_mm, to_mm) = (share?, from_mm?, to_mm?);
        if to_mm < from_mm {
            self.error(Error::new(
                ErrorKind::BadExpectation {
                    what: format!("{to_mm} mm is below {from_mm} mm"),
                    help: "write the lower position first".into(),
                },
                to.span,
            ));
            return None;
        }
        let name = subject.value.join(".");
        let entries: Vec<usize> = (a.tasks.iter().enumerate())
            .filter(|(_, t)| t.kind == "advise" && t.subject_in(&a.rooms[t.room]).name() == name)
            .map(|(k, _)| k)
            .collect();
        if entries.is_empty() {
            self.nothing_answers(
                decl,
                &format!("add `advise {name} by ... {{ from ... to ... }}`"),
            );
            return None;
        }
        // Positions along two axes are not one range.
        let along = |k: usize| {
            (a.tasks[k].options.iter())
                .find(|(n, _)| *n == "along")
                .map(|(_, v)| v.display())
        };
        let mut axes: Vec<String> = entries.iter().filter_map(|&k| along(k)).collect();
        axes.sort();
        axes.dedup();
        if axes.len() > 1 {
            self.error(Error::new(
                ErrorKind::BadExpectation {
                    what: format!(
                        "`{name}` is advised along {}: which positions?",
                        axes.join(" and ")
                    ),
                    help: "pin one axis per target: advise the other with a target of its own"
                        .into(),
                },
                subject.span,
            ));
            return None;
        }
        Some(ExpectCheck::Serves {
            entries,
            share,
            from_mm,
            to_mm,
        })
    }

    fn meets_claim(
        &mut self,
        decl: &ExpectDecl,
        room: &Name,
        standard: &Name,
        a: &Answered<'_>,
    ) -> Option<ExpectCheck> {
        let Some(r) = a.rooms.iter().position(|x| x.name == room.value) else {
            if self
                .decls
                .rooms
                .iter()
                .any(|(_, d, _)| d.name.value == room.value)
            {
                return None;
            }
            let names = a.rooms.iter().map(|x| x.name.as_str());
            self.error(self.unknown("room", &room.value, room.span, names));
            return None;
        };
        let entries: Vec<usize> = (a.standards.iter().enumerate())
            .filter(|(_, s)| s.room == r && s.name == standard.value)
            .map(|(k, _)| a.tasks.len() + k)
            .collect();
        if entries.is_empty() {
            self.nothing_answers(
                decl,
                &format!("add `standard {} in {}`", standard.value, room.value),
            );
            return None;
        }
        Some(ExpectCheck::Meets { entries })
    }

    /// A target or surface of that name in some room (else an error with
    /// the nearest names).
    fn known_subject(&mut self, subject: &Spanned<Vec<String>>, a: &Answered<'_>) -> Option<()> {
        let name = subject.value.join(".");
        let targets = a
            .rooms
            .iter()
            .flat_map(|r| r.targets.iter().map(|t| t.name.clone()));
        let surfaces = a
            .rooms
            .iter()
            .flat_map(|r| r.surfaces.iter().map(|s| s.name.clone()));
        let mapped = a
            .tasks
            .iter()
            .map(|t| t.subject_in(&a.rooms[t.room]).name().to_string());
        let names: Vec<String> = targets.chain(surfaces).chain(mapped).collect();
        let a_face = a.rooms.iter().any(|r| r.surface(&subject.value).is_some());
        if names.contains(&name) || a_face {
            return Some(());
        }
        // A target or surface of a room that failed to check: that room
        // has reported its own errors.
        let failed_room_declares = (self.decls.rooms.iter())
            .filter(|(_, d, _)| a.rooms.iter().all(|r| r.name != d.name.value))
            .any(|(_, d, _)| d.items.iter().any(|i| declares(i, &name)));
        if failed_room_declares {
            return None;
        }
        self.error(self.unknown(
            "target or surface",
            &name,
            subject.span,
            names.iter().map(String::as_str),
        ));
        None
    }

    /// A bound's comparison and value, a share from 0 to 1 (`80 %`).
    fn bound(&mut self, bound: &Bound) -> Option<(Comparison, f64)> {
        let value = self.share(&bound.value, "an expectation's bound")?;
        Some((bound.comparison.value, value))
    }

    fn nothing_answers(&mut self, decl: &ExpectDecl, hint: &str) {
        self.error(Error::new(
            ErrorKind::NothingToExpect {
                claim: decl.text.clone(),
                hint: hint.to_string(),
            },
            decl.span,
        ));
    }

    fn not_with_bound(&mut self, decl: &ExpectDecl, comparison: Comparison) {
        let turned = decl.text.replacen(" not ", " ", 1).replacen(
            comparison.symbol(),
            comparison.opposite().symbol(),
            1,
        );
        self.error(Error::new(
            ErrorKind::BadExpectation {
                what: "`not` and a bound together".into(),
                help: format!("turn the comparison round instead: `expect {turned}`"),
            },
            decl.span,
        ));
    }
}

/// Whether a room item declares a target, surface or box of that name (a
/// box's faces are surfaces: `counter.top`).
fn declares(item: &crate::syntax::ast::RoomItem, name: &str) -> bool {
    use crate::syntax::ast::RoomItem;
    let box_name = name.split('.').next().unwrap_or(name);
    match item {
        RoomItem::Target(t) => t.name.value == name,
        RoomItem::Surface(s) => s.name.value == name,
        RoomItem::Box(b) => b.name.value == box_name,
        RoomItem::Mesh(m) => m.name.value == box_name,
        _ => false,
    }
}
