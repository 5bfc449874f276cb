//! Reading the files a scenario names (`use`d scenario files, OBJ meshes,
//! URDFs) under one policy, so that a scenario someone sends you cannot
//! make the tool hang, exhaust memory or show you other files:
//!
//! - each kind of file must have its own extension (`.reach`, `.obj`,
//!   `.urdf`), so a diagnostic never quotes the lines of a system file;
//! - it must lie, symbolic links followed, inside an allowed directory: the
//!   root scenario's own directory, or one given with `--allow-path`;
//! - only regular files are read: a FIFO, a device or a directory is refused
//!   at once, without opening it for long (a FIFO is opened without
//!   waiting for a writer);
//! - the byte limit holds while reading, whatever size the file claims.

use std::fmt;
use std::fs::File;
use std::io::Read;
use std::path::{Path, PathBuf};

/// What a file is read as; each has its extension.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FileKind {
    Scenario,
    Mesh,
    /// A file a mesh refers to: a glTF's external buffer.
    MeshBuffer,
    Urdf,
}

impl FileKind {
    /// The extensions a file of this kind may have (any case).
    pub fn extensions(self) -> &'static [&'static str] {
        match self {
            FileKind::Scenario => &["reach"],
            FileKind::Mesh => &crate::meshfile::EXTENSIONS,
            FileKind::MeshBuffer => &["bin"],
            FileKind::Urdf => &["urdf"],
        }
    }

    /// The extensions as a user reads them: "`.obj`, `.stl` or `.glb`".
    fn extensions_shown(self) -> String {
        let dotted: Vec<String> = self
            .extensions()
            .iter()
            .map(|e| format!("`.{e}`"))
            .collect();
        match dotted.split_last() {
            Some((last, [])) => last.clone(),
            Some((last, rest)) => format!("{} or {last}", rest.join(", ")),
            None => String::new(),
        }
    }

    /// Whether `path` has one of this kind's extensions.
    pub fn admits(self, path: &Path) -> bool {
        path.extension()
            .and_then(|e| e.to_str())
            .is_some_and(|e| self.extensions().iter().any(|k| k.eq_ignore_ascii_case(e)))
    }

    fn what(self) -> &'static str {
        match self {
            FileKind::Scenario => "a scenario file",
            FileKind::Mesh => "a mesh",
            FileKind::MeshBuffer => "a mesh's buffer",
            FileKind::Urdf => "a URDF",
        }
    }
}

/// The directories a scenario's files may be read from.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Allowed {
    /// Canonical paths; empty means anywhere (text handed to the library
    /// with no directory of its own, when the caller allows it).
    dirs: Vec<PathBuf>,
}

impl Allowed {
    /// The directory of `root` (the working directory for text not read
    /// from a file) and the directories in `also`.
    pub fn around(root: Option<&Path>, also: &[PathBuf]) -> Self {
        let root_dir = match root.and_then(Path::parent) {
            Some(dir) if !dir.as_os_str().is_empty() => dir.to_path_buf(),
            _ => PathBuf::from("."),
        };
        let dirs = std::iter::once(&root_dir)
            .chain(also)
            .filter_map(|d| d.canonicalize().ok())
            .collect();
        Allowed { dirs }
    }

    /// Whether `path` (canonical) lies inside an allowed directory.
    fn holds(&self, canonical: &Path) -> bool {
        self.dirs.iter().any(|d| canonical.starts_with(d))
    }

    /// The allowed directories, for a message.
    pub fn shown(&self) -> String {
        let dirs: Vec<String> = self.dirs.iter().map(|d| d.display().to_string()).collect();
        dirs.join(", ")
    }
}

/// Why a file was not read.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum ReadError {
    WrongExtension { kind: FileKind },
    Outside { allowed: String },
    NotRegular { what: &'static str },
    TooLarge { limit_bytes: u64 },
    Io { reason: String },
}

impl fmt::Display for ReadError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ReadError::WrongExtension { kind } => write!(
                f,
                "{} must be a {} file (no other file is read)",
                kind.what(),
                kind.extensions_shown()
            ),
            ReadError::Outside { allowed } => write!(
                f,
                "it is outside the directories a scenario may read ({allowed}); \
                 `--allow-path DIR` allows another"
            ),
            ReadError::NotRegular { what } => write!(f, "it is {what}, not a regular file"),
            ReadError::TooLarge { limit_bytes } => write!(
                f,
                "it is larger than the limit of {limit_bytes} bytes (--max-file-bytes)"
            ),
            ReadError::Io { reason } => f.write_str(reason),
        }
    }
}

/// The bytes of `path`, read as `kind` under the policy above.
pub fn read(
    path: &Path,
    kind: FileKind,
    allowed: &Allowed,
    limit_bytes: u64,
) -> Result<Vec<u8>, ReadError> {
    if !kind.admits(path) {
        return Err(ReadError::WrongExtension { kind });
    }
    let canonical = path.canonicalize().map_err(io)?;
    if !allowed.holds(&canonical) {
        return Err(ReadError::Outside {
            allowed: allowed.shown(),
        });
    }
    read_regular(&canonical, limit_bytes)
}

/// The bytes of the root scenario, which the user named themselves: any
/// name and place, but a regular file within the limit.
pub fn read_root(path: &Path, limit_bytes: u64) -> Result<Vec<u8>, ReadError> {
    read_regular(path, limit_bytes)
}

