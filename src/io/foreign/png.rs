//! PNG images: grey, grey and alpha, RGB, RGBA or palette, of 1 to 16 bits,
//! not interlaced, decoded row by row from the file's deflate stream (the
//! `png` crate's streaming reader; the decoder's state is a window of 32
//! KiB and two rows, whatever the height). Samples become what OpenImageIO
//! 2.4's reader gives (alpha associated as it associates it), its colour
//! space a string attribute. specs/file-format.md, "PNG".

use super::raw::widened;
use super::stream::{InOrder, Stream};
use super::{sorted_components, Foreign, Format, Rows};
use exr::meta::attribute::{AttributeValue, SampleType};
use png::{BitDepth, Transformations};
use std::fs::File;
use std::io::BufReader;
use std::ops::Range;

/// The stream's read buffer.
const BUFFER: usize = 64 << 10;
/// Deflate's greatest expansion (a 258-byte match in about two bits): a
/// file whose rows would need more is cut short or lying about its size.
const INFLATE_RATIO: u64 = 1032;

type Reader = png::Reader<BufReader<Stream>>;

struct Png {
    width: usize,
    height: usize,
    /// Samples a decoded pixel holds (grey 1, grey and alpha 2, RGB 3,
    /// RGBA 4), and their bits (8 or 16, after expansion).
    components: usize,
    bits: u32,
    /// For each channel of the header, in its order, its component.
    channels: Vec<usize>,
    sample: SampleType,
    /// The file's gamma as OpenImageIO rounds it (1 without gAMA): how alpha
    /// is associated.
    gamma: f32,
    rows: InOrder<Reader>,
}

/// A reader of `file` past its header, expanding palettes, transparency
/// chunks and depths under 8 bits (as libpng's `png_set_expand`).
fn reader(file: &File) -> Result<Reader, String> {
    let stream = BufReader::with_capacity(BUFFER, Stream::new(file)?);
    let mut decoder = png::Decoder::new(stream);
    decoder.set_transformations(Transformations::EXPAND);
    decoder
        .read_info()
        .map_err(|e| format!("not a readable PNG: {e}"))
}

/// Opens a PNG file of `len` bytes: its header read and checked (its size
/// against what its length can hold), its rows decoded on demand.
pub fn open(file: &File, len: u64) -> Result<Foreign, String> {
    let reader = reader(file)?;
    let info = reader.info();
    let (width, height) = (info.width as usize, info.height as usize);
    if width == 0 || height == 0 || width > 1 << 24 || height > 1 << 24 {
        return Err(format!("its size {width} x {height} is not an image's"));
    }
    if info.interlaced {
        return Err(
            "it is interlaced (Adam7), which is not read: its rows are not stored in order; \
             save it without interlacing"
                .into(),
        );
    }
    let stored = height as u64 * (info.raw_row_length() as u64);
    if stored > INFLATE_RATIO * len {
        return Err(format!(
            "truncated PNG: {width} x {height} pixels need {stored} bytes, more than its {len} bytes \
             can inflate to"
        ));
    }
    let (color, depth) = reader.output_color_type();
    let components = color.samples();
    let names: &[&str] = match components {
        1 => &["Y"],
        2 => &["Y", "A"],
        3 => &["R", "G", "B"],
        _ => &["R", "G", "B", "A"],
    };
    let bits = if depth == BitDepth::Sixteen { 16 } else { 8 };
    // 8-bit codes are apart in half; 16-bit ones would merge (as DPX's).
    let sample = if bits == 16 {
        SampleType::F32
    } else {
        SampleType::F16
    };
    let (attributes, gamma) = attributes(info);
    let attributes = attributes.iter().map(|(n, v)| (n.as_str(), v.clone()));
    let mut header = super::header((width, height), names, sample, attributes.collect());
    if let Some((x, y)) = pixel_offset(file)? {
        if x.checked_add(width as i32).is_none() || y.checked_add(height as i32).is_none() {
            return Err(format!("its oFFs origin {x}, {y} puts pixels beyond 2^31"));
        }
        header.own_attributes.layer_position = exr::math::Vec2(x, y);
    }
    let rows = Png {
        width,
        height,
        components,
        bits,
        channels: sorted_components(names),
        sample,
        gamma,
        rows: InOrder::new(Some(reader)),
    };
    Ok(Foreign {
        format: Format::Png,
        header,
        rows: Box::new(rows),
        header_bytes: len.min(4096) as usize,
    })
}

