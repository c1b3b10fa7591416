//! The streaming `over` against the whole-image reference in tests/suite/common.

use crate::common::*;
use exr::prelude::LineOrder;
use std::path::Path;

/// How the inputs are written: compression of fg and of bg, line order.
struct Inputs<'a>(&'a str, &'a str, LineOrder);

/// Composites fg over bg with exrcomp and with the reference; returns both.
/// The output is `dir/out.exr`, and OpenEXR must read it too.
fn composite_inputs(dir: &Path, fg: &Img, bg: &Img, inputs: Inputs, args: &[&str]) -> (Img, Img) {
    let (fg_path, bg_path, out_path) =
        (dir.join("fg.exr"), dir.join("bg.exr"), dir.join("out.exr"));
    write_image(&fg_path, fg, compression(inputs.0), inputs.2);
    write_image(&bg_path, bg, compression(inputs.1), inputs.2);
    let mut command = vec!["over", s(&fg_path), s(&bg_path), "-o", s(&out_path), "-q"];
    command.extend_from_slice(args);
    let out = run(&command);
    assert!(out.status.success(), "exrcomp failed: {}", stderr(&out));
    assert_peers_read(&out_path);
    let straight = args.contains(&"--straight");
    (
        read_image(&out_path),
        reference_over(&read_image(&fg_path), &read_image(&bg_path), straight),
    )
}

/// Both inputs in `input_compression`, increasing line order.
fn composite(dir: &Path, fg: &Img, bg: &Img, input_compression: &str, args: &[&str]) -> (Img, Img) {
    let inputs = Inputs(input_compression, input_compression, LineOrder::Increasing);
    composite_inputs(dir, fg, bg, inputs, args)
}

#[test]
fn float_over_equals_reference_for_every_lossless_compression_and_odd_windows() {
    let dir = tempfile::tempdir().unwrap();
    // Windows that start off zero and do not align with 1-, 16- or 32-line blocks.
    let fg = random_rgba(1, 3, 5, 37, 45, Kind::Float, false);
    let bg = random_rgba(2, -4, -7, 29, 70, Kind::Float, true);
    for c in ["none", "rle", "zips", "zip", "piz"] {
        // The inputs in one compression, the output in another, in strips of
        // one block, of a few blocks, and of the whole image.
        for out_c in ["none", "zips", "zip", "piz"] {
            for strip in ["1", "20", "100"] {
                let args = ["--compression", out_c, "--strip-rows", strip];
                let (ours, reference) = composite(dir.path(), &fg, &bg, c, &args);
                assert_identical(&ours, &reference);
            }
        }
    }
}

#[test]
fn half_over_equals_reference_and_keeps_half() {
    let dir = tempfile::tempdir().unwrap();
    let fg = random_rgba(3, 0, 0, 50, 40, Kind::Half, false);
    let bg = random_rgba(4, 10, -3, 50, 40, Kind::Half, true);
    let (ours, reference) = composite(dir.path(), &fg, &bg, "zip", &[]);
    assert!(
        matches!(ours.channels["R"], Samples::F16(_)),
        "half stays half"
    );
    assert!(
        matches!(ours.channels["id"], Samples::U32(_)),
        "u32 stays u32"
    );
    assert_identical(&ours, &reference);
}

#[test]
fn straight_over_equals_reference_and_the_opaque_background_formula() {
    let dir = tempfile::tempdir().unwrap();
    let fg = random_rgba(5, 0, 0, 33, 17, Kind::Float, false);
    let mut bg = random_rgba(6, 0, 0, 33, 17, Kind::Float, false);
    let (ours, reference) = composite(dir.path(), &fg, &bg, "zip", &["--straight"]);
    assert_identical(&ours, &reference);

    // With an opaque background, straight over is C = af Cf + (1 - af) Cb.
    bg.channels
        .insert("A".into(), Samples::F32(vec![1.0; 33 * 17]));
    let (ours, _) = composite(dir.path(), &fg, &bg, "zip", &["--straight"]);
    for i in 0..33 * 17 {
        let af = fg.channels["A"].get_f32(i);
        let expected = af * fg.channels["G"].get_f32(i) + (1.0 - af) * bg.channels["G"].get_f32(i);
        assert_eq!(ours.channels["G"].get_f32(i), expected, "pixel {i}");
    }
}

#[test]
fn premultiplied_over_matches_the_spec_formula_at_sample_pixels() {
    // Independent of the reference: C = Cf + (1 - af) Cb, a = af + (1 - af) ab.
    let dir = tempfile::tempdir().unwrap();
    let fg = random_rgba(7, 0, 0, 16, 16, Kind::Float, false);
    let bg = random_rgba(8, 0, 0, 16, 16, Kind::Float, false);
    let (ours, _) = composite(dir.path(), &fg, &bg, "none", &[]);
    for i in [0, 17, 100, 255] {
        let af = fg.channels["A"].get_f32(i);
        let ab = bg.channels["A"].get_f32(i);
        let r = fg.channels["R"].get_f32(i) + (1.0 - af) * bg.channels["R"].get_f32(i);
        assert_eq!(ours.channels["R"].get_f32(i), r);
        assert_eq!(ours.channels["A"].get_f32(i), af + (1.0 - af) * ab);
    }
}

