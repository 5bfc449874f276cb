//! Whether a word is a name or a keyword, as the grammar says
//! (`ident` and `keyword` in `grammar/reach.pest`): for an editor's
//! rename, which must not write what the parser would refuse.

use pest::Parser;

use super::grammar::{ReachParser, Rule};

/// Whether `word` is, whole, a name the grammar takes (`ident`).
pub fn is_name(word: &str) -> bool {
    whole(Rule::ident, word)
}

/// Whether `word` is, whole, one of the words the grammar keeps from
/// names (`keyword`).
pub fn is_keyword(word: &str) -> bool {
    whole(Rule::keyword, word)
}

fn whole(rule: Rule, word: &str) -> bool {
    ReachParser::parse(rule, word).is_ok_and(|pairs| pairs.as_str() == word)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_and_keywords_are_the_grammars() {
        for name in ["ann", "_x", "shelf_2", "units_of", "byway"] {
            assert!(is_name(name), "{name}");
        }
        for not in ["", "2ann", "an-n", "ann b", "é", "room", "by"] {
            assert!(!is_name(not), "{not}");
        }
        assert!(is_keyword("room") && is_keyword("false"));
        assert!(!is_keyword("rooms") && !is_keyword("ann"));
    }
}
