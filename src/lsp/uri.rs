//! Files named as the protocol names them (`file:///home/a/kitchen.reach`)
//! and as the loader reads them (paths), through the `url` crate's
//! percent-encoding and platform rules.

use std::path::{Path, PathBuf};
use std::str::FromStr;

use lsp_types::Uri;

/// The path of a `file:` URI; none for another scheme (an editor's
/// unsaved `untitled:` buffer).
pub fn path_of(uri: &Uri) -> Option<PathBuf> {
    let url = url::Url::parse(uri.as_str()).ok()?;
    (url.scheme() == "file").then(|| url.to_file_path().ok())?
}

/// The `file:` URI of `path` (made absolute from the working directory).
pub fn uri_of_path(path: &Path) -> Option<Uri> {
    let absolute = std::path::absolute(path).ok()?;
    let url = url::Url::from_file_path(absolute).ok()?;
    Uri::from_str(url.as_str()).ok()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_path_goes_there_and_back_with_its_spaces_encoded() {
        let path = Path::new("/home/a b/kitchen.reach");
        let uri = uri_of_path(path).unwrap();
        assert_eq!(uri.as_str(), "file:///home/a%20b/kitchen.reach");
        assert_eq!(path_of(&uri).as_deref(), Some(path));
        let untitled = Uri::from_str("untitled:Untitled-1").unwrap();
        assert_eq!(path_of(&untitled), None);
    }
}