#[test]
fn inputs_without_alpha_are_opaque_inside_their_window() {
    let dir = tempfile::tempdir().unwrap();
    let mut fg = random_rgba(9, 4, 4, 8, 8, Kind::Float, false);
    fg.channels.remove("A");
    let bg = random_rgba(10, 0, 0, 20, 20, Kind::Float, false);
    let (ours, reference) = composite(dir.path(), &fg, &bg, "zips", &[]);
    assert_identical(&ours, &reference);
    // Inside fg's window the output is fg's colour exactly.
    let i = ours.index(5, 6).unwrap();
    let j = fg.index(5, 6).unwrap();
    assert_eq!(ours.channels["B"].get_f32(i), fg.channels["B"].get_f32(j));
}

#[test]
fn decreasing_line_order_inputs_read_right() {
    let dir = tempfile::tempdir().unwrap();
    let fg = random_rgba(11, 0, 0, 40, 70, Kind::Half, false);
    let bg = random_rgba(12, 0, 0, 40, 70, Kind::Half, false);
    let inputs = Inputs("zip", "piz", LineOrder::Decreasing);
    let (ours, reference) = composite_inputs(dir.path(), &fg, &bg, inputs, &[]);
    assert_identical(&ours, &reference);
}

#[test]
fn background_attributes_and_display_window_are_kept() {
    let dir = tempfile::tempdir().unwrap();
    let fg = random_rgba(13, -8, -8, 20, 20, Kind::Half, false);
    let mut bg = random_rgba(14, 0, 0, 30, 20, Kind::Half, false);
    bg.display = (30, 20);
    let inputs = Inputs("rle", "piz", LineOrder::Increasing);
    composite_inputs(dir.path(), &fg, &bg, inputs, &[]);
    let out = dir.path().join("out.exr");
    let meta = exr::meta::MetaData::read_from_file(&out, false).unwrap();
    let header = &meta.headers[0];
    assert_eq!(
        header.compression,
        compression("piz"),
        "compression defaults to the background's"
    );
    assert_eq!(
        header
            .own_attributes
            .comments
            .as_ref()
            .map(|t| t.to_string())
            .as_deref(),
        Some("written by the tests")
    );
    let display = header.shared_attributes.display_window;
    assert_eq!((display.size.width(), display.size.height()), (30, 20));
    let window = header.data_window();
    assert_eq!(
        (window.position.x(), window.position.y()),
        (-8, -8),
        "data window is the union"
    );
    assert_eq!((window.size.width(), window.size.height()), (38, 28));
}

#[test]
fn zip_levels_change_the_size_not_the_pixels() {
    let dir = tempfile::tempdir().unwrap();
    let fg = random_rgba(15, 0, 0, 64, 64, Kind::Half, false);
    let bg = random_rgba(16, 0, 0, 64, 64, Kind::Half, true);
    let (fast, reference) = composite(dir.path(), &fg, &bg, "zip", &["--zip-level", "1"]);
    assert_identical(&fast, &reference);
    let fast_size = std::fs::metadata(dir.path().join("out.exr")).unwrap().len();
    let (small, _) = composite(dir.path(), &fg, &bg, "zip", &["--zip-level", "12"]);
    assert_identical(&small, &reference);
    let small_size = std::fs::metadata(dir.path().join("out.exr")).unwrap().len();
    assert!(
        small_size < fast_size,
        "level 12: {small_size} B, level 1: {fast_size} B"
    );
    let out = run(&["over", "a.exr", "b.exr", "-o", "c.exr", "--zip-level", "13"]);
    assert_eq!(out.status.code(), Some(2));
}

#[test]
fn where_the_foreground_adds_nothing_the_background_stays_bit_for_bit() {
    // -0 in B survives under transparent black A, whole rows or single pixels.
    let dir = tempfile::tempdir().unwrap();
    let mut fg = random_rgba(17, 0, 0, 16, 8, Kind::Half, false);
    let mut bg = random_rgba(18, 0, 0, 16, 8, Kind::Half, false);
    for name in ["R", "G", "B", "A"] {
        let Samples::F16(v) = fg.channels.get_mut(name).unwrap() else {
            unreachable!()
        };
        v[..16 * 4].fill(half::f16::ZERO); // rows 0-3 transparent black
        v[16 * 5 + 3] = half::f16::ZERO; // and one pixel of row 5
        let Samples::F16(v) = bg.channels.get_mut(name).unwrap() else {
            unreachable!()
        };
        v.fill(half::f16::NEG_ZERO);
    }
    let (ours, reference) = composite(dir.path(), &fg, &bg, "zip", &[]);
    assert_identical(&ours, &reference);
    for i in (0..16 * 4).chain([16 * 5 + 3]) {
        assert_eq!(ours.channels["G"].bits(i), 0x8000, "pixel {i} keeps B's -0");
    }
}
