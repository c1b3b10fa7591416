//! Motion blur from per-pixel displacement: each pixel spreads its value
//! evenly along the segment it moved during the frame. The halo is the
//! largest vertical displacement; a longer one is an error, never a cut
//! streak. Formulas: specs/ops.md, "vblur".

use super::declare::{input, params, Args, Measured, Operation, Value};
use super::layers::Selection;
use crate::engine::graph::{Band, Op};
use crate::engine::plan::Job;
use crate::engine::prepass::max_over_rows;
use crate::io::attributes::Edit;
use crate::io::rows::{Rows, RowsMut};
use crate::io::text::Utf8Text;
use crate::params::{MAX_DISPLACEMENT, VBLUR_SCALE};
use exr::meta::attribute::ChannelDescription;

pub const VBLUR: Operation = Operation {
    name: "vblur",
    about: "Motion blur from per-pixel displacement (pixels moved during the frame)",
    inputs: &[input("input", "Input file or sequence, `:PART` for a part")],
    repeats: false,
    params: Params::PARAMS,
    layers: true,
    straight: false,
    header: Some(0),
    build: |args, graph, inputs| {
        let p = Params::read(args)?;
        let reach = match (p.max_displacement, args.job_file) {
            (Some(reach), _) => reach as usize,
            // A job's input can be any node: no first pass, the reach is given.
            (None, true) => return Err("op 'vblur' needs max_displacement in a job file".into()),
            // Not measured: a dry run, which reads no pixels.
            (None, false) => 0,
        };
        Ok(graph.add(p.blur(reach, &args.layers), inputs))
    },
    measure: Some(measure),
};

params! {
    pub struct Params {
        /// Scales the displacement, in pixels: 0 for none, 1 as rendered.
        scale: f32 [VBLUR_SCALE] {pixels} = "1",
        /// The x and y displacement channels (y down).
        vectors: Vectors = "forward.u,forward.v",
        /// Rows (pixels) a streak may reach; without it, a first pass over the vectors
        /// measures it. A longer streak is an error, never cut.
        max_displacement: Option<u32> [MAX_DISPLACEMENT] {pixels},
    }
}

impl Params {
    fn blur(&self, reach: usize, layers: &Selection) -> VectorBlur {
        VectorBlur {
            scale: self.scale,
            vectors: self.vectors.0.clone(),
            reach,
            layers: layers.clone(),
        }
    }
}

/// The longest streak of the input, where `max_displacement` is not given.
/// Not in a dry run, which reads no pixels, nor for a job file's node,
/// whose input can be any node (it gives the reach).
fn measure(args: &Args, job: &Job, _: &[Edit], dry_run: bool) -> crate::error::Result<Measured> {
    let p = Params::read(args).map_err(crate::error::Error::usage)?;
    if p.max_displacement.is_some() || dry_run || args.job_file {
        return Ok(Measured::default());
    }
    let names = [p.vectors.0[0].as_str(), p.vectors.0[1].as_str()];
    let reach = max_over_rows(job, 0, names, |u, v| rows_reached(p.scale, u, v))?;
    Ok(Measured {
        values: vec![("max_displacement", reach.to_string())],
        notes: Vec::new(),
    })
}

#[derive(Debug)]
/// Two channel names: `X,Y` (a job file's `["X", "Y"]` too).
pub struct Vectors(pub [String; 2]);

impl Value for Vectors {
    fn parse(text: &str) -> Result<Self, String> {
        match text.split(',').map(str::trim).collect::<Vec<_>>()[..] {
            [x, y] if !x.is_empty() && !y.is_empty() => Ok(Vectors([x.into(), y.into()])),
            _ => Err(format!(
                "vectors are two channel names, X,Y (or [\"X\", \"Y\"]), not '{text}'"
            )),
        }
    }
}

#[derive(Debug)]
pub struct VectorBlur {
    /// Multiplies the displacement: 0 none, 1 as rendered.
    pub scale: f32,
    /// Channels holding the x and y displacement in pixels (y down).
    pub vectors: [String; 2],
    /// Rows above and below an output row that a streak can come from.
    pub reach: usize,
    pub layers: Selection,
}

/// The most rows any pixel of a displacement row `(du, dv)` streaks,
/// scaled by `scale`.
pub fn rows_reached(scale: f32, du: &[f32], dv: &[f32]) -> usize {
    du.iter()
        .zip(dv)
        .map(|(&x, &y)| Streak::new(scale * x, scale * y).rows())
        .max()
        .unwrap_or(0)
}

/// The pixels a pixel moved by (dx, dy) spreads over: n = max(1,
/// round(length)) samples at t = k/n, k = 0..n, each rounded to the nearest
/// pixel and given 1/n of the value.
struct Streak {
    dx: f32,
    dy: f32,
    n: usize,
}

impl Streak {
    fn new(dx: f32, dy: f32) -> Self {
        let length = (dx * dx + dy * dy).sqrt();
        let n = if length.is_finite() {
            (length.round() as usize).max(1)
        } else {
            1
        };
        Streak { dx, dy, n }
    }

    fn offset(&self, k: usize) -> (i32, i32) {
        let t = k as f32 / self.n as f32;
        ((t * self.dx).round() as i32, (t * self.dy).round() as i32)
    }

    /// Rows from the first sample to the farthest (the last: |t dy| grows with k).
    fn rows(&self) -> usize {
        self.offset(self.n - 1).1.unsigned_abs() as usize
    }
}

impl Op for VectorBlur {
    fn halo(&self) -> usize {
        self.reach
    }

