//! DPX and Cineon inputs (specs/file-format.md, "Foreign inputs"): files
//! made here byte by byte (every bit depth and packing, both byte orders,
//! the orientations, timecode and frame rate) read as the formulas say and
//! as oiiotool reads them (`oiiotool IN -d half|float`, compared with
//! `idiff -fail 0`), files oiiotool writes and the shared Nuke DPX and
//! Cineon files against oiiotool, in every kind of job (transcode, info, a
//! sequence, an `over` onto an EXR, a job file), and damaged files refused
//! in one line with nothing written.

use crate::common::{
    limited, missing, peer, read_image, reference_over, run, s, stderr, write_flat, Samples,
};
use half::f16;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::Command;

/// A DPX file to write: one image element.
#[derive(Clone)]
struct Dpx {
    width: usize,
    height: usize,
    /// SMPTE 268M's descriptor: 6 luminance, 50 RGB, 51 RGBA, 52 ABGR.
    descriptor: u8,
    bits: u8,
    /// 0 packed, 1 filled method A, 2 filled method B.
    packing: u16,
    big_endian: bool,
    orientation: u16,
    time_code: u32,
    frame_rate: f32,
    transfer: u8,
    /// Codes in stored order: rows top first in the file, pixels, components.
    codes: Vec<u32>,
}

impl Dpx {
    fn new(width: usize, height: usize, descriptor: u8, bits: u8, packing: u16) -> Dpx {
        let components = components(descriptor);
        let most = (1u64 << bits) - 1;
        let codes = (0..width * height * components)
            .map(|i| ((i as u64 * 2_654_435_761) % (most + 1)) as u32)
            .collect();
        Dpx {
            width,
            height,
            descriptor,
            bits,
            packing,
            big_endian: true,
            orientation: 0,
            time_code: u32::MAX,
            frame_rate: 0.0,
            transfer: 1,
            codes,
        }
    }

    fn u16(&self, v: u16) -> [u8; 2] {
        match self.big_endian {
            true => v.to_be_bytes(),
            false => v.to_le_bytes(),
        }
    }

    fn u32(&self, v: u32) -> [u8; 4] {
        match self.big_endian {
            true => v.to_be_bytes(),
            false => v.to_le_bytes(),
        }
    }

    /// One stored row's bytes, packed as the header says.
    fn row(&self, codes: &[u32]) -> Vec<u8> {
        let words = |words: Vec<u32>| words.iter().flat_map(|w| self.u32(*w)).collect();
        match (self.bits, self.packing) {
            (8, _) => codes.iter().map(|&c| c as u8).collect(),
            (10, 1 | 2) => {
                let pad = if self.packing == 1 { 2 } else { 0 };
                let grey = codes.len() == self.width;
                words(
                    codes
                        .chunks(3)
                        .map(|group| {
                            (group.iter().enumerate()).fold(0, |word, (k, &c)| {
                                // One component: from the bottom of the word (libdpx).
                                let slot = if grey { k } else { 2 - k };
                                word | c << (slot * 10 + pad)
                            })
                        })
                        .collect(),
                )
            }
            (10 | 12, 0) => {
                let bits = self.bits as usize;
                let mut stream = vec![0u32; (codes.len() * bits).div_ceil(32)];
                for (i, &c) in codes.iter().enumerate() {
                    let (at, offset) = (i * bits / 32, i * bits % 32);
                    stream[at] |= c << offset;
                    if offset + bits > 32 {
                        stream[at + 1] |= c >> (32 - offset);
                    }
                }
                words(stream)
            }
            (12, 1) => codes
                .iter()
                .flat_map(|&c| self.u16((c << 4) as u16))
                .collect(),
            _ => codes.iter().flat_map(|&c| self.u16(c as u16)).collect(),
        }
    }

