//! Output blocks where the written merge's first input (A) hides its second
//! (an opaque foreground under `over`, any A under `copy`: `Op::hides_second`).
//! There the result is A bit for bit, so the inputs read only under the
//! merge's second input need not be decoded: their chunks of such a block
//! are only checked to decompress (a damaged plate under an opaque element
//! is still reported). Where A's part has the output's compression, channels
//! and blocks, the output block is A's chunk as it is, with no encode.
//! Together with the transparent foregrounds of `passthrough.rs`, the decode
//! order of a strip: the inputs neither hidden nor passed, then the hidden
//! ones but the blocks A hides, then the passed source but its passing and
//! hidden blocks. Rules: specs/ops.md, "Blocks skipped under an opaque
//! foreground".

use super::decode::{decode_strip, InputCursor, Region};
use super::frame_plan::{output_grid, FramePlan};
use super::graph::{Graph, Node};
use super::passthrough::{chunk_at, placed, PassThrough, PassedBlock};
use crate::error::Result;
use crate::io::rows::Rows;
use crate::io::writer::IndexedChunk;
use crate::stage_time::{self, Stage};
use exr::math::Vec2;
use exr::meta::attribute::IntegerBounds;
use exr::prelude::Compression;
use rayon::prelude::*;
use std::ops::Range;

/// How the written merge's first input hides its second.
pub struct Opaque {
    /// The merge (the output node) and its second input's node.
    merge: usize,
    second: usize,
    /// The input the merge's first input reads (A).
    first: usize,
    /// The inputs read only under the second input, through merges alone,
    /// ZIP or ZIPS: their chunks under a hidden block are only checked.
    hidden: Vec<usize>,
    /// Per input, whether `hidden` holds it.
    hides: Vec<bool>,
    /// Whether A's chunks can be output blocks.
    passes: bool,
}

/// An output block that A hides.
struct HiddenBlock {
    /// A's chunk that is the block, when A's chunks pass.
    passed: Option<PassedBlock>,
    /// The hidden inputs' chunks holding exactly the block: (input, chunk).
    under: Vec<(usize, usize)>,
}

impl Opaque {
    /// Whether `plan`'s output is a merge whose first input, an input file,
    /// can hide its second; `chunks`: whether the output takes chunks (an
    /// EXR, not review media).
    pub fn find(graph: &Graph, plan: &FramePlan, chunks: bool) -> Option<Self> {
        let merge = graph.output();
        let Node::Op { op, inputs, .. } = &graph.nodes[merge] else {
            return None;
        };
        let &[a, second] = inputs.as_slice() else {
            return None;
        };
        let Node::Input(first) = &graph.nodes[a] else {
            return None;
        };
        let lists = [
            plan.channels[a].as_slice(),
            plan.channels[second].as_slice(),
        ];
        if !op.may_hide_second(&lists) || plan.deep[*first].is_some() {
            return None;
        }
        let hidden: Vec<usize> = merges_to_inputs(graph, second)
            .unwrap_or_default()
            .into_iter()
            .filter(|&i| {
                i != *first
                    && plan.deep[i].is_none()
                    && plan.levels[i].index == Vec2(0, 0)
                    && zip(plan.header_of(i).compression)
            })
            .collect();
        let (out, source) = (&plan.header, plan.header_of(*first));
        let grid = output_grid(out);
        let channels = out.channels.list.len() == source.channels.list.len()
            && out
                .channels
                .list
                .iter()
                .zip(&source.channels.list)
                .all(|(o, i)| {
                    (&o.name, o.sample_type, o.sampling, o.quantize_linearly)
                        == (&i.name, i.sample_type, i.sampling, i.quantize_linearly)
                });
        let passes = chunks
            && channels
            && zip(out.compression)
            && source.compression == out.compression
            && source.blocks.has_tiles() == out.blocks.has_tiles()
            && plan.levels[*first].block == grid.block
            && plan.levels[*first].index == Vec2(0, 0)
            && plan.windows[a] == source.data_window();
        let mut hides = vec![false; plan.inputs.len()];
        hidden.iter().for_each(|&i| hides[i] = true);
        (passes || !hidden.is_empty()).then_some(Opaque {
            merge,
            second,
            first: *first,
            hidden,
            hides,
            passes,
        })
    }

