//! The syntax tree of one `.reach` file, as written: names unresolved,
//! numbers unevaluated, every node with its span.

use crate::span::{Name, Span, Spanned};
use crate::units::Unit;

/// One parsed file.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct File {
    pub items: Vec<Item>,
}

#[derive(Clone, Debug, PartialEq)]
pub enum Item {
    Units(Vec<Spanned<Unit>>),
    Use(Spanned<UseTarget>),
    Let(LetDecl),
    Room(RoomDecl),
    Mannequin(Box<MannequinDecl>),
    Profile(ProfileDecl),
    BasePreset(BasePreset),
    VisionPreset(VisionPreset),
    Person(PersonDecl),
    Population(Box<PopulationDecl>),
    Standard(StandardDecl),
    Limits(LimitsDecl),
    Expect(ExpectDecl),
    Task(TaskDecl),
}

/// `expect ...`: what must hold of the answers.
#[derive(Clone, Debug, PartialEq)]
pub struct ExpectDecl {
    pub claim: Claim,
    /// The expectation as written, for reports (`ann reaches kettle`).
    pub text: String,
    pub span: Span,
}

/// What an expectation claims.
#[derive(Clone, Debug, PartialEq)]
pub enum Claim {
    /// `ann reaches kettle`, `bob not sees dial`, `ann covers counter.top
    /// >= 80 %`.
    Person {
        who: Name,
        negated: bool,
        verb: Spanned<Verb>,
        subject: Spanned<Vec<String>>,
        bound: Option<Bound>,
    },
    /// `share(users, kettle) >= 90 %` (`share(users, kettle, gaze)` names
    /// the task where a population has several about the subject).
    Share {
        population: Name,
        subject: Spanned<Vec<String>>,
        task: Option<Name>,
        bound: Bound,
    },
    /// `kitchen meets ada2010`.
    Meets { room: Name, standard: Name },
    /// `advise microwave serves 90 % between 800mm and 1100mm`: every
    /// advice about the target serves that share at every position
    /// between the two.
    Advice {
        subject: Spanned<Vec<String>>,
        share: Expr,
        from: Expr,
        to: Expr,
    },
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Verb {
    Reaches,
    Sees,
    Covers,
}

/// `>= 80 %`.
#[derive(Clone, Debug, PartialEq)]
pub struct Bound {
    pub comparison: Spanned<Comparison>,
    pub value: Expr,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Comparison {
    AtLeast,
    AtMost,
    Above,
    Below,
}

impl Comparison {
    pub fn holds(self, value: f64, bound: f64) -> bool {
        match self {
            Comparison::AtLeast => value >= bound,
            Comparison::AtMost => value <= bound,
            Comparison::Above => value > bound,
            Comparison::Below => value < bound,
        }
    }

    /// The comparison that holds exactly when this one does not.
    pub fn opposite(self) -> Self {
        match self {
            Comparison::AtLeast => Comparison::Below,
            Comparison::AtMost => Comparison::Above,
            Comparison::Above => Comparison::AtMost,
            Comparison::Below => Comparison::AtLeast,
        }
    }

