//! Overnight safety: missing frames, bad frames, resuming, interruptions,
//! full disks; nothing half-written ever sits at an output path.

use crate::common::*;
use exr::prelude::LineOrder;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::Duration;

fn frame_path(dir: &Path, name: &str, frame: i64) -> PathBuf {
    dir.join(format!("{name}.{frame:04}.exr"))
}

fn json(out: &std::process::Output) -> serde_json::Value {
    serde_json::from_slice(&out.stdout)
        .unwrap_or_else(|_| panic!("no JSON summary: {}", stderr(out)))
}

/// Every file at an output path decodes completely (exrcomp's own check,
/// and OpenEXR's where the peers are installed).
fn assert_outputs_complete(dir: &Path) {
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        let name = path.file_name().unwrap().to_string_lossy().to_string();
        if name.starts_with('.') {
            continue; // a temporary name, never an output path
        }
        let out = run(&["info", s(&path)]);
        assert!(
            out.status.success(),
            "partial or bad output {name}: {}",
            stderr(&out)
        );
    }
}

#[test]
fn missing_frames_skip_hold_or_black() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write_sequence(d, "fg", [1, 2, 4], 0);
    write_sequence(d, "bg", 1..=4, 100);
    let over = |policy: &str, out: &str| {
        run(&[
            "over",
            s(&d.join("fg.####.exr")),
            s(&d.join("bg.####.exr")),
            "-o",
            s(&d.join(out)),
            "--frames",
            "1-4",
            "--missing",
            policy,
            "--json",
        ])
    };
    let out = over("skip", "skip/c.####.exr");
    assert!(out.status.success(), "{}", stderr(&out));
    assert_eq!(json(&out)["skipped_missing"], serde_json::json!([3]));
    assert!(
        !frame_path(&d.join("skip"), "c", 3).exists()
            && frame_path(&d.join("skip"), "c", 4).exists()
    );

    let out = over("hold", "hold/c.####.exr");
    assert!(out.status.success(), "{}", stderr(&out));
    let held = reference_over(
        &read_image(&frame_path(d, "fg", 2)),
        &read_image(&frame_path(d, "bg", 3)),
        false,
    );
    assert_identical(&read_image(&frame_path(&d.join("hold"), "c", 3)), &held);

    let out = over("black", "black/c.####.exr");
    assert!(out.status.success(), "{}", stderr(&out));
    // Transparent black over B is B.
    assert_identical(
        &read_image(&frame_path(&d.join("black"), "c", 3)),
        &read_image(&frame_path(d, "bg", 3)),
    );

    let out = over("error", "error/c.####.exr");
    assert_eq!(out.status.code(), Some(3));
    assert!(stderr(&out).contains("missing frame 3"), "{}", stderr(&out));
}

/// A frame made black from a job's only input is a transparent black frame
/// shaped as the nearest frame on disk, not a failure, in a dry run too.
#[test]
fn missing_black_on_the_only_input_writes_a_transparent_black_frame() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write_sequence(d, "fg", [1, 3], 0);
    let input = d.join("fg.####.exr");
    let grade = |out: &str, more: &[&str]| {
        let out = d.join(out);
        let mut args = vec!["grade", s(&input), "-o", s(&out), "--gain", "2"];
        args.extend(["--missing", "black", "-q"]);
        args.extend(more);
        run(&args)
    };
    let dry = grade("dry/g.####.exr", &["--dry-run"]);
    assert!(dry.status.success(), "{}", stderr(&dry));
    let out = grade("g/g.####.exr", &[]);
    assert!(out.status.success(), "{}", stderr(&out));
    let black = read_image(&frame_path(&d.join("g"), "g", 2));
    let near = read_image(&frame_path(d, "fg", 1));
    assert_eq!(
        (black.width, black.height, black.x, black.y),
        (near.width, near.height, near.x, near.y)
    );
    let n = black.width * black.height;
    assert!(black
        .channels
        .values()
        .all(|c| (0..n).all(|i| c.get_f32(i) == 0.0)));
    assert!(frame_path(&d.join("g"), "g", 3).exists());
}

