//! The command line: the operations' subcommands made from their
//! declarations (src/ops/declare.rs), the other commands declared here.

pub mod command_line;
pub mod commands;
pub mod program;

use crate::ops::declare::{Operation, REPEATED};
use crate::run::settings::{parse_level, CompressionName, LayerArgs, PartArgs, RunArgs};
use clap::{Arg, ArgAction, ArgMatches, Args, FromArgMatches, Parser, Subcommand, ValueHint};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// `clap::ValueEnum` for a domain type, here so that the type itself needs
/// no clap: each variant's name on the command line and its help.
macro_rules! value_enum {
    ($ty:ty { $($variant:ident => $name:literal: $help:literal),* $(,)? }) => {
        impl clap::ValueEnum for $ty {
            fn value_variants<'a>() -> &'a [Self] {
                &[$(<$ty>::$variant),*]
            }
            fn to_possible_value(&self) -> Option<clap::builder::PossibleValue> {
                Some(match self {
                    $(<$ty>::$variant => clap::builder::PossibleValue::new($name).help($help)),*
                })
            }
        }
    };
}

/// `--version`: the crate's version and the deflate engines built in, as
/// ZIP output's bytes depend on them (src/io/deflate.rs).
fn version_text() -> String {
    let engines = crate::io::deflate::ENGINES;
    format!("{} (deflate: {engines})", env!("CARGO_PKG_VERSION"))
}

#[derive(Parser)]
#[command(
    name = "exrcomp",
    version = version_text(),
    about = "Streaming OpenEXR sequence compositor"
)]
pub struct Cli {
    /// Worker threads (default: one per core).
    /// (At most a farm worker's: a local run is held to this machine's
    /// cores after parsing, `refuse_local_threads`.)
    #[arg(long, global = true, help_heading = crate::run::settings::RUN_CONTROL, allow_negative_numbers = true, value_parser = crate::params::parse_farm_threads)]
    pub threads: Option<usize>,
    #[command(subcommand)]
    pub command: Command,
}

