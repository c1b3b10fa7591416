//! Metadata and time: `--attrib`, `--erase-attrib`, `--fps` and
//! `--timecode` as exrheader reads them back (and as oiiotool 2.4 types the
//! same values), per-input time (`FILE@+10`, `@1001`, `@hold`) through
//! missing frames, overwrite protection and the default range, and the
//! `--dry-run` listing.

use crate::common::*;
use std::path::Path;
use std::process::Command;

/// exrheader's text of `path`.
fn exrheader_text(exrheader: &Path, path: &Path) -> String {
    let out = succeed(Command::new(exrheader).arg(path));
    String::from_utf8_lossy(&out.stdout).into_owned()
}

/// Attribute `name` as exrheader prints it: its line and the indented ones
/// after it (a keycode's fields, a timecode's flags, a matrix's rows).
fn attribute(text: &str, name: &str) -> Option<String> {
    let mut lines = text
        .lines()
        .skip_while(|l| !l.starts_with(&format!("{name} (type ")));
    let first = lines.next()?;
    let rest = lines.take_while(|l| l.starts_with(' '));
    Some(
        std::iter::once(first)
            .chain(rest)
            .collect::<Vec<_>>()
            .join("\n"),
    )
}

#[test]
fn attributes_read_back_typed_as_exrheader_prints_them() {
    let Some(exrheader) = peer("exrheader") else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write_sequence(d, "in", [1], 0);
    let (input, output) = (d.join("in.0001.exr"), d.join("out.exr"));
    let attribs = [
        "owner=studio",
        "shot=010",
        "take=010:string",
        "gain=1.5",
        "big=1e5",
        "note=look: warm",
        "d=0.25:double",
        "vi=1,-2:v2i",
        "vf=1,2.5:v2f",
        "v3=1,2,3:v3i",
        "v3f=0.5,1,2:v3f",
        "box=0,1,2,3:box2i",
        "boxf=0,0,1.5,2:box2f",
        "m=1,2,3,4,5,6,7,8,9:m33f",
        "expTime=2",
        "kc=1,2,3,4,5,4,64:keycode",
        "tc=10:11:12:13:timecode",
    ];
    let mut args = vec!["transcode", s(&input), "-o", s(&output), "-q"];
    for a in &attribs {
        args.extend(["--attrib", a]);
    }
    args.extend(["--fps", "23.976"]);
    ok(&args);
    let text = exrheader_text(&exrheader, &output);
    for (name, shown) in [
        ("owner", r#"owner (type string): "studio""#),
        ("shot", "shot (type int): 10"),
        ("take", r#"take (type string): "010""#),
        ("gain", "gain (type float): 1.5"),
        ("big", "big (type float): 100000"),
        ("note", r#"note (type string): "look: warm""#),
        ("d", "d (type double): 0.25"),
        ("vi", "vi (type v2i): (1 -2)"),
        ("vf", "vf (type v2f): (1 2.5)"),
        ("v3", "v3 (type v3i): (1 2 3)"),
        ("v3f", "v3f (type v3f): (0.5 1 2)"),
        ("box", "box (type box2i): (0 1) - (2 3)"),
        ("boxf", "boxf (type box2f): (0 0) - (1.5 2)"),
        ("m", "m (type m33f):\n   (1 2 3\n    4 5 6\n    7 8 9)"),
        ("expTime", "expTime (type float): 2"),
        (
            "kc",
            "kc (type keycode):\n    film manufacturer code 1\n    film type code 2\n    \
             prefix 3\n    count 4\n    perf offset 5\n    perfs per frame 4\n    perfs per count 64",
        ),
        (
            "tc",
            "tc (type timecode):\n    time 10:11:12:13\n    drop frame 0, color frame 0, \
             field/phase 0\n    bgf0 0, bgf1 0, bgf2 0\n    user data 0x0",
        ),
        (
            "framesPerSecond",
            "framesPerSecond (type rational): 24000/1001 (23.976)",
        ),
    ] {
        assert_eq!(attribute(&text, name).as_deref(), Some(shown), "{text}");
    }
    // Written once each, in name order, as every attribute.
    let names: Vec<&str> = text
        .lines()
        .filter(|l| !l.starts_with(' ') && l.contains(" (type "))
        .map(|l| l.split(" (type ").next().unwrap())
        .collect();
    let mut sorted = names.clone();
    sorted.sort();
    sorted.dedup();
    assert_eq!(names, sorted);
    assert_peers_read(&output);
}

#[test]
fn untyped_values_take_the_type_oiiotool_gives_them() {
    let (Some(exrheader), Some(oiiotool)) = (peer("exrheader"), peer("oiiotool")) else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write_sequence(d, "in", [1], 0);
    let input = d.join("in.0001.exr");
    for value in [
        "42",
        "-3",
        "+3",
        "1.5",
        ".5",
        "1e5",
        "abc",
        "1,2",
        "1/2",
        "01:00:00:00",
    ] {
        let (ours, theirs) = (d.join("ours.exr"), d.join("theirs.exr"));
        let attrib = format!("t={value}");
        ok(&[
            "transcode",
            s(&input),
            "-o",
            s(&ours),
            "-q",
            "--attrib",
            &attrib,
        ]);
        succeed(
            Command::new(&oiiotool)
                .arg(&input)
                .args(["--attrib", "t", value, "-o"])
                .arg(&theirs),
        );
        let line = |p: &Path| attribute(&exrheader_text(&exrheader, p), "t");
        assert_eq!(line(&ours), line(&theirs), "{value}");
    }
}

#[test]
fn erasing_keeps_what_exrcomp_writes_and_owned_names_are_refused() {
    let Some(exrheader) = peer("exrheader") else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write_sequence(d, "in", [1], 0);
    let (input, tagged, output) = (
        d.join("in.0001.exr"),
        d.join("tagged.exr"),
        d.join("out.exr"),
    );
    ok(&[
        "transcode",
        s(&input),
        "-o",
        s(&tagged),
        "-q",
        "--attrib",
        "cust:a=1",
        "--attrib",
        "cust:b=x",
        "--attrib",
        "owner=me",
        "--attrib",
        "comments=keep",
    ]);
    ok(&[
        "transcode",
        s(&tagged),
        "-o",
        s(&output),
        "-q",
        "--erase-attrib",
        "cust:*",
        "--erase-attrib",
        "owner",
        "--erase-attrib",
        "*Window*",
        "--erase-attrib",
        "Exif:*",
        "--erase-attrib",
        "Software",
    ]);
    let text = exrheader_text(&exrheader, &output);
    for gone in ["cust:a", "cust:b", "owner"] {
        assert!(attribute(&text, gone).is_none(), "{gone}: {text}");
    }
    for kept in [
        "comments",
        "dataWindow",
        "displayWindow",
        "screenWindowCenter",
        "screenWindowWidth",
    ] {
        assert!(attribute(&text, kept).is_some(), "{kept}: {text}");
    }
    // The input's history and writer erased, exrcomp's stamp starts anew.
    assert!(
        text.contains("Exif:ImageHistory (type string): \"exrcomp "),
        "{text}"
    );
    assert!(!text.contains("\nexrcomp "), "{text}");
    for (args, says) in [
        (
            ["--attrib", "dataWindow=0,0,1,1:box2i"],
            "'dataWindow' cannot be set",
        ),
        (["--attrib", "channels=R"], "'channels' cannot be set"),
        (["--attrib", "Software=me"], "provenance"),
        (["--attrib", "expTime=1:int"], "of type float, not int"),
        (["--attrib", "t=abc:float"], "'abc' is not of type float"),
        (
            ["--erase-attrib", "compression"],
            "'compression' cannot be erased",
        ),
        (
            ["--erase-attrib", "pixelAspectRatio"],
            "every OpenEXR header has it",
        ),
        (["--timecode", "25:00:00:00"], "hours 25 is over 23"),
        (["--fps", "fast"], "not a rational"),
        // A negative value is the option's value, refused by its own rule
        // (it had been "unexpected argument '-24'").
        (["--fps", "-24"], "a frame rate is above 0, not -24"),
        (["--dwa-level", "-1"], "invalid value '-1' for '--dwa-level"),
    ] {
        let mut all = vec!["transcode", s(&input), "-o", s(&output), "-q"];
        all.extend(args);
        let out = run(&all);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        assert!(
            stderr(&out).lines().next().unwrap().contains(says),
            "{args:?}: {}",
            stderr(&out)
        );
    }
}

/// The timecode exrheader shows for `path`: `time` and flags lines.
fn timecode(exrheader: &Path, path: &Path) -> String {
    let text = exrheader_text(exrheader, path);
    attribute(&text, "timeCode").unwrap_or_else(|| panic!("no timeCode: {text}"))
}

fn time_of(exrheader: &Path, path: &Path) -> String {
    let block = timecode(exrheader, path);
    block.lines().nth(1).unwrap().trim().to_string()
}

#[test]
fn each_frame_gets_its_timecode() {
    let Some(exrheader) = peer("exrheader") else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write_sequence(d, "bg", 1001..=1003, 0);
    let (bg, out) = (d.join("bg.####.exr"), d.join("out.####.exr"));
    let at = |frame: i64| d.join(format!("out.{frame:04}.exr"));
    ok(&[
        "transcode",
        s(&bg),
        "-o",
        s(&out),
        "-q",
        "--timecode",
        "00:59:59:23",
        "--fps",
        "24",
    ]);
    let times: Vec<String> = (1001..=1003).map(|f| time_of(&exrheader, &at(f))).collect();
    assert_eq!(
        times,
        ["time 00:59:59:23", "time 01:00:00:00", "time 01:00:00:01"]
    );
    // A chunk of the range (a farm task) counts from the shot's first frame.
    let chunk = d.join("chunk.####.exr");
    ok(&[
        "transcode",
        s(&bg),
        "-o",
        s(&chunk),
        "-q",
        "--frames",
        "1003",
        "--timecode",
        "00:59:59:23",
        "--fps",
        "24",
    ]);
    assert_eq!(
        time_of(&exrheader, &d.join("chunk.1003.exr")),
        "time 01:00:00:01"
    );
    // Shifting the input's own timecode; 24 fps read from the input.
    let shifted = d.join("shifted.####.exr");
    ok(&[
        "transcode",
        s(&out),
        "-o",
        s(&shifted),
        "-q",
        "--timecode",
        "-24",
    ]);
    assert_eq!(
        time_of(&exrheader, &d.join("shifted.1002.exr")),
        "time 00:59:59:00"
    );
    // Drop-frame at 29.97, anchored on a frame: 00:00:59;29 then 00:01:00;02.
    let df = d.join("df.####.exr");
    ok(&[
        "transcode",
        s(&bg),
        "-o",
        s(&df),
        "-q",
        "--timecode",
        "00:00:59;29@1002",
        "--fps",
        "30000/1001",
    ]);
    let block = timecode(&exrheader, &d.join("df.1003.exr"));
    assert!(block.contains("time 00:01:00:02"), "{block}");
    assert!(block.contains("drop frame 1"), "{block}");
    assert_eq!(
        time_of(&exrheader, &d.join("df.1001.exr")),
        "time 00:00:59:28"
    );
    // Frames at i64's end against an anchor far below: exact, modulo a day
    // (i64::MAX + 1e9 frames at 24 fps); it had wrapped to 09:25:41:07.
    ok(&[
        "transcode",
        s(&d.join("bg.1001.exr")),
        "-o",
        s(&d.join("far.#.exr")),
        "-q",
        "--frames",
        "9223372036854775807",
        "--timecode",
        "00:00:00:00@-1000000000",
        "--fps",
        "24",
    ]);
    assert_eq!(
        time_of(&exrheader, &d.join("far.9223372036854775807.exr")),
        "time 02:43:11:23"
    );
    // No frame rate anywhere: a one-line usage error naming the frame.
    let out = run(&[
        "transcode",
        s(&bg),
        "-o",
        s(&d.join("x.####.exr")),
        "-q",
        "--timecode",
        "01:00:00:00",
    ]);
    assert_eq!(out.status.code(), Some(2), "{}", stderr(&out));
    assert!(stderr(&out).contains("frame 1001") && stderr(&out).contains("--fps"));
}

/// Negative frame numbers without `=`: `--frames -3-2` is a range, as
/// `--frames=-3-2` was (it had been "unexpected argument '-3-2'").
#[test]
fn negative_frames_need_no_equals_sign() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let plates = d.join("g.####.exr");
    generate(&plates, "bg", (16, 8), &["--frames", "-3-2"]);
    let out = d.join("o.####.exr");
    ok(&[
        "transcode",
        s(&plates),
        "-o",
        s(&out),
        "--frames",
        "-3-2",
        "-q",
    ]);
    for frame in -3..=2 {
        assert!(exrcomp_path(&out, frame).exists(), "frame {frame}");
    }
}

/// `out.####.exr`'s file of `frame`, as exrcomp names it.
fn exrcomp_path(pattern: &Path, frame: i64) -> std::path::PathBuf {
    let text = s(pattern).replace("####", &format!("{frame:04}"));
    std::path::PathBuf::from(text)
}

#[test]
fn inputs_read_other_frames_by_offset_or_hold() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write_sequence(d, "fg", 1011..=1013, 0);
    let fg = d.join("fg.####.exr");
    let frame = |name: &str, f: i64| read_image(&d.join(format!("{name}.{f:04}.exr")));
    // Default range: fg's frames on disk, moved back by the offset.
    let out = d.join("out.####.exr");
    ok(&["transcode", &format!("{}@+10", s(&fg)), "-o", s(&out), "-q"]);
    for f in 1001..=1003 {
        assert_identical(&frame("out", f), &frame("fg", f + 10));
    }
    assert!(!d.join("out.1004.exr").exists() && !d.join("out.1000.exr").exists());
    // Held frames, through a merge: every output frame reads fg.1012.
    let held = d.join("held.####.exr");
    ok(&[
        "over",
        &format!("{}@1012", s(&fg)),
        &format!("{}@1012", s(&fg)),
        "-o",
        s(&held),
        "-q",
        "--frames",
        "1-2",
    ]);
    let once = d.join("once.exr");
    ok(&[
        "over",
        s(&d.join("fg.1012.exr")),
        s(&d.join("fg.1012.exr")),
        "-o",
        s(&once),
        "-q",
    ]);
    for f in 1..=2 {
        assert_identical(&frame("held", f), &read_image(&once));
    }
    // @hold: the first frame on disk.
    let first = d.join("first.####.exr");
    ok(&[
        "transcode",
        &format!("{}@hold", s(&fg)),
        "-o",
        s(&first),
        "-q",
        "--frames",
        "7",
    ]);
    assert_identical(&frame("first", 7), &frame("fg", 1011));
    // A frame past the end is missing, named as the file's frame and the
    // output frame that reads it; --missing still decides.
    let late = format!("{}@+11", s(&fg));
    let out2 = d.join("late.####.exr");
    let failed = run(&[
        "transcode",
        &late,
        "-o",
        s(&out2),
        "-q",
        "--frames",
        "1001-1003",
    ]);
    assert_eq!(failed.status.code(), Some(3));
    assert!(
        stderr(&failed)
            .contains("fg.####.exr@+11: missing frame 1014 (read for output frame 1003)"),
        "{}",
        stderr(&failed)
    );
    ok(&[
        "transcode",
        &late,
        "-o",
        s(&out2),
        "-q",
        "--frames",
        "1001-1003",
        "--missing",
        "hold",
    ]);
    assert_identical(&frame("late", 1003), &frame("fg", 1013));
    ok(&[
        "transcode",
        &late,
        "-o",
        s(&d.join("skip.####.exr")),
        "-q",
        "--frames",
        "1001-1003",
        "--missing",
        "skip",
    ]);
    assert!(d.join("skip.1002.exr").exists() && !d.join("skip.1003.exr").exists());
    // An output frame that is another frame's input is refused before any work.
    let itself = run(&[
        "transcode",
        &format!("{}@+1", s(&fg)),
        "-o",
        s(&fg),
        "-q",
        "--frames",
        "1011-1012",
    ]);
    assert_eq!(itself.status.code(), Some(2), "{}", stderr(&itself));
    assert!(stderr(&itself).contains("refusing to overwrite an input"));
    assert!(stderr(&itself).contains("fg.1012.exr"));
    // A malformed time is a usage error naming it.
    let bad = run(&["transcode", &format!("{}@+1O", s(&fg)), "-o", s(&out), "-q"]);
    assert_eq!(bad.status.code(), Some(2));
    assert!(stderr(&bad).contains("write @+10"), "{}", stderr(&bad));
}

#[test]
fn dry_run_lists_each_frames_files_and_writes_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write_sequence(d, "fg", 1011..=1013, 0);
    write_sequence(d, "bg", [1001, 1003], 1);
    let (fg, bg, out) = (
        d.join("fg.####.exr"),
        d.join("bg.####.exr"),
        d.join("comp.####.exr"),
    );
    let fg10 = format!("{}@+10", s(&fg));
    let listed = run(&[
        "over",
        &fg10,
        s(&bg),
        "-o",
        s(&out),
        "--dry-run",
        "--missing",
        "hold",
    ]);
    assert!(listed.status.success(), "{}", stderr(&listed));
    let p = |name: &str| s(&d.join(name)).to_string();
    let expected = [
        format!(
            "frame 1001: {}, {} -> {}",
            p("fg.1011.exr"),
            p("bg.1001.exr"),
            p("comp.1001.exr")
        ),
        format!(
            "frame 1002: {}, {} (held: {} is missing) -> {}",
            p("fg.1012.exr"),
            p("bg.1001.exr"),
            p("bg.1002.exr"),
            p("comp.1002.exr")
        ),
        format!(
            "frame 1003: {}, {} -> {}",
            p("fg.1013.exr"),
            p("bg.1003.exr"),
            p("comp.1003.exr")
        ),
    ];
    let text = String::from_utf8_lossy(&listed.stdout);
    assert_eq!(text.lines().collect::<Vec<_>>(), expected);
    let json = run(&[
        "over",
        &fg10,
        s(&bg),
        "-o",
        s(&out),
        "--dry-run",
        "--missing",
        "black",
        "--json",
        "--frames",
        "1002",
    ]);
    let value: serde_json::Value = serde_json::from_slice(&json.stdout).unwrap();
    assert_eq!(
        value,
        serde_json::json!({
            "frame": 1002,
            "reads": [
                {"file": p("fg.1012.exr"), "source": "frame"},
                {"file": p("bg.1001.exr"), "source": "black", "missing": p("bg.1002.exr")},
            ],
            "output": p("comp.1002.exr"),
        })
    );
    // --quiet prints nothing (farm templates check commands so).
    let quiet = run(&[
        "over",
        &fg10,
        s(&bg),
        "-o",
        s(&out),
        "--dry-run",
        "--missing",
        "hold",
        "-q",
    ]);
    assert!(quiet.status.success() && quiet.stdout.is_empty());
    assert!(!d.join("comp.1001.exr").exists());
}

