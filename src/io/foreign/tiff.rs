//! TIFF images: the first image of a file, grey or RGB with or without
//! alpha, 8 or 16-bit unsigned or 32-bit float samples, in strips or tiles,
//! uncompressed, LZW, Deflate or PackBits (with their predictors),
//! contiguous or planar, top-left orientation. Decoded a row of strips or
//! tiles at a time (the `tiff` crate's chunk reader), the last one kept for
//! the rows after it. specs/file-format.md, "TIFF".

use super::raw::widened;
use super::stream::Stream;
use super::{sorted_components, Foreign, Format, Rows};
use exr::meta::attribute::{AttributeValue, SampleType, Text};
use std::fs::File;
use std::io::BufReader;
use std::ops::Range;
use std::sync::Mutex;
use tiff::decoder::{Decoder, DecodingResult};
use tiff::tags::Tag;
use tiff::ColorType;

type TiffDecoder = Decoder<BufReader<Stream>>;

/// The decoder and the last row of chunks it decoded: its index and each
/// chunk's samples (planes after one another for a planar file).
struct State {
    decoder: TiffDecoder,
    band: Option<(usize, Vec<DecodingResult>)>,
}

struct Tiff {
    width: usize,
    height: usize,
    components: usize,
    planar: bool,
    /// Strip or tile width and height, and chunks across the width.
    chunk: (usize, usize),
    across: usize,
    /// Chunks in one plane (all of a contiguous file's).
    per_plane: usize,
    channels: Vec<usize>,
    sample: SampleType,
    /// Alpha stored unassociated: multiplied into the colours.
    unassociated: bool,
    state: Mutex<State>,
}

fn decoder(file: &File) -> Result<TiffDecoder, String> {
    let stream = BufReader::with_capacity(64 << 10, Stream::new(file)?);
    Decoder::new(stream).map_err(|e| format!("not a readable TIFF: {e}"))
}

fn tag_u32(d: &mut TiffDecoder, tag: Tag) -> Result<Option<u32>, String> {
    d.find_tag_unsigned::<u32>(tag)
        .map_err(|e| format!("its {tag:?} tag is not readable: {e}"))
}

/// Checks what the file's first image stores and returns its channels
/// (in the order a pixel stores them) and its sample type.
fn layout(d: &mut TiffDecoder) -> Result<(&'static [&'static str], SampleType, bool), String> {
    let color = d
        .colortype()
        .map_err(|e| format!("its pixels are not read: {e}"))?;
    let photometric = tag_u32(d, Tag::PhotometricInterpretation)?.unwrap_or(1);
    let (names, bits): (&'static [&'static str], u8) = match (photometric, color) {
        (1, ColorType::Gray(b)) => (&["Y"], b),
        (1, ColorType::GrayA(b)) => (&["Y", "A"], b),
        (2, ColorType::RGB(b)) => (&["R", "G", "B"], b),
        (2, ColorType::RGBA(b)) => (&["R", "G", "B", "A"], b),
        (photometric, color) => {
            return Err(format!(
                "its pixels ({color:?}, photometric interpretation {photometric}) are not read: \
                 grey (min-is-black) and RGB, with or without alpha, are"
            ))
        }
    };
    // One per sample; they are alike in the classes read.
    let format = d
        .find_tag_unsigned_vec::<u16>(Tag::SampleFormat)
        .map_err(|e| format!("its SampleFormat tag is not readable: {e}"))?
        .and_then(|f| f.first().copied())
        .unwrap_or(1);
    let sample = match (format, bits) {
        (1, 8) => SampleType::F16,
        (1, 16) | (3, 32) => SampleType::F32,
        _ => {
            return Err(format!(
                "its {bits}-bit samples of format {format} are not read: 8 and 16-bit unsigned \
                 integers and 32-bit floats are"
            ))
        }
    };
    let compression = tag_u32(d, Tag::Compression)?.unwrap_or(1);
    if ![1, 5, 8, 32946, 32773].contains(&compression) {
        return Err(format!(
            "its compression {compression} is not read: none, LZW, Deflate and PackBits are"
        ));
    }
    if let Some(o) = tag_u32(d, Tag::Orientation)?.filter(|&o| o != 1) {
        return Err(format!(
            "its orientation {o} is not read: 1 (top left) is; `oiiotool IN --reorient -o OUT` \
             rewrites it"
        ));
    }
    let extra = d
        .find_tag_unsigned_vec::<u16>(Tag::ExtraSamples)
        .map_err(|e| format!("its ExtraSamples tag is not readable: {e}"))?;
    let unassociated = extra.is_some_and(|e| e.first() == Some(&2));
    Ok((names, sample, unassociated))
}

