//! A resize or reformat that keeps the image's size copies its samples bit
//! for bit, whatever the filter (oiiotool 2.4's `--resize` and `--fit` at the
//! same size do): u32 ids, NaN and infinities included, placed where the
//! format puts them; one side kept and the other changed is filtered on
//! both, as oiiotool does.

use crate::common::*;
use crate::passthrough::same_as_oiiotool;
use exr::math::Vec2;
use exr::prelude::{Blocks, Compression, Encoding, LineOrder};
use std::path::Path;

/// Half RGBA, float Z and u32 ids in a 40x30 window at (3, 5) of a 46x40
/// frame; with `specials`, NaN and infinities in R and Z.
fn plate(specials: bool) -> Img {
    let mut img = random_rgba(31, 3, 5, 40, 30, Kind::Half, true);
    img.display = (46, 40);
    if specials {
        for (k, v) in [f32::NAN, f32::INFINITY, f32::NEG_INFINITY]
            .iter()
            .enumerate()
        {
            for name in ["R", "Z"] {
                let samples = img.channels.get_mut(name).unwrap();
                samples.set_f32(7 + 41 * k, *v);
            }
        }
    }
    img
}

fn encodings() -> [(&'static str, Encoding); 2] {
    let tiles = Encoding {
        compression: Compression::ZIP16,
        blocks: Blocks::Tiles(Vec2(16, 16)),
        line_order: LineOrder::Increasing,
    };
    [("scanline", zip_scanlines()), ("tiled", tiles)]
}

fn ran(command: &str, input: &Path, out: &Path, args: &[&str]) -> Img {
    let mut all = vec![command, s(input), "-o", s(out), "--quiet"];
    all.extend(args);
    let ran = run(&all);
    assert!(ran.status.success(), "{all:?}: {}", stderr(&ran));
    read_image(out)
}

#[test]
fn a_resize_or_reformat_to_the_same_size_is_its_input_bit_for_bit() {
    let dir = tempfile::tempdir().unwrap();
    let img = plate(true);
    for (kind, encoding) in encodings() {
        let input = dir.path().join(format!("{kind}.exr"));
        write_encoded(&input, &img, encoding);
        let out = dir.path().join("out.exr");
        for filter in ["box", "triangle", "gaussian", "mitchell", "lanczos3"] {
            for args in [["--size", "46x40"], ["--scale", "1"]] {
                let got = ran(
                    "resize",
                    &input,
                    &out,
                    &[args[0], args[1], "--filter", filter],
                );
                assert_identical(&got, &img);
            }
            let args = ["--format", "46x40", "--filter", filter];
            assert_identical(&ran("reformat", &input, &out, &args), &img);
        }
        // Kept by every fit, placed (centred: 3 columns right, 10 rows
        // down), the format the display window.
        for (format, fit, (dx, dy)) in [
            ("46x40", "fill", (0, 0)),
            ("46x40", "distort", (0, 0)),
            ("52x40", "fit", (3, 0)),
            ("52x40", "height", (3, 0)),
            ("46x60", "width", (0, 10)),
        ] {
            let args = ["--format", format, "--fit", fit, "--center"];
            let got = ran("reformat", &input, &out, &args);
            let mut expected = img.clone();
            (expected.x, expected.y) = (img.x + dx, img.y + dy);
            expected.display = (46 + 2 * dx as usize, 40 + 2 * dy as usize);
            assert_identical(&got, &expected);
        }
    }
}

#[test]
fn at_the_same_size_oiiotool_resize_and_fit_agree_to_the_bit() {
    let dir = tempfile::tempdir().unwrap();
    let img = plate(false);
    for (kind, encoding) in encodings() {
        let input = dir.path().join(format!("{kind}.exr"));
        write_encoded(&input, &img, encoding);
        let out = dir.path().join("out.exr");
        ran("resize", &input, &out, &["--size", "46x40"]);
        same_as_oiiotool(&input, &["--resize", "46x40"], &out);
    }
    // oiiotool 2.4's --fit places the data window as if it were the display
    // window (its offset dropped, at any size): compared where they agree.
    let mut full = random_rgba(33, 0, 0, 46, 40, Kind::Half, true);
    full.display = (46, 40);
    for (kind, encoding) in encodings() {
        let input = dir.path().join(format!("full-{kind}.exr"));
        write_encoded(&input, &full, encoding);
        let out = dir.path().join("out.exr");
        for format in ["46x40", "52x40", "46x61"] {
            let args = ["--format", format, "--fit", "fit", "--center"];
            ran("reformat", &input, &out, &args);
            same_as_oiiotool(&input, &["--fit", format], &out);
        }
    }
    let Some(desk) = public_image("ScanLines/Desk.exr") else {
        return;
    };
    let out = dir.path().join("desk.exr");
    for (format, fit) in [
        ("644x874", "width"),
        ("700x874", "fit"),
        ("644x1000", "fit"),
    ] {
        let args = [
            "--format", format, "--fit", fit, "--center", "--filter", "mitchell",
        ];
        ran("reformat", &desk, &out, &args);
        same_as_oiiotool(&desk, &["--fit:filter=mitchell", format], &out);
    }
    ran("resize", &desk, &out, &["--size", "644x874"]);
    same_as_oiiotool(&desk, &["--resize", "644x874"], &out);
}

/// The same width and another height is filtered across too (oiiotool's
/// rule): Mitchell's taps at one pixel weigh 1/18.
#[test]
fn one_side_kept_is_still_filtered_as_oiiotool_filters_it() {
    let dir = tempfile::tempdir().unwrap();
    let input = dir.path().join("in.exr");
    // A one-pixel vertical line at column 10.
    let mut img = random_rgba(32, 0, 0, 24, 24, Kind::Float, false);
    img.display = (24, 24);
    for samples in img.channels.values_mut() {
        (0..24 * 24).for_each(|i| samples.set_f32(i, (i % 24 == 10) as u8 as f32));
    }
    write_image(&input, &img, Compression::ZIP16, LineOrder::Increasing);
    let out = dir.path().join("out.exr");
    let got = ran(
        "resize",
        &input,
        &out,
        &["--size", "24x12", "--filter", "mitchell"],
    );
    let beside = got.channels["R"].get_f32(got.index(11, 5).unwrap());
    assert!((beside - 1.0 / 18.0).abs() < 1e-3, "{beside}");
}
