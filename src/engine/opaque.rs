//! Output blocks where a merge's first input (A) hides its second (an
//! opaque foreground under `over`, any A under `copy`: `Op::hides_second`):
//! the written merge's, or, down a stack of merges (through their second
//! inputs), a lower layer's. There that merge's result is A bit for bit, so
//! the inputs read only under its second input need not be decoded: their
//! chunks of such a block are only checked to decompress (a damaged plate
//! under an opaque element is still reported). Where A's part has the
//! output's compression, channels and blocks, and the layers above A are
//! transparent black there, the output block is A's chunk as it is (read
//! once: kept from A's decode), with no encode. Together with the
//! transparent foregrounds of `passthrough.rs`, the decode order of a strip:
//! the inputs neither hidden nor passed; then, layer after layer from the
//! top, the first inputs down to the next hiding merge, but the blocks
//! hidden above them; then the other hidden inputs, but the blocks hidden;
//! then the passed source but its passing and hidden blocks. Rules:
//! specs/ops.md, "Blocks skipped under an opaque foreground".

use super::decode::{decode_strip, InputCursor, Region};
use super::frame_plan::{output_grid, FramePlan};
use super::graph::{intersection, Graph, Node};
use super::passthrough::{chunk_at, placed, shows_second, PassThrough, PassedBlock, Test};
use crate::error::Result;
use crate::io::rows::Rows;
use crate::io::writer::IndexedChunk;
use crate::stage_time::{self, Stage};
use exr::block::chunk::{Chunk, CompressedBlock};
use exr::math::Vec2;
use exr::meta::attribute::IntegerBounds;
use exr::prelude::Compression;
use rayon::prelude::*;
use std::collections::{HashMap, HashSet};
use std::ops::Range;

/// Where merges' first inputs hide their second inputs.
pub struct Opaque {
    /// The merges from the output down through their second inputs, each
    /// first input an input file, top first, at the output's pixels.
    chain: Vec<Test>,
    /// The merges of `chain` whose first input can hide the second, top first.
    levels: Vec<Level>,
    /// Per input, whether a level hides it.
    hides: Vec<bool>,
}

/// A merge whose first input (A) can hide its second.
struct Level {
    /// Its place in `chain`.
    at: usize,
    /// The inputs read only under the second input, through merges alone,
    /// ZIP or ZIPS: their chunks under a hidden block are only checked.
    hidden: Vec<usize>,
    /// Whether A's chunks can be output blocks: the output's pixels where
    /// they can (inside every merge's window down to A's), or `None`.
    passes: Option<IntegerBounds>,
}

/// An output block that a level's A hides.
struct HiddenBlock {
    /// The block's index in the output's offset table.
    index: usize,
    /// A's input, and A's chunk that is the block, when A's chunks pass
    /// and the layers above A are transparent over it.
    passed: Option<(usize, PassedBlock)>,
    /// The hidden inputs' chunks holding exactly the block: (input, chunk).
    under: Vec<(usize, usize)>,
}

impl Opaque {
    /// Whether `plan`'s output is a merge, or a stack of merges, with a first
    /// input that can hide its second; `chunks`: whether the output takes
    /// chunks (an EXR, not review media).
    pub fn find(graph: &Graph, plan: &FramePlan, chunks: bool) -> Option<Self> {
        let (mut chain, mut levels) = (Vec::new(), Vec::new());
        let mut node = graph.output();
        // Merges keep pixels in place: every merge of the chain has the
        // output's coordinates. Below the top, only merges that give their
        // second input where the first is transparent (over, not copy).
        while let Node::Op { op, inputs, .. } = &graph.nodes[node] {
            let &[a, second] = inputs.as_slice() else {
                break;
            };
            let Node::Input(first) = graph.nodes[a] else {
                break;
            };
            if !chain.is_empty() && !op.passes_second() {
                break;
            }
            chain.push((node, first, second, (0, 0)));
            levels.extend(Level::find(graph, plan, chunks, &chain));
            if !op.passes_second() {
                break;
            }
            node = second;
        }
        let mut hides = vec![false; plan.inputs.len()];
        levels
            .iter()
            .flat_map(|l| &l.hidden)
            .for_each(|&i| hides[i] = true);
        (!levels.is_empty()).then_some(Opaque {
            chain,
            levels,
            hides,
        })
    }

