//! Errors as types: every problem the tool reports about its input is an
//! [`Error`] with an [`ErrorKind`] that carries the offending token, a span
//! on the offending text, and optional extra labels. A run collects them in
//! [`Diagnostics`], which renders them with miette.

use std::fmt;

use miette::{Diagnostic, LabeledSpan, SourceCode, SourceSpan};
use thiserror::Error as ThisError;

use crate::escape::escaped;
use crate::excerpt::{Excerpt, CONTEXT_LINES};
use crate::source::{Place, Sources};
use crate::span::{Name, Span};

/// What went wrong. Each variant carries what the message needs.
#[derive(Clone, Debug, PartialEq, ThisError)]
pub enum ErrorKind {
    // ------------------------------------------------------------ syntax
    #[error("expected {expected}, found {found}")]
    Syntax { expected: String, found: String },
    #[error("unknown unit `{unit}`")]
    UnknownUnit { unit: String },
    #[error("`{text}` is too large or not a finite number")]
    BadNumber { text: String },
    #[error("`units` names the {dimension} unit twice")]
    UnitsRepeated { dimension: &'static str },

    // ------------------------------------------------------------ files
    #[error("cannot read `{path}`: {reason}")]
    ReadFile { path: String, reason: String },
    #[error("`{path}` is not UTF-8 text")]
    NotUtf8 { path: String },
    #[error("`{path}` uses itself")]
    ImportCycle { path: String, chain: Vec<String> },
    #[error("there is no standard library module `std::{name}`")]
    UnknownStdModule {
        name: String,
        suggestion: Option<String>,
        available: String,
    },
    #[error("cannot use the URDF `{path}`: {reason}")]
    BadUrdf {
        path: String,
        reason: String,
        suggestion: Option<String>,
    },
    #[error("cannot load the mesh `{path}`: {reason}")]
    BadMesh { path: String, reason: String },
    #[error("a mesh's {what} must be {expected}, not `{found}`")]
    BadMeshSetting {
        what: &'static str,
        expected: &'static str,
        found: String,
    },
    #[error("cannot write `{path}`: {reason}")]
    WriteFile { path: String, reason: String },
    #[error("cannot merge `{path}`: {why}")]
    BadShard { path: String, why: String },

    // ------------------------------------------------------------ names
    #[error("unknown {what} `{name}`")]
    UnknownName {
        what: &'static str,
        name: String,
        suggestion: Option<String>,
    },
    #[error("`{name}` is in more than one room: {}", rooms.join(", "))]
    AmbiguousSurface { name: String, rooms: Vec<String> },
    /// A name in a standard's `except` that is not a target of the room
    /// checked: `is` says what it is ("a box", "a target of room `bath`").
    #[error("`{name}` is {is}: `except` names targets of the room checked")]
    NotAnElement { name: String, is: String },
    /// A standard's fixture option (`water_closet NAME`) naming what is not
    /// a box of the room checked: `is` says what it is ("a target").
    #[error("`{name}` is {is}: `{option}` names a box of the room checked")]
    NotAFixture {
        name: String,
        is: String,
        option: &'static str,
    },
    /// A standard without `in` names a fixture that some room it checks
    /// lacks.
    #[error("`{name}` is a box of room `{home}`, not of room `{room}`: without `in`, the standard checks every room")]
    FixtureNotInEveryRoom {
        name: String,
        room: String,
        home: String,
    },
    #[error("{what} `{name}` is defined twice")]
    Duplicate { what: &'static str, name: String },
    #[error("`{name}` is defined in terms of itself")]
    LetCycle { name: String },
    #[error(
        "base preset `{name}` has the name of a base plugin, which would be used in its place"
    )]
    PresetNamesPlugin { name: String },