#[derive(Subcommand)]
pub enum Command {
    /// The operations (src/ops), each made from its declaration.
    #[command(flatten)]
    Op(Invocation),
    /// Flatten a deep file: each pixel's samples composited front to back
    /// (any command reading a deep scanline input flattens it the same way).
    Flatten {
        /// Deep input file or sequence.
        #[arg(value_hint = ValueHint::FilePath)]
        input: String,
        /// Output file or sequence.
        #[arg(value_hint = ValueHint::FilePath, short, long)]
        output: String,
        #[command(flatten)]
        part: PartArgs,
        #[command(flatten)]
        run: RunArgs,
    },
    /// Merge deep files by depth, sample by sample, then flatten.
    Deepmerge {
        /// Two or more deep files or sequences; the first one's header is kept.
        #[arg(value_hint = ValueHint::FilePath, required = true, num_args = 2..)]
        inputs: Vec<String>,
        /// Output file or sequence.
        #[arg(value_hint = ValueHint::FilePath, short, long)]
        output: String,
        #[command(flatten)]
        run: RunArgs,
    },
    /// Write a farm job that runs a command over frame chunks.
    Farm {
        #[command(subcommand)]
        farm: Farm,
    },
    /// Join band files written with --rows into one file, copying their
    /// compressed chunks (nothing is decoded or re-encoded).
    Stitch {
        /// The band files, each written with --rows, in any order.
        #[arg(value_hint = ValueHint::FilePath, required = true, num_args = 2..)]
        bands: Vec<PathBuf>,
        /// The whole file written.
        #[arg(value_hint = ValueHint::FilePath, short, long)]
        output: PathBuf,
    },
    /// Run a job file: a graph of reads, operations and a write, streamed in
    /// one pass (specs/job-format.md).
    Run {
        /// The job file (TOML; its file names are relative to its folder).
        #[arg(value_hint = ValueHint::FilePath)]
        job: PathBuf,
        /// Write here instead of the job's write node's file.
        #[arg(value_hint = ValueHint::FilePath, short, long)]
        output: Option<String>,
        #[command(flatten)]
        run: RunArgs,
    },
    /// Read and write a sequence unchanged but for compression (the codec floor).
    Transcode {
        /// Input file or sequence.
        #[arg(value_hint = ValueHint::FilePath)]
        input: String,
        /// Output file or sequence.
        #[arg(value_hint = ValueHint::FilePath, short, long)]
        output: String,
        /// Level of a mipmapped input (N), or a ripmapped one (X,Y), to
        /// write instead of the full resolution (level 0).
        #[arg(long, value_parser = parse_level)]
        level: Option<exr::math::Vec2<usize>>,
        #[command(flatten)]
        part: PartArgs,
        #[command(flatten)]
        run: RunArgs,
    },
    /// Describe EXR files as exrheader does and check that every chunk decodes.
    Info {
        /// EXR files to describe (not sequences: name each frame).
        #[arg(value_hint = ValueHint::FilePath, required = true)]
        files: Vec<PathBuf>,
        /// One JSON object per file, on a line of its own, with the same facts.
        #[arg(long)]
        json: bool,
    },
    /// Generate a synthetic shot and composite it.
    Demo {
        /// Where the shot is written.
        #[arg(long, default_value = "demo-shot")]
        dir: PathBuf,
        /// Number of frames (1001 on).
        #[arg(long, default_value_t = 24, value_parser = clap::builder::RangedU64ValueParser::<usize>::new().range(1..=100_000))]
        length: usize,
        /// Plate width in pixels.
        #[arg(long, default_value_t = 1920, allow_negative_numbers = true)]
        width: usize,
        /// Plate height in pixels.
        #[arg(long, default_value_t = 1080, allow_negative_numbers = true)]
        height: usize,
        #[command(flatten)]
        run: RunArgs,
    },
    /// Time a job over several runs, each writing afresh: wall and CPU time,
    /// frames/s, bytes/s, peak memory, the machine; compare with a baseline
    /// record (specs/bench.md).
    Bench(BenchArgs),
    /// Write synthetic test plates (a grainy background or a moving foreground).
    Generate {
        /// Output file or sequence.
        #[arg(value_hint = ValueHint::FilePath)]
        output: String,
        /// What the plate shows.
        #[arg(long, value_enum, default_value = "bg")]
        kind: crate::ops::sources::plate::PlateKind,
        /// Width in pixels.
        #[arg(long, default_value_t = 1920, allow_negative_numbers = true)]
        width: usize,
        /// Height in pixels.
        #[arg(long, default_value_t = 1080, allow_negative_numbers = true)]
        height: usize,
        /// Data window origin, as X,Y (display window stays at 0,0).
        #[arg(long, value_parser = parse_origin, default_value = "0,0", allow_hyphen_values = true)]
        origin: (i32, i32),
        /// Sample type of the colour channels.
        #[arg(long, value_enum, default_value = "half")]
        pixel_type: crate::ops::sources::plate::PixelType,
        #[command(flatten)]
        run: RunArgs,
    },
}

#[derive(Args)]
pub struct BenchArgs {
    /// Counted runs.
    #[arg(long, default_value_t = 5, value_parser = clap::builder::RangedU64ValueParser::<usize>::new().range(1..=1000))]
    pub runs: usize,
    /// Runs before them, not counted.
    #[arg(long, default_value_t = 1, value_parser = clap::builder::RangedU64ValueParser::<usize>::new().range(0..=100))]
    pub warmup: usize,
    /// Keep the runs' outputs (their folder is printed) instead of removing them.
    #[arg(long)]
    pub keep: bool,
    /// Drop the inputs from the page cache before each run (measures the storage).
    #[arg(long)]
    pub cold: bool,
    /// Time the standard workload (generated once into the cache folder):
    /// transcode, over, a stack of 4, over + blur, a half-size resize and a
    /// colour conversion.
    #[arg(long)]
    pub standard: bool,
    /// The standard workload's plate size.
    #[arg(long, value_enum, default_value = "1080p")]
    pub size: Size,
    /// The standard workload's frames per job.
    #[arg(long, default_value_t = 4, value_parser = clap::builder::RangedU64ValueParser::<usize>::new().range(1..=1000))]
    pub frames: usize,
    /// Where the standard workload's plates are kept (default: ~/.cache/exrcomp/bench).
    #[arg(long, value_hint = ValueHint::DirPath)]
    pub cache: Option<PathBuf>,
    /// A command's name in the record.
    #[arg(long, default_value = "job")]
    pub name: String,
    /// Write the record here (JSON, specs/bench.md).
    #[arg(long, value_hint = ValueHint::FilePath)]
    pub json: Option<PathBuf>,
    /// An earlier record: exit 1 if a job is slower beyond the tolerance and
    /// the noise, by its ratio to the floor or its CPU per frame.
    #[arg(long, value_hint = ValueHint::FilePath, conflicts_with = "against")]
    pub baseline: Option<PathBuf>,
    /// Another exrcomp: run each job with both in turns, and say whether
    /// this one is faster or slower (exit 1 if slower).
    #[arg(long, value_hint = ValueHint::ExecutablePath)]
    pub against: Option<PathBuf>,
    /// Time no floor beside the jobs (halves the runs; the baseline is then
    /// compared by CPU per frame alone).
    #[arg(long)]
    pub no_floor: bool,
    /// A folder of earlier records (JSON): the HTML report draws each job's
    /// throughput over them.
    #[arg(long, value_hint = ValueHint::DirPath)]
    pub history: Option<PathBuf>,
    /// Percent of the baseline's median a job may be slower by.
    #[arg(long, default_value_t = 5.0, allow_negative_numbers = true, value_parser = parse_tolerance)]
    pub tolerance: f64,
    /// Draw the runs per job (and the baseline's or the other build's) to
    /// this chart, FILE.svg or FILE.png, or a report, FILE.html.
    #[arg(long, value_hint = ValueHint::FilePath, value_parser = parse_chart)]
    pub report: Option<PathBuf>,
    /// Worker threads of the timed runs.
    #[arg(skip)]
    pub threads: Option<usize>,
    /// The exrcomp command to time (after `--`), or a job file.
    #[arg(trailing_var_arg = true, allow_hyphen_values = true)]
    pub command: Vec<String>,
}

