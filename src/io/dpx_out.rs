//! DPX output (SMPTE 268M): one big-endian RGB or RGBA image element of
//! 10-bit samples (filled, method A) or 16-bit ones, as `oiiotool -d uint10`
//! and `-d uint16` write them (`--attrib oiio:Endian big`), pixels bit for
//! bit. Rows are packed as they arrive (the encode stage's `convert`) and
//! streamed after the header, whose sizes are known before the first row:
//! memory stays flat in the frame's height. The frame's fingerprint is the
//! user-defined data. specs/file-format.md, "DPX output".

use crate::error::{Error, Result};
use crate::io::rows::Rows;
use exr::meta::attribute::{AttributeValue, Rational, Text, TimeCode};
use exr::meta::header::Header;
use rayon::prelude::*;
use std::io::Write;
use std::path::Path;

/// Where the pixels start, as OpenImageIO's libdpx places them; the bytes
/// between the headers (and user data) and the pixels are 0xff.
const IMAGE_OFFSET: usize = 8192;
/// The generic and industry headers.
const HEADERS: usize = 2048;
/// The user data's identification field, then its text.
const USER_ID: &[u8] = b"exrcomp";
const USER_ID_LEN: usize = 32;
/// The all-ones pattern of an unset field.
const UNSET: u32 = u32::MAX;

/// The samples a pixel holds: R, G, B and alpha when the image has one.
fn components(alpha: bool) -> usize {
    if alpha {
        4
    } else {
        3
    }
}

/// Bits per sample written: 10 (filled, method A) or 16.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Depth {
    Ten,
    Sixteen,
}

/// Bytes of a row of `width` pixels of `n` components: 10-bit samples
/// three to a 32-bit word (each row starting a word), 16-bit ones two
/// bytes each.
pub fn row_bytes(width: usize, n: usize, bits: Depth) -> usize {
    match bits {
        Depth::Ten => (width * n).div_ceil(3) * 4,
        Depth::Sixteen => width * n * 2,
    }
}

/// The 16-bit code of `v` as OpenImageIO converts float to uint16:
/// v * 65535 + 0.5, clamped, truncated; NaN is 0.
fn code16(v: f32) -> u16 {
    (v * 65535.0 + 0.5).clamp(0.0, 65535.0) as u16
}

/// The packed rows of `rows` (R, G, B from those channels or Y, else 0;
/// A if the image has alpha), values as they are: no transfer, no
/// unpremultiplication, as oiiotool writes them.
pub fn convert(rows: &Rows, bits: Depth) -> Vec<u8> {
    let index = |name: &str| rows.channel_index(name);
    let luminance = index("Y");
    let alpha = index("A");
    let sources = ["R", "G", "B"].map(|c| index(c).or(luminance));
    let n = components(alpha.is_some());
    let width = rows.width;
    let stride = row_bytes(width, n, bits);
    let mut out = vec![0u8; stride * rows.height];
    out.par_chunks_mut(stride.max(1))
        .enumerate()
        .for_each(|(i, row)| {
            let range = rows.row_range(rows.y + i as i32);
            let mut codes = vec![0u16; width * n];
            let mut plane = vec![0f32; width];
            for (c, source) in sources.iter().chain([&alpha]).take(n).enumerate() {
                if let Some(p) = source {
                    rows.planes[*p].read_f32(range.clone(), &mut plane);
                    for (x, &v) in plane.iter().enumerate() {
                        codes[x * n + c] = code16(v);
                    }
                }
            }
            pack(&codes, bits, row);
        });
    out
}

/// A row's 16-bit `codes` as the file stores them: 10-bit codes (the top
/// ten bits, as libdpx narrows) three to a big-endian word from its high
/// bits, two low bits of padding; or big-endian 16-bit words.
fn pack(codes: &[u16], bits: Depth, row: &mut [u8]) {
    match bits {
        Depth::Ten => {
            for (word, out) in codes.chunks(3).zip(row.chunks_exact_mut(4)) {
                let datum = |k: usize| (word.get(k).copied().unwrap_or(0) >> 6) as u32;
                let packed = datum(0) << 22 | datum(1) << 12 | datum(2) << 2;
                out.copy_from_slice(&packed.to_be_bytes());
            }
        }
        Depth::Sixteen => {
            for (code, out) in codes.iter().zip(row.chunks_exact_mut(2)) {
                out.copy_from_slice(&code.to_be_bytes());
            }
        }
    }
}

