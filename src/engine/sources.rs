//! Which file each input reads for each output frame, given the frames on
//! disk and the policy for missing ones (`--missing`).

use super::plan::{FrameSources, Source};
use crate::error::{Error, Kind, Result};
use crate::io::sequence::{frames_named, FramePattern, InputTime};

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

/// Per output frame in `frames`, the frame each input reads: the one its
/// time gives (`times`, `FILE@+10`), else what `policy` makes of a missing
/// one.
pub fn resolve(
    inputs: &[FramePattern],
    times: &[InputTime],
    frames: &[i64],
    policy: MissingPolicy,
) -> Result<Resolved> {
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
    for (input, &time) in inputs.iter().zip(times) {
        let name = format!("{}{}", input.display(), time.suffix());
        let wanted: Vec<i64> = frames
            .iter()
            .map(|&f| time.read(f))
            .collect::<Result<_>>()?;
        // Output frames whose input frame is missing, and those input frames.
        let (missing_out, missing): (Vec<i64>, Vec<i64>) = frames
            .iter()
            .zip(&wanted)
            .filter(|(_, &w)| !input.path(w).exists())
            .map(|(&f, &w)| (f, w))
            .unzip();
        if missing.is_empty() {
            for (f, &w) in resolved.frames.iter_mut().zip(&wanted) {
                f.inputs.push(Source::Frame(w));
            }
            continue;
        }
        let mut missing = missing;
        missing.sort_unstable();
        missing.dedup();
        // A name that is there but leads nowhere is bad input, not a
        // missing frame, whatever the policy.
        if let Some((w, why)) = missing
            .iter()
            .find_map(|&w| broken_link(&input.path(w)).map(|why| (w, why)))
        {
            let frame = input.is_sequence().then_some(w);
            return Err(Error::input(&input.path(w), frame, why));
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
            } else if time != InputTime::default() {
                format!(
                    "missing {} (read for output {})",
                    frames_named(&missing),
                    frames_named(&missing_out)
                )
            } else {
                format!("missing {}", frames_named(&missing))
            };
            return Err(Error::new(Kind::Input, format!("{name}: {what}")));
        }
        for (f, &w) in resolved.frames.iter_mut().zip(&wanted) {
            let source = if missing.binary_search(&w).is_err() {
                Source::Frame(w)
            } else {
                let near = nearest(&on_disk, w);
                match policy {
                    MissingPolicy::Black => Source::Black(near),
                    _ => Source::Frame(near),
                }
            };
            f.inputs.push(source);
        }
        match policy {
            MissingPolicy::Skip => resolved.skipped.extend(&missing_out),
            MissingPolicy::Hold => resolved.replaced.push(format!(
                "{name}: {} held from the nearest earlier frame",
                frames_named(&missing)
            )),
            MissingPolicy::Black => resolved.replaced.push(format!(
                "{name}: {} {} transparent black",
                frames_named(&missing),
                if missing.len() == 1 { "is" } else { "are" }
            )),
            MissingPolicy::Error => unreachable!("handled above"),
        }
    }
    resolved.skipped.sort_unstable();
    resolved.skipped.dedup();
    resolved
        .frames
        .retain(|f| resolved.skipped.binary_search(&f.frame).is_err());
    Ok(resolved)
}

/// The frames a job runs without `--frames`: every frame from the first to
/// the last on disk of the first input that moves with the output (a
/// sequence neither held nor a single file), shifted by its offset, so that
/// `fg.####.exr@+10` with frames 1011-1110 on disk gives 1001-1100; a gap is
/// a missing frame like any other. With no such input, one frame: 1.
pub fn default_frames(inputs: &[FramePattern], times: &[InputTime]) -> Result<Vec<i64>> {
    let moving = inputs
        .iter()
        .zip(times)
        .find(|(input, time)| input.is_sequence() && time.moves());
    let Some((input, &InputTime::Offset(offset))) = moving else {
        return Ok(vec![1]);
    };
    let shifted = |f: i64| {
        f.checked_sub(offset).ok_or_else(|| {
            Error::usage(format!(
                "frame {f} of {} offset by {offset:+} is past the frame numbers",
                input.display()
            ))
        })
    };
    match input.frames_on_disk()?[..] {
        [first, .., last] => Ok((shifted(first)?..=shifted(last)?).collect()),
        [only] => Ok(vec![shifted(only)?]),
        [] => Err(Error::new(
            Kind::Input,
            format!("no frames of {} found", input.display()),
        )),
    }
}

/// The last frame on disk at or before `frame`, else the first after it.
fn nearest(on_disk: &[i64], frame: i64) -> i64 {
    match on_disk.partition_point(|&f| f <= frame) {
        0 => on_disk[0],
        i => on_disk[i - 1],
    }
}

/// Why `path` cannot be followed when its name is a symbolic link: it loops,
/// or it leads to no file.
fn broken_link(path: &std::path::Path) -> Option<String> {
    if !std::fs::symlink_metadata(path)
        .ok()?
        .file_type()
        .is_symlink()
    {
        return None;
    }
    let error = std::fs::metadata(path).err()?;
    Some(match error.raw_os_error() == Some(libc::ELOOP) {
        true => format!("is a symbolic link loop: {error}"),
        false => format!("is a symbolic link to no file: {error}"),
    })
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
