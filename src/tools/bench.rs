//! `exrcomp bench`: a job timed as whole processes over several runs, each
//! writing afresh into a folder of its own, with the statistics, the
//! machine and a comparison against an earlier record (specs/bench.md).

use crate::cli::{BenchArgs, Size};
use crate::error::{Error, Result};
use crate::io::overwrite::refuse_overwriting;
use crate::io::sequence::FramePattern;
use crate::io::writer::write_whole;
use crate::run::own_exe;
use crate::tools::bench_run::{figure, run_once, summarise, Run, Runner, TimedCommand};
use crate::tools::bench_stats::{judge, Stats, Verdict};
use serde_json::{json, Value};
use std::path::{Path, PathBuf};

/// The record's format, for readers of `--json`.
const SCHEMA: &str = "exrcomp-bench-1";

/// One job's record: its runs, each beside a run of its floor (in turns,
/// floor first then job first, so that a load that drifts falls on both).
fn measure(job: &TimedCommand, args: &BenchArgs, runner: &Runner) -> Result<Value> {
    let exe = own_exe()?;
    let floor = job.floor().filter(|_| !args.no_floor);
    let (mut runs, mut floors) = (Vec::new(), Vec::new());
    for k in 0..args.warmup + args.runs {
        let label = k.to_string();
        let time_floor = || floor.as_ref().map(|f| runner.time(&exe, f, &label));
        let (floor_run, run) = match k % 2 {
            0 => (time_floor().transpose()?, runner.time(&exe, job, &label)?),
            _ => {
                let run = runner.time(&exe, job, &label)?;
                (time_floor().transpose()?, run)
            }
        };
        if k >= args.warmup {
            runs.push(run);
            floors.extend(floor_run);
        }
    }
    let mut record = summarise(job, &runs);
    if let Some(floor) = &floor {
        let ratios = |f: fn(&Run) -> f64| -> Value {
            let ratios: Vec<f64> = runs.iter().zip(&floors).map(|(r, l)| f(r) / f(l)).collect();
            Stats::of(&ratios).json(&ratios)
        };
        record["floor"] = json!({
            "command": floor.args,
            "wall_seconds": figure(&floors, |r| r.wall),
            "cpu_seconds": figure(&floors, |r| r.cpu),
            "ratio": ratios(|r| r.wall),
            "cpu_ratio": ratios(|r| r.cpu),
        });
    }
    Ok(record)
}

/// What the machine and this build are.
fn machine() -> Value {
    let cpuinfo = std::fs::read_to_string("/proc/cpuinfo").unwrap_or_default();
    let model = cpuinfo
        .lines()
        .find_map(|l| {
            l.strip_prefix("model name")?
                .split_once(':')
                .map(|(_, m)| m.trim())
        })
        .unwrap_or("unknown");
    let meminfo = std::fs::read_to_string("/proc/meminfo").unwrap_or_default();
    let memory = meminfo
        .lines()
        .find_map(|l| {
            l.strip_prefix("MemTotal:")?
                .trim()
                .strip_suffix("kB")?
                .trim()
                .parse::<u64>()
                .ok()
        })
        .map_or(0, |kib| kib * 1024);
    json!({
        "cores": std::thread::available_parallelism().map_or(1, |n| n.get()),
        "model": model,
        "memory_bytes": memory,
        "os": std::env::consts::OS,
        "arch": std::env::consts::ARCH,
    })
}

fn build() -> Value {
    json!({
        "version": env!("CARGO_PKG_VERSION"),
        "profile": if cfg!(debug_assertions) { "debug" } else { "release" },
        "isal": cfg!(isal),
    })
}

/// The standard workload's plates at `size`, `frames` of each, generated
/// where `plate` names them unless their last frame is there.
fn generate_plates(
    plate: &dyn Fn(&str) -> String,
    (width, height): (usize, usize),
    frames: usize,
) -> Result<()> {
    let range = format!("1-{frames}");
    let layers = [
        ("bg", "bg", "0,0"),
        ("fg", "fg", "0,0"),
        ("fg2", "fg", "-400,120"),
        ("fg3", "fg", "300,-200"),
    ];
    for (name, kind, origin) in layers {
        let last = FramePattern::parse(&plate(name))?.path(frames as i64);
        if last.exists() {
            continue;
        }
        let (w, h) = (width.to_string(), height.to_string());
        let args = [
            "generate",
            &plate(name),
            "--kind",
            kind,
            "--width",
            &w,
            "--height",
            &h,
            "--origin",
            origin,
            "--frames",
            &range,
        ];
        run_once(&own_exe()?, &args.map(String::from), None)?;
    }
    Ok(())
}

