//! PNG inputs (specs/file-format.md, "PNG"): files written here with the
//! `png` crate in every colour type and depth (palette with transparency,
//! 1 to 16 bits, gAMA and sRGB chunks), read as the formulas say and as
//! oiiotool reads them (`oiiotool IN -d half|float`, `idiff -fail 0`), the
//! shared PNGs against oiiotool, a sequence and a job, and damaged files
//! refused in one line with nothing written.

use crate::common::{read_image, run, s, Samples};
use crate::foreign_inputs::{
    assert_as_oiiotool, assert_refused, foreign_images, shared_files_as_oiiotool, transcode,
};
use png::{BitDepth, ColorType};
use std::path::{Path, PathBuf};

/// A PNG to write.
struct Png {
    width: u32,
    height: u32,
    color: ColorType,
    depth: BitDepth,
    /// Stored bytes, rows top first, as the encoder takes them.
    data: Vec<u8>,
    palette: Option<Vec<u8>>,
    trns: Option<Vec<u8>>,
    /// gAMA's value times 100000.
    gamma: Option<u32>,
    srgb: bool,
}

impl Png {
    /// A `width` x `height` image of pseudo-random stored bytes.
    fn new(width: u32, height: u32, color: ColorType, depth: BitDepth) -> Png {
        let bits = depth as usize * color.samples();
        let row = (width as usize * bits).div_ceil(8);
        let data = (0..row * height as usize)
            .map(|i| ((i as u64 * 2_654_435_761) >> 7) as u8)
            .collect();
        Png {
            width,
            height,
            color,
            depth,
            data,
            palette: None,
            trns: None,
            gamma: None,
            srgb: false,
        }
    }

    fn bytes(&self) -> Vec<u8> {
        let mut bytes = Vec::new();
        let mut encoder = png::Encoder::new(&mut bytes, self.width, self.height);
        encoder.set_color(self.color);
        encoder.set_depth(self.depth);
        if let Some(palette) = &self.palette {
            encoder.set_palette(palette.clone());
        }
        if let Some(trns) = &self.trns {
            encoder.set_trns(trns.clone());
        }
        if let Some(g) = self.gamma {
            encoder.set_source_gamma(png::ScaledFloat::from_scaled(g));
        }
        if self.srgb {
            encoder.set_source_srgb(png::SrgbRenderingIntent::Perceptual);
        }
        let mut writer = encoder.write_header().unwrap();
        writer.write_image_data(&self.data).unwrap();
        writer.finish().unwrap();
        bytes
    }

    fn write(&self, path: &Path) -> PathBuf {
        std::fs::write(path, self.bytes()).unwrap();
        path.to_path_buf()
    }
}

/// 8 or 16-bit RGBA or grey-alpha samples as OpenImageIO associates them
/// (no gAMA chunk): `v a / max` in integers, then times `1 / max`.
fn expected(png: &Png, component: usize) -> Vec<f32> {
    let n = png.color.samples();
    let (max, wide) = match png.depth {
        BitDepth::Sixteen => (65535u32, true),
        _ => (255, false),
    };
    let code = |i: usize| match wide {
        true => u16::from_be_bytes([png.data[2 * i], png.data[2 * i + 1]]) as u32,
        false => png.data[i] as u32,
    };
    (0..(png.width * png.height) as usize)
        .map(|p| {
            let mut v = code(p * n + component);
            if matches!(n, 2 | 4) && component != n - 1 {
                v = v * code(p * n + n - 1) / max;
            }
            let v = v as f32 * (1.0 / max as f32);
            match wide {
                true => v,
                false => half::f16::from_f32(v).to_f32(),
            }
        })
        .collect()
}

