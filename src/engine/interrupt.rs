//! Ctrl-C and SIGTERM: the first asks the run to stop starting work (frames
//! in flight are abandoned and their temporary files removed); the second
//! exits at once. The exit code says which signal stopped the run, as a
//! shell reports a command a signal ended: 130 (128 + SIGINT) for Ctrl-C,
//! 143 (128 + SIGTERM) for a farm's or `kill`'s termination.

use std::sync::atomic::{AtomicBool, Ordering};

static REQUESTED: AtomicBool = AtomicBool::new(false);
/// The stop came from SIGTERM.
static TERMINATED: AtomicBool = AtomicBool::new(false);

const STOPPING: &str =
    "\nexrcomp: stopping: abandoning the frames in flight (again to quit at once)\n";

pub fn install() {
    let _ = ctrlc::set_handler(|| {
        if REQUESTED.swap(true, Ordering::SeqCst) {
            std::process::exit(exit_code());
        }
        eprint!("{STOPPING}");
    });
    // SIGTERM gets its own handler, installed over ctrlc's (which cannot
    // tell the signals apart), so that its exit code can be 143.
    // SAFETY: `on_terminate` does only what a signal handler may: atomic
    // stores, write(2) and _exit(2).
    unsafe {
        libc::signal(
            libc::SIGTERM,
            on_terminate as extern "C" fn(libc::c_int) as libc::sighandler_t,
        );
    }
}

extern "C" fn on_terminate(_: libc::c_int) {
    TERMINATED.store(true, Ordering::SeqCst);
    // SAFETY: async-signal-safe calls on a static message.
    unsafe {
        if REQUESTED.swap(true, Ordering::SeqCst) {
            libc::_exit(exit_code());
        }
        libc::write(2, STOPPING.as_ptr().cast(), STOPPING.len());
    }
}

/// A stop asked for by a front end that owns the signals itself (the
/// Python package, on KeyboardInterrupt): as Ctrl-C's first press.
pub fn request() {
    REQUESTED.store(true, Ordering::SeqCst);
}

/// A new run in a process that outlives its runs (the Python package's):
/// an earlier run's stop does not stop it.
pub fn reset() {
    REQUESTED.store(false, Ordering::SeqCst);
    TERMINATED.store(false, Ordering::SeqCst);
}

pub fn requested() -> bool {
    REQUESTED.load(Ordering::SeqCst)
}

/// The exit code of a run stopped by a signal: 143 after SIGTERM, else 130.
pub fn exit_code() -> i32 {
    match TERMINATED.load(Ordering::SeqCst) {
        true => 143,
        false => 130,
    }
}