    fn bytes(&self) -> Vec<u8> {
        let offset = 2048usize;
        let mut file = vec![0u8; offset];
        let mut put = |at: usize, bytes: &[u8]| file[at..at + bytes.len()].copy_from_slice(bytes);
        put(0, if self.big_endian { b"SDPX" } else { b"XPDS" });
        put(4, &self.u32(offset as u32));
        put(8, b"V2.0");
        put(24, &self.u32(1664));
        put(28, &self.u32(384));
        put(136, b"2026:12:03:08:15:00:UTC");
        put(160, b"exrcomp's tests");
        put(768, &self.u16(self.orientation));
        put(770, &self.u16(1));
        put(772, &self.u32(self.width as u32));
        put(776, &self.u32(self.height as u32));
        put(
            800,
            &[self.descriptor, self.transfer, self.transfer, self.bits],
        );
        put(804, &self.u16(self.packing));
        put(808, &self.u32(offset as u32));
        put(1628, &self.u32(1));
        put(1632, &self.u32(1));
        put(1724, &self.u32(self.frame_rate.to_bits()));
        put(1920, &self.u32(self.time_code));
        let row = self.width * components(self.descriptor);
        for codes in self.codes.chunks(row) {
            file.extend(self.row(codes));
        }
        file
    }

    fn write(&self, path: &Path) -> PathBuf {
        std::fs::write(path, self.bytes()).unwrap();
        path.to_path_buf()
    }

    /// Channel `name`'s samples as an image's rows top first, as OpenImageIO
    /// converts each code (specs/file-format.md, "Foreign inputs").
    fn expected(&self, name: &str) -> Vec<f32> {
        let names = channel_names(self.descriptor);
        let component = names.iter().position(|n| *n == name).unwrap();
        let (w, h, c) = (self.width, self.height, names.len());
        let mut out = Vec::new();
        for y in 0..h {
            let stored_y = if self.orientation >= 2 { h - 1 - y } else { y };
            for x in 0..w {
                let stored_x = if self.orientation % 2 == 1 {
                    w - 1 - x
                } else {
                    x
                };
                let code = self.codes[(stored_y * w + stored_x) * c + component];
                out.push(value(code, self.bits, self.packing));
            }
        }
        out
    }
}

fn components(descriptor: u8) -> usize {
    channel_names(descriptor).len()
}

fn channel_names(descriptor: u8) -> &'static [&'static str] {
    match descriptor {
        6 => &["Y"],
        50 => &["R", "G", "B"],
        51 => &["R", "G", "B", "A"],
        52 => &["A", "B", "G", "R"],
        _ => panic!("no descriptor {descriptor} in the tests"),
    }
}

/// A code as OpenImageIO's DPX reader gives it, in single precision, then
/// as the sample exrcomp reads it (HALF up to 10 bits).
fn value(code: u32, bits: u8, packing: u16) -> f32 {
    let v = match (bits, packing) {
        (8, _) => code as f32 * (1.0 / 255.0),
        (10, _) => ((code << 6) | (code >> 4)) as f32 * (1.0 / 65535.0),
        (12, 1) => (code << 4) as f32 * (1.0 / 65535.0),
        (12, _) => ((code << 4) | (code >> 8)) as f32 * (1.0 / 65535.0),
        _ => code as f32 * (1.0 / 65535.0),
    };
    match bits <= 10 {
        true => f16::from_f32(v).to_f32(),
        false => v,
    }
}

/// Transcodes `input` to `output`, which must succeed.
pub fn transcode(input: &Path, output: &Path, args: &[&str]) {
    let mut all = vec!["transcode", s(input), "-o", s(output), "-q"];
    all.extend(args);
    let out = run(&all);
    assert!(out.status.success(), "{}", stderr(&out));
}

/// Every channel of `exr` holds, bit for bit, what `dpx` says.
fn assert_reads(dpx: &Dpx, exr: &Path, what: &str) {
    let img = read_image(exr);
    assert_eq!((img.width, img.height), (dpx.width, dpx.height), "{what}");
    let names = channel_names(dpx.descriptor);
    assert_eq!(img.channels.len(), names.len(), "{what}");
    for name in names {
        let samples = &img.channels[*name];
        let expected = dpx.expected(name);
        let float = matches!(samples, Samples::F32(_));
        assert_eq!(float, dpx.bits > 10, "{what}: {name}'s type");
        for (i, want) in expected.iter().enumerate() {
            assert_eq!(
                samples.get_f32(i).to_bits(),
                want.to_bits(),
                "{what}: {name} at pixel {i}: {} instead of {want}",
                samples.get_f32(i)
            );
        }
    }
}

