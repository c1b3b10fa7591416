//! `transform`: whole-image references computed here (whole-pixel moves,
//! quarter and half turns and flips exact; any angle against bilinear
//! sampling at the inverse-mapped point), whatever the strip height;
//! oiiotool's `--flip`, `--flop` and `--rotate`; the job node; bad values.

use crate::common::*;
use exr::meta::attribute::LineOrder;
use std::path::Path;

fn transform(input: &Path, output: &Path, args: &[&str]) {
    let mut all = vec!["transform", s(input), "-o", s(output), "--quiet"];
    all.extend(args);
    let out = run(&all);
    assert!(out.status.success(), "{args:?}: {}", stderr(&out));
}

/// A random half RGBA image of `w` x `h`, display window the same, as a ZIP file.
fn plate(dir: &Path, w: usize, h: usize) -> (std::path::PathBuf, Img) {
    let input = dir.join("in.exr");
    let mut img = random_rgba(11, 0, 0, w, h, Kind::Half, false);
    img.display = (w, h);
    write_image(&input, &img, compression("zip"), LineOrder::Increasing);
    (input, img)
}

/// `img` moved: output pixel (x, y) of window `(x0, y0, w, h)` is input
/// pixel `from(x, y)`, black where that is outside it.
fn moved(img: &Img, (x0, y0, w, h): Window, from: impl Fn(i32, i32) -> (i32, i32)) -> Img {
    let mut out = Img {
        x: x0,
        y: y0,
        width: w,
        height: h,
        channels: Default::default(),
        ..img.clone()
    };
    for (name, plane) in &img.channels {
        let mut samples = plane.zeros_like(w * h);
        for i in 0..w * h {
            let (x, y) = (x0 + (i % w) as i32, y0 + (i / w) as i32);
            let (sx, sy) = from(x, y);
            if let Some(j) = img.index(sx, sy) {
                samples.copy_from(i, plane, j);
            }
        }
        out.channels.insert(name.clone(), samples);
    }
    out
}

/// A data window: x, y, width, height.
type Window = (i32, i32, usize, usize);

/// The input pixel an output pixel is.
type Source = Box<dyn Fn(i32, i32) -> (i32, i32)>;

#[test]
fn moves_turns_and_flips_are_exact_at_any_strip_height() {
    let dir = tempfile::tempdir().unwrap();
    let (w, h) = (40, 30);
    let (input, img) = plate(dir.path(), w, h);
    let out = dir.path().join("out.exr");
    let (wi, hi) = (w as i32, h as i32);
    let cases: Vec<(Vec<&str>, Window, Source)> = vec![
        // Nuke's y is up: translate 5,3 moves 3 rows up.
        (
            vec!["--translate", "5,3"],
            (5, -3, w, h),
            Box::new(|x, y| (x - 5, y + 3)),
        ),
        (
            vec!["--flip"],
            (0, 0, w, h),
            Box::new(move |x, y| (x, hi - 1 - y)),
        ),
        (
            vec!["--flop"],
            (0, 0, w, h),
            Box::new(move |x, y| (wi - 1 - x, y)),
        ),
        (
            vec!["--rotate", "180"],
            (0, 0, w, h),
            Box::new(move |x, y| (wi - 1 - x, hi - 1 - y)),
        ),
        // Counter-clockwise about (20, 15): the top row becomes the left
        // column, its right end at the top.
        (
            vec!["--rotate", "90"],
            (5, -5, h, w),
            Box::new(move |x, y| (34 - y, x - 5)),
        ),
        (
            vec!["--rotate", "-90"],
            (5, -5, h, w),
            Box::new(move |x, y| (y + 5, 34 - x)),
        ),
    ];
    for (args, window, from) in &cases {
        let expected = moved(&img, *window, from);
        for filter in ["impulse", "triangle"] {
            for strip in ["1", "7", "64"] {
                let mut all = args.clone();
                all.extend(["--filter", filter, "--strip-rows", strip]);
                transform(&input, &out, &all);
                let got = read_image(&out);
                assert_eq!(got.display, (w, h), "the display window is kept");
                assert_identical(&got, &expected);
            }
        }
    }
    assert_peers_read(&out);
}

