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
}

impl<'a> Work<'a> {
    /// None done yet; `within` says whether a total is allowed.
    pub fn new(within: &'a (dyn Fn(u64) -> bool + Sync)) -> Self {
        Work { done: 0, within }
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
}
