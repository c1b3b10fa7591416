//! `exrcomp bench`: a job timed as whole processes over several runs, each
//! writing afresh into a folder of its own, with the statistics, the
//! machine and a comparison against an earlier record (specs/bench.md).

use crate::cli::command_line::{parse_command, Flow};
use crate::cli::{BenchArgs, Size};
use crate::error::{Error, Result};
use crate::io::overwrite::refuse_overwriting;
use crate::io::sequence::FramePattern;
use crate::io::writer::write_whole;
use crate::tools::bench_stats::{verdict, Stats, Verdict};
use serde_json::{json, Value};
use std::io::Read;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::Instant;

/// The record's format, for readers of `--json`.
const SCHEMA: &str = "exrcomp-bench-1";

/// A job to time: exrcomp's arguments, the one that names the output (set
/// anew for each run) and the input patterns (for `--cold`).
struct TimedCommand {
    name: String,
    args: Vec<String>,
    output: usize,
    inputs: Vec<String>,
}

impl TimedCommand {
    /// From a command (`over a.####.exr b.####.exr -o c.####.exr`) or a job
    /// file alone (`shot.toml`).
    fn new(name: String, command: &[String]) -> Result<Self> {
        let command = match command {
            [job] if job.ends_with(".toml") => vec!["run".to_string(), job.clone()],
            _ => command.to_vec(),
        };
        let (mut task, subcommand, _) = parse_command(&command)?;
        if ["bench", "farm", "info", "stitch", "demo"].contains(&subcommand.as_str()) {
            return Err(Error::usage(format!(
                "`{subcommand}` writes no frames: bench times a command that does (over, run, transcode...)"
            )));
        }
        let mut inputs: Vec<String> = task
            .files
            .iter()
            .filter(|f| f.1 == Flow::In)
            .map(|f| task.args[f.0].clone())
            .collect();
        let mut output = task.files.iter().find(|f| f.1 == Flow::Out).map(|f| f.0);
        if subcommand == "run" {
            let plan = crate::cli::commands::load_job(
                Path::new(&inputs[0]),
                None,
                &crate::run::settings::RunArgs::none(),
            )?;
            // The job file, then what it reads.
            inputs.extend(plan.reads.into_iter().map(|(read, _)| read));
            if output.is_none() {
                task.args.extend(["-o".to_string(), plan.output]);
                output = Some(task.args.len() - 1);
            }
        }
        let output = output.ok_or_else(|| Error::usage("the command to time names no output"))?;
        Ok(TimedCommand {
            name,
            args: task.args,
            output,
            inputs,
        })
    }

    /// The arguments of a run writing into `folder`.
    fn args_into(&self, folder: &Path) -> Vec<String> {
        let mut args = self.args.clone();
        let name = Path::new(&args[self.output])
            .file_name()
            .map_or("out.exr".into(), |n| n.to_string_lossy().into_owned());
        args[self.output] = folder.join(name).to_string_lossy().into_owned();
        args.extend(["--json", "--quiet"].map(String::from));
        args
    }

    /// Every input file on disk, for dropping from the page cache.
    fn input_files(&self) -> Vec<PathBuf> {
        let mut files = Vec::new();
        for input in &self.inputs {
            let (name, _) = crate::io::parts::split_part(input);
            let Ok(pattern) = FramePattern::parse(name) else {
                continue;
            };
            match pattern.is_sequence() {
                true => files.extend(
                    pattern
                        .frames_on_disk()
                        .unwrap_or_default()
                        .into_iter()
                        .map(|f| pattern.path(f)),
                ),
                false => files.push(PathBuf::from(name)),
            }
        }
        files
    }
}

/// One run's figures.
struct Run {
    wall: f64,
    cpu: f64,
    peak_rss: f64,
    read_bytes: f64,
    written_bytes: f64,
    /// The sizes of the files it wrote.
    output_bytes: f64,
    /// The run's own `--json` summary.
    summary: Value,
}

/// The sizes of the files in `folder` together.
fn folder_bytes(folder: &Path) -> f64 {
    std::fs::read_dir(folder)
        .into_iter()
        .flatten()
        .filter_map(|e| e.ok()?.metadata().ok())
        .map(|m| m.len() as f64)
        .sum()
}

/// Drops `files` from the page cache, so the next run reads the storage.
fn drop_cached(files: &[PathBuf]) {
    for file in files {
        if let Ok(f) = std::fs::File::open(file) {
            use std::os::fd::AsRawFd;
            // SAFETY: a valid descriptor; the call only advises the kernel.
            unsafe { libc::posix_fadvise(f.as_raw_fd(), 0, 0, libc::POSIX_FADV_DONTNEED) };
        }
    }
}

