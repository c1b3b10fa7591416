//! A frame knows which job made it (specs/overnight.md, "Which job made a
//! frame"): `--resume` keeps only frames this job would write as they are,
//! and redoes those a changed parameter, job-file node or input plate, or
//! another tool, left behind; the farm warns at submit time.

use crate::common::*;
use std::path::{Path, PathBuf};

fn json(out: &std::process::Output) -> serde_json::Value {
    assert!(out.status.success(), "{}", stderr(out));
    serde_json::from_slice(&out.stdout)
        .unwrap_or_else(|_| panic!("no JSON summary: {}", stderr(out)))
}

/// The files of `dir` (hidden ones too), sorted, each with its bytes.
fn folder(dir: &Path) -> Vec<(String, Vec<u8>)> {
    let mut files: Vec<(String, Vec<u8>)> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| {
            let path = e.unwrap().path();
            let name = path.file_name().unwrap().to_string_lossy().into_owned();
            (name, std::fs::read(&path).unwrap())
        })
        .collect();
    files.sort();
    files
}

/// Runs `args` with `--json` into `out` (and `--resume` when `resume`),
/// the summary.
fn render(args: &[&str], out: &Path, resume: bool) -> serde_json::Value {
    let mut all: Vec<&str> = args.to_vec();
    all.extend(["-o", s(out), "--json"]);
    if resume {
        all.push("--resume");
    }
    json(&run(&all))
}

/// `args` rendered fresh into `dir/fresh`: what a resumed run must equal.
fn fresh(dir: &Path, args: &[&str], name: &str) -> Vec<(String, Vec<u8>)> {
    let fresh = dir.join(format!("fresh-{}", name.replace('/', "-")));
    render(args, &fresh.join("c.####.exr"), false);
    folder(&fresh)
}

fn frames(value: &serde_json::Value) -> Vec<i64> {
    serde_json::from_value(value.clone()).unwrap()
}

/// Over, then over again with `--resume` into the same folder after each
/// change: an unchanged job keeps every frame; a changed parameter or
/// input redoes exactly the frames it changes, and the folder then equals
/// a fresh run of the changed job, byte for byte.
#[test]
fn resume_keeps_this_jobs_frames_and_redoes_another_jobs() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write_sequence(d, "fg", 1..=4, 0);
    write_sequence(d, "bg", 1..=4, 100);
    let (fg, bg) = (d.join("fg.####.exr"), d.join("bg.####.exr"));
    let out_dir = d.join("out");
    let out = out_dir.join("c.####.exr");
    let first = ["over", s(&fg), s(&bg)];
    render(&first, &out, false);

    let again = render(&first, &out, true);
    assert_eq!(frames(&again["kept"]), [1, 2, 3, 4]);
    assert_eq!(frames(&again["redone"]), Vec::<i64>::new());

    // A parameter changed: every frame is another job's.
    let mixed = ["over", s(&fg), s(&bg), "--mix", "0.5"];
    let redone = render(&mixed, &out, true);
    assert_eq!(frames(&redone["redone"]), [1, 2, 3, 4], "{redone}");
    assert_eq!(frames(&redone["kept"]), Vec::<i64>::new());
    assert_eq!(folder(&out_dir), fresh(d, &mixed, "mixed"));

    // One input frame rewritten (same size, other pixels): that frame only.
    write_sequence(d, "bg", [3], 999);
    let rewritten = render(&mixed, &out, true);
    assert_eq!(frames(&rewritten["redone"]), [3], "{rewritten}");
    assert_eq!(frames(&rewritten["kept"]), [1, 2, 4]);
    assert_eq!(folder(&out_dir), fresh(d, &mixed, "rewritten"));

    // A frame another tool wrote (no fingerprint) is redone too.
    std::fs::copy(d.join("fg.0002.exr"), out_dir.join("c.0002.exr")).unwrap();
    let foreign = render(&mixed, &out, true);
    assert_eq!(frames(&foreign["redone"]), [2], "{foreign}");
    assert_eq!(folder(&out_dir), fresh(d, &mixed, "foreign"));
}

