//! `--burn-in TEXT`: a line of text drawn into a corner of each review
//! frame, white on a black box, in the built-in 5x7 font (`font.rs`)
//! scaled with the frame's height. Fields in braces are each frame's own:
//! `{frame}` (`{frame:4}` zero-padded to 4 digits), `{timecode}`, `{file}`
//! (the first input's file), `{output}` (the file written) and
//! `{attr:NAME}` (an attribute of the output's header).

use crate::draw::font;
use exr::meta::attribute::AttributeValue;
use exr::meta::header::Header;
use std::path::Path;

/// Where the text goes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default, clap::ValueEnum)]
pub enum Corner {
    #[default]
    BottomLeft,
    BottomRight,
    TopLeft,
    TopRight,
}

#[derive(Clone, Debug, PartialEq)]
enum Piece {
    Text(String),
    Frame(usize),
    Timecode,
    File,
    Output,
    Attribute(String),
}

/// A burn-in's text, its fields parsed, and its corner.
#[derive(Clone, Debug, PartialEq)]
pub struct BurnIn {
    pieces: Vec<Piece>,
    pub corner: Corner,
}

/// What a frame's fields are filled from.
pub struct Fields<'a> {
    pub frame: i64,
    pub header: &'a Header,
    pub file: Option<&'a Path>,
    pub output: &'a Path,
}

impl BurnIn {
    /// `text` with its fields; an unknown field or an unclosed brace is
    /// refused, naming the fields there are.
    pub fn parse(text: &str, corner: Corner) -> Result<BurnIn, String> {
        let mut pieces = Vec::new();
        let mut rest = text;
        while let Some(open) = rest.find('{') {
            pieces.push(Piece::Text(rest[..open].to_string()));
            let close = rest[open..]
                .find('}')
                .ok_or_else(|| format!("--burn-in '{text}': a '{{' without its '}}'"))?;
            let field = &rest[open + 1..open + close];
            pieces.push(match field.split_once(':') {
                None if field == "frame" => Piece::Frame(0),
                None if field == "timecode" => Piece::Timecode,
                None if field == "file" => Piece::File,
                None if field == "output" => Piece::Output,
                Some(("frame", digits)) => match digits.parse::<usize>() {
                    Ok(n) if n <= 20 => Piece::Frame(n),
                    _ => return Err(format!("--burn-in '{text}': {{frame:N}} pads to N digits, 0 to 20")),
                },
                Some(("attr", name)) if !name.is_empty() => Piece::Attribute(name.to_string()),
                _ => {
                    return Err(format!(
                        "--burn-in '{text}': unknown field {{{field}}} (fields: {{frame}}, {{frame:4}}, \
                         {{timecode}}, {{file}}, {{output}}, {{attr:NAME}})"
                    ))
                }
            });
            rest = &rest[open + close + 1..];
        }
        pieces.push(Piece::Text(rest.to_string()));
        pieces.retain(|p| *p != Piece::Text(String::new()));
        Ok(BurnIn { pieces, corner })
    }

    /// The text of one frame; a field the frame lacks (no timecode, no
    /// such attribute) reads `-`.
    pub fn text(&self, fields: &Fields) -> String {
        let name = |path: &Path| {
            path.file_name()
                .map(|n| n.to_string_lossy().into_owned())
                .unwrap_or_default()
        };
        self.pieces
            .iter()
            .map(|piece| match piece {
                Piece::Text(text) => text.clone(),
                Piece::Frame(width) => format!("{:0width$}", fields.frame),
                Piece::Timecode => timecode(fields.header).unwrap_or_else(|| "-".to_string()),
                Piece::File => fields.file.map(name).unwrap_or_else(|| "-".to_string()),
                Piece::Output => name(fields.output),
                Piece::Attribute(wanted) => attribute(fields.header, wanted)
                    .map(|value| attribute_text(&value))
                    .unwrap_or_else(|| "-".to_string()),
            })
            .collect()
    }

    /// `text` placed in this burn-in's corner of an image of `width` x
    /// `height` pixels.
    pub fn label(&self, text: String, (width, height): (usize, usize)) -> Label {
        let scale = scale(height);
        let margin = 2 * scale;
        let (box_width, box_height) = Label::size(&text, scale);
        let left = matches!(self.corner, Corner::BottomLeft | Corner::TopLeft);
        let top = matches!(self.corner, Corner::TopLeft | Corner::TopRight);
        let x = match left {
            true => margin,
            false => width.saturating_sub(margin + box_width),
        };
        let y = match top {
            true => margin,
            false => height.saturating_sub(margin + box_height),
        };
        Label::new(&text, (x, y), scale)
    }
}

/// `lines` one under the other from the top-left corner of an image
/// `height` pixels tall, at the burn-in's scale: a slate's text.
pub fn lines(lines: &[String], height: usize) -> Vec<Label> {
    let scale = scale(height);
    let margin = 2 * scale;
    let step = Label::size("", scale).1 + scale;
    lines
        .iter()
        .enumerate()
        .map(|(i, text)| Label::new(text, (margin, margin + i * step), scale))
        .collect()
}

