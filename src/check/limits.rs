//! A scenario's own bounds on its run (`limits { solver_work 2e9 }`):
//! each raises or lowers the command line's, a raise at most
//! [`Limits::raise`] times it, so that a file from elsewhere runs for
//! hours only where the user says so.

use super::Checker;
use crate::error::{Error, ErrorKind};
use crate::limits::Limits;
use crate::options::{ParamKind, ParamSpec, Value};
use crate::span::Span;
use crate::syntax::ast::LimitsDecl;

/// The bounds a file may set: the option, the command line's flag, and
/// where it lives in [`Limits`].
struct Bound {
    name: &'static str,
    flag: &'static str,
    doc: &'static str,
    field: fn(&mut Limits) -> &mut u64,
}

const BOUNDS: [Bound; 2] = [
    Bound {
        name: "solver_work",
        flag: "--max-solver-work",
        doc: "most work the solvers may do in this run, in the units of --max-solver-work (about a joint moved once)",
        field: |l| &mut l.solver_work,
    },
    Bound {
        name: "solver_starts",
        flag: "--max-solver-starts",
        doc: "most solver starts the tasks may need, counted at their worst before the run",
        field: |l| &mut l.solver_starts,
    },
];

/// The option block's parameters: each bound, optional.
pub fn params() -> Vec<ParamSpec> {
    BOUNDS
        .iter()
        .map(|b| ParamSpec {
            name: b.name,
            kind: ParamKind::Integer,
            default: None,
            range: Some((1.0, super::options::MAX_INTEGER)),
            optional: true,
            doc: b.doc,
        })
        .collect()
}

impl Checker<'_> {
    /// Set the bounds the root file's `limits` asks for, each within
    /// [`Limits::raise`] times the command line's.
    pub(super) fn file_limits(&mut self) {
        let decls = std::mem::take(&mut self.decls.limits);
        for (again, _) in decls.iter().skip(1) {
            let e = Error::new(
                ErrorKind::Repeated {
                    what: "`limits`".into(),
                },
                again.span,
            );
            self.error(e.with_note(decls[0].0.span, "first given here"));
        }
        // Each checked; the first applied.
        for (k, &(decl, file)) in decls.iter().enumerate() {
            let limits = self.in_file(file, |c| c.limits_of(decl));
            if let (0, Some((limits, work_set_at))) = (k, limits) {
                self.cx.limits = limits;
                self.cx.work_set_at = work_set_at;
            }
        }
    }

    /// The bounds `decl` sets, where it sets them within the ceiling, and
    /// where it sets the bound on solver work.
    fn limits_of(&mut self, decl: &LimitsDecl) -> Option<(Limits, Option<Span>)> {
        let options = self.options("`limits`", &params(), &decl.options, decl.span)?;
        let mut limits = self.cx.limits;
        let mut work_set_at = None;
        for bound in &BOUNDS {
            let Some(Value::Integer(asked)) = options.get(bound.name) else {
                continue;
            };
            let asked = *asked as u64;
            let given = *(bound.field)(&mut self.cx.limits);
            let ceiling = given.saturating_mul(self.cx.limits.raise);
            if asked > ceiling {
                let at = decl.options.iter().find(|o| o.name.value == bound.name);
                let kind = ErrorKind::AboveCeiling {
                    name: bound.name,
                    asked,
                    ceiling,
                    flag: bound.flag,
                };
                self.error(Error::new(kind, at.map_or(decl.span, |o| o.value_span)));
                continue;
            }
            *(bound.field)(&mut limits) = asked;
            if bound.name == "solver_work" {
                let at = decl.options.iter().find(|o| o.name.value == bound.name);
                work_set_at = Some(at.map_or(decl.span, |o| o.value_span));
            }
        }
        Some((limits, work_set_at))
    }
}