fn parse_tolerance(text: &str) -> Result<f64, String> {
    match text.trim_end_matches('%').parse::<f64>() {
        Ok(t) if (0.0..=1000.0).contains(&t) => Ok(t),
        _ => Err(format!(
            "expected a percentage from 0 to 1000, not '{text}'"
        )),
    }
}

/// The standard workload's sizes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Size {
    Hd,
    Uhd,
    Eight,
}

value_enum!(crate::run::report::FarmLog {
    Frames => "frames": "a line per frame: written or kept",
    Openjd => "openjd": "those and openjd_progress: / openjd_status: lines",
    Deadline => "deadline": "those and Progress: N% lines",
});

value_enum!(Size {
    Hd => "1080p": "1920x1080",
    Uhd => "4k": "3840x2160",
    Eight => "8k": "7680x4320",
});

#[derive(Subcommand)]
pub enum Farm {
    /// An Open Job Description job template (`openjd check`, `openjd run`,
    /// AWS Deadline Cloud): one task per chunk, each `--frames CHUNK --resume`.
    Openjd(OpenJdArgs),
    /// An OpenCue outline (JSON, as PyOutline loads it) with one chunked
    /// layer (frames A-B or A-B:STEP); see the README for submitting it.
    Opencue(OpenCueArgs),
    /// Deadline 10 job-info and plugin-info files for the CommandLine
    /// plugin (`deadlinecommand JOBINFO PLUGININFO`): frames A-B or A-B:STEP.
    Deadline(DeadlineArgs),
}

impl Farm {
    pub fn job(&self) -> &FarmArgs {
        match self {
            Farm::Openjd(farm) => &farm.job,
            Farm::Opencue(farm) => &farm.job,
            Farm::Deadline(farm) => &farm.job,
        }
    }

    pub fn job_mut(&mut self) -> &mut FarmArgs {
        match self {
            Farm::Openjd(farm) => &mut farm.job,
            Farm::Opencue(farm) => &mut farm.job,
            Farm::Deadline(farm) => &mut farm.job,
        }
    }
}

/// A local command to run on a farm, in frame chunks: what every farm takes.
/// (An option of one farm only is declared with it, so another refuses it.)
#[derive(Args)]
pub struct FarmArgs {
    /// All the frames, as --frames takes them.
    #[arg(long, allow_hyphen_values = true)]
    pub frames: String,
    /// Frames per task.
    #[arg(long, default_value_t = 10)]
    pub chunk: usize,
    /// The job's name (default: `exrcomp` and the command's name).
    #[arg(long)]
    pub name: Option<String>,
    /// Where the job is written.
    #[arg(value_hint = ValueHint::FilePath, short, long)]
    pub output: Option<PathBuf>,
    /// Threads of each task (the global --threads), set by main.
    #[arg(skip)]
    pub threads: Option<usize>,
    /// The exrcomp command to run, without --frames (after `--`, so that
    /// another farm's option is refused, not taken for the command).
    #[arg(required = true, last = true, allow_hyphen_values = true)]
    pub command: Vec<String>,
}

