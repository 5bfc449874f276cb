//! The names a scenario's files declare and the places they are used, read
//! from the syntax trees alone (no checking): what an editor's go to
//! definition, find references and completion of names need. A use is
//! resolved by its name and the kinds of declaration its place admits
//! (`by ann`: a person or a population; `after elbow`: a joint), and, for
//! a mannequin's parameters, by the mannequin it is in or calls.

use crate::options::PluginKind;
use crate::plugin::Registry;
use crate::span::{FileId, Name, Span};
use crate::syntax::ast::{self, Claim, Expr, ExprKind, Item, OptionValue, RoomItem, UseTarget};

/// What a name declares.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum SymbolKind {
    Constant,
    Room,
    Box,
    Mesh,
    Target,
    Surface,
    Door,
    Mannequin,
    /// A mannequin's parameter (`stature = 1755mm`).
    Parameter,
    Joint,
    Effector,
    Sphere,
    Profile,
    BasePreset,
    VisionPreset,
    Person,
    Population,
    /// A population's `draw`.
    Draw,
}

impl SymbolKind {
    /// The word a declaration of this kind starts with, as users know it.
    pub fn word(self) -> &'static str {
        match self {
            SymbolKind::Constant => "let",
            SymbolKind::Room => "room",
            SymbolKind::Box => "box",
            SymbolKind::Mesh => "mesh",
            SymbolKind::Target => "target",
            SymbolKind::Surface => "surface",
            SymbolKind::Door => "door",
            SymbolKind::Mannequin => "mannequin",
            SymbolKind::Parameter => "parameter",
            SymbolKind::Joint => "joint",
            SymbolKind::Effector => "effector",
            SymbolKind::Sphere => "sphere",
            SymbolKind::Profile => "profile",
            SymbolKind::BasePreset => "base",
            SymbolKind::VisionPreset => "vision",
            SymbolKind::Person => "person",
            SymbolKind::Population => "population",
            SymbolKind::Draw => "draw",
        }
    }
}

/// One declared name.
#[derive(Clone, Debug)]
pub struct Symbol {
    pub name: String,
    pub kind: SymbolKind,
    /// The name where it is declared.
    pub span: Span,
    /// The whole declaration (its first line is what hover shows).
    pub whole: Span,
    /// The room, mannequin or population it is declared in, if any.
    pub container: Option<String>,
}

/// One use of a name, and what it may refer to.
#[derive(Clone, Debug)]
pub struct Reference {
    pub name: String,
    pub span: Span,
    pub kinds: &'static [SymbolKind],
    /// For a parameter: the mannequin whose parameter it is.
    pub container: Option<String>,
}

/// A plugin named in the text (`wheelchair`, `incremental`, a task's kind).
#[derive(Clone, Debug)]
pub struct PluginName {
    pub kind: PluginKind,
    pub name: String,
    pub span: Span,
}

/// Whose option an option's name is.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum OptionOwner {
    /// A plugin's, by kind and name (a base preset's name resolved to its
    /// plugin where the outline can).
    Plugin(PluginKind, String),
    /// `vision { ... }`.
    Vision,
    /// `limits { ... }`.
    Limits,
}

/// An option's name in a block.
#[derive(Clone, Debug)]
pub struct OptionName {
    pub name: String,
    pub span: Span,
    pub owner: OptionOwner,
}

/// A `use`: the module or file it names.
#[derive(Clone, Debug)]
pub struct UseOf {
    pub span: Span,
    pub target: UseTarget,
}

/// Every declaration and use in the loaded files.
#[derive(Clone, Debug, Default)]
pub struct Outline {
    pub symbols: Vec<Symbol>,
    pub references: Vec<Reference>,
    pub plugins: Vec<PluginName>,
    pub options: Vec<OptionName>,
    pub uses: Vec<UseOf>,
}

