//! Text from files, names and paths made safe to print on a terminal:
//! control characters (C0, DEL, C1, and so ESC), bidirectional overrides and
//! other invisible format characters are written as `\u{..}` escapes, so
//! that a name can neither move the cursor, recolour the screen, reorder
//! what is shown nor forge a line of a report or a diagnostic. And text
//! made safe inside HTML and SVG markup ([`markup`]).

use std::borrow::Cow;
use std::fmt::Write;

/// Whether `c` is shown escaped: a control character, one that changes
/// how the characters around it are shown without being seen itself, or a
/// noncharacter (U+FDD0-U+FDEF, and the last two of every plane: XML 1.0
/// cannot hold U+FFFE and U+FFFF, so a JUnit file with one is ill-formed).
pub fn is_unsafe(c: char) -> bool {
    let code = u32::from(c);
    c.is_control()
        || (0xFDD0..=0xFDEF).contains(&code)
        || code & 0xFFFE == 0xFFFE
        || matches!(
            c,
            '\u{061C}'
                | '\u{200B}'..='\u{200F}'
                | '\u{2028}'..='\u{202E}'
                | '\u{2060}'..='\u{2069}'
                | '\u{FEFF}'
                | '\u{FFF9}'..='\u{FFFB}'
        )
}

/// `text` with every unsafe character escaped; borrowed when there is none.
pub fn escaped(text: &str) -> Cow<'_, str> {
    escaped_keeping(text, |_| false)
}

/// `text` with every unsafe character escaped but those `keep` says to
/// keep as they are (a tab in a line of source, say).
pub fn escaped_keeping(text: &str, keep: impl Fn(char) -> bool) -> Cow<'_, str> {
    if !text.chars().any(|c| is_unsafe(c) && !keep(c)) {
        return Cow::Borrowed(text);
    }
    let mut out = String::with_capacity(text.len() + 8);
    for c in text.chars() {
        push_escaped(&mut out, c, &keep);
    }
    Cow::Owned(out)
}

/// Push `c` onto `out`, escaped if it is unsafe and not kept.
pub fn push_escaped(out: &mut String, c: char, keep: impl Fn(char) -> bool) {
    if is_unsafe(c) && !keep(c) {
        let _ = write!(out, "\\u{{{:x}}}", u32::from(c));
    } else {
        out.push(c);
    }
}

/// `text` safe as HTML or SVG text or a quoted attribute: `&`, `<`, `>`
/// and `"` as entities.
pub fn markup(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn markup_keeps_text_text() {
        assert_eq!(markup("a<b & \"c\">"), "a&lt;b &amp; &quot;c&quot;&gt;");
    }

    #[test]
    fn unsafe_characters_are_escaped_and_others_kept() {
        let cases = [
            ("kettle", "kettle"),
            ("a\u{1b}[31mred", "a\\u{1b}[31mred"),
            ("line\nforged", "line\\u{a}forged"),
            ("csi\u{9b}2J", "csi\\u{9b}2J"),
            ("abc\u{202e}fed", "abc\\u{202e}fed"),
            ("isolate\u{2067}x\u{2069}", "isolate\\u{2067}x\\u{2069}"),
            ("tab\there", "tab\\u{9}here"),
            ("not\u{FFFF}xml\u{FFFE}", "not\\u{ffff}xml\\u{fffe}"),
            ("plane\u{1FFFF}\u{FDD0}", "plane\\u{1ffff}\\u{fdd0}"),
            ("Straße 10 µm", "Straße 10 µm"),
            ("bom\u{feff}", "bom\\u{feff}"),
        ];
        for (text, shown) in cases {
            assert_eq!(escaped(text), shown, "{text:?}");
        }
        assert!(matches!(escaped("plain"), Cow::Borrowed(_)));
        assert_eq!(escaped_keeping("a\tb\u{7}", |c| c == '\t'), "a\tb\\u{7}");
    }
}
