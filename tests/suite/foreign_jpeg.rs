//! JPEG inputs (specs/file-format.md, "JPEG"): files written here with the
//! `jpeg-encoder` crate (grey, YCbCr in every chroma sampling, CMYK and
//! YCCK, baseline and progressive, restart intervals, odd sizes) read as
//! oiiotool reads them (`oiiotool IN -d half`, `idiff -fail 0`), the
//! shared JPEG against oiiotool, the header's metadata as OpenImageIO
//! names it, a sequence and a job, and damaged files refused in one line
//! with nothing written.

use crate::common::{read_image, run, s, stderr};
use crate::foreign_inputs::{
    assert_as_oiiotool, assert_refused, foreign_images, shared_files_as_oiiotool, transcode,
};
use jpeg_encoder::{ColorType, Encoder, PixelDensity, PixelDensityUnit, SamplingFactor};
use std::path::{Path, PathBuf};

/// A JPEG to write.
struct Jpeg {
    width: u16,
    height: u16,
    color: ColorType,
    sampling: SamplingFactor,
    quality: u8,
    progressive: bool,
    restart: Option<u16>,
    density: Option<PixelDensity>,
    exif: Option<Vec<u8>>,
    comment: Option<&'static str>,
    /// Added to every sample (frames of a sequence differ).
    shift: u8,
}

impl Jpeg {
    fn new(width: u16, height: u16, color: ColorType) -> Jpeg {
        Jpeg {
            width,
            height,
            color,
            sampling: SamplingFactor::F_2_2,
            quality: 90,
            progressive: false,
            restart: None,
            density: None,
            exif: None,
            comment: None,
            shift: 0,
        }
    }

    /// Smooth ramps with noise, so that the IDCT's and upsampling's
    /// rounding shows.
    fn samples(&self) -> Vec<u8> {
        let n = match self.color {
            ColorType::Luma => 1,
            ColorType::Rgb => 3,
            _ => 4,
        };
        let (w, h) = (self.width as usize, self.height as usize);
        (0..w * h * n)
            .map(|i| {
                let (p, c) = (i / n, i % n);
                let (x, y) = (p % w, p / w);
                let ramp = (x * 255 / w.max(2) + y * 191 / h.max(2) + c * 60) as u64;
                let noise = ((i as u64 * 2_654_435_761) >> 9) % 61;
                ((ramp + noise) as u8).wrapping_add(self.shift)
            })
            .collect()
    }

    fn bytes(&self) -> Vec<u8> {
        let mut bytes = Vec::new();
        let mut encoder = Encoder::new(&mut bytes, self.quality);
        encoder.set_sampling_factor(self.sampling);
        encoder.set_progressive(self.progressive);
        if let Some(interval) = self.restart {
            encoder.set_restart_interval(interval);
        }
        if let Some(density) = self.density {
            encoder.set_density(density);
        }
        if let Some(exif) = &self.exif {
            encoder.add_exif_metadata(exif).unwrap();
        }
        let samples = self.samples();
        (encoder.encode(&samples, self.width, self.height, self.color)).unwrap();
        if let Some(text) = self.comment {
            // A COM segment right after SOI.
            let length = (text.len() as u16 + 2).to_be_bytes();
            let com = [&[0xff, 0xfe], &length[..], text.as_bytes()].concat();
            bytes.splice(2..2, com);
        }
        bytes
    }

    fn write(&self, path: &Path) -> PathBuf {
        std::fs::write(path, self.bytes()).unwrap();
        path.to_path_buf()
    }
}

/// An Exif block (after "Exif\0\0") whose first directory holds only an
/// orientation, little-endian.
fn exif_orientation(orientation: u16) -> Vec<u8> {
    let mut tiff = b"II*\0".to_vec();
    tiff.extend(8u32.to_le_bytes());
    tiff.extend(1u16.to_le_bytes());
    tiff.extend(274u16.to_le_bytes());
    tiff.extend(3u16.to_le_bytes());
    tiff.extend(1u32.to_le_bytes());
    tiff.extend([orientation.to_le_bytes(), [0, 0]].concat());
    tiff.extend(0u32.to_le_bytes());
    tiff
}

