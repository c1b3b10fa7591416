//! Farm jobs: a local command split into frame chunks, each task running
//! exrcomp with `--frames CHUNK --resume`, so a retried task redoes only the
//! frames it has not finished. What every farm gets (the checked command,
//! its needs, the job's files written safely) is here; each farm's files
//! are serde structs in its own file: Open Job Description templates
//! (`openjd`), OpenCue outlines (`opencue`), Deadline job files
//! (`deadline`); `frames` cuts the frames into the farms' chunks.

mod deadline;
mod frames;
mod opencue;
mod openjd;

use crate::cli::command_line::{argv, parse_command, Flow, TaskCommand};
use crate::cli::{Cli, Farm, FarmArgs};
use crate::error::{Error, Result};
use crate::io::overwrite::{refuse_overwriting, refuse_replacing};
use crate::io::writer::write_whole;
use crate::run::report::FarmLog;
use crate::run::DryRun;
use clap::Parser;
use deadline::deadline_job;
use opencue::opencue_outline;
use openjd::{openjd_template, Tasks};
use std::collections::BTreeMap;
use std::path::{Component, Path, PathBuf};

/// What differs between the farms beyond their files' formats, in one place
/// (specs/farm.md, "What each farm gets").
struct Rules {
    /// Its name in messages.
    name: &'static str,
    /// The lines its tasks print for it (`--progress`): `None` for the
    /// default off a terminal, a line per frame.
    log: Option<FarmLog>,
}

fn rules(farm: &Farm) -> Rules {
    match farm {
        Farm::Openjd(_) => Rules {
            name: "OpenJD",
            log: Some(FarmLog::Openjd),
        },
        Farm::Opencue(_) => Rules {
            name: "OpenCue",
            log: None,
        },
        Farm::Deadline(_) => Rules {
            name: "Deadline",
            log: Some(FarmLog::Deadline),
        },
    }
}

/// `path` with its `.` and `..` taken out lexically, as a shell's `cd`
/// reads them from the folder it names (a `..` after a link climbs out of
/// the link's name, not its target): the spelling path-mapping rules match.
pub fn normalise(path: &Path) -> PathBuf {
    let mut clean = PathBuf::new();
    for part in path.components() {
        match part {
            Component::CurDir => {}
            Component::ParentDir if clean.file_name().is_some() => {
                clean.pop();
            }
            // `/..` is `/`; a relative path keeps a leading `..`.
            Component::ParentDir if clean.has_root() => {}
            part => clean.push(part),
        }
    }
    clean
}

/// The folder `exrcomp farm` runs in, as the user names it: `$PWD` (the
/// shell's logical folder, through the links it was reached by) when it is
/// this very folder, else the real one.
pub fn logical_working_folder() -> Result<PathBuf> {
    use std::os::unix::fs::MetadataExt;
    let real = crate::run::working_folder()?;
    let same = |a: &Path, b: &Path| match (std::fs::metadata(a), std::fs::metadata(b)) {
        (Ok(a), Ok(b)) => (a.dev(), a.ino()) == (b.dev(), b.ino()),
        _ => false,
    };
    Ok(std::env::var_os("PWD")
        .map(PathBuf::from)
        .filter(|pwd| pwd.is_absolute() && same(pwd, &real))
        .map_or(real, |pwd| normalise(&pwd)))
}

/// The colour config the submitter resolves (`$OCIO`, else the built-in
/// one: `--config` is an argument of the command), which every task is
/// given as `$OCIO` so that no worker uses its own.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum ColourConfig {
    /// A config file, absolute: an OpenJD PATH parameter, mapped.
    File(String),
    /// A built-in config's name (`ocio://...`).
    Name(String),
}

impl ColourConfig {
    fn resolve(cwd: &Path) -> Self {
        match std::env::var("OCIO").ok().filter(|v| !v.is_empty()) {
            Some(name) if name.starts_with("ocio://") => ColourConfig::Name(name),
            Some(file) => ColourConfig::File(absolute(cwd, &file)),
            None => ColourConfig::Name(crate::ops::BUILTIN_COLOUR_CONFIG.to_string()),
        }
    }

    pub fn value(&self) -> &str {
        let (ColourConfig::File(value) | ColourConfig::Name(value)) = self;
        value
    }
}

/// `path` absolute against `cwd`, and normalised.
fn absolute(cwd: &Path, path: &str) -> String {
    normalise(&cwd.join(path)).to_string_lossy().into_owned()
}

/// Commands that render no frames, so no farm task can run them.
const NOT_FRAMES: [&str; 4] = ["farm", "info", "stitch", "demo"];

/// What each task of a job needs of its worker.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Needs {
    /// Threads of each task (its `--threads`).
    pub threads: usize,
    /// Bytes a task holds at most: the engine's memory bound of its largest
    /// frame at that many threads (specs/architecture.md).
    pub memory: u64,
    /// The submitter's `EXRCOMP_*` settings, which tasks run with.
    pub environment: BTreeMap<String, String>,
    /// The colour config tasks run with (`$OCIO`).
    pub colour: ColourConfig,
}

