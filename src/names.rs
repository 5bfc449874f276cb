//! Did-you-mean suggestions for unknown names, bounded in work: a
//! candidate whose length alone rules it out is not compared, and one check
//! of a scenario spends at most [`BUDGET`] character comparisons on
//! suggestions (a file of thousands of unknown names among thousands of
//! known ones gets its first suggestions, not minutes of them).

use std::cell::Cell;

/// Character comparisons (the product of two names' lengths) that one
/// check may spend on suggestions.
pub const BUDGET: u64 = 50_000_000;

/// The suggestions one check may still make: a budget of character
/// comparisons, owned by the check (`crate::Session::check` makes one for
/// the loader and the checker to share).
#[derive(Debug)]
pub struct Suggestions {
    left: Cell<u64>,
}

impl Default for Suggestions {
    fn default() -> Self {
        Suggestions {
            left: Cell::new(BUDGET),
        }
    }
}

impl Suggestions {
    /// Take `cost` from the budget; false (and nothing taken) if too
    /// little is left.
    fn spend(&self, cost: u64) -> bool {
        let left = self.left.get();
        let ok = cost <= left;
        if ok {
            self.left.set(left - cost);
        }
        ok
    }

    /// The candidate closest to `name`, if one is close enough to be a
    /// likely typo: at most one edit (a swap of two letters counts as one)
    /// per three letters, or a Jaro-Winkler similarity of at least 0.9 (a
    /// shared prefix). Ties go to the alphabetically first candidate, so
    /// the advice is stable. None once the budget is spent.
    pub fn suggest<'a>(
        &self,
        name: &str,
        candidates: impl IntoIterator<Item = &'a str>,
    ) -> Option<String> {
        let length = name.chars().count();
        let max_edits = (length / 3).max(1);
        let candidates: Vec<&str> = candidates
            .into_iter()
            .filter(|c| could_be_close(length, c.chars().count(), max_edits))
            .collect();
        let cost = candidates.iter().map(|c| c.len() as u64).sum::<u64>();
        if !self.spend(cost.saturating_mul(name.len() as u64)) {
            return None;
        }
        candidates
            .into_iter()
            .filter_map(|c| {
                let edits = strsim::osa_distance(name, c);
                let close = edits <= max_edits || strsim::jaro_winkler(name, c) >= 0.9;
                close.then_some((edits, c))
            })
            .min_by(|a, b| a.0.cmp(&b.0).then_with(|| a.1.cmp(b.1)))
            .map(|(_, c)| c.to_string())
    }
}

/// Whether names of `a` and `b` characters can be close: within
/// `max_edits` of each other's length, or the shorter at least half the
/// longer (below that, Jaro-Winkler stays under 0.9 whatever the letters:
/// the Jaro similarity is at most (2 + a/b) / 3 < 0.84, and a shared prefix
/// adds at most 0.4 of what is left).
fn could_be_close(a: usize, b: usize, max_edits: usize) -> bool {
    let (short, long) = (a.min(b), a.max(b));
    long - short <= max_edits || 2 * short >= long
}

#[cfg(test)]
mod tests {
    use super::{Suggestions, BUDGET};

    fn suggest<'a>(name: &str, candidates: impl IntoIterator<Item = &'a str>) -> Option<String> {
        Suggestions::default().suggest(name, candidates)
    }

    #[test]
    fn suggests_the_closest_name() {
        assert_eq!(
            suggest("mgu", ["mug", "plate", "kettle"]),
            Some("mug".into())
        );
        assert_eq!(
            suggest("incremantal", ["incremental", "dls"]),
            Some("incremental".into())
        );
        assert_eq!(
            suggest("shoulder_flex", ["shoulder_flexion", "elbow_flexion"]),
            Some("shoulder_flexion".into())
        );
        assert_eq!(suggest("arms", ["arm", "leg"]), Some("arm".into()));
    }

    #[test]
    fn suggests_nothing_for_a_distant_name() {
        assert_eq!(suggest("zzz", ["mug", "plate"]), None);
        assert_eq!(suggest("x", std::iter::empty::<&str>()), None);
    }

    #[test]
    fn a_long_name_is_not_compared_with_short_ones() {
        let long = "a".repeat(60_000);
        let budget = Suggestions::default();
        assert_eq!(budget.suggest(&long, ["aaa", "aaaa"]), None);
        assert_eq!(budget.left.get(), BUDGET);
    }

    #[test]
    fn suggestions_stop_when_the_budget_is_spent() {
        let names: Vec<String> = (0..5_000).map(|i| format!("name{i:05}")).collect();
        let budget = Suggestions::default();
        let mut given = 0;
        for i in 0..5_000 {
            let typo = format!("nmae{i:05}");
            let suggested = budget.suggest(&typo, names.iter().map(String::as_str));
            given += usize::from(suggested.is_some());
        }
        // 81 comparisons per candidate: 50,000,000 / (81 * 5,000) = 123
        // full scans, then nothing.
        assert!((100..=130).contains(&given), "{given}");
    }
}
