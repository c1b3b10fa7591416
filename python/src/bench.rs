//! `exrcomp bench` from Python: the same record (`tools::bench::record`,
//! what `--json` writes), its runs started as the command starts them (the
//! wheel's `exrcomp` command, each run a process of its own).

use crate::failure;
use exrcomp::cli::BenchArgs;
use exrcomp::error::{Error, Result};
use pyo3::prelude::*;
use std::path::PathBuf;

/// `words` (bench's options and its command, as the command line gives
/// them) as `BenchArgs`.
fn bench_args(words: &[String]) -> Result<BenchArgs> {
    use clap::{Args, FromArgMatches};
    let command = BenchArgs::augment_args(clap::Command::new("bench").no_binary_name(true));
    let usage = |e: clap::Error| Error::usage(crate::run::first_line(&e.to_string()));
    let matches = command.try_get_matches_from(words).map_err(usage)?;
    BenchArgs::from_arg_matches(&matches).map_err(usage)
}

/// The record of the bench `words` ask for (JSON text), and the message of
/// its regression if a job was slower than the baseline or the other build.
/// `exe`: the `exrcomp` the runs start (once a process, as `main`'s).
#[pyfunction]
#[pyo3(signature = (words, exe, threads=None))]
pub fn bench(
    py: Python<'_>,
    words: Vec<String>,
    exe: PathBuf,
    threads: Option<usize>,
) -> PyResult<(String, Option<String>)> {
    let mut args = bench_args(&words).map_err(|e| failure(&e))?;
    args.threads = threads;
    exrcomp::run::set_own_exe(exe);
    let benched = py
        .detach(|| {
            exrcomp::guard::catch(|| exrcomp::tools::bench::record(&args))
                .unwrap_or_else(|p| Err(Error::panicked(None, p)))
        })
        .map_err(|e| failure(&e))?;
    let text = serde_json::to_string_pretty(&benched.record).expect("JSON");
    Ok((text, benched.verdict.err().map(|e| e.message)))
}
