//! Mannequins: Denavit-Hartenberg joints with limits, neutral values and
//! comfort weights, joined in a tree (`after`), and their effectors; the
//! solids of their links and spheres, their legs and posture (`legs.rs`).

use std::collections::HashMap;

use nalgebra::Vector3;

use super::eval::fmt_num;
use super::Checker;
use crate::error::{thousands, Error, ErrorKind};
use crate::kinematics::{
    Body, Coupling, Declared, Dh, Effector, Ellipse, Folded, Joint, JointKind, Link, Rhythm,
    Sphere, Stance,
};
use crate::span::Span;
use crate::span::{FileId, Name};
use crate::syntax::ast::{
    self, CoupleDecl, Expr, JointDecl, LimitsExpr, MannequinDecl, MannequinRef, RhythmDecl,
};
use crate::units::Quantity;

const DH_PARAMS: [&str; 4] = ["theta", "d", "alpha", "a"];
/// How many mannequins may name one another in a row (`a = b`, `b = c`).
/// The largest joint range a revolute limit may name: one full turn.
const MAX_ANGLE_RAD: f64 = 2.0 * std::f64::consts::PI;

impl Checker<'_> {
    /// Build every mannequin's body once (with its parameters' defaults,
    /// or an alias's), so its errors are reported once.
    pub(super) fn build_mannequins(&mut self) {
        let decls: Vec<_> = self
            .decls
            .mannequins
            .iter()
            .map(|(n, d, f)| (n.to_string(), d, f))
            .collect();
        for (name, decl, file) in decls {
            self.built.captured = Some(Vec::new());
            let body = match (&decl.alias, &decl.urdf) {
                (Some(_), _) if !decl.params.is_empty() => {
                    self.alias_with(decl, file, &[], decl.name.span, 0)
                }
                (Some(target), _) => self
                    .body_of(target, file, 0)
                    .map(|b| self.with_posture(b, decl)),
                (None, Some(urdf)) => self.in_file(file, |c| c.urdf_body(urdf)),
                (None, None) => self.body_with(decl, file, &[], decl.name.span),
            };
            if let Some(measures) = self.built.captured.take() {
                self.built.measures.insert(name.clone(), measures);
            }
            self.built.bodies.insert(name, body);
        }
    }

    /// The body of `r` (as [`Self::body_of`]) and the measurements it was
    /// built from: the parameters of the outermost mannequin with
    /// parameters, with their values.
    pub(super) fn measured_body_of(
        &mut self,
        r: &MannequinRef,
        file: FileId,
    ) -> Option<(Body, Vec<(String, Quantity)>)> {
        let outer = self.built.captured.replace(Vec::new());
        let body = self.body_of(r, file, 0);
        let measures = std::mem::replace(&mut self.built.captured, outer);
        Some((body?, measures.unwrap_or_default()))
    }

    /// The body of mannequin reference `r` (written in `file`): the named
    /// mannequin with the parameters `r` gives.
    pub(super) fn body_of(&mut self, r: &MannequinRef, file: FileId, depth: usize) -> Option<Body> {
        let (decl, decl_file) = match self.decls.mannequins.resolve(&r.name, self.cx.suggestions) {
            Ok(found) => found,
            Err(e) => {
                self.error(e);
                return None;
            }
        };
        match &decl.alias {
            Some(_) if !decl.params.is_empty() && depth < self.cx.limits.alias_chain => {
                let at = Span {
                    file,
                    ..r.name.span
                };
                self.at_the_call(at, |c| c.alias_with(decl, decl_file, &r.args, at, depth))
            }
            Some(target) if r.args.is_empty() && depth < self.cx.limits.alias_chain => self
                .body_of(target, decl_file, depth + 1)
                .map(|b| self.with_posture(b, decl)),
            Some(_) if depth >= self.cx.limits.alias_chain => {
                self.error(Error::new(
                    ErrorKind::TooLarge {
                        what: "a chain of mannequin aliases".into(),
                        limit: format!(
                            "{} (or it loops; --max-alias-chain)",
                            self.cx.limits.alias_chain
                        ),
                    },
                    r.name.span,
                ));
                None
            }
            Some(_) => {
                self.error(Error::new(
                    ErrorKind::Unsupported {
                        what: format!("parameters for `{}`, which is itself another mannequin with parameters given", r.name.value),
                        help: "give the parameters to the mannequin it names".into(),
                    },
                    r.name.span,
                ));
                None
            }
            None if r.args.is_empty() => {
                if self.built.captured.as_ref().is_some_and(Vec::is_empty) {
                    let measures = self.built.measures.get(&r.name.value).cloned();
                    self.built.captured = measures;
                }
                self.built.bodies.get(&r.name.value).cloned().flatten()
            }
            None => {
                let at = Span {
                    file,
                    ..r.name.span
                };
                self.at_the_call(at, |c| c.body_with(decl, decl_file, &r.args, at))
            }
        }
    }

    /// `build`, a mannequin built with the arguments of a call at `at`:
    /// the errors it finds in other files (a standard library mannequin
    /// the arguments make wrong: a negative radius, an angle for a length)
    /// are moved to the call, where the user can mend them.
    fn at_the_call(
        &mut self,
        at: Span,
        build: impl FnOnce(&mut Self) -> Option<Body>,
    ) -> Option<Body> {
        let before = self.cx.errors.len();
        let body = build(self);
        for e in &mut self.cx.errors[before..] {
            if e.span().is_some_and(|s| s.file != at.file) {
                *e = e.clone().moved_to(at);
            }
        }
        body
    }

    /// The body of alias `decl` (of `file`) that has parameters of its own,
    /// with `args` (written where `at`, the call, is) for them, the others at their
    /// defaults: the mannequin it names, given what it says in terms of
    /// them.
    fn alias_with(
        &mut self,
        decl: &MannequinDecl,
        file: FileId,
        args: &[(Name, Expr)],
        at: Span,
        depth: usize,
    ) -> Option<Body> {
        let target = decl.alias.as_ref()?;
        let body =
            self.with_own_params(decl, file, args, at, |c| c.body_of(target, file, depth + 1));
        body.map(|b| self.with_posture(b, decl))
    }

    /// `build` in `decl`'s file with `decl`'s parameters in scope, and only
    /// them (not a caller's): `args` (written where `at`, the mannequin's
    /// name, is) for some, the others at their defaults; nothing where a
    /// `require` is not met.
    fn with_own_params(
        &mut self,
        decl: &MannequinDecl,
        file: FileId,
        args: &[(Name, Expr)],
        at: Span,
        build: impl FnOnce(&mut Self) -> Option<Body>,
    ) -> Option<Body> {
        let given = self.in_file(at.file, |c| c.mannequin_args(decl, args));
        self.in_file(file, |c| {
            let outer = std::mem::take(&mut c.built.params);
            c.push_params(decl, &given);
            if c.built.captured.as_ref().is_some_and(Vec::is_empty) {
                let measures = c.built.params.iter();
                let measures = measures.filter_map(|(n, v)| Some((n.clone(), (*v)?)));
                c.built.captured = Some(measures.collect());
            }
            let met = c.requirements(decl, args, at);
            let body = build(c).filter(|_| met);
            c.built.params = outer;
            body
        })
    }

    /// Whether `decl`'s parameters (in scope) meet its `require`s; each
    /// one not met is an error at the first of `args` it names (else at
    /// `at`, where the mannequin is named).
    fn requirements(&mut self, decl: &MannequinDecl, args: &[(Name, Expr)], at: Span) -> bool {
        let mut met = true;
        for r in &decl.requires {
            let (Some(value), Some(bound)) = (self.eval(&r.value), self.eval(&r.bound.value))
            else {
                met = false;
                continue;
            };
            let comparison = r.bound.comparison.value;
            let Ok(difference) = value.sum(bound, -1.0) else {
                self.error(Error::new(
                    ErrorKind::Dimension {
                        expected: bound.describe(),
                        found: value.describe(),
                    },
                    r.value.span,
                ));
                met = false;
                continue;
            };
            if comparison.holds(difference.raw(), 0.0) {
                continue;
            }
            met = false;
            // The first name of the condition (the value's before the
            // bound's) that an argument gives.
            let named: Vec<&str> = [r.value.names(), r.bound.value.names()].concat();
            let span = named
                .iter()
                .find_map(|name| args.iter().find(|(n, _)| n.value == *name))
                .map_or(at, |(n, e)| Span {
                    end: e.span.end,
                    ..n.span
                });
            let shown = format!(
                "{} {} {} does not hold",
                shown_quantity(&value),
                comparison.symbol(),
                shown_quantity(&bound)
            );
            let message = r.message.clone();
            self.error(Error::new(ErrorKind::Implausible { message, shown }, span));
        }
        met
    }

    /// `decl`'s parameters, each as `given` has it or at its default (which
    /// may use the ones before it), pushed onto the scope.
    fn push_params(&mut self, decl: &MannequinDecl, given: &[(String, Option<Quantity>)]) {
        let mut seen: Vec<&Name> = Vec::new();
        for (name, default) in &decl.params {
            if let Some(first) = seen.iter().find(|n| n.value == name.value) {
                self.error(Error::duplicate("parameter", name, first.span));
            }
            seen.push(name);
            let value = match given.iter().find(|(n, _)| n == &name.value) {
                Some((_, Some(v @ Quantity::Bare { .. }))) => Some(self.as_default_is(*v, default)),
                Some((_, v)) => *v,
                None => self.eval(default),
            };
            self.built.params.push((name.value.clone(), value));
        }
    }

    /// A bare number given for a parameter whose default is a length or an
    /// angle: that, in the default unit of the file it was written in
    /// (`sitting_height 85` in a `units cm` file is 85 cm).
    fn as_default_is(&mut self, given: Quantity, default: &Expr) -> Quantity {
        let before = self.cx.errors.len();
        let kind = self.eval(default);
        // The default is only looked at, not used: its errors are not the
        // user's.
        self.cx.errors.truncate(before);
        match kind {
            Some(Quantity::Dimensioned { dim, .. }) => match given.as_dim(dim) {
                Some(value) => Quantity::dimensioned(value, dim),
                None => given,
            },
            _ => given,
        }
    }

    /// Build `decl` (of `file`) with `args` (written where `at`, the
    /// mannequin's name, is) for its parameters, the others at their
    /// defaults.
    fn body_with(
        &mut self,
        decl: &MannequinDecl,
        file: FileId,
        args: &[(Name, Expr)],
        at: Span,
    ) -> Option<Body> {
        self.with_own_params(decl, file, args, at, |c| c.body(decl))
    }

    /// The values of `args`, each checked to name a parameter of `decl`.
    fn mannequin_args(
        &mut self,
        decl: &MannequinDecl,
        args: &[(Name, Expr)],
    ) -> Vec<(String, Option<Quantity>)> {
        let mut values: Vec<(String, Option<Quantity>)> = Vec::new();
        for (name, expr) in args {
            if !decl.params.iter().any(|(p, _)| p.value == name.value) {
                let names = decl.params.iter().map(|(p, _)| p.value.as_str());
                self.error(self.unknown(
                    "parameter of this mannequin",
                    &name.value,
                    name.span,
                    names,
                ));
                continue;
            }
            if values.iter().any(|(n, _)| n == &name.value) {
                self.repeated(std::iter::once(name.span), &format!("`{}`", name.value));
                continue;
            }
            let value = self.eval(expr);
            values.push((name.value.clone(), value));
        }
        values
    }

    fn body(&mut self, decl: &MannequinDecl) -> Option<Body> {
        if decl.joints.is_empty() {
            self.error(Error::new(
                ErrorKind::Missing {
                    owner: format!("mannequin `{}`", decl.name.value),
                    what: "joints",
                },
                decl.name.span,
            ));
        }
        if !self.within_joints(decl.joints.len(), decl.name.span) {
            return None;
        }
        let mut declared = Vec::new();
        let mut parents = Vec::new();
        let mut names: Vec<&crate::span::Name> = Vec::new();
        let mut first_named: HashMap<&str, Span> = HashMap::new();
        for (i, j) in decl.joints.iter().enumerate() {
            if let Some(first) = first_named.get(j.name.value.as_str()) {
                self.error(Error::duplicate("joint", &j.name, *first));
            } else {
                first_named.insert(&j.name.value, j.name.span);
            }
            parents.push(match &j.after {
                None => Some(i.checked_sub(1)),
                Some(after) => self.earlier_joint(&names, after).map(Some),
            });
            names.push(&j.name);
            declared.push(match j.kind {
                ast::JointKind::Fixed => self.fixed_frame(j).map(Declared::Fixed),
                _ => self.joint(j).map(|j| Declared::Moving(Box::new(j))),
            });
        }
        // Folded as far as it can be, so that the effectors, spheres and
        // couplings are checked even where a joint is wrong.
        let complete = declared.iter().all(Option::is_some) && parents.iter().all(Option::is_some);
        let declared = declared
            .into_iter()
            .map(|d| d.unwrap_or_else(stand_in))
            .collect();
        let parents: Vec<Option<usize>> = parents.into_iter().map(Option::flatten).collect();
        let folded = Folded::new(declared, &parents);
        let effectors = self.effectors(decl, &names, &folded);
        let spheres = self.spheres(decl, &names, &folded);
        let legs = self.legs(decl);
        let couplings = self.couplings(decl, &names, &folded);
        let effectors = effectors?;
        if !complete {
            return None;
        }
        if decl.joints.is_empty() {
            return None;
        }
        if folded.joints.is_empty() || effectors.iter().any(|e| e.joint.is_none()) {
            // Fixed frames only (or an effector on one before any joint
            // that moves): nothing a solver could move.
            self.error(Error::new(
                ErrorKind::Missing {
                    owner: format!("mannequin `{}`", decl.name.value),
                    what: "joint that moves before each effector",
                },
                decl.name.span,
            ));
            return None;
        }
        let body = Body {
            joints: folded.joints,
            parents: folded.parents,
            effectors,
            spheres: spheres?,
            legs: legs?,
            posture: None,
            couplings: couplings?,
        };
        Some(self.with_posture(body, decl))
    }

    /// Whether a mannequin of `joints` joints is within `--max-joints`;
    /// where it is not, an error at `at`.
    pub(super) fn within_joints(&mut self, joints: usize, at: Span) -> bool {
        let most = self.cx.limits.joints;
        if joints <= most {
            return true;
        }
        let kind = ErrorKind::TooLarge {
            what: format!("a mannequin of {} joints", thousands(joints as u64)),
            limit: format!("{} (--max-joints)", thousands(most as u64)),
        };
        self.error(Error::new(kind, at));
        false
    }

    /// `body` with the posture `decl` says (its first; an error on others).
    fn with_posture(&mut self, mut body: Body, decl: &MannequinDecl) -> Body {
        self.repeated(
            decl.postures.iter().skip(1).map(|p| p.span),
            "`seated` or `standing`",
        );
        if let Some(p) = decl.postures.first() {
            body.posture = Some(match p.value {
                ast::Stance::Seated => Stance::Seated,
                ast::Stance::Standing => Stance::Standing,
            });
        }
        body
    }

    /// The link a joint or an effector declares: its radius (a length, zero
    /// or more; else the default) and its name ("the right forearm" for
    /// `link right_forearm`; else after `fallback`).
    fn link(&mut self, decl: &ast::LinkDecl, fallback: &str) -> Option<Link> {
        let name = self.single_name(&decl.name, "`link`").map_or_else(
            || format!("the link to `{fallback}`"),
            |n| part_name(&n.value),
        );
        let radius_mm = match self.single(&decl.radius, "`radius`") {
            None => Link::DEFAULT_RADIUS_MM,
            Some(e) => self.radius(e)?,
        };
        Some(Link { name, radius_mm })
    }

    /// A radius: a length, zero or more.
    pub(super) fn radius(&mut self, e: &Expr) -> Option<f64> {
        let r = self.length(e)?;
        if r < 0.0 {
            self.out_of_range(
                e.span,
                "a radius",
                "zero or more",
                &format!("{}mm", fmt_num(r)),
            );
            return None;
        }
        Some(r)
    }

    /// The first of `names`, with an error on each further one.
    fn single_name<'n>(&mut self, names: &'n [Name], what: &str) -> Option<&'n Name> {
        self.repeated(names.iter().skip(1).map(|n| n.span), what);
        names.first()
    }

    /// The spheres: on the last joint unless `after` says which.
    fn spheres(
        &mut self,
        decl: &MannequinDecl,
        joints: &[&Name],
        folded: &Folded,
    ) -> Option<Vec<Sphere>> {
        let last = joints.len().checked_sub(1);
        let mut spheres = Vec::new();
        let mut ok = true;
        for s in &decl.spheres {
            let joint = match &s.after {
                None => Some(last),
                Some(after) => self.earlier_joint(joints, after).map(Some),
            };
            let centre = self.point(&s.at);
            let radius = self.radius(&s.radius);
            match (joint, centre, radius) {
                (Some(joint), Some(centre_mm), Some(radius_mm)) => {
                    let (joint, centre_mm) = folded.point_on(joint, centre_mm);
                    spheres.push(Sphere {
                        name: part_name(&s.name.value),
                        joint,
                        centre_mm,
                        radius_mm,
                    })
                }
                _ => ok = false,
            }
        }
        ok.then_some(spheres)
    }

    /// The couplings: each `couple` of two or more distinct joints of the
    /// mannequin, and each `rhythm` (`rhythm.rs`), by moving joint.
    fn couplings(
        &mut self,
        decl: &MannequinDecl,
        joints: &[&Name],
        folded: &Folded,
    ) -> Option<Vec<Coupling>> {
        let mut ok = true;
        let mut couplings: Vec<Coupling> = Vec::new();
        for c in &decl.couples {
            let Some(indices) = self.coupled_joints(c, joints) else {
                ok = false;
                continue;
            };
            let Some(indices) = self.moving(&c.joints, &indices, folded) else {
                ok = false;
                continue;
            };
            let sorted = |j: &[usize]| {
                let mut j = j.to_vec();
                j.sort_unstable();
                j
            };
            if couplings
                .iter()
                .any(|k| matches!(k, Coupling::Ellipse(e) if sorted(&e.joints) == sorted(&indices)))
            {
                self.repeated(std::iter::once(c.span), "this coupling");
                ok = false;
                continue;
            }
            couplings.push(Coupling::Ellipse(Ellipse { joints: indices }));
        }
        for r in &decl.rhythms {
            match self.rhythm(r, joints, folded) {
                Some(rhythm)
                    if couplings.iter().any(
                        |c| matches!(c, Coupling::Rhythm(k) if k.follower == rhythm.follower),
                    ) =>
                {
                    let what = format!("a `rhythm` of `{}`", r.follower.value);
                    self.repeated(std::iter::once(r.follower.span), &what);
                    ok = false;
                }
                Some(rhythm) => couplings.push(Coupling::Rhythm(rhythm)),
                None => ok = false,
            }
        }
        ok.then_some(couplings)
    }

    /// The moving joints' indices of declared joints `indices` (`names`),
    /// with an error at each fixed one.
    fn moving(&mut self, names: &[Name], indices: &[usize], folded: &Folded) -> Option<Vec<usize>> {
        let mut ok = true;
        let mut moving = Vec::with_capacity(indices.len());
        for (name, &i) in names.iter().zip(indices) {
            match folded.moving_index(i) {
                Some(k) => moving.push(k),
                None => {
                    self.error(Error::new(
                        ErrorKind::FixedJoint {
                            joint: name.value.clone(),
                            what: "coupling".into(),
                        },
                        name.span,
                    ));
                    ok = false;
                }
            }
        }
        ok.then_some(moving)
    }

    /// The indices of a `couple`'s joints among the mannequin's `joints`:
    /// two or more, each once, each known (else its diagnostics).
    fn coupled_joints(&mut self, c: &CoupleDecl, joints: &[&Name]) -> Option<Vec<usize>> {
        if c.joints.len() < 2 {
            self.error(Error::new(
                ErrorKind::Missing {
                    owner: "this `couple`".into(),
                    what: "second joint",
                },
                c.span,
            ));
            return None;
        }
        self.named_joints(&c.joints, "couple", joints)
    }

    /// The indices of `names` (of one `couple` or `rhythm`, the
    /// `keyword`) among the mannequin's `joints`: each once, each known
    /// (else its diagnostics).
    fn named_joints(
        &mut self,
        names: &[Name],
        keyword: &str,
        joints: &[&Name],
    ) -> Option<Vec<usize>> {
        let mut ok = true;
        let mut indices = Vec::new();
        for (k, name) in names.iter().enumerate() {
            if names[..k].iter().any(|n| n.value == name.value) {
                let what = format!("joint `{}` in one `{keyword}`", name.value);
                self.repeated(std::iter::once(name.span), &what);
                ok = false;
                continue;
            }
            match joints.iter().position(|n| n.value == name.value) {
                Some(i) => indices.push(i),
                None => {
                    self.error(self.unknown(
                        "joint of this mannequin",
                        &name.value,
                        name.span,
                        joints.iter().map(|n| n.value.as_str()),
                    ));
                    ok = false;
                }
            }
        }
        ok.then_some(indices)
    }

    /// A `rhythm`: its follower and two distinct revolute drivers, joints
    /// that move, and `from` an angle from 0 up to (not including) 180 deg.
    fn rhythm(&mut self, r: &RhythmDecl, joints: &[&Name], folded: &Folded) -> Option<Rhythm> {
        let names = [
            r.follower.clone(),
            r.drivers[0].clone(),
            r.drivers[1].clone(),
        ];
        let indices = self.named_joints(&names, "rhythm", joints)?;
        let moving = self.moving(&names, &indices, folded)?;
        for (name, &k) in names.iter().zip(&moving).skip(1) {
            if folded.joints[k].kind != JointKind::Revolute {
                self.out_of_range(
                    name.span,
                    "a joint that drives a `rhythm`",
                    "a revolute joint",
                    &format!("prismatic `{}`", name.value),
                );
                return None;
            }
        }
        let from_rad = self.angle(&r.from)?;
        if !(0.0..std::f64::consts::PI).contains(&from_rad) {
            self.out_of_range(
                r.from.span,
                "a rhythm's `from`",
                "from 0deg up to 180deg",
                &show(from_rad, ast::JointKind::Revolute),
            );
            return None;
        }
        Some(Rhythm {
            follower: moving[0],
            drivers: [moving[1], moving[2]],
            from_rad,
        })
    }

    /// A `fixed` joint's frame: its turn (`theta`, `alpha`) and nothing a
    /// moving joint has (an error at each).
    fn fixed_frame(&mut self, j: &JointDecl) -> Option<nalgebra::IsometryMatrix3<f64>> {
        let mut ok = true;
        let mut refuse = |c: &mut Self, span: Option<Span>, what: &str| {
            if let Some(span) = span {
                c.error(Error::new(
                    ErrorKind::FixedJoint {
                        joint: j.name.value.clone(),
                        what: what.into(),
                    },
                    span,
                ));
                ok = false;
            }
        };
        refuse(self, j.limits.first().map(|l| l.span), "limits");
        refuse(
            self,
            j.anatomical.first().map(|l| l.span),
            "anatomical range",
        );
        refuse(self, j.neutral.first().map(|e| e.span), "neutral value");
        refuse(self, j.weight.first().map(|e| e.span), "comfort weight");
        let link = j.link.radius.first().map(|e| e.span);
        refuse(self, link.or(j.link.name.first().map(|n| n.span)), "link");
        for (key, expr) in &j.dh {
            if (key.value == "d" || key.value == "a") && self.length(expr) != Some(0.0) {
                refuse(self, Some(expr.span), "length (d or a)");
            }
        }
        let dh = self.dh(j)?;
        ok.then(|| dh.transform(dh.theta_rad, 0.0))
    }

    /// The index of joint `name` among those declared before it.
    fn earlier_joint(
        &mut self,
        earlier: &[&crate::span::Name],
        name: &crate::span::Name,
    ) -> Option<usize> {
        let found = earlier.iter().position(|n| n.value == name.value);
        if found.is_none() {
            self.error(self.unknown(
                "joint declared before this one",
                &name.value,
                name.span,
                earlier.iter().map(|n| n.value.as_str()),
            ));
        }
        found
    }

    /// The effectors: on the last joint unless `after` says which; one
    /// called `end` at the last joint when none is declared.
    fn effectors(
        &mut self,
        decl: &MannequinDecl,
        joints: &[&crate::span::Name],
        folded: &Folded,
    ) -> Option<Vec<Effector>> {
        let last = joints.len().checked_sub(1);
        if decl.effectors.is_empty() {
            let (joint, offset_mm) = folded.point_on(last, Vector3::zeros());
            return Some(vec![Effector {
                name: "end".to_string(),
                joint,
                offset_mm,
                link: Link::named("the end"),
                point: String::new(),
            }]);
        }
        let mut effectors = Vec::new();
        let mut ok = true;
        for (k, e) in decl.effectors.iter().enumerate() {
            if let Some(first) = decl.effectors[..k]
                .iter()
                .find(|f| f.name.value == e.name.value)
            {
                self.error(Error::duplicate("effector", &e.name, first.name.span));
                ok = false;
            }
            let joint = match &e.after {
                None => Some(last),
                Some(after) => self.earlier_joint(joints, after).map(Some),
            };
            let offset = self.point(&e.at);
            let link = self.link(&e.link, &e.name.value);
            self.repeated(e.point.iter().skip(1).map(|p| p.span), "`point`");
            let point = e
                .point
                .first()
                .map_or_else(String::new, |p| p.value.clone());
            match (joint, offset, link) {
                (Some(joint), Some(offset_mm), Some(link)) => {
                    let (joint, offset_mm) = folded.point_on(joint, offset_mm);
                    effectors.push(Effector {
                        name: e.name.value.clone(),
                        joint,
                        offset_mm,
                        link,
                        point,
                    })
                }
                _ => ok = false,
            }
        }
        ok.then_some(effectors)
    }

    fn joint(&mut self, j: &JointDecl) -> Option<Joint> {
        let dh = self.dh(j);
        let limits = match j.limits.as_slice() {
            [] => {
                self.error(Error::new(
                    ErrorKind::Missing {
                        owner: format!("joint `{}`", j.name.value),
                        what: "limits",
                    },
                    j.name.span,
                ));
                None
            }
            [l, rest @ ..] => {
                self.repeated(rest.iter().map(|r| r.span), "`limits`");
                self.limits(l, j.kind)
            }
        };
        let neutral = self
            .single(&j.neutral, "`neutral`")
            .map(|e| (self.joint_value(e, j.kind), e.span));
        let weight = match self.single(&j.weight, "`weight`") {
            Some(e) => self.weight(e),
            None => Some(1.0),
        };
        let link = self.link(&j.link, &j.name.value);
        let anatomical = match j.anatomical.as_slice() {
            [] => None,
            [a, rest @ ..] => {
                self.repeated(rest.iter().map(|r| r.span), "`anatomical`");
                Some((self.limits(a, j.kind)?, a.span))
            }
        };
        let (min, max) = limits?;
        if let Some(((lo, hi), span)) = anatomical {
            self.within_anatomical(&j.name.value, (min, max), (lo, hi), j.kind, span)?;
        }
        let neutral = match neutral {
            None => 0.0_f64.clamp(min, max),
            Some((value, span)) => self.neutral_within(value?, min, max, j.kind, span)?,
        };
        Some(Joint {
            name: j.name.value.clone(),
            kind: match j.kind {
                ast::JointKind::Prismatic => JointKind::Prismatic,
                ast::JointKind::Revolute | ast::JointKind::Fixed => JointKind::Revolute,
            },
            dh: dh?,
            fixed: None,
            pre: None,
            min,
            max,
            anatomical: anatomical.map(|(range, _)| range),
            neutral,
            weight: weight?,
            link: link?,
        })
    }

    /// Whether limits `(min, max)` of joint `joint` lie within its
    /// anatomical range `(lo, hi)` (else an error at `span`).
    pub(super) fn within_anatomical(
        &mut self,
        joint: &str,
        (min, max): (f64, f64),
        (lo, hi): (f64, f64),
        kind: ast::JointKind,
        span: Span,
    ) -> Option<()> {
        let slack = 1e-9;
        if min >= lo - slack && max <= hi + slack {
            return Some(());
        }
        self.error(Error::new(
            ErrorKind::BeyondAnatomical {
                joint: joint.to_string(),
                limits: format!("{} to {}", show(min, kind), show(max, kind)),
                anatomical: format!("{} to {}", show(lo, kind), show(hi, kind)),
            },
            span,
        ));
        None
    }

    fn dh(&mut self, j: &JointDecl) -> Option<Dh> {
        let mut values: [Option<f64>; 4] = [Some(0.0); 4];
        let mut seen = [false; 4];
        let mut ok = true;
        for (key, expr) in &j.dh {
            let Some(i) = DH_PARAMS.iter().position(|p| *p == key.value) else {
                self.error(self.unknown("DH parameter", &key.value, key.span, DH_PARAMS));
                ok = false;
                continue;
            };
            if seen[i] {
                self.repeated(std::iter::once(key.span), &format!("`{}`", key.value));
            }
            seen[i] = true;
            values[i] = if i % 2 == 0 {
                self.angle(expr)
            } else {
                self.length(expr)
            };
        }
        let [theta_rad, d_mm, alpha_rad, a_mm] = values;
        let dh = Dh::new(theta_rad?, d_mm?, alpha_rad?, a_mm?);
        ok.then_some(dh)
    }

    /// A joint value: an angle for revolute joints, a length for prismatic.
    fn joint_value(&mut self, e: &Expr, kind: ast::JointKind) -> Option<f64> {
        match kind {
            ast::JointKind::Revolute | ast::JointKind::Fixed => self.angle(e),
            ast::JointKind::Prismatic => self.length(e),
        }
    }

    pub(super) fn limits(&mut self, l: &LimitsExpr, kind: ast::JointKind) -> Option<(f64, f64)> {
        let min = self.joint_value(&l.min, kind);
        let max = self.joint_value(&l.max, kind);
        let (min, max) = (min?, max?);
        let mut ok = true;
        if kind == ast::JointKind::Revolute {
            for (v, e) in [(min, &l.min), (max, &l.max)] {
                if v.abs() > MAX_ANGLE_RAD + 1e-12 {
                    self.out_of_range(
                        e.span,
                        "a joint limit",
                        "between -360deg and 360deg",
                        &show(v, kind),
                    );
                    ok = false;
                }
            }
        }
        if min > max {
            self.error(Error::new(
                ErrorKind::LimitsReversed {
                    min: show(min, kind),
                    max: show(max, kind),
                },
                l.span,
            ));
            ok = false;
        }
        ok.then_some((min, max))
    }

    pub(super) fn neutral_within(
        &mut self,
        v: f64,
        min: f64,
        max: f64,
        kind: ast::JointKind,
        span: Span,
    ) -> Option<f64> {
        if v < min || v > max {
            let bound = format!(
                "within the joint's limits, {} to {}",
                show(min, kind),
                show(max, kind)
            );
            self.out_of_range(span, "the neutral value", &bound, &show(v, kind));
            return None;
        }
        Some(v)
    }

    pub(super) fn weight(&mut self, e: &Expr) -> Option<f64> {
        let w = self.number(e)?;
        if w < 0.0 {
            self.out_of_range(e.span, "a comfort weight", "zero or more", &fmt_num(w));
            return None;
        }
        Some(w)
    }

    /// The first of `exprs`, with an error on each further one.
    fn single<'e>(&mut self, exprs: &'e [Expr], what: &str) -> Option<&'e Expr> {
        self.repeated(exprs.iter().skip(1).map(|e| e.span), what);
        exprs.first()
    }

    pub(super) fn repeated(&mut self, spans: impl Iterator<Item = Span>, what: &str) {
        for span in spans {
            self.error(Error::new(
                ErrorKind::Repeated {
                    what: what.to_string(),
                },
                span,
            ));
        }
    }
}

