//! JPEG images: grey, YCbCr (any chroma sampling) or RGB, CMYK or YCCK
//! (converted to RGB as OpenImageIO converts them), baseline, extended,
//! progressive or arithmetic-coded, with or without restart markers,
//! decoded by libjpeg-turbo's decoder (the `mozjpeg` crate's C build, no
//! SIMD, ISLOW IDCT and fancy upsampling as OpenImageIO 2.4 asks of
//! Debian's libjpeg-turbo): the same code, so the same samples, bit for
//! bit. Rows are decoded in order as asked; a single-scan file keeps a row
//! of MCUs, a progressive or multi-scan one the whole image's coefficients
//! (libjpeg reads every scan before the first row: `resident`).
//! specs/file-format.md, "JPEG".

use super::raw::widened;
use super::stream::{InOrder, Stream};
use super::{Foreign, Format, Rows};
use exr::meta::attribute::{AttributeValue, SampleType};
use mozjpeg::decompress::DecompressStarted;
use mozjpeg::{Decompress, Marker};
use mozjpeg_sys::{jpeg_common_struct, jpeg_error_mgr, J_COLOR_SPACE};
use std::fs::File;
use std::io::BufReader;
use std::ops::Range;
use std::os::raw::c_int;
use std::panic::{catch_unwind, resume_unwind, AssertUnwindSafe};

/// The stream's read buffer.
const BUFFER: usize = 64 << 10;
/// The most a progressive or multi-scan file's coefficients may take (two
/// bytes a coefficient: a 16384 x 16384 4:2:0 image takes 768 MiB).
const MAX_COEFFICIENTS: u64 = 1 << 30;

type Started = DecompressStarted<BufReader<Stream>>;

/// A started decompression. libjpeg's state is plain heap memory that no
/// other object refers to, used by one thread at a time (the `Mutex`).
struct Decoder(Started);
// SAFETY: see `Decoder`: nothing in it is tied to a thread.
unsafe impl Send for Decoder {}

struct Jpeg {
    width: usize,
    height: usize,
    /// What libjpeg is asked for: grey, RGB or CMYK (then made RGB).
    out: J_COLOR_SPACE,
    /// The bytes libjpeg keeps while rows are read (`resident`).
    working: u64,
    rows: InOrder<Decoder>,
}

/// libjpeg's message for the error or warning it is raising.
fn message(cinfo: &mut jpeg_common_struct) -> String {
    let mut buffer = [0u8; 80];
    // SAFETY: `err` is ours (`error_manager`); format_message writes at
    // most JMSG_LENGTH_MAX (80) bytes, NUL included (the binding declares
    // the buffer shared; it is written).
    unsafe {
        if let Some(format) = (*cinfo.err).format_message {
            type Writes = unsafe extern "C-unwind" fn(&mut jpeg_common_struct, &mut [u8; 80]);
            let format: Writes = std::mem::transmute(format);
            format(cinfo, &mut buffer);
        }
    }
    let end = buffer.iter().position(|&b| b == 0).unwrap_or(buffer.len());
    String::from_utf8_lossy(&buffer[..end]).into_owned()
}

/// libjpeg's fatal errors unwind to the `catch_unwind` around the call
/// (`resume_unwind` runs no panic hook: nothing is printed).
extern "C-unwind" fn error_exit(cinfo: &mut jpeg_common_struct) {
    resume_unwind(Box::new(message(cinfo)));
}

/// Warnings of damaged data (a premature end, a corrupt Huffman code, a
/// missing restart marker, extraneous bytes) are fatal too: libjpeg would
/// fill the rest with grey and go on (oiiotool says nothing and writes
/// it). Trace messages and the harmless warnings (an unknown JFIF or Adobe
/// version) are ignored.
extern "C-unwind" fn emit_message(cinfo: &mut jpeg_common_struct, level: c_int) {
    // SAFETY: `err` is ours (`error_manager`).
    let code = unsafe { (*cinfo.err).msg_code };
    let harmless = [mozjpeg_sys::JWRN_ADOBE_XFORM, mozjpeg_sys::JWRN_JFIF_MAJOR];
    if level < 0 && !harmless.contains(&code) {
        resume_unwind(Box::new(message(cinfo)));
    }
}

