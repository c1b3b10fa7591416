//! Each frame-writing subcommand translated into a run (src/run/): its
//! inputs, graph and settings.

use crate::cli::{Command, Invocation};
use crate::engine::graph::{Graph, GraphBuilder};
use crate::error::{Error, Result};
use crate::io::media::Format;
use crate::io::overwrite::refuse_overwriting;
use crate::io::sequence::FramePattern;
use crate::ops::declare::Args;
use crate::ops::layers::Selection;
use crate::ops::sources::plate::Plate;
use crate::run::job_run::run_file;
use crate::run::report::Summary;
use crate::run::settings::{LayerArgs, RunArgs};
use crate::run::{check_frame_count, frame_list, input_job, plate_job, run_job, DryRun, JobInputs};
use std::path::{Path, PathBuf};

/// Runs frame-writing `command`; a dry run gives what it found.
pub fn execute(command: Command) -> Result<Option<DryRun>> {
    match command {
        Command::Op(call) => operation(call),
        Command::Stitch { bands, output } => stitch(&bands, &output).map(|()| None),
        Command::Run { job, output, run } => run_file(&job, None, output, run),
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
        // The tools' commands are run by cli/program.rs, and refused in a farm task
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
