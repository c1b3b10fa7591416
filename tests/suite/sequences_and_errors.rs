//! Frame patterns and ranges, the run summary, and bad input: clear errors
//! naming the file and frame, the right exit codes, nothing half-written.

use crate::common::*;
use exr::prelude::LineOrder;
use std::path::Path;

fn entries(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .map(|d| {
            d.map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
                .collect()
        })
        .unwrap_or_default();
    names.sort();
    names
}

#[test]
fn frames_default_to_those_on_disk_gaps_included_and_printf_patterns_work() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write_sequence(d, "fg", [7, 8, 10], 0);
    write_sequence(d, "bg", [7, 8, 9, 10], 100);
    let (fg, bg, output) = (
        d.join("fg.%04d.exr"),
        d.join("bg.####.exr"),
        d.join("out/c.####.exr"),
    );
    let over = |extra: &[&str]| {
        let mut args = vec!["over", s(&fg), s(&bg), "-o", s(&output), "-q"];
        args.extend_from_slice(extra);
        run(&args)
    };
    // The gap at 9 is a missing frame, listed before any work.
    let out = over(&[]);
    assert_eq!(out.status.code(), Some(3), "{}", stderr(&out));
    assert!(stderr(&out).contains("missing frame 9"), "{}", stderr(&out));
    assert!(!d.join("out").exists());
    let out = over(&["--missing", "skip"]);
    assert!(out.status.success(), "{}", stderr(&out));
    assert_eq!(
        entries(&d.join("out")),
        ["c.0007.exr", "c.0008.exr", "c.0010.exr"]
    );
    let expected = reference_over(
        &read_image(&d.join("fg.0010.exr")),
        &read_image(&d.join("bg.0010.exr")),
        false,
    );
    assert_identical(&read_image(&d.join("out/c.0010.exr")), &expected);
}

/// Every spelling of an input as the output is refused before any work,
/// naming both, in commands, job files and stitch; the inputs stay as they were.
#[test]
fn an_output_naming_an_input_by_any_spelling_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write_sequence(d, "bg", [1, 2], 0);
    write_sequence(d, "fg", [1, 2], 10);
    std::os::unix::fs::symlink(d, d.join("self")).unwrap();
    std::fs::create_dir(d.join("here")).unwrap();
    std::os::unix::fs::symlink(d.join("bg.0001.exr"), d.join("link.exr")).unwrap();
    let before = std::fs::read(d.join("bg.0001.exr")).unwrap();
    let refused = |args: &[&str]| {
        let out = exrcomp()
            .args(args)
            .current_dir(d.join("here"))
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(2), "{args:?}: {}", stderr(&out));
        assert!(
            stderr(&out).contains("refusing to overwrite an input"),
            "{args:?}: {}",
            stderr(&out)
        );
    };
    let (fg1, bg1) = (d.join("fg.0001.exr"), d.join("bg.0001.exr"));
    let (fg1, bg1) = (s(&fg1), s(&bg1));
    refused(&["over", fg1, bg1, "-o", "../bg.0001.exr"]);
    refused(&["over", fg1, bg1, "-o", "./../self/bg.0001.exr"]);
    refused(&["over", fg1, bg1, "-o", bg1]);
    refused(&["over", fg1, s(&d.join("link.exr")), "-o", "../bg.0001.exr"]);
    refused(&["over", fg1, "../link.exr", "-o", "../self/link.exr"]);
    refused(&[
        "over",
        "../fg.####.exr",
        "../bg.####.exr",
        "-o",
        "../self/bg.####.exr",
    ]);
    refused(&[
        "blur",
        "../bg.####.exr",
        "-o",
        "../here/../bg.####.exr",
        "--radius",
        "1",
    ]);
    // Another pattern that reaches an input's file at another frame.
    refused(&[
        "transcode",
        "../bg.####.exr",
        "-o",
        "../bg.000#.exr",
        "--frames",
        "1",
    ]);
    refused(&["stitch", fg1, bg1, "-o", "../self/bg.0001.exr"]);
    std::fs::write(
        d.join("job.toml"),
        "[[node]]\nname = \"bg\"\nread = \"bg.####.exr\"\n\n\
         [[node]]\nname = \"out\"\nwrite = \"./self/bg.####.exr\"\ninputs = [\"bg\"]\n",
    )
    .unwrap();
    refused(&["run", "../job.toml"]);
    assert_eq!(std::fs::read(d.join("bg.0001.exr")).unwrap(), before);
}