/// Font pixels per glyph pixel in an image `height` pixels tall.
fn scale(height: usize) -> usize {
    (height / SCALE_PER).max(1)
}

/// Image rows per font pixel: 5x7 glyphs 28 pixels tall on 1080 lines.
pub const SCALE_PER: usize = 240;

/// Attribute `wanted` of `header` (its name's case aside).
pub(crate) fn attribute(header: &Header, wanted: &str) -> Option<AttributeValue> {
    header
        .all_named_attributes()
        .find(|(name, _)| name.eq_ignore_ascii_case(wanted.as_bytes()))
        .map(|(_, value)| value)
}

/// `header`'s timecode as `HH:MM:SS:FF`: the crate's field for one read,
/// or the attribute `--timecode` sets.
pub(crate) fn timecode(header: &Header) -> Option<String> {
    match attribute(header, "timeCode")? {
        AttributeValue::TimeCode(code) => Some(super::timecode::display(&code)),
        _ => None,
    }
}

/// An attribute's value as text: a string as it is, another type as
/// `exrcomp info` prints it.
pub(crate) fn attribute_text(value: &AttributeValue) -> String {
    match value {
        AttributeValue::Text(text) => text.to_string(),
        other => super::header_text::value_text(other)
            .trim_start_matches(':')
            .trim()
            .to_string(),
    }
}

/// A frame's burn-in: its box, in the image's pixels from the top-left
/// corner of the data window, and its text.
#[derive(Clone, Debug)]
pub struct Label {
    pub x: usize,
    pub y: usize,
    pub width: usize,
    pub height: usize,
    pub scale: usize,
    text: Vec<char>,
}

impl Label {
    /// The box of `text` at `scale`: one font pixel of black round the glyphs.
    fn size(text: &str, scale: usize) -> (usize, usize) {
        let width = font::text_width(text) * scale + 2 * scale;
        (width, font::HEIGHT * scale + 2 * scale)
    }

    fn new(text: &str, (x, y): (usize, usize), scale: usize) -> Label {
        let (width, height) = Label::size(text, scale);
        Label {
            x,
            y,
            width,
            height,
            scale,
            text: text.chars().collect(),
        }
    }

    /// Inside the box, whether pixel (x, y) is lit (white) or not (black);
    /// `None` outside it.
    pub fn pixel(&self, x: usize, y: usize) -> Option<bool> {
        let (dx, dy) = (x.checked_sub(self.x)?, y.checked_sub(self.y)?);
        if dx >= self.width || dy >= self.height {
            return None;
        }
        // The glyphs start one font pixel in from the box's corner.
        let inside = dx.checked_sub(self.scale).zip(dy.checked_sub(self.scale));
        Some(inside.is_some_and(|(x, y)| font::lit_in(&self.text, x, y, self.scale)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fields_are_parsed_and_unknown_ones_refused() {
        let burn = BurnIn::parse("SH010 {frame:4} {attr:owner}", Corner::TopRight).unwrap();
        let mut header = Header::new("image".into(), (1, 1), Default::default());
        header
            .own_attributes
            .other
            .insert("owner".into(), AttributeValue::Text("studio".into()));
        fn fields(header: &Header) -> Fields<'_> {
            Fields {
                frame: 7,
                header,
                file: None,
                output: Path::new("out/x.0007.jpg"),
            }
        }
        assert_eq!(burn.text(&fields(&header)), "SH010 0007 studio");
        let burn = BurnIn::parse("{output} {timecode} {file}", Corner::TopRight).unwrap();
        assert_eq!(burn.text(&fields(&header)), "x.0007.jpg - -");
        // --timecode's attribute, set among the others, is the frame's.
        let code = exr::meta::attribute::TimeCode {
            hours: 1,
            ..Default::default()
        };
        header
            .own_attributes
            .other
            .insert("timeCode".into(), AttributeValue::TimeCode(code));
        assert_eq!(burn.text(&fields(&header)), "x.0007.jpg 01:00:00:00 -");
        assert!(BurnIn::parse("{shot}", Corner::TopLeft).is_err());
        assert!(BurnIn::parse("{frame", Corner::TopLeft).is_err());
        assert!(BurnIn::parse("{frame:x}", Corner::TopLeft).is_err());
    }

    #[test]
    fn the_label_sits_in_its_corner_and_draws_the_font() {
        let burn = BurnIn::parse("L", Corner::BottomRight).unwrap();
        let label = burn.label("L".to_string(), (1920, 1080));
        assert_eq!(label.scale, 4);
        // 5 pixels of glyph and one of box each side, at scale 4.
        assert_eq!((label.width, label.height), (28, 36));
        assert_eq!((label.x, label.y), (1920 - 8 - 28, 1080 - 8 - 36));
        assert_eq!(label.pixel(label.x, label.y), Some(false));
        assert_eq!(label.pixel(label.x - 1, label.y), None);
        // L's top-left pixel is lit, its top-right not.
        assert_eq!(label.pixel(label.x + 4, label.y + 4), Some(true));
        assert_eq!(label.pixel(label.x + 4 + 16, label.y + 4), Some(false));
    }
}
