//! Command-line interface. Exit codes: 0 when the scenario evaluated (even
//! if targets are unreachable, or a person's base fits nowhere), 1 on
//! diagnostics, 2 on usage errors, 3 when the scenario ran but one of its
//! `expect`s is not met (unless `--no-expect`), or with `--strict` a
//! person's base fits nowhere in a task's room, 4 when the bound on work
//! stopped `reach run` partway (the answers before the stop are shown).
//! `reach test` exits 1 when any scenario fails, as test runners do.

use std::io::{IsTerminal, Write};
use std::path::{Path, PathBuf};

use crate::count_arg::Count;
use clap::{ArgMatches, Args, ColorChoice, CommandFactory, FromArgMatches, Parser, Subcommand};
use reach::escaped;
use reach::limits::{CEILINGS, DEFAULTS};
use reach::plugin::{PluginKind, Registry};
use reach::report::TaskReport;
use reach::Finding;
use reach::{DiagnosticStyle, Diagnostics, Input, Limits};

/// What `reach --help` and the man page say of exit codes.
const EXIT_STATUS: &str = "Exit status: 0 when the scenario evaluated and its expects are met \
(an unreachable target, or a chair that fits nowhere, is an answer); 1 when the input has \
errors, or `reach test` has a failing scenario; 2 on usage errors; 3 when the scenario ran but \
an expect is not met (unless --no-expect), or with --strict a base fits nowhere; 4 when the \
bound on solver work stopped `reach run` partway (the answers before the stop are shown, the \
rest are not evaluated).";

#[derive(Parser)]
#[command(
    name = "reach",
    version,
    about = "Can this person reach and see the things in this room?",
    after_long_help = EXIT_STATUS
)]
struct Cli {
    /// When to colour diagnostics and help: auto colours a terminal unless
    /// NO_COLOR is set
    #[arg(long, value_name = "WHEN", global = true, default_value = "auto")]
    color: ColorChoice,
    #[command(subcommand)]
    command: Command,
}

/// How failures are written, for `run`, `check` and `test`.
#[derive(Args)]
#[command(next_help_heading = "Output")]
struct Reporting {
    /// How diagnostics and failures are written on standard error: human,
    /// json (one object per line; not for `test`, which has --junit) or
    /// github (workflow commands)
    #[arg(long, value_name = "FORMAT", default_value = "human")]
    diagnostics: DiagnosticsFormat,
    /// Print only failures (diagnostics, expectations not met); the exit
    /// code says the rest
    #[arg(short, long)]
    quiet: bool,
}

#[derive(Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
enum DiagnosticsFormat {
    Human,
    Json,
    Github,
}

