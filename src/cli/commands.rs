//! Each frame-writing subcommand translated into a run (src/run/): its
//! inputs, graph and settings.

use crate::cli::job_file::{JobFileContents, Reaching};
use crate::cli::{Command, Invocation};
use crate::engine::graph::{Graph, GraphBuilder};
use crate::engine::plan::{FirstFile, Job};
use crate::error::{Error, Result};
use crate::io::media::Format;
use crate::io::overwrite::refuse_overwriting;
use crate::io::sequence::FramePattern;
use crate::ops::declare::{Args, Measured, Operation};
use crate::ops::layers::Selection;
use crate::ops::sources::plate::Plate;
use crate::run::report::Summary;
use crate::run::settings::{LayerArgs, RunArgs};
use crate::run::{check_frame_count, frame_list, input_job, plate_job, run_job, DryRun, JobInputs};
use std::cell::RefCell;
use std::collections::HashMap;
use std::path::{Path, PathBuf};

/// Runs frame-writing `command`; a dry run gives what it found.
pub fn execute(command: Command) -> Result<Option<DryRun>> {
    match command {
        Command::Op(call) => operation(call),
        Command::Stitch { bands, output } => stitch(&bands, &output).map(|()| None),
        Command::Run { job, output, run } => job_file(&job, output, run),
        Command::Flatten {
            input,
            output,
            part,
            run,
        } => {
            let layers = LayerArgs {
                part,
                ..LayerArgs::default()
            };
            copy("flatten", input, &output, &layers, &run)
        }
        Command::Deepmerge {
            inputs,
            output,
            run,
        } => {
            let graph = Graph::identity();
            let layers = LayerArgs::default();
            let (mut job, summary) = input_job(
                JobInputs::of(&inputs[..1]),
                &output,
                graph,
                0,
                &layers,
                &run,
            )?;
            job.merged[0] = inputs[1..]
                .iter()
                .map(|p| FramePattern::parse(p))
                .collect::<Result<_>>()?;
            run_job(&job, "deepmerge", &run, summary)
        }
        Command::Transcode {
            input,
            output,
            level,
            part,
            run,
        } => {
            let layers = LayerArgs {
                level,
                part,
                ..LayerArgs::default()
            };
            copy("transcode", input, &output, &layers, &run)
        }
        // The tools' commands are run by main.rs, and refused in a farm task
        // (src/tools/farm.rs) before they come here.
        Command::Info { .. } | Command::Bench(_) | Command::Demo { .. } | Command::Farm { .. } => {
            Err(Error::usage("this command writes no frames of a job"))
        }
        Command::Generate {
            output,
            kind,
            width,
            height,
            origin,
            pixel_type,
            run,
        } => {
            let plate = Plate {
                kind,
                width,
                height,
                origin,
                pixel_type,
            };
            generate(plate, &output, &run)
        }
    }
}

fn stitch(bands: &[PathBuf], output: &Path) -> Result<()> {
    let pattern = FramePattern::output(&output.to_string_lossy())?;
    if pattern.format() != Some(Format::Exr) {
        return Err(Error::usage(format!(
            "stitch writes EXR files (it joins their chunks): {} is not one",
            output.display()
        )));
    }
    refuse_overwriting(bands.to_vec(), [(None, output.to_path_buf())])?;
    crate::io::stitch::stitch(bands, output)
}

/// A job file's job, the command line's settings over its write node's.
fn job_file(path: &Path, output: Option<String>, run: RunArgs) -> Result<Option<DryRun>> {
    let (mut contents, opened) = load_job(path, output.as_deref(), &run)?;
    if let Some(output) = output {
        contents.output = output;
    }
    let run = RunArgs {
        frames: run.frames.clone().or(contents.frames),
        write: run.write.clone().over(contents.write),
        ..run
    };
    let (texts, parts): (Vec<String>, Vec<Option<String>>) = contents.reads.into_iter().unzip();
    let given = JobInputs {
        texts: &texts,
        read_parts: &parts,
        opened: &opened,
    };
    let (job, summary) = input_job(
        given,
        &contents.output,
        contents.graph,
        contents.header_from,
        &LayerArgs::default(),
        &run,
    )?;
    run_job(&job, "run", &run, summary)
}

