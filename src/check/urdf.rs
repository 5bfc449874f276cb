//! Mannequins from URDF files: `mannequin arm from urdf "arm.urdf" root
//! "torso" tip "hand"`, read with `urdf-rs` and turned into a chain by
//! `kinematics::chain_from_urdf`. Every failure is a diagnostic at the
//! `.reach` text that names the file or the link.

use super::Checker;
use crate::error::{thousands, Error, ErrorKind};
use crate::kinematics::{chain_from_urdf, Body, UrdfError};
use crate::read::{self, FileKind};
use crate::syntax::ast::UrdfSource;

impl Checker<'_> {
    pub(super) fn urdf_body(&mut self, source: &UrdfSource) -> Option<Body> {
        let path = self.relative_to_file(&source.path.value);
        self.cx.data_files.push(path.clone());
        let shown = path.display().to_string();
        let fail = |c: &mut Self, reason: String, suggestion: Option<String>, span| {
            let kind = ErrorKind::BadUrdf {
                path: shown.clone(),
                reason,
                suggestion,
            };
            c.error(Error::new(kind, span));
            None
        };
        let limit = self.cx.limits.file_bytes;
        let text = match read::read(&path, FileKind::Urdf, &self.cx.sources.allowed, limit) {
            Ok(bytes) => String::from_utf8(bytes).map_err(|_| "it is not UTF-8 text".to_string()),
            Err(e) => Err(e.to_string()),
        };
        let text = match text {
            Ok(t) => t,
            Err(reason) => return fail(self, reason, None, source.path.span),
        };
        if let Some(beyond) = xml_beyond(&text, self.cx.limits.nesting, MOST_URDF_ELEMENTS) {
            let reason = match beyond {
                XmlBeyond::Depth(depth) => format!(
                    "its elements nest {depth} deep, beyond the limit of {} levels (--max-nesting)",
                    self.cx.limits.nesting
                ),
                XmlBeyond::Elements => format!(
                    "it holds more than {} elements (links, joints and their parts): more than any body needs",
                    thousands(MOST_URDF_ELEMENTS as u64)
                ),
            };
            return fail(self, reason, None, source.path.span);
        }
        let robot = match urdf_rs::read_from_string(&text) {
            Ok(r) => r,
            Err(e) => return fail(self, format!("not valid URDF: {e}"), None, source.path.span),
        };
        let radius_mm = match &source.radius {
            Some(e) => Some(self.radius(e)?),
            None => None,
        };
        match chain_from_urdf(&robot, &source.root.value, &source.tip.value) {
            Ok(mut chain) => {
                if !self.within_joints(chain.joints.len(), source.tip.span) {
                    return None;
                }
                if let Some(r) = radius_mm {
                    chain.joints.iter_mut().for_each(|j| j.link.radius_mm = r);
                    chain.effector_link.radius_mm = r;
                }
                Some(Body::from_chain(chain))
            }
            Err(UrdfError::UnknownLink { link, available }) => {
                let at = if link == source.root.value {
                    source.root.span
                } else {
                    source.tip.span
                };
                let suggestion = self
                    .cx
                    .suggestions
                    .suggest(&link, available.iter().map(String::as_str));
                fail(
                    self,
                    UrdfError::UnknownLink { link, available }.to_string(),
                    suggestion,
                    at,
                )
            }
            Err(e) => fail(self, e.to_string(), None, source.tip.span),
        }
    }
}

/// The most elements a URDF may hold: a body of a few dozen links has a
/// few hundred; a file of millions of empty links (`<link name="a"/>`,
/// within the byte limit) took gigabytes to parse.
const MOST_URDF_ELEMENTS: usize = 100_000;

/// How an XML text is beyond what is parsed.
#[derive(Debug, PartialEq, Eq)]
enum XmlBeyond {
    /// Its elements nest this deep.
    Depth(usize),
    /// It holds more elements than allowed.
    Elements,
}

