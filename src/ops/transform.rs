//! `transform`: translate, rotate, scale and skew about a centre, and flip
//! or flop, as Nuke's Transform (its knobs' values and senses: y up,
//! degrees counter-clockwise), resampled by inverse mapping with a filter.
//! A map that puts every pixel centre on a pixel centre (whole-pixel moves,
//! flips, quarter turns) moves the samples as they are, whatever the
//! filter, and a whole-pixel move alone is a data window move whose blocks
//! can be the input's chunks (`Op::carries`). u32 channels (ids) take the
//! nearest sample. The output's data window is the transformed input
//! window's bounding box; the display window is kept. It streams: what it
//! reads of its input (`Op::request`) is the inverse-mapped footprint of the
//! output rows asked for, clipped to the input's data, plus the filter's
//! radius. Formulas and memory: specs/ops.md, "transform".

use super::crop::copy_moved;
use super::declare::{params, Args, Length, Operation, Value};
use super::resize::{nearest_only, Filter};
use super::warp::{most_taps, SampleMap, Taps, Weights};
use crate::engine::graph::{union, Band, Carried, Display, GraphBuilder, NodeId, Op};
use crate::io::rows::{Rows, RowsMut};
use crate::params::{Bound, CENTER, ROTATE, SKEW, TRANSFORM_SCALE, TRANSLATE};
use exr::meta::attribute::{ChannelDescription, IntegerBounds};
use std::sync::{Mutex, OnceLock};

pub const TRANSFORM: Operation = Operation {
    name: "transform",
    about: "Translate, rotate, scale and skew about a centre, flip or flop, as Nuke's Transform \
            (y up, degrees counter-clockwise), filtered; the data window becomes the transformed \
            one's bounding box, the display window is kept",
    params: Params::PARAMS,
    build,
    // One input, no layer options, the input's header: as resize.
    ..super::resize::RESIZE
};

params! {
    pub struct Params {
        /// Move by X,Y pixels (y up, as Nuke's translate).
        translate: Pair [TRANSLATE] {pixels} = "0,0",
        /// Degrees counter-clockwise about the centre.
        rotate: f64 [ROTATE] = "0",
        /// A factor for both sides, or X,Y (negative mirrors) about the centre.
        scale: Pair [TRANSFORM_SCALE] = "1",
        /// X,Y: x moves by X times y, then y by Y times x (about the centre, y up).
        skew: Pair [SKEW] = "0,0",
        /// The centre X,Y in pixels from the display window's bottom left corner, y up (default its middle).
        center: Option<Pair> [CENTER] {pixels},
        /// Mirror top to bottom about the centre (oiiotool's --flip).
        flip: bool,
        /// Mirror left to right about the centre (oiiotool's --flop).
        flop: bool,
        /// impulse (nearest), box, triangle (bilinear), gaussian, mitchell or lanczos3.
        filter: Sampler = "lanczos3",
    }
}

fn build(args: &Args, graph: &mut GraphBuilder, inputs: &[NodeId]) -> Result<NodeId, String> {
    let p = Params::read(args)?;
    if p.scale.0.abs() < 1e-4 || p.scale.1.abs() < 1e-4 {
        return Err(format!("{}: scale must not be 0 (under 1e-4)", args.op));
    }
    Ok(graph.add(Transform::new(p), inputs))
}

/// Two numbers `X,Y`, or one for both.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pair(pub f64, pub f64);

impl Value for Pair {
    fn parse(text: &str) -> Result<Self, String> {
        Self::bounded(text, &TRANSLATE)
    }
    fn bounded(text: &str, bound: &Bound) -> Result<Self, String> {
        match bound.parse_list::<f64>(text)?[..] {
            [v] => Ok(Pair(v, v)),
            [x, y] => Ok(Pair(x, y)),
            _ => Err(format!(
                "{}: expected X,Y or one number, not '{text}'",
                bound.name
            )),
        }
    }
}

impl Length for Pair {
    fn scaled(text: &str, factor: f64) -> Result<String, String> {
        let Pair(x, y) = Pair::parse(text)?;
        Ok(format!("{},{}", x * factor, y * factor))
    }
}

/// How a source point is sampled: the nearest pixel, or one of resize's
/// filters at the source's scale.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Sampler {
    Impulse,
    Filter(Filter),
}

