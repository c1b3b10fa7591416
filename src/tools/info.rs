//! `exrcomp info`: what a file holds, in OpenEXR's words, and proof that
//! every chunk decodes. The text is exrheader's (each attribute `name (type
//! T): value`, sorted by name, values as OpenEXR's exrheader prints them),
//! each part closed by its chunk check; `--json` gives the same facts as one
//! JSON object per file.

use crate::error::{Error, Result};
use crate::io::header_text::{
    block_type, compression, environment_map, level_mode, line_order, pixel_type, rounding, time,
    user_data, value_text,
};
use crate::io::reader::ExrFile;
use crate::io::standard_attributes::attributes;
use crate::io::text::Utf8Text;
use exr::math::Vec2;
use exr::meta::attribute::{AttributeValue, BlockType};
use serde_json::{json, Value};
use std::fmt::Write;
use std::path::Path;

/// One part: its attributes sorted by name, and its chunk check.
struct Part {
    attributes: Vec<(String, AttributeValue)>,
    chunks: usize,
    checked: String,
}

/// A file: its size, format version and flags, and parts; for a file in
/// another format (DPX, Cineon), its name instead of the version.
struct Facts {
    bytes: u64,
    format: Option<&'static str>,
    version: u8,
    flags: u32,
    parts: Vec<Part>,
}

/// Reads `path`'s headers and checks every chunk; fails on the first chunk
/// missing or not decoding.
fn facts(path: &Path) -> Result<Facts> {
    let file = ExrFile::open(path, None)?;
    if let Some(format) = file.format() {
        return foreign_facts(file, format.name());
    }
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
        format: None,
        version: (word & 0xff) as u8,
        flags: word & !0xff,
        parts,
    })
}

/// A DPX or Cineon file's facts: every attribute of the one part it is read
/// as, and its rows checked.
fn foreign_facts(file: ExrFile, format: &'static str) -> Result<Facts> {
    let header = file.header(0);
    let mut attributes: Vec<(String, AttributeValue)> = (header.all_named_attributes())
        .map(|(name, value)| (String::from_utf8_lossy(name).into_owned(), value))
        .collect();
    attributes.sort_by(|a, b| a.0.as_bytes().cmp(b.0.as_bytes()));
    file.check_part(0)?;
    let rows = header.chunk_count;
    Ok(Facts {
        bytes: file.file_len(),
        format: Some(format),
        version: 0,
        flags: 0,
        parts: vec![Part {
            attributes,
            chunks: rows,
            checked: format!("all {rows} rows decode"),
        }],
    })
}

/// Describes `path` as exrheader does, each part followed by its chunk check.
pub fn describe(path: &Path) -> Result<String> {
    let facts = facts(path)?;
    let version = match facts.format {
        Some(format) => format!("file format: {format}, read as one uncompressed scanline part"),
        None => format!(
            "file format version: {}, flags 0x{:x}",
            facts.version, facts.flags
        ),
    };
    let mut text = format!(
        "\nfile {} ({} bytes):\n\n{version}\n",
        path.display(),
        facts.bytes,
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

/// `describe`'s facts as JSON: `file`, `bytes`, `format` (OpenEXR, DPX,
/// Cineon), `version`, `flags` (0 for the others) and
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
        "format": facts.format.unwrap_or("OpenEXR"),
        "version": facts.version,
        "flags": facts.flags,
        "parts": parts,
    }))
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
