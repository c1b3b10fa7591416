//! What a damaged file may claim, bounded before anything sized from the
//! claim is allocated: a block's decoded size, and how far a codec's bytes
//! can inflate.

use exr::prelude::Compression;

/// Largest decompressed block accepted. A header field can claim anything; this
/// bound keeps a damaged file from making a codec allocate gigabytes. A 64K-wide
/// float RGBA block of 32 lines is 32 MiB, so real files stay far below it.
pub const MAX_BLOCK_BYTES: usize = 512 << 20;

/// The most bytes one compressed byte of `compression` can decode to: a
/// chunk claiming more is damaged, and is refused before anything sized from
/// the claim is allocated.
pub fn max_inflation(compression: Compression) -> usize {
    match compression {
        Compression::Uncompressed => 1,
        // A repeat run: 2 bytes give at most 128.
        Compression::RLE => 64,
        // Deflate's limit: a 258-byte match in 2 bits (1032:1).
        Compression::ZIP1 | Compression::ZIP16 => 1032,
        // Huffman: a 1-bit run code and its 8-bit count repeat the last
        // 16-bit value up to 255 times (510 bytes in 9 bits).
        Compression::PIZ => 454,
        // Deflate of samples whose floats are cut to 24 bits.
        Compression::PXR24 => 1032 * 4 / 3,
        // A flat 4x4 half block (32 bytes) in 3 bytes.
        Compression::B44 | Compression::B44A => 11,
        // Unclear (DWAA, DWAB): the loosest case found, a deflated 2-byte DC
        // coefficient per 8x8 block of float samples (256 bytes); the file's
        // size bounds the rest (`check_header_sizes`).
        _ => 1032 * 128,
    }
}

/// Checks that `packed` bytes of `compression` can hold `raw` bytes (stored
/// raw, or within the codec's ratio).
pub fn check_inflation(
    compression: Compression,
    packed: usize,
    raw: usize,
) -> std::result::Result<(), String> {
    let fits = packed == raw
        || (compression != Compression::Uncompressed
            && raw as u128 <= packed as u128 * max_inflation(compression) as u128);
    if fits {
        Ok(())
    } else {
        Err(format!(
            "{packed} bytes cannot hold the block's {raw} bytes ({compression}: at most {} per byte)",
            max_inflation(compression)
        ))
    }
}