    /// The output blocks within `rows` that `level`'s A hides but no level
    /// above does (`taken`: those blocks' indices), given the strips of the
    /// first inputs down to A's.
    fn blocks(
        &self,
        level: &Level,
        (plan, graph): (&FramePlan, &Graph),
        strips: &[Option<Rows>],
        rows: Range<i32>,
        taken: &HashSet<usize>,
    ) -> Vec<HiddenBlock> {
        let (merge, first, second, _) = self.chain[level.at];
        let Node::Op { op, .. } = &graph.nodes[merge] else {
            return Vec::new();
        };
        let a = strips[first].as_ref().expect("A is decoded first");
        let (window, grid) = (plan.window(), output_grid(&plan.header));
        let (lines, width) = (grid.block.y() as i32, grid.block.x() as i32);
        let (top, bottom) = (window.position.y(), window.end().y());
        let start = rows.start.max(top);
        let start = top + (start - top + lines - 1) / lines * lines;
        let starts: Vec<i32> = (start..rows.end.min(bottom))
            .step_by(lines as usize)
            .filter(|y0| (y0 + lines).min(bottom) <= rows.end)
            .collect();
        let second = &plan.channels[second];
        let row_of_blocks = |y0: i32| {
            let y1 = (y0 + lines).min(bottom);
            let row = ((y0 - top) / lines) as usize;
            (0..grid.blocks.x())
                .filter(|&column| !taken.contains(&grid.chunk(column, row)))
                .filter_map(|column| {
                    let x0 = window.position.x() + column as i32 * width;
                    let x1 = (x0 + width).min(window.end().x());
                    let block =
                        IntegerBounds::new((x0, y0), ((x1 - x0) as usize, (y1 - y0) as usize));
                    let index = grid.chunk(column, row);
                    let passed = level
                        .passes
                        .filter(|inside| intersection(block, *inside) == block)
                        .and_then(|_| chunk_at(plan, first, block, (0, 0)))
                        .map(|chunk| PassedBlock {
                            index,
                            chunk,
                            tile: Vec2(column, row),
                        });
                    let under: Vec<(usize, usize)> = level
                        .hidden
                        .iter()
                        .filter_map(|&i| Some((i, chunk_at(plan, i, block, (0, 0))?)))
                        .collect();
                    let worth = passed.is_some() || !under.is_empty();
                    if !worth || !op.hides_second(a, second, y0..y1, x0..x1) {
                        return None;
                    }
                    // A is the block where the layers above show it.
                    let columns = (grid.blocks.x() > 1).then_some(x0..x1);
                    let shown = |&test: &Test| {
                        shows_second(plan, graph, strips, test, y0..y1, columns.as_ref())
                    };
                    let passed = passed
                        .filter(|_| self.chain[..level.at].iter().all(shown))
                        .map(|p| (first, p));
                    Some(HiddenBlock {
                        index,
                        passed,
                        under,
                    })
                })
                .collect::<Vec<_>>()
        };
        starts
            .into_par_iter()
            .flat_map_iter(stage_time::tasks(Stage::Decode, row_of_blocks))
            .collect()
    }

    /// The blocks hidden within `rows`, level after level from the top: the
    /// first inputs down to a level are decoded (into `strips`) before its
    /// blocks are found, but their chunks the levels above hide.
    fn cover(
        &self,
        (plan, graph): (&FramePlan, &Graph),
        cursors: &mut [InputCursor],
        regions: &[Region],
        strips: &mut [Option<Rows>],
        rows: Range<i32>,
    ) -> Result<Vec<HiddenBlock>> {
        let mut covered: Vec<HiddenBlock> = Vec::new();
        for level in &self.levels {
            let firsts: Vec<usize> = self.chain[..=level.at]
                .iter()
                .map(|test| test.1)
                .filter(|&i| strips[i].is_none())
                .collect();
            if !firsts.is_empty() {
                let skipped = under(&covered);
                let decoded = decode_strip(
                    cursors,
                    regions,
                    |i| firsts.contains(&i),
                    |i, k| skipped.contains(&(i, k)),
                )?;
                for (strip, decoded) in strips.iter_mut().zip(decoded) {
                    if decoded.is_some() {
                        *strip = decoded;
                    }
                }
            }
            let taken: HashSet<usize> = covered.iter().map(|b| b.index).collect();
            let found = self.blocks(level, (plan, graph), strips, rows.clone(), &taken);
            covered.extend(found);
        }
        Ok(covered)
    }

