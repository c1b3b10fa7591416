//! The run layer, between the front ends (src/cli/, src/tools/) and the
//! engine: engine jobs made from inputs, a graph and the run settings
//! (src/run/settings.rs), their frames resolved and inputs checked, then
//! run with their progress and summary (src/run/report.rs).

pub mod job_file;
pub mod job_run;
pub mod report;
pub mod settings;

use settings::{FrameHook, LayerArgs, RunArgs};

use crate::engine::fingerprint;
use crate::engine::frame_plan::{plan_parts, FramePlan};
use crate::engine::graph::NodeId;
use crate::engine::graph::{Graph, GraphBuilder, Node, Op};
use crate::engine::interrupt;
use crate::engine::luminance_chroma;
use crate::engine::memory_bound::memory_bound;
use crate::engine::pipeline;
use crate::engine::pipeline::Events;
use crate::engine::plan::{
    frame_label, FirstFile, FrameSources, HeaderBase, Job, OutputBlocks, Review, SlateFrame, Source,
};
use crate::engine::sources::{default_frames, resolve};
use crate::error::{Error, Kind, Result};
use crate::io::attributes::Edits;
use crate::io::burn_in::BurnIn;
use crate::io::media::{Format, Media};
use crate::io::movie::Movie;
use crate::io::overwrite::{refuse_overwriting, FileSet};
use crate::io::parts::{choose_part, split_part};
use crate::io::reader::ExrFile;
use crate::io::sequence::{
    chunk_from, format_frame_list, parse_frame_list, split_time, FramePattern,
};
use crate::io::text::Utf8Text;
use crate::io::writer::remove_stale_temporaries;
use crate::ops::declare::{Args, Operation};
use crate::ops::layers::Selection;
use crate::ops::resize::{passes, Filter, Target};
use crate::ops::sources::plate::Plate;
use crate::ops::sources::slate::Slate;
use crate::params::DEFAULT_DWA_LEVEL;
use crate::run::report::{count, FarmLog, Outcome, Report, Summary};
use exr::meta::attribute::IntegerBounds;
use exr::prelude::Compression;
use std::collections::BTreeSet;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Arc, Mutex};

/// What a dry run of a frame-writing command found.
pub struct DryRun {
    /// The most bytes any of its frames would hold at once (`memory_bound`).
    pub memory: u64,
    /// Every file it would read, and every frame it would write.
    pub reads: Vec<PathBuf>,
    pub writes: Vec<PathBuf>,
    /// Frames already at the output that another job (or tool) made:
    /// `--resume` writes them again (specs/overnight.md).
    pub others: Vec<PathBuf>,
}

