//! Farm templates: an Open Job Description template that OpenJD's own CLI
//! accepts and runs, with chunked output byte-identical to a local run, and
//! a retried chunk that finishes what a killed one left.

use crate::common::*;
use serde_json::{json, Value};
use std::path::Path;
use std::process::Command;

/// Frames 1-7 of fg over bg, run locally into `d/local/`.
fn local_over(d: &Path) {
    let p = |n: &str| d.join(n);
    let (fg, bg, out) = (p("fg.####.exr"), p("bg.####.exr"), p("local/comp.####.exr"));
    ok(&[
        "over",
        s(&fg),
        s(&bg),
        "-o",
        s(&out),
        "--frames",
        "1-7",
        "-q",
    ]);
}

/// Frames 1-7 of fg and bg plates in `d`.
fn plates(d: &Path) {
    for (name, kind) in [("fg", "fg"), ("bg", "bg")] {
        generate(
            &d.join(format!("{name}.####.exr")),
            kind,
            (64, 48),
            &["--frames", "1-7"],
        );
    }
}

/// `openjd ARGS` in `cwd`, its output; a `run` gets the job's parameter
/// values, which exrcomp writes beside the template (`JOB.params.json`).
fn openjd(openjd: &Path, args: &[&str], cwd: &Path) -> String {
    let mut args: Vec<String> = args.iter().map(|a| a.to_string()).collect();
    if args[0] == "run" {
        args.extend([
            "-p".to_string(),
            format!("file://{}", s(&values(&cwd.join(&args[1])))),
        ]);
    }
    let out = Command::new(openjd)
        .args(&args)
        .current_dir(cwd)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "openjd {args:?}:\n{}\n{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8_lossy(&out.stdout).into_owned()
}

/// The OpenJD job template at `path` (exrcomp writes JSON).
fn read_template(path: &Path) -> Value {
    let text = std::fs::read_to_string(path).unwrap();
    serde_json::from_str(&text).unwrap_or_else(|e| panic!("{e}: {text}"))
}

/// The `Frames` task parameter of `template`'s step.
fn frames_parameter(template: &Value) -> &Value {
    &template["steps"][0]["parameterSpace"]["taskParameterDefinitions"][0]
}

/// The arguments of `template`'s task command.
fn task_args(template: &Value) -> Vec<&str> {
    let args = template["steps"][0]["script"]["actions"]["onRun"]["args"].as_array();
    args.unwrap().iter().map(|a| a.as_str().unwrap()).collect()
}

/// The variables of `template`'s step environment.
fn variables(template: &Value) -> &Value {
    &template["steps"][0]["stepEnvironments"][0]["variables"]
}

/// How often `words` follow each other in `args`.
fn count(args: &[&str], words: &[&str]) -> usize {
    args.windows(words.len()).filter(|w| *w == words).count()
}

/// The parameter values of the OpenJD job `template`.
fn values(template: &Path) -> std::path::PathBuf {
    let stem = template.file_stem().unwrap().to_string_lossy();
    template.with_file_name(format!("{stem}.params.json"))
}

#[test]
fn an_openjd_template_checks_runs_and_matches_a_local_run_byte_for_byte() {
    let Some(openjd_cli) = peer("openjd") else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    plates(d);
    // Relative names, made absolute in the template (tasks run elsewhere).
    let make = Command::new(env!("CARGO_BIN_EXE_exrcomp"))
        .args([
            "farm", "openjd", "--frames", "1-7", "--chunk", "3", "-o", "job.yaml", "--",
        ])
        .args([
            "over",
            "fg.####.exr",
            "bg.####.exr",
            "-o",
            "farm/comp.####.exr",
        ])
        .current_dir(d)
        .output()
        .unwrap();
    assert!(make.status.success(), "{}", stderr(&make));
    let template = read_template(&d.join("job.yaml"));
    assert_eq!(
        frames_parameter(&template)["range"],
        json!(["1-3", "4-6", "7"]),
        "{template}"
    );
    openjd(&openjd_cli, &["check", "job.yaml"], d);
    openjd(&openjd_cli, &["run", "job.yaml", "--step", "exrcomp"], d);
    let p = |n: &str| d.join(n);
    local_over(d);
    let same = |frame: i64| {
        let name = format!("comp.{frame:04}.exr");
        std::fs::read(p("farm").join(&name)).unwrap()
            == std::fs::read(p("local").join(&name)).unwrap()
    };
    assert!(
        (1..=7).all(same),
        "chunked output differs from the local run"
    );

    // A killed task leaves a hidden temporary and no frame; its retry (the
    // same chunk) writes what is missing and keeps what is done.
    std::fs::remove_file(p("farm/comp.0005.exr")).unwrap();
    std::fs::write(p("farm/.comp.0005.exr.exrcomp-999999.tmp"), b"half a frame").unwrap();
    let kept = std::fs::metadata(p("farm/comp.0004.exr"))
        .unwrap()
        .modified()
        .unwrap();
    openjd(
        &openjd_cli,
        &[
            "run",
            "job.yaml",
            "--step",
            "exrcomp",
            "--task-param",
            "Frames=4-6",
        ],
        d,
    );
    assert!((4..=6).all(same));
    assert_eq!(
        std::fs::metadata(p("farm/comp.0004.exr"))
            .unwrap()
            .modified()
            .unwrap(),
        kept,
        "a finished frame was redone"
    );
    assert!(
        !p("farm/.comp.0005.exr.exrcomp-999999.tmp").exists(),
        "the killed run's temporary stayed"
    );
}

#[test]
fn path_mapping_moves_a_whole_shot_and_its_outputs_land_there_byte_for_byte() {
    let Some(openjd_cli) = peer("openjd") else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let shot = dir.path().join("shot");
    std::fs::create_dir(&shot).unwrap();
    plates(&shot);
    let make = exrcomp()
        .args([
            "farm", "openjd", "--frames", "1-7", "--chunk", "4", "-o", "job.yaml", "--",
        ])
        .args([
            "over",
            "fg.####.exr",
            "bg.####.exr",
            "-o",
            "farm/comp.####.exr",
        ])
        .current_dir(&shot)
        .output()
        .unwrap();
    assert!(make.status.success(), "{}", stderr(&make));
    let template = std::fs::read_to_string(shot.join("job.yaml")).unwrap();
    for parameter in ["Exrcomp", "Input1", "Input2", "Output"] {
        assert!(
            template.contains(&format!("{{{{Param.{parameter}}}}}")),
            "{template}"
        );
    }
    assert!(
        !template.contains(s(&shot)),
        "a path is written into the template: {template}"
    );
    // The shot moves to another folder (another mount on the worker): the
    // rule maps every path parameter, and nothing lands in the old place.
    let moved = dir.path().join("moved");
    std::fs::rename(&shot, &moved).unwrap();
    let rules = serde_json::json!({
        "version": "pathmapping-1.0",
        "path_mapping_rules": [{
            "source_path_format": "POSIX",
            "source_path": s(&shot),
            "destination_path": s(&moved),
        }],
    });
    openjd(
        &openjd_cli,
        &[
            "run",
            "job.yaml",
            "--step",
            "exrcomp",
            "--path-mapping-rules",
            &rules.to_string(),
        ],
        &moved,
    );
    assert!(!shot.exists(), "an output was written at the unmapped path");
    local_over(&moved);
    for frame in 1..=7 {
        let name = format!("comp.{frame:04}.exr");
        assert_eq!(
            std::fs::read(moved.join("farm").join(&name)).unwrap(),
            std::fs::read(moved.join("local").join(&name)).unwrap(),
            "{name}"
        );
    }
}

