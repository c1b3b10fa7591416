//! `bench --against OTHER`: each job run by this exrcomp and another in
//! turns, the runs paired, and whether this build is faster or slower than
//! the other, with the sign test's interval (specs/bench.md).

use crate::cli::BenchArgs;
use crate::error::Result;
use crate::run::own_exe;
use crate::tools::bench_run::{figure, summarise, Runner, TimedCommand};
use crate::tools::bench_stats::{difference, paired, Difference, Paired};
use serde_json::{json, Value};
use std::path::Path;

/// One job's record, its runs by this build, with `against`: the other's
/// runs, the ratios of the pairs (this build's wall over the other's) and
/// the verdict.
pub fn measure_pairs(
    job: &TimedCommand,
    args: &BenchArgs,
    runner: &Runner,
    other: &Path,
) -> Result<Value> {
    let exe = own_exe()?;
    let (mut mine, mut theirs) = (Vec::new(), Vec::new());
    for k in 0..args.warmup + args.runs {
        // This build first, then the other first: neither always runs
        // second, on the caches the first warmed.
        let order = match k % 2 {
            0 => [exe.as_path(), other],
            _ => [other, exe.as_path()],
        };
        let first = runner.time(order[0], job, &format!("{k}a"))?;
        let second = runner.time(order[1], job, &format!("{k}b"))?;
        if k >= args.warmup {
            let (a, b) = if k % 2 == 0 {
                (first, second)
            } else {
                (second, first)
            };
            mine.push(a);
            theirs.push(b);
        }
    }
    let ratios: Vec<f64> = mine
        .iter()
        .zip(&theirs)
        .map(|(a, b)| a.wall / b.wall)
        .collect();
    let p = paired(&ratios);
    let mut record = summarise(job, &mine);
    record["against"] = json!({
        "exrcomp": other,
        "wall_seconds": figure(&theirs, |r| r.wall),
        "cpu_seconds": figure(&theirs, |r| r.cpu),
        "peak_rss_bytes": figure(&theirs, |r| r.peak_rss),
        "ratio": {"median": p.median, "low": p.low, "high": p.high,
                  "confidence": p.confidence, "runs": ratios},
        "verdict": difference(&p, args.tolerance / 100.0).words(),
    });
    Ok(record)
}

/// The pairs' table on stderr; the jobs this build is slower at, named
/// with their ratio and interval.
pub fn print_pairs(record: &Value, tolerance: f64) -> Vec<String> {
    let mut slower = Vec::new();
    eprintln!(
        "{:<12} {:>9} {:>9} {:>8} {:>17}  verdict",
        "job", "this s", "other s", "ratio", "interval"
    );
    for job in record["jobs"].as_array().into_iter().flatten() {
        let name = job["name"].as_str().unwrap_or("?");
        let against = &job["against"];
        let ratio = &against["ratio"];
        let get = |v: &Value| v.as_f64().unwrap_or(f64::NAN);
        let p = Paired {
            median: get(&ratio["median"]),
            low: get(&ratio["low"]),
            high: get(&ratio["high"]),
            confidence: get(&ratio["confidence"]),
        };
        let runs = ratio["runs"].as_array().map_or(0, Vec::len);
        let verdict = difference(&p, tolerance);
        let interval = format!("{:.3}-{:.3} ({:.0}%)", p.low, p.high, 100.0 * p.confidence);
        if verdict == Difference::Slower {
            slower.push(format!(
                "{name}: {:.3}x the other's wall, {interval}",
                p.median
            ));
        }
        eprintln!(
            "{name:<12} {:>9.3} {:>9.3} {:>7.3}x {interval:>17}  {} at {runs} runs",
            get(&job["wall_seconds"]["median"]),
            get(&against["wall_seconds"]["median"]),
            p.median,
            verdict.words(),
        );
    }
    slower
}

/// The other build's runs as a record of their own, for the chart.
pub fn other_as_record(record: &Value) -> Value {
    let jobs: Vec<Value> = record["jobs"]
        .as_array()
        .into_iter()
        .flatten()
        .map(|j| json!({"name": j["name"], "wall_seconds": j["against"]["wall_seconds"]}))
        .collect();
    json!({"jobs": jobs})
}
