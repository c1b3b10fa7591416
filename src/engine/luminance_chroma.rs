//! Luminance/chroma inputs (`Y`, `RY`, `BY`, as OpenEXR's RgbaOutputFile
//! writes them) turned into `R`, `G`, `B` the way OpenEXR's RgbaInputFile
//! reads them (ImfRgbaFile.cpp's FromYca, ImfRgbaYca.cpp): the chroma of
//! every second line is filled in along the line and then between lines by
//! 27-tap filters, converted with the luminance weights of the file's
//! chromaticities, and over-saturated pixels are pulled towards their
//! neighbours'. Values are rounded to half where OpenEXR's `Rgba` holds
//! them, and the float arithmetic is done in the same order, so the result
//! is RgbaInputFile's bit for bit. A `Y`-only image is grey (R = G = B = Y).
//!
//! A node of this op follows each input of a job with operations whose first
//! frame (any part of it, with `--all-parts`) is luminance/chroma or `Y` only
//! (`colour_inputs`); frames and parts that are RGB pass through it
//! unchanged.

use super::graph::{Graph, Op};
use crate::io::rows::{Rows, RowsMut};
use crate::io::text::Utf8Text;
use exr::math::Vec2;
use exr::meta::attribute::{ChannelDescription, Chromaticities, SampleType};
use exr::meta::header::Header;
use half::f16;

/// The reconstruction filter's taps on the samples 1, 3, ... 13 either side
/// (ImfRgbaYca.cpp, N = 27).
const TAPS: [f32; 14] = [
    0.002128, -0.007540, 0.019597, -0.043159, 0.087929, -0.186077, 0.627123, 0.627123, -0.186077,
    0.087929, -0.043159, 0.019597, -0.007540, 0.002128,
];

/// Lines either side the filter reaches (N2 = 13), plus the neighbour lines
/// the saturation fix reads.
const REACH: usize = 14;

/// How an input's channels are read.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Kind {
    /// Has R, G or B, or no Y: left as it is.
    Rgb,
    /// Y without chroma: grey.
    Grey,
    /// Y with RY and BY at every second pixel of every second line.
    Chroma,
}

fn kind(channels: &[ChannelDescription]) -> Kind {
    let has = |name: &str| channels.iter().any(|c| c.name.is(name));
    if !has("Y") || ["R", "G", "B"].iter().any(|n| has(n)) {
        Kind::Rgb
    } else if has("RY") || has("BY") {
        Kind::Chroma
    } else {
        Kind::Grey
    }
}

/// Whether a part's channels are luminance/chroma or luminance only, or
/// those of `view` (a single-part multi-view file's `right.Y`) are.
pub fn is_luminance(header: &Header, view: Option<&str>) -> bool {
    let channels = &header.channels.list;
    kind(channels) != Kind::Rgb || grey_view(channels, view).is_some()
}

/// The channel prefix of `view` ("right.") when its channels are luminance
/// only: `right.Y` without `right.R`, `G`, `B` or chroma. Only a view's:
/// another layer's `Y` may be a vector's (`N.Y`).
fn grey_view(channels: &[ChannelDescription], view: Option<&str>) -> Option<String> {
    let prefix = format!("{}.", view?);
    let has = |name: &str| {
        channels
            .iter()
            .any(|c| c.name.is(&format!("{prefix}{name}")))
    };
    let colour = ["R", "G", "B", "RY", "BY"].iter().any(|n| has(n));
    (has("Y") && !colour).then_some(prefix)
}

/// The sample type of channel `name` of `channels`, which has it.
fn type_of(channels: &[ChannelDescription], name: &str) -> SampleType {
    let found = channels.iter().find(|c| c.name.is(name));
    found.expect("channel present").sample_type
}