/// Bilinear interpolation of channel `plane` of `img` at pixel coordinates
/// (u, v), black outside its data window.
fn bilinear(img: &Img, plane: &Samples, u: f64, v: f64) -> f64 {
    let (s, t) = (u - 0.5, v - 0.5);
    let (x0, y0) = (s.floor() as i32, t.floor() as i32);
    let (fx, fy) = (s - x0 as f64, t - y0 as f64);
    let at = |x, y| img.index(x, y).map_or(0.0, |i| plane.get_f32(i) as f64);
    (1.0 - fy) * ((1.0 - fx) * at(x0, y0) + fx * at(x0 + 1, y0))
        + fy * ((1.0 - fx) * at(x0, y0 + 1) + fx * at(x0 + 1, y0 + 1))
}

/// At 23 degrees the input streams top-down, at 150 (its footprint moving
/// up as the output's rows go down) bottom-up.
#[test]
fn any_angle_is_bilinear_sampling_at_the_inverse_mapped_point() {
    for angle in ["23", "150"] {
        bilinear_at(angle);
    }
}

fn bilinear_at(angle: &str) {
    let dir = tempfile::tempdir().unwrap();
    let (w, h) = (37, 29);
    let (input, img) = plate(dir.path(), w, h);
    let out = dir.path().join("out.exr");
    // Enlarging: shrinking widens the filter past bilinear (below).
    let (theta, tx, ty, scale) = (angle.parse::<f64>().unwrap(), 1.5, -2.25, 1.1);
    let args = [
        "--rotate",
        angle,
        "--translate",
        "1.5,-2.25",
        "--scale",
        "1.1",
        "--filter",
        "triangle",
    ];
    let mut first = None;
    for strip in ["1", "5", "64"] {
        transform(
            &input,
            &out,
            &[&args[..], &["--strip-rows", strip]].concat(),
        );
        let got = read_image(&out);
        // The same bytes whatever the strips.
        match &first {
            None => first = Some(got.clone()),
            Some(f) => assert_identical(&got, f),
        }
    }
    let got = first.unwrap();
    // The inverse map with y up about the display window's middle.
    let (cx, cy) = (w as f64 / 2.0, h as f64 / 2.0);
    let (sin, cos) = theta.to_radians().sin_cos();
    let mut nonzero = 0;
    for (name, plane) in &got.channels {
        for i in 0..got.width * got.height {
            let (x, y) = (
                got.x + (i % got.width) as i32,
                got.y + (i / got.width) as i32,
            );
            let (px, py) = (
                x as f64 + 0.5 - tx - cx,
                (h as f64 - y as f64 - 0.5) - ty - cy,
            );
            let (ux, uy) = (
                (cos * px + sin * py) / scale,
                (-sin * px + cos * py) / scale,
            );
            let (u, v) = (ux + cx, h as f64 - (uy + cy));
            let expected = bilinear(&img, &img.channels[name], u, v);
            let value = plane.get_f32(i) as f64;
            // One half step (the output's rounding) plus f32 sums.
            let step = (expected.abs().max(1e-3)).log2().floor();
            assert!(
                (value - expected).abs() <= 2f64.powf(step - 10.0) + 1e-5,
                "{name} at ({x}, {y}): {value} against {expected}"
            );
            nonzero += (value != 0.0) as usize;
        }
    }
    assert!(nonzero > w * h, "{nonzero} samples not black");
    // The data window: the turned window's bounding box.
    let corners = [
        (0.0, 0.0),
        (w as f64, 0.0),
        (0.0, h as f64),
        (w as f64, h as f64),
    ];
    let mapped: Vec<(f64, f64)> = corners
        .iter()
        .map(|&(x, y)| {
            let (px, py) = (scale * (x - cx), scale * ((h as f64 - y) - cy));
            let (qx, qy) = (cos * px - sin * py + cx + tx, sin * px + cos * py + cy + ty);
            (qx, h as f64 - qy)
        })
        .collect();
    let x0 = mapped.iter().map(|p| p.0).fold(f64::MAX, f64::min).floor() as i32;
    let y1 = mapped.iter().map(|p| p.1).fold(f64::MIN, f64::max).ceil() as i32;
    assert_eq!((got.x, got.y + got.height as i32), (x0, y1));
    assert_peers_read(&out);
}

