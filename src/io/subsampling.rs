//! Subsampled channels (OpenEXR's luminance/chroma images: `Y` at every
//! pixel, `RY` and `BY` at every second pixel of every second line).
//!
//! The exr crate refuses any sampling but 1 1 when it parses a header, and
//! sizes blocks as if every channel had a sample per pixel. So the header is
//! parsed with the sampling fields read as 1 1 (`Unsampled`), the real
//! sampling is set back on the parsed channels (`restore`) with OpenEXR's own
//! rules checked, and block sizes follow OpenEXR's: a channel of sampling
//! `xs ys` has samples at the pixels whose absolute x and y are multiples of
//! `xs` and `ys`, so a line `y` holds samples of it only when `y % ys == 0`.
//! The crate's codecs lay subsampled channels out that way already; they are
//! handed the block's true size (`codec_header`).

use super::b44;
use super::standard_attributes::Attribute;
use exr::math::Vec2;
use exr::meta::attribute::{ChannelDescription, ChannelList, IntegerBounds, SampleType, Text};
use exr::meta::header::Header;
use exr::meta::{BlockDescription, MetaData};
use exr::prelude::Compression;
use std::borrow::Cow;
use std::fs::File;
use std::io::Read;
use std::os::unix::fs::FileExt;

/// A channel whose sampling is not 1 1, as its file declares it.
#[derive(Clone, Debug)]
pub struct Sampled {
    part: usize,
    channel: Text,
    sampling: Vec2<usize>,
    /// Where its x sampling field lies in the file (the y field follows).
    at: u64,
}

/// The subsampled channels of every `chlist` attribute among `attributes`
/// (read from `file`). A list too damaged to walk is left to the parse.
pub fn find(file: &File, attributes: &[Attribute]) -> Vec<Sampled> {
    let mut found = Vec::new();
    for list in attributes.iter().filter(|a| a.kind == "chlist") {
        let mut bytes = vec![0; list.size.min(1 << 20) as usize];
        if file.read_exact_at(&mut bytes, list.at).is_err() {
            continue;
        }
        let mut at = 0;
        // name\0, pixel type (4), linear (1), reserved (3), x and y sampling (4 + 4)
        while let Some(end) = bytes[at..].iter().position(|&b| b == 0) {
            if end == 0 || at + end + 17 > bytes.len() {
                break;
            }
            let name = &bytes[at..at + end];
            let field = at + end + 9;
            let int = |i: usize| i32::from_le_bytes(bytes[i..i + 4].try_into().expect("4 bytes"));
            let (xs, ys) = (int(field), int(field + 4));
            if (xs, ys) != (1, 1) && xs > 0 && ys > 0 {
                found.push(Sampled {
                    part: list.part,
                    channel: Text::from_slice_unchecked(name),
                    sampling: Vec2(xs as usize, ys as usize),
                    at: list.at + field as u64,
                });
            }
            at = field + 8;
        }
    }
    found
}

/// A reader of the file from its start that reads each subsampled channel's
/// sampling as 1 1, for the exr crate's parser.
pub struct Unsampled<'a, R> {
    pub inner: R,
    pub at: u64,
    pub sampled: &'a [Sampled],
}

impl<R: Read> Read for Unsampled<'_, R> {
    fn read(&mut self, buf: &mut [u8]) -> std::io::Result<usize> {
        let n = self.inner.read(buf)?;
        let (start, end) = (self.at, self.at + n as u64);
        for s in self.sampled {
            for (k, byte) in [1u8, 0, 0, 0, 1, 0, 0, 0].into_iter().enumerate() {
                let i = s.at + k as u64;
                if (start..end).contains(&i) {
                    buf[(i - start) as usize] = byte;
                }
            }
        }
        self.at = end;
        Ok(n)
    }
}

/// Sets the sampling of `sampled` back on the parsed headers and checks
/// OpenEXR's rules for it (ImfHeader.cpp's sanityCheck): flat scanline parts
/// only, and the data window's origin and size multiples of it.
pub fn restore(meta: &mut MetaData, sampled: &[Sampled]) -> Result<(), String> {
    for s in sampled {
        let Some(header) = meta.headers.get_mut(s.part) else {
            continue;
        };
        let name = s.channel.to_string();
        let window = header.data_window();
        let Some(channel) = header
            .channels
            .list
            .iter_mut()
            .find(|c| c.name == s.channel)
        else {
            continue;
        };
        channel.sampling = s.sampling;
        if header.deep || header.blocks.has_tiles() {
            return Err(format!(
                "channel {name} has sampling {} {}: OpenEXR allows subsampling in flat scanline parts only",
                s.sampling.x(),
                s.sampling.y()
            ));
        }
        let (xs, ys) = (s.sampling.x() as i64, s.sampling.y() as i64);
        let divides = i64::from(window.position.x()) % xs == 0
            && i64::from(window.position.y()) % ys == 0
            && window.size.width() as i64 % xs == 0
            && window.size.height() as i64 % ys == 0;
        if !divides {
            return Err(format!(
                "channel {name} has sampling {xs} {ys}, which does not divide the data window's \
                 origin ({} {}) and size ({} x {}), as OpenEXR requires",
                window.position.x(),
                window.position.y(),
                window.size.width(),
                window.size.height()
            ));
        }
    }
    Ok(())
}