/// The image's origin from an oFFs chunk in pixels (before the image
/// data), which OpenImageIO takes as the data window's origin (the display
/// window stays at 0, 0; an offset in micrometres it ignores). The png
/// crate does not parse the chunk: the chunks are walked here.
fn pixel_offset(file: &File) -> Result<Option<(i32, i32)>, String> {
    let mut at = 8u64;
    // A bound on the walk: a file of more chunks than this is not a PNG's.
    for _ in 0..100_000 {
        let Ok(head) = crate::io::positioned::read_at(file, at, 8) else {
            break;
        };
        if matches!(&head[4..8], b"IDAT" | b"IEND") {
            break;
        }
        let length = u32::from_be_bytes(head[..4].try_into().expect("4 bytes")) as u64;
        if &head[4..8] == b"oFFs" && length == 9 {
            let data = crate::io::positioned::read_at(file, at + 8, 9)?;
            let int = |i: usize| i32::from_be_bytes(data[i..i + 4].try_into().expect("4 bytes"));
            return Ok((data[8] == 0).then(|| (int(0), int(4))));
        }
        at += 12 + length;
    }
    Ok(None)
}

/// OpenImageIO's `%.2g` of a gamma (2.2, 1.8, 2, 0.45).
fn two_digits(g: f32) -> String {
    let decimals = (1 - g.abs().log10().floor() as i32).max(0) as usize;
    let text = format!("{g:.decimals$}");
    match text.contains('.') {
        true => text.trim_end_matches('0').trim_end_matches('.').to_string(),
        false => text,
    }
}

/// The attributes OpenImageIO 2.4 gives the file's chunks, and the gamma
/// it associates alpha with: `oiio:ColorSpace` ("sRGB" with an sRGB chunk
/// or none, "linear" or "GammaG" from a gAMA chunk), resolution, pixel
/// aspect and the text chunks of known keywords.
fn attributes(info: &png::Info) -> (Vec<(String, AttributeValue)>, f32) {
    let text = super::utf8;
    let mut list = Vec::new();
    let gamma = match (&info.srgb, info.gama_chunk) {
        (None, Some(g)) if g.into_scaled() > 0 => {
            let g = (1.0 / (g.into_scaled() as f64 / 100_000.0)) as f32;
            let g = (100.0 * g).round() / 100.0;
            let name = match g == 1.0 {
                true => "linear".to_string(),
                false => format!("Gamma{}", two_digits(g)),
            };
            list.push(("oiio:ColorSpace".to_string(), text(&name)));
            g
        }
        _ => {
            list.push(("oiio:ColorSpace".to_string(), text("sRGB")));
            1.0
        }
    };
    if let Some(dims) = &info.pixel_dims {
        let (scale, unit) = match dims.unit {
            png::Unit::Meter => (2.54 / 100.0, "inch"),
            png::Unit::Unspecified => (1.0, "none"),
        };
        let resolution = |ppu: u32| AttributeValue::F32((ppu as f32 as f64 * scale) as f32);
        list.push(("XResolution".into(), resolution(dims.xppu)));
        list.push(("YResolution".into(), resolution(dims.yppu)));
        list.push(("ResolutionUnit".into(), text(unit)));
        let aspect = dims.yppu as f32 / dims.xppu as f32;
        if dims.xppu > 0 && aspect != 0.0 && aspect != 1.0 {
            list.push(("pixelAspectRatio".into(), AttributeValue::F32(aspect)));
        }
    }
    let texts = (info.uncompressed_latin1_text.iter()).map(|t| (&t.keyword, t.text.clone()));
    let utf8 = (info.utf8_text.iter()).filter_map(|t| Some((&t.keyword, t.get_text().ok()?)));
    for (keyword, value) in texts.chain(utf8) {
        let name = match keyword.to_ascii_lowercase().as_str() {
            "description" => "ImageDescription",
            "author" => "Artist",
            "title" => "DocumentName",
            "software" => "Software",
            "copyright" => "Copyright",
            "comment" => "Comment",
            // Others could collide with OpenEXR's own attribute names.
            _ => continue,
        };
        list.push((name.to_string(), text(&value)));
    }
    (list, gamma)
}

