//! Output strips to compressed chunks, one block per task, in parallel.

use super::strip::Rows;
use crate::error::{Error, Result};
use crate::io::{subsampling, zip};
use exr::block::chunk::{Chunk, CompressedBlock, CompressedScanLineBlock};
use exr::block::{BlockIndex, UncompressedBlock};
use exr::math::Vec2;
use exr::meta::attribute::IntegerBounds;
use exr::meta::header::Header;
use exr::prelude::Compression;
use rayon::prelude::*;

/// A compressed block and its index in the output's offset table.
pub struct IndexedChunk {
    pub index: usize,
    pub chunk: Chunk,
}

/// Compresses `rows` (which start on a block boundary of `header`'s data
/// window) into chunks, in order; ZIP and ZIPS at libdeflate level
/// `zip_level`. Blocks that `passed` holds are taken from it as they are.
pub fn encode_rows(
    rows: &Rows,
    header: &Header,
    zip_level: u8,
    passed: Vec<IndexedChunk>,
) -> Result<Vec<IndexedChunk>> {
    let window = header.data_window();
    let lines = header.compression.scan_lines_per_block();
    let first_row = (rows.y - window.position.y()) as usize;
    debug_assert_eq!(first_row % lines, 0, "strips start on block boundaries");
    // Planes in the header's (sorted) channel order.
    let planes: Vec<usize> = header
        .channels
        .list
        .iter()
        .map(|c| {
            rows.channel_index(&c.name.to_string())
                .expect("output channel present")
        })
        .collect();
    let headers = std::slice::from_ref(header);
    let subsampled = subsampling::any(header);
    let first = first_row / lines;
    let mut chunks: Vec<IndexedChunk> = (0..rows.height.div_ceil(lines))
        .into_par_iter()
        .filter(|b| !passed.iter().any(|c| c.index == first + b))
        .map(|b| {
            let y0 = rows.y + (b * lines) as i32;
            let y1 = (y0 + lines as i32).min(rows.end());
            let rect = IntegerBounds::new((rows.x, y0), (rows.width, (y1 - y0) as usize));
            let mut data = Vec::with_capacity(subsampling::block_bytes(&header.channels, rect));
            for y in y0..y1 {
                for (&p, channel) in planes.iter().zip(&header.channels.list) {
                    let plane = &rows.planes[p];
                    let range = rows.row_range(y);
                    if channel.sampling == Vec2(1, 1) {
                        data.extend_from_slice(plane.bytes(range));
                    } else if subsampling::holds_line(channel.sampling.y(), y) {
                        // The samples at the columns that are multiples of the sampling.
                        let xs = channel.sampling.x() as i32;
                        let first = (xs - rows.x.rem_euclid(xs)) % xs;
                        (range.start + first as usize..range.end)
                            .step_by(xs as usize)
                            .for_each(|i| data.extend_from_slice(plane.bytes(i..i + 1)));
                    }
                }
            }
            if matches!(header.compression, Compression::ZIP1 | Compression::ZIP16) {
                return Ok(IndexedChunk {
                    index: first_row / lines + b,
                    chunk: scanline_chunk(y0, zip::compress(&data, zip_level).unwrap_or(data)),
                });
            }
            if subsampled {
                let packed = subsampling::compress(header, data, rect)
                    .map_err(|e| Error::internal(format!("cannot compress block: {e}")))?;
                return Ok(IndexedChunk {
                    index: first_row / lines + b,
                    chunk: scanline_chunk(y0, packed),
                });
            }
            let block = UncompressedBlock {
                index: BlockIndex {
                    layer: 0,
                    pixel_position: Vec2(0, first_row + b * lines),
                    pixel_size: Vec2(rows.width, (y1 - y0) as usize),
                    level: Vec2(0, 0),
                },
                data,
            };
            let chunk = block
                .compress_to_chunk(headers)
                .map_err(|e| Error::internal(format!("cannot compress block: {e}")))?;
            Ok(IndexedChunk {
                index: first_row / lines + b,
                chunk,
            })
        })
        .collect::<Result<_>>()?;
    chunks.extend(passed);
    chunks.sort_unstable_by_key(|c| c.index);
    Ok(chunks)
}

fn scanline_chunk(y: i32, compressed_pixels_le: Vec<u8>) -> Chunk {
    Chunk {
        layer_index: 0,
        compressed_block: CompressedBlock::ScanLine(CompressedScanLineBlock {
            y_coordinate: y,
            compressed_pixels_le,
        }),
    }
}
