//! Views and parts beyond one colour part a view: a view's colour read from
//! whichever of its parts has it, luminance-only views, `--all-parts` over
//! parts an operation does not apply to, `--part` on every command, and a
//! damaged input's error alone on its line.

use crate::common::*;
use std::collections::BTreeMap;
use std::path::Path;

/// A part holding only a float depth channel `Z`, on `like`'s window.
fn depth_only(like: &Img, seed: u64) -> Img {
    let mut rng = Lcg(seed);
    let z = (0..like.width * like.height).map(|_| rng.next() * 50.0);
    Img {
        channels: BTreeMap::from([("Z".to_string(), Samples::F32(z.collect()))]),
        ..like.clone()
    }
}

fn ok_run(args: &[&str]) -> String {
    let out = run(args);
    assert!(out.status.success(), "{args:?}: {}", stderr(&out));
    stderr(&out)
}

/// A stereo file whose left view has its depth part first (`depth_left`,
/// then `rgba_left`): `--view left` takes the colour from `rgba_left`; it
/// had picked the depth part and failed "layer '(unnamed)' not found".
#[test]
fn a_view_takes_its_colour_from_whichever_of_its_parts_has_it() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let left = random_rgba(81, 0, 0, 20, 14, Kind::Half, false);
    let right = random_rgba(82, 1, 0, 18, 14, Kind::Half, false);
    let (depth_left, depth_right) = (depth_only(&left, 83), depth_only(&right, 84));
    let stereo = d.join("stereo.exr");
    let parts = [
        ("depth_left", "left", &depth_left),
        ("rgba_left", "left", &left),
        ("rgba_right", "right", &right),
        ("depth_right", "right", &depth_right),
    ];
    write_parts(&stereo, &parts);
    for (view, index, image) in [("left", 1, &left), ("right", 2, &right)] {
        let out = d.join(format!("{view}.exr"));
        let args = ["over", s(&stereo), s(&stereo), "-o", s(&out), "-q"];
        ok_run(&[&args[..], &["--view", view]].concat());
        let written = read_parts(&out);
        assert_eq!(written.len(), 4, "{view}");
        for (i, part) in written.iter().enumerate() {
            match i == index {
                true => assert_identical(part, &reference_over(image, image, false)),
                false => assert_identical(part, parts[i].2),
            }
        }
    }
}

/// A luminance-only view (`Y`) of a multi-view file is read as grey, as
/// the default view is: single-part (`Y` and `right.Y`) and multi-part.
#[test]
fn a_luminance_only_view_is_read_as_grey() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let grey = |seed: u64| {
        let rgba = random_rgba(seed, 0, 0, 16, 10, Kind::Half, false);
        let y = rgba.channels["G"].clone();
        Img {
            channels: BTreeMap::from([("Y".to_string(), y)]),
            ..rgba
        }
    };
    let (left, right) = (grey(91), grey(92));
    // The reference: each view alone, in a file of its own.
    let exposed = |input: &Path, name: &str, args: &[&str]| {
        let out = d.join(format!("{name}.exr"));
        let command = ["exposure", s(input), "-o", s(&out), "--stops", "1", "-q"];
        ok_run(&[&command[..], args].concat());
        out
    };
    let alone = |img: &Img, name: &str| {
        let path = d.join(format!("{name}-alone.exr"));
        write_image(
            &path,
            img,
            exr::prelude::Compression::ZIP16,
            exr::prelude::LineOrder::Increasing,
        );
        read_image(&exposed(&path, &format!("{name}-ref"), &[]))
    };
    let (left_ref, right_ref) = (alone(&left, "left"), alone(&right, "right"));
    let colour = |img: &Img, prefix: &str| -> Vec<u32> {
        let plane = &img.channels[&format!("{prefix}G")];
        (0..plane.len()).map(|i| plane.bits(i)).collect()
    };

    let parts = d.join("parts.exr");
    write_parts(
        &parts,
        &[("y_left", "left", &left), ("y_right", "right", &right)],
    );
    for (view, index, reference) in [("left", 0, &left_ref), ("right", 1, &right_ref)] {
        let out = exposed(&parts, &format!("parts-{view}"), &["--view", view]);
        let written = &read_parts(&out)[index];
        assert_eq!(colour(written, ""), colour(reference, ""), "parts {view}");
    }

    let mut both = left.clone();
    both.channels
        .insert("right.Y".into(), right.channels["Y"].clone());
    let single = d.join("single.exr");
    write_multi_view(&single, &both, &["left", "right"]);
    let out = exposed(&single, "single-right", &["--view", "right"]);
    assert_eq!(
        colour(&read_image(&out), "right."),
        colour(&right_ref, ""),
        "single-part right"
    );
    let out = exposed(&single, "single-left", &["--view", "left"]);
    assert_eq!(colour(&read_image(&out), ""), colour(&left_ref, ""));
}

