//! Cineon (Kodak's 4.5) images: three channels of 10-bit printing density,
//! pixel-interleaved, three to a 32-bit word from its top (packing 5), in
//! either byte order. Its date, source, device and frame rate become
//! attributes. specs/file-format.md, "Cineon".

use super::raw::{self, Packing, Raw};
use super::{frame_rate, header_bytes, sorted_components, string, Fields, Foreign, Format};
use exr::meta::attribute::{AttributeValue, SampleType, Text};
use std::fs::File;

/// The generic and film headers.
const HEADER: usize = 1024;
/// With the motion-picture film header.
const FILM: usize = 2048;

/// Checks the image information and returns the channels' width, height
/// and names (in the order a pixel stores them).
fn layout(f: &Fields) -> Result<(u64, u64, Vec<&'static str>), String> {
    let count = f.u8(193) as usize;
    let at = |c: usize| 196 + 28 * c;
    let channel = |c: usize| (f.u8(at(c)), f.u8(at(c) + 1), f.u8(at(c) + 2));
    let size = |c: usize| (f.u32(at(c) + 4) as u64, f.u32(at(c) + 8) as u64);
    if count != 3 {
        return Err(format!(
            "it has {count} channels; Cineon files of three (RGB) are read"
        ));
    }
    let mut names = Vec::new();
    for c in 0..count {
        let (metric, designator, bits) = channel(c);
        if bits != 10 {
            return Err(format!(
                "its channel {c} has {bits}-bit samples; 10-bit ones are read"
            ));
        }
        if size(c) != size(0) {
            return Err("its channels differ in size".into());
        }
        names.push(match (metric, designator) {
            (0, 1) => "R",
            (0, 2) => "G",
            (0, 3) => "B",
            _ => {
                return Err(format!(
                    "its channel {c} is designated {metric},{designator}; \
                                     red, green and blue printing density (0,1 0,2 0,3) are read"
                ))
            }
        });
    }
    let mut sorted = names.clone();
    sorted.sort_unstable();
    sorted.dedup();
    if sorted.len() != names.len() {
        return Err("it holds a channel twice".into());
    }
    let (width, height) = size(0);
    if width == 0 || height == 0 || width > 1 << 24 || height > 1 << 24 {
        return Err(format!("its size {width} x {height} is not an image's"));
    }
    Ok((width, height, names))
}

/// The header's fields that become attributes.
fn attributes(f: &Fields, film: bool) -> Vec<(&'static str, AttributeValue)> {
    let date = match (f.text(132, 12), f.text(144, 12)) {
        (Some(d), Some(t)) if d.len() == 10 => t.get(..8).map(|t| format!("{d} {t}")),
        _ => None,
    };
    let mut list = vec![
        Some((
            "cineon:Transfer",
            AttributeValue::Text(Text::from("Printing density")),
        )),
        date.map(|d| ("capDate", super::utf8(&d))),
        string("cineon:SourceImageFileName", f.text(720, 100)),
        string("cineon:InputDevice", f.text(844, 64)),
    ];
    if film {
        list.push(string("cineon:FrameId", f.text(1076, 32)));
        let rate = frame_rate(f.f32(1072));
        list.push(rate.map(|r| ("framesPerSecond", AttributeValue::Rational(r))));
    }
    list.into_iter().flatten().collect()
}

/// Opens a Cineon file of `len` bytes: its header read and checked (sizes
/// against the file's length), its rows read on demand.
pub fn open(file: &File, len: u64) -> Result<Foreign, String> {
    let bytes = header_bytes(file, len, (HEADER, FILM), "Cineon")?;
    let f = Fields {
        big_endian: bytes[0] == 0x80,
        bytes: &bytes,
    };
    let (width, height, names) = layout(&f)?;
    let (orientation, interleave, packing, sign) = (f.u8(192), f.u8(680), f.u8(681), f.u8(682));
    if orientation != 0 {
        return Err(format!(
            "its orientation {orientation} is not read: 0 (left to right, top to bottom) is"
        ));
    }
    if interleave != 0 || packing != 5 || sign != 0 {
        return Err(format!(
            "its storage (interleave {interleave}, packing {packing}, sign {sign}) is not read: \
             unsigned pixel-interleaved samples, three to a 32-bit word (0, 5, 0) are"
        ));
    }
    let offset = f.u32(4) as u64;
    if offset < HEADER as u64 {
        return Err(format!(
            "its pixels start at byte {offset}, inside its {HEADER}-byte header"
        ));
    }
    let packing = Packing::Filled10 {
        pad: 2,
        reversed: false,
    };
    let used = raw::row_bytes(width * names.len() as u64, 10, packing);
    let stride = used + f.u32(684) as u64;
    let end = offset + stride * (height - 1) + used;
    if end > len {
        return Err(format!(
            "truncated Cineon: {width} x {height} pixels end at byte {end} but the file has {len} bytes"
        ));
    }
    let sample = SampleType::F16;
    let rows = Raw {
        first: offset,
        stride,
        width: width as usize,
        height: height as usize,
        components: names.len(),
        bits: 10,
        packing,
        big_endian: f.big_endian,
        bottom_up: false,
        right_to_left: false,
        channels: sorted_components(&names),
        table: raw::table(10, sample, |code| raw::widened(code, 10)),
        sample_bytes: sample.bytes_per_sample(),
    };
    let attributes = attributes(&f, offset >= FILM as u64 && bytes.len() >= FILM);
    Ok(Foreign {
        format: Format::Cineon,
        header: super::header((rows.width, rows.height), &names, sample, attributes),
        rows: Box::new(rows),
        header_bytes: offset.min(1 << 20) as usize,
    })
}
