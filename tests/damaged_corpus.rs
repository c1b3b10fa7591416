//! OpenEXR's own collection of damaged files (shared/exr-images/Damaged:
//! fuzzed, truncated, oversized) through every kind of command, as foreground
//! and as background, each in a child process under a 4 GiB address-space
//! limit and a time limit. Each run either succeeds with an output that
//! OpenEXR decodes, or refuses the file in one line naming it (exit 3); never a
//! panic, an abort, a signal, a hang, or anything left in the output folder.

mod common;
use common::*;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Duration;

/// Far above any run's time here (well under a second each in a debug build).
const TIMEOUT: Duration = Duration::from_secs(60);

/// The commands, by name: their arguments for a damaged file, the good plate
/// and the output path.
fn commands() -> Vec<(&'static str, fn(&str, &str, &str) -> Vec<String>)> {
    fn v(args: &[&str]) -> Vec<String> {
        args.iter().map(|a| a.to_string()).collect()
    }
    vec![
        ("over (damaged fg)", |d, good, out| {
            v(&["over", d, good, "-o", out, "-q", "--threads", "8"])
        }),
        ("over (damaged bg)", |d, good, out| {
            v(&["over", good, d, "-o", out, "-q", "--threads", "8"])
        }),
        ("transcode", |d, _, out| {
            v(&["transcode", d, "-o", out, "-q", "--threads", "8"])
        }),
        ("blur", |d, _, out| {
            v(&["blur", "--radius", "3", d, "-o", out, "-q"])
        }),
        ("flatten", |d, _, out| v(&["flatten", d, "-o", out, "-q"])),
        ("info", |d, _, _| v(&["info", d])),
    ]
}

/// Whether OpenEXR (oiiotool) decodes every pixel of `path`; without
/// oiiotool, exrcomp's own check.
fn decodes(path: &Path, oiiotool: Option<&Path>) -> Result<(), String> {
    let out = match oiiotool {
        Some(tool) => Command::new(tool).arg("--stats").arg(path).output(),
        None => exrcomp().arg("info").arg(path).output(),
    }
    .expect("the checker runs");
    let text = String::from_utf8_lossy(&out.stdout).to_string() + &stderr(&out);
    if out.status.success() && !text.to_lowercase().contains("error") {
        Ok(())
    } else {
        Err(text)
    }
}

/// Runs `command` on `damaged` in the empty folder `work`; the problem, if any.
fn problem(
    damaged: &Path,
    args: &[String],
    work: &Path,
    out: &Path,
    oiiotool: Option<&Path>,
) -> (Option<i32>, Option<String>) {
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    let ended = limited_within(&args, TIMEOUT);
    let name = damaged.file_name().unwrap().to_str().unwrap();
    let message = ended.stderr.trim_end();
    let mut left: Vec<String> = std::fs::read_dir(work)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    left.sort();
    let wrong = match ended.code {
        _ if ended.timed_out => Some(format!("still running after {TIMEOUT:?}")),
        Some(0) if left != ["out.exr"] && args[0] != "info" => {
            Some(format!("exit 0, output folder holds {left:?}"))
        }
        Some(0) => match args[0] {
            "info" => None,
            _ => decodes(out, oiiotool)
                .err()
                .map(|e| format!("exit 0 but the output does not decode: {e}")),
        },
        Some(3) if !left.is_empty() => Some(format!("exit 3, left {left:?}")),
        Some(3) if message.lines().count() != 1 || !message.contains(name) => Some(format!(
            "exit 3 without a one-line message naming the file: {message}"
        )),
        Some(3) => None,
        code => Some(format!(
            "exit {code:?} (signal {:?}), left {left:?}: {}",
            ended.signal,
            message.lines().next().unwrap_or("")
        )),
    };
    (ended.code, wrong)
}

#[test]
fn every_damaged_file_is_refused_or_processed_by_every_command() {
    let folder = shared_images().join("Damaged");
    if !folder.is_dir() {
        eprintln!("SKIPPED: no damaged images at {}", folder.display());
        return;
    }
    let mut files: Vec<PathBuf> = std::fs::read_dir(&folder)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_none_or(|e| e != "rst"))
        .collect();
    files.sort();
    assert!(!files.is_empty(), "{} is empty", folder.display());
    let dir = tempfile::tempdir().unwrap();
    let good = dir.path().join("good.exr");
    generate(&good, "bg", (64, 64), &[]);
    let oiiotool = peer("oiiotool");
    let commands = commands();

    // Two workers: the runs are short, single processes, mostly refused at
    // the header.
    let workers = 2;
    let results: Vec<(String, &str, Option<i32>, Option<String>)> = std::thread::scope(|scope| {
        let handles: Vec<_> = (0..workers)
            .map(|w| {
                let (files, commands, dir) = (&files, &commands, dir.path());
                let (good, oiiotool) = (&good, oiiotool.as_deref());
                scope.spawn(move || {
                    let mut results = Vec::new();
                    for file in files.iter().skip(w).step_by(workers) {
                        let name = file.file_name().unwrap().to_string_lossy().into_owned();
                        for (command, args) in commands {
                            let work = dir.join(format!("work{w}"));
                            std::fs::create_dir(&work).unwrap();
                            let out = work.join("out.exr");
                            let args = args(s(file), s(good), s(&out));
                            let (code, wrong) = problem(file, &args, &work, &out, oiiotool);
                            std::fs::remove_dir_all(&work).unwrap();
                            results.push((name.clone(), *command, code, wrong));
                        }
                    }
                    results
                })
            })
            .collect();
        handles
            .into_iter()
            .flat_map(|h| h.join().unwrap())
            .collect()
    });

    let mut counts: BTreeMap<(&str, Option<i32>), usize> = BTreeMap::new();
    for (_, command, code, _) in &results {
        *counts.entry((command, *code)).or_default() += 1;
    }
    eprintln!("{} files; exit codes per command: {counts:?}", files.len());
    let wrong: Vec<String> = results
        .iter()
        .filter_map(|(name, command, _, wrong)| {
            wrong.as_ref().map(|w| format!("{name}, {command}: {w}"))
        })
        .collect();
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}