#[test]
fn keep_going_reports_bad_frames_and_writes_the_rest() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write_sequence(d, "bg", 1..=5, 0);
    let bad = frame_path(d, "bg", 3);
    let bytes = std::fs::read(&bad).unwrap();
    std::fs::write(&bad, &bytes[..bytes.len() / 2]).unwrap();
    let out = run(&[
        "transcode",
        s(&d.join("bg.####.exr")),
        "-o",
        s(&d.join("o/t.####.exr")),
        "--keep-going",
        "--json",
    ]);
    assert_eq!(out.status.code(), Some(3), "{}", stderr(&out));
    let summary = json(&out);
    assert_eq!(summary["frames"], 4);
    assert_eq!(summary["failed"][0]["frame"], 3);
    assert!(summary["failed"][0]["error"]
        .as_str()
        .unwrap()
        .contains("bg.0003.exr"));
    for frame in [1, 2, 4, 5] {
        assert!(frame_path(&d.join("o"), "t", frame).exists());
    }
    assert!(!frame_path(&d.join("o"), "t", 3).exists());
    assert_outputs_complete(&d.join("o"));
    let leftovers: Vec<_> = std::fs::read_dir(d.join("o"))
        .unwrap()
        .filter(|e| {
            e.as_ref()
                .unwrap()
                .file_name()
                .to_string_lossy()
                .ends_with(".tmp")
        })
        .collect();
    assert!(leftovers.is_empty(), "temporary files left: {leftovers:?}");
}

/// A bug met in one frame (a panic planted with the test builds'
/// `EXRCOMP_TEST_PANIC=STAGE:FRAME`, on a pool thread for decode and
/// compose, on the stage's own thread for encode and write) costs that
/// frame alone: the run says so in one line naming the frame, its output
/// and the panic's place, not in Rust's words; it exits 1, within a time
/// limit (every thread and channel shut down), leaving no temporary file.
/// Under --keep-going the other frames are written, byte for byte as
/// without the bug; without it, the frames before stay and nothing else
/// is written.
#[test]
fn a_panic_in_one_frame_is_that_frames_error_and_keep_going_writes_the_rest() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write_sequence(d, "fg", 1..=5, 0);
    write_sequence(d, "bg", 1..=5, 100);
    let over = |out: &Path, panic: Option<String>, keep_going: bool| {
        let mut command = exrcomp();
        // Three strips a frame: the failed frame's later ones still come.
        command
            .args(["over", s(&d.join("fg.####.exr")), s(&d.join("bg.####.exr"))])
            .args(["-o", s(&out.join("c.####.exr")), "--strip-rows", "16"])
            .args(keep_going.then_some("--keep-going"))
            .env_remove("RUST_BACKTRACE");
        if let Some(panic) = &panic {
            command.env("EXRCOMP_TEST_PANIC", panic);
        }
        let ended = within(command, Duration::from_secs(60));
        assert!(!ended.timed_out, "{panic:?} hung: {}", ended.stderr);
        ended
    };
    let clean = d.join("clean");
    let ended = over(&clean, None, false);
    assert_eq!(ended.code, Some(0), "{}", ended.stderr);
    for stage in ["decode", "compose", "encode", "write"] {
        for keep_going in [false, true] {
            let o = d.join(format!("{stage}-{keep_going}"));
            let ended = over(&o, Some(format!("{stage}:3")), keep_going);
            let case = format!("{stage}, keep going {keep_going}: {}", ended.stderr);
            assert_eq!(ended.code, Some(1), "{case}");
            let said = format!(
                "{} (frame 3): internal error: planted panic in {stage} of frame 3 \
                 at src/engine/pipeline.rs:",
                s(&frame_path(&o, "c", 3))
            );
            let lines: Vec<&str> = ended
                .stderr
                .lines()
                .filter(|l| l.contains("internal error"))
                .collect();
            assert!(!lines.is_empty(), "{case}");
            for line in lines {
                assert!(line.contains(&said), "{case}");
                assert!(line.ends_with(" (a bug: please report it with this line)"));
            }
            for rust in ["panicked at", "RUST_BACKTRACE", "stack backtrace"] {
                assert!(!ended.stderr.contains(rust), "{case}");
            }
            if keep_going {
                assert!(
                    ended
                        .stderr
                        .ends_with("exrcomp: error: 1 frame failed: 3\n"),
                    "{case}"
                );
            }
            let written: &[i64] = if keep_going { &[1, 2, 4, 5] } else { &[1, 2] };
            let mut names: Vec<String> = std::fs::read_dir(&o)
                .unwrap()
                .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
                .collect();
            names.sort();
            let expected: Vec<String> = written.iter().map(|f| format!("c.{f:04}.exr")).collect();
            assert_eq!(names, expected, "{case}");
            for &f in written {
                let (got, clean) = (frame_path(&o, "c", f), frame_path(&clean, "c", f));
                let same = std::fs::read(got).unwrap() == std::fs::read(clean).unwrap();
                assert!(
                    same,
                    "frame {f} differs from the run without the bug: {case}"
                );
            }
        }
    }
}

