//! Mannequins from URDF files: `mannequin arm from urdf "arm.urdf" root
//! "torso" tip "hand"`, read with `urdf-rs` and turned into a chain by
//! `kinematics::chain_from_urdf`. Every failure is a diagnostic at the
//! `.reach` text that names the file or the link.

use super::Checker;
use crate::error::{Error, ErrorKind};
use crate::kinematics::{chain_from_urdf, Body, UrdfError};
use crate::names::suggest;
use crate::read::{self, FileKind};
use crate::syntax::ast::UrdfSource;

impl Checker<'_> {
    pub(super) fn urdf_body(&mut self, source: &UrdfSource) -> Option<Body> {
        let path = self.relative_to_file(&source.path.value);
        self.data_files.push(path.clone());
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
        let limit = self.limits.file_bytes;
        let text = match read::read(&path, FileKind::Urdf, &self.sources.allowed, limit) {
            Ok(bytes) => String::from_utf8(bytes).map_err(|_| "it is not UTF-8 text".to_string()),
            Err(e) => Err(e.to_string()),
        };
        let text = match text {
            Ok(t) => t,
            Err(reason) => return fail(self, reason, None, source.path.span),
        };
        let robot = match urdf_rs::read_from_string(&text) {
            Ok(r) => r,
            Err(e) => return fail(self, format!("not valid URDF: {e}"), None, source.path.span),
        };
        match chain_from_urdf(&robot, &source.root.value, &source.tip.value) {
            Ok(chain) => Some(Body::from_chain(chain)),
            Err(UrdfError::UnknownLink { link, available }) => {
                let at = if link == source.root.value {
                    source.root.span
                } else {
                    source.tip.span
                };
                let suggestion = suggest(&link, available.iter().map(String::as_str));
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