    pub fn symbol(self) -> &'static str {
        match self {
            Comparison::AtLeast => ">=",
            Comparison::AtMost => "<=",
            Comparison::Above => ">",
            Comparison::Below => "<",
        }
    }
}

/// `limits { solver_work 2e9 }`: the scenario's own bounds on its run.
#[derive(Clone, Debug, PartialEq)]
pub struct LimitsDecl {
    pub options: Vec<OptionDecl>,
    pub span: Span,
}

/// `standard ada2010 in kitchen { options }`: a building standard's rules
/// checked on one room (every room without `in`).
#[derive(Clone, Debug, PartialEq)]
pub struct StandardDecl {
    pub name: Name,
    pub room: Option<Name>,
    /// `except a, b`: targets that are not elements.
    pub except: Vec<Name>,
    pub options: Vec<OptionDecl>,
    pub span: Span,
}

#[derive(Clone, Debug, PartialEq)]
pub enum UseTarget {
    /// `use std::name`
    Std(String),
    /// `use "relative/path.reach"`
    Path(String),
}

#[derive(Clone, Debug, PartialEq)]
pub struct LetDecl {
    pub name: Name,
    pub value: Expr,
}

/// An arithmetic expression.
#[derive(Clone, Debug, PartialEq)]
pub struct Expr {
    pub kind: ExprKind,
    pub span: Span,
}

#[derive(Clone, Debug, PartialEq)]
pub enum ExprKind {
    Number {
        value: f64,
        unit: Option<Unit>,
    },
    Name(String),
    Neg(Box<Expr>),
    Binary(BinOp, Box<Expr>, Box<Expr>),
    /// `min(...)` or `max(...)`.
    Call(Function, Vec<Expr>),
}

impl Expr {
    /// The names it uses, in order, each as often as it is written.
    pub fn names(&self) -> Vec<&str> {
        match &self.kind {
            ExprKind::Number { .. } => Vec::new(),
            ExprKind::Name(n) => vec![n.as_str()],
            ExprKind::Neg(e) => e.names(),
            ExprKind::Binary(_, a, b) => [a.names(), b.names()].concat(),
            ExprKind::Call(_, args) => args.iter().flat_map(Expr::names).collect(),
        }
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Function {
    Min,
    Max,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BinOp {
    Add,
    Sub,
    Mul,
    Div,
}

/// `(x, y, z)`
#[derive(Clone, Debug, PartialEq)]
pub struct Vec3Expr {
    pub parts: [Expr; 3],
    pub span: Span,
}

/// `(x, y)`: a point on the floor.
#[derive(Clone, Debug, PartialEq)]
pub struct Vec2Expr {
    pub parts: [Expr; 2],
    pub span: Span,
}

#[derive(Clone, Debug, PartialEq)]
pub struct RoomDecl {
    pub name: Name,
    pub items: Vec<RoomItem>,
    pub span: Span,
}

#[derive(Clone, Debug, PartialEq)]
pub enum RoomItem {
    Size(Vec3Expr),
    Box(Box<BoxDecl>),
    Mesh(Box<MeshDecl>),
    Target(TargetDecl),
    Surface(SurfaceDecl),
    Door(DoorDecl),
}

/// `door NAME at (x, y) width W`: an entrance on one of the room's walls.
#[derive(Clone, Debug, PartialEq)]
pub struct DoorDecl {
    pub name: Name,
    pub at: Vec2Expr,
    pub width: Expr,
}

/// `mesh NAME from "file.obj" at (x, y, z) scale k rotate a unit m up y`.
/// Each property is kept as often as it is written, so the checker can say
/// that one is repeated.
#[derive(Clone, Debug, PartialEq)]
pub struct MeshDecl {
    pub name: Name,
    pub path: Spanned<String>,
    pub at: Vec<Vec3Expr>,
    pub scale: Vec<Expr>,
    pub rotate: Vec<Expr>,
    /// The file's length unit (`mm`, `cm`, `m`, `in`).
    pub unit: Vec<Spanned<String>>,
    /// The file's up axis (`z` or `y`).
    pub up: Vec<Spanned<String>>,
}

/// `surface NAME at (x, y, z) size (a, b, c)`, one size zero.
#[derive(Clone, Debug, PartialEq)]
pub struct SurfaceDecl {
    pub name: Name,
    pub at: Vec3Expr,
    pub size: Vec3Expr,
}

#[derive(Clone, Debug, PartialEq)]
pub struct BoxDecl {
    pub name: Name,
    pub at: Vec3Expr,
    pub size: Vec3Expr,
    pub rotate: Option<Expr>,
}

#[derive(Clone, Debug, PartialEq)]
pub struct TargetDecl {
    pub name: Name,
    pub at: Vec3Expr,
}

#[derive(Clone, Debug, PartialEq)]
pub struct MannequinDecl {
    pub name: Name,
    /// Parameters and their default expressions, in order.
    pub params: Vec<(Name, Expr)>,
    /// `= other(args)`: this mannequin is another with parameters given.
    pub alias: Option<MannequinRef>,
    /// `from urdf "file" root "a" tip "b"`.
    pub urdf: Option<UrdfSource>,
    pub joints: Vec<JointDecl>,
    pub effectors: Vec<EffectorDecl>,
    pub spheres: Vec<SphereDecl>,
    /// `legs(...)`, each given once at most (the checker says so).
    pub legs: Vec<LegsDecl>,
    /// `couple a, b`: joints whose ranges are coupled.
    pub couples: Vec<CoupleDecl>,
    /// `rhythm g with a, b from x`: a joint that follows the elevation of
    /// two others.
    pub rhythms: Vec<RhythmDecl>,
    /// `require a <= b, "why"`: what the parameters must satisfy.
    pub requires: Vec<RequireDecl>,
    /// `seated` or `standing`, in the body or after an alias.
    pub postures: Vec<Spanned<Stance>>,
    pub span: Span,
}

/// Whether a mannequin sits or stands.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Stance {
    Seated,
    Standing,
}

/// The solid of a link: `radius R`, `link NAME`, each at most once.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct LinkDecl {
    pub radius: Vec<Expr>,
    pub name: Vec<Name>,
}

/// `sphere NAME [after JOINT] at (x, y, z) radius R`.
#[derive(Clone, Debug, PartialEq)]
pub struct SphereDecl {
    pub name: Name,
    pub after: Option<Name>,
    pub at: Vec3Expr,
    pub radius: Expr,
}

/// `legs(name value, ...)`.
#[derive(Clone, Debug, PartialEq)]
pub struct LegsDecl {
    pub args: Vec<(Name, Expr)>,
    pub span: Span,
}

/// `couple a, b, ...`: two or more joints of the mannequin.
#[derive(Clone, Debug, PartialEq)]
pub struct CoupleDecl {
    pub joints: Vec<Name>,
    pub span: Span,
}

/// `require value COMPARISON bound, "message"`: a condition on a
/// mannequin's parameters.
#[derive(Clone, Debug, PartialEq)]
pub struct RequireDecl {
    pub value: Expr,
    pub bound: Bound,
    pub message: String,
    pub span: Span,
}

/// `rhythm follower with a, b from from`: `follower` leaves its lower
/// limit only as the elevation of `a` and `b` passes `from`.
#[derive(Clone, Debug, PartialEq)]
pub struct RhythmDecl {
    pub follower: Name,
    pub drivers: [Name; 2],
    pub from: Expr,
    pub span: Span,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum JointKind {
    Revolute,
    Prismatic,
    /// No motion: a frame that turns the axes of the joints after it.
    Fixed,
}

#[derive(Clone, Debug, PartialEq)]
pub struct JointDecl {
    pub name: Name,
    pub kind: JointKind,
    /// The joint it follows, if not the one declared before it.
    pub after: Option<Name>,
    /// `dh(theta .., d .., alpha .., a ..)`, parameter names as written.
    pub dh: Vec<(Name, Expr)>,
    pub dh_span: Span,
    pub limits: Vec<LimitsExpr>,
    /// `anatomical(min, max)`: the range no person's limits may leave.
    pub anatomical: Vec<LimitsExpr>,
    pub neutral: Vec<Expr>,
    pub weight: Vec<Expr>,
    pub link: LinkDecl,
}

#[derive(Clone, Debug, PartialEq)]
pub struct LimitsExpr {
    pub min: Expr,
    pub max: Expr,
    pub span: Span,
}

#[derive(Clone, Debug, PartialEq)]
pub struct EffectorDecl {
    pub name: Name,
    /// The joint it sits on, if not the last.
    pub after: Option<Name>,
    pub at: Vec3Expr,
    pub link: LinkDecl,
    /// `point "..."`: what point of the body it is, each given once at
    /// most (the checker says so).
    pub point: Vec<Spanned<String>>,
}

#[derive(Clone, Debug, PartialEq)]
pub struct PersonDecl {
    pub name: Name,
    pub mannequins: Vec<PersonMannequin>,
    pub bases: Vec<PluginUse>,
    pub visions: Vec<PersonVision>,
    pub span: Span,
}

/// `population NAME [= FROM] { ... }`: people drawn from measured adults.
/// `person` holds its `mannequin`, `base` and `vision` items (named
/// `NAME`), the rest the population's own.
#[derive(Clone, Debug, PartialEq)]
pub struct PopulationDecl {
    pub name: Name,
    /// The population it starts from, whose items it replaces.
    pub from: Option<Name>,
    pub person: PersonDecl,
    pub size: Option<Expr>,
    pub seed: Option<Expr>,
    pub women: Option<Expr>,
    pub draws: Vec<DrawDecl>,
    pub profiles: Vec<(Name, Expr)>,
    /// `profile one of (NAME SHARE, ...)`: each person gets at most one.
    pub choices: Vec<ProfileChoice>,
    pub span: Span,
}

/// `profile one of (older_adult 30%, ama_minimum 10%)`: weighted
/// categories of profiles, at most one to each person (the rest keep the
/// mannequin's own).
#[derive(Clone, Debug, PartialEq)]
pub struct ProfileChoice {
    pub options: Vec<(Name, Expr)>,
    pub span: Span,
}

/// `draw NAME normal(MEAN, SD) within (LOW, HIGH)`, or `uniform(LOW, HIGH)`.
#[derive(Clone, Debug, PartialEq)]
pub struct DrawDecl {
    pub name: Name,
    pub kind: Spanned<Distribution>,
    pub first: Expr,
    pub second: Expr,
    pub within: Option<(Expr, Expr)>,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Distribution {
    Normal,
    Uniform,
}

/// A chain read from a URDF file, from link `root` to link `tip`.
#[derive(Clone, Debug, PartialEq)]
pub struct UrdfSource {
    pub path: Spanned<String>,
    pub root: Spanned<String>,
    pub tip: Spanned<String>,
    /// `radius 20mm`: every link's (else the default).
    pub radius: Option<Expr>,
}

/// A mannequin by name, with parameters given: `upper_body(stature 1520mm)`.
#[derive(Clone, Debug, PartialEq)]
pub struct MannequinRef {
    pub name: Name,
    pub args: Vec<(Name, Expr)>,
}

#[derive(Clone, Debug, PartialEq)]
pub struct PersonMannequin {
    pub mannequin: MannequinRef,
    /// `seated` or `standing` after it, as an alias may say.
    pub posture: Option<Spanned<Stance>>,
    /// Profiles and joint overrides, applied in order.
    pub overrides: Vec<JointOverride>,
}

#[derive(Clone, Debug, PartialEq)]
pub enum JointOverride {
    Limits {
        joint: Name,
        limits: LimitsExpr,
    },
    Neutral {
        joint: Name,
        value: Expr,
    },
    Weight {
        joint: Name,
        value: Expr,
    },
    /// `profile NAME`: every override of the profile.
    Profile {
        name: Name,
    },
}

/// `profile NAME { overrides }`.
#[derive(Clone, Debug, PartialEq)]
pub struct ProfileDecl {
    pub name: Name,
    pub overrides: Vec<JointOverride>,
}

/// `base NAME = plugin { options }`.
#[derive(Clone, Debug, PartialEq)]
pub struct BasePreset {
    pub name: Name,
    pub plugin: PluginUse,
}

/// `vision NAME { options }`.
#[derive(Clone, Debug, PartialEq)]
pub struct VisionPreset {
    pub name: Name,
    pub options: Vec<OptionDecl>,
    pub span: Span,
}

/// A person's `vision`: a preset, options, or a preset with more options.
#[derive(Clone, Debug, PartialEq)]
pub struct PersonVision {
    pub preset: Option<Name>,
    pub options: Vec<OptionDecl>,
    pub span: Span,
}

/// A plugin by name with its option block: `incremental { rate 0.2 }`.
#[derive(Clone, Debug, PartialEq)]
pub struct PluginUse {
    pub name: Name,
    pub options: Vec<OptionDecl>,
    pub span: Span,
}

#[derive(Clone, Debug, PartialEq)]
pub struct OptionDecl {
    pub name: Name,
    pub value: OptionValue,
    pub value_span: Span,
}

#[derive(Clone, Debug, PartialEq)]
pub enum OptionValue {
    Expr(Expr),
    Vec3(Vec3Expr),
    /// `((x, y, z), (x, y, z), ...)`.
    Points(Vec<Vec3Expr>),
    /// `[a, b]`: names, one or more.
    Names(Vec<Name>),
    Bool(bool),
    String(String),
    Plugin(PluginUse),
}

/// `reach mug, kettle by anna { ... }`
#[derive(Clone, Debug, PartialEq)]
pub struct TaskDecl {
    pub kind: Name,
    /// Subjects as dotted paths (`mug`, `counter.top`).
    pub subjects: Vec<Spanned<Vec<String>>>,
    pub persons: Vec<Name>,
    pub options: Vec<OptionDecl>,
    pub span: Span,
}