    // ------------------------------------------------------------ values
    #[error("expected {expected}, found {found}")]
    Dimension { expected: String, found: String },
    #[error("cannot {verb} {left} and {right}")]
    Operands {
        verb: &'static str,
        left: String,
        right: String,
    },
    #[error("division by zero")]
    DivisionByZero,
    #[error("this value is not finite")]
    NotFinite,
    #[error("{what} must be {bound}, found {value}")]
    OutOfRange {
        what: String,
        bound: String,
        value: String,
    },
    #[error("the limits of `{joint}`, {limits}, go beyond its anatomical range, {anatomical}")]
    BeyondAnatomical {
        joint: String,
        limits: String,
        anatomical: String,
    },
    #[error("lower limit {min} is above upper limit {max}")]
    LimitsReversed { min: String, max: String },
    #[error("{owner} has no {what}")]
    Missing { owner: String, what: &'static str },
    #[error("{what} is given more than once")]
    Repeated { what: String },
    #[error("target `{name}` is inside box `{obstacle}`")]
    TargetInsideBox { name: String, obstacle: String },
    #[error("target `{name}` is inside mesh `{obstacle}`, which is closed")]
    TargetInsideMesh { name: String, obstacle: String },
    #[error("target `{name}` lies outside room `{room}`")]
    TargetOutsideRoom {
        name: String,
        room: String,
        bounds: String,
    },
    #[error("mixing bare numbers from files with different default units")]
    MixedDefaults,
    /// A base the scenario puts outside the room (a fixed base's `at`); a
    /// mobile base that fits nowhere is an answer of the run, not an error.
    #[error("the {base} base of `{person}` {} room `{room}`", outside_words(base))]
    BaseOutsideRoom {
        person: String,
        base: String,
        room: String,
    },
    #[error("{what} exceeds the limit of {limit}")]
    TooLarge { what: String, limit: String },
    #[error(
        "the tasks may need up to {} solver starts, more than the limit of {}",
        thousands(*.total),
        thousands(*.limit)
    )]
    TooManyStarts {
        total: u64,
        limit: u64,
        /// The share of the declaration that asks the most.
        decl_starts: u64,
    },
    #[error(
        "the run needed more solver work than the limit of {} units, and was stopped",
        thousands(*.limit)
    )]
    TooMuchWork { limit: u64 },
    #[error(
        "the run needed more solver work than the limit of {} units: {answered} of {tasks} tasks answered, the rest not evaluated",
        thousands(*.limit)
    )]
    StoppedPartway {
        limit: u64,
        /// The tasks answered (those before the first not evaluated).
        answered: usize,
        /// Every task of the run, the standards included.
        tasks: usize,
        /// The work that was left for the first task not evaluated (it
        /// alone needs more).
        left: u64,
        /// That task, in words: `mug_shelf by ann`.
        first: String,
    },
    #[error(
        "`limits` raises {name} to {}, above the {} this run lets a file raise it to",
        thousands(*.asked),
        thousands(*.ceiling)
    )]
    AboveCeiling {
        name: &'static str,
        asked: u64,
        ceiling: u64,
        /// The command line's option for this bound (`--max-solver-work`).
        flag: &'static str,
    },
    #[error("the mannequin `{mannequin}` passes through itself at rest: {part} meets {other}")]
    MeetsItself {
        mannequin: String,
        part: String,
        other: String,
    },
    #[error("{what} is not supported yet")]
    Unsupported { what: String, help: String },
    /// A mannequin's `require` that its parameters break.
    #[error("{message}")]
    Implausible { message: String, shown: String },
    #[error("joint `{joint}` is fixed: it takes no {what}")]
    FixedJoint { joint: String, what: String },
    #[error("{what} belong in the scenario file, not in a file it uses")]
    Misplaced { what: &'static str },
    #[error("an object of {size} is legible nowhere: its nearest distance {d_min} is beyond its farthest {d_max}")]
    Illegible {
        size: String,
        d_min: String,
        d_max: String,
    },
    #[error("the mannequin `{mannequin}` of `{person}` has no effector `{effector}`")]
    NoEffector {
        person: String,
        mannequin: String,
        effector: String,
        available: String,
    },
    #[error("effector `{effector}` of `{person}` has no look link")]
    NoLookLink { effector: String, person: String },
    #[error("effector `{effector}` of `{person}` is a line of sight, not a hand")]
    LookLinkReaches { effector: String, person: String },

    // ------------------------------------------------------------ plugins
    #[error("unknown {kind} `{name}`")]
    UnknownPlugin {
        kind: &'static str,
        name: String,
        suggestion: Option<String>,
        available: String,
    },
    #[error("{plugin} has no option `{name}`")]
    UnknownOption {
        plugin: String,
        name: String,
        suggestion: Option<String>,
        available: String,
    },
    #[error("option `{name}` of {plugin} must be given")]
    MissingOption { plugin: String, name: String },
    #[error("{plugin}: {message}")]
    BadOption { plugin: String, message: String },
    #[error("the {base} base does not suit `{person}`: {reason}")]
    Unfit {
        person: String,
        base: String,
        reason: String,
    },

    // ------------------------------------------------------------ expectations
    /// An expectation no task (or standard) of the scenario answers.
    #[error("nothing answers whether {claim}")]
    NothingToExpect { claim: String, hint: String },
    /// An expectation that cannot be asked so.
    #[error("{what}")]
    BadExpectation { what: String, help: String },
}