#[test]
fn job_files_take_the_same_keys() {
    let Some(exrheader) = peer("exrheader") else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write_sequence(d, "fg", 1011..=1012, 0);
    write_sequence(d, "bg", [1005], 1);
    let job = d.join("job.toml");
    let write_job = |read_keys: &str| {
        std::fs::write(
            &job,
            format!(
                r#"[[node]]
name = "fg"
read = "fg.####.exr"
{read_keys}

[[node]]
name = "bg"
read = "bg.####.exr"
hold = true

[[node]]
name = "comp"
op = "over"
inputs = ["fg", "bg"]

[[node]]
name = "out"
write = "comp.####.exr"
inputs = ["comp"]
attrib = ["owner=job", "shot=010:string"]
erase_attrib = ["Exif:*"]
timecode = "01:00:00:00"
fps = 25
"#
            ),
        )
        .unwrap();
    };
    write_job("offset = 10");
    ok(&[
        "run",
        s(&job),
        "-q",
        "--attrib",
        "comments=from the command line",
    ]);
    let once = d.join("once.exr");
    ok(&[
        "over",
        s(&d.join("fg.1012.exr")),
        s(&d.join("bg.1005.exr")),
        "-o",
        s(&once),
        "-q",
    ]);
    assert_identical(&read_image(&d.join("comp.1002.exr")), &read_image(&once));
    let text = exrheader_text(&exrheader, &d.join("comp.1002.exr"));
    for shown in [
        r#"owner (type string): "job""#,
        r#"shot (type string): "010""#,
        r#"comments (type string): "from the command line""#,
        "framesPerSecond (type rational): 25/1 (25)",
        "    time 01:00:00:01",
    ] {
        assert!(text.contains(shown), "{shown}: {text}");
    }
    write_job("offset = 10\nhold = 1011");
    let both = run(&["run", s(&job), "-q"]);
    assert_eq!(both.status.code(), Some(2));
    assert!(
        stderr(&both).contains("job.toml:5: a read takes offset or hold"),
        "{}",
        stderr(&both)
    );
}

