//! Review media outputs: PNG, JPEG and TIFF frames, chosen by the output's
//! extension (specs/file-format.md, "Review media"). The encode stage turns
//! each strip of composed rows into display code values (`Media::convert`,
//! in parallel over rows); the write stage streams them into the format's
//! encoder (`write_frame`): PNG's zlib stream and TIFF's strips as the rows
//! arrive, JPEG by bands of MCU rows encoded on the pool (`jpeg_out`), so
//! memory stays flat in the frame's height.

use super::burn_in::Label;
use super::jpeg_out::{self, JPEG_MAX_SIDE};
use crate::error::{Error, Result};
use crate::io::rows::Rows;
use exr::meta::attribute::IntegerBounds;
use rayon::prelude::*;
use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::Path;

/// The file formats exrcomp writes, by the output's extension.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    Exr,
    Png,
    Jpeg,
    Tiff,
    /// DPX for DI and editorial deliveries (`dpx_out`): code values as
    /// they are, not review frames, but written by the same path.
    Dpx,
    /// A review movie (.mov, .mp4), written by `movie.rs`.
    Movie,
}

impl Format {
    /// The format a file name ending so is written in; `None`, one exrcomp
    /// does not write.
    pub fn of(name: &str) -> Option<Format> {
        let name = name.to_ascii_lowercase();
        [
            (".exr", Format::Exr),
            (".png", Format::Png),
            (".jpg", Format::Jpeg),
            (".jpeg", Format::Jpeg),
            (".tif", Format::Tiff),
            (".tiff", Format::Tiff),
            (".dpx", Format::Dpx),
            (".mov", Format::Movie),
            (".mp4", Format::Movie),
        ]
        .into_iter()
        .find(|(end, _)| name.ends_with(end))
        .map(|(_, format)| format)
    }

    fn name(self) -> &'static str {
        match self {
            Format::Exr => "EXR",
            Format::Png => "PNG",
            Format::Jpeg => "JPEG",
            Format::Tiff => "TIFF",
            Format::Dpx => "DPX",
            Format::Movie => "movie",
        }
    }
}

/// Bits per sample of a review frame.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Bits {
    #[value(name = "8")]
    Eight,
    /// 10-bit (DPX, filled method A).
    #[value(name = "10")]
    Ten,
    #[value(name = "16")]
    Sixteen,
    /// 32-bit float (TIFF): scene-linear values as they are.
    Float,
}

/// What turns linear values into a review frame's code values.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Transfer {
    /// The sRGB OETF (IEC 61966-2-1's piecewise curve), clamped to 0..1.
    Srgb,
    /// None: the values are display code values already (after
    /// `ociodisplay`), clamped to 0..1.
    None,
}

/// JPEG quality when `--quality` is not given.
pub const DEFAULT_QUALITY: u8 = 90;

/// How review frames are written: the format and its options.
#[derive(Clone, Debug)]
pub struct Media {
    pub format: Format,
    pub bits: Bits,
    pub quality: u8,
    pub transfer: Transfer,
    /// A movie's codec carries alpha (`Format::Movie`: ProRes 4444).
    pub movie_alpha: bool,
}

