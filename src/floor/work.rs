//! The work of working out floor, in units of the meter
//! ([`crate::meter`]), counted as it is done so that it can be cut short
//! where it would take a run past its limit.

/// Floor cut short: its work so far (`work`) passed what it was allowed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct CutShort {
    pub work: u64,
}

/// The work of floor being worked out, and what it is allowed.
pub struct Work<'a> {
    pub done: u64,
    within: &'a (dyn Fn(u64) -> bool + Sync),
    /// The pieces added, where they are written down.
    looked: Option<Looked>,
}

impl<'a> Work<'a> {
    /// None done yet; `within` says whether a total is allowed.
    pub fn new(within: &'a (dyn Fn(u64) -> bool + Sync)) -> Self {
        Work {
            done: 0,
            within,
            looked: None,
        }
    }

    /// Like `new`, and the pieces added written down ([`Work::looked`]).
    pub fn looking(within: &'a (dyn Fn(u64) -> bool + Sync)) -> Self {
        Work {
            looked: Some(Looked::default()),
            ..Work::new(within)
        }
    }

    /// The pieces added, if they were written down.
    pub fn looked(self) -> Looked {
        self.looked.unwrap_or_default().settled()
    }

    /// Add the work of piece `key` (written down, if this work is
    /// looking); cut short as `add`.
    pub fn add_piece(&mut self, key: u64, units: u64) -> Result<(), CutShort> {
        if let Some(looked) = &mut self.looked {
            looked.add(key, units);
        }
        self.add(units)
    }

    /// Whether `more` units on top of the work done would be allowed.
    pub fn allows(&self, more: u64) -> bool {
        (self.within)(self.done.saturating_add(more))
    }

    /// Cut short after this work and `inner`'s more, done inside it (the
    /// work a cut short names is all that was counted).
    pub fn cut_short_with(&self, inner: u64) -> CutShort {
        CutShort {
            work: self.done.saturating_add(inner),
        }
    }

    /// Add `units`; cut short if the work done is more than allowed.
    pub fn add(&mut self, units: u64) -> Result<(), CutShort> {
        self.done = self.done.saturating_add(units);
        if (self.within)(self.done) {
            Ok(())
        } else {
            Err(CutShort { work: self.done })
        }
    }
}

/// The pieces of floor a search looked at (by the key they are kept by,
/// `region::Piece`), or the shapes it grew, with what each costs: a
/// search that looks at them again is charged for looking, not for
/// working them out. Each once, by key, once settled.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Looked(Vec<(u64, u64)>);

impl Looked {
    /// Piece `key`, costing `units` (one that costs nothing is shared by
    /// any room, and not written down).
    fn add(&mut self, key: u64, units: u64) {
        if units > 0 {
            self.0.push((key, units));
        }
    }

    /// Sorted by key, each piece once.
    fn settled(mut self) -> Looked {
        self.0.sort_unstable();
        self.0.dedup_by_key(|&mut (key, _)| key);
        self
    }

    /// Each of `keyed` (a key and what it costs) once.
    pub fn of(keyed: impl IntoIterator<Item = (u64, u64)>) -> Looked {
        let mut all = Looked::default();
        keyed
            .into_iter()
            .for_each(|(key, units)| all.add(key, units));
        all.settled()
    }

    /// The pieces of both, each once.
    pub fn with(&self, other: &Looked) -> Looked {
        Looked::of(self.iter().chain(other.iter()))
    }

    /// Whether piece `key` was looked at.
    pub fn contains(&self, key: u64) -> bool {
        self.0.binary_search_by_key(&key, |&(k, _)| k).is_ok()
    }

    /// Each key and what it costs, by key.
    pub fn iter(&self) -> impl Iterator<Item = (u64, u64)> + '_ {
        self.0.iter().copied()
    }

    /// What all of them cost.
    pub fn units(&self) -> u64 {
        (self.0.iter()).fold(0, |sum: u64, &(_, units)| sum.saturating_add(units))
    }
}

/// Allows any work.
pub fn unbounded(_: u64) -> bool {
    true
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn work_is_cut_short_once_past_what_is_allowed_and_says_how_much() {
        let allowed = |units: u64| units <= 10;
        let mut work = Work::new(&allowed);
        assert_eq!(work.add(6), Ok(()));
        assert_eq!(work.add(4), Ok(()));
        assert_eq!(work.add(1), Err(CutShort { work: 11 }));
    }

    #[test]
    fn the_pieces_looked_at_are_written_down_each_once() {
        let mut work = Work::looking(&unbounded);
        for (key, units) in [(1, 10), (2, 20), (0, 0), (1, 10)] {
            work.add_piece(key, units).unwrap();
        }
        assert_eq!(work.done, 40, "the work is all counted, twice if twice");
        let looked = work.looked();
        assert_eq!(looked, Looked(vec![(1, 10), (2, 20)]));
        assert!(looked.contains(2) && !looked.contains(0) && !looked.contains(4));
        assert_eq!(Looked::of([(2, 20), (1, 10), (2, 20), (3, 0)]), looked);
        assert_eq!(looked.units(), 30);
        assert_eq!(Work::new(&unbounded).looked(), Looked::default());
    }
}
