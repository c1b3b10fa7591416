//! Turns an input file's chunks into strips of rows in the output's columns:
//! chunks are read and decompressed in parallel, each exactly once, and
//! their buffers freed as soon as the rows are copied out. Scanline blocks
//! and the tiles of one level of a tiled part are read alike: the blocks of
//! the block rows overlapping a strip (`tiles::Level`).

use super::deep_input::DeepInput;
use crate::error::Result;
use crate::io::reader::ExrFile;
use crate::io::rows::{Extent, Rows, Samples};
use crate::io::subsampling;
use crate::io::tiles::{self, Level};
use crate::stage_time::{self, Stage};
use exr::block::chunk::CompressedBlock;
use exr::block::UncompressedBlock;
use exr::math::Vec2;
use exr::meta::attribute::IntegerBounds;
use exr::prelude::Compression;
use rayon::prelude::*;
use std::mem::MaybeUninit;
use std::ops::Range;
use std::sync::Arc;

/// A chunk's rows in each plane of a strip, to be written.
type ChunkRows<'a> = Vec<&'a mut [MaybeUninit<u8>]>;

/// Reads one input of a frame, strip after strip, top to bottom or (a zone
/// read bottom-up, `Regions::upward`) bottom to top: chunks are read through
/// the offset table, in any order whatever the file's line order.
pub struct InputCursor {
    pub file: Arc<ExrFile>,
    pub part: usize,
    /// The data window read from (the level's): empty for a black input.
    window: IntegerBounds,
    /// The level read and where its blocks are.
    level: Level,
    /// The decoded chunks of the last block row, kept when it reaches into
    /// the next strip.
    carried: Vec<(usize, UncompressedBlock)>,
    /// Strips come bottom to top: the block row carried is the first.
    pub upward: bool,
    /// Set for a deep input: strips come from flattening its samples.
    deep: Option<Arc<DeepInput>>,
    /// Whether to keep the chunks of a strip decoded straight into its
    /// planes (`decode_direct`), as read, in `kept`: those that will be
    /// written as they are (`opaque.rs`), not read twice.
    pub keep: bool,
    pub kept: Vec<(usize, CompressedBlock)>,
}

/// The decode tasks of `jobs` (input, chunk): a chunk each, but one task
/// for all the chunks of an input whose rows decode only in order (a PNG's
/// or JPEG's stream, `ExrFile::sequential`), so that they are asked in order.
fn in_tasks(inputs: &[InputCursor], jobs: Vec<(usize, usize)>) -> Vec<Vec<(usize, usize)>> {
    let mut tasks: Vec<Vec<(usize, usize)>> = Vec::new();
    let mut sequential: Vec<Option<usize>> = vec![None; inputs.len()];
    for (i, k) in jobs {
        if !inputs[i].file.sequential() {
            tasks.push(vec![(i, k)]);
            continue;
        }
        match sequential[i] {
            Some(task) => tasks[task].push((i, k)),
            None => {
                sequential[i] = Some(tasks.len());
                tasks.push(vec![(i, k)]);
            }
        }
    }
    for task in tasks.iter_mut() {
        task.sort_unstable();
    }
    tasks
}

impl InputCursor {
    /// Reads `level` of `part`; `window`: the level's data window, or an
    /// empty one to read nothing.
    pub fn new(file: Arc<ExrFile>, part: usize, level: Level, window: IntegerBounds) -> Self {
        InputCursor {
            file,
            part,
            window,
            level,
            carried: Vec::new(),
            upward: false,
            deep: None,
            keep: false,
            kept: Vec::new(),
        }
    }

    /// A cursor that flattens a deep input (and reads nothing flat).
    pub fn deep(file: Arc<ExrFile>, part: usize, deep: Arc<DeepInput>) -> Self {
        let level = tiles::levels(file.header(part))[0];
        InputCursor {
            deep: Some(deep),
            ..Self::new(file, part, level, IntegerBounds::zero())
        }
    }

    /// Chunk indices holding rows `rows` and `columns` (absolute) of the
    /// data window, block row after block row, left to right.
    fn chunks_for(&self, columns: (i32, usize), rows: &Range<i32>) -> Vec<usize> {
        let (w, level) = (self.window, self.level);
        let (top, bottom) = (rows.start.max(w.position.y()), rows.end.min(w.end().y()));
        let right = columns.0 + columns.1 as i32;
        let (left, right) = (columns.0.max(w.position.x()), right.min(w.end().x()));
        if top >= bottom || left >= right {
            return Vec::new();
        }
        let block = |at: i32, origin: i32, size: usize| (at - origin) as usize / size;
        let (x, y) = (w.position.x(), w.position.y());
        let across = block(left, x, level.block.x())..=block(right - 1, x, level.block.x());
        (block(top, y, level.block.y())..=block(bottom - 1, y, level.block.y()))
            .flat_map(|row| across.clone().map(move |column| level.chunk(column, row)))
            .collect()
    }
}

