//! The timing tests: `exrcomp bench`'s verdicts on an idle machine and under
//! a load each test starts. A test binary of their own, which cargo runs
//! after (never beside) the suite's, so that no other test shares the
//! machine with them; and one at a time (`alone`), since each starts its
//! own load (specs/bench.md).

#[path = "../suite/common/mod.rs"]
mod common;

mod against;
mod load;

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Mutex, MutexGuard};

/// Held by each timing test for its whole run.
pub fn alone() -> MutexGuard<'static, ()> {
    static LOCK: Mutex<()> = Mutex::new(());
    LOCK.lock().unwrap_or_else(|e| e.into_inner())
}

/// `f` while every core is busy: as many threads as cores spinning in this
/// process, stopped when `f` returns (or panics).
pub fn under_load<T>(f: impl FnOnce() -> T) -> T {
    let stop = AtomicBool::new(false);
    let cores = std::thread::available_parallelism().map_or(2, |n| n.get());
    std::thread::scope(|scope| {
        for _ in 0..cores {
            scope.spawn(|| {
                let mut x = 0u64;
                while !stop.load(Ordering::Relaxed) {
                    x = std::hint::black_box(x.wrapping_mul(31).wrapping_add(7));
                }
            });
        }
        struct Stop<'a>(&'a AtomicBool);
        impl Drop for Stop<'_> {
            fn drop(&mut self) {
                self.0.store(true, Ordering::Relaxed);
            }
        }
        let _stop = Stop(&stop);
        f()
    })
}

/// `exrcomp bench ARGS -- blur ...` in `d`, with `EXRCOMP_TEST_WORK=work`
/// (a planted slowdown, debug builds only) when given.
pub fn bench_blur(d: &std::path::Path, args: &[&str], work: Option<&str>) -> std::process::Output {
    let blur = [
        "--",
        "blur",
        "bg.####.exr",
        "--radius",
        "4",
        "-o",
        "b.####.exr",
    ];
    let mut command = common::exrcomp();
    command.arg("bench").args(args).args(blur).current_dir(d);
    command.env_remove("EXRCOMP_TEST_WORK");
    if let Some(work) = work {
        command.env("EXRCOMP_TEST_WORK", work);
    }
    command.output().unwrap()
}

/// `bg.####.exr`, frames 1-4, in `d`.
pub fn plates(d: &std::path::Path, size: (usize, usize)) {
    common::generate(&d.join("bg.####.exr"), "bg", size, &["--frames", "1-4"]);
}
