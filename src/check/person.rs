//! Persons: a mannequin with this person's own joint limits, neutral values
//! and weights, and a base.

use std::sync::Arc;

use super::Checker;
use crate::error::{thousands, Error, ErrorKind};
use crate::kinematics::{Body, Joint, JointKind};
use crate::options::{Options, PluginConfig, PluginKind, Settings};
use crate::plugin::{Base, BaseError};
use crate::scene::{Person, Physique, Vision};
use crate::span::{Name, Span};
use crate::syntax::ast::{
    self, JointOverride, MannequinRef, OptionDecl, PersonDecl, PersonMannequin,
};
use crate::units::Quantity;

/// How many times `--max-joints` the bodies of all a scenario's people
/// may hold together: 1,000,000 joints by default (a thousand people of
/// the stdlib hold about 25,000).
const PEOPLE_JOINTS_PER_MAX_JOINTS: u64 = 500;

/// How many bytes of mannequins' declarations building the people may
/// evaluate, for each of `--max-people`: 1 GB by default, about 8 s (a
/// thousand people of the stdlib evaluate about 5 MB).
const TEXT_PER_PERSON_LIMIT: u64 = 100_000;

/// Adds `more` to `running`, a total kept as the people are built and
/// whether passing its bound was reported: none while the total is within
/// `most`; past it, whether this is the first time (the error to report).
fn passed(running: &mut (u64, bool), more: u64, most: u64) -> Option<bool> {
    running.0 = running.0.saturating_add(more);
    if running.0 <= most {
        return None;
    }
    Some(!std::mem::replace(&mut running.1, true))
}