/// The workload's job file (over, then blur) in `folder`, reading the
/// plates `plate` names.
fn write_over_blur(folder: &Path, plate: &dyn Fn(&str) -> String) -> Result<PathBuf> {
    let job_file = folder.join("over_blur.toml");
    std::fs::write(
        &job_file,
        format!(
            "[[node]]\nname = \"fg\"\nread = {fg:?}\n\n[[node]]\nname = \"bg\"\nread = {bg:?}\n\n\
             [[node]]\nname = \"comp\"\nop = \"over\"\ninputs = [\"fg\", \"bg\"]\n\n\
             [[node]]\nname = \"soft\"\nop = \"blur\"\nradius = 10\ninputs = [\"comp\"]\n\n\
             [[node]]\nname = \"out\"\nwrite = \"over_blur.####.exr\"\ninputs = [\"soft\"]\n",
            fg = plate("fg"),
            bg = plate("bg"),
        ),
    )
    .map_err(|e| Error::output(&job_file, None, format!("cannot write: {e}")))?;
    Ok(job_file)
}

/// The standard workload at `size`: plates generated once into `cache`
/// (deterministic bytes, so every node runs the same), and the jobs.
fn standard(size: Size, frames: usize, cache: &Path) -> Result<Vec<TimedCommand>> {
    let (width, height) = match size {
        Size::Hd => (1920, 1080),
        Size::Uhd => (3840, 2160),
        Size::Eight => (7680, 4320),
    };
    // Absolute: the job file names the plates, and is read from its folder.
    let folder = std::path::absolute(cache.join(format!("{width}x{height}-{frames}")))
        .map_err(|e| Error::usage(format!("{}: {e}", cache.display())))?;
    let plate = |name: &str| {
        folder
            .join(format!("{name}.####.exr"))
            .to_string_lossy()
            .into_owned()
    };
    let range = format!("1-{frames}");
    generate_plates(&plate, (width, height), frames)?;
    let job_file = write_over_blur(&folder, &plate)?;
    #[cfg_attr(not(feature = "colour"), allow(unused_mut))]
    let mut jobs: Vec<(&str, Vec<String>)> = vec![
        (
            "transcode",
            vec![
                "transcode".into(),
                plate("bg"),
                "-o".into(),
                "t.####.exr".into(),
            ],
        ),
        (
            "over",
            vec![
                "over".into(),
                plate("fg"),
                plate("bg"),
                "-o".into(),
                "o.####.exr".into(),
            ],
        ),
        (
            "stack",
            vec![
                "stack".into(),
                plate("fg"),
                plate("fg2"),
                plate("fg3"),
                plate("bg"),
                "-o".into(),
                "s.####.exr".into(),
            ],
        ),
        ("over_blur", vec![job_file.to_string_lossy().into_owned()]),
        // A half-resolution proxy.
        (
            "resize",
            vec![
                "resize".into(),
                plate("bg"),
                "-o".into(),
                "r.####.exr".into(),
                "--scale".into(),
                "0.5".into(),
            ],
        ),
    ];
    // The working space to a log one, in the built-in config.
    #[cfg(feature = "colour")]
    jobs.push((
        "colorconvert",
        [
            "colorconvert",
            &plate("bg"),
            "-o",
            "c.####.exr",
            "--from",
            "ACEScg",
            "--to",
            "ACEScct",
        ]
        .map(String::from)
        .to_vec(),
    ));
    jobs.into_iter()
        .map(|(name, mut command)| {
            if command[0] != "run" && !command[0].ends_with(".toml") {
                command.extend(["--frames".into(), range.clone()]);
            }
            TimedCommand::new(name.to_string(), &command)
        })
        .collect()
}

