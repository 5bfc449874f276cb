//! What `--out DIR` writes: every format's files as one set (with the
//! built-in formats `DIR/report.txt`, `DIR/report.json`, `DIR/report.html`
//! (the 3D view, `html/`) with the stamp it polls, `DIR/scene.glb` and,
//! for each map, its CSV and SVG (`maps.rs`)). Every file is rendered first,
//! then written as a temporary beside its place (with the user's umask),
//! and only once all are written are they put in place (`placing.rs`:
//! renamed, undone from backups if a rename fails, journalled so that a
//! run killed outright is finished by the next); a failure before that (a
//! name taken by a directory, a full disk) removes the temporaries and
//! leaves the previous set as it was. A set lists its files in
//! [`MANIFEST`], each with its SHA-256, sealed (`seal.rs`), so that the
//! next set removes those it has not (a map taken out of the scenario),
//! and never a file it did not write: a list this tool did not write for
//! this user lists nothing, and a file changed since its set wrote it is
//! kept.
//! Temporaries a killed run left behind are swept at the next run. (The
//! command line holds SIGINT and SIGTERM back while a set is written, so
//! that they too leave a whole set.)

use std::path::{Path, PathBuf};
use std::time::{Duration, SystemTime};

use std::sync::Arc;

use super::journal;
use super::placing;
use super::seal::{self, own_record, Sealer};
use crate::error::{Error, ErrorKind};
use crate::plugin::FormatPlugin;
use crate::report::Report;
use crate::scenario::Scenario;

/// Temporaries start with this, then the process id and the file's name.
const TEMPORARY: &str = ".reach-tmp-";
/// The list of an `--out` set's files, written with it.
pub const MANIFEST: &str = ".reach-set";
/// A temporary older than this is a killed run's, and is swept.
const STALE: Duration = Duration::from_secs(60);

/// The set's files, by name, in the order they are written: every
/// format's, in the order they are registered, each format's in its own
/// order (the page before the stamp it polls: a page that sees the stamp
/// new finds itself new too).
pub fn output_set(
    report: &Report,
    scenario: &Scenario,
    formats: &[Arc<dyn FormatPlugin>],
) -> Vec<(String, Vec<u8>)> {
    let scene = scenario.format_scene();
    formats
        .iter()
        .flat_map(|format| format.files(report, &scene))
        .collect()
}

/// Every format's files of `report`, with the set's list, as one set in
/// `dir`: `report.txt`, `report.json`, `report.html` and its stamp,
/// `scene.glb`, and a CSV and an SVG for each map with the built-in
/// formats.
pub fn write_outputs(
    report: &Report,
    scenario: &Scenario,
    formats: &[Arc<dyn FormatPlugin>],
    dir: &Path,
) -> Result<Written, Error> {
    let sealer = Sealer::of_user();
    let mut files = output_set(report, scenario, formats);
    let listed: String = (files.iter())
        .map(|(name, bytes)| format!("{name}\t{}\n", seal::digest(bytes)))
        .collect();
    files.push((MANIFEST.to_string(), sealer.seal(&listed).into_bytes()));
    // Read once a journal a killed set left is finished: its list is the
    // previous set's. A file it lists that changed since is kept, and said.
    let kept = std::cell::RefCell::new(Vec::new());
    let leftovers = |dir: &Path, sealer: &Sealer| {
        let dropped = (previous_set(dir, sealer).into_iter())
            .filter(|(old, _)| !files.iter().any(|(name, _)| name == old));
        let (same, changed): (Vec<_>, Vec<_>) = dropped
            .filter(|(old, _)| dir.join(old).is_file())
            .partition(|(old, digest)| {
                seal::digest_of_file(&dir.join(old)).as_ref() == Some(digest)
            });
        *kept.borrow_mut() = changed.into_iter().map(|(old, _)| old).collect();
        same.into_iter()
            .map(|(old, _)| dir.join(old))
            .collect::<Vec<_>>()
    };
    place_set(dir, &files, &leftovers, &sealer)?;
    Ok(Written {
        sealed: sealer.has_key(),
        kept: kept.into_inner(),
    })
}

/// What writing an `--out` set did that its caller may tell the user.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Written {
    /// Whether the set's list was sealed: where the user has no key (none
    /// could be made), it is not, and the next set removes none of its
    /// files.
    pub sealed: bool,
    /// The previous set's files this one has not, kept because they
    /// changed since that set wrote them (by name).
    pub kept: Vec<String>,
}

