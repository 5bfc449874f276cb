//! Turns the pairs of the pest grammar into the AST of [`super::ast`].

use pest::iterators::{Pair, Pairs};
use pest::pratt_parser::{Assoc, Op, PrattParser};
use pest::Parser as _;
use std::sync::{LazyLock, RwLock};

use super::ast::*;
use super::expected::syntax_error;
use super::grammar::{ReachParser, Rule};
use crate::error::{Diagnostics, Error, ErrorKind};
use crate::limits::Limits;
use crate::span::{FileId, Name, Span, Spanned};
use crate::units::Unit;

/// Largest magnitude a number literal may have: 2^53, the last integer
/// below which every integer is exact in f64 (so that the largest seed can
/// be written); far beyond any room.
pub const MAX_LITERAL: f64 = 9_007_199_254_740_992.0;

/// Parse one file within the default [`Limits`].
pub fn parse_file(file: FileId, text: &str) -> Result<File, Diagnostics> {
    parse_file_within(file, text, &Limits::default())
}

/// Parse one file. Syntax errors stop at the first; errors in literals
/// (unknown units, numbers out of range) are all collected. Nesting and
/// expressions beyond `limits` are refused.
pub fn parse_file_within(file: FileId, text: &str, limits: &Limits) -> Result<File, Diagnostics> {
    if let Some(at) = too_deep(text, limits.nesting) {
        return Err(Diagnostics::single(Error::new(
            ErrorKind::TooLarge {
                what: "nesting of parentheses and braces".into(),
                limit: format!("{} levels (--max-nesting)", limits.nesting),
            },
            Span::new(file, at, at + 1),
        )));
    }
    let mut pairs =
        parse_pairs(text).map_err(|e| Diagnostics::single(syntax_error(file, text, e)))?;
    let root = pairs.next().expect("the file rule always yields one pair");
    let mut builder = Builder {
        file,
        errors: Vec::new(),
        expression_terms: limits.expression_terms,
        terms_so_far: None,
    };
    let items = root
        .into_inner()
        .filter(|p| p.as_rule() != Rule::EOI)
        .map(|p| builder.item(p))
        .collect();
    if builder.errors.is_empty() {
        Ok(File { items })
    } else {
        Err(Diagnostics {
            errors: builder.errors,
        })
    }
}

/// pest's switch for the detail of its errors is one for the process:
/// parses without it share the lock, a parse with it holds it alone.
static ERROR_DETAIL: RwLock<()> = RwLock::new(());

/// The file's pairs. The detail of every attempt, which the words of a
/// syntax error need, costs half the time of a large file: a file is
/// parsed without it, and only one that fails is parsed again with it.
fn parse_pairs(text: &str) -> Result<Pairs<'_, Rule>, pest::error::Error<Rule>> {
    {
        let _shared = ERROR_DETAIL.read().unwrap_or_else(|e| e.into_inner());
        if let Ok(pairs) = ReachParser::parse(Rule::file, text) {
            return Ok(pairs);
        }
    }
    let _alone = ERROR_DETAIL.write().unwrap_or_else(|e| e.into_inner());
    pest::set_error_detail(true);
    let parsed = ReachParser::parse(Rule::file, text);
    pest::set_error_detail(false);
    parsed
}

/// Operator precedence: unary minus binds tightest, then * and /, then
/// + and -; all left-associative.
static PRATT: LazyLock<PrattParser<Rule>> = LazyLock::new(|| {
    PrattParser::new()
        .op(Op::infix(Rule::add, Assoc::Left) | Op::infix(Rule::sub, Assoc::Left))
        .op(Op::infix(Rule::mul, Assoc::Left) | Op::infix(Rule::div, Assoc::Left))
        .op(Op::prefix(Rule::neg))
});

pub(super) struct Builder {
    file: FileId,
    errors: Vec<Error>,
    /// Most operands and operators in one expression, those inside its
    /// parentheses included: every one is a step of the recursion that
    /// builds, evaluates and drops it.
    expression_terms: usize,
    /// Operands and operators of the outermost expression being built so
    /// far; `None` outside an expression.
    terms_so_far: Option<usize>,
}

impl Builder {
    /// The pair's span without the white space and comments a rule may
    /// end with (an optional last part that is absent leaves them in).
    pub(super) fn span(&self, pair: &Pair<Rule>) -> Span {
        let s = pair.as_span();
        let end = match last_token(pair) {
            // A token: only white space may trail it.
            None => s.start() + pair.as_str().trim_end().len(),
            // Past the last inner token, only literal tokens such as `}`
            // count.
            Some(last) => {
                let after = last.as_span().end();
                after + content_len(&s.get_input()[after..s.end()])
            }
        };
        Span::new(self.file, s.start(), end)
    }

