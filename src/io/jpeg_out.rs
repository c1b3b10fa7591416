//! JPEG review frames, encoded in bands on the pool (specs/file-format.md,
//! "Review media"). The frame is cut into bands of `BAND_MCU_ROWS` rows of
//! MCUs, a fixed height, so the cuts do not depend on the threads; each band
//! is encoded on the pool as a JPEG of its own (the `jpeg-encoder` crate,
//! standard Huffman tables), and the writer thread splices their scans in
//! order under the first band's header, told the frame's height and a
//! restart interval of one band, with an RSTn marker between bands. A
//! decoder restarts the DC prediction at each marker, as each band's
//! encoder started it, so the coefficients are those of the frame encoded
//! whole, and so are the pixels; the bytes are the same at any thread count.

use crate::error::{Error, Result};
use crate::stage_time::{self, Stage};
use crossbeam_channel::{bounded, Receiver};
use std::collections::VecDeque;
use std::io::Write;
use std::sync::Arc;

/// Rows of MCUs a band holds (64 lines at 4:2:0, 32 at 4:4:4): about 20
/// bands in a 1080p frame, and a restart interval (a band's MCUs, at most
/// 8188 across) inside DRI's 16 bits.
const BAND_MCU_ROWS: usize = 4;

/// The longest side of a JPEG libjpeg reads (jmorecfg.h's JPEG_MAX_DIMENSION).
pub const JPEG_MAX_SIDE: usize = 65500;

/// The frame's lines as they arrive: a strip's count and its 8-bit RGB
/// samples; `None` after the last.
pub type Lines<'a> = &'a mut dyn FnMut() -> Result<Option<(usize, Vec<u8>)>>;
type Fail<'a> = &'a dyn Fn(&dyn std::fmt::Display) -> Error;

/// How a frame is encoded: its size, quality, and the lines of its bands.
#[derive(Clone, Copy)]
struct Frame {
    width: u16,
    height: u16,
    quality: u8,
}

impl Frame {
    /// Chroma halved both ways below quality 100, as libjpeg (oiiotool,
    /// cjpeg) does at every quality: the crate's 4:4:4 from quality 90 made
    /// review frames 1.4x oiiotool's at the same quality.
    fn halved(self) -> bool {
        self.quality < 100
    }

    /// Lines of an MCU.
    fn mcu_lines(self) -> usize {
        if self.halved() {
            16
        } else {
            8
        }
    }

    fn band_lines(self) -> usize {
        self.mcu_lines() * BAND_MCU_ROWS
    }

    /// MCUs in a band: the restart interval.
    fn band_mcus(self) -> u16 {
        let across = (self.width as usize).div_ceil(self.mcu_lines());
        (across * BAND_MCU_ROWS) as u16
    }

    fn bands(self) -> usize {
        (self.height as usize).div_ceil(self.band_lines())
    }
}

/// Bands encoding or encoded, not yet written, at most: enough to keep
/// the pool's threads busy, few enough to bound memory.
fn bands_waiting() -> usize {
    rayon::current_num_threads() + 1
}

/// Bytes the writer holds at most for a frame `width` wide at `quality`,
/// from strips of `strip` lines: the lines of the bands waiting and of the
/// one being gathered, and of the strips at either end they pin.
pub fn resident(width: usize, quality: u8, strip: usize) -> u64 {
    let frame = Frame {
        width: width.min(JPEG_MAX_SIDE) as u16,
        height: 1,
        quality,
    };
    let lines = (bands_waiting() + 2) * frame.band_lines() + 2 * strip;
    (lines * width * 3) as u64
}

/// Writes a JPEG frame of `width` x `height` from the strips `next` yields,
/// with `note` (key, text) in a comment segment.
pub fn write_jpeg(
    out: &mut dyn Write,
    quality: u8,
    (width, height): (usize, usize),
    note: (&str, &str),
    next: Lines,
    fail: Fail,
) -> Result<()> {
    let (Ok(width), Ok(height)) = (u16::try_from(width), u16::try_from(height)) else {
        return Err(fail(&format!(
            "{width}x{height} is larger than JPEG's {JPEG_MAX_SIDE} a side"
        )));
    };
    let frame = Frame {
        width,
        height,
        quality,
    };
    let mut spliced = Spliced {
        out,
        frame,
        note,
        written: 0,
    };
    rayon::in_place_scope(|scope| {
        let mut pending = VecDeque::new();
        let most = bands_waiting();
        let mut bands = Bander::new(frame);
        while let Some(band) = bands.next_band(next)? {
            let (done, results) = bounded(1);
            scope.spawn(move |_| {
                let encoded = stage_time::task(Stage::Write, || band.encode());
                // The writer gone (it failed), the band is not wanted.
                let _ = done.send(encoded);
            });
            pending.push_back(results);
            while pending.len() > most {
                if let Some(results) = pending.pop_front() {
                    spliced.band(results, fail)?;
                }
            }
        }
        while let Some(results) = pending.pop_front() {
            spliced.band(results, fail)?;
        }
        spliced.end(fail)
    })
}

