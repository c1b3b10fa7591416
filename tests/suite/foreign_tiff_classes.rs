//! TIFF classes oiiotool reads but does not write (specs/file-format.md,
//! "TIFF"): 8-bit white-is-zero grey, 8-bit palette colour, old-style LZW
//! codes (written here byte by byte), 32-bit unsigned samples (oiiotool's
//! own), each made in every compression, predictor and layout by tiffcp
//! and read as oiiotool reads them (`idiff -fail 0`); the classes outside
//! issue 33's list refused in one line.

use crate::common::{limited, peer, s, stderr};
use crate::foreign_inputs::{assert_as_oiiotool, transcode};
use std::path::{Path, PathBuf};
use std::process::Command;

const PATTERN: &str =
    "fill:topleft=0,0,0,0:topright=1,0.2,0.5,0.3:bottomleft=0.3,1,0.7,1:bottomright=1,1,1,0.6";

/// An uncompressed little-endian TIFF of one strip.
struct Tif {
    width: u32,
    height: u32,
    samples: u16,
    bits: u16,
    /// SampleFormat: 1 unsigned, 2 signed, 3 float.
    format: u16,
    photometric: u16,
    extra: Vec<u16>,
    colormap: Vec<u16>,
    /// Old-style LZW (least significant bit first) instead of none.
    old_lzw: bool,
}

impl Tif {
    fn new(samples: u16, bits: u16, photometric: u16) -> Tif {
        Tif {
            width: 37,
            height: 23,
            samples,
            bits,
            format: 1,
            photometric,
            extra: Vec::new(),
            colormap: Vec::new(),
            old_lzw: false,
        }
    }

    /// Pseudo-random samples, each `bits` bits (a float's bits in [0, 2)).
    fn data(&self) -> Vec<u8> {
        let count = (self.width * self.height * self.samples as u32) as u64;
        let bytes = self.bits as usize / 8;
        (0..count)
            .flat_map(|i| {
                let v = i.wrapping_mul(2_654_435_761) >> 3;
                let v = match self.format {
                    3 => (((v % 2000) as f32) / 1000.0).to_bits() as u64,
                    _ => v,
                };
                v.to_le_bytes()[..bytes].to_vec()
            })
            .collect()
    }

    fn bytes(&self) -> Vec<u8> {
        let mut data = self.data();
        if self.old_lzw {
            data = weezl::encode::Encoder::new(weezl::BitOrder::Lsb, 8)
                .encode(&data)
                .unwrap();
        }
        let short = |v: &[u16]| (3u16, v.iter().flat_map(|x| x.to_le_bytes()).collect());
        let long = |v: u32| (4u16, v.to_le_bytes().to_vec());
        let n = self.samples as usize;
        let mut tags: Vec<(u16, (u16, Vec<u8>))> = vec![
            (256, long(self.width)),
            (257, long(self.height)),
            (258, short(&vec![self.bits; n])),
            (259, short(&[if self.old_lzw { 5 } else { 1 }])),
            (262, short(&[self.photometric])),
            (273, long(0)),
            (277, short(&[self.samples])),
            (278, long(self.height)),
            (279, long(data.len() as u32)),
            (284, short(&[1])),
            (339, short(&vec![self.format; n])),
        ];
        if !self.colormap.is_empty() {
            tags.push((320, short(&self.colormap)));
        }
        if !self.extra.is_empty() {
            tags.push((338, short(&self.extra)));
        }
        tags.sort_by_key(|t| t.0);
        // Header, directory, then the values that do not fit in an entry,
        // then the strip.
        let directory = 2 + 12 * tags.len() + 4;
        let mut values = Vec::new();
        let mut entries = Vec::new();
        let far = |v: &Vec<u8>| v.len() > 4;
        let strip = 8
            + directory
            + tags
                .iter()
                .map(|(_, (_, v))| if far(v) { v.len() } else { 0 })
                .sum::<usize>();
        for (tag, (kind, value)) in &tags {
            let value = if *tag == 273 {
                (strip as u32).to_le_bytes().to_vec()
            } else {
                value.clone()
            };
            let size = if *kind == 3 { 2 } else { 4 };
            entries.extend(tag.to_le_bytes());
            entries.extend(kind.to_le_bytes());
            entries.extend(((value.len() / size) as u32).to_le_bytes());
            if far(&value) {
                entries.extend(((8 + directory + values.len()) as u32).to_le_bytes());
                values.extend(value);
            } else {
                entries.extend(value.iter().chain([0u8; 4].iter()).take(4));
            }
        }
        let mut file = b"II\x2a\x00\x08\x00\x00\x00".to_vec();
        file.extend((tags.len() as u16).to_le_bytes());
        file.extend(entries);
        file.extend([0u8; 4]);
        file.extend(values);
        file.extend(data);
        file
    }

    fn write(&self, path: &Path) -> PathBuf {
        std::fs::write(path, self.bytes()).unwrap();
        path.to_path_buf()
    }
}