#[derive(Subcommand)]
enum Command {
    /// Evaluate a scenario and print its report.
    Run {
        #[command(flatten)]
        evaluate: Evaluate,
        /// Run only the K-th of N equal ranges of each population's
        /// people, and print the shard's file (JSON, whatever --format) for
        /// `reach merge`, which runs the rest
        #[arg(long, value_name = "K/N", conflicts_with = "out", value_parser = shard_of)]
        shard: Option<reach::ShardOf>,
        #[command(flatten)]
        reporting: Reporting,
    },
    /// Join the files of a run's shards (`reach run FILE --shard K/N`, every
    /// K from 1 to N) into the report one run of FILE gives, byte for byte:
    /// runs each task by one person and the standards, and takes each
    /// population's people from the shards
    Merge {
        /// Instead: join the --junit files of a suite's shards (`reach test
        /// --shard K/N`; FILE and SHARD are those files) into OUT, as one
        /// `reach test --junit OUT` writes it
        #[arg(long, value_name = "OUT")]
        junit: Option<PathBuf>,
        #[command(flatten)]
        evaluate: Evaluate,
        /// The shards' files, in any order
        #[arg(required_unless_present = "junit", value_name = "SHARD")]
        shards: Vec<PathBuf>,
        #[command(flatten)]
        reporting: Reporting,
    },
    /// Evaluate a scenario, then again whenever it or a file it uses changes.
    Watch {
        #[command(flatten)]
        evaluate: Evaluate,
        /// Print only the summary of each evaluation (what changed, the
        /// expectations not met) and diagnostics, not the report
        #[arg(short, long)]
        quiet: bool,
    },
    /// Parse and check a scenario without running it.
    Check {
        /// The .reach scenario files.
        #[arg(required = true, value_hint = clap::ValueHint::FilePath)]
        files: Vec<PathBuf>,
        /// Also estimate the work a run will need, task by task, against
        /// the bound on solver work: runs every task by one person and a
        /// sample of each population's people (the square root of its
        /// size, at least 8), within the most a file may raise the bound to
        /// (--max-solver-work times --max-limits-raise)
        #[arg(long)]
        estimate: bool,
        #[command(flatten)]
        limits: LimitArgs,
        #[command(flatten)]
        reporting: Reporting,
    },
    /// Run every scenario under the paths as a test: its `expect`s, and
    /// its answers against its golden report (NAME.golden.json beside it).
    Test {
        /// Scenario files, or directories searched for .reach files
        /// (default: the current directory).
        #[arg(value_hint = clap::ValueHint::AnyPath)]
        paths: Vec<PathBuf>,
        /// Write the golden reports that are missing or whose answers
        /// changed (and only those).
        #[arg(long)]
        update: bool,
        /// Where the golden reports are, by each scenario's path under the
        /// directory it was found in (default: beside each scenario).
        #[arg(long, value_name = "DIR")]
        golden_dir: Option<PathBuf>,
        /// Also write the results as JUnit XML.
        #[arg(long, value_name = "FILE")]
        junit: Option<PathBuf>,
        /// Positions within this many millimetres count as unchanged.
        #[arg(long, value_name = "MM", default_value_t = 1.0)]
        tolerance_mm: f64,
        /// Headings within this many degrees count as unchanged.
        #[arg(long, value_name = "DEG", default_value_t = 0.1)]
        tolerance_deg: f64,
        /// Test only the K-th of N equal ranges of the scenarios found (in
        /// the order of their paths); `reach merge --junit` joins the
        /// shards' --junit files
        #[arg(long, value_name = "K/N", value_parser = shard_of)]
        shard: Option<reach::ShardOf>,
        #[command(flatten)]
        limits: LimitArgs,
        #[command(flatten)]
        reporting: Reporting,
    },
    /// Serve the Language Server Protocol over standard input and output:
    /// an editor's open .reach files checked as `reach check` checks them,
    /// their diagnostics shown as you type; completion, hover, definitions,
    /// references and rename; each scenario run when opened and when saved,
    /// its answers shown on the lines that ask them (docs/editors.md).
    Lsp {
        #[command(flatten)]
        limits: LimitArgs,
    },
    /// List every plugin with its parameters.
    Plugins,
    /// List the standard library: mannequins, profiles, bases, visions;
    /// or show one of them.
    Stdlib {
        /// A name to show: its declaration, the comment above it that
        /// names the sources of its figures, and for a mannequin the body
        /// it builds (each joint's limits and link, the effectors, the legs).
        name: Option<String>,
    },
    /// Print the JSON Schema of the report (`--format json`, `--out`).
    Schema,
    /// Print a shell completion script (see the README for where it goes).
    Completions {
        /// The shell.
        shell: clap_complete::Shell,
    },
    /// Print the man page (roff; `reach man | man -l -`), or write every
    /// command's page into a directory.
    Man {
        /// Write reach.1, reach-run.1, ... into DIR (made if missing).
        #[arg(long, value_name = "DIR")]
        out: Option<PathBuf>,
    },
}

/// `K/N` for `--shard`.
fn shard_of(text: &str) -> Result<reach::ShardOf, String> {
    reach::ShardOf::parse(text)
}