#[test]
fn outputs_must_be_of_a_format_written_and_patterns_sane() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write_sequence(d, "bg", [1], 0);
    for (output, text) in [
        ("x.gif", "does not end in .exr, .png"),
        ("x.####.exr.tmp", "does not end in .exr, .png"),
        ("out/b.%099999d.exr", "at most 20"),
    ] {
        let (input, output_path) = (d.join("bg.####.exr"), d.join(output));
        let out = run(&["transcode", s(&input), "-o", s(&output_path)]);
        assert_eq!(out.status.code(), Some(2), "{output}: {}", stderr(&out));
        assert!(stderr(&out).contains(text), "{output}: {}", stderr(&out));
    }
    // stitch joins EXR chunks: its output is EXR.
    let band = d.join("bg.0001.exr");
    let out = run(&["stitch", s(&band), s(&band), "-o", s(&d.join("x.png"))]);
    assert_eq!(out.status.code(), Some(2), "{}", stderr(&out));
    assert!(
        stderr(&out).contains("stitch writes EXR"),
        "{}",
        stderr(&out)
    );
    assert_eq!(entries(d), ["bg.0001.exr"]);
}

#[test]
fn frame_lists_and_steps_select_frames() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write_sequence(d, "fg", [1, 2, 3, 4, 5, 6], 0);
    let out = run(&[
        "over",
        s(&d.join("fg.####.exr")),
        s(&d.join("fg.####.exr")),
        "-o",
        s(&d.join("o/x.#.exr")),
        "--frames",
        "1-5:2,6",
        "-q",
    ]);
    assert!(out.status.success(), "{}", stderr(&out));
    assert_eq!(
        entries(&d.join("o")),
        ["x.1.exr", "x.3.exr", "x.5.exr", "x.6.exr"]
    );
    // Nuke's step, and the slips refused with an example.
    let frames = |list: &str| {
        let out = run(&[
            "transcode",
            s(&d.join("fg.####.exr")),
            "-o",
            s(&d.join("n/x.#.exr")),
            "--frames",
            list,
            "-q",
        ]);
        (out.status.code(), stderr(&out))
    };
    assert_eq!(frames("2-6x2").0, Some(0));
    assert_eq!(entries(&d.join("n")), ["x.2.exr", "x.4.exr", "x.6.exr"]);
    for (list, text) in [
        ("1:5", "1001-1100x2"),
        ("1,1,3", "frame 1 is listed twice"),
        ("5-1", "runs backwards: write 1-5"),
    ] {
        let (code, message) = frames(list);
        assert_eq!(code, Some(2), "{list}: {message}");
        assert!(message.contains(text), "{list}: {message}");
    }
}

#[test]
fn missing_frames_are_listed_before_any_work() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write_sequence(d, "fg", [1, 2, 5], 0);
    write_sequence(d, "bg", [1, 2, 3, 4, 5], 100);
    let out = run(&[
        "over",
        s(&d.join("fg.####.exr")),
        s(&d.join("bg.####.exr")),
        "-o",
        s(&d.join("o/c.####.exr")),
        "--frames",
        "1-5",
    ]);
    assert_eq!(out.status.code(), Some(3));
    let message = stderr(&out);
    assert!(
        message.contains("fg.####.exr") && message.contains("missing frames 3-4"),
        "{message}"
    );
    assert!(!d.join("o").exists(), "nothing is written");
}

#[test]
fn a_damaged_frame_stops_the_run_naming_file_and_frame_and_leaves_no_partial_file() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write_sequence(d, "fg", [1, 2, 3], 0);
    write_sequence(d, "bg", [1, 2, 3], 100);
    // Truncate frame 2 of the background in the middle of its pixel data.
    let bad = d.join("bg.0002.exr");
    let bytes = std::fs::read(&bad).unwrap();
    std::fs::write(&bad, &bytes[..bytes.len() * 2 / 3]).unwrap();
    let out = run(&[
        "over",
        s(&d.join("fg.####.exr")),
        s(&d.join("bg.####.exr")),
        "-o",
        s(&d.join("o/c.####.exr")),
        "-q",
    ]);
    assert_eq!(out.status.code(), Some(3), "{}", stderr(&out));
    let message = stderr(&out);
    assert!(
        message.contains("bg.0002.exr") && message.contains("frame 2"),
        "{message}"
    );
    assert_eq!(message.lines().count(), 1, "{message}");
    let written = entries(&d.join("o"));
    assert!(
        !written
            .iter()
            .any(|n| n.contains("0002") || n.contains("0003") || n.contains(".tmp")),
        "{written:?}"
    );
}

