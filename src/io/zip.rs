//! EXR's ZIP/ZIPS pixel transform over zlib (`deflate.rs`): the file format
//! of the exr crate's codec, at several times its compression speed.
//!
//! Encoding: split the bytes into even- and odd-indexed halves, replace each
//! byte by its difference to the previous one (+128), then zlib-deflate.

use super::deflate;
use libdeflater::Decompressor;
use std::cell::RefCell;
use std::mem::MaybeUninit;

#[cfg(target_endian = "big")]
compile_error!("the codecs here take native-endian samples to be little-endian");

thread_local! {
    /// Per-thread buffers for the transformed bytes and the deflate output:
    /// reused, so blocks cost no fresh zeroed pages.
    static SCRATCH: RefCell<(Vec<u8>, Vec<u8>)> = const { RefCell::new((Vec::new(), Vec::new())) };
}

/// The first `len` bytes of `buffer`, grown (never shrunk) to hold them; the
/// contents are whatever was there before.
fn scratch(buffer: &mut Vec<u8>, len: usize) -> &mut [u8] {
    if buffer.len() < len {
        buffer.resize(len, 0);
    }
    &mut buffer[..len]
}

/// Compresses little-endian block bytes at libdeflate `level` (1-12); `None`
/// when the result would not be smaller (EXR then stores the block raw).
pub fn compress(raw: &[u8], level: u8) -> Option<Vec<u8>> {
    SCRATCH.with(|buffers| {
        let (transformed, out) = &mut *buffers.borrow_mut();
        let transformed = scratch(transformed, raw.len());
        transform(raw, transformed);
        deflate::zlib_compress(transformed, level, out);
        (out.len() < raw.len()).then(|| out.clone())
    })
}

/// Decompresses to exactly `expected` little-endian bytes.
pub fn decompress(compressed: &[u8], expected: usize) -> Result<Vec<u8>, String> {
    SCRATCH.with(|buffers| {
        let mut buffers = buffers.borrow_mut();
        Ok(untransform(inflate(compressed, expected, &mut buffers.0)?))
    })
}

/// A decompressed block whose predictor is undone but whose bytes are still
/// split in halves (or a block stored raw): `place` interleaves any part of
/// it straight to where it goes, with no whole-block buffer in between.
pub enum Unpacked<'a> {
    Raw(&'a [u8]),
    Halves(&'a [u8], &'a [u8]),
}

impl Unpacked<'_> {
    /// Writes the block's bytes `from..from + out.len()` (both even) to `out`.
    pub fn place(&self, from: usize, out: &mut [MaybeUninit<u8>]) {
        assert!(
            from.is_multiple_of(2) && out.len().is_multiple_of(2),
            "whole 2-byte pairs"
        );
        match *self {
            Unpacked::Raw(raw) => write_bytes(out, &raw[from..from + out.len()]),
            Unpacked::Halves(first, second) => {
                let (start, n) = (from / 2, out.len() / 2);
                interleave(&first[start..start + n], &second[start..start + n], out);
            }
        }
    }
}

/// Decompresses a block of exactly `expected` bytes (an even count) and
/// hands it to `f` as `Unpacked`.
pub fn unpack<R>(
    compressed: &[u8],
    expected: usize,
    f: impl FnOnce(&Unpacked) -> R,
) -> Result<R, String> {
    if !expected.is_multiple_of(2) {
        return Err(format!("a block of {expected} bytes is not whole samples"));
    }
    if compressed.len() == expected {
        return Ok(f(&Unpacked::Raw(compressed)));
    }
    SCRATCH.with(|buffers| {
        let mut buffers = buffers.borrow_mut();
        let transformed = inflate(compressed, expected, &mut buffers.0)?;
        running_sum(transformed);
        let (first, second) = transformed.split_at(expected / 2);
        Ok(f(&Unpacked::Halves(first, second)))
    })
}

/// Copies `bytes` into `out` (as long).
fn write_bytes(out: &mut [MaybeUninit<u8>], bytes: &[u8]) {
    for (o, &b) in out.iter_mut().zip(bytes) {
        o.write(b);
    }
}

