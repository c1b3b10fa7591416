//! Rows of uncompressed integer samples, as DPX and Cineon store them: each
//! stored row a run of pixels, each pixel `components` codes, packed in one
//! of a few ways (`Packing`), rows `stride` bytes apart from `first`. A row
//! range is a byte range: it is read with one positioned read and each code
//! is turned into the output's sample through a table.

use super::Rows;
use crate::io::positioned::read_at;
use exr::meta::attribute::SampleType;
use std::fs::File;
use std::ops::Range;

/// How a row's codes are stored.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Packing {
    /// One byte a code (8 bits).
    Bytes,
    /// One 16-bit word a code, the code `shift` bits up (12 bits in the
    /// top of the word: 4).
    Words { shift: u32 },
    /// Three 10-bit codes a 32-bit word from its top, `pad` bits below the
    /// last (DPX's filled method A: 2, B: 0); with `reversed`, from its
    /// bottom (libdpx's order for one-component images).
    Filled10 { pad: u32, reversed: bool },
    /// A stream of codes with no gaps, filling 32-bit words from their least
    /// significant bit (DPX's packed 10 and 12 bits).
    Packed,
}

/// Where and how an image's codes are stored, and what each becomes.
pub struct Raw {
    /// The file offset of the first stored row.
    pub first: u64,
    /// Bytes from one stored row to the next (its samples and padding).
    pub stride: u64,
    pub width: usize,
    pub height: usize,
    pub components: usize,
    pub bits: u32,
    pub packing: Packing,
    pub big_endian: bool,
    /// The stored rows run bottom to top.
    pub bottom_up: bool,
    /// The stored pixels of a row run right to left.
    pub right_to_left: bool,
    /// For each channel of the header, in its order, the component of a
    /// pixel it holds.
    pub channels: Vec<usize>,
    /// Each code's sample, little-endian (2 bytes for HALF, 4 for FLOAT).
    pub table: Vec<u8>,
    pub sample_bytes: usize,
}

/// The samples of every code of `bits` bits as `sample` (HALF or FLOAT),
/// from each code's value.
pub fn table(bits: u32, sample: SampleType, value: impl Fn(u32) -> f32) -> Vec<u8> {
    (0..1u32 << bits)
        .flat_map(|code| match sample {
            SampleType::F16 => half::f16::from_f32(value(code)).to_le_bytes().to_vec(),
            _ => value(code).to_le_bytes().to_vec(),
        })
        .collect()
}

/// A code's value as OpenImageIO reads it: 8 bits times 1/255, others
/// widened to 16 bits by repeating their bits (10-bit 1023 is 65535), times
/// 1/65535, in single precision (a product by the reciprocal, not a
/// quotient: they differ in the last bit for some codes).
pub fn widened(code: u32, bits: u32) -> f32 {
    match bits {
        8 => code as f32 * (1.0 / 255.0),
        16 => code as f32 * (1.0 / 65535.0),
        _ => ((code << (16 - bits)) | (code >> (2 * bits - 16))) as f32 * (1.0 / 65535.0),
    }
}

/// The bytes a stored row's codes take (before any padding), for `packing`.
pub fn row_bytes(codes: u64, bits: u32, packing: Packing) -> u64 {
    match packing {
        Packing::Bytes => codes,
        Packing::Words { .. } => codes * 2,
        Packing::Filled10 { .. } => codes.div_ceil(3) * 4,
        Packing::Packed => (codes * bits as u64).div_ceil(32) * 4,
    }
}

impl Raw {
    fn word32(&self, bytes: &[u8], index: usize) -> u32 {
        let at = index * 4;
        let Some(b) = bytes.get(at..at + 4) else {
            return 0;
        };
        let b: [u8; 4] = b.try_into().expect("4 bytes");
        match self.big_endian {
            true => u32::from_be_bytes(b),
            false => u32::from_le_bytes(b),
        }
    }