#[test]
fn corrupted_pixel_data_is_an_error_not_a_crash() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let img = random_rgba(3, 0, 0, 64, 64, Kind::Half, false);
    for c in ["zip", "piz", "rle", "zips"] {
        let path = d.join(format!("{c}.exr"));
        write_image(&path, &img, compression(c), LineOrder::Increasing);
        let mut bytes = std::fs::read(&path).unwrap();
        let len = bytes.len();
        for i in (len * 3 / 4..len).step_by(7) {
            bytes[i] ^= 0x5a;
        }
        std::fs::write(&path, &bytes).unwrap();
        let output = d.join(format!("out-{c}.exr"));
        let out = run(&["over", s(&path), s(&path), "-o", s(&output), "-q"]);
        let message = stderr(&out);
        assert!(!message.contains("panicked"), "{message}");
        // ZIP data carries a checksum; PIZ and RLE have none, so damage can
        // decode to wrong pixels (as in OpenEXR) but never crash.
        if c.starts_with("zip") {
            assert_eq!(out.status.code(), Some(3), "{c}: {message}");
            assert!(message.contains(&format!("{c}.exr")), "{message}");
            assert!(!output.exists());
        } else {
            assert!(matches!(out.status.code(), Some(0 | 3)), "{c}: {message}");
        }
    }
}

#[test]
fn usage_errors_exit_2_and_bad_inputs_exit_3() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write_sequence(d, "fg", [1, 2], 0);
    let (fg, single, seq, none) = (
        d.join("fg.####.exr"),
        d.join("single.exr"),
        d.join("o.#.exr"),
        d.join("none.exr"),
    );
    let cases: Vec<(Vec<&str>, i32, &str)> = vec![
        (
            vec!["over", s(&fg), s(&fg), "-o", s(&single)],
            2,
            "no frame number",
        ),
        (
            vec!["over", s(&fg), s(&fg), "-o", s(&fg)],
            2,
            "overwrite an input",
        ),
        (
            vec!["over", s(&fg), s(&fg), "-o", s(&seq), "--frames", "9-1"],
            2,
            "runs backwards",
        ),
        (
            vec![
                "over",
                s(&fg),
                s(&fg),
                "-o",
                s(&seq),
                "--compression",
                "lzw",
            ],
            2,
            "unknown compression",
        ),
        (vec!["over", s(&none), s(&fg), "-o", s(&seq)], 3, "none.exr"),
    ];
    for (args, code, text) in cases {
        let out = run(&args);
        assert_eq!(out.status.code(), Some(code), "{args:?}: {}", stderr(&out));
        assert!(stderr(&out).contains(text), "{args:?}: {}", stderr(&out));
    }
    std::fs::write(d.join("notes.exr"), "not an image").unwrap();
    let out = run(&["info", s(&d.join("notes.exr"))]);
    assert_eq!(out.status.code(), Some(3));
    assert!(stderr(&out).contains("notes.exr"));
}

#[test]
fn an_unwritable_output_exits_4_naming_it() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write_sequence(d, "fg", [1], 0);
    std::fs::write(d.join("blocker"), "a file where a folder should be").unwrap();
    let target = d.join("blocker/c.####.exr");
    let out = run(&[
        "over",
        s(&d.join("fg.####.exr")),
        s(&d.join("fg.####.exr")),
        "-o",
        s(&target),
        "-q",
    ]);
    assert_eq!(out.status.code(), Some(4), "{}", stderr(&out));
    assert!(stderr(&out).contains("blocker"), "{}", stderr(&out));
}

#[test]
fn json_summary_reports_frames_pixels_and_memory() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write_sequence(d, "fg", [1, 2, 3], 0);
    let out = run(&[
        "over",
        s(&d.join("fg.####.exr")),
        s(&d.join("fg.####.exr")),
        "-o",
        s(&d.join("c.####.exr")),
        "--json",
    ]);
    assert!(out.status.success(), "{}", stderr(&out));
    let summary: serde_json::Value = serde_json::from_slice(&out.stdout).expect("one JSON record");
    assert_eq!(summary["frames"], 3);
    assert_eq!(summary["pixels"], 3 * 48 * 40);
    assert!(summary["peak_rss_bytes"].as_u64().unwrap() > 1 << 20);
    assert!(summary["pixels_per_second"].as_f64().unwrap() > 0.0);
}

