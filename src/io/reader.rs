//! A memory-mapped EXR file: headers, offset tables checked against the file,
//! and chunks read and decompressed one at a time on demand.

use super::zip;
use crate::error::{Error, Result};
use crate::guard::catch_panic;
use exr::block::chunk::{Chunk, CompressedBlock, CompressedScanLineBlock};
use exr::block::{BlockIndex, UncompressedBlock};
use exr::math::Vec2;
use exr::meta::attribute::IntegerBounds;
use exr::meta::header::Header;
use exr::meta::BlockDescription;
use exr::meta::MetaData;
use exr::prelude::Compression;
use memmap2::{Mmap, UncheckedAdvice};
use rayon::prelude::*;
use std::fs::File;
use std::ops::Range;
use std::path::{Path, PathBuf};

/// Largest decompressed block accepted. A header field can claim anything; this
/// bound keeps a damaged file from making a codec allocate gigabytes. A 64K-wide
/// float RGBA block of 32 lines is 32 MiB, so real files stay far below it.
pub const MAX_BLOCK_BYTES: usize = 512 << 20;

pub struct ExrFile {
    pub path: PathBuf,
    pub frame: Option<i64>,
    mmap: Mmap,
    pub meta: MetaData,
    /// Per part: the file offset of each chunk, in increasing-y (table) order.
    offsets: Vec<Vec<u64>>,
    /// Every chunk offset of the file, sorted: where each chunk's bytes end.
    sorted_offsets: Vec<u64>,
}

impl ExrFile {
    /// Maps the file, reads and validates its headers and offset tables.
    pub fn open(path: &Path, frame: Option<i64>) -> Result<Self> {
        let err = |message: String| Error::input(path, frame, message);
        let file = File::open(path).map_err(|e| err(format!("cannot open: {e}")))?;
        // SAFETY: the map is read-only; a file changed by another process while we
        // read it gives wrong pixels or a decode error, never unsafety in our code,
        // since every slice is bounds-checked against the length taken here.
        let mmap = unsafe { Mmap::map(&file) }.map_err(|e| err(format!("cannot map: {e}")))?;
        let file_len = mmap.len();

        super::standard_attributes::check(&mmap).map_err(err)?;
        let mut rest: &[u8] = &mmap[..];
        let meta = catch_panic(|| MetaData::read_from_buffered(&mut rest, false))
            .map_err(|p| err(format!("not a readable EXR header (decoder panic: {p})")))?
            .map_err(|e| err(format!("not a readable EXR header: {e}")))?;
        let table_start = file_len - rest.len();
        validate(&meta).map_err(|e| err(format!("invalid EXR header: {e}")))?;

        for (index, header) in meta.headers.iter().enumerate() {
            check_header_sizes(header).map_err(|m| err(format!("part {index}: {m}")))?;
        }

        let total_chunks: usize = meta.headers.iter().map(|h| h.chunk_count).sum();
        let table_end = total_chunks
            .checked_mul(8)
            .and_then(|n| n.checked_add(table_start))
            .filter(|&end| end <= file_len)
            .ok_or_else(|| {
                err(format!(
                    "truncated: the header announces {total_chunks} chunks but the file has {file_len} bytes"
                ))
            })?;

        let mut offsets = Vec::with_capacity(meta.headers.len());
        let mut cursor = table_start;
        for (part, header) in meta.headers.iter().enumerate() {
            let mut table = Vec::with_capacity(header.chunk_count);
            for index in 0..header.chunk_count {
                let bytes: [u8; 8] = mmap[cursor..cursor + 8].try_into().expect("8 bytes");
                cursor += 8;
                let offset = u64::from_le_bytes(bytes);
                if offset < table_end as u64 || offset >= file_len as u64 {
                    return Err(err(format!(
                        "truncated or damaged: part {part} chunk {index} is listed at byte {offset}, \
                         outside the chunk area {table_end}..{file_len}"
                    )));
                }
                table.push(offset);
            }
            offsets.push(table);
        }

        let mut sorted_offsets: Vec<u64> = offsets.iter().flatten().copied().collect();
        sorted_offsets.sort_unstable();
        Ok(ExrFile {
            path: path.to_path_buf(),
            frame,
            mmap,
            meta,
            offsets,
            sorted_offsets,
        })
    }

    pub fn header(&self, part: usize) -> &Header {
        &self.meta.headers[part]
    }

    pub fn file_len(&self) -> usize {
        self.mmap.len()
    }

    pub fn error(&self, message: impl std::fmt::Display) -> Error {
        Error::input(&self.path, self.frame, message)
    }

