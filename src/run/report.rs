//! Progress on the terminal and the summary at the end of a run.

use crate::error::Error;
use crate::io::sequence::format_frame_list;
use crate::stage_time::{self, StageTimes};
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressState, ProgressStyle};
use std::io::Write;
use std::path::Path;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::{Duration, Instant};

pub struct Report {
    bar: ProgressBar,
    started: Instant,
    quiet: bool,
    json: bool,
    /// The lines printed on standard output as frames finish, if any.
    log: Option<FarmLog>,
    frames: usize,
    done: AtomicUsize,
}

/// What a run prints on standard output for a log or a farm to read
/// (`--progress`): a line per frame, and the farm's own progress lines.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FarmLog {
    /// `frame 1001 written: /shot/out/c.1001.exr`.
    Frames,
    /// Those and `openjd_progress: 42.9`, `openjd_status: 3 of 7 frames done`
    /// (Open Job Description's stdout messages).
    Openjd,
    /// Those and `Progress: 42%`, for a Deadline plugin's progress handler.
    Deadline,
}

/// What became of a frame, as its line says. (Each new way a frame can end,
/// "redone as stale" for one, is a variant and a word here.)
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Outcome {
    Written,
    /// Complete already, kept (--resume).
    Kept,
    /// Written again over a file another job or tool made (--resume).
    Redone,
    Failed,
}

impl Outcome {
    fn word(self) -> &'static str {
        match self {
            Outcome::Written => "written",
            Outcome::Kept => "kept (--resume)",
            Outcome::Redone => "redone (another job's file was there)",
            Outcome::Failed => "failed",
        }
    }
}

/// The lines for frame `label`'s `outcome` (output `path`), the `done`th of
/// `frames`, in `log`'s format.
fn frame_lines(
    log: FarmLog,
    (label, outcome, path): (Option<i64>, Outcome, &Path),
    done: usize,
    frames: usize,
) -> String {
    let mut text = match label {
        Some(frame) => format!("frame {frame} {}: {}\n", outcome.word(), path.display()),
        None => format!("{}: {}\n", outcome.word(), path.display()),
    };
    let percent = 100.0 * done as f64 / frames.max(1) as f64;
    match log {
        FarmLog::Frames => {}
        FarmLog::Openjd => text.push_str(&format!(
            "openjd_progress: {percent:.1}\nopenjd_status: {done} of {} done\n",
            count(frames, "frame")
        )),
        FarmLog::Deadline => text.push_str(&format!("Progress: {}%\n", percent.floor())),
    }
    text
}

/// What a finished run did.
#[derive(Default)]
pub struct Summary {
    /// Frames written.
    pub frames: usize,
    pub pixels: u64,
    pub seconds: f64,
    /// Frames whose complete output was kept (--resume).
    pub kept: Vec<i64>,
    /// Frames written again over a file another job made (--resume).
    pub redone: Vec<i64>,
    /// Frames that failed on bad input or a bug (--keep-going), with the
    /// error.
    pub failed: Vec<(i64, Error)>,
    /// Output frames left out for a missing input (--missing skip).
    pub skipped: Vec<i64>,
    /// Frames the range named (with those skipped); 0: as many as written.
    pub named: usize,
    /// Input frames held or made black (--missing hold|black).
    pub replaced: Vec<String>,
    pub interrupted: bool,
    /// Where the run's CPU time went, once it has run.
    pub stages: Option<StageTimes>,
    /// What the job assumed where users slip (`engine::assumptions`),
    /// printed before it runs.
    pub warnings: Vec<String>,
}

impl Report {
    /// A progress bar over `frames` frames, drawn only on a terminal
    /// (standard error, with `json` too) and not with `quiet`.
    pub fn new(label: &str, frames: usize, quiet: bool, json: bool) -> Self {
        let target = if quiet {
            ProgressDrawTarget::hidden()
        } else {
            ProgressDrawTarget::stderr()
        };
        let bar = ProgressBar::with_draw_target(Some(frames as u64), target);
        let unit = if frames == 1 { "frame" } else { "frames" };
        bar.set_style(
            ProgressStyle::with_template(&format!(
                "{{prefix}} [{{bar:30}}] {{pos}}/{{len}} {unit}  {{rate}}  ETA {{eta}}"
            ))
            .expect("valid template")
            .with_key(
                "rate",
                |state: &ProgressState, w: &mut dyn std::fmt::Write| {
                    let _ = write!(w, "{}", frame_rate(state.per_sec()));
                },
            )
            .progress_chars("=> "),
        );
        bar.set_prefix(label.to_string());
        bar.enable_steady_tick(Duration::from_millis(250));
        Report {
            bar,
            started: Instant::now(),
            quiet,
            json,
            log: None,
            frames,
            done: AtomicUsize::new(0),
        }
    }

    /// The report with `log`'s lines on standard output as frames finish.
    pub fn with_log(self, log: Option<FarmLog>) -> Self {
        Report { log, ..self }
    }

    pub fn clear(&self) {
        self.bar.finish_and_clear();
    }

    pub fn frame_done(&self) {
        self.bar.inc(1);
    }

    /// A frame finished: the bar moves, and its lines go out (whole, at
    /// once, so that a farm reads them as they come).
    pub fn frame(&self, label: Option<i64>, outcome: Outcome, path: &Path) {
        self.frame_done();
        let Some(log) = self.log else {
            return;
        };
        let done = self.done.fetch_add(1, Ordering::SeqCst) + 1;
        let text = frame_lines(log, (label, outcome, path), done, self.frames);
        let mut out = std::io::stdout().lock();
        // A closed standard output stops no render.
        let _ = out.write_all(text.as_bytes()).and_then(|()| out.flush());
    }

