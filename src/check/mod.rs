//! The semantic pass: from the syntax trees of the loaded files to a
//! [`Scenario`]. Resolves every name, evaluates every expression with unit
//! checking, validates every plugin option block against the plugin's
//! declared parameters and builds the plugin from it, and reports every
//! error it finds, not just the first.

mod budget;
mod eval;
mod expect;
mod legs;
mod limits;
mod mannequin;
mod mesh;
mod options;
mod person;
mod population;
mod room;
mod standard;
mod table;
mod task;
mod urdf;

use std::collections::HashMap;
use std::path::PathBuf;

use crate::error::{Diagnostics, Error, ErrorKind};
use crate::kinematics::Body;
use crate::limits::Limits;
use crate::loader::LoadedFile;
use crate::names::Suggestions;
use crate::plugin::Registry;
use crate::scenario::{PeopleBuilt, Scenario, WorkBound};
use crate::source::Sources;
use crate::span::{FileId, Span, Spanned};
use crate::syntax::ast::{Item, LetDecl};
use crate::units::{Quantity, Unit, UnitDefaults};
use mesh::MeshFiles;

pub use limits::params as limits_params;
use table::Table;

/// Check the loaded files (dependencies first, the root file last); also
/// the data files (meshes, URDFs) the scenario names, read or not.
pub fn check(
    sources: &Sources,
    files: &[LoadedFile],
    registry: &Registry,
    (limits, built): (&Limits, PeopleBuilt),
    suggestions: &Suggestions,
) -> (Vec<PathBuf>, Result<Scenario, Diagnostics>) {
    let root = files.last().map(|f| f.id).unwrap_or_default();
    let mut c = Checker::new(registry, sources, *limits, suggestions);
    c.cx.built = built;
    for f in files {
        let defaults = c.file_defaults(&f.ast.items);
        c.cx.defaults_of.insert(f.id, defaults);
        c.collect(f, f.id == root);
    }
    c.evaluate_lets();
    c.file_limits();
    let rooms = c.rooms();
    c.build_mannequins();
    let (mut persons, mut bases): (Vec<_>, Vec<_>) = c.persons().into_iter().unzip();
    let named = c.populations_named(&persons);
    let populations = c.populations(&named, &mut persons, &mut bases);
    let tasks = c.tasks(&rooms, &persons, &bases, &populations);
    let standards = c.standards(&rooms);
    let expectations = c.expectations(&expect::Answered {
        rooms: &rooms,
        persons: &persons,
        populations: &populations,
        tasks: &tasks,
        standards: &standards,
    });
    let costliest = if c.cx.errors.is_empty() {
        c.check_budget(&tasks, &rooms, &bases, &populations, &persons)
    } else {
        None
    };
    let result = if c.cx.errors.is_empty() {
        let constants = c.constants();
        Ok(Scenario {
            file: sources.get(root).name.clone(),
            constants,
            rooms,
            persons,
            bases,
            populations,
            tasks,
            standards,
            expectations,
            work: WorkBound {
                limit: c.cx.limits.solver_work,
                costliest,
                set_at: c.cx.work_set_at,
            },
        })
    } else {
        Err(Diagnostics {
            errors: c.cx.errors,
        })
    };
    (c.cx.data_files, result)
}

/// What every phase of the pass shares: the plugins, the limits, the
/// sources, the errors found so far, the data files named, the counts
/// the limits bound, and the default units of the file being evaluated.
struct Context<'a> {
    registry: &'a Registry,
    limits: Limits,
    /// The data files (meshes, URDFs) the scenario names.
    data_files: Vec<PathBuf>,
    /// The triangles of the meshes read so far (`Limits::triangles`).
    triangles_read: usize,
    /// Each mesh file parsed, and each file a mesh refers to (a glTF's
    /// buffers) read, by its canonical path: a file named by many `mesh`
    /// lines, or by many buffers, is read and parsed once.
    mesh_files: MeshFiles,
    /// The joints of the people built so far, and whether they passed
    /// their bound (`Checker::within_people_joints`).
    people_joints: (u64, bool),
    /// Which of each population's people are built as persons.
    built: PeopleBuilt,
    /// The bytes of mannequins' declarations evaluated to build people so
    /// far, and whether they passed their bound
    /// (`Checker::within_evaluated_text`).
    evaluated_text: (u64, bool),
    /// Where the root file's `limits` sets the bound on solver work, if
    /// it does.
    work_set_at: Option<Span>,
    sources: &'a Sources,
    errors: Vec<Error>,
    /// The did-you-mean suggestions the check may still make.
    suggestions: &'a Suggestions,
    defaults_of: HashMap<FileId, UnitDefaults>,
    /// The default units of the file whose text is being evaluated.
    defaults: UnitDefaults,
    /// That file.
    file: FileId,
}

