//! Putting a written set in place: the temporaries renamed over their
//! files, all or none. Before the renames each file they replace is kept
//! as a backup (a hard link, or a copy where links are not allowed), and
//! the renames, the backups and the files the previous set had and this
//! one has not are written in a journal (`journal.rs`). If a rename fails
//! the ones made are undone from the backups, so the directory holds the
//! previous set; once all are made, the backups and the previous set's
//! leftovers are removed. A run killed during them leaves the journal,
//! and the next run finishes them.

use std::path::{Path, PathBuf};

use super::journal::{self, SetStep};
use super::seal::Sealer;

/// A backup's name starts with this (a temporary's prefix, so that a
/// killed run's backups are swept like its temporaries), then the
/// process id and the file's name.
pub const BACKUP: &str = ".reach-tmp-old-";

/// How a file is renamed: `std::fs::rename`, or a test's stand-in that
/// fails on purpose.
pub type Rename<'a> = &'a dyn Fn(&Path, &Path) -> std::io::Result<()>;

/// Rename each temporary of `renames` (temporary, final path; all in
/// `dir`) over its final path, then remove `leftovers` (files of the
/// previous set this one does not have): all, or on an error none, the
/// previous set restored. The error names the path that failed. The
/// journal is sealed by `sealer`.
pub fn place(
    dir: &Path,
    renames: &[(PathBuf, PathBuf)],
    leftovers: &[PathBuf],
    rename: Rename<'_>,
    sealer: &Sealer,
) -> Result<(), (PathBuf, std::io::Error)> {
    let backups = match back_up(dir, renames) {
        Ok(backups) => backups,
        Err(e) => {
            remove_temporaries(renames);
            return Err(e);
        }
    };
    let mut steps: Vec<SetStep> = renames
        .iter()
        .map(|(from, to)| SetStep::Rename(from.clone(), to.clone()))
        .collect();
    steps.extend(
        leftovers
            .iter()
            .chain(backups.iter().flatten())
            .cloned()
            .map(SetStep::Remove),
    );
    let log = match journal::begin(dir, &steps, sealer) {
        Ok(log) => log,
        Err(e) => {
            remove_temporaries(renames);
            remove(backups.iter().flatten());
            return Err((dir.to_path_buf(), e));
        }
    };
    for (k, (temporary, path)) in renames.iter().enumerate() {
        if let Err(e) = rename(temporary, path) {
            undo(&renames[..k], &backups[..k]);
            remove_temporaries(&renames[k..]);
            remove(backups.iter().flatten());
            let _ = std::fs::remove_file(&log);
            return Err((path.clone(), e));
        }
    }
    remove(leftovers.iter().chain(backups.iter().flatten()));
    let _ = std::fs::remove_file(&log);
    Ok(())
}

/// A backup of each final path of `renames` that is a file now (`None`
/// where there is none to keep).
fn back_up(
    dir: &Path,
    renames: &[(PathBuf, PathBuf)],
) -> Result<Vec<Option<PathBuf>>, (PathBuf, std::io::Error)> {
    let mut backups: Vec<Option<PathBuf>> = Vec::with_capacity(renames.len());
    for (_, path) in renames {
        if !path.is_file() {
            backups.push(None);
            continue;
        }
        let name = path.file_name().unwrap_or_default().to_string_lossy();
        let backup = dir.join(format!("{BACKUP}{}-{name}", std::process::id()));
        let _ = std::fs::remove_file(&backup);
        let kept =
            std::fs::hard_link(path, &backup).or_else(|_| std::fs::copy(path, &backup).map(|_| ()));
        if let Err(e) = kept {
            let _ = std::fs::remove_file(&backup);
            remove(backups.iter().flatten());
            return Err((path.clone(), e));
        }
        backups.push(Some(backup));
    }
    Ok(backups)
}