/// OpenEXR's luminance weights (computeYw) for `chromaticities` (Rec. 709
/// when the file has none): the Y row of RGBtoXYZ, normalised, in float.
pub fn luminance_weights(chromaticities: Option<&Chromaticities>) -> [f32; 3] {
    let rec709 = Chromaticities {
        red: Vec2(0.64, 0.33),
        green: Vec2(0.30, 0.60),
        blue: Vec2(0.15, 0.06),
        white: Vec2(0.3127, 0.3290),
    };
    let c = chromaticities.unwrap_or(&rec709);
    let ((rx, ry), (gx, gy), (bx, by)) = (
        (c.red.x(), c.red.y()),
        (c.green.x(), c.green.y()),
        (c.blue.x(), c.blue.y()),
    );
    let (wx, wy, y) = (c.white.x(), c.white.y(), 1.0f32);
    let big_x = wx * y / wy;
    let big_z = (1.0 - wx - wy) * y / wy;
    let d = rx * (by - gy) + bx * (gy - ry) + gx * (ry - by);
    let sr = (big_x * (by - gy) - gx * (y * (by - 1.0) + by * (big_x + big_z))
        + bx * (y * (gy - 1.0) + gy * (big_x + big_z)))
        / d;
    let sg = (big_x * (ry - by) + rx * (y * (by - 1.0) + by * (big_x + big_z))
        - bx * (y * (ry - 1.0) + ry * (big_x + big_z)))
        / d;
    let sb = (big_x * (gy - ry) - rx * (y * (gy - 1.0) + gy * (big_x + big_z))
        + gx * (y * (ry - 1.0) + ry * (big_x + big_z)))
        / d;
    let (r, g, b) = (sr * ry, sg * gy, sb * by);
    let sum = r + g + b;
    [r / sum, g / sum, b / sum]
}

/// Luminance/chroma (or luminance) to RGB.
#[derive(Debug)]
pub struct FromLuminance {
    /// Luminance weights of R, G, B.
    pub weights: [f32; 3],
    /// The view read (`--view`): its luminance-only channels (`right.Y`)
    /// become grey too.
    pub view: Option<String>,
}

impl FromLuminance {
    /// The channel prefixes made RGB, each with the type of its colour:
    /// the unnamed layer's (luminance/chroma or grey), and the view's.
    fn converted(&self, input: &[ChannelDescription]) -> Vec<(String, SampleType)> {
        let mut prefixes = match kind(input) {
            Kind::Rgb => Vec::new(),
            Kind::Chroma => vec![(String::new(), SampleType::F16)],
            Kind::Grey => vec![(String::new(), type_of(input, "Y"))],
        };
        if let Some(prefix) = grey_view(input, self.view.as_deref()) {
            let sample_type = type_of(input, &format!("{prefix}Y"));
            prefixes.push((prefix, sample_type));
        }
        prefixes
    }
}

impl Op for FromLuminance {
    fn halo(&self) -> usize {
        REACH
    }

    fn reads_luminance(&self) -> bool {
        true
    }

    fn channels(&self, inputs: &[&[ChannelDescription]]) -> Vec<ChannelDescription> {
        let input = inputs[0];
        let converted = self.converted(input);
        let replaced = |name: &str| {
            (converted.iter()).any(|(prefix, _)| {
                let own = name.strip_prefix(prefix.as_str());
                own == Some("Y") || (prefix.is_empty() && ["RY", "BY"].contains(&name))
            })
        };
        let mut channels: Vec<ChannelDescription> = input
            .iter()
            .filter(|c| !replaced(&c.name.utf8()))
            .cloned()
            .collect();
        for (prefix, colour_type) in &converted {
            for name in ["R", "G", "B"] {
                let name = format!("{prefix}{name}");
                channels.push(ChannelDescription::named(name.as_str(), *colour_type));
            }
        }
        channels
    }

    fn check(&self, inputs: &[&[ChannelDescription]]) -> Result<(), String> {
        let chroma = kind(inputs[0]) == Kind::Chroma;
        for c in inputs[0] {
            let expected = match c.name.utf8().as_str() {
                "RY" | "BY" if chroma => Vec2(2, 2),
                _ => Vec2(1, 1),
            };
            if c.sampling != expected {
                return Err(format!(
                    "channel {} has sampling {} {}: operations read luminance/chroma images \
                     (Y 1 1, RY and BY 2 2) and full-resolution channels only",
                    c.name,
                    c.sampling.x(),
                    c.sampling.y()
                ));
            }
        }
        Ok(())
    }