#[test]
fn every_colour_type_and_depth_reads_as_openimageio_reads_it() {
    let dir = tempfile::tempdir().unwrap();
    let mut cases = Vec::new();
    for (color, names) in [
        (ColorType::Grayscale, &["Y"][..]),
        (ColorType::GrayscaleAlpha, &["Y", "A"]),
        (ColorType::Rgb, &["R", "G", "B"]),
        (ColorType::Rgba, &["R", "G", "B", "A"]),
    ] {
        for depth in [BitDepth::Eight, BitDepth::Sixteen] {
            cases.push((
                format!("{color:?}-{depth:?}"),
                Png::new(67, 9, color, depth),
                names,
            ));
        }
    }
    for depth in [BitDepth::One, BitDepth::Two, BitDepth::Four] {
        let grey = Png::new(67, 9, ColorType::Grayscale, depth);
        cases.push((format!("grey-{depth:?}"), grey, &["Y"][..]));
    }
    let mut palette = Png::new(67, 9, ColorType::Indexed, BitDepth::Eight);
    palette.palette = Some((0..768).map(|i| (i * 37 % 256) as u8).collect());
    let mut transparent = Png::new(67, 9, ColorType::Indexed, BitDepth::Four);
    transparent.palette = palette.palette.clone();
    transparent.trns = Some((0..16).map(|i| (i * 17) as u8).collect());
    cases.push(("palette".into(), palette, &["R", "G", "B"][..]));
    cases.push((
        "palette-trns".into(),
        transparent,
        &["R", "G", "B", "A"][..],
    ));
    for (gamma, srgb) in [
        (Some(45455), false),
        (Some(100_000), false),
        (Some(55555), true),
    ] {
        let mut png = Png::new(67, 9, ColorType::Rgba, BitDepth::Eight);
        (png.gamma, png.srgb) = (gamma, srgb);
        cases.push((
            format!("gamma-{gamma:?}-{srgb}"),
            png,
            &["R", "G", "B", "A"][..],
        ));
    }
    for (name, png, names) in &cases {
        let input = png.write(&dir.path().join(format!("{name}.png")));
        let output = dir.path().join(format!("{name}.exr"));
        transcode(&input, &output, &[]);
        let img = read_image(&output);
        assert_eq!((img.width, img.height), (67, 9), "{name}");
        let got: Vec<&String> = img.channels.keys().collect();
        let mut want: Vec<&str> = names.to_vec();
        want.sort();
        assert_eq!(got, want, "{name}");
        let wide = png.depth == BitDepth::Sixteen;
        for samples in img.channels.values() {
            assert_eq!(matches!(samples, Samples::F32(_)), wide, "{name}'s type");
        }
        let plain = matches!(png.depth, BitDepth::Eight | BitDepth::Sixteen) && png.gamma.is_none();
        if plain && png.color != ColorType::Indexed {
            for (component, channel) in names.iter().enumerate() {
                let samples = &img.channels[*channel];
                for (i, want) in expected(png, component).iter().enumerate() {
                    assert_eq!(
                        samples.get_f32(i).to_bits(),
                        want.to_bits(),
                        "{name} {channel} {i}"
                    );
                }
            }
        }
        assert_as_oiiotool(&input, &output, wide);
    }
}

/// The string attribute `name` of `path`'s first part.
fn text(path: &Path, name: &str) -> Option<String> {
    let meta = exr::meta::MetaData::read_from_file(path, false).unwrap();
    let value = meta.headers[0]
        .own_attributes
        .other
        .get(&exr::prelude::Text::from(name))
        .cloned();
    match value {
        Some(exr::meta::attribute::AttributeValue::Text(t)) => Some(t.to_string()),
        _ => None,
    }
}

#[test]
fn the_colour_space_is_named_as_openimageio_names_it() {
    let dir = tempfile::tempdir().unwrap();
    for (gamma, srgb, name) in [
        (None, false, "sRGB"),
        (None, true, "sRGB"),
        (Some(45455), false, "Gamma2.2"),
        (Some(55555), false, "Gamma1.8"),
        (Some(100_000), false, "linear"),
        (Some(45455), true, "sRGB"),
    ] {
        let mut png = Png::new(5, 3, ColorType::Rgb, BitDepth::Eight);
        (png.gamma, png.srgb) = (gamma, srgb);
        let input = png.write(&dir.path().join("c.png"));
        let output = dir.path().join("c.exr");
        transcode(&input, &output, &[]);
        assert_eq!(text(&output, "oiio:ColorSpace").as_deref(), Some(name));
        let info = run(&["info", s(&input)]);
        let said = String::from_utf8_lossy(&info.stdout);
        assert!(said.contains("file format: PNG"), "{said}");
    }
}

#[test]
fn shared_pngs_read_as_oiiotool_reads_them() {
    let Some(root) = foreign_images() else {
        return;
    };
    let files = ["png/oiio-logo-no-alpha.png", "png/oiio-logo-with-alpha.png"];
    shared_files_as_oiiotool(&root, &files);
}

