//! The `reach` command line: run, check, list plugins.

mod bar;
mod cli;
mod completion;
mod count_arg;
mod lsp;
mod man_pages;
mod shard_command;
mod signals;
mod test_command;
mod watch;

/// The stack of the thread that parses and checks: the parser and the
/// checker recurse as deep as the input nests, within `reach::Limits`,
/// whose ceilings are tested on a stack of this size.
const STACK_BYTES: usize = 64 * 1024 * 1024;

fn main() {
    let code = std::thread::Builder::new()
        .name("reach".into())
        .stack_size(STACK_BYTES)
        .spawn(cli::main)
        .expect("a thread can be started")
        .join()
        .unwrap_or(101);
    std::process::exit(code);
}
