//! The other eye from one view and its depth: each pixel moves sideways by
//! K / Z, the nearer pixel winning where two land on one; holes take the
//! pixel beside them that is farther away (what the moved object uncovered).
//! Row by row: no halo, but whole rows read. specs/ops.md, "stereo".

use super::declare::{choice, input, params, Operation, Value};
use crate::engine::graph::Op;
use crate::io::rows::{Rows, RowsMut};
use crate::io::text::Utf8Text;
use crate::params::DISPARITY;
use exr::meta::attribute::ChannelDescription;

pub const STEREO: Operation = Operation {
    name: "stereo",
    about: "The other eye of a stereo pair from one view and its depth",
    inputs: &[input("input", "Input file or sequence, `:PART` for a part")],
    repeats: false,
    params: Params::PARAMS,
    layers: false,
    straight: false,
    header: Some(0),
    build: |args, graph, inputs| {
        let p = Params::read(args)?;
        let op = Stereo {
            eye: p.eye,
            disparity: p.disparity,
            z_channel: p.z_channel,
        };
        Ok(graph.add(op, inputs))
    },
    measure: None,
};

params! {
    pub struct Params {
        /// The eye to make: the image moves right for the left eye, left for the right.
        eye: Eye,
        /// Shift in pixels at depth 1: a pixel at depth Z moves K / Z.
        disparity: f32 [DISPARITY] {pixels},
        /// The depth channel.
        z_channel: String = "Z",
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Eye {
    Left,
    Right,
}

impl Value for Eye {
    fn parse(text: &str) -> Result<Self, String> {
        choice(text, Self::CHOICES, &[Eye::Left, Eye::Right], "eye")
    }
    const CHOICES: &'static [&'static str] = &["left", "right"];
}

#[derive(Debug)]
pub struct Stereo {
    pub eye: Eye,
    /// Pixels of shift at depth 1 (the shift is K / Z).
    pub disparity: f32,
    pub z_channel: String,
}

impl Stereo {
    /// Columns a pixel at depth `z` moves: right for the left eye, left for
    /// the right eye; none where the depth is not a positive number.
    pub fn shift(&self, z: f32) -> i64 {
        if z.is_nan() || z <= 0.0 {
            return 0;
        }
        let s = (self.disparity / z).round();
        let s = if s.is_finite() { s as i64 } else { 0 };
        match self.eye {
            Eye::Left => s,
            Eye::Right => -s,
        }
    }
}

impl Op for Stereo {
    /// A pixel may move any distance across its row (K / Z, Z near 0): the
    /// whole row is read, so a crop keeps what comes in from beyond it.
    fn across(&self) -> usize {
        usize::MAX
    }

    fn check(&self, inputs: &[&[ChannelDescription]]) -> Result<(), String> {
        match inputs[0].iter().any(|c| c.name.is(self.z_channel.as_str())) {
            true => Ok(()),
            false => Err(format!("no depth channel '{}'", self.z_channel)),
        }
    }

    fn compute(&self, _frame: i64, inputs: &[&Rows], out: &mut RowsMut) -> Result<(), String> {
        let input = inputs[0];
        let z = input.channel_index(&self.z_channel).expect("checked");
        let columns = out.valid_columns();
        let (start, end) = (columns.start as i64, columns.end as i64);
        let mut depth = vec![0.0f32; input.width];
        // Per output column: the source column and its depth.
        let mut source: Vec<Option<(usize, f32)>> = vec![None; input.width];
        for y in out.valid_rows() {
            input.planes[z].read_f32(input.row_range(y), &mut depth);
            source.fill(None);
            for x in columns.clone() {
                let to = x as i64 + self.shift(depth[x]);
                if to < start || to >= end {
                    continue;
                }
                let slot = &mut source[to as usize];
                // Nearer wins; NaN depth never does.
                if slot.is_none_or(|(_, d)| depth[x] < d) {
                    *slot = Some((x, depth[x]));
                }
            }
            // Nearest moved pixel on each side of every column, then holes.
            let mut left = vec![None; input.width];
            let mut last = None;
            for x in columns.clone() {
                last = source[x].or(last);
                left[x] = last;
            }
            let mut next = None;
            for x in columns.clone().rev() {
                let right = next;
                next = source[x].or(next);
                if source[x].is_none() {
                    source[x] = match (left[x], right) {
                        (Some(l), Some(r)) => Some(if r.1 > l.1 { r } else { l }),
                        (l, r) => l.or(r),
                    };
                }
            }
            let (from, to) = (input.row_range(y), out.row_range(y));
            for (c, channel) in out.channels.iter().enumerate() {
                let s = input
                    .channel_index(&channel.name.utf8())
                    .expect("the input's channel");
                let size = channel.sample_type.bytes_per_sample();
                for x in columns.clone() {
                    if let Some((sx, _)) = source[x] {
                        let bytes = input.planes[s].bytes(from.start + sx..from.start + sx + 1);
                        out.planes[c]
                            .bytes_mut(to.start + x..to.start + x + 1)
                            .copy_from_slice(&bytes[..size]);
                    }
                }
            }
        }
        Ok(())
    }
}