/// The jobs `args` name: the standard workload or one command.
fn jobs(args: &BenchArgs) -> Result<Vec<TimedCommand>> {
    match (args.standard, args.command.is_empty()) {
        (true, true) => {
            let cache = args.cache.clone().unwrap_or_else(default_cache);
            standard(args.size, args.frames, &cache)
        }
        (false, false) => Ok(vec![TimedCommand::new(args.name.clone(), &args.command)?]),
        (true, false) => Err(Error::usage("give --standard or a command, not both")),
        (false, true) => Err(Error::usage(
            "give a command to time (after --), a JOB.toml, or --standard",
        )),
    }
}

/// A bench's record (what `--json` writes) and its verdict: `Ok`, or the
/// jobs slower than the baseline or the other build (a `Regression`).
pub struct Benched {
    pub record: Value,
    pub verdict: Result<()>,
}

/// `exrcomp bench`: a job slower than the baseline or the other build is
/// its error, after the record and the report are written.
pub fn bench(args: &BenchArgs) -> Result<()> {
    record(args)?.verdict
}

/// The runs `args` ask for, timed: the record, written where `--json` and
/// `--report` say, and its verdict (the Python package's `exrcomp.bench`
/// returns the record whatever the verdict).
pub fn record(args: &BenchArgs) -> Result<Benched> {
    let jobs = jobs(args)?;
    // The record and the chart replace nothing a job reads (checked before
    // the runs, which may take long).
    let records = [&args.json, &args.report].into_iter().flatten();
    refuse_overwriting(
        jobs.iter().flat_map(TimedCommand::input_files),
        records.map(|path| (None, path.clone())),
    )?;
    let baseline = args.baseline.as_deref().map(read_record).transpose()?;
    let history = match (&args.history, &args.report) {
        (Some(folder), Some(_)) => read_history(folder)?,
        _ => Vec::new(),
    };
    let folder = std::env::temp_dir().join(format!("exrcomp-bench-{}", std::process::id()));
    let runner = Runner {
        threads: args.threads,
        cold: args.cold,
        keep: args.keep,
        folder: &folder,
    };
    let mut records = Vec::new();
    for job in &jobs {
        eprintln!(
            "bench: {} ({} runs after {} warm-up)",
            job.name, args.runs, args.warmup
        );
        let record = match &args.against {
            Some(other) => crate::tools::bench_ab::measure_pairs(job, args, &runner, other),
            None => measure(job, args, &runner),
        };
        if !args.keep {
            let _ = std::fs::remove_dir_all(&folder);
        }
        records.push(record?);
    }
    if args.keep {
        eprintln!("bench: outputs kept in {}", folder.display());
    }
    let record = json!({"schema": SCHEMA, "exrcomp": build(), "machine": machine(),
                        "date": utc_now(), "commit": std::env::var("EXRCOMP_COMMIT").ok(),
                        "jobs": records});
    let tolerance = args.tolerance / 100.0;
    let (failures, comparison) = match &args.against {
        Some(_) => (
            crate::tools::bench_ab::print_pairs(&record, tolerance),
            Some(crate::tools::bench_ab::other_as_record(&record)),
        ),
        None => (print_table(&record, baseline.as_ref(), tolerance), baseline),
    };
    if let Some(path) = &args.json {
        let text = serde_json::to_string_pretty(&record).expect("JSON") + "\n";
        write_whole(path, text.as_bytes())?;
    }
    if let Some(path) = &args.report {
        let report = crate::tools::bench_report::Report {
            record: &record,
            comparison: comparison.as_ref(),
            history: &history,
        };
        write_whole(path, &report.file(path))?;
    }
    let verdict = match (failures.is_empty(), &args.against) {
        (true, _) => Ok(()),
        (false, against) => Err(Error::new(
            crate::error::Kind::Regression,
            match against {
                Some(other) => format!("slower than {}: {}", other.display(), failures.join("; ")),
                None => format!("slower than the baseline: {}", failures.join("; ")),
            },
        )),
    };
    Ok(Benched { record, verdict })
}