    /// Code `i` of a stored row's bytes.
    fn code(&self, row: &[u8], i: usize) -> u32 {
        let mask = (1u32 << self.bits) - 1;
        match self.packing {
            Packing::Bytes => row[i] as u32,
            Packing::Words { shift } => {
                let b = [row[2 * i], row[2 * i + 1]];
                let word = match self.big_endian {
                    true => u16::from_be_bytes(b),
                    false => u16::from_le_bytes(b),
                };
                (word as u32 >> shift) & mask
            }
            Packing::Filled10 { pad, reversed } => {
                let k = (i % 3) as u32;
                let slot = if reversed { k } else { 2 - k };
                (self.word32(row, i / 3) >> (slot * 10 + pad)) & mask
            }
            Packing::Packed => {
                let bit = i * self.bits as usize;
                let (index, offset) = (bit / 32, bit % 32);
                let pair =
                    self.word32(row, index) as u64 | (self.word32(row, index + 1) as u64) << 32;
                (pair >> offset) as u32 & mask
            }
        }
    }

    /// A stored row's `count` codes in their stored order, into `codes`:
    /// `code`'s values, a 32-bit word at a time for filled 10 bits (most
    /// DPX scans), where the per-code `code` took a tenth of a 4K scan's
    /// conversion to ACEScg.
    fn row_codes(&self, row: &[u8], count: usize, codes: &mut Vec<u32>) {
        codes.clear();
        let Packing::Filled10 { pad, reversed } = self.packing else {
            codes.extend((0..count).map(|i| self.code(row, i)));
            return;
        };
        let slots = match reversed {
            true => [pad, 10 + pad, 20 + pad],
            false => [20 + pad, 10 + pad, pad],
        };
        for index in 0..count.div_ceil(3) {
            let word = self.word32(row, index);
            codes.extend(slots.map(|shift| (word >> shift) & 0x3ff));
        }
        codes.truncate(count);
    }

    /// Writes stored row `row`'s pixels into `out` in the header's layout.
    fn decode_row(&self, row: &[u8], codes: &mut Vec<u32>, out: &mut [u8]) {
        let (width, size) = (self.width, self.sample_bytes);
        self.row_codes(row, width * self.components, codes);
        for (c, &component) in self.channels.iter().enumerate() {
            let plane = &mut out[c * width * size..(c + 1) * width * size];
            let code = |x: usize| {
                let stored = if self.right_to_left { width - 1 - x } else { x };
                codes[stored * self.components + component] as usize
            };
            match size {
                2 => samples::<2>(plane, &self.table, code),
                _ => samples::<4>(plane, &self.table, code),
            }
        }
    }
}

/// Each of `plane`'s `N`-byte samples from `table`, at the index `code`
/// gives for its column (a copy of a known size: no call per sample).
fn samples<const N: usize>(plane: &mut [u8], table: &[u8], code: impl Fn(usize) -> usize) {
    for (x, sample) in plane.chunks_exact_mut(N).enumerate() {
        let at = code(x) * N;
        let value: [u8; N] = table[at..at + N].try_into().expect("N bytes");
        sample.copy_from_slice(&value);
    }
}

