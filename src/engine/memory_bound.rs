//! The most memory one frame's run holds at once, from its plan: the bound
//! of specs/architecture.md ("Memory bound", and "Regions of interest" for
//! nodes that stream at another size), which a farm job asks of its workers.

use super::frame_plan::FramePlan;
use super::graph::{Graph, Node};
use super::region::Regions;
use exr::meta::attribute::IntegerBounds;

/// Program, thread stacks and allocator.
const PROGRAM: u64 = 10 << 20;

/// Bytes at most resident while `plan` runs through `graph`:
///
/// ```text
/// Σ_inputs 3 (S_i + 2 L_i) R_i b_i + Σ_inputs 2 S_i R_i b_i
///     + max_live Σ W_n (S_n + 2 h_n) b_n + (5 + 2 B) S W b_o + 10 MiB
/// ```
///
/// with `W` and `S` the output's width and strip rows (at most the rows
/// computed: a strip never holds more), `W_n` a node's region's width and
/// `S_n` the most rows of its region a strip spans (`S` where nothing
/// resamples), `R_i` the width an input is decoded over (its data window
/// read: none for a black input) and `S_i` its node's span, and `B` the
/// batches of chunks the writer lets wait (`writer::IN_FLIGHT`), each with
/// its bytes laid out. An input read whole (its span its whole region: a
/// turn near 90 degrees, readers that disagree) is decoded once, its first
/// term `(S_i + 2 L_i + S_i + 2 min(T L_i, S_i + 2 L_i)) R_i b_i` and no
/// strip in the channel, `T` the threads.
pub fn memory_bound(plan: &FramePlan, graph: &Graph) -> u64 {
    let s = plan.strip_rows.min(plan.computed.size.height()) as u64;
    let threads = rayon::current_num_threads() as u64;
    let spans = spanned_rows(graph, &plan.regions, plan.computed, plan.strip_rows);
    let bytes = |channels: &[exr::meta::attribute::ChannelDescription]| {
        channels
            .iter()
            .map(|c| c.sample_type.bytes_per_sample() as u64)
            .sum::<u64>()
    };
    let decode: u64 = (0..plan.inputs.len())
        .map(|i| {
            let row = plan.read[i].size.width() as u64 * bytes(&plan.header_of(i).channels.list);
            let rows = graph.input_node(i).map_or(s, |n| spans[n] as u64);
            let lines = plan.levels[i].block.y() as u64;
            let whole = !plan.regions.shared()
                && graph
                    .input_node(i)
                    .is_some_and(|n| spans[n] >= plan.regions.rect(n).size.height());
            match whole {
                // Decoded once: its chunks and the strip built of them, and
                // a chunk's bytes read and inflated per thread.
                true => {
                    let in_flight = (threads * lines).min(rows + 2 * lines);
                    row * (rows + 2 * lines + rows + 2 * in_flight)
                }
                false => row * (3 * (rows + 2 * lines) + 2 * rows),
            }
        })
        .sum();
    let held = window_rows(graph, &spans);
    let windows = graph.peak(|n| {
        let width = plan.regions.rect(n).size.width();
        width * held[n] * bytes(&plan.channels[n]) as usize
    });
    let width = plan.computed.size.width() as u64;
    let waiting = 2 * crate::io::writer::IN_FLIGHT as u64;
    let encode = (5 + waiting) * s * width * bytes(&plan.header.channels.list);
    decode + windows as u64 + encode + PROGRAM
}

/// Per node, the most rows its compose window holds at once: the most rows
/// of its region one strip spans (`spanned_rows`) and its consumers' halo
/// above and below. Compose makes room for them before a window first
/// grows, so that it never grows by moving (a Vec doubling: its new buffer
/// twice the rows, the old one left resident in the heap).
pub fn window_rows(graph: &Graph, spans: &[usize]) -> Vec<usize> {
    let mut halo = vec![0; graph.nodes.len()];
    for node in &graph.nodes {
        if let Node::Op { op, inputs, .. } = node {
            for &i in inputs {
                halo[i] = halo[i].max(op.halo());
            }
        }
    }
    (0..graph.nodes.len())
        .map(|n| spans[n] + 2 * halo[n])
        .collect()
}

/// Per node, the most rows of its region one strip of `strip_rows` rows of
/// `computed` spans: the strip's own where nothing resamples; behind a
/// resize or transform, the most its zone's span takes over the frame's
/// strips (the whole region for a zone read whole, a turn near 90 degrees).
pub fn spanned_rows(
    graph: &Graph,
    regions: &Regions,
    computed: IntegerBounds,
    strip_rows: usize,
) -> Vec<usize> {
    let s = strip_rows.clamp(1, computed.size.height().max(1));
    let mut most = vec![s; graph.nodes.len()];
    if regions.shared() {
        return most;
    }
    most.fill(0);
    let (top, bottom) = (computed.position.y(), computed.end().y());
    for start in (top..bottom).step_by(s) {
        let spans = regions.spans(graph, start..bottom.min(start + s as i32));
        for (n, most) in most.iter_mut().enumerate() {
            *most = (*most).max(regions.span(&spans, n).len());
        }
    }
    most
}