impl Value for Sampler {
    fn parse(text: &str) -> Result<Self, String> {
        if text.trim().eq_ignore_ascii_case("impulse") {
            return Ok(Sampler::Impulse);
        }
        Filter::parse(text).map(Sampler::Filter).map_err(|_| {
            format!(
                "unknown filter '{text}' (one of: {})",
                Self::CHOICES.join(", ")
            )
        })
    }
    const CHOICES: &'static [&'static str] = &[
        "impulse", "box", "triangle", "gaussian", "mitchell", "lanczos3",
    ];
}

impl Sampler {
    /// Pixels on each side of a source point that its taps may reach, the
    /// filter widened by `stretch` (`SampleMap::stretch`'s larger).
    fn reach(self, stretch: f32) -> f64 {
        match self {
            Sampler::Impulse => 1.0,
            Sampler::Filter(f) => (f.width() as f64 * stretch as f64 / 2.0).ceil() + 1.0,
        }
    }
}

/// How far from the origin a pixel of OpenEXR's windows can be (their
/// coordinates are within ±(2^30 - 1)).
const FARTHEST: f64 = (1u64 << 30) as f64;

/// How far a mapped point may be from a pixel edge (`covering`) or a map
/// from its whole-pixel snap (`Affine::snapped`) and count as on it.
const ON_PIXEL: f64 = 1e-6;

/// x' = a x + b y + c, y' = d x + e y + f, in pixel coordinates (y down,
/// pixel (i, j) covering [i, i + 1) x [j, j + 1)).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Affine([f64; 6]);

impl Affine {
    pub fn apply(&self, x: f64, y: f64) -> (f64, f64) {
        let [a, b, c, d, e, f] = self.0;
        (a * x + b * y + c, d * x + e * y + f)
    }

    /// The map with whole entries, when it puts every pixel centre on a
    /// pixel centre: its linear part a signed permutation (quarter turns,
    /// mirrors) and its offsets whole (centre `i + 0.5` goes to
    /// `±(i + 0.5) + c`). Taken when no point within OpenEXR's coordinates
    /// lands more than `ON_PIXEL` from where the whole map puts it. Quarter
    /// turns, mirrors and unit scales give exact entries (exact sines), so
    /// the slack is for offsets rounded in the centre's arithmetic; a real
    /// turn or scale, even by 1e-9, is far beyond it.
    fn snapped(&self) -> Option<Affine> {
        let whole = Affine(self.0.map(f64::round));
        let [a, b, _, d, e, _] = whole.0;
        let permutes = a.abs() + b.abs() == 1.0 && d.abs() + e.abs() == 1.0 && a.abs() != d.abs();
        let off = |k: usize| (self.0[k] - whole.0[k]).abs();
        let close = [0, 3]
            .iter()
            .all(|&row| FARTHEST * (off(row) + off(row + 1)) + off(row + 2) < ON_PIXEL);
        (permutes && close).then_some(whole)
    }

    /// For a whole-pixel move alone (no turn or mirror): output pixel
    /// (x, y) is input pixel (x + dx, y + dy) of this map, the inverse.
    fn shift(&self) -> Option<(i32, i32)> {
        let [a, b, c, d, e, f] = self.0;
        ([a, b, d, e] == [1.0, 0.0, 0.0, 1.0]).then_some((c as i32, f as i32))
    }

    fn inverse(&self) -> Affine {
        let [a, b, c, d, e, f] = self.0;
        let det = a * e - b * d;
        let (ia, ib, id, ie) = (e / det, -b / det, -d / det, a / det);
        Affine([ia, ib, -(ia * c + ib * f), id, ie, -(id * c + ie * f)])
    }

    /// The bounding box of `rect` (pixel edges) mapped, after clipping the
    /// mapped quadrilateral to `clip` when it is given and they meet.
    fn bounds(&self, rect: IntegerBounds, clip: Option<IntegerBounds>) -> [f64; 4] {
        let (x0, y0) = (rect.position.x() as f64, rect.position.y() as f64);
        let (x1, y1) = (rect.end().x() as f64, rect.end().y() as f64);
        let mut polygon: Vec<(f64, f64)> = [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]
            .iter()
            .map(|&(x, y)| self.apply(x, y))
            .collect();
        if let Some(clip) = clip.filter(|c| c.size.area() > 0) {
            let clipped = clip_to(&polygon, clip);
            if !clipped.is_empty() {
                polygon = clipped;
            }
        }
        polygon.iter().fold(
            [f64::MAX, f64::MAX, f64::MIN, f64::MIN],
            |[a, b, c, d], &(x, y)| [a.min(x), b.min(y), c.max(x), d.max(y)],
        )
    }
}

