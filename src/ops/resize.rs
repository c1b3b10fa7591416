//! `resize`: a new display window size, filtered as oiiotool's
//! `--resize:filter=NAME` (OpenImageIO's `ImageBufAlgo::resize`), in two
//! resampling passes: across the rows (into f32), then down the columns,
//! each streaming its input in a region of its own (`Op::request`), so the
//! vertical pass holds a few rows of the horizontal one, never the image.
//! At the same size the samples are copied, as oiiotool keeps the image.
//! u32 channels (ids) take the nearest sample on both passes, as they are.
//! Formulas: specs/ops.md, "resize".

use super::crop::copy_moved;
use super::declare::{choice, input, params, Args, Length, Operation, Value};
use crate::engine::graph::{Band, Carried, Display, GraphBuilder, NodeId, Op};
use crate::io::rows::{Rows, RowsMut, Samples};
use crate::params::RESIZE_SCALE;
use exr::meta::attribute::{ChannelDescription, IntegerBounds, SampleType};
use std::ops::Range;
use std::sync::{Arc, Mutex, OnceLock};

pub const RESIZE: Operation = Operation {
    name: "resize",
    about: "Resize to a new display window size, `--size WxH` or `--scale F`, filtered as \
            oiiotool's `--resize:filter=NAME` (every channel; edges clamp to the data window)",
    inputs: &[input("input", "Input file or sequence, `:PART` for a part")],
    repeats: false,
    params: Params::PARAMS,
    layers: false,
    straight: false,
    header: Some(0),
    build,
    measure: None,
};

params! {
    pub struct Params {
        /// The new display window's size in pixels, WxH.
        size: Option<Size> {pixels},
        /// Or a factor for both sides (0.5: half size), sides rounded.
        scale: Option<f32> [RESIZE_SCALE],
        /// box, triangle, gaussian, mitchell or lanczos3.
        filter: Filter = "lanczos3",
    }
}

fn build(args: &Args, graph: &mut GraphBuilder, inputs: &[NodeId]) -> Result<NodeId, String> {
    let p = Params::read(args)?;
    let target = match (p.size, p.scale) {
        (Some(size), None) => Target::Size(size),
        (None, Some(scale)) => Target::Scale(scale),
        _ => return Err(format!("{} takes one of size (WxH) and scale", args.op)),
    };
    Ok(passes(target, p.filter, inputs[0], graph))
}

/// The two passes resizing graph node `input`; returns the second.
pub fn passes(target: Target, filter: Filter, input: NodeId, graph: &mut GraphBuilder) -> NodeId {
    let across = graph.add(Pass::new(Axis::X, target, filter), &[input]);
    // The original is read for its channels' types only.
    graph.add(Pass::new(Axis::Y, target, filter), &[across, input])
}

/// A size `WxH`, each side 1 to 1,048,576 pixels.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Size {
    pub width: usize,
    pub height: usize,
}

impl Value for Size {
    fn parse(text: &str) -> Result<Self, String> {
        let side = |s: &str| {
            s.trim()
                .parse::<usize>()
                .ok()
                .filter(|v| (1..=1 << 20).contains(v))
        };
        match text.split_once(['x', 'X']).map(|(w, h)| (side(w), side(h))) {
            Some((Some(width), Some(height))) => Ok(Size { width, height }),
            _ => Err(format!(
                "size '{text}': expected WxH, 1 to 1048576 pixels each (1920x1080)"
            )),
        }
    }
}

/// Each side scaled and rounded, at least 1 (as `--scale` does).
impl Length for Size {
    fn scaled(text: &str, factor: f64) -> Result<String, String> {
        let size = Size::parse(text)?;
        let side = |v: usize| ((v as f64 * factor).round() as usize).max(1);
        Ok(format!("{}x{}", side(size.width), side(size.height)))
    }
}

/// The new size: given, the old one scaled, or fitted to a format (of
/// this size and pixel aspect ratio).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Target {
    Size(Size),
    Scale(f32),
    Fit(Size, f32, Fit),
}

