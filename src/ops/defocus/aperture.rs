//! Aperture shapes and their footprints on the pixel grid: which offsets an
//! aperture of a given radius covers, row by row, as spans of columns.

use std::f32::consts::PI;

#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Aperture {
    Disc,
    /// A regular polygon with this many sides (3 or more), a flat side down.
    Polygon(u32),
}

impl crate::ops::declare::Value for Aperture {
    /// `disc`, `hexagon`, or `N-gon` / `Ngon` (N from 3 to 64).
    fn parse(text: &str) -> Result<Self, String> {
        let sides = match text.to_ascii_lowercase().as_str() {
            "disc" | "disk" => return Ok(Aperture::Disc),
            "hexagon" => 6,
            other => other
                .trim_end_matches("gon")
                .trim_end_matches('-')
                .parse::<u32>()
                .map_err(|_| format!("unknown aperture '{text}' (disc, hexagon or N-gon)"))?,
        };
        if (3..=64).contains(&sides) {
            Ok(Aperture::Polygon(sides))
        } else {
            Err(format!("an N-gon aperture has 3 to 64 sides, not {sides}"))
        }
    }
}

impl Aperture {
    /// Area of the aperture of radius `r`, at least one pixel.
    pub(super) fn area(self, r: f32) -> f32 {
        let area = match self {
            Aperture::Disc => PI * r * r,
            Aperture::Polygon(n) => 0.5 * n as f32 * r * r * (2.0 * PI / n as f32).sin(),
        };
        area.max(1.0)
    }
}

/// The smallest aperture radius that reaches each offset (dx, dy) within
/// `reach`, row by row from dy = -reach: |d| for the disc; for the N-gon
/// max_k (d · n_k) / cos(π/N), n_k its edge normals. Offset d is inside
/// radius r exactly when need(d) ≤ r.
pub(super) fn need_table(aperture: Aperture, reach: i32) -> Vec<f32> {
    let normals: Vec<(f32, f32)> = match aperture {
        Aperture::Disc => Vec::new(),
        Aperture::Polygon(n) => (0..n)
            .map(|k| {
                let angle = PI / 2.0 + 2.0 * PI * k as f32 / n as f32;
                (angle.cos(), angle.sin())
            })
            .collect(),
    };
    let mut table = Vec::new();
    for dy in -reach..=reach {
        for dx in -reach..=reach {
            let (dx, dy) = (dx as f32, dy as f32);
            table.push(match aperture {
                Aperture::Disc => (dx * dx + dy * dy).sqrt(),
                Aperture::Polygon(n) => {
                    let apothem = (PI / n as f32).cos();
                    normals
                        .iter()
                        .map(|&(nx, ny)| dx * nx + dy * ny)
                        .fold(f32::MIN, f32::max)
                        / apothem
                }
            });
        }
    }
    table
}

/// Columns `lo ..= hi` of one row of offsets; empty when `lo > hi`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Span {
    pub lo: i32,
    pub hi: i32,
}

const EMPTY: Span = Span { lo: 1, hi: 0 };

impl Span {
    pub fn is_empty(self) -> bool {
        self.lo > self.hi
    }
}

/// An offset and the radius that reaches it.
#[derive(Clone, Copy, Debug)]
pub(super) struct Offset {
    pub dx: i32,
    pub dy: i32,
    pub need: f32,
}

/// The footprints of one aperture for every radius up to `reach`. The
/// offsets a radius covers are convex (need is a norm, rounded monotonically),
/// so each row of them is one span, and they grow with the radius: radius r
/// covers the core of ⌊r⌋ (need ≤ ⌊r⌋) and the part of the ring of ⌊r⌋
/// (⌊r⌋ < need < ⌊r⌋ + 1) with need ≤ r.
pub(super) struct Footprints {
    reach: i32,
    side: usize,
    need: Vec<f32>,
    /// Per whole radius j, per row dy + reach: the span of need ≤ j.
    core: Vec<Span>,
    /// Per row: a column of the least need, inside every non-empty span.
    centre: Vec<i32>,
    /// Per whole radius j: the rows whose least need is under j + 1.
    rows: Vec<(i32, i32)>,
    /// Per whole radius j: its ring, least need first.
    ring: Vec<Vec<Offset>>,
}