/// `polygon` (convex) clipped to `rect`'s pixel edges (Sutherland–Hodgman).
fn clip_to(polygon: &[(f64, f64)], rect: IntegerBounds) -> Vec<(f64, f64)> {
    let (x0, y0) = (rect.position.x() as f64, rect.position.y() as f64);
    let (x1, y1) = (rect.end().x() as f64, rect.end().y() as f64);
    // Each edge: a point's signed distance inside it.
    let edges: [&dyn Fn((f64, f64)) -> f64; 4] =
        [&|p| p.0 - x0, &|p| x1 - p.0, &|p| p.1 - y0, &|p| y1 - p.1];
    let mut points = polygon.to_vec();
    for inside in edges {
        let mut kept = Vec::with_capacity(points.len() + 1);
        for (i, &p) in points.iter().enumerate() {
            let q = points[(i + 1) % points.len()];
            let (dp, dq) = (inside(p), inside(q));
            if dp >= 0.0 {
                kept.push(p);
            }
            if (dp >= 0.0) != (dq >= 0.0) {
                let t = dp / (dp - dq);
                kept.push((p.0 + t * (q.0 - p.0), p.1 + t * (q.1 - p.1)));
            }
        }
        points = kept;
        if points.is_empty() {
            break;
        }
    }
    points
}

/// Sine and cosine of `degrees`, exact at multiples of 90.
fn sin_cos(degrees: f64) -> (f64, f64) {
    let quarter = degrees / 90.0;
    if quarter.fract() == 0.0 {
        return [(0.0, 1.0), (1.0, 0.0), (0.0, -1.0), (-1.0, 0.0)]
            [quarter.rem_euclid(4.0) as usize];
    }
    degrees.to_radians().sin_cos()
}

impl Params {
    /// The inverse map filters sample by, in f32 as OpenImageIO's warp
    /// builds it (`ImageBufAlgo::rotate`: translate(-centre), rotate,
    /// translate(centre), Imath's row vectors, y down): the linear part is
    /// skew, scale and mirrors, then the turn by `-rotate` degrees (its
    /// sine and cosine in f32, exact at multiples of 90°); with none but a
    /// turn it is oiiotool's `--rotate` matrix to the bit.
    fn sampling(&self, display: IntegerBounds) -> SampleMap {
        let (cx, cy) = self.centre(display);
        let (s, c) = match (self.rotate / 90.0).fract() == 0.0 {
            true => {
                let (s, c) = sin_cos(-self.rotate);
                (s as f32, c as f32)
            }
            false => {
                let a = (-self.rotate) as f32 * (std::f64::consts::PI / 180.0) as f32;
                (a.sin(), a.cos())
            }
        };
        let (sx, sy) = (
            (self.scale.0 * if self.flop { -1.0 } else { 1.0 }) as f32,
            (self.scale.1 * if self.flip { -1.0 } else { 1.0 }) as f32,
        );
        let (kx, ky) = (self.skew.0 as f32, self.skew.1 as f32);
        // Skew then scale (y up, columns), turned to y down rows.
        let sk = [sx, sx * kx, sy * ky, sy * (1.0 + ky * kx)];
        let g = [sk[0], -sk[2], -sk[1], sk[3]];
        let r = [c, s, -s, c];
        let linear = [
            g[0] * r[0] + g[1] * r[2],
            g[0] * r[1] + g[1] * r[3],
            g[2] * r[0] + g[3] * r[2],
            g[2] * r[1] + g[3] * r[3],
        ];
        let shift = (self.translate.0 as f32, -self.translate.1 as f32);
        SampleMap::inverse_of(linear, (cx as f32, cy as f32), shift)
    }

