//! `exrcomp info`: what a file holds, in OpenEXR's words, and proof that
//! every chunk decodes. The text is exrheader's (each attribute `name (type
//! T): value`, sorted by name, values as OpenEXR's exrheader prints them),
//! each part closed by its chunk check; `--json` gives the same facts as one
//! JSON object per file.

use crate::engine::graph::box_text;
use crate::error::{Error, Result};
use crate::io::reader::ExrFile;
use crate::io::standard_attributes::attributes;
use crate::io::text::Utf8Text;
use exr::math::{RoundingMode, Vec2};
use exr::meta::attribute::{
    AttributeValue, BlockType, EnvironmentMap, LevelMode, LineOrder, SampleType, TimeCode,
};
use exr::prelude::Compression;
use serde_json::{json, Value};
use std::fmt::Write;
use std::path::Path;

/// One part: its attributes sorted by name, and its chunk check.
struct Part {
    attributes: Vec<(String, AttributeValue)>,
    chunks: usize,
    checked: String,
}

/// A file: its size, format version and flags, and parts.
struct Facts {
    bytes: u64,
    version: u8,
    flags: u32,
    parts: Vec<Part>,
}

/// Reads `path`'s headers and checks every chunk; fails on the first chunk
/// missing or not decoding.
fn facts(path: &Path) -> Result<Facts> {
    let file = ExrFile::open(path, None)?;
    // The version field as the file holds it, as exrheader prints it: the
    // crate's requirements say what it would write, which for a multi-part
    // file with a deep part lacks the non-image bit.
    let mut field = [0u8; 8];
    std::fs::File::open(path)
        .and_then(|mut f| std::io::Read::read_exact(&mut f, &mut field))
        .map_err(|e| file.error(format!("cannot read its version field: {e}")))?;
    let word = u32::from_le_bytes(field[4..8].try_into().expect("4 bytes"));
    // The crate's header also has what it computes: its `chunkCount` is
    // shown only where the file declares one, its `type` always (as OpenEXR,
    // which gives every part a type, and exrheader show it).
    let held = crate::io::reader::open_regular(path)
        .map(|f| attributes(&mut std::io::BufReader::new(f)))
        .map_err(|e| file.error(format!("cannot open: {e}")))?;
    let mut parts = Vec::new();
    for (index, header) in file.meta.headers.iter().enumerate() {
        let mut attributes: Vec<(String, AttributeValue)> = header
            .all_named_attributes()
            .map(|(name, value)| (String::from_utf8_lossy(name).into_owned(), value))
            // The crate's computed type of a deep part is the flat one's.
            .map(|(name, value)| match value {
                AttributeValue::BlockType(BlockType::ScanLine) if header.deep => {
                    (name, AttributeValue::BlockType(BlockType::DeepScanLine))
                }
                AttributeValue::BlockType(BlockType::Tile) if header.deep => {
                    (name, AttributeValue::BlockType(BlockType::DeepTile))
                }
                value => (name, value),
            })
            .filter(|(name, _)| {
                name == "type" || held.iter().any(|a| a.part == index && a.name == *name)
            })
            .collect();
        attributes.sort_by(|a, b| a.0.as_bytes().cmp(b.0.as_bytes()));
        file.check_part(index)?;
        let chunks = header.chunk_count;
        let checked = if header.deep {
            format!("all {chunks} chunks present, their sample counts consistent")
        } else {
            format!("all {chunks} chunks decode")
        };
        parts.push(Part {
            attributes,
            chunks,
            checked,
        });
    }
    Ok(Facts {
        bytes: file.file_len(),
        version: (word & 0xff) as u8,
        flags: word & !0xff,
        parts,
    })
}

/// Describes `path` as exrheader does, each part followed by its chunk check.
pub fn describe(path: &Path) -> Result<String> {
    let facts = facts(path)?;
    let mut text = format!(
        "\nfile {} ({} bytes):\n\nfile format version: {}, flags 0x{:x}\n",
        path.display(),
        facts.bytes,
        facts.version,
        facts.flags
    );
    let several = facts.parts.len() > 1;
    for (index, part) in facts.parts.iter().enumerate() {
        if several {
            let _ = write!(text, "\n\n part {index}:\n");
        }
        for (name, value) in &part.attributes {
            let kind = String::from_utf8_lossy(value.kind_name());
            let _ = writeln!(text, "{name} (type {kind}){}", value_text(value));
        }
        let _ = writeln!(text, "pixels: {}", part.checked);
    }
    text.push('\n');
    Ok(text)
}

