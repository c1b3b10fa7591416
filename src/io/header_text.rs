//! OpenEXR's header values in exrheader's words (`exrcomp info`, burn-ins
//! and messages): each attribute's value as exrheader prints it, and the
//! names of its enumerations.

use super::text::Utf8Text;
use clap::ValueEnum;
use exr::math::{RoundingMode, Vec2};
use exr::meta::attribute::{
    AttributeValue, BlockType, EnvironmentMap, IntegerBounds, LevelMode, LineOrder, SampleType,
    TimeCode,
};
use exr::prelude::Compression;

/// What follows `name (type T)` on exrheader's line: `: value`, or `:` and
/// indented lines; nothing for types it does not know.
pub fn value_text(value: &AttributeValue) -> String {
    use AttributeValue as A;
    let v2f = |v: Vec2<f32>| format!("({} {})", g(v.0.into()), g(v.1.into()));
    let lines = |rows: &[String]| {
        rows.iter()
            .map(|r| format!("\n    {r}"))
            .collect::<String>()
    };
    let matrix = |m: &[f32], n: usize| {
        let rows: Vec<String> = m
            .chunks(n)
            .map(|row| {
                row.iter()
                    .map(|&x| g(x.into()))
                    .collect::<Vec<_>>()
                    .join(" ")
            })
            .collect();
        format!(":\n   ({})", rows.join("\n    "))
    };
    match value {
        A::ChannelList(channels) => {
            let rows: Vec<String> = channels
                .list
                .iter()
                .map(|c| {
                    format!(
                        "{}, {}, sampling {} {}{}",
                        c.name.utf8(),
                        pixel_type(c.sample_type).1,
                        c.sampling.x(),
                        c.sampling.y(),
                        if c.quantize_linearly { ", plinear" } else { "" }
                    )
                })
                .collect();
            format!(":{}", lines(&rows))
        }
        A::Chromaticities(c) => format!(
            ":\n    red   {}\n    green {}\n    blue  {}\n    white {}",
            v2f(c.red),
            v2f(c.green),
            v2f(c.blue),
            v2f(c.white)
        ),
        A::Compression(c) => format!(": {}", compression(*c).1),
        A::EnvironmentMap(map) => format!(": {}", environment_map(*map)),
        A::KeyCode(k) => format!(
            ":\n    film manufacturer code {}\n    film type code {}\n    prefix {}\n    count {}\
             \n    perf offset {}\n    perfs per frame {}\n    perfs per count {}",
            k.film_manufacturer_code,
            k.film_type,
            k.film_roll_prefix,
            k.count,
            k.perforation_offset,
            k.perforations_per_frame,
            k.perforations_per_count
        ),
        A::LineOrder(order) => format!(": {}", line_order(*order)),
        A::Matrix3x3(m) => matrix(m, 3),
        A::Matrix4x4(m) => matrix(m, 4),
        A::Preview(p) => format!(": {} by {} pixels", p.size.width(), p.size.height()),
        A::Rational((n, d)) => format!(": {n}/{d} ({})", g(f64::from(*n) / f64::from(*d))),
        A::BlockType(kind) => format!(": \"{}\"", block_type(*kind)),
        A::TextVector(texts) => {
            let rows: Vec<String> = texts.iter().map(|t| format!("\"{}\"", t.utf8())).collect();
            format!(":{}", lines(&rows))
        }
        A::TileDescription(tiles) => {
            let mut text = format!(
                ":\n    {}\n    tile size {} by {} pixels",
                level_mode(tiles.level_mode),
                tiles.tile_size.width(),
                tiles.tile_size.height()
            );
            if tiles.level_mode != LevelMode::Singular {
                text += &format!(
                    "\n    level sizes rounded {}",
                    rounding(tiles.rounding_mode)
                );
            }
            text
        }
        A::TimeCode(tc) => format!(
            ":\n    time {}\n    drop frame {}, color frame {}, field/phase {}\
             \n    bgf0 {}, bgf1 {}, bgf2 {}\n    user data 0x{:x}",
            time(tc),
            u8::from(tc.drop_frame),
            u8::from(tc.color_frame),
            u8::from(tc.field_phase),
            u8::from(tc.binary_group_flags[0]),
            u8::from(tc.binary_group_flags[1]),
            u8::from(tc.binary_group_flags[2]),
            user_data(tc)
        ),
        A::Text(text) => format!(": \"{}\"", text.utf8()),
        A::F64(x) => format!(": {}", g(*x)),
        A::F32(x) => format!(": {}", g((*x).into())),
        A::I32(x) => format!(": {x}"),
        A::IntegerBounds(b) => format!(": {}", box_text(*b)),
        A::FloatRect(r) => format!(": {} - {}", v2f(r.min), v2f(r.max)),
        A::IntVec2(v) => format!(": ({} {})", v.x(), v.y()),
        A::FloatVec2(v) => format!(": {}", v2f(*v)),
        A::IntVec3((x, y, z)) => format!(": ({x} {y} {z})"),
        A::FloatVec3((x, y, z)) => format!(
            ": ({} {} {})",
            g((*x).into()),
            g((*y).into()),
            g((*z).into())
        ),
        A::Bytes { .. } | A::Custom { .. } => String::new(),
    }
}