/// Now, in UTC, as `2026-12-03T08:15:00Z`.
fn utc_now() -> String {
    let secs = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| d.as_secs() as i64);
    // Days to a civil date (Howard Hinnant's days_from_civil, inverted).
    let (days, time) = (secs.div_euclid(86400), secs.rem_euclid(86400));
    let z = days + 719468;
    let era = z.div_euclid(146097);
    let doe = z - era * 146097;
    let yoe = (doe - doe / 1460 + doe / 36524 - doe / 146096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let day = doy - (153 * mp + 2) / 5 + 1;
    let month = if mp < 10 { mp + 3 } else { mp - 9 };
    let year = yoe + era * 400 + i64::from(month <= 2);
    let (h, m, s) = (time / 3600, time / 60 % 60, time % 60);
    format!("{year:04}-{month:02}-{day:02}T{h:02}:{m:02}:{s:02}Z")
}

/// The records in `folder` (its `.json` files that are bench records; others
/// are passed over), in the order they were taken.
fn read_history(folder: &Path) -> Result<Vec<Value>> {
    let entries = std::fs::read_dir(folder).map_err(|e| {
        Error::usage(format!(
            "{}: cannot read the history: {e}",
            folder.display()
        ))
    })?;
    let mut records: Vec<(String, PathBuf, Value)> = entries
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|e| e == "json"))
        .filter_map(|p| {
            let record = read_record(&p).ok()?;
            Some((record["date"].as_str().unwrap_or("").to_string(), p, record))
        })
        .collect();
    // By date, then by name (records of the same second).
    records.sort_by(|a, b| (&a.0, &a.1).cmp(&(&b.0, &b.1)));
    Ok(records.into_iter().map(|r| r.2).collect())
}

fn default_cache() -> PathBuf {
    let base = std::env::var_os("XDG_CACHE_HOME")
        .map(PathBuf::from)
        .or_else(|| std::env::var_os("HOME").map(|h| PathBuf::from(h).join(".cache")))
        .unwrap_or_else(std::env::temp_dir);
    base.join("exrcomp").join("bench")
}

fn read_record(path: &Path) -> Result<Value> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| Error::usage(format!("{}: cannot read the baseline: {e}", path.display())))?;
    let record: Value = serde_json::from_str(&text)
        .map_err(|e| Error::usage(format!("{}: not a bench record: {e}", path.display())))?;
    match record["schema"].as_str() {
        Some(SCHEMA) => Ok(record),
        _ => Err(Error::usage(format!(
            "{}: not an {SCHEMA} record",
            path.display()
        ))),
    }
}

/// The table on stderr, each job against its baseline; the regressions,
/// named with the figure and both values.
fn print_table(record: &Value, baseline: Option<&Value>, tolerance: f64) -> Vec<String> {
    let mut regressions = Vec::new();
    eprintln!(
        "{:<12} {:>9} {:>9} {:>9} {:>8} {:>9} {:>9} {:>9} {:>7}  vs baseline",
        "job", "wall s", "min", "max", "mad", "cpu s", "frames/s", "peak MiB", "/floor"
    );
    for job in record["jobs"].as_array().into_iter().flatten() {
        let name = job["name"].as_str().unwrap_or("?");
        let before = crate::tools::bench_stats::same_job(baseline, job);
        let Some(judged) = before.map(|b| judge(job, b, tolerance)) else {
            print_row(job, "");
            continue;
        };
        let mut comparison: Vec<String> = judged
            .figures
            .iter()
            .map(|j| {
                let ratio = j.now.median / j.before.median;
                match j.verdict {
                    Verdict::Within => format!("{}: {ratio:.3}x", j.figure),
                    Verdict::Noise => format!("{}: {ratio:.3}x within noise", j.figure),
                    Verdict::Regression => format!("{}: {ratio:.3}x beyond noise", j.figure),
                }
            })
            .collect();
        if judged.regression {
            comparison.push("REGRESSION".into());
            let figures = judged.figures.iter().map(|j| {
                let ratio = j.now.median / j.before.median;
                format!(
                    "{} {:.3} against {:.3} ({ratio:.3}x)",
                    j.figure, j.now.median, j.before.median
                )
            });
            regressions.push(format!(
                "{name}: {}",
                figures.collect::<Vec<_>>().join(", ")
            ));
        }
        print_row(job, &comparison.join(", "));
    }
    regressions
}

