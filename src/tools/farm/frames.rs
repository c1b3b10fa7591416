//! A job's frames cut into the farms' chunks: OpenJD's listed range
//! expressions, and the one stepped range OpenCue and Deadline cut
//! themselves.

use crate::error::{Error, Result};
use crate::io::sequence::parse_frame_list;

/// The frame lists of the tasks: `chunk` frames of `frames` each, in order,
/// each as a range expression (`1001-1019:2`, never a long comma list).
pub fn chunks(frames: &str, chunk: usize) -> Result<Vec<String>> {
    if chunk == 0 {
        return Err(Error::usage("--chunk must be at least 1"));
    }
    let frames = parse_frame_list(frames)?;
    Ok(frames.chunks(chunk).map(range_expression).collect())
}

/// Frames as runs of one step: `1-5,7,9-21:3`, as exrcomp's `--frames`,
/// OpenJD's range expressions and OpenCue's ranges (with `x`) read them.
pub fn range_expression(frames: &[i64]) -> String {
    let mut runs = Vec::new();
    let mut i = 0;
    while i < frames.len() {
        let step = frames.get(i + 1).map_or(1, |next| next - frames[i]);
        let mut j = i;
        while step > 0 && frames.get(j + 1) == Some(&(frames[j] + step)) {
            j += 1;
        }
        runs.push(match (j - i, step) {
            (0, _) => frames[i].to_string(),
            (_, 1) => format!("{}-{}", frames[i], frames[j]),
            (_, step) => format!("{}-{}:{step}", frames[i], frames[j]),
        });
        i = j + 1;
    }
    runs.join(",")
}

/// Frames as one range and its step: OpenCue and Deadline cut a job's
/// frames into chunks of `chunk` themselves, giving a task its first and
/// last frame, which name the chunk only when the frames are one stepped
/// range.
pub struct SteppedRange {
    pub range: String,
    step: Option<String>,
}

impl SteppedRange {
    pub fn new(frames: &str, chunk: usize, farm: &str) -> Result<Self> {
        if chunk == 0 {
            return Err(Error::usage("--chunk must be at least 1"));
        }
        let range = range_expression(&parse_frame_list(frames)?);
        if range.contains(',') || !range[1..].contains('-') {
            return Err(Error::usage(format!(
                "{farm} takes one frame range, A-B or A-B:STEP (or A-BxSTEP), not {frames}"
            )));
        }
        Ok(match range.split_once(':') {
            Some((range, step)) => SteppedRange {
                range: range.to_string(),
                step: Some(step.to_string()),
            },
            None => SteppedRange { range, step: None },
        })
    }

    /// The frames in the farms' syntax, `A-B` or `A-BxS`.
    pub fn frames(&self) -> String {
        match &self.step {
            Some(step) => format!("{}x{step}", self.range),
            None => self.range.clone(),
        }
    }

    /// A chunk's `--frames` from the farm's tokens for its first and last
    /// frame; with no last frame, `start` is all the frames.
    pub fn chunk(&self, start: &str, end: &str) -> String {
        let range = match end {
            "" => start.to_string(),
            end => format!("{start}-{end}"),
        };
        match &self.step {
            Some(step) => format!("{range}:{step}"),
            None => range,
        }
    }
}
