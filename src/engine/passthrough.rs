//! Output blocks copied from an input's compressed chunks. Where the top
//! inputs of a merge (or of a stack of them) are transparent black over a
//! whole output block, the result is the bottom input's block bit for bit; if
//! the two files share compression, channels and block grid, the output block
//! is that input's chunk: checked to decompress, then written as it is, with
//! no decode, composite or encode. On a CG element over a plate most blocks
//! are such blocks. Ops that keep an input's samples (a crop, a rename, a
//! resize to the same size) or move them by whole blocks (a cut, a
//! reformat's placement) pass blocks the same way, stored at the output's
//! coordinates. Rules: specs/architecture.md,
//! "Blocks passed through".

use super::frame_plan::{output_grid, FramePlan};
use super::graph::{intersection, moved, Graph, Node};
use crate::error::Result;
use crate::io::rows::Rows;
use crate::io::writer::IndexedChunk;
use crate::stage_time::{self, Stage};
use exr::block::chunk::{Chunk, CompressedBlock};
use exr::math::Vec2;
use exr::meta::attribute::{ChannelDescription, IntegerBounds};
use exr::prelude::Compression;
use rayon::prelude::*;
use std::ops::Range;

/// How a frame's output blocks can come from one input's chunks.
pub struct PassThrough {
    /// The input whose chunks are copied (the bottom of the merges).
    pub source: usize,
    /// Per merge from the output down: the merge node, the input its first
    /// input reads, its second input's node, and the merge's pixel (x + dx,
    /// y + dy) that is the output's (x, y). All first inputs must be
    /// transparent black over a block for it to pass.
    tests: Vec<Test>,
    /// The output's pixels that every node from the output down to the
    /// source holds the source's pixels in (inside each crop's window).
    inside: IntegerBounds,
    /// The source's pixel (x + dx, y + dy) is the output's (x, y).
    shift: (i32, i32),
}

/// An output block made of an input's chunk.
pub(super) struct PassedBlock {
    /// The block's index in the output's offset table.
    pub index: usize,
    /// The input's chunk index.
    pub chunk: usize,
    /// The block's column and row in the output's grid.
    pub tile: Vec2<usize>,
}

impl PassThrough {
    /// Whether `plan`'s output can take chunks from an input, and which.
    pub fn find(graph: &Graph, plan: &FramePlan) -> Option<Self> {
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
        // The output's pixels every node on the way down holds the source's
        // pixels in, and where the node reached has the output's (x, y).
        let (mut inside, mut shift) = (window, (0, 0));
        let mut node = output;
        let source = loop {
            inside = intersection(inside, moved(plan.windows[node], (-shift.0, -shift.1)));
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
                    tests.push((node, first, inputs[1], shift));
                    node = inputs[1];
                }
                Node::Op { op, inputs, .. } => {
                    let lists: Vec<&[ChannelDescription]> = inputs
                        .iter()
                        .map(|&n| plan.channels[n].as_slice())
                        .collect();
                    let carried = op.carries(&lists)?;
                    map = map.iter().map(|&k| carried.channels[k]).collect();
                    shift = (shift.0 + carried.shift.0, shift.1 + carried.shift.1);
                    node = inputs[carried.input];
                }
                _ => return None,
            }
        };
        let source_header = plan.header_of(source);
        let (input, grid) = (source_header.data_window(), output_grid(out));
        // The output's blocks, moved, start on the source's grid: all of
        // them, or none.
        let (x, y) = (
            window.position.x() + shift.0 - input.position.x(),
            window.position.y() + shift.1 - input.position.y(),
        );
        let on_grid = x % grid.block.x() as i32 == 0 && y % grid.block.y() as i32 == 0;
        // The chunks' samples, channel after channel, must be the output's
        // blocks': the same channels in order (names aside), none dropped.
        // A subsampled channel's lines in a block depend on where the block
        // starts, so those blocks do not move.
        let list = &source_header.channels.list;
        let laid_out = map.iter().copied().eq(0..list.len())
            && out.channels.list.iter().zip(list.iter()).all(|(o, i)| {
                (o.sample_type, o.sampling, o.quantize_linearly)
                    == (i.sample_type, i.sampling, i.quantize_linearly)
                    && (shift == (0, 0) || i.sampling == Vec2(1, 1))
            });
        // The source is decoded after the inputs tested, so it is not one.
        // Its blocks must be the output's: scanline blocks of the same
        // lines, or tiles of the same size (of level 0, as written).
        let same = laid_out
            && on_grid
            && tests.iter().all(|&(_, first, _, _)| first != source)
            && plan.deep[source].is_none()
            && source_header.blocks.has_tiles() == out.blocks.has_tiles()
            && plan.levels[source].block == grid.block
            && plan.levels[source].index == exr::math::Vec2(0, 0)
            && plan.windows[node] == input
            && matches!(out.compression, Compression::ZIP1 | Compression::ZIP16)
            && source_header.compression == out.compression;
        same.then_some(PassThrough {
            source,
            tests,
            inside,
            shift,
        })
    }

    /// The source's chunk that is output block `block` (its pixels, in the
    /// output's coordinates): one of the same pixels once moved, inside
    /// every node's data window.
    fn chunk(&self, plan: &FramePlan, block: IntegerBounds) -> Option<usize> {
        if intersection(block, self.inside) != block {
            return None;
        }
        chunk_at(plan, self.source, block, self.shift)
    }

    /// The output blocks within `rows` (whole blocks of the output's grid)
    /// that are the source's chunks, given the strips of the other inputs.
    pub(super) fn blocks(
        &self,
        plan: &FramePlan,
        graph: &Graph,
        strips: &[Option<Rows>],
        rows: Range<i32>,
    ) -> Vec<PassedBlock> {
        let window = plan.window();
        let grid = output_grid(&plan.header);
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
            let y1 = (y0 + lines).min(bottom);
            let row = ((y0 - top) / lines) as usize;
            // The blocks of the row that are chunks of the source, by column.
            let copied: Vec<(usize, usize, Range<i32>)> = (0..grid.blocks.x())
                .filter_map(|column| {
                    let x0 = window.position.x() + (column * grid.block.x()) as i32;
                    let x1 = (x0 + grid.block.x() as i32).min(window.end().x());
                    let block =
                        IntegerBounds::new((x0, y0), ((x1 - x0) as usize, (y1 - y0) as usize));
                    let chunk = self.chunk(plan, block)?;
                    Some((column, chunk, x0..x1))
                })
                .collect();
            if y1 > rows.end || copied.is_empty() {
                return Vec::new();
            }
            // Whether every merge's first input hides nothing over the
            // columns `x0..x1` of these rows (a copy of them, for a tile),
            // in the merge's pixels.
            let hidden = |columns: Option<&Range<i32>>| {
                self.tests
                    .iter()
                    .all(|&test| shows_second(plan, graph, strips, test, y0..y1, columns))
            };
            // A whole row of blocks passes at once (every scanline block, and
            // most tile rows under a small element).
            let whole = hidden(None);
            copied
                .into_iter()
                .filter(|(_, _, x)| whole || (grid.blocks.x() > 1 && hidden(Some(x))))
                .map(|(column, chunk, _)| PassedBlock {
                    index: grid.chunk(column, row),
                    chunk,
                    tile: Vec2(column, row),
                })
                .collect::<Vec<_>>()
        };
        starts
            .into_par_iter()
            .flat_map_iter(stage_time::tasks(Stage::Decode, row_of_blocks))
            .collect()
    }

    /// The source's chunks for `blocks`, each checked to decompress, as
    /// output chunks, placed where the output has them.
    pub(super) fn chunks(
        &self,
        plan: &FramePlan,
        blocks: &[PassedBlock],
    ) -> Result<Vec<IndexedChunk>> {
        let (file, part) = (&plan.inputs[self.source], plan.parts[self.source]);
        blocks
            .par_iter()
            .map(|block| {
                let chunk =
                    stage_time::task(Stage::Decode, || file.checked_zip_chunk(part, block.chunk))?;
                Ok(placed(plan, chunk, block))
            })
            .collect()
    }
}

