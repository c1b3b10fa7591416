//! Separable blur as two graph nodes: a horizontal pass (no halo) into float
//! rows, then a vertical pass with a halo of `radius` rows, so each input row
//! is filtered horizontally once however the strips fall. Edges clamp to the
//! data window. Formulas: specs/ops.md, "blur".

use super::declare::{choice, input, params, Args, Operation, Value};
use super::layers::Selection;
use crate::engine::graph::{GraphBuilder, NodeId, Op};
use crate::engine::strip::{Rows, RowsMut, Samples};
use crate::io::text::Utf8Text;
use crate::params::BLUR_RADIUS;
use exr::meta::attribute::{ChannelDescription, SampleType};
use std::sync::Arc;

pub const BLUR: Operation = Operation {
    name: "blur",
    about: "Blur with a separable Gaussian or box of radius R (edges clamp to the data \
            window); `--radius R` is oiiotool's `--blur (2R+1)x(2R+1)`",
    inputs: &[input("input", "Input file or sequence, `:PART` for a part")],
    repeats: false,
    params: Params::PARAMS,
    layers: true,
    straight: false,
    header: Some(0),
    build,
    measure: None,
};

params! {
    pub struct Params {
        /// Radius in pixels: 2R + 1 taps.
        radius: u32 [BLUR_RADIUS] {pixels},
        /// gaussian or box.
        filter: Filter = "gaussian",
    }
}

fn build(args: &Args, graph: &mut GraphBuilder, inputs: &[NodeId]) -> Result<NodeId, String> {
    let p = Params::read(args)?;
    Ok(passes(
        p.filter,
        p.radius as usize,
        &args.layers,
        inputs[0],
        graph,
    ))
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Filter {
    Gaussian,
    Box,
}

impl Value for Filter {
    fn parse(text: &str) -> Result<Self, String> {
        choice(
            text,
            Self::CHOICES,
            &[Filter::Gaussian, Filter::Box],
            "filter",
        )
    }
    const CHOICES: &'static [&'static str] = &["gaussian", "box"];
}

/// The 2R + 1 weights, taps -R..=R: the Gaussian that oiiotool's
/// `--blur (2R+1)x(2R+1)` uses, exp(-8 k² / (2R+1)²) (sigma = (2R+1)/4),
/// or a box; normalised to sum 1 in f64, then rounded to f32.
pub fn weights(filter: Filter, radius: usize) -> Vec<f32> {
    let width = (2 * radius + 1) as f64;
    let raw: Vec<f64> = (0..2 * radius + 1)
        .map(|i| {
            let k = i as f64 - radius as f64;
            match filter {
                Filter::Gaussian => (-8.0 * k * k / (width * width)).exp(),
                Filter::Box => 1.0,
            }
        })
        .collect();
    let sum: f64 = raw.iter().sum();
    raw.iter().map(|w| (w / sum) as f32).collect()
}

/// The horizontal pass: the filtered channels only, as f32.
pub struct Horizontal {
    pub weights: Arc<Vec<f32>>,
    pub layers: Selection,
}

/// The vertical pass over [horizontal pass, original]: the original's
/// channels and types, the filtered ones from the first input.
pub struct Vertical {
    pub weights: Arc<Vec<f32>>,
    pub layers: Selection,
}

impl Op for Horizontal {
    fn channels(&self, inputs: &[&[ChannelDescription]]) -> Vec<ChannelDescription> {
        let names = self.layers.filtered(inputs[0]);
        inputs[0]
            .iter()
            .filter(|c| names.iter().any(|n| c.name.is(n.as_str())))
            .map(|c| ChannelDescription {
                sample_type: SampleType::F32,
                ..c.clone()
            })
            .collect()
    }

    fn check(&self, inputs: &[&[ChannelDescription]]) -> Result<(), String> {
        self.layers.check(inputs)
    }

