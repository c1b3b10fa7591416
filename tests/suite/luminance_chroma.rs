//! Luminance/chroma files (`Y` with `RY`, `BY` at sampling 2 2, as OpenEXR's
//! RgbaOutputFile writes them) and luminance-only ones: read, carried bit for
//! bit, and turned into RGB as OpenEXR's RgbaInputFile does where a job
//! composites them. The samples are parsed here from uncompressed files by a
//! reader of the test's own, and the RGB reference is computed here, whole
//! image, from ImfRgbaFile.cpp and ImfRgbaYca.cpp.

use crate::common;
use crate::common::{ok, public_image, run, s, shipped_images, stderr, Samples};
use half::f16;
use std::collections::BTreeMap;
use std::path::Path;

/// A single-part uncompressed scanline file's samples, parsed from its bytes.
struct Raw {
    x: i32,
    y: i32,
    width: usize,
    height: usize,
    /// Per channel: sampling and samples (half channels only), row-major at
    /// the channel's own resolution.
    channels: BTreeMap<String, ((usize, usize), Vec<u16>)>,
    /// red, green, blue, white (x, y), when the file has them.
    chromaticities: Option<[f32; 8]>,
}

fn raw(path: &Path) -> Raw {
    let bytes = std::fs::read(path).unwrap();
    let int = |at: usize| i32::from_le_bytes(bytes[at..at + 4].try_into().unwrap());
    let mut at = 8;
    let mut list = Vec::new();
    let (mut window, mut chromaticities, mut compression) = ([0; 4], None, 255);
    let text = |at: &mut usize| {
        let end = *at + bytes[*at..].iter().position(|&b| b == 0).unwrap();
        let t = String::from_utf8(bytes[*at..end].to_vec()).unwrap();
        *at = end + 1;
        t
    };
    loop {
        let name = text(&mut at);
        if name.is_empty() {
            break;
        }
        let _kind = text(&mut at);
        let size = int(at) as usize;
        let value = at + 4;
        match name.as_str() {
            "channels" => {
                let mut c = value;
                while bytes[c] != 0 {
                    let name = text(&mut c);
                    assert_eq!(int(c), 1, "half channels only");
                    list.push((name, (int(c + 8) as usize, int(c + 12) as usize)));
                    c += 16;
                }
            }
            "dataWindow" => window = [0, 1, 2, 3].map(|k| int(value + 4 * k)),
            "compression" => compression = bytes[value],
            "chromaticities" => {
                chromaticities = Some([0, 1, 2, 3, 4, 5, 6, 7].map(|k| {
                    f32::from_le_bytes(bytes[value + 4 * k..value + 4 * k + 4].try_into().unwrap())
                }))
            }
            _ => {}
        }
        at = value + size;
    }
    assert_eq!(
        compression,
        0,
        "{}: uncompressed files only",
        path.display()
    );
    let (x, y) = (window[0], window[1]);
    let (width, height) = ((window[2] - x + 1) as usize, (window[3] - y + 1) as usize);
    let count = |step: usize, from: i32, n: usize| {
        (from..from + n as i32)
            .filter(|v| v.rem_euclid(step as i32) == 0)
            .count()
    };
    let mut channels: BTreeMap<String, ((usize, usize), Vec<u16>)> = list
        .iter()
        .map(|(n, s)| (n.clone(), (*s, Vec::new())))
        .collect();
    // The offset table (one chunk per line), then chunks: y, size, data.
    at += 8 * height;
    for line in 0..height as i32 {
        assert_eq!(int(at), y + line);
        let mut data = at + 8;
        at = data + int(at + 4) as usize;
        for (name, (xs, ys)) in &list {
            if (y + line).rem_euclid(*ys as i32) != 0 {
                continue;
            }
            let samples = &mut channels.get_mut(name).unwrap().1;
            for _ in 0..count(*xs, x, width) {
                samples.push(u16::from_le_bytes([bytes[data], bytes[data + 1]]));
                data += 2;
            }
        }
        assert_eq!(data, at, "line {line}'s samples fill its chunk");
    }
    Raw {
        x,
        y,
        width,
        height,
        channels,
        chromaticities,
    }
}

