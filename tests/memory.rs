//! Peak memory stays flat in the number of frames and in image height.
//! (Absolute figures for big plates are the benchmark harness's business.)
//!
//! The peak of a pipelined run varies by up to 20% with how the stages'
//! buffers happen to coincide (more on a loaded machine), so the short run's
//! peak is the highest of three and the long run's the lowest of two: a leak
//! of a strip per frame or per strip shows in every long run, plainly. The
//! two tests take turns, so that neither loads the machine for the other.

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
static ONE_AT_A_TIME: std::sync::Mutex<()> = std::sync::Mutex::new(());

/// The highest (`max`) or lowest peak RSS over `runs` runs of an `over`.
fn peak_over_runs(dir: &Path, fg: &str, bg: &str, frames: &str, runs: usize, max: bool) -> u64 {
    let peaks = (0..runs).map(|_| over_peak_rss(dir, fg, bg, frames));
    if max { peaks.max() } else { peaks.min() }.unwrap()
}

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
    let _turn = ONE_AT_A_TIME.lock().unwrap_or_else(|e| e.into_inner());
    let short = peak_over_runs(d, "fs.####.exr", "bs.####.exr", "1", 3, true);
    let tall = peak_over_runs(d, "ft.####.exr", "bt.####.exr", "1", 2, false);
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
    let _turn = ONE_AT_A_TIME.lock().unwrap_or_else(|e| e.into_inner());
    let few = peak_over_runs(d, "f.####.exr", "b.####.exr", "1-2", 3, true);
    let many = peak_over_runs(d, "f.####.exr", "b.####.exr", "1-16", 2, false);
    assert!(
        many as f64 <= few as f64 * 1.25,
        "2 frames {few} B, 16 frames {many} B"
    );
}
