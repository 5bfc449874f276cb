//! From text to syntax tree: the pest grammar (`grammar/reach.pest`), its
//! conversion to the AST, and parse errors in words a user knows.

pub mod ast;
mod code;
mod expected;
mod grammar;
mod parser;
mod population;
mod word;

pub use code::code_bytes;
pub use parser::{parse_file, parse_file_within};
pub use word::{is_keyword, is_name};
