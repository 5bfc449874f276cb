//! `reach test [PATH...]`: the scenarios under the paths run as a test
//! suite (`reach::suite`): one line per scenario, then each failure in
//! words, a summary line, and exit 1 on any failure.

use std::path::PathBuf;

use reach::plugin::Registry;
use reach::suite::{self, Compared, Golden, Outcome, SuiteOptions, Tolerance};
use reach::DiagnosticStyle;

/// What `reach test` was asked.
pub struct TestArgs {
    pub paths: Vec<PathBuf>,
    pub update: bool,
    pub golden_dir: Option<PathBuf>,
    pub junit: Option<PathBuf>,
    pub tolerance: Tolerance,
    pub limits: reach::Limits,
    pub allowed: Vec<PathBuf>,
    /// Print only the scenarios that fail.
    pub quiet: bool,
    /// Test only the K-th of N equal ranges of the scenarios found (in
    /// the order of their paths).
    pub shard: Option<reach::ShardOf>,
    /// How diagnostics are written; `Github` adds a workflow command per
    /// diagnostic and per expectation not met after the summary.
    pub style: DiagnosticStyle,
}

pub fn test(registry: &Registry, args: TestArgs) -> i32 {
    if args.style == DiagnosticStyle::Json {
        eprintln!(
            "error: `reach test` writes its results for programs as JUnit XML (--junit FILE); \
             --diagnostics json is for `run` and `check`"
        );
        return 2;
    }
    let roots = if args.paths.is_empty() {
        vec![PathBuf::from(".")]
    } else {
        args.paths.clone()
    };
    let scenarios = match suite::discover(&roots) {
        Ok(s) => s,
        Err(e) => {
            eprintln!("error: {}", reach::escaped(&e));
            return 2;
        }
    };
    let options = SuiteOptions {
        golden_dir: args.golden_dir.clone(),
        update: args.update,
        tolerance: args.tolerance,
        limits: args.limits,
        allowed: args.allowed.clone(),
    };
    let scenarios = match args.shard {
        Some(shard) => scenarios[shard.people(scenarios.len())].to_vec(),
        None => scenarios,
    };
    let outcomes = suite::run_suite(&scenarios, &roots, &options, registry);
    if outcomes.is_empty() && args.shard.is_none() {
        eprintln!("error: no .reach scenario under the paths given");
        return 1;
    }
    print!("{}", summary(&outcomes, &args));
    if args.style == DiagnosticStyle::Github {
        eprint!("{}", annotations(&outcomes));
    }
    if let Some(path) = &args.junit {
        let shard = args.shard.map(|s| (s.index, s.count));
        if let Err(e) = write_junit(path, &suite::junit(&outcomes, shard)) {
            eprintln!("error: cannot write {}: {e}", path.display());
            return 1;
        }
    }
    i32::from(outcomes.iter().any(|o| !o.passed()))
}

/// `reach merge --junit OUT PART...`: the JUnit files of a suite's shards
/// joined as the whole suite's, written to `out`.
pub fn merge_junit(out: &std::path::Path, parts: &[PathBuf], limit_bytes: u64) -> i32 {
    let mut files = Vec::with_capacity(parts.len());
    for part in parts {
        let name = part.display().to_string();
        let text = reach::read_root(part, limit_bytes)
            .map_err(|e| e.to_string())
            .and_then(|bytes| String::from_utf8(bytes).map_err(|_| "not UTF-8 text".to_string()));
        match text {
            Ok(text) => files.push((name, text)),
            Err(why) => {
                eprintln!("error: cannot read {}: {why}", reach::escaped(&name));
                return 1;
            }
        }
    }
    let merged = match suite::merge_junit(&files) {
        Ok(xml) => xml,
        Err(why) => {
            eprintln!("error: cannot merge: {}", reach::escaped(&why));
            return 1;
        }
    };
    match write_junit(out, &merged) {
        Ok(()) => 0,
        Err(e) => {
            eprintln!("error: cannot write {}: {e}", out.display());
            1
        }
    }
}

fn write_junit(path: &std::path::Path, xml: &str) -> Result<(), String> {
    let dir = path
        .parent()
        .filter(|d| !d.as_os_str().is_empty())
        .unwrap_or(std::path::Path::new("."));
    let name = path
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .ok_or("not a file name")?;
    reach::output::write_set(dir, &[(name, xml.as_bytes().to_vec())]).map_err(|e| e.to_string())
}

/// One line per scenario, the failures in words, the golden reports
/// written, and the counts; quiet, only the failures.
fn summary(outcomes: &[Outcome], args: &TestArgs) -> String {
    use std::fmt::Write;
    let mut out = String::new();
    let colour = matches!(args.style, DiagnosticStyle::Human { colour: true });
    let failed: Vec<&Outcome> = outcomes.iter().filter(|o| !o.passed()).collect();
    if args.quiet {
        for o in &failed {
            let _ = writeln!(out, "FAILED  {}  ({})", shown(&o.path), counts(o));
            failure(o, colour, &mut out);
        }
        return out;
    }
    for o in outcomes {
        let mark = if o.passed() { "ok    " } else { "FAILED" };
        let _ = writeln!(out, "{mark}  {}  ({})", shown(&o.path), counts(o));
    }
    if !failed.is_empty() {
        let _ = writeln!(out, "\nfailures:");
        for o in &failed {
            let _ = writeln!(out, "\n{}", shown(&o.path));
            failure(o, colour, &mut out);
        }
    }
    let written: Vec<String> = outcomes.iter().filter_map(written).collect();
    if !written.is_empty() {
        let _ = writeln!(out, "\ngolden reports:");
        for w in written {
            let _ = writeln!(out, "  {w}");
        }
    }
    let _ = writeln!(
        out,
        "\n{} passed, {} failed",
        outcomes.len() - failed.len(),
        failed.len()
    );
    out
}

