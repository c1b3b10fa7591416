//! Output blocks copied from an input's compressed chunks. Where the top
//! inputs of a merge (or of a stack of them) are transparent black over a
//! whole output block, the result is the bottom input's block bit for bit; if
//! the two files share compression, channels and block grid, the output block
//! is that input's chunk: checked to decompress, then written as it is, with
//! no decode, composite or encode. On a CG element over a plate most blocks
//! are such blocks.

use super::decode::{decode_strip, InputCursor};
use super::graph::{Graph, Node};
use super::plan::{output_grid, FramePlan};
use super::stage_time::{self, Stage};
use super::strip::Rows;
use crate::error::Result;
use crate::io::writer::IndexedChunk;
use exr::block::chunk::CompressedBlock;
use exr::math::Vec2;
use exr::prelude::Compression;
use rayon::prelude::*;
use std::ops::Range;

/// How a frame's output blocks can come from one input's chunks.
pub struct PassThrough {
    /// The input whose chunks are copied (the bottom of the merges).
    pub source: usize,
    /// Per merge from the output down: the merge node, the input its first
    /// input reads, and its second input's node. All first inputs must be
    /// transparent black over a block for it to pass.
    tests: Vec<(usize, usize, usize)>,
    /// The rows where every node from the output down to the source holds
    /// the source's pixels (inside each crop's window).
    rows: Range<i32>,
}

/// An output block made of an input's chunk.
struct PassedBlock {
    /// The block's index in the output's offset table.
    index: usize,
    /// The input's chunk index.
    chunk: usize,
    /// The block's column and row in the output's grid.
    tile: Vec2<usize>,
}

impl PassThrough {
    /// Whether `plan`'s output can take chunks from an input, and which.
    pub fn find(graph: &Graph, plan: &FramePlan) -> Option<Self> {
        // Inputs behind a resize (or a cut) stream in rows of their own.
        if !plan.regions.shared() {
            return None;
        }
        let (out, window) = (&plan.header, plan.window());
        // Per output channel as written, the channel of the node reached
        // whose samples it is.
        let output = graph.output();
        let mut map: Vec<usize> = out
            .channels
            .list
            .iter()
            .map(|c| plan.channels[output].iter().position(|o| o.name == c.name))
            .collect::<Option<_>>()?;
        let mut tests = Vec::new();
        // The rows every node on the way down holds the source's pixels in.
        let (mut top, mut bottom) = (window.position.y(), window.end().y());
        let mut node = output;
        let source = loop {
            let w = plan.windows[node];
            if (w.position.x(), w.size.width()) != (window.position.x(), window.size.width()) {
                return None;
            }
            (top, bottom) = (top.max(w.position.y()), bottom.min(w.end().y()));
            match &graph.nodes[node] {
                Node::Input(i) if node != output => break *i,
                Node::Op { op, inputs, .. } if op.passes_second() && inputs.len() == 2 => {
                    let Node::Input(first) = graph.nodes[inputs[0]] else {
                        return None;
                    };
                    // Each channel the merge's, from its second input.
                    let (merged, second) = (&plan.channels[node], &plan.channels[inputs[1]]);
                    map = map
                        .iter()
                        .map(|&k| second.iter().position(|c| *c == merged[k]))
                        .collect::<Option<_>>()?;
                    tests.push((node, first, inputs[1]));
                    node = inputs[1];
                }
                Node::Op { op, inputs, .. } if inputs.len() == 1 => {
                    let carried = op.carries(&[&plan.channels[inputs[0]]])?;
                    map = map.iter().map(|&k| carried[k]).collect();
                    node = inputs[0];
                }
                _ => return None,
            }
        };
        let source_header = plan.header_of(source);
        let input = source_header.data_window();
        let grid = output_grid(out);
        let lines = grid.block.y() as i32;
        // The chunks' samples, channel after channel, must be the output's
        // blocks': the same channels in order (names aside), none dropped.
        let list = &source_header.channels.list;
        let laid_out = map.iter().copied().eq(0..list.len())
            && out.channels.list.iter().zip(list.iter()).all(|(o, i)| {
                (o.sample_type, o.sampling, o.quantize_linearly)
                    == (i.sample_type, i.sampling, i.quantize_linearly)
            });
        // The source is decoded after the inputs tested, so it is not one.
        // Its blocks must be the output's: scanline blocks of the same
        // columns, or tiles of the same size (of level 0, as written).
        let same = laid_out
            && tests.iter().all(|&(_, first, _)| first != source)
            && plan.deep[source].is_none()
            && source_header.blocks.has_tiles() == out.blocks.has_tiles()
            && plan.levels[source].block == grid.block
            && plan.levels[source].index == exr::math::Vec2(0, 0)
            && plan.windows[node] == input
            && matches!(out.compression, Compression::ZIP1 | Compression::ZIP16)
            && source_header.compression == out.compression
            && (input.position.y() - window.position.y()) % lines == 0;
        same.then_some(PassThrough {
            source,
            tests,
            rows: top..bottom,
        })
    }