impl ErrorKind {
    /// A stable code, shown by miette and usable by tools.
    pub fn code(&self) -> &'static str {
        use ErrorKind::*;
        match self {
            Syntax { .. } => "reach::syntax",
            UnknownUnit { .. } | UnitsRepeated { .. } => "reach::unit",
            BadNumber { .. } | NotFinite | DivisionByZero => "reach::number",
            ReadFile { .. }
            | NotUtf8 { .. }
            | WriteFile { .. }
            | BadShard { .. }
            | BadMesh { .. }
            | BadMeshSetting { .. }
            | BadUrdf { .. } => "reach::file",
            MeetsItself { .. } | FixedJoint { .. } => "reach::body",
            ImportCycle { .. } | UnknownStdModule { .. } => "reach::use",
            UnknownName { .. }
            | AmbiguousSurface { .. }
            | NotAnElement { .. }
            | NotAFixture { .. }
            | FixtureNotInEveryRoom { .. }
            | Duplicate { .. }
            | LetCycle { .. }
            | PresetNamesPlugin { .. } => "reach::name",
            Dimension { .. } | Operands { .. } | MixedDefaults => "reach::unit",
            OutOfRange { .. }
            | LimitsReversed { .. }
            | Implausible { .. }
            | BeyondAnatomical { .. } => "reach::range",
            Missing { .. } | Repeated { .. } | TargetOutsideRoom { .. } => "reach::scene",
            TargetInsideBox { .. } | TargetInsideMesh { .. } => "reach::scene",
            Unsupported { .. } | Misplaced { .. } | NoLookLink { .. } => "reach::scene",
            LookLinkReaches { .. } => "reach::scene",
            Illegible { .. } => "reach::range",
            NoEffector { .. } => "reach::name",
            TooLarge { .. } | TooManyStarts { .. } | TooMuchWork { .. } => "reach::limit",
            StoppedPartway { .. } => "reach::limit",
            AboveCeiling { .. } => "reach::limit",
            BaseOutsideRoom { .. } => "reach::scene",
            UnknownPlugin { .. }
            | UnknownOption { .. }
            | MissingOption { .. }
            | BadOption { .. } => "reach::plugin",
            NothingToExpect { .. } | BadExpectation { .. } => "reach::expect",
            Unfit { .. } => "reach::scene",
        }
    }

    /// The text of the label under the offending span.
    pub fn label(&self) -> String {
        use ErrorKind::*;
        match self {
            Syntax { expected, .. } if expected.len() <= 40 => format!("expected {expected}"),
            Syntax { .. } => "unexpected here".into(),
            UnknownUnit { .. } => "not a unit".into(),
            BadNumber { .. } => "too large or malformed".into(),
            UnitsRepeated { .. } => "second unit of this kind".into(),
            ReadFile { .. } => "used here".into(),
            BadMesh { .. } => "loaded here".into(),
            BadMeshSetting { expected, .. } => format!("not {expected}"),
            BadUrdf { .. } => "here".into(),
            MeetsItself { .. } => "this mannequin".into(),
            FixedJoint { .. } => "not for a fixed joint".into(),
            NotUtf8 { .. } => "the first byte that is not UTF-8".into(),
            ImportCycle { .. } => "this `use` closes the cycle".into(),
            UnknownStdModule { .. } => "no such module".into(),
            WriteFile { .. } => "here".into(),
            BadShard { .. } => "the scenario".into(),
            UnknownName { what, .. } => format!("no {what} of this name"),
            AmbiguousSurface { .. } => "which room's?".into(),
            NotAnElement { .. } => "not a target of this room".into(),
            NotAFixture { .. } => "not a box of this room".into(),
            FixtureNotInEveryRoom { .. } => "named for every room".into(),
            Duplicate { .. } => "defined again here".into(),
            LetCycle { .. } => "used in its own definition".into(),
            PresetNamesPlugin { .. } => "a base plugin's name".into(),
            Dimension { found, .. } => format!("this is {found}"),
            Operands { .. } => "incompatible units".into(),
            DivisionByZero => "this is zero".into(),
            NotFinite => "overflows".into(),
            OutOfRange { value, .. } => value.clone(),
            LimitsReversed { .. } => "min > max".into(),
            BeyondAnatomical { .. } => "beyond every published normal range".into(),
            Implausible { shown, .. } => shown.clone(),
            Missing { what, .. } => format!("no {what} given here"),
            Repeated { .. } => "given again here".into(),
            TargetOutsideRoom { .. } => "outside the room".into(),
            TargetInsideBox { .. } => "inside the box".into(),
            TargetInsideMesh { .. } => "inside the mesh".into(),
            MixedDefaults => "bare numbers with different default units".into(),
            Unsupported { .. } => "not supported".into(),
            TooLarge { .. } => "too large".into(),
            TooManyStarts { decl_starts, .. } => {
                format!("these tasks: up to {} starts", thousands(*decl_starts))
            }
            TooMuchWork { .. } => "the tasks that may ask the most".into(),
            StoppedPartway { left, first, .. } => format!(
                "not evaluated from `{first}` on: it alone needs more than the {} units left",
                thousands(*left)
            ),
            AboveCeiling { .. } => "above the ceiling".into(),
            BaseOutsideRoom { .. } => "cannot be placed for this task".into(),
            Misplaced { .. } => "in a used file".into(),
            Illegible { .. } => "for this size".into(),
            NoLookLink { .. } => "for this person".into(),
            LookLinkReaches { .. } => "not a hand".into(),
            NoEffector { .. } => "for this person".into(),
            UnknownPlugin { kind, .. } => format!("no {kind} of this name"),
            UnknownOption { .. } => "unknown option".into(),
            MissingOption { .. } => "needs this option".into(),
            BadOption { .. } => "here".into(),
            Unfit { .. } => "for this person".into(),
            NothingToExpect { .. } => "no task asks this".into(),
            BadExpectation { .. } => "here".into(),
        }
    }

    /// A line of advice, where one helps.
    pub fn help(&self) -> Option<String> {
        use ErrorKind::*;
        match self {
            OutOfRange { bound, value, .. } if bound == "from 0 % to 100 %" => {
                let percent = value.parse::<f64>().ok().filter(|v| *v > 1.0 && *v <= 100.0);
                percent.map(|_| {
                    format!("a share is a fraction of 1 or written with `%`: `{value} %`")
                })
            }
            Syntax { found, .. } if found.starts_with("`#") => {
                Some("a comment starts with `//` (or is `/* ... */`), not `#`".into())
            }
            UnknownUnit { .. } | UnitsRepeated { .. } => Some(
                "lengths: mm, cm, m, in; angles: deg, rad, arcmin (write the unit right after the number: `90deg`)"
                    .into(),
            ),
            BadNumber { .. } | NotFinite => Some("numbers must be finite and at most 2^53 (9007199254740992)".into()),
            ImportCycle { chain, .. } => Some(format!("the cycle: {}", chain.join(" -> "))),
            FixtureNotInEveryRoom { home, .. } => {
                Some(format!("check that room alone: `standard ... in {home} {{ ... }}`"))
            }
            UnknownStdModule {
                suggestion,
                available,
                ..
            } => Some(did_you_mean(suggestion, &format!("modules: {available}"))),
            AmbiguousSurface { name, rooms } => Some(format!(
                "name the room: `{}.{name}`",
                rooms.first().map_or("", String::as_str)
            )),
            UnknownName {
                what,
                name,
                suggestion,
                ..
            } => std_home(what, name).or_else(|| suggestion.as_ref().map(|s| format!("did you mean `{s}`?"))),
            BadUrdf { suggestion, .. } => {
                suggestion.as_ref().map(|s| format!("did you mean `{s}`?"))
            }
            Dimension { expected, .. } => Some(match example_of(expected) {
                Some(example) => format!("write {expected}, such as {example}"),
                None => format!("write {expected}"),
            }),
            Operands { .. } => Some("both sides of + and - must have the same kind of unit".into()),
            PresetNamesPlugin { name } => Some(format!(
                "give the preset another name (`reach plugins` lists the plugins'); a person's `base {name}` means the plugin"
            )),
            MeetsItself { .. } => Some(
                "a body that meets itself in its neutral posture meets itself in every posture near it, so no answer would mean anything: give its links smaller radii (`link NAME radius 20mm` on a joint; `radius 20mm` after a URDF mannequin's `tip`) or lengths that keep them apart"
                    .into(),
            ),
            BeyondAnatomical { .. } => Some(
                "a joint's anatomical range (its mannequin's `anatomical`; std::body's are the widest of the published normal ranges, docs/references.md) is what no measured range goes beyond: check the value and its sign (std::body's signs are in stdlib/body.reach); for a person known to move further, give the mannequin a wider `anatomical` range"
                    .into(),
            ),
            Implausible { .. } => Some(
                "the mannequin requires it (a `require` in its declaration): check the measurements given, and that each is the one its parameter names"
                    .into(),
            ),
            FixedJoint { .. } => Some(
                "a fixed joint only turns the axes of the joints after it (`dh(theta .., alpha ..)`): give lengths, limits, solids and couplings to the joints that move"
                    .into(),
            ),
            TargetOutsideRoom { bounds, .. } => Some(format!("the room spans {bounds}")),
            TargetInsideBox { .. } => Some(
                "a box is solid: nothing inside it can be reached or seen; model an open cabinet as boards, or put the target on the box's surface".into(),
            ),
            TargetInsideMesh { .. } => Some(
                "a closed mesh is solid, as a box is: nothing inside it can be reached or seen; put the target on its surface (an open mesh, a scan's surface, blocks only its surface)".into(),
            ),
            MixedDefaults => Some("write the units on these numbers".into()),
            BadShard { .. } => Some("merge the files of `reach run FILE --shard K/N` for every K from 1 to the same N, run on the same scenario files by the same version of reach".into()),
            Unsupported { help, .. } => Some(help.clone()),
            TooLarge { limit, .. } => Some(match limit.split_once("(--") {
                Some((_, flag)) => format!(
                    "ask for less, or raise the limit with --{} (up to its ceiling: docs/language.md, \"Limits\")",
                    flag.trim_end_matches(')')
                ),
                None => "ask for less; the limits are in docs/language.md, \"Limits\"".into(),
            }),
            TooManyStarts { .. } => Some(
                "ask less (a coarser `step`, fewer `starts`, `headings` or `blocked_retries`), or raise the bound: `limits { solver_starts N }` in the file (up to --max-limits-raise times the command line's), or --max-solver-starts".into(),
            ),
            TooMuchWork { .. } => Some(
                "ask less (a coarser `step`; fewer `starts`, `blocked_retries` or iterations: `max_iterations`, `sweeps`, `samples`, `kicks`; in a room with doors, whose routes count too, or one so crowded that the base fits only far from where it is asked to, whose floor counts too: fewer people or `headings`), or raise the bound: `limits { solver_work N }` in the file (up to --max-limits-raise times the command line's), or --max-solver-work (`reach check --estimate` says how much each task needs); no answer of this run is shown, since some were cut short".into(),
            ),
            StoppedPartway { .. } => Some(
                "the answers before this task are shown; for the rest, ask less (a coarser `step`; fewer people, `starts`, `blocked_retries` or `headings`) or raise the bound: `limits { solver_work N }` in the file (up to --max-limits-raise times the command line's), or --max-solver-work (`reach check --estimate` says how much each task needs)".into(),
            ),
            BaseOutsideRoom { .. } => Some("a fixed base must stand inside the room (check its `at`), and a moving base's zone must meet its floor (check `zone`, or `zone_from` and `zone_to`)".into()),
            AboveCeiling { asked, flag, .. } => Some(format!(
                "a file may raise a bound at most --max-limits-raise times (10 by default) the command line's: run it with {flag} {asked}, or with a larger --max-limits-raise, if you trust it to run that long"
            )),
            Misplaced { .. } => Some("move it to the file you run, which can `use` this one".into()),
            Illegible { .. } => Some(
                "D_max = size / (5 tan mar_far); the nearest is `near_point`, or size / (5 tan mar_near) when `mar_near` is given: raise the size or lower `near_point`".into(),
            ),
            NoEffector { available, .. } => Some(format!(
                "its effectors: {available}; a gaze needs one whose chain ends in a look link, as `eyes` of std::body's `upper_body`"
            )),
            NoLookLink { .. } => Some(
                "a gaze effector's chain ends in a prismatic joint along the line of sight, as `eyes` of std::body's `upper_body`".into(),
            ),
            LookLinkReaches { .. } => Some(
                "its chain ends in a look link, which stretches along the line of sight to whatever it is aimed at, so it would \"reach\" anything in view: name a hand's point (`grip`, `thumb_tip`, `fingertip`, or their `left_` twins) or leave `effector` out; whether the eyes see a target is a `gaze`".into(),
            ),
            UnknownPlugin {
                kind,
                name,
                suggestion,
                available,
                ..
            } => std_home(kind, name)
                .or_else(|| Some(did_you_mean(suggestion, &format!("available: {available}")))),
            UnknownOption {
                suggestion,
                available,
                ..
            } => Some(did_you_mean(suggestion, &format!("available: {available}"))),
            LetCycle { .. } => Some("a `let` cannot depend on itself, directly or through others".into()),
            NothingToExpect { hint, .. } | BadExpectation { help: hint, .. } => Some(hint.clone()),
            _ => None,
        }
    }
}

