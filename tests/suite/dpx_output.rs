//! DPX output (.dpx): 10-bit filled method A and 16-bit, big-endian, RGB
//! and RGBA, against oiiotool's writes of the same EXR (`-d uint10` /
//! `-d uint16`, `--attrib oiio:Endian big`): the pixels byte for byte and
//! the header but for the fields specs/file-format.md lists; timecode and
//! frame rate read back by oiiotool; --resume, interruptions, failures and
//! refusals.

use crate::common::{ok, peer, run, s, signal, started, stderr, write_flat, Samples};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Duration;

/// Where the pixels start in exrcomp's and oiiotool's DPX files.
const PIXELS: usize = 8192;

/// Header bytes that differ from oiiotool's by design: the user data's
/// size (32..36), the file name (36..136: oiiotool names its temporary
/// file), the creator (160..260) and the user data (2048..).
const OURS: [std::ops::Range<usize>; 4] = [32..36, 36..136, 160..260, 2048..PIXELS];

/// Values of every kind a conversion meets: a dense ramp over -0.25..1.25,
/// the 16-bit codes' rounding midpoints, NaN and the infinities.
fn value(i: usize) -> f32 {
    match i % 11 {
        0 => f32::NAN,
        1 => f32::INFINITY,
        2 => f32::NEG_INFINITY,
        3 => ((i * 37) % 65536) as f32 / 65535.0 + 0.5 / 65535.0,
        4 => ((i * 13) % 1024) as f32 / 1023.0,
        _ => (i as f32 * 0.000_731).fract() * 1.5 - 0.25,
    }
}

/// An EXR of float R, G, B (and A) of `value`s, `width` x 7.
fn plate(path: &Path, width: usize, alpha: bool) {
    let n = width * 7;
    let names: &[&str] = if alpha {
        &["R", "G", "B", "A"]
    } else {
        &["R", "G", "B"]
    };
    let channels: BTreeMap<String, Samples> = names
        .iter()
        .enumerate()
        .map(|(c, name)| {
            let values = (0..n).map(|i| value(i * 4 + c)).collect();
            (name.to_string(), Samples::F32(values))
        })
        .collect();
    write_flat(path, (width, 7), channels);
}

fn oiiotool_dpx(oiiotool: &Path, input: &Path, bits: &str, output: &Path) {
    let status = Command::new(oiiotool)
        .args([s(input), "-d", &format!("uint{bits}")])
        .args(["--attrib", "oiio:Endian", "big", "-o", s(output)])
        .status()
        .unwrap();
    assert!(status.success());
}

/// `bytes` with the fields exrcomp writes its own way zeroed.
fn comparable(mut bytes: Vec<u8>) -> Vec<u8> {
    for range in OURS {
        bytes[range].fill(0);
    }
    bytes
}

#[test]
fn pixels_and_header_are_oiiotools_bit_for_bit() {
    let Some(oiiotool) = peer("oiiotool") else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    for (width, alpha, bits) in [
        (1, false, "10"),
        (1, true, "10"),
        (3, false, "10"),
        (3, true, "10"),
        (33, true, "10"),
        (33, false, "16"),
        (64, true, "16"),
        (1, true, "16"),
    ] {
        let case = format!("{width} wide, alpha {alpha}, {bits} bits");
        let input = d.join(format!("in{width}{alpha}.exr"));
        plate(&input, width, alpha);
        let (ours, theirs) = (d.join("ours.dpx"), d.join("theirs.dpx"));
        ok(&["transcode", s(&input), "-o", s(&ours), "--bits", bits, "-q"]);
        oiiotool_dpx(&oiiotool, &input, bits, &theirs);
        let (a, b) = (
            std::fs::read(&ours).unwrap(),
            std::fs::read(&theirs).unwrap(),
        );
        assert_eq!(a.len(), b.len(), "{case}");
        assert!(a[PIXELS..] == b[PIXELS..], "{case}: pixels differ");
        let (a, b) = (comparable(a), comparable(b));
        let first = (0..PIXELS).find(|&i| a[i] != b[i]);
        let text = String::from_utf8_lossy(&b[820..852]).into_owned();
        assert_eq!(first, None, "{case}: header differs (first byte) {text:?}");
        let info = Command::new(&oiiotool)
            .args(["--info", "-v", s(&ours)])
            .output()
            .unwrap();
        let info = String::from_utf8_lossy(&info.stdout);
        let channels = if alpha { 4 } else { 3 };
        assert!(
            info.contains(&format!("{channels} channel, uint{bits} dpx")),
            "{case}: {info}"
        );
    }
}

#[test]
fn timecode_rate_and_transfer_are_written() {
    let Some(oiiotool) = peer("oiiotool") else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let (input, output) = (dir.path().join("in.exr"), dir.path().join("out.dpx"));
    plate(&input, 16, false);
    ok(&[
        "transcode",
        s(&input),
        "-o",
        s(&output),
        "--timecode",
        "01:02:03:04",
        "--fps",
        "24",
        "--attrib",
        "dpx:Transfer=Printing density",
        "-q",
    ]);
    let info = Command::new(&oiiotool)
        .args(["--info", "-v", s(&output)])
        .output()
        .unwrap();
    let info = String::from_utf8_lossy(&info.stdout);
    for says in [
        "dpx:TimeCode: \"01:02:03:04\"",
        "dpx:FrameRate: 24",
        "dpx:Transfer: \"Printing density\"",
        "Software: \"exrcomp",
    ] {
        assert!(info.contains(says), "{says}: {info}");
    }
    // exrcomp reads them back as OpenEXR's attributes.
    let out = run(&["info", s(&output)]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("01:02:03:04"), "{text}");
    assert!(text.contains("24"), "{text}");
}

