//! Farm jobs: a local command split into frame chunks, each task running
//! exrcomp with `--frames CHUNK --resume`, so a retried task redoes only the
//! frames it has not finished. Open Job Description templates, OpenCue
//! outlines and Deadline job files.

use crate::cli::command_line::{argv, parse_command, Flow, TaskCommand};
use crate::cli::{Cli, Farm, FarmArgs};
use crate::error::{Error, Result};
use crate::io::overwrite::{refuse_overwriting, refuse_replacing};
use crate::io::sequence::parse_frame_list;
use crate::io::writer::write_whole;
use crate::run::report::FarmLog;
use crate::run::DryRun;
use clap::Parser;
use std::collections::BTreeMap;
use std::path::{Component, Path, PathBuf};

/// Most tasks an OpenJD task parameter may list.
const OPENJD_MAX_TASKS: usize = 1024;

/// The frame lists of the tasks: `chunk` frames of `frames` each, in order,
/// each as a range expression (`1001-1019:2`, never a long comma list).
pub fn chunks(frames: &str, chunk: usize) -> Result<Vec<String>> {
    if chunk == 0 {
        return Err(Error::usage("--chunk must be at least 1"));
    }
    let frames = parse_frame_list(frames)?;
    Ok(frames.chunks(chunk).map(range_expression).collect())
}

/// Frames as runs of one step: `1-5,7,9-21:3`, as exrcomp's `--frames`,
/// OpenJD's range expressions and OpenCue's ranges (with `x`) read them.
pub fn range_expression(frames: &[i64]) -> String {
    let mut runs = Vec::new();
    let mut i = 0;
    while i < frames.len() {
        let step = frames.get(i + 1).map_or(1, |next| next - frames[i]);
        let mut j = i;
        while step > 0 && frames.get(j + 1) == Some(&(frames[j] + step)) {
            j += 1;
        }
        runs.push(match (j - i, step) {
            (0, _) => frames[i].to_string(),
            (_, 1) => format!("{}-{}", frames[i], frames[j]),
            (_, step) => format!("{}-{}:{step}", frames[i], frames[j]),
        });
        i = j + 1;
    }
    runs.join(",")
}

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

/// Seconds an OpenJD task has between its cancel's SIGTERM and SIGKILL
/// (`NOTIFY_THEN_TERMINATE`): exrcomp abandons the frames in flight at once
/// and removes their temporaries, keeping every frame done; the period
/// bounds that, with room for a frame finishing if a later exrcomp does.
const CANCEL_NOTIFY_SECONDS: u32 = 120;

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
            None => ColourConfig::Name(crate::ops::colour::BUILTIN.to_string()),
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
}

impl Needs {
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
    if !dry.others.is_empty() {
        eprintln!("exrcomp: warning: {}", crate::run::others_made(&dry.others));
    }
    let exrcomp = this_exrcomp()?;
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
                    (bundle.join("parameter_values.yaml"), written.bundle_values),
                    (bundle.join("template.yaml"), written.template),
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

/// JSON quoting is valid YAML quoting: every string goes out quoted.
fn quote(text: &str) -> String {
    serde_json::Value::String(text.to_string()).to_string()
}

/// `text` for a format string of a template: quoted, or when it holds `{{`
/// (which would open an expression) through a STRING job parameter `name`
/// whose default it is, a value OpenJD does not read as a format string.
fn literal(parameters: &mut Vec<String>, name: String, text: &str) -> String {
    if !text.contains("{{") {
        return quote(text);
    }
    parameters.push(format!(
        "- name: {name}\n\x20 type: STRING\n\x20 default: {}\n",
        quote(text)
    ));
    quote(&format!("{{{{Param.{name}}}}}"))
}

/// How an OpenJD job splits its frames into tasks.
pub enum Tasks {
    /// One STRING task parameter listing the chunks (any OpenJD scheduler).
    Listed(Vec<String>),
    /// A CHUNK[INT] task parameter over all the frames (the TASK_CHUNKING
    /// extension): the scheduler makes the chunks, adaptively towards a
    /// runtime if one is given.
    Chunked {
        frames: String,
        chunk: usize,
        contiguous: bool,
        target_seconds: Option<u32>,
    },
}

impl Tasks {
    pub fn new(
        frames: &str,
        chunk: usize,
        chunking: bool,
        target_seconds: Option<u32>,
    ) -> Result<Self> {
        if !chunking && target_seconds.is_none() {
            let chunks = chunks(frames, chunk)?;
            if chunks.len() > OPENJD_MAX_TASKS {
                return Err(Error::usage(format!(
                    "{} chunks: an OpenJD task parameter lists at most {OPENJD_MAX_TASKS}; \
                     give a larger --chunk, or --task-chunking for the scheduler to chunk",
                    chunks.len()
                )));
            }
            return Ok(Tasks::Listed(chunks));
        }
        if chunk == 0 {
            return Err(Error::usage("--chunk must be at least 1"));
        }
        let list = parse_frame_list(frames)?;
        Ok(Tasks::Chunked {
            contiguous: list.windows(2).all(|w| w[1] == w[0] + 1),
            frames: range_expression(&list),
            chunk,
            target_seconds,
        })
    }