/// The frame's rows, cut into bands as the strips arrive.
struct Bander {
    frame: Frame,
    /// Pieces of strips not yet in a band, and their lines.
    pieces: VecDeque<Piece>,
    lines: usize,
    /// Lines received, and whether the strips have ended.
    received: usize,
    ended: bool,
}

impl Bander {
    fn new(frame: Frame) -> Self {
        Bander {
            frame,
            pieces: VecDeque::new(),
            lines: 0,
            received: 0,
            ended: false,
        }
    }

    /// The next band, once its lines have arrived; `None` after the last.
    fn next_band(&mut self, next: Lines) -> Result<Option<Band>> {
        let (height, row_bytes) = (self.frame.height as usize, self.frame.width as usize * 3);
        let wanted = self.frame.band_lines();
        while self.lines < wanted && !self.ended {
            match next()? {
                Some((rows, bytes)) => {
                    if self.received + rows > height || bytes.len() != rows * row_bytes {
                        return Err(Error::internal("more rows than the JPEG's height"));
                    }
                    self.received += rows;
                    self.lines += rows;
                    let strip = Arc::new(bytes);
                    self.pieces.push_back(Piece { strip, from: 0 });
                }
                None if self.received < height => {
                    return Err(Error::internal("a JPEG frame's rows ended early"))
                }
                None => self.ended = true,
            }
        }
        if self.lines == 0 {
            return Ok(None);
        }
        let lines = self.lines.min(wanted);
        let mut band = Band {
            frame: self.frame,
            lines,
            pieces: Vec::new(),
        };
        // Whole pieces while they fit; the rest of the last one stays.
        let mut left = lines * row_bytes;
        while let Some(piece) = self.pieces.front_mut().filter(|_| left > 0) {
            let take = (piece.strip.len() - piece.from).min(left);
            band.pieces.push(Piece {
                strip: piece.strip.clone(),
                from: piece.from,
            });
            left -= take;
            piece.from += take;
            if piece.from == piece.strip.len() {
                self.pieces.pop_front();
            }
        }
        self.lines -= lines;
        Ok(Some(band))
    }
}

/// A strip's rows from byte `from` on.
struct Piece {
    strip: Arc<Vec<u8>>,
    from: usize,
}

/// A band's lines, 8-bit RGB, in the pieces of the strips they arrived in
/// (the first line at the first piece's `from`).
struct Band {
    frame: Frame,
    lines: usize,
    pieces: Vec<Piece>,
}

impl Band {
    /// The band as a JPEG of its own: its header and its scan's bytes.
    fn encode(&self) -> std::result::Result<Encoded, String> {
        let mut file = Vec::new();
        let mut encoder = jpeg_encoder::Encoder::new(&mut file, self.frame.quality);
        if self.frame.halved() {
            encoder.set_sampling_factor(jpeg_encoder::SamplingFactor::R_4_2_0);
        }
        encoder.encode_image(self).map_err(|e| e.to_string())?;
        Encoded::split(file)
    }

    /// Line `y` of the band, RGB.
    fn line(&self, y: usize) -> &[u8] {
        let row_bytes = self.frame.width as usize * 3;
        let mut at = y * row_bytes;
        for piece in &self.pieces {
            let held = piece.strip.len() - piece.from;
            if at < held {
                return &piece.strip[piece.from + at..piece.from + at + row_bytes];
            }
            at -= held;
        }
        unreachable!("a band's line past its pieces")
    }
}

impl jpeg_encoder::ImageBuffer for &Band {
    fn get_jpeg_color_type(&self) -> jpeg_encoder::JpegColorType {
        jpeg_encoder::JpegColorType::Ycbcr
    }

    fn width(&self) -> u16 {
        self.frame.width
    }

    fn height(&self) -> u16 {
        self.lines as u16
    }

    fn fill_buffers(&self, y: u16, buffers: &mut [Vec<u8>; 4]) {
        for pixel in self.line(y as usize).chunks_exact(3) {
            let (luma, cb, cr) = jpeg_encoder::rgb_to_ycbcr(pixel[0], pixel[1], pixel[2]);
            buffers[0].push(luma);
            buffers[1].push(cb);
            buffers[2].push(cr);
        }
    }
}

