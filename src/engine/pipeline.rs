//! The threads a job runs on, joined by bounded channels:
//! decode -> compose -> encode -> write. Strips of consecutive frames follow
//! each other through the same channels, so a few frames overlap in flight
//! while memory stays bounded by the channel capacities.

use super::compose::Composer;
use super::decode::{decode_regions, InputCursor, Region};
use super::encode::encode_rows;
use super::fingerprint;
use super::frame_plan::{output_grid, plan_parts, FramePlan};
use super::interrupt;
use super::opaque::{self, Opaque};
use super::passthrough::PassThrough;
use super::plan::{FrameSources, Job};
use crate::error::{Error, Kind, Result};
use crate::guard;
use crate::io::media::{self, Strip};
use crate::io::reader::ExrFile;
use crate::io::rows::Rows;
use crate::io::writer::write_file;
use crate::io::writer::IndexedChunk;
use crate::stage_time::{self, Stage, StageTimes};
use crossbeam_channel::{bounded, Receiver, Sender};
use exr::meta::attribute::IntegerBounds;
use std::ops::Range;
use std::path::Path;
use std::sync::Arc;

/// Strips a channel holds; with one strip being worked on at each end.
const CHANNEL_STRIPS: usize = 1;

enum Msg<T> {
    Begin(Arc<FramePlan>),
    /// The next part of the frame begun (`--all-parts`): its strips follow,
    /// into the same output file.
    Part(Arc<FramePlan>),
    Strip(T),
    End,
    /// The frame begun is abandoned (bad input with --keep-going, or an
    /// interruption): its temporary file is removed.
    Abort,
}

/// What a run tells its caller as it goes.
pub trait Events: Sync {
    /// An output frame is in place.
    fn written(&self, plan: &FramePlan);
    /// A frame's output already exists complete, made by this job from
    /// these inputs (--resume).
    fn kept(&self, frame: i64);
    /// A frame's output exists complete but another job (or tool) made it:
    /// it is written again (--resume).
    fn stale(&self, frame: i64);
    /// A frame failed on bad input or a bug, and the run goes on
    /// (--keep-going).
    fn failed(&self, frame: i64, error: &Error);
}

/// A strip of every input, and the output blocks that are an input's chunks
/// as they are (`passthrough.rs`).
struct Decoded {
    rows: Range<i32>,
    strips: Vec<Rows>,
    passed: Vec<IndexedChunk>,
}

/// Output rows, and chunks passed for blocks among them.
struct Composed {
    rows: Rows,
    passed: Vec<IndexedChunk>,
}

/// A strip encoded: an EXR's compressed chunks, or a review frame's rows.
enum Encoded {
    Chunks(Vec<IndexedChunk>),
    Media(Strip),
}

/// A Begin or Part for the next stage, with `plan`.
fn relay<T, U>(msg: &Msg<T>, plan: Arc<FramePlan>) -> Msg<U> {
    match msg {
        Msg::Part(_) => Msg::Part(plan),
        _ => Msg::Begin(plan),
    }
}

/// Receiving side of `stage`: `None` once the upstream stage has stopped.
fn receive<T>(stage: Stage, rx: &Receiver<Msg<T>>) -> Option<Msg<T>> {
    stage_time::wait(stage, || rx.recv().ok())
}

/// `receive`, past the rest of a frame that `failed` in this stage
/// (`abandon`); cleared at the next frame.
fn receive_past<T>(stage: Stage, rx: &Receiver<Msg<T>>, failed: &mut bool) -> Option<Msg<T>> {
    loop {
        let msg = receive(stage, rx)?;
        *failed &= !matches!(msg, Msg::Begin(_));
        if !*failed {
            return Some(msg);
        }
    }
}

/// Sends downstream from `stage`; false once the downstream stage has
/// stopped (it failed, and reports why).
fn send<T>(stage: Stage, tx: &Sender<Msg<T>>, msg: Msg<T>) -> bool {
    stage_time::wait(stage, || tx.send(msg).is_ok())
}