/// A job's row of the table, then how it compares with the baseline.
fn print_row(job: &Value, comparison: &str) {
    let name = job["name"].as_str().unwrap_or("?");
    let wall = Stats::from_json(&job["wall_seconds"]).expect("own record");
    let floor_ratio = job["floor"]["ratio"]["median"].as_f64();
    eprintln!(
        "{name:<12} {:>9.3} {:>9.3} {:>9.3} {:>8.3} {:>9.3} {:>9.2} {:>9.1} {:>7}  {}",
        wall.median,
        wall.min,
        wall.max,
        wall.mad,
        job["cpu_seconds"]["median"].as_f64().unwrap_or(0.0),
        job["frames_per_second"].as_f64().unwrap_or(0.0),
        job["peak_rss_bytes"]["median"].as_f64().unwrap_or(0.0) / 1048576.0,
        floor_ratio.map_or("-".into(), |r| format!("{r:.3}")),
        comparison,
    );
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::tools::bench_run::drop_cached;
    use crate::tools::bench_stats::verdict;

    #[test]
    fn statistics_of_known_samples() {
        let s = Stats::of(&[3.0, 1.0, 2.0, 10.0, 2.5]);
        assert_eq!((s.median, s.min, s.max), (2.5, 1.0, 10.0));
        // Deviations 0.5, 1.5, 0.5, 7.5, 0: their median 0.5.
        assert_eq!(s.mad, 0.5);
        let even = Stats::of(&[4.0, 1.0, 3.0, 2.0]);
        assert_eq!((even.median, even.mad), (2.5, 1.0));
        assert_eq!(Stats::of(&[7.0]).mad, 0.0);
    }

    #[test]
    fn a_regression_is_slower_beyond_the_tolerance_and_beyond_the_noise() {
        let before = Stats::of(&[1.00, 1.02, 0.98, 1.01, 0.99]);
        let slower =
            |by: f64, spread: f64| Stats::of(&[1.0 + by - spread, 1.0 + by, 1.0 + by + spread]);
        assert_eq!(
            verdict(&slower(0.20, 0.01), &before, 0.05),
            Verdict::Regression
        );
        assert_eq!(verdict(&slower(0.02, 0.01), &before, 0.05), Verdict::Within);
        // 20% slower at the median, but its runs spread as far: noise.
        assert_eq!(verdict(&slower(0.20, 0.19), &before, 0.05), Verdict::Noise);
        // One slow run (a busy machine) does not hide a regression.
        let outlier = Stats::of(&[1.2, 1.21, 1.19, 1.2, 0.9]);
        assert_eq!(verdict(&outlier, &before, 0.05), Verdict::Regression);
        assert_eq!(verdict(&slower(-0.3, 0.0), &before, 0.05), Verdict::Within);
    }

    /// Pages of `file` in the page cache (`mincore`), and its pages.
    fn resident(file: &Path) -> (usize, usize) {
        use std::os::fd::AsRawFd;
        let f = std::fs::File::open(file).unwrap();
        let len = f.metadata().unwrap().len() as usize;
        let page = 4096;
        let pages = len.div_ceil(page);
        let mut flags = vec![0u8; pages];
        // SAFETY: a read-only shared map of an open file, unmapped after.
        unsafe {
            let map = libc::mmap(
                std::ptr::null_mut(),
                len,
                libc::PROT_READ,
                libc::MAP_SHARED,
                f.as_raw_fd(),
                0,
            );
            assert_ne!(map, libc::MAP_FAILED);
            assert_eq!(libc::mincore(map, len, flags.as_mut_ptr()), 0);
            libc::munmap(map, len);
        }
        (flags.iter().filter(|&&f| f & 1 == 1).count(), pages)
    }

    #[test]
    fn cold_runs_drop_the_inputs_from_the_page_cache() {
        // On the disk of the build (not a tmpfs, whose pages cannot be dropped).
        let folder = Path::new(env!("CARGO_MANIFEST_DIR")).join("target/bench-cold");
        std::fs::create_dir_all(&folder).unwrap();
        let file = folder.join("plate.exr");
        std::fs::write(&file, vec![7u8; 8 << 20]).unwrap();
        let f = std::fs::File::open(&file).unwrap();
        f.sync_all().unwrap();
        let _ = std::fs::read(&file).unwrap();
        let (before, pages) = resident(&file);
        assert_eq!(before, pages, "a file just read is cached");
        drop_cached(std::slice::from_ref(&file));
        let (after, _) = resident(&file);
        assert!(after < pages / 10, "{after} of {pages} pages still cached");
    }
}
