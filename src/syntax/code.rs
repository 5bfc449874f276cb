//! The bytes of a scenario's text that are code: outside `//` and
//! `/* */` comments and string literals. What the checks made before and
//! beside pest look at (how deep brackets nest, which brace is left open).

/// Each byte of `text` outside comments and strings, with its offset.
pub fn code_bytes(text: &str) -> impl Iterator<Item = (usize, u8)> + '_ {
    let bytes = text.as_bytes();
    let mut i = 0;
    std::iter::from_fn(move || {
        while i < bytes.len() {
            let at = i;
            match bytes[i] {
                b'/' if bytes.get(i + 1) == Some(&b'/') => {
                    while i < bytes.len() && bytes[i] != b'\n' {
                        i += 1;
                    }
                }
                b'/' if bytes.get(i + 1) == Some(&b'*') => {
                    i += 2;
                    while i + 1 < bytes.len() && !(bytes[i] == b'*' && bytes[i + 1] == b'/') {
                        i += 1;
                    }
                    i += 2;
                }
                b'"' => {
                    i += 1;
                    while i < bytes.len() && bytes[i] != b'"' && bytes[i] != b'\n' {
                        i += if bytes[i] == b'\\' { 2 } else { 1 };
                    }
                    i += 1;
                }
                b => {
                    i += 1;
                    return Some((at, b));
                }
            }
        }
        None
    })
}

#[cfg(test)]
mod tests {
    use super::code_bytes;

    #[test]
    fn comments_and_strings_are_not_code() {
        let text = "a{ // {\n\"}{\" /* ( */ b}";
        let code: String = code_bytes(text).map(|(_, b)| b as char).collect();
        assert_eq!(code, "a{ \n  b}");
        let braces: Vec<usize> = code_bytes(text)
            .filter(|(_, b)| *b == b'{')
            .map(|(i, _)| i)
            .collect();
        assert_eq!(braces, [1]);
    }
}
