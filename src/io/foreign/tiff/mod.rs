//! TIFF images: the first image of a file, grey (either photometric), RGB
//! or palette colour, with or without alpha, 8, 16 or 32-bit unsigned or
//! 32-bit float samples, in strips or tiles, uncompressed, LZW (either bit
//! order), Deflate or PackBits (with their predictors), contiguous or
//! planar, top-left orientation. Compressed chunks are decoded a row of
//! strips or tiles at a time, the last one kept for the rows after it;
//! uncompressed strips are read a row at a time. specs/file-format.md, "TIFF".

mod codec;
mod ifd;
mod samples;

use super::{sorted_components, Foreign, Format, Rows};
use crate::io::positioned::read_at;
use exr::meta::attribute::{AttributeValue, Text};
use ifd::Ifd;
use samples::Stored;
use std::fs::File;
use std::ops::Range;
use std::sync::Mutex;

/// Most bytes a row of decoded chunks may take.
const MOST_BAND: usize = 1 << 30;

/// Where a file's chunks are and how their bytes become rows.
struct Chunks {
    width: usize,
    height: usize,
    /// Strip or tile width and height (one row for uncompressed strips,
    /// read a row at a time), and chunks across the width and down a plane.
    size: (usize, usize),
    across: usize,
    down: usize,
    /// Planes stored apart (a planar file's samples), samples in a chunk's
    /// pixel, bytes in a sample.
    planes: usize,
    samples: usize,
    bytes: usize,
    tiled: bool,
    compression: u16,
    predictor: u16,
    big_endian: bool,
    /// Each stored strip or tile: its offset and byte count.
    offsets: Vec<u64>,
    counts: Vec<u64>,
    /// Stored rows in a strip, when uncompressed strips are read by rows.
    rows_per_strip: Option<usize>,
}

struct Tiff {
    chunks: Chunks,
    stored: Stored,
    /// For each channel of the header, in its order, the value it holds.
    channels: Vec<usize>,
    /// The last band decoded: its index and its chunks (planes after one
    /// another, each plane's across the width).
    band: Mutex<Option<(usize, Vec<Vec<u8>>)>>,
}

fn tag(ifd: &Ifd, tag: u16, default: u64) -> Result<u64, String> {
    Ok(ifd.first_unsigned(tag)?.unwrap_or(default))
}

/// The chunk geometry of `ifd`'s image, checked against the file.
fn chunks(ifd: &Ifd, (width, height): (usize, usize), stored: &Stored) -> Result<Chunks, String> {
    let compression = tag(ifd, 259, 1)? as u16;
    if ![1, 5, 8, 32946, 32773].contains(&compression) {
        return Err(format!(
            "its compression {compression} is not read: none, LZW, Deflate and PackBits are"
        ));
    }
    // libtiff applies a predictor with LZW and Deflate only.
    let predictor = match compression {
        5 | 8 | 32946 => tag(ifd, 317, 1)? as u16,
        _ => 1,
    };
    // Horizontal differencing of floats works on their bits, as libtiff's.
    if !matches!((predictor, stored.float()), (1 | 2, _) | (3, true)) {
        return Err(format!(
            "its predictor {predictor} is not read for its samples"
        ));
    }
    let planar = tag(ifd, 284, 1)? == 2 && stored.samples > 1;
    let (planes, samples) = if planar {
        (stored.samples, 1)
    } else {
        (1, stored.samples)
    };
    let tiled = ifd.first_unsigned(322)?.is_some();
    let (size, offsets, counts) = match tiled {
        true => ((tag(ifd, 322, 0)?, tag(ifd, 323, 0)?), 324, 325),
        false => (
            (
                width as u64,
                tag(ifd, 278, height as u64)?.min(height as u64),
            ),
            273,
            279,
        ),
    };
    let size = (size.0 as usize, size.1 as usize);
    if size.0 == 0 || size.1 == 0 || size.0 > 1 << 24 || size.1 > 1 << 24 {
        return Err(format!(
            "its chunks of {} x {} pixels are not read",
            size.0, size.1
        ));
    }
    let (across, down) = (width.div_ceil(size.0), height.div_ceil(size.1));
    let want = planes * across * down;
    // libtiff takes a tiled file's places from the strips' tags as well
    // (the SGI library wrote them there).
    let list = |t: u16| -> Result<Vec<u64>, String> {
        let strips = match t {
            324 => ifd.unsigned(273)?,
            325 => ifd.unsigned(279)?,
            _ => None,
        };
        let v = (ifd.unsigned(t)?.or(strips))
            .ok_or(format!("its tag {t} (chunk places) is missing"))?;
        match v.len() >= want {
            true => Ok(v),
            false => Err(format!("it lists {} chunks of {want}", v.len())),
        }
    };
    let mut chunks = Chunks {
        width,
        height,
        size,
        across,
        down,
        planes,
        samples,
        bytes: stored.bytes,
        tiled,
        compression,
        predictor,
        big_endian: ifd.big_endian,
        offsets: list(offsets)?,
        counts: list(counts)?,
        rows_per_strip: None,
    };
    if !tiled && compression == 1 {
        chunks.rows_per_strip = Some(size.1);
        chunks.size.1 = 1;
        chunks.down = height;
    }
    let band = planes * across * chunks.chunk_bytes();
    if band > MOST_BAND {
        return Err(format!(
            "its rows of chunks take {band} bytes decoded, more than {MOST_BAND}"
        ));
    }
    Ok(chunks)
}

