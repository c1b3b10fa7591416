use clap::Parser;
use exrcomp::cli::Cli;

fn main() {
    keep_freed_memory();
    let cli = Cli::parse();
    exrcomp::engine::interrupt::install();
    if let Some(threads) = cli.threads {
        // Only fails if the pool exists already, which it cannot here.
        let _ = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build_global();
    }
    if let Err(e) = exrcomp::commands::run(cli.command) {
        eprintln!("exrcomp: error: {e}");
        std::process::exit(e.kind.exit_code());
    }
}

/// Strip buffers of a few MiB are allocated and freed for every strip. By
/// default glibc hands such blocks back to the kernel when they are freed
/// (above its mmap threshold, or by trimming the heap), and the next strip
/// faults them in again, zeroed: 10% of the CPU of a 4K `stack`. Keeping
/// them in the heap makes them reused; the peak, which is what memory is
/// bounded by, stays the same.
#[cfg(target_env = "gnu")]
fn keep_freed_memory() {
    // SAFETY: mallopt only sets allocator parameters, before any thread starts.
    unsafe {
        libc::mallopt(libc::M_MMAP_THRESHOLD, 32 << 20);
        libc::mallopt(libc::M_TRIM_THRESHOLD, 256 << 20);
    }
}

#[cfg(not(target_env = "gnu"))]
fn keep_freed_memory() {}