/// oiiotool flips and flops exactly as `--flip` and `--flop` do; its
/// `--rotate` (degrees clockwise) is ours negated, and its `--warp` a
/// matrix. With `recompute_roi=1` its data window is the pixels whose
/// centres the turned image covers, ours the whole pixels it touches (a
/// pixel wider at some edges, holding the filter's partial coverage), so
/// ours holds theirs; where both have pixels every sample is within one
/// half-float step of the larger, or 2^-16 near zero (measured: off by one
/// step at most above 0.01, the f32 sums of the taps rounded apart).
#[test]
fn flips_flops_rotations_and_warps_agree_with_oiiotool() {
    let Some(oiiotool) = peer("oiiotool") else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let (input, _) = plate(dir.path(), 48, 36);
    let oiio = |args: &[&str], out: &Path| {
        succeed(
            std::process::Command::new(&oiiotool)
                .arg(&input)
                .args(args)
                .arg("-o")
                .arg(out),
        );
        read_image(out)
    };
    let ours = dir.path().join("ours.exr");
    let theirs = dir.path().join("theirs.exr");
    for flag in ["--flip", "--flop"] {
        transform(&input, &ours, &[flag, "--filter", "impulse"]);
        assert_identical(&read_image(&ours), &oiio(&[flag], &theirs));
    }
    for filter in ["triangle", "lanczos3"] {
        for (args, theirs_args) in [
            (
                vec!["--rotate", "-30"],
                vec!["--rotate:filter=F:recompute_roi=1", "30"],
            ),
            (
                vec!["--rotate", "12.5"],
                vec!["--rotate:filter=F:recompute_roi=1", "-12.5"],
            ),
            // Scale 1.25 about the top left corner (0, 36 with y up), then
            // 3.5 right and 2 up.
            (
                vec![
                    "--scale",
                    "1.25",
                    "--center",
                    "0,36",
                    "--translate",
                    "3.5,2",
                ],
                vec![
                    "--warp:filter=F:recompute_roi=1",
                    "1.25,0,0,0,1.25,0,3.5,-2,1",
                ],
            ),
        ] {
            let what = format!("{args:?} {filter}");
            transform(&input, &ours, &[&args[..], &["--filter", filter]].concat());
            let option = theirs_args[0].replace("=F", &format!("={filter}"));
            let expected = oiio(&[&option, theirs_args[1]], &theirs);
            let compared = assert_within_a_step(&read_image(&ours), &expected, &what);
            assert!(
                compared > 4 * 48 * 36,
                "{what}: {compared} samples compared"
            );
        }
    }
}

/// Every sample of `expected`'s data window is in `got`'s and within one
/// half-float step of it (2^-16 near zero); how many were compared.
fn assert_within_a_step(got: &Img, expected: &Img, what: &str) -> usize {
    let mut compared = 0;
    for (name, e) in &expected.channels {
        let plane = &got.channels[name];
        for j in 0..expected.width * expected.height {
            let x = expected.x + (j % expected.width) as i32;
            let y = expected.y + (j / expected.width) as i32;
            let i = got
                .index(x, y)
                .unwrap_or_else(|| panic!("{what}: ({x}, {y}) missing"));
            let (a, b) = (plane.get_f32(i), e.get_f32(j));
            let step =
                2f32.powi(a.abs().max(b.abs()).max(2f32.powi(-14)).log2().floor() as i32 - 10);
            assert!(
                (a - b).abs() <= step.max(2f32.powi(-16)),
                "{what}: {name} at ({x}, {y}): {a} against {b}"
            );
            compared += 1;
        }
    }
    compared
}