const TAPS: [f32; 14] = [
    0.002128, -0.007540, 0.019597, -0.043159, 0.087929, -0.186077, 0.627123, 0.627123, -0.186077,
    0.087929, -0.043159, 0.019597, -0.007540, 0.002128,
];

fn h(v: f32) -> f32 {
    f16::from_f32(v).to_f32()
}

/// RgbaInputFile's R, G, B of a luminance/chroma file (half bits, row-major
/// over the data window), computed whole image.
fn reference_rgb(image: &Raw) -> [Vec<u16>; 3] {
    let (w, hh) = (image.width, image.height);
    let half = |bits: u16| f16::from_bits(bits).to_f32();
    let luminance = &image.channels["Y"].1;
    // Chroma at full resolution: samples at even (relative) x of even lines.
    let chroma = |name: &str| -> Vec<f32> {
        let mut full = vec![0.0; w * hh];
        if let Some((_, samples)) = image.channels.get(name) {
            for (k, &bits) in samples.iter().enumerate() {
                full[(k / (w / 2)) * 2 * w + (k % (w / 2)) * 2] = half(bits);
            }
        }
        full
    };
    let (ry, by) = (chroma("RY"), chroma("BY"));
    // computeYw from RGBtoXYZ (Y = 1).
    let c = image
        .chromaticities
        .unwrap_or([0.64, 0.33, 0.30, 0.60, 0.15, 0.06, 0.3127, 0.3290]);
    let [rx, ry_, gx, gy, bx, by_, wx, wy] = c;
    let (x_, z_) = (wx / wy, (1.0 - wx - wy) / wy);
    let d = rx * (by_ - gy) + bx * (gy - ry_) + gx * (ry_ - by_);
    let sr = (x_ * (by_ - gy) - gx * ((by_ - 1.0) + by_ * (x_ + z_))
        + bx * ((gy - 1.0) + gy * (x_ + z_)))
        / d;
    let sg = (x_ * (ry_ - by_) + rx * ((by_ - 1.0) + by_ * (x_ + z_))
        - bx * ((ry_ - 1.0) + ry_ * (x_ + z_)))
        / d;
    let sb = (x_ * (gy - ry_) - rx * ((gy - 1.0) + gy * (x_ + z_))
        + gx * ((ry_ - 1.0) + ry_ * (x_ + z_)))
        / d;
    let m = [sr * ry_, sg * gy, sb * by_];
    let sum = m[0] + m[1] + m[2];
    let yw = [m[0] / sum, m[1] / sum, m[2] / sum];

    // readYCAScanLine's clamp of lines, padTmpBuf's of columns.
    let line = |v: i64| -> usize {
        if v < 0 {
            0
        } else if v > hh as i64 - 1 {
            hh - 2
        } else {
            v as usize
        }
    };
    let filtered = |get: &dyn Fn(i64) -> f32, at: i64| {
        let mut acc = get(at - 13) * TAPS[0];
        for (k, tap) in TAPS.iter().enumerate().skip(1) {
            acc += get(at - 13 + 2 * k as i64) * tap;
        }
        h(acc)
    };
    // Chroma filled in along each even line.
    let along = |plane: &[f32], row: usize| -> Vec<f32> {
        let get = |x: i64| plane[row * w + x.clamp(0, w as i64 - 2) as usize];
        (0..w as i64)
            .map(|x| match x % 2 {
                0 => get(x),
                _ => filtered(&get, x),
            })
            .collect()
    };
    let rows: Vec<[Vec<f32>; 2]> = (0..hh)
        .map(|r| match r % 2 {
            0 => [along(&ry, r), along(&by, r)],
            _ => [Vec::new(), Vec::new()],
        })
        .collect();
    // Lines -1 ..= hh in RGB (halves), before the saturation fix.
    let rgb_line = |v: i64| -> Vec<[f32; 3]> {
        let own = line(v);
        (0..w)
            .map(|x| {
                let (cr, cb) = if v.rem_euclid(2) == 0 {
                    (rows[own][0][x], rows[own][1][x])
                } else {
                    let r = filtered(&|u| rows[line(u)][0][x], v);
                    let b = filtered(&|u| rows[line(u)][1][x], v);
                    (r, b)
                };
                let y = half(luminance[own * w + x]);
                if cr == 0.0 && cb == 0.0 {
                    return [y, y, y];
                }
                let r = (cr + 1.0) * y;
                let b = (cb + 1.0) * y;
                let g = (y - r * yw[0] - b * yw[2]) / yw[1];
                [h(r), h(g), h(b)]
            })
            .collect()
    };
    let lines: Vec<Vec<[f32; 3]>> = (-1..=hh as i64).map(rgb_line).collect();
    let saturation = |p: [f32; 3]| {
        let high = p[0].max(p[1]).max(p[2]);
        let low = p[0].min(p[1]).min(p[2]);
        if high > 0.0 {
            1.0 - low / high
        } else {
            0.0
        }
    };
    let mut out = [vec![0u16; w * hh], vec![0u16; w * hh], vec![0u16; w * hh]];
    for v in 0..hh {
        let (above, this, below) = (&lines[v], &lines[v + 1], &lines[v + 2]);
        for x in 0..w {
            let side = |l: &Vec<[f32; 3]>, dx: i64| {
                saturation(l[(x as i64 + dx).clamp(0, w as i64 - 1) as usize])
            };
            let mean = (0.25
                * (side(above, -1) + side(above, 1) + side(below, -1) + side(below, 1)))
            .min(1.0);
            let p = this[x];
            let s = saturation(p);
            let most = (1.0 - (1.0 - mean) * 0.25).min(1.0);
            let fixed = if s > mean && s > most {
                let f = most / s;
                let high = p[0].max(p[1]).max(p[2]);
                let mut o = p.map(|c| h((high - (high - c) * f).max(0.0)));
                let lum_in = p[0] * yw[0] + p[1] * yw[1] + p[2] * yw[2];
                let lum_out = o[0] * yw[0] + o[1] * yw[1] + o[2] * yw[2];
                if lum_out > 0.0 {
                    o = o.map(|c| h(c * (lum_in / lum_out)));
                }
                o
            } else {
                p
            };
            for c in 0..3 {
                out[c][v * w + x] = f16::from_f32(fixed[c]).to_bits();
            }
        }
    }
    out
}

