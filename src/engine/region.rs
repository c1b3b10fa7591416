//! Regions of interest: the rows and columns each node of a frame's graph
//! streams in. Nodes joined by ops that do not resample share one region, a
//! *zone* (the output's, when nothing resamples: every node then has the
//! output's rows and columns, the constant-halo fast path). An op that
//! resamples (`Op::request`: a resize, a transform) reads a zone of its own:
//! the rectangle its readers request of it, grown by what the graph's halos
//! reach (a blur behind a resize reads beyond it), clipped to its nodes'
//! data. Per output strip, a zone's *span* is the rows requested of it for
//! the strip's rows (grown the same way): what decode reads of an input, and
//! what a strip holds of a node.
//! A zone is read top-down, or bottom-up (*upward*) when its reader's
//! request moves up as the reader's rows go down (a flip, a half turn):
//! decode then reads its input's chunks in reverse and compose computes its
//! nodes bottom row first, so that it holds a span, not the whole input.
//! The rule and the memory bound: specs/architecture.md, "Regions of interest".

use super::graph::{grow, intersection, union, Graph, Node, Reach};
use exr::meta::attribute::IntegerBounds;
use std::ops::Range;

#[derive(Clone)]
pub struct Regions {
    /// Per node, its zone.
    zone: Vec<usize>,
    /// Per zone, the rectangle its nodes' windows cover.
    rects: Vec<IntegerBounds>,
    /// The nodes that resample, in graph order, each with its input's zone.
    resamplers: Vec<(usize, usize)>,
    /// What the graph's halos reach (`Graph::reach`), added around what a
    /// resampler requests: a node of its input's zone may read that far.
    reach: Reach,
    /// Per zone, whether it is read bottom-up.
    upward: Vec<bool>,
}

fn find(parent: &mut [usize], mut n: usize) -> usize {
    while parent[n] != n {
        parent[n] = parent[parent[n]];
        n = parent[n];
    }
    n
}

/// The rows `rows` of `rect`'s columns.
pub fn rows_of(rect: IntegerBounds, rows: &Range<i32>) -> IntegerBounds {
    let height = (rows.end - rows.start).max(0) as usize;
    IntegerBounds::new((rect.position.x(), rows.start), (rect.size.width(), height))
}

fn row_range(rect: IntegerBounds) -> Range<i32> {
    rect.position.y()..rect.end().y()
}

/// `rows` clamped to `within` (empty at its nearer end when outside it).
fn clamp(rows: Range<i32>, within: &Range<i32>) -> Range<i32> {
    let start = rows.start.clamp(within.start, within.end);
    start..rows.end.clamp(start, within.end)
}

impl Regions {
    /// The zones of `graph` whose output covers `output`, given each node's
    /// data window (`valid`). A resampling op must not read a node of its
    /// own zone: that node would stream at two rates at once, holding rows
    /// in proportion to the height.
    pub fn new(
        graph: &Graph,
        output: IntegerBounds,
        valid: &[IntegerBounds],
    ) -> Result<Self, String> {
        let count = graph.nodes.len();
        let mut parent: Vec<usize> = (0..count).collect();
        let mut resampling = vec![false; count];
        for (n, node) in graph.nodes.iter().enumerate() {
            if let Node::Op { op, inputs, .. } = node {
                resampling[n] = op.request(output).is_some();
                if !resampling[n] {
                    for &i in inputs {
                        let (a, b) = (find(&mut parent, n), find(&mut parent, i));
                        parent[a] = b;
                    }
                }
            }
        }
        let mut roots: Vec<usize> = Vec::new();
        let zone: Vec<usize> = (0..count)
            .map(|n| {
                let root = find(&mut parent, n);
                roots.iter().position(|&r| r == root).unwrap_or_else(|| {
                    roots.push(root);
                    roots.len() - 1
                })
            })
            .collect();
        let mut resamplers = Vec::new();
        for (n, node) in graph.nodes.iter().enumerate() {
            if let (true, Node::Op { inputs, .. }) = (resampling[n], node) {
                for &i in inputs {
                    if zone[i] == zone[n] {
                        return Err(
                            "an image is read both resampled (resize, transform...) and as it \
                             is by the same graph: read the file twice (two inputs) instead"
                                .into(),
                        );
                    }
                    resamplers.push((n, zone[i]));
                }
            }
        }
        let mut data = vec![IntegerBounds::zero(); roots.len()];
        for (n, &z) in zone.iter().enumerate() {
            data[z] = union(data[z], valid[n]);
        }
        let output_zone = zone[graph.output()];
        let mut regions = Regions {
            zone,
            rects: vec![IntegerBounds::zero(); roots.len()],
            resamplers,
            reach: graph.reach(),
            upward: vec![false; roots.len()],
        };
        // A zone no resampler reads (an input the graph leaves unread)
        // keeps the output's rows and columns, as every node did before.
        let read: Vec<bool> = (0..roots.len())
            .map(|z| z == output_zone || regions.resamplers.iter().any(|&(_, into)| into == z))
            .collect();
        for (z, rect) in regions.rects.iter_mut().enumerate() {
            if !read[z] {
                *rect = output;
            }
        }
        regions.rects[output_zone] = output;
        // Zones form a DAG: as many passes as zones settle every request.
        for _ in 0..roots.len() {
            for &(n, into) in regions.resamplers.iter().rev() {
                let rect = regions.rects[regions.zone[n]];
                if rect.size.area() == 0 {
                    continue;
                }
                let asked = grow(request(graph, n, rect), regions.reach);
                let asked = intersection(asked, data[into]);
                regions.rects[into] = union(regions.rects[into], asked);
            }
        }
        regions.upward = regions.read_orders(graph);
        Ok(regions)
    }

