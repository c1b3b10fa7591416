//! Depth of field from a Z channel: each pixel spreads over an aperture of
//! its circle of confusion, written as a gather over the rows within the
//! largest radius (the halo). Formulas and the depth rule: specs/ops.md,
//! "defocus".

use super::layers::Selection;
use crate::engine::graph::Op;
use crate::engine::strip::{Rows, RowsMut};
use exr::meta::attribute::ChannelDescription;
use rayon::prelude::*;
use std::f32::consts::PI;

#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Aperture {
    Disc,
    /// A regular polygon with this many sides (3 or more), a flat side down.
    Polygon(u32),
}

impl Aperture {
    /// `disc`, `hexagon`, or `N-gon` / `Ngon` (N from 3 to 64).
    pub fn parse(text: &str) -> Result<Self, String> {
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

    /// Area of the aperture of radius `r`, at least one pixel.
    fn area(self, r: f32) -> f32 {
        let area = match self {
            Aperture::Disc => PI * r * r,
            Aperture::Polygon(n) => 0.5 * n as f32 * r * r * (2.0 * PI / n as f32).sin(),
        };
        area.max(1.0)
    }
}

/// The smallest aperture radius that reaches each offset (dx, dy) within
/// `reach`: |d| for the disc; for the N-gon max_k (d · n_k) / cos(π/N), n_k
/// its edge normals. Offset d is inside radius r exactly when need(d) ≤ r.
fn need_table(aperture: Aperture, reach: i32) -> Vec<f32> {
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

pub struct Defocus {
    /// Depth in focus.
    pub focus: f32,
    /// Radius in pixels far behind the focus plane (the CoC's scale).
    pub scale: f32,
    pub max_radius: usize,
    pub aperture: Aperture,
    pub z_channel: String,
    pub layers: Selection,
}

impl Defocus {
    /// Circle of confusion radius for depth `z`: S |1 - f / z|, clamped to
    /// the maximum; 0 where the depth is not a positive number.
    pub fn coc(&self, z: f32) -> f32 {
        if z.is_nan() || z <= 0.0 {
            return 0.0;
        }
        (self.scale * (1.0 - self.focus / z).abs()).min(self.max_radius as f32)
    }
}

impl Op for Defocus {
    fn halo(&self) -> usize {
        self.max_radius
    }

    fn channels(&self, inputs: &[&[ChannelDescription]]) -> Vec<ChannelDescription> {
        inputs[0].to_vec()
    }

    fn check(&self, inputs: &[&[ChannelDescription]]) -> Result<(), String> {
        self.layers
            .check_with(inputs[0], &[&self.z_channel], "depth")
    }

    fn compute(&self, _frame: i64, inputs: &[&Rows], out: &mut RowsMut) -> Result<(), String> {
        let input = inputs[0];
        let names = self.layers.filtered(&input.channels);
        let (w, r) = (input.width, self.max_radius as i32);
        let side = 2 * r as usize + 1;
        let need = need_table(self.aperture, r);
        let columns = out.valid_columns();
        // The input rows the output rows reach: their depth, radius, colours.
        let held = input.valid_rows();
        let rows = (out.y - r).max(held.start)..(out.end() + r).min(held.end);
        let sources = input.valid_columns();
        let z = input.channel_index(&self.z_channel).expect("checked");
        let mut depth = vec![0.0f32; rows.len() * w];
        let mut values = vec![vec![0.0f32; rows.len() * w]; names.len()];
        for (i, y) in rows.clone().enumerate() {
            let line = i * w..(i + 1) * w;
            input.planes[z].read_f32(input.row_range(y), &mut depth[line.clone()]);
            for (name, plane) in names.iter().zip(values.iter_mut()) {
                let c = input.channel_index(name).expect("listed");
                input.planes[c].read_f32(input.row_range(y), &mut plane[line.clone()]);
            }
        }
        let radius: Vec<f32> = depth.iter().map(|&d| self.coc(d)).collect();
        let weight: Vec<f32> = radius
            .iter()
            .map(|&r| 1.0 / self.aperture.area(r))
            .collect();
        // Output rows in parallel: per row, per filtered channel, the values.
        let filtered: Vec<Vec<Vec<f32>>> = out
            .valid_rows()
            .into_par_iter()
            .map(|y| {
                let py = (y - rows.start) as usize;
                let mut result = vec![vec![0.0f32; columns.len()]; names.len()];
                let mut sums = vec![0.0f32; names.len()];
                for (cx, x) in columns.clone().enumerate() {
                    let p = py * w + x;
                    let (zp, rp) = (depth[p], radius[p]);
                    sums.fill(0.0);
                    let mut total = 0.0f32;
                    let qx = x.saturating_sub(r as usize).max(sources.start)
                        ..(x + r as usize + 1).min(sources.end);
                    for yq in (y - r).max(rows.start)..(y + r + 1).min(rows.end) {
                        let row = (yq - rows.start) as usize * w;
                        let offsets = (y - yq + r) as usize * side;
                        for xq in qx.clone() {
                            let (q, d) = (row + xq, need[offsets + x + r as usize - xq]);
                            // q reaches p with its own aperture; a farther q only
                            // within p's own blur (no background over sharp edges).
                            if d > radius[q] || (depth[q] > zp && d > rp) {
                                continue;
                            }
                            total += weight[q];
                            for (sum, plane) in sums.iter_mut().zip(&values) {
                                *sum += weight[q] * plane[q];
                            }
                        }
                    }
                    for (target, sum) in result.iter_mut().zip(&sums) {
                        target[cx] = sum / total;
                    }
                }
                result
            })
            .collect();
        for (y, result) in out.valid_rows().zip(filtered) {
            let range = out.row_range(y);
            for (c, channel) in out.channels.iter().enumerate() {
                let name = channel.name.to_string();
                match names.iter().position(|n| *n == name) {
                    Some(k) => out.planes[c].write_f32(
                        range.start + columns.start..range.start + columns.end,
                        &result[k],
                    ),
                    None => {
                        let s = input.channel_index(&name).expect("the input's channel");
                        out.planes[c]
                            .bytes_mut(range.clone())
                            .copy_from_slice(input.planes[s].bytes(input.row_range(y)));
                    }
                }
            }
        }
        Ok(())
    }
}
