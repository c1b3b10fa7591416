//! The node graph a job runs: inputs, operations, and the node that is written.

use super::strip::{Rows, RowsMut};
use exr::meta::attribute::{ChannelDescription, IntegerBounds};
use std::ops::Range;

/// An operation over strips of rows. Implementations are pure: the output rows
/// depend only on the input rows they are given.
pub trait Op: Send + Sync {
    /// Rows above and below an output row that the op reads from its inputs.
    fn halo(&self) -> usize {
        0
    }

    /// The output's channels, given each input's channels.
    fn channels(&self, inputs: &[&[ChannelDescription]]) -> Vec<ChannelDescription>;

    /// Whether the inputs have what the op needs (a layer asked for, say):
    /// the reason when not.
    fn check(&self, _inputs: &[&[ChannelDescription]]) -> Result<(), String> {
        Ok(())
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

    /// Fills `out` (its rows, columns and channels are set; samples are zero)
    /// for frame `frame`. Each input holds at least rows
    /// `out.y - halo .. out.end() + halo`, clipped to the output's data
    /// window, in the same columns as `out`. An op without inputs is a source.
    /// An error (bad values in an input, say) ends the frame with its message.
    ///
    /// `out` is one band of the rows the engine needs: it runs the bands of a
    /// node on the thread pool at once, so an op is written single-threaded.
    fn compute(&self, frame: i64, inputs: &[&Rows], out: &mut RowsMut) -> Result<(), String>;
}

pub enum Node {
    /// The n-th input sequence of the job.
    Input(usize),
    /// An operation on earlier nodes.
    Op { op: Box<dyn Op>, inputs: Vec<usize> },
}

/// Nodes in topological order: a node refers only to nodes before it. The last
/// node is the one written.
pub struct Graph {
    pub nodes: Vec<Node>,
}

impl Graph {
    /// `inputs` input nodes (0..inputs), then `ops` in order, each with the
    /// nodes it reads; the last one is written (the last input without ops).
    pub fn chain(inputs: usize, ops: Vec<(Box<dyn Op>, Vec<usize>)>) -> Self {
        let mut nodes: Vec<Node> = (0..inputs).map(Node::Input).collect();
        nodes.extend(ops.into_iter().map(|(op, inputs)| Node::Op { op, inputs }));
        Graph { nodes }
    }

    pub fn output(&self) -> usize {
        self.nodes.len() - 1
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
    pub fn evaluate<T: Clone>(
        &self,
        input: impl Fn(usize) -> T,
        combine: impl Fn(&dyn Op, &[T]) -> T,
    ) -> Vec<T> {
        let mut values: Vec<T> = Vec::with_capacity(self.nodes.len());
        for node in &self.nodes {
            let value = match node {
                Node::Input(i) => input(*i),
                Node::Op { op, inputs } => {
                    let args: Vec<T> = inputs.iter().map(|&n| values[n].clone()).collect();
                    combine(op.as_ref(), &args)
                }
            };
            values.push(value);
        }
        values
    }
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
        let chain = Graph::chain(1, (0..100).map(|n| (op(), vec![n])).collect());
        assert_eq!(chain.peak(|_| 1), 2);
        let merge = Graph::chain(3, vec![(op(), vec![0, 1, 2])]);
        assert_eq!(merge.peak(|_| 1), 4);
        // An input read again further down stays alive until then.
        let reuse = Graph::chain(
            1,
            vec![(op(), vec![0]), (op(), vec![1]), (op(), vec![2, 0])],
        );
        assert_eq!(reuse.peak(|n| 10 + n), 10 + 12 + 13);
    }
}
