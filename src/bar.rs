//! The command line's progress bar: drawn on standard error only when it
//! is a terminal and the work has taken more than a second; nothing at all
//! when output is piped or the work is quick.

use std::io::IsTerminal;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, Instant};

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use reach::progress::Progress;

const QUIET_FOR: Duration = Duration::from_secs(1);

pub struct Bar {
    bar: ProgressBar,
    started: Instant,
    terminal: bool,
    shown: AtomicBool,
}

impl Bar {
    /// A bar that may be shown (`shown`: not with `--quiet`).
    pub fn new(shown: bool) -> Self {
        let bar = ProgressBar::with_draw_target(Some(0), ProgressDrawTarget::hidden());
        if let Ok(style) = ProgressStyle::with_template(
            "{bar:40} {pos}/{len} points  {elapsed_precise} (about {eta} left)",
        ) {
            bar.set_style(style);
        }
        Bar {
            bar,
            started: Instant::now(),
            terminal: shown && std::io::stderr().is_terminal(),
            shown: AtomicBool::new(false),
        }
    }

    /// Take the bar off the screen.
    pub fn clear(&self) {
        self.bar.finish_and_clear();
    }
}

impl Progress for Bar {
    fn add_work(&self, n: u64) {
        self.bar.inc_length(n);
    }

    fn advance(&self, n: u64) {
        self.bar.inc(n);
        if self.terminal
            && !self.shown.load(Ordering::Relaxed)
            && self.started.elapsed() > QUIET_FOR
        {
            self.shown.store(true, Ordering::Relaxed);
            self.bar.set_draw_target(ProgressDrawTarget::stderr());
        }
    }
}