/// Shrinking, OpenImageIO's warp widens the filter by the inverse map's
/// largest derivative above 1 along each axis (2 at half size, 1/0.3 cos
/// 30° across at 0.3 turned 30°): every filter then agrees with `oiiotool
/// --warp` within a half-float step on a real image (measured: 2.4e-4 at
/// most, one step; 0.18 to 0.37 with the filter left at its width).
#[test]
fn shrinking_widens_the_filter_as_oiiotool_does() {
    let (Some(oiiotool), Some(images)) = (peer("oiiotool"), shared_images()) else {
        return;
    };
    let input = images.join("ScanLines/Carrots.exr");
    let dir = tempfile::tempdir().unwrap();
    let (ours, theirs) = (dir.path().join("ours.exr"), dir.path().join("theirs.exr"));
    // Carrots is 600 x 400: its centre (300, 200).
    let (cx, cy) = (300.0, 200.0);
    for (scale, rotate) in [(0.5f64, 0.0f64), (0.3, 30.0)] {
        // OpenImageIO's row-vector matrix: the linear part scale · turn by
        // -rotate (y down), about the centre.
        let (sin, cos) = (-rotate.to_radians()).sin_cos();
        let l = [scale * cos, scale * sin, -scale * sin, scale * cos];
        let (e, f) = (cx - cx * l[0] - cy * l[2], cy - cx * l[1] - cy * l[3]);
        let matrix = [l[0], l[1], 0.0, l[2], l[3], 0.0, e, f, 1.0].map(|v| format!("{v:.9}"));
        for filter in ["box", "triangle", "gaussian", "mitchell", "lanczos3"] {
            let what = format!("scale {scale} rotate {rotate} {filter}");
            let (scale, rotate) = (scale.to_string(), rotate.to_string());
            let args = ["--scale", &scale, "--rotate", &rotate, "--filter", filter];
            transform(&input, &ours, &args);
            succeed(
                std::process::Command::new(&oiiotool)
                    .arg(&input)
                    .arg(format!("--warp:filter={filter}:recompute_roi=1"))
                    .arg(matrix.join(","))
                    .arg("-o")
                    .arg(&theirs),
            );
            let compared = assert_within_a_step(&read_image(&ours), &read_image(&theirs), &what);
            assert!(compared > 4 * 150 * 100, "{what}: {compared} compared");
        }
    }
}

/// At 45 degrees the box and gaussian filters meet ties: source points on
/// the half-pixel grid, taps exactly at the filter's edge. Computed as
/// OpenImageIO's warp computes them (the f32 inverse matrix and point, taps
/// weighed in f32), every sample equals oiiotool 2.4's `--rotate` to the
/// bit, on its data window, at odd, even and non-square sizes, both ways.
#[test]
fn box_and_gaussian_at_45_degrees_equal_oiiotool_to_the_bit() {
    let Some(oiiotool) = peer("oiiotool") else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let (ours, theirs) = (dir.path().join("ours.exr"), dir.path().join("theirs.exr"));
    for (w, h) in [(32, 32), (33, 25), (48, 36), (31, 40)] {
        let (input, _) = plate(dir.path(), w, h);
        for filter in ["box", "gaussian"] {
            for angle in ["45", "-45"] {
                let what = format!("{w}x{h} {filter} {angle}");
                transform(&input, &ours, &["--rotate", angle, "--filter", filter]);
                let clockwise = format!("{}", -angle.parse::<f64>().unwrap());
                succeed(
                    std::process::Command::new(&oiiotool)
                        .arg(&input)
                        .arg(format!("--rotate:filter={filter}:recompute_roi=1"))
                        .arg(&clockwise)
                        .arg("-o")
                        .arg(&theirs),
                );
                let (got, expected) = (read_image(&ours), read_image(&theirs));
                let mut differ = Vec::new();
                for (name, e) in &expected.channels {
                    for j in 0..expected.width * expected.height {
                        let x = expected.x + (j % expected.width) as i32;
                        let y = expected.y + (j / expected.width) as i32;
                        let a = got
                            .index(x, y)
                            .map_or(0.0, |i| got.channels[name].get_f32(i));
                        if a.to_bits() != e.get_f32(j).to_bits() {
                            differ.push(format!("{name} ({x}, {y}): {a} against {}", e.get_f32(j)));
                        }
                    }
                }
                assert!(
                    differ.is_empty(),
                    "{what}: {} differ, {:?}",
                    differ.len(),
                    &differ[..differ.len().min(4)]
                );
            }
        }
    }
}

