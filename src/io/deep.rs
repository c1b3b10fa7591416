//! Deep chunks, scanline and tiled: a structure check (the pixel offset table must
//! unpack to one count per pixel, never decreasing, and the sample data to
//! exactly what those counts add up to), and decoding into samples.

use super::limits::{check_inflation, MAX_BLOCK_BYTES};
use super::zip;
use exr::block::chunk::CompressedBlock;
use exr::meta::attribute::{IntegerBounds, SampleType};
use exr::meta::header::Header;
use exr::prelude::Compression;

/// A deep chunk, scanline or tile, read but not unpacked: the pixels it
/// covers and its packed pixel offset table and samples.
pub struct DeepChunk {
    /// Absolute: a scanline block across the data window, or a tile of its
    /// level (cut short at the level's right and bottom edges).
    pub bounds: IntegerBounds,
    pub table: Vec<i8>,
    pub samples: Vec<u8>,
    /// The samples' unpacked size, as the chunk declares it.
    pub unpacked: usize,
}

impl DeepChunk {
    /// The deep chunk in `block` of `header`'s part; `None` for a flat one.
    pub fn new(header: &Header, block: CompressedBlock) -> Result<Option<Self>, String> {
        let window = header.data_window();
        let (bounds, table, samples, unpacked) = match block {
            CompressedBlock::DeepScanLine(b) => {
                let lines = header.compression.scan_lines_per_block() as i64;
                let rows = lines.min(window.end().y() as i64 - b.y_coordinate as i64);
                let rows = usize::try_from(rows).map_err(|_| "the block lies below the window")?;
                let bounds = IntegerBounds::new(
                    (window.position.x(), b.y_coordinate),
                    (window.size.width(), rows),
                );
                let table = b.compressed_pixel_offset_table;
                (
                    bounds,
                    table,
                    b.compressed_sample_data_le,
                    b.decompressed_sample_data_size,
                )
            }
            CompressedBlock::DeepTile(b) => {
                let tile = header
                    .get_absolute_block_pixel_coordinates(b.coordinates)
                    .map_err(|e| format!("tile coordinates: {e}"))?;
                let bounds = IntegerBounds::new(tile.position + window.position, tile.size);
                let table = b.compressed_pixel_offset_table;
                (
                    bounds,
                    table,
                    b.compressed_sample_data_le,
                    b.decompressed_sample_data_size,
                )
            }
            _ => return Ok(None),
        };
        Ok(Some(DeepChunk {
            bounds,
            table,
            samples,
            unpacked,
        }))
    }

    /// Its pixel offset table, unpacked and checked, as each pixel's first
    /// sample in the chunk (one more entry ends the last). The table counts
    /// anew on each line (OpenEXR's readers reset it there): per line, one
    /// running count per pixel, never decreasing; the lines' totals must
    /// need exactly the declared sample bytes.
    fn starts(&self, header: &Header) -> Result<Vec<usize>, String> {
        let table_bytes = (self.bounds.size.area() as u64)
            .checked_mul(4)
            .filter(|&n| n <= MAX_BLOCK_BYTES as u64)
            .ok_or("the pixel offset table would be unreasonably large")?
            as usize;
        // A table at least as long as needed is stored raw (OpenEXR writes
        // a whole tile's for an edge tile left uncompressed) and read as far
        // as needed, as OpenEXR's readers do.
        let packed: &[u8] = bytemuck::cast_slice(&self.table);
        let table = match packed.get(..table_bytes) {
            Some(raw) => raw.to_vec(),
            None => unpack(header.compression, packed, table_bytes)?,
        };
        let width = self.bounds.size.width().max(1);
        let mut starts = Vec::with_capacity(table.len() / 4 + 1);
        starts.push(0usize);
        let mut line_start = 0u64;
        for line in table.chunks(width * 4) {
            let mut previous = 0i32;
            for count in line
                .chunks_exact(4)
                .map(|b| i32::from_le_bytes(b.try_into().expect("4 bytes")))
            {
                if count < previous {
                    return Err(format!(
                        "pixel offset table decreases ({previous} then {count})"
                    ));
                }
                previous = count;
                starts.push((line_start + count as u64) as usize);
            }
            line_start += previous as u64;
            if line_start * header.channels.bytes_per_pixel as u64 > MAX_BLOCK_BYTES as u64 {
                return Err("the sample data would be unreasonably large".into());
            }
        }
        let sample_bytes = line_start * header.channels.bytes_per_pixel as u64;
        if sample_bytes != self.unpacked as u64 {
            return Err(format!(
                "{line_start} samples need {sample_bytes} bytes but the chunk announces {}",
                self.unpacked
            ));
        }
        Ok(starts)
    }