/// How a base is outside a room: a fixed one stands there; a moving one
/// is kept to a zone there.
fn outside_words(base: &str) -> &'static str {
    if base == "fixed" {
        "stands outside"
    } else {
        "is kept to a zone outside"
    }
}

/// Where an unknown `name` of this kind is declared in a module of the
/// standard library the file does not use: "add `use std::people`".
fn std_home(what: &str, name: &str) -> Option<String> {
    let keyword = match what {
        "mannequin" | "profile" | "vision" | "population" => what,
        "base" | "base preset" => "base",
        _ => return None,
    };
    let module = crate::std_texts::home_of(keyword, name)?;
    Some(format!(
        "`{name}` is a {keyword} of std::{module}: add `use std::{module}` at the top of the file"
    ))
}

fn did_you_mean(suggestion: &Option<String>, otherwise: &str) -> String {
    match suggestion {
        Some(s) => format!("did you mean `{s}`? ({otherwise})"),
        None => otherwise.to_string(),
    }
}

fn example_of(expected: &str) -> Option<&'static str> {
    let example = if expected.contains("list of points") {
        "`((0, 0, 0), (900, 0, 0), (900, 600, 0))`"
    } else if expected.contains("point") {
        "`(900, 600, 0)`"
    } else if expected.contains("length") {
        "`900mm`"
    } else if expected.contains("angle") {
        "`45deg`"
    } else if expected.contains("whole number") {
        "`6`"
    } else if expected.contains("true or false") {
        "`true`"
    } else if expected.contains("number") {
        "`0.5`"
    } else {
        return None;
    };
    Some(example)
}

