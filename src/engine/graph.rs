//! The node graph a job runs: inputs, operations, and the node that is written.

use crate::io::attributes::Edit;
use crate::io::rows::{Rows, RowsMut};
use exr::meta::attribute::{ChannelDescription, IntegerBounds};
use exr::meta::header::Header;
use std::ops::Range;
use std::sync::Arc;

/// How an image is shown: its display window, and its pixels' width over
/// their height (`pixelAspectRatio`: 2 for an anamorphic 2:1 plate).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Display {
    pub window: IntegerBounds,
    pub pixel_aspect: f32,
}

impl Display {
    /// `window` with square pixels.
    pub fn square(window: IntegerBounds) -> Self {
        Display {
            window,
            pixel_aspect: 1.0,
        }
    }

    /// A header's; a ratio no image can have (0, negative, not finite: a
    /// damaged header) is taken as square pixels.
    pub fn of(header: &Header) -> Self {
        let ratio = header.shared_attributes.pixel_aspect;
        Display {
            window: header.shared_attributes.display_window,
            pixel_aspect: match ratio.is_finite() && ratio > 0.0 {
                true => ratio,
                false => 1.0,
            },
        }
    }
}

/// An operation over strips of rows. Implementations are pure: the output rows
/// depend only on the input rows they are given. Its `Debug` text holds every
/// parameter that changes its result: it is what the frame's fingerprint
/// records of it (`fingerprint.rs`), so it must not hold addresses.
pub trait Op: Send + Sync + std::fmt::Debug {
    /// Rows above and below an output row that the op reads from its inputs.
    fn halo(&self) -> usize {
        0
    }

    /// Columns either side of an output pixel that the op may read from its
    /// inputs: as far as its halo (a neighbourhood reads as far across as
    /// down: blur, defocus, erode, luminance/chroma), unless it moves pixels
    /// sideways (stereo). Grows the columns computed (`Graph::reach`).
    fn across(&self) -> usize {
        self.halo()
    }

    /// Whether the op reads luminance/chroma and luminance-only channels as
    /// such (the conversion to RGB): every other op reads them as whatever
    /// channels they are, so such an input must reach it converted.
    fn reads_luminance(&self) -> bool {
        false
    }

    /// For an op that resamples (resize, transform): the region of its
    /// inputs it reads to compute region `out` of its own (Nuke's
    /// `_request`), unclipped. Its inputs then stream in rows and columns of
    /// their own (`region.rs`). `None`, every other op: it shares its
    /// inputs' rows and columns, reading `halo` rows above and below.
    fn request(&self, _out: IntegerBounds) -> Option<IntegerBounds> {
        None
    }

    /// Bytes a band of it (`band`) allocates while it is computed, besides
    /// the windows: buffers as long as the band, its halo's rows or its
    /// width, freed when the band is done. `memory_bound` counts one band's
    /// per thread, as the threads compute a node's bands at once.
    fn scratch(&self, _band: &Band) -> usize {
        0
    }

    /// The output's channels, given each input's channels: by default the
    /// first input's.
    fn channels(&self, inputs: &[&[ChannelDescription]]) -> Vec<ChannelDescription> {
        inputs[0].to_vec()
    }

    /// Whether the inputs have what the op needs (a layer asked for, say):
    /// the reason when not.
    fn check(&self, _inputs: &[&[ChannelDescription]]) -> Result<(), String> {
        Ok(())
    }

    /// The output's display window and pixel aspect ratio given its
    /// inputs' (a resize's: the new size; a reformat's: the format's), or
    /// `None`: the input's whose header the output keeps, as it is. An
    /// error (a size the op cannot take) ends the frame.
    fn display_window(&self, _inputs: &[Display]) -> Result<Option<Display>, String> {
        Ok(None)
    }

    /// What the op writes on or removes from the output header's
    /// attributes when that header is its input's (`Graph::edits`): a
    /// colour conversion's destination `colorInteropID` and
    /// `chromaticities`. None by default: every attribute as it was.
    fn attributes(&self) -> Vec<Edit> {
        Vec::new()
    }