const EXPRESSION: &[SymbolKind] = &[
    SymbolKind::Constant,
    SymbolKind::Parameter,
    SymbolKind::Draw,
];
/// A name an option's value gives: an element, a room, an effector, ...
const ANY_NAMED: &[SymbolKind] = &[
    SymbolKind::Constant,
    SymbolKind::Room,
    SymbolKind::Box,
    SymbolKind::Mesh,
    SymbolKind::Target,
    SymbolKind::Surface,
    SymbolKind::Door,
    SymbolKind::Effector,
    SymbolKind::Person,
    SymbolKind::Population,
];
const SUBJECT: &[SymbolKind] = &[
    SymbolKind::Target,
    SymbolKind::Surface,
    SymbolKind::Box,
    SymbolKind::Mesh,
];
const WHO: &[SymbolKind] = &[SymbolKind::Person, SymbolKind::Population];
const JOINT: &[SymbolKind] = &[SymbolKind::Joint];
const MANNEQUIN: &[SymbolKind] = &[SymbolKind::Mannequin];
const PARAMETER: &[SymbolKind] = &[SymbolKind::Parameter, SymbolKind::Draw];
const PROFILE: &[SymbolKind] = &[SymbolKind::Profile];
const ROOM: &[SymbolKind] = &[SymbolKind::Room];
const TARGET: &[SymbolKind] = &[SymbolKind::Target];
const POPULATION: &[SymbolKind] = &[SymbolKind::Population];
const VISION: &[SymbolKind] = &[SymbolKind::VisionPreset];
const BASE: &[SymbolKind] = &[SymbolKind::BasePreset];

impl Outline {
    /// The outline of `files` (each with its id), plugins looked up in
    /// `registry` for the kind of a plugin an option names.
    pub fn of<'f>(
        files: impl IntoIterator<Item = (FileId, &'f ast::File)>,
        registry: &Registry,
    ) -> Self {
        let mut walker = Walker {
            out: Outline::default(),
            registry,
            container: None,
        };
        for (_, file) in files {
            for item in &file.items {
                walker.item(item);
            }
        }
        walker.out
    }

    /// The declarations a reference may be to: of its name and one of its
    /// kinds (a parameter's in its mannequin).
    pub fn resolve(&self, reference: &Reference) -> Vec<&Symbol> {
        let named = || {
            self.symbols
                .iter()
                .filter(|s| s.name == reference.name && reference.kinds.contains(&s.kind))
        };
        // A parameter is its mannequin's; outside one, a name is no
        // parameter.
        let found: Vec<&Symbol> = named()
            .filter(|s| s.kind != SymbolKind::Parameter || s.container == reference.container)
            .collect();
        if !found.is_empty() || reference.container.is_none() {
            return found;
        }
        // A mannequin that is another with parameters given has that
        // one's parameters (which the outline does not follow).
        named()
            .filter(|s| s.kind == SymbolKind::Parameter)
            .collect()
    }

    /// What is at byte `offset` of the file of index `file` (in the
    /// check's sources): a declaration's name, or a use of one (resolved),
    /// a plugin's or an option's name, a `use`.
    pub fn at_index(&self, file: usize, offset: usize) -> Option<Found<'_>> {
        self.at(FileId(u32::try_from(file).ok()?), offset)
    }

    /// What is at byte `offset` of `file`: a declaration's name, or a
    /// use of one (resolved).
    pub fn at(&self, file: FileId, offset: usize) -> Option<Found<'_>> {
        let inside =
            |s: &Span| s.file == file && (s.start as usize) <= offset && offset <= s.end as usize;
        if let Some(symbol) = self.symbols.iter().find(|s| inside(&s.span)) {
            return Some(Found::Declaration(symbol));
        }
        if let Some(r) = self.references.iter().find(|r| inside(&r.span)) {
            return Some(Found::Use(r, self.resolve(r)));
        }
        if let Some(p) = self.plugins.iter().find(|p| inside(&p.span)) {
            return Some(Found::Plugin(p));
        }
        if let Some(o) = self.options.iter().find(|o| inside(&o.span)) {
            return Some(Found::Option(o));
        }
        self.uses
            .iter()
            .find(|u| inside(&u.span))
            .map(Found::Module)
    }

    /// Every use of `symbol`, in the order of the files.
    pub fn uses_of(&self, symbol: &Symbol) -> Vec<Span> {
        let same =
            |s: &&Symbol| s.span.file == symbol.span.file && s.span.start == symbol.span.start;
        self.references
            .iter()
            .filter(|r| self.resolve(r).iter().any(same))
            .map(|r| r.span)
            .collect()
    }

    /// The plugin of base preset `preset` (the last declared of that
    /// name), where its declaration names one.
    pub fn preset_plugin(&self, preset: &str) -> Option<String> {
        let symbol = (self.symbols.iter().rev())
            .find(|s| s.kind == SymbolKind::BasePreset && s.name == preset)?;
        self.plugins
            .iter()
            .find(|p| {
                p.span.file == symbol.span.file
                    && p.span.start >= symbol.span.end
                    && p.span.start <= symbol.whole.end
            })
            .map(|p| p.name.clone())
    }

    /// Each declared name of one of `kinds`, once, in order.
    pub fn names_of(&self, kinds: &[SymbolKind]) -> Vec<&Symbol> {
        let mut seen = std::collections::BTreeSet::new();
        self.symbols
            .iter()
            .filter(|s| kinds.contains(&s.kind) && seen.insert((s.kind, s.name.as_str())))
            .collect()
    }
}

