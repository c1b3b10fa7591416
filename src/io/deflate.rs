//! The zlib stream under EXR's ZIP/ZIPS blocks, made by two deflate libraries.
//!
//! After EXR's byte split, the first half of a half-float block holds the
//! low mantissa bytes. On film grain and render noise they are nearly random:
//! libdeflate spends about two thirds of its time there searching for matches
//! that barely exist, where ISA-L's igzip level 1 writes the same size
//! (within 0.1% on our 4K plates) about five times faster. On smooth or
//! empty content igzip is worse (up to 7% larger on the Beachball renders).
//! So: igzip tries the first half; if that half stays above half its size it
//! is kept as byte-aligned deflate blocks and libdeflate compresses the rest;
//! otherwise libdeflate compresses the whole block. One stream either way, so
//! any zlib decoder reads it.
//!
//! A noisy block under 64 KiB (a 64x64 half RGBA tile is 32 KiB, a ZIPS line
//! of a 2K plate 16 KiB) gives igzip its second half too, as the final
//! blocks. In such blocks igzip's first half is no longer nearly free (an
//! opaque alpha's low bytes are runs of a tile's width, not of a plate's,
//! which igzip crosses at memcpy speed), and libdeflate's second half made a
//! 4K plate in 64x64 tiles cost 1.5x the CPU time of the same plate in
//! scanlines. igzip does that half 3x faster, about 12% larger: the tiled
//! plate is 1.3% larger, still 0.7% smaller than OpenEXR 3.5 writes it. A
//! `--zip-level` above the default asks for size: libdeflate then ends every
//! block.
//!
//! Smooth content (a blurred plate) is told without igzip's trial: the
//! order-0 entropy of a sample of the first half under 3.2 bits a byte
//! (a blurred 4K plate: 2.3-2.9 bits, igzip 20-30% of the size; grain 6.1-6.6
//! bits, igzip 70-80%). The trial had cost a third of the encode of a
//! blurred plate, which libdeflate compresses whole.
//!
//! A build without ISA-L (`cfg(isal)` unset by build.rs: the `isal` feature
//! off, or ISA-L's build tools missing) gives every block to libdeflate at
//! the job's level: a valid stream of the same data, other bytes. So the same
//! job writes the same bytes on builds with the same `ENGINES`, which
//! `--version` and bench's record name.

use libdeflater::{CompressionLvl, Compressor};
use std::cell::RefCell;

/// libdeflate level 2 (for what ISA-L does not take). Measured
/// against OpenEXR 3.5 (oiiotool 3.2, which writes what libdeflate level 4
/// writes): grainy 4K plates +0.6%, the ScanLines and Beachball photographs
/// -2.3% to +1.7%.
pub const DEFAULT_LEVEL: u8 = 2;

/// Above this compressed/raw ratio, the first half counts as noise.
const NOISE_RATIO: f64 = 0.5;

/// Below this order-0 entropy of the sample, in bits per 8 bits, a first
/// half is smooth without igzip's trial.
const SMOOTH_ENTROPY: f64 = 0.4;

/// The sample: every `SAMPLE_EVERY`th run of `SAMPLE_RUN` bytes of the first
/// half (a sixteenth of it, spread over its rows and channels).
const SAMPLE_RUN: usize = 512;
const SAMPLE_EVERY: usize = 16;

/// Noisy blocks smaller than this are igzip's alone (at levels up to the
/// default).
const SMALL_BLOCK: usize = 64 << 10;

/// zlib header: deflate with a 32 KiB window, "fastest" level hint; the two
/// bytes read as a big-endian multiple of 31, as RFC 1950 requires.
const ZLIB_HEADER: [u8; 2] = [0x78, 0x01];

/// The deflate engines of this build, for `--version`.
#[cfg(isal)]
pub const ENGINES: &str = "ISA-L igzip + libdeflate";
#[cfg(not(isal))]
pub const ENGINES: &str = "libdeflate alone, built without ISA-L";

thread_local! {
    /// This thread's libdeflate compressor and the level it was made for.
    static LIBDEFLATE: RefCell<Option<(u8, Compressor)>> = const { RefCell::new(None) };
    /// igzip's level-1 work buffer (hash table and token space).
    static IGZIP_BUFFER: RefCell<Vec<u8>> = const { RefCell::new(Vec::new()) };
}