    fn compute(&self, _frame: i64, inputs: &[&Rows], out: &mut RowsMut) -> Result<(), String> {
        let input = inputs[0];
        let mode = kind(&input.channels);
        // Every channel the input and the output share, as it is.
        for (c, channel) in out.channels.iter().enumerate() {
            let Some(k) = input.channel_index(&channel.name.utf8()) else {
                continue;
            };
            for y in out.y..out.end() {
                let range = out.row_range(y);
                out.planes[c]
                    .bytes_mut(range)
                    .copy_from_slice(input.planes[k].bytes(input.row_range(y)));
            }
        }
        match mode {
            Kind::Rgb => {}
            Kind::Grey => grey(input, out, ""),
            Kind::Chroma => Chroma::new(input, self.weights).fill(out),
        }
        if let Some(prefix) = grey_view(&input.channels, self.view.as_deref()) {
            grey(input, out, &prefix);
        }
        Ok(())
    }
}

/// R = G = B = Y, sample for sample, of the channels named `prefix`...
fn grey(input: &Rows, out: &mut RowsMut, prefix: &str) {
    let luminance = input.channel_index(&format!("{prefix}Y"));
    let luminance = luminance.expect("Y present");
    for name in ["R", "G", "B"] {
        let c = out.channel_index(&format!("{prefix}{name}"));
        let c = c.expect("colour channel");
        for y in out.y..out.end() {
            let range = out.row_range(y);
            out.planes[c]
                .bytes_mut(range)
                .copy_from_slice(input.planes[luminance].bytes(input.row_range(y)));
        }
    }
}

/// One colour, as OpenEXR's `Rgba` holds it: halves, `r` and `b` holding the
/// chroma before the conversion.
#[derive(Clone, Copy)]
struct Rgba {
    r: f16,
    g: f16,
    b: f16,
}

/// The luminance/chroma rows of one input strip, read as FromYca reads them.
struct Chroma<'a> {
    input: &'a Rows,
    weights: [f32; 3],
    /// The input's lines held inside its data window (first, last): the
    /// window's, wherever the halo reaches them (`frame_plan::computed`), and the
    /// strip's columns inside it.
    lines: (i32, i32),
    columns: std::ops::Range<usize>,
    /// The last column a line's filter reads: the last but one at the data
    /// window's right edge (padTmpBuf), the last held where the strip ends
    /// inside the window (the columns a crop's halo holds beyond it).
    right: i64,
    planes: [usize; 3],
}

impl<'a> Chroma<'a> {
    fn new(input: &'a Rows, weights: [f32; 3]) -> Self {
        let index = |name: &str| input.channel_index(name);
        let luminance = index("Y").expect("Y present");
        // A missing chroma channel reads as 0 (the fill value); its plane
        // index is then that of Y, never read as chroma.
        let planes = [
            index("RY").unwrap_or(usize::MAX),
            luminance,
            index("BY").unwrap_or(usize::MAX),
        ];
        Chroma {
            input,
            weights,
            lines: (input.valid_rows().start, input.valid_rows().end - 1),
            columns: input.valid_columns(),
            right: {
                let columns = input.valid_columns();
                let edge = input.x + columns.end as i32 == input.valid.end().x();
                (columns.len() as i64 - 1 - i64::from(edge)).max(0)
            },
            planes,
        }
    }

    /// The line FromYca reads for line `v` (readYCAScanLine's clamp: below
    /// the window its last line but one, which is even as the chroma's).
    /// Lines computed only as a halo for other nodes may lie nearer the
    /// edge of the lines held than the filter reaches: they read the lines
    /// held, clamped the same way (never any line written).
    fn source(&self, v: i32) -> i32 {
        let (first, last) = self.lines;
        if v < first {
            first
        } else if v > last {
            (last - 1).max(first)
        } else {
            v
        }
    }

    /// Plane `p` of absolute line `y`, as halves, over the valid columns.
    fn halves(&self, p: usize, y: i32) -> Vec<f16> {
        let mut values = vec![0.0f32; self.columns.len()];
        if p != usize::MAX {
            let start = self.input.row_range(y).start;
            self.input.planes[p].read_f32(
                start + self.columns.start..start + self.columns.end,
                &mut values,
            );
        }
        values.into_iter().map(f16::from_f32).collect()
    }