/// What a place in the text is.
#[derive(Debug)]
pub enum Found<'o> {
    Declaration(&'o Symbol),
    /// A use, with the declarations it may be to.
    Use(&'o Reference, Vec<&'o Symbol>),
    Plugin(&'o PluginName),
    Option(&'o OptionName),
    Module(&'o UseOf),
}

struct Walker<'r> {
    out: Outline,
    registry: &'r Registry,
    /// The mannequin or population being walked, for parameters and draws.
    container: Option<String>,
}

impl Walker<'_> {
    fn declare(&mut self, name: &Name, kind: SymbolKind, whole: Span, container: Option<&str>) {
        self.out.symbols.push(Symbol {
            name: name.value.clone(),
            kind,
            span: name.span,
            whole,
            container: container.map(str::to_string),
        });
    }

    fn refer(&mut self, name: &Name, kinds: &'static [SymbolKind]) {
        self.refer_in(name, kinds, None);
    }

    fn refer_in(&mut self, name: &Name, kinds: &'static [SymbolKind], container: Option<String>) {
        self.out.references.push(Reference {
            name: name.value.clone(),
            span: name.span,
            kinds,
            container,
        });
    }

    fn item(&mut self, item: &Item) {
        match item {
            Item::Units(_) => {}
            Item::Use(u) => self.out.uses.push(UseOf {
                span: u.span,
                target: u.value.clone(),
            }),
            Item::Let(l) => {
                self.declare(
                    &l.name,
                    SymbolKind::Constant,
                    l.name.span.to(l.value.span),
                    None,
                );
                self.expr(&l.value);
            }
            Item::Room(room) => self.room(room),
            Item::Mannequin(m) => self.mannequin(m),
            Item::Profile(p) => {
                let whole = p.name.span;
                self.declare(&p.name, SymbolKind::Profile, whole, None);
                p.overrides.iter().for_each(|o| self.joint_override(o));
            }
            Item::BasePreset(b) => {
                self.declare(
                    &b.name,
                    SymbolKind::BasePreset,
                    b.name.span.to(b.plugin.span),
                    None,
                );
                self.plugin_use(&b.plugin, PluginKind::Base);
            }
            Item::VisionPreset(v) => {
                self.declare(&v.name, SymbolKind::VisionPreset, v.span, None);
                self.options(&v.options, &OptionOwner::Vision);
            }
            Item::Person(p) => {
                self.declare(&p.name, SymbolKind::Person, p.span, None);
                self.person(p);
            }
            Item::Population(p) => self.population(p),
            Item::Standard(s) => {
                self.plugin_name(&s.name, PluginKind::Standard);
                if let Some(room) = &s.room {
                    self.refer(room, ROOM);
                }
                s.except.iter().for_each(|t| self.refer(t, TARGET));
                let owner = OptionOwner::Plugin(PluginKind::Standard, s.name.value.clone());
                self.options(&s.options, &owner);
            }
            Item::Limits(l) => self.options(&l.options, &OptionOwner::Limits),
            Item::Expect(e) => self.expect(&e.claim),
            Item::Task(t) => {
                self.plugin_name(&t.kind, PluginKind::Task);
                t.subjects.iter().for_each(|s| self.subject(s));
                t.persons.iter().for_each(|p| self.refer(p, WHO));
                let owner = OptionOwner::Plugin(PluginKind::Task, t.kind.value.clone());
                self.options(&t.options, &owner);
            }
        }
    }

    fn room(&mut self, room: &ast::RoomDecl) {
        self.declare(&room.name, SymbolKind::Room, room.span, None);
        let inside = Some(room.name.value.as_str());
        for item in &room.items {
            match item {
                RoomItem::Size(v) => self.exprs(&v.parts),
                RoomItem::Box(b) => {
                    self.declare(
                        &b.name,
                        SymbolKind::Box,
                        b.name.span.to(b.size.span),
                        inside,
                    );
                    self.exprs(&b.at.parts);
                    self.exprs(&b.size.parts);
                    b.rotate.iter().for_each(|e| self.expr(e));
                }
                RoomItem::Mesh(m) => {
                    self.declare(
                        &m.name,
                        SymbolKind::Mesh,
                        m.name.span.to(m.path.span),
                        inside,
                    );
                    m.at.iter().for_each(|v| self.exprs(&v.parts));
                    m.scale.iter().chain(&m.rotate).for_each(|e| self.expr(e));
                }
                RoomItem::Target(t) => {
                    self.declare(
                        &t.name,
                        SymbolKind::Target,
                        t.name.span.to(t.at.span),
                        inside,
                    );
                    self.exprs(&t.at.parts);
                }
                RoomItem::Surface(s) => {
                    self.declare(
                        &s.name,
                        SymbolKind::Surface,
                        s.name.span.to(s.size.span),
                        inside,
                    );
                    self.exprs(&s.at.parts);
                    self.exprs(&s.size.parts);
                }
                RoomItem::Door(d) => {
                    self.declare(
                        &d.name,
                        SymbolKind::Door,
                        d.name.span.to(d.width.span),
                        inside,
                    );
                    self.exprs(&d.at.parts);
                    self.expr(&d.width);
                }
            }
        }
    }

    fn mannequin(&mut self, m: &ast::MannequinDecl) {
        let name = m.name.value.clone();
        self.declare(&m.name, SymbolKind::Mannequin, m.span, None);
        self.container = Some(name.clone());
        for (param, default) in &m.params {
            self.declare(
                param,
                SymbolKind::Parameter,
                param.span.to(default.span),
                Some(&name),
            );
            self.expr(default);
        }
        if let Some(alias) = &m.alias {
            self.mannequin_ref(alias);
        }
        for joint in &m.joints {
            self.declare(
                &joint.name,
                SymbolKind::Joint,
                joint.name.span.to(joint.dh_span),
                Some(&name),
            );
            joint.after.iter().for_each(|a| self.refer(a, JOINT));
            joint.dh.iter().for_each(|(_, e)| self.expr(e));
            for limits in joint.limits.iter().chain(&joint.anatomical) {
                self.expr(&limits.min);
                self.expr(&limits.max);
            }
            joint
                .neutral
                .iter()
                .chain(&joint.weight)
                .chain(&joint.link.radius)
                .for_each(|e| self.expr(e));
        }
        for effector in &m.effectors {
            self.declare(
                &effector.name,
                SymbolKind::Effector,
                effector.name.span.to(effector.at.span),
                Some(&name),
            );
            effector.after.iter().for_each(|a| self.refer(a, JOINT));
            self.exprs(&effector.at.parts);
            effector.link.radius.iter().for_each(|e| self.expr(e));
        }
        for sphere in &m.spheres {
            self.declare(
                &sphere.name,
                SymbolKind::Sphere,
                sphere.name.span.to(sphere.radius.span),
                Some(&name),
            );
            sphere.after.iter().for_each(|a| self.refer(a, JOINT));
            self.exprs(&sphere.at.parts);
            self.expr(&sphere.radius);
        }
        m.legs
            .iter()
            .flat_map(|l| &l.args)
            .for_each(|(_, e)| self.expr(e));
        m.couples
            .iter()
            .flat_map(|c| &c.joints)
            .for_each(|j| self.refer(j, JOINT));
        for rhythm in &m.rhythms {
            self.refer(&rhythm.follower, JOINT);
            rhythm.drivers.iter().for_each(|d| self.refer(d, JOINT));
            self.expr(&rhythm.from);
        }
        for require in &m.requires {
            self.expr(&require.value);
            self.expr(&require.bound.value);
        }
        self.container = None;
    }

    /// `upper_body(stature 1520mm)`: the mannequin and its parameters.
    fn mannequin_ref(&mut self, r: &ast::MannequinRef) {
        self.refer(&r.name, MANNEQUIN);
        for (param, value) in &r.args {
            self.refer_in(param, PARAMETER, Some(r.name.value.clone()));
            self.expr(value);
        }
    }

    fn person(&mut self, p: &ast::PersonDecl) {
        for m in &p.mannequins {
            self.mannequin_ref(&m.mannequin);
            m.overrides.iter().for_each(|o| self.joint_override(o));
        }
        p.bases
            .iter()
            .for_each(|b| self.plugin_use(b, PluginKind::Base));
        for vision in &p.visions {
            vision.preset.iter().for_each(|v| self.refer(v, VISION));
            self.options(&vision.options, &OptionOwner::Vision);
        }
    }

    fn population(&mut self, p: &ast::PopulationDecl) {
        let name = p.name.value.clone();
        self.declare(&p.name, SymbolKind::Population, p.span, None);
        p.from.iter().for_each(|f| self.refer(f, POPULATION));
        for draw in &p.draws {
            let whole = draw.name.span.to(draw.second.span);
            self.declare(&draw.name, SymbolKind::Draw, whole, Some(&name));
        }
        self.person(&p.person);
        p.size
            .iter()
            .chain(&p.seed)
            .chain(&p.women)
            .for_each(|e| self.expr(e));
        for draw in &p.draws {
            self.expr(&draw.first);
            self.expr(&draw.second);
            if let Some((low, high)) = &draw.within {
                self.expr(low);
                self.expr(high);
            }
        }
        for (profile, share) in p
            .profiles
            .iter()
            .chain(p.choices.iter().flat_map(|c| &c.options))
        {
            self.refer(profile, PROFILE);
            self.expr(share);
        }
    }

    fn joint_override(&mut self, o: &ast::JointOverride) {
        match o {
            ast::JointOverride::Limits { joint, limits } => {
                self.refer(joint, JOINT);
                self.expr(&limits.min);
                self.expr(&limits.max);
            }
            ast::JointOverride::Neutral { joint, value }
            | ast::JointOverride::Weight { joint, value } => {
                self.refer(joint, JOINT);
                self.expr(value);
            }
            ast::JointOverride::Profile { name } => self.refer(name, PROFILE),
        }
    }

    /// `wheelchair { ... }`: a plugin, or a base preset, and its options.
    fn plugin_use(&mut self, p: &ast::PluginUse, kind: PluginKind) {
        let preset = (kind == PluginKind::Base)
            .then(|| {
                self.out
                    .symbols
                    .iter()
                    .rev()
                    .find(|s| s.kind == SymbolKind::BasePreset && s.name == p.name.value)
            })
            .flatten()
            .map(|s| s.name.clone());
        let plugin = match &preset {
            Some(_) => {
                self.refer(&p.name, BASE);
                self.out.preset_plugin(&p.name.value).unwrap_or_default()
            }
            None if self.registry.names(kind).contains(&p.name.value.as_str()) => {
                self.plugin_name(&p.name, kind);
                p.name.value.clone()
            }
            // A base preset of a file used later, or a misspelling.
            None => {
                if kind == PluginKind::Base {
                    self.refer(&p.name, BASE);
                }
                p.name.value.clone()
            }
        };
        self.options(&p.options, &OptionOwner::Plugin(kind, plugin));
    }

    fn plugin_name(&mut self, name: &Name, kind: PluginKind) {
        self.out.plugins.push(PluginName {
            kind,
            name: name.value.clone(),
            span: name.span,
        });
    }

    fn options(&mut self, options: &[ast::OptionDecl], owner: &OptionOwner) {
        for option in options {
            self.out.options.push(OptionName {
                name: option.name.value.clone(),
                span: option.name.span,
                owner: owner.clone(),
            });
            match &option.value {
                OptionValue::Expr(e) => self.option_expr(e),
                OptionValue::Vec3(v) => self.exprs(&v.parts),
                OptionValue::Points(points) => points.iter().for_each(|v| self.exprs(&v.parts)),
                OptionValue::Names(names) => names.iter().for_each(|n| self.refer(n, ANY_NAMED)),
                OptionValue::Bool(_) | OptionValue::String(_) => {}
                OptionValue::Plugin(p) => {
                    let kind = self.option_plugin_kind(owner, &option.name.value);
                    match kind {
                        Some(kind) => self.plugin_use(p, kind),
                        None => self.options(&p.options, &OptionOwner::Limits),
                    }
                }
            }
        }
    }

    /// An option's value that is a bare name (`effector eyes`, `room
    /// kitchen`): any declared name; else an expression.
    fn option_expr(&mut self, e: &Expr) {
        match &e.kind {
            ExprKind::Name(n) => {
                let name = Name::new(n.clone(), e.span);
                self.refer(&name, ANY_NAMED);
            }
            _ => self.expr(e),
        }
    }

    /// The kind of plugin option `name` of `owner` takes.
    fn option_plugin_kind(&self, owner: &OptionOwner, name: &str) -> Option<PluginKind> {
        let OptionOwner::Plugin(kind, plugin) = owner else {
            return None;
        };
        let params = self.registry.params(*kind, plugin)?;
        params
            .iter()
            .find(|p| p.name == name)
            .and_then(|p| match p.kind {
                crate::options::ParamKind::Plugin(k) => Some(k),
                _ => None,
            })
    }

    fn subject(&mut self, subject: &crate::span::Spanned<Vec<String>>) {
        let Some(first) = subject.value.first() else {
            return;
        };
        let start = subject.span.start as usize;
        let span = Span::new(subject.span.file, start, start + first.len());
        self.refer(&Name::new(first.clone(), span), SUBJECT);
    }

    fn expect(&mut self, claim: &Claim) {
        match claim {
            Claim::Person {
                who,
                subject,
                bound,
                ..
            } => {
                self.refer(who, WHO);
                self.subject(subject);
                bound.iter().for_each(|b| self.expr(&b.value));
            }
            Claim::Share {
                population,
                subject,
                bound,
                ..
            } => {
                self.refer(population, POPULATION);
                self.subject(subject);
                self.expr(&bound.value);
            }
            Claim::Meets { room, standard } => {
                self.refer(room, ROOM);
                self.plugin_name(standard, PluginKind::Standard);
            }
            Claim::Advice {
                subject,
                share,
                from,
                to,
            } => {
                self.subject(subject);
                [share, from, to].into_iter().for_each(|e| self.expr(e));
            }
        }
    }

    fn exprs(&mut self, exprs: &[Expr]) {
        exprs.iter().for_each(|e| self.expr(e));
    }

    fn expr(&mut self, e: &Expr) {
        match &e.kind {
            ExprKind::Number { .. } => {}
            ExprKind::Name(n) => {
                let name = Name::new(n.clone(), e.span);
                let container = self.container.clone();
                self.refer_in(&name, EXPRESSION, container);
            }
            ExprKind::Neg(inner) => self.expr(inner),
            ExprKind::Binary(_, a, b) => {
                self.expr(a);
                self.expr(b);
            }
            ExprKind::Call(_, args) => self.exprs(args),
        }
    }
}