/// `exrcomp farm openjd`: the options every farm takes and OpenJD's own.
#[derive(Args)]
pub struct OpenJdArgs {
    #[command(flatten)]
    pub job: FarmArgs,
    /// Let the scheduler chunk the frames (a CHUNK[INT] task parameter, the
    /// TASK_CHUNKING extension) instead of listing the chunks.
    #[arg(long)]
    pub task_chunking: bool,
    /// Chunks sized towards this runtime from the ones done (implies
    /// --task-chunking).
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..))]
    pub target_runtime: Option<u32>,
    /// Write a job bundle in this folder instead of -o: `template.yaml` and
    /// `parameter_values.yaml`, as AWS Deadline Cloud's `deadline bundle
    /// submit DIR` takes it.
    #[arg(long, value_hint = ValueHint::DirPath, conflicts_with = "output")]
    pub bundle: Option<PathBuf>,
}

/// `exrcomp farm opencue`: the options every farm takes and OpenCue's own.
#[derive(Args)]
pub struct OpenCueArgs {
    #[command(flatten)]
    pub job: FarmArgs,
    /// The layer's service.
    #[arg(long, default_value = "shell")]
    pub service: String,
}

/// `exrcomp farm deadline`: the options every farm takes.
#[derive(Args)]
pub struct DeadlineArgs {
    #[command(flatten)]
    pub job: FarmArgs,
}

fn parse_chart(text: &str) -> Result<PathBuf, String> {
    match Path::new(text).extension().and_then(|e| e.to_str()) {
        Some("svg" | "png" | "html") => Ok(PathBuf::from(text)),
        _ => Err(format!(
            "'{text}': a chart is written as FILE.svg or FILE.png, a report as FILE.html"
        )),
    }
}

fn parse_origin(text: &str) -> Result<(i32, i32), String> {
    let (x, y) = text.split_once(',').ok_or("expected X,Y")?;
    Ok((
        x.trim().parse().map_err(|_| "bad X")?,
        y.trim().parse().map_err(|_| "bad Y")?,
    ))
}

/// An operation as the command line gave it.
pub struct Invocation {
    pub op: &'static Operation,
    /// In the declared order (a repeated last input as often as given).
    pub inputs: Vec<String>,
    pub output: String,
    /// The parameters given or defaulted, as text (switches: "true").
    pub values: BTreeMap<&'static str, String>,
    pub straight: bool,
    pub layers: LayerArgs,
    pub run: RunArgs,
}

/// `--max-radius` for `max_radius`.
fn option_name(name: &str) -> String {
    name.replace('_', "-")
}

/// An operation's subcommand: its inputs, `-o`, its parameters, then the
/// shared options it takes.
fn subcommand(op: &'static Operation) -> clap::Command {
    let mut command = clap::Command::new(op.name).allow_negative_numbers(true);
    for (i, input) in op.inputs.iter().enumerate() {
        let mut arg = Arg::new(input.name)
            .help(input.help)
            .value_name(input.name.to_uppercase())
            .value_hint(ValueHint::FilePath)
            .required(true);
        if input.named {
            arg = arg.long(option_name(input.name));
        }
        if op.repeats && i + 1 == op.inputs.len() {
            arg = arg.num_args(2..).action(ArgAction::Append);
        }
        command = command.arg(arg);
    }
    command = command.arg(
        Arg::new("output")
            .short('o')
            .long("output")
            .help("Output file or sequence")
            .value_name("OUTPUT")
            .value_hint(ValueHint::FilePath)
            .required(true),
    );
    for param in op.params {
        let mut arg = Arg::new(param.name)
            .long(option_name(param.name))
            .value_name(param.name.to_uppercase())
            .help(param.help.trim());
        if param.flag {
            arg = arg.action(ArgAction::SetTrue);
        } else {
            if param.repeats {
                arg = arg.action(ArgAction::Append);
            }
            let check = param.check;
            arg = arg
                .required(param.required())
                // Negative lists (`--lift -0.1,0,0`) are values, not options.
                .allow_hyphen_values(true)
                .value_parser(move |text: &str| check(text).map(|()| text.to_string()));
            if let Some(default) = param.default {
                arg = arg.default_value(default);
            }
        }
        // A file (a colour config, a LUT) is made absolute in a farm job.
        if param.file {
            arg = arg.value_hint(ValueHint::FilePath);
        }
        // Merge's operator has always been `--op` on the command line.
        if param.name == "operator" {
            arg = arg.visible_alias("op");
        }
        command = command.arg(arg);
    }
    if op.straight {
        command = command.arg(
            Arg::new("straight")
                .long("straight")
                .action(ArgAction::SetTrue)
                .help("Inputs and output are unpremultiplied (straight) colour"),
        );
    }
    command = match op.layers {
        true => LayerArgs::augment_args(command),
        false => PartArgs::augment_args(command),
    };
    // After the shared options, whose own doc would be taken as the about.
    RunArgs::augment_args(command).about(op.about)
}