    pub(super) fn name(&self, pair: Pair<Rule>) -> Name {
        Spanned::new(pair.as_str().to_string(), self.span(&pair))
    }

    fn item(&mut self, pair: Pair<Rule>) -> Item {
        match pair.as_rule() {
            Rule::units_decl => Item::Units(self.units(pair)),
            Rule::use_decl => Item::Use(self.use_decl(pair)),
            Rule::let_decl => {
                let mut it = pair.into_inner();
                let name = self.name(it.next().unwrap());
                let value = self.expr(it.next().unwrap());
                Item::Let(LetDecl { name, value })
            }
            Rule::room => Item::Room(self.room(pair)),
            Rule::mannequin => Item::Mannequin(Box::new(self.mannequin(pair))),
            Rule::profile => {
                let mut it = pair.into_inner();
                let name = self.name(it.next().unwrap());
                let overrides = it.map(|o| self.joint_override(o)).collect();
                Item::Profile(ProfileDecl { name, overrides })
            }
            Rule::base_preset => {
                let mut it = pair.into_inner();
                let name = self.name(it.next().unwrap());
                let plugin = self.plugin_use(it.next().unwrap());
                Item::BasePreset(BasePreset { name, plugin })
            }
            Rule::vision_preset => {
                let span = self.span(&pair);
                let mut it = pair.into_inner();
                let name = self.name(it.next().unwrap());
                let options = self.options(it.next().unwrap());
                Item::VisionPreset(VisionPreset {
                    name,
                    options,
                    span,
                })
            }
            Rule::person => Item::Person(self.person(pair)),
            Rule::population => Item::Population(Box::new(self.population(pair))),
            Rule::task => Item::Task(self.task(pair)),
            Rule::standard => Item::Standard(self.standard(pair)),
            Rule::limits_decl => {
                let span = self.span(&pair);
                let options = self.options(pair.into_inner().next().unwrap());
                Item::Limits(LimitsDecl { options, span })
            }
            Rule::expect => Item::Expect(self.expect(pair)),
            r => unreachable!("item rule {r:?}"),
        }
    }

    fn units(&mut self, pair: Pair<Rule>) -> Vec<Spanned<Unit>> {
        let mut units = Vec::new();
        for word in pair.into_inner() {
            let span = self.span(&word);
            match Unit::parse(word.as_str()) {
                Some(u) => units.push(Spanned::new(u, span)),
                None => self.errors.push(Error::new(
                    ErrorKind::UnknownUnit {
                        unit: word.as_str().to_string(),
                    },
                    span,
                )),
            }
        }
        units
    }

    fn use_decl(&mut self, pair: Pair<Rule>) -> Spanned<UseTarget> {
        let span = self.span(&pair);
        let inner = pair.into_inner().next().unwrap();
        let target = match inner.as_rule() {
            Rule::std_path => {
                UseTarget::Std(inner.into_inner().next().unwrap().as_str().to_string())
            }
            _ => UseTarget::Path(unescape(inner.into_inner().next().unwrap().as_str())),
        };
        Spanned::new(target, span)
    }

    /// An expression, refused (as the number 0, with a diagnostic) if it
    /// has more terms than the limit, its parentheses' terms included.
    pub(super) fn expr(&mut self, pair: Pair<Rule>) -> Expr {
        let outermost = self.terms_so_far.is_none();
        let before = self.terms_so_far.unwrap_or(0);
        let expr = self.expr_within(pair, before);
        if outermost {
            self.terms_so_far = None;
        }
        expr
    }

