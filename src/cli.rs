//! Command-line interface. Exit codes: 0 when the scenario evaluated (even
//! if targets are unreachable), 1 on diagnostics, 2 on usage errors.

use std::io::{IsTerminal, Write};
use std::path::{Path, PathBuf};

use clap::{Parser, Subcommand};
use reach::plugin::{PluginKind, Registry};
use reach::{Diagnostics, Error, ErrorKind, Input};

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
    Run {
        /// The .reach scenario file.
        file: PathBuf,
        /// Output format (see `reach plugins`).
        #[arg(long, default_value = "text")]
        format: String,
        /// Also write DIR/report.json, and a CSV and an SVG heat map per map.
        #[arg(long, value_name = "DIR")]
        out: Option<PathBuf>,
    },
    /// Evaluate a scenario, then again whenever it or a file it uses changes.
    Watch {
        /// The .reach scenario file.
        file: PathBuf,
        /// Output format (see `reach plugins`).
        #[arg(long, default_value = "text")]
        format: String,
        /// Also write DIR/report.json, and a CSV and an SVG heat map per map.
        #[arg(long, value_name = "DIR")]
        out: Option<PathBuf>,
    },
    /// Parse and check a scenario without running it.
    Check {
        /// The .reach scenario file.
        file: PathBuf,
    },
    /// List every plugin with its parameters.
    Plugins,
    /// List the standard library: mannequins, profiles, bases, visions.
    Stdlib,
}

pub fn main() -> i32 {
    let cli = Cli::parse();
    let registry = Registry::builtin();
    match cli.command {
        Command::Run { file, format, out } => run(&registry, &file, &format, out.as_deref()),
        Command::Watch { file, format, out } => {
            let Some(formatter) = registry.format(&format).cloned() else {
                return unknown_format(&registry, &format);
            };
            crate::watch::watch(&registry, &file, formatter.as_ref(), out.as_deref())
        }
        Command::Check { file } => check(&registry, &file),
        Command::Plugins => {
            print!("{}", plugins_listing(&registry));
            0
        }
        Command::Stdlib => {
            print!("{}", reach::stdlib::listing());
            0
        }
    }
}

fn run(registry: &Registry, file: &Path, format: &str, out: Option<&Path>) -> i32 {
    let Some(formatter) = registry.format(format) else {
        return unknown_format(registry, format);
    };
    let (_, checked) = reach::check(Input::Path(file), registry);
    let scenario = match checked {
        Ok(s) => s,
        Err(d) => return report_diagnostics(&d),
    };
    let bar = crate::bar::Bar::new();
    let report = reach::run_with_progress(&scenario, registry, &bar);
    bar.clear();
    if let Some(dir) = out {
        if let Err(e) = write_outputs(registry, &report, dir) {
            return report_diagnostics(&Diagnostics::single(e));
        }
    }
    let mut stdout = std::io::stdout().lock();
    let _ = stdout.write_all(formatter.render(&report).as_bytes());
    0
}

fn unknown_format(registry: &Registry, format: &str) -> i32 {
    eprintln!(
        "error: unknown format `{format}` (formats: {})",
        registry.names(PluginKind::Format).join(", ")
    );
    2
}

fn check(registry: &Registry, file: &Path) -> i32 {
    let (_, checked) = reach::check(Input::Path(file), registry);
    match checked {
        Ok(s) => {
            println!("{}: ok ({} tasks)", file.display(), s.tasks.len());
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

/// `DIR/report.json`, and a CSV and an SVG for each map.
pub fn write_outputs(
    registry: &Registry,
    report: &reach::report::Report,
    dir: &Path,
) -> Result<(), Error> {
    use reach::output::map_files;
    let json = registry
        .format("json")
        .expect("json is built in")
        .render(report);
    write_atomically(&dir.join("report.json"), json.as_bytes())?;
    for task in &report.tasks {
        if let reach::report::TaskReport::Map(m) = task {
            let stem = map_files::file_stem(m);
            write_atomically(
                &dir.join(format!("{stem}.csv")),
                map_files::csv(m).as_bytes(),
            )?;
            write_atomically(
                &dir.join(format!("{stem}.svg")),
                map_files::svg(m).as_bytes(),
            )?;
        }
    }
    Ok(())
}

/// Write `bytes` to a temporary file beside `path`, then rename it over
/// `path`: a reader sees the old file or the new one, never half of one.
fn write_atomically(path: &Path, bytes: &[u8]) -> Result<(), Error> {
    let fail = |e: std::io::Error| {
        Error::unplaced(ErrorKind::WriteFile {
            path: path.display().to_string(),
            reason: e.to_string(),
        })
    };
    let dir = path.parent().unwrap_or(Path::new("."));
    std::fs::create_dir_all(dir).map_err(fail)?;
    let mut tmp = tempfile::NamedTempFile::new_in(dir).map_err(fail)?;
    tmp.write_all(bytes).map_err(fail)?;
    tmp.as_file().sync_all().map_err(fail)?;
    tmp.persist(path).map_err(|e| fail(e.error))?;
    Ok(())
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
