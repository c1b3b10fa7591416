//! Synthetic plates: a grainy background and a soft-edged moving foreground,
//! with depth and motion-vector channels, computed strip by strip like any
//! other node (they are sources: ops without inputs).

use crate::engine::graph::Op;
use crate::io::rows::{Rows, RowsMut};
use exr::meta::attribute::{ChannelDescription, IntegerBounds, SampleType};

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PlateKind {
    /// Opaque grainy gradient with a checker pattern; RGBA and Z.
    Bg,
    /// A soft-edged disc moving across a transparent frame; premultiplied
    /// RGBA, Z and screen-space motion vectors (forward.u, forward.v).
    Fg,
    /// Differential rendering's object alone: a shaded ball above the middle
    /// of a transparent frame; RGBA and Z.
    Object,
    /// The proxy scene without the object: an opaque grey ground; RGBA, Z.
    Proxy,
    /// The object over the proxy with the ball's soft shadow on the ground.
    Shadowed,
    /// The demo's background for depth of field: a checker whose depth
    /// recedes from 3 (bottom) to 60 (top), 1/Z linear in y so that a
    /// defocus's blur grows in proportion to the distance from its focus
    /// row, with bright dots that show the aperture's shape; RGBA and Z.
    Set,
    /// The demo's foreground for motion blur: a striped ball going round an
    /// ellipse at 0.3 radians a frame, so it streaks in every frame;
    /// premultiplied RGBA, Z and forward.u, forward.v.
    Ball,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PixelType {
    Half,
    Float,
}

#[derive(Debug)]
pub struct Plate {
    pub kind: PlateKind,
    /// The display window is 0,0 .. width,height; the data window is that
    /// size, moved to `origin`.
    pub width: usize,
    pub height: usize,
    pub origin: (i32, i32),
    pub pixel_type: PixelType,
}

impl Plate {
    pub fn display_window(&self) -> IntegerBounds {
        IntegerBounds::new((0, 0), (self.width, self.height))
    }

    /// Centre x and speed (pixels per frame) of the foreground disc.
    fn disc(&self, frame: i64) -> (f32, f32) {
        let w = self.width as f32;
        let phase = frame as f32 * 0.2;
        (w * 0.5 + w * 0.3 * phase.sin(), w * 0.3 * 0.2 * phase.cos())
    }
}

/// The `Set`'s nearest and farthest depth (bottom and top rows).
pub const SET_DEPTH: (f32, f32) = (3.0, 60.0);

/// The `Ball`'s angular speed round its ellipse, radians a frame.
const BALL_SPEED: f32 = 0.3;

impl Plate {
    /// The `Set`'s checker cell, in pixels (whole, so its edges are sharp).
    pub fn set_cell(&self) -> i32 {
        (self.height as i32 / 16).max(4)
    }

    /// The `Set`'s depth at row centre `fy`: 1/Z linear from the top's to
    /// the bottom's.
    pub fn set_depth(&self, fy: f32) -> f32 {
        let (near, far) = SET_DEPTH;
        1.0 / (1.0 / far + (1.0 / near - 1.0 / far) * fy / self.height as f32)
    }

    /// A pixel of the `Set`, as [A, B, G, R, Z, u, v].
    fn set(&self, x: i32, y: i32, frame: i64) -> [f32; 7] {
        let (w, h) = (self.width as f32, self.height as f32);
        let (fx, fy) = (x as f32 + 0.5, y as f32 + 0.5);
        let cell = self.set_cell();
        let (i, j) = (x.div_euclid(cell), y.div_euclid(cell));
        let dark = (i + j).rem_euclid(2) == 0;
        let tone = if dark { 0.25 } else { 0.9 };
        // A highlight at the middle of every third cell of every other row.
        let centre = |k: i32| (k as f32 + 0.5) * cell as f32;
        let spot = (fx - centre(i)).hypot(fy - centre(j)) < (h / 200.0).max(1.0);
        let light = if spot && i.rem_euclid(3) == 1 && j.rem_euclid(2) == 1 {
            8.0
        } else {
            0.0
        };
        let noise = |c| grain(x, y, frame, c) * 0.02;
        [
            1.0,
            tone * (0.6 + 0.3 * fy / h) + light + noise(2),
            tone * 0.7 + light + noise(1),
            tone * (0.5 + 0.4 * fx / w) + light + noise(0),
            self.set_depth(fy),
            0.0,
            0.0,
        ]
    }

    /// A pixel of the `Ball`, as [A, B, G, R, Z, u, v].
    fn ball(&self, x: i32, y: i32, frame: i64) -> [f32; 7] {
        let (w, h) = (self.width as f32, self.height as f32);
        let (fx, fy) = (x as f32 + 0.5, y as f32 + 0.5);
        let (a, b, t) = (w * 0.3, h * 0.25, frame as f32 * BALL_SPEED);
        let (cx, cy) = (w * 0.5 + a * t.cos(), h * 0.5 + b * t.sin());
        let radius = h * 0.12;
        let d = (fx - cx).hypot(fy - cy);
        let alpha = 1.0 - smoothstep(radius - 1.5, radius, d);
        if alpha <= 0.0 {
            return [0.0, 0.0, 0.0, 0.0, 1.0e4, 0.0, 0.0];
        }
        // Diagonal stripes, so that a streak shows along the motion.
        let stripe = (((fx - cx + fy - cy) / (radius * 0.4)).floor() as i32).rem_euclid(2) == 0;
        let [r, g, bl] = if stripe {
            [0.9, 0.12, 0.04]
        } else {
            [1.0, 0.8, 0.15]
        };
        let (u, v) = (-a * BALL_SPEED * t.sin(), b * BALL_SPEED * t.cos());
        [alpha, alpha * bl, alpha * g, alpha * r, 5.0, u, v]
    }

    /// A pixel of the differential-rendering scene (no grain: renders), as
    /// [A, B, G, R, Z, u, v].
    fn scene(&self, kind: PlateKind, fx: f32, fy: f32) -> [f32; 7] {
        let (w, h) = (self.width as f32, self.height as f32);
        let (cx, cy, r) = (w * 0.5, h * 0.4, h * 0.15);
        let d = ((fx - cx).powi(2) + (fy - cy).powi(2)).sqrt();
        let a = 1.0 - smoothstep(r - 1.5, r, d);
        let lit = (0.55 + 0.45 * (cy - fy) / r).clamp(0.2, 1.0);
        let ball = [
            a,
            a * 0.2 * lit,
            a * 0.35 * lit,
            a * 0.8 * lit,
            5.0,
            0.0,
            0.0,
        ];
        let grey = 0.35 + 0.15 * fy / h;
        // The shadow: a soft ellipse on the ground below the ball.
        let (ex, ey) = ((fx - cx) / (r * 1.3), (fy - (cy + r * 1.6)) / (r * 0.35));
        let shade = 1.0 - 0.65 * (1.0 - smoothstep(0.5, 1.0, (ex * ex + ey * ey).sqrt()));
        let ground = |s: f32| [1.0, grey * s, grey * s, grey * s, 10.0, 0.0, 0.0];
        match kind {
            PlateKind::Object => ball,
            PlateKind::Proxy => ground(1.0),
            _ => {
                let g = ground(shade);
                let mut px = ball;
                for c in 0..4 {
                    px[c] = ball[c] + (1.0 - a) * g[c];
                }
                px[4] = if a > 0.0 { 5.0 } else { 10.0 };
                px
            }
        }
    }
}

/// Deterministic per-pixel noise in [-0.5, 0.5).
fn grain(x: i32, y: i32, frame: i64, channel: u32) -> f32 {
    let mut h = (x as u32).wrapping_mul(0x8da6_b343)
        ^ (y as u32).wrapping_mul(0xd816_3841)
        ^ (frame as u32).wrapping_mul(0xcb1a_b31f)
        ^ channel.wrapping_mul(0x1656_67b1);
    h ^= h >> 15;
    h = h.wrapping_mul(0x2c1b_3c6d);
    h ^= h >> 12;
    (h >> 8) as f32 / (1u32 << 24) as f32 - 0.5
}

fn smoothstep(edge0: f32, edge1: f32, x: f32) -> f32 {
    let t = ((x - edge0) / (edge1 - edge0)).clamp(0.0, 1.0);
    t * t * (3.0 - 2.0 * t)
}

impl Op for Plate {
    fn channels(&self, _: &[&[ChannelDescription]]) -> Vec<ChannelDescription> {
        let colour = match self.pixel_type {
            PixelType::Half => SampleType::F16,
            PixelType::Float => SampleType::F32,
        };
        let mut names = vec!["A", "B", "G", "R"];
        names.push("Z");
        if matches!(self.kind, PlateKind::Fg | PlateKind::Ball) {
            names.extend(["forward.u", "forward.v"]);
        }
        names
            .into_iter()
            .map(|n| {
                let kind = if n.len() == 1 && n != "Z" {
                    colour
                } else {
                    SampleType::F32
                };
                ChannelDescription::named(n, kind)
            })
            .collect()
    }

    fn data_window(&self, _: &[IntegerBounds]) -> IntegerBounds {
        IntegerBounds::new(self.origin, (self.width, self.height))
    }

    fn compute(&self, frame: i64, _: &[&Rows], out: &mut RowsMut) -> Result<(), String> {
        let (w, h) = (self.width as f32, self.height as f32);
        let (cx, speed) = self.disc(frame);
        let (cy, radius) = (h * 0.5, h * 0.25);
        let mut row = vec![[0.0f32; 7]; out.width];
        for y in out.y..out.end() {
            for (i, px) in row.iter_mut().enumerate() {
                let x = out.x + i as i32;
                let (fx, fy) = (x as f32 + 0.5, y as f32 + 0.5);
                let noise = |c| grain(x, y, frame, c) * 0.04;
                *px = match self.kind {
                    PlateKind::Bg => {
                        let check = if ((x / 64) + (y / 64)) % 2 == 0 {
                            0.05
                        } else {
                            0.0
                        };
                        [
                            1.0,
                            0.5 + check + noise(2),
                            0.3 + 0.4 * fy / h + check + noise(1),
                            0.2 + 0.6 * fx / w + check + noise(0),
                            50.0 + 10.0 * fy / h,
                            0.0,
                            0.0,
                        ]
                    }
                    PlateKind::Set => self.set(x, y, frame),
                    PlateKind::Ball => self.ball(x, y, frame),
                    PlateKind::Object | PlateKind::Proxy | PlateKind::Shadowed => {
                        self.scene(self.kind, fx, fy)
                    }
                    PlateKind::Fg => {
                        let d = ((fx - cx).powi(2) + (fy - cy).powi(2)).sqrt();
                        let a = 1.0 - smoothstep(radius * 0.85, radius, d);
                        let inside = a > 0.0;
                        [
                            a,
                            a * (0.2 + noise(2)),
                            a * (0.5 + noise(1)),
                            a * (0.9 + noise(0)),
                            if inside { 5.0 } else { 1.0e4 },
                            if inside { speed } else { 0.0 },
                            0.0,
                        ]
                    }
                };
            }
            let range = out.row_range(y);
            let mut values = vec![0.0f32; out.width];
            for c in 0..out.channels.len() {
                for (v, px) in values.iter_mut().zip(&row) {
                    *v = px[c];
                }
                out.planes[c].write_f32(range.clone(), &values);
            }
        }
        Ok(())
    }
}