#[test]
fn frames_belong_to_the_farm_command_not_the_task() {
    let dir = tempfile::tempdir().unwrap();
    let out = run(&[
        "farm",
        "openjd",
        "--frames",
        "1-4",
        "-o",
        s(&dir.path().join("j.yaml")),
        "--",
        "over",
        "a.exr",
        "b.exr",
        "-o",
        "c.exr",
        "--frames",
        "1-2",
    ]);
    assert_eq!(out.status.code(), Some(2), "{}", stderr(&out));
    assert!(
        stderr(&out).contains("give --frames to `exrcomp farm`"),
        "{}",
        stderr(&out)
    );
}

/// Python with OpenCue's PyOutline, or `None` (skip; a failure under
/// EXRCOMP_REQUIRE_PEERS=1).
fn pyoutline() -> Option<std::path::PathBuf> {
    let python = peer("python3")?;
    let found = Command::new(&python)
        .args(["-c", "import outline.backend.cue"])
        .status()
        .is_ok_and(|s| s.success());
    if !found {
        missing("PyOutline (pip install opencue-pyoutline packaging) is not importable");
    }
    found.then_some(python)
}

/// The job spec Cuebot takes for the outline `job`, as OpenCue's own library
/// loads and serialises it.
fn cue_spec(python: &Path, job: &Path) -> String {
    let script = "import sys, outline.loader, outline.cuerun\n\
        from outline.backend import cue\n\
        ol = outline.loader.load_json(open(sys.argv[1]).read())\n\
        print(cue.serialize_simple(outline.cuerun.OutlineLauncher(ol, show='test', shot='test', user='artist')))\n";
    let out = Command::new(python)
        .args(["-c", script])
        .arg(job)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8_lossy(&out.stdout).into_owned()
}

/// Runs the layer's command `cmd` for each chunk, its tokens replaced as
/// RQD replaces them, through a shell as RQD runs it.
fn run_cue_chunks(cmd: &str, chunks: &[(i64, i64)]) {
    for (start, end) in chunks {
        let line = cmd
            .replace("#FRAME_START#", &start.to_string())
            .replace("#FRAME_END#", &end.to_string());
        let status = Command::new("sh").args(["-c", &line]).status().unwrap();
        assert!(status.success(), "{line}");
    }
}

/// The layer's command in a Cuebot job spec.
fn cue_command(spec: &str) -> String {
    spec.split("<cmd>")
        .nth(1)
        .and_then(|c| c.split("</cmd>").next())
        .unwrap()
        .to_string()
}

#[test]
fn an_opencue_outline_loads_in_pyoutline_and_its_chunks_match_a_local_run() {
    let Some(python) = pyoutline() else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    plates(d);
    let p = |n: &str| d.join(n);
    let (fg, bg, out, job) = (
        p("fg.####.exr"),
        p("bg.####.exr"),
        p("cue/comp.####.exr"),
        p("job.json"),
    );
    let mut args = vec![
        "farm",
        "opencue",
        "--threads",
        "1",
        "--frames",
        "1-7",
        "--chunk",
        "3",
        "-o",
        s(&job),
        "--",
    ];
    args.extend(["over", s(&fg), s(&bg), "-o", s(&out)]);
    ok(&args);
    // OpenCue's own library loads the outline and writes the job spec cuebot takes.
    let spec = cue_spec(&python, &p("job.json"));
    for part in [
        "<range>1-7</range>",
        "<chunk>3</chunk>",
        "--resume --threads 1 --frames 1-7 --chunk-from #FRAME_START#,3</cmd>",
    ] {
        assert!(spec.contains(part), "{part} not in\n{spec}");
    }
    // Each OpenCue frame chunk, its tokens replaced as RQD does, equals the local run.
    let cmd = cue_command(&spec);
    run_cue_chunks(&cmd, &[(1, 3), (4, 6), (7, 7)]);
    local_over(d);
    for frame in 1..=7 {
        let name = format!("comp.{frame:04}.exr");
        assert_eq!(
            std::fs::read(p("cue").join(&name)).unwrap(),
            std::fs::read(p("local").join(&name)).unwrap()
        );
    }
}

#[test]
fn bands_rendered_apart_stitch_into_the_whole_render_byte_for_byte() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    generate(&d.join("fg.exr"), "fg", (64, 100), &[]);
    generate(&d.join("bg.exr"), "bg", (64, 100), &[]);
    // Halos of 5 and 3 rows one after the other: a band reads 8 rows past its edges.
    let job = "[[node]]\nname = \"fg\"\nread = \"fg.exr\"\n[[node]]\nname = \"bg\"\nread = \"bg.exr\"\n\
        [[node]]\nname = \"comp\"\nop = \"over\"\ninputs = [\"fg\", \"bg\"]\n\
        [[node]]\nname = \"soft\"\nop = \"blur\"\nradius = 5\ninputs = [\"comp\"]\n\
        [[node]]\nname = \"dof\"\nop = \"defocus\"\nfocus = 5.0\nscale = 6.0\nmax_radius = 3\ninputs = [\"soft\"]\n\
        [[node]]\nname = \"out\"\nwrite = \"whole.exr\"\ninputs = [\"dof\"]\n";
    let p = |n: &str| d.join(n);
    std::fs::write(p("job.toml"), job).unwrap();
    ok(&["run", s(&p("job.toml")), "-q"]);
    for (name, rows, height) in [
        ("b1.exr", "0-32", 32),
        ("b2.exr", "32-48", 16),
        ("b3.exr", "48-100", 52),
    ] {
        ok(&[
            "run",
            s(&p("job.toml")),
            "-o",
            s(&p(name)),
            "--rows",
            rows,
            "-q",
        ]);
        assert_eq!(read_image(&p(name)).height, height, "{name}");
    }
    // In any order on the command line.
    ok(&[
        "stitch",
        s(&p("b3.exr")),
        s(&p("b1.exr")),
        s(&p("b2.exr")),
        "-o",
        s(&p("stitched.exr")),
    ]);
    assert_eq!(
        std::fs::read(p("stitched.exr")).unwrap(),
        std::fs::read(p("whole.exr")).unwrap()
    );
    assert_peers_read(&p("stitched.exr"));
    // A band off the block grid, or past the bottom, and a gap between
    // bands, are refused.
    for rows in ["5-32", "48-200", "100-116"] {
        let out = run(&[
            "run",
            s(&p("job.toml")),
            "-o",
            s(&p("x.exr")),
            "--rows",
            rows,
        ]);
        assert_eq!(out.status.code(), Some(2), "{rows}: {}", stderr(&out));
        assert!(
            stderr(&out).contains("a band must lie in rows 0-100"),
            "{}",
            stderr(&out)
        );
        assert!(!p("x.exr").exists());
    }
    let out = run(&[
        "stitch",
        s(&p("b1.exr")),
        s(&p("b3.exr")),
        "-o",
        s(&p("gap.exr")),
    ]);
    assert_eq!(out.status.code(), Some(3), "{}", stderr(&out));
    assert!(
        stderr(&out).contains("starts at row 48 but the bands before it end at row 32"),
        "{}",
        stderr(&out)
    );
    assert!(!p("gap.exr").exists());
}

