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
//! The rule and the memory bound: specs/architecture.md, "Regions of interest".

use super::graph::{grow, intersection, union, Graph, Node, Reach};
use exr::meta::attribute::IntegerBounds;
use std::ops::Range;

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
        Ok(regions)
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
