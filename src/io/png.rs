//! A PNG writer for 8-bit RGB images (the demo's contact sheet): the zlib
//! stream from `deflate`, the chunks' CRC-32 from libdeflate, no filter
//! (the sheet is small; filters would save bytes, not time).

/// PNG's signature (RFC 2083, 3.1).
const SIGNATURE: [u8; 8] = [0x89, b'P', b'N', b'G', b'\r', b'\n', 0x1a, b'\n'];

/// An 8-bit RGB image, rows top to bottom.
pub struct Rgb8 {
    pub width: usize,
    pub height: usize,
    /// `width * height` pixels.
    pub pixels: Vec<[u8; 3]>,
}

/// The PNG file of `image`.
pub fn encode(image: &Rgb8) -> Vec<u8> {
    let mut header = Vec::with_capacity(13);
    header.extend_from_slice(&(image.width as u32).to_be_bytes());
    header.extend_from_slice(&(image.height as u32).to_be_bytes());
    // 8 bits a sample, colour type 2 (RGB), deflate, filter method 0, no interlace.
    header.extend_from_slice(&[8, 2, 0, 0, 0]);
    let mut raw = Vec::with_capacity(image.height * (1 + 3 * image.width));
    for row in image.pixels.chunks(image.width.max(1)) {
        raw.push(0); // filter type None
        raw.extend(row.iter().flatten());
    }
    let mut data = Vec::new();
    super::deflate::zlib_compress(&raw, 6, &mut data);
    let mut file = SIGNATURE.to_vec();
    for (kind, body) in [(b"IHDR", &header), (b"IDAT", &data), (b"IEND", &Vec::new())] {
        file.extend_from_slice(&(body.len() as u32).to_be_bytes());
        let start = file.len();
        file.extend_from_slice(kind);
        file.extend_from_slice(body);
        let crc = libdeflater::crc32(&file[start..]);
        file.extend_from_slice(&crc.to_be_bytes());
    }
    file
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn chunks_carry_their_length_type_and_crc() {
        let image = Rgb8 {
            width: 2,
            height: 1,
            pixels: vec![[255, 0, 0], [0, 0, 255]],
        };
        let file = encode(&image);
        assert_eq!(file[..8], SIGNATURE);
        // IHDR: length 13, then the type, 2 x 1, 8-bit RGB.
        assert_eq!(file[8..16], [0, 0, 0, 13, b'I', b'H', b'D', b'R']);
        assert_eq!(file[16..24], [0, 0, 0, 2, 0, 0, 0, 1]);
        // CRC-32 of "IEND" with no data, as every PNG ends.
        assert_eq!(file[file.len() - 4..], [0xae, 0x42, 0x60, 0x82]);
        let at = 33 + 8;
        let length = u32::from_be_bytes(file[33..37].try_into().unwrap()) as usize;
        assert_eq!(&file[37..41], b"IDAT");
        let mut raw = [0u8; 7];
        let inflated = libdeflater::Decompressor::new()
            .zlib_decompress(&file[at..at + length], &mut raw)
            .unwrap();
        assert_eq!((inflated, raw), (7, [0, 255, 0, 0, 0, 0, 255]));
    }
}