/// A band records the whole window and frame it is part of: a set missing
/// its first or last band, or mixing frames, or files that are not bands,
/// is refused naming the file, and nothing is written.
#[test]
fn stitch_refuses_bands_that_do_not_make_one_whole_frame() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let p = |n: &str| d.join(n);
    generate(&p("in.####.exr"), "bg", (64, 128), &["--frames", "1-2"]);
    ok(&[
        "transcode",
        s(&p("in.####.exr")),
        "-o",
        s(&p("whole.####.exr")),
        "-q",
    ]);
    for (name, rows) in [("top", "0-64"), ("mid", "64-112"), ("end", "112-128")] {
        let out = p(&format!("{name}.####.exr"));
        ok(&[
            "transcode",
            s(&p("in.####.exr")),
            "-o",
            s(&out),
            "--rows",
            rows,
            "-q",
        ]);
    }
    let refused = |bands: &[&str], file: &str, words: &str| {
        let mut args = vec!["stitch".to_string()];
        args.extend(bands.iter().map(|b| s(&p(b)).to_string()));
        args.extend(["-o".to_string(), s(&p("x.exr")).to_string()]);
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        let out = run(&args);
        assert_eq!(out.status.code(), Some(3), "{bands:?}: {}", stderr(&out));
        let text = stderr(&out);
        assert_eq!(text.lines().count(), 1, "{text}");
        assert!(
            text.contains(file) && text.contains(words),
            "{bands:?}: {text}"
        );
        assert!(!p("x.exr").exists(), "{bands:?} wrote a file");
    };
    refused(
        &["top.0001.exr", "mid.0001.exr"],
        "mid.0001.exr",
        "a band is missing after it",
    );
    refused(
        &["end.0001.exr", "mid.0001.exr"],
        "mid.0001.exr",
        "a band is missing before it",
    );
    refused(
        &["top.0001.exr", "mid.0002.exr", "end.0001.exr"],
        "mid.0002.exr",
        "another frame",
    );
    // A band of another job (a graded plate's rows 64-112).
    ok(&[
        "grade",
        s(&p("in.####.exr")),
        "-o",
        s(&p("graded.####.exr")),
        "--gain",
        "2",
        "--rows",
        "64-112",
        "-q",
    ]);
    refused(
        &["top.0001.exr", "graded.0001.exr", "end.0001.exr"],
        "graded.0001.exr",
        "another job",
    );
    refused(
        &["whole.0001.exr", "whole.0002.exr"],
        "whole.0001.exr",
        "is not a band",
    );
    refused(
        &["top.0001.exr", "whole.0002.exr"],
        "whole.0002.exr",
        "another frame",
    );
    // The whole set, of either frame, is the whole render byte for byte:
    // the record is not carried into it.
    for frame in ["0001", "0002"] {
        let band = |name: &str| p(&format!("{name}.{frame}.exr"));
        let joined = p(&format!("joined.{frame}.exr"));
        ok(&[
            "stitch",
            s(&band("end")),
            s(&band("top")),
            s(&band("mid")),
            "-o",
            s(&joined),
        ]);
        assert_eq!(
            std::fs::read(&joined).unwrap(),
            std::fs::read(p(&format!("whole.{frame}.exr"))).unwrap(),
            "frame {frame}"
        );
    }
}

/// Templates that would fail on every task are never written: the command is
/// parsed by exrcomp's own parser and checked over all the frames first.
#[test]
fn no_template_is_written_for_a_command_that_would_fail() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    plates(d);
    let farm = |command: &[&str]| {
        let out = exrcomp()
            .args(["farm", "openjd", "--frames", "1-7", "-o", "job.yaml", "--"])
            .args(command)
            .current_dir(d)
            .output()
            .unwrap();
        (out.status.code(), stderr(&out))
    };
    for (command, code, words) in [
        (
            &["ovr", "fg.####.exr", "bg.####.exr", "-o", "c.####.exr"][..],
            2,
            "does not parse",
        ),
        (
            &["stitch", "a.exr", "b.exr", "-o", "c.exr"],
            2,
            "renders no frames",
        ),
        (&["info", "fg.0001.exr"], 2, "renders no frames"),
        (
            &["over", "fgg.####.exr", "bg.####.exr", "-o", "c.####.exr"],
            3,
            "fgg.####.exr",
        ),
        (
            &["over", "fg.####.exr", "bg.####.exr", "-o", "./bg.####.exr"],
            2,
            "refusing to overwrite",
        ),
        (
            &[
                "blur",
                "fg.####.exr",
                "-o",
                "c.####.exr",
                "--radius",
                "1e30",
            ],
            2,
            "radius must be",
        ),
    ] {
        let (got, message) = farm(command);
        assert_eq!(got, Some(code), "{command:?}: {message}");
        assert!(message.contains(words), "{command:?}: {message}");
        assert!(!d.join("job.yaml").exists(), "{command:?} wrote a template");
    }
    // Nothing was rendered by the checks.
    assert!(!d.join("c.0001.exr").exists());
}

/// A job's own files (the template, the file beside it) never replace what
/// the job reads, its job file included, nor a frame it writes.
#[test]
fn a_template_never_replaces_an_input_the_job_file_or_a_frame() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    plates(d);
    std::fs::write(
        d.join("shot.toml"),
        "[[node]]\nname = \"a\"\nread = \"fg.####.exr\"\n\n\
         [[node]]\nname = \"out\"\nwrite = \"c.####.exr\"\ninputs = [\"a\"]\n",
    )
    .unwrap();
    std::fs::write(d.join("c.0003.exr"), "a frame rendered earlier").unwrap();
    let over = ["over", "fg.####.exr", "bg.####.exr", "-o", "c.####.exr"];
    // What the job reads, and a frame it wrote before.
    let kept = [
        "fg.0002.exr",
        "bg.0007.exr",
        "fg.0001.exr",
        "shot.toml",
        "c.0003.exr",
    ];
    let contents = || -> Vec<Vec<u8>> {
        kept.iter()
            .map(|f| std::fs::read(d.join(f)).unwrap())
            .collect()
    };
    for (farm, output, command, words) in [
        ("openjd", "fg.0002.exr", &over[..], "is the input"),
        ("deadline", "bg.0007.exr", &over[..], "is the input"),
        ("opencue", "./fg.0001.exr", &over[..], "is the input"),
        ("openjd", "shot.toml", &["run", "shot.toml"], "is the input"),
        ("openjd", "c.0003.exr", &over[..], "is the frame"),
        ("deadline", "c.0004.exr", &over[..], "is the frame"),
    ] {
        let before = contents();
        let out = exrcomp()
            .args(["farm", farm, "--frames", "1-7", "-o", output, "--"])
            .args(command)
            .current_dir(d)
            .output()
            .unwrap();
        let message = stderr(&out);
        assert_eq!(out.status.code(), Some(2), "{farm} {output}: {message}");
        assert!(
            message.contains(words) && message.contains("refusing to overwrite"),
            "{farm} {output}: {message}"
        );
        assert!(before == contents(), "{farm} -o {output} changed a file");
    }
}