/// What `run` and `watch` take.
#[derive(Args)]
struct Evaluate {
    /// The .reach scenario file.
    #[arg(value_hint = clap::ValueHint::FilePath)]
    file: PathBuf,
    /// Output format for standard output: text, json or html (glb and maps
    /// are written by --out only).
    #[arg(long, default_value = "text")]
    format: String,
    /// Also write every format's files as one set: DIR/report.txt,
    /// report.json, report.html, scene.glb, and a CSV and an SVG heat map
    /// per map; with DIR/.reach-set, its list, sealed with your key
    /// (~/.local/state/reach/key). The next set removes only files this
    /// list names and that are as it wrote them.
    #[arg(long, value_name = "DIR")]
    out: Option<PathBuf>,
    /// Exit 3 (after the report) if a person's base fits nowhere in a
    /// task's room; without it that is an answer like any other (exit 0)
    #[arg(long)]
    strict: bool,
    /// Report the scenario's `expect`s but do not exit 3 when one is not met
    #[arg(long)]
    no_expect: bool,
    #[command(flatten)]
    limits: LimitArgs,
}

/// Resource limits (docs/language.md, "Limits"); each may be raised up to
/// a ceiling the tool is tested to handle.
#[derive(Args)]
#[command(next_help_heading = "Limits")]
struct LimitArgs {
    /// Largest file read: scenario, OBJ mesh, URDF
    #[arg(long, value_name = "BYTES", default_value_t = DEFAULTS.file_bytes as u64, value_parser = Count(CEILINGS.file_bytes as u64))]
    max_file_bytes: u64,
    /// Largest scenario file (.reach), the root or a used one
    #[arg(long, value_name = "BYTES", default_value_t = DEFAULTS.scenario_bytes as u64, value_parser = Count(CEILINGS.scenario_bytes as u64))]
    max_scenario_bytes: u64,
    /// Most boxes and meshes in one room
    #[arg(long, value_name = "N", default_value_t = DEFAULTS.boxes as u64, value_parser = Count(CEILINGS.boxes as u64))]
    max_boxes: u64,
    /// Deepest nesting of parentheses and braces
    #[arg(long, value_name = "LEVELS", default_value_t = DEFAULTS.nesting as u64, value_parser = Count(CEILINGS.nesting as u64))]
    max_nesting: u64,
    /// Most operands and operators in one expression
    #[arg(long, value_name = "N", default_value_t = DEFAULTS.expression_terms as u64, value_parser = Count(CEILINGS.expression_terms as u64))]
    max_expression_terms: u64,
    /// Longest chain of constants defined in terms of each other
    #[arg(long, value_name = "N", default_value_t = DEFAULTS.constant_chain as u64, value_parser = Count(CEILINGS.constant_chain as u64))]
    max_constant_chain: u64,
    /// Longest chain of files using each other
    #[arg(long, value_name = "N", default_value_t = DEFAULTS.use_chain as u64, value_parser = Count(CEILINGS.use_chain as u64))]
    max_use_chain: u64,
    /// Longest chain of mannequins naming each other
    #[arg(long, value_name = "N", default_value_t = DEFAULTS.alias_chain as u64, value_parser = Count(CEILINGS.alias_chain as u64))]
    max_alias_chain: u64,
    /// Most solver starts the tasks may need, counted at their worst
    #[arg(long, value_name = "N", default_value_t = DEFAULTS.solver_starts as u64, value_parser = Count(CEILINGS.solver_starts as u64))]
    max_solver_starts: u64,
    /// Most work the solvers may do in one run (about a joint moved once
    /// a unit), counted as they work, with the routes from the doors
    #[arg(long, value_name = "UNITS", default_value_t = DEFAULTS.solver_work, value_parser = Count(CEILINGS.solver_work))]
    max_solver_work: u64,
    /// Most people one population may draw, and most persons a scenario
    /// declares
    #[arg(long, value_name = "N", default_value_t = DEFAULTS.people as u64, value_parser = Count(CEILINGS.people as u64))]
    max_people: u64,
    /// Most triangles all the meshes of a scenario may hold (a glTF's
    /// instances placed)
    #[arg(long, value_name = "N", default_value_t = DEFAULTS.triangles as u64, value_parser = Count(CEILINGS.triangles as u64))]
    max_triangles: u64,
    /// Most joints in one mannequin (declared, or a URDF's chain)
    #[arg(long, value_name = "N", default_value_t = DEFAULTS.joints as u64, value_parser = Count(CEILINGS.joints as u64))]
    max_joints: u64,
    /// Most points the tasks of one run answer together (a map's every
    /// point once for each person, a population's map once)
    #[arg(long, value_name = "N", default_value_t = DEFAULTS.map_points, value_parser = Count(CEILINGS.map_points))]
    max_map_points: u64,
    /// How many times --max-solver-starts and --max-solver-work a scenario
    /// may raise its own bounds to (`limits { ... }` in the file)
    #[arg(long, value_name = "TIMES", default_value_t = DEFAULTS.raise, value_parser = Count(CEILINGS.raise))]
    max_limits_raise: u64,
    /// Also read used files, meshes and URDFs from DIR (by default only
    /// from the scenario's own directory and below); may be repeated
    #[arg(long, value_name = "DIR")]
    allow_path: Vec<PathBuf>,
}