/// Operation `op` with parameters `values` (as typed) on `inputs`.
pub fn add(
    graph: &mut GraphBuilder,
    op: &'static Operation,
    values: &[(&'static str, &str)],
    inputs: &[NodeId],
) -> Result<NodeId> {
    let args = Args {
        op: op.name,
        values: values.iter().map(|&(k, v)| (k, v.to_string())).collect(),
        layers: Selection::default(),
        straight: false,
        job_file: false,
    };
    (op.build)(&args, graph, inputs).map_err(Error::usage)
}

pub fn working_folder() -> Result<PathBuf> {
    std::env::current_dir().map_err(|e| Error::usage(format!("no working folder: {e}")))
}

/// The frames `--frames` names, cut to the chunk `--chunk-from` names.
pub fn frame_list(run: &RunArgs) -> Result<Option<Vec<i64>>> {
    let Some(text) = &run.frames else {
        return match run.chunk_from {
            Some(_) => Err(Error::usage(
                "--chunk-from cuts the frames of --frames: give them",
            )),
            None => Ok(None),
        };
    };
    let frames = parse_frame_list(text)?;
    Ok(Some(match run.chunk_from {
        Some((first, count)) => chunk_from(&frames, first, count)?,
        None => frames,
    }))
}

/// A job's inputs as given: sequences (`file.exr:PART` picks a part, else a
/// job file's read's own `part` key, else `--part`), and first files that a
/// measuring job (`Operation::measure`) already opened, taken over rather
/// than opened again.
#[derive(Clone, Copy, Default)]
pub struct JobInputs<'a> {
    pub texts: &'a [String],
    pub read_parts: &'a [Option<String>],
    pub opened: &'a [Option<FirstFile>],
}

impl<'a> JobInputs<'a> {
    pub fn of(texts: &'a [String]) -> Self {
        JobInputs {
            texts,
            ..JobInputs::default()
        }
    }
}

/// A job over input sequences; the header comes from input `header_from`.
pub fn input_job(
    given: JobInputs,
    output: &str,
    graph: Graph,
    header_from: usize,
    layers: &LayerArgs,
    run: &RunArgs,
) -> Result<(Job, Summary)> {
    // A proxy: each input resized as it is read (the operations' lengths
    // were scaled when they were built).
    let graph = match run.proxy_scale {
        Some(factor) => graph.after_inputs(|graph, _, input| {
            passes(Target::Scale(factor), Filter::Box, input, graph)
        }),
        None => graph,
    };
    let mut inputs = Vec::new();
    let mut parts = Vec::new();
    let mut times = Vec::new();
    let texts = given.texts;
    for (i, text) in texts.iter().enumerate() {
        let (rest, time) = split_time(text)?;
        let (path, part) = split_part(rest);
        let pattern = FramePattern::parse(path)?;
        times.push(time.pinned(&pattern)?);
        inputs.push(pattern);
        parts.push(
            part.map(str::to_string)
                .or_else(|| given.read_parts.get(i).cloned().flatten())
                .or_else(|| layers.part.part.clone()),
        );
    }
    let output = FramePattern::output(output)?;
    let mut attributes = edits(run)?;
    let frames = match frame_list(run)? {
        Some(frames) => frames,
        None => default_frames(&inputs, &times)?,
    };
    // The shot's frames are the inputs' (all of them without --frames), so
    // that each chunk of a farm job counts its timecode from the same first
    // frame, and only the chunk starting there writes the slate.
    let shot = match &run.frames {
        Some(_) if attributes.needs_anchor() || run.write.slate => default_frames(&inputs, &times)?,
        _ => frames.clone(),
    };
    if attributes.needs_anchor() {
        attributes.anchor(shot[0]);
    }
    check_frame_count(&frames, &output)?;
    let slate = slate_frame(run, &output, &frames, &shot)?;
    if run.write.all_parts {
        check_all_parts(texts, &parts, layers)?;
    }
    let media = review(&output, run)?;
    let resolved = resolve(&inputs, &times, &frames, run.missing)?;
    let first = first_files(&inputs, &output, &resolved.frames, given.opened);
    let luminance = luminance_inputs(&first, &parts, layers, run.write.all_parts, &graph);
    let graph = luminance_chroma::colour_inputs(graph, &luminance, layers.view.as_deref());
    let reads = Job {
        merged: vec![Vec::new(); inputs.len()],
        inputs,
        times,
        parts,
        view: layers.view.clone(),
        level: layers.level,
        first_files: first,
        ..engine_job(
            output,
            resolved.frames,
            graph,
            HeaderBase::Input(header_from),
        )
    };
    let job = Job {
        compression: parse_compression(run)?,
        ..written_as(reads, run, attributes, media, slate)
    };
    let summary = Summary {
        warnings: crate::engine::assumptions::warnings(&job, texts),
        named: frames.len(),
        skipped: resolved.skipped,
        replaced: resolved.replaced,
        ..Summary::default()
    };
    Ok((job, summary))
}

/// `--all-parts` runs a one-input operation on every part of that input:
/// an operation of several inputs would have to pair parts across files, so
/// it is refused, as is choosing a part or view as well.
fn check_all_parts(texts: &[String], parts: &[Option<String>], layers: &LayerArgs) -> Result<()> {
    if texts.len() != 1 {
        return Err(Error::usage(format!(
            "--all-parts runs an operation of one input on every part of it; this one reads {} \
             inputs: choose their parts with FILE:PART or --part instead",
            texts.len()
        )));
    }
    if parts[0].is_some() || layers.view.is_some() {
        return Err(Error::usage(
            "--all-parts works on every part: give no FILE:PART, --part or --view with it",
        ));
    }
    Ok(())
}

/// Per input, its first file read (`FirstFile`), open: opened once for
/// what is read of it before the run (the luminance weights, the
/// assumptions' warnings) and by the plan of the frame reading it. None
/// where it cannot be read (that plan opens it again and reports why) or
/// every frame is black. One already in `opened` is not opened again.
fn first_files(
    inputs: &[FramePattern],
    output: &FramePattern,
    frames: &[FrameSources],
    opened: &[Option<FirstFile>],
) -> Vec<Option<FirstFile>> {
    (0..inputs.len())
        .map(|i| {
            let (frame, read) = frames.iter().find_map(|f| match f.inputs[i] {
                Source::Frame(read) => Some((f.frame, read)),
                Source::Black(_) => None,
            })?;
            let path = inputs[i].path(read);
            let file = match opened.iter().flatten().find(|f| f.file.path == path) {
                Some(first) => first.file.clone(),
                None => Arc::new(ExrFile::open(&path, frame_label(output, inputs, read)).ok()?),
            };
            Some(FirstFile { frame, read, file })
        })
        .collect()
}

/// Per input, the luminance weights of its first frame when the job has
/// operations and that frame is luminance/chroma or luminance only (with
/// `--all-parts`, any part of it: the conversion passes RGB parts as they
/// are): the operations read it as RGB. A frame that cannot be read is left
/// to the run.
fn luminance_inputs(
    first: &[Option<FirstFile>],
    parts: &[Option<String>],
    layers: &LayerArgs,
    all_parts: bool,
    graph: &Graph,
) -> Vec<Option<[f32; 3]>> {
    if !graph.nodes.iter().any(|n| matches!(n, Node::Op { .. })) {
        return vec![None; first.len()];
    }
    (0..first.len())
        .map(|i| {
            let file = &first[i].as_ref()?.file;
            let read = match all_parts {
                true => 0..file.meta.headers.len(),
                false => {
                    let part = choose_part(file, parts[i].as_deref(), layers.view.as_deref());
                    part.ok().map(|p| p..p + 1)?
                }
            };
            let header = read
                .map(|part| file.header(part))
                .find(|header| luminance_chroma::is_luminance(header, layers.view.as_deref()))?;
            Some(luminance_chroma::luminance_weights(
                header.shared_attributes.chromaticities.as_ref(),
            ))
        })
        .collect()
}

pub fn check_frame_count(frames: &[i64], output: &FramePattern) -> Result<()> {
    if frames.len() > 1 && !output.is_sequence() && output.format() != Some(Format::Movie) {
        return Err(Error::usage(format!(
            "{} frames but the output {} has no frame number (use #### or %04d)",
            frames.len(),
            output.display()
        )));
    }
    Ok(())
}

pub fn plate_job(
    plate: Plate,
    output: FramePattern,
    frames: Vec<i64>,
    run: &RunArgs,
) -> Result<Job> {
    let display = plate.display_window();
    let media = review(&output, run)?;
    let mut attributes = edits(run)?;
    attributes.anchor(frames[0]);
    let slate = slate_frame(run, &output, &frames, &frames)?;
    let compression = parse_compression(run)?.unwrap_or(Compression::ZIP16);
    let job = sourced_job(plate, display, output, frames, compression);
    Ok(written_as(job, run, attributes, media, slate))
}

/// A job of no inputs: `source` (an op of none) over `display` for
/// `frames`, into `output` (a generated plate, a slate), written as a run
/// without options writes until the caller says otherwise.
fn sourced_job(
    source: impl Op + 'static,
    display: IntegerBounds,
    output: FramePattern,
    frames: Vec<i64>,
    compression: Compression,
) -> Job {
    let mut graph = GraphBuilder::default();
    graph.add(source, &[]);
    let frames = frames
        .into_iter()
        .map(|frame| FrameSources {
            frame,
            inputs: Vec::new(),
        })
        .collect();
    Job {
        compression: Some(compression),
        ..engine_job(output, frames, graph.finish(), HeaderBase::New(display))
    }
}

/// The one engine job literal: `graph` over `frames` into `output`, reading
/// nothing yet, written as a run without options writes.
fn engine_job(
    output: FramePattern,
    frames: Vec<FrameSources>,
    graph: Graph,
    header_base: HeaderBase,
) -> Job {
    Job {
        inputs: Vec::new(),
        times: Vec::new(),
        merged: Vec::new(),
        parts: Vec::new(),
        view: None,
        level: None,
        output,
        frames,
        graph,
        compression: None,
        header_base,
        blocks: OutputBlocks::FollowInput,
        strip_rows: None,
        zip_level: crate::io::deflate::DEFAULT_LEVEL,
        resume: false,
        keep_going: false,
        rows: None,
        max_output_pixels: None,
        all_parts: false,
        attributes: Edits::default(),
        media: None,
        slate: None,
        first_files: Vec::new(),
    }
}

/// `job` written as `run` says, with its attribute edits, review media and
/// slate.
fn written_as(
    job: Job,
    run: &RunArgs,
    attributes: Edits,
    media: Option<Review>,
    slate: Option<SlateFrame>,
) -> Job {
    Job {
        blocks: run.blocks(),
        strip_rows: run.strip_rows,
        zip_level: run.zip_level,
        resume: run.resume,
        keep_going: run.keep_going,
        rows: run.rows,
        max_output_pixels: run.max_output_pixels,
        all_parts: run.write.all_parts,
        attributes,
        media,
        slate,
        ..job
    }
}

/// The slate `run` writes, if it asks for one and starts at the shot's first
/// frame: numbered one before it, introducing `shot`'s frames. Its number
/// must be a file of its own: the output a sequence, not one of its frames.
fn slate_frame(
    run: &RunArgs,
    output: &FramePattern,
    frames: &[i64],
    shot: &[i64],
) -> Result<Option<SlateFrame>> {
    if !run.write.slate || frames[0] != shot[0] {
        return Ok(None);
    }
    let frame = shot[0] - 1;
    // A movie's slate is its first frame.
    let own_file = output.is_sequence() || output.format() == Some(Format::Movie);
    if !own_file || frames.contains(&frame) {
        return Err(Error::usage(format!(
            "--slate writes frame {frame} before the shot's first: the output {} needs a frame \
             number (####) and no frame {frame} of its own",
            output.display()
        )));
    }
    let range = format_frame_list(shot);
    Ok(Some(SlateFrame { frame, range }))
}

/// The plans of `job`'s first frame when the run needs them before the
/// pipeline (for its slate), which then does not plan that frame again.
/// Without a slate the pipeline plans it: its errors are that frame's.
fn first_plans(job: &Job) -> Result<Option<Vec<FramePlan>>> {
    let movie = job.media.as_ref().and_then(|r| r.movie.as_ref());
    let Some(first) = job.frames.first() else {
        return Ok(None);
    };
    if job.slate.is_none() && movie.is_none() {
        return Ok(None);
    }
    let plans = plan_parts(job, first)?;
    // A movie's rate and timecode are its first frame's.
    if let Some(movie) = movie {
        movie.time_from(&plans[0].header, job.slate.is_some());
    }
    Ok(Some(plans))
}

/// The job writing `job`'s slate, from its first frame's `plans`: a black
/// frame of its display window, in its output's format, with the job's
/// metadata.
fn slate_job(job: &Job, plans: Option<&Vec<FramePlan>>) -> Result<Option<Job>> {
    let (Some(slate), Some(plans)) = (&job.slate, plans) else {
        return Ok(None);
    };
    let header = &plans[0].header;
    let display = header.shared_attributes.display_window;
    let set: Vec<&str> = job.attributes.set.iter().map(|a| a.name.as_str()).collect();
    let lines = crate::ops::sources::slate::lines(&job.output, &job.inputs, &set, slate, header);
    let source = Slate::new(display, &lines);
    let (output, frames) = (job.output.clone(), vec![slate.frame]);
    Ok(Some(Job {
        blocks: job.blocks,
        strip_rows: job.strip_rows,
        zip_level: job.zip_level,
        resume: job.resume,
        rows: job.rows,
        attributes: job.attributes.clone(),
        media: job.media.clone().map(|review| Review {
            burn_in: None,
            ..review
        }),
        ..sourced_job(source, display, output, frames, header.compression)
    }))
}

/// How `output` is written when it names review media (PNG, JPEG, TIFF, a
/// movie) or DPX,
/// from `run`'s options; options that do not apply to its format, and
/// EXR-only ways of writing, are refused.
fn review(output: &FramePattern, run: &RunArgs) -> Result<Option<Review>> {
    let format = output.format().unwrap_or(Format::Exr);
    let given: Vec<&str> = [
        ("--quality", run.write.quality.is_some()),
        ("--bits", run.write.bits.is_some()),
        ("--transfer", run.write.transfer.is_some()),
        ("--burn-in", run.write.burn_in.is_some()),
        ("--burn-in-corner", run.write.burn_in_corner.is_some()),
        ("--codec", run.write.codec.is_some()),
    ]
    .into_iter()
    .filter_map(|(name, given)| given.then_some(name))
    .collect();
    if format == Format::Exr {
        return match given.first() {
            Some(name) => Err(Error::usage(format!(
                "{name} applies to review media and DPX outputs (.png, .jpg, .tif, .mov, .mp4, \
                 .dpx), not {}",
                output.display()
            ))),
            None => Ok(None),
        };
    }
    let exr_only = [
        ("--compression", run.write.compression.is_some()),
        ("--dwa-level", run.dwa_level.is_some()),
        ("--tile", run.write.tile.is_some()),
        ("--rows", run.rows.is_some()),
        ("--all-parts", run.write.all_parts),
    ];
    if let Some((name, _)) = exr_only.iter().find(|(_, given)| *given) {
        return Err(Error::usage(format!(
            "{name} applies to EXR outputs, not {}",
            output.display()
        )));
    }
    let (media, movie) = match format {
        Format::Movie => movie(output, run)?,
        _ if run.write.codec.is_some() => {
            return Err(Error::usage(format!(
                "--codec applies to movies (.mov, .mp4), not {}",
                output.display()
            )))
        }
        _ => (
            Media::new(
                format,
                run.write.bits,
                run.write.quality,
                run.write.transfer,
            )
            .map_err(|e| Error::usage(format!("{}: {e}", output.display())))?,
            None,
        ),
    };
    if format == Format::Dpx && run.write.burn_in.is_some() {
        return Err(Error::usage(format!(
            "--burn-in applies to review media outputs (.png, .jpg, .tif, .mov, .mp4), not {}",
            output.display()
        )));
    }
    let burn_in = run
        .write
        .burn_in
        .as_deref()
        .map(|text| BurnIn::parse(text, run.write.burn_in_corner.unwrap_or_default()))
        .transpose()
        .map_err(Error::usage)?;
    Ok(Some(Review {
        media,
        burn_in,
        movie,
    }))
}

/// The review media and the movie of a movie output: one file, whose
/// codec sets its bits.
fn movie(output: &FramePattern, run: &RunArgs) -> Result<(Media, Option<Arc<Movie>>)> {
    let refused = [
        ("--bits", run.write.bits.is_some()),
        ("--quality", run.write.quality.is_some()),
    ];
    if let Some((name, _)) = refused.iter().find(|(_, given)| *given) {
        return Err(Error::usage(format!(
            "{name} does not apply to movies ({}): --codec sets how they are encoded",
            output.display()
        )));
    }
    if output.is_sequence() {
        return Err(Error::usage(format!(
            "{}: a movie is one file, named without a frame number",
            output.display()
        )));
    }
    // A movie has no frame numbers: a frame left out would shorten it and
    // shift every later frame's timecode, unseen.
    if run.missing == crate::engine::sources::MissingPolicy::Skip {
        return Err(Error::usage(format!(
            "{}: --missing skip would leave frames out of the movie, unseen \
             (it has no frame numbers): give --missing hold or --missing black",
            output.display()
        )));
    }
    let movie = Movie::new(&output.path(0), run.write.codec)?;
    Ok((movie.media(run.write.transfer), Some(Arc::new(movie))))
}

/// The attribute edits `run` asks for.
fn edits(run: &RunArgs) -> Result<Edits> {
    Edits::new(
        run.write.erase_attribs.clone(),
        run.write.attribs.clone(),
        run.write.fps,
        run.write.timecode,
    )
    .map_err(Error::usage)
}

fn parse_compression(run: &RunArgs) -> Result<Option<Compression>> {
    let dwa_level = run.dwa_level.unwrap_or(DEFAULT_DWA_LEVEL);
    let compression = run.write.compression.map(|c| c.compression(dwa_level));
    let dwa = matches!(
        compression,
        Some(Compression::DWAA(_) | Compression::DWAB(_))
    );
    if run.dwa_level.is_some() && !dwa {
        return Err(Error::usage(
            "--dwa-level applies to dwaa and dwab output: give --compression dwaa or dwab",
        ));
    }
    Ok(compression)
}

/// Runs `job`, prints its summary, and turns failed frames or an
/// interruption into the run's error (and exit code). A dry run plans every
/// frame and gives what it found.
pub fn run_job(job: &Job, label: &str, run: &RunArgs, summary: Summary) -> Result<Option<DryRun>> {
    let mut first = first_plans(job)?;
    let slate = slate_job(job, first.as_ref())?;
    let (reads, mut writes) = job.files();
    writes.extend(slate.iter().flat_map(|slate| slate.files().1));
    refuse_overwriting(reads.iter().cloned(), writes.iter().cloned())?;
    if run.dry_run {
        if !run.quiet {
            for warning in &summary.warnings {
                eprintln!("exrcomp: warning: {warning}");
            }
        }
        let (mut bound, mut others) = (0, Vec::new());
        let media = job.media.as_ref().map(|r| r.media.format);
        for sources in &job.frames {
            let plans = match first.take() {
                Some(plans) => plans,
                None => plan_parts(job, sources)?,
            };
            let output = &plans[0].output;
            if fingerprint::made_by(output, media, &plans[0].fingerprint) == Some(false)
                && !others.contains(output)
            {
                others.push(output.clone());
            }
            for plan in plans {
                bound = memory_bound(&plan, job).max(bound);
            }
        }
        if !run.quiet {
            if let Some(slate) = &slate {
                print!("{}", dry_run_listing(slate, run.json));
            }
            print!("{}", dry_run_listing(job, run.json));
            eprintln!(
                "{label}: would write {} to {}, holding at most {} MiB at once",
                count(writes.len(), "frame"),
                job.output.display(),
                bound.div_ceil(1 << 20)
            );
            if !others.is_empty() {
                eprintln!("exrcomp: warning: {}", others_made(&others));
            }
        }
        return Ok(Some(DryRun {
            memory: bound,
            reads,
            writes: writes.into_iter().map(|(_, path)| path).collect(),
            others,
        }));
    }
    let written = write_all(job, slate.as_ref(), label, run, summary, first);
    // A movie is placed once every frame is in it, else removed.
    match (job.media.as_ref().and_then(|r| r.movie.as_ref()), &written) {
        (Some(movie), Ok(())) => movie.finish()?,
        (Some(movie), Err(_)) => movie.abort(),
        (None, _) => {}
    }
    written.map(|()| None)
}

/// Writes `job`'s frames after its slate; a frame failed or an
/// interruption is the run's error.
fn write_all(
    job: &Job,
    slate: Option<&Job>,
    label: &str,
    run: &RunArgs,
    summary: Summary,
    first: Option<Vec<FramePlan>>,
) -> Result<()> {
    if let Some(slate) = slate {
        write_slate(slate, label, run)?;
    }
    let (report, summary) = run_with_progress(job, label, run, summary, first)?;
    planted_delay(label, summary.seconds);
    report.finish(&summary);
    if summary.interrupted {
        return Err(Error::new(
            Kind::Interrupted,
            "interrupted; no partial frame was left",
        ));
    }
    if !summary.failed.is_empty() {
        let frames: Vec<i64> = summary.failed.iter().map(|(f, _)| *f).collect();
        // A bug outranks bad input: it is the one to report.
        let kind = match summary.failed.iter().any(|(_, e)| e.kind == Kind::Internal) {
            true => Kind::Internal,
            false => Kind::Input,
        };
        return Err(Error::new(
            kind,
            format!(
                "{} failed: {}",
                count(frames.len(), "frame"),
                format_frame_list(&frames)
            ),
        ));
    }
    Ok(())
}

/// A warning that `files`, frames a job would write, are there already,
/// made by another job or tool.
pub fn others_made(files: &[PathBuf]) -> String {
    let name = |i: usize| files[i].display().to_string();
    let which = match files.len() {
        1 => name(0),
        n => format!("{} ... {}", name(0), name(n - 1)),
    };
    format!(
        "{} already at the output another job or tool made ({which}): --resume writes them again",
        count(files.len(), "frame"),
    )
}

/// Writes (or with --resume keeps) the slate, quietly: the run's report
/// counts its own frames.
fn write_slate(slate: &Job, label: &str, run: &RunArgs) -> Result<()> {
    let quiet = RunArgs {
        quiet: true,
        // Its line, but no progress of its own: the run's counts its frames.
        progress: run.progress.map(|_| FarmLog::Frames),
        on_frame: None,
        ..run.clone()
    };
    let (_, summary) = run_with_progress(slate, label, &quiet, Summary::default(), None)?;
    if summary.interrupted {
        return Err(Error::new(
            Kind::Interrupted,
            "interrupted; no partial frame was left",
        ));
    }
    match summary.failed.first() {
        Some((frame, e)) => Err(Error::new(e.kind, format!("slate {frame}: {e}"))),
        None => Ok(()),
    }
}

/// Test builds only, planted regressions for `bench`'s tests, each
/// `[COMMAND:]AMOUNT`, in every run or in `COMMAND`'s only (not the bench's
/// floor, a transcode, when another command is named):
/// `EXRCOMP_TEST_DELAY` makes a run AMOUNT seconds slower, asleep;
/// `EXRCOMP_TEST_WORK` makes it slower by AMOUNT as a fraction of the run's
/// `seconds` and of its CPU time, busy (one thread spinning).
fn planted_delay(label: &str, seconds: f64) {
    #[cfg(debug_assertions)]
    {
        let planted = |name| {
            let value = std::env::var(name).ok()?;
            let (command, amount) = value.rsplit_once(':').unwrap_or((label, &value));
            let amount = amount.parse::<f64>().ok()?.clamp(0.0, 60.0);
            (command == label).then_some(std::time::Duration::from_secs_f64(amount))
        };
        if let Some(delay) = planted("EXRCOMP_TEST_DELAY") {
            std::thread::sleep(delay);
        }
        if let Some(fraction) = planted("EXRCOMP_TEST_WORK") {
            // Slower by the fraction in wall time and in CPU time both,
            // whatever share of a core a loaded machine gives the spinning.
            let until = std::time::Instant::now() + fraction.mul_f64(seconds);
            let cpu = crate::stage_time::process_cpu;
            let cpu_until = cpu().mul_f64(1.0 + fraction.as_secs_f64());
            while std::time::Instant::now() < until || cpu() < cpu_until {
                std::hint::spin_loop();
            }
        }
    }
    #[cfg(not(debug_assertions))]
    let _ = (label, seconds);
}

/// Per output frame, the files each input reads (and why, when a missing
/// frame was held or made black) and the file written: a line of text, or
/// with `json` a JSON object, per frame.
fn dry_run_listing(job: &Job, json: bool) -> String {
    let mut text = String::new();
    for sources in &job.frames {
        let frame = sources.frame;
        let mut reads = Vec::new();
        for (i, (input, &source)) in job.inputs.iter().zip(&sources.inputs).enumerate() {
            let wanted = job.times[i].read(frame).unwrap_or(source.file_frame());
            let path = input.path(source.file_frame());
            let file = path.display().to_string();
            let missing = input.path(wanted).display().to_string();
            let part = part_read(job, i, sources);
            reads.push(match source {
                Source::Frame(f) if f == wanted => (file, part, "frame", None),
                Source::Frame(_) => (file, part, "held", Some(missing)),
                Source::Black(_) => (file, None, "black", Some(missing)),
            });
            for merged in &job.merged[i] {
                reads.push((
                    merged.path(frame).display().to_string(),
                    None,
                    "frame",
                    None,
                ));
            }
        }
        let output = job.output.path(frame).display().to_string();
        let line = match json {
            true => serde_json::json!({
                "frame": frame,
                "reads": reads.iter().map(|(file, part, source, missing)| {
                    let mut read = serde_json::json!({"file": file, "source": source});
                    if let Some(missing) = missing {
                        read["missing"] = missing.as_str().into();
                    }
                    if let Some(part) = part {
                        read["part"] = part.as_str().into();
                    }
                    read
                }).collect::<Vec<_>>(),
                "output": output,
            })
            .to_string(),
            false => {
                let reads: Vec<String> = reads
                    .iter()
                    .map(|(file, part, source, missing)| {
                        let file = match part {
                            Some(part) => format!("{file} ({part})"),
                            None => file.clone(),
                        };
                        match (source, missing) {
                            (&"held", Some(missing)) => {
                                format!("{file} (held: {missing} is missing)")
                            }
                            (&"black", Some(missing)) => format!("black ({missing} is missing)"),
                            _ => file,
                        }
                    })
                    .collect();
                let label = job
                    .frame_label(frame)
                    .map_or(String::new(), |f| format!("frame {f}: "));
                format!("{label}{} -> {output}", reads.join(", "))
            }
        };
        text.push_str(&line);
        text.push('\n');
    }
    text
}

/// The part of input `i`'s file in `sources` that its part or the view
/// picks, named for the dry run's listing: none without a choice, or when
/// the file cannot be read (the run says why).
fn part_read(job: &Job, i: usize, sources: &FrameSources) -> Option<String> {
    if job.view.is_none() && job.parts[i].is_none() {
        return None;
    }
    let file = job.input_file(i, sources).ok()?;
    let part = choose_part(&file, job.parts[i].as_deref(), job.view.as_deref()).ok()?;
    Some(match &file.header(part).own_attributes.layer_name {
        Some(name) => format!("part {part} '{}'", name.utf8()),
        None => format!("part {part}"),
    })
}

/// Runs `job` through the pipeline, its progress reported as `run` asks;
/// `first`, its first frame's plans if made already, is handed on.
pub fn run_with_progress(
    job: &Job,
    label: &str,
    run: &RunArgs,
    summary: Summary,
    first: Option<Vec<FramePlan>>,
) -> Result<(Report, Summary)> {
    let folders: BTreeSet<PathBuf> = job
        .frames
        .iter()
        .filter_map(|f| job.output.path(f.frame).parent().map(Path::to_path_buf))
        .collect();
    let inputs = FileSet::new(job.files().0);
    folders
        .iter()
        .for_each(|dir| remove_stale_temporaries(dir, &inputs));
    let report = Report::new(label, job.frames.len(), run.quiet, run.json).with_log(farm_log(run));
    let events = Progress {
        report: &report,
        job,
        warnings: match run.quiet {
            true => Vec::new(),
            false => summary.warnings.clone(),
        },
        warned: std::sync::Once::new(),
        summary: Mutex::new(summary),
        on_frame: run.on_frame.clone(),
        ended: AtomicUsize::new(0),
    };
    let stages = pipeline::run(job, &events, first)?;
    let mut summary = events
        .summary
        .into_inner()
        .expect("no panic while holding it");
    summary.stages = Some(stages);
    summary.seconds = report.elapsed();
    summary.interrupted = interrupt::requested();
    Ok((report, summary))
}

/// The lines a run prints on standard output as frames finish: those
/// `--progress` asks for, else a line per frame when standard output is not
/// a terminal (a log, a farm), --quiet or not; none with --json, whose
/// standard output is its summary, nor for a front end that shows its own
/// (`on_frame`: the Python package's host owns its standard output).
fn farm_log(run: &RunArgs) -> Option<FarmLog> {
    use std::io::IsTerminal;
    match run.progress {
        Some(log) => Some(log),
        None if run.json || run.on_frame.is_some() || std::io::stdout().is_terminal() => None,
        None => Some(FarmLog::Frames),
    }
}

/// Collects the run's events into its summary, moves the progress bar and
/// says what became of each frame.
struct Progress<'a> {
    report: &'a Report,
    job: &'a Job,
    /// Printed with the first frame done (`warn_once`).
    warnings: Vec<String>,
    warned: std::sync::Once,
    summary: Mutex<Summary>,
    /// `RunArgs::on_frame`, and the frames ended so far.
    on_frame: Option<FrameHook>,
    ended: AtomicUsize,
}