impl Media {
    /// The options for `format`, or why they do not apply to it.
    pub fn new(
        format: Format,
        bits: Option<Bits>,
        quality: Option<u8>,
        transfer: Option<Transfer>,
    ) -> std::result::Result<Media, String> {
        let bits = bits.unwrap_or(match format {
            Format::Dpx => Bits::Ten,
            _ => Bits::Eight,
        });
        match (format, bits) {
            (Format::Exr, _) => Err("EXR output keeps its pixel types".to_string()),
            (Format::Dpx, Bits::Eight | Bits::Float) => {
                Err("DPX output takes 10 bits (the default) or 16".to_string())
            }
            (Format::Dpx, _) if transfer.is_some() => Err(
                "--transfer applies to review media: DPX output writes the values as they are \
                 (convert them first, e.g. colorconvert to ADX10)"
                    .to_string(),
            ),
            (_, Bits::Ten) if format != Format::Dpx => {
                Err(format!("{} output does not take 10 bits", format.name()))
            }
            (Format::Jpeg, Bits::Sixteen | Bits::Float) | (Format::Png, Bits::Float) => {
                Err(format!(
                    "{} output takes 8 bits{}",
                    format.name(),
                    match format {
                        Format::Png => " or 16",
                        _ => "",
                    }
                ))
            }
            (_, Bits::Float) if transfer.is_some() => Err(
                "--transfer makes 8 and 16-bit code values; --bits float writes the \
                 scene-linear values as they are"
                    .to_string(),
            ),
            _ if quality.is_some() && format != Format::Jpeg => Err(format!(
                "--quality applies to JPEG output, not {}",
                format.name()
            )),
            _ => Ok(Media {
                format,
                bits,
                quality: quality.unwrap_or(DEFAULT_QUALITY),
                transfer: transfer.unwrap_or(Transfer::Srgb),
                movie_alpha: false,
            }),
        }
    }

    /// A DPX frame's bits per sample.
    pub fn dpx_depth(&self) -> super::dpx_out::Depth {
        match self.bits {
            Bits::Sixteen => super::dpx_out::Depth::Sixteen,
            _ => super::dpx_out::Depth::Ten,
        }
    }

    /// Why a frame of `width` x `height` pixels cannot be written, if it
    /// cannot: JPEG's sizes are 16-bit, but libjpeg (oiiotool, Pillow and
    /// most readers) refuses a side over its JPEG_MAX_DIMENSION, 65500.
    pub fn too_large(&self, (width, height): (usize, usize)) -> Option<String> {
        (self.format == Format::Jpeg && width.max(height) > JPEG_MAX_SIDE).then(|| {
            format!(
                "the result is {width}x{height} pixels, larger than the {JPEG_MAX_SIDE} a side \
                 JPEG readers take (libjpeg's JPEG_MAX_DIMENSION)"
            )
        })
    }

    /// Whether frames keep an alpha channel: PNG and TIFF do when the image
    /// has one; JPEG has none and is written as the image over black (its
    /// premultiplied colour, as oiiotool writes it), nor do movies but
    /// ProRes 4444.
    pub fn keeps_alpha(&self, has_alpha: bool) -> bool {
        has_alpha
            && match self.format {
                Format::Jpeg => false,
                Format::Movie => self.movie_alpha,
                _ => true,
            }
    }

    /// The display code values of `rows`, a strip of the image whose data
    /// window is `window`, interleaved R, G, B (, A) a pixel; `label`, a
    /// burn-in drawn over them.
    pub fn convert(&self, rows: &Rows, window: IntegerBounds, label: Option<&Label>) -> Strip {
        if self.format == Format::Dpx {
            return Strip {
                rows: rows.height,
                samples: Samples::Packed(super::dpx_out::convert(rows, self.dpx_depth())),
            };
        }
        let samples = match self.bits {
            Bits::Eight => {
                Samples::U8(
                    self.code_values(rows, window, label, 255, |v, colour, x, y| {
                        // Colour dithered; alpha rounded. JPEG keeps each
                        // 8x8 block's mean in one coefficient, cheaply, and
                        // a pixel pattern only in the costly others (mostly
                        // quantised away): its dither varies by block.
                        let threshold = match (colour, self.format) {
                            (false, _) => 0.5,
                            (true, Format::Jpeg) => ordered_dither(x / 8, y / 8),
                            (true, _) => ordered_dither(x, y),
                        };
                        (self.encode(v, colour) * 255.0 + threshold).min(255.0) as u8
                    }),
                )
            }
            Bits::Sixteen | Bits::Ten => {
                Samples::U16(
                    self.code_values(rows, window, label, u16::MAX, |v, colour, _, _| {
                        (self.encode(v, colour) * 65535.0 + 0.5) as u16
                    }),
                )
            }
            Bits::Float => Samples::F32(self.code_values(rows, window, label, 1.0, |v, _, _, _| v)),
        };
        Strip {
            rows: rows.height,
            samples,
        }
    }