#[test]
fn every_part_written_gets_the_edits() {
    let (Some(exrheader), Some(oiiotool)) = (peer("exrheader"), peer("oiiotool")) else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let (input, output) = (d.join("two.exr"), d.join("out.exr"));
    let first = d.join("first.exr");
    succeed(
        Command::new(&oiiotool)
            .args([
                "--create", "16x16", "4", "-d", "half", "--attrib", "cust", "them", "-o",
            ])
            .arg(&first),
    );
    succeed(
        Command::new(&oiiotool)
            .arg(&first)
            .args(["--create", "16x16", "3", "-d", "half", "--siappend", "-o"])
            .arg(&input),
    );
    // Part 1 read and written, part 0 carried chunk for chunk.
    ok(&[
        "transcode",
        &format!("{}:1", s(&input)),
        "-o",
        s(&output),
        "-q",
        "--attrib",
        "shot=a1",
        "--erase-attrib",
        "cust",
        "--timecode",
        "10:00:00:00",
        "--fps",
        "24",
    ]);
    let text = exrheader_text(&exrheader, &output);
    assert!(exrheader_text(&exrheader, &input).contains("cust (type string)"));
    let parts: Vec<&str> = text.split("\n part ").skip(1).collect();
    assert_eq!(parts.len(), 2, "{text}");
    for part in parts {
        assert!(part.contains(r#"shot (type string): "a1""#), "{text}");
        assert!(part.contains("    time 10:00:00:00"), "{text}");
        assert!(!part.contains("cust (type"), "{text}");
    }
    assert_peers_read(&output);
}
