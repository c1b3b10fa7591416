//! Peak memory stays flat in the number of frames and in image height.
//! (Absolute figures for big plates are the benchmark harness's business.)
//!
//! The peak of a pipelined run varies by up to 20% with how the stages'
//! buffers happen to coincide, so the short run's peak is the highest of
//! three; a leak of a strip per frame or per strip would still show plainly.

mod common;
use common::*;
use std::path::Path;

fn generate_sequence(
    dir: &Path,
    name: &str,
    kind: &str,
    width: usize,
    height: usize,
    frames: &str,
) {
    generate(
        &dir.join(format!("{name}.####.exr")),
        kind,
        (width, height),
        &["--frames", frames],
    );
}

/// Peak RSS of an `over` run, as the run's JSON summary reports it.
fn over_peak_rss(dir: &Path, fg: &str, bg: &str, frames: &str) -> u64 {
    let (fg, bg, out) = (dir.join(fg), dir.join(bg), dir.join("out/c.####.exr"));
    let result = run(&[
        "over",
        fg.to_str().unwrap(),
        bg.to_str().unwrap(),
        "-o",
        out.to_str().unwrap(),
        "--frames",
        frames,
        "--json",
    ]);
    assert!(result.status.success(), "{}", stderr(&result));
    let summary: serde_json::Value = serde_json::from_slice(&result.stdout).unwrap();
    summary["peak_rss_bytes"].as_u64().unwrap()
}

#[test]
fn peak_memory_does_not_grow_with_height() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    generate_sequence(d, "fs", "fg", 1024, 1024, "1");
    generate_sequence(d, "bs", "bg", 1024, 1024, "1");
    generate_sequence(d, "ft", "fg", 1024, 8192, "1");
    generate_sequence(d, "bt", "bg", 1024, 8192, "1");
    let short = (0..3)
        .map(|_| over_peak_rss(d, "fs.####.exr", "bs.####.exr", "1"))
        .max()
        .unwrap();
    let tall = over_peak_rss(d, "ft.####.exr", "bt.####.exr", "1");
    // 8 times the rows (a 64 MiB frame of raw half RGBA per input).
    assert!(
        tall as f64 <= short as f64 * 1.25,
        "short {short} B, 8x taller {tall} B"
    );
}

#[test]
fn peak_memory_does_not_grow_with_frames() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    generate_sequence(d, "f", "fg", 1024, 512, "1-16");
    generate_sequence(d, "b", "bg", 1024, 512, "1-16");
    let few = (0..3)
        .map(|_| over_peak_rss(d, "f.####.exr", "b.####.exr", "1-2"))
        .max()
        .unwrap();
    let many = over_peak_rss(d, "f.####.exr", "b.####.exr", "1-16");
    assert!(
        many as f64 <= few as f64 * 1.25,
        "2 frames {few} B, 16 frames {many} B"
    );
}