/// A job file's node changed (a blur's radius) between two runs into one
/// folder: every frame redone; its comment or a node's name changed: kept.
#[test]
fn a_changed_job_file_node_redoes_every_frame() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write_sequence(d, "p", 1..=3, 7);
    let job = |radius: &str, name: &str, out: &Path| -> PathBuf {
        let path = d.join(format!("job-{radius}-{name}.toml"));
        let text = format!(
            "# a comment\n[[node]]\nname = \"{name}\"\nread = \"{}\"\n\n[[node]]\nname = \"b\"\nop = \"blur\"\nradius = {radius}\ninputs = [\"{name}\"]\n\n[[node]]\nname = \"out\"\nwrite = \"{}\"\ninputs = [\"b\"]\n",
            s(&d.join("p.####.exr")),
            s(out)
        );
        std::fs::write(&path, text).unwrap();
        path
    };
    let out = d.join("o/c.####.exr");
    let runs = |file: &Path| json(&run(&["run", s(file), "--json", "--resume"]));
    runs(&job("2", "plate", &out));
    let renamed = runs(&job("2", "in", &out));
    assert_eq!(frames(&renamed["kept"]), [1, 2, 3], "{renamed}");
    let changed = runs(&job("3", "in", &out));
    assert_eq!(frames(&changed["redone"]), [1, 2, 3], "{changed}");
    let fresh_out = d.join("f/c.####.exr");
    json(&run(&["run", s(&job("3", "x", &fresh_out)), "--json"]));
    assert_eq!(folder(&d.join("o")), folder(&d.join("f")));
}

/// Review media carry the fingerprint too (a PNG text chunk, a JPEG
/// comment, a TIFF description): a changed grade redoes them, an unchanged
/// run keeps them.
#[test]
fn review_media_know_which_job_made_them() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write_sequence(d, "p", 1..=2, 3);
    let plate = d.join("p.####.exr");
    for ext in ["png", "jpg", "tif"] {
        let out = d.join(format!("{ext}/c.####.{ext}"));
        let grade =
            |gain: &str, resume: bool| render(&["grade", s(&plate), "--gain", gain], &out, resume);
        grade("1.5", false);
        let first = std::fs::read(d.join(format!("{ext}/c.0001.{ext}"))).unwrap();
        let found = first.windows(19).any(|w| w == b"exrcomp:fingerprint");
        assert!(found, "{ext}: no fingerprint in the file");
        assert_eq!(frames(&grade("1.5", true)["kept"]), [1, 2], "{ext}");
        let changed = grade("2", true);
        assert_eq!(frames(&changed["redone"]), [1, 2], "{ext}: {changed}");
        let again = std::fs::read(d.join(format!("{ext}/c.0001.{ext}"))).unwrap();
        assert_ne!(first, again, "{ext}");
    }
    // The comment JPEG readers see, where Pillow is installed.
    let Some(python) = peer("python3") else {
        return missing("python3");
    };
    let script = "import sys; from PIL import Image; print(Image.open(sys.argv[1]).info.get('comment', b'').decode())";
    let said = std::process::Command::new(python)
        .args(["-c", script, s(&d.join("jpg/c.0001.jpg"))])
        .output()
        .unwrap();
    let text = String::from_utf8_lossy(&said.stdout);
    if said.status.success() {
        assert!(text.starts_with("exrcomp:fingerprint="), "{text}");
    } else {
        missing("Pillow (python3 -c 'import PIL')");
    }
}

