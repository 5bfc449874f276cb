//! The `reach` command line: run, check, list plugins.

mod bar;
mod cli;
mod watch;

fn main() {
    std::process::exit(cli::main());
}
