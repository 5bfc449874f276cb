//! Command-line interface. Exit codes: 0 when the scenario evaluated (even
//! if targets are unreachable, or a person's base fits nowhere), 1 on
//! diagnostics, 2 on usage errors, 3 when the scenario ran but one of its
//! `expect`s is not met (unless `--no-expect`), or with `--strict` a
//! person's base fits nowhere in a task's room. `reach test` exits 1 when
//! any scenario fails, as test runners do.

use std::io::{IsTerminal, Write};
use std::path::{Path, PathBuf};

use clap::{Args, Parser, Subcommand};
use reach::escape::escaped;
use reach::limits::{CEILINGS, DEFAULTS};
use reach::plugin::{PluginKind, Registry};
use reach::{Diagnostics, Input, Limits};

#[derive(Parser)]
#[command(
    name = "reach",
    version,
    about = "Can this person reach and see the things in this room?"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Evaluate a scenario and print its report.
    Run(Evaluate),
    /// Evaluate a scenario, then again whenever it or a file it uses changes.
    Watch(Evaluate),
    /// Parse and check a scenario without running it.
    Check {
        /// The .reach scenario file.
        file: PathBuf,
        #[command(flatten)]
        limits: LimitArgs,
    },
    /// Run every scenario under the paths as a test: its `expect`s, and
    /// its answers against its golden report (NAME.golden.json beside it).
    Test {
        /// Scenario files, or directories searched for .reach files
        /// (default: the current directory).
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
        #[command(flatten)]
        limits: LimitArgs,
    },
    /// List every plugin with its parameters.
    Plugins,
    /// List the standard library: mannequins, profiles, bases, visions.
    Stdlib,
}

/// What `run` and `watch` take.
#[derive(Args)]
struct Evaluate {
    /// The .reach scenario file.
    file: PathBuf,
    /// Output format (see `reach plugins`).
    #[arg(long, default_value = "text")]
    format: String,
    /// Also write DIR/report.json, and a CSV and an SVG heat map per map.
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
    #[arg(long, value_name = "BYTES", default_value_t = DEFAULTS.file_bytes as u64, value_parser = clap::value_parser!(u64).range(1..=CEILINGS.file_bytes as u64))]
    max_file_bytes: u64,
    /// Deepest nesting of parentheses and braces
    #[arg(long, value_name = "LEVELS", default_value_t = DEFAULTS.nesting as u64, value_parser = clap::value_parser!(u64).range(1..=CEILINGS.nesting as u64))]
    max_nesting: u64,
    /// Most operands and operators in one expression
    #[arg(long, value_name = "N", default_value_t = DEFAULTS.expression_terms as u64, value_parser = clap::value_parser!(u64).range(1..=CEILINGS.expression_terms as u64))]
    max_expression_terms: u64,
    /// Longest chain of constants defined in terms of each other
    #[arg(long, value_name = "N", default_value_t = DEFAULTS.constant_chain as u64, value_parser = clap::value_parser!(u64).range(1..=CEILINGS.constant_chain as u64))]
    max_constant_chain: u64,
    /// Longest chain of files using each other
    #[arg(long, value_name = "N", default_value_t = DEFAULTS.use_chain as u64, value_parser = clap::value_parser!(u64).range(1..=CEILINGS.use_chain as u64))]
    max_use_chain: u64,
    /// Longest chain of mannequins naming each other
    #[arg(long, value_name = "N", default_value_t = DEFAULTS.alias_chain as u64, value_parser = clap::value_parser!(u64).range(1..=CEILINGS.alias_chain as u64))]
    max_alias_chain: u64,
    /// Most solver starts the tasks may need, counted at their worst
    #[arg(long, value_name = "N", default_value_t = DEFAULTS.solver_starts as u64, value_parser = clap::value_parser!(u64).range(1..=CEILINGS.solver_starts as u64))]
    max_solver_starts: u64,
    /// Most people one population may draw
    #[arg(long, value_name = "N", default_value_t = DEFAULTS.people as u64, value_parser = clap::value_parser!(u64).range(1..=CEILINGS.people as u64))]
    max_people: u64,
    /// Also read used files, meshes and URDFs from DIR (by default only
    /// from the scenario's own directory and below); may be repeated
    #[arg(long, value_name = "DIR")]
    allow_path: Vec<PathBuf>,
}