#[test]
fn resume_redoes_only_missing_or_damaged_outputs() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write_sequence(d, "fg", 1..=6, 0);
    write_sequence(d, "bg", 1..=6, 100);
    let (fg, bg) = (d.join("fg.####.exr"), d.join("bg.####.exr"));
    let over = |out: &str, extra: &[&str]| {
        let mut args = vec!["over", s(&fg), s(&bg), "-o", out, "--json"];
        args.extend_from_slice(extra);
        let result = run(&args);
        assert!(result.status.success(), "{}", stderr(&result));
        json(&result)
    };
    let pattern = d.join("o/c.####.exr");
    over(s(&pattern), &[]);
    let original: Vec<Vec<u8>> = (1..=6)
        .map(|f| std::fs::read(frame_path(&d.join("o"), "c", f)).unwrap())
        .collect();
    std::fs::remove_file(frame_path(&d.join("o"), "c", 2)).unwrap();
    let damaged = frame_path(&d.join("o"), "c", 5);
    std::fs::write(&damaged, &original[4][..original[4].len() - 10]).unwrap();
    let summary = over(s(&pattern), &["--resume"]);
    assert_eq!(summary["kept"], serde_json::json!([1, 3, 4, 6]));
    assert_eq!(summary["frames"], 2);
    for f in 1..=6 {
        assert_eq!(
            std::fs::read(frame_path(&d.join("o"), "c", f)).unwrap(),
            original[f as usize - 1],
            "frame {f}"
        );
    }
}

/// Starts a 30-frame transcode, sends it `signals` (5 ms apart) after
/// `after`, and returns its exit status.
fn interrupted_run(d: &Path, signals: &[&str], after: Duration) -> std::process::ExitStatus {
    let mut child = started(&[
        "transcode",
        s(&d.join("in.####.exr")),
        "-o",
        s(&d.join("o/t.####.exr")),
        "-q",
        "--compression",
        "piz",
        "--strip-rows",
        "1",
    ]);
    std::thread::sleep(after);
    for signal in signals {
        Command::new("kill")
            .args([*signal, &child.id().to_string()])
            .status()
            .unwrap();
        std::thread::sleep(Duration::from_millis(5));
    }
    child.wait().unwrap()
}