impl FromArgMatches for Invocation {
    fn from_arg_matches(matches: &ArgMatches) -> Result<Self, clap::Error> {
        let unknown = || clap::Error::new(clap::error::ErrorKind::InvalidSubcommand);
        let (name, m) = matches.subcommand().ok_or_else(unknown)?;
        let op = crate::ops::find(name).ok_or_else(unknown)?;
        let texts = |id: &str| -> Vec<String> {
            m.get_many::<String>(id)
                .into_iter()
                .flatten()
                .cloned()
                .collect()
        };
        let values = op
            .params
            .iter()
            .filter_map(|p| match (p.flag, p.repeats) {
                (true, _) => m.get_flag(p.name).then(|| (p.name, "true".to_string())),
                (false, false) => m.get_one::<String>(p.name).map(|v| (p.name, v.clone())),
                (false, true) => (m.get_many::<String>(p.name)).map(|values| {
                    let values: Vec<&str> = values.map(String::as_str).collect();
                    (p.name, values.join(&REPEATED.to_string()))
                }),
            })
            .collect();
        Ok(Invocation {
            op,
            inputs: op.inputs.iter().flat_map(|i| texts(i.name)).collect(),
            output: texts("output").concat(),
            values,
            straight: op.straight && m.get_flag("straight"),
            layers: match op.layers {
                true => LayerArgs::from_arg_matches(m)?,
                false => LayerArgs {
                    part: PartArgs::from_arg_matches(m)?,
                    ..LayerArgs::default()
                },
            },
            run: RunArgs::from_arg_matches(m)?,
        })
    }

    fn update_from_arg_matches(&mut self, matches: &ArgMatches) -> Result<(), clap::Error> {
        *self = Self::from_arg_matches(matches)?;
        Ok(())
    }
}

impl Subcommand for Invocation {
    fn augment_subcommands(command: clap::Command) -> clap::Command {
        crate::ops::ALL
            .iter()
            .fold(command, |command, op| command.subcommand(subcommand(op)))
    }

    fn augment_subcommands_for_update(command: clap::Command) -> clap::Command {
        Self::augment_subcommands(command)
    }

    fn has_subcommand(name: &str) -> bool {
        crate::ops::find(name).is_some()
    }
}

value_enum!(crate::engine::sources::MissingPolicy {
    Error => "error": "Stop before any work, listing the missing frames",
    Skip => "skip": "Leave out the output frames that miss an input",
    Hold => "hold": "Use the nearest earlier frame of that input (the nearest later one before the first)",
    Black => "black": "Use transparent black, shaped like the nearest frame of that input",
});

value_enum!(crate::ops::sources::plate::PlateKind {
    Bg => "bg": "Opaque grainy gradient with a checker pattern; RGBA and Z",
    Fg => "fg": "A soft-edged disc moving across a transparent frame; premultiplied RGBA, Z and screen-space motion vectors (forward.u, forward.v)",
    Object => "object": "Differential rendering's object alone: a shaded ball above the middle of a transparent frame; RGBA and Z",
    Proxy => "proxy": "The proxy scene without the object: an opaque grey ground; RGBA, Z",
    Shadowed => "shadowed": "The object over the proxy with the ball's soft shadow on the ground",
    Set => "set": "The demo's background for depth of field: a checker receding from Z 3 (bottom) to 60 (top), with highlights; RGBA and Z",
    Ball => "ball": "The demo's foreground for motion blur: a striped ball circling fast; premultiplied RGBA, Z, forward.u, forward.v",
});

value_enum!(crate::ops::sources::plate::PixelType {
    Half => "half": "16-bit half floats",
    Float => "float": "32-bit floats",
});