/// The half bits of channel `name` of an RGB output (read by the exr crate).
fn half_bits(path: &Path, name: &str) -> Vec<u16> {
    match &common::read_image(path).channels[name] {
        Samples::F16(v) => v.iter().map(|s| s.to_bits()).collect(),
        other => panic!("{name} is not half: {other:?}"),
    }
}

fn sample(name: &str) -> std::path::PathBuf {
    shipped_images().join("Generated").join(name)
}

/// `input` transcoded to `coded` with `compression`, and that back to
/// uncompressed `back`.
fn transcode_and_back(input: &Path, coded: &Path, compression: &str, back: &Path) {
    ok(&[
        "transcode",
        s(input),
        "-o",
        s(coded),
        "--compression",
        compression,
        "-q",
    ]);
    ok(&[
        "transcode",
        s(coded),
        "-o",
        s(back),
        "--compression",
        "none",
        "-q",
    ]);
}

#[test]
fn subsampled_channels_are_carried_bit_for_bit_through_every_lossless_compression() {
    let input = sample("YcaOffset.exr");
    let original = raw(&input);
    assert_eq!(original.channels["RY"].0, (2, 2));
    let dir = tempfile::tempdir().unwrap();
    for compression in ["none", "rle", "zips", "zip", "piz", "pxr24"] {
        let coded = dir.path().join(format!("{compression}.exr"));
        let back = dir.path().join(format!("{compression}-none.exr"));
        transcode_and_back(&input, &coded, compression, &back);
        let again = raw(&back);
        assert_eq!((again.x, again.y), (original.x, original.y));
        assert_eq!(again.channels, original.channels, "{compression}");
        // OpenEXR parses it (oiiotool refuses subsampled channels).
        if let Some(exrheader) = common::peer("exrheader") {
            common::succeed(std::process::Command::new(exrheader).arg(&coded));
        }
    }
}

