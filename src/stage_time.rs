//! Where a run's CPU time goes, stage by stage (decode, compose, encode,
//! write): each stage thread's own CPU (serial: work outside the pool), the
//! pool CPU spent on that stage's tasks (a decoded chunk, a composed band,
//! an encoded block), and how long the stage thread waited on its channels
//! (wall time blocked receiving or sending). From those, the serial share
//! of the run's CPU, which bounds the speed-up more threads can give.
//!
//! The counters are process-wide atomics that only grow; a run's figures
//! are the difference across it (`StageTimes::now`, `since`), so runs in
//! one process are measured one after another, as the commands run them.
//! A task costs two `clock_gettime(CLOCK_THREAD_CPUTIME_ID)` calls (well
//! under a microsecond against tasks of about a millisecond).

use std::sync::atomic::{AtomicU64, Ordering::Relaxed};
use std::time::{Duration, Instant};

/// A pipeline stage (`pipeline.rs`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Stage {
    Decode,
    Compose,
    Encode,
    Write,
}

impl Stage {
    pub const ALL: [Stage; 4] = [Stage::Decode, Stage::Compose, Stage::Encode, Stage::Write];

    pub fn name(self) -> &'static str {
        match self {
            Stage::Decode => "decode",
            Stage::Compose => "compose",
            Stage::Encode => "encode",
            Stage::Write => "write",
        }
    }
}

/// Nanoseconds per stage.
struct Counters {
    serial: AtomicU64,
    pool: AtomicU64,
    wait: AtomicU64,
    tasks: AtomicU64,
}

#[allow(clippy::declare_interior_mutable_const)]
const ZERO: Counters = Counters {
    serial: AtomicU64::new(0),
    pool: AtomicU64::new(0),
    wait: AtomicU64::new(0),
    tasks: AtomicU64::new(0),
};
static COUNTERS: [Counters; 4] = [ZERO; 4];

fn counters(stage: Stage) -> &'static Counters {
    &COUNTERS[stage as usize]
}

fn nanos(d: Duration) -> u64 {
    d.as_nanos().min(u64::MAX as u128) as u64
}

/// CPU time of the calling thread so far.
pub fn thread_cpu() -> Duration {
    let mut t = libc::timespec {
        tv_sec: 0,
        tv_nsec: 0,
    };
    // SAFETY: clock_gettime writes the timespec it is given.
    let ok = unsafe { libc::clock_gettime(libc::CLOCK_THREAD_CPUTIME_ID, &mut t) } == 0;
    match ok {
        true => Duration::new(t.tv_sec as u64, t.tv_nsec as u32),
        false => Duration::ZERO,
    }
}

/// CPU time (user and system) of the whole process so far.
pub fn process_cpu() -> Duration {
    // SAFETY: getrusage fills the struct it is given; zeroed is a valid one.
    let mut usage: libc::rusage = unsafe { std::mem::zeroed() };
    if unsafe { libc::getrusage(libc::RUSAGE_SELF, &mut usage) } != 0 {
        return Duration::ZERO;
    }
    let time = |t: libc::timeval| Duration::new(t.tv_sec as u64, t.tv_usec as u32 * 1000);
    time(usage.ru_utime) + time(usage.ru_stime)
}

/// Runs `task`, one of `stage`'s tasks on the pool, counting its CPU time.
pub fn task<T>(stage: Stage, task: impl FnOnce() -> T) -> T {
    let start = thread_cpu();
    let result = task();
    let c = counters(stage);
    c.pool.fetch_add(nanos(thread_cpu() - start), Relaxed);
    c.tasks.fetch_add(1, Relaxed);
    result
}

/// `each` as a function counted as one of `stage`'s tasks per call (for a
/// parallel iterator's `map` or `for_each`).
pub fn tasks<A, T>(stage: Stage, each: impl Fn(A) -> T + Sync) -> impl Fn(A) -> T + Sync {
    move |a| task(stage, || each(a))
}

/// Runs `body` as `stage`'s thread, counting the thread's CPU time (what
/// the pool tasks it waits on spend is theirs, not its).
pub fn stage_thread<T>(stage: Stage, body: impl FnOnce() -> T) -> T {
    let start = thread_cpu();
    let result = body();
    counters(stage)
        .serial
        .fetch_add(nanos(thread_cpu() - start), Relaxed);
    result
}