    /// Reads chunk `index` of `part` (table order) without decompressing it.
    pub fn read_chunk(&self, part: usize, index: usize) -> Result<Chunk> {
        let offset = self.offsets[part][index] as usize;
        self.check_chunk_sizes(part, offset).map_err(|m| {
            self.error(format!(
                "chunk {index} at byte {offset} is truncated or damaged: {m}"
            ))
        })?;
        let mut bytes = &self.mmap[offset..];
        let chunk = catch_panic(|| Chunk::read(&mut bytes, &self.meta))
            .map_err(|p| {
                self.error(format!(
                    "chunk {index} at byte {offset}: decoder panic: {p}"
                ))
            })?
            .map_err(|e| {
                self.error(format!(
                    "chunk {index} at byte {offset} is truncated or damaged: {e}"
                ))
            })?;
        if chunk.layer_index != part {
            return Err(self.error(format!(
                "chunk {index} at byte {offset} belongs to part {} instead of part {part}",
                chunk.layer_index
            )));
        }
        let header = self.header(part);
        let y = match &chunk.compressed_block {
            CompressedBlock::ScanLine(block) => Some(block.y_coordinate),
            CompressedBlock::DeepScanLine(block) => Some(block.y_coordinate),
            _ => None,
        };
        if let Some(y) = y {
            let expected = header.own_attributes.layer_position.y()
                + (index * header.compression.scan_lines_per_block()) as i32;
            if y != expected {
                return Err(self.error(format!(
                    "chunk {index} at byte {offset} starts at line {y} instead of line {expected}"
                )));
            }
        }
        Ok(chunk)
    }

    /// Checks the data sizes a chunk declares against the bytes left in the
    /// file, before anything sized from them is allocated.
    fn check_chunk_sizes(&self, part: usize, offset: usize) -> std::result::Result<(), String> {
        let header = self.header(part);
        let mut at = offset + if self.meta.headers.len() > 1 { 4 } else { 0 };
        at += if header.blocks.has_tiles() { 16 } else { 4 };
        let field = |at: usize, len: usize| -> std::result::Result<u64, String> {
            let bytes = self
                .mmap
                .get(at..at + len)
                .ok_or("the chunk header is cut off")?;
            Ok(match len {
                4 => i32::from_le_bytes(bytes.try_into().expect("4 bytes")).max(-1) as i64 as u64,
                _ => u64::from_le_bytes(bytes.try_into().expect("8 bytes")),
            })
        };
        let (data_start, declared) = if header.deep {
            // Packed offset table and packed samples follow three u64 sizes.
            let total = field(at, 8)?
                .checked_add(field(at + 8, 8)?)
                .ok_or("sizes overflow")?;
            (at + 24, total)
        } else {
            let size = field(at, 4)?;
            if size == u64::MAX {
                return Err("negative data size".into());
            }
            (at + 4, size)
        };
        let left = self.mmap.len().saturating_sub(data_start) as u64;
        if declared > left {
            return Err(format!(
                "it declares {declared} bytes but the file has {left} left"
            ));
        }
        Ok(())
    }

    /// Chunk `index` of a ZIP or ZIPS `part`, checked to decompress (size and
    /// checksum) but left compressed, as the chunk of a single-part output.
    pub fn checked_zip_chunk(&self, part: usize, index: usize) -> Result<Chunk> {
        let (block, expected) = self.zip_chunk(part, index)?;
        zip::verify(&block.compressed_pixels_le, expected)
            .map_err(|m| self.undecodable(index, m))?;
        Ok(Chunk {
            layer_index: 0,
            compressed_block: CompressedBlock::ScanLine(block),
        })
    }

    /// Decompresses ZIP or ZIPS chunk `index` of `part` and hands its bytes,
    /// in the file's line and channel order, to `f` (`zip::Unpacked`).
    pub fn unpack_zip_chunk<R>(
        &self,
        part: usize,
        index: usize,
        f: impl FnOnce(&zip::Unpacked) -> R,
    ) -> Result<R> {
        let (block, expected) = self.zip_chunk(part, index)?;
        zip::unpack(&block.compressed_pixels_le, expected, f)
            .map_err(|m| self.undecodable(index, m))
    }

    /// Scanline chunk `index` of `part` and the bytes it decompresses to.
    fn zip_chunk(&self, part: usize, index: usize) -> Result<(CompressedScanLineBlock, usize)> {
        let CompressedBlock::ScanLine(block) = self.read_chunk(part, index)?.compressed_block
        else {
            return Err(self.error(format!("chunk {index} is not a scanline block")));
        };
        let (_, expected) = block_size(self.header(part), block.y_coordinate);
        Ok((block, expected))
    }

    fn undecodable(&self, index: usize, message: impl std::fmt::Display) -> Error {
        self.error(format!("chunk {index} does not decompress: {message}"))
    }

