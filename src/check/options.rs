//! Option blocks, validated against the plugin's declared parameters: the
//! same rules for every solver, base, task and format.

use super::eval::fmt_num;
use super::Checker;
use crate::error::{Error, ErrorKind};
use crate::options::{Options, ParamKind, ParamSpec, SettingsError, Value};
use crate::span::Span;
use crate::syntax::ast::{Expr, ExprKind, OptionDecl, OptionValue, PluginUse};

/// Whole numbers up to this size are exact in f64.
pub(super) const MAX_INTEGER: f64 = 9_007_199_254_740_992.0;

impl Checker<'_> {
    /// Validate `given` against `params` of the plugin called `label`;
    /// missing options take their defaults.
    pub(super) fn options(
        &mut self,
        label: &str,
        params: &[ParamSpec],
        given: &[OptionDecl],
        at: Span,
    ) -> Option<Options> {
        let mut values: Vec<(&'static str, Option<Value>)> = Vec::new();
        let mut seen: Vec<&OptionDecl> = Vec::new();
        let mut ok = true;
        for opt in given {
            let Some(spec) = params.iter().find(|p| p.name == opt.name.value) else {
                let names: Vec<&str> = params.iter().map(|p| p.name).collect();
                self.error(Error::new(
                    ErrorKind::UnknownOption {
                        plugin: label.to_string(),
                        name: opt.name.value.clone(),
                        suggestion: self
                            .cx
                            .suggestions
                            .suggest(&opt.name.value, names.iter().copied()),
                        available: if names.is_empty() {
                            "none".into()
                        } else {
                            names.join(", ")
                        },
                    },
                    opt.name.span,
                ));
                ok = false;
                continue;
            };
            if let Some(first) = seen.iter().find(|s| s.name.value == opt.name.value) {
                let e = Error::new(
                    ErrorKind::Repeated {
                        what: format!("option `{}`", spec.name),
                    },
                    opt.name.span,
                );
                self.error(e.with_note(first.name.span, "first given here"));
                ok = false;
                continue;
            }
            seen.push(opt);
            values.push((spec.name, self.option_value(spec, opt)));
        }
        let mut options = Vec::new();
        for spec in params {
            match values.iter().find(|(n, _)| *n == spec.name) {
                Some((_, Some(v))) => options.push((spec.name, v.clone())),
                Some((_, None)) => ok = false,
                None => match &spec.default {
                    Some(d) => options.push((spec.name, self.complete_default(spec, d, at)?)),
                    None if spec.optional => {}
                    None => {
                        self.error(Error::new(
                            ErrorKind::MissingOption {
                                plugin: label.to_string(),
                                name: spec.name.to_string(),
                            },
                            at,
                        ));
                        ok = false;
                    }
                },
            }
        }
        ok.then(|| Options::new(options))
    }

    /// A default value as the plugin will read it: a default plugin gets
    /// its own options' defaults, validated like a plugin named in the file.
    fn complete_default(&mut self, spec: &ParamSpec, default: &Value, at: Span) -> Option<Value> {
        match (spec.kind, default) {
            (ParamKind::Plugin(kind), Value::Plugin(cfg)) => {
                let use_ = PluginUse {
                    name: crate::span::Spanned::new(cfg.name.clone(), at),
                    options: Vec::new(),
                    span: at,
                };
                let mut config = self.plugin_config(kind, &use_)?;
                for (name, value) in cfg.options.iter() {
                    config.options = config.options.set(name, value.clone());
                }
                Some(Value::Plugin(config))
            }
            _ => Some(default.clone()),
        }
    }

    fn option_value(&mut self, spec: &ParamSpec, opt: &OptionDecl) -> Option<Value> {
        let value = match (spec.kind, &opt.value) {
            (ParamKind::Length, OptionValue::Expr(e)) => Value::Length(self.length(e)?),
            (ParamKind::Angle, OptionValue::Expr(e)) => Value::Angle(self.angle(e)?),
            (ParamKind::Number, OptionValue::Expr(e)) => Value::Number(self.number(e)?),
            (ParamKind::Integer, OptionValue::Expr(e)) => {
                let v = self.number(e)?;
                if v.fract() != 0.0 || v.abs() > MAX_INTEGER {
                    self.mismatch(spec, "a fractional number", e.span);
                    return None;
                }
                Value::Integer(v as i64)
            }
            (ParamKind::Bool, OptionValue::Bool(b)) => Value::Bool(*b),
            (ParamKind::Point, OptionValue::Vec3(v)) => Value::Point(self.point(v)?),
            (ParamKind::Points, OptionValue::Points(ps)) => {
                let points: Option<Vec<_>> = ps.iter().map(|p| self.point(p)).collect();
                Value::Points(points?)
            }
            (ParamKind::Plugin(kind), OptionValue::Plugin(p)) => {
                Value::Plugin(self.plugin_config(kind, p)?)
            }
            (ParamKind::Names, OptionValue::Names(names)) => {
                Value::Names(names.iter().map(|n| n.value.clone()).collect())
            }
            (ParamKind::Names, OptionValue::Expr(e)) => match &e.kind {
                ExprKind::Name(name) => Value::Names(vec![name.clone()]),
                _ => return self.mismatch(spec, "an expression", opt.value_span),
            },
            (ParamKind::Name, OptionValue::Expr(e)) => match &e.kind {
                ExprKind::Name(name) => Value::Name(name.clone()),
                _ => return self.mismatch(spec, "an expression", opt.value_span),
            },
            (ParamKind::Plugin(kind), OptionValue::Expr(e)) => match &e.kind {
                ExprKind::Name(name) => {
                    let use_ = PluginUse {
                        name: crate::span::Spanned::new(name.clone(), e.span),
                        options: Vec::new(),
                        span: e.span,
                    };
                    Value::Plugin(self.plugin_config(kind, &use_)?)
                }
                _ => return self.mismatch(spec, "an expression", opt.value_span),
            },
            (_, other) => return self.mismatch(spec, &describe(other), opt.value_span),
        };
        self.in_range(spec, &value, opt.value_span).then_some(value)
    }

    /// A plugin that could not be built from its options (`label`: the
    /// plugin, `given`: its block): reported at the option the error names
    /// if the block gives it, else at `at`.
    pub(super) fn settings_error(
        &mut self,
        label: &str,
        e: &SettingsError,
        given: &[OptionDecl],
        at: Span,
    ) {
        let span = given
            .iter()
            .find(|o| o.name.value == e.option)
            .map_or(at, |o| o.value_span);
        self.error(Error::new(
            ErrorKind::BadOption {
                plugin: label.to_string(),
                message: e.to_string(),
            },
            span,
        ));
    }

    fn mismatch(&mut self, spec: &ParamSpec, found: &str, span: Span) -> Option<Value> {
        self.error(Error::new(
            ErrorKind::Dimension {
                expected: spec.kind.describe(),
                found: found.to_string(),
            },
            span,
        ));
        None
    }

    fn in_range(&mut self, spec: &ParamSpec, value: &Value, span: Span) -> bool {
        let Some((min, max)) = spec.range else {
            return true;
        };
        let v = match value {
            Value::Length(v) | Value::Angle(v) | Value::Number(v) => *v,
            Value::Integer(i) => *i as f64,
            _ => return true,
        };
        if v >= min && v <= max {
            return true;
        }
        let show = |x: f64| match spec.kind {
            ParamKind::Length => format!("{}mm", fmt_num(x)),
            ParamKind::Angle => format!("{}deg", fmt_num(x.to_degrees())),
            _ => fmt_num(x),
        };
        let bound = format!("between {} and {}", show(min), show(max));
        self.out_of_range(span, &format!("option `{}`", spec.name), &bound, &show(v));
        false
    }
}

/// What an option's value is, as a mismatch says it: a bare word is
/// named, not called a number (`why yes`).
fn describe(v: &OptionValue) -> String {
    match v {
        OptionValue::Expr(Expr {
            kind: ExprKind::Name(name),
            ..
        }) => format!("the word `{name}`"),
        OptionValue::Expr(_) => "a number".into(),
        OptionValue::Vec3(_) => "a point".into(),
        OptionValue::Points(_) => "a list of points".into(),
        OptionValue::Names(_) => "a list of names".into(),
        OptionValue::Bool(_) => "true or false".into(),
        OptionValue::String(_) => "a string".into(),
        OptionValue::Plugin(_) => "a plugin block".into(),
    }
}