/// The same command writes the same bytes for a frame whether it runs
/// alone or after another in the same process, for every kind of node (no
/// address, time or state of an earlier frame in what the fingerprint
/// records), and a farm submission into a folder holding another job's
/// frames warns, naming how many.
#[test]
fn fingerprints_hold_no_state_and_the_farm_warns_of_others() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write_sequence(d, "a", 1..=2, 1);
    write_sequence(d, "b", 1..=2, 2);
    let (a, b) = (d.join("a.####.exr"), d.join("b.####.exr"));
    let commands: Vec<Vec<&str>> = vec![
        vec!["over", s(&a), s(&b)],
        vec!["blur", s(&a), "--radius", "2"],
        vec!["grade", s(&a), "--gain", "1.2"],
        vec!["resize", s(&a), "--scale", "0.5"],
        vec!["transform", s(&a), "--rotate", "10"],
        vec!["shuffle", s(&a), "--ch", "R=G,G=R,B,A"],
        vec!["crop", s(&a), "--region", "2,2,20,20"],
        vec!["merge", "--op", "multiply", s(&a), s(&b), "--mix", "0.3"],
        vec!["exposure", s(&a), "--stops", "0.5"],
        vec!["colorconvert", s(&a), "--from", "ACEScg", "--to", "ACEScct"],
        vec!["premult", s(&a)],
    ];
    for (i, command) in commands.iter().enumerate() {
        let frame_2 = |k: usize, frames: &str| {
            let out = d.join(format!("{i}-{k}/c.####.exr"));
            let mut args = command.clone();
            args.extend(["-o", s(&out), "-q", "--frames", frames]);
            let ran = run(&args);
            assert!(ran.status.success(), "{command:?}: {}", stderr(&ran));
            std::fs::read(d.join(format!("{i}-{k}/c.0002.exr"))).unwrap()
        };
        assert!(
            frame_2(0, "1-2") == frame_2(1, "2"),
            "{command:?} wrote other bytes"
        );
    }

    // Another job's frame at the output: the farm says so at submit time.
    let out = d.join("o/c.####.exr");
    render(&["over", s(&a), s(&b), "--mix", "0.5"], &out, false);
    let template = d.join("job.yaml");
    let farm = run(&[
        "farm",
        "openjd",
        "--frames",
        "1-2",
        "-o",
        s(&template),
        "--",
        "over",
        s(&a),
        s(&b),
        "-o",
        s(&out),
    ]);
    assert!(farm.status.success(), "{}", stderr(&farm));
    let said = stderr(&farm);
    assert!(
        said.contains("2 frames already at the output another job"),
        "{said}"
    );
}

/// Bands (`--rows`) carry the whole frame's fingerprint, so that `stitch`
/// joins them; `--resume` must still not keep a band where this run writes
/// the whole frame or another band (16 rows short, exit 0), nor the whole
/// frame where it writes a band: it keeps a file of the rows it writes.
#[test]
fn resume_keeps_only_a_file_of_the_rows_this_run_writes() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write_sequence(d, "p", 1..=2, 5);
    let plate = d.join("p.####.exr");
    let out_dir = d.join("out");
    let out = out_dir.join("c.####.exr");
    let blur = |rows: Option<&'static str>| {
        let mut args = vec!["blur", s(&plate), "--radius", "1"];
        if let Some(rows) = rows {
            args.extend(["--rows", rows]);
        }
        args
    };
    // (left at the output, then run with --resume): each redoes both frames.
    let cases = [
        (Some("0-16"), None),
        (Some("0-16"), Some("16-40")),
        (Some("0-40"), None),
        (None, Some("0-16")),
        (None, Some("0-40")),
    ];
    for (i, (before, after)) in cases.into_iter().enumerate() {
        render(&blur(before), &out, false);
        let resumed = render(&blur(after), &out, true);
        let case = format!("{before:?} then {after:?}: {resumed}");
        assert_eq!(frames(&resumed["redone"]), [1, 2], "{case}");
        assert_eq!(frames(&resumed["kept"]), Vec::<i64>::new(), "{case}");
        assert_eq!(folder(&out_dir), fresh(d, &blur(after), &i.to_string()));
        // The same rows again: kept.
        let again = render(&blur(after), &out, true);
        assert_eq!(frames(&again["kept"]), [1, 2], "{case}, again: {again}");
    }
}
