//! Farm templates: an Open Job Description template that OpenJD's own CLI
//! accepts and runs, with chunked output byte-identical to a local run, and
//! a retried chunk that finishes what a killed one left.

mod common;
use common::*;
use std::path::Path;
use std::process::Command;

fn ok(args: &[&str]) {
    let out = run(args);
    assert!(out.status.success(), "{args:?}: {}", stderr(&out));
}

fn openjd(openjd: &Path, args: &[&str], cwd: &Path) {
    let out = Command::new(openjd)
        .args(args)
        .current_dir(cwd)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "openjd {args:?}:\n{}\n{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
}

#[test]
fn an_openjd_template_checks_runs_and_matches_a_local_run_byte_for_byte() {
    let Some(openjd_cli) = peer("openjd") else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    for (name, kind) in [("fg", "fg"), ("bg", "bg")] {
        generate(
            &d.join(format!("{name}.####.exr")),
            kind,
            (64, 48),
            &["--frames", "1-7"],
        );
    }
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
    let template = std::fs::read_to_string(d.join("job.yaml")).unwrap();
    assert!(
        template.contains(r#"range: ["1-3", "4-6", "7"]"#),
        "{template}"
    );
    openjd(&openjd_cli, &["check", "job.yaml"], d);
    openjd(&openjd_cli, &["run", "job.yaml", "--step", "exrcomp"], d);
    let p = |n: &str| d.join(n);
    ok(&[
        "over",
        s(&p("fg.####.exr")),
        s(&p("bg.####.exr")),
        "-o",
        s(&p("local/comp.####.exr")),
        "--frames",
        "1-7",
        "-q",
    ]);
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
