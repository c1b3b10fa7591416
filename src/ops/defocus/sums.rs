//! The sums of weights and weighted colours each output pixel gathers, in
//! O(R) per pixel: specs/ops.md, "defocus", gives the decomposition.

use super::aperture::Footprints;
use std::ops::Range;

/// Layer of a sample in front of the focus plane or without a depth: it
/// reaches within its own aperture whatever the depth of the output pixel.
pub(super) const NEAR: u32 = u32::MAX;

/// The input rows the output rows reach, one sample per pixel.
pub(super) struct Sources {
    pub rows: Range<i32>,
    pub width: usize,
    /// Values per sample: its weight, then weight × each colour.
    pub k: usize,
    pub depth: Vec<f32>,
    pub radius: Vec<f32>,
    /// ⌊radius⌋ of a sample at or behind the focus plane, else NEAR.
    pub layer: Vec<u32>,
    /// k per sample, 0 outside the valid columns (no sample there).
    pub values: Vec<f64>,
}

impl Sources {
    fn row_start(&self, y: i32) -> usize {
        (y - self.rows.start) as usize * self.width
    }

    fn value(&self, q: usize) -> &[f64] {
        &self.values[q * self.k..(q + 1) * self.k]
    }

    fn far(&self, q: usize) -> bool {
        self.layer[q] != NEAR
    }
}

fn add(sum: &mut [f64], value: &[f64]) {
    sum.iter_mut().zip(value).for_each(|(s, v)| *s += v);
}

/// The class of output pixel p, which decides which samples reach it.
#[derive(Clone, Copy, PartialEq)]
enum Class {
    /// Depth not a number: every sample reaches within its own aperture.
    Any,
    /// Depth 0 or less: every other sample is farther and p is sharp, so p
    /// alone reaches itself.
    Alone,
    /// A positive depth, of radius in [j, j + 1).
    Radius(usize),
}

/// Output columns per tile: a tile's sums, difference rows and prefix rows
/// stay in a core's cache while its sources pass R times over them.
pub(super) const TILE: usize = 128;

/// Per output pixel of `rows` × `columns`, k sums: of the weights, then of
/// weight × colour, over the samples that reach it.
pub(super) fn sums(
    sources: &Sources,
    footprints: &Footprints,
    rows: Range<i32>,
    columns: Range<usize>,
) -> Vec<f64> {
    let k = sources.k;
    let count = columns.len();
    let mut sums = vec![0.0f64; rows.len() * count * k];
    let at = |(y, x): (i32, usize)| ((y - rows.start) as usize * count + x - columns.start) * k;
    // One difference row per output row, across the whole width: a tile
    // writes and reads only its own columns (and the one past them, which
    // the next tile clears).
    let mut diff = vec![0.0f64; rows.len() * (sources.width + 1) * k];
    for start in columns.clone().step_by(TILE) {
        let tile = start..(start + TILE).min(columns.end);
        tile_sums(sources, footprints, &rows, tile, &mut diff, &mut sums, at);
    }
    sums
}

fn tile_sums(
    sources: &Sources,
    footprints: &Footprints,
    rows: &Range<i32>,
    tile: Range<usize>,
    diff: &mut [f64],
    sums: &mut [f64],
    at: impl Fn((i32, usize)) -> usize + Copy,
) {
    let (k, reach) = (sources.k, footprints.reach() as usize);
    // Output pixels by radius j (index j), those of class Any last (index
    // reach + 1); each in row order.
    let mut targets: Vec<Vec<(i32, usize)>> = vec![Vec::new(); reach + 2];
    for y in rows.clone() {
        let start = sources.row_start(y);
        for x in tile.clone() {
            let p = start + x;
            let z = sources.depth[p];
            let class = if z.is_nan() {
                Class::Any
            } else if z <= 0.0 {
                Class::Alone
            } else {
                Class::Radius(sources.radius[p] as usize)
            };
            match class {
                Class::Alone => {
                    let at = at((y, x));
                    sums[at..at + k].copy_from_slice(sources.value(p));
                }
                Class::Radius(j) => targets[j].push((y, x)),
                Class::Any => targets[reach + 1].push((y, x)),
            }
        }
    }
    // The sources within reach of the tile.
    let window = tile.start.saturating_sub(reach)..(tile.end + reach).min(sources.width);
    near_scatter(
        sources, footprints, rows, &tile, &window, &targets, diff, sums, at,
    );
    for (j, group) in targets.iter().enumerate().take(reach + 1) {
        if !group.is_empty() {
            core_gather(sources, footprints, j, &window, group, sums, at);
            ring_gather(sources, footprints, j, group, sums, at);
        }
    }
}

