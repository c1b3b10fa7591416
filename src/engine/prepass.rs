//! A measuring pass over an input before a job runs, for operations whose
//! halo depends on the pixels (vblur's longest vertical streak).

use super::decode::{decode_all, InputCursor};
use super::frame_plan::input_level;
use super::plan::{Job, Source};
use crate::error::Result;
use crate::io::parts::choose_part;
use crate::io::text::Utf8Text;
use rayon::prelude::*;

/// The largest `measure(first, second)` over every row of channels `names`
/// of input `input`, in every frame the job reads from disk.
pub fn max_over_rows(
    job: &Job,
    input: usize,
    names: [&str; 2],
    measure: impl Fn(&[f32], &[f32]) -> usize + Sync,
) -> Result<usize> {
    let mut most = 0;
    for sources in &job.frames {
        if matches!(sources.inputs[input], Source::Black(_)) {
            continue;
        }
        let file = job.input_file(input, sources)?;
        let part = choose_part(&file, job.parts[input].as_deref(), job.view.as_deref())?;
        let header = file.header(part);
        let position = |name: &str| {
            header
                .channels
                .list
                .iter()
                .position(|c| c.name.is(name))
                .ok_or_else(|| file.error(format!("has no channel '{name}'")))
        };
        let wanted = [position(names[0])?, position(names[1])?];
        // Read as the job reads it: strips of the level's rows, in its columns.
        let level = input_level(job, &file, part)?;
        let window = level.window(header);
        let columns = (window.position.x(), window.size.width());
        let step = level.block.y().max(64) * rayon::current_num_threads();
        let mut cursor = InputCursor::new(file.clone(), part, level, window);
        let mut frame_most = 0;
        for top in (window.position.y()..window.end().y()).step_by(step) {
            let rows = top..(top + step as i32).min(window.end().y());
            let strip = decode_all(std::slice::from_mut(&mut cursor), columns, rows.clone())?
                .pop()
                .expect("one input");
            let strip_most = rows
                .into_par_iter()
                .map(|y| {
                    let mut pair = [vec![0.0f32; strip.width], vec![0.0f32; strip.width]];
                    for (&c, out) in wanted.iter().zip(&mut pair) {
                        strip.planes[c].read_f32(strip.row_range(y), out);
                    }
                    measure(&pair[0], &pair[1])
                })
                .max()
                .unwrap_or(0);
            frame_most = frame_most.max(strip_most);
        }
        most = most.max(frame_most);
    }
    Ok(most)
}