    /// Per zone, whether it is read bottom-up: its readers' request moves
    /// the other way from their own zone's order. Readers that disagree (a
    /// zone flipped and read as it is) read it top-down, holding it whole
    /// while the other order catches up (as every reversed read did before).
    fn read_orders(&self, graph: &Graph) -> Vec<bool> {
        // Per resampler, whether its request moves up as its rows go down:
        // its first row's footprint lies below its last row's.
        let reverses: Vec<bool> = self
            .resamplers
            .iter()
            .map(|&(n, _)| {
                let rect = self.rect(n);
                let (top, bottom) = (rect.position.y(), rect.end().y());
                let middle = |rows: Range<i32>| {
                    let asked = request(graph, n, rows_of(rect, &rows));
                    asked.position.y() as i64 + asked.end().y() as i64
                };
                bottom - top > 1 && middle(bottom - 1..bottom) < middle(top..top + 1)
            })
            .collect();
        let mut upward = vec![false; self.rects.len()];
        // Zones form a DAG: as many passes as zones settle every order.
        for _ in 0..self.rects.len() {
            let mut wanted: Vec<Option<bool>> = vec![None; self.rects.len()];
            let mut split = vec![false; self.rects.len()];
            for (&(n, into), &reverses) in self.resamplers.iter().zip(&reverses) {
                let order = upward[self.zone[n]] != reverses;
                split[into] |= wanted[into].is_some_and(|w| w != order);
                wanted[into] = Some(order);
            }
            upward = (0..self.rects.len())
                .map(|z| !split[z] && wanted[z] == Some(true))
                .collect();
        }
        upward
    }

    /// Whether node `n`'s zone is read bottom-up.
    pub fn upward(&self, n: usize) -> bool {
        self.upward[self.zone[n]]
    }

    /// Whether every node shares the output's rows and columns.
    pub fn shared(&self) -> bool {
        self.resamplers.is_empty()
    }

    /// The rows and columns node `n`'s window covers.
    pub fn rect(&self, n: usize) -> IntegerBounds {
        self.rects[self.zone[n]]
    }

    /// Per zone, the rows requested of it for output rows `rows` (the
    /// output's zone: `rows` itself), clipped to the zone; empty where
    /// nothing is asked.
    pub fn spans(&self, graph: &Graph, rows: Range<i32>) -> Vec<Range<i32>> {
        let output = self.zone[graph.output()];
        // The output's zone, and any zone no resampler reads, stream the
        // output's rows.
        let mut spans: Vec<Option<Range<i32>>> = (0..self.rects.len())
            .map(|z| {
                let read = self.resamplers.iter().any(|&(_, into)| into == z);
                (z == output || !read).then(|| rows.clone())
            })
            .collect();
        for _ in 0..self.rects.len() {
            for &(n, into) in self.resamplers.iter().rev() {
                let Some(out) = spans[self.zone[n]].clone().filter(|r| r.end > r.start) else {
                    continue;
                };
                let asked = request(graph, n, rows_of(self.rect(n), &out));
                let asked = grow(asked, self.reach);
                let asked = clamp(row_range(asked), &row_range(self.rects[into]));
                spans[into] = Some(match spans[into].take() {
                    Some(s) if s.end > s.start => s.start.min(asked.start)..s.end.max(asked.end),
                    _ => asked,
                });
            }
        }
        spans
            .into_iter()
            .enumerate()
            .map(|(z, s)| s.unwrap_or(self.rects[z].position.y()..self.rects[z].position.y()))
            .collect()
    }

