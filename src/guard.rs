//! Panics become errors, reported in one line by whoever catches them.
//!
//! Damaged files can make a codec panic; that panic must become an error
//! naming the file, not a crash. A bug of exrcomp's own met in one frame
//! (src/engine/pipeline.rs) must cost that frame, not an unattended night,
//! and be said in one line with the panic's place, to be reported.
//!
//! The hook keeps caught panics off the terminal and records where each
//! happened: a frame's panic is often on a pool thread, and rayon hands its
//! payload (which holds only the message) to the thread waiting on that
//! work, where it is caught.

use std::cell::Cell;
use std::collections::VecDeque;
use std::fmt;
use std::panic::{self, AssertUnwindSafe};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Mutex, Once};

thread_local! {
    /// Inside `catch` on this thread: a panic here is caught and reported.
    static GUARDED: Cell<bool> = const { Cell::new(false) };
}

/// `catch` calls in progress, on any thread.
static CATCHING: AtomicUsize = AtomicUsize::new(0);

/// The latest panics kept quiet, with where they happened, until caught.
/// Bounded: rayon passes on one panic of a scope, so others are never
/// claimed.
static RECORDED: Mutex<VecDeque<Panic>> = Mutex::new(VecDeque::new());
const RECORDED_MAX: usize = 16;

/// A panic caught: its message and, when the hook saw it, its place.
#[derive(Debug, Clone)]
pub struct Panic {
    pub message: String,
    pub location: Option<String>,
}

impl fmt::Display for Panic {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.location {
            Some(location) => write!(f, "{} at {location}", self.message),
            None => f.write_str(&self.message),
        }
    }
}

/// Calls `f`; a panic inside it, on this thread or in pool tasks it waits
/// on, is returned as `Err`, with no message printed.
pub fn catch<T>(f: impl FnOnce() -> T) -> Result<T, Panic> {
    install_hook();
    let was = GUARDED.with(|g| g.replace(true));
    CATCHING.fetch_add(1, Ordering::SeqCst);
    let result = panic::catch_unwind(AssertUnwindSafe(f));
    CATCHING.fetch_sub(1, Ordering::SeqCst);
    GUARDED.with(|g| g.set(was));
    result.map_err(|payload| {
        let message = payload
            .downcast_ref::<&str>()
            .map(|s| s.to_string())
            .or_else(|| payload.downcast_ref::<String>().cloned())
            .unwrap_or_else(|| "unknown panic".to_string());
        claim(message)
    })
}

/// `catch`, giving the panic's message alone.
pub fn catch_panic<T>(f: impl FnOnce() -> T) -> Result<T, String> {
    catch(f).map_err(|p| p.message)
}

fn recorded() -> std::sync::MutexGuard<'static, VecDeque<Panic>> {
    RECORDED.lock().unwrap_or_else(|e| e.into_inner())
}

/// The latest panic recorded with `message` (panics caught at once on
/// several threads are told apart by their messages).
fn claim(message: String) -> Panic {
    let mut recorded = recorded();
    match recorded.iter().rposition(|p| p.message == message) {
        Some(i) => recorded.remove(i).expect("found"),
        None => Panic {
            message,
            location: None,
        },
    }
}

fn install_hook() {
    static ONCE: Once = Once::new();
    ONCE.call_once(|| {
        let default = panic::take_hook();
        panic::set_hook(Box::new(move |info| {
            // A pool task's panic goes to the thread waiting on it: caught
            // there while any catch is in progress (the whole run, under
            // the binary's `main`).
            let pooled = rayon::current_thread_index().is_some();
            let caught =
                GUARDED.with(|g| g.get()) || (pooled && CATCHING.load(Ordering::SeqCst) > 0);
            if !caught {
                return default(info);
            }
            let mut recorded = recorded();
            if recorded.len() == RECORDED_MAX {
                recorded.pop_front();
            }
            recorded.push_back(Panic {
                message: info.payload_as_str().unwrap_or("unknown panic").into(),
                location: info.location().map(|l| l.to_string()),
            });
        }));
    });
}

#[cfg(test)]
mod tests {
    use super::*;
    use rayon::prelude::*;

    #[test]
    fn a_panic_in_a_pool_task_is_caught_with_its_place() {
        let caught = catch(|| {
            (0..64).into_par_iter().for_each(|i| {
                if i == 37 {
                    panic!("task {i} failed");
                }
            })
        })
        .unwrap_err();
        assert_eq!(caught.message, "task 37 failed");
        let location = caught.location.expect("the hook saw it");
        assert!(location.starts_with("src/guard.rs:"), "{location}");
    }

    #[test]
    fn panics_caught_at_once_on_several_threads_keep_their_own_places() {
        (0..8).into_par_iter().for_each(|i| {
            let line = line!() + 1;
            let caught = catch(|| panic!("thread {i}")).unwrap_err();
            assert_eq!(caught.message, format!("thread {i}"));
            let location = caught.location.expect("the hook saw it");
            assert!(location.starts_with(&format!("src/guard.rs:{line}:")));
        });
    }
}