/// `describe`'s facts as JSON: `file`, `bytes`, `version`, `flags` and
/// `parts`, each part's `attributes` by name as `{"type", "value"}`, its
/// `chunks` and `checked`.
pub fn describe_json(path: &Path) -> Result<Value> {
    let facts = facts(path)?;
    let parts: Vec<Value> = facts
        .parts
        .iter()
        .map(|part| {
            let attributes: serde_json::Map<String, Value> = part
                .attributes
                .iter()
                .map(|(name, value)| {
                    let kind = String::from_utf8_lossy(value.kind_name());
                    (
                        name.clone(),
                        json!({"type": kind, "value": value_json(value)}),
                    )
                })
                .collect();
            json!({"attributes": attributes, "chunks": part.chunks, "checked": part.checked})
        })
        .collect();
    Ok(json!({
        "file": path.display().to_string(),
        "bytes": facts.bytes,
        "version": facts.version,
        "flags": facts.flags,
        "parts": parts,
    }))
}

/// What follows `name (type T)` on exrheader's line: `: value`, or `:` and
/// indented lines; nothing for types it does not know.
pub(crate) fn value_text(value: &AttributeValue) -> String {
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

/// The same facts as `value_text`, as JSON values (numbers as numbers,
/// vectors as arrays); for unknown types, the size of their bytes.
fn value_json(value: &AttributeValue) -> Value {
    use AttributeValue as A;
    let v2f = |v: Vec2<f32>| json!([v.0, v.1]);
    match value {
        A::ChannelList(channels) => channels
            .list
            .iter()
            .map(|c| {
                json!({
                    "name": c.name.utf8(),
                    "type": pixel_type(c.sample_type).0,
                    "sampling": [c.sampling.x(), c.sampling.y()],
                    "plinear": c.quantize_linearly,
                })
            })
            .collect(),
        A::Chromaticities(c) => json!({
            "red": v2f(c.red), "green": v2f(c.green), "blue": v2f(c.blue), "white": v2f(c.white)
        }),
        A::Compression(c) => json!(compression(*c).0),
        A::EnvironmentMap(map) => json!(environment_map(*map)),
        A::KeyCode(k) => json!({
            "film_manufacturer_code": k.film_manufacturer_code,
            "film_type": k.film_type,
            "prefix": k.film_roll_prefix,
            "count": k.count,
            "perf_offset": k.perforation_offset,
            "perfs_per_frame": k.perforations_per_frame,
            "perfs_per_count": k.perforations_per_count,
        }),
        A::LineOrder(order) => json!(line_order(*order)),
        A::Matrix3x3(m) => json!(m.to_vec()),
        A::Matrix4x4(m) => json!(m.to_vec()),
        A::Preview(p) => json!({"width": p.size.width(), "height": p.size.height()}),
        A::Rational((n, d)) => json!([n, d]),
        A::BlockType(kind) => json!(block_type(*kind)),
        A::TextVector(texts) => texts.iter().map(|t| json!(t.utf8())).collect(),
        A::TileDescription(tiles) => json!({
            "size": [tiles.tile_size.width(), tiles.tile_size.height()],
            "levels": level_mode(tiles.level_mode),
            "rounding": rounding(tiles.rounding_mode),
        }),
        A::TimeCode(tc) => json!({
            "time": time(tc),
            "drop_frame": tc.drop_frame,
            "color_frame": tc.color_frame,
            "field_phase": tc.field_phase,
            "binary_group_flags": tc.binary_group_flags,
            "user_data": user_data(tc),
        }),
        A::Text(text) => json!(text.utf8()),
        A::F64(x) => json!(x),
        A::F32(x) => json!(x),
        A::I32(x) => json!(x),
        A::IntegerBounds(b) => {
            let end = b.end();
            json!({"min": [b.position.x(), b.position.y()], "max": [end.x() - 1, end.y() - 1]})
        }
        A::FloatRect(r) => json!({"min": v2f(r.min), "max": v2f(r.max)}),
        A::IntVec2(v) => json!([v.x(), v.y()]),
        A::FloatVec2(v) => v2f(*v),
        A::IntVec3((x, y, z)) => json!([x, y, z]),
        A::FloatVec3((x, y, z)) => json!([x, y, z]),
        A::Bytes { bytes, .. } | A::Custom { bytes, .. } => json!({"bytes": bytes.len()}),
    }
}

/// A pixel type's short name and exrheader's words.
fn pixel_type(sample: SampleType) -> (&'static str, &'static str) {
    match sample {
        SampleType::U32 => ("uint", "32-bit unsigned integer"),
        SampleType::F16 => ("half", "16-bit floating-point"),
        SampleType::F32 => ("float", "32-bit floating-point"),
    }
}

/// A compression's name (as `--compression` spells it) and exrheader's words.
fn compression(c: Compression) -> (&'static str, &'static str) {
    match c {
        Compression::Uncompressed => ("none", "none"),
        Compression::RLE => ("rle", "run-length encoding"),
        Compression::ZIP1 => ("zips", "zip, individual scanlines"),
        Compression::ZIP16 => ("zip", "zip, multi-scanline blocks"),
        Compression::PIZ => ("piz", "piz"),
        Compression::PXR24 => ("pxr24", "pxr24"),
        Compression::B44 => ("b44", "b44"),
        Compression::B44A => ("b44a", "b44a"),
        Compression::DWAA(_) => ("dwaa", "dwa, small scanline blocks"),
        Compression::DWAB(_) => ("dwab", "dwa, medium scanline blocks"),
        Compression::HTJ2K32 => ("htj2k32", "htj2k, 32-scanline blocks"),
        Compression::HTJ2K256 => ("htj2k256", "htj2k, 256-scanline blocks"),
    }
}

fn environment_map(map: EnvironmentMap) -> &'static str {
    match map {
        EnvironmentMap::LatitudeLongitude => "latitude-longitude map",
        EnvironmentMap::Cube => "cube-face map",
    }
}

