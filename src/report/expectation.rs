//! An expectation's result: what the scenario file claims of its answers
//! (`expect ann reaches kettle`), whether it holds, and why, in words, so
//! that a failing one says what changed ("NOT reachable: blocked by
//! `upper_cabinet`").

use serde::Serialize;

#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ExpectationReport {
    /// The expectation as written (`ann reaches kettle`).
    pub expect: String,
    /// Where it is written: `file:line`.
    pub at: String,
    pub met: bool,
    /// What the answers say (`NOT reachable: blocked by `shelf` (12.3 mm
    /// away)`, `covers 72.5 % (58 of 80 points)`).
    pub because: String,
}