    fn expr_within(&mut self, pair: Pair<Rule>, before: usize) -> Expr {
        let span = self.span(&pair);
        let pairs = pair.into_inner();
        let terms = before.saturating_add(pairs.len());
        // Once refused, the outermost expression's count stays past the
        // limit, so that its other parentheses are not refused again.
        let refused_already = before > self.expression_terms;
        self.terms_so_far = Some(terms);
        if terms > self.expression_terms {
            let kind = ExprKind::Number {
                value: 0.0,
                unit: None,
            };
            if refused_already {
                return Expr { kind, span };
            }
            // Refused before a tree of that depth is built (or dropped).
            self.errors.push(Error::new(
                ErrorKind::TooLarge {
                    what: "this expression".into(),
                    limit: format!(
                        "{} operands and operators, those in parentheses included \
                         (--max-expression-terms)",
                        self.expression_terms
                    ),
                },
                span,
            ));
            return Expr { kind, span };
        }
        let file = self.file;
        let span_of = move |p: &Pair<Rule>| {
            Span::new(
                file,
                p.as_span().start(),
                p.as_span().start() + p.as_str().trim_end().len(),
            )
        };
        let expr = PRATT
            .map_primary(|p| self.primary(p))
            .map_prefix(|op, rhs| {
                let span = span_of(&op).to(rhs.span);
                Expr {
                    kind: ExprKind::Neg(Box::new(rhs)),
                    span,
                }
            })
            .map_infix(|lhs, op, rhs| {
                let op = match op.as_rule() {
                    Rule::add => BinOp::Add,
                    Rule::sub => BinOp::Sub,
                    Rule::mul => BinOp::Mul,
                    _ => BinOp::Div,
                };
                let span = lhs.span.to(rhs.span);
                Expr {
                    kind: ExprKind::Binary(op, Box::new(lhs), Box::new(rhs)),
                    span,
                }
            })
            .parse(pairs);
        expr
    }

    fn primary(&mut self, pair: Pair<Rule>) -> Expr {
        let span = self.span(&pair);
        let kind = match pair.as_rule() {
            Rule::quantity => self.quantity(pair),
            Rule::ident => ExprKind::Name(pair.as_str().to_string()),
            Rule::call => {
                let mut it = pair.into_inner();
                let function = match it.next().map(|f| f.as_str()) {
                    Some("min") => Function::Min,
                    _ => Function::Max,
                };
                ExprKind::Call(function, it.map(|arg| self.expr(arg)).collect())
            }
            Rule::paren => {
                // The parentheses belong to the expression's span.
                let inner = self.expr(pair.into_inner().next().unwrap());
                return Expr { span, ..inner };
            }
            r => unreachable!("primary rule {r:?}"),
        };
        Expr { kind, span }
    }

    fn quantity(&mut self, pair: Pair<Rule>) -> ExprKind {
        let mut it = pair.into_inner();
        let number = it.next().unwrap();
        let text = number.as_str();
        let value: f64 = text.parse().unwrap_or(f64::INFINITY);
        // An integer beyond 2^53 would round to a neighbour unseen: its
        // digits are compared, not its rounded value.
        let integer_too_large = text.bytes().all(|b| b.is_ascii_digit())
            && text.trim_start_matches('0').len() >= 16
            && text
                .parse::<u128>()
                .map_or(true, |n| n > MAX_LITERAL as u128);
        if !value.is_finite() || value.abs() > MAX_LITERAL || integer_too_large {
            self.errors.push(Error::new(
                ErrorKind::BadNumber {
                    text: text.to_string(),
                },
                self.span(&number),
            ));
        }
        let unit = match it.next() {
            None => None,
            Some(u) if u.as_rule() == Rule::unit => Unit::parse(u.as_str()),
            Some(u) if u.as_rule() == Rule::percent => Some(Unit::Percent),
            Some(bad) => {
                self.errors.push(Error::new(
                    ErrorKind::UnknownUnit {
                        unit: bad.as_str().to_string(),
                    },
                    self.span(&bad),
                ));
                None
            }
        };
        ExprKind::Number { value, unit }
    }

    fn vec3(&mut self, pair: Pair<Rule>) -> Vec3Expr {
        let span = self.span(&pair);
        let mut it = pair.into_inner();
        let mut next = || it.next().unwrap();
        let (a, b, c) = (next(), next(), next());
        Vec3Expr {
            parts: [self.expr(a), self.expr(b), self.expr(c)],
            span,
        }
    }

    fn vec2(&mut self, pair: Pair<Rule>) -> Vec2Expr {
        let span = self.span(&pair);
        let mut it = pair.into_inner();
        let mut next = || it.next().unwrap();
        let (a, b) = (next(), next());
        Vec2Expr {
            parts: [self.expr(a), self.expr(b)],
            span,
        }
    }

    fn room(&mut self, pair: Pair<Rule>) -> RoomDecl {
        let span = self.span(&pair);
        let mut it = pair.into_inner();
        let name = self.name(it.next().unwrap());
        let items = it.map(|p| self.room_item(p)).collect();
        RoomDecl { name, items, span }
    }