/// The samples in front (every NEAR one) and, for the targets of class j,
/// the far ones of layers under j: each reaches within its own aperture, so
/// it is spread (scattered) over it, one span per row, as +v at the span's
/// first column and −v past its last in a per-row difference array; a
/// target reads the running sum at its column, after the layers under its
/// own were spread.
#[allow(clippy::too_many_arguments)]
fn near_scatter(
    sources: &Sources,
    footprints: &Footprints,
    rows: &Range<i32>,
    tile: &Range<usize>,
    window: &Range<usize>,
    targets: &[Vec<(i32, usize)>],
    diff: &mut [f64],
    sums: &mut [f64],
    at: impl Fn((i32, usize)) -> usize,
) {
    let (k, w) = (sources.k, sources.width);
    let line = (w + 1) * k;
    for row in diff.chunks_mut(line) {
        row[tile.start * k..(tile.end + 1) * k].fill(0.0);
    }
    // Samples of each far layer and the near ones (last).
    let layers = targets.len();
    let mut by_layer: Vec<Vec<usize>> = vec![Vec::new(); layers];
    let top = targets.iter().rposition(|g| !g.is_empty()).unwrap_or(0);
    for start in (0..sources.rows.len()).map(|i| i * w) {
        for q in start + window.start..start + window.end {
            let layer = sources.layer[q];
            let slot = if layer == NEAR {
                layers - 1
            } else {
                layer as usize
            };
            // A far layer is read only by targets of a higher class.
            if slot == layers - 1 || slot < top {
                by_layer[slot].push(q);
            }
        }
    }
    let spread = |samples: &[usize], diff: &mut [f64]| {
        for &q in samples {
            let (yq, xq) = (sources.rows.start + (q / w) as i32, (q % w) as i32);
            let r = sources.radius[q];
            let (first, last) = footprints.rows(r as usize);
            let value = sources.value(q);
            for y in (yq + first).max(rows.start)..=(yq + last).min(rows.end - 1) {
                let span = footprints.span(r, y - yq);
                let (lo, hi) = (
                    (xq + span.lo).max(tile.start as i32),
                    (xq + span.hi).min(tile.end as i32 - 1),
                );
                if lo > hi {
                    continue;
                }
                let row = (y - rows.start) as usize * line;
                let start = row + lo as usize * k;
                add(&mut diff[start..start + k], value);
                let end = row + (hi as usize + 1) * k;
                diff[end..end + k]
                    .iter_mut()
                    .zip(value)
                    .for_each(|(d, v)| *d -= v);
            }
        }
    };
    spread(&by_layer[layers - 1], diff);
    let mut running = vec![0.0f64; k];
    for (j, group) in targets.iter().enumerate() {
        // Each target row once: the group is in row order.
        let mut i = 0;
        while i < group.len() {
            let y = group[i].0;
            let row = &diff[(y - rows.start) as usize * line..][..line];
            running.fill(0.0);
            let mut x = tile.start;
            while i < group.len() && group[i].0 == y {
                let target = group[i].1;
                while x <= target {
                    add(&mut running, &row[x * k..(x + 1) * k]);
                    x += 1;
                }
                let at = at(group[i]);
                add(&mut sums[at..at + k], &running);
                i += 1;
            }
        }
        if j < layers - 1 {
            spread(&by_layer[j], diff);
        }
    }
}

/// For the targets of class j: the far samples of layers j and up within
/// the core of radius j, which they reach whatever their own radius (both
/// are at least j): per source row, prefix sums over the row, and per
/// target row within j of it, one span per target.
fn core_gather(
    sources: &Sources,
    footprints: &Footprints,
    j: usize,
    window: &Range<usize>,
    targets: &[(i32, usize)],
    sums: &mut [f64],
    at: impl Fn((i32, usize)) -> usize,
) {
    let (k, w) = (sources.k, sources.width);
    let reach = j as i32;
    let (first, last) = (window.start as i32, window.end as i32 - 1);
    let (top, bottom) = (targets[0].0, targets[targets.len() - 1].0);
    let mut prefix = vec![0.0f64; (w + 1) * k];
    // Where each target row's targets start, for the rows top ..= bottom.
    let mut starts = vec![targets.len(); (bottom - top + 2) as usize];
    for (i, &(y, _)) in targets.iter().enumerate().rev() {
        starts[(y - top) as usize] = i;
    }
    for r in (0..starts.len() - 1).rev() {
        starts[r] = starts[r].min(starts[r + 1]);
    }
    for yq in (top - reach).max(sources.rows.start)..(bottom + reach + 1).min(sources.rows.end) {
        let start = sources.row_start(yq);
        for x in window.clone() {
            let q = start + x;
            let within = sources.far(q) && sources.layer[q] as usize >= j;
            for c in 0..k {
                let value = if within {
                    sources.values[q * k + c]
                } else {
                    0.0
                };
                prefix[(x + 1) * k + c] = prefix[x * k + c] + value;
            }
        }
        for y in (yq - reach).max(top)..=(yq + reach).min(bottom) {
            let span = footprints.core(j, y - yq);
            if span.is_empty() {
                continue;
            }
            let row = (y - top) as usize;
            for &target in &targets[starts[row]..starts[row + 1]] {
                let x = target.1 as i32;
                let (a, b) = ((x - span.hi).max(first), (x - span.lo).min(last));
                if a > b {
                    continue;
                }
                let (a, b) = (a as usize * k, (b as usize + 1) * k);
                let at = at(target);
                for (c, s) in sums[at..at + k].iter_mut().enumerate() {
                    *s += prefix[b + c] - prefix[a + c];
                }
            }
        }
    }
}

/// For the targets of class j: the far samples of layers j and up at the
/// offsets of the ring of j, which reach where the offset is within both
/// radii (the far samples of lower layers fail the test, being inside
/// radius j).
fn ring_gather(
    sources: &Sources,
    footprints: &Footprints,
    j: usize,
    targets: &[(i32, usize)],
    sums: &mut [f64],
    at: impl Fn((i32, usize)) -> usize,
) {
    let k = sources.k;
    let (w, rows) = (sources.width as i32, &sources.rows);
    for &(y, x) in targets {
        let p = sources.row_start(y) + x;
        let radius = sources.radius[p];
        let at = at((y, x));
        for offset in footprints.ring(j) {
            if offset.need > radius {
                break;
            }
            let (yq, xq) = (y - offset.dy, x as i32 - offset.dx);
            if !rows.contains(&yq) || xq < 0 || xq >= w {
                continue;
            }
            let q = sources.row_start(yq) + xq as usize;
            if sources.far(q) && offset.need <= sources.radius[q] {
                add(&mut sums[at..at + k], sources.value(q));
            }
        }
    }
}
