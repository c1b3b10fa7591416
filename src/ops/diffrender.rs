//! The shadow steps of Debevec's differential rendering, between two `over`
//! merges: I5 = I4 - I3 (the light the proxy loses to the object) and
//! I6 = P - G I5 (the plate darkened by it), in R, G, B only.
//! specs/ops.md, "diffrender".

use super::declare::{named, params, Operation};
use super::layers::Selection;
use super::merge::{Merge, MergeOp};
use crate::engine::graph::{GraphBuilder, NodeId, Op};
use crate::io::rows::{Rows, RowsMut};
use crate::io::text::Utf8Text;
use crate::params::SHADOW_GAIN;
use exr::meta::attribute::{ChannelDescription, IntegerBounds};

pub const DIFFRENDER: Operation = Operation {
    name: "diffrender",
    about: "Differential rendering (Debevec): an object rendered into a plate with the \
            shadows and light it casts on a proxy of the real scene",
    inputs: &[
        named("object", "I1: the object alone"),
        named("proxy", "I2: the proxy of the scene, without the object"),
        named(
            "with_shadows",
            "I3: the proxy with the object's shadows (and light) on it",
        ),
        named(
            "plate",
            "P: the real plate; its header and other channels are kept",
        ),
    ],
    repeats: false,
    params: Params::PARAMS,
    layers: false,
    straight: false,
    header: Some(3),
    build: |args, graph, inputs| {
        let p = Params::read(args)?;
        let [object, proxy, shadowed, plate] = inputs else {
            unreachable!("four inputs, as declared")
        };
        let steps = [*object, *proxy, *shadowed, *plate];
        Ok(push_steps(graph, steps, p.shadow_gain, p.shadow_only))
    },
    measure: None,
};

params! {
    pub struct Params {
        /// G in P - G (I4 - I3).
        shadow_gain: f32 [SHADOW_GAIN] = "1",
        /// Write I5 = (I1 over I2) - I3 instead, for grading.
        shadow_only: bool,
    }
}

const COLOURS: [&str; 3] = ["R", "G", "B"];

#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Step {
    /// Inputs (I4, I3): I4 with its colours replaced by I4 - I3.
    Light,
    /// Inputs (I5, P): the plate with its colours replaced by P - G I5.
    Apply { gain: f32 },
}

#[derive(Debug)]
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
                let name = channel.name.utf8();
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

/// The whole method on nodes `[object I1, proxy I2, with shadows I3, plate
/// P]`: I4 = I1 over I2, I5, then (unless `shadow_only`) I6 and I1 over I6.
/// Returns the last node.
fn push_steps(
    graph: &mut GraphBuilder,
    [object, proxy, shadowed, plate]: [NodeId; 4],
    gain: f32,
    shadow_only: bool,
) -> NodeId {
    let over = || Merge {
        op: MergeOp::Over,
        straight: false,
        mix: 1.0,
        layers: Selection::default(),
    };
    let i4 = graph.add(over(), &[object, proxy]);
    let i5 = graph.add(Shadow(Step::Light), &[i4, shadowed]);
    if shadow_only {
        return i5;
    }
    let i6 = graph.add(Shadow(Step::Apply { gain }), &[i5, plate]);
    graph.add(over(), &[object, i6])
}