/// `blur --all-parts` over a file with a depth-only part: that part is
/// written unchanged, with a note naming it; the colour part is blurred as
/// it is alone. It had failed the frame.
#[test]
fn all_parts_carries_a_part_the_operation_does_not_apply_to() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let rgba = random_rgba(95, 0, 0, 24, 16, Kind::Half, true);
    let depth = depth_only(&rgba, 96);
    let input = d.join("parts.exr");
    write_parts(&input, &[("depth", "", &depth), ("rgba", "", &rgba)]);
    let out = d.join("blurred.exr");
    let message = ok_run(&[
        "blur",
        s(&input),
        "-o",
        s(&out),
        "--radius",
        "2",
        "--all-parts",
    ]);
    assert!(
        message.contains("exrcomp: warning: part 0 ('depth') is written unchanged"),
        "{message}"
    );
    let written = read_parts(&out);
    assert_eq!(written.len(), 2);
    assert_identical(&written[0], &depth);
    let alone = d.join("rgba.exr");
    write_parts(&alone, &[("rgba", "", &rgba)]);
    let reference = d.join("rgba-blurred.exr");
    ok_run(&[
        "blur",
        s(&alone),
        "-o",
        s(&reference),
        "--radius",
        "2",
        "-q",
    ]);
    assert_identical(&written[1], &read_image(&reference));
}

/// The README's `--part PART` works on every command that reads EXR
/// inputs, as `FILE:PART` does; twelve refused it ("unexpected argument").
#[test]
fn every_command_takes_part() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let first = random_rgba(97, 0, 0, 16, 12, Kind::Half, true);
    let second = random_rgba(98, 0, 0, 16, 12, Kind::Half, true);
    let input = d.join("two.exr");
    write_parts(&input, &[("a", "", &first), ("b", "", &second)]);
    for command in [
        "zmerge",
        "resize",
        "stereo",
        "reformat",
        "crop",
        "diffrender",
        "key",
        "diffmatte",
        "triangulate",
        "shuffle",
        "copy",
        "transcode",
        "flatten",
    ] {
        let help = run(&[command, "--help"]);
        let text = String::from_utf8_lossy(&help.stdout);
        assert!(text.contains("--part <PART>"), "{command}: {text}");
    }
    let by = |name: &str, args: &[&str]| {
        let out = d.join(format!("{name}.exr"));
        let command = ["shuffle", "-o", s(&out), "--ch", "R=G,G=R,B,A", "-q"];
        ok_run(&[&command[..], args].concat());
        read_parts(&out)
    };
    let by_suffix = by("suffix", &[&format!("{}:b", s(&input))]);
    let by_option = by("option", &[s(&input), "--part", "b"]);
    assert_eq!(by_option.len(), 2);
    for (a, b) in by_suffix.iter().zip(&by_option) {
        assert_identical(a, b);
    }
    assert_identical(&by_option[0], &first);
    let transcoded = d.join("transcoded.exr");
    ok_run(&[
        "transcode",
        s(&input),
        "--part",
        "1",
        "-o",
        s(&transcoded),
        "-q",
    ]);
    assert_identical(&read_parts(&transcoded)[1], &second);
}

/// A damaged input without alpha (a ZIP chunk whose stream is garbage)
/// under `over`: the error alone, in one line; the no-alpha warning had
/// come first.
#[test]
fn a_damaged_input_s_error_is_one_line_without_warnings_before_it() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let mut rgb = random_rgba(99, 0, 0, 16, 32, Kind::Half, false);
    rgb.channels.remove("A");
    let (fg, bg) = (d.join("fg.exr"), d.join("bg.exr"));
    write_image(
        &fg,
        &rgb,
        exr::prelude::Compression::ZIP16,
        exr::prelude::LineOrder::Increasing,
    );
    write_image(
        &bg,
        &random_rgba(100, 0, 0, 16, 32, Kind::Half, false),
        exr::prelude::Compression::ZIP16,
        exr::prelude::LineOrder::Increasing,
    );
    // Chunk 1's compressed bytes, after its y and size fields, overwritten.
    let file = exrcomp::io::reader::ExrFile::open(&fg, None).unwrap();
    let start = file.chunk_range(0, 1).start as usize + 8;
    let mut bytes = std::fs::read(&fg).unwrap();
    bytes[start..start + 16].fill(0xFF);
    std::fs::write(&fg, bytes).unwrap();
    let out = run(&["over", s(&fg), s(&bg), "-o", s(&d.join("out.exr"))]);
    let message = stderr(&out);
    assert_eq!(out.status.code(), Some(3), "{message}");
    assert_eq!(message.trim_end().lines().count(), 1, "{message}");
    assert!(message.contains("fg.exr"), "{message}");
}
