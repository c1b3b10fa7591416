//! `--proxy-scale F`: the graph at a fraction of the size, as the same graph on
//! inputs resized first (resize's box filter) with every length in pixels
//! scaled: from the command line and from a job file; windows scaled,
//! attributes kept.

use crate::common::*;
use exr::meta::attribute::{AttributeValue, IntegerBounds};
use std::path::Path;

fn ok_run(args: &[&str]) {
    let out = run(args);
    assert!(out.status.success(), "{args:?}: {}", stderr(&out));
}

/// The windows and the string attribute `shot` of `path`.
fn header(path: &Path) -> (IntegerBounds, IntegerBounds, Option<String>) {
    let meta = exr::meta::MetaData::read_from_file(path, false).unwrap();
    let h = &meta.headers[0];
    let shot = h
        .all_named_attributes()
        .find(|(n, _)| *n == b"shot".as_slice())
        .map(|(_, v)| match v {
            AttributeValue::Text(text) => text.to_string(),
            other => panic!("shot is {other:?}"),
        });
    (h.data_window(), h.shared_attributes.display_window, shot)
}

/// What a proxy of 0.5 reads: `input` resized by half (box).
fn halved(input: &Path, output: &Path) {
    ok_run(&[
        "resize",
        s(input),
        "-o",
        s(output),
        "--scale",
        "0.5",
        "--filter",
        "box",
        "--quiet",
    ]);
}

/// A 64x48 half RGBA plate with a `shot` attribute.
fn plate(dir: &Path) -> std::path::PathBuf {
    let raw = dir.join("raw.exr");
    let mut img = random_rgba(21, 0, 0, 64, 48, Kind::Half, false);
    img.display = (64, 48);
    write_image(
        &raw,
        &img,
        compression("zip"),
        exr::meta::attribute::LineOrder::Increasing,
    );
    let input = dir.join("in.exr");
    ok_run(&[
        "transcode",
        s(&raw),
        "-o",
        s(&input),
        "--attrib",
        "shot=sh010",
        "--quiet",
    ]);
    input
}

#[test]
fn a_proxy_blur_is_the_half_radius_blur_of_the_resized_input() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let input = plate(d);
    let proxy = d.join("proxy.exr");
    ok_run(&[
        "blur",
        s(&input),
        "-o",
        s(&proxy),
        "--radius",
        "6",
        "--proxy-scale",
        "0.5",
        "--quiet",
    ]);
    let half = d.join("half.exr");
    let expected = d.join("expected.exr");
    halved(&input, &half);
    ok_run(&[
        "blur",
        s(&half),
        "-o",
        s(&expected),
        "--radius",
        "3",
        "--quiet",
    ]);
    assert_identical(&read_image(&proxy), &read_image(&expected));
    let half_size = IntegerBounds::new((0, 0), (32, 24));
    assert_eq!(header(&proxy), (half_size, half_size, Some("sh010".into())));
    assert_peers_read(&proxy);
}

#[test]
fn a_proxy_job_scales_regions_and_shifts_as_the_command_line_does() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let input = plate(d);
    let job = d.join("job.toml");
    let from_job = d.join("job.exr");
    std::fs::write(
        &job,
        format!(
            "[[node]]\nname = \"in\"\nread = \"{}\"\n\n\
             [[node]]\nname = \"c\"\nop = \"crop\"\nregion = \"40x30+4+2\"\ninputs = [\"in\"]\n\n\
             [[node]]\nname = \"t\"\nop = \"transform\"\ntranslate = \"6,-4\"\nfilter = \"impulse\"\ninputs = [\"c\"]\n\n\
             [[node]]\nname = \"out\"\nwrite = \"{}\"\ninputs = [\"t\"]\n",
            s(&input),
            s(&from_job)
        ),
    )
    .unwrap();
    ok_run(&["run", s(&job), "--proxy-scale", "0.5", "--quiet"]);
    // By hand: the input halved, the region and the shift halved.
    let half = d.join("half.exr");
    let cut = d.join("cut.exr");
    let expected = d.join("expected.exr");
    halved(&input, &half);
    ok_run(&[
        "crop",
        s(&half),
        "-o",
        s(&cut),
        "--region",
        "20x15+2+1",
        "--quiet",
    ]);
    ok_run(&[
        "transform",
        s(&cut),
        "-o",
        s(&expected),
        "--translate",
        "3,-2",
        "--filter",
        "impulse",
        "--quiet",
    ]);
    assert_identical(&read_image(&from_job), &read_image(&expected));
    let (data, display, shot) = header(&from_job);
    assert_eq!(data, IntegerBounds::new((5, 3), (20, 15)));
    assert_eq!(
        (display, shot),
        (IntegerBounds::new((0, 0), (32, 24)), Some("sh010".into()))
    );
    // The command line's crop scales its region the same way.
    let cli = d.join("cli.exr");
    ok_run(&[
        "crop",
        s(&input),
        "-o",
        s(&cli),
        "--region",
        "40x30+4+2",
        "--proxy-scale",
        "0.5",
        "--quiet",
    ]);
    assert_identical(&read_image(&cli), &read_image(&cut));
    let bad = run(&[
        "blur",
        s(&input),
        "-o",
        s(&cli),
        "--radius",
        "2",
        "--proxy-scale",
        "0",
    ]);
    assert!(
        stderr(&bad).contains("proxy_scale must be a number"),
        "{}",
        stderr(&bad)
    );
}
