//! transform's filtered sampling, computed as OpenImageIO's warp computes it
//! (`ImageBufAlgo::warp`, oiiotool's `--rotate` and `--warp`): the map built
//! and inverted in f32 with Imath's row-vector matrices, each output pixel
//! centre mapped in f32, and the taps of the window `floor(s - W/2) ..
//! ceil(s + W/2)` weighed `f(x) f(y)` at f32 distances, summed row by row
//! and divided by the sum of all the window's weights. At ties (a point on
//! the half-pixel grid, a tap on the filter's edge, as at 45°) which side
//! a tap falls is then oiiotool's, so box and gaussian agree to the bit.
//! Where the map shrinks, the filter widens by the inverse map's largest
//! derivative along each axis above 1 (`filtered_sample`'s isotropic
//! footprint). Formulas: specs/ops.md, "transform".

use super::resize::Filter;
use crate::io::rows::{Rows, Samples};

/// x' = x a + y c + e, y' = x b + y d + f: Imath's `M33f` (row vectors),
/// its rows `[a, b]`, `[c, d]`, `[e, f]`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SampleMap([f32; 6]);

impl SampleMap {
    /// The inverse of `translate(-centre) · linear · translate(centre +
    /// shift)` (row-vector order: applied left to right), `linear` a 2x2
    /// row-vector matrix `[a, b, c, d]`, built and inverted as Imath does.
    pub fn inverse_of(linear: [f32; 4], centre: (f32, f32), shift: (f32, f32)) -> SampleMap {
        let [a, b, c, d] = linear;
        let (cx, cy) = centre;
        // translate(-centre) · linear: its last row (the sums' zero terms
        // are exact).
        let e = -cx * a + -cy * c;
        let f = -cx * b + -cy * d;
        // · translate(centre + shift).
        let (e, f) = (e + (cx + shift.0), f + (cy + shift.1));
        // Imath's affine inverse (Matrix33::inverse, last column 0, 0, 1).
        let r = a * d - c * b;
        let (ia, ib, ic, id) = (d / r, -b / r, -c / r, a / r);
        SampleMap([ia, ib, ic, id, -e * ia - f * ic, -e * ib - f * id])
    }

    /// Output pixel (x, y)'s centre mapped: OpenImageIO's `robust_multVecMatrix`.
    pub fn apply(&self, x: i32, y: i32) -> (f32, f32) {
        let [a, b, c, d, e, f] = self.0;
        let (x, y) = (x as f32 + 0.5, y as f32 + 0.5);
        (x * a + y * c + e, x * b + y * d + f)
    }

    /// How much the filter widens along s and t: the largest of 1 and the
    /// map's derivatives of s (of t) by x and y, as `filtered_sample`
    /// takes them (the derivatives of an affine map are its matrix's).
    pub fn stretch(&self) -> (f32, f32) {
        let [a, b, c, d, _, _] = self.0;
        (
            1f32.max(a.abs().max(c.abs())),
            1f32.max(b.abs().max(d.abs())),
        )
    }
}

/// The most taps along one axis of `filter` widened by `stretch`.
pub fn most_taps(filter: Filter, stretch: f32) -> usize {
    (filter.width() * stretch).ceil() as usize + 2
}

/// The source pixels `lo..hi`: held and inside the data; the filter
/// widened by `stretch` along each axis (`SampleMap::stretch`).
pub struct Taps {
    pub lo: (i32, i32),
    pub hi: (i32, i32),
    pub stretch: (f32, f32),
}

/// One output pixel's taps: the window's first column and row, where its
/// weights along each axis over the whole window start in the row's
/// weights (`nx` of x, then `ny` of y), the part of it inside the source
/// pixels (`x0..x1`, `y0..y1`, offsets into the window), and the sum of
/// all the window's 2-D weights.
pub struct Weights {
    x: i32,
    y: i32,
    at: usize,
    nx: usize,
    cut: [usize; 4],
    total: f32,
}

impl Taps {
    /// The sample index in `rows` of the pixel holding source point (u, v)
    /// (pixel coordinates), if it is one of the source pixels.
    pub fn nearest(&self, u: f64, v: f64, rows: &Rows) -> Option<usize> {
        let (x, y) = (u.floor(), v.floor());
        let inside = |p: f64, lo: i32, hi: i32| p >= lo as f64 && p < hi as f64;
        (inside(x, self.lo.0, self.hi.0) && inside(y, self.lo.1, self.hi.1))
            .then(|| rows.row_range(y as i32).start + (x as i32 - rows.x) as usize)
    }