#[test]
fn interrupted_runs_leave_no_partial_output_and_resume_to_identical_results() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let img = random_rgba(7, 0, 0, 256, 256, Kind::Float, true);
    for frame in 1..=30 {
        write_image(
            &frame_path(d, "in", frame),
            &img,
            compression("zip"),
            LineOrder::Increasing,
        );
    }
    // The uninterrupted result.
    let whole = run(&[
        "transcode",
        s(&d.join("in.####.exr")),
        "-o",
        s(&d.join("ref/t.####.exr")),
        "-q",
        "--compression",
        "piz",
    ]);
    assert!(whole.status.success(), "{}", stderr(&whole));
    let mut seed = Lcg(99);
    // The second -INT of a pair makes the run exit at once.
    let rounds: [&[&str]; 6] = [
        &["-INT"],
        &["-KILL"],
        &["-TERM"],
        &["-INT", "-INT"],
        &["-KILL"],
        &["-INT"],
    ];
    for (round, signals) in rounds.iter().enumerate() {
        let after = Duration::from_millis(50 + (seed.next() * 600.0) as u64);
        let status = interrupted_run(d, signals, after);
        // 128 + the signal: SIGINT 130, SIGTERM 143.
        let expected = match signals[0] {
            "-TERM" => 143,
            _ => 130,
        };
        if signals[0] != "-KILL" && !status.success() {
            assert_eq!(
                status.code(),
                Some(expected),
                "round {round}: {signals:?} gives exit {expected}"
            );
        }
        assert_outputs_complete(&d.join("o"));
    }
    // A temporary file a killed run left behind, and one of a live process.
    let stale = d.join("o/.t.0001.exr.exrcomp-4194305.tmp");
    let live = d.join(format!("o/.t.0002.exr.exrcomp-{}.tmp", std::process::id()));
    std::fs::write(&stale, "left by a killed run").unwrap();
    std::fs::write(&live, "being written by a live process").unwrap();
    // One a live writer elsewhere holds (another host's, or another PID
    // namespace's: its PID names no process here), locked as exrcomp locks
    // what it writes.
    let elsewhere = d.join("o/.t.0003.exr.exrcomp-4194306.tmp");
    std::fs::write(&elsewhere, "being written on another host").unwrap();
    let held = std::fs::File::open(&elsewhere).unwrap();
    held.try_lock().unwrap();
    let resumed = run(&[
        "transcode",
        s(&d.join("in.####.exr")),
        "-o",
        s(&d.join("o/t.####.exr")),
        "-q",
        "--compression",
        "piz",
        "--resume",
    ]);
    assert!(resumed.status.success(), "{}", stderr(&resumed));
    assert!(
        !stale.exists() && live.exists() && elsewhere.exists(),
        "stale temporaries go, live ones stay"
    );
    drop(held);
    for frame in 1..=30 {
        let a = std::fs::read(frame_path(&d.join("o"), "t", frame)).unwrap();
        let b = std::fs::read(frame_path(&d.join("ref"), "t", frame)).unwrap();
        assert!(a == b, "frame {frame} differs from the uninterrupted run");
    }
    // An input named as a temporary is read, never removed; a FIFO named
    // as one is neither opened (that would block) nor removed.
    let odd = d.join("o/.in.exr.exrcomp-4194307.tmp");
    std::fs::copy(frame_path(&d.join("o"), "t", 1), &odd).unwrap();
    let fifo = d.join("o/.f.exr.exrcomp-4194308.tmp");
    assert!(Command::new("mkfifo")
        .arg(&fifo)
        .status()
        .unwrap()
        .success());
    let out = d.join("o/odd.exr");
    let args = ["transcode", s(&odd), "-o", s(&out), "-q"];
    let ended = limited_within(&args, Duration::from_secs(60));
    assert_eq!(ended.code, Some(0), "{}", ended.stderr);
    assert!(odd.exists(), "an input named as a temporary was removed");
    assert!(fifo.exists(), "a FIFO named as a temporary was removed");
}

