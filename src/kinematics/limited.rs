//! What the couplings ask of a joint: its limits.

/// Something with limits: a joint (`min`, `max`).
pub trait Limited {
    fn limits(&self) -> (f64, f64);
}
