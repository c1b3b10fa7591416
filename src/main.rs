use clap::Parser;
use exrcomp::cli::Cli;

fn main() {
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