    fn room_item(&mut self, pair: Pair<Rule>) -> RoomItem {
        match pair.as_rule() {
            Rule::room_size => {
                // `(x, y, z)` or `x x y x z`: both hold three expressions.
                let inner = pair.into_inner().next().unwrap();
                RoomItem::Size(self.vec3(inner))
            }
            Rule::box_decl => {
                let mut it = pair.into_inner();
                let name = self.name(it.next().unwrap());
                let at = self.vec3(it.next().unwrap());
                let size = self.vec3(it.next().unwrap());
                let rotate = it.next().map(|p| self.expr(p));
                RoomItem::Box(Box::new(BoxDecl {
                    name,
                    at,
                    size,
                    rotate,
                }))
            }
            Rule::mesh_decl => {
                let mut it = pair.into_inner();
                let name = self.name(it.next().unwrap());
                let path_pair = it.next().unwrap();
                let path_span = self.span(&path_pair);
                let path = unescape(path_pair.into_inner().next().unwrap().as_str());
                let mut mesh = MeshDecl {
                    name,
                    path: Spanned::new(path, path_span),
                    at: Vec::new(),
                    scale: Vec::new(),
                    rotate: Vec::new(),
                    unit: Vec::new(),
                    up: Vec::new(),
                };
                for prop in it {
                    let rule = prop.as_rule();
                    let inner = prop.into_inner().next().unwrap();
                    match rule {
                        Rule::mesh_at => mesh.at.push(self.vec3(inner)),
                        Rule::mesh_scale => mesh.scale.push(self.expr(inner)),
                        Rule::mesh_unit => mesh.unit.push(self.name(inner)),
                        Rule::mesh_up => mesh.up.push(self.name(inner)),
                        _ => mesh.rotate.push(self.expr(inner)),
                    }
                }
                RoomItem::Mesh(Box::new(mesh))
            }
            Rule::target_decl => {
                let mut it = pair.into_inner();
                let name = self.name(it.next().unwrap());
                let at = self.vec3(it.next().unwrap());
                RoomItem::Target(TargetDecl { name, at })
            }
            Rule::surface_decl => {
                let mut it = pair.into_inner();
                let name = self.name(it.next().unwrap());
                let at = self.vec3(it.next().unwrap());
                let size = self.vec3(it.next().unwrap());
                RoomItem::Surface(SurfaceDecl { name, at, size })
            }
            Rule::door_decl => {
                let mut it = pair.into_inner();
                let name = self.name(it.next().unwrap());
                let at = self.vec2(it.next().unwrap());
                let width = self.expr(it.next().unwrap());
                RoomItem::Door(DoorDecl { name, at, width })
            }
            r => unreachable!("room item {r:?}"),
        }
    }

    fn mannequin(&mut self, pair: Pair<Rule>) -> MannequinDecl {
        let span = self.span(&pair);
        let mut it = pair.into_inner();
        let name = self.name(it.next().unwrap());
        let mut joints = Vec::new();
        let mut effectors = Vec::new();
        let mut spheres = Vec::new();
        let mut legs = Vec::new();
        let mut couples = Vec::new();
        let mut rhythms = Vec::new();
        let mut requires = Vec::new();
        let mut postures = Vec::new();
        let mut params = Vec::new();
        let mut alias = None;
        let mut urdf = None;
        for p in it {
            match p.as_rule() {
                Rule::joint_decl => joints.push(self.joint(p)),
                Rule::sphere_decl => spheres.push(self.sphere(p)),
                Rule::legs_decl => {
                    let span = self.span(&p);
                    let args = self.call_args(p.into_inner().next().unwrap());
                    legs.push(LegsDecl { args, span });
                }
                Rule::couple_decl => {
                    let span = self.span(&p);
                    let joints = p.into_inner().map(|q| self.name(q)).collect();
                    couples.push(CoupleDecl { joints, span });
                }
                Rule::rhythm_decl => {
                    let span = self.span(&p);
                    let mut parts = p
                        .into_inner()
                        .filter(|q| !matches!(q.as_rule(), Rule::with_kw | Rule::from_kw));
                    let follower = self.name(parts.next().unwrap());
                    let drivers = [
                        self.name(parts.next().unwrap()),
                        self.name(parts.next().unwrap()),
                    ];
                    let from = self.expr(parts.next().unwrap());
                    rhythms.push(RhythmDecl {
                        follower,
                        drivers,
                        from,
                        span,
                    });
                }
                Rule::posture => postures.push(self.posture(p)),
                Rule::mannequin_urdf => {
                    let mut parts = p.into_inner();
                    let mut string = || {
                        let q = parts.next().unwrap();
                        let span = self.span(&q);
                        Spanned::new(unescape(q.into_inner().next().unwrap().as_str()), span)
                    };
                    let (path, root, tip) = (string(), string(), string());
                    let radius = parts
                        .next()
                        .map(|r| self.expr(r.into_inner().next().unwrap()));
                    urdf = Some(UrdfSource {
                        path,
                        root,
                        tip,
                        radius,
                    });
                }
                Rule::mannequin_alias => {
                    let mut parts = p.into_inner();
                    alias = Some(self.mannequin_ref(parts.next().unwrap()));
                    for q in parts {
                        match q.as_rule() {
                            Rule::require_decl => requires.push(self.require(q)),
                            _ => postures.push(self.posture(q)),
                        }
                    }
                }
                Rule::require_decl => requires.push(self.require(p)),
                Rule::mannequin_params => {
                    for param in p.into_inner() {
                        let mut kv = param.into_inner();
                        let key = self.name(kv.next().unwrap());
                        params.push((key, self.expr(kv.next().unwrap())));
                    }
                }
                _ => {
                    let mut e = p.into_inner().peekable();
                    let (name, after, at) = self.placed(&mut e);
                    let mut link = LinkDecl::default();
                    let mut point = Vec::new();
                    for q in e {
                        match q.as_rule() {
                            Rule::effector_point => {
                                let s = q.into_inner().next().unwrap();
                                let span = self.span(&s);
                                let text = s.into_inner().next().unwrap().as_str();
                                point.push(Spanned::new(unescape(text), span));
                            }
                            _ => self.link_prop(q, &mut link),
                        }
                    }
                    effectors.push(EffectorDecl {
                        name,
                        after,
                        at,
                        link,
                        point,
                    });
                }
            }
        }
        MannequinDecl {
            name,
            params,
            alias,
            urdf,
            joints,
            effectors,
            spheres,
            legs,
            couples,
            rhythms,
            requires,
            postures,
            span,
        }
    }