impl Needs {
    /// The settings with `OCIO`, for a farm that passes values as they are.
    pub fn settings(&self) -> BTreeMap<String, String> {
        let mut settings = self.environment.clone();
        settings.insert("OCIO".into(), self.colour.value().into());
        settings
    }

    /// The memory bound in whole MiB, as the farms ask for memory.
    pub fn memory_mib(&self) -> u64 {
        self.memory.div_ceil(1 << 20)
    }
}

/// `command` parsed as exrcomp parses it, its file names made absolute
/// against `cwd` (a task runs in a session folder of the farm's), and run as
/// a dry run over all `frames`, so that no template is written for a command
/// that would fail on every task (a typo, a missing input, an output that is
/// an input). The arguments every task runs, but for `--frames`: with
/// `--resume`, `--quiet` and `--threads` once (COMMAND's own, else
/// `threads`, else this machine's cores), and what each task needs.
pub fn task_command(
    command: &[String],
    frames: &str,
    cwd: &Path,
    (threads, log): (Option<usize>, Option<FarmLog>),
) -> Result<(TaskCommand, Needs, DryRun)> {
    for option in ["--frames", "--chunk-from"] {
        if command
            .iter()
            .any(|a| a == option || a.starts_with(&format!("{option}=")))
        {
            return Err(Error::usage(format!(
                "give --frames to `exrcomp farm`, not {option} to the command: each task gets its chunk"
            )));
        }
    }
    let (mut task, name, sub) = parse_command(command)?;
    if NOT_FRAMES.contains(&name.as_str()) {
        return Err(Error::usage(format!(
            "`{name}` renders no frames: a farm job runs a command that writes frames (over, blur, run, transcode...)"
        )));
    }
    for &(at, _) in &task.files {
        task.args[at] = absolute(cwd, &task.args[at]);
    }
    if sub.try_get_one::<bool>("resume").ok().flatten() != Some(&true) {
        task.args.push("--resume".into());
    }
    let given = |id: &str| sub.value_source(id) == Some(clap::parser::ValueSource::CommandLine);
    if let Some(log) = log.filter(|_| !given("progress") && !given("json")) {
        task.args.push("--progress".into());
        task.args.push(
            clap::ValueEnum::to_possible_value(&log)
                .expect("named")
                .get_name()
                .into(),
        );
    }
    // Memory grows with the threads (strips give each a block): a task runs
    // with the threads its memory is computed for.
    let threads = match sub.try_get_one::<usize>("threads").ok().flatten() {
        Some(&given) => given,
        None => {
            let threads = threads.unwrap_or_else(rayon::current_num_threads);
            task.args.extend(["--threads".into(), threads.to_string()]);
            threads
        }
    };
    // The check says nothing but its error (tasks are not quiet: a farm's
    // log wants their lines and summary).
    let quiet = (!given("quiet")).then(|| "--quiet".to_string());
    let check = argv(&task.args)
        .chain(["--frames".into(), frames.into(), "--dry-run".into()])
        .chain(quiet)
        .collect::<Vec<_>>();
    let cli = Cli::try_parse_from(check).map_err(|e| Error::usage(e.to_string()))?;
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .map_err(|e| Error::internal(format!("cannot start {threads} threads: {e}")))?;
    let mut dry = pool
        .install(|| crate::cli::commands::execute(cli.command))?
        .expect("a frame-writing command's dry run says what it found");
    // The job file and the other files the command names are read too.
    dry.reads.extend(
        task.files
            .iter()
            .filter(|&&(_, flow)| flow == Flow::In)
            .map(|&(at, _)| PathBuf::from(&task.args[at])),
    );
    let needs = Needs {
        threads,
        memory: dry.memory,
        environment: std::env::vars()
            .filter(|(name, _)| name.starts_with("EXRCOMP_"))
            .collect(),
        colour: ColourConfig::resolve(cwd),
    };
    Ok((task, needs, dry))
}