/// One diagnostic: a kind, where it is, and extra labelled places. Boxed,
/// so that a `Result` carrying one stays small.
#[derive(Clone, Debug)]
pub struct Error(Box<ErrorData>);

#[derive(Clone, Debug)]
struct ErrorData {
    kind: ErrorKind,
    span: Option<Span>,
    /// Further labels in the same file, such as "first defined here".
    notes: Vec<(Span, String)>,
    /// What the diagnostic shows of its file, and its labels (the span's,
    /// then the notes') moved onto that; set by [`Diagnostics::attach`].
    shown: Option<(Excerpt, Vec<SourceSpan>)>,
    /// Where the span, then each note, is in its file; set by
    /// [`Diagnostics::attach`].
    places: Vec<Place>,
}

impl Error {
    pub fn new(kind: ErrorKind, span: Span) -> Self {
        Error(Box::new(ErrorData {
            kind,
            span: Some(span),
            notes: Vec::new(),
            shown: None,
            places: Vec::new(),
        }))
    }

    /// An error that belongs to no place in a file (a missing input file).
    pub fn unplaced(kind: ErrorKind) -> Self {
        Error(Box::new(ErrorData {
            kind,
            span: None,
            notes: Vec::new(),
            shown: None,
            places: Vec::new(),
        }))
    }