/// Undo the renames `made`: each final path back to its backup, or
/// removed where it had none.
fn undo(made: &[(PathBuf, PathBuf)], backups: &[Option<PathBuf>]) {
    for ((_, path), backup) in made.iter().zip(backups) {
        match backup {
            Some(backup) => {
                let _ = std::fs::rename(backup, path);
            }
            None => {
                let _ = std::fs::remove_file(path);
            }
        }
    }
}

fn remove_temporaries(renames: &[(PathBuf, PathBuf)]) {
    remove(renames.iter().map(|(temporary, _)| temporary));
}

fn remove<'p>(paths: impl IntoIterator<Item = &'p PathBuf>) {
    for path in paths {
        let _ = std::fs::remove_file(path);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `dir` with `name` holding `text`, for each pair.
    fn files(dir: &Path, named: &[(&str, &str)]) {
        for (name, text) in named {
            std::fs::write(dir.join(name), text).unwrap();
        }
    }

    fn listing(dir: &Path) -> Vec<(String, String)> {
        let mut all: Vec<(String, String)> = std::fs::read_dir(dir)
            .unwrap()
            .map(|e| {
                let e = e.unwrap();
                let text = std::fs::read_to_string(e.path()).unwrap();
                (e.file_name().to_string_lossy().into_owned(), text)
            })
            .collect();
        all.sort();
        all
    }

    fn renames(dir: &Path, names: &[&str]) -> Vec<(PathBuf, PathBuf)> {
        names
            .iter()
            .map(|n| (dir.join(format!(".reach-tmp-1-{n}")), dir.join(n)))
            .collect()
    }

    /// The third rename fails: the first two are undone (a file that was
    /// there is back, one that was not is gone), and nothing of the new
    /// set, no backup and no journal is left.
    #[test]
    fn a_rename_that_fails_leaves_the_previous_set() {
        let dir = tempfile::tempdir().unwrap();
        let d = dir.path();
        files(d, &[("a", "old a"), ("c", "old c"), ("gone", "old")]);
        let before = listing(d);
        files(
            d,
            &[(".reach-tmp-1-a", "new a"), (".reach-tmp-1-b", "new b")],
        );
        files(
            d,
            &[(".reach-tmp-1-c", "new c"), (".reach-tmp-1-d", "new d")],
        );
        let calls = std::cell::Cell::new(0);
        let failing = |from: &Path, to: &Path| {
            calls.set(calls.get() + 1);
            if calls.get() == 3 {
                return Err(std::io::Error::other("disk gone"));
            }
            std::fs::rename(from, to)
        };
        let r = renames(d, &["a", "b", "c", "d"]);
        let sealer = Sealer::with_key(Some([5; 32]));
        let e = place(d, &r, &[d.join("gone")], &failing, &sealer).unwrap_err();
        assert_eq!(e.0, d.join("c"));
        assert_eq!(listing(d), before);
    }

    /// All renames made: the new set is in place, the previous set's file
    /// it does not have is removed, and no backup or journal is left.
    #[test]
    fn a_set_placed_whole_removes_the_previous_sets_leftovers() {
        let dir = tempfile::tempdir().unwrap();
        let d = dir.path();
        files(d, &[("a", "old a"), ("gone", "old"), ("mine", "user's")]);
        files(
            d,
            &[(".reach-tmp-1-a", "new a"), (".reach-tmp-1-b", "new b")],
        );
        let r = renames(d, &["a", "b"]);
        let sealer = Sealer::with_key(Some([5; 32]));
        place(
            d,
            &r,
            &[d.join("gone")],
            &|f, t| std::fs::rename(f, t),
            &sealer,
        )
        .unwrap();
        let expected = [("a", "new a"), ("b", "new b"), ("mine", "user's")];
        let expected: Vec<(String, String)> = expected
            .iter()
            .map(|(n, t)| (n.to_string(), t.to_string()))
            .collect();
        assert_eq!(listing(d), expected);
    }
}
