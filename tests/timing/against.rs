//! `exrcomp bench --against OTHER`: two builds paired run by run. The same
//! build twice is "no difference detected" in 10 trials of 10, idle and
//! under load; a build 50% slower is slower, and the other way round faster.

use crate::common::*;
use crate::{alone, bench_blur, plates, under_load};
use std::path::Path;

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
fn the_same_build_twice_is_no_difference_in_ten_trials_of_ten() {
    let _alone = alone();
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    // Small plates: the trials' verdicts, not the work, are tested.
    plates(d, (256, 256));
    let same = other_build(d, "same.sh", None);
    let args = [
        "--runs",
        "10",
        "--warmup",
        "1",
        "--against",
        &same,
        "--json",
        "ab.json",
    ];
    let mut ratios = Vec::new();
    // Five trials idle, five with every core busy.
    for trial in 0..10 {
        let run = || bench_blur(d, &args, None);
        let out = if trial < 5 { run() } else { under_load(run) };
        assert!(out.status.success(), "trial {trial}: {}", stderr(&out));
        let record: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(d.join("ab.json")).unwrap()).unwrap();
        let against = &record["jobs"][0]["against"];
        assert_eq!(
            against["verdict"],
            "no difference detected",
            "trial {trial}: {}",
            stderr(&out)
        );
        assert!(
            stderr(&out).contains("no difference detected at 10 runs"),
            "{}",
            stderr(&out)
        );
        assert_eq!(against["ratio"]["runs"].as_array().unwrap().len(), 10);
        // The sign test's interval at 10 pairs: the range, 1 - 2/1024.
        let confidence = against["ratio"]["confidence"].as_f64().unwrap();
        assert!(
            (confidence - (1.0 - 2.0 / 1024.0)).abs() < 1e-9,
            "{confidence}"
        );
        ratios.push(against["ratio"]["median"].as_f64().unwrap());
    }
    eprintln!("the trials' median ratios: {ratios:.3?}");
}

#[test]
fn a_slower_build_is_slower_and_the_other_way_round_faster() {
    let _alone = alone();
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    plates(d, (512, 512));
    let runs = ["--runs", "12", "--warmup", "1"];
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