impl LimitArgs {
    fn limits(&self) -> Limits {
        Limits {
            file_bytes: self.max_file_bytes,
            scenario_bytes: self.max_scenario_bytes,
            boxes: self.max_boxes as usize,
            nesting: self.max_nesting as usize,
            expression_terms: self.max_expression_terms as usize,
            constant_chain: self.max_constant_chain as usize,
            use_chain: self.max_use_chain as usize,
            alias_chain: self.max_alias_chain as usize,
            solver_starts: self.max_solver_starts,
            solver_work: self.max_solver_work,
            people: self.max_people as usize,
            triangles: self.max_triangles as usize,
            joints: self.max_joints as usize,
            map_points: self.max_map_points,
            raise: self.max_limits_raise,
        }
    }
}

pub fn main() -> i32 {
    let cli = parse();
    let registry = Registry::builtin();
    let colour = cli.color;
    match cli.command {
        Command::Run {
            evaluate,
            shard: Some(shard),
            reporting,
        } => run_shard(&registry, &evaluate, shard, &Shown::new(&reporting, colour)),
        Command::Run {
            evaluate,
            shard: None,
            reporting,
        } => run(&registry, &evaluate, &Shown::new(&reporting, colour)),
        Command::Merge {
            junit: Some(out),
            evaluate,
            shards,
            ..
        } => {
            let parts: Vec<PathBuf> = std::iter::once(evaluate.file).chain(shards).collect();
            crate::test_command::merge_junit(&out, &parts, evaluate.limits.limits().file_bytes)
        }
        Command::Merge {
            junit: None,
            evaluate,
            shards,
            reporting,
        } => merge(
            &registry,
            &evaluate,
            &shards,
            &Shown::new(&reporting, colour),
        ),
        Command::Watch { evaluate: e, quiet } => {
            let Some(formatter) = registry.format(&e.format).cloned() else {
                return unknown_format(&registry, &e.format);
            };
            if !formatter.prints() {
                return unprintable_format(&registry, &e.format);
            }
            let limits = e.limits.limits();
            crate::watch::watch(
                &registry,
                (&limits, &e.limits.allow_path),
                &e.file,
                formatter.as_ref(),
                (
                    e.out.as_deref(),
                    colours(colour, std::io::stdout().is_terminal()),
                    quiet,
                ),
            )
        }
        Command::Check {
            files,
            estimate,
            limits,
            reporting,
        } => {
            let shown = Shown::new(&reporting, colour);
            // Every file is checked; the exit code is the worst.
            files
                .iter()
                .map(|file| check(&registry, &limits, file, estimate, &shown))
                .max()
                .unwrap_or(0)
        }
        Command::Lsp { limits } => {
            let session = reach::Session::default()
                .limits(limits.limits())
                .allowing(&limits.allow_path);
            match crate::lsp::serve_stdio(session, &registry) {
                Ok(()) => 0,
                Err(e) => {
                    eprintln!("reach lsp: {}", escaped(&e.to_string()));
                    1
                }
            }
        }
        Command::Test {
            paths,
            update,
            golden_dir,
            junit,
            tolerance_mm,
            tolerance_deg,
            shard,
            limits,
            reporting,
        } => crate::test_command::test(
            &registry,
            crate::test_command::TestArgs {
                paths,
                update,
                golden_dir,
                junit,
                tolerance: reach::suite::Tolerance {
                    mm: tolerance_mm,
                    deg: tolerance_deg,
                },
                limits: limits.limits(),
                allowed: limits.allow_path,
                quiet: reporting.quiet,
                shard,
                style: Shown::new(&reporting, colour).style,
            },
        ),
        Command::Plugins => {
            print!("{}", plugins_listing(&registry));
            0
        }
        Command::Stdlib { name: None } => {
            print!("{}", reach::stdlib_listing());
            0
        }
        Command::Stdlib { name: Some(name) } => stdlib_entry(&name),
        Command::Schema => {
            print!("{}", reach::report::schema_json());
            0
        }
        Command::Completions { shell } => {
            let mut script = Vec::new();
            clap_complete::generate(shell, &mut Cli::command(), "reach", &mut script);
            if shell == clap_complete::Shell::Bash {
                script.extend_from_slice(
                    crate::completion::bash_scenario_files(&Cli::command()).as_bytes(),
                );
            }
            match std::io::stdout().write_all(&script) {
                Ok(()) => 0,
                Err(_) => 1,
            }
        }
        Command::Man { out } => man(out.as_deref()),
    }
}