/// Options given to the command in any spelling reach every task once, with
/// file names made absolute by parsing; chunks are range expressions, and
/// more tasks than OpenJD lists go to the scheduler's own chunking.
#[test]
fn templates_take_any_spelling_and_any_number_of_frames() {
    let Some(openjd_cli) = peer("openjd") else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    plates(d);
    let make = |farm: &[&str], command: &[&str]| {
        let out = exrcomp()
            .args(["farm", "openjd"])
            .args(farm)
            .arg("--")
            .args(command)
            .current_dir(d)
            .output()
            .unwrap();
        assert!(out.status.success(), "{}", stderr(&out));
    };
    // --output= and a --resume of the user's own: one --resume per task.
    let over = [
        "over",
        "fg.####.exr",
        "bg.####.exr",
        "--output=jobs/out/c.####.exr",
        "--resume",
        "-q",
    ];
    make(
        &["--frames", "1-7", "--chunk", "3", "-o", "jobs/a/job.yaml"],
        &over,
    );
    let template = read_template(&d.join("jobs/a/job.yaml"));
    let given = std::fs::read_to_string(values(&d.join("jobs/a/job.yaml"))).unwrap();
    let output = d.join("jobs/out/c.####.exr");
    assert!(
        given.contains(&format!("\"Output\": \"{}\"", s(&output))),
        "{given}"
    );
    // In the task's arguments (the description quotes the command as given).
    let args = task_args(&template);
    assert_eq!(count(&args, &["--resume"]), 1, "{template}");
    assert_eq!(count(&args, &["-q"]) + count(&args, &["--quiet"]), 1);
    openjd(&openjd_cli, &["check", "jobs/a/job.yaml"], d);
    openjd(
        &openjd_cli,
        &["run", "jobs/a/job.yaml", "--step", "exrcomp"],
        d,
    );
    local_over(d);
    for frame in 1..=7 {
        let name = format!("c.{frame:04}.exr");
        let local = format!("local/comp.{frame:04}.exr");
        assert_eq!(
            std::fs::read(d.join("jobs/out").join(name)).unwrap(),
            std::fs::read(d.join(local)).unwrap()
        );
    }
    // Stepped frames: each chunk a range expression, not a list.
    make(
        &["--frames", "1-7x2", "--chunk", "2", "-o", "b.yaml"],
        &["over", "fg.####.exr", "bg.####.exr", "-o", "b/c.####.exr"],
    );
    let template = read_template(&d.join("b.yaml"));
    assert_eq!(
        frames_parameter(&template)["range"],
        json!(["1-3:2", "5-7:2"]),
        "{template}"
    );
    openjd(&openjd_cli, &["check", "b.yaml"], d);
    // 2,000 one-frame chunks: more than OpenJD lists, so the scheduler chunks
    // (CHUNK[INT]); a file name with {{ goes through a parameter.
    for frame in 8..=2000 {
        std::fs::copy(
            d.join("fg.0001.exr"),
            d.join(format!("f{{{{x}}}}.{frame:04}.exr")),
        )
        .unwrap();
    }
    for frame in 1..=7 {
        std::fs::copy(
            d.join("fg.0001.exr"),
            d.join(format!("f{{{{x}}}}.{frame:04}.exr")),
        )
        .unwrap();
    }
    let listed = exrcomp()
        .args([
            "farm", "openjd", "--frames", "1-2000", "--chunk", "1", "-o", "c.yaml", "--",
        ])
        .args(["premult", "f{{x}}.####.exr", "-o", "c/p.####.exr"])
        .current_dir(d)
        .output()
        .unwrap();
    assert_eq!(listed.status.code(), Some(2));
    assert!(
        stderr(&listed).contains("--task-chunking"),
        "{}",
        stderr(&listed)
    );
    make(
        &[
            "--frames",
            "1-2000",
            "--chunk",
            "100",
            "--target-runtime",
            "60",
            "-o",
            "c.yaml",
        ],
        &["premult", "f{{x}}.####.exr", "-o", "c/p.####.exr"],
    );
    let template = read_template(&d.join("c.yaml"));
    let frames = frames_parameter(&template);
    let parameters = template["parameterDefinitions"].as_array().unwrap();
    assert_eq!(template["extensions"], json!(["TASK_CHUNKING"]));
    assert_eq!(frames["type"], "CHUNK[INT]", "{template}");
    assert_eq!(frames["range"], "{{Param.Frames}}", "{template}");
    assert!(
        parameters.iter().any(|p| p["default"] == "1-2000"),
        "{template}"
    );
    assert_eq!(
        frames["chunks"],
        json!({"defaultTaskCount": "{{Param.ChunkSize}}", "rangeConstraint": "CONTIGUOUS", "targetRuntimeSeconds": 60}),
        "{template}"
    );
    assert!(task_args(&template).contains(&"{{Param.Input1}}"));
    let given = std::fs::read_to_string(values(&d.join("c.yaml"))).unwrap();
    assert!(given.contains("f{{x}}.####.exr"), "{given}");
    openjd(&openjd_cli, &["check", "c.yaml"], d);
    openjd(
        &openjd_cli,
        &[
            "run",
            "c.yaml",
            "--step",
            "exrcomp",
            "--task-param",
            "Frames=1995-2000",
        ],
        d,
    );
    assert!(d.join("c/p.2000.exr").exists() && d.join("c/p.1995.exr").exists());
    assert!(!d.join("c/p.1994.exr").exists());
}

/// `exrcomp farm FARM ARGS -- COMMAND` in `d` with `env` set; its output.
fn farm_in(
    d: &Path,
    env: &[(&str, &str)],
    args: &[&str],
    command: &[&str],
) -> std::process::Output {
    exrcomp()
        .args(["farm"])
        .args(args)
        .arg("--")
        .args(command)
        .envs(env.iter().copied())
        .current_dir(d)
        .output()
        .unwrap()
}

/// The `min` of the OpenJD amount `name` in `template`.
fn amount(template: &Value, name: &str) -> u64 {
    let amounts = template["steps"][0]["hostRequirements"]["amounts"].as_array();
    let amount = amounts.unwrap().iter().find(|a| a["name"] == name);
    let amount = amount.unwrap_or_else(|| panic!("no {name} in {template}"));
    amount["min"].as_u64().unwrap()
}

/// The memory bound of specs/architecture.md worked by hand, in MiB, for
/// one frame of `over` on one thread of the generated fg (half RGBA, float
/// Z and vectors: 20 bytes a pixel) and bg (12 bytes, as the result), W
/// wide, strips of S rows, ZIP blocks of 16 lines: both inputs and the
/// merge alive at once, none with a halo; ZIP inputs inflate into the
/// thread's buffers and then straight into the strip (two strips each, and
/// for the larger input, fg, its chunks read, T L rows at most, and a
/// strip's chunks the heap keeps); the ZIP output transforms in the
/// thread's buffers (c_o = 0); the writer's two batches waiting, each also
/// laid out; the thread's
/// codec buffers: the largest block (fg's), a read block with its 64 bytes
/// of padding, an output block deflated (1/512 over) and the compressors at
/// the default level (660 KiB libdeflate, 300 KiB igzip).
fn over_bound_by_hand(w: u64, s: u64) -> u64 {
    let (l, fg, bg) = (16, 20, 12);
    let decode = w * (fg + bg) * 2 * s + w * fg * (l.min(s + 2 * l) + s + 2 * l);
    let windows = w * s * (fg + bg + bg);
    let encode = (4 + 2 * 2) * s * w * bg;
    let (read, written) = (w * l * fg, w * l * bg);
    let codec = read + (read + 64) + (written + written / 512) + (660 << 10) + (300 << 10);
    (decode + windows + encode + codec + (10 << 20)).div_ceil(1 << 20)
}

/// OpenJD's host requirements: the task's threads as vcpus and the
/// engine's memory bound in MiB (worked by hand, and above a run's peak);
/// the threads reach the task's command once; the submitter's EXRCOMP_*
/// settings are the step's environment, `{{` and all; a description says
/// what the job does and needs.
#[test]
fn openjd_jobs_ask_for_their_threads_and_memory_and_carry_the_settings() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    for (name, kind) in [("fg", "fg"), ("bg", "bg")] {
        generate(
            &d.join(format!("{name}.####.exr")),
            kind,
            (1024, 256),
            &["--frames", "1-2"],
        );
    }
    let over = ["over", "fg.####.exr", "bg.####.exr", "-o", "out/c.####.exr"];
    let settings = [("EXRCOMP_TEST_SETTING", "a{{b}}")];
    let out = farm_in(
        d,
        &settings,
        &[
            "openjd",
            "--threads",
            "1",
            "--frames",
            "1-2",
            "-o",
            "job.yaml",
        ],
        &over,
    );
    assert!(out.status.success(), "{}", stderr(&out));
    let template = read_template(&d.join("job.yaml"));
    assert_eq!(amount(&template, "amount.worker.vcpu"), 1, "{template}");
    let memory = amount(&template, "amount.worker.memory");
    // On one thread a block is 1024 x 16 x 12 = 196,608 bytes: a strip is
    // ceil(2 MiB / block) = 11 blocks, 176 rows.
    assert_eq!(memory, over_bound_by_hand(1024, 176), "{template}");
    assert_eq!(
        count(&task_args(&template), &["--threads", "1"]),
        1,
        "{template}"
    );
    let setting = variables(&template)["EXRCOMP_TEST_SETTING"].as_str();
    let parameters = template["parameterDefinitions"].as_array().unwrap();
    assert!(
        setting.unwrap().starts_with("{{Param.Env")
            && parameters.iter().any(|p| p["default"] == "a{{b}}"),
        "{template}"
    );
    let description = template["description"].as_str().unwrap();
    assert!(
        description.starts_with("exrcomp over fg.####.exr")
            && description.contains(&format!("at most {memory} MiB")),
        "{template}"
    );
    // A run of the command on those threads holds less than the bound.
    let local = exrcomp()
        .args(over)
        .args(["--frames", "1-2", "--threads", "1", "--json"])
        .current_dir(d)
        .output()
        .unwrap();
    assert!(local.status.success(), "{}", stderr(&local));
    let summary: serde_json::Value = serde_json::from_slice(&local.stdout).unwrap();
    let peak = summary["peak_rss_bytes"].as_u64().unwrap();
    assert!(
        peak <= memory << 20,
        "peak {peak} over the bound {memory} MiB"
    );
    // COMMAND's own --threads is the one the job asks for, once.
    let out = farm_in(
        d,
        &[],
        &["openjd", "--frames", "1-2", "-o", "two.yaml"],
        &[&over[..], &["--threads", "2"]].concat(),
    );
    assert!(out.status.success(), "{}", stderr(&out));
    let two = read_template(&d.join("two.yaml"));
    assert_eq!(amount(&two, "amount.worker.vcpu"), 2, "{two}");
    assert_eq!(count(&task_args(&two), &["--threads"]), 1, "{two}");
    let Some(openjd_cli) = peer("openjd") else {
        return;
    };
    openjd(&openjd_cli, &["check", "job.yaml"], d);
    let log = openjd(&openjd_cli, &["run", "job.yaml", "--step", "exrcomp"], d);
    assert!(
        log.contains("Setting: EXRCOMP_TEST_SETTING=a{{b}}"),
        "{log}"
    );
    assert!(d.join("out/c.0002.exr").exists());
}

