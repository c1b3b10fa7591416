//! DPX (SMPTE 268M) images: one image element of 8, 10 (packed, filled
//! method A or B), 12 (packed, filled A or B) or 16-bit unsigned samples,
//! uncompressed, RGB, RGBA, ABGR or one channel, in either byte order, in
//! any of the four unrotated orientations. What the header says of the
//! pixels' meaning (transfer, colorimetric, timecode, frame rate...) becomes
//! attributes. specs/file-format.md, "DPX".

use super::raw::{self, Packing, Raw};
use super::{frame_rate, header_bytes, sorted_components, string, Fields, Foreign, Format};
use exr::meta::attribute::{AttributeValue, SampleType, TimeCode};
use std::fs::File;

/// The generic header (file and image information, orientation): the least
/// a file holds before its pixels.
const GENERIC: usize = 1664;
/// With the industry header (film and television information).
const INDUSTRY: usize = 2048;

/// The all-ones pattern DPX writes for an unset field.
const UNSET: u32 = u32::MAX;

/// A descriptor's channels, in the order a pixel stores them.
fn channels(descriptor: u8) -> Result<&'static [&'static str], String> {
    Ok(match descriptor {
        1 => &["R"],
        2 => &["G"],
        3 => &["B"],
        4 => &["A"],
        6 => &["Y"],
        50 => &["R", "G", "B"],
        51 => &["R", "G", "B", "A"],
        52 => &["A", "B", "G", "R"],
        other => {
            return Err(format!(
                "its image descriptor {other} ({}) is not read: RGB (50), RGBA (51), ABGR (52) \
                 and single channels (1-4, 6 luminance) are",
                match other {
                    7 | 8 => "chrominance or depth",
                    100..=103 => "Y'CbCr video",
                    150..=156 => "user-defined components",
                    _ => "undefined",
                }
            ))
        }
    })
}

/// SMPTE 268M's names of the transfer and colorimetric codes.
fn characteristic(code: u8, colorimetric: bool) -> String {
    match code {
        0 => "User defined",
        1 => "Printing density",
        2 | 3 | 11 | 12 if colorimetric => "Not applicable",
        2 => "Linear",
        3 => "Logarithmic",
        4 => "Unspecified video",
        5 => "SMPTE 274M",
        6 => "ITU-R 709-4",
        7 => "ITU-R 601-5 system B or G",
        8 => "ITU-R 601-5 system M",
        9 => "Composite video (NTSC)",
        10 => "Composite video (PAL)",
        11 => "Z (depth) - linear",
        12 => "Z (depth) - homogeneous",
        13 => "ADX",
        14 => "ITU-R 2020 NCL",
        15 => "ITU-R 2020 CL",
        other => return format!("Undefined ({other})"),
    }
    .to_string()
}

/// How `bits`-bit samples with DPX packing code `packing` are stored.
fn packing(bits: u8, packing: u16, components: usize) -> Result<Packing, String> {
    Ok(match (bits, packing) {
        (8, _) => Packing::Bytes,
        (10, 0) | (12, 0) => Packing::Packed,
        (10, 1 | 2) => Packing::Filled10 {
            pad: if packing == 1 { 2 } else { 0 },
            reversed: components == 1,
        },
        (12, 1) => Packing::Words { shift: 4 },
        (12, 2) | (16, _) => Packing::Words { shift: 0 },
        (10 | 12, other) => return Err(format!("its packing {other} is not 0, 1 or 2")),
        (other, _) => {
            return Err(format!(
                "its {other}-bit samples are not read (8, 10, 12 and 16-bit integers are)"
            ))
        }
    })
}

/// The header's fields that become attributes.
fn attributes(f: &Fields, industry: bool) -> Vec<(&'static str, AttributeValue)> {
    let element = 780;
    let mut list: Vec<Option<(&'static str, AttributeValue)>> = vec![
        string(
            "dpx:Transfer",
            Some(characteristic(f.u8(element + 21), false)),
        ),
        string(
            "dpx:Colorimetric",
            Some(characteristic(f.u8(element + 22), true)),
        ),
        string("dpx:Creator", f.text(160, 100)),
        string("dpx:Project", f.text(260, 200)),
        string("dpx:Copyright", f.text(460, 200)),
        string("dpx:InputDevice", f.text(1556, 32)),
        Some((
            "dpx:BitsPerSample",
            AttributeValue::I32(f.u8(element + 23) as i32),
        )),
        capture_date(f.text(136, 24)).map(|d| ("capDate", d)),
    ];
    let (h, v) = (f.u32(1628), f.u32(1632));
    if h != 0 && v != 0 && h != UNSET && v != UNSET {
        list.push(Some((
            "pixelAspectRatio",
            AttributeValue::F32(h as f32 / v as f32),
        )));
    }
    if industry {
        list.push(string("dpx:FrameId", f.text(1732, 32)));
        let rate = frame_rate(f.f32(1724)).or_else(|| frame_rate(f.f32(1940)));
        list.push(rate.map(|r| ("framesPerSecond", AttributeValue::Rational(r))));
        list.push(time_code(f.u32(1920), f.u32(1924)).map(|t| ("timeCode", t)));
    }
    list.into_iter().flatten().collect()
}