/// `reach stdlib NAME`: the entry, or an error (exit 2) with the closest
/// name the standard library declares.
fn stdlib_entry(name: &str) -> i32 {
    match reach::stdlib_entry(name) {
        Ok(text) => {
            print!("{text}");
            0
        }
        Err(suggestion) => {
            let hint = suggestion.map_or(String::new(), |s| format!(" (did you mean `{s}`?)"));
            eprintln!(
                "error: the standard library declares no `{}`{hint}; `reach stdlib` lists its names",
                reach::escaped(name)
            );
            2
        }
    }
}

/// `reach man`: the top page on standard output, or every page into `out`.
fn man(out: Option<&Path>) -> i32 {
    let written = crate::man_pages::pages(Cli::command()).and_then(|pages| match out {
        None => std::io::stdout().write_all(&pages[0].1),
        Some(dir) => reach::output::write_set(dir, &pages).map_err(std::io::Error::other),
    });
    match written {
        Ok(()) => 0,
        Err(e) => {
            eprintln!("error: cannot write the man pages: {e}");
            1
        }
    }
}

/// The command line, with clap's own help and errors coloured as
/// `--color` says (clap reads NO_COLOR itself for `auto`).
fn parse() -> Cli {
    // Read leniently (a file name need not be UTF-8): clap checks them.
    let args: Vec<String> = (std::env::args_os().skip(1))
        .map(|a| a.to_string_lossy().into_owned())
        .take_while(|a| a != "--")
        .collect();
    let choice = args
        .iter()
        .enumerate()
        .find_map(|(i, a)| match a.strip_prefix("--color")? {
            "" => args.get(i + 1).cloned(),
            value => value.strip_prefix('=').map(str::to_string),
        });
    let colour = match choice.as_deref() {
        Some("always") => ColorChoice::Always,
        Some("never") => ColorChoice::Never,
        _ => ColorChoice::Auto,
    };
    let matches: ArgMatches = Cli::command().color(colour).get_matches();
    Cli::from_arg_matches(&matches).unwrap_or_else(|e| e.exit())
}