    /// Line `y` (a chroma line) with its chroma filled in along the line
    /// (reconstructChromaHoriz; the line is padded with its first sample on
    /// the left and on the right its last but one pixel's, as padTmpBuf, or
    /// the last held: `right`).
    fn along(&self, y: i32) -> Vec<Rgba> {
        let [r, g, b] = self.planes.map(|p| self.halves(p, y));
        let n = self.columns.len() as i64;
        let x0 = self.input.x as i64 + self.columns.start as i64;
        let odd = |j: i64| (x0 + j).rem_euclid(2) == 1;
        (0..n)
            .map(|j| {
                let i = j as usize;
                if !odd(j) {
                    return Rgba {
                        r: r[i],
                        g: g[i],
                        b: b[i],
                    };
                }
                let at = |k: usize| (j - 13 + 2 * k as i64).clamp(0, self.right) as usize;
                Rgba {
                    r: filter(|k| r[at(k)]),
                    g: g[i],
                    b: filter(|k| b[at(k)]),
                }
            })
            .collect()
    }

    /// Lines `from..to` (virtual: beyond the window they are read clamped)
    /// in RGB, before the saturation fix: chroma lines converted as they are,
    /// the others with their chroma filled in between the chroma lines
    /// (reconstructChromaVert), then YCAtoRGBA.
    fn rgb(&self, from: i32, to: i32) -> Vec<Vec<Rgba>> {
        // Each line read (clamped), its chroma filled in along once.
        let first = from - REACH as i32;
        let mut along: Vec<Option<Vec<Rgba>>> = vec![None; (to - first + REACH as i32) as usize];
        for v in from - 13..to + 13 {
            let s = self.source(v);
            along[(s - first) as usize].get_or_insert_with(|| self.along(s));
        }
        let line = |v: i32| {
            along[(self.source(v) - first) as usize]
                .as_deref()
                .expect("read above")
        };
        (from..to)
            .map(|v| {
                let own = line(v);
                if v.rem_euclid(2) == 0 {
                    return own.iter().map(|p| self.to_rgb(*p)).collect();
                }
                let taps: Vec<&[Rgba]> = (0..14).map(|k| line(v - 13 + 2 * k)).collect();
                (0..own.len())
                    .map(|i| {
                        self.to_rgb(Rgba {
                            r: filter(|k| taps[k][i].r),
                            g: own[i].g,
                            b: filter(|k| taps[k][i].b),
                        })
                    })
                    .collect()
            })
            .collect()
    }

    /// YCAtoRGBA: chroma 0 gives grey exactly.
    fn to_rgb(&self, p: Rgba) -> Rgba {
        if p.r == f16::ZERO && p.b == f16::ZERO {
            return Rgba {
                r: p.g,
                g: p.g,
                b: p.g,
            };
        }
        let [wr, wg, wb] = self.weights;
        let y = p.g.to_f32();
        let r = (p.r.to_f32() + 1.0) * y;
        let b = (p.b.to_f32() + 1.0) * y;
        let g = (y - r * wr - b * wb) / wg;
        Rgba {
            r: f16::from_f32(r),
            g: f16::from_f32(g),
            b: f16::from_f32(b),
        }
    }

    /// Fills R, G, B of `out`'s rows inside the input's window.
    fn fill(&self, out: &mut RowsMut) {
        let (first, last) = self.lines;
        let (top, bottom) = (out.y.max(first), out.end().min(last + 1));
        if top >= bottom || self.columns.is_empty() {
            return;
        }
        let lines = self.rgb(top - 1, bottom + 1);
        let colours = ["R", "G", "B"].map(|n| out.channel_index(n).expect("colour channel"));
        let mut values = [const { Vec::new() }; 3];
        for y in top..bottom {
            let at = (y - top + 1) as usize;
            let fixed = fix_saturation(self.weights, [&lines[at - 1], &lines[at], &lines[at + 1]]);
            for (c, v) in values.iter_mut().enumerate() {
                *v = fixed
                    .iter()
                    .map(|p| [p.r, p.g, p.b][c].to_f32())
                    .collect::<Vec<f32>>();
            }
            let start = out.row_range(y).start;
            let range = start + self.columns.start..start + self.columns.end;
            for (&c, v) in colours.iter().zip(&values) {
                out.planes[c].write_f32(range.clone(), v);
            }
        }
    }
}