/// A value as a user reads it: `520mm`, `30deg`, or a bare number.
fn shown_quantity(q: &Quantity) -> String {
    use crate::units::Dim;
    match *q {
        Quantity::Dimensioned { value, dim } if dim == Dim::LENGTH => {
            show(value, ast::JointKind::Prismatic)
        }
        Quantity::Dimensioned { value, dim } if dim == Dim::ANGLE => {
            show(value, ast::JointKind::Revolute)
        }
        _ => fmt_num(q.raw()),
    }
}

/// A joint in place of one with errors, so that the rest of its mannequin
/// is still checked (the mannequin is not built).
fn stand_in() -> Declared {
    Declared::Moving(Box::new(Joint::locked(
        "",
        nalgebra::IsometryMatrix3::identity(),
    )))
}

/// How a part's name reads in a report: `right_forearm` is "the right
/// forearm".
pub(super) fn part_name(name: &str) -> String {
    format!("the {}", name.replace('_', " "))
}

/// A joint value in the unit a user reads: degrees or millimetres.
pub(super) fn show(v: f64, kind: ast::JointKind) -> String {
    match kind {
        ast::JointKind::Revolute | ast::JointKind::Fixed => {
            format!("{}deg", fmt_num(v.to_degrees()))
        }
        ast::JointKind::Prismatic => format!("{}mm", fmt_num(v)),
    }
}