/// A job file's contents, its nodes' measured parameters (`from = "auto"`)
/// read from the files as the command line's are, once per read (`output`
/// and `run`: the command line's, over the job's); and the first files the
/// measuring opened, for the job to take over.
pub fn load_job(
    path: &Path,
    output: Option<&str>,
    run: &RunArgs,
) -> Result<(JobFileContents, Vec<Option<FirstFile>>)> {
    let jobs: RefCell<HashMap<String, Job>> = RefCell::default();
    let measure = |op: &'static Operation, args: &Args, at: &Reaching| -> Result<Measured> {
        let Some(measure) = op.measure else {
            return Ok(Measured::default());
        };
        let key = format!("{}:{:?}", at.read, at.part);
        if !jobs.borrow().contains_key(&key) {
            let run = RunArgs {
                frames: run.frames.clone().or(at.frames.clone()),
                ..run.clone()
            };
            let output = output.unwrap_or(&at.output);
            let (texts, parts) = ([at.read.clone()], [at.part.clone()]);
            let layers = LayerArgs::default();
            let given = JobInputs {
                texts: &texts,
                read_parts: &parts,
                opened: &[],
            };
            let (job, _) = input_job(given, output, Graph::identity(), 0, &layers, &run)?;
            jobs.borrow_mut().insert(key.clone(), job);
        }
        let measured = measure(args, &jobs.borrow()[&key], &at.edits, run.dry_run)
            .map_err(|e| Error::new(e.kind, format!("{}: {}", at.place, e.message)))?;
        if run.dry_run && !run.quiet {
            (measured.notes.iter()).for_each(|n| eprintln!("{}: {n}", at.place));
        }
        Ok(measured)
    };
    let contents = crate::cli::job_file::load(path, run.proxy_scale, &measure)?;
    let opened = jobs.take().into_values().flat_map(|job| job.first_files);
    Ok((contents, opened.collect()))
}

/// `input` written again as `output` (`label`: flatten, transcode).
fn copy(
    label: &str,
    input: String,
    output: &str,
    layers: &LayerArgs,
    run: &RunArgs,
) -> Result<Option<DryRun>> {
    let (job, summary) = input_job(
        JobInputs::of(&[input]),
        output,
        Graph::identity(),
        0,
        layers,
        run,
    )?;
    run_job(&job, label, run, summary)
}

fn generate(plate: Plate, output: &str, run: &RunArgs) -> Result<Option<DryRun>> {
    let output = FramePattern::output(output)?;
    let frames = frame_list(run)?.unwrap_or(vec![1]);
    check_frame_count(&frames, &output)?;
    if run.proxy_scale.is_some() {
        return Err(Error::usage(
            "generate writes plates at their size: --proxy-scale is for commands that read inputs",
        ));
    }
    let job = plate_job(plate, output, frames, run)?;
    run_job(&job, "generate", run, Summary::default())
}

fn selection(layers: &LayerArgs) -> Selection {
    Selection {
        layers: layers.layers.clone(),
        all: layers.all_layers,
        view: layers.view.clone(),
    }
}

/// An operation's job: its graph built from its declaration, after a first
/// pass over the inputs for what it measures (in a dry run, what needs no
/// pixels, said).
fn operation(call: Invocation) -> Result<Option<DryRun>> {
    let op = call.op;
    let mut args = Args {
        op: op.name,
        values: call.values,
        layers: selection(&call.layers),
        straight: call.straight,
        job_file: false,
    };
    let header = op.header.unwrap_or(call.inputs.len() - 1);
    let job = |given: JobInputs, graph, header| {
        input_job(given, &call.output, graph, header, &call.layers, &call.run)
    };
    let mut opened = Vec::new();
    if let Some(measure) = op.measure {
        let (first, _) = job(JobInputs::of(&call.inputs[..1]), Graph::identity(), 0)?;
        let measured = measure(&args, &first, &[], call.run.dry_run)?;
        if call.run.dry_run && !call.run.quiet {
            measured
                .notes
                .iter()
                .for_each(|n| eprintln!("{}: {n}", op.name));
        }
        args.values.extend(measured.values);
        opened = first.first_files;
    }
    if let Some(factor) = call.run.proxy_scale {
        op.scale_lengths(&mut args, factor as f64)
            .map_err(|m| Error::usage(format!("--proxy-scale: {m}")))?;
    }
    let (mut graph, inputs) = GraphBuilder::with_inputs(call.inputs.len());
    (op.build)(&args, &mut graph, &inputs).map_err(Error::usage)?;
    let given = JobInputs {
        opened: &opened,
        ..JobInputs::of(&call.inputs)
    };
    let (job, summary) = job(given, graph.finish(), header)?;
    run_job(&job, op.name, &call.run, summary)
}
