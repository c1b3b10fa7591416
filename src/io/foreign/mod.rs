//! Images in formats other than OpenEXR, read as what the engine reads: a
//! single-part flat scanline image (data and display window, channels R, G,
//! B, [A] or Y as HALF or FLOAT, attributes) whose rows are decoded on
//! demand, by row range, with positioned reads, so that memory stays flat in
//! the image's height. `ExrFile::open` asks `sniff` for a magic number it
//! knows and `open` for the reader; a format is one file here that parses
//! its header into a `Foreign` (a TIFF, PNG or JPEG reader is another file
//! and a line in `sniff` and `open`). specs/file-format.md, "Foreign inputs".

pub mod cineon;
pub mod dpx;
pub mod jpeg;
pub mod png;
mod raw;
mod stream;
pub mod tiff;

use exr::meta::attribute::{AttributeValue, ChannelDescription, SampleType, Text};
use exr::meta::header::Header;
use exr::meta::BlockDescription;
use exr::prelude::{Compression, LineOrder};
use std::fs::File;
use std::ops::Range;

/// The formats read besides OpenEXR.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    Dpx,
    Cineon,
    Png,
    Tiff,
    Jpeg,
}

impl Format {
    pub fn name(self) -> &'static str {
        match self {
            Format::Dpx => "DPX",
            Format::Cineon => "Cineon",
            Format::Png => "PNG",
            Format::Tiff => "TIFF",
            Format::Jpeg => "JPEG",
        }
    }
}

/// The format whose magic number starts a file, in either byte order.
pub fn sniff(magic: [u8; 4]) -> Option<Format> {
    match &magic {
        b"SDPX" | b"XPDS" => Some(Format::Dpx),
        [0x80, 0x2a, 0x5f, 0xd7] | [0xd7, 0x5f, 0x2a, 0x80] => Some(Format::Cineon),
        [0x89, b'P', b'N', b'G'] => Some(Format::Png),
        [b'I', b'I', 42, 0] | [b'M', b'M', 0, 42] | [b'I', b'I', 43, 0] | [b'M', b'M', 0, 43] => {
            Some(Format::Tiff)
        }
        [0xff, 0xd8, 0xff, _] => Some(Format::Jpeg),
        _ => None,
    }
}

/// A foreign image's rows, as an uncompressed EXR scanline block holds
/// them: per row, each channel of the header (sorted by name) as a run of
/// little-endian samples across the width.
pub trait Rows: Send + Sync {
    /// Rows `rows` (counted from the data window's top) read from `file`;
    /// an error says what is wrong in a few words (the caller names the
    /// file).
    fn read(&self, file: &File, rows: Range<usize>) -> Result<Vec<u8>, String>;

    /// Whether rows decode only in order from the image's top (a
    /// compressed stream): a row asked before the last one read starts
    /// the decoding over, so readers ask in order (`ExrFile::sequential`).
    fn sequential(&self) -> bool {
        false
    }

    /// The bytes the reader holds between reads (decoder state, a strip
    /// decoded): its term in the memory bound.
    fn resident(&self) -> u64 {
        0
    }
}

/// A foreign file opened: its format, the header it is read as and the
/// reader of its rows.
pub struct Foreign {
    pub format: Format,
    pub header: Header,
    pub rows: Box<dyn Rows>,
    /// The bytes before the pixels (the file's headers): what a frame's
    /// fingerprint hashes of it besides its length and time.
    pub header_bytes: usize,
}

/// Reads `file`'s header as `format` and checks it against `len`, the
/// file's length, before anything is allocated in proportion to its sizes.
pub fn open(file: &File, len: u64, format: Format) -> Result<Foreign, String> {
    match format {
        Format::Dpx => dpx::open(file, len),
        Format::Cineon => cineon::open(file, len),
        Format::Png => png::open(file, len),
        Format::Tiff => tiff::open(file, len),
        Format::Jpeg => jpeg::open(file, len),
    }
}