    /// The taps of `filter` at source point (s, t) (pixel coordinates),
    /// their weights pushed to `pool` (a row's).
    pub fn at(&self, filter: Filter, s: f32, t: f32, pool: &mut Vec<f32>) -> Weights {
        let width = filter.width();
        let at = pool.len();
        // Along one axis: the window, its weights at (p + 0.5) - s (scaled
        // by 1 / stretch, the filter's own width kept), and the part of it
        // from lo to hi.
        let mut axis = |s: f32, stretch: f32, lo: i32, hi: i32| {
            let (radius, inverse) = (0.5 * stretch * width, 1.0 / stretch);
            let first = (s - radius).floor() as i32;
            let n = ((s + radius).ceil() as i32).saturating_sub(first).max(0);
            let n = n.min(most_taps(filter, stretch) as i32);
            pool.extend((0..n).map(|i| filter.at(inverse * ((first + i) as f32 + 0.5 - s), width)));
            let cut = |p: i32| (p.clamp(first, first + n) - first) as usize;
            (first, n as usize, cut(lo), cut(hi))
        };
        let (x, nx, x0, x1) = axis(s, self.stretch.0, self.lo.0, self.hi.0);
        let (y, ny, y0, y1) = axis(t, self.stretch.1, self.lo.1, self.hi.1);
        let (wx, wy) = pool[at..].split_at(nx);
        let mut total = 0.0f32;
        for &v in &wy[..ny] {
            for &u in wx {
                total += u * v;
            }
        }
        Weights {
            x,
            y,
            at,
            nx,
            cut: [x0, x1, y0, y1],
            total,
        }
    }
}

impl Weights {
    /// The weighted sum of `source`'s taps (a plane of `rows`), row by row,
    /// over the sum of the weights (`pool`: the row's, as `Taps::at` left
    /// it); taps of weight 0 are not read (an infinity there would make
    /// NaN), those outside the source are black.
    pub fn apply(&self, pool: &[f32], source: &Samples, rows: &Rows) -> f32 {
        let [x0, x1, y0, y1] = self.cut;
        if self.total <= 0.0 || x0 == x1 {
            return 0.0;
        }
        let (wx, wy) = pool[self.at..].split_at(self.nx);
        let mut sum = 0.0f32;
        for j in y0..y1 {
            let start =
                rows.row_range(self.y + j as i32).start + (self.x + x0 as i32 - rows.x) as usize;
            let wy = wy[j];
            let weights = wx[x0..x1].iter().map(|&u| u * wy);
            match source {
                Samples::F16(v) => add(&mut sum, weights, &v[start..], |s| s.to_f32()),
                Samples::F32(v) => add(&mut sum, weights, &v[start..], |s| s),
                Samples::U32(_) => unreachable!("u32 channels take the nearest sample"),
            }
        }
        sum / self.total
    }
}

fn add<T: Copy>(
    sum: &mut f32,
    weights: impl Iterator<Item = f32>,
    samples: &[T],
    value: impl Fn(T) -> f32,
) {
    for (w, &s) in weights.zip(samples) {
        if w != 0.0 {
            *sum += w * value(s);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// oiiotool's `--rotate 45` of a 48x36 image (about (24, 18)): Imath's
    /// f32 arithmetic, checked against the bits it gives.
    #[test]
    fn the_map_is_imaths_in_f32() {
        let a = 45f32 * (std::f64::consts::PI / 180.0) as f32;
        let (s, c) = (a.sin(), a.cos());
        let map = SampleMap::inverse_of([c, s, -s, c], (24.0, 18.0), (0.0, 0.0));
        // The inverse of a turn is its transpose, up to f32 rounding.
        let [ia, ib, ic, id, _, _] = map.0;
        assert!((ia - c).abs() < 1e-6 && (ib + s).abs() < 1e-6);
        assert!((ic - s).abs() < 1e-6 && (id - c).abs() < 1e-6);
        // Pixel (23, 17)'s centre, half a pixel up and left of the turn's
        // centre, is turned back by 45° about it.
        let (u, v) = map.apply(23, 17);
        let back = 24.0 - 0.5 * std::f32::consts::SQRT_2;
        assert!(
            (u - back).abs() < 1e-5 && (v - 18.0).abs() < 1e-5,
            "{u} {v}"
        );
    }

    /// A point on a pixel edge takes both pixels beside it at the box's
    /// edge (|x| = 0.5 is in), and their weights sum to what is divided.
    #[test]
    fn a_box_on_a_tie_takes_both_pixels() {
        let taps = Taps {
            lo: (0, 0),
            hi: (10, 10),
            stretch: (1.0, 1.0),
        };
        let mut pool = Vec::new();
        let w = taps.at(Filter::Box, 4.0, 4.5, &mut pool);
        assert_eq!((w.x, w.y), (3, 4));
        assert_eq!(w.total, 2.0);
        assert_eq!(&pool[..2], &[1.0, 1.0]);
    }

    /// Shrinking by 4 along x (the inverse map's derivative 4) widens the
    /// box to four pixels there, each weighed 1 (at a quarter of their
    /// distance); y keeps its one pixel of two taps.
    #[test]
    fn a_shrinking_map_widens_the_filter() {
        let map = SampleMap::inverse_of([0.25, 0.0, 0.0, 1.0], (0.0, 0.0), (0.0, 0.0));
        assert_eq!(map.stretch(), (4.0, 1.0));
        let taps = Taps {
            lo: (0, 0),
            hi: (20, 20),
            stretch: map.stretch(),
        };
        let mut pool = Vec::new();
        let w = taps.at(Filter::Box, 10.0, 5.3, &mut pool);
        assert_eq!((w.x, w.y, w.nx), (8, 4, 4));
        assert_eq!(&pool[..6], &[1.0, 1.0, 1.0, 1.0, 0.0, 1.0]);
        assert_eq!(w.total, 4.0);
    }
}