/// The command line: the declared commands, each offering the shared
/// options that apply to it (`NOT_APPLICABLE`) and saying what its output's
/// compression is by default.
pub fn command() -> clap::Command {
    use clap::CommandFactory;
    let mut command = Cli::command();
    let names: Vec<String> = command
        .get_subcommands()
        .map(|c| c.get_name().to_string())
        .collect();
    for name in names {
        command = command.mut_subcommand(&name, |mut sub| {
            for (id, _) in not_applicable(&name) {
                sub = sub.mut_arg(id, |arg| arg.hide(true));
            }
            match compression_default(&name) {
                Some(default) => sub.mut_arg("compression", |arg| {
                    arg.help(format!(
                        "Output compression: {} (default: {default})",
                        CompressionName::names()
                    ))
                }),
                None => sub,
            }
        });
    }
    command
}

/// The shared options that do not apply to command `name`, and why: they
/// are not offered (hidden, and refused by `refuse_not_applicable`).
fn not_applicable(name: &str) -> Vec<(&'static str, &'static str)> {
    let reads_none = "it reads no input";
    let own_shot = "it makes its own shot (--length sets its frames)";
    let several = "it reads several inputs (--all-parts is for operations of one)";
    match name {
        "generate" => ["missing", "keep_going", "all_parts"]
            .map(|id| (id, reads_none))
            .to_vec(),
        "demo" => [
            "frames",
            "chunk_from",
            "missing",
            "keep_going",
            "all_parts",
            "rows",
            "resume",
            "dry_run",
        ]
        .map(|id| (id, own_shot))
        .to_vec(),
        "deepmerge" => vec![("all_parts", several)],
        _ => match crate::ops::find(name) {
            Some(op) if op.inputs.len() > 1 || op.repeats => vec![("all_parts", several)],
            _ => Vec::new(),
        },
    }
}

/// What command `name` writes when `--compression` is not given.
fn compression_default(name: &str) -> Option<String> {
    Some(match name {
        "generate" | "demo" => "zip".to_string(),
        "transcode" | "flatten" => "the input's".to_string(),
        "deepmerge" => "the first input's".to_string(),
        "run" => "the job's write node's `compression`, else its header input's".to_string(),
        _ => {
            let op = crate::ops::find(name)?;
            let input = &op.inputs[op.header.unwrap_or(op.inputs.len() - 1)];
            format!(
                "the {} input's, whose header the output keeps",
                input.name.to_uppercase()
            )
        }
    })
}

/// A usage error for a shared option given to a command it does not apply to.
pub fn refuse_not_applicable(matches: &ArgMatches) -> Result<(), clap::Error> {
    let Some((name, sub)) = matches.subcommand() else {
        return Ok(());
    };
    for (id, why) in not_applicable(name) {
        if sub.value_source(id) == Some(clap::parser::ValueSource::CommandLine) {
            let mut command = command();
            let command = command
                .find_subcommand_mut(name)
                .expect("parsed, so declared");
            return Err(command.error(
                clap::error::ErrorKind::ArgumentConflict,
                format!("--{} does not apply to `{name}`: {why}", option_name(id)),
            ));
        }
    }
    Ok(())
}

/// `--threads` beyond this machine's bound (`parse_threads`), but for
/// `farm`, whose tasks run on farm workers (`parse_farm_threads`).
fn refuse_local_threads(matches: &ArgMatches) -> Result<(), clap::Error> {
    let Some((name, sub)) = matches.subcommand() else {
        return Ok(());
    };
    let given = sub
        .try_get_one::<usize>("threads")
        .ok()
        .flatten()
        .or(matches.try_get_one::<usize>("threads").ok().flatten());
    match given {
        Some(threads) if name != "farm" => crate::params::parse_threads(&threads.to_string())
            .map(drop)
            .map_err(|why| {
                command().error(
                    clap::error::ErrorKind::ValueValidation,
                    format!("invalid value '{threads}' for '--threads': {why}"),
                )
            }),
        _ => Ok(()),
    }
}

/// The command line parsed, or the process ended with clap's message.
pub fn parse<I: Into<std::ffi::OsString> + Clone>(args: impl IntoIterator<Item = I>) -> Cli {
    let matches = command().get_matches_from(args);
    refuse_not_applicable(&matches)
        .and_then(|()| refuse_local_threads(&matches))
        .and_then(|()| Cli::from_arg_matches(&matches))
        .unwrap_or_else(|e| e.exit())
}
