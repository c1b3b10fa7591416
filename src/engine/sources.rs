//! Which file each input reads for each output frame, given the frames on
//! disk and the policy for missing ones (`--missing`).

use super::plan::{FrameSources, Source};
use crate::error::{Error, Kind, Result};
use crate::io::sequence::{format_frame_list, FramePattern};

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MissingPolicy {
    /// Stop before any work, listing the missing frames.
    Error,
    /// Leave out the output frames that miss an input.
    Skip,
    /// Use the nearest earlier frame of that input (the nearest later one
    /// before the first).
    Hold,
    /// Use transparent black, shaped like the nearest frame of that input.
    Black,
}

/// The frames to run, and what the policy did (for the summary).
pub struct Resolved {
    pub frames: Vec<FrameSources>,
    /// Output frames left out (skip).
    pub skipped: Vec<i64>,
    /// Human-readable lines: which input frames were held or made black.
    pub replaced: Vec<String>,
}

pub fn resolve(inputs: &[FramePattern], frames: &[i64], policy: MissingPolicy) -> Result<Resolved> {
    let mut resolved = Resolved {
        frames: frames
            .iter()
            .map(|&frame| FrameSources {
                frame,
                inputs: Vec::new(),
            })
            .collect(),
        skipped: Vec::new(),
        replaced: Vec::new(),
    };
    for input in inputs {
        let missing: Vec<i64> = frames
            .iter()
            .copied()
            .filter(|&f| !input.path(f).exists())
            .collect();
        if missing.is_empty() {
            resolved
                .frames
                .iter_mut()
                .for_each(|f| f.inputs.push(Source::Frame(f.frame)));
            continue;
        }
        let on_disk = if input.is_sequence() {
            input.frames_on_disk()?
        } else {
            Vec::new()
        };
        if policy == MissingPolicy::Error || on_disk.is_empty() {
            let what = if !input.is_sequence() {
                "no such file".to_string()
            } else if on_disk.is_empty() {
                "no frames on disk".to_string()
            } else {
                format!("missing frames {}", format_frame_list(&missing))
            };
            return Err(Error::new(
                Kind::Input,
                format!("{}: {what}", input.display()),
            ));
        }
        for f in resolved.frames.iter_mut() {
            let source = if !missing.contains(&f.frame) {
                Source::Frame(f.frame)
            } else {
                let near = nearest(&on_disk, f.frame);
                match policy {
                    MissingPolicy::Black => Source::Black(near),
                    _ => Source::Frame(near),
                }
            };
            f.inputs.push(source);
        }
        match policy {
            MissingPolicy::Skip => resolved.skipped.extend(&missing),
            MissingPolicy::Hold => resolved.replaced.push(format!(
                "{}: frames {} held from the nearest earlier frame",
                input.display(),
                format_frame_list(&missing)
            )),
            MissingPolicy::Black => resolved.replaced.push(format!(
                "{}: frames {} are transparent black",
                input.display(),
                format_frame_list(&missing)
            )),
            MissingPolicy::Error => unreachable!("handled above"),
        }
    }
    resolved.skipped.sort_unstable();
    resolved.skipped.dedup();
    resolved
        .frames
        .retain(|f| !resolved.skipped.contains(&f.frame));
    Ok(resolved)
}

/// The last frame on disk at or before `frame`, else the first after it.
fn nearest(on_disk: &[i64], frame: i64) -> i64 {
    match on_disk.partition_point(|&f| f <= frame) {
        0 => on_disk[0],
        i => on_disk[i - 1],
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nearest_prefers_the_earlier_frame() {
        assert_eq!(nearest(&[3, 5, 9], 7), 5);
        assert_eq!(nearest(&[3, 5, 9], 9), 9);
        assert_eq!(nearest(&[3, 5, 9], 1), 3);
        assert_eq!(nearest(&[3, 5, 9], 20), 9);
    }
}