impl Chunks {
    /// Bytes a decoded chunk's row and whole chunk take.
    fn row_bytes(&self) -> usize {
        self.size.0 * self.samples * self.bytes
    }

    fn chunk_bytes(&self) -> usize {
        self.row_bytes() * self.size.1
    }

    /// The stored bytes of the chunk of `plane` at `band`, `column`, and
    /// the rows it holds.
    fn stored(
        &self,
        file: &File,
        plane: usize,
        band: usize,
        column: usize,
    ) -> Result<Vec<u8>, String> {
        let (at, count) = match self.rows_per_strip {
            Some(rps) => {
                let strip = plane * self.height.div_ceil(rps) + band / rps;
                let within = ((band % rps) * self.row_bytes()) as u64;
                let count = self.counts[strip]
                    .saturating_sub(within)
                    .min(self.row_bytes() as u64);
                (self.offsets[strip] + within, count)
            }
            None => {
                let index = (plane * self.down + band) * self.across + column;
                (self.offsets[index], self.counts[index])
            }
        };
        read_at(file, at, count as usize)
    }

    /// The decoded chunks of `band`: every plane's, across the width.
    fn band(&self, file: &File, band: usize) -> Result<Vec<Vec<u8>>, String> {
        let mut out = Vec::with_capacity(self.planes * self.across);
        // A last strip holds the image's last rows only; tiles are whole.
        let rows = match self.tiled {
            true => self.size.1,
            false => self.size.1.min(self.height - band * self.size.1),
        };
        for plane in 0..self.planes {
            for column in 0..self.across {
                let decoded = self.stored(file, plane, band, column).and_then(|stored| {
                    codec::decompress(self.compression, &stored, rows * self.row_bytes())
                });
                let mut chunk = decoded.map_err(|e| {
                    let index = (plane * self.down + band) * self.across + column;
                    format!("its chunk {index} does not decode: {e}")
                })?;
                let row = (self.size.0 * self.samples, self.samples, self.bytes);
                codec::unpredict(self.predictor, &mut chunk, row, self.big_endian);
                out.push(chunk);
            }
        }
        Ok(out)
    }
}