/// Runs exrcomp with `args` once: wall time, the child's CPU and peak RSS
/// (`wait4`) and the bytes it read and wrote (`/proc/PID/io`, read before
/// the child is reaped).
fn run_once(args: &[String], threads: Option<usize>) -> Result<Run> {
    let exe = std::env::current_exe()
        .map_err(|e| Error::internal(format!("cannot find exrcomp's own path: {e}")))?;
    let mut command = Command::new(exe);
    if let Some(threads) = threads {
        command.arg(format!("--threads={threads}"));
    }
    let started = Instant::now();
    let mut child = command
        .args(args)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .map_err(|e| Error::internal(format!("cannot start exrcomp: {e}")))?;
    // Standard error in a thread, so that neither pipe can fill and stall it.
    let mut stderr = child.stderr.take().expect("piped");
    let errors = std::thread::spawn(move || {
        let mut text = String::new();
        let _ = stderr.read_to_string(&mut text);
        text
    });
    let mut out = String::new();
    let _ = child.stdout.take().map(|mut s| s.read_to_string(&mut out));
    let err = errors.join().unwrap_or_default();
    let pid = child.id() as libc::pid_t;
    // SAFETY: plain calls on our own child, with zeroed out-structs.
    let (status, usage, io) = unsafe {
        let mut info: libc::siginfo_t = std::mem::zeroed();
        libc::waitid(
            libc::P_PID,
            pid as libc::id_t,
            &mut info,
            libc::WEXITED | libc::WNOWAIT,
        );
        let wall = started.elapsed();
        let io = std::fs::read_to_string(format!("/proc/{pid}/io")).unwrap_or_default();
        let (mut status, mut usage) = (0, std::mem::zeroed::<libc::rusage>());
        libc::wait4(pid, &mut status, 0, &mut usage);
        ((status, wall), usage, io)
    };
    let ((status, wall), io_field) = (status, |name: &str| {
        io.lines()
            .find_map(|l| l.strip_prefix(name)?.trim().parse::<f64>().ok())
            .unwrap_or(0.0)
    });
    if !libc::WIFEXITED(status) || libc::WEXITSTATUS(status) != 0 {
        let last = err.lines().last().unwrap_or("(no message)");
        return Err(Error::new(
            crate::error::Kind::Input,
            format!("the timed command failed: {last}"),
        ));
    }
    let seconds = |t: libc::timeval| t.tv_sec as f64 + t.tv_usec as f64 * 1e-6;
    Ok(Run {
        wall: wall.as_secs_f64(),
        cpu: seconds(usage.ru_utime) + seconds(usage.ru_stime),
        peak_rss: usage.ru_maxrss as f64 * 1024.0,
        read_bytes: io_field("rchar:"),
        written_bytes: io_field("wchar:"),
        output_bytes: 0.0,
        summary: serde_json::from_str(out.trim()).unwrap_or(Value::Null),
    })
}

/// One job's record.
fn measure(job: &TimedCommand, args: &BenchArgs, folder: &Path) -> Result<Value> {
    let files = job.input_files();
    let mut runs = Vec::new();
    for k in 0..args.warmup + args.runs {
        let run_folder = folder.join(format!("{}-{k}", job.name));
        std::fs::create_dir_all(&run_folder)
            .map_err(|e| Error::output(&run_folder, None, format!("cannot create: {e}")))?;
        if args.cold {
            drop_cached(&files);
        }
        let mut run = run_once(&job.args_into(&run_folder), args.threads)
            .map_err(|e| Error::new(e.kind, format!("{}: {}", job.name, e.message)))?;
        run.output_bytes = folder_bytes(&run_folder);
        if !args.keep {
            let _ = std::fs::remove_dir_all(&run_folder);
        }
        if k >= args.warmup {
            runs.push(run);
        }
    }
    let column = |f: fn(&Run) -> f64| runs.iter().map(f).collect::<Vec<f64>>();
    let figure = |f: fn(&Run) -> f64| {
        let values = column(f);
        Stats::of(&values).json(&values)
    };
    let wall = Stats::of(&column(|r| r.wall));
    // The engine's share of CPU outside the pool, where it reports one.
    let shares: Vec<f64> = runs
        .iter()
        .filter_map(|r| r.summary["serial_share"].as_f64())
        .collect();
    let first = &runs[0].summary;
    let frames = first["frames"].as_f64().unwrap_or(0.0);
    let pixels = first["pixels"].as_f64().unwrap_or(0.0);
    let per_second = |v: f64| v / wall.median.max(1e-9);
    Ok(json!({
        "name": job.name,
        "command": job.args,
        "frames": first["frames"],
        "pixels": first["pixels"],
        "wall_seconds": figure(|r| r.wall),
        "cpu_seconds": figure(|r| r.cpu),
        "peak_rss_bytes": figure(|r| r.peak_rss),
        "output_bytes": figure(|r| r.output_bytes),
        "frames_per_second": per_second(frames),
        "megapixels_per_second": per_second(pixels) / 1e6,
        "read_bytes_per_second": per_second(Stats::of(&column(|r| r.read_bytes)).median),
        "written_bytes_per_second": per_second(Stats::of(&column(|r| r.written_bytes)).median),
        "stages": stage_medians(&runs),
        "serial_share": (!shares.is_empty()).then(|| Stats::of(&shares).median),
    }))
}

