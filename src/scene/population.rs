//! A population: people drawn from the measured adults of ANSUR II, each a
//! [`crate::scene::Person`] of the scenario, and what was drawn for each
//! (which row, which profiles, which values), for reports to say who fails.

/// A population's people: what was drawn for each, in draw order, and
/// those built as the scenario's persons `members` (everyone, unless a
/// shard of a run asked for its own people only), the first of them the
/// `first`-th drawn.
#[derive(Clone, Debug, PartialEq)]
pub struct Population {
    pub name: String,
    pub members: std::ops::Range<usize>,
    /// The draw's index (0 for the first drawn) of the person at
    /// `members.start`.
    pub first: usize,
    pub drawn: Vec<Drawn>,
    pub seed: u64,
}

/// What was drawn for one person.
#[derive(Clone, Debug, PartialEq)]
pub struct Drawn {
    /// The survey's row (0 for the first person after the header).
    pub row: usize,
    pub female: bool,
    pub age_years: f64,
    pub stature_mm: f64,
    /// The `draw`s' values, in internal units (mm, rad), by name.
    pub values: Vec<(String, f64)>,
    /// The profiles applied, in the population's order.
    pub profiles: Vec<String>,
}

impl Population {
    /// How many people were drawn.
    pub fn len(&self) -> usize {
        self.drawn.len()
    }

    pub fn is_empty(&self) -> bool {
        self.drawn.is_empty()
    }

    /// The scenario's person for the `i`-th drawn (0 for the first), if
    /// they were built.
    pub fn person_of(&self, i: usize) -> Option<usize> {
        let k = i.checked_sub(self.first)?;
        (k < self.members.len()).then_some(self.members.start + k)
    }
}