    /// The output blocks within `rows` that A hides, given A's strip.
    fn blocks(
        &self,
        plan: &FramePlan,
        graph: &Graph,
        a: &Rows,
        rows: Range<i32>,
    ) -> Vec<HiddenBlock> {
        let Node::Op { op, .. } = &graph.nodes[self.merge] else {
            return Vec::new();
        };
        let (window, grid) = (plan.window(), output_grid(&plan.header));
        let (lines, width) = (grid.block.y() as i32, grid.block.x() as i32);
        let (top, bottom) = (window.position.y(), window.end().y());
        let first = rows.start.max(top);
        let first = top + (first - top + lines - 1) / lines * lines;
        let starts: Vec<i32> = (first..rows.end.min(bottom))
            .step_by(lines as usize)
            .filter(|y0| (y0 + lines).min(bottom) <= rows.end)
            .collect();
        let second = &plan.channels[self.second];
        let row_of_blocks = |y0: i32| {
            let y1 = (y0 + lines).min(bottom);
            let row = ((y0 - top) / lines) as usize;
            (0..grid.blocks.x())
                .filter_map(|column| {
                    let x0 = window.position.x() + column as i32 * width;
                    let x1 = (x0 + width).min(window.end().x());
                    let block =
                        IntegerBounds::new((x0, y0), ((x1 - x0) as usize, (y1 - y0) as usize));
                    let passed = self
                        .passes
                        .then(|| chunk_at(plan, self.first, block, (0, 0)))
                        .flatten()
                        .map(|chunk| PassedBlock {
                            index: grid.chunk(column, row),
                            chunk,
                            tile: Vec2(column, row),
                        });
                    let under: Vec<(usize, usize)> = self
                        .hidden
                        .iter()
                        .filter_map(|&i| Some((i, chunk_at(plan, i, block, (0, 0))?)))
                        .collect();
                    let worth = passed.is_some() || !under.is_empty();
                    (worth && op.hides_second(a, second, y0..y1, x0..x1))
                        .then_some(HiddenBlock { passed, under })
                })
                .collect::<Vec<_>>()
        };
        starts
            .into_par_iter()
            .flat_map_iter(stage_time::tasks(Stage::Decode, row_of_blocks))
            .collect()
    }

    /// The hidden inputs' chunks of `blocks` checked to decompress, and A's
    /// chunks that are output blocks, as output chunks. A's were decoded
    /// (and so checked) for this strip already: they are read as they are.
    fn chunks(&self, plan: &FramePlan, blocks: &[HiddenBlock]) -> Result<Vec<IndexedChunk>> {
        let checked: Vec<(usize, usize)> = blocks.iter().flat_map(|b| b.under.clone()).collect();
        checked.par_iter().try_for_each(|&(i, k)| {
            let (file, part) = (&plan.inputs[i], plan.parts[i]);
            stage_time::task(Stage::Decode, || file.checked_zip_chunk(part, k)).map(drop)
        })?;
        let (file, part) = (&plan.inputs[self.first], plan.parts[self.first]);
        blocks
            .par_iter()
            .filter_map(|b| b.passed.as_ref())
            .map(|block| {
                let mut chunk =
                    stage_time::task(Stage::Decode, || file.read_chunk(part, block.chunk))?;
                chunk.layer_index = 0;
                Ok(placed(plan, chunk, block))
            })
            .collect()
    }
}

fn zip(compression: Compression) -> bool {
    matches!(compression, Compression::ZIP1 | Compression::ZIP16)
}