    /// A second definition of `name`, a `what` ("joint", "target"), at
    /// `name`'s span, with a note at the `first` one.
    pub fn duplicate(what: &'static str, name: &Name, first: Span) -> Self {
        let kind = ErrorKind::Duplicate {
            what,
            name: name.value.clone(),
        };
        Error::new(kind, name.span).with_note(first, "first defined here")
    }

    /// An unknown name: `name`, a `what` ("target", "room"), at `span`,
    /// with the nearest of the `known` names as a suggestion (while the
    /// check's `suggestions` last).
    pub fn unknown<'a>(
        what: &'static str,
        (name, span): (&str, Span),
        known: impl IntoIterator<Item = &'a str>,
        suggestions: &crate::names::Suggestions,
    ) -> Self {
        let kind = ErrorKind::UnknownName {
            what,
            name: name.to_string(),
            suggestion: suggestions.suggest(name, known),
        };
        Error::new(kind, span)
    }

    /// This error at `span` instead, without its notes: where a caller's
    /// arguments made a mannequin of another file wrong, the error belongs
    /// at the call, which the user can change.
    pub fn moved_to(mut self, span: Span) -> Self {
        self.0.span = Some(span);
        self.0.notes.clear();
        self
    }

    pub fn with_note(mut self, span: Span, text: impl Into<String>) -> Self {
        self.0.notes.push((span, text.into()));
        self
    }

    pub fn kind(&self) -> &ErrorKind {
        &self.0.kind
    }

    /// Where the error is, if it is in a file.
    pub fn span(&self) -> Option<Span> {
        self.0.span
    }

    /// Its labels with where each is: the error's own (its label), then
    /// each note's; empty for an error in no file, or before
    /// [`Diagnostics::attach`].
    pub fn placed_labels(&self) -> Vec<(&Place, String)> {
        let texts = std::iter::once(self.0.kind.label())
            .chain(self.0.notes.iter().map(|(_, text)| text.clone()));
        self.0.places.iter().zip(texts).collect()
    }

    fn attach(&mut self, sources: &Sources) {
        let data = &mut *self.0;
        if let Some(span) = data.span {
            if (span.file.0 as usize) < sources.len() {
                data.notes.retain(|(s, _)| s.file == span.file);
                let file = sources.get(span.file);
                let labels: Vec<(usize, usize)> = std::iter::once(span)
                    .chain(data.notes.iter().map(|(s, _)| *s))
                    .map(|s| (s.start as usize, s.end as usize))
                    .collect();
                data.shown = Some(Excerpt::new(file, &escaped(&file.name), &labels));
                data.places = labels.iter().map(|&(a, b)| file.place(a, b)).collect();
            }
        }
    }
}

