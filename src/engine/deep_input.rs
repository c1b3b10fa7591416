//! Deep scanline inputs, flattened as they are read: the samples of one or
//! more deep files (a deep merge) are put in depth order per pixel and
//! composited front to back into flat rows, strip by strip, so the rest of
//! the engine sees an ordinary input. specs/ops.md, "Deep data".

use super::graph::union;
use super::strip::Rows;
use crate::error::Result;
use crate::io::deep::{decode_deep_scanline, DeepBlock};
use crate::io::reader::ExrFile;
use exr::block::chunk::CompressedBlock;
use exr::meta::attribute::{ChannelDescription, IntegerBounds};
use rayon::prelude::*;
use std::ops::Range;
use std::sync::Arc;

/// The channels a flattened deep file has: its own but ZBack.
pub fn flat_channels(file: &ExrFile, part: usize) -> Vec<ChannelDescription> {
    file.header(part)
        .channels
        .list
        .iter()
        .filter(|c| !c.name.eq("ZBack"))
        .cloned()
        .collect()
}

pub struct DeepInput {
    /// The files merged, with the part read from each.
    pub files: Vec<(Arc<ExrFile>, usize)>,
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

/// One file's decoded blocks for a strip: lines per block, the first
/// block's index, and them.
struct Blocks {
    lines: usize,
    first: usize,
    blocks: Vec<DeepBlock>,
}

impl DeepInput {
    pub fn new(files: Vec<(Arc<ExrFile>, usize)>) -> Self {
        let (first, part) = &files[0];
        let channels = flat_channels(first, *part);
        let window = files
            .iter()
            .map(|(f, p)| f.header(*p).data_window())
            .reduce(union)
            .expect("at least one file");
        DeepInput {
            files,
            channels,
            window,
        }
    }

    /// Rows `rows` in columns `(x, width)`, flattened.
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
        let decoded: Vec<Blocks> = self
            .files
            .iter()
            .map(|(file, part)| read_blocks(file, *part, &rows))
            .collect::<Result<_>>()?;
        // Per file, where each output channel (and Z, A) is among its channels.
        let index = |file: &ExrFile, part: usize, name: &str| {
            file.header(part)
                .channels
                .list
                .iter()
                .position(|c| c.name.eq(name))
        };
        let maps: Vec<ChannelMap> = self
            .files
            .iter()
            .map(|(f, p)| ChannelMap {
                channels: self
                    .channels
                    .iter()
                    .map(|c| index(f, *p, &c.name.to_string()))
                    .collect(),
                z: index(f, *p, "Z"),
                alpha: index(f, *p, "A"),
            })
            .collect();
        let is = |c: &ChannelDescription, n: &str| c.name.eq(n);
        let (alpha_out, z_out) = (
            self.channels.iter().position(|c| is(c, "A")),
            self.channels.iter().position(|c| is(c, "Z")),
        );
        let n = self.channels.len();
        // Per sample: depth, alpha, file, block, sample index.
        let mut samples: Vec<(f32, f32, usize, usize, usize)> = Vec::new();
        let mut row = vec![vec![0.0f32; columns.1]; n];
        for y in rows.clone() {
            row.iter_mut().for_each(|r| r.fill(0.0));
            for i in 0..columns.1 {
                let x = columns.0 + i as i32;
                samples.clear();
                for (f, ((file, part), blocks)) in self.files.iter().zip(&decoded).enumerate() {
                    let Some((b, pixel)) = locate(file.header(*part).data_window(), blocks, x, y)
                    else {
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
        Ok(out)
    }
}

/// Decodes, in parallel, the chunks of `file` holding rows `rows`.
fn read_blocks(file: &ExrFile, part: usize, rows: &Range<i32>) -> Result<Blocks> {
    let header = file.header(part);
    let window = header.data_window();
    let lines = header.compression.scan_lines_per_block() as i32;
    let (top, bottom) = (
        rows.start.max(window.position.y()),
        rows.end.min(window.end().y()),
    );
    if top >= bottom {
        return Ok(Blocks {
            lines: lines as usize,
            first: 0,
            blocks: Vec::new(),
        });
    }
    let first = ((top - window.position.y()) / lines) as usize;
    let last = ((bottom - 1 - window.position.y()) / lines) as usize;
    let blocks = (first..=last)
        .into_par_iter()
        .map(|k| {
            let chunk = file.read_chunk(part, k)?;
            match &chunk.compressed_block {
                CompressedBlock::DeepScanLine(block) => decode_deep_scanline(header, block)
                    .map_err(|m| file.error(format!("deep chunk {k}: {m}"))),
                _ => Err(file.error(format!("chunk {k} is not a deep scanline chunk"))),
            }
        })
        .collect::<Result<Vec<_>>>()?;
    Ok(Blocks {
        lines: lines as usize,
        first,
        blocks,
    })
}

/// Which decoded block holds row `y` of a file, and the index of pixel
/// (x, y) in it; `None` outside the file's data window.
fn locate(window: IntegerBounds, blocks: &Blocks, x: i32, y: i32) -> Option<(usize, usize)> {
    let inside = x >= window.position.x()
        && x < window.end().x()
        && y >= window.position.y()
        && y < window.end().y();
    if !inside {
        return None;
    }
    let k = ((y - window.position.y()) as usize / blocks.lines).checked_sub(blocks.first)?;
    let block = blocks.blocks.get(k)?;
    let pixel = (y - block.y) as usize * window.size.width() + (x - window.position.x()) as usize;
    Some((k, pixel))
}