/// An OpenCue outline as OpenJD's templates are made: COMMAND parsed and
/// checked (nothing written for one that would fail), names absolute by
/// parsing, --resume and --quiet once, ranges with steps; the layer asks
/// for its service, the task's threads as cores and the memory bound, and
/// carries the EXRCOMP_* settings. Its chunks, run as RQD runs them (tokens
/// replaced, through a shell), write what a local run writes.
#[test]
fn opencue_layers_get_service_cores_memory_and_checked_commands() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    plates(d);
    for (frames, input, code) in [("1-7", "fgg.####.exr", 3), ("1,2,5", "fg.####.exr", 2)] {
        let out = farm_in(
            d,
            &[],
            &["opencue", "--frames", frames, "-o", "bad.json"],
            &["over", input, "bg.####.exr", "-o", "c.####.exr"],
        );
        assert_eq!(out.status.code(), Some(code), "{}", stderr(&out));
        assert!(!d.join("bad.json").exists());
    }
    let out = farm_in(
        d,
        &[("EXRCOMP_TEST_SETTING", "x y")],
        &[
            "opencue",
            "--threads",
            "1",
            "--frames",
            "1-7x2",
            "--chunk",
            "2",
            "--service",
            "comp",
            "-o",
            "jobs/cue.json",
        ],
        &[
            "over",
            "fg.####.exr",
            "bg.####.exr",
            "--output=cue dir/c.####.exr",
            "-q",
            "--resume",
        ],
    );
    assert!(out.status.success(), "{}", stderr(&out));
    let Some(python) = pyoutline() else {
        return;
    };
    let spec = cue_spec(&python, &d.join("jobs/cue.json"));
    for part in [
        "<range>1-7x2</range>".to_string(),
        "<chunk>2</chunk>".to_string(),
        "<cores>1.0</cores>".to_string(),
        // A strip of a 64x48 frame is its 48 rows.
        format!("<memory>{}m</memory>", over_bound_by_hand(64, 48)),
        "<key name=\"EXRCOMP_TEST_SETTING\">x y</key>".to_string(),
        "<service>comp</service>".to_string(),
    ] {
        assert!(spec.contains(&part), "{part} not in\n{spec}");
    }
    let cmd = cue_command(&spec);
    assert_eq!(cmd.matches("--resume").count(), 1, "{cmd}");
    assert_eq!(
        cmd.matches("-q").count() + cmd.matches("--quiet").count(),
        1,
        "{cmd}"
    );
    assert!(
        cmd.contains(&format!("'{}/cue dir/c.####.exr'", s(d))),
        "{cmd}"
    );
    run_cue_chunks(&cmd, &[(1, 3), (5, 7)]);
    local_over(d);
    for frame in 1..=7 {
        let name = format!("comp.{frame:04}.exr");
        let cue = d.join("cue dir").join(format!("c.{frame:04}.exr"));
        match frame % 2 {
            1 => assert_eq!(
                std::fs::read(cue).unwrap(),
                std::fs::read(d.join("local").join(&name)).unwrap()
            ),
            _ => assert!(!cue.exists(), "{frame} is not in 1-7x2"),
        }
    }
}

/// Job-info keys of Deadline 10 (User Manual, "Manual Job Submission", job
/// info file; "Render Environment" for EnvironmentKeyValue#), those
/// numbered with # for their index.
const DEADLINE_JOB_KEYS: [&str; 33] = [
    "Plugin",
    "Frames",
    "Name",
    "Comment",
    "Department",
    "BatchName",
    "Pool",
    "SecondaryPool",
    "Group",
    "Priority",
    "ChunkSize",
    "ConcurrentTasks",
    "LimitConcurrentTasksToNumberOfCpus",
    "MachineLimit",
    "Whitelist",
    "Blacklist",
    "LimitGroups",
    "JobDependencies",
    "OnJobComplete",
    "InitialStatus",
    "TaskTimeoutMinutes",
    "EnableAutoTimeout",
    "MinRenderTimeSeconds",
    "OverrideTaskFailureDetection",
    "FailureDetectionTaskErrors",
    "OutputDirectory#",
    "OutputFilename#",
    "EnvironmentKeyValue#",
    "IncludeEnvironment",
    "UseJobEnvironmentOnly",
    "ExtraInfo#",
    "ExtraInfoKeyValue#",
    "UserName",
];

/// Plugin-info keys of Deadline's CommandLine plugin (the
/// `-SubmitCommandLineJob` options it is submitted with).
const DEADLINE_COMMANDLINE_KEYS: [&str; 5] = [
    "Executable",
    "Arguments",
    "StartupDirectory",
    "Shell",
    "ShellExecute",
];

/// A Deadline key=value file, every key one of `allowed` (`#` an index).
fn deadline_file(path: &Path, allowed: &[&str]) -> Vec<(String, String)> {
    let text = std::fs::read_to_string(path).unwrap();
    text.lines()
        .map(|line| {
            let (key, value) = line.split_once('=').unwrap_or_else(|| panic!("{line:?}"));
            let base = key.trim_end_matches(|c: char| c.is_ascii_digit());
            let known = allowed.contains(&key)
                || (base != key && allowed.contains(&format!("{base}#").as_str()));
            assert!(known, "{key} is not a documented key: {text}");
            (key.to_string(), value.to_string())
        })
        .collect()
}

/// `farm deadline ARGS` of fg over bg into `output`, with `env`: its job
/// info and plugin info (`JOB.job`, `JOB.plugin.job`), documented keys only.
type Pairs = Vec<(String, String)>;
fn deadline_over(d: &Path, env: &[(&str, &str)], args: &[&str], output: &str) -> (Pairs, Pairs) {
    let args = [&["deadline"][..], args].concat();
    let out = farm_in(
        d,
        env,
        &args,
        &["over", "fg.####.exr", "bg.####.exr", "-o", output],
    );
    assert!(out.status.success(), "{}", stderr(&out));
    let job = d.join(args.last().unwrap());
    let plugin = job.with_extension("plugin.job");
    (
        deadline_file(&job, &DEADLINE_JOB_KEYS),
        deadline_file(&plugin, &DEADLINE_COMMANDLINE_KEYS),
    )
}