/// `b` as exrheader prints a box: `(x0 y0) - (x1 y1)`, its last pixels.
pub fn box_text(b: IntegerBounds) -> String {
    let end = b.max();
    format!(
        "({} {}) - ({} {})",
        b.position.x(),
        b.position.y(),
        end.x(),
        end.y()
    )
}

/// A pixel type's short name and exrheader's words.
pub fn pixel_type(sample: SampleType) -> (&'static str, &'static str) {
    match sample {
        SampleType::U32 => ("uint", "32-bit unsigned integer"),
        SampleType::F16 => ("half", "16-bit floating-point"),
        SampleType::F32 => ("float", "32-bit floating-point"),
    }
}

/// A compression's name (as `--compression` spells it) and exrheader's words.
pub fn compression(c: Compression) -> (String, &'static str) {
    match (CompressionName::of(c), c) {
        (Some(name), _) => (name.name(), name.words()),
        // Read, never written.
        (None, Compression::HTJ2K32) => ("htj2k32".into(), "htj2k, 32-scanline blocks"),
        (None, _) => ("htj2k256".into(), "htj2k, 256-scanline blocks"),
    }
}

/// The compressions exrcomp writes, by the names `--compression`, the job
/// file's `compression` (any case) and `info` give them: the one list of
/// them, each variant's name its clap name.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum CompressionName {
    #[value(name = "none")]
    Uncompressed,
    Rle,
    Zips,
    Zip,
    Piz,
    Pxr24,
    B44,
    B44a,
    Dwaa,
    Dwab,
}

impl CompressionName {
    /// The names, as help and errors list them.
    pub fn names() -> String {
        let names: Vec<String> = Self::value_variants()
            .iter()
            .filter_map(|c| c.to_possible_value())
            .map(|v| v.get_name().to_string())
            .collect();
        names.join(", ")
    }

    pub fn parse(text: &str) -> Result<Self, String> {
        Self::from_str(text, true).map_err(|_| {
            let name = text.to_ascii_lowercase();
            format!("unknown compression '{name}' ({})", Self::names())
        })
    }

    /// The compression, DWA at `dwa_level`.
    pub fn compression(self, dwa_level: f32) -> Compression {
        match self {
            Self::Uncompressed => Compression::Uncompressed,
            Self::Rle => Compression::RLE,
            Self::Zips => Compression::ZIP1,
            Self::Zip => Compression::ZIP16,
            Self::Piz => Compression::PIZ,
            Self::Pxr24 => Compression::PXR24,
            Self::B44 => Compression::B44,
            Self::B44a => Compression::B44A,
            Self::Dwaa => Compression::DWAA(Some(dwa_level)),
            Self::Dwab => Compression::DWAB(Some(dwa_level)),
        }
    }

    /// The one `c` is, if exrcomp writes it.
    pub fn of(c: Compression) -> Option<Self> {
        let kind = std::mem::discriminant(&c);
        let same = |name: &&Self| std::mem::discriminant(&name.compression(0.0)) == kind;
        Self::value_variants().iter().find(same).copied()
    }

    /// Its name.
    pub fn name(self) -> String {
        let value = self
            .to_possible_value()
            .expect("every compression is named");
        value.get_name().to_string()
    }

    /// exrheader's words for it.
    fn words(self) -> &'static str {
        match self {
            Self::Uncompressed => "none",
            Self::Rle => "run-length encoding",
            Self::Zips => "zip, individual scanlines",
            Self::Zip => "zip, multi-scanline blocks",
            Self::Piz => "piz",
            Self::Pxr24 => "pxr24",
            Self::B44 => "b44",
            Self::B44a => "b44a",
            Self::Dwaa => "dwa, small scanline blocks",
            Self::Dwab => "dwa, medium scanline blocks",
        }
    }
}

