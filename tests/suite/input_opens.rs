//! Each input file is opened once a run: the first frame's file, read
//! before the run (luminance, warnings, the slate's header), is the one its
//! plan reads, and `--all-parts` plans every part from one open. Counted
//! with strace (a skipped check where it is missing or cannot trace).

use crate::common::{random_rgba, s, skip, stderr, write_parts, write_sequence, Kind};
use std::path::Path;
use std::process::Command;

/// Whether strace can trace here: installed, and ptrace allowed.
fn strace_works() -> bool {
    let traced = Command::new("strace")
        .args(["-f", "-e", "trace=openat", "-o", "/dev/null", "true"])
        .output();
    match traced {
        Ok(out) if out.status.success() => true,
        Ok(out) => {
            skip(&format!(
                "strace cannot trace here: {}",
                stderr(&out).trim()
            ));
            false
        }
        Err(e) => {
            skip(&format!("strace is not installed ({e})"));
            false
        }
    }
}

/// Runs exrcomp with `args` under strace in `dir`, and counts, per name
/// of `files`, the successful opens of that file.
fn opens(dir: &Path, args: &[&str], files: &[&str]) -> Vec<usize> {
    let log = dir.join("openat.log");
    let out = Command::new("strace")
        .args(["-f", "-e", "trace=openat", "-o", s(&log)])
        .arg(env!("CARGO_BIN_EXE_exrcomp"))
        .args(args)
        .output()
        .expect("strace runs");
    assert!(out.status.success(), "exrcomp {args:?}: {}", stderr(&out));
    let log = std::fs::read_to_string(&log).unwrap();
    files
        .iter()
        .map(|name| {
            let quoted = format!("/{name}\"");
            (log.lines())
                .filter(|l| l.contains("openat(") && l.contains(&quoted) && !l.contains(" = -"))
                .count()
        })
        .collect()
}

#[test]
fn each_input_frame_is_opened_once_a_run() {
    if !strace_works() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write_sequence(d, "fg", 1..=3, 7);
    write_sequence(d, "bg", 1..=3, 70);
    let frames = [
        "fg.0001.exr",
        "fg.0002.exr",
        "fg.0003.exr",
        "bg.0001.exr",
        "bg.0002.exr",
        "bg.0003.exr",
    ];
    let (fg, bg, one) = (
        d.join("fg.0001.exr"),
        d.join("bg.0001.exr"),
        d.join("one.exr"),
    );
    let over = ["over", s(&fg), s(&bg), "-o", s(&one), "-q"];
    assert_eq!(opens(d, &over, &[frames[0], frames[3]]), [1, 1]);

    // A job file's sequence with a slate: its first frame planned for the
    // slate's header, from the files the warnings read.
    let job = d.join("slate.toml");
    std::fs::write(
        &job,
        "[[node]]\nname = \"fg\"\nread = \"fg.####.exr\"\n\n\
         [[node]]\nname = \"bg\"\nread = \"bg.####.exr\"\n\n\
         [[node]]\nname = \"comp\"\nop = \"over\"\ninputs = [\"fg\", \"bg\"]\n\n\
         [[node]]\nname = \"out\"\nwrite = \"comp.####.exr\"\nslate = true\ninputs = [\"comp\"]\n",
    )
    .unwrap();
    assert_eq!(opens(d, &["run", s(&job), "-q"], &frames), [1; 6]);
    assert!(d.join("comp.0000.exr").is_file(), "the slate is written");

    // --all-parts: every part planned, warned of and run from one open.
    let img = random_rgba(3, 0, 0, 32, 24, Kind::Half, false);
    let (parts, blurred) = (d.join("parts.exr"), d.join("blurred.exr"));
    write_parts(&parts, &[("a", "left", &img), ("b", "right", &img)]);
    let blur = [
        "blur",
        s(&parts),
        "-o",
        s(&blurred),
        "--radius",
        "1",
        "--all-parts",
        "-q",
    ];
    assert_eq!(opens(d, &blur, &["parts.exr"]), [1]);

    // An operation that measures its input first (--from auto) plans from
    // the file its measuring opened; a job file's node likewise.
    let cg = d.join("cg.exr");
    crate::colour_metadata::tagged(&cg, None, Some("lin_ap1_scene"));
    let (aces, config) = (d.join("aces.exr"), crate::colour_metadata::V4);
    let to_aces = ["--from", "auto", "--to", "ACES2065-1", "--config", config];
    let auto = [
        &["colorconvert", s(&cg), "-o", s(&aces), "-q"],
        &to_aces[..],
    ]
    .concat();
    assert_eq!(opens(d, &auto, &["cg.exr"]), [1]);
    let job = d.join("auto.toml");
    std::fs::write(
        &job,
        format!(
            "[[node]]\nname = \"in\"\nread = \"cg.exr\"\n\n\
             [[node]]\nname = \"cc\"\nop = \"colorconvert\"\ninputs = [\"in\"]\n\
             from = \"auto\"\nto = \"ACES2065-1\"\nconfig = \"{config}\"\n\n\
             [[node]]\nname = \"out\"\nwrite = \"aces2.exr\"\ninputs = [\"cc\"]\n"
        ),
    )
    .unwrap();
    assert_eq!(opens(d, &["run", s(&job), "-q"], &["cg.exr"]), [1]);
}