/// Runs `work`, part of the frame written to `output` (`label`: its number
/// in messages). A panic in it, on this thread or in the pool tasks it
/// waits on, is a bug met in that frame: the frame's error, as bad input
/// would be, not the end of the process.
fn frame_work<T>(output: &Path, label: Option<i64>, work: impl FnOnce() -> Result<T>) -> Result<T> {
    guard::catch(work).unwrap_or_else(|p| Err(Error::panicked(Some((output, label)), p)))
}

/// Whether a frame's error abandons that frame alone: with --keep-going,
/// bad input or a bug met in its work; an output error would repeat on
/// every frame.
fn goes_on(job: &Job, e: &Error) -> bool {
    job.keep_going && matches!(e.kind, Kind::Input | Kind::Internal)
}

/// A frame that failed in `stage`, after decode: under `goes_on` it is
/// reported, abandoned downstream (`Ok(false)` when downstream has
/// stopped), and its messages still coming are dropped (`failed`);
/// otherwise its error ends the run.
fn abandon<T>(
    job: &Job,
    events: &impl Events,
    (stage, tx): (Stage, &Sender<Msg<T>>),
    frame: i64,
    e: Error,
    failed: &mut bool,
) -> Result<bool> {
    if !goes_on(job, &e) {
        return Err(e);
    }
    events.failed(frame, &e);
    *failed = true;
    Ok(send(stage, tx, Msg::Abort))
}

/// Test builds only (debug assertions, as the suite's binary is built):
/// `EXRCOMP_TEST_PANIC=STAGE:FRAME` (decode, compose, encode or write)
/// panics in that stage's work on that frame. No input makes exrcomp panic
/// on purpose, and the tests must see a bug met in one frame cost that
/// frame alone (tests/suite/overnight.rs). The panic's place is the call's.
#[track_caller]
fn planted_panic(stage: Stage, frame: i64) {
    if !cfg!(debug_assertions) {
        return;
    }
    static PLANTED: std::sync::OnceLock<Option<(String, i64)>> = std::sync::OnceLock::new();
    let planted = PLANTED.get_or_init(|| {
        let planted = std::env::var("EXRCOMP_TEST_PANIC").ok()?;
        let (stage, frame) = planted.split_once(':')?;
        Some((stage.to_string(), frame.parse().ok()?))
    });
    if planted.as_ref() == Some(&(stage.name().to_string(), frame)) {
        panic!("planted panic in {} of frame {frame}", stage.name());
    }
}

/// Runs `body` as `stage`'s thread. Each frame's work is caught on its own
/// (`frame_work`); a panic outside it, in the hand-over between frames,
/// ends the run as an internal error, in one line.
fn stage_thread(stage: Stage, body: impl FnOnce() -> Result<()>) -> Result<()> {
    stage_time::stage_thread(stage, || {
        guard::catch(body).unwrap_or_else(|p| Err(Error::panicked(None, p)))
    })
}

/// Runs `job`, reporting each frame to `events`, and returns where its CPU
/// time went (`stage_time.rs`). Stops early, without an error, when an
/// interruption is requested (`interrupt::requested`). `first` is the
/// first frame's plans (`plan_parts`) when the caller made them already.
pub fn run(job: &Job, events: &impl Events, first: Option<Vec<FramePlan>>) -> Result<StageTimes> {
    let start = StageTimes::now();
    let (decoded_tx, decoded_rx) = bounded::<Msg<Decoded>>(CHANNEL_STRIPS);
    let (composed_tx, composed_rx) = bounded::<Msg<Composed>>(CHANNEL_STRIPS);
    let (encoded_tx, encoded_rx) = bounded::<Msg<Encoded>>(CHANNEL_STRIPS);
    let results = std::thread::scope(|scope| {
        let stages = [
            scope.spawn(|| {
                stage_thread(Stage::Decode, || {
                    decode_stage(job, events, first, decoded_tx)
                })
            }),
            scope.spawn(|| {
                stage_thread(Stage::Compose, || {
                    compose_stage(job, events, decoded_rx, composed_tx)
                })
            }),
            scope.spawn(|| {
                stage_thread(Stage::Encode, || {
                    encode_stage(job, events, composed_rx, encoded_tx)
                })
            }),
            scope.spawn(|| stage_thread(Stage::Write, || write_stage(job, encoded_rx, events))),
        ];
        stages.map(|stage| {
            stage
                .join()
                .unwrap_or_else(|_| Err(Error::internal("a pipeline thread panicked")))
        })
    });
    // The earliest stage's error is the cause; later ones only saw it stop.
    results.into_iter().collect::<Result<Vec<()>>>()?;
    Ok(StageTimes::now().since(&start))
}