#[test]
fn b44_of_subsampled_channels_is_written_and_read_back() {
    let input = sample("YcaOffset.exr");
    let original = raw(&input);
    let dir = tempfile::tempdir().unwrap();
    for compression in ["b44", "b44a"] {
        let (coded, back) = (dir.path().join("out.exr"), dir.path().join("back.exr"));
        transcode_and_back(&input, &coded, compression, &back);
        let again = raw(&back);
        assert_eq!((again.x, again.y), (original.x, original.y));
        for (name, (sampling, samples)) in &original.channels {
            let (s2, got) = &again.channels[name];
            assert_eq!(
                (sampling, samples.len()),
                (s2, got.len()),
                "{compression} {name}"
            );
            // Lossy, and coarse where a block's samples change sign (B44
            // orders halves by sign first): the samples are checked against
            // OpenEXR's own packing in
            // files_openexr_writes_in_every_compression_are_read_or_refused_clearly.
        }
        if let Some(exrheader) = common::peer("exrheader") {
            common::succeed(std::process::Command::new(exrheader).arg(&coded));
        }
    }
}

/// OpenEXR allows subsampled channels in scanline parts only: a tiled output
/// of them (--tile, or a write node's tile) is refused before anything is
/// written (it had written a file no reader takes, or panicked). Composited
/// over a tiled plate they are RGB, and the output follows the plate's tiles.
#[test]
fn a_tiled_output_of_subsampled_channels_is_refused_and_a_tiled_plate_takes_their_rgb() {
    let input = sample("YcaOffset.exr");
    let dir = tempfile::tempdir().unwrap();
    let output = dir.path().join("out.exr");
    let job = dir.path().join("job.toml");
    std::fs::write(
        &job,
        format!(
            "[[node]]\nname = \"in\"\nread = \"{}\"\n\n[[node]]\nname = \"out\"\nwrite = \"{}\"\ninputs = [\"in\"]\ntile = \"16x16\"\n",
            s(&input),
            s(&output)
        ),
    )
    .unwrap();
    for args in [
        vec!["transcode", s(&input), "-o", s(&output), "--tile", "16"],
        vec!["transcode", s(&input), "-o", s(&output), "--tile", "64"],
        vec!["run", s(&job)],
    ] {
        let out = run(&args);
        let message = stderr(&out);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {message}");
        assert_eq!(message.trim().lines().count(), 1, "{message}");
        assert!(
            message.contains("YcaOffset.exr") && message.contains("scanline parts only"),
            "{message}"
        );
        assert!(!output.exists());
    }
    let (plain, plate) = (dir.path().join("plain.exr"), dir.path().join("plate.exr"));
    ok(&[
        "generate",
        s(&plain),
        "--width",
        "40",
        "--height",
        "40",
        "-q",
    ]);
    ok(&[
        "transcode",
        s(&plain),
        "-o",
        s(&plate),
        "--tile",
        "16",
        "-q",
    ]);
    ok(&["over", s(&input), s(&plate), "-o", s(&output), "-q"]);
    let out = run(&["info", s(&output)]);
    let text = String::from_utf8_lossy(&out.stdout).to_string();
    assert!(out.status.success(), "{}", stderr(&out));
    assert!(text.contains("tiles (type tiledesc)"), "{text}");
    assert!(
        text.contains("sampling 1 1") && !text.contains("sampling 2 2"),
        "{text}"
    );
    common::assert_peers_read(&output);
}