    /// `require value COMPARISON bound, "message"`.
    fn require(&mut self, p: Pair<Rule>) -> RequireDecl {
        let span = self.span(&p);
        let mut it = p.into_inner();
        let value = self.expr(it.next().unwrap());
        let bound = self.bound(it.next().unwrap());
        let message = unescape(it.next().unwrap().into_inner().next().unwrap().as_str());
        RequireDecl {
            value,
            bound,
            message,
            span,
        }
    }

    fn posture(&mut self, p: Pair<Rule>) -> Spanned<Stance> {
        let span = self.span(&p);
        let posture = match p.as_str() {
            "seated" => Stance::Seated,
            _ => Stance::Standing,
        };
        Spanned::new(posture, span)
    }

    /// `radius R` or `link NAME` of a joint or an effector.
    fn link_prop(&mut self, p: Pair<Rule>, link: &mut LinkDecl) {
        match p.as_rule() {
            Rule::radius => link.radius.push(self.expr(p.into_inner().next().unwrap())),
            Rule::link_name => link.name.push(self.name(p.into_inner().next().unwrap())),
            r => unreachable!("link part {r:?}"),
        }
    }

    /// `NAME [after JOINT] at (x, y, z)`: an effector's or a sphere's
    /// name, the joint it sits on if it says, and its point.
    fn placed<'i>(
        &mut self,
        e: &mut std::iter::Peekable<pest::iterators::Pairs<'i, Rule>>,
    ) -> (Name, Option<Name>, Vec3Expr) {
        let name = self.name(e.next().unwrap());
        let after = e
            .next_if(|q| q.as_rule() == Rule::after)
            .map(|q| self.name(q.into_inner().next().unwrap()));
        let at = self.vec3(e.next().unwrap());
        (name, after, at)
    }

    fn sphere(&mut self, p: Pair<Rule>) -> SphereDecl {
        let mut e = p.into_inner().peekable();
        let (name, after, at) = self.placed(&mut e);
        let radius = self.expr(e.next().unwrap().into_inner().next().unwrap());
        SphereDecl {
            name,
            after,
            at,
            radius,
        }
    }

    fn joint(&mut self, pair: Pair<Rule>) -> JointDecl {
        let mut it = pair.into_inner();
        let name = self.name(it.next().unwrap());
        let mut joint = JointDecl {
            name,
            kind: JointKind::Revolute,
            after: None,
            dh: Vec::new(),
            dh_span: Span::default(),
            limits: Vec::new(),
            anatomical: Vec::new(),
            neutral: Vec::new(),
            weight: Vec::new(),
            link: LinkDecl::default(),
        };
        for p in it {
            match p.as_rule() {
                Rule::joint_kind => {
                    joint.kind = match p.as_str() {
                        "prismatic" => JointKind::Prismatic,
                        "fixed" => JointKind::Fixed,
                        _ => JointKind::Revolute,
                    }
                }
                Rule::after => joint.after = Some(self.name(p.into_inner().next().unwrap())),
                Rule::dh => {
                    joint.dh_span = self.span(&p);
                    for param in p.into_inner() {
                        let mut kv = param.into_inner();
                        let key = self.name(kv.next().unwrap());
                        let value = self.expr(kv.next().unwrap());
                        joint.dh.push((key, value));
                    }
                }
                Rule::limits => joint.limits.push(self.limits(p)),
                Rule::anatomical => joint.anatomical.push(self.limits(p)),
                Rule::neutral => joint
                    .neutral
                    .push(self.expr(p.into_inner().next().unwrap())),
                Rule::weight => joint.weight.push(self.expr(p.into_inner().next().unwrap())),
                Rule::radius | Rule::link_name => self.link_prop(p, &mut joint.link),
                r => unreachable!("joint part {r:?}"),
            }
        }
        joint
    }

    /// `limits(min, max)`, from the pair whose inner pairs end with the two
    /// expressions.
    fn limits(&mut self, pair: Pair<Rule>) -> LimitsExpr {
        let span = self.span(&pair);
        let exprs: Vec<Pair<Rule>> = pair
            .into_inner()
            .filter(|p| p.as_rule() == Rule::expr)
            .collect();
        let mut it = exprs.into_iter();
        let min = self.expr(it.next().unwrap());
        let max = self.expr(it.next().unwrap());
        LimitsExpr { min, max, span }
    }

    fn person(&mut self, pair: Pair<Rule>) -> PersonDecl {
        let span = self.span(&pair);
        let mut it = pair.into_inner();
        let name = self.name(it.next().unwrap());
        let mut person = PersonDecl {
            name,
            mannequins: Vec::new(),
            bases: Vec::new(),
            visions: Vec::new(),
            span,
        };
        for p in it {
            self.person_item(&mut person, p);
        }
        person
    }

    /// One `mannequin`, `base` or `vision` item of a person or population.
    pub(super) fn person_item(&mut self, person: &mut PersonDecl, p: Pair<Rule>) {
        {
            match p.as_rule() {
                Rule::person_mannequin => {
                    let mut m = p.into_inner().peekable();
                    let mannequin = self.mannequin_ref(m.next().unwrap());
                    let posture = m
                        .next_if(|q| q.as_rule() == Rule::posture)
                        .map(|q| self.posture(q));
                    let overrides = m.map(|o| self.joint_override(o)).collect();
                    person.mannequins.push(PersonMannequin {
                        mannequin,
                        posture,
                        overrides,
                    });
                }
                Rule::person_vision => {
                    let span = self.span(&p);
                    let mut preset = None;
                    let mut options = Vec::new();
                    for part in p.into_inner() {
                        match part.as_rule() {
                            Rule::ident => preset = Some(self.name(part)),
                            _ => options = self.options(part),
                        }
                    }
                    person.visions.push(PersonVision {
                        preset,
                        options,
                        span,
                    });
                }
                _ => {
                    let plugin = p.into_inner().next().unwrap();
                    person.bases.push(self.plugin_use(plugin));
                }
            }
        }
    }

    /// `name` or `name(arg value, ...)`.
    fn mannequin_ref(&mut self, pair: Pair<Rule>) -> MannequinRef {
        let mut it = pair.into_inner();
        let name = self.name(it.next().unwrap());
        let args = it
            .next()
            .map(|args| self.call_args(args))
            .unwrap_or_default();
        MannequinRef { name, args }
    }

    /// `(name value, ...)`.
    fn call_args(&mut self, pair: Pair<Rule>) -> Vec<(Name, Expr)> {
        pair.into_inner()
            .map(|arg| {
                let mut kv = arg.into_inner();
                let key = self.name(kv.next().unwrap());
                (key, self.expr(kv.next().unwrap()))
            })
            .collect()
    }

    fn joint_override(&mut self, pair: Pair<Rule>) -> JointOverride {
        let rule = pair.as_rule();
        if rule == Rule::profile_use {
            let name = self.name(pair.into_inner().next().unwrap());
            return JointOverride::Profile { name };
        }
        if rule == Rule::limit_override {
            let joint = self.name(pair.clone().into_inner().next().unwrap());
            let limits = self.limits(pair);
            return JointOverride::Limits { joint, limits };
        }
        let mut it = pair.into_inner();
        let joint = self.name(it.next().unwrap());
        let value = self.expr(it.next().unwrap());
        match rule {
            Rule::neutral_override => JointOverride::Neutral { joint, value },
            _ => JointOverride::Weight { joint, value },
        }
    }

    fn plugin_use(&mut self, pair: Pair<Rule>) -> PluginUse {
        let span = self.span(&pair);
        let mut it = pair.into_inner();
        let name = self.name(it.next().unwrap());
        let options = it.next().map(|o| self.options(o)).unwrap_or_default();
        PluginUse {
            name,
            options,
            span,
        }
    }

    fn options(&mut self, pair: Pair<Rule>) -> Vec<OptionDecl> {
        pair.into_inner()
            .map(|opt| {
                let mut it = opt.into_inner();
                let name = self.name(it.next().unwrap());
                let value_pair = it.next().unwrap();
                let value_span = self.span(&value_pair);
                let v = value_pair.into_inner().next().unwrap();
                let value = match v.as_rule() {
                    Rule::vec3 => OptionValue::Vec3(self.vec3(v)),
                    Rule::point_list => {
                        OptionValue::Points(v.into_inner().map(|p| self.vec3(p)).collect())
                    }
                    Rule::name_list => {
                        OptionValue::Names(v.into_inner().map(|n| self.name(n)).collect())
                    }
                    Rule::plugin_block => OptionValue::Plugin(self.plugin_use(v)),
                    Rule::boolean => OptionValue::Bool(v.as_str() == "true"),
                    Rule::string => {
                        OptionValue::String(unescape(v.into_inner().next().unwrap().as_str()))
                    }
                    _ => OptionValue::Expr(self.expr(v)),
                };
                OptionDecl {
                    name,
                    value,
                    value_span,
                }
            })
            .collect()
    }

    fn expect(&mut self, pair: Pair<Rule>) -> ExpectDecl {
        let span = self.span(&pair);
        // As written, without a comment the rule's span may take in after
        // it (an expectation holds no strings, so `//` or `/*` starts one).
        let written = pair.as_str().trim_start_matches("expect");
        let written = written.split("//").next().unwrap_or_default();
        let written = written.split("/*").next().unwrap_or_default();
        let text = written.split_whitespace().collect::<Vec<_>>().join(" ");
        let inner = pair.into_inner().next().unwrap();
        let claim = match inner.as_rule() {
            Rule::expect_share => {
                let mut it = inner.into_inner().skip(1).peekable();
                let population = self.name(it.next().unwrap());
                let subject = self.subject_path(it.next().unwrap());
                let task = it
                    .next_if(|p| p.as_rule() == Rule::ident)
                    .map(|p| self.name(p));
                let bound = self.bound(it.next().unwrap());
                Claim::Share {
                    population,
                    subject,
                    task,
                    bound,
                }
            }
            Rule::expect_advice => {
                let mut it = inner.into_inner().skip(1);
                let subject = self.subject_path(it.next().unwrap());
                let share = self.expr(it.nth(1).unwrap());
                let from = self.expr(it.nth(1).unwrap());
                let to = self.expr(it.nth(1).unwrap());
                Claim::Advice {
                    subject,
                    share,
                    from,
                    to,
                }
            }
            Rule::expect_meets => {
                let mut it = inner.into_inner();
                let room = self.name(it.next().unwrap());
                let standard = self.name(it.nth(1).unwrap());
                Claim::Meets { room, standard }
            }
            _ => {
                let mut it = inner.into_inner().peekable();
                let who = self.name(it.next().unwrap());
                let negated = it.next_if(|p| p.as_rule() == Rule::negation).is_some();
                let verb_pair = it.next().unwrap();
                let verb = match verb_pair.as_str() {
                    "reaches" => Verb::Reaches,
                    "sees" => Verb::Sees,
                    _ => Verb::Covers,
                };
                let verb = Spanned::new(verb, self.span(&verb_pair));
                let subject = self.subject_path(it.next().unwrap());
                let bound = it.next().map(|p| self.bound(p));
                Claim::Person {
                    who,
                    negated,
                    verb,
                    subject,
                    bound,
                }
            }
        };
        ExpectDecl { claim, text, span }
    }

    /// `counter.top`: a subject's dotted path.
    fn subject_path(&mut self, pair: Pair<Rule>) -> Spanned<Vec<String>> {
        let span = self.span(&pair);
        let path = pair.into_inner().map(|p| p.as_str().to_string()).collect();
        Spanned::new(path, span)
    }

    fn bound(&mut self, pair: Pair<Rule>) -> Bound {
        let mut it = pair.into_inner();
        let op = it.next().unwrap();
        let comparison = match op.as_str() {
            ">=" => Comparison::AtLeast,
            "<=" => Comparison::AtMost,
            ">" => Comparison::Above,
            _ => Comparison::Below,
        };
        let comparison = Spanned::new(comparison, self.span(&op));
        Bound {
            comparison,
            value: self.expr(it.next().unwrap()),
        }
    }

    fn standard(&mut self, pair: Pair<Rule>) -> StandardDecl {
        let span = self.span(&pair);
        let mut it = pair.into_inner().peekable();
        let name = self.name(it.next().unwrap());
        let room = it
            .next_if(|p| p.as_rule() == Rule::in_room)
            .and_then(|_| it.next())
            .map(|p| self.name(p));
        let except = it
            .next_if(|p| p.as_rule() == Rule::except)
            .map(|p| {
                let list = p.into_inner().nth(1).unwrap();
                list.into_inner().map(|n| self.name(n)).collect()
            })
            .unwrap_or_default();
        let options = it.next().map(|o| self.options(o)).unwrap_or_default();
        StandardDecl {
            name,
            room,
            except,
            options,
            span,
        }
    }

    fn task(&mut self, pair: Pair<Rule>) -> TaskDecl {
        let span = self.span(&pair);
        let mut it = pair.into_inner();
        let mut kind = self.name(it.next().unwrap());
        let subjects = it
            .next()
            .unwrap()
            .into_inner()
            .map(|s| {
                let span = self.span(&s);
                let path = s.into_inner().map(|p| p.as_str().to_string()).collect();
                Spanned::new(path, span)
            })
            .collect();
        let mut it = it.peekable();
        if let Some(and) = it.next_if(|p| p.as_rule() == Rule::and_task) {
            // `reach mug and gaze` runs the task plugin `reach_and_gaze`.
            let second = self.name(and.into_inner().next().unwrap());
            kind = Spanned::new(
                format!("{}_and_{}", kind.value, second.value),
                kind.span.to(second.span),
            );
        }
        let persons = it
            .next()
            .unwrap()
            .into_inner()
            .map(|p| self.name(p))
            .collect();
        let options = it.next().map(|o| self.options(o)).unwrap_or_default();
        TaskDecl {
            kind,
            subjects,
            persons,
            options,
            span,
        }
    }
}

