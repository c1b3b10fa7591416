//! Frame-numbered file names (`####`, `%04d`) and frame lists (`1001-1100:2,1200`).

use crate::error::{Error, Kind, Result};
use std::path::{Path, PathBuf};

/// A file name with an optional frame-number placeholder.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct FramePattern {
    /// As the user wrote it, for messages.
    text: String,
    prefix: String,
    suffix: String,
    /// `None` for a plain file name; else the minimum digit count (zero padded).
    padding: Option<usize>,
}

impl FramePattern {
    /// `####` stands for one zero-padded digit per `#`; `%0Nd` and `%d` as in
    /// printf, `%%` then standing for `%`. The last placeholder in the text is
    /// the frame number, padded to at most `MAX_PADDING` digits (a frame
    /// number never has more).
    pub fn parse(text: &str) -> Result<Self> {
        let hashes = text.rfind('#').map(|end| {
            let start = text[..end].trim_end_matches('#').len();
            (start, end + 1, end + 1 - start)
        });
        let printf = find_printf(text);
        let placeholder = match (hashes, printf) {
            (Some(h), Some(p)) => Some(if h.0 > p.0 { h } else { p }),
            (h, p) => h.or(p),
        };
        Ok(match placeholder {
            Some((_, _, padding)) if padding > MAX_PADDING => {
                return Err(Error::usage(format!(
                    "'{text}' pads frame numbers to {padding} digits; at most {MAX_PADDING} (#### or %04d)"
                )))
            }
            Some((start, end, padding)) => {
                // A printf placeholder makes the name a printf format.
                let literal = |part: &str| match placeholder == printf {
                    true => part.replace("%%", "%"),
                    false => part.to_string(),
                };
                FramePattern {
                    text: text.to_string(),
                    prefix: literal(&text[..start]),
                    suffix: literal(&text[end..]),
                    padding: Some(padding),
                }
            }
            None => FramePattern {
                text: text.to_string(),
                prefix: text.to_string(),
                suffix: String::new(),
                padding: None,
            },
        })
    }

    /// A pattern to write: as `parse`, and it must name a file of a format
    /// exrcomp writes (`media::Format`: .exr, .png, .jpg, .jpeg, .tif, .tiff,
    /// .dpx, .mov, .mp4).
    pub fn output(text: &str) -> Result<Self> {
        let pattern = Self::parse(text)?;
        if pattern.format().is_none() {
            return Err(Error::usage(format!(
                "the output '{text}' does not end in .exr, .png, .jpg, .jpeg, .tif, .tiff, .dpx, \
                 .mov or .mp4: the formats exrcomp writes"
            )));
        }
        Ok(pattern)
    }

    /// The format of the files named, by their extension.
    pub fn format(&self) -> Option<crate::io::media::Format> {
        crate::io::media::Format::of(self.suffix_or_name())
    }

    /// The text after the frame number, or the whole name of a plain file.
    fn suffix_or_name(&self) -> &str {
        match self.padding {
            Some(_) => &self.suffix,
            None => &self.prefix,
        }
    }

    pub fn is_sequence(&self) -> bool {
        self.padding.is_some()
    }

    /// The file of one frame (a plain name ignores the frame).
    pub fn path(&self, frame: i64) -> PathBuf {
        match self.padding {
            Some(width) => {
                PathBuf::from(format!("{}{:0width$}{}", self.prefix, frame, self.suffix))
            }
            None => PathBuf::from(&self.prefix),
        }
    }

    /// The pattern as the user wrote it, for messages.
    pub fn display(&self) -> String {
        self.text.clone()
    }

    /// The pattern with `#` placeholders (one per digit), as render
    /// managers name sequences.
    pub fn with_hashes(&self) -> String {
        match self.padding {
            Some(width) => format!("{}{}{}", self.prefix, "#".repeat(width.max(1)), self.suffix),
            None => self.prefix.clone(),
        }
    }

