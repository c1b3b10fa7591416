//! `erode` and `dilate`: the smallest or largest alpha within a disc of
//! radius R (halo R rows), for shrinking or growing a pulled matte; colour
//! is left alone. specs/ops.md, "Matting".

use super::declare::{input, params, Args, Operation};
use super::layers::Selection;
use crate::engine::graph::{Band, GraphBuilder, NodeId, Op};
use crate::io::rows::{Rows, RowsMut};
use crate::io::text::Utf8Text;
use crate::params::MORPH_RADIUS;
use exr::meta::attribute::ChannelDescription;

pub const ERODE: Operation = Operation {
    name: "erode",
    about: "Shrink a matte: the smallest alpha within a disc of the radius",
    inputs: &[input("input", "Input file or sequence, `:PART` for a part")],
    repeats: false,
    params: Params::PARAMS,
    layers: true,
    straight: false,
    header: Some(0),
    build: |args, graph, inputs| build(args, graph, inputs, false),
    measure: None,
};

pub const DILATE: Operation = Operation {
    name: "dilate",
    about: "Grow a matte: the largest alpha within a disc of the radius",
    build: |args, graph, inputs| build(args, graph, inputs, true),
    ..ERODE
};

params! {
    pub struct Params {
        /// Radius of the disc in pixels.
        radius: u32 [MORPH_RADIUS] {pixels},
        /// 1 - alpha afterwards.
        invert: bool,
    }
}

fn build(
    args: &Args,
    graph: &mut GraphBuilder,
    inputs: &[NodeId],
    dilate: bool,
) -> Result<NodeId, String> {
    let p = Params::read(args)?;
    let op = Morphology {
        radius: p.radius as usize,
        dilate,
        invert: p.invert,
        layers: args.layers.clone(),
    };
    Ok(graph.add(op, inputs))
}

#[derive(Debug)]
pub struct Morphology {
    pub radius: usize,
    /// Largest (dilate) instead of smallest (erode).
    pub dilate: bool,
    /// 1 - alpha afterwards.
    pub invert: bool,
    pub layers: Selection,
}

impl Op for Morphology {
    fn halo(&self) -> usize {
        self.radius
    }

    /// An alpha's rows that the band's discs reach, as f32, and a row of
    /// results.
    fn scratch(&self, band: &Band) -> usize {
        ((band.rows + 2 * self.radius) * band.widths[0] + band.width) * 4
    }

    fn check(&self, inputs: &[&[ChannelDescription]]) -> Result<(), String> {
        let alphas: Vec<String> = self
            .layers
            .resolve(inputs)
            .iter()
            .map(|l| l.alpha_channel())
            .collect();
        match alphas
            .iter()
            .find(|a| !inputs[0].iter().any(|c| c.name.is(a.as_str())))
        {
            Some(missing) => Err(format!("no alpha channel '{missing}' to erode or dilate")),
            None => Ok(()),
        }
    }

    fn compute(&self, _frame: i64, inputs: &[&Rows], out: &mut RowsMut) -> Result<(), String> {
        let input = inputs[0];
        let r = self.radius as i32;
        // Half-width of the disc on each row offset.
        let spans: Vec<usize> = (-r..=r)
            .map(|dy| (((r * r - dy * dy) as f32).sqrt().floor()) as usize)
            .collect();
        let columns = input.valid_columns();
        let held = input.valid_rows();
        let alphas: Vec<usize> = self
            .layers
            .resolve(&[input.channels.as_slice()])
            .iter()
            .filter_map(|l| input.channel_index(&l.alpha_channel()))
            .collect();
        for y in out.valid_rows() {
            out.copy_row_from(input, y);
        }
        // Only the input rows this band's discs reach are converted.
        let wanted = out.valid_rows();
        let held = (wanted.start - r).max(held.start)..(wanted.end + r).min(held.end);
        let mut values = vec![0.0f32; columns.len()];
        for &a in &alphas {
            let rows: Vec<Vec<f32>> = held
                .clone()
                .map(|y| {
                    let mut v = vec![0.0f32; input.width];
                    input.planes[a].read_f32(input.row_range(y), &mut v);
                    v
                })
                .collect();
            for y in out.valid_rows() {
                for (value, x) in values.iter_mut().zip(columns.clone()) {
                    let mut best = if self.dilate { f32::MIN } else { f32::MAX };
                    for (dy, &span) in (-r..=r).zip(&spans) {
                        let yy = y + dy;
                        if yy < held.start || yy >= held.end {
                            continue;
                        }
                        let row = &rows[(yy - held.start) as usize];
                        let from = x.saturating_sub(span).max(columns.start);
                        let to = (x + span + 1).min(columns.end);
                        for &v in &row[from..to] {
                            best = if self.dilate {
                                best.max(v)
                            } else {
                                best.min(v)
                            };
                        }
                    }
                    *value = if self.invert { 1.0 - best } else { best };
                }
                let range = out.row_range(y);
                out.planes[a].write_f32(
                    range.start + columns.start..range.start + columns.end,
                    &values,
                );
            }
        }
        Ok(())
    }
}