impl LimitArgs {
    fn limits(&self) -> Limits {
        Limits {
            file_bytes: self.max_file_bytes,
            nesting: self.max_nesting as usize,
            expression_terms: self.max_expression_terms as usize,
            constant_chain: self.max_constant_chain as usize,
            use_chain: self.max_use_chain as usize,
            alias_chain: self.max_alias_chain as usize,
            solver_starts: self.max_solver_starts,
            people: self.max_people as usize,
        }
    }
}

pub fn main() -> i32 {
    let cli = Cli::parse();
    let registry = Registry::builtin();
    match cli.command {
        Command::Run(e) => run(&registry, &e),
        Command::Watch(e) => {
            let Some(formatter) = registry.format(&e.format).cloned() else {
                return unknown_format(&registry, &e.format);
            };
            let limits = e.limits.limits();
            crate::watch::watch(
                &registry,
                (&limits, &e.limits.allow_path),
                &e.file,
                formatter.as_ref(),
                e.out.as_deref(),
            )
        }
        Command::Check { file, limits } => check(&registry, &limits, &file),
        Command::Test {
            paths,
            update,
            golden_dir,
            junit,
            tolerance_mm,
            tolerance_deg,
            limits,
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
            },
        ),
        Command::Plugins => {
            print!("{}", plugins_listing(&registry));
            0
        }
        Command::Stdlib => {
            print!("{}", reach::std_modules::listing());
            0
        }
    }
}

fn run(registry: &Registry, e: &Evaluate) -> i32 {
    let Some(formatter) = registry.format(&e.format) else {
        return unknown_format(registry, &e.format);
    };
    let limits = e.limits.limits();
    let allowed = &e.limits.allow_path;
    let (_, checked) = reach::check_allowing(Input::Path(&e.file), registry, &limits, allowed);
    let scenario = match checked {
        Ok(s) => s,
        Err(d) => return report_diagnostics(&d),
    };
    let bar = crate::bar::Bar::new();
    let report = reach::run_with_progress(&scenario, &bar);
    bar.clear();
    if let Some(dir) = &e.out {
        if let Err(error) =
            crate::signals::whole(|| reach::output::write_outputs(&report, &scenario, dir))
        {
            return report_diagnostics(&Diagnostics::single(error));
        }
    }
    let mut stdout = std::io::stdout().lock();
    let _ = stdout.write_all(
        formatter
            .render(&report, &scenario.format_scene())
            .as_bytes(),
    );
    let not_placed = report.tasks.iter().any(|t| match t {
        reach::report::TaskReport::NotPlaced(_) => true,
        reach::report::TaskReport::Population(p) => p.not_placed > 0,
        _ => false,
    });
    if e.strict && not_placed {
        eprintln!(
            "error: a person's base fits nowhere in a task's room, or cannot get there from its doors (--strict)"
        );
        return NOT_AS_EXPECTED;
    }
    if !e.no_expect && !report.expectations_met() {
        let missed = report.expectations.iter().filter(|x| !x.met).count();
        eprintln!("error: {missed} of the scenario's expectations not met");
        return NOT_AS_EXPECTED;
    }
    0
}

/// The exit code when the scenario ran but an expectation is not met, or
/// (`--strict`) a person's base fits nowhere or cannot get in: not 1,
/// which says the input is wrong.
const NOT_AS_EXPECTED: i32 = 3;

fn unknown_format(registry: &Registry, format: &str) -> i32 {
    eprintln!(
        "error: unknown format `{}` (formats: {})",
        escaped(format),
        registry.names(PluginKind::Format).join(", ")
    );
    2
}

fn check(registry: &Registry, args: &LimitArgs, file: &Path) -> i32 {
    let limits = args.limits();
    let (_, checked) =
        reach::check_allowing(Input::Path(file), registry, &limits, &args.allow_path);
    match checked {
        Ok(s) => {
            let shown = file.display().to_string();
            println!("{}: ok ({} tasks)", escaped(&shown), s.tasks.len());
            0
        }
        Err(d) => report_diagnostics(&d),
    }
}

fn report_diagnostics(d: &Diagnostics) -> i32 {
    let plain = !std::io::stderr().is_terminal() || std::env::var_os("NO_COLOR").is_some();
    eprint!("{}", d.render(plain));
    1
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
                let default = match &param.default {
                    Some(v) => format!("default {}", v.display()),
                    None if param.optional => "optional".to_string(),
                    None => "required".to_string(),
                };
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