/// How an image is fitted to a format (Nuke's Reformat resize types).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Fit {
    /// Scaled to the format's width, aspect kept.
    Width,
    /// To its height.
    Height,
    /// Inside it, whole (letterboxed).
    Inside,
    /// Covering it (cropped to it by the display window).
    Fill,
    /// To both sides, aspect changed.
    Distort,
}

impl Value for Fit {
    fn parse(text: &str) -> Result<Self, String> {
        use Fit::*;
        choice(
            text,
            Self::CHOICES,
            &[Width, Height, Inside, Fill, Distort],
            "fit",
        )
    }
    const CHOICES: &'static [&'static str] = &["width", "height", "fit", "fill", "distort"];
}

impl Target {
    /// The new length along `axis` of an image shown as `old`.
    fn length(self, axis: Axis, old: Display) -> usize {
        let size = old.window.size;
        let (w, h) = (size.width() as f64, size.height() as f64);
        let side = match axis {
            Axis::X => w,
            Axis::Y => h,
        };
        let scale = match self {
            Target::Size(s) => return [s.width, s.height][(axis == Axis::Y) as usize],
            Target::Scale(f) => f as f64,
            Target::Fit(format, pixel_aspect, fit) => {
                // The picture keeps its shape, as in Nuke's Reformat: the
                // height is scaled by the width's scale times the format's
                // pixel aspect over the image's (an anamorphic 2:1 plate
                // into square pixels: half as much).
                let squeeze = pixel_aspect as f64 / old.pixel_aspect as f64;
                let (sx, sy) = (format.width as f64 / w, format.height as f64 / h);
                let across = match fit {
                    Fit::Width => sx,
                    Fit::Height => sy / squeeze,
                    Fit::Inside => sx.min(sy / squeeze),
                    Fit::Fill => sx.max(sy / squeeze),
                    Fit::Distort => {
                        return [format.width, format.height][(axis == Axis::Y) as usize]
                    }
                };
                match axis {
                    Axis::X => across,
                    Axis::Y => across * squeeze,
                }
            }
        };
        ((side * scale).round() as usize).max(1)
    }

    /// The pixel aspect ratio of an image shown with `old`'s once resized:
    /// a format's own, else kept.
    fn pixel_aspect(self, old: f32) -> f32 {
        match self {
            Target::Fit(_, pixel_aspect, _) => pixel_aspect,
            Target::Size(_) | Target::Scale(_) => old,
        }
    }
}

/// Whether channels of type `kind` are resampled by their nearest sample,
/// not filtered (resize and transform): u32 ones, object ids, which a
/// weighted sum would turn into other objects' ids (or none), and which f32
/// cannot hold past 2^24.
pub fn nearest_only(kind: SampleType) -> bool {
    kind == SampleType::U32
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Filter {
    Box,
    Triangle,
    Gaussian,
    Mitchell,
    Lanczos3,
}

impl Value for Filter {
    fn parse(text: &str) -> Result<Self, String> {
        use Filter::*;
        choice(
            text,
            Self::CHOICES,
            &[Box, Triangle, Gaussian, Mitchell, Lanczos3],
            "filter",
        )
    }
    const CHOICES: &'static [&'static str] =
        &["box", "triangle", "gaussian", "mitchell", "lanczos3"];
}

impl Filter {
    /// OpenImageIO's default width, in pixels of the smaller image.
    pub fn width(self) -> f32 {
        match self {
            Filter::Box => 1.0,
            Filter::Triangle => 2.0,
            Filter::Gaussian => 3.0,
            Filter::Mitchell => 4.0,
            Filter::Lanczos3 => 6.0,
        }
    }

    /// The filter stretched to `width`, at `x` (OpenImageIO's 1-D forms).
    /// `x` over the radius is `x × (2 / width)` and the gaussian's exp is
    /// OpenImageIO's `fast_exp`, as its filters compute them (filter.cpp),
    /// so a weight is its bits.
    pub fn at(self, x: f32, width: f32) -> f32 {
        let x = x.abs();
        let unit = x * (2.0 / width);
        match self {
            Filter::Box => (x <= width * 0.5) as u8 as f32,
            Filter::Triangle => (1.0 - unit).max(0.0),
            Filter::Gaussian if unit < 1.0 => fast_exp(-2.0 * (unit * unit)),
            Filter::Gaussian => 0.0,
            Filter::Mitchell => mitchell(unit),
            Filter::Lanczos3 => lanczos3(x * 6.0 / width),
        }
    }
}