    /// What the op assumes of inputs that may not be what the user meant
    /// (a foreground without alpha taken as opaque): one warning each,
    /// saying what was assumed and what changes it. `names` says what each
    /// input is (a file, or another node's result).
    fn assumptions(
        &self,
        _names: &[String],
        _inputs: &[&[ChannelDescription]],
        _windows: &[IntegerBounds],
    ) -> Vec<String> {
        Vec::new()
    }

    /// The output's data window, given each input's.
    fn data_window(&self, inputs: &[IntegerBounds]) -> IntegerBounds {
        inputs
            .iter()
            .copied()
            .reduce(union)
            .expect("an operation has inputs")
    }

    /// Whether the result is the second input, bit for bit, wherever the
    /// first is transparent black (merge over, plus...): what lets an output
    /// block be the second input's chunk as it is (`passthrough.rs`).
    fn passes_second(&self) -> bool {
        false
    }

    /// For an op whose result is one input's samples as they are, wherever
    /// both data windows hold them, in the same pixels (a crop, a pad, a
    /// channel rename or drop, a resize to the same size) or moved by whole
    /// pixels (a cut, a placement): what lets an output block be a chunk of
    /// the input below it (`passthrough.rs`); `None` for every other op.
    fn carries(&self, _inputs: &[&[ChannelDescription]]) -> Option<Carried> {
        None
    }

    /// Whether rows `rows` of `first` are transparent black all along, as
    /// this op sees them (given the second input's channels). Asked only of
    /// ops that pass the second input.
    fn hides_nothing(
        &self,
        _first: &Rows,
        _second: &[ChannelDescription],
        _rows: Range<i32>,
    ) -> bool {
        false
    }

    /// Whether, given its inputs' channels, the result can be the first
    /// input bit for bit whatever the second holds, where `hides_second`
    /// says so (merge over and copy, premultiplied, unmixed, every output
    /// channel composited): what lets an output block be the first input's
    /// chunk and the second's go undecoded (`opaque.rs`).
    fn may_hide_second(&self, _inputs: &[&[ChannelDescription]]) -> bool {
        false
    }

    /// Whether the result is `first` bit for bit over rows `rows` and
    /// columns `columns` (absolute), whatever the second input holds there
    /// (given its channels): an opaque foreground. Asked only where
    /// `may_hide_second`.
    fn hides_second(
        &self,
        _first: &Rows,
        _second: &[ChannelDescription],
        _rows: Range<i32>,
        _columns: Range<i32>,
    ) -> bool {
        false
    }

    /// Fills `out` (its rows, columns and channels are set; samples are zero)
    /// for frame `frame`. Each input holds at least rows
    /// `out.y - halo .. out.end() + halo`, clipped to the output's data
    /// window and to the rows computed (those written, grown by the graph's
    /// reach: `frame_plan::computed`; an op reads only the rows it holds), in the
    /// same columns as `out`; for an op that resamples, the
    /// rows and columns `request` gave, clipped to the input's region. An op
    /// without inputs is a source.
    /// An error (bad values in an input, say) ends the frame with its message.
    ///
    /// `out` is one band of the rows the engine needs: it runs the bands of a
    /// node on the thread pool at once, so an op is written single-threaded.
    fn compute(&self, frame: i64, inputs: &[&Rows], out: &mut RowsMut) -> Result<(), String>;
}

/// What a band's scratch depends on (`Op::scratch`): its rows, the columns
/// of its node's region, and each input's channels and region width.
pub struct Band<'a> {
    pub rows: usize,
    pub width: usize,
    pub inputs: &'a [&'a [ChannelDescription]],
    pub widths: &'a [usize],
}

pub enum Node {
    /// The n-th input sequence of the job.
    Input(usize),
    /// An operation on earlier nodes; `origin` says where it came from (a
    /// job file's line and node) for its errors.
    Op {
        op: Box<dyn Op>,
        inputs: Vec<usize>,
        origin: Option<Arc<str>>,
    },
}

impl Node {
    /// `message` (from the node's `check` or `compute`) prefixed with where
    /// the node came from.
    pub fn locate(&self, message: String) -> String {
        match self {
            Node::Op {
                origin: Some(at), ..
            } => format!("{at}: {message}"),
            _ => message,
        }
    }
}