    /// Frames present on disk, sorted.
    pub fn frames_on_disk(&self) -> Result<Vec<i64>> {
        let Some(width) = self.padding else {
            return Ok(Vec::new());
        };
        let (dir, file_prefix) = match self.prefix.rfind('/') {
            Some(slash) => (&self.prefix[..=slash], &self.prefix[slash + 1..]),
            None => ("./", self.prefix.as_str()),
        };
        let entries = std::fs::read_dir(dir)
            .map_err(|e| Error::input(Path::new(dir), None, format!("cannot list folder: {e}")))?;
        let mut frames: Vec<i64> = entries
            .filter_map(|entry| entry.ok())
            .filter_map(|entry| {
                let name = entry.file_name().into_string().ok()?;
                let number = name.strip_prefix(file_prefix)?.strip_suffix(&self.suffix)?;
                parse_frame_digits(number, width)
            })
            .collect();
        frames.sort_unstable();
        frames.dedup();
        Ok(frames)
    }
}

/// Which frame of an input each output frame reads: `FILE@+10` reads frame
/// f + 10 for output frame f, `FILE@-5` f - 5, `FILE@1001` frame 1001 for
/// every output frame, `FILE@hold` the first frame on disk for every one.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum InputTime {
    Offset(i64),
    /// One frame throughout; `None` (`@hold`) is the first on disk.
    Hold(Option<i64>),
}

impl Default for InputTime {
    fn default() -> Self {
        InputTime::Offset(0)
    }
}

impl InputTime {
    /// `+N`, `-N`, `hold` or `N`, as written after `@`.
    pub fn parse(text: &str) -> std::result::Result<Self, String> {
        let text = text.trim();
        let number = |t: &str| t.parse::<i64>().ok().filter(|n| n.abs() <= MAX_OFFSET);
        let time = match text.as_bytes().first() {
            _ if text == "hold" => Some(InputTime::Hold(None)),
            Some(b'+' | b'-') => number(text).map(InputTime::Offset),
            Some(b'0'..=b'9') => number(text).map(|f| InputTime::Hold(Some(f))),
            _ => None,
        };
        time.ok_or_else(|| {
            format!(
                "'@{text}': write @+10 or @-5 (an offset of at most {MAX_OFFSET} frames), \
                 @1001 (hold that frame) or @hold (the first frame on disk)"
            )
        })
    }

    /// As written after the file name (`@+10`), empty for the default.
    pub fn suffix(self) -> String {
        match self {
            InputTime::Offset(0) => String::new(),
            InputTime::Offset(n) => format!("@{n:+}"),
            InputTime::Hold(None) => "@hold".into(),
            InputTime::Hold(Some(f)) => format!("@{f}"),
        }
    }

    /// The frame of the input that output frame `frame` reads (`@hold` of a
    /// single file: any, the file is the same).
    pub fn read(self, frame: i64) -> Result<i64> {
        match self {
            InputTime::Offset(n) => frame.checked_add(n).ok_or_else(|| {
                Error::usage(format!(
                    "frame {frame} offset by {n:+} is past the frame numbers"
                ))
            }),
            InputTime::Hold(Some(f)) => Ok(f),
            InputTime::Hold(None) => Ok(frame),
        }
    }

    /// `@hold` of a sequence as the frame it holds: its first on disk.
    pub fn pinned(self, pattern: &FramePattern) -> Result<Self> {
        match self {
            InputTime::Hold(None) if pattern.is_sequence() => match pattern.frames_on_disk()?[..] {
                [first, ..] => Ok(InputTime::Hold(Some(first))),
                [] => Err(Error::new(
                    Kind::Input,
                    format!("{}@hold: no frames on disk", pattern.display()),
                )),
            },
            time => Ok(time),
        }
    }

    /// Whether the input moves with the output frames.
    pub fn moves(self) -> bool {
        matches!(self, InputTime::Offset(_))
    }
}

/// Largest offset taken, in frames.
const MAX_OFFSET: i64 = 1_000_000_000;

/// Splits `fg.####.exr@+10` (or `fg.####.exr:left@+10`) into the rest and
/// its time. Only a suffix after an `.exr` name (or its `:PART`) counts, so
/// other names with an `@` stay whole; after one, a malformed time is an
/// error.
pub fn split_time(text: &str) -> Result<(&str, InputTime)> {
    let Some((rest, time)) = text.rsplit_once('@') else {
        return Ok((text, InputTime::default()));
    };
    let name = super::parts::split_part(rest).0;
    if !name.to_ascii_lowercase().ends_with(".exr") {
        return Ok((text, InputTime::default()));
    }
    let time = InputTime::parse(time).map_err(|m| Error::usage(format!("{text}: {m}")))?;
    Ok((rest, time))
}

/// More digits than any i64 frame number has.
const MAX_PADDING: usize = 20;