/// Columns (x, width) and rows of an input to decode.
pub type Region = ((i32, usize), Range<i32>);

/// Decodes rows `rows` of every input (see `decode_strip`).
pub fn decode_all(
    inputs: &mut [InputCursor],
    columns: (i32, usize),
    rows: Range<i32>,
) -> Result<Vec<Rows>> {
    let regions = vec![(columns, rows); inputs.len()];
    decode_regions(inputs, &regions)
}

/// Decodes region `regions[i]` of each input `i` (see `decode_strip`).
pub fn decode_regions(inputs: &mut [InputCursor], regions: &[Region]) -> Result<Vec<Rows>> {
    let strips = decode_strip(inputs, regions, |_| true, |_, _| false)?;
    Ok(strips
        .into_iter()
        .map(|s| s.expect("every input selected"))
        .collect())
}

/// Decodes region `regions[i]` (columns x, width and rows) of each input
/// `i` that `selected` picks (`None` for the others) into a strip: zeros
/// where the input has no data, and for chunks `skip(input, chunk)` names
/// (taken as read).
pub fn decode_strip(
    inputs: &mut [InputCursor],
    regions: &[Region],
    selected: impl Fn(usize) -> bool,
    skip: impl Fn(usize, usize) -> bool,
) -> Result<Vec<Option<Rows>>> {
    // Straight into the planes only where every chunk of the strip is decoded.
    let direct: Vec<bool> = inputs
        .iter()
        .enumerate()
        .map(|(i, input)| {
            let (columns, rows) = &regions[i];
            input.direct(*columns, rows)
                && !input
                    .chunks_for(*columns, rows)
                    .into_iter()
                    .any(|k| skip(i, k))
        })
        .collect();
    let jobs: Vec<(usize, usize)> = inputs
        .iter()
        .enumerate()
        .filter(|(i, _)| selected(*i) && !direct[*i])
        .flat_map(|(i, input)| {
            let (columns, rows) = &regions[i];
            input
                .chunks_for(*columns, rows)
                .into_iter()
                .filter(|&k| !input.carried.iter().any(|(c, _)| *c == k))
                .map(move |k| (i, k))
        })
        .filter(|&(i, k)| !skip(i, k))
        .collect();
    let decoded: Vec<(usize, usize, UncompressedBlock)> = in_tasks(inputs, jobs)
        .par_iter()
        .map(stage_time::tasks(
            Stage::Decode,
            |task: &Vec<(usize, usize)>| {
                let decode = |&(i, k): &(usize, usize)| {
                    Ok((i, k, inputs[i].file.decode_chunk(inputs[i].part, k)?))
                };
                task.iter().map(decode).collect::<Result<Vec<_>>>()
            },
        ))
        .collect::<Result<Vec<_>>>()?
        .into_iter()
        .flatten()
        .collect();

    let mut blocks: Vec<Vec<(usize, UncompressedBlock)>> = inputs
        .iter_mut()
        .map(|input| std::mem::take(&mut input.carried))
        .collect();
    for (i, k, block) in decoded {
        blocks[i].push((k, block));
    }
    let mut strips = Vec::with_capacity(inputs.len());
    for (i, input) in inputs.iter_mut().enumerate() {
        let (columns, rows) = &regions[i];
        let strip = match (selected(i), direct[i]) {
            (false, _) => None,
            (true, true) => {
                let (strip, kept) = input.decode_direct(*columns, rows)?;
                input.kept = kept;
                Some(strip)
            }
            (true, false) => {
                input.kept.clear();
                Some(input.strip(*columns, rows, &mut blocks[i])?)
            }
        };
        strips.push(strip);
    }
    Ok(strips)
}