    /// The template's extensions and its `Frames` task parameter's type and
    /// range; scheduler chunking adds the job parameters `Frames` and
    /// `ChunkSize` to `parameters`.
    fn openjd(&self, parameters: &mut Vec<String>) -> (String, String) {
        match self {
            Tasks::Listed(chunks) => (
                String::new(),
                format!(
                    "\x20     type: STRING\n\x20     range: [{}]\n",
                    chunks
                        .iter()
                        .map(|c| quote(c))
                        .collect::<Vec<_>>()
                        .join(", ")
                ),
            ),
            Tasks::Chunked {
                frames,
                chunk,
                contiguous,
                target_seconds,
            } => {
                parameters.push(format!(
                    "- name: Frames\n\x20 type: STRING\n\x20 default: {}\n\
                     - name: ChunkSize\n\x20 type: INT\n\x20 default: {chunk}\n\x20 minValue: 1\n",
                    quote(frames)
                ));
                (
                    "extensions: [TASK_CHUNKING]\n".to_string(),
                    format!(
                        "\x20     type: CHUNK[INT]\n\x20     range: \"{{{{Param.Frames}}}}\"\n\
                         \x20     chunks:\n\x20       defaultTaskCount: \"{{{{Param.ChunkSize}}}}\"\n\
                         \x20       rangeConstraint: {}\n{}",
                        if *contiguous {
                            "CONTIGUOUS"
                        } else {
                            "NONCONTIGUOUS"
                        },
                        target_seconds.map_or(String::new(), |t| {
                            format!("\x20       targetRuntimeSeconds: {t}\n")
                        }),
                    ),
                )
            }
        }
    }
}

/// An Open Job Description job (specification 2023-09): its template and
/// the values of its job parameters.
pub struct OpenJdArgs {
    pub template: String,
    /// `{"NAME": "VALUE"}`, as `openjd run -p file://FILE` and render
    /// managers take job parameters.
    pub values: String,
    /// The same as a job bundle's `parameter_values.yaml` (`parameterValues`,
    /// a list of `name` and `value`), as `deadline bundle submit` reads it.
    pub bundle_values: String,
}

/// An Open Job Description job template: one step whose tasks are the frame
/// chunks. The executable and every file argument are PATH job parameters
/// (`Exrcomp`, `Input1`..., `Output`), which a render manager's path mapping
/// rewrites for the worker; OpenJD allows a PATH parameter no absolute
/// default, so their values go in `values`. An argument that holds `{{` goes
/// through a STRING job parameter, whose value is not a format string. With
/// scheduler chunking, `Frames` and `ChunkSize` are job parameters too, the
/// given values their defaults. The step asks for the task's threads and
/// memory bound (`hostRequirements`), and its environment carries the
/// submitter's `EXRCOMP_*` settings.
pub fn openjd_template(
    exrcomp: &Path,
    task: &TaskCommand,
    tasks: &Tasks,
    needs: &Needs,
    (name, description): (&str, String),
) -> OpenJdArgs {
    let command = &task.args;
    let mut parameters = Vec::new();
    let mut values = serde_json::Map::new();
    // Every path is a FILE: a sequence's pattern names files.
    let mut path = |parameters: &mut Vec<String>, name: String, value: &str, flow: &str| {
        parameters.push(format!(
            "- name: {name}\n\x20 type: PATH\n\x20 objectType: FILE\n\x20 dataFlow: {flow}\n"
        ));
        values.insert(name.clone(), value.into());
        quote(&format!("{{{{Param.{name}}}}}"))
    };
    let executable = path(
        &mut parameters,
        "Exrcomp".into(),
        &exrcomp.to_string_lossy(),
        "NONE",
    );
    let mut args = Vec::new();
    let mut inputs = 0;
    for (i, arg) in command.iter().enumerate() {
        let file = task.files.iter().find(|(at, _)| *at == i).map(|f| f.1);
        args.push(match file {
            Some(Flow::Out) => path(&mut parameters, "Output".into(), arg, "OUT"),
            Some(Flow::In) => {
                inputs += 1;
                path(&mut parameters, format!("Input{inputs}"), arg, "IN")
            }
            None => literal(&mut parameters, format!("Arg{i}"), arg),
        });
    }
    // The colour config as the submitter resolved it: a file is a PATH
    // parameter (mapped), a built-in one's name a literal.
    let colour = match &needs.colour {
        ColourConfig::File(file) => path(&mut parameters, "ColourConfig".into(), file, "IN"),
        ColourConfig::Name(name) => quote(name),
    };
    let environment = format!(
        "\x20 stepEnvironments:\n\
         \x20 - name: ExrcompSettings\n\
         \x20   description: \"The submitter's colour config and EXRCOMP_* settings\"\n\
         \x20   variables:\n\
         \x20     OCIO: {colour}\n{}",
        needs
            .environment
            .iter()
            .enumerate()
            .map(|(i, (name, value))| format!(
                "\x20     {name}: {}\n",
                literal(&mut parameters, format!("Env{i}"), value)
            ))
            .collect::<String>()
    );
    args.extend(["--frames", "{{Task.Param.Frames}}"].map(quote));
    let (extensions, task_parameter) = tasks.openjd(&mut parameters);
    let template = format!(
        "specificationVersion: jobtemplate-2023-09\n\
         {extensions}\
         name: {name}\n\
         description: {description}\n\
         parameterDefinitions:\n\
         {parameters}\
         steps:\n\
         - name: exrcomp\n\
         \x20 parameterSpace:\n\
         \x20   taskParameterDefinitions:\n\
         \x20   - name: Frames\n\
         {task_parameter}\
         \x20 hostRequirements:\n\
         \x20   amounts:\n\
         \x20   - name: amount.worker.vcpu\n\
         \x20     min: {threads}\n\
         \x20   - name: amount.worker.memory\n\
         \x20     min: {memory}\n\
         \x20   attributes:\n\
         \x20   - name: attr.worker.os.family\n\
         \x20     anyOf: [linux]\n\
         {environment}\
         \x20 script:\n\
         \x20   actions:\n\
         \x20     onRun:\n\
         \x20       command: {executable}\n\
         \x20       args: [{args}]\n\
         \x20       cancelation:\n\
         \x20         mode: NOTIFY_THEN_TERMINATE\n\
         \x20         notifyPeriodInSeconds: {CANCEL_NOTIFY_SECONDS}\n",
        name = quote(name),
        description = quote(&description),
        threads = needs.threads,
        memory = needs.memory_mib(),
        parameters = parameters.concat(),
        args = args.join(", "),
    );
    let bundle_values = std::iter::once("parameterValues:\n".to_string())
        .chain(
            values
                .iter()
                .map(|(name, value)| format!("- name: {}\n  value: {value}\n", quote(name))),
        )
        .collect();
    let values = serde_json::to_string_pretty(&values).expect("JSON values serialise") + "\n";
    OpenJdArgs {
        template,
        values,
        bundle_values,
    }
}

/// A file written beside a job's: `JOB.yaml` and `params.json` give
/// `JOB.params.json` (an OpenJD job's parameter values), `JOB.job` and
/// `plugin.job` give `JOB.plugin.job` (a Deadline job's plugin info).
pub fn beside(job: &Path, suffix: &str) -> PathBuf {
    let stem = job.file_stem().unwrap_or_default().to_string_lossy();
    job.with_file_name(format!("{stem}.{suffix}"))
}

/// Frames as one range and its step: OpenCue and Deadline cut a job's
/// frames into chunks of `chunk` themselves, giving a task its first and
/// last frame, which name the chunk only when the frames are one stepped
/// range.
struct SteppedRange {
    range: String,
    step: Option<String>,
}

impl SteppedRange {
    fn new(frames: &str, chunk: usize, farm: &str) -> Result<Self> {
        if chunk == 0 {
            return Err(Error::usage("--chunk must be at least 1"));
        }
        let range = range_expression(&parse_frame_list(frames)?);
        if range.contains(',') || !range[1..].contains('-') {
            return Err(Error::usage(format!(
                "{farm} takes one frame range, A-B or A-B:STEP (or A-BxSTEP), not {frames}"
            )));
        }
        Ok(match range.split_once(':') {
            Some((range, step)) => SteppedRange {
                range: range.to_string(),
                step: Some(step.to_string()),
            },
            None => SteppedRange { range, step: None },
        })
    }