/// A node of a graph being built.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct NodeId(usize);

impl NodeId {
    pub fn index(self) -> usize {
        self.0
    }
}

/// Builds a graph in order, each node after the nodes it reads; the last
/// node added is the output.
#[derive(Default)]
pub struct GraphBuilder {
    nodes: Vec<Node>,
    /// Given to the operations added from now on.
    origin: Option<Arc<str>>,
}

impl GraphBuilder {
    /// A builder whose first nodes are inputs `0..count`.
    pub fn with_inputs(count: usize) -> (Self, Vec<NodeId>) {
        let mut builder = GraphBuilder::default();
        let inputs = (0..count).map(|i| builder.input(i)).collect();
        (builder, inputs)
    }

    pub fn input(&mut self, index: usize) -> NodeId {
        self.nodes.push(Node::Input(index));
        NodeId(self.nodes.len() - 1)
    }

    pub fn add(&mut self, op: impl Op + 'static, inputs: &[NodeId]) -> NodeId {
        self.add_boxed(Box::new(op), inputs)
    }

    pub fn add_boxed(&mut self, op: Box<dyn Op>, inputs: &[NodeId]) -> NodeId {
        self.nodes.push(Node::Op {
            op,
            inputs: inputs.iter().map(|n| n.0).collect(),
            origin: self.origin.clone(),
        });
        NodeId(self.nodes.len() - 1)
    }

    /// Where the operations added from now on came from.
    pub fn locate(&mut self, origin: Option<String>) {
        self.origin = origin.map(Arc::from);
    }

    /// The attribute edits on the way from input `from` to `node`
    /// (`Graph::edits` of the graph ending there): what a job file's node
    /// sees of the header its input brings (`from = "auto"`).
    pub fn edits(&self, from: usize, node: NodeId) -> Vec<Edit> {
        edits(&self.nodes[..=node.0], from)
    }

    /// The graph whose output is the last node added.
    pub fn finish(self) -> Graph {
        assert!(!self.nodes.is_empty(), "a graph has nodes");
        Graph { nodes: self.nodes }
    }
}

/// Nodes in topological order: a node refers only to nodes before it. The last
/// node is the one written.
pub struct Graph {
    pub nodes: Vec<Node>,
}

impl Graph {
    /// The graph of one input, as it is.
    pub fn identity() -> Self {
        GraphBuilder::with_inputs(1).0.finish()
    }

    /// The graph with `add`'s nodes after each input node (given the input's
    /// index and node), its last one read in the input's place by every
    /// node that read it (`--proxy-scale`'s resize, a luminance input's
    /// conversion).
    pub fn after_inputs(self, add: impl Fn(&mut GraphBuilder, usize, NodeId) -> NodeId) -> Graph {
        let mut builder = GraphBuilder::default();
        let mut moved: Vec<usize> = Vec::with_capacity(self.nodes.len());
        for node in self.nodes {
            let id = match node {
                Node::Input(i) => {
                    let input = builder.input(i);
                    add(&mut builder, i, input).0
                }
                Node::Op { op, inputs, origin } => {
                    let inputs = inputs.iter().map(|&n| moved[n]).collect();
                    builder.nodes.push(Node::Op { op, inputs, origin });
                    builder.nodes.len() - 1
                }
            };
            moved.push(id);
        }
        builder.finish()
    }

    pub fn output(&self) -> usize {
        self.nodes.len() - 1
    }

    /// The node of input sequence `i`, if the graph reads it.
    pub fn input_node(&self, i: usize) -> Option<usize> {
        self.nodes
            .iter()
            .position(|n| matches!(n, Node::Input(j) if *j == i))
    }

    /// Whether an operation not converting luminance (`Op::reads_luminance`)
    /// reads input `i` as it is.
    pub fn reads_unconverted(&self, i: usize) -> bool {
        let Some(n) = self.input_node(i) else {
            return false;
        };
        self.nodes.iter().any(|node| {
            matches!(node, Node::Op { op, inputs, .. }
                if inputs.contains(&n) && !op.reads_luminance())
        })
    }