/// The medians, over the runs, of every number under the runs' `stages`
/// (the engine's per-stage figures, when it reports them).
fn stage_medians(runs: &[Run]) -> Value {
    fn walk(values: &[&Value]) -> Value {
        match values[0] {
            Value::Object(map) => Value::Object(
                map.keys()
                    .map(|k| {
                        let inner: Vec<&Value> = values.iter().map(|v| &v[k.as_str()]).collect();
                        (k.clone(), walk(&inner))
                    })
                    .collect(),
            ),
            Value::Number(_) => {
                let numbers: Vec<f64> = values.iter().filter_map(|v| v.as_f64()).collect();
                json!(Stats::of(&numbers).median)
            }
            other => other.clone(),
        }
    }
    let stages: Vec<&Value> = runs.iter().map(|r| &r.summary["stages"]).collect();
    walk(&stages)
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
        run_once(&args.map(String::from), None)?;
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

/// `exrcomp bench`.
pub fn bench(args: &BenchArgs) -> Result<()> {
    let jobs = match (args.standard, args.command.is_empty()) {
        (true, true) => {
            let cache = args.cache.clone().unwrap_or_else(default_cache);
            standard(args.size, args.frames, &cache)?
        }
        (false, false) => vec![TimedCommand::new(args.name.clone(), &args.command)?],
        (true, false) => return Err(Error::usage("give --standard or a command, not both")),
        (false, true) => {
            return Err(Error::usage(
                "give a command to time (after --), a JOB.toml, or --standard",
            ))
        }
    };
    // The record and the chart replace nothing a job reads (checked before
    // the runs, which may take long).
    let records = [&args.json, &args.report].into_iter().flatten();
    refuse_overwriting(
        jobs.iter().flat_map(TimedCommand::input_files),
        records.map(|path| (None, path.clone())),
    )?;
    let folder = std::env::temp_dir().join(format!("exrcomp-bench-{}", std::process::id()));
    let mut records = Vec::new();
    for job in &jobs {
        eprintln!(
            "bench: {} ({} runs after {} warm-up)",
            job.name, args.runs, args.warmup
        );
        let record = measure(job, args, &folder);
        if !args.keep {
            let _ = std::fs::remove_dir_all(&folder);
        }
        records.push(record?);
    }
    if args.keep {
        eprintln!("bench: outputs kept in {}", folder.display());
    }
    let record =
        json!({"schema": SCHEMA, "exrcomp": build(), "machine": machine(), "jobs": records});
    let baseline = match &args.baseline {
        Some(path) => Some(read_record(path)?),
        None => None,
    };
    let regressions = print_table(&record, baseline.as_ref(), args.tolerance / 100.0);
    if let Some(path) = &args.json {
        let text = serde_json::to_string_pretty(&record).expect("JSON") + "\n";
        write_whole(path, text.as_bytes())?;
    }
    if let Some(path) = &args.report {
        let chart = match path.extension().and_then(|e| e.to_str()) {
            Some("png") => crate::tools::bench_chart::png(&record, baseline.as_ref()),
            _ => crate::tools::bench_chart::svg(&record, baseline.as_ref()).into_bytes(),
        };
        write_whole(path, &chart)?;
    }
    match regressions.is_empty() {
        true => Ok(()),
        false => Err(Error::new(
            crate::error::Kind::Regression,
            format!("slower than the baseline: {}", regressions.join("; ")),
        )),
    }
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
        "{:<12} {:>9} {:>9} {:>9} {:>8} {:>9} {:>9} {:>9}  vs baseline",
        "job", "wall s", "min", "max", "mad", "cpu s", "frames/s", "peak MiB"
    );
    for job in record["jobs"].as_array().into_iter().flatten() {
        let name = job["name"].as_str().unwrap_or("?");
        let wall = Stats::from_json(&job["wall_seconds"]).expect("own record");
        let before = crate::tools::bench_stats::same_job(baseline, job)
            .and_then(|j| Stats::from_json(&j["wall_seconds"]));
        let comparison = match before {
            None => String::new(),
            Some(before) => {
                let ratio = wall.median / before.median;
                match verdict(&wall, &before, tolerance) {
                    Verdict::Within => format!("{ratio:.3}x"),
                    Verdict::Noise => format!("{ratio:.3}x, within noise"),
                    Verdict::Regression => {
                        regressions.push(format!(
                            "{name}: median wall {:.3} s against {:.3} s ({ratio:.3}x)",
                            wall.median, before.median
                        ));
                        format!("{ratio:.3}x REGRESSION")
                    }
                }
            }
        };
        eprintln!(
            "{name:<12} {:>9.3} {:>9.3} {:>9.3} {:>8.3} {:>9.3} {:>9.2} {:>9.1}  {comparison}",
            wall.median,
            wall.min,
            wall.max,
            wall.mad,
            job["cpu_seconds"]["median"].as_f64().unwrap_or(0.0),
            job["frames_per_second"].as_f64().unwrap_or(0.0),
            job["peak_rss_bytes"]["median"].as_f64().unwrap_or(0.0) / 1048576.0,
        );
    }
    regressions
}

#[cfg(test)]
mod tests {
    use super::*;

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