impl InputCursor {
    /// The strip of rows `rows` from `blocks` (this input's decoded chunks,
    /// taken); keeps those of the last block row when it reaches into the
    /// next strip.
    fn strip(
        &mut self,
        columns: (i32, usize),
        rows: &Range<i32>,
        blocks: &mut Vec<(usize, UncompressedBlock)>,
    ) -> Result<Rows> {
        if let Some(deep) = &self.deep {
            return deep.strip(columns, rows.clone());
        }
        let header = self.file.header(self.part);
        let mut strip = Rows::zeros(
            columns.0,
            rows.start,
            columns.1,
            (rows.end - rows.start) as usize,
            header.channels.list.to_vec(),
            self.window,
        );
        let window = self.window;
        for (_, block) in blocks.iter() {
            copy_block(block, window, &mut strip, rows);
        }
        // The last block row read (the first, reading upwards) may hold rows
        // of the next strip: keep it decoded.
        let upward = self.upward;
        let reaches_on = |(_, block): &(usize, UncompressedBlock)| {
            let index = block.index;
            let top = window.position.y() + index.pixel_position.y() as i32;
            match upward {
                true => top < rows.start,
                false => top + index.pixel_size.y() as i32 > rows.end,
            }
        };
        let more = match upward {
            true => rows.start > window.position.y(),
            false => rows.end < window.end().y(),
        };
        self.carried = match more {
            true => blocks.drain(..).filter(reaches_on).collect(),
            false => Vec::new(),
        };
        Ok(strip)
    }

    /// Whether strip `rows` can be decoded straight into its planes: ZIP or
    /// ZIPS chunks (scanline blocks or tiles), none carried, that lie wholly
    /// inside the strip's rows and cover all its rows and columns (the usual
    /// case: the input on the output's grid, or strips of whole tile rows).
    fn direct(&self, columns: (i32, usize), rows: &Range<i32>) -> bool {
        let header = self.file.header(self.part);
        let w = self.window;
        let (top, bottom) = (w.position.y(), w.end().y());
        let lines = self.level.block.y() as i32;
        self.deep.is_none()
            && columns.1 > 0
            && self.carried.is_empty()
            && !subsampling::any(header)
            && matches!(header.compression, Compression::ZIP1 | Compression::ZIP16)
            && w.position.x() <= columns.0
            && w.end().x() >= columns.0 + columns.1 as i32
            && top <= rows.start
            && bottom >= rows.end
            && (rows.start - top) % lines == 0
            && ((rows.end - top) % lines == 0 || rows.end == bottom)
    }

    /// Strip `rows` decoded straight into new planes, chunks in parallel:
    /// each chunk's bytes are interleaved from its decompressed halves to
    /// their place in the strip (each of its lines, in each plane, clipped to
    /// the strip's columns), with no block buffer, copy or zero fill (see
    /// `direct`). With the chunks read, as they are, when `keep` is set.
    fn decode_direct(
        &self,
        columns: (i32, usize),
        rows: &Range<i32>,
    ) -> Result<(Rows, Vec<(usize, CompressedBlock)>)> {
        let (file, part, level) = (&self.file, self.part, self.level);
        let header = file.header(part);
        let channels = header.channels.list.to_vec();
        let sizes: Vec<usize> = channels
            .iter()
            .map(|c| c.sample_type.bytes_per_sample())
            .collect();
        let (width, height) = (columns.1, (rows.end - rows.start) as usize);
        let (x, top) = (self.window.position.x(), self.window.position.y());
        let (block_width, lines) = (level.block.x(), level.block.y());
        // The strip's block rows, and per block column its columns in the
        // strip (from, to) and in the block (skip, its width).
        let first_row = (rows.start - top) as usize / lines;
        let spans: Vec<(usize, usize, usize, usize)> = (0..level.blocks.x())
            .filter_map(|column| {
                let left = x + (column * block_width) as i32;
                let block = block_width.min(level.size.x() - column * block_width);
                let from = left.max(columns.0);
                let to = (left + block as i32).min(columns.0 + width as i32);
                (from < to).then(|| {
                    let at = (from - columns.0) as usize;
                    (at, (to - columns.0) as usize, (from - left) as usize, block)
                })
            })
            .collect();
        let first_column = (columns.0 - x) as usize / block_width;
        let mut planes: Vec<Samples> = channels
            .iter()
            .map(|c| Samples::with_capacity(c.sample_type, width * height))
            .collect();
        // Per chunk (block row after block row, left to right): its lines
        // and their slices, plane after plane, line after line.
        let mut tasks: Vec<(usize, usize, usize, ChunkRows)> = Vec::new();
        for line in 0..height {
            let row = first_row + line / lines;
            if line % lines == 0 {
                let count = lines.min(height - line);
                for (j, _) in spans.iter().enumerate() {
                    let chunk = level.chunk(first_column + j, row);
                    tasks.push((chunk, j, count, Vec::new()));
                }
            }
        }
        let per_row = spans.len();
        for (plane, &size) in planes.iter_mut().zip(&sizes) {
            let bytes = &mut plane.unset_bytes()[..width * height * size];
            for (line, mut rest) in bytes.chunks_exact_mut(width * size).enumerate() {
                let base = line / lines * per_row;
                let mut done = 0;
                for (j, &(from, to, _, _)) in spans.iter().enumerate() {
                    debug_assert_eq!(from, done, "the blocks cover the strip's columns");
                    let (mine, after) = rest.split_at_mut((to - from) * size);
                    tasks[base + j].3.push(mine);
                    (rest, done) = (after, to);
                }
                assert!(rest.is_empty(), "the blocks cover the strip's columns");
            }
        }
        let keep = self.keep;
        let kept = tasks.into_par_iter().map(stage_time::tasks(
            Stage::Decode,
            |(k, j, count, mut slices): (usize, usize, usize, ChunkRows)| {
                let (_, _, skip, block) = spans[j];
                let line_bytes = header.channels.bytes_per_pixel * block;
                let (_, packed) = file.unpack_zip_chunk_kept(part, k, |unpacked| {
                    let mut slices = slices.iter_mut();
                    let mut channel_at = 0;
                    for &size in &sizes {
                        for line in 0..count {
                            let out = slices.next().expect("a slice per line and plane");
                            unpacked.place(line * line_bytes + channel_at + skip * size, out);
                        }
                        channel_at += block * size;
                    }
                })?;
                Ok(keep.then_some((k, packed)))
            },
        ));
        let kept: Vec<(usize, CompressedBlock)> = kept
            .collect::<Result<Vec<_>>>()?
            .into_iter()
            .flatten()
            .collect();
        for plane in &mut planes {
            // SAFETY: the tasks wrote every row of every plane (asserted
            // above: the chunks' rows and columns are exactly the strip's).
            unsafe { plane.set_len(width * height) };
        }
        let strip = Rows {
            extent: Extent {
                x: columns.0,
                y: rows.start,
                width,
                height,
                valid: self.window,
            },
            channels,
            planes,
        };
        Ok((strip, kept))
    }
}