#[test]
fn the_job_node_agrees_and_bad_values_are_refused() {
    let dir = tempfile::tempdir().unwrap();
    let (input, _) = plate(dir.path(), 16, 12);
    let out = dir.path().join("cli.exr");
    transform(&input, &out, &["--rotate", "10", "--center", "4,4"]);
    let from_job = one_op_job(
        dir.path(),
        &input,
        "op = \"transform\"\nrotate = 10\ncenter = \"4,4\"",
    );
    assert_identical(&read_image(&from_job), &read_image(&out));
    let bad = dir.path().join("bad.exr");
    assert_refused(
        "transform",
        &input,
        &bad,
        &[
            (&["--scale", "0"], "scale must not be 0"),
            (&["--translate", "1,2,3"], "expected X,Y"),
            (&["--rotate", "nan"], "rotate must be a number"),
            (&["--filter", "sinc"], "unknown filter"),
        ],
    );
}

/// A flip reads its input bottom-up: it streams, and its peak stays far
/// under the frame it would hold whole. A quarter turn reads a whole column
/// of its input for each output row: it holds the input, and a frame that
/// would hold more than the strip limit is refused before anything is read
/// or written.
#[test]
fn a_flip_of_a_wide_plate_streams_and_a_quarter_turn_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let input = dir.path().join("wide.exr");
    // 16384 x 1152 half RGBA: 144 MiB of pixels.
    generate(&input, "proxy", (16384, 1152), &[]);
    let out = dir.path().join("out.exr");
    let turned = run(&["transform", s(&input), "-o", s(&out), "--rotate", "90"]);
    assert_eq!(turned.status.code(), Some(3), "{}", stderr(&turned));
    let message = stderr(&turned);
    assert!(
        message.contains("wide.exr") && message.contains("a turn near 90"),
        "{message}"
    );
    assert!(!out.exists());
    for flag in ["--flip", "--flop"] {
        let done = run(&[
            "transform",
            s(&input),
            "-o",
            s(&out),
            flag,
            "--filter",
            "impulse",
            "--json",
        ]);
        assert!(done.status.success(), "{}", stderr(&done));
        let summary: serde_json::Value = serde_json::from_slice(&done.stdout).unwrap();
        let peak = summary["peak_rss_bytes"].as_u64().unwrap();
        assert!(peak < 120 << 20, "{flag}: {peak} B");
    }
}