#[test]
fn operations_read_luminance_chroma_as_openexrs_rgba_interface_does() {
    let input = sample("YcaOffset.exr");
    let dir = tempfile::tempdir().unwrap();
    let output = dir.path().join("copy.exr");
    // `copy` gives its first input as it is: the RGB of the file.
    ok(&[
        "merge",
        "--op",
        "copy",
        s(&input),
        s(&input),
        "-o",
        s(&output),
        "-q",
    ]);
    let expected = reference_rgb(&raw(&input));
    for (c, name) in ["R", "G", "B"].iter().enumerate() {
        assert!(half_bits(&output, name) == expected[c], "{name} differs");
    }
    // Alpha is carried as it is.
    let alpha: Vec<u16> = half_bits(&output, "A");
    assert_eq!(alpha, raw(&input).channels["A"].1);
}

#[test]
fn a_luminance_only_image_is_grey() {
    let input = sample("LuminanceOnly.exr");
    let dir = tempfile::tempdir().unwrap();
    let output = dir.path().join("over.exr");
    ok(&["over", s(&input), s(&input), "-o", s(&output), "-q"]);
    let luminance = &raw(&input).channels["Y"].1;
    for name in ["R", "G", "B"] {
        assert_eq!(&half_bits(&output, name), luminance, "{name}");
    }
}

/// The converting node sits between the inputs in the graph: each input must
/// still be read with its own data window (the fuzzer's GrayRampsHorizontal
/// over a 64x64 plate read the plate with the 800x800 one and panicked).
#[test]
fn a_luminance_image_over_a_smaller_plate_reads_the_plate_with_its_own_window() {
    let input = sample("LuminanceOnly.exr");
    let dir = tempfile::tempdir().unwrap();
    let (plate, output) = (dir.path().join("plate.exr"), dir.path().join("over.exr"));
    ok(&["generate", s(&plate), "--width", "8", "--height", "8", "-q"]);
    ok(&["over", s(&input), s(&plate), "-o", s(&output), "-q"]);
    // The luminance image has no alpha: opaque, it covers the plate.
    let luminance = &raw(&input).channels["Y"].1;
    for name in ["R", "G", "B"] {
        assert_eq!(&half_bits(&output, name), luminance, "{name}");
    }
}
/// A crop keeps fewer rows or columns than the image: the conversion still
/// reads the lines and pixels beyond the crop that its filters reach (it had
/// read rows it did not hold and panicked), so the result is the crop of the
/// whole image's RGB, bit for bit, wherever the strips fall.
#[test]
fn a_crop_of_a_luminance_chroma_image_is_the_crop_of_its_rgb() {
    let input = sample("YcaOffset.exr");
    let image = raw(&input);
    let expected = reference_rgb(&image);
    let dir = tempfile::tempdir().unwrap();
    let output = dir.path().join("crop.exr");
    // Rows off the top and bottom, a corner, one column, the bottom right;
    // then cut to the origin, and strips of one row.
    for (region, cut, strip) in [
        ("-6,9,31,30", false, "64"),
        ("-3,5,4,11", false, "64"),
        ("1,4,1,33", false, "64"),
        ("20,25,31,33", false, "64"),
        ("-3,5,4,11", true, "64"),
        ("0,6,17,28", false, "1"),
    ] {
        let mut args = vec!["crop", s(&input), "--region", region, "-o", s(&output)];
        args.extend(["--strip-rows", strip, "-q"]);
        if cut {
            args.push("--cut");
        }
        ok(&args);
        let bounds: Vec<i32> = region.split(',').map(|v| v.parse().unwrap()).collect();
        let (x0, y0, x1, y1) = (bounds[0], bounds[1], bounds[2], bounds[3]);
        for (c, name) in ["R", "G", "B"].iter().enumerate() {
            let mut crop = Vec::new();
            for y in y0..=y1 {
                for x in x0..=x1 {
                    let at = (y - image.y) as usize * image.width + (x - image.x) as usize;
                    crop.push(expected[c][at]);
                }
            }
            assert!(
                half_bits(&output, name) == crop,
                "{name} of {region} (cut {cut}, strips of {strip}) differs"
            );
        }
    }
}

