//! The journal of an output set's placing (`placing.rs`). Once every
//! file of a set is written as a temporary, the renames that put them in
//! place and the removals after them (backups, the previous set's
//! leftovers) are written down (itself by a rename, so it is whole or
//! absent), made, and the journal removed. A run killed outright
//! (SIGKILL, a power cut) during those few milliseconds leaves a directory
//! holding part of each set and the journal; the next run that writes
//! there first finishes what the journal lists (the renames whose
//! temporaries are still there, then the removals), so that the directory
//! holds the new set whole again. A journal is sealed (`seal.rs`): one
//! this tool did not write for this user is never replayed.

use std::io::Write;
use std::path::{Path, PathBuf};

use super::seal::{own_record, Sealer};

/// The journal's name: this, then the writing process's id.
const JOURNAL: &str = ".reach-journal-";

/// One step of placing a set, on files of one directory.
#[derive(Clone, Debug, PartialEq)]
pub enum SetStep {
    /// A temporary renamed over its final path.
    Rename(PathBuf, PathBuf),
    /// A file removed once every rename is made.
    Remove(PathBuf),
}

/// Write down that `steps` (on files in `dir`) are about to be made,
/// sealed by `sealer`; returns the journal's path. A line a step: `R`, the
/// temporary's name and the final name; or `D` and the name removed;
/// tab-separated.
pub fn begin(dir: &Path, steps: &[SetStep], sealer: &Sealer) -> std::io::Result<PathBuf> {
    let name = |p: &Path| p.file_name().map(|n| n.to_string_lossy().into_owned());
    let mut text = String::new();
    for step in steps {
        match step {
            SetStep::Rename(temporary, path) => {
                if let (Some(from), Some(to)) = (name(temporary), name(path)) {
                    text.push_str(&format!("R\t{from}\t{to}\n"));
                }
            }
            SetStep::Remove(path) => {
                if let Some(gone) = name(path) {
                    text.push_str(&format!("D\t{gone}\n"));
                }
            }
        }
    }
    let journal = dir.join(format!("{JOURNAL}{}", std::process::id()));
    let draft = dir.join(format!("{JOURNAL}{}.draft", std::process::id()));
    write_new(&draft, sealer.seal(&text).as_bytes())?;
    std::fs::rename(&draft, &journal)?;
    Ok(journal)
}

/// A new file (replacing a temporary or draft a run with this process id
/// left), created with the user's umask, written and flushed to disk:
/// created new, never through a link planted at its name (which would
/// truncate the file it points to, anywhere).
pub(super) fn write_new(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    let _ = std::fs::remove_file(path);
    let mut file = std::fs::OpenOptions::new()
        .write(true)
        .create_new(true)
        .open(path)?;
    file.write_all(bytes)?;
    file.sync_all()
}

/// Finish the renames of every journal in `dir` that a process no longer
/// running left, then remove it. A journal of a running process (another
/// run writing here now) is left alone, and so is one whose seal does not
/// hold under `sealer` (not this tool's for this user: it is not replayed,
/// and not removed either).
pub fn recover(dir: &Path, sealer: &Sealer) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    for entry in entries.flatten() {
        let name = entry.file_name().to_string_lossy().into_owned();
        let Some(pid) = name.strip_prefix(JOURNAL) else {
            continue;
        };
        let (pid, draft) = match pid.strip_suffix(".draft") {
            Some(pid) => (pid, true),
            None => (pid, false),
        };
        let Ok(pid) = pid.parse::<u32>() else {
            continue;
        };
        if running(pid) {
            continue;
        }
        // A regular file of the user's, of at most RECORD_BYTES, sealed:
        // a FIFO at a journal's name was waited on for ever, and a
        // journal written by hand renamed and removed the user's files.
        let Some(bytes) = own_record(&entry.path(), RECORD_BYTES) else {
            continue;
        };
        let text = String::from_utf8_lossy(&bytes);
        let Some(steps) = sealer.open(&text) else {
            continue;
        };
        // A draft's renames never began: the previous set is whole.
        if !draft {
            roll_forward(dir, steps);
        }
        let _ = std::fs::remove_file(entry.path());
    }
}

/// The most bytes a set's records (its list of names, a journal) are read
/// to: far more than any set's names and renames.
pub(super) const RECORD_BYTES: u64 = 1 << 20;

/// Whether `name` is a plain name of a file in a set's directory: a
/// record (a journal, a set's list) names only such, so it cannot touch a
/// file outside the directory.
pub(super) fn plain_name(name: &str) -> bool {
    !name.is_empty() && !name.contains(['/', '\\']) && name != "." && name != ".."
}

/// Make each rename of a journal's `text` whose temporary is still there,
/// then each removal.
fn roll_forward(dir: &Path, text: &str) {
    let fields = |line: &str| line.split('\t').map(str::to_string).collect::<Vec<_>>();
    let lines: Vec<Vec<String>> = text.lines().map(fields).collect();
    for line in &lines {
        if let [tag, from, to] = line.as_slice() {
            let temporary = dir.join(from);
            if tag == "R" && plain_name(from) && plain_name(to) && temporary.is_file() {
                let _ = std::fs::rename(&temporary, dir.join(to));
            }
        }
    }
    for line in &lines {
        if let [tag, gone] = line.as_slice() {
            if tag == "D" && plain_name(gone) && dir.join(gone).is_file() {
                let _ = std::fs::remove_file(dir.join(gone));
            }
        }
    }
}