/// The last `%d` or `%0Nd`: (start, end, padding); `%%` is a `%` (printf's
/// rule), never a placeholder's start.
fn find_printf(text: &str) -> Option<(usize, usize, usize)> {
    let mut found = None;
    let mut at = 0;
    while let Some(start) = text[at..].find('%').map(|i| at + i) {
        let rest = &text[start + 1..];
        at = start + 1;
        if rest.starts_with('%') {
            at += 1;
            continue;
        }
        let digits = rest.len() - rest.trim_start_matches(|c: char| c.is_ascii_digit()).len();
        if rest[digits..].starts_with('d') {
            // `%d` is unpadded; a number too long to parse is over the limit.
            let padding = match digits {
                0 => 1,
                _ => rest[..digits].parse().unwrap_or(usize::MAX).max(1),
            };
            found = Some((start, start + 2 + digits, padding));
            at = start + 2 + digits;
        }
    }
    found
}

/// A frame number as it appears in a name written with this padding.
fn parse_frame_digits(number: &str, width: usize) -> Option<i64> {
    let digits = number.strip_prefix('-').unwrap_or(number);
    if digits.is_empty() || !digits.bytes().all(|b| b.is_ascii_digit()) {
        return None;
    }
    let frame: i64 = number.parse().ok()?;
    // The name must be exactly what formatting this frame would give.
    (format!("{:0width$}", frame) == number).then_some(frame)
}

/// Most frames a list may hold.
const MAX_FRAMES: usize = 10_000_000;

/// Parses `A`, `A-B`, `A-BxSTEP` (Nuke's), `A-B:STEP` and comma-separated
/// lists of those. A frame listed twice and a range that runs backwards are
/// errors: either would be a slip, and a frame written twice races itself.
/// The chunk of `count` frames of `frames` that starts at frame `first`:
/// frames cut into chunks of `count` in order, as a farm cuts them, so
/// `first` must start one (a task named by another frame would overlap).
pub fn chunk_from(frames: &[i64], first: i64, count: usize) -> Result<Vec<i64>> {
    match frames.iter().position(|&f| f == first) {
        Some(at) if at % count == 0 => Ok(frames[at..].iter().take(count).copied().collect()),
        found => Err(Error::usage(format!(
            "--chunk-from {first},{count}: frame {first} {} of --frames {}",
            match found {
                Some(_) => format!("does not start a chunk of {count}"),
                None => "is not one".to_string(),
            },
            format_frame_list(frames)
        ))),
    }
}

pub fn parse_frame_list(text: &str) -> Result<Vec<i64>> {
    let mut frames = Vec::new();
    let mut seen = std::collections::HashSet::new();
    for item in text.split(',').map(str::trim) {
        let bad = || {
            Error::usage(format!(
                "bad frame range '{item}': write 1001, 1001-1100, 1001-1100x2 or 1001-1100:2"
            ))
        };
        let (range, step) = match item.split_once(['x', ':']) {
            Some((range, step)) => (range, step.trim().parse::<i64>().map_err(|_| bad())?),
            None => (item, 1),
        };
        // A '-' after the first character separates the ends; a leading one is a sign.
        let (first, last) = match range.char_indices().skip(1).find(|&(_, c)| c == '-') {
            Some((dash, _)) => (&range[..dash], &range[dash + 1..]),
            // A step needs a range to step over.
            None if range.len() < item.len() => return Err(bad()),
            None => (range, range),
        };
        let first: i64 = first.trim().parse().map_err(|_| bad())?;
        let last: i64 = last.trim().parse().map_err(|_| bad())?;
        if step < 1 {
            return Err(bad());
        }
        if last < first {
            return Err(Error::usage(format!(
                "frame range '{item}' runs backwards: write {last}-{first}"
            )));
        }
        let count = (last.abs_diff(first) / step as u64).saturating_add(1);
        if count > (MAX_FRAMES - frames.len()) as u64 {
            return Err(Error::usage(format!(
                "frame list '{text}' has more than {MAX_FRAMES} frames"
            )));
        }
        for frame in (first..=last).step_by(step as usize) {
            if !seen.insert(frame) {
                return Err(Error::usage(format!(
                    "frame {frame} is listed twice in '{text}'"
                )));
            }
            frames.push(frame);
        }
    }
    Ok(frames)
}

