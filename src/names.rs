//! Did-you-mean suggestions for unknown names.

/// The candidate closest to `name`, if one is close enough to be a likely
/// typo (Jaro-Winkler similarity of at least 0.8).
pub fn suggest<'a>(name: &str, candidates: impl IntoIterator<Item = &'a str>) -> Option<String> {
    candidates
        .into_iter()
        .map(|c| (strsim::jaro_winkler(name, c), c))
        .filter(|(score, _)| *score >= 0.8)
        .max_by(|a, b| a.0.total_cmp(&b.0).then_with(|| b.1.cmp(a.1)))
        .map(|(_, c)| c.to_string())
}

#[cfg(test)]
mod tests {
    use super::suggest;

    #[test]
    fn suggests_the_closest_name() {
        assert_eq!(suggest("mgu", ["mug", "plate", "kettle"]), Some("mug".into()));
        assert_eq!(suggest("incremantal", ["incremental", "dls"]), Some("incremental".into()));
    }

    #[test]
    fn suggests_nothing_for_a_distant_name() {
        assert_eq!(suggest("zzz", ["mug", "plate"]), None);
        assert_eq!(suggest("x", std::iter::empty::<&str>()), None);
    }
}