impl Checker<'_> {
    /// The persons, each with their base built.
    pub(super) fn persons(&mut self) -> Vec<(Person, Arc<dyn Base>)> {
        let mut decls: Vec<_> = self.decls.persons.iter().map(|(_, d, f)| (d, f)).collect();
        let most = self.cx.limits.people;
        if let Some(&(first_beyond, f)) = decls.get(most) {
            let kind = ErrorKind::TooLarge {
                what: format!("{} people declared", thousands(decls.len() as u64)),
                limit: format!("{} (--max-people)", thousands(most as u64)),
            };
            self.in_file(f, |c| c.error(Error::new(kind, first_beyond.name.span)));
            decls.truncate(most);
        }
        let mut built = Vec::new();
        for (d, f) in decls {
            let bytes = d
                .mannequins
                .first()
                .map_or(0, |m| self.mannequin_bytes(&m.mannequin.name));
            if !self.in_file(f, |c| c.within_evaluated_text(bytes, d.name.span)) {
                break;
            }
            let Some(person) = self.in_file(f, |c| c.person(d)) else {
                continue;
            };
            let joints = person.0.body.joints.len();
            if !self.in_file(f, |c| c.within_people_joints(joints, d.name.span)) {
                break;
            }
            built.push(person);
        }
        built
    }

    /// The bytes of the declarations of mannequin `name`, through its
    /// aliases: what building one person of it evaluates.
    pub(super) fn mannequin_bytes(&self, name: &Name) -> u64 {
        let mut bytes = 0_u64;
        let mut name = name.clone();
        for _ in 0..=self.cx.limits.alias_chain {
            let Ok((decl, _)) = self.decls.mannequins.resolve(&name, self.cx.suggestions) else {
                break;
            };
            bytes += u64::from(decl.span.end.saturating_sub(decl.span.start));
            match &decl.alias {
                Some(alias) => name = alias.name.clone(),
                None => break,
            }
        }
        bytes
    }

    /// Whether `bytes` more of mannequins' declarations, evaluated to
    /// build people, keep the scenario within [`TEXT_PER_PERSON_LIMIT`]
    /// times `--max-people` bytes (each person's body is their mannequin
    /// evaluated again: 300 people of a mannequin of 6.6 MB took 16 s);
    /// where they do not, an error at `at`, the first time.
    pub(super) fn within_evaluated_text(&mut self, bytes: u64, at: Span) -> bool {
        let most = (self.cx.limits.people as u64).saturating_mul(TEXT_PER_PERSON_LIMIT);
        let past = passed(&mut self.cx.evaluated_text, bytes, most);
        self.within_or_reported(past, at, || ErrorKind::TooLarge {
            what: "the mannequins' text evaluated to build the people".into(),
            limit: format!(
                "{} bytes ({} times --max-people)",
                thousands(most),
                thousands(TEXT_PER_PERSON_LIMIT)
            ),
        })
    }

    /// Whether the people built so far, with one more of `joints` joints,
    /// hold at most [`PEOPLE_JOINTS_PER_MAX_JOINTS`] times `--max-joints`
    /// joints together (each person's body is built, about 300 bytes a
    /// joint: 10,000 people of 2,000 joints took 6.5 GB); where they do
    /// not, an error at `at`, the first time.
    pub(super) fn within_people_joints(&mut self, joints: usize, at: Span) -> bool {
        let most = (self.cx.limits.joints as u64).saturating_mul(PEOPLE_JOINTS_PER_MAX_JOINTS);
        let past = passed(&mut self.cx.people_joints, joints as u64, most);
        self.within_or_reported(past, at, || ErrorKind::TooLarge {
            what: "the joints of the people, each body counted,".into(),
            limit: format!(
                "{} ({PEOPLE_JOINTS_PER_MAX_JOINTS} times --max-joints)",
                thousands(most)
            ),
        })
    }

    /// Whether a running total is within its bound, `past` saying how
    /// [`passed`] found it; past it the first time, the error `kind` at
    /// `at`.
    fn within_or_reported(
        &mut self,
        past: Option<bool>,
        at: Span,
        kind: impl FnOnce() -> ErrorKind,
    ) -> bool {
        if past == Some(true) {
            self.error(Error::new(kind(), at));
        }
        past.is_none()
    }

    fn person(&mut self, decl: &PersonDecl) -> Option<(Person, Arc<dyn Base>)> {
        let owner = format!("person `{}`", decl.name.value);
        let mannequin = self.one_of(
            &decl.mannequins,
            |m| m.mannequin.name.span,
            &owner,
            "mannequin",
            decl.name.span,
        );
        let base_use = self.one_of(&decl.bases, |b| b.span, &owner, "base", decl.name.span);
        let body = mannequin.and_then(|m| self.person_body(m));
        let base = base_use.and_then(|b| self.base_config(b));
        let built = match (base_use, base.as_ref(), body.as_ref()) {
            (Some(b), Some(config), Some((body, _))) => {
                self.build_base(&decl.name.value, b, config, &Physique::of(body))
            }
            _ => None,
        };
        let vision = self.person_vision(&decl.visions);
        let (body, measures) = body?;
        let person = Person {
            name: decl.name.value.clone(),
            mannequin: mannequin?.mannequin.name.value.clone(),
            body,
            base: base?,
            vision: vision?,
            measures,
        };
        Some((person, built?))
    }

    /// A base plugin, or a base preset (`base power_chair = wheelchair
    /// {...}`) with the person's own options over the preset's.
    pub(super) fn base_config(&mut self, b: &ast::PluginUse) -> Option<PluginConfig> {
        let preset = self.decls.base_presets.get(&b.name.value);
        let (Some((preset, file)), None) = (preset, self.cx.registry.base(&b.name.value)) else {
            return self.plugin_config(PluginKind::Base, b);
        };
        let mut config =
            self.in_file(file, |c| c.plugin_config(PluginKind::Base, &preset.plugin))?;
        if b.options.is_empty() {
            return Some(config);
        }
        let own = ast::PluginUse {
            name: preset.plugin.name.clone(),
            options: b.options.clone(),
            span: b.span,
        };
        let own = self.plugin_config(PluginKind::Base, &own)?;
        for (name, value) in own.options.iter() {
            if b.options.iter().any(|given| given.name.value == *name) {
                config.options = config.options.set(name, value.clone());
            }
        }
        Some(config)
    }

    /// The base `config` gives, built for `person` of `physique`; an
    /// error at the option it names (in the person's block, else the
    /// preset's), or at the base if the person does not suit it.
    pub(super) fn build_base(
        &mut self,
        person: &str,
        b: &ast::PluginUse,
        config: &PluginConfig,
        physique: &Physique,
    ) -> Option<Arc<dyn Base>> {
        let plugin = self.cx.registry.base(&config.name)?.clone();
        match plugin.build(&config.options, physique) {
            Ok(base) => Some(Arc::from(base)),
            Err(BaseError::Unfit(reason)) => {
                self.error(Error::new(
                    ErrorKind::Unfit {
                        person: person.to_string(),
                        base: config.name.clone(),
                        reason,
                    },
                    b.span,
                ));
                None
            }
            Err(BaseError::Settings(e)) => {
                let label = format!("base `{}`", config.name);
                let given = b.options.iter().any(|o| o.name.value == e.option);
                match self.decls.base_presets.get(&b.name.value) {
                    Some((preset, file)) if !given => {
                        let options = preset.plugin.options.clone();
                        let span = preset.plugin.span;
                        self.in_file(file, |c| c.settings_error(&label, &e, &options, span));
                    }
                    _ => self.settings_error(&label, &e, &b.options, b.span),
                }
                None
            }
        }
    }

    /// The person's vision settings: a preset's, then their own over them;
    /// only those given (a gaze task's own come first, then these, then the
    /// defaults).
    pub(super) fn person_vision(&mut self, visions: &[ast::PersonVision]) -> Option<Vision> {
        self.repeated(visions.iter().skip(1).map(|v| v.span), "`vision`");
        let Some(vision) = visions.first() else {
            return Some(Vision::default());
        };
        let params = Vision::params();
        let mut preset_vision = Vision::default();
        if let Some(name) = &vision.preset {
            let (preset, file) = match self.decls.vision_presets.resolve(name, self.cx.suggestions)
            {
                Ok(found) => found,
                Err(e) => {
                    self.error(e);
                    return None;
                }
            };
            let label = format!("vision `{}`", name.value);
            let options = self.in_file(file, |c| {
                c.options(&label, &params, &preset.options, preset.span)
            })?;
            preset_vision = self.vision_of(&label, &options, &preset.options, preset.span)?;
        }
        let options = self.options("`vision`", &params, &vision.options, vision.span)?;
        let own = self.vision_of("`vision`", &options, &vision.options, vision.span)?;
        Some(own.or(&preset_vision))
    }

    fn vision_of(
        &mut self,
        label: &str,
        options: &Options,
        given: &[OptionDecl],
        at: crate::span::Span,
    ) -> Option<Vision> {
        match Vision::from_options(options) {
            Ok(v) => Some(v),
            Err(e) => {
                self.settings_error(label, &e, given, at);
                None
            }
        }
    }

    /// Exactly one of `items`: errors for none and for each extra one.
    fn one_of<'i, T>(
        &mut self,
        items: &'i [T],
        span_of: impl Fn(&T) -> crate::span::Span,
        owner: &str,
        what: &'static str,
        owner_span: crate::span::Span,
    ) -> Option<&'i T> {
        for extra in items.iter().skip(1) {
            self.error(Error::new(
                ErrorKind::Repeated {
                    what: format!("`{what}`"),
                },
                span_of(extra),
            ));
        }
        if items.is_empty() {
            self.error(Error::new(
                ErrorKind::Missing {
                    owner: owner.to_string(),
                    what,
                },
                owner_span,
            ));
        }
        items.first()
    }

    /// The person's body and the measurements it was built from.
    fn person_body(&mut self, m: &PersonMannequin) -> Option<(Body, Vec<(String, Quantity)>)> {
        let file = self.cx.file;
        // A mannequin that failed to build has reported its own errors.
        let (mut body, measures) = self.measured_body_of(&m.mannequin, file)?;
        with_stance(&mut body, m);
        let mut ok = true;
        for o in &m.overrides {
            ok &= self.apply_override(&mut body.joints, o).is_some();
        }
        // Limits may have moved past the neutral values left in place.
        for j in &mut body.joints {
            j.neutral = j.neutral.clamp(j.min, j.max);
        }
        if ok {
            ok = self.apart_at_rest(&body, &m.mannequin);
        }
        ok.then_some((body, measures))
    }

    /// Whether each of `body`'s chains keeps its solids apart in the
    /// neutral posture (else a diagnostic at the mannequin, naming the two
    /// that meet): once per person, a look at every pair of solids.
    pub(super) fn apart_at_rest(&mut self, body: &Body, mannequin: &MannequinRef) -> bool {
        for e in 0..body.effectors.len() {
            let chain = body.chain(e);
            let v = chain.volumes(&chain.neutral());
            if let Some((i, j)) = v.self_hit() {
                let mut error = Error::new(
                    ErrorKind::MeetsItself {
                        mannequin: mannequin.name.value.clone(),
                        part: chain.volume_name(v.owners[j]).to_string(),
                        other: chain.volume_name(v.owners[i]).to_string(),
                    },
                    mannequin.name.span,
                );
                // Where the radii are given: the declaration.
                if let Ok((decl, _)) = self
                    .decls
                    .mannequins
                    .resolve(&mannequin.name, self.cx.suggestions)
                {
                    error = match decl.urdf {
                        Some(_) => {
                            error.with_note(decl.span, "declared here: `radius` goes after `tip`")
                        }
                        None => error.with_note(decl.name.span, "declared here"),
                    };
                }
                self.error(error);
                return false;
            }
        }
        true
    }

    pub(super) fn apply_override(&mut self, joints: &mut [Joint], o: &JointOverride) -> Option<()> {
        let joint = match o {
            JointOverride::Limits { joint, .. }
            | JointOverride::Neutral { joint, .. }
            | JointOverride::Weight { joint, .. } => joint,
            JointOverride::Profile { name } => return self.apply_profile(joints, name),
        };
        let i = self.joint_index(joints, joint)?;
        let kind = match joints[i].kind {
            JointKind::Revolute => ast::JointKind::Revolute,
            JointKind::Prismatic => ast::JointKind::Prismatic,
        };
        let j = &joints[i];
        let (min, max) = (j.min, j.max);
        match o {
            JointOverride::Limits { limits, .. } => {
                let (min, max) = self.limits(limits, kind)?;
                if let Some(range) = joints[i].anatomical {
                    self.within_anatomical(&joints[i].name, (min, max), range, kind, limits.span)?;
                }
                joints[i].min = min;
                joints[i].max = max;
            }
            JointOverride::Neutral { value, .. } => {
                let v = match kind {
                    ast::JointKind::Revolute | ast::JointKind::Fixed => self.angle(value)?,
                    ast::JointKind::Prismatic => self.length(value)?,
                };
                joints[i].neutral = self.neutral_within(v, min, max, kind, value.span)?;
            }
            JointOverride::Weight { value, .. } => joints[i].weight = self.weight(value)?,
            JointOverride::Profile { .. } => unreachable!("profiles are applied above"),
        }
        Some(())
    }

    /// Every override of profile `name`, in its own file's units.
    pub(super) fn apply_profile(&mut self, joints: &mut [Joint], name: &Name) -> Option<()> {
        let (profile, file) = match self.decls.profiles.resolve(name, self.cx.suggestions) {
            Ok(found) => found,
            Err(e) => {
                self.error(e);
                return None;
            }
        };
        self.in_file(file, |c| {
            let mut ok = true;
            for o in &profile.overrides {
                ok &= c.apply_override(joints, o).is_some();
            }
            ok.then_some(())
        })
    }

    fn joint_index(&mut self, joints: &[Joint], joint: &Name) -> Option<usize> {
        let found = joints.iter().position(|j| j.name == joint.value);
        if found.is_none() {
            self.error(self.unknown(
                "joint",
                &joint.value,
                joint.span,
                joints.iter().map(|j| j.name.as_str()),
            ));
        }
        found
    }

    /// A plugin by name with its options validated.
    pub(super) fn plugin_config(
        &mut self,
        kind: PluginKind,
        use_: &ast::PluginUse,
    ) -> Option<PluginConfig> {
        let Some(params) = self.cx.registry.params(kind, &use_.name.value) else {
            // A person's base may also be a preset of the file or a module
            // it uses.
            let presets: Vec<String> = match kind {
                PluginKind::Base => self
                    .decls
                    .base_presets
                    .names()
                    .map(str::to_string)
                    .collect(),
                _ => Vec::new(),
            };
            let mut names = self.cx.registry.names(kind);
            names.extend(presets.iter().map(String::as_str));
            self.error(Error::new(
                ErrorKind::UnknownPlugin {
                    kind: kind.noun(),
                    name: use_.name.value.clone(),
                    suggestion: self
                        .cx
                        .suggestions
                        .suggest(&use_.name.value, names.iter().copied()),
                    available: names.join(", "),
                },
                use_.name.span,
            ));
            return None;
        };
        let label = format!("{} `{}`", kind.noun(), use_.name.value);
        let options = self.options(&label, &params, &use_.options, use_.span)?;
        Some(PluginConfig {
            name: use_.name.value.clone(),
            options,
        })
    }
}

/// `body` `seated` or `standing` where the person's `mannequin` line says
/// so after the mannequin (`mannequin upper_body(stature 1.6m) seated`).
pub(super) fn with_stance(body: &mut Body, m: &PersonMannequin) {
    if let Some(p) = &m.posture {
        body.posture = Some(match p.value {
            ast::Stance::Seated => crate::kinematics::Stance::Seated,
            ast::Stance::Standing => crate::kinematics::Stance::Standing,
        });
    }
}
