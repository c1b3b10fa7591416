//! Two-input merges, A (top) with B (bottom): the Porter-Duff operators and
//! the arithmetic ones, as in Nuke's Merge. Formulas: specs/ops.md, "merge".

use super::declare::{choice, input, params, Args, Operation, Value};
use super::layers::{Layer, Selection};
use crate::engine::graph::{intersection, union, GraphBuilder, NodeId, Op};
use crate::io::rows::{Extent, Rows, RowsMut};
use crate::io::text::Utf8Text;
use crate::params::MIX;
use exr::meta::attribute::{ChannelDescription, IntegerBounds, SampleType};
use std::ops::Range;

/// Runs `$body` with `$op` a constant of `$value`'s operator: one copy of
/// the loop per operator, its formula inlined, so that each vectorises.
macro_rules! by_operator {
    ($value:expr, $op:ident => $body:block) => {
        by_operator!(@arms $value, $op, $body, Over Under In Out Atop Xor Plus Minus From
            Multiply Screen Max Min Difference Divide Mask Stencil Copy)
    };
    (@arms $value:expr, $op:ident, $body:block, $($variant:ident)*) => {
        match $value {
            $(MergeOp::$variant => {
                const $op: MergeOp = MergeOp::$variant;
                $body
            })*
        }
    };
}

pub const OVER: Operation = Operation {
    name: "over",
    about: "Composite FG over BG: C = Cfg + (1 - Afg) Cbg (premultiplied)",
    inputs: &[
        input(
            "fg",
            "Foreground: a file or a sequence (fg.####.exr, fg.%04d.exr), with `:PART` \
             (name or index) to read one part of a multi-part file",
        ),
        input(
            "bg",
            "Background: its header, display window and other channels are kept",
        ),
    ],
    repeats: false,
    params: OverParams::PARAMS,
    layers: true,
    straight: true,
    header: Some(1),
    build: |args, graph, inputs| {
        let mix = OverParams::read(args)?.mix;
        Ok(graph.add(merge(args, MergeOp::Over, mix), inputs))
    },
    measure: None,
};

pub const MERGE: Operation = Operation {
    name: "merge",
    about: "Merge A (top) with B (bottom) by an operator, as Nuke's Merge does",
    inputs: &[
        input("a", "Top input: a file or sequence, `:PART` for a part"),
        input(
            "b",
            "Bottom input: its header, display window and other channels are kept",
        ),
    ],
    repeats: false,
    params: Params::PARAMS,
    layers: true,
    straight: true,
    header: Some(1),
    build: |args, graph, inputs| {
        let p = Params::read(args)?;
        Ok(graph.add(merge(args, p.operator, p.mix), inputs))
    },
    measure: None,
};

pub const STACK: Operation = Operation {
    name: "stack",
    about: "Composite layers L1 over L2 over ... Ln in one pass (L1 on top)",
    inputs: &[input(
        "inputs",
        "Two or more inputs, top first; the last one's header is kept",
    )],
    repeats: true,
    params: &[],
    layers: true,
    straight: true,
    header: None,
    build: |args, graph, inputs| {
        Ok(push_stack(graph, inputs, || {
            merge(args, MergeOp::Over, 1.0)
        }))
    },
    measure: None,
};

params! {
    /// Merge's with the operator fixed.
    pub struct OverParams {
        /// Blend the result with B: 0 gives B, 1 the result.
        mix: f32 [MIX] = "1",
    }
}

params! {
    pub struct Params {
        /// The operator (specs/ops.md): over, under, in, out, atop, xor, plus,
        /// minus, from, multiply, screen, max, min, difference, divide, mask,
        /// stencil, copy.
        operator: MergeOp,
        /// Blend the result with B: 0 gives B, 1 the result.
        mix: f32 [MIX] = "1",
    }
}