    /// The pivot in pixel coordinates (y down): `--center`, given from the
    /// display window's bottom left with y up, else the window's centre.
    fn centre(&self, display: IntegerBounds) -> (f64, f64) {
        let (left, bottom) = (display.position.x() as f64, display.end().y() as f64);
        match self.center {
            Some(Pair(x, y)) => (left + x, bottom - y),
            None => (
                left + display.size.width() as f64 / 2.0,
                bottom - display.size.height() as f64 / 2.0,
            ),
        }
    }

    /// The forward map for display window `display`: translate · centre ·
    /// rotate · scale · skew · centre⁻¹, built with y up (Nuke's) and
    /// turned to pixel coordinates (y down) by conjugating with y → -y.
    fn affine(&self, display: IntegerBounds) -> Affine {
        let (cx, cy) = self.centre(display);
        let (s, c) = sin_cos(self.rotate);
        let (sx, sy) = (
            self.scale.0 * if self.flop { -1.0 } else { 1.0 },
            self.scale.1 * if self.flip { -1.0 } else { 1.0 },
        );
        let (kx, ky) = (self.skew.0, self.skew.1);
        // Skew (x then y), scale, rotate: a 2x2 matrix, y up.
        let k = [1.0, kx, ky, 1.0 + ky * kx];
        let sk = [sx * k[0], sx * k[1], sy * k[2], sy * k[3]];
        let m = [
            c * sk[0] - s * sk[2],
            c * sk[1] - s * sk[3],
            s * sk[0] + c * sk[2],
            s * sk[1] + c * sk[3],
        ];
        // y down: the off-diagonal terms change sign, and so does ty.
        let (a, b, d, e) = (m[0], -m[1], -m[2], m[3]);
        let (tx, ty) = (self.translate.0, -self.translate.1);
        Affine([
            a,
            b,
            cx + tx - a * cx - b * cy,
            d,
            e,
            cy + ty - d * cx - e * cy,
        ])
    }
}

pub struct Transform {
    params: Params,
    /// The maps, from the first frame's display window (a sequence keeps it).
    maps: OnceLock<Maps>,
    /// The union of the input data windows seen so far: what a request is
    /// clipped to (a frame's is always in it by the time it is asked).
    data: Mutex<IntegerBounds>,
}

/// Its parameters: the maps and windows are worked out from the frames
/// (`Op`'s `Debug`: what the fingerprint records).
impl std::fmt::Debug for Transform {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Transform")
            .field("params", &self.params)
            .finish_non_exhaustive()
    }
}

impl Transform {
    pub fn new(params: Params) -> Self {
        Transform {
            params,
            maps: OnceLock::new(),
            data: Mutex::new(IntegerBounds::zero()),
        }
    }

    fn maps(&self) -> &Maps {
        self.maps.get().expect("the display window comes first")
    }
}

/// A display window's forward and inverse maps, snapped to whole pixels
/// when they put pixel centres on pixel centres (`exact`).
struct Maps {
    display: IntegerBounds,
    forward: Affine,
    inverse: Affine,
    exact: bool,
    /// The inverse as OpenImageIO computes it, where filters sample.
    sampling: SampleMap,
}

impl Maps {
    fn new(display: IntegerBounds, params: &Params) -> Self {
        let forward = params.affine(display);
        let snapped = forward.snapped();
        let forward = snapped.unwrap_or(forward);
        Maps {
            display,
            forward,
            inverse: forward.inverse(),
            exact: snapped.is_some(),
            sampling: params.sampling(display),
        }
    }
}

/// Whole pixels covering `[x0, y0, x1, y1]`, grown by `by` on each side;
/// within a millionth of a pixel edge counts as on it.
fn covering([x0, y0, x1, y1]: [f64; 4], by: f64) -> IntegerBounds {
    let snap = |v: f64| match (v - v.round()).abs() < ON_PIXEL {
        true => v.round(),
        false => v,
    };
    let (x0, y0) = ((snap(x0) - by).floor(), (snap(y0) - by).floor());
    let (x1, y1) = ((snap(x1) + by).ceil(), (snap(y1) + by).ceil());
    // Beyond OpenEXR's ±(2^30 - 1), so that planning refuses a window past
    // them as it is (not clipped, or emptied); corners and sides short of
    // i32's.
    let limit = ((1i64 << 31) - (1 << 24)) as f64;
    let (x0, y0) = (x0.clamp(-limit, limit), y0.clamp(-limit, limit));
    let (x1, y1) = (
        x1.clamp(x0, limit.min(x0 + limit)),
        y1.clamp(y0, limit.min(y0 + limit)),
    );
    IntegerBounds::new(
        (x0 as i32, y0 as i32),
        ((x1 - x0) as usize, (y1 - y0) as usize),
    )
}

