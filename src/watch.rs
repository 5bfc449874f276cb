//! `reach watch FILE`: evaluate, then again whenever FILE or a file it uses
//! changes. The directories of those files are watched (not the files), so
//! that saving by rename or by delete-and-create is seen like writing in
//! place; a burst of events is one change once it has been quiet for a
//! moment. On a terminal each evaluation replaces the screen; piped, each
//! is printed in full after a separator line. A save is said at once, with
//! the files that changed; a long run draws a progress bar on a terminal.
//! Every evaluation ends with a summary: the time it took, the tasks run
//! again, and last, each result that changed since the last good
//! evaluation (`-q`: the summary alone, and diagnostics). A change that leaves the files the last evaluation read as
//! they were, byte for byte, is not evaluated again.

use std::collections::BTreeSet;
use std::io::{IsTerminal, Write};
use std::path::{Path, PathBuf};
use std::sync::mpsc::{channel, Receiver, RecvTimeoutError};
use std::time::{Duration, Instant};

use notify::event::ModifyKind;
use notify::{EventKind, RecommendedWatcher, RecursiveMode, Watcher};
use reach::plugin::{FormatPlugin, Registry};
use reach::report::{Answer, Report};
use reach::TaskCache;
use reach::{Input, Limits};

/// A burst of events ends after this much quiet.
const QUIET: Duration = Duration::from_millis(25);
/// How long the tasks a save runs again may take before the answers kept
/// are shown without them.
const FIRST_WAIT: Duration = Duration::from_millis(30);
/// How long a file that vanished (deleted before being written again) is
/// waited for before it is reported missing.
const MISSING_GRACE: Duration = Duration::from_millis(500);

type Events = Receiver<notify::Result<notify::Event>>;

pub fn watch(
    registry: &Registry,
    (limits, also_allowed): (&Limits, &[PathBuf]),
    file: &Path,
    formatter: &dyn FormatPlugin,
    (out, colour, quiet): (Option<&Path>, bool, bool),
) -> i32 {
    let (tx, rx) = channel();
    let mut watcher = match notify::recommended_watcher(tx) {
        Ok(w) => w,
        Err(e) => {
            eprintln!("error: cannot watch files: {e}");
            return 1;
        }
    };
    let root = absolute(file);
    let mut state = State {
        terminal: std::io::stdout().is_terminal(),
        colour,
        quiet,
        limits: *limits,
        also_allowed: also_allowed.to_vec(),
        cache: TaskCache::default(),
        last_good: None,
        evaluations: 0,
        watched_dirs: BTreeSet::new(),
        watched_files: BTreeSet::new(),
    };
    // Watching starts before the first evaluation, and each evaluation is
    // shown only once the files it read are watched, so that a save made
    // the moment the result appears is never missed.
    state.rewatch(&mut watcher, &root, Vec::new());
    loop {
        // The bytes of the files the last evaluation read, taken before
        // this one reads them: a change made meanwhile is seen next time.
        let read_before = state.watched_files.clone();
        let max_bytes = state.limits.file_bytes;
        let before = fingerprints(&read_before, max_bytes);
        // The evaluation watches the files it read before it shows anything.
        let (files, screen) = state.evaluate(registry, file, formatter, out, (&mut watcher, &root));
        state.show(&screen);
        // Only where this evaluation read the same files is the
        // fingerprint theirs.
        let shown = (state.watched_files == read_before).then_some(&before);
        loop {
            if !wait_for_change(&rx, &state.watched_files, &state.watched_dirs) {
                return 0;
            }
            wait_until_present(&root);
            // A save that leaves every file as it was (an editor's rename
            // after the write was already seen, a file saved unchanged)
            // would show the same screen again. A directory made again
            // since is watched first, then the files are read: what is
            // written in it from then on is an event, and before, a change.
            state.rewatch(&mut watcher, &root, files.clone());
            let now = fingerprints(&state.watched_files, max_bytes);
            if shown != Some(&now) {
                state.announce(&changed_files(&now, &before));
                break;
            }
        }
    }
}

/// Each of `files` and a hash of what reading it gives, as an evaluation
/// reads it (`reach::read`: regular files only, a FIFO never waited on, at
/// most `max_bytes`): its bytes, or why it could not be read.
fn fingerprints(files: &BTreeSet<PathBuf>, max_bytes: u64) -> Vec<(PathBuf, u64)> {
    use std::hash::{Hash, Hasher};
    let fingerprint = |path: &PathBuf| {
        let mut h = std::collections::hash_map::DefaultHasher::new();
        match reach::read_root(path, max_bytes) {
            Ok(bytes) => (0u8, bytes).hash(&mut h),
            Err(e) => (1u8, e.to_string()).hash(&mut h),
        }
        h.finish()
    };
    files.iter().map(|f| (f.clone(), fingerprint(f))).collect()
}

