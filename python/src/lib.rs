//! The Python package's extension module, `exrcomp._native`: the registry
//! the package makes its API from (the operations' declarations, the read,
//! write and run settings), a job run from its text with progress and
//! KeyboardInterrupt (run.rs), bench's record (bench.rs), and the command line (`exrcomp` on PATH).
//! The Python side is python/exrcomp/__init__.py; the design:
//! specs/python.md.

mod bench;
mod registry;
mod run;

use exrcomp::error::{Error, Kind};
use pyo3::exceptions::PyException;
use pyo3::prelude::*;
use std::path::PathBuf;

pyo3::create_exception!(
    _native,
    Failure,
    PyException,
    "An exrcomp error: (kind, message, file, frame); the package raises its own classes from it."
);

/// `error` as a `Failure`, which python/exrcomp/__init__.py turns into the
/// class of its kind.
pub(crate) fn failure(error: &Error) -> PyErr {
    let kind = match error.kind {
        Kind::Usage => "usage",
        Kind::Input => "input",
        Kind::Output => "output",
        Kind::Interrupted => "interrupted",
        Kind::Regression => "regression",
        Kind::Internal | Kind::Stopped => "internal",
    };
    let file = error.file.as_ref().map(|f| f.display().to_string());
    Failure::new_err((
        kind,
        error.message.clone(),
        file,
        error.frame,
        error.kind.exit_code(),
    ))
}

/// What `exrcomp info --json FILE` prints for `path`, as JSON text.
#[pyfunction]
fn info(py: Python<'_>, path: PathBuf) -> PyResult<String> {
    py.detach(|| exrcomp::tools::info::describe_json(&path))
        .map(|value| value.to_string())
        .map_err(|e| failure(&e))
}

/// The command line `args` (its program name first) run as the `exrcomp`
/// command runs it; the exit code.
#[pyfunction]
#[pyo3(signature = (args, exe=None))]
fn main(py: Python<'_>, args: Vec<String>, exe: Option<std::path::PathBuf>) -> i32 {
    // bench and farm start exrcomp again: the script, not the interpreter.
    if let Some(exe) = exe {
        exrcomp::run::set_own_exe(exe);
    }
    py.detach(|| exrcomp::cli::program::main(args))
}

/// A job file's text as JSON text (the package reads job files with it:
/// Python 3.9 has no TOML reader).
#[pyfunction]
fn toml_to_json(text: &str) -> PyResult<String> {
    let value: toml::Value = toml::from_str(text)
        .map_err(|e| failure(&Error::usage(format!("not a job file: {}", e.message()))))?;
    Ok(serde_json::to_string(&value).expect("TOML values are JSON"))
}

#[pymodule]
fn _native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("Failure", m.py().get_type::<Failure>())?;
    m.add("VERSION", env!("CARGO_PKG_VERSION"))?;
    m.add_function(wrap_pyfunction!(info, m)?)?;
    m.add_function(wrap_pyfunction!(main, m)?)?;
    m.add_function(wrap_pyfunction!(toml_to_json, m)?)?;
    m.add_function(wrap_pyfunction!(registry::registry, m)?)?;
    m.add_function(wrap_pyfunction!(registry::check_param, m)?)?;
    m.add_function(wrap_pyfunction!(run::run_job, m)?)?;
    m.add_function(wrap_pyfunction!(bench::bench, m)?)?;
    Ok(())
}