/// The text and resolution tags OpenImageIO keeps, as its attributes, and
/// `oiio:ColorSpace` "sRGB": a TIFF does not say, and sRGB is what the lab's
/// and the art department's TIFFs hold (oiiotool 2.4 reports none; the
/// attribute lets `--from auto` and the next tool know).
fn attributes(d: &mut TiffDecoder) -> Vec<(&'static str, AttributeValue)> {
    let mut list = vec![("oiio:ColorSpace", AttributeValue::Text(Text::from("sRGB")))];
    for (tag, name) in [
        (Tag::ImageDescription, "ImageDescription"),
        (Tag::Software, "Software"),
        (Tag::Artist, "Artist"),
        (Tag::DateTime, "DateTime"),
    ] {
        if let Ok(Some(tiff::decoder::ifd::Value::Ascii(text))) = d.find_tag(tag) {
            let text = text.trim_end_matches('\0');
            if !text.is_empty() {
                list.push((name, super::utf8(text)));
            }
        }
    }
    for (tag, name) in [
        (Tag::XResolution, "XResolution"),
        (Tag::YResolution, "YResolution"),
    ] {
        if let Ok(Some(tiff::decoder::ifd::Value::Rational(n, d))) = d.find_tag(tag) {
            if d > 0 {
                list.push((name, AttributeValue::F32(n as f32 / d as f32)));
            }
        }
    }
    let unit = match tag_u32(d, Tag::ResolutionUnit).ok().flatten() {
        Some(1) => Some("none"),
        Some(3) => Some("cm"),
        Some(2) => Some("inch"),
        _ => None,
    };
    if let Some(unit) = unit.filter(|_| list.iter().any(|(n, _)| *n == "XResolution")) {
        list.push(("ResolutionUnit", AttributeValue::Text(Text::from(unit))));
    }
    list
}

/// Opens a TIFF file: its first image's tags read and checked, its rows
/// decoded on demand a row of chunks at a time.
pub fn open(file: &File, len: u64) -> Result<Foreign, String> {
    let mut d = decoder(file)?;
    let (width, height) = d
        .dimensions()
        .map_err(|e| format!("not a readable TIFF: {e}"))?;
    let (width, height) = (width as usize, height as usize);
    if width == 0 || height == 0 || width > 1 << 24 || height > 1 << 24 {
        return Err(format!("its size {width} x {height} is not an image's"));
    }
    let (names, sample, unassociated) = layout(&mut d)?;
    let planar = tag_u32(&mut d, Tag::PlanarConfiguration)?.unwrap_or(1) == 2;
    let (cw, ch) = d.chunk_dimensions();
    let chunk = (cw.max(1) as usize, ch.max(1) as usize);
    let across = width.div_ceil(chunk.0);
    let per_plane = across * height.div_ceil(chunk.1);
    let header = super::header((width, height), names, sample, attributes(&mut d));
    let rows = Tiff {
        width,
        height,
        components: names.len(),
        planar,
        chunk,
        across,
        per_plane,
        channels: sorted_components(names),
        sample,
        unassociated,
        state: Mutex::new(State {
            decoder: d,
            band: None,
        }),
    };
    Ok(Foreign {
        format: Format::Tiff,
        header,
        rows: Box::new(rows),
        header_bytes: len.min(4096) as usize,
    })
}

/// Sample `i` of a decoded chunk as a value: 8 and 16-bit codes as
/// OpenImageIO converts them, floats as they are.
fn value(chunk: &DecodingResult, i: usize) -> f32 {
    match chunk {
        DecodingResult::U8(v) => widened(v[i] as u32, 8),
        DecodingResult::U16(v) => widened(v[i] as u32, 16),
        DecodingResult::F32(v) => v[i],
        _ => 0.0,
    }
}

