//! The TextMate grammar of the VS Code extension (`editors/vscode/`)
//! against the pest grammar it highlights: every word the pest grammar
//! takes as a keyword is one the TextMate grammar colours, every task
//! plugin is coloured as a task, and the extension names the grammar and
//! starts `reach lsp`.

use std::collections::BTreeSet;
use std::path::Path;

use reach::plugin::{PluginKind, Registry};

const ROOT: &str = env!("CARGO_MANIFEST_DIR");

fn read(path: &str) -> String {
    std::fs::read_to_string(Path::new(ROOT).join(path)).unwrap()
}

/// The words in the pest grammar's quoted literals, comments left out.
fn pest_words() -> BTreeSet<String> {
    let mut words = BTreeSet::new();
    for line in read("grammar/reach.pest").lines() {
        let code = line.split("//").next().unwrap_or_default();
        for (k, part) in code.split('"').enumerate() {
            let is_word =
                !part.is_empty() && part.chars().all(|c| c.is_ascii_lowercase() || c == '_');
            if k % 2 == 1 && is_word && part != "_" {
                words.insert(part.to_string());
            }
        }
    }
    words
}

/// The words of every `\b(a|b|c)` alternation in the TextMate grammar's
/// patterns, by the repository entry they are in.
fn coloured(grammar: &serde_json::Value, entry: &str) -> BTreeSet<String> {
    let text = grammar["repository"][entry].to_string();
    let mut words = BTreeSet::new();
    for group in text.split('(').skip(1) {
        let Some(body) = group.split(')').next() else {
            continue;
        };
        for word in body.split('|') {
            if !word.is_empty() && word.chars().all(|c| c.is_ascii_lowercase() || c == '_') {
                words.insert(word.to_string());
            }
        }
    }
    words
}

#[test]
fn the_textmate_grammar_colours_every_keyword_of_the_pest_grammar_and_every_task() {
    let grammar: serde_json::Value =
        serde_json::from_str(&read("editors/vscode/syntaxes/reach.tmLanguage.json")).unwrap();
    let mut known = BTreeSet::new();
    for entry in ["declarations", "keywords", "numbers", "tasks"] {
        known.extend(coloured(&grammar, entry));
    }
    // `e` is a number's exponent, which the numbers pattern takes.
    let missing: Vec<String> = pest_words()
        .into_iter()
        .filter(|w| w != "e" && !known.contains(w))
        .collect();
    assert!(missing.is_empty(), "not coloured: {missing:?}");
    let tasks = coloured(&grammar, "tasks");
    for task in Registry::builtin().names(PluginKind::Task) {
        assert!(
            tasks.contains(task),
            "task `{task}` is not coloured as a task"
        );
    }
}

#[test]
fn the_extension_names_its_grammar_and_starts_the_language_server() {
    let package: serde_json::Value =
        serde_json::from_str(&read("editors/vscode/package.json")).unwrap();
    let grammar = &package["contributes"]["grammars"][0];
    assert_eq!(grammar["language"], "reach");
    let path = grammar["path"].as_str().unwrap();
    assert!(
        Path::new(ROOT).join("editors/vscode").join(path).is_file(),
        "{path}"
    );
    assert_eq!(
        package["contributes"]["languages"][0]["extensions"][0],
        ".reach"
    );
    let extension = read("editors/vscode/extension.js");
    assert!(
        extension.contains("args: [\"lsp\"]"),
        "the extension starts `reach lsp`"
    );
}