/// OpenImageIO's `fast_exp` (fmath.h): `2^(x log2 e)`, the fraction's
/// power by a degree-5 polynomial (within a few ulps of exp), the whole
/// part added to the exponent; its constants as it writes them.
#[allow(clippy::excessive_precision)]
fn fast_exp(x: f32) -> f32 {
    let x = (x * std::f32::consts::LOG2_E).clamp(-126.0, 126.0);
    let m = x as i32;
    let f = x - m as f32;
    let f = 1.0 - (1.0 - f);
    let mut r = 1.33336498402e-3f32;
    for c in [
        9.810352697968e-3f32,
        5.551834031939e-2,
        0.2401793301105,
        0.693144857883,
        1.0,
    ] {
        r = f * r + c;
    }
    f32::from_bits(r.to_bits().wrapping_add((m as u32) << 23))
}

/// Mitchell–Netravali, B = C = 1/3, over -1..1 (its -2..2 halved).
fn mitchell(x: f32) -> f32 {
    if x > 1.0 {
        return 0.0;
    }
    let x = 2.0 * x;
    let (b, c) = (1.0 / 3.0, 1.0 / 3.0);
    let (x2, x3) = (x * x, x * x * x);
    let v = match x >= 1.0 {
        true => {
            (-b - 6.0 * c) * x3
                + (6.0 * b + 30.0 * c) * x2
                + (-12.0 * b - 48.0 * c) * x
                + (8.0 * b + 24.0 * c)
        }
        false => {
            (12.0 - 9.0 * b - 6.0 * c) * x3 + (-18.0 + 12.0 * b + 6.0 * c) * x2 + (6.0 - 2.0 * b)
        }
    };
    v / 6.0
}

