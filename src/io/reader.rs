//! An EXR file read with positioned reads (`pread`): headers, offset tables
//! checked against the file, and chunks read and decompressed one at a time on
//! demand. Each read takes exactly the bytes it needs into a buffer that is
//! freed after use, so resident memory does not grow with the file, and a file
//! cut short by another process while we read it is an input error, where a
//! memory map would kill the process with SIGBUS.

use super::deep::DeepChunk;
use super::foreign::{self, Foreign, Format};
use super::limits::{check_inflation, max_inflation, MAX_BLOCK_BYTES};
use super::positioned::read_at;
use super::{standard_attributes, subsampling, tiles, zip};
use crate::error::{Error, Result};
use crate::guard::catch_panic;
use exr::block::chunk::{
    Chunk, CompressedBlock, CompressedDeepScanLineBlock, CompressedDeepTileBlock,
    CompressedScanLineBlock, CompressedTileBlock, TileCoordinates,
};
use exr::block::{BlockIndex, UncompressedBlock};
use exr::math::Vec2;
use exr::meta::attribute::IntegerBounds;
use exr::meta::header::Header;
use exr::meta::BlockDescription;
use exr::meta::MetaData;
use exr::prelude::Compression;
use rayon::prelude::*;
use std::fs::File;
use std::io::{BufReader, Read};
use std::ops::Range;
use std::os::unix::fs::FileExt;
use std::path::{Path, PathBuf};

/// Opens `path` for reading if it is a regular file, without blocking: a
/// FIFO, socket, device or directory is refused ("not a regular file (a
/// FIFO)") rather than waited on or read forever.
pub fn open_regular(path: &Path) -> std::io::Result<File> {
    use std::os::unix::fs::OpenOptionsExt;
    let file = std::fs::OpenOptions::new()
        .read(true)
        .custom_flags(libc::O_NONBLOCK)
        .open(path)?;
    match not_regular(file.metadata()?.file_type()) {
        None => Ok(file),
        Some(what) => Err(std::io::Error::other(format!(
            "not a regular file ({what})"
        ))),
    }
}

/// What a file that is not a regular one is ("a FIFO"); `None` for a
/// regular file.
pub fn not_regular(kind: std::fs::FileType) -> Option<&'static str> {
    use std::os::unix::fs::FileTypeExt;
    Some(match () {
        _ if kind.is_file() => return None,
        _ if kind.is_dir() => "a directory",
        _ if kind.is_fifo() => "a FIFO",
        _ if kind.is_socket() => "a socket",
        _ if kind.is_char_device() => "a character device",
        _ if kind.is_block_device() => "a block device",
        _ => "not a file",
    })
}

/// `ExrFile::identity` of `file`, whose header ends at `table_start`.
fn identity(
    file: &File,
    len: u64,
    table_start: u64,
    table: &[u8],
) -> std::result::Result<u128, String> {
    let header = read_at(file, 0, table_start as usize).map_err(|m| format!("the header: {m}"))?;
    let modified = file
        .metadata()
        .and_then(|m| m.modified())
        .map_err(|e| format!("cannot read its modification time: {e}"))?;
    let since = modified
        .duration_since(std::time::UNIX_EPOCH)
        .unwrap_or_default();
    let mut hash = xxhash_rust::xxh3::Xxh3::new();
    hash.update(&len.to_le_bytes());
    hash.update(&since.as_nanos().to_le_bytes());
    hash.update(&header);
    hash.update(table);
    Ok(hash.digest128())
}

pub struct ExrFile {
    pub path: PathBuf,
    pub frame: Option<i64>,
    file: File,
    /// The file's length when opened: the offsets are checked against it.
    len: u64,
    pub meta: MetaData,
    /// Per part: the file offset of each chunk, in increasing-y (table) order.
    offsets: Vec<Vec<u64>>,
    /// Every chunk offset of the file, sorted: where each chunk's bytes end.
    sorted_offsets: Vec<u64>,
    /// What the file is, for frames' fingerprints (`identity`).
    identity: u128,
    /// A DPX or Cineon file: its format and rows (`io::foreign`), read as
    /// the one uncompressed scanline part of `meta`, a line per chunk.
    foreign: Option<(Format, Box<dyn foreign::Rows>)>,
}

