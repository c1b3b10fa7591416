//! OpenEXR's B44 and B44A for blocks with subsampled channels (the exr
//! crate's B44 lays every channel out at full resolution, which is right only
//! for sampling 1 1). The layout, from ImfB44Compressor.cpp: channel after
//! channel in the list's order, each at its own resolution (`nx` by `ny`
//! samples); a half channel is cut into 4 x 4 blocks of 14 bytes (3 when the
//! block is flat, B44A), the last row and column repeated into a partial
//! block; any other channel is stored raw. Blocks are unpacked here; the
//! crate is still used for parts without subsampled channels; `subsampling`
//! lays the unpacked channels out as lines.

/// A B44 block's flat (3-byte) form has this or more in its third byte.
const FLAT: u8 = 13 << 2;

/// The 16 samples of a 14-byte block (ImfB44Compressor.cpp's unpack14):
/// differences of 6 bits, scaled by the block's shift, from the first.
fn unpack14(b: &[u8]) -> [u16; 16] {
    let b: [u32; 14] = std::array::from_fn(|i| u32::from(b[i]));
    let shift = b[2] >> 2;
    let bias = 0x20u32 << shift;
    let mut s = [0u32; 16];
    let step = |from: u32, six: u32| from.wrapping_add((six & 0x3f) << shift).wrapping_sub(bias);
    s[0] = (b[0] << 8) | b[1];
    s[4] = step(s[0], (b[2] << 4) | (b[3] >> 4));
    s[8] = step(s[4], (b[3] << 2) | (b[4] >> 6));
    s[12] = step(s[8], b[4]);
    // Each column from the one before, four bytes a column pair.
    for (column, at) in [(1, 5), (2, 8), (3, 11)] {
        s[column] = step(s[column - 1], b[at] >> 2);
        s[column + 4] = step(s[column + 3], (b[at] << 4) | (b[at + 1] >> 4));
        s[column + 8] = step(s[column + 7], (b[at + 1] << 2) | (b[at + 2] >> 6));
        s[column + 12] = step(s[column + 11], b[at + 2]);
    }
    s.map(|v| ordered_to_half(v as u16))
}

/// The samples of a flat block: all the same (unpack3).
fn unpack3(b: &[u8]) -> [u16; 16] {
    [ordered_to_half(u16::from_be_bytes([b[0], b[1]])); 16]
}

/// B44 packs halves mapped to an order in which they compare as integers.
fn ordered_to_half(v: u16) -> u16 {
    if v & 0x8000 != 0 {
        v & 0x7fff
    } else {
        !v
    }
}

/// A channel of a block: its samples across and down (at its own
/// resolution), and their size in bytes (2: half).
#[derive(Clone, Copy, Debug)]
pub struct Plane {
    pub nx: usize,
    pub ny: usize,
    pub bytes: usize,
}

/// Unpacks one half channel's 4 x 4 blocks from `packed`, little-endian
/// samples out; `packed` is advanced past them.
fn unpack_plane(nx: usize, ny: usize, packed: &mut &[u8]) -> Result<Vec<u8>, String> {
    let mut samples = vec![0u16; nx * ny];
    for y in (0..ny).step_by(4) {
        for x in (0..nx).step_by(4) {
            let (s, used) = match packed {
                [_, _, third, ..] if *third >= FLAT => (unpack3(packed), 3),
                _ if packed.len() >= 14 => (unpack14(packed), 14),
                _ => return Err("B44 block ends early".into()),
            };
            *packed = &packed[used..];
            for row in 0..4.min(ny - y) {
                for column in 0..4.min(nx - x) {
                    samples[(y + row) * nx + x + column] = s[row * 4 + column];
                }
            }
        }
    }
    Ok(samples.iter().flat_map(|v| v.to_le_bytes()).collect())
}

/// Unpacks a B44 or B44A block of channels `planes` (in the channel list's
/// order) into each channel's samples, row-major, little-endian.
pub fn decompress(planes: &[Plane], packed: &[u8]) -> Result<Vec<Vec<u8>>, String> {
    let mut rest = packed;
    let mut out = Vec::with_capacity(planes.len());
    for plane in planes {
        if plane.bytes == 2 {
            out.push(unpack_plane(plane.nx, plane.ny, &mut rest)?);
        } else {
            let n = plane.nx * plane.ny * plane.bytes;
            if rest.len() < n {
                return Err("B44 block ends early".into());
            }
            out.push(rest[..n].to_vec());
            rest = &rest[n..];
        }
    }
    match rest.len() {
        0 => Ok(out),
        n => Err(format!("B44 block has {n} bytes too many")),
    }
}

#[cfg(test)]
mod tests {
    use super::{decompress, Plane};

    #[test]
    fn unpacks_flat_and_stepped_blocks_into_a_partial_plane() {
        // A flat block of 1.0 (0x3c00, ordered 0xbc00), then a 14-byte one:
        // 2.0 (0x4000, ordered 0xc000), shift 0, every difference +1.
        let mut packed = vec![0xbc, 0x00, 0xfc, 0xc0, 0x00];
        let six = 0x21u32; // +1 over the bias of 0x20
        let bits: u128 = (0..15).fold(0, |acc, _| (acc << 6) | u128::from(six));
        // Bytes 2 to 13: the shift (6 bits, 0) and the first three
        // differences, then three groups of four differences.
        let groups = [
            bits >> 72,
            (bits >> 48) & 0xff_ffff,
            (bits >> 24) & 0xff_ffff,
            bits & 0xff_ffff,
        ];
        packed.extend_from_slice(&(groups[0] as u32).to_be_bytes()[1..]);
        for g in &groups[1..] {
            packed.extend_from_slice(&(*g as u32).to_be_bytes()[1..]);
        }
        let planes = [Plane {
            nx: 6,
            ny: 2,
            bytes: 2,
        }];
        let out = decompress(&planes, &packed).unwrap();
        let s: Vec<u16> = out[0]
            .chunks(2)
            .map(|b| u16::from_le_bytes([b[0], b[1]]))
            .collect();
        assert_eq!(&s[..4], &[0x3c00; 4]);
        assert_eq!(&s[6..10], &[0x3c00; 4]);
        // Ordered 0xc000 + 1 per step down and across: t = 0xc000 + row + column.
        assert_eq!(&s[4..6], &[0x4000, 0x4001]);
        assert_eq!(&s[10..12], &[0x4001, 0x4002]);
    }
}
