//! The threads a job runs on, joined by bounded channels:
//! decode -> compose -> encode -> write. Strips of consecutive frames follow
//! each other through the same channels, so a few frames overlap in flight
//! while memory stays bounded by the channel capacities.

use super::compose::Composer;
use super::decode::{decode_strip, InputCursor};
use super::encode::{encode_rows, IndexedChunk};
use super::plan::{plan_frame, FramePlan, Job};
use super::strip::Rows;
use crate::error::{Error, Kind, Result};
use crate::io::writer::write_file;
use crossbeam_channel::{bounded, Receiver, Sender};
use std::ops::Range;
use std::sync::Arc;

/// Strips a channel holds; with one strip being worked on at each end.
const CHANNEL_STRIPS: usize = 1;

enum Msg<T> {
    Begin(Arc<FramePlan>),
    Strip(T),
    End,
}

/// Receiving side of a stage: `None` once the upstream stage has stopped.
fn receive<T>(rx: &Receiver<Msg<T>>) -> Option<Msg<T>> {
    rx.recv().ok()
}

/// Sends downstream; false once the downstream stage has stopped (it failed,
/// and reports why).
fn send<T>(tx: &Sender<Msg<T>>, msg: Msg<T>) -> bool {
    tx.send(msg).is_ok()
}

/// Runs `job`, calling `frame_done` after each output file is in place.
pub fn run(job: &Job, frame_done: impl Fn(&FramePlan) + Sync) -> Result<()> {
    let (decoded_tx, decoded_rx) = bounded::<Msg<(Range<i32>, Vec<Rows>)>>(CHANNEL_STRIPS);
    let (composed_tx, composed_rx) = bounded::<Msg<Rows>>(CHANNEL_STRIPS);
    let (encoded_tx, encoded_rx) = bounded::<Msg<Vec<IndexedChunk>>>(CHANNEL_STRIPS);
    let results = std::thread::scope(|scope| {
        let stages = [
            scope.spawn(|| decode_stage(job, decoded_tx)),
            scope.spawn(|| compose_stage(job, decoded_rx, composed_tx)),
            scope.spawn(|| encode_stage(job, composed_rx, encoded_tx)),
            scope.spawn(|| write_stage(encoded_rx, &frame_done)),
        ];
        stages.map(|stage| {
            stage
                .join()
                .unwrap_or_else(|_| Err(Error::internal("a pipeline thread panicked")))
        })
    });
    // The earliest stage's error is the cause; later ones only saw it stop.
    results.into_iter().collect::<Result<Vec<()>>>().map(drop)
}

fn decode_stage(job: &Job, tx: Sender<Msg<(Range<i32>, Vec<Rows>)>>) -> Result<()> {
    for &frame in &job.frames {
        let plan = Arc::new(plan_frame(job, frame)?);
        let mut cursors: Vec<InputCursor> = plan
            .inputs
            .iter()
            .map(|file| InputCursor::new(file.clone(), 0))
            .collect();
        let window = plan.window();
        let columns = (window.position.x(), window.size.width());
        if !send(&tx, Msg::Begin(plan.clone())) {
            return Ok(());
        }
        for rows in plan.strips() {
            let strips = decode_strip(&mut cursors, columns, rows.clone())?;
            if !send(&tx, Msg::Strip((rows, strips))) {
                return Ok(());
            }
        }
        if !send(&tx, Msg::End) {
            return Ok(());
        }
    }
    Ok(())
}

fn compose_stage(
    job: &Job,
    rx: Receiver<Msg<(Range<i32>, Vec<Rows>)>>,
    tx: Sender<Msg<Rows>>,
) -> Result<()> {
    let mut composer = None;
    let mut frame = 0;
    while let Some(msg) = receive(&rx) {
        let out = match msg {
            Msg::Begin(plan) => {
                frame = plan.frame;
                let lines = plan.header.compression.scan_lines_per_block();
                composer = Some(Composer::new(
                    &job.graph,
                    plan.window(),
                    &plan.channels,
                    &plan.windows,
                    lines,
                ));
                Msg::Begin(plan)
            }
            Msg::Strip((rows, strips)) => {
                let composer = composer
                    .as_mut()
                    .ok_or_else(|| Error::internal("strip before frame"))?;
                match composer.push(frame, rows, strips) {
                    Some(rows) => Msg::Strip(rows),
                    None => continue,
                }
            }
            Msg::End => Msg::End,
        };
        if !send(&tx, out) {
            break;
        }
    }
    Ok(())
}

fn encode_stage(
    job: &Job,
    rx: Receiver<Msg<Rows>>,
    tx: Sender<Msg<Vec<IndexedChunk>>>,
) -> Result<()> {
    let mut plan: Option<Arc<FramePlan>> = None;
    while let Some(msg) = receive(&rx) {
        let out = match msg {
            Msg::Begin(p) => {
                plan = Some(p.clone());
                Msg::Begin(p)
            }
            Msg::Strip(rows) => {
                let plan = plan
                    .as_ref()
                    .ok_or_else(|| Error::internal("strip before frame"))?;
                Msg::Strip(encode_rows(&rows, &plan.header, job.zip_level)?)
            }
            Msg::End => Msg::End,
        };
        if !send(&tx, out) {
            break;
        }
    }
    Ok(())
}

fn write_stage(
    rx: Receiver<Msg<Vec<IndexedChunk>>>,
    frame_done: &(impl Fn(&FramePlan) + Sync),
) -> Result<()> {
    while let Some(msg) = receive(&rx) {
        let Msg::Begin(plan) = msg else {
            return Err(Error::internal("frame data without a frame"));
        };
        let next = || match receive(&rx) {
            Some(Msg::Strip(chunks)) => Ok(Some(chunks)),
            Some(Msg::End) => Ok(None),
            Some(Msg::Begin(_)) => Err(Error::internal("frame begun inside a frame")),
            None => Err(Error::stopped()),
        };
        match write_file(&plan.output, plan.label, plan.header.clone(), next) {
            Ok(()) => frame_done(&plan),
            // An earlier stage failed and reports why; the half-written frame is gone.
            Err(e) if e.kind == Kind::Stopped => return Ok(()),
            Err(e) => return Err(e),
        }
    }
    Ok(())
}
