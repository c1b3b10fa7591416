//! EXR's ZIP/ZIPS pixel transform over libdeflate: the file format of the
//! exr crate's codec, at several times its compression speed.
//!
//! Encoding: split the bytes into even- and odd-indexed halves, replace each
//! byte by its difference to the previous one (+128), then zlib-deflate.

use libdeflater::{CompressionLvl, Compressor, Decompressor};
use std::cell::RefCell;

#[cfg(target_endian = "big")]
compile_error!("the codecs here take native-endian samples to be little-endian");

/// libdeflate level 4: files within a few percent of OpenEXR's own ZIP
/// output size at a fraction of zlib's time (see the issue notes).
const LEVEL: i32 = 4;

thread_local! {
    static COMPRESSOR: RefCell<Compressor> =
        RefCell::new(Compressor::new(CompressionLvl::new(LEVEL).expect("valid level")));
}

/// Compresses little-endian block bytes; `None` when the result would not be
/// smaller (EXR then stores the block raw).
pub fn compress(raw: &[u8]) -> Option<Vec<u8>> {
    let mut transformed = vec![0u8; raw.len()];
    let half = raw.len().div_ceil(2);
    let (first, second) = transformed.split_at_mut(half);
    for (i, pair) in raw.chunks(2).enumerate() {
        first[i] = pair[0];
        if let Some(&odd) = pair.get(1) {
            second[i] = odd;
        }
    }
    let mut previous = transformed.first().copied().unwrap_or(0);
    for byte in transformed.iter_mut().skip(1) {
        let current = *byte;
        *byte = current.wrapping_sub(previous).wrapping_add(128);
        previous = current;
    }
    COMPRESSOR.with(|c| {
        let mut c = c.borrow_mut();
        let mut out = vec![0u8; c.zlib_compress_bound(raw.len())];
        let size = c.zlib_compress(&transformed, &mut out).ok()?;
        out.truncate(size);
        (size < raw.len()).then_some(out)
    })
}

/// Decompresses to exactly `expected` little-endian bytes.
pub fn decompress(compressed: &[u8], expected: usize) -> Result<Vec<u8>, String> {
    let mut transformed = vec![0u8; expected];
    let size = Decompressor::new()
        .zlib_decompress(compressed, &mut transformed)
        .map_err(|e| format!("zlib data is damaged: {e:?}"))?;
    if size != expected {
        return Err(format!(
            "zlib data holds {size} bytes instead of {expected}"
        ));
    }
    Ok(untransform(transformed))
}

/// Undoes the predictor and the byte split (shared with RLE, which uses both).
pub fn untransform(transformed: Vec<u8>) -> Vec<u8> {
    let n = transformed.len();
    if n < 2 {
        return transformed;
    }
    let (first, second) = transformed.split_at(n.div_ceil(2));
    // The predictor is a running sum through both halves. The value entering
    // the second half is a plain sum, so the two halves then run as two
    // independent chains, interleaved into place in one pass.
    let mut even = first[0];
    let mut odd = first[1..]
        .iter()
        .fold(even, |s, &d| s.wrapping_add(d).wrapping_sub(128));
    let mut raw = vec![0u8; n];
    raw[0] = even;
    let mut pairs = raw[1..].chunks_exact_mut(2);
    for (out, (&d_odd, &d_even)) in (&mut pairs).zip(second.iter().zip(&first[1..])) {
        odd = odd.wrapping_add(d_odd).wrapping_sub(128);
        even = even.wrapping_add(d_even).wrapping_sub(128);
        out[0] = odd;
        out[1] = even;
    }
    // With an even length the second half has one byte more.
    if let ([last], Some(&d_odd)) = (pairs.into_remainder(), second.last()) {
        *last = odd.wrapping_add(d_odd).wrapping_sub(128);
    }
    raw
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn round_trips_odd_and_even_lengths() {
        for len in [1usize, 2, 3, 100, 1001] {
            let raw: Vec<u8> = (0..len).map(|i| ((i * 7) % 13) as u8).collect();
            if let Some(packed) = compress(&raw) {
                assert_eq!(decompress(&packed, len).unwrap(), raw);
            }
        }
    }

    #[test]
    fn decodes_the_transform_as_specified() {
        let raw: Vec<u8> = (0..17u8).map(|i| i.wrapping_mul(37)).collect();
        assert_eq!(
            decompress(&reference_compress(&raw), raw.len()).unwrap(),
            raw
        );
    }

    #[test]
    fn rejects_short_and_damaged_data() {
        let raw: Vec<u8> = (0..64u8).collect();
        let packed = reference_compress(&raw);
        assert!(decompress(&packed, raw.len() + 1).is_err());
        assert!(decompress(&packed[..packed.len() / 2], raw.len()).is_err());
    }

    /// The transform written out step by step as the OpenEXR spec gives it.
    fn reference_compress(raw: &[u8]) -> Vec<u8> {
        let mut t: Vec<u8> = raw
            .iter()
            .step_by(2)
            .chain(raw.iter().skip(1).step_by(2))
            .copied()
            .collect();
        for i in (1..t.len()).rev() {
            t[i] = t[i].wrapping_sub(t[i - 1]).wrapping_add(128);
        }
        let mut c = Compressor::new(CompressionLvl::new(9).unwrap());
        let mut out = vec![0; c.zlib_compress_bound(t.len())];
        let n = c.zlib_compress(&t, &mut out).unwrap();
        out.truncate(n);
        out
    }
}