    /// Checks the structure (`starts`) and that the samples unpack to their
    /// declared size.
    pub fn check(&self, header: &Header) -> Result<(), String> {
        self.starts(header)?;
        unpack(header.compression, &self.samples, self.unpacked).map(drop)
    }
}

/// Deep data allows only none, RLE, ZIPS and ZIP; a part smaller unpacked
/// than packed is stored raw.
fn unpack(compression: Compression, packed: &[u8], expected: usize) -> Result<Vec<u8>, String> {
    check_inflation(compression, packed.len(), expected)?;
    if packed.len() == expected {
        return Ok(packed.to_vec());
    }
    match compression {
        Compression::ZIP1 | Compression::ZIP16 => zip::decompress(packed, expected),
        Compression::RLE => unpack_rle(packed, expected),
        other => Err(format!(
            "{other} is not allowed for deep data, or the data size is wrong"
        )),
    }
}

/// EXR's run-length code (a signed count byte: negative, that many literal
/// bytes follow; else the next byte repeats count + 1 times) over the same
/// byte split and predictor as ZIP.
fn unpack_rle(packed: &[u8], expected: usize) -> Result<Vec<u8>, String> {
    let mut out = Vec::with_capacity(expected);
    let mut i = 0;
    while i < packed.len() {
        let count = packed[i] as i8;
        i += 1;
        if count < 0 {
            let n = (-(count as i32)) as usize;
            let literal = packed
                .get(i..i + n)
                .ok_or("RLE data ends inside a literal run")?;
            out.extend_from_slice(literal);
            i += n;
        } else {
            let value = *packed.get(i).ok_or("RLE data ends inside a repeat run")?;
            out.resize(out.len() + count as usize + 1, value);
            i += 1;
        }
        if out.len() > expected {
            return Err("RLE data unpacks to more bytes than announced".into());
        }
    }
    if out.len() != expected {
        return Err(format!(
            "RLE data holds {} bytes instead of {expected}",
            out.len()
        ));
    }
    Ok(zip::untransform(&mut out))
}

/// The samples of one deep chunk.
pub struct DeepBlock {
    /// The pixels it covers (absolute).
    pub bounds: IntegerBounds,
    /// Per pixel of the block (line by line, the block's width), the
    /// index of its first sample; one more entry ends the last pixel.
    pub starts: Vec<usize>,
    /// Per channel of the header, every sample of the block, as f32.
    pub channels: Vec<Vec<f32>>,
}

impl DeepBlock {
    pub fn samples(&self, pixel: usize) -> std::ops::Range<usize> {
        self.starts[pixel]..self.starts[pixel + 1]
    }
}

/// Decodes a deep chunk, after `DeepChunk::check`'s checks: the sample
/// data holds, line after line, each channel's samples of the line in pixel
/// order (scanline blocks and tiles alike, as flat data lies).
pub fn decode_deep(header: &Header, chunk: &DeepChunk) -> Result<DeepBlock, String> {
    let starts = chunk.starts(header)?;
    let data = unpack(header.compression, &chunk.samples, chunk.unpacked)?;
    let total = *starts.last().expect("one entry at least");
    let mut channels: Vec<Vec<f32>> = header
        .channels
        .list
        .iter()
        .map(|_| Vec::with_capacity(total))
        .collect();
    let width = chunk.bounds.size.width();
    let mut offset = 0;
    for line in 0..chunk.bounds.size.height() {
        let samples = starts[(line + 1) * width] - starts[line * width];
        for (channel, out) in header.channels.list.iter().zip(&mut channels) {
            let size = channel.sample_type.bytes_per_sample();
            let bytes = &data[offset..offset + samples * size];
            offset += samples * size;
            match channel.sample_type {
                SampleType::F16 => out.extend(
                    bytes
                        .chunks_exact(2)
                        .map(|b| half::f16::from_le_bytes([b[0], b[1]]).to_f32()),
                ),
                SampleType::F32 => out.extend(
                    bytes
                        .chunks_exact(4)
                        .map(|b| f32::from_le_bytes([b[0], b[1], b[2], b[3]])),
                ),
                SampleType::U32 => out.extend(
                    bytes
                        .chunks_exact(4)
                        .map(|b| u32::from_le_bytes([b[0], b[1], b[2], b[3]]) as f32),
                ),
            }
        }
    }
    Ok(DeepBlock {
        bounds: chunk.bounds,
        starts,
        channels,
    })
}
