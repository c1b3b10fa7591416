//! Runs the graph over strips as they arrive: each node keeps a window of the
//! rows it produced, as long as a consumer's halo still needs them. The
//! nodes of a zone read bottom-up (`Regions::upward`) grow their windows
//! upwards, bottom row first.

use super::graph::{Graph, Node, Op};
use super::memory_bound::{band_rows, spanned_rows, window_rows};
use super::region::{rows_of, Regions};
use crate::io::rows::Rows;
use crate::stage_time::{self, Stage};
use exr::meta::attribute::{ChannelDescription, IntegerBounds};
use rayon::prelude::*;
use std::ops::Range;

/// One frame's evaluation state.
pub struct Composer<'g> {
    graph: &'g Graph,
    /// Per node: the rows it has produced and still keeps.
    windows: Vec<Rows>,
    /// Per node: the most rows its window holds (`window_rows`), worked out
    /// at the first strip, whose height is the frame's strips'.
    held: Vec<usize>,
    /// Per node: the nodes that read it, in graph order.
    consumers: Vec<Vec<usize>>,
    /// Rows of the output node already handed out.
    emitted: i32,
    /// The end of the strips pushed so far.
    fed: i32,
    /// Output rows are handed out in whole multiples of this (a block).
    emit_multiple: usize,
    window: IntegerBounds,
    /// The rows and columns each node's window covers, and whether it is
    /// computed bottom-up (`region.rs`).
    regions: Regions,
}

impl<'g> Composer<'g> {
    /// `channels[n]` and `valid[n]`: each node's channels and data window;
    /// `regions`: the rows and columns each covers, the output's first.
    pub fn new(
        graph: &'g Graph,
        regions: &Regions,
        channels: &[Vec<ChannelDescription>],
        valid: &[IntegerBounds],
        emit_multiple: usize,
    ) -> Self {
        let window = regions.rect(graph.output());
        let top = window.position.y();
        let windows = (0..graph.nodes.len())
            .map(|n| {
                let rect = regions.rect(n);
                // Empty, at the row computed first.
                let first = match regions.upward(n) {
                    true => rect.end().y(),
                    false => rect.position.y(),
                };
                Rows::zeros(
                    rect.position.x(),
                    first,
                    rect.size.width(),
                    0,
                    channels[n].clone(),
                    valid[n],
                )
            })
            .collect();
        let mut consumers = vec![Vec::new(); graph.nodes.len()];
        for (n, node) in graph.nodes.iter().enumerate() {
            if let Node::Op { inputs, .. } = node {
                inputs.iter().for_each(|&i| consumers[i].push(n));
            }
        }
        Composer {
            graph,
            windows,
            held: Vec::new(),
            consumers,
            emitted: top,
            fed: top,
            emit_multiple,
            window,
            regions: regions.clone(),
        }
    }

    fn bottom(&self) -> i32 {
        self.window.end().y()
    }

    /// Where node `n` computes next: the end of its window, or its start
    /// computing bottom-up.
    fn frontier(&self, n: usize) -> i32 {
        match self.regions.upward(n) {
            true => self.windows[n].y,
            false => self.windows[n].end(),
        }
    }

    /// Whether node `n` holds every row it will read of input `i` for rows
    /// `asked` of its own (reached from its frontier): `i` has computed all
    /// its rows, or as far as `asked` reaches in its direction.
    fn holds(&self, i: usize, asked: IntegerBounds) -> bool {
        let (held, rect) = (self.frontier(i), self.regions.rect(i));
        match self.regions.upward(i) {
            true => held <= rect.position.y() || asked.position.y().max(rect.position.y()) >= held,
            false => held >= rect.end().y() || asked.end().y().min(rect.end().y()) <= held,
        }
    }