impl Rows for Raw {
    fn read(&self, file: &File, rows: Range<usize>) -> Result<Vec<u8>, String> {
        if rows.start >= rows.end || rows.end > self.height {
            return Err(format!("rows {rows:?} are outside the image"));
        }
        let count = rows.end - rows.start;
        // The stored rows holding them, top first in the file.
        let first_stored = match self.bottom_up {
            true => self.height - rows.end,
            false => rows.start,
        };
        let codes = (self.width * self.components) as u64;
        let used = row_bytes(codes, self.bits, self.packing);
        let span = (count as u64 - 1) * self.stride + used;
        let at = self.first + first_stored as u64 * self.stride;
        let bytes = read_at(file, at, span as usize)?;
        let out_row = self.channels.len() * self.width * self.sample_bytes;
        let mut out = vec![0u8; count * out_row];
        let mut codes = Vec::new();
        for (k, out) in out.chunks_exact_mut(out_row).enumerate() {
            let stored = match self.bottom_up {
                true => count - 1 - k,
                false => k,
            };
            let start = stored * self.stride as usize;
            self.decode_row(&bytes[start..start + used as usize], &mut codes, out);
        }
        Ok(out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn widening_repeats_the_bits_as_openimageio_does() {
        assert_eq!(widened(1023, 10), 1.0);
        assert_eq!(widened(255, 8), 1.0);
        assert_eq!(widened(4095, 12), 1.0);
        assert_eq!(
            widened(512, 10),
            ((512 << 6) | (512 >> 4)) as f32 * (1.0 / 65535.0)
        );
        // Not 65535 / 65535 = 1 exactly: the reciprocal's rounding shows.
        assert_eq!(widened(3, 8), 3.0 * (1.0f32 / 255.0));
    }

    fn raw(bits: u32, packing: Packing, components: usize, width: usize) -> Raw {
        Raw {
            first: 0,
            stride: 0,
            width,
            height: 1,
            components,
            bits,
            packing,
            big_endian: true,
            bottom_up: false,
            right_to_left: false,
            channels: (0..components).collect(),
            table: Vec::new(),
            sample_bytes: 2,
        }
    }

    #[test]
    fn packed_codes_fill_words_from_their_low_bits() {
        // Codes 1, 2, 3, 4 of 10 bits: bits 0-9, 10-19, 20-29, 30-39.
        let stream: u64 = 1 | 2 << 10 | 3 << 20 | 4 << 30;
        let mut bytes = (stream as u32).to_be_bytes().to_vec();
        bytes.extend(((stream >> 32) as u32).to_be_bytes());
        let r = raw(10, Packing::Packed, 1, 4);
        assert_eq!(
            (0..4).map(|i| r.code(&bytes, i)).collect::<Vec<_>>(),
            [1, 2, 3, 4]
        );
    }

    #[test]
    fn filled_codes_run_from_the_top_of_a_word() {
        let word: u32 = (5 << 22) | (6 << 12) | (7 << 2);
        let bytes = word.to_be_bytes();
        let a = raw(
            10,
            Packing::Filled10 {
                pad: 2,
                reversed: false,
            },
            3,
            1,
        );
        assert_eq!(
            (0..3).map(|i| a.code(&bytes, i)).collect::<Vec<_>>(),
            [5, 6, 7]
        );
        let grey = raw(
            10,
            Packing::Filled10 {
                pad: 2,
                reversed: true,
            },
            1,
            3,
        );
        assert_eq!(
            (0..3).map(|i| grey.code(&bytes, i)).collect::<Vec<_>>(),
            [7, 6, 5]
        );
        let b = raw(
            10,
            Packing::Filled10 {
                pad: 0,
                reversed: false,
            },
            3,
            1,
        );
        let word: u32 = (5 << 20) | (6 << 10) | 7;
        assert_eq!(
            (0..3)
                .map(|i| b.code(&word.to_be_bytes(), i))
                .collect::<Vec<_>>(),
            [5, 6, 7]
        );
    }

    /// Filled 10-bit rows decoded a word at a time give the per-code
    /// reading's codes, for both fillings, both orders and byte orders,
    /// and counts that end inside a word.
    #[test]
    fn filled_rows_decode_as_their_codes() {
        let bytes: Vec<u8> = (0u32..64)
            .map(|i| (i.wrapping_mul(2_654_435_761) >> 13) as u8)
            .collect();
        for (pad, reversed, big_endian) in (0..8).map(|k| (2 * (k & 1), k & 2 != 0, k & 4 != 0)) {
            let mut r = raw(10, Packing::Filled10 { pad, reversed }, 1, 0);
            r.big_endian = big_endian;
            for count in [1, 2, 3, 10, 41, 42] {
                let mut codes = Vec::new();
                r.row_codes(&bytes, count, &mut codes);
                let each: Vec<u32> = (0..count).map(|i| r.code(&bytes, i)).collect();
                assert_eq!(codes, each, "pad {pad}, reversed {reversed}, {count} codes");
            }
        }
    }
}
