//! Separable blur as two graph nodes: a horizontal pass (no halo) into float
//! rows, then a vertical pass with a halo of `radius` rows, so each input row
//! is filtered horizontally once however the strips fall. Edges clamp to the
//! data window. Formulas: specs/ops.md, "blur".

use super::declare::{choice, input, params, Args, Operation, Value};
use super::layers::Selection;
use crate::engine::graph::{GraphBuilder, NodeId, Op};
use crate::io::rows::{PlaneMut, Rows, RowsMut, Samples};
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
#[derive(Debug)]
pub struct Horizontal {
    pub weights: Arc<Vec<f32>>,
    pub layers: Selection,
}

/// The vertical pass over [horizontal pass, original]: the original's
/// channels and types, the filtered ones from the first input.
#[derive(Debug)]
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
        // The row with `radius` clamped samples added on each side.
        let mut padded = vec![0.0f32; columns.len() + 2 * radius];
        for y in out.valid_rows() {
            let range = out.row_range(y);
            for (plane, &source) in out.planes.iter_mut().zip(&sources) {
                let n = columns.len();
                let from = input.row_range(y).start;
                input.planes[source].read_f32(
                    from + columns.start..from + columns.end,
                    &mut padded[radius..radius + n],
                );
                let (first, last) = (padded[radius], padded[radius + n - 1]);
                padded[..radius].fill(first);
                padded[radius + n..].fill(last);
                let taps: Vec<&[f32]> =
                    (0..self.weights.len()).map(|k| &padded[k..k + n]).collect();
                let PlaneMut::F32(plane) = plane else {
                    unreachable!("the horizontal pass writes f32")
                };
                let to = range.start + columns.start..range.start + columns.end;
                filter(&self.weights, &taps, &mut plane[to]);
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
                        let taps: Vec<&[f32]> = (-radius..=radius)
                            .map(|k| {
                                let from =
                                    blurred.row_range((y + k).clamp(rows.start, rows.end - 1));
                                &plane[from.start + columns.start..from.start + columns.end]
                            })
                            .collect();
                        filter(&self.weights, &taps, &mut sums);
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

/// Output samples summed in registers at a time: every tap is read once per
/// block of them, where summing tap by tap across a row read and wrote the
/// sums 2R + 1 times.
const LANES: usize = 64;

crate::simd::avx2_where_there! {
    /// out[i] = the sum of weights[k] * taps[k][i] in f32, from k = 0 up (-R
    /// in the filter's offsets), a multiply then an add per tap: no fused
    /// multiply-add, so the AVX2 build of the same loop gives the same bits
    /// as SSE2, twice as wide.
    fn filter(weights: &[f32], taps: &[&[f32]], out: &mut [f32]) {
        filter_lanes(weights, taps, out)
    }
}

#[inline(always)]
fn filter_lanes(weights: &[f32], taps: &[&[f32]], out: &mut [f32]) {
    let whole = out.len() / LANES * LANES;
    for (x, block) in (0..whole).step_by(LANES).zip(out.chunks_exact_mut(LANES)) {
        let mut sums = [0.0f32; LANES];
        for (w, tap) in weights.iter().zip(taps) {
            let values: &[f32; LANES] = tap[x..x + LANES].try_into().expect("LANES values");
            for (sum, v) in sums.iter_mut().zip(values) {
                *sum += w * v;
            }
        }
        block.copy_from_slice(&sums);
    }
    let rest = &mut out[whole..];
    rest.fill(0.0);
    for (w, tap) in weights.iter().zip(taps) {
        for (sum, v) in rest.iter_mut().zip(&tap[whole..]) {
            *sum += w * v;
        }
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

#[cfg(test)]
mod tests {
    use super::*;

    /// Every sum as specs/ops.md states it, one sample at a time.
    fn naive(weights: &[f32], taps: &[&[f32]], n: usize) -> Vec<f32> {
        (0..n)
            .map(|i| {
                let mut sum = 0.0f32;
                for (w, tap) in weights.iter().zip(taps) {
                    sum += w * tap[i];
                }
                sum
            })
            .collect()
    }

    #[test]
    fn filter_sums_in_the_specified_order_with_every_instruction_set() {
        let mut seed = 7u32;
        let mut value = || {
            seed = seed.wrapping_mul(1664525).wrapping_add(1013904223);
            // Mixed signs and magnitudes (2^-16 to 2^15), so another order
            // or a fused multiply-add rounds differently.
            let mantissa = (seed >> 8) as f32 / (1 << 24) as f32 * 2.0 - 1.0;
            mantissa * ((seed & 0x1f) as f32 - 16.0).exp2()
        };
        let weights = weights(Filter::Gaussian, 10);
        type Kernel = fn(&[f32], &[&[f32]], &mut [f32]);
        for n in [0usize, 1, 63, 64, 65, 100, 3840] {
            let rows: Vec<Vec<f32>> = (0..weights.len())
                .map(|_| (0..n).map(|_| value()).collect())
                .collect();
            let taps: Vec<&[f32]> = rows.iter().map(|r| r.as_slice()).collect();
            let bits = |v: &[f32]| v.iter().map(|v| v.to_bits()).collect::<Vec<_>>();
            let expected = bits(&naive(&weights, &taps, n));
            for (name, kernel) in [("lanes", filter_lanes as Kernel), ("dispatched", filter)] {
                let mut out = vec![f32::NAN; n];
                kernel(&weights, &taps, &mut out);
                assert_eq!(bits(&out), expected, "{n} samples, {name}");
            }
        }
    }
}