    /// How far node `n` can compute from its inputs' windows, from its
    /// frontier `start` (downwards, or upwards for a node computed so).
    fn computable(&self, n: usize, op: &dyn Op, inputs: &[usize], start: i32) -> i32 {
        let (top, bottom) = (
            self.regions.rect(n).position.y(),
            self.regions.rect(n).end().y(),
        );
        let up = self.regions.upward(n);
        if op.request(self.regions.rect(n)).is_none() {
            // The fast path: inputs share the node's rows (and its order).
            let halo = op.halo() as i32;
            return match up {
                // A source (no inputs) computes all its rows at once.
                true => match inputs.iter().map(|&i| self.frontier(i)).max() {
                    Some(ready) if ready > top => ready + halo,
                    _ => top,
                },
                false => {
                    // A source produces as far as the inputs were fed.
                    let ready = inputs.iter().map(|&i| self.frontier(i)).min();
                    match ready.unwrap_or(self.fed) {
                        ready if ready >= bottom => ready,
                        ready => ready - halo,
                    }
                }
            };
        }
        // Resampling: the farthest row whose request the inputs hold
        // (requests grow with the rows asked, so a bisection finds it).
        let fits = |to: i32| {
            let rows = match up {
                true => to..start,
                false => start..to,
            };
            let asked = op.request(rows_of(self.regions.rect(n), &rows));
            let asked = asked.expect("a resampling op");
            inputs.iter().all(|&i| self.holds(i, asked))
        };
        let (mut good, mut bad) = match up {
            true => (start, top - 1),
            false => (start, bottom + 1),
        };
        while (bad - good).abs() > 1 {
            let mid = good + (bad - good) / 2;
            match fits(mid) {
                true => good = mid,
                false => bad = mid,
            }
        }
        good
    }

    /// Takes strip `rows` of every input and returns the output rows that
    /// became complete, if any.
    pub fn push(
        &mut self,
        frame: i64,
        rows: Range<i32>,
        strips: Vec<Rows>,
    ) -> Result<Option<Rows>, String> {
        let mut strips: Vec<Option<Rows>> = strips.into_iter().map(Some).collect();
        self.fed = rows.end;
        if self.held.is_empty() {
            let spans = spanned_rows(self.graph, &self.regions, self.window, rows.len());
            self.held = window_rows(self.graph, &spans);
        }
        // A resampler whose input is read whole could compute every row
        // left at once (an enlarging resize of a short input): it computes
        // what the rows fed so far ask of it, band by band.
        let top = self.window.position.y();
        let spans = match self.regions.shared() {
            true => Vec::new(),
            false => self.regions.spans(self.graph, top..rows.end),
        };
        for n in 0..self.graph.nodes.len() {
            let graph_node = &self.graph.nodes[n];
            match graph_node {
                Node::Input(i) => {
                    let strip = strips[*i].take().expect("one strip per input");
                    // An empty window takes the strip's planes as they
                    // are, if they hold all it will.
                    if self.windows[n].height > 0 || strip.height < self.held[n] {
                        self.make_room(n);
                    }
                    match self.regions.upward(n) {
                        true => self.windows[n].prepend(strip),
                        false => self.windows[n].append(strip),
                    }
                }
                Node::Op { op, inputs, .. } => {
                    let start = self.frontier(n);
                    let mut end = self.computable(n, op.as_ref(), inputs, start);
                    if !self.regions.upward(n) && op.request(self.regions.rect(n)).is_some() {
                        end = end.min(self.regions.needed_end(&spans, n));
                    }
                    let rows = match self.regions.upward(n) {
                        true => end..start,
                        false => start..end,
                    };
                    if !rows.is_empty() {
                        // Computed in place, band by band on the pool: nodes
                        // come after their inputs, so those are borrowed apart.
                        self.make_room(n);
                        let (earlier, rest) = self.windows.split_at_mut(n);
                        let node = &mut rest[0];
                        let height = rows.len();
                        match self.regions.upward(n) {
                            true => node.grow_up(height),
                            false => node.grow(height),
                        }
                        let args: Vec<&Rows> = inputs.iter().map(|&i| &earlier[i]).collect();
                        let band = band_rows(height, node.width);
                        node.bands_in(rows, band)
                            .into_par_iter()
                            .try_for_each(|mut out| {
                                stage_time::task(Stage::Compose, || {
                                    op.compute(frame, &args, &mut out)
                                })
                            })
                            .map_err(|m| graph_node.locate(m))?;
                    }
                    // Inputs read by no later node are trimmed now, not after
                    // the last node: a long chain holds a few strips, not one
                    // per node.
                    for &i in inputs {
                        if self.consumers[i].last() == Some(&n) {
                            self.forget_used_rows(i);
                        }
                    }
                }
            }
        }
        let result = self.take_output();
        self.forget_used_rows(self.graph.output());
        Ok(result)
    }