    /// The frames in the farms' syntax, `A-B` or `A-BxS`.
    fn frames(&self) -> String {
        match &self.step {
            Some(step) => format!("{}x{step}", self.range),
            None => self.range.clone(),
        }
    }

    /// A chunk's `--frames` from the farm's tokens for its first and last
    /// frame; with no last frame, `start` is all the frames.
    fn chunk(&self, start: &str, end: &str) -> String {
        let range = match end {
            "" => start.to_string(),
            end => format!("{start}-{end}"),
        };
        match &self.step {
            Some(step) => format!("{range}:{step}"),
            None => range,
        }
    }
}

/// `arg` as a POSIX shell reads it back: quoted unless it is plain.
fn shell_quote(arg: &str) -> String {
    let plain = |c: char| c.is_ascii_alphanumeric() || "_-./:=,+@%".contains(c);
    match !arg.is_empty() && arg.chars().all(plain) {
        true => arg.to_string(),
        false => format!("'{}'", arg.replace('\'', r"'\''")),
    }
}

/// An OpenCue outline in the JSON form PyOutline loads
/// (`outline.loader.load_json`): one Shell layer over the frame range,
/// chunked, on the layer's service with the task's threads as cores, its
/// memory bound as memory, and the colour config and `EXRCOMP_*` settings
/// as its environment. Each chunk runs `--frames ALL --chunk-from
/// #FRAME_START#,N` (a shell command, its arguments quoted): exrcomp cuts
/// the chunk from its first frame, as Cuebot before 1.0 sets #FRAME_END#
/// to the first frame + N - 1 whatever the step.
pub fn opencue_outline(
    exrcomp: &Path,
    command: &[String],
    (job, service): (&FarmArgs, &str),
    (name, needs): (&str, &Needs),
) -> Result<String> {
    let frames = SteppedRange::new(&job.frames, job.chunk, "OpenCue")?;
    let mut line: Vec<String> = std::iter::once(exrcomp.to_string_lossy().as_ref())
        .chain(command.iter().map(String::as_str))
        .map(shell_quote)
        .collect();
    line.extend([
        "--frames".to_string(),
        frames.chunk(&frames.range, ""),
        "--chunk-from".to_string(),
        format!("#FRAME_START#,{}", job.chunk),
    ]);
    // OpenCue's job names are one word.
    let name: String = name
        .chars()
        .map(|c| if c.is_whitespace() { '-' } else { c })
        .collect();
    let outline = serde_json::json!({
        "name": name,
        "range": frames.frames(),
        "layers": [{
            "name": "exrcomp",
            "module": "outline.modules.shell.Shell",
            "command": line.join(" "),
            "chunk": job.chunk,
            "service": service,
            "cores": needs.threads,
            "memory": format!("{}m", needs.memory_mib()),
            "env": needs.settings(),
        }],
    });
    Ok(serde_json::to_string_pretty(&outline).expect("JSON values serialise") + "\n")
}

/// A Deadline job: its job-info and plugin-info files.
pub struct DeadlineArgs {
    pub job_info: String,
    pub plugin_info: String,
}

/// Deadline 10 job files for the CommandLine plugin, which
/// `deadlinecommand JOBINFO PLUGININFO` submits: the frames (`A-B` or
/// `A-BxS`) in chunks of `ChunkSize`, each task running the command with
/// `--frames <STARTFRAME>-<ENDFRAME>`; the output's folder and file name (as
/// `####`) for the Monitor; the submitter's `EXRCOMP_*` settings as the job's
/// environment. Deadline has no keys for a task's cores and memory: they go
/// in the comment and as extra info (`exrcomp.threads`,
/// `exrcomp.memory_mib`) for the farm's groups and limits.
pub fn deadline_job(
    exrcomp: &Path,
    task: &TaskCommand,
    job: &FarmArgs,
    needs: &Needs,
    (name, description): (&str, String),
) -> Result<DeadlineArgs> {
    let frames = SteppedRange::new(&job.frames, job.chunk, "Deadline")?;
    // Key=value lines: a value holds no line break. The CommandLine plugin
    // reads a task's `Progress: N%` lines (its own stdout handler) only from
    // a command it runs in the worker's shell (`ShellExecute`: its
    // RunProcess path does not capture them), so Arguments is the whole
    // command line, each word quoted for that shell.
    let value = |text: &str| match text.contains(['\n', '\r']) {
        true => Err(Error::usage(format!(
            "{text:?} holds a line break, which a Deadline job file cannot carry"
        ))),
        false => Ok(text.to_string()),
    };
    let plain = |c: char| c.is_ascii_alphanumeric() || "_./:=,+@%-".contains(c);
    let argument = |arg: &str| match (arg.contains('"'), !arg.is_empty() && arg.chars().all(plain))
    {
        (true, _) => Err(Error::usage(format!(
            "{arg:?} holds a double quote, which Deadline's Arguments cannot carry"
        ))),
        (false, true) => value(arg),
        (false, false) => value(&format!("'{}'", arg.replace('\'', "'\\''"))),
    };
    let mut arguments = std::iter::once(exrcomp.to_string_lossy().as_ref())
        .chain(task.args.iter().map(String::as_str))
        .map(argument)
        .collect::<Result<Vec<_>>>()?;
    arguments.extend([
        "--frames".to_string(),
        frames.chunk("<STARTFRAME>", "<ENDFRAME>"),
    ]);
    let mut info = vec![
        ("Plugin".to_string(), "CommandLine".to_string()),
        ("Name".to_string(), value(name)?),
        ("Comment".to_string(), value(&description)?),
        ("Frames".to_string(), frames.frames()),
        ("ChunkSize".to_string(), job.chunk.to_string()),
    ];
    if let Some(&(at, _)) = task.files.iter().find(|(_, flow)| *flow == Flow::Out) {
        let output = Path::new(&task.args[at]);
        let pattern = crate::io::sequence::FramePattern::parse(&task.args[at])?;
        let name = Path::new(&pattern.with_hashes())
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_default();
        let folder = output.parent().unwrap_or(Path::new("/"));
        info.push(("OutputDirectory0".into(), value(&folder.to_string_lossy())?));
        info.push(("OutputFilename0".into(), value(&name)?));
    }
    for (i, (name, setting)) in needs.settings().iter().enumerate() {
        info.push((
            format!("EnvironmentKeyValue{i}"),
            value(&format!("{name}={setting}"))?,
        ));
    }
    info.push((
        "ExtraInfoKeyValue0".into(),
        format!("exrcomp.threads={}", needs.threads),
    ));
    info.push((
        "ExtraInfoKeyValue1".into(),
        format!("exrcomp.memory_mib={}", needs.memory_mib()),
    ));
    let lines = |pairs: &[(String, String)]| {
        pairs
            .iter()
            .map(|(key, value)| format!("{key}={value}\n"))
            .collect::<String>()
    };
    let plugin = [
        ("Executable".to_string(), value(&exrcomp.to_string_lossy())?),
        ("Arguments".to_string(), arguments.join(" ")),
        ("Shell".to_string(), "default".to_string()),
        ("ShellExecute".to_string(), "True".to_string()),
    ];
    Ok(DeadlineArgs {
        job_info: lines(&info),
        plugin_info: lines(&plugin),
    })
}

/// This executable, for the template's command.
pub fn this_exrcomp() -> Result<PathBuf> {
    std::env::current_exe()
        .map_err(|e| Error::internal(format!("cannot find exrcomp's own path: {e}")))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn files_are_path_parameters_and_braces_elsewhere_go_through_a_string() {
        let task = TaskCommand {
            args: [
                "over",
                "/s/a{{x}}.exr",
                "--layer",
                "l{{y}}",
                "-o",
                "/s/o.exr",
            ]
            .map(String::from)
            .to_vec(),
            files: vec![(1, Flow::In), (5, Flow::Out)],
        };
        let tasks = Tasks::new("1-4", 2, false, None).unwrap();
        let needs = Needs {
            threads: 2,
            memory: 1,
            environment: BTreeMap::new(),
            colour: ColourConfig::File("/s/c{{z}}.ocio".into()),
        };
        let job = openjd_template(
            Path::new("/bin/exrcomp"),
            &task,
            &tasks,
            &needs,
            ("n", "d".into()),
        );
        let args = r#"args: ["over", "{{Param.Input1}}", "--layer", "{{Param.Arg3}}", "-o", "{{Param.Output}}", "--frames", "{{Task.Param.Frames}}"]"#;
        assert!(job.template.contains(args), "{}", job.template);
        assert!(job
            .template
            .contains("- name: Arg3\n  type: STRING\n  default: \"l{{y}}\"\n"));
        assert!(job
            .template
            .contains("- name: Output\n  type: PATH\n  objectType: FILE\n  dataFlow: OUT\n"));
        let values: serde_json::Value = serde_json::from_str(&job.values).unwrap();
        assert_eq!(
            values,
            serde_json::json!({"Exrcomp": "/bin/exrcomp", "Input1": "/s/a{{x}}.exr", "Output": "/s/o.exr", "ColourConfig": "/s/c{{z}}.ocio"})
        );
        assert!(job.template.contains("OCIO: \"{{Param.ColourConfig}}\""));
        assert!(job.bundle_values.starts_with(
            "parameterValues:\n- name: \"ColourConfig\"\n  value: \"/s/c{{z}}.ocio\"\n"
        ));
    }

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
