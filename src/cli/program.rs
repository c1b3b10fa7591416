//! The program: its command line parsed and run, its error said in one
//! line and turned into the exit code. The `exrcomp` binary (src/main.rs)
//! and the Python package's `exrcomp` command both run it.

use crate::cli::Command;
use crate::error::{Error, Kind, Result};
use crate::tools;

/// Runs the command line `args` (the program's name first); the exit code.
pub fn main<I: Into<std::ffi::OsString> + Clone>(args: impl IntoIterator<Item = I>) -> i32 {
    keep_freed_memory();
    let mut cli = crate::cli::parse(args);
    // The runs that bench times get the threads it was given.
    if let Command::Bench(bench) = &mut cli.command {
        bench.threads = cli.threads;
    }
    // A farm job's tasks get them too.
    if let Command::Farm { farm } = &mut cli.command {
        farm.job_mut().threads = cli.threads;
    }
    crate::engine::interrupt::install();
    if let Some(threads) = cli.threads {
        // Only fails if the pool exists already, which it cannot here.
        let _ = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build_global();
    }
    // A bug anywhere is one line to report and exit code 1, as a frame's is
    // (src/guard.rs), not Rust's report and 101.
    let result =
        crate::guard::catch(|| run(cli.command)).unwrap_or_else(|p| Err(Error::panicked(None, p)));
    match result {
        Ok(()) => 0,
        Err(e) => {
            eprintln!("exrcomp: error: {e}");
            // Interrupted: 130 after Ctrl-C, 143 after SIGTERM.
            match e.kind {
                Kind::Interrupted => crate::engine::interrupt::exit_code(),
                kind => kind.exit_code(),
            }
        }
    }
}

/// Runs `command`: a tool's (src/tools/), or a job's (src/cli/commands.rs).
fn run(command: Command) -> Result<()> {
    match command {
        Command::Info { files, json } => tools::info::print(&files, json),
        Command::Bench(args) => tools::bench::bench(&args),
        Command::Demo {
            dir,
            length,
            width,
            height,
            run,
        } => tools::demo::demo(&dir, length, width, height, &run),
        Command::Farm { farm } => {
            tools::farm::write_job(&farm, &tools::farm::logical_working_folder()?)
        }
        job => crate::cli::commands::execute(job).map(drop),
    }
}

/// Strip buffers of a few MiB are allocated and freed for every strip. By
/// default glibc hands such blocks back to the kernel when they are freed
/// (above its mmap threshold, or by trimming the heap), and the next strip
/// faults them in again, zeroed: 10% of the CPU of a 4K `stack`. Kept in the
/// heap, they are reused. One arena: with one per thread, each would keep
/// its own high-water mark, and the peak crept up with the frames as threads
/// met new arenas; the peak, which bounds memory, stays flat with one.
/// (Set before any thread of ours starts; a Python process has only its
/// main thread when its `exrcomp` command gets here.)
#[cfg(target_env = "gnu")]
pub fn keep_freed_memory() {
    // SAFETY: mallopt only sets allocator parameters.
    unsafe {
        libc::mallopt(libc::M_ARENA_MAX, 1);
        libc::mallopt(libc::M_MMAP_THRESHOLD, 32 << 20);
        libc::mallopt(libc::M_TRIM_THRESHOLD, 256 << 20);
    }
}

#[cfg(not(target_env = "gnu"))]
pub fn keep_freed_memory() {}
