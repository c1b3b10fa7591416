//! `stitch`: band files (`--rows`) joined into one file by copying their
//! compressed chunks under a new offset table, decoding nothing.
//!
//! A band records what it is a band of (`mark_band`): the whole output's
//! data window and its frame. Stitch joins only a set of bands of one frame
//! that covers that window exactly, and the joined file carries no record,
//! so it is the whole render byte for byte.

use super::attributes::FINGERPRINT;
use super::reader::ExrFile;
use super::writer::IndexedChunk;
use super::writer::{write_file, Parts};
use crate::error::Result;
use exr::meta::attribute::{AttributeValue, IntegerBounds, Text};
use exr::meta::header::Header;
use std::path::{Path, PathBuf};

/// The whole output's data window a band is part of (box2i).
const BAND_OF: &str = "exrcomp:bandOf";
/// The frame a band is part of (a string: frame numbers are 64-bit).
const BAND_FRAME: &str = "exrcomp:bandFrame";

/// Records in a band's `header` that it is a band of `frame`'s output whose
/// data window is `whole`.
pub fn mark_band(header: &mut Header, whole: IntegerBounds, frame: i64) {
    let other = &mut header.own_attributes.other;
    other.insert(Text::from(BAND_OF), AttributeValue::IntegerBounds(whole));
    let frame = Text::from_slice_unchecked(frame.to_string().as_bytes());
    other.insert(Text::from(BAND_FRAME), AttributeValue::Text(frame));
}

/// Drops a band's record from `header`: a header copied from a band
/// describes another image unless `mark_band` says so again.
pub fn erase_band_record(header: &mut Header) {
    for name in [BAND_OF, BAND_FRAME] {
        header.own_attributes.other.remove(&Text::from(name));
    }
}

/// Whether a file's header `found` holds the rows `planned` (the header a
/// run writes) does: the same data window, and the same band record or
/// none. `--resume` keeps only such a file (a band's fingerprint is the
/// whole frame's).
pub fn same_rows(found: &Header, planned: &Header) -> bool {
    found.data_window() == planned.data_window() && band_record(found) == band_record(planned)
}

/// What a band's header says it is a band of: the whole window and frame.
fn band_record(header: &Header) -> Option<(IntegerBounds, Vec<u8>)> {
    let other = &header.own_attributes.other;
    match (
        other.get(&Text::from(BAND_OF)),
        other.get(&Text::from(BAND_FRAME)),
    ) {
        (Some(AttributeValue::IntegerBounds(whole)), Some(AttributeValue::Text(frame))) => {
            Some((*whole, frame.bytes().to_vec()))
        }
        _ => None,
    }
}

/// Why `header` is not a band of the same image as `first`, if it is not:
/// every attribute but the data window must be the same (the band record
/// included: the same whole window and frame), the job's fingerprint too.
fn differs(first: &Header, header: &Header) -> Option<&'static str> {
    // The rows differ, the rest does not.
    let mut own = header.own_attributes.clone();
    own.layer_position.1 = first.own_attributes.layer_position.y();
    if band_record(header) != band_record(first) {
        return Some("is a band of another frame or image than the first band (its exrcomp:bandOf or exrcomp:bandFrame differ)");
    }
    // Of the same frame and window, but of another job (whose fingerprint
    // also holds the frame: the frame is the one to name first).
    let print = |h: &Header| {
        h.own_attributes
            .other
            .get(&Text::from(FINGERPRINT))
            .cloned()
    };
    if print(header) != print(first) {
        return Some(
            "was made by another job than the first band (its exrcomp:fingerprint differs)",
        );
    }
    let same = header.channels == first.channels
        && header.compression == first.compression
        && header.shared_attributes == first.shared_attributes
        && own == first.own_attributes
        && header.deep == first.deep
        && header.layer_size.width() == first.layer_size.width();
    (!same).then_some(
        "is not a band of the same image (channels, compression, columns or attributes differ)",
    )
}

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
    if let Some(file) = files.iter().find(|f| f.meta.headers.len() != 1) {
        return Err(
            file.error("has several parts: stitch joins bands of one part (as --rows writes them)")
        );
    }
    let Some((whole, _)) = band_record(files[0].header(0)) else {
        return Err(files[0].error(format!(
            "is not a band (no {BAND_OF} or {BAND_FRAME} record): stitch joins the bands --rows writes"
        )));
    };
    let window = joined(&files, whole)?;
    let mut header = files[0].header(0).clone();
    erase_band_record(&mut header);
    let lines = header.compression.scan_lines_per_block();
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

/// The window `files` (bands sorted by first row) cover together, checked
/// to be `whole`, the window they record: each band of the same image,
/// starting where the one before it ended, on a block boundary, from the
/// whole window's first row to its last.
fn joined(files: &[ExrFile], whole: IntegerBounds) -> Result<IntegerBounds> {
    let first = files[0].header(0);
    let lines = first.compression.scan_lines_per_block();
    let mut window = first.data_window();
    if window.position.y() != whole.position.y() {
        return Err(files[0].error(format!(
            "is the first band but starts at row {}, where the image it is a band of starts at \
             row {}: a band is missing before it",
            window.position.y(),
            whole.position.y()
        )));
    }
    if window.position.x() != whole.position.x() || window.size.width() != whole.size.width() {
        return Err(files[0].error("does not span the columns of the image it is a band of"));
    }
    for file in &files[1..] {
        let header = file.header(0);
        let band = header.data_window();
        if let Some(message) = differs(first, header) {
            return Err(file.error(message));
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
    if window.end().y() != whole.end().y() {
        let last = &files[files.len() - 1];
        return Err(last.error(format!(
            "is the last band but ends at row {}, where the image it is a band of ends at row {}: \
             a band is missing after it",
            window.end().y(),
            whole.end().y()
        )));
    }
    Ok(window)
}