/// The header a foreign image of `width` x `height` pixels with `channels`
/// (any order) of `sample` is read as: one uncompressed scanline part at
/// the origin, a line per block, with `attributes` (names and values).
pub fn header(
    (width, height): (usize, usize),
    channels: &[&str],
    sample: SampleType,
    attributes: Vec<(&str, AttributeValue)>,
) -> Header {
    let mut list: Vec<ChannelDescription> = channels
        .iter()
        .map(|name| ChannelDescription::named(*name, sample))
        .collect();
    list.sort_by(|a, b| a.name.cmp(&b.name));
    let mut header = Header::new(Text::from(""), (width, height), list.into()).with_encoding(
        Compression::Uncompressed,
        BlockDescription::ScanLines,
        LineOrder::Increasing,
    );
    header.own_attributes.layer_name = None;
    for (name, value) in attributes {
        match (name, value) {
            ("timeCode", AttributeValue::TimeCode(code)) => {
                header.shared_attributes.time_code = Some(code)
            }
            ("framesPerSecond", AttributeValue::Rational(rate)) => {
                header.own_attributes.frames_per_second = Some(rate)
            }
            ("pixelAspectRatio", AttributeValue::F32(ratio)) => {
                header.shared_attributes.pixel_aspect = ratio
            }
            ("capDate", AttributeValue::Text(date)) => {
                header.own_attributes.capture_date = Some(date)
            }
            (name, value) => {
                header.own_attributes.other.insert(Text::from(name), value);
            }
        }
    }
    header
}

/// The first `most` bytes of a `format` file of `len` bytes (its headers),
/// refused when the file is shorter than its `least`-byte header.
pub fn header_bytes(
    file: &File,
    len: u64,
    (least, most): (usize, usize),
    format: &str,
) -> Result<Vec<u8>, String> {
    if len < least as u64 {
        return Err(format!(
            "truncated {format}: {len} bytes, less than its {least}-byte header"
        ));
    }
    crate::io::positioned::read_at(file, 0, (len as usize).min(most))
}

/// A fixed-length text field: up to its first NUL, trimmed; `None` when
/// empty or not printable (an unset field is zeros or 0xff bytes).
pub fn text_field(bytes: &[u8]) -> Option<String> {
    let end = bytes.iter().position(|&b| b == 0).unwrap_or(bytes.len());
    let text = std::str::from_utf8(&bytes[..end]).ok()?.trim();
    let printable = text.chars().all(|c| !c.is_control());
    (!text.is_empty() && printable).then(|| text.to_string())
}

/// A header's frame rate as `framesPerSecond`: the NTSC rates as their
/// fractions (23.976 is 24000/1001), others to a thousandth; `None` for an
/// unset field (0, NaN, or the all-ones "undefined" pattern).
pub fn frame_rate(rate: f32) -> Option<exr::meta::attribute::Rational> {
    if !(rate.is_finite() && rate > 0.0 && rate < 10_000.0) {
        return None;
    }
    let text = format!("{rate:.3}");
    let text = text.trim_end_matches('0').trim_end_matches('.');
    crate::io::attributes::parse_fps(text).ok()
}

/// A string attribute, when the text is set.
pub fn string(name: &'static str, text: Option<String>) -> Option<(&'static str, AttributeValue)> {
    text.map(|t| (name, utf8(&t)))
}

/// A string attribute holding `text`'s UTF-8 bytes, as OpenEXR's strings
/// do and `--attrib` writes them (exr's `Text::from` panics on a character
/// beyond Latin-1, which a file's text field may hold).
pub fn utf8(text: &str) -> AttributeValue {
    AttributeValue::Text(Text::from_slice_unchecked(text.as_bytes()))
}

/// Big- or little-endian fields of a header.
pub struct Fields<'a> {
    pub bytes: &'a [u8],
    pub big_endian: bool,
}

impl Fields<'_> {
    pub fn u8(&self, at: usize) -> u8 {
        self.bytes[at]
    }
    pub fn u16(&self, at: usize) -> u16 {
        let b = [self.bytes[at], self.bytes[at + 1]];
        match self.big_endian {
            true => u16::from_be_bytes(b),
            false => u16::from_le_bytes(b),
        }
    }
    pub fn u32(&self, at: usize) -> u32 {
        let b: [u8; 4] = self.bytes[at..at + 4].try_into().expect("4 bytes");
        match self.big_endian {
            true => u32::from_be_bytes(b),
            false => u32::from_le_bytes(b),
        }
    }
    pub fn f32(&self, at: usize) -> f32 {
        f32::from_bits(self.u32(at))
    }
    pub fn text(&self, at: usize, len: usize) -> Option<String> {
        text_field(&self.bytes[at..at + len])
    }
}

/// For each of `names` sorted (the header's channel order), its position
/// among `names` (the order a pixel stores them).
pub fn sorted_components(names: &[&str]) -> Vec<usize> {
    let mut order: Vec<usize> = (0..names.len()).collect();
    order.sort_by_key(|&i| names[i]);
    order
}
