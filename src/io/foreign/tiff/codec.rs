//! A TIFF chunk's (strip's or tile's) stored bytes to its samples' bytes:
//! decompression (none, LZW in its current and its old bit order,
//! Deflate, PackBits) and the predictors (horizontal differencing, and
//! floating point's byte planes). The samples stay in the file's byte order.

/// Decompresses `stored` (compression `method`) into `size` bytes.
pub fn decompress(method: u16, stored: &[u8], size: usize) -> Result<Vec<u8>, String> {
    let mut out = vec![0u8; size];
    let made = match method {
        1 => {
            let n = stored.len().min(size);
            out[..n].copy_from_slice(&stored[..n]);
            n
        }
        5 => lzw(stored, &mut out)?,
        8 | 32946 => deflate(stored, &mut out)?,
        32773 => packbits(stored, &mut out),
        _ => return Err(format!("compression {method} is not decoded")),
    };
    if made < size {
        return Err(format!("it decodes to {made} bytes, not {size}"));
    }
    Ok(out)
}

/// LZW codes: most significant bit first with the early code-width change
/// (TIFF 6), or, when the stream starts 0x00 then an odd byte, least
/// significant bit first without it (the pre-TIFF 6 codes libtiff reads).
fn lzw(stored: &[u8], out: &mut [u8]) -> Result<usize, String> {
    use weezl::{decode::Decoder, BitOrder, LzwStatus};
    let old = stored.len() >= 2 && stored[0] == 0 && stored[1] & 1 == 1;
    let mut decoder = match old {
        true => Decoder::new(BitOrder::Lsb, 8),
        false => Decoder::with_tiff_size_switch(BitOrder::Msb, 8),
    };
    let (mut read, mut made) = (0, 0);
    while made < out.len() {
        let r = decoder.decode_bytes(&stored[read..], &mut out[made..]);
        read += r.consumed_in;
        made += r.consumed_out;
        match r.status {
            Ok(LzwStatus::Ok) => {}
            // Its end code, or the data's end: what was decoded is checked.
            Ok(LzwStatus::Done | LzwStatus::NoProgress) => break,
            Err(e) => return Err(format!("bad LZW codes: {e}")),
        }
    }
    Ok(made)
}

/// A zlib stream; one that holds more than the chunk (a last strip written
/// whole) gives its first bytes, as libtiff does.
fn deflate(stored: &[u8], out: &mut [u8]) -> Result<usize, String> {
    use libdeflater::{DecompressionError, Decompressor};
    let mut d = Decompressor::new();
    match d.zlib_decompress(stored, out) {
        Ok(n) => Ok(n),
        Err(DecompressionError::InsufficientSpace) => {
            let mut more = vec![0u8; out.len().saturating_mul(4).max(1 << 16)];
            let n = d
                .zlib_decompress(stored, &mut more)
                .map_err(|e| format!("bad Deflate stream: {e}"))?;
            let n = n.min(out.len());
            out[..n].copy_from_slice(&more[..n]);
            Ok(n)
        }
        Err(e) => Err(format!("bad Deflate stream: {e}")),
    }
}

/// PackBits runs, up to `out`'s length.
fn packbits(stored: &[u8], out: &mut [u8]) -> usize {
    let (mut i, mut made) = (0, 0);
    while i < stored.len() && made < out.len() {
        let n = stored[i] as i8;
        i += 1;
        if n >= 0 {
            let count = (n as usize + 1).min(stored.len() - i).min(out.len() - made);
            out[made..made + count].copy_from_slice(&stored[i..i + count]);
            i += n as usize + 1;
            made += count;
        } else if n != -128 && i < stored.len() {
            let count = (1 - n as isize) as usize;
            let count = count.min(out.len() - made);
            out[made..made + count].fill(stored[i]);
            i += 1;
            made += count;
        }
    }
    made
}

/// Undoes predictor `predictor` on `chunk`, rows of `row` samples
/// (`samples` a pixel) of `bytes` bytes each in the file's byte order.
pub fn unpredict(
    predictor: u16,
    chunk: &mut [u8],
    (row, samples, bytes): (usize, usize, usize),
    big_endian: bool,
) {
    let row_bytes = row * bytes;
    if row_bytes == 0 {
        return;
    }
    for r in chunk.chunks_exact_mut(row_bytes) {
        match predictor {
            2 => horizontal(r, samples, bytes, big_endian),
            3 => floating(r, samples, bytes, big_endian),
            _ => {}
        }
    }
}

/// Each sample the sum of itself and the one `samples` before it.
fn horizontal(row: &mut [u8], samples: usize, bytes: usize, big_endian: bool) {
    if bytes == 1 {
        for i in samples..row.len() {
            row[i] = row[i].wrapping_add(row[i - samples]);
        }
        return;
    }
    let get = |row: &[u8], j: usize| {
        let b = &row[j * bytes..(j + 1) * bytes];
        let fold = |v: u64, &byte: &u8| v << 8 | byte as u64;
        match big_endian {
            true => b.iter().fold(0, fold),
            false => b.iter().rev().fold(0, fold),
        }
    };
    for j in samples..row.len() / bytes {
        let v = get(row, j).wrapping_add(get(row, j - samples));
        let b = &mut row[j * bytes..(j + 1) * bytes];
        for (k, byte) in b.iter_mut().enumerate() {
            let shift = 8 * if big_endian { bytes - 1 - k } else { k };
            *byte = (v >> shift) as u8;
        }
    }
}

/// Floating point: the row's bytes differenced across `samples`, then the
/// samples' bytes in planes, most significant first.
fn floating(row: &mut [u8], samples: usize, bytes: usize, big_endian: bool) {
    for i in samples..row.len() {
        row[i] = row[i].wrapping_add(row[i - samples]);
    }
    let planes = row.to_vec();
    let count = row.len() / bytes;
    for j in 0..count {
        for k in 0..bytes {
            let at = if big_endian { k } else { bytes - 1 - k };
            row[j * bytes + at] = planes[k * count + j];
        }
    }
}
