//! The `--json` summary says where the run's CPU time went, stage by stage
//! (src/stage_time.rs), and the figures add up to what the kernel
//! charged the process.

use crate::common::*;
use std::io::Read;
use std::process::Stdio;

const STAGES: [&str; 4] = ["decode", "compose", "encode", "write"];

/// Runs exrcomp with `args`; its standard output and the user plus system
/// CPU seconds the kernel charged it (wait4's rusage: this child's alone,
/// whatever other tests run meanwhile).
#[allow(clippy::zombie_processes)] // reaped by wait4, which `Child` does not see
fn run_with_cpu(args: &[&str]) -> (Vec<u8>, f64) {
    let mut child = exrcomp()
        .args(args)
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .expect("exrcomp runs");
    let mut stdout = Vec::new();
    child
        .stdout
        .take()
        .unwrap()
        .read_to_end(&mut stdout)
        .unwrap();
    let (mut status, pid) = (0, child.id() as libc::pid_t);
    // SAFETY: wait4 fills the status and rusage it is given; zeroed is a
    // valid rusage. The child is reaped here, not by `Child::wait`.
    let mut usage: libc::rusage = unsafe { std::mem::zeroed() };
    assert_eq!(unsafe { libc::wait4(pid, &mut status, 0, &mut usage) }, pid);
    assert!(libc::WIFEXITED(status) && libc::WEXITSTATUS(status) == 0);
    let seconds = |t: libc::timeval| t.tv_sec as f64 + t.tv_usec as f64 * 1e-6;
    (stdout, seconds(usage.ru_utime) + seconds(usage.ru_stime))
}

#[test]
fn json_summary_accounts_for_the_process_cpu_by_stage() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let frames = ["--frames", "1-3"];
    generate(&d.join("fg.####.exr"), "fg", (1024, 768), &frames);
    generate(&d.join("bg.####.exr"), "bg", (1024, 768), &frames);
    // A blur after the over, so that compose has bands of its own to run.
    let job = d.join("job.toml");
    std::fs::write(
        &job,
        format!(
            "[[node]]\nname = \"fg\"\nread = \"{}\"\n\n[[node]]\nname = \"bg\"\nread = \"{}\"\n\n\
             [[node]]\nname = \"comp\"\nop = \"over\"\ninputs = [\"fg\", \"bg\"]\n\n\
             [[node]]\nname = \"soft\"\nop = \"blur\"\nradius = 4\ninputs = [\"comp\"]\n\n\
             [[node]]\nname = \"out\"\nwrite = \"{}\"\ninputs = [\"soft\"]\n",
            s(&d.join("fg.####.exr")),
            s(&d.join("bg.####.exr")),
            s(&d.join("out/c.####.exr")),
        ),
    )
    .unwrap();
    let (stdout, process_cpu) = run_with_cpu(&["run", s(&job), "--json"]);
    let record: serde_json::Value = serde_json::from_slice(&stdout).unwrap();
    let figure = |stage: &str, key: &str| {
        record["stages"][stage][key]
            .as_f64()
            .unwrap_or_else(|| panic!("no {stage}.{key} in {record}"))
    };
    let (mut serial, mut pool) = (0.0, 0.0);
    for stage in STAGES {
        serial += figure(stage, "serial_cpu_s");
        pool += figure(stage, "pool_cpu_s");
        assert!(figure(stage, "wait_s") >= 0.0);
        assert!(figure(stage, "serial_cpu_s") > 0.0, "{stage}: {record}");
        // The writer's tasks write placed chunks (`writer::Batches`).
        assert!(figure(stage, "pool_cpu_s") > 0.0, "{stage}: {record}");
        assert!(figure(stage, "tasks") >= 1.0, "{stage}: {record}");
    }
    // What the stages do not hold: start-up, the job's set-up on the main
    // thread, the pool's scheduling.
    let stages = serial + pool;
    assert!(
        stages <= process_cpu * 1.02 + 0.01 && stages >= process_cpu * 0.75,
        "stages {stages:.3} s of a process's {process_cpu:.3} s CPU: {record}"
    );
    let reported = record["process_cpu_s"].as_f64().unwrap();
    assert!(reported <= process_cpu + 0.01 && reported >= stages * 0.98);
    let share = record["serial_share"].as_f64().unwrap();
    assert!(share > 0.0 && share < 1.0, "{share}");
    assert!(
        (share - serial / stages).abs() < 1e-9,
        "{share} {serial} {pool}"
    );
}
