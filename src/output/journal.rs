//! The journal of an output set's renames. Once every file of a set is
//! written as a temporary, the renames that put them in place are written
//! down (itself by a rename, so it is whole or absent), done, and the
//! journal removed. A run killed outright (SIGKILL, a power cut) during
//! those few milliseconds leaves a directory holding part of each set
//! and the journal; the next run that writes there first finishes the
//! renames the journal lists (whose temporaries are still there), so
//! that the directory holds the new set whole again.

use std::io::Write;
use std::path::{Path, PathBuf};

/// The journal's name: this, then the writing process's id.
const JOURNAL: &str = ".reach-journal-";

/// Write down that `renames` (temporary, final path; both in `dir`) are
/// about to be made; returns the journal's path.
pub fn begin(dir: &Path, renames: &[(PathBuf, PathBuf)]) -> std::io::Result<PathBuf> {
    let mut text = String::new();
    for (temporary, path) in renames {
        let name = |p: &Path| p.file_name().map(|n| n.to_string_lossy().into_owned());
        let (Some(from), Some(to)) = (name(temporary), name(path)) else {
            continue;
        };
        text.push_str(&format!("{from}\t{to}\n"));
    }
    let journal = dir.join(format!("{JOURNAL}{}", std::process::id()));
    let draft = dir.join(format!("{JOURNAL}{}.draft", std::process::id()));
    let mut file = std::fs::File::create(&draft)?;
    file.write_all(text.as_bytes())?;
    file.sync_all()?;
    std::fs::rename(&draft, &journal)?;
    Ok(journal)
}

/// Finish the renames of every journal in `dir` that a process no longer
/// running left, then remove it. A journal of a running process (another
/// run writing here now) is left alone.
pub fn recover(dir: &Path) {
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
        if draft {
            // The renames never began: the previous set is whole.
            let _ = std::fs::remove_file(entry.path());
            continue;
        }
        if let Ok(text) = std::fs::read_to_string(entry.path()) {
            roll_forward(dir, &text);
        }
        let _ = std::fs::remove_file(entry.path());
    }
}

/// Make each rename of a journal's `text` whose temporary is still there.
fn roll_forward(dir: &Path, text: &str) {
    for line in text.lines() {
        let Some((from, to)) = line.split_once('\t') else {
            continue;
        };
        // Names only: a journal cannot move a file out of `dir`.
        let plain = |n: &str| !n.is_empty() && !n.contains(['/', '\\']) && n != "." && n != "..";
        if !(plain(from) && plain(to)) {
            continue;
        }
        let temporary = dir.join(from);
        if temporary.is_file() {
            let _ = std::fs::rename(&temporary, dir.join(to));
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

    /// A run killed after renaming report.json and before scene.glb: the
    /// next run's recovery puts the new scene.glb in place, removes the
    /// journal, and touches nothing outside the directory.
    #[test]
    fn a_killed_set_is_finished_by_the_next_run() {
        let dir = tempfile::tempdir().unwrap();
        let d = dir.path();
        std::fs::write(d.join("report.json"), "new").unwrap();
        std::fs::write(d.join("scene.glb"), "old").unwrap();
        std::fs::write(d.join(".reach-tmp-4000000-scene.glb"), "new").unwrap();
        let journal = "\
.reach-tmp-4000000-report.json\treport.json
.reach-tmp-4000000-scene.glb\tscene.glb
.reach-tmp-4000000-x\t../escaped
";
        std::fs::write(d.join(".reach-journal-4000000"), journal).unwrap();
        std::fs::write(d.join(".reach-tmp-4000000-x"), "x").unwrap();
        recover(d);
        let read = |n: &str| std::fs::read_to_string(d.join(n)).unwrap();
        assert_eq!(read("report.json"), "new");
        assert_eq!(read("scene.glb"), "new");
        assert!(!d.join(".reach-journal-4000000").exists());
        assert!(!dir.path().parent().unwrap().join("escaped").exists());
    }

    #[test]
    fn a_live_writers_journal_is_left_alone() {
        let dir = tempfile::tempdir().unwrap();
        let d = dir.path();
        let ours = d.join(format!("{JOURNAL}{}", std::process::id()));
        std::fs::write(&ours, "").unwrap();
        recover(d);
        assert!(ours.exists());
    }
}
