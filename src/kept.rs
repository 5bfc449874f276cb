//! Values kept for a run or a watch session, keyed by a hash of
//! everything they depend on: watch mode checks and runs the scenario
//! again at every save, and most of what it worked out (a base's floor,
//! the floor a standard's route travels) depends only on things a save
//! seldom changes.
//!
//! A [`Memo`] is owned by whoever runs (`reach::Session`: one for a run,
//! or one a watch session keeps across its runs) and reached by the code
//! that keeps values through the run's allowance
//! ([`crate::allowance::Allowance::memo`]). Each kind of value is a
//! [`Table`], a constant that names it and bounds how many are kept.
//!
//! The key must hash all the value depends on; then a kept value is the
//! value worked out afresh (the tests of each user say how they know).

use std::any::Any;
use std::collections::HashMap;
use std::convert::Infallible;
use std::marker::PhantomData;
use std::sync::{Arc, Mutex, MutexGuard};

/// The values a run or a watch session keeps, a table of each kind.
#[derive(Default)]
pub struct Memo {
    tables: Mutex<HashMap<&'static str, Arc<dyn Any + Send + Sync>>>,
    /// A memo that keeps nothing: every value is worked out afresh (the
    /// allowance of a bench or a test of one computation).
    forgets: bool,
    /// Set by [`Memo::cancel`]: every run keeping values here stops as a
    /// run past its bound on work stops, and gives no answer.
    cancelled: std::sync::atomic::AtomicBool,
}

impl std::fmt::Debug for Memo {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Memo")
            .field("tables", &self.lock().len())
            .field("forgets", &self.forgets)
            .finish()
    }
}

impl Memo {
    /// A memo that keeps nothing.
    pub fn forgetting() -> Self {
        Memo {
            tables: Mutex::default(),
            forgets: true,
            cancelled: Default::default(),
        }
    }

    /// Stop the runs that keep values here (an editor's run that the
    /// next edit makes stale): each stops as a run past its bound stops,
    /// with an error and no answer, and keeps only values worked out
    /// whole. Until [`Memo::resume`].
    pub fn cancel(&self) {
        self.cancelled
            .store(true, std::sync::atomic::Ordering::Relaxed);
    }

    /// Let runs keeping values here run again.
    pub fn resume(&self) {
        self.cancelled
            .store(false, std::sync::atomic::Ordering::Relaxed);
    }

    /// Whether [`Memo::cancel`] stopped the runs.
    pub fn cancelled(&self) -> bool {
        self.cancelled.load(std::sync::atomic::Ordering::Relaxed)
    }

    fn lock(&self) -> MutexGuard<'_, HashMap<&'static str, Arc<dyn Any + Send + Sync>>> {
        // A thread that panicked while holding the lock left whole entries.
        self.tables.lock().unwrap_or_else(|e| e.into_inner())
    }

    /// `table`'s values in this memo, none if it keeps nothing.
    fn values<V: Clone + Send + Sync + 'static>(&self, table: &Table<V>) -> Option<Arc<Values<V>>> {
        if self.forgets {
            return None;
        }
        let any = Arc::clone(self.lock().entry(table.name).or_insert_with(|| {
            Arc::new(Values::<V> {
                values: Mutex::default(),
                most: table.most,
            })
        }));
        // Two tables of one name with different values would be a bug of
        // this crate's; such a table keeps nothing rather than panicking.
        any.downcast::<Values<V>>().ok()
    }
}

/// One kind of value a memo keeps: its name (unique in the crate) and at
/// most how many are kept at a time (when full, it starts again empty: a
/// scenario needs a few dozen; a population's members each their own).
pub struct Table<V> {
    name: &'static str,
    most: usize,
    value: PhantomData<fn() -> V>,
}

impl<V: Clone + Send + Sync + 'static> Table<V> {
    pub const fn new(name: &'static str, most: usize) -> Self {
        Table {
            name,
            most,
            value: PhantomData,
        }
    }

    /// The value `memo` keeps for `key`, or `compute`'s, then kept. Two
    /// threads asking at once may both compute it; both get the same value.
    pub fn get_or(&self, memo: &Memo, key: u64, compute: impl FnOnce() -> V) -> V {
        match self.get_or_try(memo, key, || Ok::<V, Infallible>(compute())) {
            Ok(value) => value,
            Err(never) => match never {},
        }
    }

    /// The value `memo` keeps for `key`, or `compute`'s, kept only where
    /// it is one (a computation cut short is not kept).
    pub fn get_or_try<E>(
        &self,
        memo: &Memo,
        key: u64,
        compute: impl FnOnce() -> Result<V, E>,
    ) -> Result<V, E> {
        let Some(values) = memo.values(self) else {
            return compute();
        };
        if let Some(value) = values.lock().get(&key) {
            return Ok(value.clone());
        }
        let value = compute()?;
        let mut kept = values.lock();
        if kept.len() >= values.most {
            kept.clear();
        }
        kept.insert(key, value.clone());
        Ok(value)
    }
}

/// A table's values in one memo.
struct Values<V> {
    values: Mutex<HashMap<u64, V>>,
    most: usize,
}

impl<V> Values<V> {
    fn lock(&self) -> MutexGuard<'_, HashMap<u64, V>> {
        self.values.lock().unwrap_or_else(|e| e.into_inner())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const NUMBERS: Table<u32> = Table::new("numbers", 2);

    #[test]
    fn a_value_is_computed_once_per_key_and_the_table_starts_again_when_full() {
        let memo = Memo::default();
        assert_eq!(NUMBERS.get_or(&memo, 1, || 10), 10);
        assert_eq!(NUMBERS.get_or(&memo, 1, || unreachable!("kept")), 10);
        assert_eq!(NUMBERS.get_or(&memo, 2, || 20), 20);
        // Full: the third starts again.
        assert_eq!(NUMBERS.get_or(&memo, 3, || 30), 30);
        assert_eq!(NUMBERS.get_or(&memo, 1, || 11), 11);
    }

    #[test]
    fn a_value_that_failed_is_not_kept() {
        let memo = Memo::default();
        assert_eq!(NUMBERS.get_or_try(&memo, 1, || Err::<u32, ()>(())), Err(()));
        assert_eq!(NUMBERS.get_or_try(&memo, 1, || Ok::<u32, ()>(10)), Ok(10));
        assert_eq!(NUMBERS.get_or_try(&memo, 1, || Err::<u32, ()>(())), Ok(10));
    }

    #[test]
    fn memos_keep_apart_and_a_forgetting_one_keeps_nothing() {
        let (a, b) = (Memo::default(), Memo::forgetting());
        assert_eq!(NUMBERS.get_or(&a, 1, || 10), 10);
        assert_eq!(NUMBERS.get_or(&Memo::default(), 1, || 12), 12);
        assert_eq!(NUMBERS.get_or(&b, 1, || 13), 13);
        assert_eq!(NUMBERS.get_or(&b, 1, || 14), 14);
        assert_eq!(NUMBERS.get_or(&a, 1, || unreachable!("kept")), 10);
    }
}