/// Operations that read rows above their own (a blur) or all of them (a
/// quarter turn) read `foreign` as they read `exr`, the EXR made of it
/// (outputs in `dir`).
pub fn reads_as_its_exr(dir: &Path, foreign: &Path, exr: &Path) {
    for args in [
        vec!["blur", "--radius", "5"],
        vec!["transform", "--rotate", "90"],
    ] {
        let from = |input: &Path, name: &str| {
            let output = dir.join(name);
            let mut all = vec![args[0], s(input), "-o", s(&output), "-q"];
            all.extend(&args[1..]);
            let out = run(&all);
            assert!(out.status.success(), "{}", stderr(&out));
            read_image(&output)
        };
        let ours = from(foreign, "from-foreign.exr");
        crate::common::assert_identical(&ours, &from(exr, "from-exr.exr"));
    }
}

/// `oiiotool IN -d half|float -o REF` and `idiff -fail 0 REF OURS`, when
/// both peers are installed.
pub fn assert_as_oiiotool(input: &Path, ours: &Path, float: bool) {
    let (Some(oiiotool), Some(idiff)) = (peer("oiiotool"), peer("idiff")) else {
        return;
    };
    let reference = ours.with_extension("oiiotool.exr");
    let made = Command::new(oiiotool)
        .arg(input)
        .args(["-d", if float { "float" } else { "half" }, "-o"])
        .arg(&reference)
        .output()
        .unwrap();
    assert!(made.status.success(), "{}", stderr(&made));
    let compared = Command::new(idiff)
        .args(["-fail", "0", "-warn", "0"])
        .arg(&reference)
        .arg(ours)
        .output()
        .unwrap();
    assert!(
        compared.status.success(),
        "{} is not read as oiiotool reads it:\n{}",
        input.display(),
        String::from_utf8_lossy(&compared.stdout)
    );
}

#[test]
fn every_bit_depth_packing_and_byte_order_reads_as_openimageio_reads_it() {
    let dir = tempfile::tempdir().unwrap();
    // 66 pixels: no variant ends a row in a word's first of three 10-bit
    // slots, which oiiotool 2.4 reads as 0 (libdpx rounds the row's
    // words down there).
    let variants: &[(u8, &[u16])] = &[(8, &[0]), (10, &[0, 1, 2]), (12, &[0, 1, 2]), (16, &[0])];
    for &(bits, packings) in variants {
        for &packing in packings {
            for descriptor in [6, 50, 51, 52] {
                for big_endian in [true, false] {
                    let what = format!(
                        "{bits}-bit, packing {packing}, descriptor {descriptor}, {}",
                        if big_endian {
                            "big-endian"
                        } else {
                            "little-endian"
                        }
                    );
                    let name = what.replace([',', ' '], "_");
                    let dpx = Dpx {
                        big_endian,
                        ..Dpx::new(66, 5, descriptor, bits, packing)
                    };
                    let input = dpx.write(&dir.path().join(format!("{name}.dpx")));
                    let output = dir.path().join(format!("{name}.exr"));
                    transcode(&input, &output, &[]);
                    assert_reads(&dpx, &output, &what);
                    assert_as_oiiotool(&input, &output, bits > 10);
                }
            }
        }
    }
}

#[test]
fn every_code_of_each_depth_reads_as_openimageio_reads_it() {
    let dir = tempfile::tempdir().unwrap();
    for (bits, packing) in [
        (8, 0),
        (10, 1),
        (10, 2),
        (10, 0),
        (12, 0),
        (12, 1),
        (12, 2),
        (16, 0),
    ] {
        // RGB: whole words of 10-bit codes, however many.
        let count = 1usize << bits;
        let mut dpx = Dpx::new(count.div_ceil(3), 1, 50, bits, packing);
        dpx.codes = (0..dpx.codes.len() as u32)
            .map(|c| c % count as u32)
            .collect();
        let input = dpx.write(&dir.path().join(format!("ramp{bits}-{packing}.dpx")));
        let output = dir.path().join(format!("ramp{bits}-{packing}.exr"));
        transcode(&input, &output, &[]);
        assert_reads(
            &dpx,
            &output,
            &format!("every {bits}-bit code, packing {packing}"),
        );
        assert_as_oiiotool(&input, &output, bits > 10);
    }
}