/// 3 sin(πx) sin(πx/3) / (πx)², 0 beyond 3.
fn lanczos3(x: f32) -> f32 {
    if x > 3.0 {
        return 0.0;
    }
    if x < 1e-4 {
        return 1.0;
    }
    let pi = std::f32::consts::PI;
    3.0 * (pi * x).sin() * (pi * x / 3.0).sin() / (pi * pi * x * x)
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Axis {
    X,
    Y,
}

impl Axis {
    fn range(self, w: IntegerBounds) -> Range<i32> {
        match self {
            Axis::X => w.position.x()..w.end().x(),
            Axis::Y => w.position.y()..w.end().y(),
        }
    }

    /// `w` with its range along this axis replaced by `range`.
    fn with(self, w: IntegerBounds, range: Range<i32>) -> IntegerBounds {
        let len = (range.end - range.start).max(0) as usize;
        match self {
            Axis::X => IntegerBounds::new((range.start, w.position.y()), (len, w.size.height())),
            Axis::Y => IntegerBounds::new((w.position.x(), range.start), (w.size.width(), len)),
        }
    }
}

/// A resize along one axis: the display windows' ranges it maps, from the
/// first frame (a sequence must keep its size).
#[derive(Clone, Debug, PartialEq)]
struct Geometry {
    from: Range<i32>,
    to: Range<i32>,
    /// The new length over the old.
    ratio: f32,
    /// The filter's width and radius in source pixels, as OpenImageIO has
    /// them: wider by the ratio when enlarging.
    width: f32,
    radius: i32,
    /// The image keeps its size on both axes: its samples are copied, bit
    /// for bit, whatever the filter (as oiiotool's `--resize` and `--fit`;
    /// one side kept and the other changed is filtered on both, as there).
    copies: bool,
}

impl Geometry {
    fn new(from: Range<i32>, length: usize, filter: Filter, copies: bool) -> Self {
        let to = from.start..from.start + length as i32;
        let ratio = length as f32 / (from.end - from.start) as f32;
        let width = filter.width() * ratio.max(1.0);
        let radius = (width / 2.0 / ratio).ceil() as i32;
        Geometry {
            from,
            to,
            ratio,
            width,
            radius,
            copies,
        }
    }

    /// Where output pixel `x`'s centre falls in the source, as OpenImageIO
    /// computes it in f32.
    fn source_point(&self, x: i32) -> f32 {
        let (f0, flen) = (
            self.from.start as f32,
            (self.from.end - self.from.start) as f32,
        );
        let (t0, tlen) = (self.to.start as f32, (self.to.end - self.to.start) as f32);
        f0 + (x as f32 - t0 + 0.5) * (1.0 / tlen) * flen
    }

    /// The source pixel holding output pixel `x`'s centre (its middle tap).
    fn nearest(&self, x: i32) -> i32 {
        self.source_point(x).floor() as i32
    }

    /// The first source pixel of output pixel `x`, and its 2R + 1 weights
    /// (normalised), as OpenImageIO computes them in f32.
    fn taps(&self, filter: Filter, x: i32, weights: &mut Vec<f32>) -> i32 {
        let s = self.source_point(x);
        let floor = s.floor();
        let frac = s - floor;
        weights.clear();
        let r = self.radius;
        weights.extend(
            (0..2 * r + 1)
                .map(|i| filter.at(self.ratio * ((i - r) as f32 - (frac - 0.5)), self.width)),
        );
        let total: f32 = weights.iter().sum();
        if total != 0.0 {
            weights.iter_mut().for_each(|w| *w /= total);
        }
        floor as i32 - r
    }

    /// The source pixels output pixels `out` read: their taps, and the
    /// display window's pixels a tap outside the data window is moved to.
    fn source(&self, filter: Filter, out: Range<i32>) -> Range<i32> {
        if out.is_empty() {
            return out;
        }
        let mut weights = Vec::new();
        let first = self.taps(filter, out.start, &mut weights);
        let last = self.taps(filter, out.end - 1, &mut weights) + weights.len() as i32 - 1;
        let clamp = |p: i32| p.clamp(self.from.start, self.from.end - 1);
        first.min(clamp(first))..last.max(clamp(last)) + 1
    }

    /// Source pixel `p` as OpenImageIO's resize reads it from data `data`:
    /// itself inside the data window, else moved into the display window
    /// (its clamp wrap), `None` (black) if that is outside the data window.
    fn read_at(&self, p: i32, data: &Range<i32>) -> Option<i32> {
        let q = match data.contains(&p) {
            true => p,
            false => p.clamp(self.from.start, self.from.end - 1),
        };
        data.contains(&q).then_some(q)
    }

    /// Where data `data` lies once resized, as OpenImageIO's resize places
    /// it: its start mapped and floored, its length scaled and ceiled, in
    /// whole numbers (OpenImageIO's f32 ratio makes some a pixel longer:
    /// 874 rows to 240 gave 241).
    fn data(&self, data: Range<i32>) -> Range<i32> {
        if data.is_empty() {
            return 0..0;
        }
        let (to, from) = (self.to.len() as i64, self.from.len() as i64);
        let start = ((data.start as i64 - self.from.start as i64) * to).div_euclid(from);
        let length = -(-(data.len() as i64 * to)).div_euclid(from);
        let at = |v: i64| (self.to.start as i64 + v).clamp(i32::MIN as i64, i32::MAX as i64) as i32;
        at(start)..at(start + length)
    }
}

/// One pass: along `axis`, every channel, as f32 (X) or the original
/// input's types (Y, whose second input is the original); u32 channels
/// (`nearest_only`) stay u32 on both.
pub struct Pass {
    axis: Axis,
    target: Target,
    filter: Filter,
    geometry: OnceLock<Geometry>,
    /// The last bands' taps across (`Pass::across`): every band of a frame
    /// has the same columns, so they are worked out (with their sines)
    /// once, not per band.
    across_taps: Mutex<Option<(TapsKey, Arc<ColumnTaps>)>>,
}

/// Per output column: the offsets in the input row of its taps, and their
/// weights; and per run of `GROUP` columns, those taps laid out to be
/// summed together where every column of the run has as many, consecutive
/// (not at the edges, nor where a tap of weight 0 is left out).
struct ColumnTaps {
    columns: Vec<(Vec<usize>, Vec<f32>)>,
    groups: Vec<Option<Group>>,
}

/// Columns summed together: eight chains of additions that do not wait on
/// each other, their products vectorised (the across pass was 23% of the
/// 4K dailies' instructions, one dependent addition and three bounds checks
/// a tap).
const GROUP: usize = 8;

/// `GROUP` columns' taps, each `n` pixels from its `first`: weight `k` of
/// column `j` at `weights[k * GROUP + j]`.
struct Group {
    first: [usize; GROUP],
    n: usize,
    weights: Vec<f32>,
}

impl ColumnTaps {
    fn new(columns: Vec<(Vec<usize>, Vec<f32>)>) -> Self {
        let groups = columns.chunks(GROUP).map(Group::of).collect();
        ColumnTaps { columns, groups }
    }

    /// Each value the sum of its column's taps in `row`, `w * row[i]`
    /// added in tap order from -0.0 (as `Iterator::sum`): the same bits
    /// in a group as alone.
    fn filter(&self, row: &[f32], values: &mut [f32]) {
        let runs = values.chunks_mut(GROUP).zip(self.columns.chunks(GROUP));
        for ((values, columns), group) in runs.zip(&self.groups) {
            if let Some(group) = group {
                group.sum(row, values);
                continue;
            }
            for (v, (at, w)) in values.iter_mut().zip(columns) {
                *v = at.iter().zip(w).map(|(&i, &w)| w * row[i]).sum();
            }
        }
    }
}

impl Group {
    fn of(columns: &[(Vec<usize>, Vec<f32>)]) -> Option<Group> {
        let n = columns.first()?.0.len();
        let consecutive = |(at, _): &(Vec<usize>, Vec<f32>)| {
            at.len() == n && at.windows(2).all(|p| p[1] == p[0] + 1)
        };
        if columns.len() != GROUP || n == 0 || !columns.iter().all(consecutive) {
            return None;
        }
        Some(Group {
            first: std::array::from_fn(|j| columns[j].0[0]),
            n,
            weights: (0..n)
                .flat_map(|k| columns.iter().map(move |(_, w)| w[k]))
                .collect(),
        })
    }

    fn sum(&self, row: &[f32], values: &mut [f32]) {
        let taps: [&[f32]; GROUP] = self.first.map(|f| &row[f..f + self.n]);
        let mut sums = [-0.0f32; GROUP];
        for (k, w) in self.weights.chunks_exact(GROUP).enumerate() {
            let x: [f32; GROUP] = std::array::from_fn(|j| taps[j][k]);
            for j in 0..GROUP {
                sums[j] += w[j] * x[j];
            }
        }
        values.copy_from_slice(&sums);
    }
}

/// What the taps across depend on besides the geometry: the output's first
/// column and valid columns, the input's first column and valid columns.
type TapsKey = (i32, Range<usize>, i32, Range<usize>);

/// Its parameters: the geometry and taps are worked out from the frames
/// (`Op`'s `Debug`: what the fingerprint records).
impl std::fmt::Debug for Pass {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Pass")
            .field("axis", &self.axis)
            .field("target", &self.target)
            .field("filter", &self.filter)
            .finish_non_exhaustive()
    }
}

