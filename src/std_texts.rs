//! The standard library's module texts, embedded in the binary, and which
//! module declares a name: what an unknown name's diagnostic needs to say
//! "add `use std::people`" (this module imports nothing, so that the
//! errors may use it).

/// Every module, by name, in the order `reach stdlib` lists them.
pub const MODULES: &[(&str, &str)] = &[
    ("arm", include_str!("../stdlib/arm.reach")),
    ("body", include_str!("../stdlib/body.reach")),
    ("paper", include_str!("../stdlib/paper.reach")),
    ("people", include_str!("../stdlib/people.reach")),
    ("populations", include_str!("../stdlib/populations.reach")),
];

/// The text of module `name`, if there is one.
pub fn module(name: &str) -> Option<&'static str> {
    MODULES
        .iter()
        .find(|(n, _)| *n == name)
        .map(|(_, text)| *text)
}

/// The module that declares `name` as a `keyword` (`mannequin`,
/// `profile`, `base`, `vision`, `population`) at the start of a line, if
/// one does.
pub fn home_of(keyword: &str, name: &str) -> Option<&'static str> {
    MODULES
        .iter()
        .find(|(_, text)| text.lines().any(|l| declares(l, keyword, name)))
        .map(|(module, _)| *module)
}

/// Whether `line` starts the declaration of `name` as a `keyword`.
pub fn declares(line: &str, keyword: &str, name: &str) -> bool {
    let Some(rest) = line.strip_prefix(keyword).and_then(|r| r.strip_prefix(' ')) else {
        return false;
    };
    rest.trim_start().strip_prefix(name).is_some_and(|after| {
        after
            .chars()
            .next()
            .is_none_or(|c| !(c.is_alphanumeric() || c == '_'))
    })
}

#[cfg(test)]
mod tests {
    use super::home_of;

    #[test]
    fn the_module_that_declares_a_name_is_found() {
        assert_eq!(home_of("mannequin", "woman_5th_seated"), Some("people"));
        assert_eq!(home_of("mannequin", "woman_5th"), Some("people"));
        assert_eq!(home_of("base", "power_wheelchair"), Some("people"));
        assert_eq!(
            home_of("population", "manual_wheelchair_users"),
            Some("populations")
        );
        assert_eq!(home_of("mannequin", "right_arm"), Some("arm"));
        assert_eq!(home_of("mannequin", "woman_5"), None);
        assert_eq!(home_of("base", "woman_5th"), None);
    }
}
