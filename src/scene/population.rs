//! A population: people drawn from the measured adults of ANSUR II, each a
//! [`crate::scene::Person`] of the scenario, and what was drawn for each
//! (which row, which profiles, which values), for reports to say who fails.

/// A population's people: the scenario's persons `members`, in draw order,
/// and what was drawn for each.
#[derive(Clone, Debug, PartialEq)]
pub struct Population {
    pub name: String,
    pub members: std::ops::Range<usize>,
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
    pub fn len(&self) -> usize {
        self.members.len()
    }

    pub fn is_empty(&self) -> bool {
        self.members.is_empty()
    }
}