impl Pass {
    fn new(axis: Axis, target: Target, filter: Filter) -> Self {
        Pass {
            axis,
            target,
            filter,
            geometry: OnceLock::new(),
            across_taps: Mutex::new(None),
        }
    }

    fn geometry(&self) -> &Geometry {
        self.geometry.get().expect("the display window comes first")
    }
}

impl Op for Pass {
    /// Across: an input row as f32, a row of values and of nearest columns,
    /// and the columns' taps, again in groups (shared by the bands: counted
    /// with each);
    /// down: a row of sums.
    fn scratch(&self, band: &Band) -> usize {
        let taps = self.geometry.get().map_or(1, |g| 2 * g.radius as usize + 1);
        match self.axis {
            Axis::X => band.widths[0] * 4 + band.width * (24 + 48 + 16 * taps),
            Axis::Y => band.width * 4 + taps * 4,
        }
    }

    fn display_window(&self, inputs: &[Display]) -> Result<Option<Display>, String> {
        // The length from the original's display window (the vertical
        // pass's second input: the first's is already resized across).
        let display = inputs[0].window;
        let from = self.axis.range(display);
        let original = inputs[inputs.len() - 1];
        let length = self.target.length(self.axis, original);
        let copies = [Axis::X, Axis::Y]
            .iter()
            .all(|&a| self.target.length(a, original) == a.range(original.window).len());
        let new = Geometry::new(from, length, self.filter, copies);
        let first = self.geometry.get_or_init(|| new.clone());
        if *first != new {
            return Err(format!(
                "resize: the display window changed size within the sequence ({} pixels along \
                 {:?}, the first frame's {}): resize one size at a time",
                new.from.len(),
                self.axis,
                first.from.len()
            ));
        }
        Ok(Some(Display {
            window: self.axis.with(display, first.to.clone()),
            pixel_aspect: self.target.pixel_aspect(original.pixel_aspect),
        }))
    }