impl Progress<'_> {
    fn report(&self, frame: i64, outcome: Outcome) {
        let label = self.job.frame_label(frame);
        self.report
            .frame(label, outcome, &self.job.output.path(frame));
        if let Some(hook) = &self.on_frame {
            let ended = self.ended.fetch_add(1, Ordering::SeqCst) + 1;
            hook(frame, outcome, ended, self.job.frames.len());
        }
    }

    /// The run's warnings, printed once a frame is done: a run that fails
    /// before (a damaged first frame) says only its error, in one line.
    fn warn_once(&self) {
        self.warned.call_once(|| {
            for warning in &self.warnings {
                self.report.warning(warning);
            }
        });
    }
}

impl Events for Progress<'_> {
    fn written(&self, plan: &FramePlan) {
        self.warn_once();
        let mut summary = self.summary.lock().expect("not poisoned");
        summary.frames += 1;
        summary.pixels += plan.pixels() as u64;
        let outcome = match summary.redone.contains(&plan.frame) {
            true => Outcome::Redone,
            false => Outcome::Written,
        };
        drop(summary);
        self.report(plan.frame, outcome);
    }

    fn kept(&self, frame: i64) {
        self.warn_once();
        self.summary.lock().expect("not poisoned").kept.push(frame);
        self.report(frame, Outcome::Kept);
    }

    fn stale(&self, frame: i64) {
        self.summary
            .lock()
            .expect("not poisoned")
            .redone
            .push(frame);
    }

    fn failed(&self, frame: i64, error: &Error) {
        let mut summary = self.summary.lock().expect("not poisoned");
        // Two stages can each fail the same frame (a later one first,
        // before the earlier meets its own error); the first counts.
        if summary.failed.iter().any(|(f, _)| *f == frame) {
            return;
        }
        let label = self
            .job
            .frame_label(frame)
            .map_or(String::new(), |f| format!(" {f}"));
        self.report
            .note(&format!("exrcomp: frame{label} failed, going on: {error}"));
        summary.failed.push((frame, error.clone()));
        drop(summary);
        self.report(frame, Outcome::Failed);
    }
}

/// The command that runs this exrcomp, for what starts it again (bench's
/// runs, a farm's tasks): this executable, or the one a front end that
/// runs inside another program set (the Python package's `exrcomp`
/// script, whose process is the Python interpreter).
pub fn own_exe() -> Result<std::path::PathBuf> {
    if let Some(exe) = OWN_EXE.get() {
        return Ok(exe.clone());
    }
    std::env::current_exe()
        .map_err(|e| Error::internal(format!("cannot find exrcomp's own path: {e}")))
}

/// Sets what `own_exe` gives, once a process (later calls change nothing).
pub fn set_own_exe(exe: std::path::PathBuf) {
    let _ = OWN_EXE.set(exe);
}

static OWN_EXE: std::sync::OnceLock<std::path::PathBuf> = std::sync::OnceLock::new();