    /// Decodes strip `rows` of every input but the source's chunks of the
    /// blocks that pass, which come back checked, as output chunks.
    pub fn decode(
        &self,
        plan: &FramePlan,
        graph: &Graph,
        cursors: &mut [InputCursor],
        columns: (i32, usize),
        rows: Range<i32>,
    ) -> Result<(Vec<Rows>, Vec<IndexedChunk>)> {
        let source = self.source;
        let regions = vec![(columns, rows.clone()); cursors.len()];
        let mut strips = decode_strip(cursors, &regions, |i| i != source, |_, _| false)?;
        let blocks = self.blocks(plan, graph, &strips, rows.clone());
        let passed = |k: usize| blocks.iter().any(|b| b.chunk == k);
        let mut own = decode_strip(cursors, &regions, |i| i == source, |_, k| passed(k))?;
        strips[source] = own[source].take();
        let strips = strips
            .into_iter()
            .map(|s| s.expect("every input decoded"))
            .collect();
        Ok((strips, self.chunks(plan, &blocks)?))
    }

    /// The output blocks within `rows` (whole blocks of the output's grid)
    /// that are the source's chunks, given the strips of the other inputs.
    fn blocks(
        &self,
        plan: &FramePlan,
        graph: &Graph,
        strips: &[Option<Rows>],
        rows: Range<i32>,
    ) -> Vec<PassedBlock> {
        let window = plan.window();
        let input = plan.header_of(self.source).data_window();
        let (inside, end) = (&self.rows, input.end().y());
        let (grid, source) = (output_grid(&plan.header), plan.levels[self.source]);
        let lines = grid.block.y() as i32;
        let (top, bottom) = (window.position.y(), window.end().y());
        let first = rows.start.max(top);
        let first = top + (first - top + lines - 1) / lines * lines;
        // Each row of blocks is tested on the pool: the foreground's scan is
        // most of what decides, and no business of the decode thread's.
        let starts: Vec<i32> = (first..rows.end.min(bottom))
            .step_by(lines as usize)
            .collect();
        let row_of_blocks = |y0: i32| {
            let mut passed = Vec::new();
            let y1 = (y0 + lines).min(bottom);
            // The input's chunk must hold exactly these rows, every node
            // the source's pixels.
            let same_end = (y0 + lines).min(end) == y1;
            if y1 > rows.end || y0 < inside.start || y1 > inside.end || !same_end {
                return passed;
            }
            let (row, source_row) = ((y0 - top) / lines, (y0 - input.position.y()) / lines);
            // Whether every merge's first input hides nothing over the
            // columns `x0..x1` of these rows (a copy of them, for a tile).
            let hidden = |columns: Option<(i32, i32)>| {
                self.tests.iter().all(|&(merge, first, second)| {
                    let Node::Op { op, .. } = &graph.nodes[merge] else {
                        return false;
                    };
                    let strip = strips[first]
                        .as_ref()
                        .expect("tested inputs are decoded first");
                    let second = &plan.channels[second];
                    match columns {
                        None => op.hides_nothing(strip, second, y0..y1),
                        Some((x0, x1)) => {
                            op.hides_nothing(&strip.copy_region(y0..y1, x0..x1), second, y0..y1)
                        }
                    }
                })
            };
            // A whole row of blocks passes at once (every scanline block, and
            // most tile rows under a small element).
            let whole = hidden(None);
            for column in 0..grid.blocks.x() {
                let x0 = window.position.x() + (column * grid.block.x()) as i32;
                let x1 = (x0 + grid.block.x() as i32).min(window.end().x());
                if whole || (grid.blocks.x() > 1 && hidden(Some((x0, x1)))) {
                    passed.push(PassedBlock {
                        index: grid.chunk(column, row as usize),
                        chunk: source.chunk(column, source_row as usize),
                        tile: Vec2(column, row as usize),
                    });
                }
            }
            passed
        };
        starts
            .into_par_iter()
            .flat_map_iter(stage_time::tasks(Stage::Decode, row_of_blocks))
            .collect()
    }

    /// The source's chunks for `blocks`, each checked to decompress, as
    /// output chunks.
    fn chunks(&self, plan: &FramePlan, blocks: &[PassedBlock]) -> Result<Vec<IndexedChunk>> {
        let (file, part) = (&plan.inputs[self.source], plan.parts[self.source]);
        blocks
            .par_iter()
            .map(|block| {
                let mut chunk =
                    stage_time::task(Stage::Decode, || file.checked_zip_chunk(part, block.chunk))?;
                // A tile's coordinates count from the data window's top.
                if let CompressedBlock::Tile(tile) = &mut chunk.compressed_block {
                    tile.coordinates.tile_index = block.tile;
                }
                Ok(IndexedChunk {
                    index: block.index,
                    chunk,
                })
            })
            .collect()
    }
}