/// The file from byte `at` on, as a `Read` of positioned reads (the header
/// parser reads as far as it needs).
struct ReadFrom<'a> {
    file: &'a File,
    at: u64,
}

impl Read for ReadFrom<'_> {
    fn read(&mut self, buf: &mut [u8]) -> std::io::Result<usize> {
        let n = self.file.read_at(buf, self.at)?;
        self.at += n as u64;
        Ok(n)
    }
}

impl ExrFile {
    /// Opens the file, reads and validates its headers and offset tables.
    pub fn open(path: &Path, frame: Option<i64>) -> Result<Self> {
        let err = |message: String| Error::input(path, frame, message);
        let file = open_regular(path).map_err(|e| err(format!("cannot open: {e}")))?;
        let len = file
            .metadata()
            .map_err(|e| err(format!("cannot open: {e}")))?
            .len();
        let mut magic = [0u8; 4];
        if file.read_exact_at(&mut magic, 0).is_ok() {
            if let Some(format) = foreign::sniff(magic) {
                let opened = foreign::open(&file, len, format).map_err(err)?;
                return Self::from_foreign(path, frame, file, len, opened).map_err(err);
            }
        }

        let header = || BufReader::with_capacity(16 << 10, ReadFrom { file: &file, at: 0 });
        let attributes = standard_attributes::attributes(&mut header());
        standard_attributes::check(&attributes).map_err(err)?;
        standard_attributes::check_compression(&file, &attributes).map_err(err)?;
        // The crate refuses subsampled channels: it parses them as 1 1, and
        // their sampling is set back once it has validated the rest.
        let sampled = subsampling::find(&file, &attributes);
        let mut reader = BufReader::with_capacity(
            16 << 10,
            subsampling::Unsampled {
                inner: ReadFrom { file: &file, at: 0 },
                at: 0,
                sampled: &sampled,
            },
        );
        let mut meta = catch_panic(|| MetaData::read_from_buffered(&mut reader, false))
            .map_err(|p| err(format!("not a readable EXR header (decoder panic: {p})")))?
            .map_err(|e| err(format!("not a readable EXR header: {e}")))?;
        let table_start = reader.get_ref().at - reader.buffer().len() as u64;
        validate(&meta).map_err(|e| err(format!("invalid EXR header: {e}")))?;
        subsampling::restore(&mut meta, &sampled)
            .map_err(|e| err(format!("invalid EXR header: {e}")))?;

        let total_chunks: usize = meta.headers.iter().map(|h| h.chunk_count).sum();
        let table_end = (total_chunks as u64)
            .checked_mul(8)
            .and_then(|n| n.checked_add(table_start))
            .filter(|&end| end <= len)
            .ok_or_else(|| {
                err(format!(
                    "truncated: the header announces {total_chunks} chunks but the file has {len} bytes"
                ))
            })?;
        for (index, header) in meta.headers.iter().enumerate() {
            check_header_sizes(header, len - table_end)
                .map_err(|m| err(format!("part {index}: {m}")))?;
        }

        let table = read_at(&file, table_start, total_chunks * 8)
            .map_err(|m| err(format!("the offset table: {m}")))?;
        let identity = identity(&file, len, table_start, &table).map_err(err)?;
        let mut entries = table
            .chunks_exact(8)
            .map(|b| u64::from_le_bytes(b.try_into().expect("8 bytes")));
        let mut offsets = Vec::with_capacity(meta.headers.len());
        for (part, header) in meta.headers.iter().enumerate() {
            let mut table = Vec::with_capacity(header.chunk_count);
            for index in 0..header.chunk_count {
                let offset = entries.next().expect("one entry per chunk");
                if offset < table_end || offset >= len {
                    return Err(err(format!(
                        "truncated or damaged: part {part} chunk {index} is listed at byte {offset}, \
                         outside the chunk area {table_end}..{len}"
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
            file,
            len,
            meta,
            offsets,
            sorted_offsets,
            identity,
            foreign: None,
        })
    }

    /// A foreign file, `opened`, as a single-part scanline EXR file.
    fn from_foreign(
        path: &Path,
        frame: Option<i64>,
        file: File,
        len: u64,
        opened: Foreign,
    ) -> std::result::Result<Self, String> {
        let header = opened.header;
        let identity = identity(&file, len, opened.header_bytes as u64, &[])?;
        let meta = MetaData {
            requirements: exr::meta::Requirements {
                file_format_version: 2,
                is_single_layer_and_tiled: false,
                has_long_names: false,
                has_deep_data: false,
                has_multiple_layers: false,
            },
            headers: vec![header].into(),
        };
        Ok(ExrFile {
            path: path.to_path_buf(),
            frame,
            file,
            len,
            meta,
            offsets: vec![Vec::new()],
            sorted_offsets: Vec::new(),
            identity,
            foreign: Some((opened.format, opened.rows)),
        })
    }

    /// The file's format when it is not OpenEXR (DPX, Cineon).
    pub fn format(&self) -> Option<Format> {
        self.foreign.as_ref().map(|(format, _)| *format)
    }

    /// Whether the file's rows decode only in order, from its start (a
    /// PNG's stream): its readers ask for them in order, or each row asked
    /// before the last one read starts the decoding over.
    pub fn sequential(&self) -> bool {
        self.foreign
            .as_ref()
            .is_some_and(|(_, rows)| rows.sequential())
    }

    /// Bytes the file's row reader holds while it is read (a TIFF's strip,
    /// a PNG's inflate state): the memory bound's share of it.
    pub fn decoder_bytes(&self) -> u64 {
        self.foreign.as_ref().map_or(0, |(_, rows)| rows.resident())
    }

    /// Row `index` of a foreign file's one part, in an uncompressed
    /// block's layout.
    fn foreign_row(&self, index: usize) -> Result<Option<Vec<u8>>> {
        let Some((_, rows)) = &self.foreign else {
            return Ok(None);
        };
        let row = rows
            .read(&self.file, index..index + 1)
            .map_err(|m| self.error(format!("row {index}: {m}")))?;
        Ok(Some(row))
    }

    /// A hash of the file's length, modification time, header and offset
    /// table: what a frame's fingerprint records of each file it read
    /// (specs/overnight.md). Rewriting a plate changes its chunks' sizes,
    /// so its table, or at least its time; the header holds what is not
    /// pixels. A copy that does not keep the time is another file to it:
    /// its frames are made again, never kept wrongly.
    pub fn identity(&self) -> u128 {
        self.identity
    }

    pub fn header(&self, part: usize) -> &Header {
        &self.meta.headers[part]
    }

    pub fn file_len(&self) -> u64 {
        self.len
    }

    pub fn error(&self, message: impl std::fmt::Display) -> Error {
        Error::input(&self.path, self.frame, message)
    }

    /// The bytes chunk `index` of `part` may occupy: from its offset to the
    /// next-higher offset of any chunk, or to the end of the file.
    pub fn chunk_range(&self, part: usize, index: usize) -> Range<u64> {
        let start = self.offsets[part][index];
        let next = self.sorted_offsets.partition_point(|&o| o <= start);
        start..self.sorted_offsets.get(next).copied().unwrap_or(self.len)
    }

    /// Reads chunk `index` of `part` (table order) without decompressing it.
    pub fn read_chunk(&self, part: usize, index: usize) -> Result<Chunk> {
        if let Some(row) = self.foreign_row(index)? {
            let y = self.header(part).own_attributes.layer_position.y() + index as i32;
            return Ok(Chunk {
                layer_index: part,
                compressed_block: CompressedBlock::ScanLine(CompressedScanLineBlock {
                    y_coordinate: y,
                    compressed_pixels_le: row,
                }),
            });
        }
        let offset = self.offsets[part][index];
        let damaged = |m: &dyn std::fmt::Display| {
            self.error(format!(
                "chunk {index} at byte {offset} is truncated or damaged: {m}"
            ))
        };
        let (fields, data) = self
            .read_chunk_bytes(part, index)
            .map_err(|m| damaged(&m))?;
        let header = self.header(part);
        let chunk = if header.deep {
            // Read here, not by `Chunk::read`, which caps a deep tile's
            // samples at a flat tile's size.
            deep_chunk(part, header.blocks.has_tiles(), &fields, data).map_err(|m| damaged(&m))?
        } else if header.blocks.has_tiles() {
            let bytes = [fields, data].concat();
            catch_panic(|| Chunk::read(&mut &bytes[..], &self.meta))
                .map_err(|p| {
                    self.error(format!(
                        "chunk {index} at byte {offset}: decoder panic: {p}"
                    ))
                })?
                .map_err(|e| damaged(&e))?
        } else {
            // A flat scanline chunk, as `Chunk::read` would make it, but with
            // its data read straight into the block.
            let at = fields.len() - 8;
            let y = i32::from_le_bytes(fields[at..at + 4].try_into().expect("4 bytes"));
            Chunk {
                layer_index: part,
                compressed_block: CompressedBlock::ScanLine(CompressedScanLineBlock {
                    y_coordinate: y,
                    compressed_pixels_le: data,
                }),
            }
        };
        if chunk.layer_index != part {
            return Err(self.error(format!(
                "chunk {index} at byte {offset} belongs to part {} instead of part {part}",
                chunk.layer_index
            )));
        }
        let tile = match &chunk.compressed_block {
            CompressedBlock::Tile(tile) => Some(tile.coordinates),
            CompressedBlock::DeepTile(tile) => Some(tile.coordinates),
            _ => None,
        };
        if let Some(coordinates) = tile {
            let expected = tiles::block_at(header, index).expect("one table entry per block");
            if coordinates != expected {
                let show = |t: &TileCoordinates| {
                    format!(
                        "tile {},{} of level {},{}",
                        t.tile_index.x(),
                        t.tile_index.y(),
                        t.level_index.x(),
                        t.level_index.y()
                    )
                };
                return Err(self.error(format!(
                    "chunk {index} at byte {offset} holds {} instead of {}",
                    show(&coordinates),
                    show(&expected)
                )));
            }
        }
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
        self.check_block_size(part, &chunk.compressed_block)
            .map_err(|m| damaged(&m))?;
        Ok(chunk)
    }

    /// The fixed fields (part number, coordinates, sizes) and the data of
    /// chunk `index` of `part`, read once the sizes the fields declare are
    /// checked against the chunk's room in the file.
    fn read_chunk_bytes(
        &self,
        part: usize,
        index: usize,
    ) -> std::result::Result<(Vec<u8>, Vec<u8>), String> {
        let header = self.header(part);
        let range = self.chunk_range(part, index);
        let room = range.end - range.start;
        let multipart = self.meta.headers.len() > 1;
        let coordinates = if header.blocks.has_tiles() { 16 } else { 4 };
        // Deep: the packed offset table and packed samples follow three u64 sizes.
        let sizes = if header.deep { 24 } else { 4 };
        let fixed = if multipart { 4 } else { 0 } + coordinates + sizes;
        if room < fixed as u64 {
            return Err("the chunk header is cut off".into());
        }
        let fields = read_at(&self.file, range.start, fixed)?;
        let number = |at: usize, len: usize| -> u64 {
            match len {
                4 => i32::from_le_bytes(fields[at..at + 4].try_into().expect("4 bytes")).max(-1)
                    as i64 as u64,
                _ => u64::from_le_bytes(fields[at..at + 8].try_into().expect("8 bytes")),
            }
        };
        if multipart && number(0, 4) != part as u64 {
            return Err(format!(
                "it belongs to part {} instead of part {part}",
                number(0, 4) as i64
            ));
        }
        let at = fixed - sizes;
        let declared = if header.deep {
            number(at, 8)
                .checked_add(number(at + 8, 8))
                .ok_or("sizes overflow")?
        } else {
            let size = number(at, 4);
            if size == u64::MAX {
                return Err("negative data size".into());
            }
            size
        };
        let left = room - fixed as u64;
        if declared > left {
            return Err(format!(
                "it declares {declared} bytes but only {left} lie before the next chunk or the end of the file"
            ));
        }
        let data = read_at(&self.file, range.start + fixed as u64, declared as usize)?;
        Ok((fields, data))
    }

    /// Checks the bytes a flat block decompresses to against what its
    /// compressed bytes can hold (`check_inflation`), before a decoder
    /// allocates them.
    fn check_block_size(
        &self,
        part: usize,
        block: &CompressedBlock,
    ) -> std::result::Result<(), String> {
        let header = self.header(part);
        let packed = match block {
            CompressedBlock::ScanLine(b) => b.compressed_pixels_le.len(),
            CompressedBlock::Tile(b) => b.compressed_pixels_le.len(),
            // Deep sizes are checked where they are unpacked (`io::deep`).
            _ => return Ok(()),
        };
        let index = block_index(header, part, block)?;
        check_inflation(header.compression, packed, raw_size(header, &index))
    }

    /// Chunk `index` of a ZIP or ZIPS `part`, checked to decompress (size and
    /// checksum) but left compressed, as the chunk of a single-part output.
    pub fn checked_zip_chunk(&self, part: usize, index: usize) -> Result<Chunk> {
        let (block, expected) = self.zip_chunk(part, index)?;
        zip::verify(packed_pixels(&block), expected).map_err(|m| self.undecodable(index, m))?;
        Ok(Chunk {
            layer_index: 0,
            compressed_block: block,
        })
    }

    /// Decompresses ZIP or ZIPS chunk `index` of `part` (a scanline block or
    /// a tile) and hands its bytes, in the file's line and channel order, to
    /// `f` (`zip::Unpacked`).
    pub fn unpack_zip_chunk<R>(
        &self,
        part: usize,
        index: usize,
        f: impl FnOnce(&zip::Unpacked) -> R,
    ) -> Result<R> {
        Ok(self.unpack_zip_chunk_kept(part, index, f)?.0)
    }

    /// As `unpack_zip_chunk`, also giving the chunk as read, so that it can
    /// be written as it is without being read again.
    pub fn unpack_zip_chunk_kept<R>(
        &self,
        part: usize,
        index: usize,
        f: impl FnOnce(&zip::Unpacked) -> R,
    ) -> Result<(R, CompressedBlock)> {
        let (block, expected) = self.zip_chunk(part, index)?;
        let unpacked = zip::unpack(packed_pixels(&block), expected, f)
            .map_err(|m| self.undecodable(index, m))?;
        Ok((unpacked, block))
    }

    /// Flat chunk `index` of `part` and the bytes it decompresses to.
    fn zip_chunk(&self, part: usize, index: usize) -> Result<(CompressedBlock, usize)> {
        let block = self.read_chunk(part, index)?.compressed_block;
        let header = self.header(part);
        let at = block_index(header, part, &block).map_err(|m| self.undecodable(index, m))?;
        if !matches!(
            block,
            CompressedBlock::ScanLine(_) | CompressedBlock::Tile(_)
        ) {
            return Err(self.error(format!("chunk {index} is not a flat block")));
        }
        Ok((block, raw_size(header, &at)))
    }

    fn undecodable(&self, index: usize, message: impl std::fmt::Display) -> Error {
        self.error(format!("chunk {index} does not decompress: {message}"))
    }

    /// Reads and decompresses chunk `index` of `part`.
    pub fn decode_chunk(&self, part: usize, index: usize) -> Result<UncompressedBlock> {
        if let Some(data) = self.foreign_row(index)? {
            let width = self.header(part).layer_size.width();
            let index = BlockIndex {
                layer: part,
                pixel_position: Vec2(0, index),
                pixel_size: Vec2(width, 1),
                level: Vec2(0, 0),
            };
            return Ok(UncompressedBlock { index, data });
        }
        let chunk = self.read_chunk(part, index)?;
        let header = self.header(part);
        let block = match (&chunk.compressed_block, header.compression) {
            // Our own ZIP decoder: libdeflate, several times faster than the
            // crate's. A tile's bytes are laid out as a scanline block's of
            // the tile's width.
            (
                CompressedBlock::ScanLine(CompressedScanLineBlock {
                    compressed_pixels_le: packed,
                    ..
                })
                | CompressedBlock::Tile(CompressedTileBlock {
                    compressed_pixels_le: packed,
                    ..
                }),
                Compression::ZIP1 | Compression::ZIP16,
            ) => {
                let at = block_index(header, part, &chunk.compressed_block)
                    .map_err(|m| self.undecodable(index, m))?;
                let expected = raw_size(header, &at);
                let data = if packed.len() == expected {
                    packed.clone()
                } else {
                    zip::decompress(packed, expected).map_err(|m| self.undecodable(index, m))?
                };
                UncompressedBlock { index: at, data }
            }
            // The crate's codecs, told the true size of a subsampled block.
            (CompressedBlock::ScanLine(block), _) if subsampling::any(header) => {
                let at = block_index(header, part, &chunk.compressed_block)
                    .map_err(|m| self.undecodable(index, m))?;
                let packed = block.compressed_pixels_le.clone();
                let data =
                    catch_panic(|| subsampling::decompress(header, packed, absolute(header, &at)))
                        .map_err(|p| self.error(format!("chunk {index}: decoder panic: {p}")))?
                        .map_err(|m| self.undecodable(index, m))?;
                UncompressedBlock { index: at, data }
            }
            _ => catch_panic(|| UncompressedBlock::decompress_chunk(chunk, &self.meta, false))
                .map_err(|p| self.error(format!("chunk {index}: decoder panic: {p}")))?
                .map_err(|e| self.error(format!("chunk {index} does not decompress: {e}")))?,
        };
        let expected = raw_size(header, &block.index);
        if block.data.len() != expected {
            return Err(self.error(format!(
                "chunk {index} decompresses to {} bytes instead of {expected}",
                block.data.len()
            )));
        }
        Ok(block)
    }

    /// Deep chunk `index` of `part`, read but not unpacked.
    pub fn read_deep_chunk(&self, part: usize, index: usize) -> Result<DeepChunk> {
        let block = self.read_chunk(part, index)?.compressed_block;
        DeepChunk::new(self.header(part), block)
            .map_err(|m| self.error(format!("deep chunk {index}: {m}")))?
            .ok_or_else(|| self.error(format!("chunk {index} is not a deep chunk")))
    }

    /// Checks a deep chunk's structure.
    pub fn check_deep_chunk(&self, part: usize, index: usize) -> Result<()> {
        let chunk = self.read_deep_chunk(part, index)?;
        catch_panic(|| chunk.check(self.header(part)))
            .unwrap_or_else(|p| Err(format!("decoder panic: {p}")))
            .map_err(|m| self.error(format!("deep chunk {index}: {m}")))
    }

    /// Whether `part`'s chunks have a codec here: HTJ2K (OpenEXR 3.4) has
    /// none in the exr crate.
    pub fn check_codec(&self, part: usize) -> Result<()> {
        match self.header(part).compression {
            Compression::HTJ2K32 | Compression::HTJ2K256 => {
                Err(self.error("HTJ2K compression is not supported"))
            }
            _ => Ok(()),
        }
    }

    /// Decodes every chunk of `part` (deep chunks: checks their structure), in
    /// parallel; each chunk's bytes are freed once it is checked.
    pub fn check_part(&self, part: usize) -> Result<()> {
        self.check_codec(part)?;
        if self.sequential() {
            return (0..self.header(part).chunk_count)
                .try_for_each(|k| self.decode_chunk(part, k).map(drop));
        }
        (0..self.header(part).chunk_count)
            .into_par_iter()
            .try_for_each(|k| {
                if self.header(part).deep {
                    self.check_deep_chunk(part, k)
                } else {
                    self.decode_chunk(part, k).map(drop)
                }
            })
    }
}

/// A deep chunk of `part` from its fixed fields (part number if any,
/// coordinates, then the offset table's and the samples' packed sizes and
/// the samples' unpacked size, as u64) and its data (the packed table, then
/// the packed samples), as `read_chunk_bytes` reads them.
fn deep_chunk(
    part: usize,
    tiled: bool,
    fields: &[u8],
    mut data: Vec<u8>,
) -> std::result::Result<Chunk, String> {
    let int = |at: usize| i32::from_le_bytes(fields[at..at + 4].try_into().expect("4 bytes"));
    let long = |at: usize| u64::from_le_bytes(fields[at..at + 8].try_into().expect("8 bytes"));
    let sizes = fields.len() - 24;
    let table_size = usize::try_from(long(sizes)).map_err(|_| "table size overflows")?;
    let unpacked = usize::try_from(long(sizes + 16)).map_err(|_| "sample size overflows")?;
    let samples = data.split_off(table_size.min(data.len()));
    let table = data.into_iter().map(|b| b as i8).collect();
    let compressed_block = match tiled {
        false => CompressedBlock::DeepScanLine(CompressedDeepScanLineBlock {
            y_coordinate: int(sizes - 4),
            decompressed_sample_data_size: unpacked,
            compressed_pixel_offset_table: table,
            compressed_sample_data_le: samples,
        }),
        true => {
            let at = sizes - 16;
            let index = |at: usize| usize::try_from(int(at)).map_err(|_| "negative tile index");
            CompressedBlock::DeepTile(CompressedDeepTileBlock {
                coordinates: TileCoordinates {
                    tile_index: Vec2(index(at)?, index(at + 4)?),
                    level_index: Vec2(index(at + 8)?, index(at + 12)?),
                },
                decompressed_sample_data_size: unpacked,
                compressed_pixel_offset_table: table,
                compressed_sample_data_le: samples,
            })
        }
    };
    Ok(Chunk {
        layer_index: part,
        compressed_block,
    })
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

/// Sizes a damaged header could inflate, checked before anything is allocated:
/// a block stays under `MAX_BLOCK_BYTES`, and a flat part's pixels must fit in
/// what the file's `chunk_bytes` bytes of chunks can decompress to. Without
/// the latter, a few kilobytes claiming a data window millions of pixels wide
/// would make every strip, and every decoder thread, allocate hundreds of
/// megabytes.
fn check_header_sizes(header: &Header, chunk_bytes: u64) -> std::result::Result<(), String> {
    let window: IntegerBounds = header.data_window();
    if window.size.width() == 0 || window.size.height() == 0 {
        return Err("empty data window".into());
    }
    if header.deep {
        return Ok(());
    }
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
    let pixel_bytes: u128 = header
        .channels
        .list
        .iter()
        .map(|c| {
            c.subsampled_resolution(window.size).area() as u128
                * c.sample_type.bytes_per_sample() as u128
        })
        .sum();
    let most = chunk_bytes as u128 * max_inflation(header.compression) as u128;
    if pixel_bytes > most {
        return Err(format!(
            "a data window of {} x {} pixels takes {pixel_bytes} bytes, more than the file's \
             {chunk_bytes} bytes of chunks can hold ({}: at most {} per byte)",
            window.size.width(),
            window.size.height(),
            header.compression,
            max_inflation(header.compression)
        ));
    }
    Ok(())
}

/// A flat chunk's compressed pixels.
fn packed_pixels(block: &CompressedBlock) -> &[u8] {
    match block {
        CompressedBlock::ScanLine(b) => &b.compressed_pixels_le,
        CompressedBlock::Tile(b) => &b.compressed_pixels_le,
        _ => &[],
    }
}

/// Where a flat scanline block lies in the image (absolute coordinates).
pub fn absolute(header: &Header, index: &BlockIndex) -> IntegerBounds {
    let origin = header.own_attributes.layer_position;
    IntegerBounds::new(
        (
            origin.x() + index.pixel_position.x() as i32,
            origin.y() + index.pixel_position.y() as i32,
        ),
        index.pixel_size,
    )
}

/// The bytes a flat block decompresses to (fewer where channels are
/// subsampled).
pub fn raw_size(header: &Header, index: &BlockIndex) -> usize {
    match subsampling::any(header) {
        true => subsampling::block_bytes(&header.channels, absolute(header, index)),
        false => index.pixel_size.area() * header.channels.bytes_per_pixel,
    }
}

/// Where a flat block's pixels lie in its level (from its data window's
/// origin), and its size.
fn block_index(
    header: &Header,
    part: usize,
    block: &CompressedBlock,
) -> std::result::Result<BlockIndex, String> {
    let tile = header
        .get_block_data_indices(block)
        .map_err(|e| format!("block coordinates: {e}"))?;
    let bounds = header
        .get_absolute_block_pixel_coordinates(tile)
        .map_err(|e| format!("block coordinates: {e}"))?;
    Ok(BlockIndex {
        layer: part,
        pixel_position: Vec2(bounds.position.x() as usize, bounds.position.y() as usize),
        pixel_size: bounds.size,
        level: tile.level_index,
    })
}
