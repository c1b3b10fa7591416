//! The shadow steps of Debevec's differential rendering, between two `over`
//! merges: I5 = I4 - I3 (the light the proxy loses to the object) and
//! I6 = P - G I5 (the plate darkened by it), in R, G, B only.
//! specs/ops.md, "diffrender".

use super::layers::Selection;
use super::merge::{Merge, MergeOp};
use crate::engine::graph::Op;
use crate::engine::strip::{Rows, RowsMut};
use exr::meta::attribute::{ChannelDescription, IntegerBounds};

const COLOURS: [&str; 3] = ["R", "G", "B"];

#[derive(Clone, Copy, PartialEq)]
pub enum Step {
    /// Inputs (I4, I3): I4 with its colours replaced by I4 - I3.
    Light,
    /// Inputs (I5, P): the plate with its colours replaced by P - G I5.
    Apply { gain: f32 },
}

pub struct Shadow(pub Step);

impl Op for Shadow {
    /// The channels of the image the step changes (I4, or the plate).
    fn channels(&self, inputs: &[&[ChannelDescription]]) -> Vec<ChannelDescription> {
        match self.0 {
            Step::Light => inputs[0].to_vec(),
            Step::Apply { .. } => inputs[1].to_vec(),
        }
    }

    /// The light lost is wherever either render has data; the plate's
    /// window is the shot.
    fn data_window(&self, inputs: &[IntegerBounds]) -> IntegerBounds {
        match self.0 {
            Step::Light => crate::engine::graph::union(inputs[0], inputs[1]),
            Step::Apply { .. } => inputs[1],
        }
    }

    fn compute(&self, _frame: i64, inputs: &[&Rows], out: &mut RowsMut) -> Result<(), String> {
        let (first, second) = (inputs[0], inputs[1]);
        let kept = match self.0 {
            Step::Light => first,
            Step::Apply { .. } => second,
        };
        let columns = out.valid_columns();
        let (mut a, mut b) = (vec![0.0f32; out.width], vec![0.0f32; out.width]);
        let read =
            |rows: &Rows, name: &str, y: i32, buffer: &mut [f32]| match rows.channel_index(name) {
                Some(c) => rows.planes[c].read_f32(rows.row_range(y), buffer),
                None => buffer.fill(0.0),
            };
        for y in out.valid_rows() {
            let range = out.row_range(y);
            for (c, channel) in out.channels.iter().enumerate() {
                let name = channel.name.to_string();
                if !COLOURS.contains(&name.as_str()) {
                    let s = kept.channel_index(&name).expect("the kept image's channel");
                    out.planes[c]
                        .bytes_mut(range.clone())
                        .copy_from_slice(kept.planes[s].bytes(kept.row_range(y)));
                    continue;
                }
                read(first, &name, y, &mut a);
                read(second, &name, y, &mut b);
                for x in columns.clone() {
                    a[x] = match self.0 {
                        Step::Light => a[x] - b[x],
                        Step::Apply { gain } => b[x] - gain * a[x],
                    };
                }
                out.planes[c].write_f32(
                    range.start + columns.start..range.start + columns.end,
                    &a[columns.clone()],
                );
            }
        }
        Ok(())
    }
}

/// Appends to `ops` (whose first op is graph node `base`) the whole method
/// on graph nodes `[object I1, proxy I2, with shadows I3, plate P]`:
/// I4 = I1 over I2, I5, then (unless `shadow_only`) I6 and I1 over I6. The
/// last op pushed is the result.
pub fn push_steps(
    ops: &mut Vec<(Box<dyn Op>, Vec<usize>)>,
    base: usize,
    [object, proxy, shadowed, plate]: [usize; 4],
    gain: f32,
    shadow_only: bool,
) {
    let over = || -> Box<dyn Op> {
        Box::new(Merge {
            op: MergeOp::Over,
            straight: false,
            mix: 1.0,
            layers: Selection::default(),
        })
    };
    let mut push = |op: Box<dyn Op>, inputs: Vec<usize>| {
        ops.push((op, inputs));
        base + ops.len() - 1
    };
    let i4 = push(over(), vec![object, proxy]);
    let i5 = push(Box::new(Shadow(Step::Light)), vec![i4, shadowed]);
    if !shadow_only {
        let i6 = push(Box::new(Shadow(Step::Apply { gain })), vec![i5, plate]);
        push(over(), vec![object, i6]);
    }
}