impl Op for Transform {
    /// A row's taps (none for an exact map: a move copies, a flip takes
    /// the nearest samples, and their weights along each axis) and nearest
    /// samples, vectors grown by doubling (twice the columns at most), and
    /// its values.
    fn scratch(&self, band: &Band) -> usize {
        let maps = self.maps.get();
        // Asked before any frame: the unwidened filter's.
        let (s, t) = maps.map_or((1.0, 1.0), |m| m.sampling.stretch());
        let floats = match self.params.filter {
            Sampler::Filter(f) => most_taps(f, s) + most_taps(f, t),
            Sampler::Impulse => 0,
        };
        let weights = match maps.is_some_and(|m| m.exact) {
            true => 0,
            false => std::mem::size_of::<Weights>() + floats * std::mem::size_of::<f32>(),
        };
        band.width * (2 * (weights + std::mem::size_of::<Option<usize>>()) + 4)
    }

    fn display_window(&self, inputs: &[Display]) -> Result<Option<Display>, String> {
        let display = inputs[0].window;
        let first = self.maps.get_or_init(|| Maps::new(display, &self.params));
        if first.display != display {
            return Err(
                "transform: the display window changed within the sequence: transform one \
                 size at a time"
                    .into(),
            );
        }
        Ok(None)
    }

    fn data_window(&self, inputs: &[IntegerBounds]) -> IntegerBounds {
        if inputs[0].size.area() == 0 {
            return IntegerBounds::zero();
        }
        let mut seen = self.data.lock().expect("not poisoned");
        *seen = union(*seen, inputs[0]);
        covering(self.maps().forward.bounds(inputs[0], None), 0.0)
    }

    fn request(&self, out: IntegerBounds) -> Option<IntegerBounds> {
        let Some(maps) = self.maps.get() else {
            // Asked before any frame (whether it resamples): it does.
            return Some(out);
        };
        let data = *self.data.lock().expect("not poisoned");
        // An exact map reads the pixels it moves, no taps around them.
        let (s, t) = maps.sampling.stretch();
        let reach = match maps.exact {
            true => 0.0,
            false => self.params.filter.reach(s.max(t)),
        };
        Some(covering(maps.inverse.bounds(out, Some(data)), reach))
    }

    /// A whole-pixel move alone: the input's samples, moved.
    fn carries(&self, inputs: &[&[ChannelDescription]]) -> Option<Carried> {
        let maps = self.maps.get().filter(|m| m.exact)?;
        Some(Carried {
            input: 0,
            channels: (0..inputs[0].len()).collect(),
            shift: maps.inverse.shift()?,
        })
    }