/// `source` rewritten by tiffcp in every compression (with and without
/// predictor), in strips of 7 rows and in 16 x 16 tiles (its planar
/// configuration kept), and with a predictor as big-endian BigTIFF; each
/// read as oiiotool reads it.
fn every_layout_as_oiiotool(tiffcp: &Path, source: &Path, float: bool) {
    let stem = source.file_stem().unwrap().to_str().unwrap().to_string();
    let predictor = if stem.contains("float") { "3" } else { "2" };
    let (lzw, zip) = (format!("lzw:{predictor}"), format!("zip:{predictor}"));
    for compression in ["none", "lzw", "zip", "packbits", &lzw, &zip] {
        // Big-endian BigTIFF too, with the predictors (which work on the
        // samples in the file's byte order).
        let big = &["-B", "-8", "-r", "5"][..];
        for layout in [&["-r", "7"][..], &["-t", "-w", "16", "-l", "16"], big] {
            if layout == big && !compression.contains(':') {
                continue;
            }
            let name = format!(
                "{stem}-{}{}.tif",
                compression.replace(':', "_"),
                layout.len()
            );
            let input = source.with_file_name(name);
            let made = Command::new(tiffcp)
                .args(["-c", compression])
                .args(layout)
                .arg(source)
                .arg(&input)
                .output()
                .unwrap();
            assert!(made.status.success(), "{}", stderr(&made));
            let output = input.with_extension("exr");
            transcode(&input, &output, &[]);
            assert_as_oiiotool(&input, &output, float);
        }
    }
}

#[test]
fn classes_oiiotool_reads_read_as_it_reads_them_in_every_layout() {
    let (Some(oiiotool), Some(tiffcp)) = (peer("oiiotool"), peer("tiffcp")) else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let white_is_zero = Tif::new(1, 8, 0).write(&dir.path().join("white.tif"));
    every_layout_as_oiiotool(&tiffcp, &white_is_zero, false);
    // A colour map of 16-bit entries, not multiples of 257.
    let mut palette = Tif::new(1, 8, 3);
    palette.colormap = (0..768u32).map(|i| (i * 40_503 % 65_536) as u16).collect();
    let palette = palette.write(&dir.path().join("palette.tif"));
    every_layout_as_oiiotool(&tiffcp, &palette, false);
    for (channels, planar) in [
        ("0", "contig"),
        ("0,1,2", "contig"),
        ("0,1,2,3", "separate"),
    ] {
        let uint32 = dir.path().join(format!("uint32-{}.tif", channels.len()));
        let made = Command::new(&oiiotool)
            .args(["--pattern", PATTERN, "67x45", "4", "--ch", channels])
            .args(["-d", "uint32", "--planarconfig", planar, "-o"])
            .arg(&uint32)
            .output()
            .unwrap();
        assert!(made.status.success(), "{}", stderr(&made));
        every_layout_as_oiiotool(&tiffcp, &uint32, true);
    }
    // Codes of every 32-bit range, not only oiiotool's multiples of 65537.
    let uint32 = Tif::new(3, 32, 2).write(&dir.path().join("uint32-codes.tif"));
    every_layout_as_oiiotool(&tiffcp, &uint32, true);
    let float = Tif {
        format: 3,
        ..Tif::new(3, 32, 2)
    };
    let float = float.write(&dir.path().join("float.tif"));
    every_layout_as_oiiotool(&tiffcp, &float, true);
}

#[test]
fn old_style_lzw_codes_read_as_oiiotool_reads_them() {
    let dir = tempfile::tempdir().unwrap();
    for (samples, bits, photometric) in [(3, 8, 2), (1, 16, 1), (4, 8, 2)] {
        let mut tif = Tif::new(samples, bits, photometric);
        tif.old_lzw = true;
        if samples == 4 {
            tif.extra = vec![2];
        }
        let input = tif.write(&dir.path().join(format!("old-{samples}-{bits}.tif")));
        let output = input.with_extension("exr");
        transcode(&input, &output, &[]);
        assert_as_oiiotool(&input, &output, bits > 8);
    }
}

#[test]
fn classes_outside_the_list_are_refused_in_one_line() {
    let Some(tiffcp) = peer("tiffcp") else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let path = |name: &str| dir.path().join(name);
    let mut files = vec![
        (
            Tif::new(1, 16, 0).write(&path("white-16.tif")),
            "white-is-zero",
        ),
        (
            Tif {
                extra: vec![2],
                ..Tif::new(2, 8, 0)
            }
            .write(&path("white-alpha.tif")),
            "white-is-zero",
        ),
        (
            Tif {
                format: 2,
                ..Tif::new(1, 16, 1)
            }
            .write(&path("signed.tif")),
            "16-bit samples of format 2",
        ),
        (
            Tif {
                format: 3,
                ..Tif::new(3, 64, 2)
            }
            .write(&path("double.tif")),
            "64-bit samples of format 3",
        ),
        (
            Tif::new(3, 8, 6).write(&path("ycbcr.tif")),
            "photometric interpretation 6",
        ),
        (Tif::new(5, 8, 2).write(&path("five.tif")), "5 samples"),
    ];
    let rgb = Tif::new(3, 8, 2).write(&path("rgb.tif"));
    let jpeg = path("jpeg.tif");
    let made = Command::new(&tiffcp)
        .args(["-c", "jpeg:r"])
        .arg(&rgb)
        .arg(&jpeg)
        .output()
        .unwrap();
    assert!(made.status.success(), "{}", stderr(&made));
    files.push((jpeg, "compression 7"));
    for (input, says) in files {
        let output = input.with_extension("exr");
        let out = limited(&["transcode", s(&input), "-o", s(&output)]);
        let said = stderr(&out);
        assert_eq!(out.status.code(), Some(3), "{}: {said}", input.display());
        assert!(said.contains(says) && said.contains(" not read"), "{said}");
        assert!(said.contains(s(&input)), "{said}");
        assert_eq!(said.trim_end().lines().count(), 1, "{said}");
        assert!(!output.exists());
    }
}