/// Whether to colour a stream: `--color always` or `never` as said; `auto`
/// colours a terminal unless NO_COLOR is set to anything but nothing.
fn colours(choice: ColorChoice, terminal: bool) -> bool {
    match choice {
        ColorChoice::Always => true,
        ColorChoice::Never => false,
        ColorChoice::Auto => terminal && std::env::var_os("NO_COLOR").is_none_or(|v| v.is_empty()),
    }
}

/// How `run` and `check` show what they found.
struct Shown {
    style: DiagnosticStyle,
    quiet: bool,
}

impl Shown {
    fn new(r: &Reporting, colour: ColorChoice) -> Self {
        let style = match r.diagnostics {
            DiagnosticsFormat::Human => DiagnosticStyle::Human {
                colour: colours(colour, std::io::stderr().is_terminal()),
            },
            DiagnosticsFormat::Json => DiagnosticStyle::Json,
            DiagnosticsFormat::Github => DiagnosticStyle::Github,
        };
        Shown {
            style,
            quiet: r.quiet,
        }
    }

    /// Write the diagnostics on standard error (standard output keeps the
    /// report). Exit code 1.
    fn diagnostics(&self, d: &Diagnostics) -> i32 {
        eprint!("{}", d.render_in(self.style));
        1
    }

    /// A failure of the run, on standard error: for people only with
    /// `--quiet` (the report above says it), always for programs.
    fn finding(&self, f: &Finding) {
        if self.quiet || !matches!(self.style, DiagnosticStyle::Human { .. }) {
            eprint!("{}", f.render_in(self.style));
        }
    }

    /// The last line of a failed run, for people (programs have had each
    /// finding, and the exit code says the rest).
    fn summary(&self, text: &str) {
        if matches!(self.style, DiagnosticStyle::Human { .. }) {
            eprintln!("error: {text}");
        }
    }
}

fn run(registry: &Registry, e: &Evaluate, shown: &Shown) -> i32 {
    let Some(formatter) = registry.format(&e.format) else {
        return unknown_format(registry, &e.format);
    };
    if !formatter.prints() {
        return unprintable_format(registry, &e.format);
    }
    let limits = e.limits.limits();
    let allowed = &e.limits.allow_path;
    let session = reach::Session::default().limits(limits).allowing(allowed);
    let (sources, checked) = session.check(Input::Path(&e.file), registry);
    let scenario = match checked {
        Ok(s) => s,
        Err(d) => return shown.diagnostics(&d),
    };
    let bar = crate::bar::Bar::new(!shown.quiet);
    // Where the bound stops the run, the file checked afresh runs again
    // one task at a time (Session::run_partly).
    let again = || session.check(Input::Path(&e.file), registry).1.ok();
    let ran = session.progress(&bar).run_partly(&scenario, &again);
    bar.clear();
    let ran = Presented {
        scenario: &scenario,
        sources: &sources,
        report: ran.report,
        stopped: ran.stopped,
    };
    present(registry, e, formatter.as_ref(), shown, ran)
}

/// `reach run FILE --shard K/N`: the shard's file on standard output.
fn run_shard(registry: &Registry, e: &Evaluate, shard: reach::ShardOf, shown: &Shown) -> i32 {
    let bar = crate::bar::Bar::new(!shown.quiet);
    let file = crate::shard_command::shard_file(registry, &e.reading(), shard, &bar);
    bar.clear();
    match file {
        Ok(text) => {
            let _ = std::io::stdout().lock().write_all(text.as_bytes());
            0
        }
        Err(d) => shown.diagnostics(&d),
    }
}

