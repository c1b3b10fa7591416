//! The demo's contact sheet: EXR frames shrunk into labelled panels on one
//! PNG, a column per image and a row per frame, so a user sees what each
//! effect did without an EXR viewer. Each frame is read strip by strip
//! through the engine's decoder and box-filtered into its panel as it goes:
//! memory holds the panels, never a frame.

use crate::draw::font;
use crate::engine::decode::{decode_all, InputCursor};
use crate::error::{Error, Result};
use crate::io::media::{png_file, Rgb8};
use crate::io::parts::choose_part;
use crate::io::reader::ExrFile;
use crate::io::tiles;
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// The sheet's background: bluer than any panel's pixel can be (the demo's
/// images are grey, or warmer than grey), so panels are told from it.
pub const BACKGROUND: [u8; 3] = [24, 24, 32];
const TEXT: [u8; 3] = [230, 230, 230];
/// Space around and between panels, and the labels' scale, in pixels.
const MARGIN: usize = 8;
const TEXT_SCALE: usize = 2;
/// Rows decoded at a time.
const STRIP_ROWS: usize = 64;

/// Panels `width` pixels wide, tall as the images' display windows are
/// (the first image's), titled by `columns`; each row a label and one
/// file per column.
pub fn write(
    path: &Path,
    width: usize,
    columns: &[&str],
    rows: &[(String, Vec<PathBuf>)],
) -> Result<()> {
    let first = rows
        .first()
        .and_then(|(_, files)| files.first())
        .ok_or_else(|| Error::internal("a contact sheet of no images"))?;
    let display = display_window(first)?;
    let height = (width * display.1 / display.0.max(1)).max(1);
    let line = font::HEIGHT * TEXT_SCALE;
    let label_width = rows
        .iter()
        .map(|(label, _)| font::text_width(label) * TEXT_SCALE)
        .max()
        .unwrap_or(0);
    let left = MARGIN + label_width + MARGIN;
    let top = MARGIN + line + MARGIN;
    let mut sheet = Rgb8 {
        width: left + columns.len() * (width + MARGIN),
        height: top + rows.len() * (height + MARGIN),
        pixels: Vec::new(),
    };
    sheet.pixels = vec![BACKGROUND; sheet.width * sheet.height];
    for (c, title) in columns.iter().enumerate() {
        let x = left + c * (width + MARGIN);
        draw_text(&mut sheet, title, (x, MARGIN), width);
    }
    for (r, (label, files)) in rows.iter().enumerate() {
        let y = top + r * (height + MARGIN);
        draw_text(
            &mut sheet,
            label,
            (MARGIN, y + (height - line.min(height)) / 2),
            label_width,
        );
        for (c, file) in files.iter().enumerate() {
            let panel = shrink(file, (width, height))?;
            let x = left + c * (width + MARGIN);
            for (j, row) in panel.chunks(width).enumerate() {
                let at = (y + j) * sheet.width + x;
                sheet.pixels[at..at + width].copy_from_slice(row);
            }
        }
    }
    crate::io::writer::write_whole(path, &png_file(&sheet))
}

fn display_window(file: &Path) -> Result<(usize, usize)> {
    let exr = ExrFile::open(file, None)?;
    let part = choose_part(&exr, None, None)?;
    let size = exr.header(part).shared_attributes.display_window.size;
    Ok((size.width(), size.height()))
}

/// `file`'s display window shrunk to `size` by averaging the pixels that
/// fall in each panel pixel (outside the data window: black), then turned
/// to sRGB.
fn shrink(file: &Path, (width, height): (usize, usize)) -> Result<Vec<[u8; 3]>> {
    let exr = Arc::new(ExrFile::open(file, None)?);
    let part = choose_part(&exr, None, None)?;
    let header = exr.header(part);
    let display = header.shared_attributes.display_window;
    let level = tiles::levels(header)[0];
    let window = level.window(header);
    let mut sums = vec![[0.0f64; 3]; width * height];
    let (dw, dh) = (display.size.width().max(1), display.size.height().max(1));
    // Panel pixel of display column or row `at` (a display offset).
    let bin = |at: i64, from: usize, to: usize| (at * to as i64 / from as i64) as usize;
    let mut cursor = [InputCursor::new(exr.clone(), part, level, window)];
    let (x0, y0) = (window.position.x(), window.position.y());
    let mut values = vec![0.0f32; window.size.width()];
    for top in (y0..window.end().y()).step_by(STRIP_ROWS) {
        let end = (top + STRIP_ROWS as i32).min(window.end().y());
        let rows = decode_all(&mut cursor, (x0, window.size.width()), top..end)?.remove(0);
        for y in top..end {
            let dy = (y - display.position.y()) as i64;
            if dy < 0 || dy >= dh as i64 {
                continue;
            }
            let j = bin(dy, dh, height);
            for (k, name) in ["R", "G", "B"].iter().enumerate() {
                let Some(c) = rows.channel_index(name) else {
                    continue;
                };
                rows.planes[c].read_f32(rows.row_range(y), &mut values);
                for (i, &v) in values.iter().enumerate() {
                    let dx = (x0 + i as i32 - display.position.x()) as i64;
                    if dx >= 0 && dx < dw as i64 && v.is_finite() {
                        sums[j * width + bin(dx, dw, width)][k] += v as f64;
                    }
                }
            }
        }
    }
    // How many display columns and rows fall in each panel column and row
    // (they differ by one where the scale is not a whole number); pixels
    // outside the data window count as black.
    let covered = |from: usize, to: usize| {
        let mut counts = vec![0.0f64; to];
        (0..from).for_each(|at| counts[bin(at as i64, from, to)] += 1.0);
        counts
    };
    let (columns, rows) = (covered(dw, width), covered(dh, height));
    Ok(sums
        .iter()
        .enumerate()
        .map(|(at, s)| {
            let n = (columns[at % width] * rows[at / width]).max(1.0);
            s.map(|v| srgb(v / n))
        })
        .collect())
}

/// A linear value as an 8-bit sRGB code, clipped to 0..1.
fn srgb(v: f64) -> u8 {
    let v = v.clamp(0.0, 1.0);
    let encoded = if v <= 0.0031308 {
        12.92 * v
    } else {
        1.055 * v.powf(1.0 / 2.4) - 0.055
    };
    (encoded * 255.0).round() as u8
}

/// Draws `text` at `(x, y)`, cut at `room` pixels wide.
fn draw_text(sheet: &mut Rgb8, text: &str, (x, y): (usize, usize), room: usize) {
    for (px, py) in font::pixels(text, TEXT_SCALE) {
        let (sx, sy) = (x + px, y + py);
        if px < room && sx < sheet.width && sy < sheet.height {
            sheet.pixels[sy * sheet.width + sx] = TEXT;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn srgb_codes_of_linear_values() {
        assert_eq!(srgb(0.0), 0);
        assert_eq!(srgb(1.0), 255);
        assert_eq!(srgb(8.0), 255);
        // 18% grey is about 118 in sRGB.
        assert_eq!(srgb(0.18), 118);
        assert_eq!(srgb(f64::NAN.max(0.0)), 0);
    }

    #[test]
    fn text_is_drawn_in_its_room_only() {
        let mut sheet = Rgb8 {
            width: 40,
            height: 20,
            pixels: vec![BACKGROUND; 800],
        };
        draw_text(&mut sheet, "II", (0, 0), 12);
        let lit: Vec<usize> = (0..40).filter(|&x| sheet.pixels[x] == TEXT).collect();
        // The top row of an I is its three middle pixels, doubled: x 2..8.
        assert_eq!(lit, (2..8).collect::<Vec<_>>());
    }
}