    fn compute(&self, _frame: i64, inputs: &[&Rows], out: &mut RowsMut) -> Result<(), String> {
        let input = inputs[0];
        let columns = out.valid_columns();
        if columns.is_empty() {
            return Ok(());
        }
        let radius = self.weights.len() / 2;
        let sources: Vec<usize> = out
            .channels
            .iter()
            .map(|c| {
                input
                    .channel_index(&c.name.utf8())
                    .expect("a filtered channel")
            })
            .collect();
        let mut row = vec![0.0f32; input.width];
        // The row with `radius` clamped samples added on each side.
        let mut padded = vec![0.0f32; columns.len() + 2 * radius];
        let mut sums = vec![0.0f32; columns.len()];
        for y in out.valid_rows() {
            let range = out.row_range(y);
            for (plane, &source) in out.planes.iter_mut().zip(&sources) {
                input.planes[source].read_f32(input.row_range(y), &mut row);
                let line = &row[columns.clone()];
                let (first, last) = (line[0], line[line.len() - 1]);
                padded[..radius].fill(first);
                padded[radius..radius + line.len()].copy_from_slice(line);
                padded[radius + line.len()..].fill(last);
                // Tap by tap across the row (vectorises), each pixel's sum
                // still taken from k = -R upwards.
                sums.fill(0.0);
                for (k, w) in self.weights.iter().enumerate() {
                    for (sum, v) in sums.iter_mut().zip(&padded[k..]) {
                        *sum += w * v;
                    }
                }
                plane.write_f32(
                    range.start + columns.start..range.start + columns.end,
                    &sums,
                );
            }
        }
        Ok(())
    }
}

impl Op for Vertical {
    fn halo(&self) -> usize {
        self.weights.len() / 2
    }

    fn channels(&self, inputs: &[&[ChannelDescription]]) -> Vec<ChannelDescription> {
        inputs[1].to_vec()
    }

    fn compute(&self, _frame: i64, inputs: &[&Rows], out: &mut RowsMut) -> Result<(), String> {
        let (blurred, original) = (inputs[0], inputs[1]);
        let radius = self.weights.len() as i32 / 2;
        // The data window's rows (as far as they are held): the clamp's edges.
        let rows = blurred.valid_rows();
        let columns = out.valid_columns();
        // Per output channel, the first pass's f32 plane, or none (copied).
        let planes: Vec<Option<&[f32]>> = out
            .channels
            .iter()
            .map(|c| {
                blurred
                    .channel_index(&c.name.utf8())
                    .map(|i| match &blurred.planes[i] {
                        Samples::F32(v) => v.as_slice(),
                        _ => unreachable!("the first pass writes f32"),
                    })
            })
            .collect();
        let mut sums = vec![0.0f32; columns.len()];
        for y in out.valid_rows() {
            let range = out.row_range(y);
            for (c, plane) in planes.iter().enumerate() {
                match plane {
                    Some(plane) => {
                        sums.fill(0.0);
                        for (k, w) in (-radius..=radius).zip(self.weights.iter()) {
                            let from = blurred.row_range((y + k).clamp(rows.start, rows.end - 1));
                            let source =
                                &plane[from.start + columns.start..from.start + columns.end];
                            for (sum, v) in sums.iter_mut().zip(source) {
                                *sum += w * v;
                            }
                        }
                        out.planes[c].write_f32(
                            range.start + columns.start..range.start + columns.end,
                            &sums,
                        );
                    }
                    None => {
                        let name = out.channels[c].name.utf8();
                        let s = original
                            .channel_index(&name)
                            .expect("the original's channel");
                        let bytes = original.planes[s].bytes(original.row_range(y));
                        out.planes[c]
                            .bytes_mut(range.clone())
                            .copy_from_slice(bytes);
                    }
                }
            }
        }
        Ok(())
    }
}

/// A blur of graph node `input` as its two passes; returns the second.
pub fn passes(
    filter: Filter,
    radius: usize,
    layers: &Selection,
    input: NodeId,
    graph: &mut GraphBuilder,
) -> NodeId {
    let weights = Arc::new(weights(filter, radius));
    let horizontal = Horizontal {
        weights: weights.clone(),
        layers: layers.clone(),
    };
    let first = graph.add(horizontal, &[input]);
    let vertical = Vertical {
        weights,
        layers: layers.clone(),
    };
    graph.add(vertical, &[first, input])
}