#[test]
fn every_sampling_coding_and_colour_space_reads_as_oiiotool_reads_it() {
    let dir = tempfile::tempdir().unwrap();
    let mut cases: Vec<(String, Jpeg, &[&str])> = Vec::new();
    let rgb: &[&str] = &["B", "G", "R"];
    for (w, h) in [(33, 17), (1, 1), (97, 61)] {
        for (name, sampling) in [
            ("444", SamplingFactor::F_1_1),
            ("422", SamplingFactor::F_2_1),
            ("420", SamplingFactor::F_2_2),
            ("440", SamplingFactor::F_1_2),
            ("411", SamplingFactor::F_4_1),
        ] {
            for progressive in [false, true] {
                let mut jpeg = Jpeg::new(w, h, ColorType::Rgb);
                (jpeg.sampling, jpeg.progressive) = (sampling, progressive);
                jpeg.quality = if progressive { 50 } else { 95 };
                cases.push((format!("rgb-{name}-{progressive}-{w}x{h}"), jpeg, rgb));
            }
        }
        for progressive in [false, true] {
            let mut grey = Jpeg::new(w, h, ColorType::Luma);
            grey.progressive = progressive;
            cases.push((format!("grey-{progressive}-{w}x{h}"), grey, &["Y"]));
        }
        for (name, color) in [("cmyk", ColorType::Cmyk), ("ycck", ColorType::CmykAsYcck)] {
            cases.push((format!("{name}-{w}x{h}"), Jpeg::new(w, h, color), rgb));
        }
        let mut restart = Jpeg::new(w, h, ColorType::Rgb);
        restart.restart = Some(3);
        cases.push((format!("restart-{w}x{h}"), restart, rgb));
    }
    for (name, jpeg, channels) in &cases {
        let input = jpeg.write(&dir.path().join(format!("{name}.jpg")));
        let output = dir.path().join(format!("{name}.exr"));
        transcode(&input, &output, &[]);
        let img = read_image(&output);
        let size = (jpeg.width as usize, jpeg.height as usize);
        assert_eq!((img.width, img.height), size, "{name}");
        let got: Vec<&str> = img.channels.keys().map(|k| k.as_str()).collect();
        assert_eq!(&got, channels, "{name}");
        assert_as_oiiotool(&input, &output, false);
    }
}

#[test]
fn the_shared_jpeg_reads_as_oiiotool_reads_it() {
    let Some(root) = foreign_images() else {
        return;
    };
    shared_files_as_oiiotool(&root, &["tahoe-gps.jpg"]);
}

/// The attributes of `path`'s first part, as exrheader-like text.
fn attributes(path: &Path) -> String {
    let meta = exr::meta::MetaData::read_from_file(path, false).unwrap();
    let header = &meta.headers[0];
    let mut text = format!(
        "pixelAspectRatio {}\n",
        header.shared_attributes.pixel_aspect
    );
    for (name, value) in &header.own_attributes.other {
        text.push_str(&format!("{name} {value:?}\n"));
    }
    text
}

#[test]
fn comment_density_orientation_and_colour_space_are_named_as_openimageio_names_them() {
    let dir = tempfile::tempdir().unwrap();
    let mut jpeg = Jpeg::new(20, 10, ColorType::Rgb);
    jpeg.comment = Some("shot 12, take 3");
    jpeg.density = Some(PixelDensity {
        density: (300, 150),
        unit: PixelDensityUnit::Inches,
    });
    jpeg.exif = Some(exif_orientation(6));
    let input = jpeg.write(&dir.path().join("meta.jpg"));
    let output = dir.path().join("meta.exr");
    transcode(&input, &output, &[]);
    let said = attributes(&output);
    for want in [
        "pixelAspectRatio 2",
        "ImageDescription Text(exr::Text(\"shot 12, take 3\"))",
        "XResolution F32(300.0)",
        "YResolution F32(150.0)",
        "ResolutionUnit Text(exr::Text(\"in\"))",
        "Orientation I32(6)",
        "oiio:ColorSpace Text(exr::Text(\"sRGB\"))",
        "jpeg:subsampling Text(exr::Text(\"4:2:0\"))",
    ] {
        assert!(said.contains(want), "{want} missing from:\n{said}");
    }
    // The pixels are not turned (oiiotool's plain read does not turn them).
    assert_eq!(read_image(&output).width, 20);
    let info = run(&["info", s(&input)]);
    assert!(info.status.success(), "{}", stderr(&info));
    let shown = String::from_utf8_lossy(&info.stdout);
    assert!(shown.contains("file format: JPEG"), "{shown}");
    assert!(shown.contains("all 10 rows decode"), "{shown}");
    // A file without density or comment says neither; CMYK says so.
    let plain = Jpeg::new(20, 10, ColorType::Cmyk).write(&dir.path().join("plain.jpg"));
    transcode(&plain, &output, &[]);
    let said = attributes(&output);
    assert!(said.contains("pixelAspectRatio 1\n"), "{said}");
    assert!(
        said.contains("jpeg:ColorSpace Text(exr::Text(\"CMYK\"))"),
        "{said}"
    );
    for absent in ["XResolution", "ImageDescription", "Orientation"] {
        assert!(!said.contains(absent), "{absent} in:\n{said}");
    }
}