/// Checks that a chunk's bytes decompress to exactly `expected` bytes,
/// checksum included, leaving the pixels transformed: all that a chunk
/// copied into an output unchanged needs.
pub fn verify(compressed: &[u8], expected: usize) -> Result<(), String> {
    if compressed.len() == expected {
        return Ok(()); // stored raw
    }
    SCRATCH.with(|buffers| inflate(compressed, expected, &mut buffers.borrow_mut().0).map(drop))
}

/// Zero bytes after the deflate data handed to libdeflate. It decodes the
/// last ~40 bytes of its input outside its fast loop, copying matches byte
/// by byte: a block of a flat colour (a transparent tile: 50 bytes for
/// 32 KiB) decoded wholly there, 5x slower than the same pixels in a
/// scanline block. Decoding stops at the final block, so the zeros are only
/// read ahead, as libdeflate reads zeros past the end of its input anyway.
pub const PADDING: usize = 64;

thread_local! {
    /// The deflate data of the block being inflated, and its padding.
    static PADDED: RefCell<Vec<u8>> = const { RefCell::new(Vec::new()) };
}

/// zlib-inflates `compressed` into `buffer`: the `expected` bytes. The zlib
/// wrapper is checked here (RFC 1950: header, Adler-32 of the output) as
/// libdeflate's zlib decoder checks it.
fn inflate<'b>(
    compressed: &[u8],
    expected: usize,
    buffer: &'b mut Vec<u8>,
) -> Result<&'b mut [u8], String> {
    let damaged = || "zlib data is damaged: BadData".to_string();
    let n = compressed.len();
    if n < 6 {
        return Err(damaged());
    }
    let (method, flags) = (compressed[0], compressed[1]);
    if u16::from_be_bytes([method, flags]) % 31 != 0
        || method & 0x0f != 8
        || method >> 4 > 7
        || flags & 0x20 != 0
    {
        return Err(damaged());
    }
    let transformed = scratch(buffer, expected);
    let size = PADDED.with(|padded| {
        let mut padded = padded.borrow_mut();
        padded.clear();
        // Room for the padding too: grown by it alone, the buffer doubled.
        padded.reserve_exact(n - 6 + PADDING);
        padded.extend_from_slice(&compressed[2..n - 4]);
        padded.resize(n - 6 + PADDING, 0);
        Decompressor::new()
            .deflate_decompress(&padded, transformed)
            .map_err(|e| format!("zlib data is damaged: {e:?}"))
    })?;
    if size != expected {
        return Err(format!(
            "zlib data holds {size} bytes instead of {expected}"
        ));
    }
    let checksum = u32::from_be_bytes(compressed[n - 4..].try_into().expect("4 bytes"));
    if libdeflater::adler32(transformed) != checksum {
        return Err(damaged());
    }
    Ok(transformed)
}

/// The byte split and the predictor into `t` (as long as `raw`): t = evens
/// then odds; t[i] -= t[i-1] - 128.
fn transform(raw: &[u8], t: &mut [u8]) {
    let (first, second) = t.split_at_mut(raw.len().div_ceil(2));
    split(raw, first, second);
    differences(t);
}

/// first[i] = raw[2i], second[i] = raw[2i + 1].
fn split(raw: &[u8], first: &mut [u8], second: &mut [u8]) {
    #[cfg(target_arch = "x86_64")]
    let done = {
        let done = second.len() / 16 * 16;
        simd::split(&raw[..2 * done], &mut first[..done], &mut second[..done]);
        done
    };
    #[cfg(not(target_arch = "x86_64"))]
    let done = 0;
    for (i, pair) in raw[2 * done..].chunks(2).enumerate() {
        first[done + i] = pair[0];
        if let Some(&odd) = pair.get(1) {
            second[done + i] = odd;
        }
    }
}