    /// `convert`'s samples of one type: `quantise(v, colour, x, y)` makes
    /// the sample of value `v` (a colour's, unpremultiplied if alpha is
    /// kept, or alpha's) at (x, y) of the image; `white` is the burn-in's.
    fn code_values<T: Copy + Default + Send + Sync>(
        &self,
        rows: &Rows,
        window: IntegerBounds,
        label: Option<&Label>,
        white: T,
        quantise: impl Fn(f32, bool, usize, usize) -> T + Sync,
    ) -> Vec<T> {
        let index = |name: &str| rows.channel_index(name);
        let luminance = index("Y");
        let sources = ["R", "G", "B"].map(|c| index(c).or(luminance));
        let alpha_plane = index("A");
        let alpha = self.keeps_alpha(alpha_plane.is_some());
        let samples = if alpha { 4 } else { 3 };
        let width = rows.width;
        let x0 = (rows.x - window.position.x()) as usize;
        let mut out = vec![T::default(); width * samples * rows.height];
        out.par_chunks_mut((width * samples).max(1))
            .enumerate()
            .for_each(|(i, row)| {
                let y = rows.y + i as i32;
                let image_y = (y - window.position.y()) as usize;
                let range = rows.row_range(y);
                let mut planes = [(); 4].map(|_| vec![0f32; width]);
                for (plane, source) in planes.iter_mut().zip(sources.iter().chain([&alpha_plane])) {
                    match source {
                        Some(p) => rows.planes[*p].read_f32(range.clone(), plane),
                        None => plane.fill(0.0),
                    }
                }
                if alpha_plane.is_none() {
                    planes[3].fill(1.0);
                }
                let [r, g, b, a] = &planes;
                for (x, &a) in a.iter().enumerate() {
                    let pixel = &mut row[x * samples..(x + 1) * samples];
                    for (c, plane) in [r, g, b].into_iter().enumerate() {
                        let mut v = plane[x];
                        if alpha && a > 0.0 {
                            v /= a;
                        }
                        pixel[c] = quantise(v, true, x0 + x, image_y);
                    }
                    if alpha {
                        pixel[3] = quantise(a, false, x0 + x, image_y);
                    }
                    if let Some(lit) = label.and_then(|l| l.pixel(x0 + x, image_y)) {
                        pixel[..3].fill(if lit { white } else { T::default() });
                        if alpha {
                            pixel[3] = white;
                        }
                    }
                }
            });
        out
    }

    /// A linear colour value (`colour`), or alpha, as a code value, 0..1.
    fn encode(&self, v: f32, colour: bool) -> f32 {
        match (colour, self.transfer) {
            (true, Transfer::Srgb) => srgb_oetf(v.clamp(0.0, 1.0)),
            _ => v.clamp(0.0, 1.0),
        }
    }
}

/// The sRGB encoding of linear `v` in 0..1 (IEC 61966-2-1).
pub fn srgb_oetf(v: f32) -> f32 {
    if v <= 0.003_130_8 {
        12.92 * v
    } else {
        1.055 * v.powf(1.0 / 2.4) - 0.055
    }
}

/// The threshold 8-bit samples are rounded at, in (0, 1): an 8x8 Bayer
/// matrix over the image, so a gradient does not band, and the same pixel
/// of the same image always gets the same code.
fn ordered_dither(x: usize, y: usize) -> f32 {
    const BAYER: [[u8; 8]; 8] = [
        [0, 32, 8, 40, 2, 34, 10, 42],
        [48, 16, 56, 24, 50, 18, 58, 26],
        [12, 44, 4, 36, 14, 46, 6, 38],
        [60, 28, 52, 20, 62, 30, 54, 22],
        [3, 35, 11, 43, 1, 33, 9, 41],
        [51, 19, 59, 27, 49, 17, 57, 25],
        [15, 47, 7, 39, 13, 45, 5, 37],
        [63, 31, 55, 23, 61, 29, 53, 21],
    ];
    (BAYER[y % 8][x % 8] as f32 + 0.5) / 64.0
}

