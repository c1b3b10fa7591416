//! In-memory images for the operations' own tests: rows built from
//! functions of the pixel, and an op computed over them as the engine would
//! (one node, its inputs holding every row), with no files and no process.

use crate::engine::graph::Op;
use crate::io::rows::Rows;
use exr::meta::attribute::{ChannelDescription, IntegerBounds, SampleType};

/// A sample of a channel at absolute pixel (x, y).
pub type Pixel<'a> = &'a dyn Fn(i32, i32) -> f32;

/// Float rows covering `columns` x `rows` (absolute), with data only inside
/// `valid`: each channel is `value(x, y)` there, 0 outside it.
pub fn image_in(
    columns: std::ops::Range<i32>,
    rows: std::ops::Range<i32>,
    valid: IntegerBounds,
    channels: &[(&str, Pixel)],
) -> Rows {
    let descriptions = channels
        .iter()
        .map(|(name, _)| ChannelDescription::named(*name, SampleType::F32))
        .collect();
    let width = (columns.end - columns.start) as usize;
    let height = (rows.end - rows.start) as usize;
    let mut image = Rows::zeros(
        columns.start,
        rows.start,
        width,
        height,
        descriptions,
        valid,
    );
    for (c, (_, value)) in channels.iter().enumerate() {
        for y in image.valid_rows() {
            let range = image.row_range(y);
            let values: Vec<f32> = (0..width as i32)
                .map(|i| columns.start + i)
                .map(|x| {
                    if inside(valid, x, y) {
                        value(x, y)
                    } else {
                        0.0
                    }
                })
                .collect();
            image.planes[c].write_f32(range, &values);
        }
    }
    image
}

/// A `width` x `height` float image at the origin, with data everywhere.
pub fn image(width: usize, height: usize, channels: &[(&str, Pixel)]) -> Rows {
    let window = IntegerBounds::new((0, 0), (width, height));
    image_in(0..width as i32, 0..height as i32, window, channels)
}

fn inside(window: IntegerBounds, x: i32, y: i32) -> bool {
    let (start, end) = (window.position, window.end());
    x >= start.x() && x < end.x() && y >= start.y() && y < end.y()
}

/// `op` over `inputs` (which share columns and rows), every row in one band,
/// with the channels and data window the op gives for them.
pub fn compute(op: &dyn Op, inputs: &[&Rows]) -> Result<Rows, String> {
    let lists: Vec<&[ChannelDescription]> = inputs.iter().map(|i| i.channels.as_slice()).collect();
    op.check(&lists)?;
    let windows: Vec<IntegerBounds> = inputs.iter().map(|i| i.valid).collect();
    let first = inputs[0];
    let mut out = Rows::zeros(
        first.x,
        first.y,
        first.width,
        0,
        op.channels(&lists),
        op.data_window(&windows),
    );
    out.grow(first.height);
    for mut band in out.bands(first.y, first.height.max(1)) {
        op.compute(0, inputs, &mut band)?;
    }
    Ok(out)
}

/// Channel `name` at absolute pixel (x, y); `None` when there is no such
/// channel.
pub fn sample(rows: &Rows, name: &str, x: i32, y: i32) -> Option<f32> {
    let c = rows.channel_index(name)?;
    let mut value = [0.0f32];
    let at = rows.row_range(y).start + (x - rows.x) as usize;
    rows.planes[c].read_f32(at..at + 1, &mut value);
    Some(value[0])
}