/// Copies the lines of `block` that fall in `rows` into `strip`, clipped to
/// the strip's columns (an input can be wider than the result).
fn copy_block(
    block: &UncompressedBlock,
    window: IntegerBounds,
    strip: &mut Rows,
    rows: &Range<i32>,
) {
    let width = block.index.pixel_size.x();
    let block_top = window.position.y() + block.index.pixel_position.y() as i32;
    let line_x = window.position.x() + block.index.pixel_position.x() as i32;
    let x0 = line_x.max(strip.x);
    let x1 = (line_x + width as i32).min(strip.x + strip.width as i32);
    let (skip, count) = ((x0 - line_x).max(0) as usize, (x1 - x0).max(0) as usize);
    let column = (x0 - strip.x).max(0) as usize;
    let mut offset = 0;
    for line in 0..block.index.pixel_size.y() {
        let y = block_top + line as i32;
        for c in 0..strip.channels.len() {
            let channel = &strip.channels[c];
            let size = channel.sample_type.bytes_per_sample();
            if channel.sampling != Vec2(1, 1) {
                offset +=
                    copy_subsampled(&block.data[offset..], (line_x, width), y, c, strip, rows);
                continue;
            }
            if rows.contains(&y) && count > 0 {
                let start = strip.row_range(y).start + column;
                let from = offset + skip * size;
                strip.planes[c]
                    .bytes_mut(start..start + count)
                    .copy_from_slice(&block.data[from..from + count * size]);
            }
            offset += width * size;
        }
    }
}

/// Copies the samples of subsampled channel `c` that line `y` of a block
/// holds (from `data` on; the block's line covers `columns`, x and width) to
/// their pixels in `strip` (whose other pixels stay zero); returns the bytes
/// they take.
fn copy_subsampled(
    data: &[u8],
    columns: (i32, usize),
    y: i32,
    c: usize,
    strip: &mut Rows,
    rows: &Range<i32>,
) -> usize {
    let channel = &strip.channels[c];
    let (xs, size) = (channel.sampling.x(), channel.sample_type.bytes_per_sample());
    if !subsampling::holds_line(channel.sampling.y(), y) {
        return 0;
    }
    let (x0, x1) = (columns.0, columns.0 + columns.1 as i32);
    let samples = subsampling::count(xs, x0, x1);
    if rows.contains(&y) {
        let first = x0 + (xs as i32 - x0.rem_euclid(xs as i32)) % xs as i32;
        let row = strip.row_range(y).start;
        let (left, right) = (strip.x, strip.x + strip.width as i32);
        for k in 0..samples {
            let x = first + (k * xs) as i32;
            if x >= left && x < right {
                let at = row + (x - left) as usize;
                strip.planes[c]
                    .bytes_mut(at..at + 1)
                    .copy_from_slice(&data[k * size..(k + 1) * size]);
            }
        }
    }
    samples * size
}
