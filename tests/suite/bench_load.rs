//! `exrcomp bench` on a busy machine: a baseline taken before the load is
//! judged by the job's ratio to its floor and its CPU per frame, so the load
//! is no regression and a planted slowdown is one, with and without it; and
//! `--against` another build, paired run by run.

use crate::common::*;
use std::path::Path;
use std::sync::atomic::{AtomicBool, Ordering};

/// `f` while every core is busy: as many threads as cores spinning in this
/// process, stopped when `f` returns.
fn under_load<T>(f: impl FnOnce() -> T) -> T {
    let stop = AtomicBool::new(false);
    let cores = std::thread::available_parallelism().map_or(2, |n| n.get());
    std::thread::scope(|scope| {
        for _ in 0..cores {
            scope.spawn(|| {
                let mut x = 0u64;
                while !stop.load(Ordering::Relaxed) {
                    x = std::hint::black_box(x.wrapping_mul(31).wrapping_add(7));
                }
            });
        }
        let out = f();
        stop.store(true, Ordering::Relaxed);
        out
    })
}

/// `exrcomp bench ARGS -- blur ...` in `d`, with `EXRCOMP_TEST_WORK=work`
/// (a planted slowdown, debug builds only) when given.
fn bench_blur(d: &Path, args: &[&str], work: Option<&str>) -> std::process::Output {
    let blur = [
        "--",
        "blur",
        "bg.####.exr",
        "--radius",
        "4",
        "-o",
        "b.####.exr",
    ];
    let mut command = exrcomp();
    command.arg("bench").args(args).args(blur).current_dir(d);
    if let Some(work) = work {
        command.env("EXRCOMP_TEST_WORK", work);
    }
    command.output().unwrap()
}

/// Plates big enough that a run is mostly work, not the process starting
/// (at 512x512 a busy machine added 25% to the CPU per frame, at 1024x512
/// 4%: specs/bench.md).
fn plates(d: &Path) {
    generate(
        &d.join("bg.####.exr"),
        "bg",
        (1024, 512),
        &["--frames", "1-4"],
    );
}

#[test]
fn a_busy_machine_is_no_regression_and_a_slower_build_is_one_even_so() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    plates(d);
    let runs = ["--runs", "7"];
    let base = bench_blur(d, &[&runs[..], &["--json", "base.json"]].concat(), None);
    assert!(base.status.success(), "{}", stderr(&base));
    let against = [
        &runs[..],
        &["--baseline", "base.json", "--json", "now.json"],
    ]
    .concat();
    let loaded = under_load(|| bench_blur(d, &against, None));
    let record = |name: &str| -> serde_json::Value {
        serde_json::from_str(&std::fs::read_to_string(d.join(name)).unwrap()).unwrap()
    };
    let wall = |name: &str| {
        record(name)["jobs"][0]["wall_seconds"]["median"]
            .as_f64()
            .unwrap()
    };
    eprintln!(
        "wall: idle {:.3} s, loaded {:.3} s",
        wall("base.json"),
        wall("now.json")
    );
    eprintln!("{}", stderr(&loaded));
    assert!(loaded.status.success(), "{}", stderr(&loaded));
    assert!(
        stderr(&loaded).contains("floor ratio: "),
        "{}",
        stderr(&loaded)
    );
    // The floor is in the record: a transcode of the same plates, run for run.
    let floor = &record("now.json")["jobs"][0]["floor"];
    assert_eq!(floor["command"][0], "transcode");
    assert_eq!(floor["ratio"]["runs"].as_array().unwrap().len(), 7);
    // The blur (not the floor) 15% slower, busy: caught idle and loaded,
    // beyond a 10% tolerance.
    for load in [false, true] {
        let run = || bench_blur(d, &against, Some("blur:0.15"));
        let slow = if load { under_load(run) } else { run() };
        assert_eq!(
            slow.status.code(),
            Some(1),
            "loaded {load}: {}",
            stderr(&slow)
        );
        assert!(stderr(&slow).contains("REGRESSION"), "{}", stderr(&slow));
    }
}

/// A script that runs exrcomp with `EXRCOMP_TEST_WORK` as given (or unset):
/// another build, for `--against`.
fn other_build(d: &Path, name: &str, work: Option<&str>) -> String {
    use std::os::unix::fs::PermissionsExt;
    let exe = env!("CARGO_BIN_EXE_exrcomp");
    let set = match work {
        Some(work) => format!("export EXRCOMP_TEST_WORK={work}"),
        None => "unset EXRCOMP_TEST_WORK".into(),
    };
    let script = d.join(name);
    std::fs::write(&script, format!("#!/bin/sh\n{set}\nexec '{exe}' \"$@\"\n")).unwrap();
    std::fs::set_permissions(&script, std::fs::Permissions::from_mode(0o755)).unwrap();
    script.to_string_lossy().into_owned()
}

#[test]
fn against_another_build_the_pairs_say_slower_or_no_difference() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    plates(d);
    let same = other_build(d, "same.sh", None);
    let runs = ["--runs", "12", "--warmup", "1"];
    // The same build twice, on a busy machine: no difference, twice over.
    for trial in 0..2 {
        let args = [&runs[..], &["--against", &same, "--json", "ab.json"]].concat();
        let out = under_load(|| bench_blur(d, &args, None));
        assert!(out.status.success(), "trial {trial}: {}", stderr(&out));
        assert!(
            stderr(&out).contains("no difference detected at 12 runs"),
            "{}",
            stderr(&out)
        );
        let record: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(d.join("ab.json")).unwrap()).unwrap();
        let against = &record["jobs"][0]["against"];
        assert_eq!(against["verdict"], "no difference detected");
        assert_eq!(against["ratio"]["runs"].as_array().unwrap().len(), 12);
        // The sign test's interval at 12 pairs: the 2nd to the 11th ratio, 99.4%.
        let confidence = against["ratio"]["confidence"].as_f64().unwrap();
        assert!(
            (confidence - (1.0 - 26.0 / 4096.0)).abs() < 1e-9,
            "{confidence}"
        );
    }
    // This build's blur half as slow again as the other's: slower, exit 1.
    // (The wall time of a run here varies by tens of percent: 12 pairs see
    // 50% surely, 15% not always.)
    let unplanted = other_build(d, "unplanted.sh", None);
    let args = [&runs[..], &["--against", &unplanted]].concat();
    let out = bench_blur(d, &args, Some("blur:0.5"));
    assert_eq!(out.status.code(), Some(1), "{}", stderr(&out));
    assert!(
        stderr(&out).contains("slower at 12 runs"),
        "{}",
        stderr(&out)
    );
    // And the other way round: faster.
    let planted = other_build(d, "planted.sh", Some("blur:0.5"));
    let args = [&runs[..], &["--against", &planted]].concat();
    let out = bench_blur(d, &args, None);
    assert!(out.status.success(), "{}", stderr(&out));
    assert!(
        stderr(&out).contains("faster at 12 runs"),
        "{}",
        stderr(&out)
    );
}
