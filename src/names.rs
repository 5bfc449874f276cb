//! Did-you-mean suggestions for unknown names.

/// The candidate closest to `name`, if one is close enough to be a likely
/// typo: at most one edit (a swap of two letters counts as one) per three
/// letters, or a Jaro-Winkler similarity of at least 0.9 (a shared prefix).
/// Ties go to the alphabetically first candidate, so the advice is stable.
pub fn suggest<'a>(name: &str, candidates: impl IntoIterator<Item = &'a str>) -> Option<String> {
    let max_edits = (name.chars().count() / 3).max(1);
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
}
