//! The most memory one frame's run holds at once, from its plan: the bound
//! of specs/architecture.md ("Memory bound"), which a farm job asks of its
//! workers.

use super::graph::{Graph, Node};
use super::plan::FramePlan;

/// Program, thread stacks and allocator.
const PROGRAM: u64 = 10 << 20;

/// Bytes at most resident while `plan` runs through `graph`:
///
/// ```text
/// W × [ Σ_inputs 3 (S + 2 L_i) b_i + Σ_inputs 2 S b_i
///     + max_live Σ (S + 2 h_n) b_n + (5 + 2 B) S b_o ] + 10 MiB
/// ```
///
/// with an input's terms across the width it is decoded over (its data
/// window read: none for a black input), and `S` at most the rows computed
/// (a strip never holds more), and `B` the batches of chunks the writer
/// lets wait (`writer::IN_FLIGHT`), each with its bytes laid out.
pub fn memory_bound(plan: &FramePlan, graph: &Graph) -> u64 {
    let s = plan.strip_rows.min(plan.computed.size.height()) as u64;
    let width = plan.computed.size.width() as u64;
    let bytes = |channels: &[exr::meta::attribute::ChannelDescription]| {
        channels
            .iter()
            .map(|c| c.sample_type.bytes_per_sample() as u64)
            .sum::<u64>()
    };
    let decode: u64 = (0..plan.inputs.len())
        .map(|i| {
            let row = plan.read[i].size.width() as u64 * bytes(&plan.header_of(i).channels.list);
            let lines = plan.levels[i].block.y() as u64;
            row * (3 * (s + 2 * lines) + 2 * s)
        })
        .sum();
    // A node's window holds its consumers' halo above and below the strip.
    let mut halo = vec![0u64; graph.nodes.len()];
    for node in &graph.nodes {
        if let Node::Op { op, inputs, .. } = node {
            for &i in inputs {
                halo[i] = halo[i].max(op.halo() as u64);
            }
        }
    }
    let windows = graph.peak(|n| (width * (s + 2 * halo[n]) * bytes(&plan.channels[n])) as usize);
    let waiting = 2 * crate::io::writer::IN_FLIGHT as u64;
    let encode = (5 + waiting) * s * width * bytes(&plan.header.channels.list);
    decode + windows as u64 + encode + PROGRAM
}