impl Png {
    /// Code `component` of pixel `x` of a decoded row.
    fn code(&self, row: &[u8], x: usize, component: usize) -> u32 {
        let i = x * self.components + component;
        match self.bits {
            16 => u16::from_be_bytes([row[2 * i], row[2 * i + 1]]) as u32,
            _ => row[i] as u32,
        }
    }

    /// Colour code `v` associated with alpha code `a` as OpenImageIO's PNG
    /// reader does, in integers: `v a / max` rounded down, or with a gamma
    /// `v (a / max)^gamma` in single precision, rounded down.
    fn associate(&self, v: u32, a: u32) -> u32 {
        let max = (1u32 << self.bits) - 1;
        if self.gamma == 1.0 {
            return v * a / max;
        }
        let inverse = (1.0 / max as f64) as f32;
        (v as f32 * (a as f32 * inverse).powf(self.gamma)) as u32
    }

    /// Writes a decoded row's pixels into `out` in the header's layout.
    fn convert(&self, row: &[u8], out: &mut [u8]) {
        let size = self.sample.bytes_per_sample();
        let alpha = matches!(self.components, 2 | 4).then_some(self.components - 1);
        for (c, &component) in self.channels.iter().enumerate() {
            let plane = &mut out[c * self.width * size..(c + 1) * self.width * size];
            for (x, sample) in plane.chunks_exact_mut(size).enumerate() {
                let mut v = self.code(row, x, component);
                if let Some(a) = alpha.filter(|&a| a != component) {
                    v = self.associate(v, self.code(row, x, a));
                }
                let value = widened(v, self.bits);
                match self.sample {
                    SampleType::F16 => {
                        sample.copy_from_slice(&half::f16::from_f32(value).to_le_bytes())
                    }
                    _ => sample.copy_from_slice(&value.to_le_bytes()),
                }
            }
        }
    }
}

impl Rows for Png {
    fn read(&self, file: &File, rows: Range<usize>) -> Result<Vec<u8>, String> {
        let row_bytes = self.channels.len() * self.width * self.sample.bytes_per_sample();
        let next = |reader: &mut Reader, out: Option<&mut [u8]>| {
            let row = reader
                .next_row()
                .map_err(|e| format!("its image data does not decode (damaged or cut short): {e}"))?
                .ok_or("its image data ends before its last row")?;
            if let Some(out) = out {
                self.convert(row.data(), out);
            }
            Ok(())
        };
        (self.rows).read(rows, (self.height, row_bytes), || reader(file), next)
    }

    fn sequential(&self) -> bool {
        true
    }

    fn resident(&self) -> u64 {
        // The read buffer, the inflater's window and output buffer, the
        // current and previous rows as stored and as expanded.
        let row = (self.width * self.components * self.bits as usize / 8) as u64;
        BUFFER as u64 + (128 << 10) + 4 * row
    }
}

#[cfg(test)]
mod tests {
    use super::two_digits;

    #[test]
    fn gammas_are_named_as_printf_g_names_them() {
        assert_eq!(two_digits(2.2), "2.2");
        assert_eq!(two_digits(2.0), "2");
        assert_eq!(two_digits(1.8), "1.8");
        assert_eq!(two_digits(0.45), "0.45");
        assert_eq!(two_digits(10.0), "10");
    }
}