/// Bytes a thread's compressors keep once made (`LIBDEFLATE`,
/// `IGZIP_BUFFER`), for the memory bound: libdeflate's at `level` (its
/// near-optimal parser from level 10: 8.6 MiB, 0.64 below, heaptrack) and
/// igzip's work buffer.
pub fn state_bytes(level: u8) -> usize {
    let libdeflate = match level {
        10.. => 8_800 << 10,
        _ => 660 << 10,
    };
    libdeflate + (300 << 10)
}

/// Appends the zlib stream of `data` to `out` (cleared first), with libdeflate
/// at `level` (1-12) for whatever igzip does not take.
pub fn zlib_compress(data: &[u8], level: u8, out: &mut Vec<u8>) {
    out.clear();
    out.reserve(bound(data.len()));
    out.extend_from_slice(&ZLIB_HEADER);
    let half = data.len().div_ceil(2);
    let noisy = !smooth(&data[..half])
        && match igzip_blocks(&data[..half], false, out) {
            Some(size) if size as f64 > NOISE_RATIO * half as f64 => true,
            _ => {
                out.truncate(ZLIB_HEADER.len());
                false
            }
        };
    let rest = if noisy { &data[half..] } else { data };
    let noisy_and_small =
        rest.len() < data.len() && data.len() < SMALL_BLOCK && level <= DEFAULT_LEVEL;
    if !(noisy_and_small && igzip_blocks(rest, true, out).is_some()) {
        libdeflate_final_blocks(rest, level, out);
    }
    out.extend_from_slice(&libdeflater::adler32(data).to_be_bytes());
}

/// Whether the order-0 entropy of `half`'s sample is under `SMOOTH_ENTROPY`;
/// a half shorter than a run is left to igzip's trial.
fn smooth(half: &[u8]) -> bool {
    if half.len() < SAMPLE_RUN {
        return false;
    }
    let mut counts = [0u32; 256];
    let mut n = 0;
    for run in half.chunks(SAMPLE_RUN).step_by(SAMPLE_EVERY) {
        run.iter().for_each(|&b| counts[b as usize] += 1);
        n += run.len();
    }
    let bits: f64 = counts
        .iter()
        .filter(|&&c| c > 0)
        .map(|&c| {
            let p = c as f64 / n as f64;
            -p * p.log2()
        })
        .sum();
    bits < SMOOTH_ENTROPY * 8.0
}

/// Room for any input: stored blocks cost 5 bytes per 64 KiB, and igzip's
/// dynamic header at most 328 bytes per block.
fn bound(len: usize) -> usize {
    len + 5 * (len / 65535 + 2) + 2 * 328 + 16
}

/// Without ISA-L: never taken, libdeflate compresses whole blocks.
#[cfg(not(isal))]
fn igzip_blocks(_: &[u8], _: bool, _: &mut Vec<u8>) -> Option<usize> {
    None
}

/// Appends `data` as deflate blocks: the `last` ones of the stream, or
/// non-final blocks ending byte-aligned (igzip's full flush), so further
/// blocks can follow; the size written, or `None` (with `out` unchanged in
/// length) if igzip refused.
#[cfg(isal)]
fn igzip_blocks(data: &[u8], last: bool, out: &mut Vec<u8>) -> Option<usize> {
    use isal_sys::igzip_lib as isal;
    if data.is_empty() || u32::try_from(bound(data.len())).is_err() {
        return None;
    }
    IGZIP_BUFFER.with(|buffer| {
        let mut level_buf = buffer.borrow_mut();
        level_buf.resize(isal::ISAL_DEF_LVL1_DEFAULT as usize, 0);
        let start = out.len();
        let room = bound(data.len());
        out.reserve(room);
        // SAFETY: the stream is initialised by igzip itself; it reads only
        // `data` and writes at most `room` bytes into `out`'s spare capacity,
        // both alive for the call; nothing keeps the pointers afterwards.
        let written = unsafe {
            let mut stream: isal::isal_zstream = std::mem::zeroed();
            isal::isal_deflate_stateless_init(&mut stream);
            stream.next_in = data.as_ptr().cast_mut();
            stream.avail_in = data.len() as u32;
            stream.next_out = out.as_mut_ptr().add(start);
            stream.avail_out = room as u32;
            stream.level = 1;
            stream.level_buf = level_buf.as_mut_ptr();
            stream.level_buf_size = level_buf.len() as u32;
            stream.end_of_stream = last as u16;
            stream.flush = if last {
                isal::NO_FLUSH
            } else {
                isal::FULL_FLUSH
            } as u16;
            stream.gzip_flag = isal::IGZIP_DEFLATE as u16;
            if isal::isal_deflate_stateless(&mut stream) != isal::COMP_OK as i32
                || stream.avail_in != 0
            {
                return None;
            }
            let written = stream.total_out as usize;
            out.set_len(start + written);
            written
        };
        Some(written)
    })
}