fn error_manager() -> jpeg_error_mgr {
    // SAFETY: jpeg_std_error fills the struct it is given.
    let mut err: jpeg_error_mgr = unsafe { std::mem::zeroed() };
    unsafe { mozjpeg_sys::jpeg_std_error(&mut err) };
    err.error_exit = Some(error_exit);
    err.emit_message = Some(emit_message);
    err
}

/// Runs `f`, which calls into libjpeg, with its errors as `Err` (the
/// decompression they interrupt is dropped by the caller).
fn guarded<T>(f: impl FnOnce() -> std::io::Result<T>) -> Result<T, String> {
    match catch_unwind(AssertUnwindSafe(f)) {
        Ok(Ok(value)) => Ok(value),
        Ok(Err(e)) => Err(e.to_string()),
        Err(payload) => Err(match payload.downcast::<String>() {
            Ok(text) => *text,
            Err(_) => "the decoder failed".into(),
        }),
    }
}

/// A decompression of `file` with its header read (and its comment and
/// Exif markers kept).
fn header(file: &File) -> Result<Decompress<BufReader<Stream>>, String> {
    let stream = BufReader::with_capacity(BUFFER, Stream::new(file)?);
    guarded(|| {
        Decompress::builder()
            .with_err(error_manager())
            .with_markers(&[Marker::APP(1), Marker::COM])
            .from_reader(stream)
    })
    .map_err(|e| format!("not a readable JPEG: {e}"))
}

/// The colour space libjpeg is asked for, from the file's, and the
/// channels it is read as; other spaces are refused.
fn output(space: J_COLOR_SPACE) -> Result<(J_COLOR_SPACE, &'static [&'static str]), String> {
    use J_COLOR_SPACE::*;
    match space {
        JCS_GRAYSCALE => Ok((JCS_GRAYSCALE, &["Y"])),
        JCS_YCbCr | JCS_RGB => Ok((JCS_RGB, &["R", "G", "B"])),
        // libjpeg makes YCCK CMYK; OpenImageIO makes CMYK RGB.
        JCS_CMYK | JCS_YCCK => Ok((JCS_CMYK, &["R", "G", "B"])),
        other => Err(format!(
            "its colour space ({other:?}) is not one read: grey, YCbCr, RGB, CMYK or YCCK"
        )),
    }
}

/// The coefficients a multi-scan file is read into: each component's
/// blocks, rounded up to its sampling factors, 64 two-byte coefficients.
fn coefficient_bytes(d: &Decompress<BufReader<Stream>>) -> u64 {
    let round = |n: u32, f: i32| (n as u64).div_ceil(f.max(1) as u64) * f.max(1) as u64;
    (d.components().iter())
        .map(|c| {
            round(c.width_in_blocks, c.h_samp_factor) * round(c.height_in_blocks, c.v_samp_factor)
        })
        .sum::<u64>()
        * 128
}

/// Whether the file is decoded through libjpeg's whole-image coefficient
/// buffer: progressive (SOF2, SOF6, SOF10, SOF14), or its first scan holds
/// fewer components than the frame. Read from the markers up to the first
/// scan (libjpeg has read them without error); anything unexpected
/// counts as multi-scan, the larger memory.
fn multi_scan(file: &File, components: usize) -> bool {
    let mut at = 2u64;
    let mut progressive = false;
    for _ in 0..4096 {
        let Ok(bytes) = crate::io::positioned::read_at(file, at, 5) else {
            return true;
        };
        if bytes.len() < 5 || bytes[0] != 0xff {
            return true;
        }
        if bytes[1] == 0xff {
            at += 1; // a fill byte
            continue;
        }
        let length = u16::from_be_bytes([bytes[2], bytes[3]]) as u64;
        match bytes[1] {
            0xda => return progressive || (bytes[4] as usize) < components,
            0xc2 | 0xc6 | 0xca | 0xce => progressive = true,
            _ => {}
        }
        at += 2 + length;
    }
    true
}

