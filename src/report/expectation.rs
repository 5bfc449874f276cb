//! An expectation's result: what the scenario file claims of its answers
//! (`expect ann reaches kettle`), whether it holds, and why, in words, so
//! that a failing one says what changed ("NOT reachable: blocked by
//! `upper_cabinet`").

use serde::Serialize;

#[derive(Clone, Debug, PartialEq, Serialize, schemars::JsonSchema)]
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

impl ExpectationReport {
    /// `expectation NOT met: ann reaches kettle: NOT reachable ... (k.reach:12)`.
    pub fn not_met_line(&self) -> String {
        let shown = |t: &str| crate::escape::escaped(t).into_owned();
        format!(
            "expectation NOT met: {}: {} ({})",
            shown(&self.expect),
            shown(&self.because),
            shown(&self.at)
        )
    }

    /// The expectation not met as a finding, on the line it is written
    /// on.
    pub fn finding(&self) -> crate::machine_diagnostics::Finding {
        let (file, line) = match self.at.rsplit_once(':') {
            Some((file, line)) if line.parse::<usize>().is_ok() => {
                (Some(file.to_string()), line.parse().ok())
            }
            _ => (Some(self.at.clone()), None),
        };
        crate::machine_diagnostics::Finding {
            code: "reach::expect",
            message: format!("expectation NOT met: {}: {}", self.expect, self.because),
            file,
            line,
        }
    }
}
