//! Deep inputs, scanline or tiled, flattened as they are read: the samples
//! of one or more deep files (a deep merge) are put in depth order per pixel
//! and composited front to back into flat rows, strip by strip, so the rest
//! of the engine sees an ordinary input. A file's chunks are read a block
//! row at a time (a scanline block, or a row of tiles across the level),
//! so memory stays flat in height. specs/ops.md, "Deep data".

use super::graph::union;
use super::plan::MAX_STRIP_BYTES;
use crate::error::Result;
use crate::io::deep::{decode_deep, DeepBlock, DeepChunk};
use crate::io::limits::MAX_BLOCK_BYTES;
use crate::io::reader::ExrFile;
use crate::io::rows::Rows;
use crate::io::text::Utf8Text;
use crate::io::tiles::Level;
use crate::stage_time::{self, Stage};
use exr::meta::attribute::{ChannelDescription, IntegerBounds};
use exr::meta::header::Header;
use rayon::prelude::*;
use std::ops::Range;
use std::sync::Arc;

/// The channels a flattened deep file has: its own but ZBack.
pub fn flat_channels(file: &ExrFile, part: usize) -> Vec<ChannelDescription> {
    file.header(part)
        .channels
        .list
        .iter()
        .filter(|c| !c.name.is("ZBack"))
        .cloned()
        .collect()
}

/// Most bytes decoding and flattening one deep chunk may take (see
/// `decoded_bytes`). The reader bounds a chunk's unpacked samples by
/// `MAX_BLOCK_BYTES`, but a few hundred kilobytes of zlib can unpack to that
/// many samples in one pixel, each then an f32 per channel and a sort entry:
/// several times more.
const MAX_DEEP_CHUNK_BYTES: usize = MAX_BLOCK_BYTES;

/// Per file, chunks read (still compressed) with their block rows and
/// indices, in order.
type ChunksRead = Vec<Vec<(usize, usize, DeepChunk)>>;

/// One sample of a pixel being flattened: depth, alpha, file, block, index.
type SortEntry = (f32, f32, usize, usize, usize);

pub struct DeepInput {
    /// The files merged, with the part read from each.
    pub files: Vec<(Arc<ExrFile>, usize)>,
    /// Per file, the level read (a scanline part's only one).
    levels: Vec<Level>,
    /// Output channels (the first file's, flattened).
    pub channels: Vec<ChannelDescription>,
    /// The union of the files' data windows.
    pub window: IntegerBounds,
}

/// Where, among one file's channels, each output channel, Z and A are.
struct ChannelMap {
    channels: Vec<Option<usize>>,
    z: Option<usize>,
    alpha: Option<usize>,
}

/// One file's decoded blocks for a strip: whole block rows of its level
/// from `first_row` on, row by row, left to right.
struct Blocks {
    level: Level,
    window: IntegerBounds,
    first_row: usize,
    blocks: Vec<DeepBlock>,
}

impl DeepInput {
    /// Merges `files`, reading `levels` of them (one each).
    pub fn new(files: Vec<(Arc<ExrFile>, usize)>, levels: Vec<Level>) -> Self {
        let (first, part) = &files[0];
        let channels = flat_channels(first, *part);
        let window = files
            .iter()
            .zip(&levels)
            .map(|((f, p), l)| l.window(f.header(*p)))
            .reduce(union)
            .expect("at least one file");
        DeepInput {
            files,
            levels,
            channels,
            window,
        }
    }