fn length(chunk: &DecodingResult) -> usize {
    match chunk {
        DecodingResult::U8(v) => v.len(),
        DecodingResult::U16(v) => v.len(),
        DecodingResult::F32(v) => v.len(),
        _ => 0,
    }
}

impl Tiff {
    /// Decodes the chunks of band `band` (a row of strips or tiles), every
    /// plane's.
    fn band(&self, d: &mut TiffDecoder, band: usize) -> Result<Vec<DecodingResult>, String> {
        let planes = if self.planar { self.components } else { 1 };
        let mut chunks = Vec::with_capacity(planes * self.across);
        for plane in 0..planes {
            for column in 0..self.across {
                let index = plane * self.per_plane + band * self.across + column;
                let chunk = d
                    .read_chunk(index as u32)
                    .map_err(|e| format!("its chunk {index} does not decode: {e}"))?;
                chunks.push(chunk);
            }
        }
        Ok(chunks)
    }

    /// Component `c` of pixel `x` of row `y` (inside band's chunks).
    fn component(
        &self,
        chunks: &[DecodingResult],
        y: usize,
        x: usize,
        c: usize,
    ) -> Result<f32, String> {
        let (column, cx) = (x / self.chunk.0, x % self.chunk.0);
        let cy = y % self.chunk.1;
        let chunk_width = self.chunk.0.min(self.width - column * self.chunk.0);
        let (chunk, per_pixel, at) = match self.planar {
            true => (&chunks[c * self.across + column], 1, 0),
            false => (&chunks[column], self.components, c),
        };
        let i = (cy * chunk_width + cx) * per_pixel + at;
        if i >= length(chunk) {
            return Err("a chunk decodes to fewer samples than its size".into());
        }
        Ok(value(chunk, i))
    }

    /// Writes row `y` into `out` in the header's layout.
    fn convert(&self, chunks: &[DecodingResult], y: usize, out: &mut [u8]) -> Result<(), String> {
        let size = self.sample.bytes_per_sample();
        let alpha = matches!(self.components, 2 | 4).then_some(self.components - 1);
        for (k, &c) in self.channels.iter().enumerate() {
            let plane = &mut out[k * self.width * size..(k + 1) * self.width * size];
            for (x, sample) in plane.chunks_exact_mut(size).enumerate() {
                let mut v = self.component(chunks, y, x, c)?;
                if let Some(a) = alpha.filter(|&a| a != c && self.unassociated) {
                    v *= self.component(chunks, y, x, a)?;
                }
                match self.sample {
                    SampleType::F16 => {
                        sample.copy_from_slice(&half::f16::from_f32(v).to_le_bytes())
                    }
                    _ => sample.copy_from_slice(&v.to_le_bytes()),
                }
            }
        }
        Ok(())
    }
}

impl Rows for Tiff {
    fn read(&self, _file: &File, rows: Range<usize>) -> Result<Vec<u8>, String> {
        if rows.start >= rows.end || rows.end > self.height {
            return Err(format!("rows {rows:?} are outside the image"));
        }
        let out_row = self.channels.len() * self.width * self.sample.bytes_per_sample();
        let mut out = vec![0u8; rows.len() * out_row];
        let mut state = self.state.lock().unwrap_or_else(|e| e.into_inner());
        let state = &mut *state;
        for (k, y) in rows.enumerate() {
            let band = y / self.chunk.1;
            if state.band.as_ref().map(|(b, _)| *b) != Some(band) {
                state.band = None;
                let chunks = self.band(&mut state.decoder, band)?;
                state.band = Some((band, chunks));
            }
            let (_, chunks) = state.band.as_ref().expect("a band");
            self.convert(chunks, y, &mut out[k * out_row..(k + 1) * out_row])?;
        }
        Ok(out)
    }

    fn sequential(&self) -> bool {
        // A band is decoded once when its rows are asked in order.
        true
    }

    fn resident(&self) -> u64 {
        // Decoded samples of 1, 2 or 4 bytes: counted as 4.
        let bytes = 4;
        let band = self.across * self.chunk.0 * self.chunk.1 * self.components * bytes;
        // The band, and a chunk's compressed bytes and buffers as it decodes.
        (2 * band + (128 << 10)) as u64
    }
}
