//! Warnings, before a run, where users slip: inputs whose display windows
//! differ, and what each operation assumes of its inputs
//! (`Op::assumptions`). They are read from the first frame of each input,
//! opened as the job was made (`Job::first_files`); `run::run_job` prints
//! each once, unless `--quiet`.

use super::frame_plan::plan_parts;
use super::graph::{Display, Node};
use super::plan::{FirstFile, FrameSources, HeaderBase, Job};
use crate::io::header_text::box_text;
use crate::io::parts::choose_part;
use exr::meta::attribute::{ChannelDescription, IntegerBounds};
use exr::meta::header::Header;

/// The warnings for `job`, whose inputs were given as `texts`. None when a
/// first frame cannot be read or decoded (the run reports that) or is made
/// black.
pub fn warnings(job: &Job, texts: &[String]) -> Vec<String> {
    let Some(first) = job.frames.first() else {
        return Vec::new();
    };
    let mut warnings = assumed(job, texts, first);
    if job.all_parts {
        warnings.extend(carried_parts(job, first));
    }
    warnings
}

/// The warnings of the first frame's inputs (with `--all-parts`, of the
/// first part).
fn assumed(job: &Job, texts: &[String], first: &FrameSources) -> Vec<String> {
    let headers: Option<Vec<Header>> = (0..job.inputs.len())
        .map(|i| {
            let FirstFile { frame, file, .. } = job.first_files.get(i)?.as_ref()?;
            if *frame != first.frame {
                return None;
            }
            let part = choose_part(file, job.parts[i].as_deref(), job.view.as_deref()).ok()?;
            // A part the run cannot decode is its error alone.
            file.check_codec(part).ok()?;
            Some(file.header(part).clone())
        })
        .collect();
    let Some(headers) = headers else {
        return Vec::new();
    };
    let mut warnings = display_windows(job, texts, &headers);
    warnings.extend(lossy_default(job, texts, &headers));
    let graph = &job.graph;
    // As a frame's plan does, display windows before data windows; one an
    // op refuses is the run's error, not a warning's.
    let displays = graph.display_windows(|i| Display::of(&headers[i]));
    if displays.iter().any(Result::is_err) {
        return warnings;
    }
    let channels = graph.evaluate(
        |i| headers[i].channels.list.to_vec(),
        |op, args| {
            let lists: Vec<&[ChannelDescription]> = args.iter().map(Vec::as_slice).collect();
            op.channels(&lists)
        },
    );
    let windows = graph.evaluate(
        |i| {
            IntegerBounds::new(
                headers[i].own_attributes.layer_position,
                headers[i].layer_size,
            )
        },
        |op, args| op.data_window(args),
    );
    for node in &graph.nodes {
        if let Node::Op { op, inputs, .. } = node {
            let names: Vec<String> = inputs
                .iter()
                .map(|&n| match graph.nodes[n] {
                    Node::Input(i) => texts[i].clone(),
                    _ => format!("the result of node {n}"),
                })
                .collect();
            let lists: Vec<&[ChannelDescription]> =
                inputs.iter().map(|&n| channels[n].as_slice()).collect();
            let boxes: Vec<IntegerBounds> = inputs.iter().map(|&n| windows[n]).collect();
            warnings.extend(
                op.assumptions(&names, &lists, &boxes)
                    .into_iter()
                    .map(|w| node.locate(w)),
            );
        }
    }
    warnings
}

/// A lossy compression (DWAA, B44...) kept from the header input because
/// none was given: every channel is encoded again and loses a little more,
/// those the job leaves alone too (a transcode included).
fn lossy_default(job: &Job, texts: &[String], headers: &[Header]) -> Option<String> {
    let HeaderBase::Input(kept) = job.header_base else {
        return None;
    };
    let header = &headers[kept];
    let lossy = header
        .channels
        .list
        .iter()
        .any(|c| !header.compression.is_lossless_for(c.sample_type));
    (job.compression.is_none() && lossy).then(|| {
        format!(
            "{} has {}, which is lossy, and the output keeps it: every channel is \
             encoded again and loses a little more, those the job leaves alone too (give \
             --compression zip or piz to keep them exact)",
            texts[kept], header.compression
        )
    })
}

/// An input whose display window is not the header input's: the output
/// keeps the header input's, and pixels meet at their coordinates.
fn display_windows(job: &Job, texts: &[String], headers: &[Header]) -> Vec<String> {
    let HeaderBase::Input(kept) = job.header_base else {
        return Vec::new();
    };
    let display = |i: usize| headers[i].shared_attributes.display_window;
    (0..headers.len())
        .filter(|&i| i != kept && display(i) != display(kept))
        .map(|i| {
            format!(
                "{}'s display window {} is not {}'s {}: the output keeps {}'s, and the two meet \
                 pixel for pixel at the same coordinates, neither scaled nor moved (resize or \
                 move one first, e.g. oiiotool --resize or --origin)",
                texts[i],
                box_text(display(i)),
                texts[kept],
                box_text(display(kept)),
                texts[kept]
            )
        })
        .collect()
}

/// With `--all-parts`, the parts of the first frame the operations cannot
/// apply to, which are written unchanged: one note each, with the reason.
fn carried_parts(job: &Job, first: &FrameSources) -> Vec<String> {
    let Ok(plans) = plan_parts(job, first) else {
        return Vec::new();
    };
    let headers = plans[0].every_part.clone().unwrap_or_default();
    let name = |part: usize| match headers
        .get(part)
        .and_then(|h| h.own_attributes.layer_name.as_ref())
    {
        Some(name) => format!("part {part} ('{name}')"),
        None => format!("part {part}"),
    };
    (plans.iter().enumerate())
        .filter_map(|(part, plan)| {
            let refusal = plan.carried_as_is.as_ref()?;
            Some(format!(
                "{} is written unchanged: the operation does not apply to it ({})",
                name(part),
                refusal.message
            ))
        })
        .collect()
}