/// Decodes `job`'s frames in order; `first`, the first frame's plans when
/// the run made them already (for its slate), is not planned again.
fn decode_stage(
    job: &Job,
    events: &impl Events,
    mut first: Option<Vec<FramePlan>>,
    tx: Sender<Msg<Decoded>>,
) -> Result<()> {
    for sources in &job.frames {
        let planned = first.take();
        if interrupt::requested() {
            break;
        }
        let mut begun = false;
        let (output, label) = (
            job.output.path(sources.frame),
            job.frame_label(sources.frame),
        );
        match frame_work(&output, label, || {
            decode_frame(job, events, sources, planned, &tx, &mut begun)
        }) {
            Ok(true) => {}
            // Downstream has stopped (and reports why) or we were interrupted.
            Ok(false) => {
                if begun {
                    send(Stage::Decode, &tx, Msg::Abort);
                }
                return Ok(());
            }
            Err(e) if goes_on(job, &e) => {
                if begun && !send(Stage::Decode, &tx, Msg::Abort) {
                    return Ok(());
                }
                events.failed(sources.frame, &e);
            }
            Err(e) => return Err(e),
        }
    }
    Ok(())
}

/// Sends one frame downstream, part after part (one, but with
/// `--all-parts`), unless `--resume` keeps its output; `Ok(false)` when it
/// had to stop part-way.
fn decode_frame(
    job: &Job,
    events: &impl Events,
    sources: &FrameSources,
    planned: Option<Vec<FramePlan>>,
    tx: &Sender<Msg<Decoded>>,
    begun: &mut bool,
) -> Result<bool> {
    let plans = match planned {
        Some(plans) => plans,
        None => plan_parts(job, sources)?,
    };
    if job.resume {
        match resumed(job, &plans[0]) {
            Resumed::Kept => {
                events.kept(sources.frame);
                return Ok(true);
            }
            Resumed::Stale => events.stale(sources.frame),
            Resumed::Absent => {}
        }
    }
    for plan in plans {
        let plan = Arc::new(plan);
        let msg = match *begun {
            false => Msg::Begin(plan.clone()),
            true => Msg::Part(plan.clone()),
        };
        if !send(Stage::Decode, tx, msg) {
            return Ok(false);
        }
        *begun = true;
        if !decode_part(job, &plan, tx)? {
            return Ok(false);
        }
    }
    Ok(send(Stage::Decode, tx, Msg::End))
}