/// The declarations of every file by name (the first phase's output,
/// which the others read), and the tasks, standards and expectations of
/// the root file in order.
struct Declarations<'a> {
    lets: Table<'a, LetDecl>,
    rooms: Table<'a, crate::syntax::ast::RoomDecl>,
    mannequins: Table<'a, crate::syntax::ast::MannequinDecl>,
    profiles: Table<'a, crate::syntax::ast::ProfileDecl>,
    base_presets: Table<'a, crate::syntax::ast::BasePreset>,
    vision_presets: Table<'a, crate::syntax::ast::VisionPreset>,
    persons: Table<'a, crate::syntax::ast::PersonDecl>,
    populations: Table<'a, crate::syntax::ast::PopulationDecl>,
    tasks: Vec<(&'a crate::syntax::ast::TaskDecl, FileId)>,
    standards: Vec<(&'a crate::syntax::ast::StandardDecl, FileId)>,
    limits: Vec<(&'a crate::syntax::ast::LimitsDecl, FileId)>,
    expects: Vec<(&'a crate::syntax::ast::ExpectDecl, FileId)>,
}

/// What the phases have built that later ones look up: constants'
/// values, mannequins' bodies, the parameters in scope, the targets.
#[derive(Default)]
struct Built {
    let_values: HashMap<String, Option<Quantity>>,
    let_stack: Vec<String>,
    bodies: HashMap<String, Option<Body>>,
    /// Mannequin parameters in scope while a mannequin is built, innermost
    /// last; they hide constants of the same name.
    params: Vec<(String, Option<Quantity>)>,
    /// Each target's room and place in it, by name, for the tasks.
    target_index: HashMap<String, (usize, usize)>,
    /// The measurements each mannequin (named without arguments) was
    /// built from: its outermost parameters with values.
    measures: HashMap<String, Vec<(String, Quantity)>>,
    /// While a mannequin's or a person's body is built: the outermost
    /// parameters met so far (`Some(empty)` until a mannequin with
    /// parameters is met; `None` when nothing is being measured).
    captured: Option<Vec<(String, Quantity)>>,
}

/// The pass, in phases (`check` runs them in order: declarations, the
/// constants, rooms, bodies, persons, populations, tasks, standards,
/// expectations, the budget), each a method group in its own file that
/// takes its inputs and returns its output, sharing the context, the
/// declarations and what earlier phases built.
struct Checker<'a> {
    cx: Context<'a>,
    decls: Declarations<'a>,
    built: Built,
}

impl<'a> Checker<'a> {
    fn new(
        registry: &'a Registry,
        sources: &'a Sources,
        limits: Limits,
        suggestions: &'a Suggestions,
    ) -> Self {
        Checker {
            cx: Context {
                registry,
                limits,
                data_files: Vec::new(),
                triangles_read: 0,
                mesh_files: MeshFiles::default(),
                people_joints: (0, false),
                built: PeopleBuilt::Everyone,
                evaluated_text: (0, false),
                work_set_at: None,
                sources,
                errors: Vec::new(),
                suggestions,
                defaults_of: HashMap::new(),
                defaults: UnitDefaults::default(),
                file: FileId::default(),
            },
            decls: Declarations {
                lets: Table::new("constant"),
                rooms: Table::new("room"),
                mannequins: Table::new("mannequin"),
                profiles: Table::new("profile"),
                base_presets: Table::new("base preset"),
                vision_presets: Table::new("vision"),
                persons: Table::new("person"),
                populations: Table::new("population"),
                tasks: Vec::new(),
                standards: Vec::new(),
                limits: Vec::new(),
                expects: Vec::new(),
            },
            built: Built::default(),
        }
    }

    fn error(&mut self, e: Error) {
        self.cx.errors.push(e);
    }

    /// An unknown name (`Error::unknown`), with a suggestion while the
    /// check's budget lasts.
    fn unknown<'k>(
        &self,
        what: &'static str,
        name: &str,
        span: crate::span::Span,
        known: impl IntoIterator<Item = &'k str>,
    ) -> Error {
        Error::unknown(what, (name, span), known, self.cx.suggestions)
    }

    /// Run `f` with the default units of `file`.
    fn in_file<T>(&mut self, file: FileId, f: impl FnOnce(&mut Self) -> T) -> T {
        let saved = (self.cx.defaults, self.cx.file);
        self.cx.defaults = self.cx.defaults_of.get(&file).copied().unwrap_or_default();
        self.cx.file = file;
        let out = f(self);
        (self.cx.defaults, self.cx.file) = saved;
        out
    }

    /// The file's `units` line: at most one length and one angle unit.
    fn file_defaults(&mut self, items: &[Item]) -> UnitDefaults {
        let mut defaults = UnitDefaults::default();
        let mut seen: Vec<Spanned<Unit>> = Vec::new();
        for item in items {
            let Item::Units(units) = item else { continue };
            for u in units {
                if seen
                    .iter()
                    .any(|s| s.value.is_length() == u.value.is_length())
                {
                    let dimension = if u.value.is_length() {
                        "length"
                    } else {
                        "angle"
                    };
                    self.error(Error::new(ErrorKind::UnitsRepeated { dimension }, u.span));
                    continue;
                }
                seen.push(*u);
                if u.value.is_length() {
                    defaults.length = u.value;
                } else {
                    defaults.angle = u.value;
                }
            }
        }
        defaults
    }

    /// Enter the file's declarations into the tables.
    fn collect(&mut self, f: &'a LoadedFile, is_root: bool) {
        for item in &f.ast.items {
            let dup = match item {
                Item::Let(d) => self.decls.lets.insert(&d.name, d, f.id),
                Item::Room(d) => self.decls.rooms.insert(&d.name, d, f.id),
                Item::Mannequin(d) => self.decls.mannequins.insert(&d.name, d, f.id),
                Item::Profile(d) => self.decls.profiles.insert(&d.name, d, f.id),
                Item::BasePreset(d) => {
                    if self.cx.registry.base(&d.name.value).is_some() {
                        let name = d.name.value.clone();
                        let kind = ErrorKind::PresetNamesPlugin { name };
                        self.error(Error::new(kind, d.name.span));
                    }
                    self.decls.base_presets.insert(&d.name, d, f.id)
                }
                Item::VisionPreset(d) => self.decls.vision_presets.insert(&d.name, d, f.id),
                Item::Person(d) => self.decls.persons.insert(&d.name, d, f.id),
                Item::Population(d) => self.decls.populations.insert(&d.name, d, f.id),
                Item::Task(d) if is_root => {
                    self.decls.tasks.push((d, f.id));
                    None
                }
                Item::Task(d) => Some(Error::new(ErrorKind::Misplaced { what: "tasks" }, d.span)),
                Item::Standard(d) if is_root => {
                    self.decls.standards.push((d, f.id));
                    None
                }
                Item::Standard(d) => Some(Error::new(
                    ErrorKind::Misplaced { what: "standards" },
                    d.span,
                )),
                Item::Limits(d) if is_root => {
                    self.decls.limits.push((d, f.id));
                    None
                }
                Item::Limits(d) => {
                    Some(Error::new(ErrorKind::Misplaced { what: "limits" }, d.span))
                }
                Item::Expect(d) if is_root => {
                    self.decls.expects.push((d, f.id));
                    None
                }
                Item::Expect(d) => Some(Error::new(
                    ErrorKind::Misplaced {
                        what: "expectations",
                    },
                    d.span,
                )),
                Item::Units(_) | Item::Use(_) => None,
            };
            if let Some(e) = dup {
                self.error(e);
            }
        }
    }
}
