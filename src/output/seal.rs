//! Seals on the records an output set writes beside its files (its list
//! of files, `.reach-set`; its journal while it is placed): the record's
//! text with an HMAC-SHA256 of it under a random key of the user's
//! (`$XDG_STATE_HOME/reach/key`, else `~/.local/state/reach/key`, made on
//! first use, readable by the user alone). A record is acted on only
//! where it is a regular file of the user's, not larger than
//! `RECORD_BYTES`, and its seal holds: a list or a journal that this tool
//! did not write for this user (one a repository carries, one another
//! user planted in a shared folder, one written by hand) lists nothing and
//! replays nothing. Where the user has no key and none can be made (no
//! home, a home that cannot be written), records are written unsealed and
//! none is acted on: a set then removes no file of an earlier set (the
//! command line says so), and a killed set is not finished.

use std::io::{Read, Write};
use std::path::{Path, PathBuf};

use hmac::{Hmac, Mac};
use sha2::{Digest, Sha256};

/// A key's length in bytes.
const KEY_BYTES: usize = 32;
/// A sealed record's first line: this, then the seal in hex.
const SEALED: &str = "reach-sealed ";

/// What seals records and opens them: the user's key, if there is one.
#[derive(Clone)]
pub struct Sealer {
    key: Option<[u8; KEY_BYTES]>,
}

impl Sealer {
    /// The user's sealer: their key, made the first time.
    pub fn of_user() -> Self {
        Sealer {
            key: key_dir().and_then(|dir| user_key(&dir)),
        }
    }

    /// A sealer with `key` (tests), or none.
    #[cfg(test)]
    pub fn with_key(key: Option<[u8; KEY_BYTES]>) -> Self {
        Sealer { key }
    }

    /// Whether there is a key to seal with.
    pub fn has_key(&self) -> bool {
        self.key.is_some()
    }

    /// `body` with its seal first (unsealed where there is no key).
    pub fn seal(&self, body: &str) -> String {
        match self.mac(body) {
            Some(mac) => format!("{SEALED}{}\n{body}", hex(&mac.finalize().into_bytes())),
            None => body.to_string(),
        }
    }

    /// The body of `text` where its seal holds under this key.
    pub fn open<'t>(&self, text: &'t str) -> Option<&'t str> {
        let (first, body) = text.split_once('\n')?;
        let seal = unhex(first.strip_prefix(SEALED)?)?;
        self.mac(body)?.verify_slice(&seal).ok()?;
        Some(body)
    }

    fn mac(&self, body: &str) -> Option<Hmac<Sha256>> {
        let mut mac = Hmac::<Sha256>::new_from_slice(self.key.as_ref()?).ok()?;
        mac.update(body.as_bytes());
        Some(mac)
    }
}

/// The SHA-256 of `bytes`, in hex: what a set's list records of each of
/// its files.
pub fn digest(bytes: &[u8]) -> String {
    hex(&Sha256::digest(bytes))
}

/// The SHA-256 of the regular file at `path` (not through a link), in
/// hex; none where it is not one or cannot be read.
pub fn digest_of_file(path: &Path) -> Option<String> {
    if !std::fs::symlink_metadata(path).ok()?.is_file() {
        return None;
    }
    let mut file = std::fs::File::open(path).ok()?;
    let mut hasher = Sha256::new();
    let mut buffer = vec![0u8; 1 << 16];
    loop {
        match file.read(&mut buffer).ok()? {
            0 => break,
            n => hasher.update(&buffer[..n]),
        }
    }
    Some(hex(&hasher.finalize()))
}

/// The bytes of the record at `path`, where it is a regular file (not a
/// link, a FIFO or a device) of this user's, of at most `most` bytes.
pub fn own_record(path: &Path, most: u64) -> Option<Vec<u8>> {
    let meta = std::fs::symlink_metadata(path).ok()?;
    if !meta.is_file() || meta.len() > most || !owned_by_user(&meta) {
        return None;
    }
    crate::read::read_root(path, most).ok()
}

#[cfg(unix)]
fn owned_by_user(meta: &std::fs::Metadata) -> bool {
    use std::os::unix::fs::MetadataExt;
    // SAFETY: geteuid has no preconditions and cannot fail.
    meta.uid() == unsafe { libc::geteuid() }
}

#[cfg(not(unix))]
fn owned_by_user(_meta: &std::fs::Metadata) -> bool {
    true
}

/// Where the user's key is kept.
fn key_dir() -> Option<PathBuf> {
    // A home that is not there is not made (a user without one, a
    // service account): then there is no key.
    let state = std::env::var_os("XDG_STATE_HOME")
        .map(PathBuf::from)
        .filter(|p| p.is_absolute())
        .or_else(|| {
            let home = PathBuf::from(std::env::var_os("HOME")?);
            home.is_dir().then(|| home.join(".local/state"))
        })?;
    Some(state.join("reach"))
}

/// The key in `dir`, made there first where there is none.
fn user_key(dir: &Path) -> Option<[u8; KEY_BYTES]> {
    let path = dir.join("key");
    if std::fs::symlink_metadata(&path).is_err() {
        make_key(dir, &path)?;
    }
    read_key(&path)
}