/// Messages carry names and paths from files: shown escaped.
impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&escaped(&self.0.kind.to_string()))
    }
}

impl std::error::Error for Error {}

impl Diagnostic for Error {
    fn code<'a>(&'a self) -> Option<Box<dyn fmt::Display + 'a>> {
        Some(Box::new(self.0.kind.code()))
    }

    fn help<'a>(&'a self) -> Option<Box<dyn fmt::Display + 'a>> {
        self.0
            .kind
            .help()
            .map(|h| Box::new(escaped(&h).into_owned()) as Box<dyn fmt::Display>)
    }

    fn source_code(&self) -> Option<&dyn SourceCode> {
        self.0.shown.as_ref().map(|(s, _)| s as &dyn SourceCode)
    }

    fn labels(&self) -> Option<Box<dyn Iterator<Item = LabeledSpan> + '_>> {
        let (_, spans) = self.0.shown.as_ref()?;
        let label = escaped(&self.0.kind.label()).into_owned();
        let primary = LabeledSpan::new_primary_with_span(Some(label), spans[0]);
        let notes = self
            .0
            .notes
            .iter()
            .zip(&spans[1..])
            .map(|((_, text), span)| {
                LabeledSpan::new_with_span(Some(escaped(text).into_owned()), *span)
            });
        Some(Box::new(std::iter::once(primary).chain(notes)))
    }
}

