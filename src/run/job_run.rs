//! A job file's job, loaded and run: the one way every front end runs a
//! graph of nodes (`exrcomp run JOB.toml`, the Python package's `Graph`,
//! which gives its job as text), so that the same job writes the same bytes
//! whichever front end gave it.

use crate::engine::graph::Graph;
use crate::engine::plan::{FirstFile, Job};
use crate::error::{Error, Result};
use crate::ops::declare::{Args, Measured, Operation};
use crate::run::job_file::{JobFileContents, Reaching};
use crate::run::settings::{LayerArgs, RunArgs};
use crate::run::{input_job, run_job, DryRun, JobInputs};
use std::cell::RefCell;
use std::collections::HashMap;
use std::path::Path;

/// The job file at `path` (or its `text`, given by a front end: `path`
/// then names it in messages and its folder is where relative file names
/// start) run with `run`, the command line's settings over its write node's.
pub fn run_file(
    path: &Path,
    text: Option<&str>,
    output: Option<String>,
    run: RunArgs,
) -> Result<Option<DryRun>> {
    let (mut contents, opened) = load_job(path, text, output.as_deref(), &run)?;
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
    text: Option<&str>,
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
    let contents = crate::run::job_file::load(path, text, run.proxy_scale, &measure)?;
    let opened = jobs.take().into_values().flat_map(|job| job.first_files);
    Ok((contents, opened.collect()))
}
