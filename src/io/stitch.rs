//! `stitch`: band files (`--rows`) joined into one file by copying their
//! compressed chunks under a new offset table, decoding nothing.

use super::reader::ExrFile;
use super::writer::IndexedChunk;
use super::writer::{write_file, Parts};
use crate::error::Result;
use exr::meta::attribute::IntegerBounds;
use std::path::{Path, PathBuf};

pub fn stitch(bands: &[PathBuf], output: &Path) -> Result<()> {
    let mut files: Vec<ExrFile> = bands
        .iter()
        .map(|p| ExrFile::open(p, None))
        .collect::<Result<_>>()?;
    files.sort_by_key(|f| f.header(0).data_window().position.y());
    // Bands are scanline files (`--rows` writes no tiles): tiles of a band
    // would need renumbering, and a partial tile row cannot be joined.
    if let Some(tiled) = files.iter().find(|f| f.header(0).blocks.has_tiles()) {
        return Err(tiled.error("is tiled: stitch joins scanline bands (as --rows writes them)"));
    }
    let first = files[0].header(0).clone();
    let lines = first.compression.scan_lines_per_block();
    let mut window = first.data_window();
    for file in &files[1..] {
        let header = file.header(0);
        let band = header.data_window();
        let same = header.channels == first.channels
            && header.compression == first.compression
            && header.shared_attributes == first.shared_attributes
            && header.deep == first.deep
            && band.position.x() == window.position.x()
            && band.size.width() == window.size.width();
        if file.meta.headers.len() != 1 || !same {
            return Err(file.error("is not a band of the same image (channels, compression, columns or attributes differ)"));
        }
        if band.position.y() != window.end().y() {
            return Err(file.error(format!(
                "starts at row {} but the bands before it end at row {}",
                band.position.y(),
                window.end().y()
            )));
        }
        if !window.size.height().is_multiple_of(lines) {
            return Err(file.error("follows a band that does not end on a block boundary"));
        }
        window = IntegerBounds::new(
            window.position,
            (
                window.size.width(),
                window.size.height() + band.size.height(),
            ),
        );
    }
    let mut header = first;
    header.own_attributes.layer_position = window.position;
    header.layer_size = window.size;
    header.chunk_count = window.size.height().div_ceil(lines);
    let mut next_file = files.iter();
    let mut index = 0;
    write_file(output, None, Parts::single(header), || {
        let Some(file) = next_file.next() else {
            return Ok(None);
        };
        let chunks = (0..file.header(0).chunk_count)
            .map(|k| {
                let chunk = file.read_chunk(0, k)?;
                index += 1;
                Ok(IndexedChunk {
                    index: index - 1,
                    chunk,
                })
            })
            .collect::<Result<Vec<_>>>()?;
        Ok(Some(chunks))
    })
}
