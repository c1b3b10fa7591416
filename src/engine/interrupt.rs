//! Ctrl-C and SIGTERM: the first asks the run to stop starting work (frames
//! in flight are abandoned and their temporary files removed); the second
//! exits at once.

use std::sync::atomic::{AtomicBool, Ordering};

static REQUESTED: AtomicBool = AtomicBool::new(false);

pub fn install() {
    let _ = ctrlc::set_handler(|| {
        if REQUESTED.swap(true, Ordering::SeqCst) {
            std::process::exit(crate::error::Kind::Interrupted.exit_code());
        }
        eprintln!("\nexrcomp: stopping: abandoning the frames in flight (again to quit at once)");
    });
}

pub fn requested() -> bool {
    REQUESTED.load(Ordering::SeqCst)
}