    /// The hidden inputs' chunks of `blocks` checked to decompress, and A's
    /// chunks that are output blocks, as output chunks: as read when A's
    /// strip was decoded (and so checked), or read again.
    fn chunks(
        &self,
        plan: &FramePlan,
        cursors: &mut [InputCursor],
        blocks: &[HiddenBlock],
    ) -> Result<Vec<IndexedChunk>> {
        let checked: Vec<(usize, usize)> = blocks.iter().flat_map(|b| b.under.clone()).collect();
        checked.par_iter().try_for_each(|&(i, k)| {
            let (file, part) = (&plan.inputs[i], plan.parts[i]);
            stage_time::task(Stage::Decode, || file.checked_zip_chunk(part, k)).map(drop)
        })?;
        let mut kept: HashMap<(usize, usize), CompressedBlock> = HashMap::new();
        for level in &self.levels {
            let first = self.chain[level.at].1;
            let chunks = std::mem::take(&mut cursors[first].kept);
            kept.extend(chunks.into_iter().map(|(k, block)| ((first, k), block)));
        }
        let passed: Vec<_> = blocks
            .iter()
            .filter_map(|b| b.passed.as_ref())
            .map(|(i, block)| (*i, block, kept.remove(&(*i, block.chunk))))
            .collect();
        passed
            .into_par_iter()
            .map(|(i, block, read)| {
                let chunk = match read {
                    Some(compressed_block) => Chunk {
                        layer_index: 0,
                        compressed_block,
                    },
                    None => {
                        let (file, part) = (&plan.inputs[i], plan.parts[i]);
                        let mut chunk =
                            stage_time::task(Stage::Decode, || file.read_chunk(part, block.chunk))?;
                        chunk.layer_index = 0;
                        chunk
                    }
                };
                Ok(placed(plan, chunk, block))
            })
            .collect()
    }

    /// Marks the first inputs whose chunks may pass, to be kept as read.
    fn keep(&self, cursors: &mut [InputCursor]) {
        for level in self.levels.iter().filter(|l| l.passes.is_some()) {
            cursors[self.chain[level.at].1].keep = true;
        }
    }
}

impl Level {
    /// The last merge of `chain` as a level, if its first input, an input
    /// file, can hide its second and that hides inputs or passes chunks.
    fn find(graph: &Graph, plan: &FramePlan, chunks: bool, chain: &[Test]) -> Option<Level> {
        let &(merge, first, second, _) = chain.last()?;
        let Node::Op { op, inputs, .. } = &graph.nodes[merge] else {
            return None;
        };
        let lists = [
            plan.channels[inputs[0]].as_slice(),
            plan.channels[second].as_slice(),
        ];
        if !op.may_hide_second(&lists) || plan.deep[first].is_some() {
            return None;
        }
        let hidden: Vec<usize> = merges_to_inputs(graph, second)
            .unwrap_or_default()
            .into_iter()
            .filter(|&i| {
                i != first
                    && plan.deep[i].is_none()
                    && plan.levels[i].index == Vec2(0, 0)
                    && zip(plan.header_of(i).compression)
            })
            .collect();
        let (out, source) = (&plan.header, plan.header_of(first));
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
        // The merges above give their second input's channels as they are.
        let above = chain[..chain.len() - 1]
            .iter()
            .all(|&(m, _, s, _)| plan.channels[m] == plan.channels[s]);
        let passes = chunks
            && channels
            && above
            && zip(out.compression)
            && source.compression == out.compression
            && source.blocks.has_tiles() == out.blocks.has_tiles()
            && plan.levels[first].block == grid.block
            && plan.levels[first].index == Vec2(0, 0)
            && plan.windows[inputs[0]] == source.data_window();
        let inside = chain.iter().fold(plan.window(), |w, &(m, ..)| {
            intersection(w, plan.windows[m])
        });
        let passes = passes.then_some(inside);
        (passes.is_some() || !hidden.is_empty()).then_some(Level {
            at: chain.len() - 1,
            hidden,
            passes,
        })
    }
}

/// The hidden inputs' chunks of `blocks`.
fn under(blocks: &[HiddenBlock]) -> HashSet<(usize, usize)> {
    blocks
        .iter()
        .flat_map(|b| b.under.iter().copied())
        .collect()
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
/// transparent foregrounds, a level's A's under opaque ones) or that a
/// level's A hides, which are checked; returns the strips and the passing
/// blocks as output chunks.
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
    if let Some(o) = opaque {
        o.keep(cursors);
    }
    let mut strips = decode_strip(
        cursors,
        regions,
        |i| !hidden(i) && Some(i) != source,
        |_, _| false,
    )?;
    let covered = match opaque {
        Some(o) => o.cover((plan, graph), cursors, regions, &mut strips, rows.clone())?,
        None => Vec::new(),
    };
    let skipped = under(&covered);
    let skipped = |i: usize, k: usize| skipped.contains(&(i, k));
    let later = decode_strip(
        cursors,
        regions,
        |i| strips[i].is_none() && Some(i) != source,
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
        passed.extend(o.chunks(plan, cursors, &covered)?);
    }
    let strips = strips
        .into_iter()
        .map(|s| s.expect("every input decoded"))
        .collect();
    Ok((strips, passed))
}