/// A band encoded as a JPEG: its segments between the start-of-image
/// marker and the start of its scan, the scan's header, and the scan's
/// entropy-coded bytes (without the end-of-image marker).
struct Encoded {
    file: Vec<u8>,
    /// Where the start-of-scan segment begins, and its scan's bytes.
    scan_header: usize,
    scan: usize,
}

impl Encoded {
    fn split(file: Vec<u8>) -> std::result::Result<Encoded, String> {
        let bad = || "the encoder's JPEG has no scan".to_string();
        let mut at = 2;
        while file.get(at) == Some(&0xff) && file.get(at + 1) != Some(&0xda) {
            at += 2 + segment_length(&file, at).ok_or_else(bad)?;
        }
        let scan = at + 2 + segment_length(&file, at).ok_or_else(bad)?;
        match file.ends_with(&[0xff, 0xd9]) && scan + 2 <= file.len() {
            true => Ok(Encoded {
                file,
                scan_header: at,
                scan,
            }),
            false => Err(bad()),
        }
    }

    fn entropy(&self) -> &[u8] {
        &self.file[self.scan..self.file.len() - 2]
    }
}

/// The length of the segment whose marker is at `at` (its length field
/// counts itself, not the marker).
fn segment_length(file: &[u8], at: usize) -> Option<usize> {
    let length = file.get(at + 2..at + 4)?;
    Some(u16::from_be_bytes([length[0], length[1]]) as usize)
}

/// The frame's file, written band by band in order.
struct Spliced<'o, 'n> {
    out: &'o mut dyn Write,
    frame: Frame,
    note: (&'n str, &'n str),
    /// Bands written.
    written: usize,
}

type Results = Receiver<std::result::Result<Encoded, String>>;

impl Spliced<'_, '_> {
    /// Writes the band `results` brings once it is encoded.
    fn band(&mut self, results: Results, fail: Fail) -> Result<()> {
        let encoded = stage_time::wait(Stage::Write, || results.recv())
            .map_err(|_| Error::internal("a JPEG band's encoding stopped"))?
            .map_err(|e| fail(&e))?;
        let io = |e: std::io::Error| fail(&e);
        if self.written == 0 {
            self.header(&encoded).map_err(io)?;
        } else {
            // RSTn, n counting restarts mod 8.
            let n = (self.written - 1) % 8;
            self.out.write_all(&[0xff, 0xd0 + n as u8]).map_err(io)?;
        }
        self.out.write_all(encoded.entropy()).map_err(io)?;
        self.written += 1;
        Ok(())
    }

    /// The first band's header, told the frame's height, with the comment
    /// after the start-of-image marker and, where there is more than one
    /// band, the restart interval before the scan.
    fn header(&mut self, first: &Encoded) -> std::io::Result<()> {
        let file = &first.file;
        let (key, text) = self.note;
        let body = format!("{key}={text}");
        let comment_length = (body.len() + 2) as u16;
        self.out.write_all(&file[..2])?;
        self.out.write_all(&[0xff, 0xfe])?;
        self.out.write_all(&comment_length.to_be_bytes())?;
        self.out.write_all(body.as_bytes())?;
        let mut segments = file[2..first.scan_header].to_vec();
        set_height(&mut segments, self.frame.height)?;
        self.out.write_all(&segments)?;
        if self.frame.bands() > 1 {
            self.out.write_all(&[0xff, 0xdd, 0, 4])?;
            self.out.write_all(&self.frame.band_mcus().to_be_bytes())?;
        }
        self.out.write_all(&file[first.scan_header..first.scan])
    }

    /// Checks every band was written, and ends the image.
    fn end(&mut self, fail: Fail) -> Result<()> {
        if self.written != self.frame.bands() {
            return Err(Error::internal("a JPEG frame's bands are missing"));
        }
        self.out.write_all(&[0xff, 0xd9]).map_err(|e| fail(&e))
    }
}