/// A header under construction: big-endian fields at their offsets.
struct Fields(Vec<u8>);

impl Fields {
    fn put(&mut self, at: usize, bytes: &[u8]) {
        self.0[at..at + bytes.len()].copy_from_slice(bytes);
    }
    fn u32(&mut self, at: usize, v: u32) {
        self.put(at, &v.to_be_bytes());
    }
    fn f32(&mut self, at: usize, v: f32) {
        self.put(at, &v.to_be_bytes());
    }
    /// A text field of `len` bytes, cut to leave its closing NUL.
    fn text(&mut self, at: usize, len: usize, text: &str) {
        let bytes = text.as_bytes();
        self.put(at, &bytes[..bytes.len().min(len - 1)]);
    }
}

/// SMPTE 268M's code of a transfer or colorimetric name (as
/// `dpx:Transfer` and the reader name them; OpenImageIO's names too).
fn characteristic(name: &str) -> Option<u8> {
    let names: [&[&str]; 16] = [
        &["User defined"],
        &["Printing density"],
        &["Linear"],
        &["Logarithmic"],
        &["Unspecified video"],
        &["SMPTE 274M"],
        &["ITU-R 709-4"],
        &["ITU-R 601-5 system B or G"],
        &["ITU-R 601-5 system M"],
        &["Composite video (NTSC)", "NTSC composite video"],
        &["Composite video (PAL)", "PAL composite video"],
        &["Z (depth) - linear", "Z depth linear"],
        &["Z (depth) - homogeneous", "Z depth homogeneous"],
        &["ADX"],
        &["ITU-R 2020 NCL"],
        &["ITU-R 2020 CL"],
    ];
    let code = names
        .iter()
        .position(|n| n.iter().any(|n| n.eq_ignore_ascii_case(name)))?;
    Some(code as u8)
}

/// A text attribute of `header`, if set and not empty.
fn text(header: &Header, name: &str) -> Option<String> {
    match header.own_attributes.other.get(&Text::from(name)) {
        Some(AttributeValue::Text(t)) => String::from_utf8(t.bytes().to_vec()).ok(),
        _ => None,
    }
    .filter(|t| !t.is_empty())
}

/// `header`'s time code and frame rate, wherever the reader or the exr
/// crate put them.
fn timing(header: &Header) -> (Option<TimeCode>, Option<Rational>) {
    let own = &header.own_attributes;
    let other = |name: &str| own.other.get(&Text::from(name));
    let time_code = header
        .shared_attributes
        .time_code
        .or(match other("timeCode") {
            Some(AttributeValue::TimeCode(t)) => Some(*t),
            _ => None,
        });
    let rate = own.frames_per_second.or(match other("framesPerSecond") {
        Some(AttributeValue::Rational(r)) => Some(*r),
        _ => None,
    });
    (time_code, rate)
}