/// Whether process `pid` is running (not this one's journal, which is
/// never left behind by a live writer but its own).
#[cfg(unix)]
fn running(pid: u32) -> bool {
    let Ok(pid) = libc::pid_t::try_from(pid) else {
        return false;
    };
    // Signal 0 checks that the process exists without touching it.
    // SAFETY: kill with signal 0 sends nothing.
    let alive = unsafe { libc::kill(pid, 0) } == 0;
    alive || std::io::Error::last_os_error().raw_os_error() == Some(libc::EPERM)
}

#[cfg(not(unix))]
fn running(_pid: u32) -> bool {
    false
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sealer() -> Sealer {
        Sealer::with_key(Some([3; 32]))
    }

    /// A run killed after renaming report.json and before scene.glb: the
    /// next run's recovery puts the new scene.glb in place, removes the
    /// previous set's leftover and the journal, and touches nothing
    /// outside the directory.
    #[test]
    fn a_killed_set_is_finished_by_the_next_run() {
        let dir = tempfile::tempdir().unwrap();
        let d = dir.path();
        std::fs::write(d.join("report.json"), "new").unwrap();
        std::fs::write(d.join("scene.glb"), "old").unwrap();
        std::fs::write(d.join("map-old.csv"), "old").unwrap();
        std::fs::write(d.join(".reach-tmp-4000000-scene.glb"), "new").unwrap();
        let journal = "\
R\t.reach-tmp-4000000-report.json\treport.json
R\t.reach-tmp-4000000-scene.glb\tscene.glb
R\t.reach-tmp-4000000-x\t../escaped
D\tmap-old.csv
D\t../outside
";
        std::fs::write(d.join(".reach-journal-4000000"), sealer().seal(journal)).unwrap();
        std::fs::write(d.join(".reach-tmp-4000000-x"), "x").unwrap();
        recover(d, &sealer());
        let read = |n: &str| std::fs::read_to_string(d.join(n)).unwrap();
        assert_eq!(read("report.json"), "new");
        assert_eq!(read("scene.glb"), "new");
        assert!(!d.join("map-old.csv").exists());
        assert!(!d.join(".reach-journal-4000000").exists());
        assert!(!dir.path().parent().unwrap().join("escaped").exists());
    }

    /// A link planted at the draft's name is replaced, never written
    /// through: the file it points to is left as it was.
    #[cfg(unix)]
    #[test]
    fn a_link_at_the_drafts_name_is_not_followed() {
        let dir = tempfile::tempdir().unwrap();
        let (d, outside) = (dir.path().join("out"), dir.path().join("precious"));
        std::fs::create_dir(&d).unwrap();
        std::fs::write(&outside, "keep me").unwrap();
        let draft = d.join(format!("{JOURNAL}{}.draft", std::process::id()));
        std::os::unix::fs::symlink(&outside, &draft).unwrap();
        let journal = begin(&d, &[SetStep::Remove(d.join("old.csv"))], &sealer()).unwrap();
        assert_eq!(std::fs::read_to_string(&outside).unwrap(), "keep me");
        let text = std::fs::read_to_string(&journal).unwrap();
        assert_eq!(sealer().open(&text), Some("D\told.csv\n"));
    }

    /// A journal (of a process not running) that is a FIFO is not waited
    /// on: recovery goes on and removes it.
    #[cfg(unix)]
    #[test]
    fn a_fifo_at_a_journals_name_is_not_waited_on() {
        let dir = tempfile::tempdir().unwrap();
        let fifo = dir.path().join(format!("{JOURNAL}4000001"));
        let c = std::ffi::CString::new(fifo.to_str().unwrap()).unwrap();
        assert_eq!(unsafe { libc::mkfifo(c.as_ptr(), 0o600) }, 0);
        recover(dir.path(), &sealer());
        assert!(
            fifo.exists(),
            "not this tool's: left alone, and not waited on"
        );
    }

    /// A journal this tool did not write (by hand, in a repository, or
    /// under another user's key) is not replayed: the files it names are
    /// not renamed or removed, and it is left where it is.
    #[test]
    fn a_journal_not_sealed_by_this_user_is_not_replayed() {
        let dir = tempfile::tempdir().unwrap();
        let d = dir.path();
        std::fs::write(d.join("thesis.txt"), "mine").unwrap();
        std::fs::write(d.join("notes.txt"), "mine too").unwrap();
        let journal = "R\tthesis.txt\tnotes.txt\nD\tthesis.txt\n";
        let other = Sealer::with_key(Some([4; 32]));
        for (k, text) in [journal.to_string(), other.seal(journal)]
            .iter()
            .enumerate()
        {
            let name = d.join(format!("{JOURNAL}{}", 4000010 + k));
            std::fs::write(&name, text).unwrap();
            recover(d, &sealer());
            assert!(name.exists());
        }
        assert_eq!(
            std::fs::read_to_string(d.join("thesis.txt")).unwrap(),
            "mine"
        );
        assert_eq!(
            std::fs::read_to_string(d.join("notes.txt")).unwrap(),
            "mine too"
        );
    }

    #[test]
    fn a_live_writers_journal_is_left_alone() {
        let dir = tempfile::tempdir().unwrap();
        let d = dir.path();
        let ours = d.join(format!("{JOURNAL}{}", std::process::id()));
        std::fs::write(&ours, sealer().seal("")).unwrap();
        recover(d, &sealer());
        assert!(ours.exists());
    }
}