#[test]
fn a_jpeg_sequence_and_a_jpeg_job_read_every_row_in_order() {
    let dir = tempfile::tempdir().unwrap();
    // Tall enough for several strips; progressive frames too.
    for (k, ext) in [(1, "jpg"), (2, "jpg"), (3, "jpeg"), (4, "jpeg")] {
        let mut jpeg = Jpeg::new(40, 700, ColorType::Rgb);
        (jpeg.shift, jpeg.progressive) = (30 * k as u8, k % 2 == 0);
        jpeg.write(&dir.path().join(format!("ref.{k:04}.{ext}")));
    }
    let frame = |k: u32, ext: &str| dir.path().join(format!("ref.{k:04}.{ext}"));
    transcode(
        &dir.path().join("ref.####.jpg"),
        &dir.path().join("out.####.exr"),
        &[],
    );
    transcode(
        &dir.path().join("ref.####.jpeg"),
        &dir.path().join("out.####.exr"),
        &[],
    );
    let job = dir.path().join("job.toml");
    std::fs::write(
        &job,
        format!(
            "[[node]]\nname = \"in\"\nread = \"{}\"\n\n[[node]]\nname = \"out\"\nwrite = \"{}\"\ninputs = [\"in\"]\n",
            s(&dir.path().join("ref.####.jpg")),
            s(&dir.path().join("job.####.exr"))
        ),
    )
    .unwrap();
    let ran = run(&["run", s(&job), "--quiet"]);
    assert!(ran.status.success(), "{}", stderr(&ran));
    for (k, ext) in [(1, "jpg"), (2, "jpg"), (3, "jpeg"), (4, "jpeg")] {
        let out = dir.path().join(format!("out.{k:04}.exr"));
        assert_as_oiiotool(&frame(k, ext), &out, false);
        if ext == "jpg" {
            let by_job = read_image(&dir.path().join(format!("job.{k:04}.exr")));
            crate::common::assert_identical(&by_job, &read_image(&out));
        }
    }
    // A blur reads rows above its own, a quarter turn all of them: the
    // JPEG reads as the EXR made of it.
    let exr = dir.path().join("out.0002.exr");
    crate::foreign_inputs::reads_as_its_exr(dir.path(), &frame(2, "jpg"), &exr);
}

/// `bytes` with its frame header's (SOF0 or SOF2) height and width set.
fn sized(mut bytes: Vec<u8>, width: u16, height: u16) -> Vec<u8> {
    let sof = (0..bytes.len() - 1)
        .find(|&i| bytes[i] == 0xff && matches!(bytes[i + 1], 0xc0 | 0xc2))
        .expect("a frame header");
    bytes[sof + 5..sof + 7].copy_from_slice(&height.to_be_bytes());
    bytes[sof + 7..sof + 9].copy_from_slice(&width.to_be_bytes());
    bytes
}

#[test]
fn damaged_jpegs_are_refused_in_one_line_and_nothing_is_written() {
    let dir = tempfile::tempdir().unwrap();
    let good = Jpeg::new(300, 200, ColorType::Rgb).bytes();
    let mut progressive = Jpeg::new(64, 64, ColorType::Rgb);
    (progressive.progressive, progressive.sampling) = (true, SamplingFactor::F_1_1);
    let progressive = progressive.bytes();
    let cases: Vec<(&str, Vec<u8>, &str)> = vec![
        (
            "cut",
            good[..good.len() / 2].to_vec(),
            "Premature end of JPEG file",
        ),
        ("header", good[..300].to_vec(), "not a readable JPEG"),
        (
            "cut-progressive",
            progressive[..progressive.len() / 2].to_vec(),
            "does not decode",
        ),
        ("empty", sized(good.clone(), 0, 200), "not a readable JPEG"),
        (
            "huge",
            sized(progressive.clone(), 65000, 65000),
            "over the 1073741824-byte limit",
        ),
        (
            "huge-baseline",
            sized(good.clone(), 65000, 65000),
            "does not decode",
        ),
    ];
    assert_refused(dir.path(), "jpg", cases);
}