    fn data_window(&self, inputs: &[IntegerBounds]) -> IntegerBounds {
        if inputs[0].size.area() == 0 {
            return IntegerBounds::zero();
        }
        let range = self.geometry().data(self.axis.range(inputs[0]));
        self.axis.with(inputs[0], range)
    }

    fn request(&self, out: IntegerBounds) -> Option<IntegerBounds> {
        // Asked before any frame (whether it resamples: it does), or at the
        // same size: the output's own pixels.
        let Some(geometry) = self.geometry.get().filter(|g| !g.copies) else {
            return Some(out);
        };
        let source = geometry.source(self.filter, self.axis.range(out));
        Some(self.axis.with(out, source))
    }

    fn channels(&self, inputs: &[&[ChannelDescription]]) -> Vec<ChannelDescription> {
        let sample_type = |c: &ChannelDescription| match self.axis {
            Axis::X if !nearest_only(c.sample_type) => SampleType::F32,
            _ => c.sample_type,
        };
        inputs[inputs.len() - 1]
            .iter()
            .map(|c| ChannelDescription {
                sample_type: sample_type(c),
                ..c.clone()
            })
            .collect()
    }

    /// At the same size, the vertical pass is its original input (whose
    /// types it has), the horizontal one unread.
    fn carries(&self, inputs: &[&[ChannelDescription]]) -> Option<Carried> {
        let copies = self.axis == Axis::Y && self.geometry.get()?.copies;
        copies.then(|| Carried {
            input: 1,
            channels: (0..inputs[1].len()).collect(),
            shift: (0, 0),
        })
    }

    fn compute(&self, _frame: i64, inputs: &[&Rows], out: &mut RowsMut) -> Result<(), String> {
        match (self.axis, self.geometry().copies) {
            (Axis::X, true) => {}
            (Axis::Y, true) => copy_moved(inputs[1], out, (0, 0)),
            (Axis::X, false) => self.across(inputs[0], out),
            (Axis::Y, false) => self.down(inputs[0], out),
        }
        Ok(())
    }
}

impl Pass {
    /// The taps of output `columns` in `input`'s rows, clamped to its valid
    /// `data` columns: the last bands', if they were the same.
    fn taps_across(
        &self,
        input: &Rows,
        out: &RowsMut,
        columns: Range<usize>,
        data: Range<usize>,
    ) -> Arc<ColumnTaps> {
        let key = (out.x, columns.clone(), input.x, data.clone());
        let mut cached = self.across_taps.lock().unwrap_or_else(|e| e.into_inner());
        if let Some((_, taps)) = cached.as_ref().filter(|(k, _)| *k == key) {
            return taps.clone();
        }
        let geometry = self.geometry();
        let mut weights = Vec::new();
        // The data window's columns, in the picture's coordinates.
        let data = input.x + data.start as i32..input.x + data.end as i32;
        let taps = columns
            .map(|c| {
                let first = geometry.taps(self.filter, out.x + c as i32, &mut weights);
                weights
                    .iter()
                    .zip(first..)
                    .filter(|&(&w, _)| w != 0.0)
                    .filter_map(|(&w, p)| {
                        Some(((geometry.read_at(p, &data)? - input.x) as usize, w))
                    })
                    .unzip()
            })
            .collect();
        let taps = Arc::new(ColumnTaps::new(taps));
        *cached = Some((key, taps.clone()));
        taps
    }