/// What a scenario's line says in brackets: how many answers, the
/// expectations met, and what became of its golden report.
fn counts(o: &Outcome) -> String {
    if o.diagnostics.is_some() {
        return "does not check".into();
    }
    let mut parts = vec![plural(o.answers, "answer", "answers")];
    if !o.expectations.is_empty() {
        let met = o.expectations.iter().filter(|e| e.met).count();
        parts.push(format!(
            "{met} of {} met",
            plural(o.expectations.len(), "expectation", "expectations")
        ));
    }
    parts.push(
        match &o.golden {
            Golden::Absent => "no golden report",
            Golden::Compared(Compared::Same) => "as in the golden report",
            Golden::Compared(_) => "NOT as in the golden report",
            Golden::Written { fresh: true, .. } => "golden report written",
            Golden::Written { .. } => "golden report rewritten",
            Golden::NotWritten { .. } => "golden report NOT written",
            Golden::Shared { .. } => "golden report shared with another scenario",
        }
        .into(),
    );
    parts.join(", ")
}

fn plural(n: usize, one: &str, many: &str) -> String {
    format!("{n} {}", if n == 1 { one } else { many })
}

/// What failed in one scenario.
fn failure(o: &Outcome, colour: bool, out: &mut String) {
    use std::fmt::Write;
    if let Some(d) = &o.diagnostics {
        // Rendered text escapes what it quotes of the file already.
        for line in d.render(!colour).lines() {
            let _ = writeln!(out, "  {line}");
        }
    }
    for e in o.expectations.iter().filter(|e| !e.met) {
        let _ = writeln!(out, "  {}", e.not_met_line());
    }
    failure_of_golden(o, out);
}

/// How a scenario's golden report failed, if it did.
fn failure_of_golden(o: &Outcome, out: &mut String) {
    use std::fmt::Write;
    match &o.golden {
        Golden::Compared(Compared::Changed(changes)) => {
            let _ = writeln!(out, "  answers changed from the golden report:");
            for c in changes {
                let _ = writeln!(out, "    {}", shown_text(c));
            }
        }
        Golden::Compared(Compared::OtherSchema { golden }) => {
            let _ = writeln!(
                out,
                "  the golden report was written by schema {golden}, not this reach's; \
                 check the answers and run `reach test --update` to write it again"
            );
        }
        Golden::Compared(Compared::Unreadable(why)) => {
            let _ = writeln!(
                out,
                "  the golden report cannot be read: {}",
                shown_text(why)
            );
        }
        Golden::NotWritten { path, reason } => {
            let _ = writeln!(
                out,
                "  cannot write {}: {}",
                shown(path),
                shown_text(reason)
            );
        }
        Golden::Shared { path, with } => {
            let _ = writeln!(out, "  {}", shown_text(&Golden::shared_words(path, with)));
        }
        _ => {}
    }
}

/// GitHub workflow commands for what failed: each diagnostic and each
/// expectation not met on its line, each other failure on its scenario.
fn annotations(outcomes: &[Outcome]) -> String {
    use reach::machine_diagnostics::{data, property};
    let mut out = String::new();
    for o in outcomes.iter().filter(|o| !o.passed()) {
        if let Some(d) = &o.diagnostics {
            out.push_str(&d.render_in(DiagnosticStyle::Github));
        }
        for e in o.expectations.iter().filter(|e| !e.met) {
            out.push_str(&e.finding().render_in(DiagnosticStyle::Github));
        }
        let mut rest = String::new();
        failure_of_golden(o, &mut rest);
        if !rest.is_empty() {
            out.push_str(&format!(
                "::error file={},title={}::{}\n",
                property(&o.path.display().to_string()),
                property("reach::golden"),
                data(&trimmed_lines(&rest))
            ));
        }
    }
    out
}

/// `text`'s lines without their indentation.
fn trimmed_lines(text: &str) -> String {
    text.lines().map(str::trim).collect::<Vec<_>>().join("\n")
}

/// The golden report `--update` wrote, if it did, in words.
fn written(o: &Outcome) -> Option<String> {
    let Golden::Written {
        path,
        changes,
        fresh,
    } = &o.golden
    else {
        return None;
    };
    Some(if *fresh {
        format!("wrote {} (new)", shown(path))
    } else {
        let n = changes.len();
        let what = if n == 1 { "answer" } else { "answers" };
        format!("rewrote {} ({n} {what} changed)", shown(path))
    })
}

fn shown(path: &std::path::Path) -> String {
    reach::escaped(&path.display().to_string()).into_owned()
}

fn shown_text(text: &str) -> String {
    reach::escaped(text).into_owned()
}
