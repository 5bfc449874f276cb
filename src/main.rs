//! The `reach` command line: run, check, list plugins.

mod cli;

fn main() {
    std::process::exit(cli::main());
}