/// Appends `data` as deflate blocks, the last one final.
fn libdeflate_final_blocks(data: &[u8], level: u8, out: &mut Vec<u8>) {
    LIBDEFLATE.with(|c| {
        let mut c = c.borrow_mut();
        if c.as_ref().is_none_or(|(l, _)| *l != level) {
            let lvl = CompressionLvl::new(level.into()).expect("level checked by the command line");
            *c = Some((level, Compressor::new(lvl)));
        }
        let (_, c) = c.as_mut().expect("just made");
        let start = out.len();
        let room = c.deflate_compress_bound(data.len());
        out.resize(start + room, 0);
        let size = c
            .deflate_compress(data, &mut out[start..])
            .expect("the output has the bound's room");
        out.truncate(start + size);
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use libdeflater::Decompressor;

    fn round_trip(data: &[u8]) -> Vec<u8> {
        let mut out = Vec::new();
        zlib_compress(data, 2, &mut out);
        let mut back = vec![0u8; data.len()];
        let size = Decompressor::new()
            .zlib_decompress(&out, &mut back)
            .expect("a valid zlib stream with its checksum");
        assert_eq!(size, data.len());
        back
    }

    /// xorshift noise, so the first half takes igzip's path.
    fn noise(len: usize, seed: u64) -> Vec<u8> {
        let mut x = seed | 1;
        (0..len)
            .map(|_| {
                x ^= x << 13;
                x ^= x >> 7;
                x ^= x << 17;
                x as u8
            })
            .collect()
    }

    #[test]
    fn noisy_smooth_and_mixed_blocks_round_trip() {
        let smooth: Vec<u8> = (0..100_000).map(|i| (i / 300) as u8).collect();
        let mixed = |len| {
            let mut data = noise(len, 7);
            data.extend(std::iter::repeat_n(128u8, len));
            data
        };
        for data in [
            noise(1, 3),
            noise(2, 3),
            noise(300_001, 5),
            noise(20_001, 5),
            smooth,
            mixed(60_001),
            mixed(10_000),
            vec![],
        ] {
            assert_eq!(round_trip(&data), data);
        }
    }

    #[cfg(isal)]
    #[test]
    fn noise_goes_through_igzip_and_smooth_data_does_not() {
        let mut noisy_start = Vec::new();
        let data = noise(200_000, 11);
        assert!(igzip_blocks(&data[..100_000], false, &mut noisy_start).is_some());
        let mut out = Vec::new();
        zlib_compress(&data, 2, &mut out);
        // igzip's blocks open the stream (after the zlib header).
        assert_eq!(out[2..2 + noisy_start.len()], noisy_start[..]);
        let smooth: Vec<u8> = (0..200_000).map(|i| (i / 1000) as u8).collect();
        let mut igzip_start = Vec::new();
        igzip_blocks(&smooth[..100_000], false, &mut igzip_start);
        zlib_compress(&smooth, 2, &mut out);
        assert_ne!(
            out[2..2 + igzip_start.len().min(out.len() - 2)],
            igzip_start[..]
        );
    }

    #[cfg(isal)]
    #[test]
    fn a_half_told_smooth_by_its_sample_is_one_igzip_would_not_keep() {
        // Bytes uniform over `values` symbols: log2(values) bits of
        // entropy, from a run of flat runs to grain.
        let uniform = |values: u64, len: usize| -> Vec<u8> {
            let mut x = 0x9e37_79b9_7f4a_7c15u64;
            (0..len)
                .map(|_| {
                    x ^= x << 13;
                    x ^= x >> 7;
                    x ^= x << 17;
                    (x % values) as u8
                })
                .collect()
        };
        let mut told = [0, 0];
        for values in [1, 2, 3, 5, 8, 9, 10, 12, 16, 24, 32, 64, 128, 256] {
            let half = uniform(values, 245_760);
            let mut out = Vec::new();
            let size = igzip_blocks(&half, false, &mut out).unwrap();
            let kept = size as f64 > NOISE_RATIO * half.len() as f64;
            if smooth(&half) {
                assert!(
                    !kept,
                    "{values} values: smooth, but igzip keeps {size} bytes"
                );
            }
            told[smooth(&half) as usize] += 1;
        }
        assert!(told[0] > 0 && told[1] > 0, "both kinds seen: {told:?}");
        assert!(smooth(&[128; 1000]), "a flat half");
        assert!(!smooth(&noise(100_000, 3)));
        assert!(!smooth(&[128; SAMPLE_RUN - 1]), "too short to sample");
    }

    /// The deflate data of `zlib_compress(data)`, without the zlib header
    /// and checksum.
    #[cfg(isal)]
    fn deflate_data(data: &[u8]) -> Vec<u8> {
        let mut out = Vec::new();
        zlib_compress(data, 2, &mut out);
        out[2..out.len() - 4].to_vec()
    }

    #[cfg(isal)]
    #[test]
    fn a_small_noisy_block_is_igzips_alone_and_a_large_one_ends_in_libdeflate() {
        // A noisy first half and a smooth second half, as a tile of grain.
        let block = |len: usize| {
            let mut data = noise(len / 2, 13);
            data.extend((0..len / 2).map(|i| (i / 500) as u8));
            data
        };
        let igzip = |data: &[u8]| {
            let mut out = Vec::new();
            let half = data.len() / 2;
            igzip_blocks(&data[..half], false, &mut out).unwrap();
            igzip_blocks(&data[half..], true, &mut out).unwrap();
            out
        };
        let small = block(SMALL_BLOCK - 2);
        assert_eq!(deflate_data(&small), igzip(&small));
        assert_eq!(round_trip(&small), small);
        // A higher level asks for size: libdeflate ends the block.
        let mut higher = Vec::new();
        zlib_compress(&small, 3, &mut higher);
        assert_ne!(higher[2..higher.len() - 4], igzip(&small)[..]);
        let large = block(SMALL_BLOCK);
        let ours = deflate_data(&large);
        let mut first = Vec::new();
        igzip_blocks(&large[..large.len() / 2], false, &mut first).unwrap();
        assert_eq!(ours[..first.len()], first[..]);
        assert_ne!(ours, igzip(&large), "libdeflate writes the second half");
    }

    /// Calls `f` with the stack grown by 0, 64 KiB, 128 KiB... `levels` times.
    #[cfg(isal)]
    fn at_stack_depths(levels: usize, f: &mut dyn FnMut()) {
        f();
        if levels > 0 {
            // Never written: the stack moves, its pages stay untouched.
            let pad = std::mem::MaybeUninit::<[u8; 64 << 10]>::uninit();
            std::hint::black_box(&pad);
            at_stack_depths(levels - 1, f);
            std::hint::black_box(&pad);
        }
    }

    /// Upstream igzip (levels 1-2) hashed a stream's third byte from the
    /// address of its `isal_zstream`, on our stack, instead of the data
    /// (vendor/isal-sys carries the fix). The block is ZIP block 44 of frame
    /// 2 of the 4K grain bench plate, whose first half came out differently
    /// at about 1 stack address in 1300 (upstream failed 10 runs in 10, first
    /// at depths 223 to 5389).
    #[cfg(isal)]
    #[test]
    fn igzip_writes_the_same_bytes_wherever_its_stream_lives() {
        let check = || {
            let zlib = include_bytes!("testdata/grain-block.zlib");
            let mut block = vec![0u8; 491_520];
            Decompressor::new()
                .zlib_decompress(zlib, &mut block)
                .unwrap();
            let half = &block[..block.len() / 2];
            let compress = || {
                let mut out = Vec::new();
                igzip_blocks(half, false, &mut out).expect("grain takes igzip");
                out
            };
            let first = compress();
            let mut depth = 0;
            at_stack_depths(6144, &mut || {
                assert!(compress() == first, "differs at stack depth {depth}");
                depth += 1;
            });
        };
        std::thread::Builder::new()
            .stack_size(480 << 20)
            .spawn(check)
            .unwrap()
            .join()
            .unwrap();
    }
}