/// t[i] = t[i] - t[i-1] + 128 for i >= 1, from the back so each byte still
/// sees its predecessor's original value.
fn differences(t: &mut [u8]) {
    if t.is_empty() {
        return;
    }
    // Whole 16-byte blocks cover indices 1 .. 1 + blocks; the rest is above.
    let blocks = t.len().saturating_sub(1) / 16 * 16;
    for i in (1 + blocks..t.len()).rev() {
        t[i] = t[i].wrapping_sub(t[i - 1]).wrapping_add(128);
    }
    #[cfg(target_arch = "x86_64")]
    simd::differences(&mut t[..1 + blocks]);
    #[cfg(not(target_arch = "x86_64"))]
    for i in (1..1 + blocks).rev() {
        t[i] = t[i].wrapping_sub(t[i - 1]).wrapping_add(128);
    }
}

/// Undoes the predictor (in place) and the byte split (shared with RLE,
/// which uses both).
pub fn untransform(transformed: &mut [u8]) -> Vec<u8> {
    let n = transformed.len();
    running_sum(transformed);
    let (first, second) = transformed.split_at(n.div_ceil(2));
    let mut raw = Vec::with_capacity(n);
    interleave(first, second, &mut raw.spare_capacity_mut()[..n]);
    // SAFETY: `interleave` wrote all `n` bytes.
    unsafe { raw.set_len(n) };
    raw
}

/// The predictor's inverse: s[0] = d[0], s[i] = s[i-1] + d[i] - 128. Written
/// as a plain prefix sum of (d[i] - 128) seeded with 128.
fn running_sum(bytes: &mut [u8]) {
    let mut sum = 128u8;
    #[cfg(target_arch = "x86_64")]
    let bytes = {
        let blocks = bytes.len() / 16 * 16;
        sum = simd::running_sum(&mut bytes[..blocks], sum);
        &mut bytes[blocks..]
    };
    for b in bytes {
        sum = sum.wrapping_add(*b ^ 0x80);
        *b = sum;
    }
}

/// raw[2i] = first[i], raw[2i + 1] = second[i] (first may be one longer);
/// writes every byte of `raw`.
fn interleave(first: &[u8], second: &[u8], raw: &mut [MaybeUninit<u8>]) {
    assert_eq!(first.len() + second.len(), raw.len(), "halves fill raw");
    #[cfg(target_arch = "x86_64")]
    let done = {
        let done = second.len() / 16 * 16;
        simd::interleave(&first[..done], &second[..done], &mut raw[..2 * done]);
        done
    };
    #[cfg(not(target_arch = "x86_64"))]
    let done = 0;
    for (i, out) in raw[2 * done..].chunks_mut(2).enumerate() {
        out[0].write(first[done + i]);
        if let Some(odd) = out.get_mut(1) {
            odd.write(second[done + i]);
        }
    }
}

/// SSE2 (always present on x86_64) versions of the two loops, 16 bytes at a time.
#[cfg(target_arch = "x86_64")]
mod simd {
    use std::arch::x86_64::*;
    use std::mem::MaybeUninit;

    /// `bytes.len()` is a multiple of 16; returns the last sum.
    pub fn running_sum(bytes: &mut [u8], seed: u8) -> u8 {
        // SAFETY: SSE2 is part of x86_64; loads and stores are unaligned and
        // stay inside `bytes` (whole 16-byte blocks).
        unsafe {
            let bias = _mm_set1_epi8(-128);
            let mut carry = _mm_set1_epi8(seed as i8);
            for block in bytes.chunks_exact_mut(16) {
                let p = block.as_mut_ptr() as *mut __m128i;
                let mut v = _mm_xor_si128(_mm_loadu_si128(p), bias);
                v = _mm_add_epi8(v, _mm_slli_si128(v, 1));
                v = _mm_add_epi8(v, _mm_slli_si128(v, 2));
                v = _mm_add_epi8(v, _mm_slli_si128(v, 4));
                v = _mm_add_epi8(v, _mm_slli_si128(v, 8));
                v = _mm_add_epi8(v, carry);
                _mm_storeu_si128(p, v);
                // Broadcast byte 15 to all lanes.
                let last = _mm_srli_si128(v, 15);
                let last = _mm_unpacklo_epi8(last, last);
                let last = _mm_unpacklo_epi16(last, last);
                carry = _mm_shuffle_epi32(last, 0);
            }
            _mm_cvtsi128_si32(carry) as u8
        }
    }