/// A flip or a half turn reads its input's chunks bottom to top, whatever
/// their layout: scanline blocks of 1, 16 and 32 lines or tiles, in any line
/// order, a window off the display's origin, a tiled part of a multi-part
/// file;
/// output strips of 1 line (input blocks carried over many strips) to 64.
#[test]
fn flips_and_half_turns_read_any_layout_bottom_up_exactly() {
    use exr::image::Encoding;
    use exr::math::Vec2;
    use exr::prelude::{Blocks, Compression};
    let dir = tempfile::tempdir().unwrap();
    let (input, out) = (dir.path().join("in.exr"), dir.path().join("out.exr"));
    let mut img = random_rgba(5, -7, 13, 45, 83, Kind::Half, true);
    img.display = (50, 100);
    let (dw, dh) = (50, 100);
    let encoding = |compression, blocks, line_order| Encoding {
        compression,
        blocks,
        line_order,
    };
    let layouts = [
        encoding(Compression::ZIP16, Blocks::ScanLines, LineOrder::Increasing),
        encoding(Compression::PIZ, Blocks::ScanLines, LineOrder::Decreasing),
        encoding(
            Compression::Uncompressed,
            Blocks::ScanLines,
            LineOrder::Decreasing,
        ),
        encoding(
            Compression::ZIP1,
            Blocks::Tiles(Vec2(16, 16)),
            LineOrder::Unspecified,
        ),
        encoding(
            Compression::RLE,
            Blocks::Tiles(Vec2(8, 24)),
            LineOrder::Decreasing,
        ),
    ];
    let (x0, y0, w, h) = (img.x, img.y, img.width, img.height);
    let cases: Vec<(&str, Window, Source)> = vec![
        (
            "--flip",
            (x0, dh - y0 - h as i32, w, h),
            Box::new(move |x, y| (x, dh - 1 - y)),
        ),
        (
            "--rotate=180",
            (dw - x0 - w as i32, dh - y0 - h as i32, w, h),
            Box::new(move |x, y| (dw - 1 - x, dh - 1 - y)),
        ),
    ];
    for layout in layouts {
        write_encoded(&input, &img, layout);
        for (flag, window, from) in &cases {
            let expected = moved(&img, *window, from);
            for strip in ["1", "7", "64"] {
                transform(
                    &input,
                    &out,
                    &[
                        flag,
                        "--filter",
                        "impulse",
                        "--strip-rows",
                        strip,
                        "--compression",
                        "zips",
                    ],
                );
                assert_identical(&read_image(&out), &expected);
            }
        }
    }
    // The second part of a multi-part file, tiled, read bottom-up.
    let mut other = random_rgba(6, 0, 0, 50, 100, Kind::Half, false);
    other.display = img.display;
    let tiled = encoding(
        Compression::ZIP16,
        Blocks::Tiles(Vec2(16, 16)),
        LineOrder::Decreasing,
    );
    write_encoded_parts(
        &input,
        &[("a", "", &other, zip_scanlines()), ("b", "", &img, tiled)],
    );
    let (_, window, from) = &cases[0];
    let part = format!("{}:b", s(&input));
    transform(
        Path::new(&part),
        &out,
        &["--flip", "--filter", "impulse", "--strip-rows", "7"],
    );
    // The other parts are carried along, as they are.
    let parts = read_parts(&out);
    assert_identical(&parts[0], &other);
    assert_identical(&parts[1], &moved(&img, *window, from));
}

/// A blur (a halo of rows) behind a flip is computed bottom-up with its
/// input: the same bytes as the blur written whole, then flipped.
#[test]
fn a_blur_behind_a_flip_computes_bottom_up_exactly() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let (input, _) = plate(d, 60, 150);
    let blurred = d.join("blurred.exr");
    ok(&[
        "blur",
        s(&input),
        "-o",
        s(&blurred),
        "--radius",
        "6",
        "--quiet",
    ]);
    let apart = d.join("apart.exr");
    transform(&blurred, &apart, &["--flip", "--filter", "impulse"]);
    let job = d.join("job.toml");
    let out = d.join("job.exr");
    let text = format!(
        "[[node]]\nname = \"in\"\nread = \"{}\"\n\n[[node]]\nname = \"b\"\nop = \"blur\"\nradius = 6\ninputs = [\"in\"]\n\n[[node]]\nname = \"f\"\nop = \"transform\"\nflip = true\nfilter = \"impulse\"\ninputs = [\"b\"]\n\n[[node]]\nname = \"out\"\nwrite = \"{}\"\ninputs = [\"f\"]\n",
        s(&input),
        s(&out)
    );
    std::fs::write(&job, text).unwrap();
    for strip in ["1", "16"] {
        ok(&["run", s(&job), "--quiet", "--strip-rows", strip]);
        assert_identical(&read_image(&out), &read_image(&apart));
    }
}