/// Whether the elements of an XML text nest deeper than `max_depth` (a
/// URDF nests three or four deep) or number more than `max_elements`:
/// checked in one pass before the XML parser, whose cost grows with the
/// depth and whose memory with the elements, sees the text. Comments,
/// processing instructions, declarations and quoted attribute values are
/// skipped; a malformed text is left for the parser to report.
fn xml_beyond(text: &str, max_depth: usize, max_elements: usize) -> Option<XmlBeyond> {
    let bytes = text.as_bytes();
    let skip_past = |from: usize, end: &[u8]| {
        bytes[from..]
            .windows(end.len())
            .position(|w| w == end)
            .map_or(bytes.len(), |p| from + p + end.len())
    };
    let (mut depth, mut i, mut elements) = (0usize, 0usize, 0usize);
    while let Some(p) = bytes[i..].iter().position(|&b| b == b'<') {
        i += p + 1;
        match bytes.get(i) {
            Some(b'!') if bytes[i..].starts_with(b"!--") => i = skip_past(i, b"-->"),
            Some(b'!') if bytes[i..].starts_with(b"![CDATA[") => i = skip_past(i, b"]]>"),
            Some(b'!' | b'?') => i = skip_past(i, b">"),
            Some(b'/') => {
                depth = depth.saturating_sub(1);
                i = skip_past(i, b">");
            }
            Some(_) => {
                let (end, self_closing) = tag_end(bytes, i);
                i = end;
                elements += 1;
                if elements > max_elements {
                    return Some(XmlBeyond::Elements);
                }
                if !self_closing {
                    depth += 1;
                    if depth > max_depth {
                        return Some(XmlBeyond::Depth(depth));
                    }
                }
            }
            None => break,
        }
    }
    None
}

/// Where a start tag beginning at `from` ends (past its `>`), and whether
/// it closes itself (`/>`); quoted attribute values may hold `>`.
fn tag_end(bytes: &[u8], from: usize) -> (usize, bool) {
    let mut quote = None;
    for (k, &b) in bytes[from..].iter().enumerate() {
        match (quote, b) {
            (Some(q), _) if b == q => quote = None,
            (Some(_), _) => {}
            (None, b'"' | b'\'') => quote = Some(b),
            (None, b'>') => {
                let self_closing = k > 0 && bytes[from + k - 1] == b'/';
                return (from + k + 1, self_closing);
            }
            _ => {}
        }
    }
    (bytes.len(), false)
}

#[cfg(test)]
mod tests {
    use super::{xml_beyond, XmlBeyond};

    fn xml_too_deep(text: &str, max_depth: usize) -> Option<usize> {
        match xml_beyond(text, max_depth, usize::MAX) {
            Some(XmlBeyond::Depth(depth)) => Some(depth),
            _ => None,
        }
    }

    #[test]
    fn elements_are_counted_to_their_bound() {
        let links = "<link name=\"a\"/>".repeat(10);
        let urdf = format!("<robot name=\"r\"><!-- <link/> -->{links}</robot>");
        assert_eq!(xml_beyond(&urdf, 8, 11), None);
        assert_eq!(xml_beyond(&urdf, 8, 10), Some(XmlBeyond::Elements));
    }

    #[test]
    fn nesting_is_counted_past_comments_quotes_and_empty_elements() {
        let urdf = r#"<?xml version="1.0"?><!-- <a><b><c> -->
            <robot name="r"><link name="a>b"/><joint name="j" type="fixed">
            <origin xyz="0 0 1"/><parent link="a"/><child link="b"/></joint></robot>"#;
        assert_eq!(xml_too_deep(urdf, 2), None);
        assert_eq!(xml_too_deep(urdf, 1), Some(2));
        let deep = format!("{}{}", "<a>".repeat(100_000), "</a>".repeat(100_000));
        assert_eq!(xml_too_deep(&deep, 64), Some(65));
        assert_eq!(xml_too_deep("<a><![CDATA[<b><c>]]></a>", 1), None);
    }
}
