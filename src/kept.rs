//! Values kept by the process, keyed by a hash of everything they depend
//! on: watch mode checks and runs the scenario again at every save, and
//! most of what it worked out (a base's floor, the floor a standard's
//! route travels) depends only on things a save seldom changes.
//!
//! The key must hash all the value depends on; then a kept value is the
//! value worked out afresh (the tests of each user say how they know).

use std::collections::HashMap;
use std::convert::Infallible;
use std::sync::{Mutex, OnceLock};

/// Values of one kind, at most `most` at a time: when full, it starts
/// again empty (a scenario needs a few dozen; a population's members each
/// their own).
pub struct Kept<V> {
    values: OnceLock<Mutex<HashMap<u64, V>>>,
    most: usize,
}

impl<V: Clone> Kept<V> {
    pub const fn new(most: usize) -> Self {
        Kept {
            values: OnceLock::new(),
            most,
        }
    }

    /// The value kept for `key`, or `compute`'s, then kept. Two threads
    /// asking at once may both compute it; both get the same value.
    pub fn get_or(&self, key: u64, compute: impl FnOnce() -> V) -> V {
        match self.get_or_try(key, || Ok::<V, Infallible>(compute())) {
            Ok(value) => value,
            Err(never) => match never {},
        }
    }

    /// The value kept for `key`, or `compute`'s, kept only where it is
    /// one (a computation cut short is not kept).
    pub fn get_or_try<E>(&self, key: u64, compute: impl FnOnce() -> Result<V, E>) -> Result<V, E> {
        let values = self.values.get_or_init(Mutex::default);
        // A thread that panicked while holding the lock left whole entries.
        let lock = || values.lock().unwrap_or_else(|e| e.into_inner());
        if let Some(value) = lock().get(&key) {
            return Ok(value.clone());
        }
        let value = compute()?;
        let mut kept = lock();
        if kept.len() >= self.most {
            kept.clear();
        }
        kept.insert(key, value.clone());
        Ok(value)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_value_is_computed_once_per_key_and_the_store_starts_again_when_full() {
        let kept: Kept<u32> = Kept::new(2);
        assert_eq!(kept.get_or(1, || 10), 10);
        assert_eq!(kept.get_or(1, || unreachable!("kept")), 10);
        assert_eq!(kept.get_or(2, || 20), 20);
        // Full: the third starts again.
        assert_eq!(kept.get_or(3, || 30), 30);
        assert_eq!(kept.get_or(1, || 11), 11);
    }

    #[test]
    fn a_value_that_failed_is_not_kept() {
        let kept: Kept<u32> = Kept::new(2);
        assert_eq!(kept.get_or_try(1, || Err::<u32, ()>(())), Err(()));
        assert_eq!(kept.get_or_try(1, || Ok::<u32, ()>(10)), Ok(10));
        assert_eq!(kept.get_or_try(1, || Err::<u32, ()>(())), Ok(10));
    }
}
