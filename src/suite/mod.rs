//! `reach test`: a designer's scenarios as a test suite. Every `.reach`
//! file under the paths given (but those another of them `use`s) is
//! checked and run, in parallel; each passes when it checks, its `expect`s
//! are met and its answers are those of its golden report
//! (`NAME.golden.json` beside it, or under a directory of goldens), compared
//! as answers, not bytes (`golden.rs`). `--update` writes the golden
//! reports that are missing or changed, and only those; `--junit` writes
//! JUnit XML (`junit.rs`).

mod golden;
mod junit;

use std::collections::HashSet;
use std::path::{Path, PathBuf};

use rayon::prelude::*;

pub use golden::{compare, Compared, Tolerance};
pub use junit::{junit, merge_junit};

use crate::error::Diagnostics;
use crate::limits::Limits;
use crate::plugin::Registry;
use crate::report::ExpectationReport;
use crate::Input;

/// How a suite is run.
#[derive(Clone, Debug, Default)]
pub struct SuiteOptions {
    /// Where golden reports are, by the scenario's path under the paths
    /// given (none: beside each scenario).
    pub golden_dir: Option<PathBuf>,
    /// Write the golden reports that are missing or changed.
    pub update: bool,
    pub tolerance: Tolerance,
    pub limits: Limits,
    /// Directories scenarios may read from besides their own.
    pub allowed: Vec<PathBuf>,
}

/// One scenario's result.
#[derive(Clone, Debug)]
pub struct Outcome {
    pub path: PathBuf,
    /// Its diagnostics if it does not check.
    pub diagnostics: Option<Diagnostics>,
    /// How many tasks and standards it answered.
    pub answers: usize,
    pub expectations: Vec<ExpectationReport>,
    pub golden: Golden,
}

/// The golden comparison of a scenario.
#[derive(Clone, Debug, PartialEq)]
pub enum Golden {
    /// No golden report, and none written.
    Absent,
    Compared(Compared),
    /// `--update` wrote it: `fresh` if there was none, else what changed.
    Written {
        path: PathBuf,
        changes: Vec<String>,
        fresh: bool,
    },
    /// It could not be written.
    NotWritten {
        path: PathBuf,
        reason: String,
    },
    /// Its path is also the golden report of the scenarios `with` (two
    /// `x.reach` under two roots, with `--golden-dir`): neither compared
    /// nor written, since each would overwrite or be judged by the other's.
    Shared {
        path: PathBuf,
        with: Vec<PathBuf>,
    },
}

impl Golden {
    /// For [`Golden::Shared`], in words: which golden report, whose too,
    /// and what to do.
    pub fn shared_words(path: &Path, with: &[PathBuf]) -> String {
        let others: Vec<String> = with.iter().map(|p| p.display().to_string()).collect();
        format!(
            "its golden report {} would also be that of {}: neither is compared or written; \
             give the scenarios different names, or name the folder that holds them all \
             (`--golden-dir` keeps each scenario's path under the path it was found under)",
            path.display(),
            others.join(", ")
        )
    }
}

impl Outcome {
    pub fn passed(&self) -> bool {
        self.diagnostics.is_none()
            && self.expectations.iter().all(|e| e.met)
            && matches!(
                self.golden,
                Golden::Absent | Golden::Compared(Compared::Same) | Golden::Written { .. }
            )
    }
}

/// The scenarios under `paths`: `.reach` files, directories searched
/// recursively, in path order; or what is wrong with a path.
pub fn discover(paths: &[PathBuf]) -> Result<Vec<PathBuf>, String> {
    let mut found = Vec::new();
    for path in paths {
        let meta = std::fs::metadata(path).map_err(|e| format!("{}: {e}", path.display()))?;
        if meta.is_dir() {
            walk(path, &mut found).map_err(|e| format!("{}: {e}", path.display()))?;
        } else {
            found.push(path.clone());
        }
    }
    found.sort();
    found.dedup();
    Ok(found)
}

fn walk(dir: &Path, found: &mut Vec<PathBuf>) -> std::io::Result<()> {
    for entry in std::fs::read_dir(dir)? {
        let entry = entry?;
        let path = entry.path();
        let kind = entry.file_type()?;
        if kind.is_dir() {
            walk(&path, found)?;
        } else if kind.is_file() && path.extension().is_some_and(|e| e == "reach") {
            found.push(path);
        }
    }
    Ok(())
}

/// Run every scenario of `scenarios` (found under `roots`) that no other
/// of them uses, in parallel; the outcomes in path order.
pub fn run_suite(
    scenarios: &[PathBuf],
    roots: &[PathBuf],
    options: &SuiteOptions,
    registry: &Registry,
) -> Vec<Outcome> {
    let golden_paths: Vec<PathBuf> = (scenarios.iter())
        .map(|path| golden_path(path, roots, options.golden_dir.as_deref()))
        .collect();
    let ran: Vec<(Outcome, Vec<PathBuf>)> = (scenarios.par_iter().zip(&golden_paths))
        .map(|(path, golden)| {
            let sharing: Vec<PathBuf> = (scenarios.iter().zip(&golden_paths))
                .filter(|(other, g)| *g == golden && *other != path)
                .map(|(other, _)| other.clone())
                .collect();
            run_one(path, (golden, &sharing), options, registry)
        })
        .collect();
    // A file another scenario uses is a part of it, not a scenario.
    let used: HashSet<PathBuf> = ran
        .iter()
        .flat_map(|(o, used)| {
            let root = canonical(&o.path);
            used.iter()
                .map(|p| canonical(p))
                .filter(move |p| *p != root)
        })
        .collect();
    ran.into_iter()
        .map(|(o, _)| o)
        .filter(|o| !used.contains(&canonical(&o.path)))
        .collect()
}