fn line_order(order: LineOrder) -> &'static str {
    match order {
        LineOrder::Increasing => "increasing y",
        LineOrder::Decreasing => "decreasing y",
        LineOrder::Unspecified => "random y",
    }
}

fn block_type(kind: BlockType) -> &'static str {
    match kind {
        BlockType::ScanLine => "scanlineimage",
        BlockType::Tile => "tiledimage",
        BlockType::DeepScanLine => "deepscanline",
        BlockType::DeepTile => "deeptile",
    }
}

fn level_mode(mode: LevelMode) -> &'static str {
    match mode {
        LevelMode::Singular => "single level",
        LevelMode::MipMap => "mip-map",
        LevelMode::RipMap => "rip-map",
    }
}

fn rounding(mode: RoundingMode) -> &'static str {
    match mode {
        RoundingMode::Down => "down",
        RoundingMode::Up => "up",
    }
}

fn time(tc: &TimeCode) -> String {
    format!(
        "{:02}:{:02}:{:02}:{:02}",
        tc.hours, tc.minutes, tc.seconds, tc.frame
    )
}

/// The eight 4-bit binary groups as OpenEXR's one user-data word.
fn user_data(tc: &TimeCode) -> u32 {
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

/// Prints what `files` hold, as text or JSON; a file that cannot be read
/// is named and the others are still printed.
pub fn print(files: &[std::path::PathBuf], json: bool) -> Result<()> {
    let describe = |path: &std::path::Path| match json {
        true => describe_json(path).map(|v| format!("{v}\n")),
        false => describe(path),
    };
    if let [file] = files {
        print!("{}", describe(file)?);
        return Ok(());
    }
    let mut failed: Vec<Error> = Vec::new();
    for path in files {
        match describe(path) {
            Ok(text) => print!("{text}"),
            Err(e) => {
                eprintln!("exrcomp: error: {e}");
                failed.push(e);
            }
        }
    }
    match failed.first() {
        None => Ok(()),
        Some(first) => Err(Error::new(
            first.kind,
            format!(
                "{} of {} files could not be read",
                failed.len(),
                files.len()
            ),
        )),
    }
}

#[cfg(test)]
mod tests {
    use super::g;

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