/// Sends the strips of one planned part; `Ok(false)` when it had to stop.
fn decode_part(job: &Job, plan: &Arc<FramePlan>, tx: &Sender<Msg<Decoded>>) -> Result<bool> {
    let mut cursors: Vec<InputCursor> = plan
        .inputs
        .iter()
        .enumerate()
        .map(|(i, file)| match &plan.deep[i] {
            Some(deep) => InputCursor::deep(file.clone(), plan.parts[i], deep.clone()),
            None => InputCursor::new(file.clone(), plan.parts[i], plan.levels[i], plan.read[i]),
        })
        .collect();
    // The columns computed: the window's, and those the halos reach beyond it.
    let columns = (plan.computed.position.x(), plan.computed.size.width());
    // Review media have no chunks to pass, but decode nothing hidden.
    let pass = match job.media {
        Some(_) => None,
        None => PassThrough::find(plan.graph(job), plan),
    };
    let opaque = Opaque::find(plan.graph(job), plan, job.media.is_none());
    // Per input, its columns, whether it is read bottom-up, and the rows
    // read so far (none yet: an empty range at its first row).
    let mut fed: Vec<((i32, usize), bool, Range<i32>)> = (0..plan.inputs.len())
        .map(|i| match plan.graph(job).input_node(i) {
            Some(n) => {
                let (rect, upward) = (plan.regions.rect(n), plan.regions.upward(n));
                let first = match upward {
                    true => rect.end().y(),
                    false => rect.position.y(),
                };
                ((rect.position.x(), rect.size.width()), upward, first..first)
            }
            None => (
                columns,
                false,
                plan.computed.position.y()..plan.computed.position.y(),
            ),
        })
        .collect();
    for (cursor, &(_, upward, _)) in cursors.iter_mut().zip(&fed) {
        cursor.upward = upward;
    }
    for rows in plan.strips() {
        if interrupt::requested() {
            return Ok(false);
        }
        // Each strip reads the rows of the span not read yet.
        let regions: Vec<Region> = fed
            .iter_mut()
            .zip(plan.input_spans(plan.graph(job), rows.end))
            .map(|((columns, upward, done), span)| {
                let read = match upward {
                    true => span.start.min(done.start)..done.start,
                    false => done.end..span.end.max(done.end),
                };
                *done = done.start.min(read.start)..done.end.max(read.end);
                (*columns, read)
            })
            .collect();
        // On a pool thread, as the compose stage's strips are.
        let (strips, passed) = rayon::scope(|_| {
            planted_panic(Stage::Decode, plan.frame);
            match (&pass, &opaque) {
                (None, None) => Ok((decode_regions(&mut cursors, &regions)?, Vec::new())),
                skips => {
                    let (graph, skips) = (plan.graph(job), (skips.0.as_ref(), skips.1.as_ref()));
                    opaque::decode(skips, plan, graph, &mut cursors, &regions, rows.clone())
                }
            }
        })?;
        let decoded = Decoded {
            rows,
            strips,
            passed,
        };
        if !send(Stage::Decode, tx, Msg::Strip(decoded)) {
            return Ok(false);
        }
    }
    Ok(true)
}

/// What `--resume` finds at a frame's output.
enum Resumed {
    /// Nothing: the frame is written.
    Absent,
    /// A file this job would not write as it is: another job's, another
    /// tool's (no fingerprint) or damaged. The frame is written again.
    Stale,
    /// A complete frame with this job's fingerprint for it: kept.
    Kept,
}

/// Whether `plan`'s output is there, complete (an EXR file whose every
/// chunk decodes, or a complete review frame: `media::complete`), made by
/// this job from these inputs (its fingerprint, `fingerprint.rs`) and of
/// the rows this run writes: a band (`--rows`) carries the whole frame's
/// fingerprint, so a band left where the whole frame or another band goes
/// (or the whole frame where a band goes) is told by its data window and
/// band record (`stitch::same_rows`).
fn resumed(job: &Job, plan: &FramePlan) -> Resumed {
    // A movie is one output, written whole again.
    if job.media.as_ref().is_some_and(|r| r.movie.is_some()) {
        return Resumed::Absent;
    }
    let (path, media) = (&plan.output, job.media.as_ref().map(|r| r.media.format));
    // Only a frame that would be kept is worth decoding whole.
    let complete = || match media {
        Some(format) => media::complete(path, format),
        None => ExrFile::open(path, None).is_ok_and(|file| {
            let (written, found) = (plan.output_parts().headers, &file.meta.headers);
            written.len() == found.len()
                && (written.iter().zip(found)).all(|(w, f)| crate::io::stitch::same_rows(f, w))
                && (0..found.len()).all(|part| file.check_part(part).is_ok())
        }),
    };
    match fingerprint::made_by(path, media, &plan.fingerprint) {
        None => Resumed::Absent,
        Some(true) if complete() => Resumed::Kept,
        Some(_) => Resumed::Stale,
    }
}

