//! `population` declarations: from pest pairs to [`PopulationDecl`].

use pest::iterators::Pair;

use super::ast::{Distribution, DrawDecl, PersonDecl, PopulationDecl, ProfileChoice};
use super::grammar::Rule;
use super::parser::Builder;
use crate::span::Spanned;

impl Builder {
    pub(super) fn population(&mut self, pair: Pair<Rule>) -> PopulationDecl {
        let span = self.span(&pair);
        let mut it = pair.into_inner();
        let name = self.name(it.next().unwrap());
        let mut population = PopulationDecl {
            person: PersonDecl {
                name: name.clone(),
                mannequins: Vec::new(),
                bases: Vec::new(),
                visions: Vec::new(),
                span,
            },
            name,
            from: None,
            size: None,
            seed: None,
            women: None,
            draws: Vec::new(),
            profiles: Vec::new(),
            choices: Vec::new(),
            span,
        };
        for p in it {
            let first_expr = |b: &mut Self, p: Pair<Rule>| b.expr(p.into_inner().next().unwrap());
            match p.as_rule() {
                Rule::population_from => {
                    population.from = Some(self.name(p.into_inner().next().unwrap()));
                }
                Rule::population_size => population.size = Some(first_expr(self, p)),
                Rule::population_seed => population.seed = Some(first_expr(self, p)),
                Rule::population_women => population.women = Some(first_expr(self, p)),
                Rule::population_draw => {
                    let draw = self.draw(p);
                    population.draws.push(draw);
                }
                Rule::population_profile => {
                    let mut parts = p.into_inner();
                    let name = self.name(parts.next().unwrap());
                    let share = self.expr(parts.next().unwrap());
                    population.profiles.push((name, share));
                }
                Rule::population_choice => {
                    let span = self.span(&p);
                    let options = p
                        .into_inner()
                        .filter(|part| part.as_rule() == Rule::choice_share)
                        .map(|part| {
                            let mut parts = part.into_inner();
                            let name = self.name(parts.next().unwrap());
                            (name, self.expr(parts.next().unwrap()))
                        })
                        .collect();
                    population.choices.push(ProfileChoice { options, span });
                }
                _ => self.person_item(&mut population.person, p),
            }
        }
        population
    }

    fn draw(&mut self, pair: Pair<Rule>) -> DrawDecl {
        let mut it = pair.into_inner();
        let name = self.name(it.next().unwrap());
        let mut dist = it.next().unwrap().into_inner();
        let kind_pair = dist.next().unwrap();
        let kind = match kind_pair.as_str() {
            "normal" => Distribution::Normal,
            _ => Distribution::Uniform,
        };
        let kind = Spanned::new(kind, self.span(&kind_pair));
        let first = self.expr(dist.next().unwrap());
        let second = self.expr(dist.next().unwrap());
        let within = match (it.next(), it.next()) {
            (Some(low), Some(high)) => Some((self.expr(low), self.expr(high))),
            _ => None,
        };
        DrawDecl {
            name,
            kind,
            first,
            second,
            within,
        }
    }
}