#[test]
fn orientations_are_applied_and_the_transposed_ones_refused() {
    let dir = tempfile::tempdir().unwrap();
    for orientation in 0..4 {
        let dpx = Dpx {
            orientation,
            ..Dpx::new(9, 4, 50, 10, 1)
        };
        let input = dpx.write(&dir.path().join(format!("o{orientation}.dpx")));
        let output = dir.path().join(format!("o{orientation}.exr"));
        transcode(&input, &output, &[]);
        assert_reads(&dpx, &output, &format!("orientation {orientation}"));
    }
    let transposed = Dpx {
        orientation: 4,
        ..Dpx::new(9, 4, 50, 10, 1)
    };
    let input = transposed.write(&dir.path().join("o4.dpx"));
    let output = dir.path().join("o4.exr");
    let out = run(&["transcode", s(&input), "-o", s(&output)]);
    assert_eq!(out.status.code(), Some(3), "{}", stderr(&out));
    assert!(stderr(&out).contains("orientation 4 (transposed) is not read"));
    assert!(!output.exists());
}

/// The header of `path`'s first part.
fn header(path: &Path) -> exr::meta::header::Header {
    exr::meta::MetaData::read_from_file(path, false)
        .unwrap()
        .headers
        .into_iter()
        .next()
        .unwrap()
}

#[test]
fn timecode_frame_rate_and_transfer_are_kept_and_shown_by_info() {
    let dir = tempfile::tempdir().unwrap();
    let dpx = Dpx {
        time_code: 0x0102_0304,
        frame_rate: 23.976,
        ..Dpx::new(6, 2, 50, 10, 1)
    };
    let input = dpx.write(&dir.path().join("tc.dpx"));
    let output = dir.path().join("tc.exr");
    transcode(&input, &output, &[]);
    let written = header(&output);
    let code = written.shared_attributes.time_code.expect("a timeCode");
    assert_eq!(
        (code.hours, code.minutes, code.seconds, code.frame),
        (1, 2, 3, 4)
    );
    assert_eq!(
        written.own_attributes.frames_per_second,
        Some((24000, 1001))
    );
    let text = |name: &str| {
        let value = written
            .own_attributes
            .other
            .get(&exr::prelude::Text::from(name));
        value.map(|v| format!("{v:?}"))
    };
    assert!(text("dpx:Transfer").unwrap().contains("Printing density"));
    assert!(text("dpx:Creator").unwrap().contains("exrcomp's tests"));
    assert_eq!(written.compression, exr::prelude::Compression::ZIP16);

    let info = run(&["info", s(&input)]);
    assert!(info.status.success(), "{}", stderr(&info));
    let said = String::from_utf8_lossy(&info.stdout);
    for line in [
        "file format: DPX, read as one uncompressed scanline part",
        "dpx:Transfer (type string): \"Printing density\"",
        "framesPerSecond (type rational): 24000/1001",
        "time 01:02:03:04",
        "capDate (type string): \"2026:12:03 08:15:00\"",
        "pixels: all 2 rows decode",
    ] {
        assert!(said.contains(line), "info lacks {line:?}:\n{said}");
    }
    let json = run(&["info", s(&input), "--json"]);
    assert!(String::from_utf8_lossy(&json.stdout).contains("\"format\":\"DPX\""));
}

