//! What the couplings ask of a joint: its limits.

/// Something with limits: a joint (`min`, `max`).
pub trait Limited {
    fn limits(&self) -> (f64, f64);
}

/// For tests: a bare range.
#[cfg(test)]
pub(super) struct Range(pub f64, pub f64);

#[cfg(test)]
impl Limited for Range {
    fn limits(&self) -> (f64, f64) {
        (self.0, self.1)
    }
}