impl Footprints {
    pub fn new(aperture: Aperture, reach: i32) -> Self {
        let side = 2 * reach as usize + 1;
        let need = need_table(aperture, reach);
        let radii = reach as usize + 1;
        let mut core = vec![EMPTY; radii * side];
        let mut centre = Vec::with_capacity(side);
        let mut ring = vec![Vec::new(); radii];
        for (row, line) in need.chunks(side).enumerate() {
            // The leftmost column within each radius, largest radius first
            // (it is the farthest left), then the rightmost likewise.
            let mut j = reach;
            for (c, &n) in line.iter().enumerate() {
                while j >= 0 && n <= j as f32 {
                    core[j as usize * side + row].lo = c as i32 - reach;
                    j -= 1;
                }
            }
            let mut j = reach;
            for (c, &n) in line.iter().enumerate().rev() {
                while j >= 0 && n <= j as f32 {
                    core[j as usize * side + row].hi = c as i32 - reach;
                    j -= 1;
                }
            }
            let least = (0..side).fold(0, |m, c| if line[c] < line[m] { c } else { m });
            centre.push(least as i32 - reach);
            for (c, &n) in line.iter().enumerate() {
                let j = n.floor();
                if n <= reach as f32 && n != j {
                    let (dx, dy) = (c as i32 - reach, row as i32 - reach);
                    ring[j as usize].push(Offset { dx, dy, need: n });
                }
            }
        }
        for offsets in &mut ring {
            offsets.sort_by(|a, b| a.need.total_cmp(&b.need));
        }
        let least = |dy: i32| {
            need[(dy + reach) as usize * side + (centre[(dy + reach) as usize] + reach) as usize]
        };
        let rows = (0..radii)
            .map(|j| {
                let mut within = (-reach..=reach).filter(|&dy| least(dy) < (j + 1) as f32);
                let first = within.clone().next().unwrap_or(1);
                (first, within.next_back().unwrap_or(0))
            })
            .collect();
        Footprints {
            reach,
            side,
            need,
            core,
            centre,
            rows,
            ring,
        }
    }

    pub fn reach(&self) -> i32 {
        self.reach
    }

    pub fn need(&self, dx: i32, dy: i32) -> f32 {
        self.need[(dy + self.reach) as usize * self.side + (dx + self.reach) as usize]
    }

    /// Row `dy` of the offsets with need ≤ `j`.
    pub fn core(&self, j: usize, dy: i32) -> Span {
        self.core[j * self.side + (dy + self.reach) as usize]
    }

    /// The rows `first ..= last` that radii under `j + 1` can reach.
    pub fn rows(&self, j: usize) -> (i32, i32) {
        self.rows[j]
    }

    /// The offsets with j < need < j + 1, least need first.
    pub fn ring(&self, j: usize) -> &[Offset] {
        &self.ring[j]
    }

    /// Row `dy` of the offsets within radius `r` (0 ≤ r ≤ reach): the core of
    /// ⌊r⌋ grown column by column while the need stays within r.
    pub fn span(&self, r: f32, dy: i32) -> Span {
        let mut span = self.core(r as usize, dy);
        if span.is_empty() {
            let c = self.centre[(dy + self.reach) as usize];
            if self.need(c, dy) > r {
                return EMPTY;
            }
            span = Span { lo: c, hi: c };
        }
        while span.lo > -self.reach && self.need(span.lo - 1, dy) <= r {
            span.lo -= 1;
        }
        while span.hi < self.reach && self.need(span.hi + 1, dy) <= r {
            span.hi += 1;
        }
        span
    }
}