    /// Reads and decompresses chunk `index` of `part`.
    pub fn decode_chunk(&self, part: usize, index: usize) -> Result<UncompressedBlock> {
        let chunk = self.read_chunk(part, index)?;
        let header = self.header(part);
        let block = match (&chunk.compressed_block, header.compression) {
            // Our own ZIP decoder: libdeflate, several times faster than the crate's.
            (CompressedBlock::ScanLine(block), Compression::ZIP1 | Compression::ZIP16) => {
                let window = header.data_window();
                let top = (block.y_coordinate - window.position.y()) as usize;
                let (rows, expected) = block_size(header, block.y_coordinate);
                let packed = &block.compressed_pixels_le;
                let data = if packed.len() == expected {
                    packed.clone()
                } else {
                    zip::decompress(packed, expected).map_err(|m| self.undecodable(index, m))?
                };
                UncompressedBlock {
                    index: BlockIndex {
                        layer: part,
                        pixel_position: Vec2(0, top),
                        pixel_size: Vec2(window.size.width(), rows),
                        level: Vec2(0, 0),
                    },
                    data,
                }
            }
            _ => catch_panic(|| UncompressedBlock::decompress_chunk(chunk, &self.meta, false))
                .map_err(|p| self.error(format!("chunk {index}: decoder panic: {p}")))?
                .map_err(|e| self.error(format!("chunk {index} does not decompress: {e}")))?,
        };
        let expected = block.index.pixel_size.area() * header.channels.bytes_per_pixel;
        if block.data.len() != expected {
            return Err(self.error(format!(
                "chunk {index} decompresses to {} bytes instead of {expected}",
                block.data.len()
            )));
        }
        Ok(block)
    }

    /// Checks a deep chunk's structure (tiled deep chunks: presence only).
    pub fn check_deep_chunk(&self, part: usize, index: usize) -> Result<()> {
        match self.read_chunk(part, index)?.compressed_block {
            CompressedBlock::DeepScanLine(block) => {
                catch_panic(|| super::deep::check_deep_scanline(self.header(part), &block))
                    .unwrap_or_else(|p| Err(format!("decoder panic: {p}")))
                    .map_err(|m| self.error(format!("deep chunk {index}: {m}")))
            }
            _ => Ok(()),
        }
    }

    /// Decodes every chunk of `part` (deep chunks: checks their structure), in
    /// parallel batches so memory stays bounded.
    pub fn check_part(&self, part: usize) -> Result<()> {
        let count = self.header(part).chunk_count;
        let batch = rayon::current_num_threads() * 4;
        for start in (0..count).step_by(batch) {
            let range = start..(start + batch).min(count);
            range
                .clone()
                .into_par_iter()
                .try_for_each(|k| -> Result<()> {
                    if self.header(part).deep {
                        self.check_deep_chunk(part, k)
                    } else {
                        self.decode_chunk(part, k).map(drop)
                    }
                })?;
            self.release_bytes(self.chunk_bytes(part, range));
        }
        Ok(())
    }

    /// The bytes chunks `indices` of `part` occupy in the file (assuming each
    /// chunk ends where the next-higher offset begins).
    pub fn chunk_bytes(&self, part: usize, indices: Range<usize>) -> Range<usize> {
        let table = &self.offsets[part];
        let start = indices.clone().map(|i| table[i]).min().unwrap_or(0) as usize;
        let last = indices.map(|i| table[i]).max().unwrap_or(0);
        let next = self.sorted_offsets.partition_point(|&o| o <= last);
        let end = self
            .sorted_offsets
            .get(next)
            .map_or(self.mmap.len(), |&o| o as usize);
        start..end
    }

    /// Drops the mapped pages of `bytes`, so that resident memory does not
    /// grow with the file size. A dropped page that is needed again is only
    /// read back from the page cache.
    pub fn release_bytes(&self, bytes: Range<usize>) {
        // SAFETY: the mapping is read-only and file-backed: dropped pages are
        // re-read from the file on the next access, with the same contents.
        let _ = unsafe {
            self.mmap
                .unchecked_advise_range(UncheckedAdvice::DontNeed, bytes.start, bytes.len())
        };
    }
}

/// The exr crate's validation, which refuses deep parts outright; those get
/// the per-header checks only, so that they can at least be described.
fn validate(meta: &MetaData) -> exr::error::UnitResult {
    if meta.headers.iter().any(|h| h.deep) {
        let mut long_names = false;
        let multipart = meta.headers.len() > 1;
        meta.headers
            .iter()
            .try_for_each(|h| h.validate(multipart, &mut long_names, false))
    } else {
        MetaData::validate(&meta.headers, false).map(drop)
    }
}

/// Sizes a damaged header could inflate, checked before anything is allocated.
fn check_header_sizes(header: &Header) -> std::result::Result<(), String> {
    let window: IntegerBounds = header.data_window();
    if window.size.width() == 0 || window.size.height() == 0 {
        return Err("empty data window".into());
    }
    if !header.deep {
        let block_bytes = header.max_block_byte_size();
        if block_bytes > MAX_BLOCK_BYTES {
            return Err(format!(
                "a block of {} x {} pixels would take {block_bytes} bytes, over the {MAX_BLOCK_BYTES}-byte limit",
                window.size.width(),
                match header.blocks {
                    BlockDescription::ScanLines => header.compression.scan_lines_per_block(),
                    BlockDescription::Tiles(t) => t.tile_size.height(),
                }
            ));
        }
    }
    Ok(())
}

/// The lines and raw bytes of the scanline block starting at line `y`.
fn block_size(header: &Header, y: i32) -> (usize, usize) {
    let window = header.data_window();
    let top = (y - window.position.y()) as usize;
    let rows = header
        .compression
        .scan_lines_per_block()
        .min(window.size.height() - top);
    (
        rows,
        window.size.width() * rows * header.channels.bytes_per_pixel,
    )
}
