//! `exrcomp bench --report FILE.html`: one page, no script, no network, whose
//! charts' points are the records' figures.

use crate::common::*;
use std::path::Path;

fn bench(d: &Path, args: &[&str], commit: Option<&str>) {
    let transcode = ["--", "transcode", "bg.####.exr", "-o", "t.####.exr"];
    let mut command = exrcomp();
    command.arg("bench").args(["--runs", "2", "--warmup", "0"]);
    command.args(args).args(transcode).current_dir(d);
    if let Some(commit) = commit {
        command.env("EXRCOMP_COMMIT", commit);
    }
    succeed(&mut command);
}

/// The figures drawn equal the record's, to a part in 10^12: serde_json
/// (without its float_roundtrip feature) may parse the record's last digit
/// one unit off what Rust's own parsing of the page's text gives.
fn assert_close(drawn: &[f64], record: &[f64]) {
    assert_eq!(drawn.len(), record.len(), "{drawn:?} vs {record:?}");
    for (a, b) in drawn.iter().zip(record) {
        assert!((a - b).abs() <= 1e-12 * b.abs(), "{drawn:?} vs {record:?}");
    }
}

fn record(path: &Path) -> serde_json::Value {
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

/// The page parsed as XML by Python: each dot's tooltip, in order.
const DOTS: &str = "import sys, json, xml.etree.ElementTree as E\n\
    page = open(sys.argv[1]).read()\n\
    root = E.fromstring(page)\n\
    print(json.dumps([c.find('title').text for c in root.iter('circle')]))";

#[test]
fn the_html_report_draws_the_records_figures_and_needs_nothing_else() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    generate(
        &d.join("bg.####.exr"),
        "bg",
        (256, 128),
        &["--frames", "1-2"],
    );
    std::fs::create_dir(d.join("history")).unwrap();
    bench(d, &["--json", "history/a.json"], Some("abc1234"));
    bench(d, &["--json", "history/b.json"], None);
    let args = [
        "--baseline",
        "history/b.json",
        "--tolerance",
        "1000",
        "--history",
        "history",
        "--json",
        "r.json",
        "--report",
        "r.html",
    ];
    bench(d, &args, None);
    let page = std::fs::read_to_string(d.join("r.html")).unwrap();
    assert!(!page.to_lowercase().contains("<script"), "no script");
    assert!(!page.contains("http"), "no reference to the network");
    assert!(page.contains("<td>job</td>"), "the job's row");
    for heading in ["Runs: wall seconds", "Stages: CPU", "Throughput over time"] {
        assert!(page.contains(heading), "{heading}");
    }
    assert!(
        page.contains("abc1234"),
        "a history point labelled by its commit"
    );
    let Some(python) = peer("python3") else {
        return;
    };
    let out = succeed(std::process::Command::new(python).args(["-c", DOTS, s(&d.join("r.html"))]));
    let titles: Vec<String> = serde_json::from_slice(&out.stdout).unwrap();
    let figures = |unit: &str| -> Vec<f64> {
        let values = titles.iter().filter_map(|t| t.strip_suffix(unit));
        values.map(|v| v.parse().unwrap()).collect()
    };
    // The runs' dots: the baseline's, then this record's wall seconds.
    let runs = |r: &serde_json::Value| -> Vec<f64> {
        let runs = r["jobs"][0]["wall_seconds"]["runs"].as_array().unwrap();
        runs.iter().map(|v| v.as_f64().unwrap()).collect()
    };
    let (before, now) = (record(&d.join("history/b.json")), record(&d.join("r.json")));
    assert_close(&figures(" s"), &[runs(&before), runs(&now)].concat());
    // Throughput over time: a dot per record, oldest first, this one last.
    let a = record(&d.join("history/a.json"));
    let rates: Vec<f64> = [&a, &before, &now]
        .iter()
        .map(|r| r["jobs"][0]["megapixels_per_second"].as_f64().unwrap())
        .collect();
    assert_close(&figures(" MP/s"), &rates);
    // The stage bars: each stage's CPU of the record's medians.
    let stages = &now["jobs"][0]["stages"];
    for stage in ["decode", "compose", "encode", "write"] {
        let cpu = stages[stage]["serial_cpu_s"].as_f64().unwrap()
            + stages[stage]["pool_cpu_s"].as_f64().unwrap();
        let title = format!("<title>{stage}: ");
        let drawn = page
            .split(&title)
            .nth(1)
            .and_then(|t| t.split(" s CPU").next());
        let drawn: f64 = drawn.unwrap_or_else(|| panic!("{stage}")).parse().unwrap();
        assert!(
            (drawn - cpu).abs() <= 1e-9 * cpu.max(1.0),
            "{stage}: {drawn} vs {cpu}"
        );
    }
    // Rendered where Chromium is installed. The page has no script (checked
    // above), so it renders as with JavaScript off; Chromium 156's
    // `--disable-javascript` is ignored and `--blink-settings=
    // scriptEnabled=false` makes headless write no screenshot.
    if let Some(chromium) = peer("chromium") {
        let shot = d.join("report.png");
        let url = format!("file://{}", d.join("r.html").display());
        succeed(std::process::Command::new(chromium).args([
            "--headless",
            "--disable-gpu",
            "--no-sandbox",
            &format!("--screenshot={}", shot.display()),
            &url,
        ]));
        assert!(decode_png(&shot).is_some(), "a screenshot");
    }
}