#[test]
fn a_png_sequence_and_a_png_job_read_every_row_in_order() {
    let dir = tempfile::tempdir().unwrap();
    // Tall enough for several strips, so that rows are asked strip by strip.
    let frames: Vec<Png> = (0..2)
        .map(|k| {
            let mut png = Png::new(40, 700, ColorType::Rgba, BitDepth::Sixteen);
            png.data.iter_mut().for_each(|b| *b = b.wrapping_add(k));
            png.write(&dir.path().join(format!("ref.{}.png", 1 + k)));
            png
        })
        .collect();
    transcode(
        &dir.path().join("ref.#.png"),
        &dir.path().join("out.#.exr"),
        &[],
    );
    // Operations that read rows above their own (a blur) or all of them
    // (a quarter turn) read the PNG as they read the EXR made of it.
    let png = dir.path().join("ref.1.png");
    let exr = dir.path().join("out.1.exr");
    crate::foreign_inputs::reads_as_its_exr(dir.path(), &png, &exr);
    for (k, png) in frames.iter().enumerate() {
        let img = read_image(&dir.path().join(format!("out.{}.exr", 1 + k)));
        for (component, channel) in ["R", "G", "B", "A"].iter().enumerate() {
            for (i, want) in expected(png, component).iter().enumerate() {
                assert_eq!(
                    img.channels[*channel].get_f32(i),
                    *want,
                    "frame {k} {channel} {i}"
                );
            }
        }
    }
}

/// The CRC-32 of a chunk's type and data, as PNG stores it.
fn crc32(bytes: &[u8]) -> u32 {
    let mut crc = !0u32;
    for &b in bytes {
        crc ^= b as u32;
        for _ in 0..8 {
            crc = (crc >> 1) ^ (0xedb8_8320 & (crc & 1).wrapping_neg());
        }
    }
    !crc
}

#[test]
fn damaged_pngs_are_refused_in_one_line_and_nothing_is_written() {
    let dir = tempfile::tempdir().unwrap();
    let good = Png::new(300, 200, ColorType::Rgb, BitDepth::Eight).bytes();
    // IHDR's fields are bytes 16..29, its CRC 29..33.
    let ihdr = |width: u32, height: u32, interlace: u8| {
        let mut bytes = good.clone();
        bytes[16..20].copy_from_slice(&width.to_be_bytes());
        bytes[20..24].copy_from_slice(&height.to_be_bytes());
        bytes[28] = interlace;
        let crc = crc32(&bytes[12..29]);
        bytes[29..33].copy_from_slice(&crc.to_be_bytes());
        bytes
    };
    let mut flipped = good.clone();
    let at = flipped.len() / 2;
    flipped[at] ^= 0x55;
    let cases: Vec<(&str, Vec<u8>, &str)> = vec![
        ("cut", good[..good.len() / 2].to_vec(), "does not decode"),
        ("header", good[..20].to_vec(), "not a readable PNG"),
        ("crc", flipped, "does not decode"),
        ("huge", ihdr(1 << 24, 1 << 24, 0), "truncated PNG"),
        ("wide", ihdr(1 << 30, 1, 0), "not a readable PNG"),
        ("interlaced", ihdr(300, 200, 1), "interlaced"),
    ];
    assert_refused(dir.path(), "png", cases);
}

/// `png` with a chunk `kind` of `data` inserted after IHDR (bytes 8..33).
fn with_chunk(png: &[u8], kind: &[u8; 4], data: &[u8]) -> Vec<u8> {
    let mut chunk = (data.len() as u32).to_be_bytes().to_vec();
    chunk.extend(kind);
    chunk.extend(data);
    chunk.extend(crc32(&chunk[4..]).to_be_bytes());
    [&png[..33], &chunk[..], &png[33..]].concat()
}

#[test]
fn an_offset_in_pixels_moves_the_data_window_as_oiiotool_moves_it() {
    let dir = tempfile::tempdir().unwrap();
    let plain = Png::new(5, 3, ColorType::Rgb, BitDepth::Eight).bytes();
    // oFFs: x, y (signed, big-endian) and the unit (0 pixels, 1 micrometres).
    let offs =
        |x: i32, y: i32, unit: u8| [&x.to_be_bytes()[..], &y.to_be_bytes(), &[unit]].concat();
    for (name, chunk, origin) in [
        ("pixels", offs(7, -3, 0), (7, -3)),
        ("micrometres", offs(7, 3, 1), (0, 0)),
    ] {
        let input = dir.path().join(format!("{name}.png"));
        std::fs::write(&input, with_chunk(&plain, b"oFFs", &chunk)).unwrap();
        let output = dir.path().join(format!("{name}.exr"));
        transcode(&input, &output, &[]);
        let meta = exr::meta::MetaData::read_from_file(&output, false).unwrap();
        let header = &meta.headers[0];
        let position = header.own_attributes.layer_position;
        assert_eq!((position.x(), position.y()), origin, "{name}");
        let display = header.shared_attributes.display_window;
        assert_eq!(
            (display.position.x(), display.position.y()),
            (0, 0),
            "{name}"
        );
        assert_eq!((display.size.x(), display.size.y()), (5, 3), "{name}");
        assert_as_oiiotool(&input, &output, false);
    }
}