    /// Each row filtered across: output column x from its taps in the row
    /// (clamped to the display window, black outside the data window).
    fn across(&self, input: &Rows, out: &mut RowsMut) {
        let (columns, data) = (out.valid_columns(), input.valid_columns());
        if columns.is_empty() || data.is_empty() {
            return;
        }
        let taps = self.taps_across(input, out, columns.clone(), data.clone());
        let geometry = self.geometry();
        let (lo, hi) = (data.start as i32, data.end as i32 - 1);
        // Each column's nearest source column, for u32 channels (none else).
        let ids = input.planes.iter().any(|p| nearest_only(p.kind()));
        let nearest: Vec<usize> = match ids {
            true => columns
                .clone()
                .map(|c| (geometry.nearest(out.x + c as i32) - input.x).clamp(lo, hi) as usize)
                .collect(),
            false => Vec::new(),
        };
        let mut row = vec![0.0f32; input.width];
        let mut values = vec![0.0f32; columns.len()];
        for y in out.valid_rows() {
            let range = out.row_range(y);
            for (c, plane) in out.planes.iter_mut().enumerate() {
                let (source, start) = (&input.planes[c], input.row_range(y).start);
                if nearest_only(source.kind()) {
                    let at = nearest.iter().map(|&i| Some(start + i));
                    plane.gather(
                        range.start + columns.start..range.start + columns.end,
                        source,
                        at,
                    );
                    continue;
                }
                source.read_f32(input.row_range(y), &mut row);
                taps.filter(&row, &mut values);
                plane.write_f32(
                    range.start + columns.start..range.start + columns.end,
                    &values,
                );
            }
        }
    }