/// Whether any channel of `header` is subsampled.
pub fn any(header: &Header) -> bool {
    header
        .channels
        .list
        .iter()
        .any(|c| c.sampling != Vec2(1, 1))
}

/// `headers` with every sampling 1 1 (for the exr crate's validation, which
/// refuses any other); the rules for the real ones are `restore`'s.
pub fn unsampled(headers: &[Header]) -> Cow<'_, [Header]> {
    if !headers.iter().any(any) {
        return Cow::Borrowed(headers);
    }
    let mut headers = headers.to_vec();
    for header in &mut headers {
        header
            .channels
            .list
            .iter_mut()
            .for_each(|c| c.sampling = Vec2(1, 1));
    }
    Cow::Owned(headers)
}

/// How many multiples of `step` lie in `start..end` (OpenEXR's numSamples).
pub fn count(step: usize, start: i32, end: i32) -> usize {
    let step = step as i64;
    let below = |v: i64| v.div_euclid(step);
    (below(i64::from(end) - 1) - below(i64::from(start) - 1)).max(0) as usize
}

/// Whether absolute line `y` holds samples of a channel of y sampling `ys`.
pub fn holds_line(ys: usize, y: i32) -> bool {
    i64::from(y).rem_euclid(ys as i64) == 0
}

/// The bytes of the pixels of `rect` (absolute) of a flat block.
pub fn block_bytes(channels: &ChannelList, rect: IntegerBounds) -> usize {
    let (x0, y0) = (rect.position.x(), rect.position.y());
    let (x1, y1) = (rect.end().x(), rect.end().y());
    channels
        .list
        .iter()
        .map(|c| {
            count(c.sampling.x(), x0, x1)
                * count(c.sampling.y(), y0, y1)
                * c.sample_type.bytes_per_sample()
        })
        .sum()
}

/// A header for the exr crate's codecs on block `rect` (absolute) of a part
/// with subsampled channels: the crate sizes a block as its area times the
/// channel list's bytes per pixel, so that is set to what makes the block's
/// true size. None when no whole number does (the block cannot go through
/// the crate).
fn codec_header(header: &Header, rect: IntegerBounds) -> Option<Header> {
    let bytes = block_bytes(&header.channels, rect);
    let area = rect.size.area();
    if area == 0 || !bytes.is_multiple_of(area) {
        return None;
    }
    let mut channels = header.channels.clone();
    channels.bytes_per_pixel = bytes / area;
    let mut codec = Header::new(
        Text::from("codec"),
        header.layer_size,
        channels.list.clone(),
    );
    codec.channels = channels;
    codec.compression = header.compression;
    codec.blocks = BlockDescription::ScanLines;
    codec.own_attributes.layer_position = header.own_attributes.layer_position;
    Some(codec)
}

fn is_b44(compression: Compression) -> bool {
    matches!(compression, Compression::B44 | Compression::B44A)
}

fn codec(header: &Header, rect: IntegerBounds) -> Result<Header, String> {
    codec_header(header, rect).ok_or_else(|| {
        format!(
            "{} blocks of these subsampled channels cannot be coded (their size is not a whole \
             number of bytes per pixel); zip, zips, rle and none can",
            header.compression
        )
    })
}

/// Decompresses block `rect` (absolute) of a part with subsampled channels
/// (not ZIP: see `zip`), little-endian bytes in, native out. The crate's
/// B44 lays subsampled channels out at full resolution (a panic, or wrong
/// samples): B44 is unpacked by `b44`, or kept when stored raw.
pub fn decompress(
    header: &Header,
    packed: Vec<u8>,
    rect: IntegerBounds,
) -> Result<Vec<u8>, String> {
    if is_b44(header.compression) {
        return match packed.len() == block_bytes(&header.channels, rect) {
            true => Ok(packed),
            false => b44_decompress(&header.channels, &packed, rect),
        };
    }
    let codec = codec(header, rect)?;
    header
        .compression
        .decompress_image_section_from_le(&codec, packed, rect, false)
        .map_err(|e| e.to_string())
}

/// Each channel's samples across and down in block `rect` (absolute), for
/// `b44`; an error for a pLinear channel, whose B44 is not implemented.
fn b44_planes(channels: &ChannelList, rect: IntegerBounds) -> Result<Vec<b44::Plane>, String> {
    if let Some(c) = channels.list.iter().find(|c| c.quantize_linearly) {
        return Err(format!(
            "B44 of subsampled channels with a perceptually linear channel ({}) is not supported",
            c.name
        ));
    }
    let (x0, y0, x1, y1) = (
        rect.position.x(),
        rect.position.y(),
        rect.end().x(),
        rect.end().y(),
    );
    Ok(channels
        .list
        .iter()
        .map(|c| b44::Plane {
            nx: count(c.sampling.x(), x0, x1),
            ny: count(c.sampling.y(), y0, y1),
            bytes: c.sample_type.bytes_per_sample(),
        })
        .collect())
}