/// An I/O failure in a few plain words (not the OS's own message, which
/// differs between systems and would change golden diagnostics).
fn io(e: std::io::Error) -> ReadError {
    let reason = match e.kind() {
        std::io::ErrorKind::NotFound => "there is no such file".to_string(),
        std::io::ErrorKind::PermissionDenied => "permission denied".to_string(),
        other => other.to_string(),
    };
    ReadError::Io { reason }
}

/// The bytes of a regular file, at most `limit_bytes` of them.
fn read_regular(path: &Path, limit_bytes: u64) -> Result<Vec<u8>, ReadError> {
    // stat does not block; the opened file is checked again below, in case
    // the name was swapped in between.
    regular(&std::fs::metadata(path).map_err(io)?)?;
    let file = open_without_waiting(path).map_err(io)?;
    let metadata = file.metadata().map_err(io)?;
    regular(&metadata)?;
    // Room for the whole file at once, as its size says (within the
    // limit): a growing buffer would hold up to twice a large mesh.
    let expected = metadata.len().min(limit_bytes).saturating_add(1);
    let mut bytes = Vec::with_capacity(usize::try_from(expected).unwrap_or(0));
    file.take(limit_bytes.saturating_add(1))
        .read_to_end(&mut bytes)
        .map_err(io)?;
    if bytes.len() as u64 > limit_bytes {
        return Err(ReadError::TooLarge { limit_bytes });
    }
    Ok(bytes)
}

/// Refuse anything but a regular file, naming what it is.
fn regular(meta: &std::fs::Metadata) -> Result<(), ReadError> {
    let kind = meta.file_type();
    if kind.is_file() {
        return Ok(());
    }
    let what = if kind.is_dir() {
        "a directory"
    } else if is_fifo(&kind) {
        "a FIFO"
    } else {
        "a device or socket"
    };
    Err(ReadError::NotRegular { what })
}

#[cfg(unix)]
fn is_fifo(kind: &std::fs::FileType) -> bool {
    use std::os::unix::fs::FileTypeExt;
    kind.is_fifo()
}

#[cfg(not(unix))]
fn is_fifo(_: &std::fs::FileType) -> bool {
    false
}

/// Open for reading; on Unix without blocking, so that a FIFO swapped in
/// after the check does not wait for a writer.
fn open_without_waiting(path: &Path) -> std::io::Result<File> {
    let mut options = std::fs::OpenOptions::new();
    options.read(true);
    #[cfg(unix)]
    {
        use std::os::unix::fs::OpenOptionsExt;
        options.custom_flags(libc::O_NONBLOCK);
    }
    options.open(path)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn here() -> (tempfile::TempDir, Allowed) {
        let dir = tempfile::tempdir().unwrap();
        let allowed = Allowed::around(Some(&dir.path().join("root.reach")), &[]);
        (dir, allowed)
    }

    #[test]
    fn a_regular_file_inside_is_read_within_the_limit() {
        let (dir, allowed) = here();
        let path = dir.path().join("a.reach");
        std::fs::write(&path, "let a = 1\n").unwrap();
        assert_eq!(
            read(&path, FileKind::Scenario, &allowed, 10).unwrap(),
            b"let a = 1\n"
        );
        assert_eq!(
            read(&path, FileKind::Scenario, &allowed, 9),
            Err(ReadError::TooLarge { limit_bytes: 9 })
        );
    }

    #[test]
    fn other_extensions_and_places_are_refused_unread() {
        let (dir, allowed) = here();
        let path = dir.path().join("a.txt");
        std::fs::write(&path, "secret").unwrap();
        assert_eq!(
            read(&path, FileKind::Scenario, &allowed, 100),
            Err(ReadError::WrongExtension {
                kind: FileKind::Scenario
            })
        );
        let other = tempfile::tempdir().unwrap();
        let outside = other.path().join("b.reach");
        std::fs::write(&outside, "let b = 1").unwrap();
        let refused = read(&outside, FileKind::Scenario, &allowed, 100);
        assert!(
            matches!(refused, Err(ReadError::Outside { .. })),
            "{refused:?}"
        );
        let widened = Allowed::around(Some(&dir.path().join("root.reach")), &[other.path().into()]);
        assert!(read(&outside, FileKind::Scenario, &widened, 100).is_ok());
        // A link inside that leads outside is outside.
        #[cfg(unix)]
        {
            let link = dir.path().join("link.reach");
            std::os::unix::fs::symlink(&outside, &link).unwrap();
            let refused = read(&link, FileKind::Scenario, &allowed, 100);
            assert!(
                matches!(refused, Err(ReadError::Outside { .. })),
                "{refused:?}"
            );
        }
    }

    #[cfg(unix)]
    #[test]
    fn fifos_and_directories_are_refused_at_once() {
        let (dir, allowed) = here();
        let fifo = dir.path().join("pipe.reach");
        let made = std::process::Command::new("mkfifo")
            .arg(&fifo)
            .status()
            .unwrap();
        assert!(made.success());
        assert_eq!(
            read(&fifo, FileKind::Scenario, &allowed, 100),
            Err(ReadError::NotRegular { what: "a FIFO" })
        );
        let sub = dir.path().join("sub.reach");
        std::fs::create_dir(&sub).unwrap();
        assert_eq!(
            read(&sub, FileKind::Scenario, &allowed, 100),
            Err(ReadError::NotRegular {
                what: "a directory"
            })
        );
    }
}