/// A new random key at `path`, made whole or not at all: written to a
/// file of this process's, then linked to its name (which fails where
/// another process made one first: then theirs is the key).
fn make_key(dir: &Path, path: &Path) -> Option<()> {
    let mut key = [0u8; KEY_BYTES];
    getrandom::fill(&mut key).ok()?;
    create_private_dir(dir).ok()?;
    let draft = dir.join(format!("key.{}.new", std::process::id()));
    let _ = std::fs::remove_file(&draft);
    let written = private_file(&draft).and_then(|mut f| {
        f.write_all(&key)?;
        f.sync_all()
    });
    let linked = written.and_then(|()| std::fs::hard_link(&draft, path));
    let _ = std::fs::remove_file(&draft);
    match linked {
        Ok(()) => Some(()),
        Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => Some(()),
        Err(_) => None,
    }
}

/// The key at `path`: a regular file of the user's, of `KEY_BYTES`
/// bytes, that no one else may read or write.
fn read_key(path: &Path) -> Option<[u8; KEY_BYTES]> {
    let meta = std::fs::symlink_metadata(path).ok()?;
    if !meta.is_file() || meta.len() != KEY_BYTES as u64 || !owned_by_user(&meta) {
        return None;
    }
    if !private(&meta) {
        return None;
    }
    let bytes = std::fs::read(path).ok()?;
    bytes.try_into().ok()
}

#[cfg(unix)]
fn private(meta: &std::fs::Metadata) -> bool {
    use std::os::unix::fs::PermissionsExt;
    meta.permissions().mode() & 0o077 == 0
}

#[cfg(not(unix))]
fn private(_meta: &std::fs::Metadata) -> bool {
    true
}

#[cfg(unix)]
fn create_private_dir(dir: &Path) -> std::io::Result<()> {
    use std::os::unix::fs::DirBuilderExt;
    std::fs::DirBuilder::new()
        .recursive(true)
        .mode(0o700)
        .create(dir)
}

#[cfg(not(unix))]
fn create_private_dir(dir: &Path) -> std::io::Result<()> {
    std::fs::create_dir_all(dir)
}

/// A new file at `path` that only the user may read and write.
fn private_file(path: &Path) -> std::io::Result<std::fs::File> {
    let mut options = std::fs::OpenOptions::new();
    options.write(true).create_new(true);
    #[cfg(unix)]
    std::os::unix::fs::OpenOptionsExt::mode(&mut options, 0o600);
    options.open(path)
}

fn hex(bytes: &[u8]) -> String {
    bytes.iter().map(|b| format!("{b:02x}")).collect()
}

fn unhex(text: &str) -> Option<Vec<u8>> {
    if !text.len().is_multiple_of(2) {
        return None;
    }
    (0..text.len())
        .step_by(2)
        .map(|k| u8::from_str_radix(text.get(k..k + 2)?, 16).ok())
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_seal_holds_under_its_key_only_and_for_its_text_only() {
        let sealer = Sealer::with_key(Some([7; KEY_BYTES]));
        let sealed = sealer.seal("report.json\tabc\n");
        assert_eq!(sealer.open(&sealed), Some("report.json\tabc\n"));
        let other = Sealer::with_key(Some([8; KEY_BYTES]));
        assert_eq!(other.open(&sealed), None);
        let changed = sealed.replace("report.json", "precious.txt");
        assert_eq!(sealer.open(&changed), None);
        // Unsealed text, or no key: nothing opens.
        assert_eq!(sealer.open("report.json\tabc\n"), None);
        let keyless = Sealer::with_key(None);
        assert_eq!(keyless.seal("x\n"), "x\n");
        assert_eq!(keyless.open(&sealed), None);
    }

    #[test]
    fn the_users_key_is_made_once_private_and_kept() {
        let home = tempfile::tempdir().unwrap();
        let dir = home.path().join("reach");
        let key = user_key(&dir).expect("a key is made");
        assert_eq!(user_key(&dir), Some(key), "the same key the next time");
        #[cfg(unix)]
        {
            use std::os::unix::fs::PermissionsExt;
            let mode = std::fs::metadata(dir.join("key"))
                .unwrap()
                .permissions()
                .mode();
            assert_eq!(mode & 0o777, 0o600);
            // A key others may read is no key.
            std::fs::set_permissions(dir.join("key"), std::fs::Permissions::from_mode(0o644))
                .unwrap();
            assert_eq!(user_key(&dir), None);
        }
    }

    #[test]
    fn a_files_digest_is_its_bytes_digest_and_a_link_has_none() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("a.csv");
        std::fs::write(&path, "x,y\n").unwrap();
        assert_eq!(digest_of_file(&path), Some(digest(b"x,y\n")));
        #[cfg(unix)]
        {
            let link = dir.path().join("link.csv");
            std::os::unix::fs::symlink(&path, &link).unwrap();
            assert_eq!(digest_of_file(&link), None);
            assert!(own_record(&link, 100).is_none());
        }
        assert_eq!(own_record(&path, 100).unwrap(), b"x,y\n");
        assert!(own_record(&path, 2).is_none(), "larger than allowed");
    }
}
