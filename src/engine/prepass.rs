//! A measuring pass over an input before a job runs, for operations whose
//! halo depends on the pixels (vblur's longest vertical streak).

use super::plan::{Job, Source};
use crate::error::Result;
use crate::io::parts::choose_part;
use crate::io::reader::ExrFile;
use exr::meta::attribute::SampleType;
use half::f16;
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
        let Source::Frame(at) = sources.inputs[input] else {
            continue;
        };
        let file = ExrFile::open(&job.inputs[input].path(at), job.frame_label(at))?;
        let part = choose_part(&file, job.parts[input].as_deref(), job.view.as_deref())?;
        let header = file.header(part);
        let list = &header.channels.list;
        let position = |name: &str| {
            list.iter()
                .position(|c| c.name.eq(name))
                .ok_or_else(|| file.error(format!("has no channel '{name}'")))
        };
        let wanted = [position(names[0])?, position(names[1])?];
        let width = header.layer_size.width();
        let frame_most = (0..header.chunk_count)
            .into_par_iter()
            .map(|k| {
                let block = file.decode_chunk(part, k)?;
                let mut rows = [vec![0.0f32; width], vec![0.0f32; width]];
                let line_bytes: usize = list
                    .iter()
                    .map(|c| c.sample_type.bytes_per_sample())
                    .sum::<usize>()
                    * width;
                let mut most = 0;
                for line in block.data.chunks_exact(line_bytes.max(1)) {
                    let mut offset = 0;
                    for (c, channel) in list.iter().enumerate() {
                        let bytes = channel.sample_type.bytes_per_sample() * width;
                        if let Some(slot) = wanted.iter().position(|&w| w == c) {
                            decode_row(
                                channel.sample_type,
                                &line[offset..offset + bytes],
                                &mut rows[slot],
                            );
                        }
                        offset += bytes;
                    }
                    most = most.max(measure(&rows[0], &rows[1]));
                }
                Ok(most)
            })
            .try_reduce(|| 0, |a, b| Ok(a.max(b)))?;
        most = most.max(frame_most);
    }
    Ok(most)
}

/// Little-endian samples of one type as f32.
fn decode_row(kind: SampleType, bytes: &[u8], out: &mut [f32]) {
    match kind {
        SampleType::F16 => {
            for (o, b) in out.iter_mut().zip(bytes.chunks_exact(2)) {
                *o = f16::from_le_bytes([b[0], b[1]]).to_f32();
            }
        }
        SampleType::F32 => {
            for (o, b) in out.iter_mut().zip(bytes.chunks_exact(4)) {
                *o = f32::from_le_bytes([b[0], b[1], b[2], b[3]]);
            }
        }
        SampleType::U32 => {
            for (o, b) in out.iter_mut().zip(bytes.chunks_exact(4)) {
                *o = u32::from_le_bytes([b[0], b[1], b[2], b[3]]) as f32;
            }
        }
    }
}
