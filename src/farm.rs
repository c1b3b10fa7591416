//! Farm jobs: a local command split into frame chunks, each task running
//! exrcomp with `--frames CHUNK --resume`, so a retried task redoes only the
//! frames it has not finished. Open Job Description templates and OpenCue
//! outlines.

use crate::error::{Error, Result};
use crate::io::sequence::{format_frame_list, parse_frame_list};
use std::path::{Path, PathBuf};

/// The frame lists of the tasks: `chunk` frames of `frames` each, in order.
pub fn chunks(frames: &str, chunk: usize) -> Result<Vec<String>> {
    if chunk == 0 {
        return Err(Error::usage("--chunk must be at least 1"));
    }
    let frames = parse_frame_list(frames)?;
    Ok(frames.chunks(chunk).map(format_frame_list).collect())
}

/// `command` with relative file names made absolute (against `cwd`): a task
/// runs in a session folder of the farm's, not where the template was made.
pub fn absolute_args(command: &[String], cwd: &Path) -> Result<Vec<String>> {
    if command
        .iter()
        .any(|a| a == "--frames" || a.starts_with("--frames="))
    {
        return Err(Error::usage(
            "give --frames to `exrcomp farm`, not to the command: each task gets its chunk",
        ));
    }
    Ok(command
        .iter()
        .map(|arg| {
            let file = arg.to_ascii_lowercase();
            let names_file = [".exr", ".toml"]
                .iter()
                .any(|e| file.ends_with(e) || file.contains(&format!("{e}:")));
            if names_file && Path::new(arg).is_relative() {
                cwd.join(arg).to_string_lossy().into_owned()
            } else {
                arg.clone()
            }
        })
        .collect())
}

/// JSON quoting is valid YAML quoting: every string goes out quoted.
fn quote(text: &str) -> String {
    serde_json::Value::String(text.to_string()).to_string()
}

/// An Open Job Description job template (specification 2023-09): one step
/// whose tasks are the frame chunks.
pub fn openjd_template(exrcomp: &Path, command: &[String], chunks: &[String]) -> String {
    let name = format!("exrcomp {}", command.first().map_or("", String::as_str));
    let list = |items: &[String]| {
        items
            .iter()
            .map(|s| quote(s))
            .collect::<Vec<_>>()
            .join(", ")
    };
    let mut args: Vec<String> = command.to_vec();
    args.extend(["--frames", "{{Task.Param.Frames}}", "--resume", "--quiet"].map(String::from));
    format!(
        "specificationVersion: jobtemplate-2023-09\n\
         name: {name}\n\
         steps:\n\
         - name: exrcomp\n\
         \x20 parameterSpace:\n\
         \x20   taskParameterDefinitions:\n\
         \x20   - name: Frames\n\
         \x20     type: STRING\n\
         \x20     range: [{chunks}]\n\
         \x20 script:\n\
         \x20   actions:\n\
         \x20     onRun:\n\
         \x20       command: {command}\n\
         \x20       args: [{args}]\n",
        name = quote(&name),
        chunks = list(chunks),
        command = quote(&exrcomp.to_string_lossy()),
        args = list(&args),
    )
}

/// Writes `text` to `path` under a temporary name, renamed when complete.
pub fn write_template(path: &Path, text: &str) -> Result<()> {
    let temporary = crate::io::writer::temporary_path(path);
    std::fs::write(&temporary, text)
        .and_then(|()| std::fs::rename(&temporary, path))
        .map_err(|e| {
            let _ = std::fs::remove_file(&temporary);
            Error::output(path, None, format!("cannot write the template: {e}"))
        })
}

/// An OpenCue outline in the JSON form PyOutline loads
/// (`outline.loader.load_json`): one Shell layer over the frame range,
/// chunked, each frame chunk running `--frames #FRAME_START#-#FRAME_END#`.
/// OpenCue ranges are `A-B` or `A-BxS`: other frame lists are refused.
pub fn opencue_outline(
    exrcomp: &Path,
    command: &[String],
    frames: &str,
    chunk: usize,
) -> Result<String> {
    if chunk == 0 {
        return Err(Error::usage("--chunk must be at least 1"));
    }
    let (range, step) = match frames.split_once(':') {
        Some((range, step)) => (range, Some(step)),
        None => (frames, None),
    };
    let contiguous = range
        .split_once('-')
        .is_some_and(|(a, b)| a.parse::<i64>().is_ok() && b.parse::<i64>().is_ok());
    if !contiguous || range.contains(',') {
        return Err(Error::usage("OpenCue takes frame ranges A-B or A-B:STEP"));
    }
    let (cue_range, chunk_frames) = match step {
        Some(step) => (
            format!("{range}x{step}"),
            format!("#FRAME_START#-#FRAME_END#:{step}"),
        ),
        None => (range.to_string(), "#FRAME_START#-#FRAME_END#".to_string()),
    };
    let mut args = vec![exrcomp.to_string_lossy().into_owned()];
    args.extend(command.iter().cloned());
    args.extend([
        "--frames".to_string(),
        chunk_frames,
        "--resume".into(),
        "--quiet".into(),
    ]);
    let name = format!("exrcomp-{}", command.first().map_or("job", String::as_str));
    let outline = serde_json::json!({
        "name": name,
        "range": cue_range,
        "layers": [{
            "name": "exrcomp",
            "module": "outline.modules.shell.Shell",
            "command": args,
            "chunk": chunk,
        }],
    });
    Ok(serde_json::to_string_pretty(&outline).expect("JSON values serialise") + "\n")
}

/// This executable, for the template's command.
pub fn this_exrcomp() -> Result<PathBuf> {
    std::env::current_exe()
        .map_err(|e| Error::internal(format!("cannot find exrcomp's own path: {e}")))
}
