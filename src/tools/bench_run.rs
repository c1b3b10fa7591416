//! One run of a bench job: the command (its output moved into a folder of
//! its own), the process started and its figures taken as it exits, and the
//! floor each job is timed beside (specs/bench.md).

use crate::cli::command_line::{parse_command, Flow};
use crate::error::{Error, Result};
use crate::io::sequence::FramePattern;
use crate::tools::bench_stats::Stats;
use serde_json::{json, Value};
use std::io::Read;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::Instant;

/// A job to time: exrcomp's arguments, the one that names the output (set
/// anew for each run) and the input patterns (for `--cold`).
pub struct TimedCommand {
    pub name: String,
    pub args: Vec<String>,
    output: usize,
    inputs: Vec<String>,
}

impl TimedCommand {
    /// From a command (`over a.####.exr b.####.exr -o c.####.exr`) or a job
    /// file alone (`shot.toml`).
    pub fn new(name: String, command: &[String]) -> Result<Self> {
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
            let (plan, _) = crate::run::job_run::load_job(
                Path::new(&inputs[0]),
                None,
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

    /// The machine's floor timed beside this job: a transcode of its first
    /// image input (the codec work every job does) over the same
    /// `--frames`; none for a job that reads no image.
    pub fn floor(&self) -> Option<TimedCommand> {
        let input = self.inputs.iter().find(|i| !i.ends_with(".toml"))?;
        let (name, _) = crate::io::parts::split_part(input);
        let output = match FramePattern::parse(name).ok()?.is_sequence() {
            true => "floor.####.exr",
            false => "floor.exr",
        };
        let mut args = ["transcode", input, "-o", output]
            .map(String::from)
            .to_vec();
        let frames = self.args.iter().position(|a| a == "--frames");
        args.extend(
            frames
                .iter()
                .flat_map(|&i| self.args[i..].iter().take(2).cloned()),
        );
        args.extend(
            self.args
                .iter()
                .filter(|a| a.starts_with("--frames="))
                .cloned(),
        );
        Some(TimedCommand {
            name: format!("{}-floor", self.name),
            args,
            output: 3,
            inputs: vec![input.clone()],
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
    pub fn input_files(&self) -> Vec<PathBuf> {
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
pub struct Run {
    pub wall: f64,
    pub cpu: f64,
    pub peak_rss: f64,
    pub read_bytes: f64,
    pub written_bytes: f64,
    /// The sizes of the files it wrote.
    pub output_bytes: f64,
    /// The run's own `--json` summary.
    pub summary: Value,
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
pub fn drop_cached(files: &[PathBuf]) {
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
pub fn run_once(exe: &Path, args: &[String], threads: Option<usize>) -> Result<Run> {
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
        .map_err(|e| Error::internal(format!("cannot start {}: {e}", exe.display())))?;
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

/// How a bench's runs are made: threads, cold or not, and the folder their
/// outputs go into (removed after each run unless kept).
pub struct Runner<'a> {
    pub threads: Option<usize>,
    pub cold: bool,
    pub keep: bool,
    pub folder: &'a Path,
}

impl Runner<'_> {
    /// `job` once by the exrcomp at `exe`, into the folder `NAME-LABEL`.
    pub fn time(&self, exe: &Path, job: &TimedCommand, label: &str) -> Result<Run> {
        let run_folder = self.folder.join(format!("{}-{label}", job.name));
        std::fs::create_dir_all(&run_folder)
            .map_err(|e| Error::output(&run_folder, None, format!("cannot create: {e}")))?;
        if self.cold {
            drop_cached(&job.input_files());
        }
        let mut run = run_once(exe, &job.args_into(&run_folder), self.threads)
            .map_err(|e| Error::new(e.kind, format!("{}: {}", job.name, e.message)))?;
        run.output_bytes = folder_bytes(&run_folder);
        if !self.keep {
            let _ = std::fs::remove_dir_all(&run_folder);
        }
        Ok(run)
    }
}

/// Statistics of one figure of `runs`, with the runs' values.
pub fn figure(runs: &[Run], f: fn(&Run) -> f64) -> Value {
    let values: Vec<f64> = runs.iter().map(f).collect();
    Stats::of(&values).json(&values)
}

/// The figures of a job's runs (specs/bench.md, the record).
pub fn summarise(job: &TimedCommand, runs: &[Run]) -> Value {
    let column = |f: fn(&Run) -> f64| runs.iter().map(f).collect::<Vec<f64>>();
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
    let cpu_per_frame: Vec<f64> = runs.iter().map(|r| r.cpu / frames.max(1.0)).collect();
    json!({
        "name": job.name,
        "command": job.args,
        "frames": first["frames"],
        "pixels": first["pixels"],
        "wall_seconds": figure(runs, |r| r.wall),
        "cpu_seconds": figure(runs, |r| r.cpu),
        "cpu_seconds_per_frame": Stats::of(&cpu_per_frame).json(&cpu_per_frame),
        "peak_rss_bytes": figure(runs, |r| r.peak_rss),
        "output_bytes": figure(runs, |r| r.output_bytes),
        "frames_per_second": per_second(frames),
        "megapixels_per_second": per_second(pixels) / 1e6,
        "read_bytes_per_second": per_second(Stats::of(&column(|r| r.read_bytes)).median),
        "written_bytes_per_second": per_second(Stats::of(&column(|r| r.written_bytes)).median),
        "stages": stage_medians(runs),
        "serial_share": (!shares.is_empty()).then(|| Stats::of(&shares).median),
    })
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
