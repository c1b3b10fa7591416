//! `exrcomp bench`: records, the standard workload and the chart (the
//! verdicts, timed, are in tests/timing/).

use crate::common::*;
use std::path::Path;

/// `exrcomp bench ARGS` in `d`; each timed run `delay` seconds slower.
fn bench(d: &Path, args: &[&str], delay: Option<&str>) -> std::process::Output {
    let mut command = exrcomp();
    command.arg("bench").args(args).current_dir(d);
    if let Some(f) = delay {
        command.env("EXRCOMP_TEST_DELAY", f);
    }
    command.output().unwrap()
}

fn record(path: &Path) -> serde_json::Value {
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

#[test]
fn a_record_holds_the_runs_the_machine_and_leaves_no_output() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    generate(&d.join("bg.####.exr"), "bg", (96, 64), &["--frames", "1-3"]);
    let out = bench(
        d,
        &[
            "--runs",
            "3",
            "--json",
            "r.json",
            "--report",
            "r.svg",
            "--",
            "transcode",
            "bg.####.exr",
            "-o",
            "t.####.exr",
        ],
        None,
    );
    assert!(out.status.success(), "{}", stderr(&out));
    let r = record(&d.join("r.json"));
    assert_eq!(r["schema"], "exrcomp-bench-1");
    assert!(r["machine"]["cores"].as_u64().unwrap() >= 1);
    let job = &r["jobs"][0];
    assert_eq!(
        (job["frames"].as_u64(), job["pixels"].as_u64()),
        (Some(3), Some(3 * 96 * 64))
    );
    for figure in ["wall_seconds", "cpu_seconds", "peak_rss_bytes"] {
        let runs = job[figure]["runs"].as_array().unwrap();
        assert_eq!(runs.len(), 3, "{figure}");
        let (min, median, max) = (
            job[figure]["min"].as_f64().unwrap(),
            job[figure]["median"].as_f64().unwrap(),
            job[figure]["max"].as_f64().unwrap(),
        );
        assert!(
            min > 0.0 && min <= median && median <= max,
            "{figure}: {}",
            job[figure]
        );
    }
    // It read the inputs and wrote the outputs, then removed them.
    let input: u64 = (1..=3)
        .map(|f| {
            std::fs::metadata(d.join(format!("bg.{f:04}.exr")))
                .unwrap()
                .len()
        })
        .sum();
    let read = job["read_bytes_per_second"].as_f64().unwrap()
        * job["wall_seconds"]["median"].as_f64().unwrap();
    assert!(read >= input as f64, "read {read} bytes of {input}");
    // Each run wrote the bytes the same transcode writes.
    let copy = d.join("copy");
    ok(&[
        "transcode",
        s(&d.join("bg.####.exr")),
        "-o",
        s(&copy.join("t.####.exr")),
        "-q",
    ]);
    let written: u64 = std::fs::read_dir(&copy)
        .unwrap()
        .map(|e| e.unwrap().metadata().unwrap().len())
        .sum();
    let outputs = job["output_bytes"]["runs"].as_array().unwrap();
    assert!(
        outputs.iter().all(|b| b.as_f64() == Some(written as f64)),
        "{outputs:?} vs {written}"
    );
    std::fs::remove_dir_all(&copy).unwrap();
    assert!(!d.join("t.0001.exr").exists());
    let names: Vec<_> = std::fs::read_dir(d)
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(names.len(), 5, "{names:?}");
    // The chart is well-formed SVG with a dot a run (python3's XML parser).
    if let Some(python) = peer("python3") {
        let check = "import sys, xml.etree.ElementTree as E; t = E.parse(sys.argv[1]); \
                     print(sum(1 for e in t.iter() if e.tag.endswith('circle')))";
        let out =
            succeed(std::process::Command::new(python).args(["-c", check, s(&d.join("r.svg"))]));
        assert_eq!(String::from_utf8_lossy(&out.stdout).trim(), "3");
    }
    // The chart as PNG, against the first record as baseline: decoded by
    // Python, a blue dot at each run's wall time on this record's line and
    // a grey one at each of the baseline's, on the axis the chart spec
    // draws (150 px + 560 px x seconds / (1.1 x the slowest run)).
    // (Any slowdown up to 11x is within the tolerance: this checks the
    // chart, not the machine's noise; the verdict's rule has unit tests.)
    let args = [
        "--runs",
        "2",
        "--baseline",
        "r.json",
        "--tolerance",
        "1000",
        "--json",
        "r2.json",
        "--report",
        "r.png",
    ];
    let transcode = ["--", "transcode", "bg.####.exr", "-o", "t.####.exr"];
    let out = bench(d, &[&args[..], &transcode].concat(), None);
    assert!(out.status.success(), "{}", stderr(&out));
    if let Some((w, h, pixels)) = decode_png(&d.join("r.png")) {
        assert_eq!((w, h), (800, 116));
        let runs = |r: &serde_json::Value| -> Vec<f64> {
            let runs = r["jobs"][0]["wall_seconds"]["runs"].as_array().unwrap();
            runs.iter().map(|v| v.as_f64().unwrap()).collect()
        };
        let (before, now) = (runs(&r), runs(&record(&d.join("r2.json"))));
        let most = before.iter().chain(&now).fold(0f64, |m, &v| m.max(v)) * 1.1;
        let at = |v: f64, y: usize| pixels[y * w + (150.0 + 560.0 * v / most) as usize];
        for v in now {
            assert_eq!(at(v, 70), [0x1f, 0x6f, 0xd0], "this record's run {v}");
        }
        for v in before {
            assert_eq!(at(v, 52), [0x88; 3], "the baseline's run {v}");
        }
        let ink = pixels.iter().filter(|&&p| p == [0; 3]).count();
        assert!(ink > 100, "the title and the job's name are written");
    }
    let out = bench(d, &[&["--report", "r.jpg"][..], &transcode].concat(), None);
    assert_eq!(out.status.code(), Some(2), "{}", stderr(&out));
    // A command that writes nothing is refused at once.
    let out = bench(d, &["--", "info", "bg.0001.exr"], None);
    assert_eq!(out.status.code(), Some(2), "{}", stderr(&out));
}