/// Code values of whole rows, interleaved, as the format stores them.
pub enum Samples {
    U8(Vec<u8>),
    U16(Vec<u16>),
    F32(Vec<f32>),
    /// Rows as the file stores them (DPX's packed words).
    Packed(Vec<u8>),
}

/// A strip of converted rows.
pub struct Strip {
    pub rows: usize,
    pub samples: Samples,
}

/// Writes one review frame of `width` x `height` pixels (with alpha or
/// not) from the strips `next` yields, top to bottom (`Ok(None)` ends
/// them), under a temporary name renamed when complete, recording `note`
/// (a key and its text: the frame's fingerprint) where the format keeps
/// text (`note`). An error from `next` abandons the file and is returned
/// as is.
pub fn write_frame(
    path: &Path,
    frame: Option<i64>,
    media: &Media,
    size: (usize, usize),
    alpha: bool,
    note: (&str, &str),
    mut next: impl FnMut() -> Result<Option<Strip>>,
) -> Result<()> {
    let fail = |e: &dyn std::fmt::Display| Error::output(path, frame, e);
    super::writer::write_in_place(path, frame, |out| match media.format {
        Format::Png => write_png(out, media.bits, size, alpha, note, &mut next, &fail),
        Format::Jpeg => {
            let mut lines = || match next()? {
                Some(Strip {
                    rows,
                    samples: Samples::U8(bytes),
                }) => Ok(Some((rows, bytes))),
                Some(_) => Err(Error::internal("a JPEG frame's samples are not 8-bit")),
                None => Ok(None),
            };
            jpeg_out::write_jpeg(out, media.quality, size, note, &mut lines, &fail)
        }
        Format::Tiff => write_tiff(out, media.bits, size, alpha, note, &mut next, &fail),
        Format::Exr | Format::Dpx | Format::Movie => {
            Err(Error::internal("a frame of another format as review media"))
        }
    })
}

/// An 8-bit RGB image, rows top to bottom (the demo's contact sheet, the
/// bench chart).
pub struct Rgb8 {
    pub width: usize,
    pub height: usize,
    /// `width * height` pixels.
    pub pixels: Vec<[u8; 3]>,
}

/// The PNG file of `image`.
pub fn png_file(image: &Rgb8) -> Vec<u8> {
    let mut file = Vec::new();
    let mut encoder = png::Encoder::new(&mut file, image.width as u32, image.height as u32);
    encoder.set_color(png::ColorType::Rgb);
    encoder.set_depth(png::BitDepth::Eight);
    // Only a size of 0 or over 2^31 fails, or a short write, none of which
    // a sheet or chart (margins around whatever they hold) nor a Vec gives.
    let mut writer = encoder.write_header().expect("a PNG header in memory");
    (writer.write_image_data(image.pixels.as_flattened())).expect("PNG pixels in memory");
    writer.finish().expect("a PNG in memory");
    file
}

type Next<'a> = &'a mut dyn FnMut() -> Result<Option<Strip>>;
type Fail<'a> = &'a dyn Fn(&dyn std::fmt::Display) -> Error;

fn write_png(
    out: &mut BufWriter<&File>,
    bits: Bits,
    (width, height): (usize, usize),
    alpha: bool,
    (key, text): (&str, &str),
    next: Next,
    fail: Fail,
) -> Result<()> {
    let mut encoder = png::Encoder::new(out, width as u32, height as u32);
    (encoder.add_text_chunk(key.into(), text.into())).map_err(|e| fail(&e))?;
    encoder.set_color(match alpha {
        true => png::ColorType::Rgba,
        false => png::ColorType::Rgb,
    });
    encoder.set_depth(match bits {
        Bits::Eight => png::BitDepth::Eight,
        _ => png::BitDepth::Sixteen,
    });
    encoder.set_compression(png::Compression::Fast);
    let mut writer = encoder.write_header().map_err(|e| fail(&e))?;
    let mut stream = writer.stream_writer().map_err(|e| fail(&e))?;
    while let Some(strip) = next()? {
        match strip.samples {
            Samples::U8(bytes) => stream.write_all(&bytes),
            Samples::U16(samples) => {
                let bytes: Vec<u8> = samples.iter().flat_map(|s| s.to_be_bytes()).collect();
                stream.write_all(&bytes)
            }
            Samples::F32(_) | Samples::Packed(_) => {
                return Err(Error::internal("float or packed samples for a PNG"))
            }
        }
        .map_err(|e| fail(&e))?;
    }
    stream.finish().map_err(|e| fail(&e))?;
    writer.finish().map_err(|e| fail(&e))
}