/// The text and resolution tags OpenImageIO keeps, as its attributes, and
/// `oiio:ColorSpace` "sRGB": a TIFF does not say, and sRGB is what the lab's
/// and the art department's TIFFs hold (oiiotool 2.4 reports none; the
/// attribute lets `--from auto` and the next tool know).
fn attributes(ifd: &Ifd) -> Vec<(&'static str, AttributeValue)> {
    let mut list = vec![("oiio:ColorSpace", AttributeValue::Text(Text::from("sRGB")))];
    for (tag, name) in [
        (270, "ImageDescription"),
        (305, "Software"),
        (315, "Artist"),
        (306, "DateTime"),
    ] {
        if let Some(text) = ifd.text(tag).filter(|t| !t.is_empty()) {
            list.push((name, super::utf8(&text)));
        }
    }
    for (tag, name) in [(282, "XResolution"), (283, "YResolution")] {
        if let Some(v) = ifd.rational(tag) {
            list.push((name, AttributeValue::F32(v)));
        }
    }
    let unit = match ifd.first_unsigned(296).ok().flatten() {
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
    let ifd = Ifd::first(file, len)?;
    let (width, height) = (tag(&ifd, 256, 0)? as usize, tag(&ifd, 257, 0)? as usize);
    if width == 0 || height == 0 || width > 1 << 24 || height > 1 << 24 {
        return Err(format!("its size {width} x {height} is not an image's"));
    }
    if let Some(o) = ifd.first_unsigned(274)?.filter(|&o| o != 1) {
        return Err(format!(
            "its orientation {o} is not read: 1 (top left) is; `oiiotool IN --reorient -o OUT` \
             rewrites it"
        ));
    }
    if let Some(f) = ifd.first_unsigned(266)?.filter(|&f| f != 1) {
        return Err(format!(
            "its fill order {f} is not read: 1 (most significant bit first) is"
        ));
    }
    let stored = Stored::new(&ifd)?;
    let chunks = chunks(&ifd, (width, height), &stored)?;
    let names = stored.names();
    let header = super::header(
        (width, height),
        names,
        stored.sample_type(),
        attributes(&ifd),
    );
    let rows = Tiff {
        chunks,
        channels: sorted_components(names),
        stored,
        band: Mutex::new(None),
    };
    Ok(Foreign {
        format: Format::Tiff,
        header,
        rows: Box::new(rows),
        header_bytes: len.min(4096) as usize,
    })
}

impl Tiff {
    /// Writes row `y` into `out` in the header's layout.
    fn convert(&self, chunks: &[Vec<u8>], y: usize, out: &mut [u8]) -> Result<(), String> {
        let c = &self.chunks;
        let width = c.width;
        let size = self.stored.sample_type().bytes_per_sample();
        let cy = y % c.size.1;
        let mut pixel = Vec::with_capacity(4);
        for x in 0..width {
            let (column, cx) = (x / c.size.0, x % c.size.0);
            let at = cy * c.row_bytes() + cx * c.samples * c.bytes;
            let sample = |s: usize| -> Result<&[u8], String> {
                let (chunk, at) = match c.planes {
                    1 => (&chunks[column], at + s * c.bytes),
                    _ => (&chunks[s * c.across + column], at),
                };
                chunk
                    .get(at..at + c.bytes)
                    .ok_or_else(|| "a chunk is short".to_string())
            };
            pixel.clear();
            self.stored.pixel(sample, &mut pixel)?;
            for (k, &v) in self.channels.iter().enumerate() {
                let value = pixel[v];
                let o = &mut out[(k * width + x) * size..(k * width + x + 1) * size];
                match size {
                    2 => o.copy_from_slice(&half::f16::from_f32(value).to_le_bytes()),
                    _ => o.copy_from_slice(&value.to_le_bytes()),
                }
            }
        }
        Ok(())
    }
}

impl Rows for Tiff {
    fn read(&self, file: &File, rows: Range<usize>) -> Result<Vec<u8>, String> {
        let c = &self.chunks;
        if rows.start >= rows.end || rows.end > c.height {
            return Err(format!("rows {rows:?} are outside the image"));
        }
        let size = self.stored.sample_type().bytes_per_sample();
        let out_row = self.channels.len() * c.width * size;
        let mut out = vec![0u8; rows.len() * out_row];
        let mut state = self.band.lock().unwrap_or_else(|e| e.into_inner());
        for (k, y) in rows.enumerate() {
            let band = y / c.size.1;
            if state.as_ref().map(|(b, _)| *b) != Some(band) {
                *state = None;
                *state = Some((band, c.band(file, band)?));
            }
            let (_, chunks) = state.as_ref().expect("a band");
            self.convert(chunks, y, &mut out[k * out_row..(k + 1) * out_row])?;
        }
        Ok(out)
    }

    fn sequential(&self) -> bool {
        // A band is decoded once when its rows are asked in order.
        true
    }

    fn resident(&self) -> u64 {
        let c = &self.chunks;
        let band = c.planes * c.across * c.chunk_bytes();
        // The band, and a chunk's stored bytes and buffers as it decodes.
        (3 * band + (128 << 10)) as u64
    }
}