/// The record never replaces a file the timed job reads (its frames, its
/// job file), and is refused before any run.
#[test]
fn a_record_never_replaces_what_the_job_reads() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    generate(&d.join("bg.####.exr"), "bg", (32, 16), &["--frames", "1-2"]);
    std::fs::write(
        d.join("shot.toml"),
        "[[node]]\nname = \"a\"\nread = \"bg.####.exr\"\n\n\
         [[node]]\nname = \"out\"\nwrite = \"c.####.exr\"\ninputs = [\"a\"]\n",
    )
    .unwrap();
    let transcode = ["transcode", "bg.####.exr", "-o", "t.####.exr"];
    // (A chart is FILE.svg or FILE.png, which no job reads.)
    for (file, job) in [
        ("bg.0002.exr", &transcode[..]),
        ("./bg.0001.exr", &transcode[..]),
        ("shot.toml", &["shot.toml"][..]),
        ("bg.0001.exr", &["shot.toml"][..]),
    ] {
        let before = std::fs::read(d.join(file)).unwrap();
        let out = bench(
            d,
            &[&["--runs", "1", "--json", file, "--"][..], job].concat(),
            None,
        );
        let message = stderr(&out);
        assert_eq!(out.status.code(), Some(2), "--json {file}: {message}");
        assert!(
            message.contains("refusing to overwrite an input"),
            "{message}"
        );
        assert!(!message.contains("runs after"), "refused before the runs");
        assert!(
            std::fs::read(d.join(file)).unwrap() == before,
            "--json {file}"
        );
    }
}

#[test]
fn the_standard_workload_times_its_jobs_on_plates_made_once() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let args = [
        "--standard",
        "--frames",
        "1",
        "--runs",
        "1",
        "--warmup",
        "0",
        "--cache",
        "cache",
        "--json",
        "s.json",
    ];
    let out = bench(d, &args, None);
    assert!(out.status.success(), "{}", stderr(&out));
    let r = record(&d.join("s.json"));
    let names: Vec<&str> = r["jobs"]
        .as_array()
        .unwrap()
        .iter()
        .map(|j| j["name"].as_str().unwrap())
        .collect();
    let mut expected = vec!["transcode", "over", "stack", "over_blur", "resize"];
    if cfg!(feature = "colour") {
        expected.push("colorconvert");
    }
    assert_eq!(names, expected);
    for job in r["jobs"].as_array().unwrap() {
        // The stack's layers are moved about: its window is their union;
        // the resize writes a quarter of the pixels.
        let least = match job["name"].as_str() {
            Some("resize") => 960 * 540,
            _ => 1920 * 1080,
        };
        assert!(job["pixels"].as_u64().unwrap() >= least, "{}", job["name"]);
    }
    let plate = d.join("cache/1920x1080-1/bg.0001.exr");
    let made = std::fs::metadata(&plate).unwrap().modified().unwrap();
    let again = bench(d, &args, None);
    assert!(again.status.success(), "{}", stderr(&again));
    assert_eq!(
        std::fs::metadata(&plate).unwrap().modified().unwrap(),
        made,
        "plates made again"
    );
}