fn compose_stage(
    job: &Job,
    events: &impl Events,
    rx: Receiver<Msg<Decoded>>,
    tx: Sender<Msg<Composed>>,
) -> Result<()> {
    let mut composer = None;
    // Passed chunks wait here until their rows come out of the graph.
    let mut passed: Vec<IndexedChunk> = Vec::new();
    // The output's block rows and blocks per row.
    let (mut lines, mut across) = (1, 1);
    let mut current: Option<Arc<FramePlan>> = None;
    let mut written = IntegerBounds::zero();
    let mut failed = false;
    while let Some(msg) = receive_past(Stage::Compose, &rx, &mut failed) {
        let out = match msg {
            Msg::Begin(ref plan) | Msg::Part(ref plan) => {
                current = Some(plan.clone());
                written = plan.window();
                let grid = output_grid(&plan.header);
                (lines, across) = (grid.block.y(), grid.blocks.x());
                passed.clear();
                composer = Some(Composer::new(
                    plan.graph(job),
                    &plan.regions,
                    &plan.channels,
                    &plan.windows,
                    lines,
                ));
                relay(&msg, plan.clone())
            }
            Msg::Strip(decoded) => {
                let (Some(plan), Some(composer)) = (&current, composer.as_mut()) else {
                    return Err(Error::internal("strip before frame"));
                };
                passed.extend(decoded.passed);
                let (rows, strips, frame) = (decoded.rows, decoded.strips, plan.frame);
                let pushed = frame_work(&plan.output, plan.label, || {
                    // On a pool thread: each node's bands then run as nested
                    // tasks, not as one call into the pool per node from here.
                    rayon::scope(|_| {
                        planted_panic(Stage::Compose, frame);
                        composer.push(frame, rows, strips)
                    })
                    .map_err(|m| Error::new(Kind::Input, format!("frame {frame}: {m}")))
                });
                match pushed {
                    Ok(Some(rows)) => match written_rows(rows, written) {
                        Some(rows) => {
                            let top = written.position.y();
                            let blocks = (rows.y - top) as usize / lines
                                ..((rows.end() - top) as usize).div_ceil(lines);
                            let (now, later) = passed
                                .drain(..)
                                .partition(|c| blocks.contains(&(c.index / across)));
                            passed = later;
                            Msg::Strip(Composed { rows, passed: now })
                        }
                        None => continue,
                    },
                    Ok(None) => continue,
                    Err(e) => {
                        match abandon(job, events, (Stage::Compose, &tx), frame, e, &mut failed)? {
                            true => continue,
                            false => break,
                        }
                    }
                }
            }
            Msg::End => Msg::End,
            Msg::Abort => {
                composer = None;
                Msg::Abort
            }
        };
        if !send(Stage::Compose, &tx, out) {
            break;
        }
    }
    Ok(())
}

/// The part of composed `rows` inside the written window: a band's rows,
/// and without the rows and columns computed around it for the halos
/// (`frame_plan::computed`); whole blocks, as the band is on the grid.
fn written_rows(rows: Rows, window: IntegerBounds) -> Option<Rows> {
    let (top, bottom) = (
        rows.y.max(window.position.y()),
        rows.end().min(window.end().y()),
    );
    if top >= bottom {
        return None;
    }
    let columns = window.position.x()..window.end().x();
    if (top, bottom) == (rows.y, rows.end()) && columns == (rows.x..rows.x + rows.width as i32) {
        return Some(rows);
    }
    Some(rows.copy_region(top..bottom, columns))
}

fn encode_stage(
    job: &Job,
    events: &impl Events,
    rx: Receiver<Msg<Composed>>,
    tx: Sender<Msg<Encoded>>,
) -> Result<()> {
    let mut plan: Option<Arc<FramePlan>> = None;
    // A review frame's burn-in, placed.
    let mut label = None;
    let mut failed = false;
    while let Some(msg) = receive_past(Stage::Encode, &rx, &mut failed) {
        let out = match msg {
            Msg::Begin(ref p) | Msg::Part(ref p) => {
                plan = Some(p.clone());
                label = job.media.as_ref().and_then(|review| p.label(review));
                relay(&msg, p.clone())
            }
            Msg::Strip(composed) => {
                let plan = plan
                    .as_ref()
                    .ok_or_else(|| Error::internal("strip before frame"))?;
                let encoded = frame_work(&plan.output, plan.label, || {
                    planted_panic(Stage::Encode, plan.frame);
                    Ok(match &job.media {
                        Some(review) => Encoded::Media(review.media.convert(
                            &composed.rows,
                            plan.header.data_window(),
                            label.as_ref(),
                        )),
                        None => Encoded::Chunks(encode_rows(
                            &composed.rows,
                            &plan.header,
                            job.zip_level,
                            composed.passed,
                        )?),
                    })
                });
                match encoded {
                    Ok(encoded) => Msg::Strip(encoded),
                    Err(e) => {
                        let tx = (Stage::Encode, &tx);
                        match abandon(job, events, tx, plan.frame, e, &mut failed)? {
                            true => continue,
                            false => break,
                        }
                    }
                }
            }
            Msg::End => Msg::End,
            Msg::Abort => Msg::Abort,
        };
        if !send(Stage::Encode, &tx, out) {
            break;
        }
    }
    Ok(())
}