/// Deadline 10 job files for the CommandLine plugin: documented keys only,
/// the frames and chunk size, the output for the Monitor, the settings as
/// the job's environment, the needs as extra info; each chunk's command,
/// its tokens replaced as Deadline replaces them, writes what a local run
/// writes. Frame lists Deadline cannot chunk, and commands that would fail,
/// write nothing.
#[test]
fn deadline_job_files_hold_documented_keys_and_chunks_match_a_local_run() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    plates(d);
    for (frames, command) in [
        (
            "1,2,5",
            &["over", "fg.####.exr", "bg.####.exr", "-o", "c.####.exr"][..],
        ),
        (
            "1-7",
            &["over", "fg.####.exr", "bg.####.exr", "-o", "./bg.####.exr"],
        ),
        ("1-7", &["stitch", "a.exr", "-o", "c.exr"]),
    ] {
        let out = farm_in(
            d,
            &[],
            &["deadline", "--frames", frames, "-o", "bad.job"],
            command,
        );
        assert_eq!(out.status.code(), Some(2), "{command:?}: {}", stderr(&out));
        assert!(!d.join("bad.job").exists() && !d.join("bad.plugin.job").exists());
    }
    let (info, plugin) = deadline_over(
        d,
        &[("EXRCOMP_TEST_SETTING", "on")],
        &[
            "--threads",
            "1",
            "--frames",
            "1-7",
            "--chunk",
            "3",
            "-o",
            "jobs/comp.job",
        ],
        "dl out/c.%04d.exr",
    );
    let get = |pairs: &[(String, String)], key: &str| {
        pairs
            .iter()
            .find(|(k, _)| k == key)
            .map(|(_, v)| v.clone())
            .unwrap_or_else(|| panic!("no {key} in {pairs:?}"))
    };
    for (key, value) in [
        ("Plugin", "CommandLine".to_string()),
        ("Name", "exrcomp over".to_string()),
        ("Frames", "1-7".to_string()),
        ("ChunkSize", "3".to_string()),
        ("OutputDirectory0", s(&d.join("dl out")).to_string()),
        ("OutputFilename0", "c.####.exr".to_string()),
        ("ExtraInfoKeyValue0", "exrcomp.threads=1".to_string()),
    ] {
        assert_eq!(get(&info, key), value, "{key}");
    }
    assert!(get(&info, "ExtraInfoKeyValue1").starts_with("exrcomp.memory_mib="));
    assert!(
        info.iter()
            .any(|(k, v)| k.starts_with("EnvironmentKeyValue") && v == "EXRCOMP_TEST_SETTING=on"),
        "{info:?}"
    );
    assert!(get(&info, "Comment").contains("--threads 1"));
    let arguments = get(&plugin, "Arguments");
    assert!(
        arguments.ends_with("--frames <STARTFRAME>-<ENDFRAME>"),
        "{arguments}"
    );
    assert_eq!(arguments.matches("--resume").count(), 1, "{arguments}");
    // The plugin's stdout handler (`.*Progress: (\d+)%.*`) sees a task's
    // output only when it runs it in the worker's shell.
    assert_eq!(get(&plugin, "ShellExecute"), "True");
    // Deadline's chunks of 1-7 by 3, each run with its tokens replaced, as
    // the plugin runs it: `SHELL -c 'ARGUMENTS'`.
    for (start, end) in [(1, 3), (4, 6), (7, 7)] {
        let line = arguments
            .replace("<STARTFRAME>", &start.to_string())
            .replace("<ENDFRAME>", &end.to_string())
            .replace("<QUOTE>", "\"");
        let out = Command::new("sh").arg("-c").arg(&line).output().unwrap();
        assert!(out.status.success(), "{line}: {}", stderr(&out));
        let progress = stdout(&out);
        assert!(
            progress.lines().any(|l| l == "Progress: 100%"),
            "{line}: no progress for the plugin's handler in\n{progress}"
        );
    }
    local_over(d);
    for frame in 1..=7 {
        assert_eq!(
            std::fs::read(d.join(format!("dl out/c.{frame:04}.exr"))).unwrap(),
            std::fs::read(d.join(format!("local/comp.{frame:04}.exr"))).unwrap(),
            "frame {frame}"
        );
    }
    // A stepped range: Deadline's own `x` syntax, each chunk's frames stepped.
    let (info, plugin) = deadline_over(
        d,
        &[],
        &["--frames", "1-7:2", "--chunk", "2", "-o", "step.job"],
        "step/c.####.exr",
    );
    assert_eq!(get(&info, "Frames"), "1-7x2");
    assert!(get(&plugin, "Arguments").ends_with("--frames <STARTFRAME>-<ENDFRAME>:2"));
}

/// Frames 1-12 of small fg and bg plates in `d`.
fn twelve_plates(d: &Path) {
    for kind in ["fg", "bg"] {
        generate(
            &d.join(format!("{kind}.####.exr")),
            kind,
            (32, 16),
            &["--frames", "1-12"],
        );
    }
}

/// The frames a run's per-frame lines (standard output, not a terminal)
/// say were written.
fn written_frames(stdout: &[u8]) -> Vec<i64> {
    String::from_utf8_lossy(stdout)
        .lines()
        .filter_map(|line| line.strip_prefix("frame "))
        .filter(|rest| rest.contains(" written: "))
        .map(|rest| rest.split(' ').next().unwrap().parse().unwrap())
        .collect()
}

/// Cuebot before 1.0 sets #FRAME_END# to the chunk's first frame + chunk -
/// 1 whatever the step (1.0 and later: the chunk's last frame). Either way
/// each task runs only its chunk, cut by exrcomp from its first frame:
/// every frame is written once, every task exits 0.
#[test]
fn opencue_chunks_render_every_frame_once_on_any_cuebot() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    twelve_plates(d);
    for (frames, step, chunk) in [("1-12x2", 2, 2), ("1-12", 1, 5)] {
        for old_cuebot in [true, false] {
            let out = format!("o{step}{chunk}{old_cuebot}/c.####.exr");
            let made = farm_in(
                d,
                &[],
                &[
                    "opencue",
                    "--threads",
                    "1",
                    "--frames",
                    frames,
                    "--chunk",
                    &chunk.to_string(),
                    "-o",
                    "cue.json",
                ],
                &["over", "fg.####.exr", "bg.####.exr", "-o", &out],
            );
            assert!(made.status.success(), "{}", stderr(&made));
            let outline: serde_json::Value =
                serde_json::from_slice(&std::fs::read(d.join("cue.json")).unwrap()).unwrap();
            let cmd = outline["layers"][0]["command"].as_str().unwrap();
            let all: Vec<i64> = (1..=12).step_by(step).collect();
            let mut written = Vec::new();
            for frames in all.chunks(chunk) {
                let start = frames[0];
                let end = match old_cuebot {
                    true => start + chunk as i64 - 1,
                    false => *frames.last().unwrap(),
                };
                let line = cmd
                    .replace("#FRAME_START#", &start.to_string())
                    .replace("#FRAME_END#", &end.to_string());
                let task = Command::new("sh")
                    .args(["-c", &line])
                    .current_dir(d)
                    .output()
                    .unwrap();
                assert!(task.status.success(), "{line}: {}", stderr(&task));
                written.extend(written_frames(&task.stdout));
            }
            written.sort();
            assert_eq!(
                written, all,
                "{frames} in chunks of {chunk}, old: {old_cuebot}"
            );
        }
    }
}