    /// The rows past which node `n` need not compute for output rows
    /// `rows`: its zone's span, grown by what the halos reach (a node of
    /// the output's zone feeds halos too).
    pub fn needed_end(&self, spans: &[Range<i32>], n: usize) -> i32 {
        self.span(spans, n).end.saturating_add(self.reach.down)
    }

    /// Node `n`'s zone's span among `spans`.
    pub fn span<'s>(&self, spans: &'s [Range<i32>], n: usize) -> &'s Range<i32> {
        &spans[self.zone[n]]
    }
}

/// What resampling node `n` requests for its region `out`.
pub fn request(graph: &Graph, n: usize, out: IntegerBounds) -> IntegerBounds {
    match &graph.nodes[n] {
        Node::Op { op, .. } => op.request(out).expect("a resampling node"),
        Node::Input(_) => unreachable!("inputs do not resample"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::engine::graph::Op;
    use crate::io::rows::{Rows, RowsMut};
    use exr::meta::attribute::ChannelDescription;

    /// Mirrors rows about the middle of `0..height` (a flip) when `flip`,
    /// else reads each row as it is, and either way resamples (requests).
    #[derive(Debug)]
    struct Mirror {
        height: i32,
        flip: bool,
    }

    impl Op for Mirror {
        fn request(&self, out: IntegerBounds) -> Option<IntegerBounds> {
            let (top, bottom) = match self.flip {
                true => (self.height - out.end().y(), self.height - out.position.y()),
                false => (out.position.y(), out.end().y()),
            };
            Some(rows_of(out, &(top..bottom)))
        }
        fn channels(&self, inputs: &[&[ChannelDescription]]) -> Vec<ChannelDescription> {
            inputs[0].to_vec()
        }
        fn compute(&self, _: i64, _: &[&Rows], _: &mut RowsMut) -> Result<(), String> {
            Ok(())
        }
    }

    /// Adds its inputs (any op that does not resample).
    #[derive(Debug)]
    struct Sum;

    impl Op for Sum {
        fn channels(&self, inputs: &[&[ChannelDescription]]) -> Vec<ChannelDescription> {
            inputs[0].to_vec()
        }
        fn compute(&self, _: i64, _: &[&Rows], _: &mut RowsMut) -> Result<(), String> {
            Ok(())
        }
    }

    /// The read order of each node of a graph of `ops` (each with its
    /// inputs) after one input.
    fn orders(ops: Vec<(Box<dyn Op>, Vec<usize>)>) -> Vec<bool> {
        let mut nodes = vec![Node::Input(0)];
        for (op, inputs) in ops {
            nodes.push(Node::Op {
                op,
                inputs,
                origin: None,
            });
        }
        let graph = Graph { nodes };
        let window = IntegerBounds::new((0, 0), (8, 100));
        let valid = vec![window; graph.nodes.len()];
        let regions = Regions::new(&graph, window, &valid).unwrap();
        (0..graph.nodes.len()).map(|n| regions.upward(n)).collect()
    }

    fn mirror(flip: bool) -> Box<dyn Op> {
        Box::new(Mirror { height: 100, flip })
    }

    #[test]
    fn a_zone_is_read_bottom_up_where_its_reader_moves_up() {
        // A flip reads its input bottom-up; one that keeps the rows' order
        // reads it top-down.
        assert_eq!(orders(vec![(mirror(true), vec![0])]), [true, false]);
        assert_eq!(orders(vec![(mirror(false), vec![0])]), [false, false]);
        // A flip of a flip: the middle zone bottom-up, the input top-down.
        let twice = vec![(mirror(true), vec![0]), (mirror(true), vec![1])];
        assert_eq!(orders(twice), [false, true, false]);
        // Read flipped and as it is at once: top-down (held whole).
        let split = vec![
            (mirror(true), vec![0]),
            (mirror(false), vec![0]),
            (Box::new(Sum) as Box<dyn Op>, vec![1, 2]),
        ];
        assert_eq!(orders(split), [false; 4]);
        // Read flipped twice: bottom-up.
        let both = vec![
            (mirror(true), vec![0]),
            (mirror(true), vec![0]),
            (Box::new(Sum) as Box<dyn Op>, vec![1, 2]),
        ];
        assert_eq!(orders(both), [true, false, false, false]);
    }
}
