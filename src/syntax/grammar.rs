//! The pest grammar of `.reach` files (`grammar/reach.pest`) and the
//! [`Rule`] enum pest derives from it, which the parser and the error
//! messages both read.

use pest_derive::Parser;

#[derive(Parser)]
#[grammar = "../grammar/reach.pest"]
pub(super) struct ReachParser;