/// Submitted from inside a symlinked show folder with `-o ../renders/...`:
/// the job names the paths as the artist does (the link, no `..`), so a
/// rule mapping the link's path moves the whole job, to a worker that has
/// neither the link nor its target at the submitter's paths.
#[test]
fn paths_are_logical_and_normalised_so_mapping_rules_match_them() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let show = d.join("store/show");
    std::fs::create_dir_all(show.join("plates")).unwrap();
    plates(&show.join("plates"));
    let link = d.join("link");
    std::os::unix::fs::symlink(&show, &link).unwrap();
    let made = exrcomp()
        .args([
            "farm", "openjd", "--frames", "1-7", "--chunk", "4", "-o", "job.yaml", "--",
        ])
        .args([
            "over",
            "fg.####.exr",
            "bg.####.exr",
            "-o",
            "../renders/c.####.exr",
        ])
        .current_dir(link.join("plates"))
        .env("PWD", link.join("plates"))
        .output()
        .unwrap();
    assert!(made.status.success(), "{}", stderr(&made));
    let values: serde_json::Value =
        serde_json::from_slice(&std::fs::read(show.join("plates/job.params.json")).unwrap())
            .unwrap();
    assert_eq!(
        values["Output"],
        s(&link.join("renders/c.####.exr")),
        "{values}"
    );
    assert_eq!(values["Input1"], s(&link.join("plates/fg.####.exr")));
    let Some(openjd_cli) = peer("openjd") else {
        return;
    };
    // The worker mounts the show elsewhere: nothing at the submitter's
    // paths, the link's or its target's.
    std::fs::rename(d.join("store"), d.join("mnt")).unwrap();
    std::fs::remove_file(&link).unwrap();
    let worker = d.join("mnt/show");
    let rules = serde_json::json!({
        "version": "pathmapping-1.0",
        "path_mapping_rules": [{
            "source_path_format": "POSIX",
            "source_path": s(&link),
            "destination_path": s(&worker),
        }],
    });
    openjd(
        &openjd_cli,
        &[
            "run",
            "job.yaml",
            "--step",
            "exrcomp",
            "--path-mapping-rules",
            &rules.to_string(),
        ],
        &worker.join("plates"),
    );
    assert!(!link.exists() && !d.join("store").exists());
    local_over(&worker.join("plates"));
    for frame in 1..=7 {
        assert_eq!(
            std::fs::read(worker.join(format!("renders/c.{frame:04}.exr"))).unwrap(),
            std::fs::read(worker.join(format!("plates/local/comp.{frame:04}.exr"))).unwrap(),
            "frame {frame}"
        );
    }
}

/// A colour config of the same names as the built-in one's and other
/// maths (none): what a worker's own `$OCIO` may be.
const OTHER_CONFIG: &str = "ocio_profile_version: 2\n\
roles:\n  default: ACEScg\n  scene_linear: ACEScg\n\
file_rules:\n  - !<Rule> {name: Default, colorspace: default}\n\
displays:\n  sRGB:\n    - !<View> {name: Raw, colorspace: ACEScg}\n\
colorspaces:\n  - !<ColorSpace>\n    name: ACES2065-1\n  - !<ColorSpace>\n    name: ACEScg\n";

/// The submitter's colour config travels with the job: a worker whose own
/// `$OCIO` has the same names and other maths writes the submitter's pixels.
#[test]
fn a_worker_with_another_ocio_writes_the_submitters_pixels() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    plates(d);
    std::fs::write(d.join("other.ocio"), OTHER_CONFIG).unwrap();
    let convert = [
        "colorconvert",
        "fg.####.exr",
        "--from",
        "ACES2065-1",
        "--to",
        "ACEScg",
    ];
    let made = exrcomp()
        .args(["farm", "openjd", "--frames", "1-2", "-o", "job.yaml", "--"])
        .args(convert)
        .args(["-o", "farm/c.####.exr"])
        .env_remove("OCIO")
        .current_dir(d)
        .output()
        .unwrap();
    assert!(made.status.success(), "{}", stderr(&made));
    let template = read_template(&d.join("job.yaml"));
    assert_eq!(
        variables(&template)["OCIO"],
        "ocio://cg-config-latest",
        "{template}"
    );
    let local = exrcomp()
        .args(convert)
        .args(["-o", "local/c.####.exr", "--frames", "1-2"])
        .env_remove("OCIO")
        .current_dir(d)
        .output()
        .unwrap();
    assert!(local.status.success(), "{}", stderr(&local));
    let Some(openjd_cli) = peer("openjd") else {
        return;
    };
    let values = format!("file://{}", s(&values(&d.join("job.yaml"))));
    let run = Command::new(openjd_cli)
        .args(["run", "job.yaml", "--step", "exrcomp", "-p", &values])
        .env("OCIO", d.join("other.ocio"))
        .current_dir(d)
        .output()
        .unwrap();
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stdout)
    );
    for frame in 1..=2 {
        assert_eq!(
            std::fs::read(d.join(format!("farm/c.{frame:04}.exr"))).unwrap(),
            std::fs::read(d.join(format!("local/c.{frame:04}.exr"))).unwrap(),
            "frame {frame}"
        );
    }
}

/// A farm task's threads are bounded by a farm worker's cores, not the
/// submitter's; a local run stays held to this machine's.
#[test]
fn farm_threads_are_a_workers_not_the_submitters() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    plates(d);
    let over = ["over", "fg.####.exr", "bg.####.exr", "-o", "c.####.exr"];
    let made = farm_in(
        d,
        &[],
        &[
            "openjd",
            "--threads",
            "256",
            "--frames",
            "1-2",
            "-o",
            "j.yaml",
        ],
        &over,
    );
    assert!(made.status.success(), "{}", stderr(&made));
    let template = read_template(&d.join("j.yaml"));
    assert_eq!(amount(&template, "amount.worker.vcpu"), 256, "{template}");
    let cores = std::thread::available_parallelism().unwrap().get();
    if cores * 8 < 256 {
        let local = exrcomp()
            .args(["--threads", "256"])
            .args(over)
            .current_dir(d)
            .output()
            .unwrap();
        assert_eq!(local.status.code(), Some(2), "{}", stderr(&local));
        assert!(stderr(&local).contains("per core"), "{}", stderr(&local));
    }
    let too_many = farm_in(
        d,
        &[],
        &[
            "openjd",
            "--threads",
            "5000",
            "--frames",
            "1-2",
            "-o",
            "k.yaml",
        ],
        &over,
    );
    assert_eq!(too_many.status.code(), Some(2));
    assert!(!d.join("k.yaml").exists());
}

/// Options of one farm are refused by the others (exit 2, nothing written).
#[test]
fn an_option_of_another_farm_is_a_usage_error() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    plates(d);
    let over = ["over", "fg.####.exr", "bg.####.exr", "-o", "c.####.exr"];
    for args in [
        &[
            "deadline",
            "--task-chunking",
            "--frames",
            "1-2",
            "-o",
            "x.job",
        ][..],
        &[
            "deadline",
            "--service",
            "comp",
            "--frames",
            "1-2",
            "-o",
            "x.job",
        ],
        &[
            "opencue",
            "--target-runtime",
            "60",
            "--frames",
            "1-2",
            "-o",
            "x.job",
        ],
        &["opencue", "--bundle", "b", "--frames", "1-2", "-o", "x.job"],
        &[
            "openjd",
            "--service",
            "comp",
            "--frames",
            "1-2",
            "-o",
            "x.job",
        ],
    ] {
        let out = farm_in(d, &[], args, &over);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {}", stderr(&out));
        assert!(
            !d.join("x.job").exists() && !d.join("b").exists(),
            "{args:?}"
        );
    }
}

