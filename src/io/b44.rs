//! OpenEXR's B44 and B44A for blocks with subsampled channels (the exr
//! crate's B44 lays every channel out at full resolution, which is right only
//! for sampling 1 1). The layout, from ImfB44Compressor.cpp: channel after
//! channel in the list's order, each at its own resolution (`nx` by `ny`
//! samples); a half channel is cut into 4 x 4 blocks of 14 bytes (3 when the
//! block is flat, B44A), the last row and column repeated into a partial
//! block; any other channel is stored raw. Channels are packed and unpacked
//! here, `subsampling` lays them out as lines; the crate's B44 still codes
//! parts without subsampled channels.

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

/// Packs 16 halves into 14 bytes, or 3 when they are all equal and `flat`
/// (B44A) asks for it (ImfB44Compressor.cpp's pack, exactMax true: the
/// largest sample kept as accurately as the shift allows).
fn pack(s: &[u16; 16], flat: bool, out: &mut Vec<u8>) {
    let t: [u16; 16] = s.map(half_to_ordered);
    let t_max = *t.iter().max().expect("16 samples");
    // Differences from the largest, rounded off by a growing shift until
    // every running difference fits 6 bits (biased by 0x20).
    let (mut shift, mut d, mut r) = (0, [0i32; 16], [0i32; 15]);
    loop {
        for (d, &t) in d.iter_mut().zip(&t) {
            *d = shift_and_round(i32::from(t_max) - i32::from(t), shift);
        }
        r[..3].copy_from_slice(&[d[0] - d[4], d[4] - d[8], d[8] - d[12]]);
        for column in 0..3 {
            for row in 0..4 {
                r[3 + column * 4 + row] = d[row * 4 + column] - d[row * 4 + column + 1];
            }
        }
        r.iter_mut().for_each(|r| *r += 0x20);
        if r.iter().all(|&r| (0..=0x3f).contains(&r)) {
            break;
        }
        shift += 1;
    }
    if flat && r.iter().all(|&r| r == 0x20) {
        out.extend_from_slice(&[(t[0] >> 8) as u8, t[0] as u8, 0xfc]);
        return;
    }
    let t0 = (i32::from(t_max) - (d[0] << shift)) as u16;
    let r = r.map(|r| r as u32);
    let b = [
        (shift << 2) as u32 | (r[0] >> 4),
        (r[0] << 4) | (r[1] >> 2),
        (r[1] << 6) | r[2],
        (r[3] << 2) | (r[4] >> 4),
        (r[4] << 4) | (r[5] >> 2),
        (r[5] << 6) | r[6],
        (r[7] << 2) | (r[8] >> 4),
        (r[8] << 4) | (r[9] >> 2),
        (r[9] << 6) | r[10],
        (r[11] << 2) | (r[12] >> 4),
        (r[12] << 4) | (r[13] >> 2),
        (r[13] << 6) | r[14],
    ];
    out.extend_from_slice(&t0.to_be_bytes());
    out.extend(b.map(|b| b as u8));
}

/// `x` over 2^shift, rounded half to even (shiftAndRound).
fn shift_and_round(x: i32, shift: i32) -> i32 {
    let x = x << 1;
    let a = (1 << shift) - 1;
    let b = (x >> (shift + 1)) & 1;
    (x + a + b) >> (shift + 1)
}

/// The order B44 compares halves in (the inverse of `ordered_to_half`;
/// infinities and NaNs all as 0x8000).
fn half_to_ordered(v: u16) -> u16 {
    if v & 0x7c00 == 0x7c00 {
        0x8000
    } else if v & 0x8000 != 0 {
        !v
    } else {
        v | 0x8000
    }
}

/// One half channel's samples (row-major, little-endian) in 4 x 4 blocks,
/// the last row and column repeated into a partial block.
fn pack_plane(nx: usize, ny: usize, samples: &[u8], flat: bool, out: &mut Vec<u8>) {
    let at = |x: usize, y: usize| {
        let i = 2 * (y.min(ny - 1) * nx + x.min(nx - 1));
        u16::from_le_bytes([samples[i], samples[i + 1]])
    };
    for y in (0..ny).step_by(4) {
        for x in (0..nx).step_by(4) {
            pack(
                &std::array::from_fn(|i| at(x + i % 4, y + i / 4)),
                flat,
                out,
            );
        }
    }
}

/// Packs channels `planes` (their samples row-major, little-endian, in the
/// channel list's order) as B44, or B44A when `flat`.
pub fn compress(planes: &[Plane], samples: &[Vec<u8>], flat: bool) -> Vec<u8> {
    let mut out = Vec::new();
    for (plane, samples) in planes.iter().zip(samples) {
        match plane.bytes == 2 && plane.nx * plane.ny > 0 {
            true => pack_plane(plane.nx, plane.ny, samples, flat, &mut out),
            false => out.extend_from_slice(samples),
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::{compress, decompress, Plane};

    #[test]
    fn packs_as_it_unpacks_exactly_where_the_differences_fit() {
        let plane = [Plane {
            nx: 5,
            ny: 3,
            bytes: 2,
        }];
        // Halves 1.0 + k ulps: differences of at most 14, shift 0, exact.
        let ones: Vec<u8> = (0..15u16)
            .flat_map(|k| (0x3c00 + k).to_le_bytes())
            .collect();
        let packed = compress(&plane, std::slice::from_ref(&ones), true);
        assert_eq!(packed.len(), 2 * 14);
        assert_eq!(decompress(&plane, &packed).unwrap(), vec![ones]);
        // All equal: B44A's 3 bytes a block, B44's 14.
        let flat: Vec<u8> = [0x00, 0xc0].repeat(15);
        assert_eq!(
            compress(&plane, std::slice::from_ref(&flat), true).len(),
            2 * 3
        );
        let packed = compress(&plane, std::slice::from_ref(&flat), false);
        assert_eq!(packed.len(), 2 * 14);
        assert_eq!(decompress(&plane, &packed).unwrap(), vec![flat]);
    }

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