impl Written {
    /// What the user is told of the set written in `dir`, if anything.
    pub fn note(&self, dir: &Path) -> Option<String> {
        let shown = dir.display().to_string();
        let shown = crate::escape::escaped(&shown);
        let mut lines = Vec::new();
        if !self.kept.is_empty() {
            let names: Vec<String> = (self.kept.iter())
                .map(|n| format!("`{}`", crate::escape::escaped(n)))
                .collect();
            lines.push(format!(
                "note: kept {} in `{shown}`: the set before wrote it, this one has not, and it was changed since",
                names.join(", ")
            ));
        }
        if !self.sealed {
            lines.push(format!(
                "note: no key to seal output sets could be read or made (`$XDG_STATE_HOME/reach/key`, by default `~/.local/state/reach/key`: a home that is missing or cannot be written, or a key others may read): the list of `{shown}` is unsealed, so the next set written there removes none of these files"
            ));
        }
        (!lines.is_empty()).then(|| lines.join("\n"))
    }
}

/// The files the set now in `dir` lists, each with the SHA-256 it was
/// written with (none where it lists none): plain names in `dir`, never a
/// path elsewhere. A list that is not a regular file of the user's (a
/// FIFO, which was waited on for ever; a link to `/dev/zero`), is larger
/// than `journal::RECORD_BYTES`, or whose seal does not hold under
/// `sealer` (written by hand, carried by a repository, planted by another
/// user) lists none.
fn previous_set(dir: &Path, sealer: &Sealer) -> Vec<(String, String)> {
    let bytes = own_record(&dir.join(MANIFEST), super::journal::RECORD_BYTES).unwrap_or_default();
    let text = String::from_utf8_lossy(&bytes);
    let Some(listed) = sealer.open(&text) else {
        return Vec::new();
    };
    (listed.lines())
        .filter_map(|line| line.split_once('\t'))
        .filter(|(n, _)| journal::plain_name(n) && !n.starts_with(TEMPORARY) && *n != MANIFEST)
        .map(|(n, digest)| (n.to_string(), digest.to_string()))
        .collect()
}

fn write_error(path: &Path, e: &std::io::Error) -> Error {
    Error::unplaced(ErrorKind::WriteFile {
        path: path.display().to_string(),
        reason: e.to_string(),
    })
}

/// Write `files` into `dir` as one set: all of them, or none (the files
/// they replace as they were).
pub fn write_set(dir: &Path, files: &[(String, Vec<u8>)]) -> Result<(), Error> {
    place_set(dir, files, &|_, _| Vec::new(), &Sealer::of_user())
}

/// Write `files` into `dir` as one set and remove the files of `dir` that
/// `leftovers` names (asked once `dir` is locked and a killed set's
/// journal finished): all of it, or none. One set at a time in a process: the
/// temporaries and the journal are named by the process (`reach test`
/// writes golden reports from several threads).
fn place_set(
    dir: &Path,
    files: &[(String, Vec<u8>)],
    leftovers: &dyn Fn(&Path, &Sealer) -> Vec<PathBuf>,
    sealer: &Sealer,
) -> Result<(), Error> {
    static WRITING: std::sync::Mutex<()> = std::sync::Mutex::new(());
    let _one_at_a_time = WRITING.lock().unwrap_or_else(|e| e.into_inner());
    if std::fs::symlink_metadata(dir).is_ok_and(|m| !m.is_dir()) && !dir.is_dir() {
        let e = std::io::Error::other("it is a file, not a folder");
        return Err(write_error(dir, &e));
    }
    std::fs::create_dir_all(dir).map_err(|e| write_error(dir, &e))?;
    let _across_processes = lock_dir(dir).map_err(|e| write_error(dir, &e))?;
    journal::recover(dir, sealer);
    sweep_stale(dir);
    let leftovers = leftovers(dir, sealer);
    for (name, _) in files {
        let path = dir.join(name);
        if path.is_dir() {
            let e = std::io::Error::other("a directory has that name");
            return Err(write_error(&path, &e));
        }
    }
    let mut written: Vec<(PathBuf, PathBuf)> = Vec::with_capacity(files.len());
    for (name, bytes) in files {
        let temporary = dir.join(format!("{TEMPORARY}{}-{name}", std::process::id()));
        if let Err(e) = journal::write_new(&temporary, bytes) {
            let _ = std::fs::remove_file(&temporary);
            remove_all(&written);
            return Err(write_error(&dir.join(name), &e));
        }
        written.push((temporary, dir.join(name)));
    }
    let rename = |from: &Path, to: &Path| std::fs::rename(from, to);
    placing::place(dir, &written, &leftovers, &rename, sealer)
        .map_err(|(path, e)| write_error(&path, &e))
}

/// `dir` locked against other processes writing a set there (an
/// exclusive lock on the directory itself, so that no lock file is left
/// in it), until the handle is dropped: two runs writing one `--out` at
/// once each leave a whole set, the last one's, never a mix of both.
#[cfg(unix)]
fn lock_dir(dir: &Path) -> std::io::Result<std::fs::File> {
    use std::os::fd::AsRawFd;
    let handle = std::fs::File::open(dir)?;
    // SAFETY: flock on a descriptor this handle owns; it is released when
    // the handle is dropped (closed).
    if unsafe { libc::flock(handle.as_raw_fd(), libc::LOCK_EX) } != 0 {
        return Err(std::io::Error::last_os_error());
    }
    Ok(handle)
}