/// Off a terminal a run says what became of each frame, --quiet or not;
/// OpenJD tasks add openjd_progress / openjd_status lines and Deadline
/// tasks `Progress: N%`.
#[test]
fn tasks_print_a_line_per_frame_and_their_farms_progress() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    plates(d);
    let over = ["over", "fg.####.exr", "bg.####.exr", "-o", "c.####.exr"];
    let first = exrcomp()
        .args(over)
        .args(["--frames", "1-2", "-q"])
        .current_dir(d)
        .output()
        .unwrap();
    assert!(first.status.success(), "{}", stderr(&first));
    assert_eq!(written_frames(&first.stdout), [1, 2], "{}", stdout(&first));
    let again = exrcomp()
        .args(over)
        .args(["--frames", "1-3", "--resume", "--progress", "deadline"])
        .current_dir(d)
        .output()
        .unwrap();
    let text = stdout(&again);
    for line in [
        // The output as the command names it.
        "frame 1 kept (--resume): c.0001.exr".to_string(),
        "frame 3 written: c.0003.exr".to_string(),
        "Progress: 33%".to_string(),
        "Progress: 100%".to_string(),
    ] {
        assert!(text.lines().any(|l| l == line), "{line} not in\n{text}");
    }
    // A deadline task runs with --progress deadline, an OpenJD one with
    // --progress openjd; an OpenCue one with the default lines.
    let (_, plugin) = deadline_over(d, &[], &["--frames", "1-2", "-o", "p.job"], "dl/c.####.exr");
    let arguments = &plugin.iter().find(|(k, _)| k == "Arguments").unwrap().1;
    assert!(arguments.contains("--progress deadline"), "{arguments}");
    let made = farm_in(
        d,
        &[],
        &[
            "openjd",
            "--name",
            "shot 10 comp",
            "--frames",
            "1-2",
            "-o",
            "j.yaml",
        ],
        &["over", "fg.####.exr", "bg.####.exr", "-o", "oj/c.####.exr"],
    );
    assert!(made.status.success(), "{}", stderr(&made));
    let template = read_template(&d.join("j.yaml"));
    let step = &template["steps"][0];
    assert_eq!(template["name"], "shot 10 comp", "{template}");
    assert_eq!(count(&task_args(&template), &["--progress", "openjd"]), 1);
    assert_eq!(
        step["hostRequirements"]["attributes"],
        json!([{"name": "attr.worker.os.family", "anyOf": ["linux"]}]),
        "{template}"
    );
    assert_eq!(
        step["script"]["actions"]["onRun"]["cancelation"],
        json!({"mode": "NOTIFY_THEN_TERMINATE", "notifyPeriodInSeconds": 120}),
        "{template}"
    );
    let Some(openjd_cli) = peer("openjd") else {
        return;
    };
    openjd(&openjd_cli, &["check", "j.yaml"], d);
    let log = openjd(&openjd_cli, &["run", "j.yaml", "--step", "exrcomp"], d);
    for part in [
        "frame 2 written: ",
        "openjd_progress: 100.0",
        "openjd_status: 2 of 2 frames done",
    ] {
        assert!(log.contains(part), "{part} not in\n{log}");
    }
}

/// `farm openjd --bundle DIR`: a job bundle as `deadline bundle submit`
/// reads it, `template.json` (which `openjd check` accepts) and
/// `parameter_values.json` (`parameterValues`, a name and a value each);
/// run with those values it writes the frames.
#[test]
fn openjd_bundles_hold_a_template_and_its_parameter_values() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    plates(d);
    let made = farm_in(
        d,
        &[],
        &["openjd", "--frames", "1-3", "--bundle", "bundle"],
        &["over", "fg.####.exr", "bg.####.exr", "-o", "b/c.####.exr"],
    );
    assert!(made.status.success(), "{}", stderr(&made));
    let template = read_template(&d.join("bundle/template.json"));
    let text = std::fs::read_to_string(d.join("bundle/parameter_values.json")).unwrap();
    let values: Value = serde_json::from_str(&text).unwrap();
    let values = values["parameterValues"].as_array().unwrap();
    let parameters = template["parameterDefinitions"].as_array().unwrap();
    for name in ["Exrcomp", "Input1", "Input2", "Output"] {
        let value = values.iter().find(|v| v["name"] == name);
        assert!(
            value.is_some_and(|v| v["value"].as_str().unwrap().starts_with('/')),
            "{text}"
        );
        assert!(parameters.iter().any(|p| p["name"] == name), "{template}");
    }
    let Some(openjd_cli) = peer("openjd") else {
        return;
    };
    openjd(&openjd_cli, &["check", "bundle/template.json"], d);
    // The bundle's values as `openjd run` takes them ({NAME: VALUE}), read
    // by Python's parser, not by hand.
    let python = openjd_cli.with_file_name("python3");
    let script = "import sys, json\n\
        values = json.load(open(sys.argv[1]))['parameterValues']\n\
        print(json.dumps({v['name']: v['value'] for v in values}))\n";
    let read = Command::new(python)
        .args(["-c", script, "bundle/parameter_values.json"])
        .current_dir(d)
        .output()
        .unwrap();
    assert!(read.status.success(), "{}", stderr(&read));
    std::fs::write(d.join("values.json"), &read.stdout).unwrap();
    let run = Command::new(&openjd_cli)
        .args(["run", "bundle/template.json", "--step", "exrcomp", "-p"])
        .arg(format!("file://{}", s(&d.join("values.json"))))
        .current_dir(d)
        .output()
        .unwrap();
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stdout)
    );
    assert!((1..=3).all(|f| d.join(format!("b/c.{f:04}.exr")).exists()));
}

fn stdout(out: &std::process::Output) -> String {
    String::from_utf8_lossy(&out.stdout).into_owned()
}

/// `--name` is the job's name as the user gives it, in a template OpenJD
/// accepts: one holding `{{` goes through a job parameter (the name is a
/// format string); a name OpenJD refuses (empty, over 128 characters, a
/// control character) is a usage error, nothing written, not a template
/// `openjd check` refuses after exit 0.
#[test]
fn openjd_job_names_are_the_users_or_refused() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    plates(d);
    let over = ["over", "fg.####.exr", "bg.####.exr", "-o", "c.####.exr"];
    let openjd_cli = peer("openjd");
    let longest = "x".repeat(128);
    for (i, name) in ["shot {{10}} comp", "über", &longest].iter().enumerate() {
        let job = format!("ok{i}.yaml");
        let made = farm_in(
            d,
            &[],
            &["openjd", "--frames", "1-7", "--name", name, "-o", &job],
            &over,
        );
        assert!(made.status.success(), "{name}: {}", stderr(&made));
        if let Some(openjd_cli) = &openjd_cli {
            openjd(openjd_cli, &["check", &job], d);
            let log = openjd(openjd_cli, &["run", &job, "--step", "exrcomp"], d);
            assert!(log.contains("frame 7 "), "{name}: {log}");
        }
    }
    let too_long = "x".repeat(129);
    for (i, name) in ["", &too_long, "tab\there", "two\nlines"]
        .iter()
        .enumerate()
    {
        let job = d.join(format!("bad{i}.yaml"));
        let made = farm_in(
            d,
            &[],
            &["openjd", "--frames", "1-7", "--name", name, "-o", s(&job)],
            &over,
        );
        assert_eq!(made.status.code(), Some(2), "{name:?}: {}", stderr(&made));
        let said = stderr(&made);
        assert!(
            said.contains("--name") && said.lines().count() == 1,
            "{said}"
        );
        assert!(!job.exists(), "{name:?}: a template was written");
    }
}

/// A command that does not parse is refused in one line that says why,
/// the arguments missing included (clap lists them after a colon).
#[test]
fn a_command_that_does_not_parse_is_refused_saying_what_is_missing() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    plates(d);
    let defocus = [
        "defocus",
        "bg.####.exr",
        "--focus",
        "10",
        "-o",
        "c.####.exr",
    ];
    let made = farm_in(
        d,
        &[],
        &["openjd", "--frames", "1-2", "-o", "j.yaml"],
        &defocus,
    );
    assert_eq!(made.status.code(), Some(2), "{}", stderr(&made));
    let said = stderr(&made);
    assert_eq!(said.lines().count(), 1, "{said}");
    assert!(
        said.contains("--scale") && said.contains("--max-radius"),
        "{said}"
    );
    assert!(!d.join("j.yaml").exists());
}
