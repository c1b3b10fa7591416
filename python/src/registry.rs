//! The declarations the package's API is made from, as JSON: each
//! operation (`exrcomp::ops::ALL`: name, help, inputs, parameters with
//! their help, defaults and choices), the read node's keys, the write
//! node's (`WriteArgs`, as the job file takes them), the run's settings
//! (`RunArgs`' options but the write node's) and bench's (`BenchArgs`).
//! Nothing here lists an operation or a setting: a new one in Rust is a
//! new one in Python.

use exrcomp::cli::BenchArgs;
use exrcomp::ops::declare::Operation;
use exrcomp::run::job_file::{LAYER_KEYS, READ_KEYS};
use exrcomp::run::settings::{RunArgs, WriteArgs};
use pyo3::prelude::*;
use serde_json::{json, Value};

/// Run options the package does not take as settings: `plan` is the dry
/// run, and the terminal's outputs are the command line's.
const NOT_SETTINGS: &[&str] = &["dry_run", "json", "progress"];

fn operation(op: &Operation) -> Value {
    let inputs: Vec<Value> = op
        .inputs
        .iter()
        .map(|i| json!({"name": i.name, "help": i.help}))
        .collect();
    let params: Vec<Value> = op
        .params
        .iter()
        .map(|p| {
            json!({"name": p.name, "help": p.help, "default": p.default,
                   "required": p.required(), "flag": p.flag, "choices": p.choices,
                   "file": p.file, "repeats": p.repeats, "pixels": p.pixels.is_some()})
        })
        .collect();
    json!({"name": op.name, "about": op.about, "inputs": inputs, "repeats": op.repeats,
           "params": params, "layers": op.layers, "straight": op.straight,
           "arity": op.arity()})
}

/// A clap option as a key: its name with `_`, help, whether it is a
/// switch or repeated, its choices.
fn options(command: clap::Command) -> Vec<Value> {
    command
        .get_arguments()
        .filter(|arg| !arg.is_hide_set())
        .filter_map(|arg| {
            let name = arg.get_long()?.replace('-', "_");
            let action = arg.get_action();
            let choices: Vec<String> = arg
                .get_possible_values()
                .iter()
                .map(|v| v.get_name().to_string())
                .collect();
            Some(json!({"name": name,
                        "help": arg.get_long_help().or(arg.get_help()).map(|h| h.to_string()),
                        "flag": matches!(action, clap::ArgAction::SetTrue),
                        "repeats": matches!(action, clap::ArgAction::Append),
                        "choices": choices}))
        })
        .collect()
}

/// Everything the package is made from, as JSON text.
#[pyfunction]
pub fn registry() -> String {
    use clap::Args;
    let write = options(WriteArgs::augment_args(clap::Command::new("write")));
    let write_names: Vec<&str> = write.iter().filter_map(|k| k["name"].as_str()).collect();
    let run: Vec<Value> = options(RunArgs::augment_args(clap::Command::new("run")))
        .into_iter()
        .filter(|k| {
            let name = k["name"].as_str().unwrap_or_default();
            !write_names.contains(&name) && !NOT_SETTINGS.contains(&name)
        })
        .collect();
    let ops: Vec<Value> = exrcomp::ops::ALL.iter().map(|op| operation(op)).collect();
    let bench = options(BenchArgs::augment_args(clap::Command::new("bench")));
    json!({"operations": ops, "read_keys": READ_KEYS, "layer_keys": LAYER_KEYS,
           "write_keys": write, "run_keys": run, "bench_keys": bench})
    .to_string()
}

/// Whether `value` (as text) is one operation `op`'s parameter `name`
/// takes: `None`, or why not (the parameter's own check, bounds included).
#[pyfunction]
pub fn check_param(op: &str, name: &str, value: &str) -> Option<String> {
    let param = exrcomp::ops::find(op)?.param(name)?;
    (param.check)(value).err()
}
