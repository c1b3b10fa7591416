//! Depth of field from a Z channel: each pixel spreads over an aperture of
//! its circle of confusion, written as a gather over the rows within the
//! largest radius (the halo). Formulas and the depth rule: specs/ops.md,
//! "defocus".

use super::layers::Selection;
use crate::engine::graph::Op;
use crate::engine::strip::Rows;
use exr::meta::attribute::ChannelDescription;
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

/// Edge normals and apothem factor of a polygon aperture: a point d is
/// inside radius r when d·n ≤ r cos(π/N) for every normal n.
struct Shape {
    aperture: Aperture,
    normals: Vec<(f32, f32)>,
    apothem: f32,
}

impl Shape {
    fn new(aperture: Aperture) -> Self {
        let (normals, apothem) = match aperture {
            Aperture::Disc => (Vec::new(), 1.0),
            Aperture::Polygon(n) => (
                (0..n)
                    .map(|k| {
                        let angle = PI / 2.0 + 2.0 * PI * k as f32 / n as f32;
                        (angle.cos(), angle.sin())
                    })
                    .collect(),
                (PI / n as f32).cos(),
            ),
        };
        Shape {
            aperture,
            normals,
            apothem,
        }
    }

    fn inside(&self, dx: f32, dy: f32, r: f32) -> bool {
        match self.aperture {
            Aperture::Disc => dx * dx + dy * dy <= r * r,
            Aperture::Polygon(_) => self
                .normals
                .iter()
                .all(|&(nx, ny)| dx * nx + dy * ny <= r * self.apothem),
        }
    }
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
        if !inputs[0].iter().any(|c| c.name.eq(self.z_channel.as_str())) {
            return Err(format!("no depth channel '{}'", self.z_channel));
        }
        self.layers.check(inputs)
    }

    fn compute(&self, _frame: i64, inputs: &[&Rows], out: &mut Rows) -> Result<(), String> {
        let input = inputs[0];
        let shape = Shape::new(self.aperture);
        let layers = self.layers.resolve(&[input.channels.as_slice()]);
        let names: Vec<String> = layers
            .iter()
            .flat_map(|l| l.colours().chain([l.alpha_channel()]).collect::<Vec<_>>())
            .filter(|n| input.channel_index(n).is_some())
            .collect();
        let (w, r) = (input.width, self.max_radius as i32);
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
        let weight: Vec<f32> = radius.iter().map(|&r| 1.0 / self.aperture.area(r)).collect();
        let mut sums = vec![0.0f32; names.len()];
        let mut result = vec![vec![0.0f32; columns.len()]; names.len()];
        for y in out.valid_rows() {
            let py = (y - rows.start) as usize;
            for (cx, x) in columns.clone().enumerate() {
                let p = py * w + x;
                let (zp, rp) = (depth[p], radius[p]);
                sums.fill(0.0);
                let mut total = 0.0f32;
                let qy = (y - r).max(rows.start)..(y + r + 1).min(rows.end);
                let qx = x.saturating_sub(r as usize).max(sources.start)
                    ..(x + r as usize + 1).min(sources.end);
                for yq in qy {
                    let dy = (y - yq) as f32;
                    let row = (yq - rows.start) as usize * w;
                    for xq in qx.clone() {
                        let q = row + xq;
                        let dx = x as f32 - xq as f32;
                        // q reaches p with its own aperture; a farther q only
                        // within p's own blur (no background over sharp edges).
                        if !shape.inside(dx, dy, radius[q])
                            || (depth[q] > zp && !shape.inside(dx, dy, rp))
                        {
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
            let range = out.row_range(y);
            for (c, channel) in out.channels.iter().enumerate() {
                let name = channel.name.to_string();
                match names.iter().position(|n| *n == name) {
                    Some(k) => out.planes[c]
                        .write_f32(range.start + columns.start..range.start + columns.end, &result[k]),
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