/// Every error one step found, in the order of the text.
#[derive(Clone, Debug, Default)]
pub struct Diagnostics {
    pub errors: Vec<Error>,
}

impl Diagnostics {
    pub fn single(error: Error) -> Self {
        Diagnostics {
            errors: vec![error],
        }
    }

    pub fn is_empty(&self) -> bool {
        self.errors.is_empty()
    }

    pub fn len(&self) -> usize {
        self.errors.len()
    }

    /// Attach each error's file so it can be rendered on its own, and sort
    /// them by file and position.
    pub fn attach(mut self, sources: &Sources) -> Self {
        for e in &mut self.errors {
            e.attach(sources);
        }
        self.errors
            .sort_by_key(|e| e.span().map(|s| (s.file, s.start, s.end)));
        self
    }

    /// The diagnostics rendered as text: without colour and at a fixed width
    /// when `plain` (files and tests), with colour for a terminal otherwise.
    pub fn render(&self, plain: bool) -> String {
        use miette::{GraphicalReportHandler, GraphicalTheme};
        let theme = if plain {
            GraphicalTheme::unicode_nocolor()
        } else {
            GraphicalTheme::unicode()
        };
        let handler = GraphicalReportHandler::new_themed(theme)
            .with_context_lines(CONTEXT_LINES)
            .with_width(100)
            .with_links(false);
        let mut out = String::new();
        for e in &self.errors {
            let _ = handler.render_report(&mut out, e);
        }
        let n = self.errors.len();
        out.push_str(&format!(
            "{} error{} found\n",
            n,
            if n == 1 { "" } else { "s" }
        ));
        out
    }
}

impl fmt::Display for Diagnostics {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} error(s) in the scenario", self.errors.len())
    }
}

impl std::error::Error for Diagnostics {}

impl Diagnostic for Diagnostics {
    fn related<'a>(&'a self) -> Option<Box<dyn Iterator<Item = &'a dyn Diagnostic> + 'a>> {
        Some(Box::new(self.errors.iter().map(|e| e as &dyn Diagnostic)))
    }
}

impl From<Error> for Diagnostics {
    fn from(e: Error) -> Self {
        Diagnostics::single(e)
    }
}

/// `n` with commas between groups of three digits: 1,234,567.
pub(crate) fn thousands(n: u64) -> String {
    let digits = n.to_string();
    let mut out = String::with_capacity(digits.len() + digits.len() / 3);
    for (i, c) in digits.chars().enumerate() {
        if i > 0 && (digits.len() - i).is_multiple_of(3) {
            out.push(',');
        }
        out.push(c);
    }
    out
}

#[cfg(test)]
mod thousands_tests {
    use super::thousands;

    #[test]
    fn groups_of_three() {
        assert_eq!(thousands(0), "0");
        assert_eq!(thousands(999), "999");
        assert_eq!(thousands(1000), "1,000");
        assert_eq!(thousands(945_672_021_744), "945,672,021,744");
    }
}