/// The reconstruction filter over the 14 samples `sample(0..14)`, summed in
/// OpenEXR's order from the first product on (a sum started at 0 would turn
/// a -0 result into +0), rounded to half.
fn filter(sample: impl Fn(usize) -> f16) -> f16 {
    let mut sum = sample(0).to_f32() * TAPS[0];
    for (k, tap) in TAPS.iter().enumerate().skip(1) {
        sum += sample(k).to_f32() * tap;
    }
    f16::from_f32(sum)
}

/// `max` and `min` as std::max and std::min compare (the first unless the
/// second is greater, or less).
fn max(a: f32, b: f32) -> f32 {
    if a < b {
        b
    } else {
        a
    }
}

fn min(a: f32, b: f32) -> f32 {
    if b < a {
        b
    } else {
        a
    }
}

fn saturation(p: &Rgba) -> f32 {
    let (r, g, b) = (p.r.to_f32(), p.g.to_f32(), p.b.to_f32());
    let high = max(r, max(g, b));
    let low = min(r, min(g, b));
    if high > 0.0 {
        1.0 - low / high
    } else {
        0.0
    }
}

/// fixSaturation: a pixel much more saturated than the mean of its four
/// diagonal neighbours (clamped at the line's ends) is desaturated to at
/// most that mean's limit, keeping its luminance.
fn fix_saturation(weights: [f32; 3], lines: [&[Rgba]; 3]) -> Vec<Rgba> {
    let n = lines[1].len();
    let [above, below] =
        [lines[0], lines[2]].map(|l| l.iter().map(saturation).collect::<Vec<f32>>());
    let side = |line: &[f32], i: i64| line[i.clamp(0, n as i64 - 1) as usize];
    (0..n)
        .map(|i| {
            let j = i as i64;
            let mean = min(
                1.0,
                0.25 * (side(&above, j - 1)
                    + side(&above, j + 1)
                    + side(&below, j - 1)
                    + side(&below, j + 1)),
            );
            let pixel = lines[1][i];
            let s = saturation(&pixel);
            if s > mean {
                let most = min(1.0, 1.0 - (1.0 - mean) * 0.25);
                if s > most {
                    return desaturate(pixel, most / s, weights);
                }
            }
            pixel
        })
        .collect()
}

fn desaturate(p: Rgba, f: f32, [wr, wg, wb]: [f32; 3]) -> Rgba {
    let (r, g, b) = (p.r.to_f32(), p.g.to_f32(), p.b.to_f32());
    let high = max(r, max(g, b));
    let pull = |c: f32| f16::from_f32(max(high - (high - c) * f, 0.0));
    let mut out = Rgba {
        r: pull(r),
        g: pull(g),
        b: pull(b),
    };
    let luminance_in = r * wr + g * wg + b * wb;
    let luminance_out = out.r.to_f32() * wr + out.g.to_f32() * wg + out.b.to_f32() * wb;
    if luminance_out > 0.0 {
        let scale = |c: f16| f16::from_f32(c.to_f32() * (luminance_in / luminance_out));
        out = Rgba {
            r: scale(out.r),
            g: scale(out.g),
            b: scale(out.b),
        };
    }
    out
}

/// `graph` with a `FromLuminance` node after each input node `luminance`
/// marks (with its luminance weights), which its readers read instead.
pub fn colour_inputs(graph: Graph, luminance: &[Option<[f32; 3]>], view: Option<&str>) -> Graph {
    if luminance.iter().all(Option::is_none) {
        return graph;
    }
    graph.after_inputs(|builder, i, input| match luminance.get(i) {
        Some(&Some(weights)) => {
            let view = view.map(str::to_string);
            builder.add(FromLuminance { weights, view }, &[input])
        }
        _ => input,
    })
}
