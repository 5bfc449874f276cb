//! Evaluating expressions: `let` constants (in any order, cycles are
//! errors), arithmetic with unit checking, and conversion to the kind of
//! value the place of use expects.

use nalgebra::Vector3;

use super::Checker;
use crate::error::{Error, ErrorKind};
use crate::span::Span;
use crate::syntax::ast::{BinOp, Expr, ExprKind, Function, Vec3Expr};
use crate::units::{Dim, Quantity, QuantityError};

impl Checker<'_> {
    /// Evaluate every `let` once, so that an error in a definition is
    /// reported there, once, whether or not it is used.
    pub(super) fn evaluate_lets(&mut self) {
        let names: Vec<String> = self.decls.lets.names().map(str::to_string).collect();
        for name in names {
            self.let_value(&name, None);
        }
    }

    /// Every constant that has a value, by name (for the editor's hover).
    pub(super) fn constants(&self) -> Vec<(String, Quantity)> {
        let mut constants: Vec<(String, Quantity)> = (self.built.let_values.iter())
            .filter_map(|(name, value)| Some((name.clone(), (*value)?)))
            .collect();
        constants.sort_by(|a, b| a.0.cmp(&b.0));
        constants
    }

    /// The value of constant `name`; `use_span` is where it is used.
    fn let_value(&mut self, name: &str, use_span: Option<Span>) -> Option<Quantity> {
        if let Some(v) = self.built.let_values.get(name) {
            return *v;
        }
        let (decl, file) = self.decls.lets.get(name)?;
        if self.built.let_stack.iter().any(|n| n == name) {
            let span = use_span.unwrap_or(decl.name.span);
            self.error(Error::new(
                ErrorKind::LetCycle {
                    name: name.to_string(),
                },
                span,
            ));
            return None;
        }
        if self.built.let_stack.len() >= self.cx.limits.constant_chain {
            let span = use_span.unwrap_or(decl.name.span);
            // One report is enough; the rest of the chain fails silently.
            let reported = self
                .cx
                .errors
                .iter()
                .any(|e| matches!(e.kind(), ErrorKind::TooLarge { .. }));
            self.built.let_values.insert(name.to_string(), None);
            if reported {
                return None;
            }
            self.error(Error::new(
                ErrorKind::TooLarge {
                    what: format!("the chain of constants leading to `{name}`"),
                    limit: format!(
                        "{} constants (--max-constant-chain)",
                        self.cx.limits.constant_chain
                    ),
                },
                span,
            ));
            return None;
        }
        self.built.let_stack.push(name.to_string());
        let value = self.in_file(file, |c| c.eval(&decl.value));
        self.built.let_stack.pop();
        // A cycle may already have recorded the value as failed.
        self.built
            .let_values
            .entry(name.to_string())
            .or_insert(value);
        self.built.let_values[name]
    }

    /// Evaluate an expression; errors are recorded and give `None`.
    pub(super) fn eval(&mut self, e: &Expr) -> Option<Quantity> {
        let q = match &e.kind {
            ExprKind::Number { value, unit } => match unit {
                Some(u) => Quantity::dimensioned(value * u.to_internal(), u.dim()),
                None => Quantity::Bare {
                    value: *value,
                    defaults: self.cx.defaults,
                },
            },
            ExprKind::Name(name) => return self.name_value(name, e.span),
            ExprKind::Neg(inner) => self.eval(inner)?.negated(),
            ExprKind::Call(function, args) => return self.extreme(*function, args, e.span),
            ExprKind::Binary(op, l_expr, r_expr) => {
                let (l, r) = (self.eval(l_expr), self.eval(r_expr));
                let (l, r) = (l?, r?);
                let result = match op {
                    BinOp::Add => l.sum(r, 1.0),
                    BinOp::Sub => l.sum(r, -1.0),
                    BinOp::Mul => l.product(r),
                    BinOp::Div => l.quotient(r),
                };
                match result {
                    Ok(q) => q,
                    Err(err) => {
                        // A zero divisor is pointed at; other errors are about both sides.
                        let span = if err == QuantityError::DivisionByZero {
                            r_expr.span
                        } else {
                            e.span
                        };
                        self.error(Error::new(quantity_error(err), span));
                        return None;
                    }
                }
            }
        };
        if !q.raw().is_finite() {
            self.error(Error::new(ErrorKind::NotFinite, e.span));
            return None;
        }
        Some(q)
    }

    /// `min(...)` or `max(...)` of values of one kind (a bare number
    /// takes the unit of the others' kind, as in a sum).
    fn extreme(&mut self, function: Function, args: &[Expr], span: Span) -> Option<Quantity> {
        let values: Vec<Option<Quantity>> = args.iter().map(|a| self.eval(a)).collect();
        let mut values = values.into_iter().collect::<Option<Vec<_>>>()?.into_iter();
        let mut best = values.next()?;
        for next in values {
            // The difference checks the kinds and gives the order; adding
            // nothing of the other's kind gives the result that kind (a
            // bare number beside a length is a length; two bare numbers
            // stay bare, to take the unit of the place they are used).
            let ordered = best.sum(next, -1.0).and_then(|difference| {
                let take_next = match function {
                    Function::Min => difference.raw() > 0.0,
                    Function::Max => difference.raw() < 0.0,
                };
                let (kept, other) = if take_next {
                    (next, best)
                } else {
                    (best, next)
                };
                kept.sum(other.zero(), 1.0)
            });
            match ordered {
                Ok(q) => best = q,
                Err(err) => {
                    self.error(Error::new(quantity_error(err), span));
                    return None;
                }
            }
        }
        Some(best)
    }

    fn name_value(&mut self, name: &str, span: Span) -> Option<Quantity> {
        if let Some((_, value)) = self.built.params.iter().rev().find(|(n, _)| n == name) {
            // A parameter that failed to evaluate has reported its error.
            return *value;
        }
        if self.decls.lets.get(name).is_some() {
            return self.let_value(name, Some(span));
        }
        let params = self.built.params.iter().map(|(n, _)| n.as_str());
        let known = self.decls.lets.names().chain(params);
        self.error(self.unknown("constant", name, span, known));
        None
    }

    /// Evaluate `e` as a quantity of dimension `want`.
    fn eval_as(&mut self, e: &Expr, want: Dim) -> Option<f64> {
        let q = self.eval(e)?;
        match q.as_dim(want) {
            Some(v) => Some(v),
            None => {
                self.error(Error::new(
                    ErrorKind::Dimension {
                        expected: want.to_string(),
                        found: q.describe(),
                    },
                    e.span,
                ));
                None
            }
        }
    }

    pub(super) fn length(&mut self, e: &Expr) -> Option<f64> {
        self.eval_as(e, Dim::LENGTH)
    }

    pub(super) fn angle(&mut self, e: &Expr) -> Option<f64> {
        self.eval_as(e, Dim::ANGLE)
    }

    pub(super) fn number(&mut self, e: &Expr) -> Option<f64> {
        self.eval_as(e, Dim::NONE)
    }

    /// A point or size `(x, y, z)` of lengths.
    pub(super) fn point(&mut self, v: &Vec3Expr) -> Option<Vector3<f64>> {
        let [x, y, z] = &v.parts;
        let (x, y, z) = (self.length(x), self.length(y), self.length(z));
        Some(Vector3::new(x?, y?, z?))
    }

    /// A size: a point whose parts must all be positive.
    pub(super) fn size(&mut self, v: &Vec3Expr, what: &str) -> Option<Vector3<f64>> {
        let size = self.point(v)?;
        self.each_part(v, size, (what, "greater than zero"), |mm| mm > 0.0)
    }

    /// `size` (the value of `v`) if `fits` each of its parts, else an
    /// error at each part that does not (`what` it is, and the `bound`
    /// in words).
    pub(super) fn each_part(
        &mut self,
        v: &Vec3Expr,
        size: Vector3<f64>,
        (what, bound): (&str, &str),
        fits: impl Fn(f64) -> bool,
    ) -> Option<Vector3<f64>> {
        let mut ok = true;
        for (i, part) in v.parts.iter().enumerate() {
            if !fits(size[i]) {
                self.out_of_range(part.span, what, bound, &format!("{} mm", fmt_num(size[i])));
                ok = false;
            }
        }
        ok.then_some(size)
    }

    pub(super) fn out_of_range(&mut self, span: Span, what: &str, bound: &str, value: &str) {
        self.error(Error::new(
            ErrorKind::OutOfRange {
                what: what.to_string(),
                bound: bound.to_string(),
                value: value.to_string(),
            },
            span,
        ));
    }
}

fn quantity_error(e: QuantityError) -> ErrorKind {
    match e {
        QuantityError::Operands { verb, left, right } => ErrorKind::Operands { verb, left, right },
        QuantityError::DivisionByZero => ErrorKind::DivisionByZero,
        QuantityError::MixedDefaults => ErrorKind::MixedDefaults,
    }
}

/// A number for a message: up to three decimals, no trailing zeros.
pub(super) fn fmt_num(v: f64) -> String {
    let s = format!("{v:.3}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" {
        "0".to_string()
    } else {
        s.to_string()
    }
}