/// Rows per TIFF strip.
const TIFF_STRIP_ROWS: usize = 16;

fn write_tiff(
    out: &mut BufWriter<&File>,
    bits: Bits,
    size: (usize, usize),
    alpha: bool,
    note: (&str, &str),
    next: Next,
    fail: Fail,
) -> Result<()> {
    use tiff::encoder::colortype;
    let mut encoder = tiff::encoder::TiffEncoder::new(out).map_err(|e| fail(&e))?;
    match bits {
        Bits::Eight => {
            tiff_image::<colortype::RGB8, _>(&mut encoder, size, alpha, note, next, fail, |s| {
                match s {
                    Samples::U8(v) => Some(v),
                    _ => None,
                }
            })
        }
        Bits::Sixteen | Bits::Ten => {
            tiff_image::<colortype::RGB16, _>(&mut encoder, size, alpha, note, next, fail, |s| {
                match s {
                    Samples::U16(v) => Some(v),
                    _ => None,
                }
            })
        }
        Bits::Float => tiff_image::<colortype::RGB32Float, _>(
            &mut encoder,
            size,
            alpha,
            note,
            next,
            fail,
            |s| match s {
                Samples::F32(v) => Some(v),
                _ => None,
            },
        ),
    }
}

/// One TIFF image of colour type `C` (and alpha, unassociated, as an extra
/// sample), in strips of `TIFF_STRIP_ROWS` rows.
fn tiff_image<C, W>(
    encoder: &mut tiff::encoder::TiffEncoder<W>,
    (width, height): (usize, usize),
    alpha: bool,
    (key, text): (&str, &str),
    next: Next,
    fail: Fail,
    take: fn(Samples) -> Option<Vec<C::Inner>>,
) -> Result<()>
where
    C: tiff::encoder::colortype::ColorType,
    [C::Inner]: tiff::encoder::TiffValue,
    C::Inner: Copy,
    W: Write + std::io::Seek,
{
    let mut image = encoder
        .new_image::<C>(width as u32, height as u32)
        .map_err(|e| fail(&e))?;
    if alpha {
        image
            .extra_samples(&[tiff::tags::ExtraSamples::UnassociatedAlpha])
            .map_err(|e| fail(&e))?;
    }
    image
        .rows_per_strip(TIFF_STRIP_ROWS as u32)
        .map_err(|e| fail(&e))?;
    // TIFF has no key-value text: the description holds `key=text`.
    (image.encoder())
        .write_tag(tiff::tags::Tag::ImageDescription, &*format!("{key}={text}"))
        .map_err(|e| fail(&e))?;
    let row_samples = width * if alpha { 4 } else { 3 };
    let mut held: Vec<C::Inner> = Vec::with_capacity(row_samples * TIFF_STRIP_ROWS);
    let mut done = 0;
    loop {
        let strip = next()?;
        let end = strip.is_none();
        if let Some(strip) = strip {
            let samples = take(strip.samples)
                .ok_or_else(|| Error::internal("TIFF samples of another type"))?;
            held.extend_from_slice(&samples);
        }
        let full = row_samples * TIFF_STRIP_ROWS;
        while held.len() >= full || (end && !held.is_empty()) {
            let take = full.min(held.len());
            image.write_strip(&held[..take]).map_err(|e| fail(&e))?;
            held.drain(..take);
            done += take / row_samples.max(1);
        }
        if end {
            break;
        }
    }
    if done != height {
        return Err(Error::internal(format!(
            "{done} of a TIFF's {height} rows arrived"
        )));
    }
    image.finish().map_err(|e| fail(&e))
}

