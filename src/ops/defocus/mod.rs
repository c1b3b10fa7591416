//! Depth of field from a Z channel: each pixel spreads over an aperture of
//! its circle of confusion. Formulas, the depth rule and how the sums are
//! made in O(R) per pixel: specs/ops.md, "defocus".

mod aperture;
mod sums;
#[cfg(test)]
mod tests;

pub use aperture::Aperture;

use super::declare::{input, params, Operation};
use super::layers::Selection;
use crate::engine::graph::{Band, Op};
use crate::io::rows::{Rows, RowsMut};
use crate::io::text::Utf8Text;
use crate::params::{DEFOCUS_SCALE, FOCUS, MAX_RADIUS};
use aperture::Footprints;
use exr::meta::attribute::ChannelDescription;
use sums::{sums, Sources, NEAR, TILE};

pub const DEFOCUS: Operation = Operation {
    name: "defocus",
    about: "Depth of field from a depth channel: each pixel spreads over an aperture whose \
            radius grows with its distance from the focus plane",
    inputs: &[input("input", "Input file or sequence, `:PART` for a part")],
    repeats: false,
    params: Params::PARAMS,
    layers: true,
    straight: false,
    header: Some(0),
    build: |args, graph, inputs| {
        let p = Params::read(args)?;
        let op = Defocus {
            focus: p.focus,
            scale: p.scale,
            max_radius: p.max_radius as usize,
            aperture: p.aperture,
            z_channel: p.z_channel,
            layers: args.layers.clone(),
        };
        Ok(graph.add(op, inputs))
    },
    measure: None,
};

params! {
    pub struct Params {
        /// Depth in focus.
        focus: f32 [FOCUS],
        /// Blur radius in pixels of what is far behind the focus plane:
        /// radius = scale * |1 - focus / Z|.
        scale: f32 [DEFOCUS_SCALE] {pixels},
        /// Largest radius in pixels (the rows read above and below).
        max_radius: u32 [MAX_RADIUS] {pixels},
        /// disc, hexagon, or N-gon (5-gon, 8-gon...).
        aperture: Aperture = "disc",
        /// The depth channel.
        z_channel: String = "Z",
    }
}

#[derive(Debug)]
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

    /// Rows `rows` of the input: depth, radius, layer and weighted colours
    /// of `names`, over the valid columns.
    fn sources(&self, input: &Rows, names: &[String], rows: std::ops::Range<i32>) -> Sources {
        let (w, k) = (input.width, names.len() + 1);
        let n = rows.len() * w;
        let z = input.channel_index(&self.z_channel).expect("checked");
        let planes: Vec<usize> = names
            .iter()
            .map(|name| input.channel_index(name).expect("listed"))
            .collect();
        let mut depth = vec![0.0f32; n];
        let mut colours = vec![vec![0.0f32; w]; names.len()];
        let mut radius = vec![0.0f32; n];
        let mut layer = vec![NEAR; n];
        let mut values = vec![0.0f64; n * k];
        let valid = input.valid_columns();
        for (i, y) in rows.clone().enumerate() {
            let line = i * w..(i + 1) * w;
            input.planes[z].read_f32(input.row_range(y), &mut depth[line.clone()]);
            for (&c, colour) in planes.iter().zip(&mut colours) {
                input.planes[c].read_f32(input.row_range(y), colour);
            }
            for x in valid.clone() {
                let q = line.start + x;
                let (d, r) = (depth[q], self.coc(depth[q]));
                radius[q] = r;
                // At or behind the focus plane the radius grows with depth.
                if d > 0.0 && d >= self.focus {
                    layer[q] = r as u32;
                }
                let weight = 1.0 / self.aperture.area(r);
                values[q * k] = weight as f64;
                for (c, colour) in colours.iter().enumerate() {
                    values[q * k + 1 + c] = weight as f64 * colour[x] as f64;
                }
            }
        }
        Sources {
            rows,
            width: w,
            k,
            depth,
            radius,
            layer,
            values,
        }
    }
}

impl Op for Defocus {
    fn halo(&self) -> usize {
        self.max_radius
    }

    /// The sources of the band's rows and its halo (depth, radius and
    /// layer, 4 bytes each, and k f64 values), its sums and difference rows
    /// (k f64 per pixel each), a tile's sample lists (usize, grown by
    /// doubling) and the footprints' tables.
    fn scratch(&self, band: &Band) -> usize {
        let (w, r) = (band.widths[0], self.max_radius);
        let names = self.layers.filtered(band.inputs[0]).len();
        let k = names + 1;
        let sources = (band.rows + 2 * r) * w * (12 + 8 * k) + names * w * 4;
        let sums = 2 * band.rows * (w + 1) * 8 * k + (w + 1) * 8 * k;
        let lists = 2 * ((band.rows + 2 * r) * (TILE + 2 * r) + band.rows * TILE * 2) * 8;
        let side = 2 * r + 1;
        sources + sums + lists + side * side * 24 + w * 4
    }

    fn check(&self, inputs: &[&[ChannelDescription]]) -> Result<(), String> {
        self.layers
            .check_with(inputs[0], &[&self.z_channel], "depth")
    }

    fn compute(&self, _frame: i64, inputs: &[&Rows], out: &mut RowsMut) -> Result<(), String> {
        let input = inputs[0];
        let names = self.layers.filtered(&input.channels);
        let r = self.max_radius as i32;
        let held = input.valid_rows();
        let rows = (out.y - r).max(held.start)..(out.end() + r).min(held.end);
        let sources = self.sources(input, &names, rows);
        let footprints = Footprints::new(self.aperture, r);
        let (targets, columns) = (out.valid_rows(), out.valid_columns());
        let sums = sums(&sources, &footprints, targets.clone(), columns.clone());
        let k = names.len() + 1;
        let mut result = vec![0.0f32; columns.len()];
        for (i, y) in targets.enumerate() {
            let range = out.row_range(y);
            let row = &sums[i * columns.len() * k..(i + 1) * columns.len() * k];
            for (c, channel) in out.channels.iter().enumerate() {
                let name = channel.name.utf8();
                match names.iter().position(|n| *n == name) {
                    Some(n) => {
                        for (value, sum) in result.iter_mut().zip(row.chunks(k)) {
                            *value = (sum[1 + n] / sum[0]) as f32;
                        }
                        out.planes[c].write_f32(
                            range.start + columns.start..range.start + columns.end,
                            &result,
                        );
                    }
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
