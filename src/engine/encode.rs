//! Output strips to compressed chunks, one block per task, in parallel.

use super::frame_plan::output_grid;
use crate::error::{Error, Result};
use crate::io::rows::Rows;
use crate::io::text::Utf8Text;
use crate::io::writer::IndexedChunk;
use crate::io::{subsampling, zip};
use crate::stage_time::{self, Stage};
use exr::block::chunk::{
    Chunk, CompressedBlock, CompressedScanLineBlock, CompressedTileBlock, TileCoordinates,
};
use exr::block::{BlockIndex, UncompressedBlock};
use exr::math::Vec2;
use exr::meta::attribute::IntegerBounds;
use exr::meta::header::Header;
use exr::prelude::Compression;
use rayon::prelude::*;

/// Compresses `rows` (which start on a block row of `header`'s data window:
/// scanline blocks, or tile rows) into chunks, in offset-table order; ZIP
/// and ZIPS at libdeflate level `zip_level`. Blocks that `passed` holds are
/// taken from it as they are.
pub fn encode_rows(
    rows: &Rows,
    header: &Header,
    zip_level: u8,
    passed: Vec<IndexedChunk>,
) -> Result<Vec<IndexedChunk>> {
    let window = header.data_window();
    let grid = output_grid(header);
    let (block_width, lines) = (grid.block.x(), grid.block.y());
    let first_row = (rows.y - window.position.y()) as usize;
    debug_assert_eq!(first_row % lines, 0, "strips start on block rows");
    debug_assert_eq!(rows.width, window.size.width(), "strips span the window");
    // Planes in the header's (sorted) channel order.
    let planes: Vec<usize> = header
        .channels
        .list
        .iter()
        .map(|c| {
            rows.channel_index(&c.name.utf8())
                .expect("output channel present")
        })
        .collect();
    let headers = std::slice::from_ref(header);
    let subsampled = subsampling::any(header);
    let first = first_row / lines;
    let blocks: Vec<(usize, usize)> = (first..first + rows.height.div_ceil(lines))
        .flat_map(|row| (0..grid.blocks.x()).map(move |column| (column, row)))
        .filter(|&(column, row)| !passed.iter().any(|c| c.index == grid.chunk(column, row)))
        .collect();
    let mut chunks: Vec<IndexedChunk> = blocks
        .into_par_iter()
        .map(stage_time::tasks(Stage::Encode, |(column, row)| {
            let index = grid.chunk(column, row);
            let y0 = window.position.y() + (row * lines) as i32;
            let y1 = (y0 + lines as i32).min(rows.end());
            let x0 = column * block_width;
            let width = block_width.min(rows.width - x0);
            let rect = IntegerBounds::new((rows.x + x0 as i32, y0), (width, (y1 - y0) as usize));
            let mut data = Vec::with_capacity(subsampling::block_bytes(&header.channels, rect));
            for y in y0..y1 {
                let start = rows.row_range(y).start + x0;
                for (&p, channel) in planes.iter().zip(&header.channels.list) {
                    let plane = &rows.planes[p];
                    if channel.sampling == Vec2(1, 1) {
                        data.extend_from_slice(plane.bytes(start..start + width));
                    } else if subsampling::holds_line(channel.sampling.y(), y) {
                        // The samples at the columns that are multiples of the sampling.
                        let xs = channel.sampling.x() as i32;
                        let first = (xs - rect.position.x().rem_euclid(xs)) % xs;
                        (start + first as usize..start + width)
                            .step_by(xs as usize)
                            .for_each(|i| data.extend_from_slice(plane.bytes(i..i + 1)));
                    }
                }
            }
            // Our own codecs' output as the block's chunk.
            let chunk = |packed: Vec<u8>| IndexedChunk {
                index,
                chunk: Chunk {
                    layer_index: 0,
                    compressed_block: match header.blocks.has_tiles() {
                        true => CompressedBlock::Tile(CompressedTileBlock {
                            coordinates: TileCoordinates {
                                tile_index: Vec2(column, row),
                                level_index: Vec2(0, 0),
                            },
                            compressed_pixels_le: packed,
                        }),
                        false => CompressedBlock::ScanLine(CompressedScanLineBlock {
                            y_coordinate: y0,
                            compressed_pixels_le: packed,
                        }),
                    },
                },
            };
            if matches!(header.compression, Compression::ZIP1 | Compression::ZIP16) {
                return Ok(chunk(zip::compress(&data, zip_level).unwrap_or(data)));
            }
            if subsampled {
                let packed = subsampling::compress(header, data, rect)
                    .map_err(|e| Error::internal(format!("cannot compress block: {e}")))?;
                return Ok(chunk(packed));
            }
            let block = UncompressedBlock {
                index: BlockIndex {
                    layer: 0,
                    pixel_position: Vec2(x0, row * lines),
                    pixel_size: Vec2(width, (y1 - y0) as usize),
                    level: Vec2(0, 0),
                },
                data,
            };
            let chunk = block
                .compress_to_chunk(headers)
                .map_err(|e| Error::internal(format!("cannot compress block: {e}")))?;
            Ok(IndexedChunk { index, chunk })
        }))
        .collect::<Result<_>>()?;
    chunks.extend(passed);
    chunks.sort_unstable_by_key(|c| c.index);
    Ok(chunks)
}
