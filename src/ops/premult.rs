//! `premult` and `unpremult`: colour times or divided by its layer's alpha.

use super::declare::{input, Operation};
use super::layers::Selection;
use crate::engine::graph::Op;
use crate::io::rows::{Rows, RowsMut};
use exr::meta::attribute::ChannelDescription;

pub const PREMULT: Operation = Operation {
    name: "premult",
    about: "Multiply colour by alpha",
    build: |args, graph, inputs| {
        let op = Premult {
            inverse: false,
            layers: args.layers.clone(),
        };
        Ok(graph.add(op, inputs))
    },
    ..UNPREMULT
};

pub const UNPREMULT: Operation = Operation {
    name: "unpremult",
    about: "Divide colour by alpha (colour unchanged where alpha is 0)",
    inputs: &[input("input", "Input file or sequence, `:PART` for a part")],
    repeats: false,
    params: &[],
    layers: true,
    straight: false,
    header: Some(0),
    build: |args, graph, inputs| {
        let op = Premult {
            inverse: true,
            layers: args.layers.clone(),
        };
        Ok(graph.add(op, inputs))
    },
    measure: None,
};

#[derive(Debug)]
pub struct Premult {
    /// Divide instead of multiply (`unpremult`).
    pub inverse: bool,
    pub layers: Selection,
}

impl Premult {
    /// C·α, or C/α where α is not 0 (C unchanged where it is, as oiiotool
    /// does: there is no colour to recover).
    fn apply(&self, c: f32, alpha: f32) -> f32 {
        match (self.inverse, alpha == 0.0) {
            (false, _) => c * alpha,
            (true, true) => c,
            (true, false) => c / alpha,
        }
    }
}

impl Op for Premult {
    fn check(&self, inputs: &[&[ChannelDescription]]) -> Result<(), String> {
        self.layers.check(inputs)
    }

    fn compute(&self, _frame: i64, inputs: &[&Rows], out: &mut RowsMut) -> Result<(), String> {
        let input = inputs[0];
        let layers = self.layers.resolve(&[input.channels.as_slice()]);
        let mut alpha = vec![0.0f32; out.width];
        let mut colour = vec![0.0f32; out.width];
        for y in out.valid_rows() {
            let range = out.row_range(y);
            // Every channel as it is, then the selected colours recomputed.
            out.copy_row_from(input, y);
            for layer in &layers {
                layer.read_alpha(input, y, 0, &mut alpha);
                for name in layer.colours() {
                    let Some(c) = input.channel_index(&name) else {
                        continue;
                    };
                    input.planes[c].read_f32(input.row_range(y), &mut colour);
                    for (v, &a) in colour.iter_mut().zip(&alpha) {
                        *v = self.apply(*v, a);
                    }
                    out.planes[c].write_f32(range.clone(), &colour);
                }
            }
        }
        Ok(())
    }
}