/// The 8192 bytes before the pixels of a `width` x `height` frame of
/// `path`, holding `note` (key, text) as user data. Fields oiiotool sets
/// from attributes exrcomp does not carry keep oiiotool's unset values.
fn header(
    path: &Path,
    header: &Header,
    (width, height): (usize, usize),
    alpha: bool,
    bits: Depth,
    note: (&str, &str),
) -> Vec<u8> {
    let mut f = Fields(vec![0u8; IMAGE_OFFSET]);
    f.0[HEADERS..].fill(0xff);
    let image_bytes = row_bytes(width, components(alpha), bits) * height;
    let user = format!("{}={}", note.0, note.1);
    f.put(0, b"SDPX");
    f.u32(4, IMAGE_OFFSET as u32);
    f.put(8, b"V2.0");
    f.u32(16, (IMAGE_OFFSET + image_bytes) as u32);
    f.u32(20, 1);
    f.u32(24, 1664);
    f.u32(28, 384);
    f.u32(32, (USER_ID_LEN + user.len()) as u32);
    let name = path.file_name().unwrap_or_default().to_string_lossy();
    f.text(36, 100, &name);
    f.text(160, 100, concat!("exrcomp ", env!("CARGO_PKG_VERSION")));
    f.u32(660, UNSET);
    // Image information: one element.
    f.put(770, &1u16.to_be_bytes());
    f.u32(772, width as u32);
    f.u32(776, height as u32);
    for element in 0..8 {
        let at = 780 + 72 * element;
        let (unset_quantity, used) = match element {
            0 => (f32::NAN, true),
            _ => (4294967296.0, false),
        };
        f.u32(at, if used { 0 } else { UNSET });
        f.u32(at + 4, UNSET);
        f.f32(at + 8, unset_quantity);
        f.u32(at + 12, UNSET);
        f.f32(at + 16, unset_quantity);
        if !used {
            f.put(at + 20, &[0xff; 16]);
            f.u32(at + 36, UNSET);
        }
    }
    let transfer = text(header, "dpx:Transfer").and_then(|t| characteristic(&t));
    let colorimetric = text(header, "dpx:Colorimetric").and_then(|t| characteristic(&t));
    let bit_size = if bits == Depth::Ten { 10 } else { 16 };
    f.put(
        800,
        &[
            if alpha { 51 } else { 50 },
            transfer.unwrap_or(2),
            colorimetric.unwrap_or(0),
            bit_size,
        ],
    );
    // Filled, method A (for 16-bit samples too, as libdpx marks them).
    f.put(804, &1u16.to_be_bytes());
    f.u32(808, IMAGE_OFFSET as u32);
    // The element's description: OpenEXR's comments, as OpenImageIO's
    // ImageDescription.
    if let Some(comments) = &header.own_attributes.comments {
        f.text(820, 32, &String::from_utf8_lossy(comments.bytes()));
    }
    // Orientation: the centre unset, the original size the frame's.
    f.f32(1416, f32::NAN);
    f.f32(1420, f32::NAN);
    f.u32(1424, width as u32);
    f.u32(1428, height as u32);
    f.put(1620, &[0xff; 8]);
    let (numerator, denominator) = aspect(header.shared_attributes.pixel_aspect);
    f.u32(1628, numerator);
    f.u32(1632, denominator);
    // The scanned sizes unset as libdpx writes and reads them, whatever
    // the byte order (a little-endian NaN): oiiotool reads a big-endian
    // NaN here as 6.9e-41.
    f.put(1636, &[0, 0, 0xc0, 0x7f, 0, 0, 0xc0, 0x7f]);
    // Film and television: frame rate and time code.
    let (time_code, rate) = timing(header);
    let rate = rate.map_or(f32::NAN, |(n, d)| n as f32 / d as f32);
    f.put(1712, &[0xff; 12]);
    f.f32(1724, rate);
    f.f32(1728, f32::NAN);
    let (code, user_bits) = match time_code {
        Some(t) => (
            t.pack_time_as_tv60_u32().unwrap_or(UNSET),
            t.pack_user_data_as_u32(),
        ),
        None => (UNSET, UNSET),
    };
    f.u32(1920, code);
    f.u32(1924, user_bits);
    f.put(1928, &[0xff, 0xff, 0, 0xff]);
    for k in 0..10 {
        f.f32(1932 + 4 * k, if k == 2 { rate } else { f32::NAN });
    }
    f.put(HEADERS, &[0; USER_ID_LEN]);
    f.put(HEADERS, USER_ID);
    f.put(HEADERS + USER_ID_LEN, user.as_bytes());
    f.0
}