    /// Rows `rows` in columns `(x, width)`, flattened: in batches of rows
    /// whose chunks, decoded, stay within `MAX_STRIP_BYTES` together.
    pub fn strip(&self, columns: (i32, usize), rows: Range<i32>) -> Result<Rows> {
        let height = (rows.end - rows.start) as usize;
        let mut out = Rows::zeros(
            columns.0,
            rows.start,
            columns.1,
            height,
            self.channels.clone(),
            self.window,
        );
        // Per file, where each output channel (and Z, A) is among its channels.
        let index = |file: &ExrFile, part: usize, name: &str| {
            file.header(part)
                .channels
                .list
                .iter()
                .position(|c| c.name.is(name))
        };
        let maps: Vec<ChannelMap> = self
            .files
            .iter()
            .map(|(f, p)| ChannelMap {
                channels: self
                    .channels
                    .iter()
                    .map(|c| index(f, *p, &c.name.utf8()))
                    .collect(),
                z: index(f, *p, "Z"),
                alpha: index(f, *p, "A"),
            })
            .collect();
        let mut y = rows.start;
        while y < rows.end {
            let (end, chunks) = self.batch(y, rows.end)?;
            let decoded: Vec<Blocks> = self
                .files
                .iter()
                .zip(&self.levels)
                .zip(chunks)
                .map(|(((file, part), level), chunks)| decode_blocks(file, *part, *level, chunks))
                .collect::<Result<_>>()?;
            self.flatten(columns, y..end, &decoded, &maps, &mut out);
            y = end;
        }
        Ok(out)
    }

    /// The rows from `top` on (before `bottom`) whose chunks, decoded, take
    /// at most `MAX_STRIP_BYTES` together, at least row `top`'s; and per
    /// file, those chunks read (still compressed), in order.
    fn batch(&self, top: i32, bottom: i32) -> Result<(i32, ChunksRead)> {
        let mut chunks: ChunksRead = self.files.iter().map(|_| Vec::new()).collect();
        let mut cost = 0;
        let mut end = top;
        while end < bottom {
            // The chunks holding row `end` that the batch does not have yet.
            let mut added = Vec::new();
            let mut row_cost = 0;
            for (f, (file, part)) in self.files.iter().enumerate() {
                let level = self.levels[f];
                let window = level.window(file.header(*part));
                if end < window.position.y() || end >= window.end().y() {
                    continue;
                }
                let row = (end - window.position.y()) as usize / level.block.y();
                if chunks[f].last().is_some_and(|(r, _, _)| *r == row) {
                    continue;
                }
                for column in 0..level.blocks.x() {
                    let k = level.chunk(column, row);
                    let chunk = file.read_deep_chunk(*part, k)?;
                    let bytes = decoded_bytes(file.header(*part), &chunk);
                    if bytes > MAX_DEEP_CHUNK_BYTES {
                        return Err(file.error(format!(
                            "deep chunk {k}: its {} bytes of samples would take {bytes} bytes \
                             decoded and sorted, over the {MAX_DEEP_CHUNK_BYTES}-byte limit",
                            chunk.unpacked
                        )));
                    }
                    row_cost += bytes;
                    added.push((f, row, k, chunk));
                }
            }
            if end > top && cost + row_cost > MAX_STRIP_BYTES {
                break;
            }
            cost += row_cost;
            for (f, row, k, chunk) in added {
                chunks[f].push((row, k, chunk));
            }
            end += 1;
        }
        Ok((end, chunks))
    }