#[cfg(not(unix))]
fn lock_dir(_dir: &Path) -> std::io::Result<()> {
    Ok(())
}

fn remove_all(written: &[(PathBuf, PathBuf)]) {
    for (temporary, _) in written {
        let _ = std::fs::remove_file(temporary);
    }
}

/// Remove temporaries that a killed run left in `dir` (older than
/// [`STALE`], so that a run writing beside this one keeps its own).
fn sweep_stale(dir: &Path) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    let now = SystemTime::now();
    for entry in entries.flatten() {
        let is_temporary = entry.file_name().to_string_lossy().starts_with(TEMPORARY);
        let modified = entry.metadata().and_then(|m| m.modified());
        let old = modified.is_ok_and(|t| now.duration_since(t).unwrap_or_default() > STALE);
        if is_temporary && old {
            let _ = std::fs::remove_file(entry.path());
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sealer() -> Sealer {
        Sealer::with_key(Some([6; 32]))
    }

    /// A set's list that is a FIFO (or a link to a device) is not read:
    /// it lists nothing, so nothing is removed, and nothing waits.
    #[cfg(unix)]
    #[test]
    fn a_list_that_is_not_a_regular_file_lists_nothing() {
        let dir = tempfile::tempdir().unwrap();
        let list = dir.path().join(MANIFEST);
        let c = std::ffi::CString::new(list.to_str().unwrap()).unwrap();
        assert_eq!(unsafe { libc::mkfifo(c.as_ptr(), 0o600) }, 0);
        assert!(previous_set(dir.path(), &sealer()).is_empty());
        std::fs::remove_file(&list).unwrap();
        std::os::unix::fs::symlink("/dev/zero", &list).unwrap();
        assert!(previous_set(dir.path(), &sealer()).is_empty());
        std::fs::remove_file(&list).unwrap();
        let listed = "report.json\tab\n../outside\tcd\n";
        std::fs::write(&list, sealer().seal(listed)).unwrap();
        let set = previous_set(dir.path(), &sealer());
        assert_eq!(set, [("report.json".to_string(), "ab".to_string())]);
    }

    /// A set killed during its renames left its journal: the next set
    /// finishes it before it reads the previous list, so the killed set's
    /// files that the next has not are removed (read before, the list
    /// was the one before the killed set, and they stayed for good).
    #[test]
    fn the_previous_list_is_read_once_a_killed_sets_journal_is_finished() {
        let dir = tempfile::tempdir().unwrap();
        let d = dir.path();
        let sealer = sealer();
        let killed = ".reach-tmp-4000020-";
        let listed = format!("map-a.csv\t{}\n", seal::digest(b"a"));
        std::fs::write(d.join(format!("{killed}{MANIFEST}")), sealer.seal(&listed)).unwrap();
        std::fs::write(d.join(format!("{killed}map-a.csv")), "a").unwrap();
        std::fs::write(d.join(MANIFEST), sealer.seal("")).unwrap();
        let journal =
            format!("R\t{killed}{MANIFEST}\t{MANIFEST}\nR\t{killed}map-a.csv\tmap-a.csv\n");
        std::fs::write(d.join(".reach-journal-4000020"), sealer.seal(&journal)).unwrap();
        let files = [("report.json".to_string(), b"{}".to_vec())];
        let leftovers = |dir: &Path, sealer: &Sealer| {
            (previous_set(dir, sealer).into_iter())
                .map(|(old, _)| dir.join(old))
                .collect::<Vec<_>>()
        };
        place_set(d, &files, &leftovers, &sealer).unwrap();
        assert!(!d.join("map-a.csv").exists());
        assert!(d.join("report.json").exists());
    }

    /// A list this tool did not write for this user (by hand, or sealed
    /// under another key) lists nothing: the files it names are not
    /// removed by the next set.
    #[test]
    fn a_list_not_sealed_by_this_user_lists_nothing() {
        let dir = tempfile::tempdir().unwrap();
        let list = dir.path().join(MANIFEST);
        let digest = seal::digest(b"mine");
        let listed = format!("thesis.txt\t{digest}\n");
        std::fs::write(&list, &listed).unwrap();
        assert!(previous_set(dir.path(), &sealer()).is_empty());
        let other = Sealer::with_key(Some([9; 32]));
        std::fs::write(&list, other.seal(&listed)).unwrap();
        assert!(previous_set(dir.path(), &sealer()).is_empty());
    }
}