/// Runs `blocking` (a channel's receive or send) on `stage`'s thread,
/// counting the wall time it takes.
pub fn wait<T>(stage: Stage, blocking: impl FnOnce() -> T) -> T {
    let start = Instant::now();
    let result = blocking();
    counters(stage)
        .wait
        .fetch_add(nanos(start.elapsed()), Relaxed);
    result
}

/// One stage's figures.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct StageTime {
    /// CPU time of the stage's own thread.
    pub serial_cpu: Duration,
    /// CPU time of its tasks on the pool.
    pub pool_cpu: Duration,
    /// Wall time its thread spent blocked on its channels.
    pub wait: Duration,
    /// Tasks it ran on the pool.
    pub tasks: u64,
}

/// Every stage's figures, in `Stage::ALL` order.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct StageTimes(pub [StageTime; 4]);

impl StageTimes {
    /// The counters so far.
    pub fn now() -> Self {
        let load = |a: &AtomicU64| Duration::from_nanos(a.load(Relaxed));
        StageTimes(Stage::ALL.map(|s| {
            let c = counters(s);
            StageTime {
                serial_cpu: load(&c.serial),
                pool_cpu: load(&c.pool),
                wait: load(&c.wait),
                tasks: c.tasks.load(Relaxed),
            }
        }))
    }

    /// What was counted between `earlier` and `self`.
    pub fn since(&self, earlier: &StageTimes) -> Self {
        let mut out = *self;
        for (o, e) in out.0.iter_mut().zip(&earlier.0) {
            o.serial_cpu = o.serial_cpu.saturating_sub(e.serial_cpu);
            o.pool_cpu = o.pool_cpu.saturating_sub(e.pool_cpu);
            o.wait = o.wait.saturating_sub(e.wait);
            o.tasks -= e.tasks;
        }
        out
    }

    pub fn serial_cpu(&self) -> Duration {
        self.0.iter().map(|s| s.serial_cpu).sum()
    }

    pub fn pool_cpu(&self) -> Duration {
        self.0.iter().map(|s| s.pool_cpu).sum()
    }

    /// The share of the stages' CPU spent outside the pool (0 without any).
    pub fn serial_share(&self) -> f64 {
        let total = (self.serial_cpu() + self.pool_cpu()).as_secs_f64();
        match total > 0.0 {
            true => self.serial_cpu().as_secs_f64() / total,
            false => 0.0,
        }
    }

    /// `{"decode": {"serial_cpu_s": …, "pool_cpu_s": …, "wait_s": …,
    /// "tasks": …}, …}`.
    pub fn to_json(&self) -> serde_json::Value {
        let stages = Stage::ALL.iter().zip(&self.0).map(|(stage, t)| {
            let figures = serde_json::json!({
                "serial_cpu_s": t.serial_cpu.as_secs_f64(),
                "pool_cpu_s": t.pool_cpu.as_secs_f64(),
                "wait_s": t.wait.as_secs_f64(),
                "tasks": t.tasks,
            });
            (stage.name().to_string(), figures)
        });
        serde_json::Value::Object(stages.collect())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tasks_and_threads_are_counted_to_their_stage() {
        let before = StageTimes::now();
        let spin = || {
            let start = thread_cpu();
            while thread_cpu() - start < Duration::from_millis(5) {}
        };
        stage_thread(Stage::Encode, spin);
        task(Stage::Encode, spin);
        let got = StageTimes::now().since(&before).0[Stage::Encode as usize];
        // Other tests may run encode stages meanwhile: at least ours is there.
        assert!(got.pool_cpu >= Duration::from_millis(5), "{got:?}");
        assert!(got.serial_cpu >= Duration::from_millis(5), "{got:?}");
        assert!(got.tasks >= 1);
    }

    #[test]
    fn serial_share_is_the_stage_threads_part() {
        let mut times = StageTimes::default();
        times.0[0].serial_cpu = Duration::from_millis(10);
        times.0[1].pool_cpu = Duration::from_millis(30);
        times.0[2].serial_cpu = Duration::from_millis(10);
        times.0[2].pool_cpu = Duration::from_millis(50);
        assert!((times.serial_share() - 0.2).abs() < 1e-12);
        assert_eq!(StageTimes::default().serial_share(), 0.0);
        let json = times.to_json();
        assert_eq!(json["encode"]["pool_cpu_s"], 0.05);
        assert_eq!(json["write"]["tasks"], 0);
    }
}
