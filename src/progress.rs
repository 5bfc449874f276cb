//! Progress of long tasks (a map's points), for a caller that wants to show
//! it. The library only counts; the command line draws a bar.

/// Told how much work there is and how much is done. Called from several
/// threads at once.
pub trait Progress: Send + Sync {
    /// `n` more units of work are coming.
    fn add_work(&self, n: u64);
    /// `n` units are done.
    fn advance(&self, n: u64);
}

/// Progress nobody watches.
pub struct NoProgress;

impl Progress for NoProgress {
    fn add_work(&self, _: u64) {}
    fn advance(&self, _: u64) {}
}