/// Walks the lines of block `rect` (absolute): for each channel holding
/// samples on a line, `each(channel, bytes of its samples there)`.
fn walk_lines(
    channels: &ChannelList,
    planes: &[b44::Plane],
    rect: IntegerBounds,
    mut each: impl FnMut(usize, usize),
) {
    for y in rect.position.y()..rect.end().y() {
        for (k, (plane, c)) in planes.iter().zip(&channels.list).enumerate() {
            if holds_line(c.sampling.y(), y) {
                each(k, plane.nx * plane.bytes);
            }
        }
    }
}

/// B44 block `rect` (absolute) of `channels` unpacked (`b44`) and laid out
/// as OpenEXR's uncompressed block: line after line, on each the channels
/// that hold samples on it.
fn b44_decompress(
    channels: &ChannelList,
    packed: &[u8],
    rect: IntegerBounds,
) -> Result<Vec<u8>, String> {
    let planes = b44_planes(channels, rect)?;
    let samples = b44::decompress(&planes, packed)?;
    let mut out = Vec::with_capacity(block_bytes(channels, rect));
    let mut at = vec![0; planes.len()];
    walk_lines(channels, &planes, rect, |k, n| {
        out.extend_from_slice(&samples[k][at[k]..at[k] + n]);
        at[k] += n;
    });
    Ok(out)
}

/// Block `rect` (absolute) of `channels` (OpenEXR's uncompressed layout)
/// packed as B44, or B44A when `flat`; kept raw when that is not smaller.
fn b44_compress(
    channels: &ChannelList,
    data: Vec<u8>,
    rect: IntegerBounds,
    flat: bool,
) -> Result<Vec<u8>, String> {
    let planes = b44_planes(channels, rect)?;
    let mut samples: Vec<Vec<u8>> = planes
        .iter()
        .map(|p| Vec::with_capacity(p.nx * p.ny * p.bytes))
        .collect();
    let mut at = 0;
    walk_lines(channels, &planes, rect, |k, n| {
        samples[k].extend_from_slice(&data[at..at + n]);
        at += n;
    });
    let packed = b44::compress(&planes, &samples, flat);
    Ok(if packed.len() < data.len() {
        packed
    } else {
        data
    })
}

/// Compresses block `rect` (absolute) of a part with subsampled channels
/// (not ZIP: see `zip`).
pub fn compress(header: &Header, data: Vec<u8>, rect: IntegerBounds) -> Result<Vec<u8>, String> {
    if is_b44(header.compression) {
        let flat = header.compression == Compression::B44A;
        return b44_compress(&header.channels, data, rect, flat);
    }
    let codec = codec(header, rect)?;
    let raw = data.len();
    let packed = header
        .compression
        .compress_image_section_to_le(&codec, data.clone(), rect)
        .map_err(|e| e.to_string())?;
    if header.compression != Compression::PXR24 || packed.len() == raw {
        return Ok(packed);
    }
    // The crate's PXR24 deflates a buffer sized for every channel at full
    // resolution, the subsampled samples followed by zeros. OpenEXR reads
    // that, but it is not the format: deflated again without the zeros.
    let width = |c: &ChannelDescription| match c.sample_type {
        SampleType::F16 => 2,
        SampleType::F32 => 3,
        SampleType::U32 => 4,
    };
    let full: usize = codec.channels.list.iter().map(width).sum::<usize>() * rect.size.area();
    let (x0, y0, x1, y1) = (
        rect.position.x(),
        rect.position.y(),
        rect.end().x(),
        rect.end().y(),
    );
    let true_size: usize = codec
        .channels
        .list
        .iter()
        .map(|c| width(c) * count(c.sampling.x(), x0, x1) * count(c.sampling.y(), y0, y1))
        .sum();
    let mut inflated = vec![0; full];
    let n = libdeflater::Decompressor::new()
        .zlib_decompress(&packed, &mut inflated)
        .map_err(|e| format!("PXR24 re-deflate: {e}"))?;
    if n < true_size {
        return Err(format!("PXR24 block of {n} bytes, {true_size} expected"));
    }
    let mut out = Vec::new();
    super::deflate::zlib_compress(&inflated[..true_size], PXR24_LEVEL, &mut out);
    Ok(if out.len() < raw { out } else { data })
}

/// libdeflate's level for re-deflated PXR24 blocks (zlib's default level 6
/// compresses about as well).
const PXR24_LEVEL: u8 = 6;

#[cfg(test)]
mod tests {
    use super::count;

    #[test]
    fn counts_samples_as_openexr() {
        assert_eq!(count(2, 0, 4), 2);
        assert_eq!(count(2, 1, 2), 0);
        assert_eq!(count(2, 2, 3), 1);
        assert_eq!(count(2, -4, 0), 2);
        assert_eq!(count(2, -3, -2), 0);
        assert_eq!(count(1, 5, 9), 4);
        assert_eq!(count(3, 0, 7), 3);
    }
}