    /// Flattens rows `rows` from `decoded` (per file, blocks holding them)
    /// into `out`.
    fn flatten(
        &self,
        columns: (i32, usize),
        rows: Range<i32>,
        decoded: &[Blocks],
        maps: &[ChannelMap],
        out: &mut Rows,
    ) {
        let is = |c: &ChannelDescription, n: &str| c.name.is(n);
        let (alpha_out, z_out) = (
            self.channels.iter().position(|c| is(c, "A")),
            self.channels.iter().position(|c| is(c, "Z")),
        );
        let n = self.channels.len();
        let mut samples: Vec<SortEntry> = Vec::new();
        let mut row = vec![vec![0.0f32; columns.1]; n];
        for y in rows {
            row.iter_mut().for_each(|r| r.fill(0.0));
            for i in 0..columns.1 {
                let x = columns.0 + i as i32;
                samples.clear();
                for (f, blocks) in decoded.iter().enumerate() {
                    let Some((b, pixel)) = locate(blocks, x, y) else {
                        continue;
                    };
                    let block = &blocks.blocks[b];
                    let map = &maps[f];
                    for s in block.samples(pixel) {
                        let depth = map.z.map_or(0.0, |z| block.channels[z][s]);
                        let alpha = map.alpha.map_or(1.0, |a| block.channels[a][s]);
                        samples.push((depth, alpha, f, b, s));
                    }
                }
                if samples.is_empty() {
                    continue;
                }
                // Nearest first; equal depths keep file, then sample, order.
                samples.sort_by(|a, b| a.0.total_cmp(&b.0));
                let mut coverage = 0.0f32;
                for &(_, alpha, f, b, s) in &samples {
                    let block = &decoded[f].blocks[b];
                    for (c, out) in row.iter_mut().enumerate() {
                        if Some(c) == alpha_out || Some(c) == z_out {
                            continue;
                        }
                        if let Some(k) = maps[f].channels[c] {
                            out[i] += (1.0 - coverage) * block.channels[k][s];
                        }
                    }
                    coverage += (1.0 - coverage) * alpha;
                }
                if let Some(a) = alpha_out {
                    row[a][i] = coverage;
                }
                if let Some(z) = z_out {
                    row[z][i] = samples[0].0;
                }
            }
            let range = out.row_range(y);
            for (plane, values) in out.planes.iter_mut().zip(&row) {
                plane.write_f32(range.clone(), values);
            }
        }
    }
}

/// What decoding and flattening a deep chunk takes at most, from the sizes it
/// declares: its samples unpacked, as f32 per channel, and a sort entry each
/// (a pixel may hold them all); its offset table unpacked and as starts.
fn decoded_bytes(header: &Header, chunk: &DeepChunk) -> usize {
    let unpacked = chunk.unpacked;
    let samples = unpacked / header.channels.bytes_per_pixel.max(1);
    let per_sample = 4 * header.channels.list.len() + std::mem::size_of::<SortEntry>();
    let pixels = chunk.bounds.size.area();
    unpacked
        .saturating_add(samples.saturating_mul(per_sample))
        .saturating_add(pixels.saturating_mul(4 + std::mem::size_of::<usize>()))
}

/// Decodes, in parallel, `chunks` (whole block rows of `level`, in order)
/// of `file`.
fn decode_blocks(
    file: &ExrFile,
    part: usize,
    level: Level,
    chunks: Vec<(usize, usize, DeepChunk)>,
) -> Result<Blocks> {
    let header = file.header(part);
    let first_row = chunks.first().map_or(0, |(row, _, _)| *row);
    let blocks = chunks
        .into_par_iter()
        .map(|(_, k, chunk)| {
            stage_time::task(Stage::Decode, || decode_deep(header, &chunk))
                .map_err(|m| file.error(format!("deep chunk {k}: {m}")))
        })
        .collect::<Result<Vec<_>>>()?;
    Ok(Blocks {
        level,
        window: level.window(header),
        first_row,
        blocks,
    })
}

/// Which decoded block holds pixel (x, y) of a file, and the pixel's index
/// in it; `None` outside the file's data window.
fn locate(blocks: &Blocks, x: i32, y: i32) -> Option<(usize, usize)> {
    let (window, level) = (blocks.window, blocks.level);
    let inside = x >= window.position.x()
        && x < window.end().x()
        && y >= window.position.y()
        && y < window.end().y();
    if !inside {
        return None;
    }
    let row =
        ((y - window.position.y()) as usize / level.block.y()).checked_sub(blocks.first_row)?;
    let column = (x - window.position.x()) as usize / level.block.x();
    let k = row * level.blocks.x() + column;
    let block = blocks.blocks.get(k)?;
    let at = block.bounds.position;
    let pixel = (y - at.y()) as usize * block.bounds.size.width() + (x - at.x()) as usize;
    Some((k, pixel))
}