    /// The most that nodes hold at once as compose sweeps them in order,
    /// node `n` holding `size(n)`: from when it is computed until its last
    /// consumer has read it (the output, until it is written).
    pub fn peak(&self, size: impl Fn(usize) -> usize) -> usize {
        let mut last_use: Vec<usize> = (0..self.nodes.len()).collect();
        for (n, node) in self.nodes.iter().enumerate() {
            if let Node::Op { inputs, .. } = node {
                inputs.iter().for_each(|&i| last_use[i] = n);
            }
        }
        let (mut live, mut peak) = (0usize, 0usize);
        for (n, node) in self.nodes.iter().enumerate() {
            live = live.saturating_add(size(n));
            peak = peak.max(live);
            if let Node::Op { inputs, .. } = node {
                for &i in inputs {
                    if last_use[i] == n {
                        live -= size(i);
                    }
                }
            }
        }
        peak
    }

    /// Per node, a value computed from its inputs' values: `input` for input
    /// nodes, `combine(op, values of its inputs)` for operations.
    /// Each node's display window from its inputs' (`input` gives the
    /// graph inputs'), and whether an op changed it on the way: evaluated
    /// before data windows, since an op whose geometry follows them (a
    /// resize's scale) learns them here.
    pub fn display_windows(
        &self,
        input: impl Fn(usize) -> Display,
    ) -> Vec<Result<(Display, bool), String>> {
        self.evaluate(
            |i| Ok((input(i), false)),
            |op, args: &[Result<(Display, bool), String>]| {
                let args: Vec<(Display, bool)> = args.iter().cloned().collect::<Result<_, _>>()?;
                let displays: Vec<Display> = args.iter().map(|a| a.0).collect();
                Ok(match op.display_window(&displays)? {
                    Some(display) => (display, true),
                    None => (
                        displays
                            .last()
                            .copied()
                            .unwrap_or(Display::square(IntegerBounds::zero())),
                        args.iter().any(|a| a.1),
                    ),
                })
            },
        )
    }

    /// The attribute edits (`Op::attributes`) of the ops on the way from
    /// input `from` (whose header the output keeps) to the output, in
    /// order; an op reached from it by more than one way counts once, by
    /// its first input that is.
    pub fn edits(&self, from: usize) -> Vec<Edit> {
        edits(&self.nodes, from)
    }

    /// How far the output reaches into the inputs: the deepest sums of
    /// `across` and of `halo` along any path.
    pub fn reach(&self) -> Reach {
        let sum = |per: fn(&dyn Op) -> usize| {
            let reach = self.evaluate(
                |_| 0usize,
                |op, args: &[usize]| {
                    args.iter()
                        .copied()
                        .max()
                        .unwrap_or(0)
                        .saturating_add(per(op))
                },
            )[self.output()];
            i32::try_from(reach).unwrap_or(i32::MAX)
        };
        Reach {
            across: sum(|op| op.across()),
            down: sum(|op| op.halo()),
        }
    }

    pub fn evaluate<T: Clone>(
        &self,
        input: impl Fn(usize) -> T,
        combine: impl Fn(&dyn Op, &[T]) -> T,
    ) -> Vec<T> {
        evaluate(&self.nodes, input, combine)
    }
}

/// Each of `nodes`' values: an input's from `input`, an op's by `combine`
/// from its inputs' values.
fn evaluate<T: Clone>(
    nodes: &[Node],
    input: impl Fn(usize) -> T,
    combine: impl Fn(&dyn Op, &[T]) -> T,
) -> Vec<T> {
    let mut values: Vec<T> = Vec::with_capacity(nodes.len());
    for node in nodes {
        let value = match node {
            Node::Input(i) => input(*i),
            Node::Op { op, inputs, .. } => {
                let args: Vec<T> = inputs.iter().map(|&n| values[n].clone()).collect();
                combine(op.as_ref(), &args)
            }
        };
        values.push(value);
    }
    values
}

/// `Graph::edits` of the graph `nodes` whose output is their last.
fn edits(nodes: &[Node], from: usize) -> Vec<Edit> {
    let edits = evaluate(
        nodes,
        |i| (i == from).then(Vec::new),
        |op, args: &[Option<Vec<Edit>>]| {
            let mut edits = args.iter().flatten().next()?.clone();
            edits.extend(op.attributes());
            Some(edits)
        },
    );
    edits.last().cloned().flatten().unwrap_or_default()
}