/// Writes the job `farm` asks for: the command checked over all its frames
/// first, nothing written if it would fail.
pub fn write_job(farm: &Farm, cwd: &Path) -> Result<()> {
    let job = farm.job();
    let rules = rules(farm);
    let (task, needs, dry) =
        task_command(&job.command, &job.frames, cwd, (job.threads, rules.log))?;
    one_task_for_a_movie(farm, &dry)?;
    if !dry.others.is_empty() {
        eprintln!("exrcomp: warning: {}", crate::run::others_made(&dry.others));
    }
    let exrcomp = crate::run::own_exe()?;
    let name = job
        .name
        .clone()
        .unwrap_or_else(|| format!("exrcomp {}", task.args[0]));
    let output = || {
        job.output.clone().ok_or_else(|| {
            Error::usage(format!(
                "give -o FILE: where the {} job is written",
                rules.name
            ))
        })
    };
    let files = match farm {
        Farm::Openjd(openjd) => {
            openjd::check_name(&name)?;
            let tasks = Tasks::new(
                &job.frames,
                job.chunk,
                openjd.task_chunking,
                openjd.target_runtime,
            )?;
            let about = (name.as_str(), description(job, &needs));
            let written = openjd_template(&exrcomp, &task, &tasks, &needs, about);
            match &openjd.bundle {
                Some(bundle) => vec![
                    (bundle.join("parameter_values.json"), written.bundle_values),
                    (bundle.join("template.json"), written.template),
                ],
                None => {
                    let output = output()?;
                    vec![
                        (beside(&output, "params.json"), written.values),
                        (output, written.template),
                    ]
                }
            }
        }
        Farm::Opencue(opencue) => vec![(
            output()?,
            opencue_outline(
                &exrcomp,
                &task.args,
                (job, &opencue.service),
                (&name, &needs),
            )?,
        )],
        Farm::Deadline(_) => {
            let about = (name.as_str(), description(job, &needs));
            let files = deadline_job(&exrcomp, &task, job, &needs, about)?;
            let output = output()?;
            vec![
                (beside(&output, "plugin.job"), files.plugin_info),
                (output, files.job_info),
            ]
        }
    };
    // The job's files replace neither what it reads nor a frame it writes.
    let written = || files.iter().map(|(path, _)| (None, path.clone()));
    refuse_overwriting(dry.reads, written())?;
    refuse_replacing(
        dry.writes,
        ("the frame", "a frame the job writes"),
        written(),
    )?;
    files
        .iter()
        .try_for_each(|(path, text)| write_whole(path, text.as_bytes()))
}

/// A movie output is one file, which one task writes whole (a retried task
/// writes it again): a job writing one is refused unless its chunk holds
/// every frame, and OpenJD's scheduler may not chunk it.
fn one_task_for_a_movie(farm: &Farm, dry: &DryRun) -> Result<()> {
    use crate::io::media::Format;
    let Some(output) = dry.writes.first() else {
        return Ok(());
    };
    if Format::of(&output.to_string_lossy()) != Some(Format::Movie) {
        return Ok(());
    }
    let job = farm.job();
    let frames = crate::io::sequence::parse_frame_list(&job.frames)?.len();
    let scheduled =
        matches!(farm, Farm::Openjd(o) if o.task_chunking || o.target_runtime.is_some());
    if job.chunk < frames || scheduled {
        return Err(Error::usage(format!(
            "{} is a movie, written whole by one task: give --chunk {frames} (all the job's \
             frames){}",
            output.display(),
            if scheduled {
                " and no --task-chunking or --target-runtime"
            } else {
                ""
            }
        )));
    }
    Ok(())
}

/// What the job does and needs, for a render manager's view of it.
fn description(job: &FarmArgs, needs: &Needs) -> String {
    let mut text = format!(
        "exrcomp {}: frames {} in chunks of {}; each task: --threads {}, at most {} MiB",
        job.command.join(" "),
        job.frames,
        job.chunk,
        needs.threads,
        needs.memory_mib()
    );
    // OpenJD's descriptions hold 2,048 characters, no control characters.
    text.retain(|c| !c.is_control());
    if let Some((at, _)) = text.char_indices().nth(2048) {
        text.truncate(at);
    }
    text
}

/// A file written beside a job's: `JOB.yaml` and `params.json` give
/// `JOB.params.json` (an OpenJD job's parameter values), `JOB.job` and
/// `plugin.job` give `JOB.plugin.job` (a Deadline job's plugin info).
pub fn beside(job: &Path, suffix: &str) -> PathBuf {
    let stem = job.file_stem().unwrap_or_default().to_string_lossy();
    job.with_file_name(format!("{stem}.{suffix}"))
}

/// `value` as a farm file's JSON, pretty, with a final line break.
fn json(value: &impl serde::Serialize) -> String {
    serde_json::to_string_pretty(value).expect("a farm file serialises") + "\n"
}

/// `arg` as a POSIX shell reads it back: quoted unless it is plain.
fn shell_quote(arg: &str) -> String {
    let plain = |c: char| c.is_ascii_alphanumeric() || "_-./:=,+@%".contains(c);
    match !arg.is_empty() && arg.chars().all(plain) {
        true => arg.to_string(),
        false => format!("'{}'", arg.replace('\'', r"'\''")),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn paths_lose_dots_lexically() {
        for (path, clean) in [
            ("/shot/plates/../renders/c.exr", "/shot/renders/c.exr"),
            ("/shot/./a/b/../../c", "/shot/c"),
            ("/../a", "/a"),
            ("a/../../b", "../b"),
        ] {
            assert_eq!(normalise(Path::new(path)), Path::new(clean), "{path}");
        }
        assert_eq!(
            beside(Path::new("a/job.yaml"), "params.json"),
            Path::new("a/job.params.json")
        );
    }
}