/// The names of the files of `now` whose bytes are not those `before`
/// holds (a file new since: all of them).
fn changed_files(now: &[(PathBuf, u64)], before: &[(PathBuf, u64)]) -> Vec<String> {
    let mut names: Vec<String> = now
        .iter()
        .filter(|entry| !before.contains(entry))
        .filter_map(|(f, _)| f.file_name().map(|n| n.to_string_lossy().into_owned()))
        .collect();
    names.dedup();
    names
}

struct State {
    terminal: bool,
    /// Whether diagnostics are coloured (`--color`, NO_COLOR).
    colour: bool,
    /// `-q`: show only what changed, diagnostics and expectations not met.
    quiet: bool,
    limits: Limits,
    also_allowed: Vec<PathBuf>,
    cache: TaskCache,
    last_good: Option<Report>,
    evaluations: u64,
    watched_dirs: BTreeSet<PathBuf>,
    watched_files: BTreeSet<PathBuf>,
}

impl State {
    /// Check and run the scenario: the files read, and what to show. The
    /// files read are watched (`watching`) before any answer is shown, the
    /// first answers included.
    fn evaluate(
        &mut self,
        registry: &Registry,
        file: &Path,
        formatter: &dyn FormatPlugin,
        out: Option<&Path>,
        (watcher, root): (&mut RecommendedWatcher, &Path),
    ) -> (Vec<PathBuf>, String) {
        let started = Instant::now();
        self.evaluations += 1;
        let session = reach::Session::default()
            .limits(self.limits)
            .allowing(&self.also_allowed);
        let (sources, checked) = session.check(Input::Path(file), registry);
        self.rewatch(watcher, root, sources.disk_paths());
        let mut screen = String::new();
        // A run past the bound on solver work is an error like the others.
        // A bar on the terminal for a run that takes more than a second.
        let bar = crate::bar::Bar::new(!self.quiet);
        let ran = checked.and_then(|scenario| {
            match self.run_showing_first(&scenario, formatter, &bar, started) {
                Ok(ran) => Ok((scenario, ran)),
                Err(e) => Err(reach::Diagnostics::single(e).attach(&sources)),
            }
        });
        bar.clear();
        let summary = match ran {
            Ok((scenario, (report, stats))) => {
                if !self.quiet {
                    let text = formatter.render(&report, &scenario.format_scene());
                    screen.push_str(&text.unwrap_or_default());
                }
                if let Some(dir) = out {
                    let written = crate::signals::whole(|| {
                        reach::output::write_outputs(&report, &scenario, registry.formats(), dir)
                    });
                    match written {
                        Err(e) => {
                            screen.push_str(&reach::Diagnostics::single(e).render(!self.colour))
                        }
                        Ok(written) => {
                            if let Some(note) = written.note(dir) {
                                screen.push_str(&format!("{note}\n"));
                            }
                        }
                    }
                }
                let (changed, listed) = changes(self.last_good.as_ref(), &report);
                let expected = expectations(&report);
                let rerun = rerun(&report, &stats.ran_tasks);
                self.last_good = Some(report);
                let plural = |n: usize| if n == 1 { "" } else { "s" };
                format!(
                    "evaluated in {} ms ({} task{} run, {} unchanged); {changed}{expected}{rerun}{listed}",
                    started.elapsed().as_millis(),
                    stats.ran,
                    plural(stats.ran),
                    stats.reused,
                )
            }
            Err(d) => {
                screen.push_str(&d.render(!self.colour));
                format!(
                    "errors found in {} ms; watching for the next save",
                    started.elapsed().as_millis()
                )
            }
        };
        screen.push_str(&format!("\n{summary}\n"));
        (sources.disk_paths(), screen)
    }