    /// Per colour channel the band's f32 sums and a row read, and the
    /// vectors' rows.
    fn scratch(&self, band: &Band) -> usize {
        let names = self.layers.filtered(band.inputs[0]).len();
        (names * (band.rows + 1) + 2) * band.widths[0] * 4
    }

    fn check(&self, inputs: &[&[ChannelDescription]]) -> Result<(), String> {
        let [u, v] = &self.vectors;
        self.layers.check_with(inputs[0], &[u, v], "displacement")
    }

    fn compute(&self, _frame: i64, inputs: &[&Rows], out: &mut RowsMut) -> Result<(), String> {
        let input = inputs[0];
        let names = self.layers.filtered(&input.channels);
        let (w, reach) = (input.width, self.reach as i32);
        let columns = out.valid_columns();
        let held = input.valid_rows();
        let sources = (out.y - reach).max(held.start)..(out.end() + reach).min(held.end);
        let (u, v) = (
            input.channel_index(&self.vectors[0]).expect("checked"),
            input.channel_index(&self.vectors[1]).expect("checked"),
        );
        let mut sums = vec![vec![0.0f32; out.height * w]; names.len()];
        let (mut du, mut dv) = (vec![0.0f32; w], vec![0.0f32; w]);
        let mut values = vec![vec![0.0f32; w]; names.len()];
        for y in sources {
            input.planes[u].read_f32(input.row_range(y), &mut du);
            input.planes[v].read_f32(input.row_range(y), &mut dv);
            for (name, row) in names.iter().zip(values.iter_mut()) {
                let c = input.channel_index(name).expect("listed");
                input.planes[c].read_f32(input.row_range(y), row);
            }
            for x in input.valid_columns() {
                if (du[x] == 0.0 && dv[x] == 0.0) || self.scale == 0.0 {
                    // Still: the value stays where it is (the one sample, share 1).
                    if out.valid_row(y) && y >= out.y && y < out.end() && columns.contains(&x) {
                        let at = (y - out.y) as usize * w + x;
                        for (sum, row) in sums.iter_mut().zip(&values) {
                            sum[at] += row[x];
                        }
                    }
                    continue;
                }
                let streak = Streak::new(self.scale * du[x], self.scale * dv[x]);
                if streak.rows() > self.reach {
                    return Err(format!(
                        "pixel ({}, {y}) streaks {} rows, beyond the {reach} the blur reaches \
                         (raise --max-displacement, or leave it out to measure it)",
                        input.x + x as i32,
                        streak.rows()
                    ));
                }
                let share = 1.0 / streak.n as f32;
                for (ox, oy) in (0..streak.n).map(|k| streak.offset(k)) {
                    let (tx, ty) = (x as i32 + ox, y + oy);
                    if ty < out.y || ty >= out.end() || !out.valid_row(ty) {
                        continue;
                    }
                    if tx < columns.start as i32 || tx >= columns.end as i32 {
                        continue;
                    }
                    let at = (ty - out.y) as usize * w + tx as usize;
                    for (sum, row) in sums.iter_mut().zip(&values) {
                        sum[at] += share * row[x];
                    }
                }
            }
        }
        let samples = out.height * w;
        for (c, channel) in out.channels.iter().enumerate() {
            let name = channel.name.utf8();
            match names.iter().position(|n| *n == name) {
                Some(k) => out.planes[c].write_f32(0..samples, &sums[k]),
                None => {
                    let s = input.channel_index(&name).expect("the input's channel");
                    for y in out.valid_rows() {
                        let range = out.row_range(y);
                        out.planes[c]
                            .bytes_mut(range)
                            .copy_from_slice(input.planes[s].bytes(input.row_range(y)));
                    }
                }
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The samples of specs/ops.md's loop, written out again.
    fn samples(dx: f32, dy: f32) -> Vec<(i32, i32)> {
        let n = ((dx * dx + dy * dy).sqrt().round() as usize).max(1);
        (0..n)
            .map(|k| {
                let t = k as f32 / n as f32;
                ((t * dx).round() as i32, (t * dy).round() as i32)
            })
            .collect()
    }

    #[test]
    fn a_streak_samples_its_segment_and_reaches_its_farthest_row() {
        for (dx, dy) in [
            (0.0, 0.0),
            (5.0, 0.0),
            (0.0, -7.0),
            (3.5, 2.25),
            (-10.0, 10.0),
        ] {
            let streak = Streak::new(dx, dy);
            let want = samples(dx, dy);
            assert_eq!(streak.n, want.len(), "({dx}, {dy})");
            for (k, &at) in want.iter().enumerate() {
                assert_eq!(streak.offset(k), at, "({dx}, {dy}) sample {k}");
            }
            let farthest = want.iter().map(|s| s.1.unsigned_abs()).max().unwrap() as usize;
            assert_eq!(streak.rows(), farthest, "({dx}, {dy})");
        }
        // A pixel moved by (d, 0) covers d pixels from where it was.
        assert_eq!(samples(4.0, 0.0), [(0, 0), (1, 0), (2, 0), (3, 0)]);
    }

    #[test]
    fn rows_reached_is_the_longest_scaled_vertical_reach() {
        assert_eq!(rows_reached(1.0, &[0.0, 3.0, 1.0], &[0.0, 0.0, -6.0]), 5);
        assert_eq!(rows_reached(2.0, &[0.0, 3.0, 1.0], &[0.0, 0.0, -6.0]), 11);
        assert_eq!(rows_reached(0.0, &[9.0], &[9.0]), 0);
        // Not a number streaks nowhere, never everywhere.
        assert_eq!(rows_reached(1.0, &[f32::NAN], &[f32::INFINITY]), 0);
    }
}