fn merge(args: &Args, op: MergeOp, mix: f32) -> Merge {
    Merge {
        op,
        straight: args.straight,
        mix,
        layers: args.layers.clone(),
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MergeOp {
    Over,
    Under,
    In,
    Out,
    Atop,
    Xor,
    Plus,
    Minus,
    From,
    Multiply,
    Screen,
    Max,
    Min,
    Difference,
    Divide,
    Mask,
    Stencil,
    Copy,
}

impl Value for MergeOp {
    fn parse(text: &str) -> Result<Self, String> {
        use MergeOp::*;
        let all = [
            Over, Under, In, Out, Atop, Xor, Plus, Minus, From, Multiply, Screen, Max, Min,
            Difference, Divide, Mask, Stencil, Copy,
        ];
        choice(text, Self::CHOICES, &all, "operator")
    }
    const CHOICES: &'static [&'static str] = &[
        "over",
        "under",
        "in",
        "out",
        "atop",
        "xor",
        "plus",
        "minus",
        "from",
        "multiply",
        "screen",
        "max",
        "min",
        "difference",
        "divide",
        "mask",
        "stencil",
        "copy",
    ];
}

/// `w · x`: 0 where the weight `w` is 0 whatever `x` is (an infinity or a
/// NaN under an opaque or empty alpha is not taken: 0 · ∞ would be NaN),
/// and `x` exactly (a NaN's payload too) where it is 1.
#[inline(always)]
fn times(w: f32, x: f32) -> f32 {
    // Computed, then chosen: selects, so that rows vectorise.
    let r = w * x;
    let r = if w == 1.0 { x } else { r };
    if w == 0.0 {
        0.0
    } else {
        r
    }
}

/// `x + w · y`, exactly `x` (its bits: −0, a NaN's payload) where `w` is 0.
#[inline(always)]
fn plus(x: f32, w: f32, y: f32) -> f32 {
    let r = x + w * y;
    if w == 0.0 {
        x
    } else {
        r
    }
}

/// Which inputs' data windows bound the result (where it can be nonzero).
enum Bounds {
    Union,
    Intersection,
    A,
    B,
}

impl MergeOp {
    /// Colour from premultiplied colours `a`, `b` and alphas `aa`, `ab`.
    #[inline(always)]
    pub fn colour(self, a: f32, aa: f32, b: f32, ab: f32) -> f32 {
        use MergeOp::*;
        match self {
            Over => plus(a, 1.0 - aa, b),
            Under => plus(b, 1.0 - ab, a),
            In => times(ab, a),
            Out => times(1.0 - ab, a),
            Atop => plus(times(ab, a), 1.0 - aa, b),
            Xor => plus(times(1.0 - ab, a), 1.0 - aa, b),
            Plus => a + b,
            Minus => a - b,
            From => b - a,
            Multiply => a * b,
            // Above 1 on both sides the formula would darken: take the larger.
            Screen if a > 1.0 && b > 1.0 => a.max(b),
            Screen => a + b - a * b,
            Max => a.max(b),
            Min => a.min(b),
            Difference => (a - b).abs(),
            Divide if b == 0.0 => 0.0,
            Divide => a / b,
            Mask => times(aa, b),
            Stencil => times(1.0 - aa, b),
            Copy => a,
        }
    }

    /// Result alpha: the colour formula applied to the alphas (which is the
    /// Porter-Duff alpha for the compositing operators).
    #[inline(always)]
    pub fn alpha(self, aa: f32, ab: f32) -> f32 {
        use MergeOp::*;
        match self {
            // a·αB + B(1 - αA) on alphas is αB, up to rounding.
            Atop => ab,
            _ => self.colour(aa, aa, ab, ab),
        }
    }

    /// Whether a transparent black A (colour and alpha 0) leaves B as it is.
    fn keeps_b_under_nothing(self) -> bool {
        use MergeOp::*;
        matches!(self, Over | Under | Atop | Xor | Plus | From | Stencil)
    }

    fn bounds(self) -> Bounds {
        use MergeOp::*;
        match self {
            In | Mask | Multiply | Divide => Bounds::Intersection,
            Out | Copy => Bounds::A,
            Atop | Stencil => Bounds::B,
            _ => Bounds::Union,
        }
    }
}

crate::simd::avx2_where_there! {
    /// `colour` over a row, premultiplied and unmixed, into `a`; with
    /// `keep_b`, B exactly where A is transparent black. One loop per
    /// operator and per `keep_b`, free of branches: it vectorises.
    fn colour_row(op: MergeOp, a: &mut [f32], aa: &[f32], b: &[f32], ab: &[f32], keep_b: bool) {
        #[inline(always)]
        fn row<const KEEP_B: bool>(op: MergeOp, a: &mut [f32], aa: &[f32], b: &[f32], ab: &[f32]) {
            let (aa, b, ab) = (&aa[..a.len()], &b[..a.len()], &ab[..a.len()]);
            for x in 0..a.len() {
                let r = op.colour(a[x], aa[x], b[x], ab[x]);
                let keep = KEEP_B & (aa[x] == 0.0) & (a[x] == 0.0);
                a[x] = if keep { b[x] } else { r };
            }
        }
        by_operator!(op, OP => {
            if keep_b {
                row::<true>(OP, a, aa, b, ab)
            } else {
                row::<false>(OP, a, aa, b, ab)
            }
        })
    }
}

crate::simd::avx2_where_there! {
    /// `alpha` over a row, unmixed, into `ar`; with `keep_b`, B's where A's
    /// is 0.
    fn alpha_row(op: MergeOp, aa: &[f32], ab: &[f32], ar: &mut [f32], keep_b: bool) {
        #[inline(always)]
        fn row<const KEEP_B: bool>(op: MergeOp, aa: &[f32], ab: &[f32], ar: &mut [f32]) {
            let (aa, ab) = (&aa[..ar.len()], &ab[..ar.len()]);
            for x in 0..ar.len() {
                let r = op.alpha(aa[x], ab[x]);
                ar[x] = if KEEP_B & (aa[x] == 0.0) { ab[x] } else { r };
            }
        }
        by_operator!(op, OP => {
            if keep_b {
                row::<true>(OP, aa, ab, ar)
            } else {
                row::<false>(OP, aa, ab, ar)
            }
        })
    }
}

/// Nodes `layers` (top first) composited with `over()`, bottom up: returns
/// the last merge.
fn push_stack(graph: &mut GraphBuilder, layers: &[NodeId], over: impl Fn() -> Merge) -> NodeId {
    let (bottom, above) = layers.split_last().expect("a stack has layers");
    above
        .iter()
        .rev()
        .fold(*bottom, |below, &layer| graph.add(over(), &[layer, below]))
}

#[derive(Debug)]
pub struct Merge {
    pub op: MergeOp,
    /// Inputs and output are straight colour: premultiply, merge, unpremultiply.
    pub straight: bool,
    /// 0..1: the result blended with B (1: the result alone).
    pub mix: f32,
    pub layers: Selection,
}

/// What an output channel is.
#[derive(Clone, Copy)]
enum Role {
    Colour(usize),
    Alpha(usize),
    FromB,
}

impl Merge {
    fn roles(&self, channels: &[ChannelDescription], layers: &[Layer]) -> Vec<Role> {
        channels
            .iter()
            .map(|c| {
                let name = c.name.utf8();
                layers
                    .iter()
                    .enumerate()
                    .find_map(|(l, layer)| {
                        if layer.colours().any(|n| n == name) {
                            Some(Role::Colour(l))
                        } else if layer.alpha_channel() == name {
                            Some(Role::Alpha(l))
                        } else {
                            None
                        }
                    })
                    .unwrap_or(Role::FromB)
            })
            .collect()
    }

    /// Where the result keeps B exactly: a transparent black A under an
    /// operator that leaves B alone, with nothing to blend.
    fn b_passes(&self) -> bool {
        self.op.keeps_b_under_nothing() && !self.straight
    }
}

impl Op for Merge {
    /// B's channels, plus the selected layers' R, G, B, A that only A has.
    fn channels(&self, inputs: &[&[ChannelDescription]]) -> Vec<ChannelDescription> {
        let (a, b) = (inputs[0], inputs[1]);
        let mut out = b.to_vec();
        for layer in self.layers.resolve(inputs) {
            for name in layer.colours().chain([layer.alpha_channel()]) {
                let in_b = b.iter().any(|c| c.name.is(name.as_str()));
                if let Some(c) = a
                    .iter()
                    .find(|c| c.name.is(name.as_str()))
                    .filter(|_| !in_b)
                {
                    out.push(c.clone());
                }
            }
        }
        out.sort_by(|x, y| x.name.bytes().cmp(y.name.bytes()));
        out
    }

    fn check(&self, inputs: &[&[ChannelDescription]]) -> Result<(), String> {
        self.layers.check(inputs)
    }

    /// A top input without alpha, where the operator reads its alpha: it is
    /// opaque inside its data window, hiding B there.
    fn assumptions(
        &self,
        names: &[String],
        inputs: &[&[ChannelDescription]],
        _: &[IntegerBounds],
    ) -> Vec<String> {
        if !matches!(self.op, MergeOp::Over | MergeOp::Atop | MergeOp::Xor) {
            return Vec::new();
        }
        let has = |name: &String| inputs[0].iter().any(|c| c.name.is(name.as_str()));
        self.layers
            .resolve(inputs)
            .iter()
            .filter(|layer| layer.colours().any(|c| has(&c)) && !layer.alphas.iter().any(has))
            .map(|layer| {
                format!(
                    "{} has no alpha channel ({}): it is taken as opaque (alpha 1 inside its \
                     data window), hiding {} there; to add its colour instead use merge --op \
                     plus, or choose the layer holding its alpha with --layer",
                    names[0],
                    layer.alpha_channel(),
                    names[1]
                )
            })
            .collect()
    }

    fn data_window(&self, inputs: &[IntegerBounds]) -> IntegerBounds {
        let (a, b) = (inputs[0], inputs[1]);
        let window = match self.op.bounds() {
            Bounds::Union => union(a, b),
            Bounds::Intersection => intersection(a, b),
            Bounds::A => a,
            Bounds::B => b,
        };
        if self.mix < 1.0 {
            union(window, b)
        } else {
            window
        }
    }

    fn passes_second(&self) -> bool {
        self.b_passes()
    }

    fn hides_nothing(&self, a: &Rows, b: &[ChannelDescription], rows: Range<i32>) -> bool {
        let layers = self.layers.resolve(&[a.channels.as_slice(), b]);
        rows.into_iter()
            .all(|y| visible_columns(a, &layers, y).is_empty())
    }

    /// Over: a + (1 − αa) b is a exactly where αa = 1 (the weight 0 drops b,
    /// an infinity or NaN too), and its alpha 1; copy is a, αa everywhere.
    /// Straight colour divides by the alpha (which quiets a signalling NaN),
    /// a mix below 1 and a channel from B alone bring B in.
    fn may_hide_second(&self, inputs: &[&[ChannelDescription]]) -> bool {
        let layers = self.layers.resolve(inputs);
        matches!(self.op, MergeOp::Over | MergeOp::Copy)
            && !self.straight
            && self.mix == 1.0
            && self
                .roles(&self.channels(inputs), &layers)
                .iter()
                .all(|role| !matches!(role, Role::FromB))
    }

    fn hides_second(
        &self,
        a: &Rows,
        b: &[ChannelDescription],
        rows: Range<i32>,
        columns: Range<i32>,
    ) -> bool {
        let v = a.valid;
        let inside = v.position.y() <= rows.start
            && rows.end <= v.end().y()
            && v.position.x() <= columns.start
            && columns.end <= v.end().x()
            && a.y <= rows.start
            && rows.end <= a.end()
            && a.x <= columns.start
            && columns.end <= a.x + a.width as i32;
        if !inside || self.op == MergeOp::Copy {
            return inside;
        }
        let layers = self.layers.resolve(&[a.channels.as_slice(), b]);
        let from = (columns.start - a.x) as usize..(columns.end - a.x) as usize;
        rows.into_iter()
            .all(|y| layers.iter().all(|l| opaque(a, l, y, from.clone())))
    }

    fn compute(&self, _frame: i64, inputs: &[&Rows], out: &mut RowsMut) -> Result<(), String> {
        let (a, b) = (inputs[0], inputs[1]);
        let lists = [a.channels.as_slice(), b.channels.as_slice()];
        let layers = self.layers.resolve(&lists);
        let roles = self.roles(out.channels, &layers);
        let columns = out.valid_columns();
        let w = columns.len();
        let mut alphas = vec![(vec![0.0f32; w], vec![0.0f32; w], vec![0.0f32; w]); layers.len()];
        let (mut ca, mut cb) = (vec![0.0f32; w], vec![0.0f32; w]);
        let keep_b = self.b_passes();
        // Where A hides B along a whole row (`hides_second`) the result is
        // A's samples, copied rather than blended: the same bits (half and
        // float alone: a u32 through f32 would round).
        let copies_a = self.may_hide_second(&lists)
            && out.channels.iter().all(|c| {
                let kind = c.sample_type;
                matches!(kind, SampleType::F16 | SampleType::F32)
                    && a.channel_index(&c.name.utf8())
                        .is_some_and(|i| a.channels[i].sample_type == kind)
            });
        for y in out.valid_rows() {
            if copies_a && self.hides_row(a, &layers, y, &columns) {
                copy_row(out, a, y, &columns);
                continue;
            }
            // Where A is transparent black, B passes as it is (bit for bit);
            // only the columns between A's first and last visible pixels blend.
            let span = if keep_b {
                let s = visible_columns(a, &layers, y);
                s.start.max(columns.start)..s.end.min(columns.end).max(columns.start)
            } else {
                columns.clone()
            };
            // An empty span sits at the end, so the side before it is the row.
            let span = if span.is_empty() {
                columns.end..columns.end
            } else {
                span
            };
            for side in [columns.start..span.start, span.end..columns.end] {
                if !side.is_empty() {
                    pass_b(out, b, &roles, &layers, y, side, &mut cb);
                }
            }
            if span.is_empty() {
                continue;
            }
            let n = span.len();
            let at = |rows: &Extent| {
                let r = rows.row_range(y);
                r.start + span.start..r.start + span.end
            };
            for (layer, (aa, ab, ar)) in layers.iter().zip(alphas.iter_mut()) {
                layer.read_alpha(a, y, span.start, &mut aa[..n]);
                layer.read_alpha(b, y, span.start, &mut ab[..n]);
                alpha_row(self.op, &aa[..n], &ab[..n], &mut ar[..n], keep_b);
                if self.mix != 1.0 {
                    for x in (0..n).filter(|&x| !(keep_b && aa[x] == 0.0)) {
                        ar[x] = blend(ar[x], ab[x], self.mix);
                    }
                }
            }
            let dst = at(out);
            for (c, role) in roles.iter().enumerate() {
                let name = out.channels[c].name.utf8();
                match *role {
                    Role::Alpha(l) => out.planes[c].write_f32(dst.clone(), &alphas[l].2[..n]),
                    Role::Colour(l) => {
                        let (aa, ab, ar) = &alphas[l];
                        read_or_zero(a, &name, at(a), &mut ca[..n]);
                        read_or_zero(b, &name, at(b), &mut cb[..n]);
                        if self.straight || self.mix != 1.0 {
                            for x in 0..n {
                                ca[x] = self.colour(ca[x], aa[x], cb[x], ab[x], ar[x]);
                            }
                        } else {
                            colour_row(self.op, &mut ca[..n], &aa[..n], &cb[..n], &ab[..n], keep_b);
                        }
                        out.planes[c].write_f32(dst.clone(), &ca[..n]);
                    }
                    Role::FromB => {
                        let s = b.channel_index(&name).expect("the channel comes from B");
                        out.planes[c]
                            .bytes_mut(dst.clone())
                            .copy_from_slice(b.planes[s].bytes(at(b)));
                    }
                }
            }
        }
        Ok(())
    }
}

impl Merge {
    /// Whether A hides B over sample offsets `columns` of row `y`: inside
    /// A's data window, and (but for copy) opaque in every layer.
    fn hides_row(&self, a: &Rows, layers: &[Layer], y: i32, columns: &Range<usize>) -> bool {
        let inside = a.valid_columns();
        a.valid_row(y)
            && inside.start <= columns.start
            && columns.end <= inside.end
            && (self.op == MergeOp::Copy || layers.iter().all(|l| opaque(a, l, y, columns.clone())))
    }
}

/// Copies A's samples of row `y`, sample offsets `columns`, into each
/// channel of `out` of the same name.
fn copy_row(out: &mut RowsMut, a: &Rows, y: i32, columns: &Range<usize>) {
    let at = |rows: &Extent| {
        let r = rows.row_range(y);
        r.start + columns.start..r.start + columns.end
    };
    let dst = at(out);
    for c in 0..out.channels.len() {
        let s = a
            .channel_index(&out.channels[c].name.utf8())
            .expect("every channel is A's");
        out.planes[c]
            .bytes_mut(dst.clone())
            .copy_from_slice(a.planes[s].bytes(at(a)));
    }
}

/// Copies B's samples of row `y`, sample offsets `columns`, into `out`; an
/// alpha only A has takes B's alpha as B implies it, colours only A has stay 0.
fn pass_b(
    out: &mut RowsMut,
    b: &Rows,
    roles: &[Role],
    layers: &[Layer],
    y: i32,
    columns: Range<usize>,
    scratch: &mut [f32],
) {
    let at = |rows: &Extent| {
        let r = rows.row_range(y);
        r.start + columns.start..r.start + columns.end
    };
    let dst = at(out);
    for (c, role) in roles.iter().enumerate() {
        match (b.channel_index(&out.channels[c].name.utf8()), role) {
            (Some(s), _) => out.planes[c]
                .bytes_mut(dst.clone())
                .copy_from_slice(b.planes[s].bytes(at(b))),
            (None, Role::Alpha(l)) => {
                let alpha = &mut scratch[..columns.len()];
                layers[*l].read_alpha(b, y, columns.start, alpha);
                out.planes[c].write_f32(dst.clone(), alpha);
            }
            (None, _) => {}
        }
    }
}

impl Merge {
    /// One colour sample: `a`, `b` as stored, `ar` the result alpha.
    fn colour(&self, a: f32, aa: f32, b: f32, ab: f32, ar: f32) -> f32 {
        if self.b_passes() && aa == 0.0 && a == 0.0 {
            // B exactly (the formula gives it too, but for a -0 in B).
            return b;
        }
        if !self.straight {
            return blend(self.op.colour(a, aa, b, ab), b, self.mix);
        }
        let (a, b) = (times(aa, a), times(ab, b));
        let premultiplied = blend(self.op.colour(a, aa, b, ab), b, self.mix);
        if ar == 0.0 {
            0.0
        } else {
            premultiplied / ar
        }
    }
}

/// `mix` of the result over B: exactly the result at 1.
fn blend(result: f32, b: f32, mix: f32) -> f32 {
    if mix == 1.0 {
        result
    } else {
        b + mix * (result - b)
    }
}

/// The first and last nonzero byte of `bytes`, looked for 64 at a time.
fn nonzero_bytes(bytes: &[u8]) -> Option<(usize, usize)> {
    const BLOCK: usize = 64;
    let zero = |chunk: &[u8]| chunk.iter().fold(0, |acc, &v| acc | v) == 0;
    let first = bytes.chunks(BLOCK).position(|c| !zero(c))? * BLOCK;
    let first = first + bytes[first..].iter().position(|&v| v != 0)?;
    // Chunk k from the end spans `len - (k + 1)·BLOCK .. len - k·BLOCK`.
    let end = bytes.len() - bytes.rchunks(BLOCK).position(|c| !zero(c))? * BLOCK;
    let start = end.saturating_sub(BLOCK);
    let last = start + bytes[start..end].iter().rposition(|&v| v != 0)?;
    Some((first, last))
}

fn read_or_zero(rows: &Rows, name: &str, range: Range<usize>, out: &mut [f32]) {
    match rows.channel_index(name) {
        Some(c) => rows.planes[c].read_f32(range, out),
        None => out.fill(0.0),
    }
}

/// Whether `layer`'s alpha is exactly 1 in sample offsets `columns` of row
/// `y` of `rows` (inside its data window), compared as stored: 1 of any
/// sample type, no NaN. Without an alpha channel it is 1 there.
fn opaque(rows: &Rows, layer: &Layer, y: i32, columns: Range<usize>) -> bool {
    let Some(c) = layer.alphas.iter().find_map(|n| rows.channel_index(n)) else {
        return true;
    };
    let start = rows.row_range(y).start;
    let bytes = rows.planes[c].bytes(start + columns.start..start + columns.end);
    match rows.channels[c].sample_type {
        SampleType::F16 => all_are(bytes, [0x00, 0x3c]),
        SampleType::F32 => all_are(bytes, [0x00, 0x00, 0x80, 0x3f]),
        SampleType::U32 => all_are(bytes, [1, 0, 0, 0]),
    }
}

/// Whether every `N`-byte sample of `bytes` is `one`: compared as arrays,
/// one integer compare a sample (as slices, a `memcmp` call each: 15% of a
/// 4K over-dense frame's instructions).
fn all_are<const N: usize>(bytes: &[u8], one: [u8; N]) -> bool {
    bytes.as_chunks::<N>().0.iter().all(|sample| *sample == one)
}

/// The sample offsets of row `y` from A's first to its last pixel that is
/// not transparent black in the selected layers (empty when A is transparent
/// black all along). Transparent black: outside the data window, or every
/// colour and alpha sample +0 with an alpha channel present.
fn visible_columns(rows: &Rows, layers: &[Layer], y: i32) -> Range<usize> {
    if !rows.valid_row(y) {
        return 0..0;
    }
    let mut span = rows.width..0;
    for layer in layers {
        if !layer.alphas.iter().any(|n| rows.channel_index(n).is_some()) {
            return rows.valid_columns();
        }
        for c in layer
            .colours()
            .chain(layer.alphas.iter().cloned())
            .filter_map(|n| rows.channel_index(&n))
        {
            let bytes = rows.planes[c].bytes(rows.row_range(y));
            let size = rows.channels[c].sample_type.bytes_per_sample();
            if let Some((first, last)) = nonzero_bytes(bytes) {
                span = span.start.min(first / size)..span.end.max(last / size + 1);
            }
        }
    }
    if span.is_empty() {
        0..0
    } else {
        span
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ops::testing::{compute, image_in, sample, Pixel};

    /// The table of specs/ops.md, written out again: colour and alpha of
    /// each operator, and its data window rule.
    fn reference(op: &str, a: f32, aa: f32, b: f32, ab: f32) -> (f32, f32) {
        let f = |a: f32, aa: f32, b: f32, ab: f32| -> f32 {
            match op {
                "over" => a + (1.0 - aa) * b,
                "under" => b + (1.0 - ab) * a,
                "in" => a * ab,
                "out" => a * (1.0 - ab),
                "atop" => a * ab + b * (1.0 - aa),
                "xor" => a * (1.0 - ab) + b * (1.0 - aa),
                "plus" => a + b,
                "minus" => a - b,
                "from" => b - a,
                "multiply" => a * b,
                "screen" if a > 1.0 && b > 1.0 => a.max(b),
                "screen" => a + b - a * b,
                "max" => a.max(b),
                "min" => a.min(b),
                "difference" => (a - b).abs(),
                "divide" if b == 0.0 => 0.0,
                "divide" => a / b,
                "mask" => b * aa,
                "stencil" => b * (1.0 - aa),
                "copy" => a,
                _ => unreachable!("{op}"),
            }
        };
        let alpha = if op == "atop" { ab } else { f(aa, aa, ab, ab) };
        (f(a, aa, b, ab), alpha)
    }

    fn window_rule(op: &str) -> &'static str {
        match op {
            "in" | "mask" | "multiply" | "divide" => "intersection",
            "out" | "copy" => "A",
            "atop" | "stencil" => "B",
            _ => "union",
        }
    }

    fn close(x: f32, y: f32) -> bool {
        x == y || (x - y).abs() <= 1e-6 * x.abs().max(y.abs()).max(1.0)
    }

    // Colours that cross 0 and 1, alphas from 0 to above 1 and negative.
    fn colour_a(x: i32, y: i32) -> f32 {
        [0.25, -0.5, 1.5, 0.0, 3.0, 0.75][((x + 2 * y) % 6) as usize]
    }
    fn alpha_a(x: i32, y: i32) -> f32 {
        [0.5, 0.0, 1.0, 0.25, 1.25, 0.0][((2 * x + y) % 6) as usize]
    }
    fn colour_b(x: i32, y: i32) -> f32 {
        [2.0, 0.5, 0.0, -0.25, 1.0, 4.0, 0.125][((x + y) % 7) as usize]
    }
    fn alpha_b(x: i32, y: i32) -> f32 {
        [1.0, 0.5, 0.0, 0.75, -0.5][((x * y + x) % 5) as usize]
    }

    /// A and B on overlapping windows inside 10 x 6 rows.
    fn inputs() -> (Rows, Rows) {
        let side = |window, colour: Pixel, alpha: Pixel| {
            let channels = [("A", alpha), ("B", colour), ("G", colour), ("R", colour)];
            image_in(0..10, 0..6, window, &channels)
        };
        (
            side(IntegerBounds::new((0, 0), (6, 4)), &colour_a, &alpha_a),
            side(IntegerBounds::new((3, 1), (7, 5)), &colour_b, &alpha_b),
        )
    }

    fn merge(op: MergeOp, mix: f32, straight: bool) -> Merge {
        Merge {
            op,
            straight,
            mix,
            layers: Selection::default(),
        }
    }

    /// Every pixel of `op` over the inputs against `expected(a, αa, b, αb)`.
    fn check_every_pixel(
        name: &str,
        merge: &Merge,
        expected: impl Fn(f32, f32, f32, f32) -> (f32, f32),
    ) {
        let (a, b) = inputs();
        let out = compute(merge, &[&a, &b]).unwrap();
        let window = out.valid;
        for y in 0..6 {
            for x in 0..10 {
                let inside = |w: IntegerBounds| {
                    x >= w.position.x() && x < w.end().x() && y >= w.position.y() && y < w.end().y()
                };
                let get = |rows: &Rows, c: &str| match inside(rows.valid) {
                    true => sample(rows, c, x, y).unwrap(),
                    false => 0.0,
                };
                let (want_c, want_a) =
                    expected(get(&a, "R"), get(&a, "A"), get(&b, "R"), get(&b, "A"));
                let (got_c, got_a) = (get(&out, "R"), get(&out, "A"));
                if inside(window) {
                    assert!(
                        close(got_c, want_c) && close(got_a, want_a),
                        "{name} at {x},{y}: ({got_c}, {got_a}) where ({want_c}, {want_a})"
                    );
                }
            }
        }
    }

    #[test]
    fn every_operator_gives_the_table_s_colour_alpha_and_window() {
        let (a, b) = inputs();
        for name in MergeOp::CHOICES {
            let op = MergeOp::parse(name).unwrap();
            let m = merge(op, 1.0, false);
            check_every_pixel(name, &m, |a, aa, b, ab| reference(name, a, aa, b, ab));
            let window = m.data_window(&[a.valid, b.valid]);
            let want = match window_rule(name) {
                "union" => union(a.valid, b.valid),
                "intersection" => intersection(a.valid, b.valid),
                "A" => a.valid,
                _ => b.valid,
            };
            assert_eq!(window, want, "{name}'s window");
        }
    }

    #[test]
    fn mix_blends_with_b_and_adds_b_s_window() {
        let (a, b) = inputs();
        for name in ["over", "multiply", "copy", "difference"] {
            let op = MergeOp::parse(name).unwrap();
            let m = merge(op, 0.25, false);
            check_every_pixel(name, &m, |a, aa, b, ab| {
                let (c, alpha) = reference(name, a, aa, b, ab);
                (b + 0.25 * (c - b), ab + 0.25 * (alpha - ab))
            });
            let unmixed = merge(op, 1.0, false).data_window(&[a.valid, b.valid]);
            assert_eq!(
                m.data_window(&[a.valid, b.valid]),
                union(unmixed, b.valid),
                "{name}"
            );
        }
    }

    #[test]
    fn straight_colour_is_premultiplied_merged_and_divided_again() {
        for name in ["over", "plus", "screen"] {
            let m = merge(MergeOp::parse(name).unwrap(), 1.0, true);
            check_every_pixel(name, &m, |a, aa, b, ab| {
                let (c, alpha) = reference(name, a * aa, aa, b * ab, ab);
                (if alpha == 0.0 { 0.0 } else { c / alpha }, alpha)
            });
        }
    }

    /// A weight of exactly 0 (an opaque or empty alpha) takes nothing of
    /// the sample it weighs, infinite or NaN; a sample given as it is keeps
    /// its bits (−0, a signalling NaN's payload).
    #[test]
    fn a_zero_weight_takes_nothing_of_an_infinity_or_nan() {
        use MergeOp::*;
        let (inf, snan) = (f32::INFINITY, f32::from_bits(0x7f80_2000));
        let same = |got: f32, want: f32, what: &str| {
            assert_eq!(got.to_bits(), want.to_bits(), "{what}: {got} where {want}")
        };
        for (b, ab) in [(inf, 1.0), (-inf, 0.5), (f32::NAN, inf), (0.25, -inf)] {
            for a in [0.5, -0.0, snan, inf] {
                same(Over.colour(a, 1.0, b, ab), a, "over, opaque A");
                same(Under.colour(b, ab, a, 1.0), a, "under, opaque B");
                same(Atop.colour(a, 1.0, b, 1.0), a, "atop, both opaque");
                same(In.colour(a, ab, b, 1.0), a, "in, opaque B");
                same(Xor.colour(b, 1.0, a, 1.0), 0.0, "xor, both opaque");
                same(In.colour(b, ab, a, 0.0), 0.0, "in, empty B");
                same(Out.colour(b, ab, a, 1.0), 0.0, "out, opaque B");
                same(Mask.colour(b, 0.0, a, ab), 0.0, "mask, empty A");
                same(Stencil.colour(b, 1.0, a, ab), 0.0, "stencil, opaque A");
            }
            same(Over.alpha(1.0, ab), 1.0, "over's alpha, opaque A");
        }
    }

    #[test]
    fn a_transparent_black_a_leaves_b_bit_for_bit_under_the_operators_that_pass_it() {
        let b_window = IntegerBounds::new((0, 0), (4, 2));
        let minus_zero: Pixel = &|x, _| if x == 1 { -0.0 } else { 0.3 };
        let zero: Pixel = &|_, _| 0.0;
        let b = image_in(0..4, 0..2, b_window, &[("A", zero), ("R", minus_zero)]);
        let a = image_in(0..4, 0..2, b_window, &[("A", zero), ("R", zero)]);
        for name in MergeOp::CHOICES {
            let m = merge(MergeOp::parse(name).unwrap(), 1.0, false);
            let passes = m.passes_second();
            assert_eq!(
                passes,
                ["over", "under", "atop", "xor", "plus", "from", "stencil"].contains(name),
                "{name}"
            );
            // Asked only of the operators that pass B.
            if passes {
                assert!(m.hides_nothing(&a, &b.channels, 0..2), "{name}");
                let out = compute(&m, &[&a, &b]).unwrap();
                let bits = sample(&out, "R", 1, 0).unwrap().to_bits();
                assert_eq!(bits, (-0.0f32).to_bits(), "{name} keeps B's -0");
            }
        }
        // A visible pixel anywhere in the rows: the block must be composited.
        let one: Pixel = &|x, y| if (x, y) == (3, 1) { 0.5 } else { 0.0 };
        let visible = image_in(0..4, 0..2, b_window, &[("A", one), ("R", zero)]);
        assert!(!merge(MergeOp::Over, 1.0, false).hides_nothing(&visible, &b.channels, 0..2));
        assert!(merge(MergeOp::Over, 1.0, false).hides_nothing(&visible, &b.channels, 0..1));
    }

    #[test]
    fn channels_are_b_s_plus_the_layer_s_that_only_a_has() {
        let v: Pixel = &|_, _| 1.0;
        let a = image_in(
            0..2,
            0..1,
            IntegerBounds::new((0, 0), (2, 1)),
            &[("A", v), ("R", v), ("Z", v)],
        );
        let b = image_in(
            0..2,
            0..1,
            IntegerBounds::new((0, 0), (2, 1)),
            &[("G", v), ("Y", v)],
        );
        let m = merge(MergeOp::Over, 1.0, false);
        let names: Vec<String> = m
            .channels(&[&a.channels, &b.channels])
            .iter()
            .map(|c| c.name.utf8())
            .collect();
        // A's Z is not composited, so it does not come through.
        assert_eq!(names, ["A", "G", "R", "Y"]);
        let out = compute(&m, &[&a, &b]).unwrap();
        // B without alpha is opaque inside its window: A over it.
        assert_eq!(sample(&out, "A", 0, 0), Some(1.0));
        assert_eq!(sample(&out, "G", 0, 0), Some(0.0));
        assert_eq!(sample(&out, "Y", 1, 0), Some(1.0));
    }
}