/// `1001, 1003-1005` for messages.
pub fn format_frame_list(frames: &[i64]) -> String {
    let mut parts = Vec::new();
    let mut i = 0;
    while i < frames.len() {
        let mut j = i;
        while j + 1 < frames.len() && frames[j + 1] == frames[j] + 1 {
            j += 1;
        }
        parts.push(if i == j {
            frames[i].to_string()
        } else {
            format!("{}-{}", frames[i], frames[j])
        });
        i = j + 1;
    }
    parts.join(", ")
}

/// `frame 1003` or `frames 1001, 1003-1005`, for messages.
pub fn frames_named(frames: &[i64]) -> String {
    match frames {
        [one] => format!("frame {one}"),
        _ => format!("frames {}", format_frame_list(frames)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_frame_is_named_in_the_singular() {
        assert_eq!(frames_named(&[1003]), "frame 1003");
        assert_eq!(frames_named(&[1, 3, 4, 5]), "frames 1, 3-5");
    }

    #[test]
    fn hashes_pad_one_digit_each() {
        let p = FramePattern::parse("shots/fg.####.exr").unwrap();
        assert_eq!(p.path(7), PathBuf::from("shots/fg.0007.exr"));
        assert_eq!(p.path(12345), PathBuf::from("shots/fg.12345.exr"));
        assert_eq!(
            FramePattern::parse("a.#.exr").unwrap().path(42),
            PathBuf::from("a.42.exr")
        );
    }

    #[test]
    fn printf_patterns() {
        assert_eq!(
            FramePattern::parse("x.%04d.exr").unwrap().path(5),
            PathBuf::from("x.0005.exr")
        );
        assert_eq!(
            FramePattern::parse("x.%d.exr").unwrap().path(5),
            PathBuf::from("x.5.exr")
        );
        assert_eq!(
            FramePattern::parse("x.%04d.exr").unwrap().path(-5),
            PathBuf::from("x.-005.exr")
        );
        // `%%` is a `%` (printf's rule), and never starts a placeholder.
        let percent = FramePattern::parse("50%%/x.%%d.%04d.exr").unwrap();
        assert_eq!(percent.path(5), PathBuf::from("50%/x.%d.0005.exr"));
        assert_eq!(
            FramePattern::parse("x.%%04d.exr").unwrap().path(5),
            PathBuf::from("x.%%04d.exr")
        );
        // Messages show the pattern as written; render managers get hashes.
        assert_eq!(percent.display(), "50%%/x.%%d.%04d.exr");
        assert_eq!(percent.with_hashes(), "50%/x.%d.####.exr");
    }

    #[test]
    fn padding_is_bounded() {
        assert!(FramePattern::parse("b.%099999d.exr").is_err());
        assert!(FramePattern::parse("b.%0999999999999999999999d.exr").is_err());
        assert!(FramePattern::parse(&format!("b.{}.exr", "#".repeat(21))).is_err());
        assert!(FramePattern::parse("b.%020d.exr").is_ok());
    }

    #[test]
    fn outputs_must_be_of_a_format_written() {
        use crate::io::media::Format;
        assert!(FramePattern::output("x.gif").is_err());
        assert_eq!(
            FramePattern::output("x.####.png").unwrap().format(),
            Some(Format::Png)
        );
        assert_eq!(
            FramePattern::output("x.JPEG").unwrap().format(),
            Some(Format::Jpeg)
        );
        assert_eq!(
            FramePattern::output("x.%04d.tif").unwrap().format(),
            Some(Format::Tiff)
        );
        assert!(FramePattern::output("x.exr.tmp").is_err());
        assert!(FramePattern::output("x.####.EXR").is_ok());
        assert!(FramePattern::output("x.%04d.exr").is_ok());
        assert!(FramePattern::output("dir.exr/x").is_err());
    }

    #[test]
    fn plain_names_are_not_sequences() {
        let p = FramePattern::parse("plate.exr").unwrap();
        assert!(!p.is_sequence());
        assert_eq!(p.path(1001), PathBuf::from("plate.exr"));
    }

    #[test]
    fn frame_digits_must_match_padding() {
        assert_eq!(parse_frame_digits("0012", 4), Some(12));
        assert_eq!(parse_frame_digits("012", 4), None);
        assert_eq!(parse_frame_digits("12345", 4), Some(12345));
        assert_eq!(parse_frame_digits("00012", 4), None);
        assert_eq!(parse_frame_digits("12a4", 4), None);
    }

    #[test]
    fn frame_lists() {
        assert_eq!(
            parse_frame_list("1001-1004").unwrap(),
            vec![1001, 1002, 1003, 1004]
        );
        assert_eq!(parse_frame_list("1-9:4").unwrap(), vec![1, 5, 9]);
        let odd = parse_frame_list("1-12x2").unwrap();
        assert_eq!(chunk_from(&odd, 5, 2).unwrap(), vec![5, 7]);
        assert_eq!(chunk_from(&odd, 9, 2).unwrap(), vec![9, 11]);
        assert_eq!(
            chunk_from(&[1, 2, 3, 4, 5, 6, 7], 6, 5).unwrap(),
            vec![6, 7]
        );
        assert!(chunk_from(&odd, 3, 2).is_err());
        assert!(chunk_from(&odd, 2, 2).is_err());
        assert_eq!(
            parse_frame_list("1001,1005-1006").unwrap(),
            vec![1001, 1005, 1006]
        );
        assert_eq!(parse_frame_list("-2-1").unwrap(), vec![-2, -1, 0, 1]);
        assert_eq!(parse_frame_list("1-9x4").unwrap(), vec![1, 5, 9]);
        assert_eq!(parse_frame_list("-9--5x2").unwrap(), vec![-9, -7, -5]);
        assert!(parse_frame_list("1-5:0").is_err());
        assert!(parse_frame_list("abc").is_err());
        assert!(parse_frame_list("").is_err());
    }

    #[test]
    fn frame_list_slips_are_refused() {
        let message = |text| parse_frame_list(text).unwrap_err().message;
        assert!(message("5-1").contains("runs backwards: write 1-5"));
        assert!(message("1001:1005").contains("1001-1100x2"));
        assert!(message("1001x2").contains("1001-1100x2"));
        assert!(message("1001,1001,1003").contains("frame 1001 is listed twice"));
        assert!(message("1-10,5").contains("frame 5 is listed twice"));
        assert!(message("1-10y2").contains("bad frame range"));
        assert!(message("0-99999999").contains("more than"));
        assert!(message(&format!("{}-{}", i64::MIN, i64::MAX)).contains("more than"));
    }

    #[test]
    fn input_times() {
        let split = |t| split_time(t).unwrap();
        assert_eq!(
            split("fg.####.exr@+10"),
            ("fg.####.exr", InputTime::Offset(10))
        );
        assert_eq!(
            split("fg.####.exr@-5"),
            ("fg.####.exr", InputTime::Offset(-5))
        );
        assert_eq!(
            split("fg.####.exr:left@+1"),
            ("fg.####.exr:left", InputTime::Offset(1))
        );
        assert_eq!(
            split("plate.1001.exr@hold"),
            ("plate.1001.exr", InputTime::Hold(None))
        );
        assert_eq!(
            split("p.####.EXR@1001"),
            ("p.####.EXR", InputTime::Hold(Some(1001)))
        );
        // An @ elsewhere in a name is the name's.
        assert_eq!(
            split("user@host/fg.exr"),
            ("user@host/fg.exr", InputTime::Offset(0))
        );
        assert_eq!(split("fg.exr"), ("fg.exr", InputTime::Offset(0)));
        for bad in [
            "fg.exr@",
            "fg.exr@+1O",
            "fg.exr@later",
            "fg.exr@+99999999999",
        ] {
            let message = split_time(bad).unwrap_err().message;
            assert!(message.contains("write @+10"), "{bad}: {message}");
        }
        assert_eq!(InputTime::Offset(10).read(1001).unwrap(), 1011);
        assert_eq!(InputTime::Hold(Some(7)).read(1001).unwrap(), 7);
        assert!(InputTime::Offset(1).read(i64::MAX).is_err());
        for time in [
            InputTime::Offset(-3),
            InputTime::Hold(None),
            InputTime::Hold(Some(5)),
        ] {
            assert_eq!(InputTime::parse(&time.suffix()[1..]).unwrap(), time);
        }
        assert_eq!(InputTime::Offset(0).suffix(), "");
    }

    #[test]
    fn frame_lists_format_compactly() {
        assert_eq!(format_frame_list(&[1, 2, 3, 5, 7, 8]), "1-3, 5, 7-8");
    }
}
