//! Populations: the `population` declarations the tasks name, drawn and
//! built. Each person is a whole row of ANSUR II (women with the
//! population's share `women`), the values of its `draw`s, and its share
//! of each `profile`, all from one seed; their measurements, `age` and the
//! drawn values are names the mannequin's arguments and the base's options
//! may use. Each becomes a person of the scenario (`NAME#1`, `NAME#2`, ...)
//! with its base built, as a `person` declaration would.

use std::sync::Arc;

use rand_chacha::rand_core::SeedableRng;
use rand_chacha::ChaCha8Rng;
use rand_distr::{Distribution as _, Normal, Uniform};

use super::Checker;
use crate::ansur::survey;
use crate::error::{Error, ErrorKind};
use crate::plugin::Base;
use crate::scene::{Drawn, Person, Physique, Population};
use crate::span::{FileId, Name, Span};
use crate::syntax::ast::{
    Distribution, DrawDecl, Expr, PersonMannequin, PersonVision, PluginUse, PopulationDecl,
    ProfileChoice,
};
use crate::units::{Dim, Quantity};

/// A population's items after `=` chains: each with the file it is written
/// in (the nearest declaration that gives it wins).
#[derive(Default)]
struct Items<'a> {
    size: Option<(&'a Expr, FileId)>,
    seed: Option<(&'a Expr, FileId)>,
    women: Option<(&'a Expr, FileId)>,
    draws: Vec<(&'a DrawDecl, FileId)>,
    profiles: Vec<(&'a Name, &'a Expr, FileId)>,
    choice: Option<(&'a ProfileChoice, FileId)>,
    mannequin: Option<(&'a PersonMannequin, FileId)>,
    base: Option<(&'a PluginUse, FileId)>,
    vision: Option<(&'a [PersonVision], FileId)>,
}

/// A `draw` evaluated: how to draw its value and what kind of value it is.
struct Draw {
    name: String,
    sampler: Sampler,
    within: Option<(f64, f64)>,
    /// A bare number keeps its file's default units; else its dimension.
    kind: Quantity,
    span: Span,
}

enum Sampler {
    Normal(Normal<f64>),
    Uniform(Uniform<f64>),
}

/// The people drawn: survey rows, the values drawn, the profiles applied.
struct Plan {
    name: String,
    seed: u64,
    drawn: Vec<Drawn>,
    quantities: Vec<Vec<Quantity>>,
}

/// How many draws of one value may fall outside its `within` before the
/// interval is taken to be one the distribution hardly reaches.
const REDRAWS: usize = 10_000;

impl<'a> Checker<'a> {
    /// The populations the tasks name (names that are no person's), each
    /// once, in the order first named.
    pub(super) fn populations_named(&self, persons: &[Person]) -> Vec<Name> {
        let mut named: Vec<Name> = Vec::new();
        for (decl, _) in &self.decls.tasks {
            for who in &decl.persons {
                let is_person = persons.iter().any(|p| p.name == who.value)
                    || self.decls.persons.get(&who.value).is_some();
                let known = named.iter().any(|n| n.value == who.value);
                if !is_person && !known && self.decls.populations.get(&who.value).is_some() {
                    named.push(who.clone());
                }
            }
        }
        named
    }

    /// The populations `names` (those the tasks name that are no person),
    /// each drawn and built: their people appended to `persons` and
    /// `bases`. In the order given.
    pub(super) fn populations(
        &mut self,
        names: &[Name],
        persons: &mut Vec<Person>,
        bases: &mut Vec<Arc<dyn Base>>,
    ) -> Vec<Population> {
        let mut out = Vec::new();
        for name in names {
            let Some(items) = self.population_items(name) else {
                continue;
            };
            let Some(plan) = self.draw_people(&name.value, &items) else {
                continue;
            };
            if !self.within_evaluated(plan.drawn.len(), &items, name.span) {
                continue;
            }
            let start = persons.len();
            let built = self.cx.built.range(plan.drawn.len());
            for (i, drawn) in plan
                .drawn
                .iter()
                .enumerate()
                .skip(built.start)
                .take(built.len())
            {
                let member = format!("{}#{}", plan.name, i + 1);
                let errors = self.cx.errors.len();
                let built = self.member(&member, &items, drawn, &plan.quantities[i], name.span);
                match built {
                    Some((person, base)) => {
                        let joints = person.body.joints.len();
                        if !self.within_people_joints(joints, name.span) {
                            break;
                        }
                        persons.push(person);
                        bases.push(base);
                    }
                    None => {
                        // One person's errors say it for all of them.
                        self.cx.errors.truncate(errors + 1);
                        break;
                    }
                }
            }
            if persons.len() - start == built.len() {
                join_floor_group(&bases[start..]);
                out.push(Population {
                    name: plan.name,
                    members: start..persons.len(),
                    first: built.start,
                    drawn: plan.drawn,
                    seed: plan.seed,
                });
            }
        }
        out
    }

    /// The items of population `name`, following `=` back to the first.
    fn population_items(&mut self, name: &Name) -> Option<Items<'a>> {
        let mut chain: Vec<(&'a PopulationDecl, FileId)> = Vec::new();
        let mut at = name.clone();
        loop {
            let found = match self.decls.populations.resolve(&at, self.cx.suggestions) {
                Ok(found) => found,
                Err(e) => {
                    self.error(e);
                    return None;
                }
            };
            if chain.len() >= self.cx.limits.alias_chain {
                self.error(Error::new(
                    ErrorKind::TooLarge {
                        what: "a chain of populations".into(),
                        limit: format!(
                            "{} (or it loops; --max-alias-chain)",
                            self.cx.limits.alias_chain
                        ),
                    },
                    at.span,
                ));
                return None;
            }
            chain.push(found);
            match &found.0.from {
                Some(from) => at = from.clone(),
                None => break,
            }
        }
        let mut items = Items::default();
        for &(decl, file) in chain.iter().rev() {
            self.merge(&mut items, decl, file);
        }
        Some(items)
    }

    fn merge(&mut self, items: &mut Items<'a>, decl: &'a PopulationDecl, file: FileId) {
        let with = |e: &'a Option<Expr>| e.as_ref().map(|e| (e, file));
        items.size = with(&decl.size).or(items.size);
        items.seed = with(&decl.seed).or(items.seed);
        items.women = with(&decl.women).or(items.women);
        for draw in &decl.draws {
            items.draws.retain(|(d, _)| d.name.value != draw.name.value);
            items.draws.push((draw, file));
        }
        for (profile, share) in &decl.profiles {
            items.profiles.retain(|(p, ..)| p.value != profile.value);
            items.profiles.push((profile, share, file));
        }
        self.repeated(
            decl.choices.iter().skip(1).map(|c| c.span),
            "`profile one of`",
        );
        if let Some(choice) = decl.choices.first() {
            items.choice = Some((choice, file));
        }
        let person = &decl.person;
        self.repeated(
            person
                .mannequins
                .iter()
                .skip(1)
                .map(|m| m.mannequin.name.span),
            "`mannequin`",
        );
        self.repeated(person.bases.iter().skip(1).map(|b| b.span), "`base`");
        if let Some(m) = person.mannequins.first() {
            items.mannequin = Some((m, file));
        }
        if let Some(b) = person.bases.first() {
            items.base = Some((b, file));
        }
        if !person.visions.is_empty() {
            items.vision = Some((&person.visions, file));
        }
    }

    /// Who is drawn: `size` rows of the survey (women with probability
    /// `women`), each with its `draw`s' values and its profiles.
    fn draw_people(&mut self, name: &str, items: &Items<'a>) -> Option<Plan> {
        let size = self.population_size(items)?;
        let seed = match items.seed {
            Some((e, file)) => self.in_file(file, |c| {
                c.whole(e, "a population's seed", 0.0, super::options::MAX_INTEGER)
            })?,
            None => 1.0,
        } as u64;
        let women = match items.women {
            Some((e, file)) => self.in_file(file, |c| c.share(e, "`women`"))?,
            None => 0.5,
        };
        let draws: Vec<Draw> = items
            .draws
            .iter()
            .map(|&(d, file)| self.in_file(file, |c| c.draw_decl(d)))
            .collect::<Option<_>>()?;
        // Every profile named, known, each mistake said where it is written.
        let names = items.profiles.iter().map(|&(p, _, file)| (p, file));
        let chosen = items
            .choice
            .into_iter()
            .flat_map(|(c, file)| c.options.iter().map(move |(p, _)| (p, file)));
        let known: Vec<bool> = names
            .chain(chosen)
            .map(|(p, file)| self.in_file(file, |c| c.known_profile(p)).is_some())
            .collect();
        if known.contains(&false) {
            return None;
        }
        let mut profile_shares = Vec::new();
        for &(profile, share, file) in &items.profiles {
            let share = self.in_file(file, |c| c.share(share, "a profile's share"))?;
            profile_shares.push((profile.value.clone(), share));
        }
        let categories = match items.choice {
            Some((choice, file)) => self.in_file(file, |c| c.categories(choice))?,
            None => Vec::new(),
        };
        let rows = survey();
        let stature = rows.columns.iter().position(|c| c == "stature");
        let by_sex = |female: bool| -> Vec<usize> {
            (0..rows.rows.len())
                .filter(|&i| rows.rows[i].female == female)
                .collect()
        };
        let (women_rows, men_rows) = (by_sex(true), by_sex(false));
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let mut drawn = Vec::with_capacity(size);
        let mut quantities = Vec::with_capacity(size);
        for _ in 0..size {
            let female = Uniform::new(0.0, 1.0).is_ok_and(|u| u.sample(&mut rng) < women);
            let pool = if female { &women_rows } else { &men_rows };
            let row = pool[Uniform::new(0, pool.len()).map_or(0, |u| u.sample(&mut rng))];
            let measured = &rows.rows[row];
            let mut values = Vec::new();
            let mut drawn_quantities = Vec::new();
            for d in &draws {
                let value = self.draw_value(d, &mut rng)?;
                values.push((d.name.clone(), value));
                drawn_quantities.push(with_kind(&d.kind, value));
            }
            drawn.push(Drawn {
                row,
                female,
                age_years: measured.age_years,
                stature_mm: stature.map_or(f64::NAN, |s| measured.lengths_mm[s]),
                values,
                profiles: Vec::new(),
            });
            quantities.push(drawn_quantities);
        }
        // The categories first: they give a person's ranges, which the
        // other profiles may narrow.
        for (i, profile) in categorised(&categories, size, seed) {
            drawn[i].profiles.push(profile);
        }
        for (k, (profile, share)) in profile_shares.iter().enumerate() {
            // Each profile its own stream: adding one leaves the others'
            // people as they were.
            let mut order: Vec<usize> = (0..size).collect();
            let mut rng =
                ChaCha8Rng::seed_from_u64(seed ^ (0x9e37_79b9_7f4a_7c15 * (k as u64 + 1)));
            shuffle(&mut order, &mut rng);
            let count = (share * size as f64).round() as usize;
            for &i in order.iter().take(count) {
                drawn[i].profiles.push(profile.clone());
            }
        }
        Some(Plan {
            name: name.to_string(),
            seed,
            drawn,
            quantities,
        })
    }

    /// Whether a profile of this name is declared (else a diagnostic at
    /// the name, with the nearest names).
    fn known_profile(&mut self, name: &Name) -> Option<()> {
        match self.decls.profiles.resolve(name, self.cx.suggestions) {
            Ok(_) => Some(()),
            Err(e) => {
                self.error(e);
                None
            }
        }
    }

    /// The categories of `profile one of`: each profile's share, the
    /// shares from 0 % to 100 % and at most 100 % in all.
    fn categories(&mut self, choice: &ProfileChoice) -> Option<Vec<(String, f64)>> {
        let mut categories = Vec::new();
        for (profile, share) in &choice.options {
            let share = self.share(share, "a profile's share")?;
            categories.push((profile.value.clone(), share));
        }
        let total: f64 = categories.iter().map(|(_, s)| s).sum();
        if total > 1.0 + 1e-9 {
            let value = format!("{} %", super::eval::fmt_num(total * 100.0));
            self.out_of_range(
                choice.span,
                "the shares of `profile one of`, added up,",
                "at most 100 %",
                &value,
            );
            return None;
        }
        Some(categories)
    }

    fn population_size(&mut self, items: &Items<'a>) -> Option<usize> {
        let Some((e, file)) = items.size else {
            return Some(1000.min(self.cx.limits.people));
        };
        let most = self.cx.limits.people;
        let size = self.in_file(file, |c| c.whole(e, "a population's size", 1.0, f64::MAX))?;
        if size > most as f64 {
            self.error(Error::new(
                ErrorKind::TooLarge {
                    what: format!("a population of {size} people"),
                    limit: format!("{most} (--max-people)"),
                },
                e.span,
            ));
            return None;
        }
        Some(size as usize)
    }

    /// A whole number in `[low, high]`.
    fn whole(&mut self, e: &Expr, what: &str, low: f64, high: f64) -> Option<f64> {
        let v = self.number(e)?;
        if v.fract() != 0.0 || v < low || v > high {
            let bound = format!("a whole number from {low}");
            self.out_of_range(e.span, what, &bound, &super::eval::fmt_num(v));
            return None;
        }
        Some(v)
    }

    /// A share from 0 to 1 (`30%` or `0.3`).
    pub(super) fn share(&mut self, e: &Expr, what: &str) -> Option<f64> {
        let v = self.number(e)?;
        if !(0.0..=1.0).contains(&v) {
            self.out_of_range(e.span, what, "from 0 % to 100 %", &super::eval::fmt_num(v));
            return None;
        }
        Some(v)
    }

    fn draw_decl(&mut self, d: &DrawDecl) -> Option<Draw> {
        let (first, second) = (self.eval(&d.first), self.eval(&d.second));
        let kind = kind_of(&first?, &second?);
        let Some(kind) = kind else {
            self.error(Error::new(
                ErrorKind::Dimension {
                    expected: first?.describe(),
                    found: second?.describe(),
                },
                d.second.span,
            ));
            return None;
        };
        let dim = dim_of(&kind);
        let value = |c: &mut Self, e: &Expr| c.eval(e).and_then(|q| c.as_kind(&q, dim, e.span));
        let a = value(self, &d.first)?;
        let b = value(self, &d.second)?;
        let sampler = match d.kind.value {
            Distribution::Normal => match Normal::new(a, b) {
                Ok(n) if b >= 0.0 => Sampler::Normal(n),
                _ => {
                    self.out_of_range(
                        d.second.span,
                        "a standard deviation",
                        "at least 0",
                        &super::eval::fmt_num(b),
                    );
                    return None;
                }
            },
            Distribution::Uniform => match Uniform::new(a, b) {
                Ok(u) => Sampler::Uniform(u),
                Err(_) => {
                    self.out_of_range(
                        d.second.span,
                        "the upper end",
                        "above the lower end",
                        &super::eval::fmt_num(b),
                    );
                    return None;
                }
            },
        };
        let within = match &d.within {
            None => None,
            Some((low, high)) => {
                let lo = value(self, low)?;
                let hi = value(self, high)?;
                if hi < lo {
                    self.out_of_range(
                        high.span,
                        "the upper end",
                        "at least the lower end",
                        &super::eval::fmt_num(hi),
                    );
                    return None;
                }
                Some((lo, hi))
            }
        };
        Some(Draw {
            name: d.name.value.clone(),
            sampler,
            within,
            kind,
            span: d.name.span,
        })
    }

    /// `q` in internal units of `dim` (a bare number of the file's
    /// default units where `dim` is none).
    fn as_kind(&mut self, q: &Quantity, dim: Option<Dim>, span: Span) -> Option<f64> {
        let found = match (q, dim) {
            (Quantity::Bare { value, .. }, None) => Some(*value),
            (_, Some(dim)) => q.as_dim(dim),
            (Quantity::Dimensioned { .. }, None) => None,
        };
        if found.is_none() {
            self.error(Error::new(
                ErrorKind::Dimension {
                    expected: dim.map_or("a number without unit".into(), |d| d.to_string()),
                    found: q.describe(),
                },
                span,
            ));
        }
        found
    }

    fn draw_value(&mut self, d: &Draw, rng: &mut ChaCha8Rng) -> Option<f64> {
        for _ in 0..REDRAWS {
            let v = match &d.sampler {
                Sampler::Normal(n) => n.sample(rng),
                Sampler::Uniform(u) => u.sample(rng),
            };
            match d.within {
                Some((lo, hi)) if v < lo || v > hi => continue,
                _ => return Some(v),
            }
        }
        self.error(Error::new(
            ErrorKind::Unsupported {
                what: format!(
                    "`within` that the distribution of `{}` hardly reaches",
                    d.name
                ),
                help: format!(
                    "{REDRAWS} draws in a row fell outside it; widen it or move the distribution"
                ),
            },
            d.span,
        ));
        None
    }

    /// Whether building `people` people of `items`' mannequin keeps the
    /// scenario's evaluated text within its bound
    /// ([`Checker::within_evaluated_text`]).
    fn within_evaluated(&mut self, people: usize, items: &Items<'a>, at: Span) -> bool {
        let Some((m, _)) = items.mannequin else {
            return true;
        };
        let bytes = self.mannequin_bytes(&m.mannequin.name);
        self.within_evaluated_text(bytes.saturating_mul(people as u64), at)
    }

    /// One person of a population: their mannequin with the population's
    /// profiles drawn for them, then its own overrides; their base.
    fn member(
        &mut self,
        name: &str,
        items: &Items<'a>,
        drawn: &Drawn,
        quantities: &[Quantity],
        at: Span,
    ) -> Option<(Person, Arc<dyn Base>)> {
        let (Some((m, m_file)), Some((b, b_file))) = (items.mannequin, items.base) else {
            let what = if items.mannequin.is_none() {
                "mannequin"
            } else {
                "base"
            };
            self.error(Error::new(
                ErrorKind::Missing {
                    owner: "this population".into(),
                    what,
                },
                at,
            ));
            return None;
        };
        let outer = self.built.params.len();
        self.bind_measurements(drawn, quantities);
        let built = self.member_with_names(name, drawn, m, m_file, b, b_file, items.vision);
        self.built.params.truncate(outer);
        built
    }

    #[allow(clippy::too_many_arguments)]
    fn member_with_names(
        &mut self,
        name: &str,
        drawn: &Drawn,
        m: &PersonMannequin,
        m_file: FileId,
        b: &PluginUse,
        b_file: FileId,
        vision: Option<(&'a [PersonVision], FileId)>,
    ) -> Option<(Person, Arc<dyn Base>)> {
        let (mut body, measures) =
            self.in_file(m_file, |c| c.measured_body_of(&m.mannequin, m_file))?;
        super::person::with_stance(&mut body, m);
        for profile in &drawn.profiles {
            let profile = Name {
                value: profile.clone(),
                span: m.mannequin.name.span,
            };
            self.apply_profile(&mut body.joints, &profile)?;
        }
        let mut ok = true;
        for o in &m.overrides {
            ok &= self
                .in_file(m_file, |c| c.apply_override(&mut body.joints, o))
                .is_some();
        }
        for j in &mut body.joints {
            j.neutral = j.neutral.clamp(j.min, j.max);
        }
        // As for a person: a body through itself at rest is no one (a
        // population of such bodies ran the solvers at every posture to
        // no answer).
        if ok {
            ok = self.in_file(m_file, |c| c.apart_at_rest(&body, &m.mannequin));
        }
        let config = self.in_file(b_file, |c| c.base_config(b))?;
        let base = self.in_file(b_file, |c| {
            c.build_base(name, b, &config, &Physique::of(&body))
        })?;
        let vision = match vision {
            Some((v, file)) => self.in_file(file, |c| c.person_vision(v))?,
            None => Default::default(),
        };
        ok.then(|| {
            let person = Person {
                name: name.to_string(),
                mannequin: m.mannequin.name.value.clone(),
                body,
                base: config,
                vision,
                measures,
            };
            (person, base)
        })
    }

    /// The survey's measurements of `drawn` (lengths), `age` (years, a
    /// number) and the drawn values, as names in scope.
    fn bind_measurements(&mut self, drawn: &Drawn, quantities: &[Quantity]) {
        let rows = survey();
        let measured = &rows.rows[drawn.row];
        for (column, value) in rows.columns.iter().zip(&measured.lengths_mm) {
            let q = Quantity::dimensioned(*value, Dim::LENGTH);
            self.built.params.push((column.clone(), Some(q)));
        }
        let age = Quantity::dimensioned(drawn.age_years, Dim::NONE);
        self.built.params.push(("age".into(), Some(age)));
        for ((name, _), q) in drawn.values.iter().zip(quantities) {
            self.built.params.push((name.clone(), Some(*q)));
        }
    }
}

/// The kind two values of a draw share: the dimension of whichever has
/// one (a bare number takes the file's default unit of it), or bare; none
/// if their dimensions differ.
fn kind_of(a: &Quantity, b: &Quantity) -> Option<Quantity> {
    match (a, b) {
        (Quantity::Dimensioned { dim: da, .. }, Quantity::Dimensioned { dim: db, .. }) => {
            (da == db).then_some(*a)
        }
        (Quantity::Dimensioned { .. }, _) => Some(*a),
        (_, Quantity::Dimensioned { .. }) => Some(*b),
        _ => Some(*a),
    }
}

fn dim_of(kind: &Quantity) -> Option<Dim> {
    match kind {
        Quantity::Dimensioned { dim, .. } => Some(*dim),
        Quantity::Bare { .. } => None,
    }
}

/// `value` as a quantity of `kind`'s kind.
fn with_kind(kind: &Quantity, value: f64) -> Quantity {
    match *kind {
        Quantity::Dimensioned { dim, .. } => Quantity::dimensioned(value, dim),
        Quantity::Bare { defaults, .. } => Quantity::Bare { value, defaults },
    }
}

/// Fisher-Yates, from `rng`.
fn shuffle(order: &mut [usize], rng: &mut ChaCha8Rng) {
    for i in (1..order.len()).rev() {
        let j = Uniform::new_inclusive(0, i).map_or(0, |u| u.sample(rng));
        order.swap(i, j);
    }
}

/// Who of `size` people gets which of the `categories` (profiles and their
/// shares), at most one each: the people in an order shuffled from the
/// seed, the first share's worth to the first profile, the next to the
/// next, each count rounded so that the counts add up to the rounded
/// total.
fn categorised(categories: &[(String, f64)], size: usize, seed: u64) -> Vec<(usize, String)> {
    let mut order: Vec<usize> = (0..size).collect();
    let mut rng = ChaCha8Rng::seed_from_u64(seed ^ 0x6a09_e667_f3bc_c908);
    shuffle(&mut order, &mut rng);
    let mut given = Vec::new();
    let (mut cumulative, mut start) = (0.0, 0);
    for (profile, share) in categories {
        cumulative += share;
        let end = ((cumulative * size as f64).round() as usize).min(size);
        given.extend(
            order[start..end.max(start)]
                .iter()
                .map(|&i| (i, profile.clone())),
        );
        start = end.max(start);
    }
    given
}

/// The members' bases (`members`) put in groups of about
/// [`FLOOR_GROUP`] of the most alike footprints (by their length and
/// width), each sharing the routes from a room's doors by its
/// footprints' bounds, where they are alike enough to be bounded
/// (`FloorGroup::of`). The tighter the bounds, the fewer places they
/// leave to a member's own routes. A population of more first shares the
/// bounds of all its members: where those decide (most of a room whose
/// doors and passages every member's base gets through), their routes
/// are worked out once for the whole population; where they do not, the
/// tighter group's decide, as if there were no wider one.
fn join_floor_group(members: &[Arc<dyn Base>]) {
    let Some(footprints) = members
        .iter()
        .map(|b| b.footprint())
        .collect::<Option<Vec<&crate::floor::Footprint>>>()
    else {
        return;
    };
    let mut order: Vec<usize> = (0..members.len()).collect();
    let size = |k: usize| footprints[k].size_mm();
    order.sort_by(|&a, &b| {
        let (sa, sb) = (size(a), size(b));
        (sa[1].total_cmp(&sb[1]))
            .then(sa[0].total_cmp(&sb[0]))
            .then(a.cmp(&b))
    });
    let groups = order.len().div_ceil(FLOOR_GROUP).max(1);
    let everyone = (groups > 1)
        .then(|| crate::floor::FloorGroup::of(&footprints))
        .flatten()
        .map(Arc::new);
    for k in 0..groups {
        // Even shares, in order of size.
        let part = &order[k * order.len() / groups..(k + 1) * order.len() / groups];
        let alike: Vec<&crate::floor::Footprint> = part.iter().map(|&i| footprints[i]).collect();
        let tight = crate::floor::FloorGroup::of(&alike).map(Arc::new);
        let joined: Vec<Arc<crate::floor::FloorGroup>> =
            everyone.iter().chain(&tight).cloned().collect();
        if joined.is_empty() {
            continue;
        }
        for &i in part {
            members[i].join_floor_groups(&joined);
        }
    }
}

/// About how many members share one group's bounds on their routes
/// (`join_floor_group`).
const FLOOR_GROUP: usize = 16;