    /// `t.len()` is 1 + a multiple of 16; bytes 1.. become differences,
    /// block by block from the back, so each block reads its predecessor's
    /// bytes before they change.
    pub fn differences(t: &mut [u8]) {
        // SAFETY: as above; every access is inside `t` (j >= 1, j + 16 <= len).
        unsafe {
            let bias = _mm_set1_epi8(-128);
            let base = t.as_mut_ptr();
            let mut j = t.len();
            while j >= 17 {
                j -= 16;
                let v = _mm_loadu_si128(base.add(j) as *const __m128i);
                let previous = _mm_loadu_si128(base.add(j - 1) as *const __m128i);
                let d = _mm_add_epi8(_mm_sub_epi8(v, previous), bias);
                _mm_storeu_si128(base.add(j) as *mut __m128i, d);
            }
        }
    }

    /// `first` and `second` have the same length, a multiple of 16; `raw`
    /// twice that.
    pub fn split(raw: &[u8], first: &mut [u8], second: &mut [u8]) {
        // SAFETY: as above.
        unsafe {
            let low = _mm_set1_epi16(0x00ff);
            for ((pairs, a), b) in raw
                .chunks_exact(32)
                .zip(first.chunks_exact_mut(16))
                .zip(second.chunks_exact_mut(16))
            {
                let v0 = _mm_loadu_si128(pairs.as_ptr() as *const __m128i);
                let v1 = _mm_loadu_si128(pairs.as_ptr().add(16) as *const __m128i);
                let evens = _mm_packus_epi16(_mm_and_si128(v0, low), _mm_and_si128(v1, low));
                let odds = _mm_packus_epi16(_mm_srli_epi16(v0, 8), _mm_srli_epi16(v1, 8));
                _mm_storeu_si128(a.as_mut_ptr() as *mut __m128i, evens);
                _mm_storeu_si128(b.as_mut_ptr() as *mut __m128i, odds);
            }
        }
    }

