//! Deep scanline chunks: a structure check (the pixel offset table must
//! unpack to one count per pixel, never decreasing, and the sample data to
//! exactly what those counts add up to), and decoding into samples.

use super::reader::{check_inflation, MAX_BLOCK_BYTES};
use super::zip;
use exr::block::chunk::CompressedDeepScanLineBlock;
use exr::meta::attribute::SampleType;
use exr::meta::header::Header;
use exr::prelude::Compression;

pub fn check_deep_scanline(
    header: &Header,
    block: &CompressedDeepScanLineBlock,
) -> Result<(), String> {
    let window = header.data_window();
    let lines = header.compression.scan_lines_per_block() as i64;
    let rows = lines.min(window.end().y() as i64 - block.y_coordinate as i64);
    let table_bytes = (window.size.width() as u64)
        .checked_mul(rows as u64 * 4)
        .filter(|&n| n <= MAX_BLOCK_BYTES as u64)
        .ok_or("the pixel offset table would be unreasonably large")?
        as usize;
    let table = unpack(
        header.compression,
        bytemuck::cast_slice(&block.compressed_pixel_offset_table),
        table_bytes,
    )?;
    let mut previous = 0i32;
    for count in table
        .chunks_exact(4)
        .map(|b| i32::from_le_bytes(b.try_into().expect("4 bytes")))
    {
        if count < previous {
            return Err(format!(
                "pixel offset table decreases ({previous} then {count})"
            ));
        }
        previous = count;
    }
    let sample_bytes = previous as u64 * header.channels.bytes_per_pixel as u64;
    if sample_bytes != block.decompressed_sample_data_size as u64 {
        return Err(format!(
            "{previous} samples need {sample_bytes} bytes but the chunk announces {}",
            block.decompressed_sample_data_size
        ));
    }
    if sample_bytes > MAX_BLOCK_BYTES as u64 {
        return Err("the sample data would be unreasonably large".into());
    }
    unpack(
        header.compression,
        &block.compressed_sample_data_le,
        sample_bytes as usize,
    )
    .map(drop)
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

/// The samples of one deep scanline chunk.
pub struct DeepBlock {
    /// First line (absolute y) and number of lines.
    pub y: i32,
    pub lines: usize,
    /// Per pixel of the block (line by line, the data window's width), the
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

/// Decodes a deep scanline chunk (after `check_deep_scanline`'s checks,
/// which it repeats): the sample data holds, channel after channel, every
/// sample of the block in pixel order.
pub fn decode_deep_scanline(
    header: &Header,
    block: &CompressedDeepScanLineBlock,
) -> Result<DeepBlock, String> {
    check_deep_scanline(header, block)?;
    let window = header.data_window();
    let width = window.size.width();
    let lines = (header.compression.scan_lines_per_block() as i64)
        .min(window.end().y() as i64 - block.y_coordinate as i64) as usize;
    let table = unpack(
        header.compression,
        bytemuck::cast_slice(&block.compressed_pixel_offset_table),
        width * lines * 4,
    )?;
    let mut starts = vec![0usize];
    starts.extend(
        table
            .chunks_exact(4)
            .map(|b| i32::from_le_bytes(b.try_into().expect("4 bytes")) as usize),
    );
    let total = *starts.last().expect("one entry at least");
    let data = unpack(
        header.compression,
        &block.compressed_sample_data_le,
        block.decompressed_sample_data_size,
    )?;
    let mut channels = Vec::new();
    let mut offset = 0;
    for channel in header.channels.list.iter() {
        let size = channel.sample_type.bytes_per_sample();
        let bytes = &data[offset..offset + total * size];
        channels.push(match channel.sample_type {
            SampleType::F16 => bytes
                .chunks_exact(2)
                .map(|b| half::f16::from_le_bytes([b[0], b[1]]).to_f32())
                .collect(),
            SampleType::F32 => bytes
                .chunks_exact(4)
                .map(|b| f32::from_le_bytes([b[0], b[1], b[2], b[3]]))
                .collect(),
            SampleType::U32 => bytes
                .chunks_exact(4)
                .map(|b| u32::from_le_bytes([b[0], b[1], b[2], b[3]]) as f32)
                .collect(),
        });
        offset += total * size;
    }
    Ok(DeepBlock {
        y: block.y_coordinate,
        lines,
        starts,
        channels,
    })
}