    /// Run the scenario through the cache; where the tasks that must run
    /// again have not finished within [`FIRST_WAIT`], show the answers
    /// kept meanwhile, the others marked as being evaluated.
    fn run_showing_first(
        &mut self,
        scenario: &reach::Scenario,
        formatter: &dyn FormatPlugin,
        bar: &crate::bar::Bar,
        started: Instant,
    ) -> Result<(Report, reach::CacheStats), reach::Error> {
        let plan = self.cache.plan(scenario);
        // `-q` shows the summaries alone: no first answers.
        let first = (plan.first_report(scenario))
            .filter(|_| !self.quiet)
            .map(|report| (report, plan.to_run()));
        // The answers kept, the others marked, and a line naming those.
        let first_screen = |(report, to_run): (Report, Vec<usize>)| {
            let kept = report.tasks.len() - to_run.len() - scenario.standards.len();
            let text = formatter.render(&report, &scenario.format_scene());
            let mut screen = text.unwrap_or_default();
            screen.push_str(&format!(
                "\nfirst answers in {} ms ({kept} kept); evaluating {}\n",
                started.elapsed().as_millis(),
                named(&report, &to_run),
            ));
            screen
        };
        let (terminal, evaluation) = (self.terminal, self.evaluations);
        let cache = &mut self.cache;
        let (done, finished) = channel();
        std::thread::scope(|scope| {
            let finishing = scope.spawn(move || {
                let ran = cache.finish(plan, scenario, bar);
                let _ = done.send(());
                ran
            });
            if let Some(first) = first {
                if finished.recv_timeout(FIRST_WAIT) == Err(RecvTimeoutError::Timeout) {
                    let header = format!("=== first answers, evaluation {evaluation} ===");
                    print_screen(terminal, &header, &first_screen(first));
                }
            }
            finishing
                .join()
                .unwrap_or_else(|panic| std::panic::resume_unwind(panic))
        })
    }

    /// Say at once that a save is being evaluated, and which files
    /// changed: the screen keeps the last results until the new ones are
    /// shown (a terminal), or the line comes before them (a pipe).
    fn announce(&self, changed: &[String]) {
        let what = match changed {
            [] => "a file it uses was saved".to_string(),
            names => format!("{} changed", names.join(", ")),
        };
        let mut stdout = std::io::stdout().lock();
        let _ = writeln!(stdout, "--- {what}: evaluating ...");
        let _ = stdout.flush();
    }

    /// Replace the screen (terminal) or append after a separator (pipe).
    fn show(&self, screen: &str) {
        let header = format!("=== evaluation {} ===", self.evaluations);
        print_screen(self.terminal, &header, screen);
    }

    /// Watch the directories of the scenario's files (and of the root file,
    /// even while it is missing); stop watching those no longer needed.
    ///
    /// A file reached through a symbolic link is watched at both ends (an
    /// edit of the link's target changes no entry of the link's
    /// directory). Each directory's own directory is watched too, so that
    /// a directory removed and made again is seen, and every directory is
    /// watched afresh at each evaluation (a removed one's watch is gone).
    fn rewatch(&mut self, watcher: &mut RecommendedWatcher, root: &Path, files: Vec<PathBuf>) {
        let files: BTreeSet<PathBuf> = files
            .iter()
            .chain([&root.to_path_buf()])
            .flat_map(|f| {
                let shown = absolute(f);
                let target = f.canonicalize().ok().filter(|t| *t != shown);
                std::iter::once(shown).chain(target)
            })
            .collect();
        let dirs: BTreeSet<PathBuf> = files
            .iter()
            .filter_map(|f| f.parent())
            .flat_map(|d| std::iter::once(d).chain(d.parent()))
            .map(Path::to_path_buf)
            .collect();
        for gone in self.watched_dirs.difference(&dirs) {
            let _ = watcher.unwatch(gone);
        }
        for dir in &dirs {
            let _ = watcher.watch(dir, RecursiveMode::NonRecursive);
        }
        self.watched_dirs = dirs;
        self.watched_files = files;
    }
}

/// Replace the screen (`terminal`) or append after the `header` line.
fn print_screen(terminal: bool, header: &str, screen: &str) {
    let mut stdout = std::io::stdout().lock();
    if terminal {
        let _ = write!(stdout, "\x1b[2J\x1b[H");
    } else {
        let _ = writeln!(stdout, "{header}");
    }
    let _ = write!(stdout, "{screen}");
    let _ = stdout.flush();
}

