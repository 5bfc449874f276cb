//! The `reach` command line: run, check, list plugins.

mod bar;
mod cli;

fn main() {
    std::process::exit(cli::main());
}
