//! Deadline 10 job files for the CommandLine plugin: key=value lines, each
//! file a struct whose fields are Deadline's keys.

use super::frames::SteppedRange;
use super::{shell_quote, Needs};
use crate::cli::command_line::{Flow, TaskCommand};
use crate::cli::FarmArgs;
use crate::error::{Error, Result};
use serde::Serialize;
use std::path::Path;

/// The job-info file's keys.
#[derive(Serialize)]
#[serde(rename_all = "PascalCase")]
struct JobInfo {
    plugin: &'static str,
    name: String,
    comment: String,
    frames: String,
    chunk_size: usize,
    #[serde(rename = "OutputDirectory0", skip_serializing_if = "Option::is_none")]
    output_directory: Option<String>,
    #[serde(rename = "OutputFilename0", skip_serializing_if = "Option::is_none")]
    output_filename: Option<String>,
    /// `NAME=VALUE` each, as `EnvironmentKeyValue0`...
    environment_key_value: Vec<String>,
    /// `KEY=VALUE` each, as `ExtraInfoKeyValue0`...
    extra_info_key_value: Vec<String>,
}

/// The CommandLine plugin-info file's keys.
#[derive(Serialize)]
#[serde(rename_all = "PascalCase")]
struct PluginInfo {
    executable: String,
    arguments: String,
    shell: &'static str,
    shell_execute: bool,
}

/// `info` as Deadline's key=value lines: a list `Key` as `Key0`, `Key1`...,
/// a flag `True` or `False`. A value holds no line break (refused).
fn key_values(info: &impl Serialize) -> Result<String> {
    use serde_json::Value;
    let Ok(Value::Object(fields)) = serde_json::to_value(info) else {
        unreachable!("a Deadline file is a struct of plain values")
    };
    let mut lines = String::new();
    for (key, value) in fields {
        let values = match value {
            Value::Array(items) => (items.into_iter().enumerate())
                .map(|(i, item)| (format!("{key}{i}"), item))
                .collect(),
            value => vec![(key, value)],
        };
        for (key, value) in values {
            let value = match value {
                Value::String(text) => text,
                Value::Bool(true) => "True".into(),
                Value::Bool(false) => "False".into(),
                value => value.to_string(),
            };
            if value.contains(['\n', '\r']) {
                return Err(Error::usage(format!(
                    "{value:?} holds a line break, which a Deadline job file cannot carry"
                )));
            }
            lines += &format!("{key}={value}\n");
        }
    }
    Ok(lines)
}

/// A Deadline job: its job-info and plugin-info files.
pub struct DeadlineArgs {
    pub job_info: String,
    pub plugin_info: String,
}

/// Deadline 10 job files for the CommandLine plugin, which
/// `deadlinecommand JOBINFO PLUGININFO` submits: the frames (`A-B` or
/// `A-BxS`) in chunks of `ChunkSize`, each task running the command with
/// `--frames <STARTFRAME>-<ENDFRAME>`; the output's folder and file name (as
/// `####`) for the Monitor; the submitter's `EXRCOMP_*` settings as the job's
/// environment. Deadline has no keys for a task's cores and memory: they go
/// in the comment and as extra info (`exrcomp.threads`,
/// `exrcomp.memory_mib`) for the farm's groups and limits.
pub fn deadline_job(
    exrcomp: &Path,
    task: &TaskCommand,
    job: &FarmArgs,
    needs: &Needs,
    (name, description): (&str, String),
) -> Result<DeadlineArgs> {
    let frames = SteppedRange::new(&job.frames, job.chunk, "Deadline")?;
    // The CommandLine plugin reads a task's `Progress: N%` lines (its own
    // stdout handler) only from a command it runs in the worker's shell
    // (`ShellExecute`: its RunProcess path does not capture them), so
    // Arguments is the whole command line, each word quoted for that shell.
    let argument = |arg: &str| match arg.contains('"') {
        true => Err(Error::usage(format!(
            "{arg:?} holds a double quote, which Deadline's Arguments cannot carry"
        ))),
        false => Ok(shell_quote(arg)),
    };
    let mut arguments = std::iter::once(exrcomp.to_string_lossy().as_ref())
        .chain(task.args.iter().map(String::as_str))
        .map(argument)
        .collect::<Result<Vec<_>>>()?;
    arguments.extend([
        "--frames".to_string(),
        frames.chunk("<STARTFRAME>", "<ENDFRAME>"),
    ]);
    let output = match task.files.iter().find(|(_, flow)| *flow == Flow::Out) {
        Some(&(at, _)) => {
            let output = Path::new(&task.args[at]);
            let pattern = crate::io::sequence::FramePattern::parse(&task.args[at])?;
            let name = Path::new(&pattern.with_hashes())
                .file_name()
                .map(|n| n.to_string_lossy().into_owned())
                .unwrap_or_default();
            let folder = output.parent().unwrap_or(Path::new("/"));
            Some((folder.to_string_lossy().into_owned(), name))
        }
        None => None,
    };
    let (output_directory, output_filename) = output.unzip();
    let info = JobInfo {
        plugin: "CommandLine",
        name: name.to_string(),
        comment: description,
        frames: frames.frames(),
        chunk_size: job.chunk,
        output_directory,
        output_filename,
        environment_key_value: (needs.settings().iter())
            .map(|(name, setting)| format!("{name}={setting}"))
            .collect(),
        extra_info_key_value: vec![
            format!("exrcomp.threads={}", needs.threads),
            format!("exrcomp.memory_mib={}", needs.memory_mib()),
        ],
    };
    let plugin = PluginInfo {
        executable: exrcomp.to_string_lossy().into_owned(),
        arguments: arguments.join(" "),
        shell: "default",
        shell_execute: true,
    };
    Ok(DeadlineArgs {
        job_info: key_values(&info)?,
        plugin_info: key_values(&plugin)?,
    })
}