pub fn environment_map(map: EnvironmentMap) -> &'static str {
    match map {
        EnvironmentMap::LatitudeLongitude => "latitude-longitude map",
        EnvironmentMap::Cube => "cube-face map",
    }
}

pub fn line_order(order: LineOrder) -> &'static str {
    match order {
        LineOrder::Increasing => "increasing y",
        LineOrder::Decreasing => "decreasing y",
        LineOrder::Unspecified => "random y",
    }
}

pub fn block_type(kind: BlockType) -> &'static str {
    match kind {
        BlockType::ScanLine => "scanlineimage",
        BlockType::Tile => "tiledimage",
        BlockType::DeepScanLine => "deepscanline",
        BlockType::DeepTile => "deeptile",
    }
}

pub fn level_mode(mode: LevelMode) -> &'static str {
    match mode {
        LevelMode::Singular => "single level",
        LevelMode::MipMap => "mip-map",
        LevelMode::RipMap => "rip-map",
    }
}

pub fn rounding(mode: RoundingMode) -> &'static str {
    match mode {
        RoundingMode::Down => "down",
        RoundingMode::Up => "up",
    }
}

pub fn time(tc: &TimeCode) -> String {
    format!(
        "{:02}:{:02}:{:02}:{:02}",
        tc.hours, tc.minutes, tc.seconds, tc.frame
    )
}

/// The eight 4-bit binary groups as OpenEXR's one user-data word.
pub fn user_data(tc: &TimeCode) -> u32 {
    tc.binary_groups
        .iter()
        .enumerate()
        .fold(0, |word, (i, &group)| {
            word | u32::from(group & 15) << (4 * i)
        })
}

/// A number as C++ streams print it (`%g`: six significant digits, trailing
/// zeros dropped, an exponent outside 1e-4..1e6), as exrheader shows values.
fn g(x: f64) -> String {
    if !x.is_finite() {
        return if x.is_nan() {
            "nan"
        } else if x > 0.0 {
            "inf"
        } else {
            "-inf"
        }
        .into();
    }
    if x == 0.0 {
        return if x.is_sign_negative() { "-0" } else { "0" }.into();
    }
    let scientific = format!("{x:.5e}");
    let (mantissa, exponent) = scientific.split_once('e').expect("an exponent");
    let exponent: i32 = exponent.parse().expect("a number");
    let trim = |digits: &str| -> String {
        match digits.contains('.') {
            true => digits.trim_end_matches('0').trim_end_matches('.').into(),
            false => digits.into(),
        }
    };
    if (-4..6).contains(&exponent) {
        trim(&format!("{x:.*}", (5 - exponent) as usize))
    } else {
        let sign = if exponent < 0 { '-' } else { '+' };
        format!("{}e{sign}{:02}", trim(mantissa), exponent.abs())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn compression_names_are_listed_once_and_read_in_any_case() {
        assert_eq!(
            CompressionName::names(),
            "none, rle, zips, zip, piz, pxr24, b44, b44a, dwaa, dwab"
        );
        assert_eq!(CompressionName::parse("ZIPS"), Ok(CompressionName::Zips));
        assert_eq!(
            CompressionName::parse("none").map(|c| c.compression(45.0)),
            Ok(Compression::Uncompressed)
        );
        // exrheader's words and the names, from the one list.
        assert_eq!(
            compression(Compression::DWAB(None)),
            ("dwab".to_string(), "dwa, medium scanline blocks")
        );
        assert_eq!(CompressionName::of(Compression::HTJ2K32), None);
        let refused = CompressionName::parse("LZW").unwrap_err();
        assert!(
            refused.starts_with("unknown compression 'lzw' (none, rle,"),
            "{refused}"
        );
    }

    #[test]
    fn numbers_print_as_cpp_streams_print_them() {
        for (x, text) in [
            (1.0, "1"),
            (1.5, "1.5"),
            (0.01, "0.01"),
            (2.8, "2.8"),
            (0.3127, "0.3127"),
            (1.0 / 3.0, "0.333333"),
            (24.0, "24"),
            (123456.0, "123456"),
            (1234567.0, "1.23457e+06"),
            (0.0001, "0.0001"),
            (0.00001, "1e-05"),
            (-2.5e-7, "-2.5e-07"),
            (999999.7, "1e+06"),
            (0.0, "0"),
        ] {
            assert_eq!(g(x), text, "{x}");
        }
        assert_eq!(g(f64::from(0.3f32)), "0.3");
        assert_eq!(g(f64::from(0.64f32)), "0.64");
    }
}