#[test]
fn a_dpx_sequence_is_read_frame_by_frame() {
    let dir = tempfile::tempdir().unwrap();
    let frames: Vec<Dpx> = (0..3)
        .map(|k| {
            let mut dpx = Dpx::new(12, 6, 50, 10, 1);
            dpx.codes
                .iter_mut()
                .for_each(|c| *c = (*c + 100 * k) % 1024);
            dpx.write(&dir.path().join(format!("scan.{}.dpx", 1001 + k)));
            dpx
        })
        .collect();
    let pattern = dir.path().join("scan.####.dpx");
    let output = dir.path().join("plate.####.exr");
    transcode(&pattern, &output, &[]);
    for (k, dpx) in frames.iter().enumerate() {
        let written = dir.path().join(format!("plate.{}.exr", 1001 + k));
        assert_reads(dpx, &written, &format!("frame {}", 1001 + k));
    }
}

/// An RGBA DPX, `fg.dpx`, and the EXR it reads as, in `dir`.
fn foreground(dir: &Path) -> (PathBuf, PathBuf) {
    let mut dpx = Dpx::new(16, 8, 51, 16, 0);
    // Premultiplied: each colour at most its alpha.
    for pixel in dpx.codes.chunks_mut(4) {
        for c in 0..3 {
            pixel[c] = pixel[c].min(pixel[3]);
        }
    }
    let input = dpx.write(&dir.join("fg.dpx"));
    let read = dir.join("fg.exr");
    transcode(&input, &read, &[]);
    assert_reads(&dpx, &read, "the foreground");
    (input, read)
}

/// A half RGBA EXR background of 16 x 8, `bg.exr`, in `dir`.
fn background(dir: &Path) -> PathBuf {
    let path = dir.join("bg.exr");
    let channels: BTreeMap<String, Samples> = ["A", "B", "G", "R"]
        .iter()
        .enumerate()
        .map(|(c, name)| {
            let v = (0..16 * 8).map(|i| f16::from_f32(((i * 7 + c * 13) % 17) as f32 / 16.0));
            (name.to_string(), Samples::F16(v.collect()))
        })
        .collect();
    write_flat(&path, (16, 8), channels);
    path
}

#[test]
fn a_dpx_composites_over_an_exr() {
    let dir = tempfile::tempdir().unwrap();
    let (fg, fg_read) = foreground(dir.path());
    let bg = background(dir.path());
    let output = dir.path().join("comp.exr");
    let out = run(&["over", s(&fg), s(&bg), "-o", s(&output), "-q"]);
    assert!(out.status.success(), "{}", stderr(&out));
    let expected = reference_over(&read_image(&fg_read), &read_image(&bg), false);
    crate::common::assert_identical(&read_image(&output), &expected);
}

#[test]
fn a_job_file_reads_a_dpx_sequence() {
    let dir = tempfile::tempdir().unwrap();
    let dpx = Dpx::new(10, 4, 6, 12, 2);
    for frame in [1, 2] {
        dpx.write(&dir.path().join(format!("grey.000{frame}.dpx")));
    }
    let job = dir.path().join("job.toml");
    let output = dir.path().join("out.####.exr");
    std::fs::write(
        &job,
        format!(
            "[[node]]\nname = \"in\"\nread = \"{}\"\n\n[[node]]\nname = \"out\"\nwrite = \"{}\"\ninputs = [\"in\"]\n",
            s(&dir.path().join("grey.####.dpx")),
            s(&output)
        ),
    )
    .unwrap();
    let ran = run(&["run", s(&job), "--quiet"]);
    assert!(ran.status.success(), "{}", stderr(&ran));
    for frame in [1, 2] {
        assert_reads(&dpx, &dir.path().join(format!("out.000{frame}.exr")), "job");
    }
}

/// A Cineon file of 10-bit RGB codes, three to a big-endian word.
fn cineon(width: usize, height: usize, codes: &[u32]) -> Vec<u8> {
    let mut file = vec![0u8; 2048];
    let mut put = |at: usize, bytes: &[u8]| file[at..at + bytes.len()].copy_from_slice(bytes);
    put(0, &0x802a_5fd7u32.to_be_bytes());
    put(4, &2048u32.to_be_bytes());
    put(24, b"V4.5");
    put(193, &[3]);
    for c in 0..3 {
        let at = 196 + 28 * c;
        put(at, &[0, c as u8 + 1, 10]);
        put(at + 4, &(width as u32).to_be_bytes());
        put(at + 8, &(height as u32).to_be_bytes());
    }
    put(681, &[5]);
    put(1072, &24.0f32.to_be_bytes());
    for pixel in codes.chunks(3) {
        let word = pixel[0] << 22 | pixel[1] << 12 | pixel[2] << 2;
        file.extend(word.to_be_bytes());
    }
    file
}