    fn compute(&self, _frame: i64, inputs: &[&Rows], out: &mut RowsMut) -> Result<(), String> {
        let input = inputs[0];
        let maps = self.maps();
        if let Some(shift) = maps.inverse.shift().filter(|_| maps.exact) {
            copy_moved(input, out, shift);
            return Ok(());
        }
        let inverse = maps.inverse;
        // The source pixels there are: held and inside the data window.
        let have = crate::engine::graph::intersection(
            input.valid,
            IntegerBounds::new((input.x, input.y), (input.width, input.height)),
        );
        let columns = out.valid_columns();
        if have.size.area() == 0 || columns.is_empty() {
            return Ok(());
        }
        let taps = Taps {
            lo: (have.position.x(), have.position.y()),
            hi: (have.end().x(), have.end().y()),
            stretch: maps.sampling.stretch(),
        };
        // The filter, unless the map is exact or the sampler impulse: then
        // every channel takes its nearest sample, as u32 ones always do.
        let filter = match self.params.filter {
            Sampler::Filter(f) if !maps.exact => Some(f),
            _ => None,
        };
        let filtered: Vec<bool> = out
            .channels
            .iter()
            .map(|c| filter.is_some() && !nearest_only(c.sample_type))
            .collect();
        let filter = filter.filter(|_| filtered.contains(&true));
        let any_nearest = filtered.contains(&false);
        let mut values = vec![0.0f32; columns.len()];
        let (mut weights, mut nearest, mut pool) = (Vec::new(), Vec::new(), Vec::new());
        for y in out.valid_rows() {
            weights.clear();
            nearest.clear();
            pool.clear();
            for c in columns.clone() {
                let x = out.x + c as i32;
                if let Some(f) = filter {
                    let (s, t) = maps.sampling.apply(x, y);
                    weights.push(taps.at(f, s, t, &mut pool));
                }
                if any_nearest {
                    let (u, v) = inverse.apply(x as f64 + 0.5, y as f64 + 0.5);
                    nearest.push(taps.nearest(u, v, input));
                }
            }
            let range = out.row_range(y);
            let range = range.start + columns.start..range.start + columns.end;
            for (k, (plane, source)) in out.planes.iter_mut().zip(&input.planes).enumerate() {
                if !filtered[k] {
                    plane.gather(range.clone(), source, nearest.iter().copied());
                    continue;
                }
                for (value, w) in values.iter_mut().zip(&weights) {
                    *value = w.apply(&pool, source, input);
                }
                plane.write_f32(range.clone(), &values);
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ops::testing::{image_in, sample, Pixel};

    fn params(values: &[(&'static str, &str)]) -> Params {
        let args = Args {
            op: "transform",
            values: values.iter().map(|&(k, v)| (k, v.to_string())).collect(),
            layers: Default::default(),
            straight: false,
            job_file: false,
        };
        Params::read(&args).unwrap()
    }

    /// A `width` x `height` image at the origin (display window and data).
    fn source(width: usize, height: usize, value: Pixel) -> Rows {
        let window = IntegerBounds::new((0, 0), (width, height));
        image_in(0..width as i32, 0..height as i32, window, &[("R", value)])
    }

    /// The transform of `input` (whose display window is its data window),
    /// every output row computed at once from every input row.
    fn run(values: &[(&'static str, &str)], input: &Rows) -> Rows {
        let op = Transform::new(params(values));
        assert_eq!(op.display_window(&[Display::square(input.valid)]), Ok(None));
        let window = op.data_window(&[input.valid]);
        let mut out = Rows::zeros(
            window.position.x(),
            window.position.y(),
            window.size.width(),
            0,
            input.channels.clone(),
            window,
        );
        out.grow(window.size.height());
        let top = window.position.y();
        for mut band in out.bands(top, 3) {
            op.compute(0, &[input], &mut band).unwrap();
        }
        out
    }

    fn value(x: i32, y: i32) -> f32 {
        (x * 7 + y * 13 % 5) as f32 + 0.25 * y as f32
    }

    fn each(out: &Rows, mut check: impl FnMut(i32, i32, f32)) {
        for y in out.y..out.end() {
            for x in out.x..out.x + out.width as i32 {
                check(x, y, sample(out, "R", x, y).unwrap());
            }
        }
    }

    #[test]
    fn whole_pixel_translations_are_exact() {
        let input = source(9, 6, &value);
        for filter in ["impulse", "triangle", "box"] {
            // Nuke's y is up: +2 moves the image 2 rows up.
            let out = run(&[("translate", "3,2"), ("filter", filter)], &input);
            assert_eq!(out.valid, IntegerBounds::new((3, -2), (9, 6)), "{filter}");
            each(&out, |x, y, v| {
                assert_eq!(v, value(x - 3, y + 2), "{filter} {x},{y}")
            });
        }
    }

    #[test]
    fn quarter_and_half_turns_are_exact_whatever_the_filter() {
        let (w, h) = (6, 4);
        let input = source(w, h, &value);
        // Counter-clockwise about the centre (3, 2): the top row becomes
        // the left column, read from right to left downwards.
        let out = run(&[("rotate", "90"), ("filter", "impulse")], &input);
        assert_eq!(out.valid, IntegerBounds::new((1, -1), (4, 6)));
        each(&out, |x, y, v| {
            assert_eq!(v, value(4 - y, x - 1), "{x},{y}")
        });
        let out = run(&[("rotate", "-90"), ("filter", "impulse")], &input);
        each(&out, |x, y, v| {
            assert_eq!(v, value(y + 1, 4 - x), "{x},{y}")
        });
        for turn in [
            &[("rotate", "180")][..],
            &[("flip", "true"), ("flop", "true")],
        ] {
            let out = run(&[turn, &[("filter", "impulse")]].concat(), &input);
            assert_eq!(out.valid, input.valid);
            each(&out, |x, y, v| {
                assert_eq!(v, value(5 - x, 3 - y), "{x},{y}")
            });
        }
        let out = run(&[("flip", "true"), ("filter", "triangle")], &input);
        each(&out, |x, y, v| {
            assert_eq!(v, value(x, 3 - y), "flip {x},{y}")
        });
        // Whatever the filter: the samples are moved, not filtered.
        let out = run(&[("flop", "true"), ("filter", "lanczos3")], &input);
        each(&out, |x, y, v| {
            assert_eq!(v, value(5 - x, y), "flop {x},{y}")
        });
    }

    /// Bilinear interpolation of `f` at pixel coordinates (u, v), black
    /// outside `width` x `height`.
    fn bilinear(f: Pixel, width: i32, height: i32, u: f64, v: f64) -> f64 {
        let (s, t) = (u - 0.5, v - 0.5);
        let (x0, y0) = (s.floor() as i32, t.floor() as i32);
        let (fx, fy) = (s - x0 as f64, t - y0 as f64);
        let at = |x: i32, y: i32| match (0..width).contains(&x) && (0..height).contains(&y) {
            true => f(x, y) as f64,
            false => 0.0,
        };
        (1.0 - fy) * ((1.0 - fx) * at(x0, y0) + fx * at(x0 + 1, y0))
            + fy * ((1.0 - fx) * at(x0, y0 + 1) + fx * at(x0 + 1, y0 + 1))
    }

    #[test]
    fn any_transform_samples_where_the_inverse_map_says() {
        let (w, h) = (23, 17);
        let f = |x: i32, y: i32| ((x as f32 * 0.7).sin() + (y as f32 * 0.3).cos()) * 2.0;
        let input = source(w, h, &f);
        let out = run(
            &[
                ("translate", "2.5,-1.25"),
                ("rotate", "30"),
                // Enlarging: shrinking widens the filter past bilinear.
                ("scale", "1.3,1.2"),
                ("skew", "0.1,0"),
                ("center", "10,5"),
                ("filter", "triangle"),
            ],
            &input,
        );
        // The inverse, step by step in Nuke's coordinates (y up from the
        // bottom edge): untranslate, about the centre unrotate, unscale,
        // unskew.
        let (cx, cy) = (10.0, 5.0);
        let (s, c) = 30f64.to_radians().sin_cos();
        let inverse = |x: f64, y: f64| {
            let (x, y) = (x - 2.5 - cx, (h as f64 - y) + 1.25 - cy);
            let (x, y) = (c * x + s * y, -s * x + c * y);
            let (x, y) = (x / 1.3, y / 1.2);
            let x = x - 0.1 * y;
            (x + cx, h as f64 - (y + cy))
        };
        let mut nonzero = 0;
        each(&out, |x, y, v| {
            let (u, t) = inverse(x as f64 + 0.5, y as f64 + 0.5);
            let expected = bilinear(&f, w as i32, h as i32, u, t);
            assert!(
                (v as f64 - expected).abs() < 1e-4,
                "{x},{y}: {v} {expected}"
            );
            nonzero += (v != 0.0) as usize;
        });
        assert!(nonzero > w * h / 2, "{nonzero}");
    }

    #[test]
    fn a_band_reads_only_what_it_requests_and_that_is_flat_in_height() {
        let f = |x: i32, y: i32| (x % 11) as f32 + (y % 7) as f32 * 0.5;
        let input = source(40, 30, &f);
        let values = [
            ("rotate", "7"),
            ("translate", "0.3,0.6"),
            ("filter", "lanczos3"),
        ];
        let whole = run(&values, &input);
        let op = Transform::new(params(&values));
        op.display_window(&[Display::square(input.valid)]).unwrap();
        let window = op.data_window(&[input.valid]);
        for top in [window.position.y(), window.position.y() + 11] {
            let rows = top..top + 5;
            let asked = op
                .request(crate::engine::region::rows_of(window, &rows))
                .unwrap();
            let (y0, y1) = (asked.position.y().max(0), asked.end().y().min(30));
            let valid = IntegerBounds::new((0, 0), (40, 30));
            let held = image_in(0..40, y0..y1, valid, &[("R", &f)]);
            let mut out = Rows::zeros(
                window.position.x(),
                top,
                window.size.width(),
                0,
                held.channels.clone(),
                window,
            );
            out.grow(5);
            for mut band in out.bands(top, 5) {
                op.compute(0, &[&held], &mut band).unwrap();
            }
            each(&out, |x, y, v| {
                assert_eq!(v, sample(&whole, "R", x, y).unwrap())
            });
        }
        // A row of a wide image at a small angle reads about W tan θ rows,
        // whatever the height.
        let height = |h: usize| {
            let op = Transform::new(params(&[("rotate", "2")]));
            let input = IntegerBounds::new((0, 0), (4096, h));
            op.display_window(&[Display::square(input)]).unwrap();
            let window = op.data_window(&[input]);
            let middle = window.position.y() + window.size.height() as i32 / 2;
            op.request(crate::engine::region::rows_of(
                window,
                &(middle..middle + 1),
            ))
            .unwrap()
            .size
            .height()
        };
        let (short, tall) = (height(1000), height(16000));
        assert_eq!(short, tall);
        assert!(short < 4096 / 20 + 10, "{short}");
    }

    #[test]
    fn maps_that_put_centres_on_centres_are_snapped_and_no_others() {
        let snapped = |values: &[(&'static str, &str)], (w, h)| {
            let display = IntegerBounds::new((0, 0), (w, h));
            params(values).affine(display).snapped()
        };
        for values in [
            &[("translate", "3,-2")][..],
            &[("rotate", "90")],
            &[("rotate", "-90")],
            &[("rotate", "180")],
            &[("rotate", "270")],
            &[("rotate", "450")],
            &[("flip", "true")],
            &[("flop", "true")],
            &[("scale", "-1,1")],
            &[("rotate", "90"), ("flip", "true"), ("translate", "-5,7")],
            &[("translate", "3.0000000001,0")],
        ] {
            let exact = snapped(values, (6, 4));
            assert!(
                exact.is_some_and(|m| m.0.iter().all(|v| v.fract() == 0.0)),
                "{values:?}"
            );
        }
        // An offset rounded in the centre's arithmetic: 0.2 + 2.6 + 0.2.
        let rounded = [
            ("flop", "true"),
            ("center", "0.2,0"),
            ("translate", "2.6,0"),
        ];
        let display = IntegerBounds::new((0, 0), (6, 4));
        assert_eq!(params(&rounded).affine(display).0[2], 3.0000000000000004);
        assert_eq!(snapped(&rounded, (6, 4)).unwrap().0[2], 3.0);
        for values in [
            &[("translate", "0.5,0")][..],
            &[("translate", "3.00001,0")],
            &[("rotate", "1e-9")],
            &[("rotate", "90.000001")],
            &[("scale", "1.000000001")],
            &[("scale", "2")],
            &[("skew", "1e-12,0")],
        ] {
            assert_eq!(snapped(values, (6, 4)), None, "{values:?}");
        }
        // About the middle of a 5 x 4 frame a quarter turn lands centres on
        // corners; a half turn does not.
        assert_eq!(snapped(&[("rotate", "90")], (5, 4)), None);
        assert!(snapped(&[("rotate", "180")], (5, 4)).is_some());
        // A move alone: output pixel (x, y) is input pixel (x - 3, y - 2).
        let moved = snapped(&[("translate", "3,-2")], (6, 4)).unwrap();
        assert_eq!(moved.inverse().shift(), Some((-3, -2)));
        let turned = snapped(&[("rotate", "180")], (6, 4)).unwrap();
        assert_eq!(turned.inverse().shift(), None);
    }

    #[test]
    fn values_parse_and_bad_ones_are_refused() {
        assert_eq!(Pair::parse("1.5,-2"), Ok(Pair(1.5, -2.0)));
        assert_eq!(Pair::parse("3"), Ok(Pair(3.0, 3.0)));
        assert!(Pair::parse("1,2,3").is_err() && Pair::parse("x").is_err());
        assert_eq!(Sampler::parse("Impulse"), Ok(Sampler::Impulse));
        assert!(Sampler::parse("cubic")
            .unwrap_err()
            .contains("impulse, box"));
    }
}