/// `reach merge FILE SHARD...`: shown and written as `reach run` would.
fn merge(registry: &Registry, e: &Evaluate, shards: &[PathBuf], shown: &Shown) -> i32 {
    let Some(formatter) = registry.format(&e.format) else {
        return unknown_format(registry, &e.format);
    };
    if !formatter.prints() {
        return unprintable_format(registry, &e.format);
    }
    let bar = crate::bar::Bar::new(!shown.quiet);
    let merged = crate::shard_command::merged(registry, &e.reading(), shards, &bar);
    bar.clear();
    match merged {
        Ok(m) => {
            let ran = Presented {
                scenario: &m.scenario,
                sources: &m.sources,
                report: m.report,
                stopped: None,
            };
            present(registry, e, formatter.as_ref(), shown, ran)
        }
        Err(d) => shown.diagnostics(&d),
    }
}

impl Evaluate {
    fn reading(&self) -> crate::shard_command::Reading<'_> {
        crate::shard_command::Reading {
            file: &self.file,
            limits: self.limits.limits(),
            allowed: &self.limits.allow_path,
        }
    }
}

/// A run's report, to show and write.
struct Presented<'a> {
    pub scenario: &'a reach::Scenario,
    pub sources: &'a reach::Sources,
    pub report: reach::report::Report,
    /// Where the bound stopped the run partway.
    pub stopped: Option<reach::Error>,
}

/// Show and write a run's report as `reach run` does (`formatter` on
/// standard output, every format's files with `--out`), and its exit
/// code: a stop partway, expectations not met, `--strict`.
fn present(
    registry: &Registry,
    e: &Evaluate,
    formatter: &dyn reach::plugin::FormatPlugin,
    shown: &Shown,
    ran: Presented<'_>,
) -> i32 {
    let Presented {
        scenario,
        sources,
        report,
        stopped,
    } = ran;
    if let Some(dir) = &e.out {
        match crate::signals::whole(|| {
            reach::output::write_outputs(&report, scenario, registry.formats(), dir)
        }) {
            Err(error) => return shown.diagnostics(&Diagnostics::single(error)),
            Ok(written) => {
                if let Some(note) = written.note(dir) {
                    eprintln!("{note}");
                }
            }
        }
    }
    let mut stdout = std::io::stdout().lock();
    if !shown.quiet {
        let _ = stdout.write_all(
            formatter
                .render(&report, &scenario.format_scene())
                .unwrap_or_default()
                .as_bytes(),
        );
    }
    // The tasks whose person, or some of whose population, fits nowhere
    // or cannot get in, each in words.
    let not_placed: Vec<String> = (report.tasks.iter())
        .filter_map(|t| {
            let answer = t.answer();
            match t {
                TaskReport::NotPlaced(_) => Some(answer.verdict.clone()),
                TaskReport::Population(p) if p.not_placed > 0 => Some(format!(
                    "{} of {} fit nowhere or cannot get in",
                    p.not_placed, p.people
                )),
                _ => None,
            }
            .map(|why| format!("{}: {why}", answer.label()))
        })
        .collect();
    if let Some(error) = stopped {
        // The expectations of the tasks answered that are not met, as a
        // whole run would give them (those of tasks not evaluated are not
        // met either; the stop says why).
        let missed = (report.expectations.iter())
            .filter(|x| !x.met && !x.because.starts_with("not evaluated"));
        for x in missed {
            shown.finding(&x.finding());
        }
        eprint!(
            "{}",
            Diagnostics::single(error)
                .attach(sources)
                .render_in(shown.style)
        );
        return STOPPED_PARTWAY;
    }
    if e.strict && !not_placed.is_empty() {
        let file = e.file.display().to_string();
        for message in not_placed {
            shown.finding(&Finding {
                code: "reach::strict",
                message,
                file: Some(file.clone()),
                line: None,
            });
        }
        shown.summary(
            "a person's base fits nowhere in a task's room, or cannot get there from its doors (--strict)",
        );
        return NOT_AS_EXPECTED;
    }
    if !e.no_expect && !report.expectations_met() {
        let missed: Vec<_> = report.expectations.iter().filter(|x| !x.met).collect();
        for x in &missed {
            shown.finding(&x.finding());
        }
        shown.summary(&format!(
            "{} of the scenario's expectations not met",
            missed.len()
        ));
        return NOT_AS_EXPECTED;
    }
    0
}