/// The Exif orientation (tag 274 of the first directory) of an APP1
/// marker's data, when it has one.
fn orientation(data: &[u8]) -> Option<i32> {
    let tiff = data.strip_prefix(b"Exif\0\0")?;
    let big = match tiff.get(..2)? {
        b"MM" => true,
        b"II" => false,
        _ => return None,
    };
    let u16_at = |at: usize| -> Option<u16> {
        let b: [u8; 2] = tiff.get(at..at + 2)?.try_into().ok()?;
        Some(if big {
            u16::from_be_bytes(b)
        } else {
            u16::from_le_bytes(b)
        })
    };
    let u32_at = |at: usize| -> Option<u32> {
        let b: [u8; 4] = tiff.get(at..at + 4)?.try_into().ok()?;
        Some(if big {
            u32::from_be_bytes(b)
        } else {
            u32::from_le_bytes(b)
        })
    };
    let directory = u32_at(4)? as usize;
    let entries = u16_at(directory)? as usize;
    (0..entries)
        .map(|k| directory + 2 + 12 * k)
        .find(|&entry| u16_at(entry) == Some(274))
        .and_then(|entry| u16_at(entry + 8))
        .map(i32::from)
}

/// OpenImageIO's name of the chroma sampling of a three- or more
/// component file (its first three components' factors).
fn subsampling(d: &Decompress<BufReader<Stream>>) -> Option<&'static str> {
    let c = d.components();
    let factors: Vec<i32> = (c.get(..3)?.iter())
        .flat_map(|c| [c.h_samp_factor, c.v_samp_factor])
        .collect();
    match factors[..] {
        [1, 1, 1, 1, 1, 1] => Some("4:4:4"),
        [2, 1, 1, 1, 1, 1] => Some("4:2:2"),
        [2, 2, 1, 1, 1, 1] => Some("4:2:0"),
        [4, 1, 1, 1, 1, 1] => Some("4:1:1"),
        _ => None,
    }
}

/// The attributes OpenImageIO 2.4 gives a JPEG's header and markers:
/// `oiio:ColorSpace` sRGB, the chroma sampling, a CMYK or YCCK file's
/// colour space, the first comment as `ImageDescription`, the Exif
/// orientation (pixels are not turned, as oiiotool's plain read does not
/// turn them), and the JFIF density as resolution and pixel aspect.
fn attributes(d: &mut Decompress<BufReader<Stream>>) -> Vec<(&'static str, AttributeValue)> {
    let text = super::utf8;
    let mut list = vec![("oiio:ColorSpace", text("sRGB"))];
    match d.color_space() {
        J_COLOR_SPACE::JCS_CMYK => list.push(("jpeg:ColorSpace", text("CMYK"))),
        J_COLOR_SPACE::JCS_YCCK => list.push(("jpeg:ColorSpace", text("YCbCrK"))),
        _ => {}
    }
    if let Some(name) = subsampling(d) {
        list.push(("jpeg:subsampling", text(name)));
    }
    let mut described = false;
    for marker in d.markers() {
        match marker.marker {
            Marker::COM if !described => {
                let end = (marker.data.iter().position(|&b| b == 0)).unwrap_or(marker.data.len());
                list.push((
                    "ImageDescription",
                    text(&String::from_utf8_lossy(&marker.data[..end])),
                ));
                described = true;
            }
            Marker::APP(1) => {
                if let Some(o) = orientation(marker.data) {
                    list.push(("Orientation", AttributeValue::I32(o)));
                }
            }
            _ => {}
        }
    }
    if let Some(density) = d.pixel_density() {
        let (x, y) = (density.x as f32, density.y as f32);
        if x > 1.0 && y > 1.0 {
            list.push(("XResolution", AttributeValue::F32(x)));
            list.push(("YResolution", AttributeValue::F32(y)));
            let unit = match density.unit {
                mozjpeg::PixelDensityUnit::PixelAspectRatio => "none",
                mozjpeg::PixelDensityUnit::Inches => "in",
                mozjpeg::PixelDensityUnit::Centimeters => "cm",
            };
            list.push(("ResolutionUnit", text(unit)));
        }
        // Backwards (x over y), as Nuke, Photoshop and OpenImageIO have it.
        if x > 0.0 && y > 0.0 && x / y != 1.0 {
            list.push(("pixelAspectRatio", AttributeValue::F32(x / y)));
        }
    }
    list
}