/// The header's time code (SMPTE's BCD HH:MM:SS:FF, as OpenEXR's) when set
/// and within what `timeCode` holds (frames 0-29).
fn time_code(code: u32, user_bits: u32) -> Option<AttributeValue> {
    let bcd = |shift: u32, tens: u32| {
        let (t, u) = ((code >> (shift + 4)) & tens, (code >> shift) & 0xf);
        (u <= 9).then_some(t * 10 + u)
    };
    let (h, m, s, f) = (bcd(24, 0x3)?, bcd(16, 0x7)?, bcd(8, 0x7)?, bcd(0, 0x3)?);
    if code == UNSET || h > 23 || m > 59 || s > 59 || f > 29 {
        return None;
    }
    let user_bits = if user_bits == UNSET { 0 } else { user_bits };
    Some(AttributeValue::TimeCode(TimeCode::from_tv60_time(
        code, user_bits,
    )))
}

/// `YYYY:MM:DD:hh:mm:ss...` as OpenEXR's `capDate`, `YYYY:MM:DD hh:mm:ss`.
fn capture_date(stamp: Option<String>) -> Option<AttributeValue> {
    let stamp = stamp?;
    let b = stamp.as_bytes();
    let shaped = b.len() >= 19
        && [4, 7, 10, 13, 16]
            .iter()
            .all(|&i| b[i] == b':' || (i == 10 && b[i] == b' '))
        && [0, 1, 2, 3, 5, 6, 8, 9, 11, 12, 14, 15, 17, 18]
            .iter()
            .all(|&i| b[i].is_ascii_digit());
    shaped.then(|| {
        let date = format!("{} {}", &stamp[..10], &stamp[11..19]);
        AttributeValue::Text(exr::meta::attribute::Text::from(date.as_str()))
    })
}

/// Opens a DPX file of `len` bytes: its header read and checked (sizes
/// against the file's length), its rows read on demand.
pub fn open(file: &File, len: u64) -> Result<Foreign, String> {
    let bytes = header_bytes(file, len, (GENERIC, INDUSTRY), "DPX")?;
    let f = Fields {
        big_endian: &bytes[..4] == b"SDPX",
        bytes: &bytes,
    };
    let elements = f.u16(770);
    if elements != 1 {
        return Err(format!(
            "it has {elements} image elements; DPX files of one are read"
        ));
    }
    let (width, height) = (f.u32(772) as u64, f.u32(776) as u64);
    if width == 0 || height == 0 || width > 1 << 24 || height > 1 << 24 {
        return Err(format!("its size {width} x {height} is not an image's"));
    }
    let element = 780;
    if f.u32(element) != 0 {
        return Err("its samples are signed; unsigned samples are read".into());
    }
    if f.u16(element + 26) != 0 {
        return Err("its samples are run-length encoded; uncompressed ones are read".into());
    }
    let names = channels(f.u8(element + 20))?;
    let bits = f.u8(element + 23);
    let packing = packing(bits, f.u16(element + 24), names.len())?;
    let orientation = f.u16(768);
    if orientation > 3 {
        return Err(format!(
            "its orientation {orientation} (transposed) is not read: 0 to 3 are"
        ));
    }
    let offset = match f.u32(element + 28) {
        0 | UNSET => f.u32(4),
        at => at,
    } as u64;
    if offset < GENERIC as u64 {
        return Err(format!(
            "its pixels start at byte {offset}, inside its {GENERIC}-byte header"
        ));
    }
    let padding = match f.u32(element + 32) {
        UNSET => 0,
        pad => pad as u64,
    };
    let used = raw::row_bytes(width * names.len() as u64, bits as u32, packing);
    let stride = used + padding;
    let end = offset + stride * (height - 1) + used;
    if end > len {
        return Err(format!(
            "truncated DPX: {width} x {height} pixels of {} {bits}-bit samples end at byte {end} \
             but the file has {len} bytes",
            names.len()
        ));
    }
    let sample = if bits <= 10 {
        SampleType::F16
    } else {
        SampleType::F32
    };
    let bits = bits as u32;
    let rows = Raw {
        first: offset,
        stride,
        width: width as usize,
        height: height as usize,
        components: names.len(),
        bits,
        packing,
        big_endian: f.big_endian,
        bottom_up: orientation >= 2,
        right_to_left: orientation % 2 == 1,
        channels: sorted_components(names),
        table: raw::table(bits, sample, |code| value(code, bits, packing)),
        sample_bytes: sample.bytes_per_sample(),
    };
    let mut attributes = attributes(&f, offset >= INDUSTRY as u64 && bytes.len() >= INDUSTRY);
    attributes.push(("dpx:Orientation", orientation_name(orientation)));
    Ok(Foreign {
        format: Format::Dpx,
        header: super::header((rows.width, rows.height), names, sample, attributes),
        rows: Box::new(rows),
        header_bytes: offset.min(1 << 20) as usize,
    })
}

/// A code's value as OpenImageIO reads it (`raw::widened`), but for 12-bit
/// filled method A, whose 16-bit words it takes as they are (the code
/// shifted up, its low 4 bits zero), not widened.
fn value(code: u32, bits: u32, packing: Packing) -> f32 {
    match packing {
        Packing::Words { shift: 4 } => (code << 4) as f32 * (1.0 / 65535.0),
        _ => raw::widened(code, bits),
    }
}

fn orientation_name(orientation: u16) -> AttributeValue {
    let name = [
        "Left to right, top to bottom",
        "Right to left, top to bottom",
        "Left to right, bottom to top",
        "Right to left, bottom to top",
    ][orientation as usize];
    AttributeValue::Text(exr::meta::attribute::Text::from(name))
}