#[test]
fn mt_tam_north_reads_carries_and_composites() {
    let Some(path) = public_image("../exr-images-more/LuminanceChroma/MtTamNorth.exr") else {
        return;
    };
    // info: the channels as exrheader prints them, and every chunk decodes.
    let out = run(&["info", s(&path)]);
    let text = String::from_utf8_lossy(&out.stdout).to_string();
    assert!(out.status.success(), "{}", stderr(&out));
    assert!(
        text.contains("    RY, 16-bit floating-point, sampling 2 2\n"),
        "{text}"
    );
    assert!(text.contains("pixels: all 25 chunks decode"), "{text}");
    if let Some(exrheader) = common::peer("exrheader") {
        let theirs = common::succeed(std::process::Command::new(exrheader).arg(&path));
        let theirs = String::from_utf8_lossy(&theirs.stdout).to_string();
        let channels = |t: &str| {
            t.lines()
                .skip_while(|l| !l.starts_with("channels"))
                .take(4)
                .collect::<Vec<_>>()
                .join("\n")
        };
        assert_eq!(channels(&text), channels(&theirs));
    }
    // Carried: PIZ to ZIP to none is PIZ to none, sample for sample.
    let dir = tempfile::tempdir().unwrap();
    let (zip, direct, back) = (
        dir.path().join("z.exr"),
        dir.path().join("n.exr"),
        dir.path().join("zn.exr"),
    );
    ok(&[
        "transcode",
        s(&path),
        "-o",
        s(&zip),
        "--compression",
        "zip",
        "-q",
    ]);
    ok(&[
        "transcode",
        s(&zip),
        "-o",
        s(&back),
        "--compression",
        "none",
        "-q",
    ]);
    ok(&[
        "transcode",
        s(&path),
        "-o",
        s(&direct),
        "--compression",
        "none",
        "-q",
    ]);
    let decoded = raw(&direct);
    assert_eq!(raw(&back).channels, decoded.channels);
    // Over itself: its RGB, as RgbaInputFile reads it.
    let over = dir.path().join("over.exr");
    ok(&["over", s(&path), s(&path), "-o", s(&over), "-q"]);
    let expected = reference_rgb(&decoded);
    for (c, name) in ["R", "G", "B"].iter().enumerate() {
        assert!(half_bits(&over, name) == expected[c], "{name} differs");
    }
}

#[test]
fn a_tiled_luminance_file_is_grey_too() {
    let Some(path) = public_image("../exr-images-more/LuminanceChroma/Garden.exr") else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let (over, plain) = (dir.path().join("over.exr"), dir.path().join("plain.exr"));
    ok(&["over", s(&path), s(&path), "-o", s(&over), "-q"]);
    ok(&[
        "transcode",
        s(&path),
        "-o",
        s(&plain),
        "--compression",
        "none",
        "--scanline",
        "-q",
    ]);
    let luminance = &raw(&plain).channels["Y"].1;
    for name in ["R", "G", "B"] {
        assert_eq!(&half_bits(&over, name), luminance, "{name}");
    }
}