/// Opens a JPEG file: its header read and checked (the memory its scans
/// need), its rows decoded on demand.
pub fn open(file: &File, len: u64) -> Result<Foreign, String> {
    let mut d = header(file)?;
    let (width, height) = d.size();
    if width == 0 || height == 0 {
        return Err(format!("its size {width} x {height} is not an image's"));
    }
    let (out, names) = output(d.color_space())?;
    let components = d.components().len();
    // libjpeg's row buffers: a row of MCUs of coefficients and of samples
    // (at most 4 x 8 rows each), upsampled and converted.
    let mut working = (width as u64) * components as u64 * 32 * 6 + BUFFER as u64 + (256 << 10);
    if multi_scan(file, components) {
        let coefficients = coefficient_bytes(&d);
        if coefficients > MAX_COEFFICIENTS {
            return Err(format!(
                "its {width} x {height} progressive (or multi-scan) image needs {coefficients} \
                 bytes of coefficients, over the {MAX_COEFFICIENTS}-byte limit"
            ));
        }
        working += coefficients;
    }
    let header = super::header((width, height), names, SampleType::F16, attributes(&mut d));
    let rows = Jpeg {
        width,
        height,
        out,
        working,
        rows: InOrder::new(None),
    };
    Ok(Foreign {
        format: Format::Jpeg,
        header,
        rows: Box::new(rows),
        header_bytes: len.min(4096) as usize,
    })
}

impl Jpeg {
    /// Components libjpeg gives a pixel.
    fn components(&self) -> usize {
        match self.out {
            J_COLOR_SPACE::JCS_GRAYSCALE => 1,
            J_COLOR_SPACE::JCS_CMYK => 4,
            _ => 3,
        }
    }

    /// A decoded row's pixels into `out` in the header's layout (B, G, R or
    /// Y planes of halfs). CMYK becomes RGB as OpenImageIO makes it: each
    /// of C, M, Y times K in single precision, rounded back to a code.
    fn convert(&self, row: &[u8], out: &mut [u8]) {
        let n = self.components();
        let planes = if n == 1 { 1 } else { 3 };
        for p in 0..planes {
            // Channels sort B, G, R: plane p holds component 2 - p.
            let component = if n == 1 { 0 } else { 2 - p };
            let plane = &mut out[p * self.width * 2..(p + 1) * self.width * 2];
            for (x, sample) in plane.chunks_exact_mut(2).enumerate() {
                let mut code = row[x * n + component] as u32;
                if n == 4 {
                    let k = row[x * n + 3] as f32 / 255.0;
                    let v = (code as f32 / 255.0) * k;
                    code = (v * 255.0 + 0.5).clamp(0.0, 255.0) as u32;
                }
                let value = half::f16::from_f32(widened(code, 8));
                sample.copy_from_slice(&value.to_le_bytes());
            }
        }
    }

    fn start(&self, file: &File) -> Result<Decoder, String> {
        let d = header(file)?;
        let out = self.out;
        guarded(|| d.to_colorspace(out))
            .map(Decoder)
            .map_err(|e| format!("its image data does not decode (damaged or cut short): {e}"))
    }
}

impl Rows for Jpeg {
    fn read(&self, file: &File, rows: Range<usize>) -> Result<Vec<u8>, String> {
        let row_bytes = if self.components() == 1 { 1 } else { 3 } * self.width * 2;
        let mut row = vec![0u8; self.width * self.components()];
        let next = |decoder: &mut Decoder, out: Option<&mut [u8]>| {
            guarded(|| decoder.0.read_scanlines_into(&mut row).map(|_| ())).map_err(|e| {
                format!("its image data does not decode (damaged or cut short): {e}")
            })?;
            if let Some(out) = out {
                self.convert(&row, out);
            }
            Ok(())
        };
        (self.rows).read(rows, (self.height, row_bytes), || self.start(file), next)
    }

    fn sequential(&self) -> bool {
        true
    }

    fn resident(&self) -> u64 {
        self.working
    }
}
