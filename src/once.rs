//! A value worked out once and kept in a [`OnceLock`], where the work
//! itself runs on rayon's threads.
//!
//! `OnceLock::get_or_init` blocks while another call initialises the
//! cell, and deadlocks where the call that initialises it asks for it
//! again. Work that runs rayon jobs inside the initialisation does that
//! without meaning to: a thread waiting for its jobs takes up another job
//! from its queue (the next tile of the same floor, another point of the
//! same map), and that job asks for the very cell the thread is
//! initialising. [`get_or_compute`] never blocks: whoever finds the cell
//! empty works the value out, and the first value set is kept. Two
//! threads may then both work it out; the value must not depend on which
//! did (it is the same computation), and work charged for it must be
//! charged by a key, not by whoever computed it.

use std::sync::OnceLock;

/// The value in `cell`, or `compute`'s, set if the cell is still empty
/// (a value set meanwhile, by another thread or by a call made from
/// inside `compute`, is kept and `compute`'s dropped).
pub fn get_or_compute<T>(cell: &OnceLock<T>, compute: impl FnOnce() -> T) -> &T {
    if let Some(value) = cell.get() {
        return value;
    }
    let value = compute();
    // Set by whoever finished first; the same value either way.
    let _ = cell.set(value);
    cell.get().expect("the cell was just set")
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::mpsc;
    use std::time::Duration;

    /// Runs `f` on a thread of its own and fails if it has not finished
    /// within a minute (a deadlock would otherwise hang the tests).
    fn finishes<T: Send + 'static>(f: impl FnOnce() -> T + Send + 'static) -> T {
        let (tx, rx) = mpsc::channel();
        std::thread::spawn(move || _ = tx.send(f()));
        rx.recv_timeout(Duration::from_secs(60))
            .expect("finished within a minute: no deadlock")
    }

    #[test]
    fn a_cell_asked_for_again_from_inside_its_own_computation_does_not_deadlock() {
        let got = finishes(|| {
            let cell = OnceLock::new();
            *get_or_compute(&cell, || *get_or_compute(&cell, || 7) + 1)
        });
        // The inner call set the cell first; the outer value is dropped.
        assert_eq!(got, 7);
    }

    #[test]
    fn rayon_jobs_that_ask_for_the_cell_their_caller_initialises_finish() {
        // Some jobs ask for the cell; the first to find it empty runs jobs
        // of its own while it works the value out, and a thread waiting
        // for those (stolen by another) takes up outer jobs, some of which
        // ask again.
        let sums = finishes(|| {
            use rayon::prelude::*;
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(8)
                .build()
                .expect("a pool");
            pool.install(|| {
                (0..400)
                    .map(|_| {
                        let cell = OnceLock::new();
                        let inner = || (0..4000u64).into_par_iter().map(busy).sum::<u64>();
                        (0..256u64)
                            .into_par_iter()
                            .map(|k| match k % 4 {
                                0 => *get_or_compute(&cell, inner) + k,
                                _ => (0..64u64).into_par_iter().map(busy).sum::<u64>() + k,
                            })
                            .sum::<u64>()
                    })
                    .collect::<Vec<u64>>()
            })
        });
        let inner: u64 = (0..4000u64).map(busy).sum();
        let other: u64 = (0..64u64).map(busy).sum();
        let expected = 64 * inner + 192 * other + (0..256).sum::<u64>();
        assert!(sums.iter().all(|&s| s == expected));
    }

    /// A little arithmetic that takes a while.
    fn busy(k: u64) -> u64 {
        (0..200u64).fold(k, |a, b| a.wrapping_mul(31).wrapping_add(b)) % 1000
    }

    #[test]
    fn a_value_already_set_is_returned_without_computing() {
        let cell = OnceLock::new();
        assert_eq!(*get_or_compute(&cell, || 1), 1);
        assert_eq!(*get_or_compute(&cell, || unreachable!("kept")), 1);
    }
}