    /// Each output row from its taps among the first pass's rows (clamped
    /// to the display window, black outside the data window, a tap of
    /// weight 0 not read: 0 · ∞ is not taken). The first pass's region may
    /// start left of the
    /// output's (grown by the graph's reach: `engine::region`), so its
    /// columns are offset.
    fn down(&self, across: &Rows, out: &mut RowsMut) {
        let (rows, columns) = (across.valid_rows(), out.valid_columns());
        if rows.is_empty() || columns.is_empty() {
            return;
        }
        // The first pass's sample of the output's first valid column.
        let first_column = (out.x + columns.start as i32 - across.x) as usize;
        let geometry = self.geometry();
        let mut weights = Vec::new();
        let mut sums = vec![0.0f32; columns.len()];
        for y in out.valid_rows() {
            let first = geometry.taps(self.filter, y, &mut weights);
            let range = out.row_range(y);
            let to = range.start + columns.start..range.start + columns.end;
            for (c, plane) in out.planes.iter_mut().enumerate() {
                let source = match &across.planes[c] {
                    Samples::F32(source) => source,
                    // u32, nearest across: the nearest row.
                    ids => {
                        let from = geometry.nearest(y).clamp(rows.start, rows.end - 1);
                        let line = across.row_range(from).start + first_column;
                        plane.gather(to.clone(), ids, (line..).map(Some));
                        continue;
                    }
                };
                sums.fill(0.0);
                for (i, &w) in weights.iter().enumerate() {
                    let Some(from) = geometry.read_at(first + i as i32, &rows) else {
                        continue;
                    };
                    if w == 0.0 {
                        continue;
                    }
                    let line = across.row_range(from).start + first_column;
                    let line = &source[line..line + columns.len()];
                    for (sum, v) in sums.iter_mut().zip(line) {
                        *sum += w * v;
                    }
                }
                plane.write_f32(to.clone(), &sums);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes_parse_and_bad_ones_say_what_is_expected() {
        assert_eq!(
            Size::parse("1920x1080"),
            Ok(Size {
                width: 1920,
                height: 1080
            })
        );
        for bad in ["1920", "0x10", "ax2", "10x"] {
            assert!(
                Size::parse(bad).unwrap_err().contains("expected WxH"),
                "{bad}"
            );
        }
    }

    /// The sizes a fit gives, worked by hand from the rule (specs/ops.md,
    /// "reformat"): the picture's shape, width x pixel aspect over height,
    /// is kept but by distort.
    #[test]
    fn a_fit_keeps_the_pictures_shape_across_pixel_aspect_ratios() {
        let shown = |w, h, pixel_aspect| Display {
            window: IntegerBounds::new((0, 0), (w, h)),
            pixel_aspect,
        };
        let fit = |old: Display, (w, h, r): (usize, usize, f32), fit| {
            let target = Target::Fit(
                Size {
                    width: w,
                    height: h,
                },
                r,
                fit,
            );
            (
                target.length(Axis::X, old),
                target.length(Axis::Y, old),
                target.pixel_aspect(old.pixel_aspect),
            )
        };
        let anamorphic = shown(1828, 1556, 2.0);
        let hd = (1920, 1080, 1.0);
        // 1920 / 1828 across; down, that times 1 / 2: 1556 x 0.5252 = 817.2.
        assert_eq!(fit(anamorphic, hd, Fit::Width), (1920, 817, 1.0));
        // 1080 / 1556 down; across, that times 2: 1828 x 1.3882 = 2537.6.
        assert_eq!(fit(anamorphic, hd, Fit::Height), (2538, 1080, 1.0));
        assert_eq!(fit(anamorphic, hd, Fit::Inside), (1920, 817, 1.0));
        assert_eq!(fit(anamorphic, hd, Fit::Fill), (2538, 1080, 1.0));
        assert_eq!(fit(anamorphic, hd, Fit::Distort), (1920, 1080, 1.0));
        // Square pixels into an anamorphic format: squeezed across.
        let square = shown(3656, 1556, 1.0);
        let scope = (1828, 1556, 2.0);
        assert_eq!(fit(square, scope, Fit::Height), (1828, 1556, 2.0));
        // The same ratio on both sides: as square pixels (1.0 to 1.0).
        let pal = shown(720, 576, 1.09);
        assert_eq!(fit(pal, (360, 400, 1.09), Fit::Inside), (360, 288, 1.09));
        // A plain resize keeps the ratio.
        assert_eq!(Target::Scale(0.5).pixel_aspect(2.0), 2.0);
    }

    /// Columns summed in groups give the bits of each summed alone, in
    /// tap order from -0.0: magnitudes 1e8 apart that partly cancel
    /// (another order rounds otherwise), a column whose products are all
    /// -0.0, infinities, NaN.
    #[test]
    fn columns_summed_together_give_the_bits_of_one_at_a_time() {
        let mut row: Vec<f32> = (0..64)
            .map(|i| (i as f32 * 1.7).sin() * [1.0, 1e8, -1e8][i % 3])
            .collect();
        row[16..21].fill(-0.0);
        row[40] = f32::INFINITY;
        row[45] = f32::NAN;
        // 25 columns of 5 taps, two pixels apart: three groups and one
        // column alone.
        let columns: Vec<(Vec<usize>, Vec<f32>)> = (0..25)
            .map(|c| {
                let w = (0..5).map(|k| 0.1 + ((c * 7 + k) as f32 * 0.61).cos().abs());
                ((2 * c..2 * c + 5).collect(), w.collect())
            })
            .collect();
        let taps = ColumnTaps::new(columns.clone());
        let grouped: Vec<bool> = taps.groups.iter().map(Option::is_some).collect();
        assert_eq!(grouped, [true, true, true, false]);
        let mut values = vec![0.0; 25];
        taps.filter(&row, &mut values);
        let alone = columns
            .iter()
            .map(|(at, w)| -> f32 { at.iter().zip(w).map(|(&i, &w)| w * row[i]).sum() });
        let bits = |v: f32| v.to_bits();
        assert!(values[8] == 0.0 && values[8].is_sign_negative());
        assert_eq!(
            values.iter().map(|&v| bits(v)).collect::<Vec<_>>(),
            alone.map(bits).collect::<Vec<_>>()
        );
    }
}