/// Sets the height in the frame header (SOF0) among `segments`.
fn set_height(segments: &mut [u8], height: u16) -> std::io::Result<()> {
    let mut at = 0;
    while let Some(length) = segment_length(segments, at) {
        if segments[at + 1] == 0xc0 && length >= 7 {
            // FF C0, length (2), precision (1), height (2).
            segments[at + 5..at + 7].copy_from_slice(&height.to_be_bytes());
            return Ok(());
        }
        at += 2 + length;
    }
    Err(std::io::Error::other(
        "the encoder's JPEG has no frame header",
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// An RGB image with detail everywhere (so every band's scan differs).
    fn image(width: usize, height: usize) -> Vec<u8> {
        (0..width * height * 3)
            .map(|i| {
                let (x, y, c) = ((i / 3) % width, i / 3 / width, i % 3);
                ((x * 7 + y * 13 + c * 50) ^ (x * y / 5)) as u8
            })
            .collect()
    }

    /// `pixels` written by `write_jpeg` from strips of `strip` rows.
    fn written(
        pixels: &[u8],
        (width, height): (usize, usize),
        quality: u8,
        strip: usize,
    ) -> Vec<u8> {
        let mut strips = pixels.chunks(width * 3 * strip);
        let mut lines = || {
            Ok(strips
                .next()
                .map(|bytes| (bytes.len() / (width * 3), bytes.to_vec())))
        };
        let mut file = Vec::new();
        let fail = |e: &dyn std::fmt::Display| Error::internal(e.to_string());
        let note = ("key", "text");
        write_jpeg(&mut file, quality, (width, height), note, &mut lines, &fail).unwrap();
        file
    }

    /// The frame encoded whole, as one band: the encoder's stream as it was
    /// written before frames were banded (without the comment).
    fn whole(pixels: &[u8], (width, height): (usize, usize), quality: u8) -> Vec<u8> {
        let band = Band {
            frame: Frame {
                width: width as u16,
                height: height as u16,
                quality,
            },
            lines: height,
            pieces: vec![Piece {
                strip: Arc::new(pixels.to_vec()),
                from: 0,
            }],
        };
        band.encode().unwrap().file
    }

    /// The samples libjpeg-turbo decodes, RGB.
    fn decoded(file: &[u8]) -> Vec<u8> {
        let mut image = mozjpeg::Decompress::new_mem(file).unwrap().rgb().unwrap();
        let samples = image.read_scanlines::<u8>().unwrap();
        image.finish().unwrap();
        samples
    }

    /// Restart markers in a stream: an FF followed by D0..D7.
    fn restarts(file: &[u8]) -> Vec<u8> {
        file.windows(2)
            .filter(|w| w[0] == 0xff && (0xd0..=0xd7).contains(&w[1]))
            .map(|w| w[1] - 0xd0)
            .collect()
    }

    #[test]
    fn bands_decode_to_the_frame_encoded_whole() {
        // 4:2:0 bands of 64 lines, 4:4:4 of 32; heights past a whole number
        // of bands and MCUs, widths past a whole MCU.
        for (size, quality) in [((100, 300), 90), ((37, 150), 100), ((300, 700), 75)] {
            let pixels = image(size.0, size.1);
            let reference = decoded(&whole(&pixels, size, quality));
            let file = written(&pixels, size, quality, 16);
            assert!(decoded(&file) == reference, "{size:?} at {quality}");
            // One marker between bands, counting 0..7 and round again.
            let bands = Frame {
                width: size.0 as u16,
                height: size.1 as u16,
                quality,
            }
            .bands();
            let counted: Vec<u8> = (0..bands - 1).map(|n| (n % 8) as u8).collect();
            assert_eq!(restarts(&file), counted, "{size:?} at {quality}");
            // However the strips cut the rows, the same bytes.
            for strip in [1, 7, 64, 1000] {
                assert!(
                    written(&pixels, size, quality, strip) == file,
                    "strips of {strip}"
                );
            }
        }
    }

    #[test]
    fn a_frame_of_one_band_is_the_encoder_s_stream_with_its_comment() {
        let size = (50, 40);
        let pixels = image(size.0, size.1);
        let reference = whole(&pixels, size, 90);
        let comment = [&[0xff, 0xfe, 0, 10][..], b"key=text"].concat();
        let expected = [&reference[..2], &comment, &reference[2..]].concat();
        assert!(written(&pixels, size, 90, 8) == expected);
        assert!(restarts(&expected).is_empty());
    }

    #[test]
    fn rows_past_the_height_or_short_of_it_fail() {
        let size = (20, 100);
        let pixels = image(size.0, size.1 + 1);
        let fail = |e: &dyn std::fmt::Display| Error::internal(e.to_string());
        for given in [size.1 - 1, size.1 + 1] {
            let mut strips = pixels[..given * 60].chunks(60 * 10);
            let mut lines = || Ok(strips.next().map(|b| (b.len() / 60, b.to_vec())));
            let mut file = Vec::new();
            let result = write_jpeg(&mut file, 90, size, ("k", "t"), &mut lines, &fail);
            assert!(result.is_err(), "{given} rows of {}", size.1);
        }
    }
}