fn frames(dir: &Path, count: i64, width: usize) -> PathBuf {
    for frame in 1..=count {
        plate(&dir.join(format!("in.{frame:04}.exr")), width, true);
    }
    dir.join("in.####.exr")
}

#[test]
fn resume_keeps_this_jobs_frames_and_redoes_others() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let pattern = frames(d, 3, 40);
    let out = d.join("out.####.dpx");
    let path = |f: i64| d.join(format!("out.{f:04}.dpx"));
    ok(&["transcode", s(&pattern), "-o", s(&out), "-q"]);
    let whole: Vec<Vec<u8>> = (1..=3).map(|f| std::fs::read(path(f)).unwrap()).collect();
    // Frame 2 cut short, frame 3 another job's (16-bit).
    std::fs::write(path(2), &whole[1][..whole[1].len() - 100]).unwrap();
    let other = d.join("other.dpx");
    let input3 = d.join("in.0003.exr");
    ok(&[
        "transcode",
        s(&input3),
        "-o",
        s(&other),
        "--bits",
        "16",
        "-q",
    ]);
    std::fs::rename(&other, path(3)).unwrap();
    let before = std::fs::metadata(path(1)).unwrap().modified().unwrap();
    std::thread::sleep(Duration::from_millis(20));
    ok(&["transcode", s(&pattern), "-o", s(&out), "--resume", "-q"]);
    let after = std::fs::metadata(path(1)).unwrap().modified().unwrap();
    assert_eq!(before, after, "frame 1 was written again");
    for f in 1..=3 {
        assert!(
            std::fs::read(path(f)).unwrap() == whole[f as usize - 1],
            "frame {f}"
        );
    }
    // The same job writes the same bytes.
    std::fs::remove_file(path(1)).unwrap();
    ok(&["transcode", s(&pattern), "-o", s(&out), "--resume", "-q"]);
    assert!(std::fs::read(path(1)).unwrap() == whole[0]);
}

/// The names in `dir` starting with "out".
fn outputs(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.contains("out"))
        .collect();
    names.sort();
    names
}

#[test]
fn a_failed_or_interrupted_frame_leaves_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let pattern = frames(d, 2, 8);
    // Frame 2's input cut: frame 1 is written, frame 2 nothing.
    let cut = d.join("in.0002.exr");
    let bytes = std::fs::read(&cut).unwrap();
    std::fs::write(&cut, &bytes[..bytes.len() - 20]).unwrap();
    let out = run(&[
        "transcode",
        s(&pattern),
        "-o",
        s(&d.join("out.####.dpx")),
        "-q",
    ]);
    assert!(!out.status.success());
    assert_eq!(outputs(d), ["out.0001.dpx"], "{}", stderr(&out));
    // Interrupted inside a large frame: nothing at the path, no temporary.
    let big = d.join("big.exr");
    crate::common::generate(&big, "bg", (4096, 2048), &[]);
    let target = d.join("out.big.dpx");
    let mut child = started(&[
        "transcode",
        s(&big),
        "-o",
        s(&target),
        "-q",
        "--strip-rows",
        "1",
    ]);
    // Signalled while the frame is being written: once its temporary is there.
    let writing = || outputs(d).iter().any(|n| n.ends_with(".tmp"));
    let start = std::time::Instant::now();
    while !writing() && start.elapsed() < Duration::from_secs(30) {
        std::thread::sleep(Duration::from_millis(1));
    }
    signal(&child, "-INT");
    let status = child.wait().unwrap();
    assert_eq!(status.code(), Some(130), "finished before the signal");
    assert_eq!(outputs(d), ["out.0001.dpx"]);
}

#[test]
fn an_output_naming_an_input_and_options_that_do_not_fit_are_refused() {
    let dir = tempfile::tempdir().unwrap();
    let (input, dpx) = (dir.path().join("in.exr"), dir.path().join("in.dpx"));
    plate(&input, 8, false);
    ok(&["transcode", s(&input), "-o", s(&dpx), "-q"]);
    let before = std::fs::read(&dpx).unwrap();
    for (args, says) in [
        (vec!["transcode", s(&dpx), "-o", s(&dpx)], "in.dpx"),
        (
            vec!["transcode", s(&input), "-o", "x.dpx", "--bits", "8"],
            "10 bits",
        ),
        (
            vec!["transcode", s(&input), "-o", "x.dpx", "--bits", "float"],
            "10 bits",
        ),
        (
            vec!["transcode", s(&input), "-o", "x.png", "--bits", "10"],
            "10 bits",
        ),
        (
            vec!["transcode", s(&input), "-o", "x.dpx", "--transfer", "srgb"],
            "as they are",
        ),
        (
            vec![
                "transcode",
                s(&input),
                "-o",
                "x.dpx",
                "--burn-in",
                "{frame}",
            ],
            "--burn-in",
        ),
        (
            vec![
                "transcode",
                s(&input),
                "-o",
                "x.dpx",
                "--compression",
                "zip",
            ],
            "EXR outputs",
        ),
    ] {
        let out = run(&args);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {}", stderr(&out));
        assert!(stderr(&out).contains(says), "{args:?}: {}", stderr(&out));
    }
    assert!(std::fs::read(&dpx).unwrap() == before);
}