#[test]
fn a_cineon_file_reads_as_its_codes() {
    let dir = tempfile::tempdir().unwrap();
    let (w, h) = (11, 3);
    let codes: Vec<u32> = (0..w * h * 3).map(|i| (i as u32 * 337) % 1024).collect();
    let input = dir.path().join("scan.cin");
    std::fs::write(&input, cineon(w, h, &codes)).unwrap();
    let output = dir.path().join("scan.exr");
    transcode(&input, &output, &[]);
    let img = read_image(&output);
    for (c, name) in ["R", "G", "B"].iter().enumerate() {
        for i in 0..w * h {
            let want = value(codes[i * 3 + c], 10, 1);
            assert_eq!(img.channels[*name].get_f32(i).to_bits(), want.to_bits());
        }
    }
    assert_eq!(
        header(&output).own_attributes.frames_per_second,
        Some((24, 1))
    );
    assert_as_oiiotool(&input, &output, false);
}

/// `../shared/foreign-images`, or `None` (a skipped check).
pub fn foreign_images() -> Option<PathBuf> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/foreign-images");
    if root.is_dir() {
        return Some(root);
    }
    missing(&format!(
        "the foreign image set {} is absent",
        root.display()
    ));
    None
}

#[test]
fn nuke_dpx_and_cineon_files_read_as_oiiotool_reads_them() {
    let Some(root) = foreign_images() else {
        return;
    };
    shared_files_as_oiiotool(
        &root,
        &["dpx/dpx_nuke_10bits_rgb.dpx", "cineon/checker.cin"],
    );
}

/// Each of `files` (under the foreign image set `root`) transcoded equals
/// oiiotool's reading of it, and `info` reads it.
pub fn shared_files_as_oiiotool(root: &Path, files: &[&str]) {
    let dir = tempfile::tempdir().unwrap();
    for file in files {
        let input = root.join(file);
        let output = dir
            .path()
            .join(Path::new(file).with_extension("exr").file_name().unwrap());
        transcode(&input, &output, &[]);
        assert_as_oiiotool(&input, &output, false);
        let info = run(&["info", s(&input)]);
        assert!(info.status.success(), "{}", stderr(&info));
    }
}

#[test]
fn files_oiiotool_writes_read_as_it_reads_them() {
    let Some(oiiotool) = peer("oiiotool") else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let pattern =
        "fill:topleft=0,0,0,0:topright=1,0.2,0.5,0.3:bottomleft=0.3,1,0.7,1:bottomright=1,1,1,0.6";
    for depth in ["uint8", "uint10", "uint12", "uint16"] {
        for channels in ["0", "0,1,2", "0,1,2,3"] {
            let input = dir.path().join(format!("{depth}-{}.dpx", channels.len()));
            let made = Command::new(&oiiotool)
                .args([
                    "--pattern",
                    pattern,
                    "66x13",
                    "4",
                    "--ch",
                    channels,
                    "-d",
                    depth,
                    "-o",
                ])
                .arg(&input)
                .output()
                .unwrap();
            assert!(made.status.success(), "{}", stderr(&made));
            let output = input.with_extension("exr");
            transcode(&input, &output, &[]);
            assert_as_oiiotool(&input, &output, depth == "uint12" || depth == "uint16");
        }
    }
}

