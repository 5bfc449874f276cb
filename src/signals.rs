//! SIGINT, SIGTERM and SIGHUP (a terminal closed, an SSH session
//! dropped) held back while an `--out` set is written, so that
//! DIR holds the previous set or the new one, never part of each: outside
//! [`whole`], they end the program at once as usual; inside, they are
//! noted, and the program ends (with 128 + the signal, as the shell
//! reports it) once the set is whole. SIGKILL cannot be held back: the
//! temporaries it leaves are swept at the next run.

use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::{Arc, OnceLock};

struct Held {
    /// True outside a set: a signal does what it always does.
    act_at_once: Arc<AtomicBool>,
    /// The signal that arrived while held, or 0.
    arrived: Arc<AtomicUsize>,
}

static HELD: OnceLock<Option<Held>> = OnceLock::new();

#[cfg(unix)]
fn install() -> Option<Held> {
    use signal_hook::consts::{SIGHUP, SIGINT, SIGTERM};
    let held = Held {
        act_at_once: Arc::new(AtomicBool::new(true)),
        arrived: Arc::new(AtomicUsize::new(0)),
    };
    for signal in [SIGINT, SIGTERM, SIGHUP] {
        // The default action first, when allowed; else only noted.
        signal_hook::flag::register_conditional_default(signal, Arc::clone(&held.act_at_once))
            .ok()?;
        signal_hook::flag::register_usize(signal, Arc::clone(&held.arrived), signal as usize)
            .ok()?;
    }
    Some(held)
}

#[cfg(not(unix))]
fn install() -> Option<Held> {
    None
}

/// Run `write` (an output set being written) with SIGINT, SIGTERM and
/// SIGHUP held back; if one arrived meanwhile, end the program once it is
/// done.
pub fn whole<T>(write: impl FnOnce() -> T) -> T {
    let Some(held) = HELD.get_or_init(install) else {
        return write();
    };
    held.act_at_once.store(false, Ordering::SeqCst);
    let result = write();
    held.act_at_once.store(true, Ordering::SeqCst);
    let signal = held.arrived.swap(0, Ordering::SeqCst);
    if signal != 0 {
        std::process::exit(128 + signal as i32);
    }
    result
}