/// Where parentheses and braces first nest deeper than `max_depth`, if
/// they do; comments and strings are skipped. Checked before pest sees the
/// text, whose recursive descent would otherwise follow the nesting on the
/// stack.
fn too_deep(text: &str, max_depth: usize) -> Option<usize> {
    let mut depth = 0usize;
    for (i, b) in super::code::code_bytes(text) {
        match b {
            b'(' | b'{' => {
                depth += 1;
                if depth > max_depth {
                    return Some(i);
                }
            }
            b')' | b'}' => depth = depth.saturating_sub(1),
            _ => {}
        }
    }
    None
}

/// The last innermost pair within `pair` (none if `pair` has no inner
/// pairs): followed down the last child, so as deep as the pair, not as
/// large.
fn last_token<'i>(pair: &Pair<'i, Rule>) -> Option<Pair<'i, Rule>> {
    let mut last = pair.clone().into_inner().last()?;
    while let Some(child) = last.clone().into_inner().last() {
        last = child;
    }
    Some(last)
}

/// How much of `text` (the end of a rule, after its last inner pair) is
/// more than white space and comments: up to its last other character.
fn content_len(text: &str) -> usize {
    let bytes = text.as_bytes();
    let (mut i, mut end) = (0, 0);
    while i < bytes.len() {
        if bytes[i..].starts_with(b"//") {
            while i < bytes.len() && bytes[i] != b'\n' {
                i += 1;
            }
        } else if bytes[i..].starts_with(b"/*") {
            i += 2;
            while i < bytes.len() && !bytes[i..].starts_with(b"*/") {
                i += 1;
            }
            i += 2;
        } else {
            if !bytes[i].is_ascii_whitespace() {
                end = i + 1;
            }
            i += 1;
        }
    }
    end.min(bytes.len())
}

/// The text of a string literal: `\x` stands for `x`.
fn unescape(raw: &str) -> String {
    let mut out = String::with_capacity(raw.len());
    let mut chars = raw.chars();
    while let Some(c) = chars.next() {
        if c == '\\' {
            if let Some(n) = chars.next() {
                out.push(n);
            }
        } else {
            out.push(c);
        }
    }
    out
}