/// One rule for every number, on the command line: finite and within bounds.
#[test]
fn numeric_options_are_finite_and_bounded() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let (input, output) = (d.join("in.exr"), d.join("out.exr"));
    generate(&input, "fg", (16, 16), &[]);
    let (i, o) = (s(&input), s(&output));
    let cases: Vec<Vec<&str>> = vec![
        vec!["vblur", i, "-o", o, "--scale", "1e30"],
        vec!["vblur", i, "-o", o, "--scale", "NaN"],
        vec!["vblur", i, "-o", o, "--max-displacement", "4000000000"],
        vec!["stereo", i, "-o", o, "--eye", "left", "--disparity", "1e30"],
        vec!["stereo", i, "-o", o, "--eye", "left", "--disparity", "nan"],
        vec!["key", i, "-o", o, "--screen", "NaN,1,0"],
        vec!["key", i, "-o", o, "--gain", "inf"],
        vec![
            "defocus",
            i,
            "-o",
            o,
            "--focus",
            "1",
            "--scale",
            "1e30",
            "--max-radius",
            "4",
        ],
        vec![
            "defocus",
            i,
            "-o",
            o,
            "--focus",
            "NaN",
            "--scale",
            "1",
            "--max-radius",
            "4",
        ],
        vec!["merge", "--op", "over", i, i, "-o", o, "--mix", "NaN"],
        vec![
            "diffmatte",
            i,
            "--clean-plate",
            i,
            "-o",
            o,
            "--softness=-inf",
        ],
        vec!["--threads", "0", "transcode", i, "-o", o],
        vec!["--threads", "100000", "transcode", i, "-o", o],
    ];
    for args in cases {
        let out = run(&args);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {}", stderr(&out));
        assert!(
            stderr(&out).contains("must be"),
            "{args:?}: {}",
            stderr(&out)
        );
        assert!(!output.exists());
    }
    let out = run(&[
        "stereo",
        i,
        "-o",
        o,
        "--eye",
        "left",
        "--disparity",
        "-20",
        "-q",
    ]);
    assert!(out.status.success(), "{}", stderr(&out));
}

/// An image too wide for the reader's block limit is refused before any
/// allocation, with nothing left in the folder (it aborted and left a
/// temporary file).
#[test]
fn a_generated_image_too_large_is_refused_before_writing() {
    let dir = tempfile::tempdir().unwrap();
    let out = limited(&[
        "generate",
        s(&dir.path().join("big.exr")),
        "--width",
        "100000000",
        "--height",
        "100000000",
    ]);
    assert_eq!(out.status.code(), Some(2), "{}", stderr(&out));
    assert!(stderr(&out).contains("over the"), "{}", stderr(&out));
    assert_eq!(entries(dir.path()), Vec::<String>::new());
}

/// Messages name inputs as the user wrote them: a `%04d` pattern as
/// `%04d` (it had been shown as `####`), `%%` being a `%` (printf's rule:
/// it had been kept as `%%` in the names read), and a symbolic link loop
/// as one (it had been "no such file").
#[test]
fn inputs_are_named_as_written_and_link_loops_as_loops() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write_sequence(d, "p%", [1, 2], 0);
    let written = d.join("p%%.%04d.exr");
    let output = d.join("o%%.%04d.exr");
    ok(&["blur", s(&written), "--radius", "1", "-o", s(&output), "-q"]);
    assert_eq!(
        entries(d),
        ["o%.0001.exr", "o%.0002.exr", "p%.0001.exr", "p%.0002.exr"]
    );
    let out = run(&[
        "blur",
        s(&written),
        "--radius",
        "1",
        "-o",
        s(&output),
        "--frames",
        "1-3",
    ]);
    let message = stderr(&out);
    assert_eq!(out.status.code(), Some(3), "{message}");
    assert!(
        message.contains("p%%.%04d.exr: missing frame 3"),
        "{message}"
    );
    // A plain file and a sequence's frame that loop.
    std::os::unix::fs::symlink("loop.exr", d.join("loop.exr")).unwrap();
    std::os::unix::fs::symlink("p%.0003.exr", d.join("p%.0003.exr")).unwrap();
    for (input, named) in [("loop.exr", "loop.exr"), ("p%%.%04d.exr", "p%.0003.exr")] {
        let out = run(&[
            "blur",
            s(&d.join(input)),
            "--radius",
            "1",
            "-o",
            s(&output),
            "--frames",
            "3",
        ]);
        let message = stderr(&out);
        assert_eq!(out.status.code(), Some(3), "{message}");
        assert!(
            message.contains(named) && message.contains("is a symbolic link loop"),
            "{message}"
        );
    }
}