/// A merge, the input its first input reads, its second input's node, and
/// the merge's pixel (x + dx, y + dy) that is the output's (x, y).
pub(super) type Test = (usize, usize, usize, (i32, i32));

/// Whether merge `test`'s first input (decoded in `strips`) is transparent
/// black over the output's rows `rows` and columns `columns` (the strip's
/// all along: `None`), where the merge gives its second input bit for bit.
pub(super) fn shows_second(
    plan: &FramePlan,
    graph: &Graph,
    strips: &[Option<Rows>],
    (merge, first, second, (dx, dy)): Test,
    rows: Range<i32>,
    columns: Option<&Range<i32>>,
) -> bool {
    let Node::Op { op, .. } = &graph.nodes[merge] else {
        return false;
    };
    let strip = strips[first]
        .as_ref()
        .expect("tested inputs are decoded first");
    let (second, rows) = (&plan.channels[second], rows.start + dy..rows.end + dy);
    match columns {
        None => op.hides_nothing(strip, second, rows),
        Some(x) => {
            let copy = strip.copy_region(rows.clone(), x.start + dx..x.end + dx);
            op.hides_nothing(&copy, second, rows)
        }
    }
}

/// Chunk `chunk` as output block `block`, stored at the output's
/// coordinates: a tile's column and row count from the data window's
/// corner, a scanline block's y is its first row's.
pub(super) fn placed(plan: &FramePlan, mut chunk: Chunk, block: &PassedBlock) -> IndexedChunk {
    let (top, lines) = (
        plan.window().position.y(),
        output_grid(&plan.header).block.y(),
    );
    match &mut chunk.compressed_block {
        CompressedBlock::Tile(tile) => tile.coordinates.tile_index = block.tile,
        CompressedBlock::ScanLine(line) => {
            line.y_coordinate = top + (block.tile.y() * lines) as i32
        }
        _ => unreachable!("flat chunks only"),
    }
    IndexedChunk {
        index: block.index,
        chunk,
    }
}

/// Input `input`'s chunk (of the level it reads) holding exactly output
/// block `block` moved by `shift`: the block inside the input's data
/// window, starting a whole number of its blocks from its corner, and as
/// large as the chunk's pixels (the last column and row cut short).
pub(super) fn chunk_at(
    plan: &FramePlan,
    input: usize,
    block: IntegerBounds,
    shift: (i32, i32),
) -> Option<usize> {
    let (window, level) = (plan.header_of(input).data_window(), plan.levels[input]);
    let at = moved(block, shift);
    let (x, y) = (
        at.position.x() - window.position.x(),
        at.position.y() - window.position.y(),
    );
    let (bx, by) = (level.block.x() as i32, level.block.y() as i32);
    if intersection(at, window) != at || x % bx != 0 || y % by != 0 {
        return None;
    }
    let covers = intersection(IntegerBounds::new(at.position, level.block), window);
    (covers == at).then(|| level.chunk((x / bx) as usize, (y / by) as usize))
}
