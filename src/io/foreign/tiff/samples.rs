//! What a TIFF pixel stores and the values it is read as, as OpenImageIO
//! 2.4 reads them: integer codes times the reciprocal of their largest
//! (8 and 16 bits as DPX's, `raw::widened`; 32 bits in single precision),
//! floats as they are, 8-bit white-is-zero grey inverted, palette indices
//! through the colour map (its 16-bit entries divided by 257 to 8 bits),
//! unassociated alpha multiplied into the colours.

use super::ifd::Ifd;
use crate::io::foreign::raw::widened;
use exr::meta::attribute::SampleType;

#[derive(Clone, Copy, PartialEq, Eq)]
enum Kind {
    U8,
    U16,
    U32,
    F32,
}

#[derive(Clone, Copy, PartialEq, Eq)]
enum Colour {
    Grey,
    /// Grey stored inverted (photometric 0).
    WhiteIsZero,
    Rgb,
    Palette,
}

/// A file's stored pixel and how it is read.
pub struct Stored {
    /// Samples in a stored pixel and bytes in a sample.
    pub samples: usize,
    pub bytes: usize,
    kind: Kind,
    colour: Colour,
    big_endian: bool,
    unassociated: bool,
    /// A palette file's colours, red, green and blue of each index.
    palette: Vec<[f32; 3]>,
}

impl Stored {
    /// The stored pixel `ifd` describes, or why it is not read.
    pub fn new(ifd: &Ifd) -> Result<Stored, String> {
        let photometric = ifd.first_unsigned(262)?.unwrap_or(1);
        let samples = ifd.first_unsigned(277)?.unwrap_or(1);
        let bits = ifd.unsigned(258)?.unwrap_or(vec![1]);
        let first = bits.first().copied().unwrap_or(1);
        if bits.iter().any(|&b| b != first) {
            return Err(format!(
                "its samples of {bits:?} bits are not read: samples alike are"
            ));
        }
        // Void (4) is read as unsigned, as libtiff does.
        let format = match ifd.first_unsigned(339)?.unwrap_or(1) {
            4 => 1,
            f => f,
        };
        let kind = match (format, first) {
            (1, 8) => Kind::U8,
            (1, 16) => Kind::U16,
            (1, 32) => Kind::U32,
            (3, 32) => Kind::F32,
            _ => {
                return Err(format!(
                    "its {first}-bit samples of format {format} are not read: 8, 16 and 32-bit \
                     unsigned integers and 32-bit floats are"
                ))
            }
        };
        let colour = match (photometric, samples) {
            (0, 1) if kind == Kind::U8 => Colour::WhiteIsZero,
            (0, _) => {
                return Err(format!(
                    "its white-is-zero grey of {samples} {first}-bit samples is not read: 8-bit \
                     grey without alpha is (oiiotool 2.4 leaves deeper samples uninverted and \
                     inverts alpha)"
                ))
            }
            (1, 1 | 2) => Colour::Grey,
            (2, 3 | 4) => Colour::Rgb,
            (3, 1) if kind == Kind::U8 => Colour::Palette,
            _ => {
                return Err(format!(
                    "its pixels ({samples} samples of {first} bits, photometric interpretation \
                     {photometric}) are not read: grey, RGB (with or without alpha) and 8-bit \
                     palette colour are"
                ))
            }
        };
        let extra = ifd.unsigned(338)?.unwrap_or_default();
        let palette = match colour {
            Colour::Palette => palette(ifd)?,
            _ => Vec::new(),
        };
        Ok(Stored {
            samples: samples as usize,
            bytes: first as usize / 8,
            kind,
            colour,
            big_endian: ifd.big_endian,
            unassociated: matches!(samples, 2 | 4) && extra.first() == Some(&2),
            palette,
        })
    }

    pub fn float(&self) -> bool {
        self.kind == Kind::F32
    }

    /// The channels a pixel is read as, in the order `pixel` gives them.
    pub fn names(&self) -> &'static [&'static str] {
        match (self.colour, self.samples) {
            (Colour::Palette, _) | (Colour::Rgb, 3) => &["R", "G", "B"],
            (Colour::Rgb, _) => &["R", "G", "B", "A"],
            (_, 1) => &["Y"],
            _ => &["Y", "A"],
        }
    }

    /// HALF for 8-bit codes, which it holds exactly; FLOAT for the others.
    pub fn sample_type(&self) -> SampleType {
        match self.kind {
            Kind::U8 => SampleType::F16,
            _ => SampleType::F32,
        }
    }

    /// The values of a pixel whose sample `s`'s bytes `sample(s)` gives.
    pub fn pixel<'a>(
        &self,
        sample: impl Fn(usize) -> Result<&'a [u8], String>,
        out: &mut Vec<f32>,
    ) -> Result<(), String> {
        if self.colour == Colour::Palette {
            out.extend(self.palette[sample(0)?[0] as usize]);
            return Ok(());
        }
        for s in 0..self.samples {
            let b = sample(s)?;
            let code = |n: usize| -> u32 {
                let fold = |v: u32, &byte: &u8| v << 8 | byte as u32;
                match self.big_endian {
                    true => b[..n].iter().fold(0, fold),
                    false => b[..n].iter().rev().fold(0, fold),
                }
            };
            out.push(match self.kind {
                Kind::U8 if self.colour == Colour::WhiteIsZero => widened(255 - b[0] as u32, 8),
                Kind::U8 => widened(b[0] as u32, 8),
                Kind::U16 => widened(code(2), 16),
                Kind::U32 => code(4) as f32 * (1.0 / u32::MAX as f32),
                Kind::F32 => f32::from_bits(code(4)),
            });
        }
        if self.unassociated {
            let (colours, alpha) = out.split_at_mut(self.samples - 1);
            colours.iter_mut().for_each(|v| *v *= alpha[0]);
        }
        Ok(())
    }
}

/// The colour map of an 8-bit palette file: 256 reds, greens, blues.
fn palette(ifd: &Ifd) -> Result<Vec<[f32; 3]>, String> {
    let map = ifd.unsigned(320)?.unwrap_or_default();
    if map.len() != 3 * 256 {
        return Err(format!(
            "its colour map has {} entries, not 3 x 256",
            map.len()
        ));
    }
    let value = |v: u64| widened((v / 257) as u32, 8);
    Ok((0..256)
        .map(|i| [value(map[i]), value(map[256 + i]), value(map[512 + i])])
        .collect())
}