#[test]
fn files_openexr_writes_in_every_compression_are_read_or_refused_clearly() {
    let Some(python) = common::openexr_python() else {
        return;
    };
    let script = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/peers/openexr_subsampled.py");
    let peer = |args: &[&str]| {
        std::process::Command::new(&python)
            .arg(&script)
            .args(args)
            .output()
            .unwrap()
    };
    let dir = tempfile::tempdir().unwrap();
    let files = dir.path();
    assert!(peer(&["write", s(files)]).status.success());
    for prefix in ["yc", "yca"] {
        let source = files.join(format!("{prefix}_none.exr"));
        let reference = raw(&source);
        for compression in [
            "none", "rle", "zips", "zip", "piz", "pxr24", "dwaa", "b44", "b44a",
        ] {
            let input = files.join(format!("{prefix}_{compression}.exr"));
            let decoded = files.join(format!("{prefix}_{compression}-none.exr"));
            let out = run(&[
                "transcode",
                s(&input),
                "-o",
                s(&decoded),
                "--compression",
                "none",
                "-q",
            ]);
            assert!(out.status.success(), "{compression}: {}", stderr(&out));
            if compression.starts_with("b44") {
                b44_reads_as_openexr(&peer, &input, &decoded, prefix);
                continue;
            }
            let ours = raw(&decoded);
            if compression == "dwaa" {
                // Lossy: the samples are OpenEXR's decoding, so only the layout is compared.
                assert_eq!(
                    ours.channels.keys().collect::<Vec<_>>(),
                    reference.channels.keys().collect::<Vec<_>>()
                );
                continue;
            }
            assert_eq!(ours.channels, reference.channels, "{prefix} {compression}");
            // What we write, OpenEXR reads back sample for sample.
            let written = files.join(format!("{prefix}_ours_{compression}.exr"));
            ok(&[
                "transcode",
                s(&source),
                "-o",
                s(&written),
                "--compression",
                compression,
                "-q",
            ]);
            let same = peer(&["same", s(&source), s(&written)]);
            assert!(
                same.status.success(),
                "{prefix} {compression}: {}",
                String::from_utf8_lossy(&same.stderr)
            );
        }
    }
}

/// B44 is lossy: the samples read from `input` are OpenEXR's decoding of
/// it, bit for bit (they had been refused, "b44 compression of subsampled
/// channels is not supported"), and a composite takes their RGB. Writing
/// B44 of subsampled channels is refused in one line.
fn b44_reads_as_openexr(
    peer: &dyn Fn(&[&str]) -> std::process::Output,
    input: &Path,
    decoded: &Path,
    prefix: &str,
) {
    let same = peer(&["same", s(input), s(decoded)]);
    assert!(
        same.status.success(),
        "{}: {}",
        input.display(),
        String::from_utf8_lossy(&same.stderr)
    );
    // (--compression none: the input's B44 would be lossy again.)
    let composite = decoded.with_extension("copy.exr");
    ok(&[
        "merge",
        "--op",
        "copy",
        s(input),
        s(input),
        "-o",
        s(&composite),
        "--compression",
        "none",
        "-q",
    ]);
    let expected = reference_rgb(&raw(decoded));
    for (c, name) in ["R", "G", "B"].iter().enumerate() {
        assert!(
            half_bits(&composite, name) == expected[c],
            "{prefix} {name} differs"
        );
    }
    // What we write from the uncompressed source, OpenEXR reads as it
    // reads its own B44 of it: the same packing (it had been refused).
    let (source, compression) = (
        input.with_file_name(format!("{prefix}_none.exr")),
        ext(input),
    );
    let written = decoded.with_extension("ours.exr");
    ok(&[
        "transcode",
        s(&source),
        "-o",
        s(&written),
        "--compression",
        &compression,
        "-q",
    ]);
    let same = peer(&["same", s(input), s(&written)]);
    assert!(
        same.status.success(),
        "{prefix} {compression} written: {}",
        String::from_utf8_lossy(&same.stderr)
    );
}

/// `b44` of `yc_b44.exr`.
fn ext(input: &Path) -> String {
    let stem = input.file_stem().unwrap().to_string_lossy();
    stem.rsplit('_').next().unwrap().to_string()
}