    /// `first` and `second` have the same length, a multiple of 16; `raw`
    /// twice that.
    pub fn interleave(first: &[u8], second: &[u8], raw: &mut [MaybeUninit<u8>]) {
        let halves = first.chunks_exact(16).zip(second.chunks_exact(16));
        for ((a, b), out) in halves.zip(raw.chunks_exact_mut(32)) {
            // SAFETY: as above; each store stays inside its 32-byte `out`.
            unsafe {
                let a = _mm_loadu_si128(a.as_ptr() as *const __m128i);
                let b = _mm_loadu_si128(b.as_ptr() as *const __m128i);
                let out = out.as_mut_ptr() as *mut __m128i;
                _mm_storeu_si128(out, _mm_unpacklo_epi8(a, b));
                _mm_storeu_si128(out.add(1), _mm_unpackhi_epi8(a, b));
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn round_trips_odd_and_even_lengths() {
        for len in [1usize, 2, 3, 15, 16, 17, 31, 32, 33, 64, 100, 1001, 4099] {
            let raw: Vec<u8> = (0..len).map(|i| ((i * 7) % 13) as u8).collect();
            match compress(&raw, deflate::DEFAULT_LEVEL) {
                Some(packed) => assert_eq!(decompress(&packed, len).unwrap(), raw),
                None => assert!(len < 64, "a repetitive block of {len} bytes must shrink"),
            }
        }
    }

    #[test]
    fn unpacked_parts_are_the_decompressed_bytes() {
        for len in [2usize, 32, 34, 66, 1000, 4098] {
            let raw: Vec<u8> = (0..len).map(|i| (i * i % 251) as u8).collect();
            let random: Vec<u8> = (0..len).map(|i| ((i * 2654435761) >> 13) as u8).collect();
            for raw in [raw, random] {
                let packed = compress(&raw, deflate::DEFAULT_LEVEL).unwrap_or_else(|| raw.clone());
                for (from, n) in [(0, len), (0, 2), (len - 2, 2), (len / 4 * 2, len / 4 * 2)] {
                    let mut out = vec![MaybeUninit::new(0xAAu8); n];
                    unpack(&packed, len, |u| u.place(from, &mut out)).unwrap();
                    // SAFETY: every byte was set, by 0xAA or by `place`.
                    let out: Vec<u8> = out.iter().map(|b| unsafe { b.assume_init() }).collect();
                    assert_eq!(out, raw[from..from + n], "length {len}, bytes {from}+{n}");
                }
            }
        }
        assert!(
            unpack(&[1, 2, 3], 3, |_| ()).is_err(),
            "odd sizes are not samples"
        );
    }

    #[test]
    fn untransform_matches_the_naive_definition() {
        let mut seed = 12345u32;
        for len in [0usize, 1, 2, 3, 15, 16, 17, 31, 32, 33, 47, 100, 1001, 4099] {
            let t: Vec<u8> = (0..len)
                .map(|_| {
                    seed = seed.wrapping_mul(1664525).wrapping_add(1013904223);
                    (seed >> 24) as u8
                })
                .collect();
            let mut sums = t.clone();
            for i in 1..len {
                sums[i] = sums[i - 1].wrapping_add(t[i]).wrapping_sub(128);
            }
            let half = len.div_ceil(2);
            let naive: Vec<u8> = (0..len)
                .map(|i| {
                    if i % 2 == 0 {
                        sums[i / 2]
                    } else {
                        sums[half + i / 2]
                    }
                })
                .collect();
            assert_eq!(untransform(&mut t.clone()), naive, "length {len}");
        }
    }

    #[test]
    fn transform_matches_the_naive_definition() {
        for len in [0usize, 1, 2, 3, 31, 32, 33, 64, 65, 1001] {
            let raw: Vec<u8> = (0..len).map(|i| (i * i * 31 % 251) as u8).collect();
            let mut t = naive_transform(&raw);
            let mut ours = vec![0u8; len];
            transform(&raw, &mut ours);
            assert_eq!(ours, t, "length {len}");
            assert_eq!(untransform(&mut t), raw, "length {len}");
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
        // The zlib wrapper, checked here: a header that is not zlib's, and
        // an Adler-32 that is not the output's.
        for at in [0, 1, packed.len() - 1] {
            let mut bad = packed.clone();
            bad[at] ^= 0x21;
            assert!(decompress(&bad, raw.len()).is_err(), "byte {at} damaged");
        }
    }

    #[test]
    fn flat_blocks_decode_from_a_few_bytes() {
        // A transparent 64x64 tile of half RGBA: a few dozen bytes of
        // deflate data, all of it inside libdeflate's end margin.
        let flat = vec![0u8; 64 * 64 * 8];
        let packed = reference_compress(&flat);
        assert!(packed.len() < 100, "{} bytes", packed.len());
        assert_eq!(decompress(&packed, flat.len()).unwrap(), flat);
        let mut out = vec![MaybeUninit::new(1u8); flat.len()];
        unpack(&packed, flat.len(), |u| u.place(0, &mut out)).unwrap();
        assert!(out.iter().all(|b| unsafe { b.assume_init() } == 0));
    }

    /// The transform written out step by step as the OpenEXR spec gives it:
    /// even bytes then odd bytes, each the difference to the previous + 128.
    fn naive_transform(raw: &[u8]) -> Vec<u8> {
        let mut t: Vec<u8> = raw
            .iter()
            .step_by(2)
            .chain(raw.iter().skip(1).step_by(2))
            .copied()
            .collect();
        for i in (1..t.len()).rev() {
            t[i] = t[i].wrapping_sub(t[i - 1]).wrapping_add(128);
        }
        t
    }

    /// The naive transform, zlib-compressed.
    fn reference_compress(raw: &[u8]) -> Vec<u8> {
        let t = naive_transform(raw);
        let mut c = libdeflater::Compressor::new(libdeflater::CompressionLvl::new(9).unwrap());
        let mut out = vec![0; c.zlib_compress_bound(t.len())];
        let n = c.zlib_compress(&t, &mut out).unwrap();
        out.truncate(n);
        out
    }
}