    /// Room in node `n`'s window for the most rows it holds: it then grows
    /// in place all frame long (past them, as a Vec grows).
    fn make_room(&mut self, n: usize) {
        self.windows[n].reserve(self.held[n]);
    }

    fn take_output(&mut self) -> Option<Rows> {
        let top = self.window.position.y();
        let mut end = self.windows[self.graph.output()].end();
        if end < self.bottom() {
            let m = self.emit_multiple as i32;
            end = top + (end - top) / m * m;
        }
        if end <= self.emitted {
            return None;
        }
        let rows = self.windows[self.graph.output()].take_rows(self.emitted..end);
        self.emitted = end;
        Some(rows)
    }

    /// Drops the rows of node `n` that no consumer will read again (its
    /// consumers have all computed what they can from this strip): those
    /// before the first row a consumer's rows still to compute read, or
    /// after the last for a node computed bottom-up.
    fn forget_used_rows(&mut self, n: usize) {
        let up = self.regions.upward(n);
        let mut keep = match (n == self.graph.output(), up) {
            (true, _) => self.emitted,
            (false, true) => i32::MIN,
            (false, false) => i32::MAX,
        };
        for &c in &self.consumers[n] {
            let Node::Op { op, .. } = &self.graph.nodes[c] else {
                continue;
            };
            let (frontier, rect) = (self.frontier(c), self.regions.rect(c));
            let needed = match op.request(rect) {
                // The same zone, so the same order: the halo behind.
                None if up => frontier + op.halo() as i32,
                None => frontier - op.halo() as i32,
                // What its rows still to compute request: beyond the next
                // row's footprint where the consumer reads the other way
                // from this node's order (a zone both orders read).
                Some(_) => {
                    let rest = match self.regions.upward(c) {
                        true => rect.position.y()..frontier,
                        false => frontier..rect.end().y(),
                    };
                    if rest.is_empty() {
                        continue;
                    }
                    let asked = op.request(rows_of(rect, &rest)).expect("a resampling op");
                    match up {
                        true => asked.end().y(),
                        false => asked.position.y(),
                    }
                }
            };
            keep = match up {
                true => keep.max(needed),
                false => keep.min(needed),
            };
        }
        match up {
            true => self.windows[n].drop_rows_from(keep),
            false => self.windows[n].drop_rows_before(keep),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::engine::graph::Op;
    use crate::io::rows::{RowsMut, Samples};
    use exr::meta::attribute::SampleType;
    use std::sync::atomic::{AtomicUsize, Ordering};
    use std::sync::Arc;

    /// Sums each pixel's column over rows y - halo ..= y + halo, clamped to
    /// the image: a stand-in for any neighbourhood filter.
    #[derive(Debug)]
    struct VerticalSum {
        halo: usize,
        top: i32,
        bottom: i32,
        /// How many bands it computed.
        bands: Arc<AtomicUsize>,
    }

    impl VerticalSum {
        fn new(halo: usize, top: i32, bottom: i32) -> Self {
            let bands = Arc::default();
            VerticalSum {
                halo,
                top,
                bottom,
                bands,
            }
        }
    }

    impl Op for VerticalSum {
        fn halo(&self) -> usize {
            self.halo
        }
        fn channels(&self, inputs: &[&[ChannelDescription]]) -> Vec<ChannelDescription> {
            inputs[0].to_vec()
        }
        fn compute(&self, _frame: i64, inputs: &[&Rows], out: &mut RowsMut) -> Result<(), String> {
            self.bands.fetch_add(1, Ordering::Relaxed);
            let input = inputs[0];
            let h = self.halo as i32;
            for y in out.y..out.end() {
                let mut sums = vec![0.0f32; out.width];
                let mut row = vec![0.0f32; out.width];
                for source in (y - h).max(self.top)..=(y + h).min(self.bottom - 1) {
                    input.planes[0].read_f32(input.row_range(source), &mut row);
                    sums.iter_mut().zip(&row).for_each(|(s, r)| *s += r);
                }
                let range = out.row_range(y);
                out.planes[0].write_f32(range, &sums);
            }
            Ok(())
        }
    }

    fn regions(graph: &Graph, window: IntegerBounds, valid: &[IntegerBounds]) -> Regions {
        Regions::new(graph, window, valid).unwrap()
    }

    #[test]
    fn bands_are_a_few_per_thread_and_never_tiny() {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(4)
            .build()
            .unwrap();
        pool.install(|| {
            // 16 bands for 4 threads where rows are many and wide.
            assert_eq!(band_rows(256, 3840), 16);
            assert_eq!(band_rows(250, 3840), 16);
            // Narrow rows: 16 Ki samples at least, so 2048 wide takes 8.
            assert_eq!(band_rows(64, 2048), 8);
            assert_eq!(band_rows(64, 1), 16 << 10);
            // Wider than the floor: one row a band at the least.
            assert_eq!(band_rows(3, 1 << 20), 1);
        });
    }

    fn column_image(height: usize) -> Vec<f32> {
        (0..height).map(|y| (y * y % 17) as f32).collect()
    }

    fn reference(values: &[f32], halo: usize) -> Vec<f32> {
        let n = values.len() as i64;
        (0..n)
            .map(|y| {
                let lo = (y - halo as i64).max(0);
                let hi = (y + halo as i64).min(n - 1);
                (lo..=hi).map(|i| values[i as usize]).sum()
            })
            .collect()
    }

    /// Streams a one-pixel-wide column through `halos` chained sums.
    fn stream(values: &[f32], halos: &[usize], strip: usize, emit: usize) -> Vec<f32> {
        let (top, height) = (-3, values.len());
        let bottom = top + height as i32;
        let window = IntegerBounds::new((0, top), (1, height));
        let mut nodes = vec![Node::Input(0)];
        for (i, &halo) in halos.iter().enumerate() {
            nodes.push(Node::Op {
                op: Box::new(VerticalSum::new(halo, top, bottom)),
                inputs: vec![i],
                origin: None,
            });
        }
        let graph = Graph { nodes };
        let channels =
            vec![vec![ChannelDescription::named("Y", SampleType::F32)]; graph.nodes.len()];
        let valid = vec![window; graph.nodes.len()];
        let mut composer = Composer::new(
            &graph,
            &regions(&graph, window, &valid),
            &channels,
            &valid,
            emit,
        );
        let mut out = Vec::new();
        for y in (top..bottom).step_by(strip) {
            let end = (y + strip as i32).min(bottom);
            let mut rows = Rows::zeros(0, y, 1, (end - y) as usize, channels[0].clone(), window);
            let slice = &values[(y - top) as usize..(end - top) as usize];
            rows.planes[0] = Samples::F32(slice.to_vec());
            if let Some(done) = composer.push(0, y..end, vec![rows]).unwrap() {
                assert_eq!(done.y, top + out.len() as i32, "rows come out in order");
                let mut v = vec![0.0; done.height];
                done.planes[0].read_f32(0..done.height, &mut v);
                out.extend(v);
            }
        }
        out
    }

    #[test]
    fn halo_windows_give_the_whole_image_result_for_any_strip_size() {
        for height in [1, 5, 40, 97] {
            let values = column_image(height);
            for halos in [vec![0], vec![3], vec![2, 7], vec![50]] {
                let mut expected = values.clone();
                for &h in &halos {
                    expected = reference(&expected, h);
                }
                for strip in [1, 4, 16, 200] {
                    for emit in [1, 16] {
                        let got = stream(&values, &halos, strip, emit);
                        assert_eq!(
                            got, expected,
                            "height {height} halos {halos:?} strip {strip} emit {emit}"
                        );
                    }
                }
            }
        }
    }

    /// Scales a one-channel image by `num / den` in both axes, each output
    /// pixel the mean of the input pixels whose centres fall in it (or the
    /// one it falls in, enlarging): a stand-in for any resampling op.
    #[derive(Debug)]
    struct Rescale {
        num: i32,
        den: i32,
    }

    impl Rescale {
        /// Input pixels `first..end` that output pixels `out` read.
        fn source(&self, out: Range<i32>) -> Range<i32> {
            let (n, d) = (self.num, self.den);
            let first = (out.start * d).div_euclid(n);
            let end = (out.end * d + n - 1).div_euclid(n);
            first..end.max(first + 1)
        }
    }

    impl Op for Rescale {
        fn request(&self, out: IntegerBounds) -> Option<IntegerBounds> {
            let x = self.source(out.position.x()..out.end().x());
            let y = self.source(out.position.y()..out.end().y());
            Some(IntegerBounds::new(
                (x.start, y.start),
                ((x.end - x.start) as usize, (y.end - y.start) as usize),
            ))
        }
        fn data_window(&self, inputs: &[IntegerBounds]) -> IntegerBounds {
            let scale = |v: i32| v * self.num / self.den;
            let w = inputs[0];
            let (x0, y0) = (scale(w.position.x()), scale(w.position.y()));
            let (x1, y1) = (scale(w.end().x()), scale(w.end().y()));
            IntegerBounds::new((x0, y0), ((x1 - x0) as usize, (y1 - y0) as usize))
        }
        fn channels(&self, inputs: &[&[ChannelDescription]]) -> Vec<ChannelDescription> {
            inputs[0].to_vec()
        }
        fn compute(&self, _frame: i64, inputs: &[&Rows], out: &mut RowsMut) -> Result<(), String> {
            let input = inputs[0];
            let mut row = vec![0.0f32; input.width];
            let mut values = vec![0.0f32; out.width];
            for y in out.y..out.end() {
                values.fill(0.0);
                let rows = self.source(y..y + 1);
                for source in rows.clone() {
                    input.planes[0].read_f32(input.row_range(source), &mut row);
                    for (i, v) in values.iter_mut().enumerate() {
                        let x = out.x + i as i32;
                        for c in self.source(x..x + 1) {
                            *v += row[(c - input.x) as usize];
                        }
                    }
                }
                for (i, v) in values.iter_mut().enumerate() {
                    let x = out.x + i as i32;
                    *v /= (rows.len() * self.source(x..x + 1).len()) as f32;
                }
                let range = out.row_range(y);
                out.planes[0].write_f32(range, &values);
            }
            Ok(())
        }
    }

    /// Streams `image` (`width` x `height` from the origin) through `ops`
    /// (each reading the one before), strip by strip of the output's rows
    /// as the pipeline does, decode reading each strip's span of the input;
    /// the output rows and the most input rows held at once.
    fn stream_regions(
        image: &[f32],
        (width, height): (usize, usize),
        ops: Vec<Box<dyn Op>>,
        strip: usize,
    ) -> (Vec<f32>, IntegerBounds, usize) {
        let mut nodes = vec![Node::Input(0)];
        for (i, op) in ops.into_iter().enumerate() {
            nodes.push(Node::Op {
                op,
                inputs: vec![i],
                origin: None,
            });
        }
        let graph = Graph { nodes };
        let input = IntegerBounds::new((0, 0), (width, height));
        let valid = graph.evaluate(|_| input, |op, args| op.data_window(args));
        let output = valid[graph.output()];
        let regions = Regions::new(&graph, output, &valid).unwrap();
        assert_eq!(
            regions.rect(0),
            input,
            "the input's region is its data window"
        );
        let channels =
            vec![vec![ChannelDescription::named("Y", SampleType::F32)]; graph.nodes.len()];
        let mut composer = Composer::new(&graph, &regions, &channels, &valid, 1);
        let (top, bottom) = (output.position.y(), output.end().y());
        let (mut fed, mut out, mut most) = (0i32, Vec::new(), 0);
        for y in (top..bottom).step_by(strip) {
            let end = (y + strip as i32).min(bottom);
            let read_to = match end == bottom {
                true => height as i32,
                false => regions
                    .span(&regions.spans(&graph, top..end), 0)
                    .end
                    .max(fed),
            };
            let mut rows = Rows::zeros(
                0,
                fed,
                width,
                (read_to - fed) as usize,
                channels[0].clone(),
                input,
            );
            rows.planes[0] =
                Samples::F32(image[fed as usize * width..read_to as usize * width].to_vec());
            fed = read_to;
            if let Some(done) = composer.push(0, y..end, vec![rows]).unwrap() {
                // About a strip's rows (a request's rounding may hold one
                // back), never all those left once the input is read.
                assert!(
                    done.height <= strip + 2,
                    "{} rows for a strip of {strip}",
                    done.height
                );
                let mut v = vec![0.0; done.height * done.width];
                done.planes[0].read_f32(0..v.len(), &mut v);
                out.extend(v);
            }
            most = most.max(composer.windows[0].height);
        }
        (out, output, most)
    }

    /// The whole-image reference of a `Rescale`.
    fn rescaled(
        image: &[f32],
        (width, height): (usize, usize),
        op: &Rescale,
    ) -> (Vec<f32>, (usize, usize)) {
        let size = |v: usize| (v as i32 * op.num / op.den) as usize;
        let (w, h) = (size(width), size(height));
        let mut out = vec![0.0; w * h];
        for y in 0..h as i32 {
            for x in 0..w as i32 {
                let (rows, columns) = (op.source(y..y + 1), op.source(x..x + 1));
                let count = (rows.len() * columns.len()) as f32;
                let sum: f32 = rows
                    .flat_map(|r| {
                        columns
                            .clone()
                            .map(move |c| image[r as usize * width + c as usize])
                    })
                    .sum();
                out[y as usize * w + x as usize] = sum / count;
            }
        }
        (out, (w, h))
    }

    #[test]
    fn nodes_of_other_sizes_stream_to_the_whole_image_result() {
        let (width, height) = (12usize, 240usize);
        let image: Vec<f32> = (0..width * height).map(|i| ((i * 7) % 23) as f32).collect();
        for (num, den) in [(1, 2), (1, 4), (2, 1), (3, 2)] {
            let op = Rescale { num, den };
            let (expected, _) = rescaled(&image, (width, height), &op);
            for strip in [1, 3, 16, 1000] {
                let (got, _, most) = stream_regions(
                    &image,
                    (width, height),
                    vec![Box::new(Rescale { num, den })],
                    strip,
                );
                assert_eq!(got, expected, "scale {num}/{den} strip {strip}");
                // Flat in height: the input holds about a strip's span.
                if strip < 100 {
                    let span = strip * den as usize / num as usize + 2;
                    assert!(
                        most <= span + strip,
                        "scale {num}/{den} strip {strip}: held {most} rows"
                    );
                }
            }
        }
        // Enlarged from an input read whole by the first strip.
        let tiny: Vec<f32> = (0..8).map(|i| i as f32).collect();
        let op = Rescale { num: 100, den: 1 };
        let (expected, _) = rescaled(&tiny, (4, 2), &op);
        let (got, _, _) = stream_regions(&tiny, (4, 2), vec![Box::new(op)], 3);
        assert_eq!(got, expected);
        // Down, then up again: two regions behind the output's.
        let (half, size) = rescaled(&image, (width, height), &Rescale { num: 1, den: 2 });
        let (expected, _) = rescaled(&half, size, &Rescale { num: 3, den: 1 });
        let ops: Vec<Box<dyn Op>> = vec![
            Box::new(Rescale { num: 1, den: 2 }),
            Box::new(Rescale { num: 3, den: 1 }),
        ];
        let (got, output, _) = stream_regions(&image, (width, height), ops, 5);
        assert_eq!(output.size, exr::math::Vec2(18, 360));
        assert_eq!(got, expected);
    }

    #[test]
    fn windows_hold_no_more_than_the_halo_needs() {
        let values = column_image(200);
        let (top, bottom) = (-3, 197);
        let window = IntegerBounds::new((0, top), (1, 200));
        let graph = Graph {
            nodes: vec![
                Node::Input(0),
                Node::Op {
                    op: Box::new(VerticalSum::new(5, top, bottom)),
                    inputs: vec![0],
                    origin: None,
                },
            ],
        };
        let channels = vec![vec![ChannelDescription::named("Y", SampleType::F32)]; 2];
        let mut composer = Composer::new(
            &graph,
            &regions(&graph, window, &[window; 2]),
            &channels,
            &[window; 2],
            1,
        );
        for y in (top..bottom).step_by(8) {
            let mut rows = Rows::zeros(0, y, 1, 8, channels[0].clone(), window);
            rows.planes[0] =
                Samples::F32(values[(y - top) as usize..(y - top) as usize + 8].to_vec());
            composer.push(0, y..y + 8, vec![rows]).unwrap();
            // Input rows kept: at most the strip plus twice the halo.
            assert!(
                composer.windows[0].height <= 8 + 2 * 5,
                "kept {}",
                composer.windows[0].height
            );
        }
    }

    #[test]
    fn bands_computed_apart_give_the_rows_computed_whole() {
        // Wide enough rows that a strip makes several bands.
        let (width, height, halo) = (4096usize, 64usize, 3usize);
        let window = IntegerBounds::new((0, 0), (width, height));
        let op = VerticalSum::new(halo, 0, height as i32);
        let bands = op.bands.clone();
        let graph = Graph {
            nodes: vec![
                Node::Input(0),
                Node::Op {
                    op: Box::new(op),
                    inputs: vec![0],
                    origin: None,
                },
            ],
        };
        let channels = vec![vec![ChannelDescription::named("Y", SampleType::F32)]; 2];
        let image: Vec<f32> = (0..width * height).map(|i| (i % 251) as f32).collect();
        let mut input = Rows::zeros(0, 0, width, height, channels[0].clone(), window);
        input.planes[0] = Samples::F32(image.clone());
        let mut composer = Composer::new(
            &graph,
            &regions(&graph, window, &[window; 2]),
            &channels,
            &[window; 2],
            1,
        );
        let done = composer
            .push(0, 0..height as i32, vec![input])
            .unwrap()
            .unwrap();
        assert!(bands.load(Ordering::Relaxed) > 1, "one band only");
        let mut got = vec![0.0; width * height];
        done.planes[0].read_f32(0..width * height, &mut got);
        for x in [0, 1, width / 2, width - 1] {
            let column: Vec<f32> = (0..height).map(|y| image[y * width + x]).collect();
            let expected = reference(&column, halo);
            let got: Vec<f32> = (0..height).map(|y| got[y * width + x]).collect();
            assert_eq!(got, expected, "column {x}");
        }
    }
}