fn canonical(path: &Path) -> PathBuf {
    std::fs::canonicalize(path).unwrap_or_else(|_| path.to_path_buf())
}

/// One scenario: checked, run, its expectations judged and its answers
/// compared with (or, updating, written to) its golden report at
/// `golden_path` (unless that is also the golden report of the scenarios
/// `sharing`); and the files it read.
fn run_one(
    path: &Path,
    (golden_path, sharing): (&Path, &[PathBuf]),
    options: &SuiteOptions,
    registry: &Registry,
) -> (Outcome, Vec<PathBuf>) {
    let mut outcome = Outcome {
        path: path.to_path_buf(),
        diagnostics: None,
        answers: 0,
        expectations: Vec::new(),
        golden: Golden::Absent,
    };
    let session = crate::Session::default()
        .limits(options.limits)
        .allowing(&options.allowed);
    let (sources, checked) = session.check(Input::Path(path), registry);
    let used = sources.disk_paths();
    let scenario = match checked {
        Ok(s) => s,
        Err(d) => {
            outcome.diagnostics = Some(d);
            return (outcome, used);
        }
    };
    let report = match crate::run(&scenario) {
        Ok(report) => report,
        Err(e) => {
            outcome.diagnostics = Some(Diagnostics::single(e).attach(&sources));
            return (outcome, used);
        }
    };
    outcome.answers = report.tasks.len();
    outcome.expectations = report.expectations.clone();
    if !sharing.is_empty() {
        outcome.golden = Golden::Shared {
            path: golden_path.to_path_buf(),
            with: sharing.to_vec(),
        };
        return (outcome, used);
    }
    let golden_path = golden_path.to_path_buf();
    let compared = read_golden(&golden_path, options.limits.file_bytes).map(|g| match g {
        Ok(text) => compare(&text, &report.tasks, options.tolerance),
        Err(why) => Compared::Unreadable(why),
    });
    outcome.golden = match (compared, options.update) {
        (None, false) => Golden::Absent,
        (Some(c), false) | (Some(c @ Compared::Same), true) => Golden::Compared(c),
        (c, true) => {
            let changes = match &c {
                Some(Compared::Changed(changes)) => changes.clone(),
                Some(Compared::OtherSchema { golden }) => {
                    vec![format!("written by schema {golden}")]
                }
                Some(Compared::Unreadable(why)) => vec![why.clone()],
                _ => Vec::new(),
            };
            let json = (registry.format("json"))
                .and_then(|f| f.render(&report, &scenario.format_scene()))
                .unwrap_or_default();
            match write_whole(&golden_path, json.as_bytes()) {
                Ok(()) => Golden::Written {
                    path: golden_path,
                    changes,
                    fresh: c.is_none(),
                },
                Err(reason) => Golden::NotWritten {
                    path: golden_path,
                    reason,
                },
            }
        }
    };
    (outcome, used)
}

/// The golden report at `path`: none where there is no file there; else
/// its text, read as the tool reads its inputs (a regular file only, a
/// FIFO never waited on, at most `limit_bytes`), or why it could not be
/// read, which fails the test (a golden that exists but cannot be read
/// was taken as none, and the test passed).
fn read_golden(path: &Path, limit_bytes: u64) -> Option<Result<String, String>> {
    match std::fs::metadata(path) {
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return None,
        _ => {}
    }
    let text = crate::read::read_root(path, limit_bytes)
        .map_err(|e| e.to_string())
        .and_then(|bytes| String::from_utf8(bytes).map_err(|_| "it is not UTF-8".to_string()));
    Some(text)
}

/// Where `scenario`'s golden report is: `NAME.golden.json` beside it, or
/// under `dir` at its path relative to the root it was found under.
pub fn golden_path(scenario: &Path, roots: &[PathBuf], dir: Option<&Path>) -> PathBuf {
    let name = scenario.with_extension("golden.json");
    let Some(dir) = dir else {
        return name;
    };
    let relative = roots
        .iter()
        .filter(|r| r.is_dir())
        .find_map(|r| name.strip_prefix(r).ok())
        .map(Path::to_path_buf)
        .or_else(|| name.file_name().map(PathBuf::from))
        .unwrap_or(name.clone());
    dir.join(relative)
}

/// `bytes` written to `path` whole or not at all, as `--out` writes its
/// files: a temporary beside it (with the user's umask), renamed into
/// place.
fn write_whole(path: &Path, bytes: &[u8]) -> Result<(), String> {
    let dir = path
        .parent()
        .filter(|d| !d.as_os_str().is_empty())
        .unwrap_or(Path::new("."));
    let name = path
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    crate::output::write_set(dir, &[(name, bytes.to_vec())]).map_err(|e| e.to_string())
}