fn write_stage(job: &Job, rx: Receiver<Msg<Encoded>>, events: &impl Events) -> Result<()> {
    // A frame failed here (--keep-going): its messages still coming are
    // dropped.
    let mut failed = false;
    while let Some(msg) = receive_past(Stage::Write, &rx, &mut failed) {
        let plan = match msg {
            Msg::Begin(plan) => plan,
            Msg::Abort => continue,
            _ => return Err(Error::internal("frame data without a frame")),
        };
        let mut abandoned = false;
        // The writer tells a frame's parts apart by their chunk counts.
        let mut next = || loop {
            planted_panic(Stage::Write, plan.frame);
            return match receive(Stage::Write, &rx) {
                Some(Msg::Strip(encoded)) => Ok(Some(encoded)),
                Some(Msg::Part(_)) => continue,
                Some(Msg::End) => Ok(None),
                Some(Msg::Abort) => {
                    abandoned = true;
                    Err(Error::stopped())
                }
                Some(Msg::Begin(_)) => Err(Error::internal("frame begun inside a frame")),
                None => Err(Error::stopped()),
            };
        };
        let written = frame_work(&plan.output, plan.label, || match &job.media {
            Some(review) => {
                let window = plan.header.data_window();
                let size = (window.size.width(), window.size.height());
                let alpha = plan
                    .header
                    .channels
                    .list
                    .iter()
                    .any(|c| c.name.to_string() == "A");
                let alpha = review.media.keeps_alpha(alpha);
                let mut strips = || match next()? {
                    Some(Encoded::Media(strip)) => Ok(Some(strip)),
                    Some(Encoded::Chunks(_)) => Err(Error::internal("chunks for a review frame")),
                    None => Ok(None),
                };
                if let Some(movie) = &review.movie {
                    return movie.frame(plan.label, size, alpha, strips);
                }
                let note = (fingerprint::ATTRIBUTE, plan.fingerprint.as_str());
                match review.media.format {
                    media::Format::Dpx => crate::io::dpx_out::write_frame(
                        &plan.output,
                        plan.label,
                        review.media.dpx_depth(),
                        &plan.header,
                        alpha,
                        note,
                        || match strips()?.map(|strip| strip.samples) {
                            Some(media::Samples::Packed(bytes)) => Ok(Some(bytes)),
                            Some(_) => Err(Error::internal("unpacked rows for a DPX frame")),
                            None => Ok(None),
                        },
                    ),
                    _ => media::write_frame(
                        &plan.output,
                        plan.label,
                        &review.media,
                        size,
                        alpha,
                        note,
                        strips,
                    ),
                }
            }
            None => {
                let chunks = || match next()? {
                    Some(Encoded::Chunks(chunks)) => Ok(Some(chunks)),
                    Some(Encoded::Media(_)) => Err(Error::internal("rows for an EXR frame")),
                    None => Ok(None),
                };
                write_file(&plan.output, plan.label, plan.output_parts(), chunks)
            }
        });
        match written {
            Ok(()) => events.written(&plan),
            // The temporary file is gone; an abandoned frame is reported upstream.
            Err(e) if e.kind == Kind::Stopped && abandoned => continue,
            // An earlier stage failed and reports why.
            Err(e) if e.kind == Kind::Stopped => return Ok(()),
            // Its temporary file is gone too.
            Err(e) if goes_on(job, &e) => {
                events.failed(plan.frame, &e);
                failed = true;
            }
            Err(e) => return Err(e),
        }
    }
    Ok(())
}