#[test]
fn a_data_window_the_sampling_does_not_divide_is_refused() {
    let mut bytes = std::fs::read(sample("YcaOffset.exr")).unwrap();
    let name = b"dataWindow\0box2i\0";
    let at = bytes.windows(name.len()).position(|w| w == name).unwrap() + name.len() + 4;
    // xMax one less: 37 columns, not a multiple of RY's and BY's 2.
    let x_max = i32::from_le_bytes(bytes[at + 8..at + 12].try_into().unwrap()) - 1;
    bytes[at + 8..at + 12].copy_from_slice(&x_max.to_le_bytes());
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("odd.exr");
    std::fs::write(&path, bytes).unwrap();
    let out = run(&["info", s(&path)]);
    let message = stderr(&out);
    assert!(
        !out.status.success() && message.trim().lines().count() == 1,
        "{message}"
    );
    assert!(
        message.contains("odd.exr") && message.contains("sampling 2 2"),
        "{message}"
    );
}

/// A random RGBA image and a luminance-only one (Y, half) of its size.
fn rgba_and_grey() -> (common::Img, common::Img) {
    let rgba = common::random_rgba(5, 0, 0, 24, 16, common::Kind::Half, false);
    let luminance = rgba.channels["R"].clone();
    let grey = common::Img {
        channels: BTreeMap::from([("Y".to_string(), luminance)]),
        ..common::random_rgba(5, 0, 0, 24, 16, common::Kind::Half, false)
    };
    (rgba, grey)
}

/// `--all-parts` converts each luminance-only part, whichever part comes
/// first (the conversion had been set up from part 0 only: an RGB part 0
/// left part 1's Y to the blur, "layer '(unnamed)' not found"): each part
/// is the blur of that part alone.
#[test]
fn all_parts_converts_a_luminance_part_after_an_rgb_one() {
    let dir = tempfile::tempdir().unwrap();
    let (rgba, grey) = rgba_and_grey();
    let input = dir.path().join("two.exr");
    let list = [("beauty", "main", &rgba), ("grey", "main", &grey)];
    common::write_parts(&input, &list);
    let output = dir.path().join("all.exr");
    ok(&[
        "blur",
        s(&input),
        "--radius",
        "2",
        "--all-parts",
        "-o",
        s(&output),
        "-q",
    ]);
    let parts = common::read_parts(&output);
    assert_eq!(parts.len(), 2);
    for (p, part) in list.iter().enumerate() {
        let single = dir.path().join(format!("part{p}.exr"));
        common::write_parts(&single, &[*part]);
        let reference = dir.path().join(format!("blur{p}.exr"));
        ok(&[
            "blur",
            s(&single),
            "--radius",
            "2",
            "-o",
            s(&reference),
            "-q",
        ]);
        common::assert_identical(&parts[p], &common::read_image(&reference));
    }
    assert!(parts[1].channels.contains_key("G") && !parts[1].channels.contains_key("Y"));
}

/// A frame luminance-only in a sequence whose first frame is RGB: one line
/// naming the file and frame and what differs (it had been "layer
/// '(unnamed)' not found"); nothing is written for it.
#[test]
fn a_luminance_frame_after_rgb_ones_is_named() {
    let dir = tempfile::tempdir().unwrap();
    let (rgba, grey) = rgba_and_grey();
    let pattern = dir.path().join("plate.####.exr");
    for (frame, img) in [(1, &rgba), (2, &grey)] {
        let path = dir.path().join(format!("plate.000{frame}.exr"));
        common::write_image(
            &path,
            img,
            common::compression("zip"),
            exr::meta::attribute::LineOrder::Increasing,
        );
    }
    let output = dir.path().join("out.####.exr");
    let out = run(&["blur", s(&pattern), "--radius", "1", "-o", s(&output), "-q"]);
    let message = stderr(&out);
    assert_eq!(out.status.code(), Some(3), "{message}");
    assert_eq!(message.trim().lines().count(), 1, "{message}");
    for part in [
        "plate.0002.exr",
        "frame 2",
        "luminance-only",
        "first frame is RGB",
    ] {
        assert!(message.contains(part), "{part}: {message}");
    }
    assert!(!dir.path().join("out.0002.exr").exists());
}
