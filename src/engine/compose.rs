//! Runs the graph over strips as they arrive: each node keeps a window of the
//! rows it produced, as long as a consumer's halo still needs them.

use super::graph::{Graph, Node};
use super::strip::Rows;
use exr::meta::attribute::{ChannelDescription, IntegerBounds};
use std::ops::Range;

/// One frame's evaluation state.
pub struct Composer<'g> {
    graph: &'g Graph,
    /// Per node: the rows it has produced and still keeps.
    windows: Vec<Rows>,
    /// Rows of the output node already handed out.
    emitted: i32,
    /// The end of the strips pushed so far.
    fed: i32,
    /// Output rows are handed out in whole multiples of this (a block).
    emit_multiple: usize,
    window: IntegerBounds,
}

impl<'g> Composer<'g> {
    /// `channels[n]` and `valid[n]`: each node's channels and data window.
    pub fn new(
        graph: &'g Graph,
        window: IntegerBounds,
        channels: &[Vec<ChannelDescription>],
        valid: &[IntegerBounds],
        emit_multiple: usize,
    ) -> Self {
        let top = window.position.y();
        let windows = (0..graph.nodes.len())
            .map(|n| {
                Rows::zeros(
                    window.position.x(),
                    top,
                    window.size.width(),
                    0,
                    channels[n].clone(),
                    valid[n],
                )
            })
            .collect();
        Composer {
            graph,
            windows,
            emitted: top,
            fed: top,
            emit_multiple,
            window,
        }
    }

    fn bottom(&self) -> i32 {
        self.window.end().y()
    }

    /// Takes strip `rows` of every input and returns the output rows that
    /// became complete, if any.
    pub fn push(&mut self, frame: i64, rows: Range<i32>, strips: Vec<Rows>) -> Option<Rows> {
        let mut strips: Vec<Option<Rows>> = strips.into_iter().map(Some).collect();
        self.fed = rows.end;
        for n in 0..self.graph.nodes.len() {
            match &self.graph.nodes[n] {
                Node::Input(i) => {
                    let strip = strips[*i].take().expect("one strip per input");
                    self.windows[n].append(strip);
                }
                Node::Op { op, inputs } => {
                    let halo = op.halo() as i32;
                    // A source (no inputs) produces as far as the inputs were fed.
                    let ready = inputs
                        .iter()
                        .map(|&i| self.windows[i].end())
                        .min()
                        .unwrap_or(self.fed);
                    let end = if ready >= self.bottom() {
                        ready
                    } else {
                        ready - halo
                    };
                    let start = self.windows[n].end();
                    if end > start {
                        let node = &self.windows[n];
                        let mut out = Rows::zeros(
                            node.x,
                            start,
                            node.width,
                            (end - start) as usize,
                            node.channels.clone(),
                            node.valid,
                        );
                        let args: Vec<&Rows> = inputs.iter().map(|&i| &self.windows[i]).collect();
                        op.compute(frame, &args, &mut out);
                        self.windows[n].append(out);
                    }
                }
            }
        }
        let result = self.take_output();
        self.forget_used_rows();
        result
    }

    fn take_output(&mut self) -> Option<Rows> {
        let out = &self.windows[self.graph.output()];
        let top = self.window.position.y();
        let mut end = out.end();
        if end < self.bottom() {
            let m = self.emit_multiple as i32;
            end = top + (end - top) / m * m;
        }
        if end <= self.emitted {
            return None;
        }
        let rows = out.copy_rows(self.emitted..end);
        self.emitted = end;
        Some(rows)
    }

    /// Drops rows no consumer will read again.
    fn forget_used_rows(&mut self) {
        let n_nodes = self.graph.nodes.len();
        let mut keep_from: Vec<i32> = vec![i32::MAX; n_nodes];
        keep_from[self.graph.output()] = self.emitted;
        for (n, node) in self.graph.nodes.iter().enumerate() {
            if let Node::Op { op, inputs } = node {
                let next_needed = self.windows[n].end() - op.halo() as i32;
                for &i in inputs {
                    keep_from[i] = keep_from[i].min(next_needed);
                }
            }
        }
        for (window, from) in self.windows.iter_mut().zip(keep_from) {
            window.drop_rows_before(from);
        }
    }
}