/// What an op keeps of one input's samples (`Op::carries`).
pub struct Carried {
    /// The input whose samples it keeps.
    pub input: usize,
    /// Per output channel, the input channel it carries.
    pub channels: Vec<usize>,
    /// Output pixel (x, y) is input pixel (x + dx, y + dy).
    pub shift: (i32, i32),
}

/// How far a graph's output reads its inputs: columns either side, rows
/// above and below (`Graph::reach`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Reach {
    pub across: i32,
    pub down: i32,
}

/// `rect` grown by `by` on every side (an empty one stays empty), within
/// OpenEXR's coordinates (where every file's windows are): a reach of whole
/// rows (stereo's) leaves its width an i32.
pub fn grow(rect: IntegerBounds, by: Reach) -> IntegerBounds {
    if rect.size.area() == 0 {
        return rect;
    }
    let limit = i32::MAX / 2;
    let out = |start: i32, end: i32, by: i32| {
        let start = start.saturating_sub(by).max(-limit).min(start);
        (
            start,
            (i64::from(end.saturating_add(by).min(limit).max(end)) - i64::from(start)) as usize,
        )
    };
    let (x, width) = out(rect.position.x(), rect.end().x(), by.across);
    let (y, height) = out(rect.position.y(), rect.end().y(), by.down);
    IntegerBounds::new((x, y), (width, height))
}

/// The smallest window holding both; an empty window adds nothing.
pub fn union(a: IntegerBounds, b: IntegerBounds) -> IntegerBounds {
    if a.size.area() == 0 {
        return b;
    }
    if b.size.area() == 0 {
        return a;
    }
    let x0 = a.position.x().min(b.position.x());
    let y0 = a.position.y().min(b.position.y());
    let x1 = a.end().x().max(b.end().x());
    let y1 = a.end().y().max(b.end().y());
    IntegerBounds::new((x0, y0), ((x1 - x0) as usize, (y1 - y0) as usize))
}

/// `w` moved by (dx, dy).
pub fn moved(w: IntegerBounds, (dx, dy): (i32, i32)) -> IntegerBounds {
    IntegerBounds::new((w.position.x() + dx, w.position.y() + dy), w.size)
}

/// The window both cover; empty (zero size at the origin) when they do not
/// meet.
pub fn intersection(a: IntegerBounds, b: IntegerBounds) -> IntegerBounds {
    let x0 = a.position.x().max(b.position.x());
    let y0 = a.position.y().max(b.position.y());
    let x1 = a.end().x().min(b.end().x());
    let y1 = a.end().y().min(b.end().y());
    if a.size.area() == 0 || b.size.area() == 0 || x1 <= x0 || y1 <= y0 {
        return IntegerBounds::zero();
    }
    IntegerBounds::new((x0, y0), ((x1 - x0) as usize, (y1 - y0) as usize))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ops::premult::Premult;

    fn op() -> Box<dyn Op> {
        Box::new(Premult {
            inverse: false,
            layers: Default::default(),
        })
    }

    #[test]
    fn the_peak_counts_only_the_nodes_alive_at_once() {
        // A chain holds a node and its input; a merge of three, all four.
        let (mut chain, inputs) = GraphBuilder::with_inputs(1);
        let mut last = inputs[0];
        for _ in 0..100 {
            last = chain.add_boxed(op(), &[last]);
        }
        assert_eq!(chain.finish().peak(|_| 1), 2);
        let (mut merge, inputs) = GraphBuilder::with_inputs(3);
        merge.add_boxed(op(), &inputs);
        assert_eq!(merge.finish().peak(|_| 1), 4);
        // An input read again further down stays alive until then.
        let (mut reuse, inputs) = GraphBuilder::with_inputs(1);
        let first = reuse.add_boxed(op(), &[inputs[0]]);
        let second = reuse.add_boxed(op(), &[first]);
        reuse.add_boxed(op(), &[second, inputs[0]]);
        assert_eq!(reuse.finish().peak(|n| 10 + n), 10 + 12 + 13);
    }
}
