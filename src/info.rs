//! `exrcomp info`: what a file holds, and proof that every chunk decodes.

use crate::error::Result;
use crate::io::reader::ExrFile;
use exr::meta::attribute::IntegerBounds;
use exr::meta::header::Header;
use exr::meta::BlockDescription;
use std::fmt::Write;
use std::path::Path;

/// Describes `path`; fails if any chunk is missing or does not decode.
pub fn describe(path: &Path) -> Result<String> {
    let file = ExrFile::open(path, None)?;
    let mut text = String::new();
    let parts = file.meta.headers.len();
    let _ = writeln!(
        text,
        "{}: {} part(s), {} bytes",
        path.display(),
        parts,
        file.file_len()
    );
    for (index, header) in file.meta.headers.iter().enumerate() {
        describe_part(&mut text, index, header);
        let checked = check_chunks(&file, index)?;
        let _ = writeln!(text, "    pixels: {checked}");
    }
    Ok(text)
}

fn describe_part(text: &mut String, index: usize, header: &Header) {
    let name = header
        .own_attributes
        .layer_name
        .as_ref()
        .map(|n| format!(" \"{n}\""))
        .unwrap_or_default();
    let kind = match (header.deep, header.blocks) {
        (false, BlockDescription::ScanLines) => "scanline".to_string(),
        (true, BlockDescription::ScanLines) => "deep scanline".to_string(),
        (deep, BlockDescription::Tiles(t)) => format!(
            "{}tiled {}x{} {:?}",
            if deep { "deep " } else { "" },
            t.tile_size.x(),
            t.tile_size.y(),
            t.level_mode
        ),
    };
    let _ = writeln!(
        text,
        "  part {index}{name}: {kind}, compression {} ({} lines per block), line order {:?}, {} chunks",
        header.compression,
        header.compression.scan_lines_per_block(),
        header.line_order,
        header.chunk_count
    );
    let _ = writeln!(text, "    data window:    {}", window(header.data_window()));
    let _ = writeln!(
        text,
        "    display window: {}",
        window(header.shared_attributes.display_window)
    );
    let channels: Vec<String> = header
        .channels
        .list
        .iter()
        .map(|c| {
            let sampling = if c.sampling.x() == 1 && c.sampling.y() == 1 {
                String::new()
            } else {
                format!(" sampled {}x{}", c.sampling.x(), c.sampling.y())
            };
            format!("{} {:?}{}", c.name, c.sample_type, sampling)
        })
        .collect();
    let _ = writeln!(
        text,
        "    channels ({}): {}",
        channels.len(),
        channels.join(", ")
    );
    let _ = writeln!(text, "    attributes:");
    let mut attributes: Vec<String> = header
        .all_named_attributes()
        .map(|(name, value)| format!("      {}: {value:?}", String::from_utf8_lossy(name)))
        .collect();
    attributes.sort();
    for line in attributes {
        let _ = writeln!(text, "{line}");
    }
}

fn window(w: IntegerBounds) -> String {
    format!(
        "({}, {}) - ({}, {}), {} x {}",
        w.position.x(),
        w.position.y(),
        w.end().x() - 1,
        w.end().y() - 1,
        w.size.width(),
        w.size.height()
    )
}

fn check_chunks(file: &ExrFile, part: usize) -> Result<String> {
    file.check_part(part)?;
    let count = file.header(part).chunk_count;
    Ok(if file.header(part).deep {
        format!("all {count} chunks present, their sample counts consistent")
    } else {
        format!("all {count} chunks decode")
    })
}
