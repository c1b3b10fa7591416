//! A job given as job-file text, run as `exrcomp run` runs a job file
//! (`exrcomp::run::job_run::run_file`): the engine on threads of its own,
//! the calling thread (the GIL released while it waits) calling `progress`
//! as frames end and checking for signals, so that KeyboardInterrupt stops
//! the run as Ctrl-C stops the command (the frames in flight abandoned,
//! their temporaries removed, complete frames kept).

use crate::failure;
use crossbeam_channel::RecvTimeoutError;
use exrcomp::error::{Error, Kind, Result};
use exrcomp::run::report::Outcome;
use exrcomp::run::settings::RunArgs;
use exrcomp::run::DryRun;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::path::Path;
use std::sync::{Arc, OnceLock};
use std::time::Duration;

/// How often the waiting thread looks for a signal.
const POLL: Duration = Duration::from_millis(50);

/// The worker threads of this process's runs: rayon's pool is made once.
static THREADS: OnceLock<usize> = OnceLock::new();

/// `settings` (run options as the command line gives them) as `RunArgs`.
fn run_args(settings: &[String]) -> Result<RunArgs> {
    use clap::{Args, FromArgMatches};
    let command = RunArgs::augment_args(clap::Command::new("run").no_binary_name(true));
    let matches = command
        .try_get_matches_from(settings)
        .map_err(|e| Error::usage(first_line(&e.to_string())))?;
    RunArgs::from_arg_matches(&matches).map_err(|e| Error::usage(first_line(&e.to_string())))
}

/// clap's message without its "error: " and usage lines.
pub(crate) fn first_line(text: &str) -> String {
    let line = text.lines().next().unwrap_or_default();
    line.strip_prefix("error: ").unwrap_or(line).to_string()
}

/// The pool's threads, made once a process by its first run (`threads`, or
/// rayon's default): a later run asking for another count is refused, not
/// run on the old count (rayon's global pool cannot be remade).
fn set_threads(threads: Option<usize>) -> Result<()> {
    if let Some(wanted) = threads {
        exrcomp::params::parse_threads(&wanted.to_string())
            .map_err(|why| Error::usage(format!("threads: {why}")))?;
    }
    let made = *THREADS.get_or_init(|| {
        let Some(wanted) = threads else {
            return rayon::current_num_threads();
        };
        let built = rayon::ThreadPoolBuilder::new()
            .num_threads(wanted)
            .build_global();
        match built {
            Ok(()) => wanted,
            Err(_) => rayon::current_num_threads(),
        }
    });
    match threads {
        Some(wanted) if wanted != made => Err(Error::usage(format!(
            "threads: this process runs its jobs on {made} threads (set by its first run, \
             once a process), not {wanted}"
        ))),
        _ => Ok(()),
    }
}

/// One frame ended: its number, what became of it, frames ended, of.
type Ended = (i64, Outcome, usize, usize);

/// Runs the job `text` (named `label` in messages, relative file names from
/// the working folder) with `settings`; a dry run gives its plan.
#[pyfunction]
#[pyo3(signature = (text, label, settings, threads=None, progress=None))]
pub fn run_job(
    py: Python<'_>,
    text: String,
    label: String,
    settings: Vec<String>,
    threads: Option<usize>,
    progress: Option<Py<PyAny>>,
) -> PyResult<Py<PyAny>> {
    // glibc's malloc set as the command sets it (one arena, freed strips
    // kept): without it a Python run of `over` took 9.7% more wall time.
    static ALLOCATOR: std::sync::Once = std::sync::Once::new();
    ALLOCATOR.call_once(exrcomp::cli::program::keep_freed_memory);
    let mut run = run_args(&settings).map_err(|e| failure(&e))?;
    set_threads(threads).map_err(|e| failure(&e))?;
    let (send, ended) = crossbeam_channel::unbounded::<Ended>();
    run.on_frame = Some(Arc::new(move |frame, outcome, done, total| {
        let _ = send.send((frame, outcome, done, total));
    }));
    exrcomp::engine::interrupt::reset();
    let engine = std::thread::spawn(move || {
        exrcomp::guard::catch(|| {
            exrcomp::run::job_run::run_file(Path::new(&label), Some(&text), None, run)
        })
        .unwrap_or_else(|p| Err(Error::panicked(None, p)))
    });
    let outcomes = PyDict::new(py);
    let mut raised: Option<PyErr> = None;
    loop {
        let next = py.detach(|| ended.recv_timeout(POLL));
        match next {
            Ok((frame, outcome, done, total)) => {
                match outcomes.get_item(word(outcome))? {
                    Some(list) => drop(list.call_method1("append", (frame,))?),
                    None => outcomes.set_item(word(outcome), vec![frame])?,
                }
                if let (Some(callback), None) = (&progress, &raised) {
                    if let Err(e) = callback.call1(py, (frame, done, total)) {
                        stop(&mut raised, e);
                    }
                }
            }
            Err(RecvTimeoutError::Timeout) => {}
            // The hook is dropped with the run: every frame's told.
            Err(RecvTimeoutError::Disconnected) => break,
        }
        if let Err(e) = py.check_signals() {
            stop(&mut raised, e);
        }
    }
    let result = py
        .detach(|| engine.join())
        .unwrap_or_else(|_| Err(Error::internal("the run's thread panicked")));
    finish(py, result, raised, outcomes)
}

/// A Python exception met while the run goes on (KeyboardInterrupt, or the
/// progress callback's): the run is stopped as Ctrl-C stops it.
fn stop(raised: &mut Option<PyErr>, e: PyErr) {
    exrcomp::engine::interrupt::request();
    raised.get_or_insert(e);
}

fn word(outcome: Outcome) -> &'static str {
    match outcome {
        Outcome::Written => "written",
        Outcome::Kept => "kept",
        Outcome::Redone => "redone",
        Outcome::Failed => "failed",
    }
}

/// The run's result: a dry run's plan, else the frames by outcome; the
/// run's error as its class, an interrupted run's as `Interrupted` (the
/// progress callback's own exception when it raised).
fn finish(
    py: Python<'_>,
    result: Result<Option<DryRun>>,
    raised: Option<PyErr>,
    outcomes: Bound<'_, PyDict>,
) -> PyResult<Py<PyAny>> {
    match (result, raised) {
        (Err(e), Some(raised)) if e.kind == Kind::Interrupted => {
            match raised.is_instance_of::<pyo3::exceptions::PyKeyboardInterrupt>(py) {
                true => Err(failure(&e)),
                false => Err(raised),
            }
        }
        (_, Some(raised)) => Err(raised),
        (Err(e), None) => Err(failure(&e)),
        (Ok(Some(plan)), None) => {
            let dict = PyDict::new(py);
            dict.set_item("memory", plan.memory)?;
            let texts = |paths: Vec<std::path::PathBuf>| -> Vec<String> {
                paths.iter().map(|p| p.display().to_string()).collect()
            };
            dict.set_item("reads", texts(plan.reads))?;
            dict.set_item("writes", texts(plan.writes))?;
            dict.set_item("others", texts(plan.others))?;
            Ok(dict.into_any().unbind())
        }
        (Ok(None), None) => Ok(outcomes.into_any().unbind()),
    }
}