/// Whether `path` holds a complete review frame of `format`: a PNG or TIFF
/// that decodes whole, a JPEG from its start marker to its end marker
/// (frames are renamed into place only once written whole).
pub fn complete(path: &Path, format: Format) -> bool {
    let Ok(file) = super::reader::open_regular(path) else {
        return false;
    };
    let reader = std::io::BufReader::new(file);
    match format {
        Format::Png => (|| {
            let mut decoder = png::Decoder::new(reader).read_info().ok()?;
            while decoder.next_row().ok()?.is_some() {}
            decoder.finish().ok()
        })()
        .is_some(),
        Format::Tiff => tiff::decoder::Decoder::new(reader)
            .and_then(|mut d| d.read_image())
            .is_ok(),
        Format::Jpeg => std::fs::read(path)
            .is_ok_and(|b| b.starts_with(&[0xff, 0xd8]) && b.ends_with(&[0xff, 0xd9])),
        Format::Dpx => super::dpx_out::complete(path),
        Format::Exr | Format::Movie => false,
    }
}

/// The text a review frame written by `write_frame` records under `key`,
/// if it is there.
pub fn note(path: &Path, format: Format, key: &str) -> Option<String> {
    if format == Format::Dpx {
        return super::dpx_out::note(path, key);
    }
    let file = super::reader::open_regular(path).ok()?;
    let reader = std::io::BufReader::new(file);
    let prefix = format!("{key}=");
    let from = |text: String| text.strip_prefix(&prefix).map(str::to_string);
    match format {
        Format::Png => {
            let decoder = png::Decoder::new(reader).read_info().ok()?;
            let chunks = &decoder.info().uncompressed_latin1_text;
            chunks
                .iter()
                .find(|c| c.keyword == key)
                .map(|c| c.text.clone())
        }
        Format::Tiff => {
            let mut decoder = tiff::decoder::Decoder::new(reader).ok()?;
            from(
                decoder
                    .get_tag_ascii_string(tiff::tags::Tag::ImageDescription)
                    .ok()?,
            )
        }
        Format::Jpeg => jpeg_comments(reader).into_iter().find_map(from),
        Format::Exr | Format::Dpx | Format::Movie => None,
    }
}

/// The comment segments of a JPEG stream, up to its first scan.
fn jpeg_comments(mut reader: impl std::io::Read) -> Vec<String> {
    let mut comments = Vec::new();
    let mut marker = [0u8; 4];
    if reader.read_exact(&mut marker[..2]).is_err() || marker[..2] != [0xff, 0xd8] {
        return comments;
    }
    // Each segment: FF, its kind, a big-endian length counting itself.
    while reader.read_exact(&mut marker).is_ok() && marker[0] == 0xff && marker[1] != 0xda {
        let length = u16::from_be_bytes([marker[2], marker[3]]).saturating_sub(2);
        let mut body = vec![0; length as usize];
        if reader.read_exact(&mut body).is_err() {
            break;
        }
        if marker[1] == 0xfe {
            comments.push(String::from_utf8_lossy(&body).into_owned());
        }
    }
    comments
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_png_file_decodes_to_its_pixels() {
        let image = Rgb8 {
            width: 2,
            height: 1,
            pixels: vec![[255, 0, 0], [0, 0, 255]],
        };
        let file = png_file(&image);
        let mut reader = png::Decoder::new(std::io::Cursor::new(file))
            .read_info()
            .unwrap();
        let mut pixels = vec![0; reader.output_buffer_size().unwrap()];
        let info = reader.next_frame(&mut pixels).unwrap();
        assert_eq!((info.width, info.height), (2, 1));
        assert_eq!(info.color_type, png::ColorType::Rgb);
        assert_eq!(pixels, [255, 0, 0, 0, 0, 255]);
    }
}