#[test]
fn damaged_files_are_refused_in_one_line_and_nothing_is_written() {
    let dir = tempfile::tempdir().unwrap();
    let good = Dpx::new(64, 32, 50, 10, 1).bytes();
    let at = |mut bytes: Vec<u8>, offset: usize, patch: &[u8]| {
        bytes[offset..offset + patch.len()].copy_from_slice(patch);
        bytes
    };
    let cases: Vec<(&str, Vec<u8>, &str)> = vec![
        ("cut", good[..good.len() - 100].to_vec(), "truncated DPX"),
        (
            "header",
            good[..1000].to_vec(),
            "less than its 1664-byte header",
        ),
        (
            "wide",
            at(good.clone(), 772, &0x00ff_ffffu32.to_be_bytes()),
            "truncated DPX",
        ),
        (
            "tall",
            at(good.clone(), 776, &u32::MAX.to_be_bytes()),
            "is not an image's",
        ),
        (
            "descriptor",
            at(good.clone(), 800, &[100]),
            "descriptor 100",
        ),
        (
            "bits",
            at(good.clone(), 803, &[32]),
            "32-bit samples are not read",
        ),
        (
            "elements",
            at(good.clone(), 770, &2u16.to_be_bytes()),
            "2 image elements",
        ),
        (
            "encoded",
            at(good.clone(), 806, &1u16.to_be_bytes()),
            "run-length",
        ),
        (
            "offset",
            at(good.clone(), 808, &16u32.to_be_bytes()),
            "inside its 1664-byte header",
        ),
        (
            "cineon",
            cineon(1 << 20, 1 << 20, &[0; 3]),
            "truncated Cineon",
        ),
    ];
    assert_refused(dir.path(), "dpx", cases);
}

#[test]
fn memory_stays_flat_in_a_dpx_plates_height() {
    let dir = tempfile::tempdir().unwrap();
    // Peak resident memory and the dry run's bound of a transcode of a
    // 512-wide 10-bit plate `height` rows tall. The short one is tall
    // enough to fill the pipeline's channels (at 1024 rows they are not
    // yet full: 16 MiB against a plateau of 23-27, as for an EXR input).
    let measure = |height: usize| {
        let mut dpx = Dpx::new(512, height, 50, 10, 1);
        dpx.codes = (0..dpx.codes.len() as u32)
            .map(|i| (i * 7) % 1024)
            .collect();
        let input = dpx.write(&dir.path().join(format!("tall{height}.dpx")));
        let output = dir.path().join(format!("tall{height}.exr"));
        let dry = run(&["transcode", s(&input), "-o", s(&output), "--dry-run"]);
        assert!(dry.status.success(), "{}", stderr(&dry));
        let ran = run(&["transcode", s(&input), "-o", s(&output), "--json", "-q"]);
        assert!(ran.status.success(), "{}", stderr(&ran));
        let summary: serde_json::Value = serde_json::from_slice(&ran.stdout).unwrap();
        let peak = summary["peak_rss_bytes"].as_u64().unwrap();
        (peak, crate::common::memory_bound(&dry))
    };
    let (short, short_bound) = measure(4096);
    let (tall, tall_bound) = measure(16384);
    assert_eq!(short_bound, tall_bound, "the bound grows with the height");
    assert!(
        tall <= tall_bound && short <= short_bound,
        "{short} {tall} over {tall_bound}"
    );
    assert!(
        tall < short * 3 / 2,
        "peak grew from {short} to {tall} bytes with 4x the rows"
    );
}

/// Each damaged file (`name`, its bytes, what the message says) refused by
/// transcode and info: exit 3, one line naming the file, nothing written.
pub fn assert_refused(dir: &Path, ext: &str, cases: Vec<(&str, Vec<u8>, &str)>) {
    for (name, bytes, says) in cases {
        let input = dir.join(format!("{name}.{ext}"));
        std::fs::write(&input, bytes).unwrap();
        let output = dir.join(format!("{name}.exr"));
        for args in [
            vec!["transcode", s(&input), "-o", s(&output)],
            vec!["info", s(&input)],
        ] {
            let out = limited(&args);
            let said = stderr(&out);
            assert_eq!(out.status.code(), Some(3), "{name}: {said}");
            assert!(said.contains(says), "{name}: {said}");
            assert!(said.contains(s(&input)), "{name} is not named: {said}");
            assert_eq!(said.trim_end().lines().count(), 1, "{name}: {said}");
            assert!(!output.exists(), "{name}: an output was written");
        }
    }
}
