//! OpenCue outlines, in the JSON form PyOutline loads.

use super::frames::SteppedRange;
use super::{json, shell_quote, Needs};
use crate::cli::FarmArgs;
use crate::error::Result;
use serde::Serialize;
use std::collections::BTreeMap;
use std::path::Path;

/// An outline as `outline.loader.load_json` reads it.
#[derive(Serialize)]
struct Outline {
    name: String,
    range: String,
    layers: [Layer; 1],
}

#[derive(Serialize)]
struct Layer {
    name: &'static str,
    module: &'static str,
    command: String,
    chunk: usize,
    service: String,
    cores: usize,
    memory: String,
    env: BTreeMap<String, String>,
}

/// An OpenCue outline in the JSON form PyOutline loads
/// (`outline.loader.load_json`): one Shell layer over the frame range,
/// chunked, on the layer's service with the task's threads as cores, its
/// memory bound as memory, and the colour config and `EXRCOMP_*` settings
/// as its environment. Each chunk runs `--frames ALL --chunk-from
/// #FRAME_START#,N` (a shell command, its arguments quoted): exrcomp cuts
/// the chunk from its first frame, as Cuebot before 1.0 sets #FRAME_END#
/// to the first frame + N - 1 whatever the step.
pub fn opencue_outline(
    exrcomp: &Path,
    command: &[String],
    (job, service): (&FarmArgs, &str),
    (name, needs): (&str, &Needs),
) -> Result<String> {
    let frames = SteppedRange::new(&job.frames, job.chunk, "OpenCue")?;
    let mut line: Vec<String> = std::iter::once(exrcomp.to_string_lossy().as_ref())
        .chain(command.iter().map(String::as_str))
        .map(shell_quote)
        .collect();
    line.extend([
        "--frames".to_string(),
        frames.chunk(&frames.range, ""),
        "--chunk-from".to_string(),
        format!("#FRAME_START#,{}", job.chunk),
    ]);
    let outline = Outline {
        // OpenCue's job names are one word.
        name: name
            .chars()
            .map(|c| if c.is_whitespace() { '-' } else { c })
            .collect(),
        range: frames.frames(),
        layers: [Layer {
            name: "exrcomp",
            module: "outline.modules.shell.Shell",
            command: line.join(" "),
            chunk: job.chunk,
            service: service.to_string(),
            cores: needs.threads,
            memory: format!("{}m", needs.memory_mib()),
            env: needs.settings(),
        }],
    };
    Ok(json(&outline))
}