/// A pixel aspect ratio as the integers DPX keeps, as OpenImageIO's
/// float_to_rational makes them for the ratios met (whole, or to a
/// thousandth).
fn aspect(ratio: f32) -> (u32, u32) {
    if ratio.is_nan() || ratio <= 0.0 || ratio.is_infinite() {
        return (1, 1);
    }
    if ratio.fract() == 0.0 {
        return (ratio as u32, 1);
    }
    let numerator = (ratio * 1000.0).round() as u32;
    let common = gcd(numerator, 1000);
    (numerator / common, 1000 / common)
}

fn gcd(a: u32, b: u32) -> u32 {
    if b == 0 {
        a
    } else {
        gcd(b, a % b)
    }
}

/// Writes one DPX frame of `header`'s data window (with alpha or not)
/// from the packed rows `next` yields (`convert`'s), under a temporary
/// name renamed when complete, `note` its user data. An error from `next`
/// abandons the file and is returned as is.
pub fn write_frame(
    path: &Path,
    frame: Option<i64>,
    bits: Depth,
    frame_header: &Header,
    alpha: bool,
    note: (&str, &str),
    mut next: impl FnMut() -> Result<Option<Vec<u8>>>,
) -> Result<()> {
    let window = frame_header.data_window();
    let size = (window.size.width(), window.size.height());
    let expected = row_bytes(size.0, components(alpha), bits) * size.1;
    let fail = |e: &dyn std::fmt::Display| Error::output(path, frame, e);
    super::writer::write_in_place(path, frame, |out| {
        let head = header(path, frame_header, size, alpha, bits, note);
        out.write_all(&head).map_err(|e| fail(&e))?;
        let mut written = 0;
        while let Some(bytes) = next()? {
            written += bytes.len();
            out.write_all(&bytes).map_err(|e| fail(&e))?;
        }
        if written != expected {
            return Err(Error::internal(format!(
                "{written} of a DPX frame's {expected} pixel bytes arrived"
            )));
        }
        Ok(())
    })
}

/// The fields `complete` and `note` read: the magic, the pixels' offset
/// and the file's size, the user data's size.
fn header_of(path: &Path) -> Option<(Vec<u8>, u64)> {
    let file = super::reader::open_regular(path).ok()?;
    let len = file.metadata().ok()?.len();
    let head = crate::io::positioned::read_at(&file, 0, (len as usize).min(IMAGE_OFFSET)).ok()?;
    (head.len() >= 36 && head.starts_with(b"SDPX")).then_some((head, len))
}

fn field(head: &[u8], at: usize) -> usize {
    u32::from_be_bytes(head[at..at + 4].try_into().unwrap_or_default()) as usize
}

/// Whether `path` holds a whole DPX frame: its length the size its header
/// gives (frames are renamed into place only once written whole; a short
/// or damaged one is redone).
pub fn complete(path: &Path) -> bool {
    header_of(path).is_some_and(|(head, len)| field(&head, 16) as u64 == len)
}

/// The text a frame written by `write_frame` records under `key` in its
/// user data, if it is there.
pub fn note(path: &Path, key: &str) -> Option<String> {
    let (head, _) = header_of(path)?;
    let size = field(&head, 32);
    let data = head.get(HEADERS + USER_ID_LEN..HEADERS + size.max(USER_ID_LEN))?;
    let text = std::str::from_utf8(data).ok()?;
    let found = text.strip_prefix(key)?.strip_prefix('=')?;
    Some(found.to_string())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn codes_round_and_clamp_as_openimageio() {
        assert_eq!(code16(f32::NAN), 0);
        assert_eq!(code16(-1.0), 0);
        assert_eq!(code16(2.0), 65535);
        assert_eq!(code16(f32::INFINITY), 65535);
        assert_eq!(code16(0.5), 32768);
    }

    #[test]
    fn ten_bit_rows_pad_to_whole_words() {
        assert_eq!(row_bytes(1, 4, Depth::Ten), 8);
        assert_eq!(row_bytes(33, 3, Depth::Ten), 132);
        let mut row = [0u8; 8];
        pack(&[0xffff, 0, 0xffff, 0xffc0], Depth::Ten, &mut row);
        assert_eq!(row, [0xff, 0xc0, 0x0f, 0xfc, 0xff, 0xc0, 0, 0]);
    }
}
