//! Frame-numbered file names (`####`, `%04d`) and frame lists (`1001-1100:2,1200`).

use crate::error::{Error, Result};
use std::path::{Path, PathBuf};

/// A file name with an optional frame-number placeholder.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct FramePattern {
    prefix: String,
    suffix: String,
    /// `None` for a plain file name; else the minimum digit count (zero padded).
    padding: Option<usize>,
}

impl FramePattern {
    /// `####` stands for one zero-padded digit per `#`; `%0Nd` and `%d` as in printf.
    /// The last placeholder in the text is the frame number.
    pub fn parse(text: &str) -> Self {
        let hashes = text.rfind('#').map(|end| {
            let start = text[..end].trim_end_matches('#').len();
            (start, end + 1, end + 1 - start)
        });
        let printf = find_printf(text);
        let placeholder = match (hashes, printf) {
            (Some(h), Some(p)) => Some(if h.0 > p.0 { h } else { p }),
            (h, p) => h.or(p),
        };
        match placeholder {
            Some((start, end, padding)) => FramePattern {
                prefix: text[..start].to_string(),
                suffix: text[end..].to_string(),
                padding: Some(padding),
            },
            None => FramePattern {
                prefix: text.to_string(),
                suffix: String::new(),
                padding: None,
            },
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

/// `%d` or `%0Nd`: (start, end, padding).
fn find_printf(text: &str) -> Option<(usize, usize, usize)> {
    let mut found = None;
    for (start, _) in text.match_indices('%') {
        let rest = &text[start + 1..];
        let digits = rest.len() - rest.trim_start_matches(|c: char| c.is_ascii_digit()).len();
        if rest[digits..].starts_with('d') {
            let padding = rest[..digits].parse().unwrap_or(1).max(1);
            found = Some((start, start + 2 + digits, padding));
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

/// Parses `A`, `A-B`, `A-B:STEP` and comma-separated lists of those.
pub fn parse_frame_list(text: &str) -> Result<Vec<i64>> {
    let mut frames = Vec::new();
    for item in text.split(',').map(str::trim) {
        let bad = || {
            Error::usage(format!(
                "bad frame range '{item}' (expected A, A-B or A-B:STEP)"
            ))
        };
        let (range, step) = match item.split_once(':') {
            Some((range, step)) => (range, step.trim().parse::<i64>().map_err(|_| bad())?),
            None => (item, 1),
        };
        if step < 1 {
            return Err(bad());
        }
        // A '-' after the first character separates the ends; a leading one is a sign.
        let (first, last) = match range.char_indices().skip(1).find(|&(_, c)| c == '-') {
            Some((dash, _)) => (&range[..dash], &range[dash + 1..]),
            None => (range, range),
        };
        let first: i64 = first.trim().parse().map_err(|_| bad())?;
        let last: i64 = last.trim().parse().map_err(|_| bad())?;
        if last < first {
            return Err(bad());
        }
        if (last - first) / step >= 10_000_000 {
            return Err(Error::usage(format!("frame range '{item}' is too long")));
        }
        frames.extend((first..=last).step_by(step as usize));
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hashes_pad_one_digit_each() {
        let p = FramePattern::parse("shots/fg.####.exr");
        assert_eq!(p.path(7), PathBuf::from("shots/fg.0007.exr"));
        assert_eq!(p.path(12345), PathBuf::from("shots/fg.12345.exr"));
        assert_eq!(
            FramePattern::parse("a.#.exr").path(42),
            PathBuf::from("a.42.exr")
        );
    }

    #[test]
    fn printf_patterns() {
        assert_eq!(
            FramePattern::parse("x.%04d.exr").path(5),
            PathBuf::from("x.0005.exr")
        );
        assert_eq!(
            FramePattern::parse("x.%d.exr").path(5),
            PathBuf::from("x.5.exr")
        );
        assert_eq!(
            FramePattern::parse("x.%04d.exr").path(-5),
            PathBuf::from("x.-005.exr")
        );
    }

    #[test]
    fn plain_names_are_not_sequences() {
        let p = FramePattern::parse("plate.exr");
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
        assert_eq!(
            parse_frame_list("1001,1005-1006").unwrap(),
            vec![1001, 1005, 1006]
        );
        assert_eq!(parse_frame_list("-2-1").unwrap(), vec![-2, -1, 0, 1]);
        assert!(parse_frame_list("5-1").is_err());
        assert!(parse_frame_list("1-5:0").is_err());
        assert!(parse_frame_list("abc").is_err());
    }

    #[test]
    fn frame_lists_format_compactly() {
        assert_eq!(format_frame_list(&[1, 2, 3, 5, 7, 8]), "1-3, 5, 7-8");
    }
}
