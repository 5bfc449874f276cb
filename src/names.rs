//! Did-you-mean suggestions for unknown names, bounded in work: a
//! candidate whose length alone rules it out is not compared, and one check
//! of a scenario spends at most [`BUDGET`] character comparisons on
//! suggestions (a file of thousands of unknown names among thousands of
//! known ones gets its first suggestions, not minutes of them).

use std::cell::Cell;

/// Character comparisons (the product of two names' lengths) that one
/// check may spend on suggestions.
pub const BUDGET: u64 = 50_000_000;

thread_local! {
    static LEFT: Cell<u64> = const { Cell::new(BUDGET) };
}

/// Give this thread's checks a fresh budget; returns a guard that gives
/// the next one a fresh budget too.
pub fn fresh_budget() -> BudgetGuard {
    LEFT.with(|l| l.set(BUDGET));
    BudgetGuard
}

/// Restores the budget when a check ends.
pub struct BudgetGuard;

impl Drop for BudgetGuard {
    fn drop(&mut self) {
        LEFT.with(|l| l.set(BUDGET));
    }
}

/// Take `cost` from the budget; false (and nothing taken) if too little
/// is left.
fn spend(cost: u64) -> bool {
    LEFT.with(|l| {
        let left = l.get();
        let ok = cost <= left;
        if ok {
            l.set(left - cost);
        }
        ok
    })
}

/// The candidate closest to `name`, if one is close enough to be a likely
/// typo: at most one edit (a swap of two letters counts as one) per three
/// letters, or a Jaro-Winkler similarity of at least 0.9 (a shared prefix).
/// Ties go to the alphabetically first candidate, so the advice is stable.
pub fn suggest<'a>(name: &str, candidates: impl IntoIterator<Item = &'a str>) -> Option<String> {
    let length = name.chars().count();
    let max_edits = (length / 3).max(1);
    let candidates: Vec<&str> = candidates
        .into_iter()
        .filter(|c| could_be_close(length, c.chars().count(), max_edits))
        .collect();
    let cost = candidates.iter().map(|c| c.len() as u64).sum::<u64>();
    if !spend(cost.saturating_mul(name.len() as u64)) {
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
    use super::suggest;

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
        let _fresh = super::fresh_budget();
        assert_eq!(suggest(&long, ["aaa", "aaaa"]), None);
        assert_eq!(super::LEFT.with(|l| l.get()), super::BUDGET);
    }

    #[test]
    fn suggestions_stop_when_the_budget_is_spent() {
        let names: Vec<String> = (0..5_000).map(|i| format!("name{i:05}")).collect();
        let _fresh = super::fresh_budget();
        let mut given = 0;
        for i in 0..5_000 {
            let typo = format!("nmae{i:05}");
            given += usize::from(suggest(&typo, names.iter().map(String::as_str)).is_some());
        }
        // 81 comparisons per candidate: 50,000,000 / (81 * 5,000) = 123
        // full scans, then nothing.
        assert!((100..=130).contains(&given), "{given}");
    }
}