/// oiiotool 2.4's `--flip` and `--rotate180` give the same pixels, to the
/// bit (`idiff -fail 0`), from scanline and tiled plates several strips tall.
#[test]
fn flips_and_half_turns_equal_oiiotool_to_the_bit() {
    let (Some(oiiotool), Some(idiff)) = (peer("oiiotool"), peer("idiff")) else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let (plate, _) = plate(d, 320, 517);
    let tiled = d.join("tiled.exr");
    succeed(
        std::process::Command::new(&oiiotool)
            .arg(&plate)
            .args(["--tile", "64", "64", "-o"])
            .arg(&tiled),
    );
    for input in [&plate, &tiled] {
        for (ours, theirs) in [("--flip", "--flip"), ("--rotate=180", "--rotate180")] {
            let (a, b) = (d.join("ours.exr"), d.join("theirs.exr"));
            transform(
                input,
                &a,
                &[ours, "--filter", "impulse", "--strip-rows", "16"],
            );
            succeed(
                std::process::Command::new(&oiiotool)
                    .arg(input)
                    .arg(theirs)
                    .arg("-o")
                    .arg(&b),
            );
            assert_idiff_identical(&idiff, &a, &b);
        }
    }
}

/// An image read in two orders at once (flipped and flopped, turned 150
/// degrees and moved) is held by its one read, and the result is exact; two
/// reads of the file stream each its own way.
#[test]
fn an_image_read_in_two_orders_gives_the_exact_result() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let (input, img) = plate(d, 40, 90);
    let (w, h) = (40i32, 90i32);
    let window = (0, 0, 40, 90);
    let flipped = moved(&img, window, move |x, y| (x, h - 1 - y));
    let flopped = moved(&img, window, move |x, y| (w - 1 - x, y));
    let job = |nodes: &str| {
        let path = d.join("job.toml");
        let output = d.join("job.exr");
        let text = format!(
            "{nodes}\n[[node]]\nname = \"out\"\nwrite = \"{}\"\ninputs = [\"m\"]\n",
            s(&output)
        );
        std::fs::write(&path, text).unwrap();
        let ran = run(&["run", s(&path), "--quiet", "--strip-rows", "8"]);
        assert!(ran.status.success(), "{}", stderr(&ran));
        read_image(&output)
    };
    let read = |name: &str| format!("[[node]]\nname = \"{name}\"\nread = \"{}\"\n", s(&input));
    let turn = |name: &str, how: &str, from: &str| {
        format!(
            "[[node]]\nname = \"{name}\"\nop = \"transform\"\n{how} = true\nfilter = \"impulse\"\ninputs = [\"{from}\"]\n"
        )
    };
    let over = |a: &str, b: &str| {
        format!("[[node]]\nname = \"m\"\nop = \"over\"\ninputs = [\"{a}\", \"{b}\"]\n")
    };
    // One read, flipped and flopped: the two transforms ask opposite orders.
    let nodes = [
        read("in"),
        turn("f", "flip", "in"),
        turn("g", "flop", "in"),
        over("f", "g"),
    ];
    let both = job(&nodes.concat());
    assert_identical(&both, &reference_over(&flipped, &flopped, false));
    // The plate over its own flip, the file read twice.
    let twice = job(&[
        read("in"),
        read("in2"),
        turn("f", "flip", "in"),
        over("f", "in2"),
    ]
    .concat());
    assert_identical(&twice, &reference_over(&flipped, &img, false));
    // One read, turned 150 degrees (its footprint moving up) and moved half
    // a pixel: as the over of the two made apart.
    let apart = |args: &[&str], name: &str| {
        let path = d.join(name);
        transform(&input, &path, &[args, &["--filter", "triangle"]].concat());
        read_image(&path)
    };
    let turned = apart(&["--rotate", "150"], "turned.exr");
    let shifted = apart(&["--translate", "0.5,0"], "shifted.exr");
    let node = |name: &str, knob: &str| {
        format!(
            "[[node]]\nname = \"{name}\"\nop = \"transform\"\n{knob}\nfilter = \"triangle\"\ninputs = [\"in\"]\n"
        )
    };
    let nodes = [
        read("in"),
        node("f", "rotate = 150"),
        node("g", "translate = \"0.5,0\""),
        over("f", "g"),
    ];
    assert_identical(
        &job(&nodes.concat()),
        &reference_over(&turned, &shifted, false),
    );
}