/// The inputs `node` reads through merges alone (ops that keep pixels in
/// place and read no neighbours), each node on the way read by one node
/// alone; `None` when it reads anything else. Walked without recursion: a
/// job file's stack may be thousands of merges deep.
fn merges_to_inputs(graph: &Graph, node: usize) -> Option<Vec<usize>> {
    let mut readers = vec![0usize; graph.nodes.len()];
    for n in &graph.nodes {
        if let Node::Op { inputs, .. } = n {
            let mut read = inputs.clone();
            read.sort_unstable();
            read.dedup();
            read.into_iter().for_each(|i| readers[i] += 1);
        }
    }
    if readers[node] != 1 {
        return None;
    }
    let (mut found, mut todo) = (Vec::new(), vec![node]);
    while let Some(n) = todo.pop() {
        match &graph.nodes[n] {
            Node::Input(i) => found.push(*i),
            Node::Op { op, inputs, .. } if op.passes_second() => {
                if inputs.iter().any(|&i| readers[i] != 1) {
                    return None;
                }
                todo.extend(inputs);
            }
            Node::Op { .. } => return None,
        }
    }
    // An input read as two nodes is read elsewhere too.
    let mut nodes_of = vec![0usize; found.iter().max().map_or(0, |m| m + 1)];
    for n in &graph.nodes {
        if let Node::Input(i) = n {
            if let Some(count) = nodes_of.get_mut(*i) {
                *count += 1;
            }
        }
    }
    let mut once = found.clone();
    once.sort_unstable();
    once.dedup();
    (once.len() == found.len() && found.iter().all(|&i| nodes_of[i] == 1)).then_some(found)
}

/// Decodes `regions` of every input (those of output strip `rows`) but the
/// chunks of blocks that pass as an input's chunk (`pass`'s source's under
/// transparent foregrounds, A's under opaque ones) or that A hides, which
/// are checked; returns the strips and the passing blocks as output chunks.
pub fn decode(
    (pass, opaque): (Option<&PassThrough>, Option<&Opaque>),
    plan: &FramePlan,
    graph: &Graph,
    cursors: &mut [InputCursor],
    regions: &[Region],
    rows: Range<i32>,
) -> Result<(Vec<Rows>, Vec<IndexedChunk>)> {
    let source = pass.map(|p| p.source);
    let hidden = |i: usize| opaque.is_some_and(|o| o.hides[i]);
    let mut strips = decode_strip(
        cursors,
        regions,
        |i| !hidden(i) && Some(i) != source,
        |_, _| false,
    )?;
    let covered = match opaque {
        Some(o) => {
            let a = strips[o.first].as_ref().expect("A is decoded first");
            o.blocks(plan, graph, a, rows.clone())
        }
        None => Vec::new(),
    };
    let skipped = |i: usize, k: usize| covered.iter().any(|b| b.under.contains(&(i, k)));
    let later = decode_strip(
        cursors,
        regions,
        |i| hidden(i) && Some(i) != source,
        skipped,
    )?;
    for (strip, decoded) in strips.iter_mut().zip(later) {
        if decoded.is_some() {
            *strip = decoded;
        }
    }
    let mut passed = Vec::new();
    if let (Some(pass), Some(s)) = (pass, source) {
        let blocks = pass.blocks(plan, graph, &strips, rows);
        let through = |k: usize| blocks.iter().any(|b| b.chunk == k);
        let mut own = decode_strip(
            cursors,
            regions,
            |i| i == s,
            |i, k| through(k) || skipped(i, k),
        )?;
        strips[s] = own[s].take();
        passed = pass.chunks(plan, &blocks)?;
    }
    if let Some(o) = opaque {
        passed.extend(o.chunks(plan, &covered)?);
    }
    let strips = strips
        .into_iter()
        .map(|s| s.expect("every input decoded"))
        .collect();
    Ok((strips, passed))
}