/// Block until one of `files` (or another `.reach` file beside them, which
/// may be a file about to be used, or one of the watched `dirs` itself)
/// changes, then until events have been quiet for a moment. False when
/// the watcher is gone.
fn wait_for_change(rx: &Events, files: &BTreeSet<PathBuf>, dirs: &BTreeSet<PathBuf>) -> bool {
    // Reading the files (as every evaluation does) raises access events;
    // only writes, renames, creations and removals are changes.
    let relevant = |event: &notify::Result<notify::Event>| match event {
        Ok(e) => {
            let change = matches!(
                e.kind,
                EventKind::Create(_)
                    | EventKind::Remove(_)
                    | EventKind::Modify(
                        ModifyKind::Data(_) | ModifyKind::Name(_) | ModifyKind::Any
                    )
            );
            change
                && e.paths.iter().any(|p| {
                    files.contains(p)
                        || dirs.contains(p)
                        || p.extension().is_some_and(|x| x == "reach")
                })
        }
        Err(_) => false,
    };
    loop {
        match rx.recv() {
            Ok(event) if relevant(&event) => break,
            Ok(_) => continue,
            Err(_) => return false,
        }
    }
    loop {
        match rx.recv_timeout(QUIET) {
            Ok(_) => continue,
            Err(RecvTimeoutError::Timeout) => return true,
            Err(RecvTimeoutError::Disconnected) => return false,
        }
    }
}

/// An editor that deletes before writing leaves the file missing for a
/// moment: wait a little for it.
fn wait_until_present(file: &Path) {
    let started = Instant::now();
    while !file.exists() && started.elapsed() < MISSING_GRACE {
        std::thread::sleep(Duration::from_millis(10));
    }
}

fn absolute(path: &Path) -> PathBuf {
    std::path::absolute(path).unwrap_or_else(|_| path.to_path_buf())
}

/// The expectations in a few words, where the scenario has any: which
/// are not met, so that a designer who moves a shelf sees at once which
/// signed-off answer broke.
fn expectations(report: &Report) -> String {
    let all = &report.expectations;
    if all.is_empty() {
        return String::new();
    }
    let missed: Vec<&str> = all
        .iter()
        .filter(|e| !e.met)
        .map(|e| e.expect.as_str())
        .collect();
    if missed.is_empty() {
        format!("; every expectation met ({})", all.len())
    } else {
        format!(
            "; expectations NOT met ({} of {}): {}",
            missed.len(),
            all.len(),
            missed.join("; ")
        )
    }
}

/// The tasks run again rather than kept (by position in `report`), as
/// "; run again: mug by ann, ..." (at most [`RERUN_NAMED`] named), or
/// nothing where none or every one was.
fn rerun(report: &Report, ran: &[usize]) -> String {
    if ran.is_empty() || ran.len() == report.tasks.len() {
        return String::new();
    }
    format!("; run again: {}", named(report, ran))
}

/// The tasks at `positions` of `report`, by name: "mug by ann, ..." (at
/// most [`RERUN_NAMED`] named).
fn named(report: &Report, positions: &[usize]) -> String {
    let mut names: Vec<String> = (positions.iter().filter_map(|&i| report.tasks.get(i)))
        .map(|t| t.answer().label())
        .take(RERUN_NAMED)
        .collect();
    if positions.len() > RERUN_NAMED {
        names.push(format!("and {} more", positions.len() - RERUN_NAMED));
    }
    names.join(", ")
}

/// The most tasks run again the summary names.
const RERUN_NAMED: usize = 6;

/// Which answers changed since `before`, in a few words ("2 results
/// changed", "no result changed", "first results"), and listed, a line
/// each after the summary ("mug by ann: reachable -> NOT reachable"), new
/// and removed tasks too. Answers compare by their verdict in words.
fn changes(before: Option<&Report>, now: &Report) -> (String, String) {
    let Some(before) = before else {
        return ("first results".to_string(), String::new());
    };
    let (before, now) = (before.answers(), now.answers());
    let key = |a: &Answer| (a.task, a.subject.clone(), a.person.clone());
    let mut lines = Vec::new();
    for a in &now {
        match before.iter().find(|b| key(b) == key(a)) {
            Some(b) if b.verdict != a.verdict => {
                lines.push(format!("{}: {} -> {}", a.label(), b.verdict, a.verdict));
            }
            Some(_) => {}
            None => lines.push(format!("{}: new, {}", a.label(), a.verdict)),
        }
    }
    for b in &before {
        if !now.iter().any(|a| key(a) == key(b)) {
            lines.push(format!("{}: removed", b.label()));
        }
    }
    match lines.len() {
        0 => ("no result changed".to_string(), String::new()),
        n => (
            format!("{n} result{} changed", if n == 1 { "" } else { "s" }),
            lines.iter().map(|l| format!("\n  changed: {l}")).collect(),
        ),
    }
}