    /// A line above the progress bar (or plain, without one).
    pub fn note(&self, line: &str) {
        if self.bar.is_hidden() {
            if !self.json {
                eprintln!("{line}");
            }
        } else {
            self.bar.suspend(|| eprintln!("{line}"));
        }
    }

    /// "exrcomp: warning: TEXT", above the progress bar, with `json` too.
    pub fn warning(&self, text: &str) {
        let line = format!("exrcomp: warning: {text}");
        match self.bar.is_hidden() {
            true => eprintln!("{line}"),
            false => self.bar.suspend(|| eprintln!("{line}")),
        }
    }

    pub fn elapsed(&self) -> f64 {
        self.started.elapsed().as_secs_f64()
    }

    /// Prints the summary: a line on stderr, and JSON on stdout with `json`.
    pub fn finish(&self, summary: &Summary) {
        self.clear();
        let seconds = summary.seconds.max(1e-9);
        let rss = peak_rss_bytes();
        if self.json {
            let failed: Vec<_> = summary
                .failed
                .iter()
                .map(|(frame, e)| serde_json::json!({"frame": frame, "error": e.message}))
                .collect();
            let record = serde_json::json!({
                "frames": summary.frames,
                "seconds": summary.seconds,
                "frames_per_second": summary.frames as f64 / seconds,
                "pixels": summary.pixels,
                "pixels_per_second": summary.pixels as f64 / seconds,
                "peak_rss_bytes": rss,
                "kept": summary.kept,
                "redone": summary.redone,
                "failed": failed,
                "skipped_missing": summary.skipped,
                "replaced_missing": summary.replaced,
                "interrupted": summary.interrupted,
                // The whole process's, from its start.
                "process_cpu_s": stage_time::process_cpu().as_secs_f64(),
                "stages": summary.stages.map(|s| s.to_json()),
                "serial_share": summary.stages.map(|s| s.serial_share()),
            });
            println!("{record}");
            return;
        }
        for (frame, reason) in &summary.failed {
            eprintln!("frame {frame} failed: {reason}");
        }
        if summary.interrupted {
            eprintln!("interrupted after {}", count(summary.frames, "frame"));
        }
        if !self.quiet {
            if !summary.kept.is_empty() {
                eprintln!(
                    "{} already complete, kept (--resume)",
                    count(summary.kept.len(), "frame")
                );
            }
            if !summary.redone.is_empty() {
                eprintln!(
                    "{} redone: the file there was another job's, another tool's or damaged \
                     (--resume): {}",
                    count(summary.redone.len(), "frame"),
                    format_frame_list(&summary.redone)
                );
            }
            for line in &summary.replaced {
                eprintln!("{line}");
            }
            // Fewer frames than the range named: the last line says so.
            let short = match summary.skipped.as_slice() {
                [] => String::new(),
                skipped => format!(
                    "; {} of the {} frames named left out for missing input (--missing skip): {}",
                    skipped.len(),
                    summary.named.max(summary.frames + skipped.len()),
                    format_frame_list(skipped)
                ),
            };
            eprintln!(
                "{} in {:.2} s: {}, {:.1} Mpixels/s, peak memory {}{short}",
                count(summary.frames, "frame"),
                summary.seconds,
                frame_rate(summary.frames as f64 / seconds),
                summary.pixels as f64 / seconds / 1e6,
                rss.map_or("unknown".to_string(), |b| format!(
                    "{:.1} MiB",
                    b as f64 / 1048576.0
                )),
            );
        }
    }
}

/// `n things` or `1 thing`.
pub fn count(n: usize, thing: &str) -> String {
    match n {
        1 => format!("1 {thing}"),
        n => format!("{n} {thing}s"),
    }
}

/// "0.30 frames/s", as the progress bar and the summary both say it.
pub fn frame_rate(per_second: f64) -> String {
    format!("{per_second:.2} frames/s")
}

/// Peak resident set size of this process (Linux: VmHWM).
pub fn peak_rss_bytes() -> Option<u64> {
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    let line = status.lines().find(|l| l.starts_with("VmHWM:"))?;
    let kib: u64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kib * 1024)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn counts_and_rates_read_as_words() {
        assert_eq!(count(1, "frame"), "1 frame");
        assert_eq!(count(0, "frame"), "0 frames");
        assert_eq!(count(24, "file"), "24 files");
        assert_eq!(frame_rate(0.2641), "0.26 frames/s");
    }

    #[test]
    fn frame_lines_say_the_frame_and_the_farm_its_progress() {
        let frame = (Some(1001), Outcome::Written, Path::new("/o/c.1001.exr"));
        assert_eq!(
            frame_lines(FarmLog::Frames, frame, 1, 7),
            "frame 1001 written: /o/c.1001.exr\n"
        );
        assert_eq!(
            frame_lines(FarmLog::Openjd, frame, 3, 7),
            "frame 1001 written: /o/c.1001.exr\nopenjd_progress: 42.9\nopenjd_status: 3 of 7 frames done\n"
        );
        let kept = (None, Outcome::Kept, Path::new("/o/c.exr"));
        assert_eq!(
            frame_lines(FarmLog::Deadline, kept, 2, 3),
            "kept (--resume): /o/c.exr\nProgress: 66%\n"
        );
    }
}
