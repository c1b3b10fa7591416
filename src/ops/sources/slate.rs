//! `--slate`: a frame before the shot's first, black, with the job's
//! metadata in white in the built-in font (the burn-in's drawing), as a
//! source node (specs/file-format.md, "Slate").

use crate::engine::graph::Op;
use crate::engine::plan::SlateFrame;
use crate::io::burn_in::{self, attribute_text, Label};
use crate::io::rows::{Rows, RowsMut};
use crate::io::sequence::FramePattern;
use exr::meta::attribute::{ChannelDescription, IntegerBounds, SampleType};
use exr::meta::header::Header;
use std::path::Path;

/// Attributes a dailies slate shows when the output has them, besides the
/// ones the user sets.
const SHOWN: &[&str] = &["shot", "owner", "comments"];

/// The slate's lines for a job writing `output` from `inputs`, whose first
/// frame's output header is `header` and which sets attributes `set`:
/// output, frames, inputs, timecode and fps, then attributes.
pub fn lines(
    output: &FramePattern,
    inputs: &[FramePattern],
    set: &[&str],
    slate: &SlateFrame,
    header: &Header,
) -> Vec<String> {
    let name = |pattern: String| {
        Path::new(&pattern)
            .file_name()
            .map_or(pattern.clone(), |n| n.to_string_lossy().into_owned())
    };
    let mut lines = vec![
        format!("OUTPUT: {}", name(output.display())),
        format!("FRAMES: {}", slate.range),
    ];
    lines.extend(
        inputs
            .iter()
            .map(|input| format!("INPUT: {}", name(input.display()))),
    );
    if let Some(timecode) = burn_in::timecode(header) {
        lines.push(format!("TIMECODE: {timecode}"));
    }
    let mut names: Vec<&str> = vec!["framesPerSecond"];
    names.extend(SHOWN);
    names.extend(set);
    let mut shown: Vec<&str> = vec!["timeCode"];
    for wanted in names {
        if shown.iter().any(|s| s.eq_ignore_ascii_case(wanted)) {
            continue;
        }
        shown.push(wanted);
        if let Some(value) = burn_in::attribute(header, wanted) {
            let key = match wanted {
                "framesPerSecond" => "FPS",
                other => other,
            };
            lines.push(format!(
                "{}: {}",
                key.to_ascii_uppercase(),
                attribute_text(&value)
            ));
        }
    }
    lines
}

/// The slate's pixels: RGBA, black and opaque, the text's lit pixels white.
#[derive(Debug)]
pub struct Slate {
    pub window: IntegerBounds,
    pub labels: Vec<Label>,
}

impl Slate {
    /// A slate of `lines` over `window` (the output's display window).
    pub fn new(window: IntegerBounds, lines: &[String]) -> Slate {
        Slate {
            window,
            labels: burn_in::lines(lines, window.size.height()),
        }
    }
}

impl Op for Slate {
    fn channels(&self, _: &[&[ChannelDescription]]) -> Vec<ChannelDescription> {
        ["A", "B", "G", "R"]
            .into_iter()
            .map(|n| ChannelDescription::named(n, SampleType::F16))
            .collect()
    }

    fn data_window(&self, _: &[IntegerBounds]) -> IntegerBounds {
        self.window
    }

    fn compute(&self, _: i64, _: &[&Rows], out: &mut RowsMut) -> Result<(), String> {
        let origin = self.window.position;
        let alpha = out.channel_index("A");
        let opaque = vec![1.0f32; out.width];
        let mut lit = vec![0.0f32; out.width];
        for y in out.y..out.end() {
            for (i, v) in lit.iter_mut().enumerate() {
                let x = (out.x + i as i32 - origin.x()) as usize;
                let row = (y - origin.y()) as usize;
                let on = self.labels.iter().any(|l| l.pixel(x, row) == Some(true));
                *v = if on { 1.0 } else { 0.0 };
            }
            let range = out.row_range(y);
            for c in 0..out.channels.len() {
                let values = if Some(c) == alpha { &opaque } else { &lit };
                out.planes[c].write_f32(range.clone(), values);
            }
        }
        Ok(())
    }
}