/// Two runs writing the same frames at once, each in its own PID namespace
/// (as two containers are: both can be PID 1, so a PID does not tell their
/// temporaries apart), both finish, and every frame is one complete
/// writer's: the uninterrupted result, byte for byte (its fingerprint
/// with it). Then as two hosts on one NFS folder: each also in its own UTS
/// namespace, with the same host name (and both PID 1: only the random
/// part of a temporary's name tells them apart), then with two names.
#[test]
fn two_pid_namespaces_writing_the_same_frames_both_finish_with_whole_frames() {
    let namespaced = Command::new("unshare")
        .args([
            "--pid",
            "--uts",
            "--fork",
            "--mount-proc",
            "hostname",
            "probe",
        ])
        .stderr(Stdio::null())
        .status();
    if !namespaced.is_ok_and(|s| s.success()) {
        assert!(
            std::env::var_os("CI").is_none(),
            "CI must be able to run unshare --pid --uts for the two-container test"
        );
        skip("cannot make PID and UTS namespaces here (unshare --pid --uts needs root)");
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let img = random_rgba(5, 0, 0, 128, 128, Kind::Float, true);
    for frame in 1..=20 {
        write_image(
            &frame_path(d, "in", frame),
            &img,
            compression("zip"),
            LineOrder::Increasing,
        );
    }
    // The run in its own PID namespace and, given a host name, its own UTS
    // namespace named so; exrcomp is PID 1 there either way (exec'd by the
    // namespace's first process).
    let args = |out: &str, host: Option<&str>| {
        let mut command = Command::new("unshare");
        command.args(["--pid", "--fork", "--mount-proc"]);
        if let Some(host) = host {
            command.args(["--uts", "sh", "-c", "hostname \"$0\" && exec \"$@\"", host]);
        } else {
            command.args(["sh", "-c", "exec \"$@\"", "sh"]);
        }
        command
            .arg(env!("CARGO_BIN_EXE_exrcomp"))
            .args(["transcode", s(&d.join("in.####.exr")), "-o"])
            .arg(d.join(out))
            .args(["-q", "--compression", "piz", "--strip-rows", "1"]);
        command
    };
    let reference = within(args("ref/t.####.exr", None), Duration::from_secs(300));
    assert_eq!(reference.code, Some(0), "{}", reference.stderr);
    let rounds = [
        ("two containers", [None, None]),
        ("two hosts of one name", [Some("render"), Some("render")]),
        ("two hosts", [Some("render-a"), Some("render-b")]),
    ];
    for (round, hosts) in rounds {
        let both: Vec<Ended> = std::thread::scope(|scope| {
            let runs: Vec<_> = hosts
                .iter()
                .map(|&host| {
                    scope
                        .spawn(move || within(args("o/t.####.exr", host), Duration::from_secs(300)))
                })
                .collect();
            runs.into_iter().map(|r| r.join().unwrap()).collect()
        });
        for ended in both {
            assert_eq!(ended.code, Some(0), "{round}: {}", ended.stderr);
        }
        for frame in 1..=20 {
            let a = std::fs::read(frame_path(&d.join("o"), "t", frame)).unwrap();
            let b = std::fs::read(frame_path(&d.join("ref"), "t", frame)).unwrap();
            assert!(a == b, "{round}: frame {frame} is not one whole writer's");
        }
        let left: Vec<_> = std::fs::read_dir(d.join("o"))
            .unwrap()
            .map(|e| e.unwrap().file_name())
            .filter(|n| n.to_string_lossy().starts_with('.'))
            .collect();
        assert!(left.is_empty(), "{round}: temporaries left: {left:?}");
    }
}

#[test]
fn a_full_disk_is_a_clear_output_error_with_nothing_left_behind() {
    let dir = tempfile::tempdir().unwrap();
    let mount = dir.path().join("small");
    std::fs::create_dir(&mount).unwrap();
    let mounted = Command::new("mount")
        .args(["-t", "tmpfs", "-o", "size=256k", "tmpfs", s(&mount)])
        .status();
    if !mounted.is_ok_and(|s| s.success()) {
        assert!(
            std::env::var_os("CI").is_none(),
            "CI must be able to mount a small tmpfs for the full-disk test"
        );
        skip("cannot mount a small tmpfs here (needs root)");
        return;
    }
    let img = random_rgba(8, 0, 0, 300, 300, Kind::Float, true);
    let input = dir.path().join("in.exr");
    write_image(&input, &img, compression("none"), LineOrder::Increasing);
    let target = mount.join("out.exr");
    let out = run(&[
        "transcode",
        s(&input),
        "-o",
        s(&target),
        "--compression",
        "none",
    ]);
    let listing: Vec<_> = std::fs::read_dir(&mount)
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    Command::new("umount").arg(&mount).status().unwrap();
    assert_eq!(out.status.code(), Some(4), "{}", stderr(&out));
    assert!(
        stderr(&out).contains("out.exr") && stderr(&out).contains("No space left"),
        "{}",
        stderr(&out)
    );
    assert!(listing.is_empty(), "left behind: {listing:?}");
}