/// The exit code when the scenario ran but an expectation is not met, or
/// (`--strict`) a person's base fits nowhere or cannot get in: not 1,
/// which says the input is wrong.
const NOT_AS_EXPECTED: i32 = 3;

/// The exit code when the bound on work stopped the run partway: the
/// answers before it are shown and written, the rest are not evaluated.
const STOPPED_PARTWAY: i32 = 4;

/// A format with no text for standard output (`glb`, `maps`): a usage
/// error, with the formats that have one.
fn unprintable_format(registry: &Registry, format: &str) -> i32 {
    eprintln!(
        "error: format `{}` writes files only, which `--out DIR` writes with every other format's; `--format` picks what standard output shows: {}",
        escaped(format),
        format_names(registry, true)
    );
    2
}

fn unknown_format(registry: &Registry, format: &str) -> i32 {
    eprintln!(
        "error: unknown format `{}` (formats: {}; written by --out only: {})",
        escaped(format),
        format_names(registry, true),
        format_names(registry, false)
    );
    2
}

/// The names of the formats that print to standard output (`prints`), or
/// of those that only write files.
fn format_names(registry: &Registry, prints: bool) -> String {
    (registry.formats().iter())
        .filter(|f| f.prints() == prints)
        .map(|f| f.name())
        .collect::<Vec<_>>()
        .join(", ")
}

fn check(registry: &Registry, args: &LimitArgs, file: &Path, estimate: bool, shown: &Shown) -> i32 {
    let limits = args.limits();
    let session = reach::Session::default()
        .limits(limits)
        .allowing(&args.allow_path);
    let (_, checked) = session.check(Input::Path(file), registry);
    let scenario = match checked {
        Ok(s) => s,
        Err(d) => return shown.diagnostics(&d),
    };
    if !shown.quiet {
        let name = file.display().to_string();
        // What a run answers: each task's, then each standard's.
        let answers = scenario.tasks.len() + scenario.standards.len();
        let noun = if answers == 1 { "task" } else { "tasks" };
        println!("{}: ok ({answers} {noun})", escaped(&name));
    }
    if estimate {
        let bar = crate::bar::Bar::new(!shown.quiet);
        // The most a file may raise its bound to: the estimate of a file
        // beyond its bound says by how much.
        let file_ceiling =
            (limits.solver_work.saturating_mul(limits.raise)).max(scenario.work.limit);
        let estimated = scenario.estimate_work(&bar, file_ceiling);
        bar.clear();
        for line in estimated.text(scenario.work.limit, file_ceiling).lines() {
            println!("{}", escaped(line));
        }
    }
    0
}

fn plugins_listing(registry: &Registry) -> String {
    let mut out = String::new();
    let all = || {
        PluginKind::ALL
            .into_iter()
            .flat_map(|k| registry.of_kind(k))
    };
    let plugin_width = all().map(|p| p.name().len()).max().unwrap_or(0);
    let param_width = all()
        .flat_map(|p| p.params())
        .map(|p| p.name.len())
        .max()
        .unwrap_or(0);
    for kind in PluginKind::ALL {
        out.push_str(&format!("{}s:\n", kind.noun()));
        for p in registry.of_kind(kind) {
            out.push_str(&format!("  {:<plugin_width$}  {}\n", p.name(), p.doc()));
            for param in p.params() {
                let default = param.default_words();
                out.push_str(&format!(
                    "      {:<param_width$}  {:<8} {:<22} {}\n",
                    param.name,
                    param.kind.short(),
                    default,
                    param.doc
                ));
            }
        }
        out.push('\n');
    }
    out
}
