//! Pulling mattes from footage: a colour-difference keyer, a difference
//! matte against a clean plate, and triangulation matting from two known
//! backgrounds. Pointwise; each writes premultiplied R, G, B, A.
//! Formulas: specs/ops.md, "Matting".

use super::declare::{input, named, params, Operation, Value};
use crate::engine::graph::Op;
use crate::io::rows::{Rows, RowsMut};
use crate::io::text::Utf8Text;
use crate::params::{BALANCE, CLIP, GAIN, SCREEN, SOFTNESS, THRESHOLD};
use exr::meta::attribute::{ChannelDescription, IntegerBounds, SampleType};

pub const KEY: Operation = Operation {
    name: "key",
    about: "Colour-difference keyer: alpha from how far the screen channel rises above the \
            other two, the screen taken out of the colour",
    inputs: &[input("input", "Input file or sequence, `:PART` for a part")],
    repeats: false,
    params: KeyParams::PARAMS,
    layers: false,
    straight: false,
    header: Some(0),
    build: |args, graph, inputs| {
        let p = KeyParams::read(args)?;
        if p.clip_white <= p.clip_black {
            return Err("clip_white must be above clip_black".into());
        }
        let key = Key {
            screen: p.screen.0,
            gain: p.gain,
            balance: p.balance,
            clip: (p.clip_black, p.clip_white),
            despill: p.despill,
            invert: p.invert,
        };
        Ok(graph.add(Matte(Pull::Key(key)), inputs))
    },
    measure: None,
};

params! {
    pub struct KeyParams {
        /// green, blue, or the screen's colour as R,G,B.
        screen: Screen = "green",
        /// Scales the difference: above 1 more transparent.
        gain: f32 [GAIN] = "1",
        /// Weight of the first other channel against the second (0..1).
        balance: f32 [BALANCE] = "0.5",
        /// Alpha at or below this becomes 0.
        clip_black: f32 [CLIP] = "0",
        /// Alpha at or above this becomes 1.
        clip_white: f32 [CLIP] = "1",
        /// Limit the screen channel to the other two (spill suppression).
        despill: bool,
        /// 1 - alpha.
        invert: bool,
    }
}

pub const DIFFMATTE: Operation = Operation {
    name: "diffmatte",
    about: "Difference matte: alpha from the difference with a clean plate",
    inputs: &[
        input("input", "Input file or sequence, `:PART` for a part"),
        named("clean_plate", "The background alone"),
    ],
    repeats: false,
    params: DiffParams::PARAMS,
    layers: false,
    straight: false,
    header: Some(0),
    build: |args, graph, inputs| {
        let p = DiffParams::read(args)?;
        let matte = DiffMatte {
            threshold: p.threshold,
            softness: p.softness,
            invert: p.invert,
        };
        Ok(graph.add(Matte(Pull::Difference(matte)), inputs))
    },
    measure: None,
};

params! {
    pub struct DiffParams {
        /// Differences up to this are background (alpha 0).
        threshold: f32 [THRESHOLD] = "0.05",
        /// Alpha reaches 1 at threshold + softness.
        softness: f32 [SOFTNESS] = "0.1",
        /// 1 - alpha.
        invert: bool,
    }
}

pub const TRIANGULATE: Operation = Operation {
    name: "triangulate",
    about: "Triangulation matting: one foreground over two known backgrounds gives alpha \
            and colour exactly",
    inputs: &[
        named("over_a", "The foreground over background A"),
        named("bg_a", "Background A alone"),
        named("over_b", "The foreground over background B"),
        named("bg_b", "Background B alone"),
    ],
    repeats: false,
    params: &[],
    layers: false,
    straight: false,
    header: Some(0),
    build: |_, graph, inputs| Ok(graph.add(Matte(Pull::Triangulation), inputs)),
    measure: None,
};

#[derive(Debug)]
/// A screen colour: `green`, `blue` or R,G,B with one channel above the
/// others.
pub struct Screen(pub [f32; 3]);

impl Value for Screen {
    fn parse(text: &str) -> Result<Self, String> {
        match text.to_ascii_lowercase().as_str() {
            "green" => return Ok(Screen([0.0, 1.0, 0.0])),
            "blue" => return Ok(Screen([0.0, 0.0, 1.0])),
            _ => {}
        }
        let values: Vec<f32> = SCREEN
            .parse_list(text)
            .map_err(|m| format!("expected green, blue or R,G,B: {m}"))?;
        match values[..] {
            [r, g, b] if r.max(g).max(b) > r.min(g).min(b) => Ok(Screen([r, g, b])),
            [_, _, _] => Err("a screen colour needs one channel above the others".into()),
            _ => Err("expected green, blue or R,G,B".into()),
        }
    }
}

const RGB: [&str; 3] = ["R", "G", "B"];

/// Backgrounds closer than this (squared RGB distance) tell nothing apart.
pub const TRIANGULATION_EPSILON: f32 = 1e-4;

#[derive(Debug)]
pub struct Key {
    /// The screen's colour.
    pub screen: [f32; 3],
    pub gain: f32,
    /// Weight of the first of the two other channels in what the screen
    /// channel is compared with (0.5: their mean).
    pub balance: f32,
    pub clip: (f32, f32),
    pub despill: bool,
    pub invert: bool,
}

impl Key {
    /// The screen's channel: the largest of the screen colour's.
    fn channel(&self) -> usize {
        (0..3).fold(0, |best, c| {
            if self.screen[c] > self.screen[best] {
                c
            } else {
                best
            }
        })
    }

    /// How much the screen channel of `c` exceeds the balanced other two.
    fn excess(&self, c: [f32; 3]) -> f32 {
        let s = self.channel();
        let (o1, o2) = ((s + 1) % 3, (s + 2) % 3);
        c[s] - (self.balance * c[o1] + (1.0 - self.balance) * c[o2])
    }

    /// Premultiplied colour and alpha of one pixel.
    pub fn pixel(&self, c: [f32; 3]) -> ([f32; 3], f32) {
        let raw = 1.0 - self.gain * self.excess(c) / self.excess(self.screen);
        let (black, white) = self.clip;
        let mut alpha = ((raw - black) / (white - black)).clamp(0.0, 1.0);
        if self.invert {
            alpha = 1.0 - alpha;
        }
        // Take away what the screen adds where it shows through.
        let mut out: [f32; 3] = std::array::from_fn(|k| c[k] - (1.0 - alpha) * self.screen[k]);
        if self.despill {
            let s = self.channel();
            let limit = out[s] - self.excess(out).max(0.0);
            out[s] = limit;
        }
        (out, alpha)
    }
}

#[derive(Debug)]
pub struct DiffMatte {
    pub threshold: f32,
    pub softness: f32,
    pub invert: bool,
}

impl DiffMatte {
    /// Alpha from the largest channel difference d with the clean plate: 0
    /// up to the threshold, 1 from threshold + softness, smooth between.
    pub fn alpha(&self, c: [f32; 3], plate: [f32; 3]) -> f32 {
        let d = (0..3)
            .map(|k| (c[k] - plate[k]).abs())
            .fold(0.0f32, f32::max);
        let alpha = if self.softness <= 0.0 {
            if d > self.threshold {
                1.0
            } else {
                0.0
            }
        } else {
            let t = ((d - self.threshold) / self.softness).clamp(0.0, 1.0);
            t * t * (3.0 - 2.0 * t)
        };
        if self.invert {
            1.0 - alpha
        } else {
            alpha
        }
    }
}

/// Triangulation matting (Smith and Blinn): the same foreground over two
/// known backgrounds. With F premultiplied, C_a = F + (1 - α) B_a and
/// C_b = F + (1 - α) B_b, so 1 - α = (C_a - C_b)·(B_a - B_b) / |B_a - B_b|²
/// (least squares over R, G, B) and F = C_a - (1 - α) B_a.
pub fn triangulate(ca: [f32; 3], ba: [f32; 3], cb: [f32; 3], bb: [f32; 3]) -> ([f32; 3], f32) {
    let db: [f32; 3] = std::array::from_fn(|k| ba[k] - bb[k]);
    let norm: f32 = db.iter().map(|d| d * d).sum();
    if norm < TRIANGULATION_EPSILON {
        // No contrast between the backgrounds: taken as opaque foreground.
        return (std::array::from_fn(|k| 0.5 * (ca[k] + cb[k])), 1.0);
    }
    let dot: f32 = (0..3).map(|k| (ca[k] - cb[k]) * db[k]).sum();
    let alpha = (1.0 - dot / norm).clamp(0.0, 1.0);
    (
        std::array::from_fn(|k| ca[k] - (1.0 - alpha) * ba[k]),
        alpha,
    )
}

#[derive(Debug)]
/// Which matte an op pulls.
pub enum Pull {
    /// Input: the footage.
    Key(Key),
    /// Inputs: the footage, the clean plate.
    Difference(DiffMatte),
    /// Inputs: foreground over A, background A, over B, background B.
    Triangulation,
}

#[derive(Debug)]
pub struct Matte(pub Pull);

fn rgb(rows: &Rows, y: i32, columns: &std::ops::Range<usize>, out: &mut [Vec<f32>; 3]) {
    for (k, name) in RGB.iter().enumerate() {
        out[k].resize(rows.width, 0.0);
        match rows.channel_index(name) {
            Some(c) => rows.planes[c].read_f32(rows.row_range(y), &mut out[k]),
            None => out[k].fill(0.0),
        }
        out[k].truncate(columns.end);
    }
}

impl Op for Matte {
    /// The footage's channels with R, G, B, A (float where it adds them).
    fn channels(&self, inputs: &[&[ChannelDescription]]) -> Vec<ChannelDescription> {
        let mut out = inputs[0].to_vec();
        for name in RGB.iter().chain(&["A"]) {
            if !out.iter().any(|c| c.name.is(name)) {
                out.push(ChannelDescription::named(*name, SampleType::F32));
            }
        }
        out.sort_by(|a, b| a.name.bytes().cmp(b.name.bytes()));
        out
    }

    /// A clean plate whose data window is not the footage's: compared
    /// pixel for pixel at the same coordinates, not scaled.
    fn assumptions(
        &self,
        names: &[String],
        _: &[&[ChannelDescription]],
        windows: &[IntegerBounds],
    ) -> Vec<String> {
        let Pull::Difference(_) = self.0 else {
            return Vec::new();
        };
        let size = |w: IntegerBounds| format!("{}x{}", w.size.width(), w.size.height());
        match windows {
            [footage, plate] if footage != plate => vec![format!(
                "the clean plate {} ({} at {}, {}) is not the size and place of the footage {} \
                 ({} at {}, {}): they are compared at the same pixel coordinates, not scaled, \
                 and where the plate has no pixels the footage is matted against black; resize \
                 the plate to the footage first (e.g. oiiotool --resize)",
                names[1],
                size(*plate),
                plate.position.x(),
                plate.position.y(),
                names[0],
                size(*footage),
                footage.position.x(),
                footage.position.y(),
            )],
            _ => Vec::new(),
        }
    }

    /// The footage's window: a matte is pulled where there is footage.
    fn data_window(&self, inputs: &[IntegerBounds]) -> IntegerBounds {
        inputs[0]
    }

    fn compute(&self, _frame: i64, inputs: &[&Rows], out: &mut RowsMut) -> Result<(), String> {
        let columns = out.valid_columns();
        let mut colours: Vec<[Vec<f32>; 3]> = vec![Default::default(); inputs.len()];
        let mut result: [Vec<f32>; 4] = Default::default();
        for y in out.valid_rows() {
            for (rows, buffer) in inputs.iter().zip(colours.iter_mut()) {
                rgb(rows, y, &columns, buffer);
            }
            for r in result.iter_mut() {
                r.clear();
            }
            for x in columns.clone() {
                let at = |i: usize| -> [f32; 3] { std::array::from_fn(|k| colours[i][k][x]) };
                let (c, a) = match &self.0 {
                    Pull::Key(key) => key.pixel(at(0)),
                    Pull::Difference(matte) => {
                        let a = matte.alpha(at(0), at(1));
                        (at(0).map(|v| v * a), a)
                    }
                    Pull::Triangulation => triangulate(at(0), at(1), at(2), at(3)),
                };
                for k in 0..3 {
                    result[k].push(c[k]);
                }
                result[3].push(a);
            }
            let range = out.row_range(y);
            let dst = range.start + columns.start..range.start + columns.end;
            for (c, channel) in out.channels.iter().enumerate() {
                let name = channel.name.utf8();
                match RGB.iter().chain(&["A"]).position(|n| *n == name) {
                    Some(k) => out.planes[c].write_f32(dst.clone(), &result[k]),
                    None => {
                        let s = inputs[0]
                            .channel_index(&name)
                            .expect("the footage's channel");
                        out.planes[c]
                            .bytes_mut(range.clone())
                            .copy_from_slice(inputs[0].planes[s].bytes(inputs[0].row_range(y)));
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

    fn key(screen: [f32; 3]) -> Key {
        Key {
            screen,
            gain: 1.0,
            balance: 0.5,
            clip: (0.0, 1.0),
            despill: false,
            invert: false,
        }
    }

    #[test]
    fn the_keyer_gives_the_screen_no_alpha_and_a_foreground_without_excess_all() {
        let green = key([0.1, 0.8, 0.15]);
        assert_eq!(green.pixel([0.1, 0.8, 0.15]).1, 0.0);
        assert_eq!(green.pixel([0.6, 0.3, 0.5]).1, 1.0);
        let blue = key([0.0, 0.0, 1.0]);
        assert_eq!(blue.pixel([0.2, 0.3, 0.25]).1, 1.0);
        // F over the screen with alpha α, F without screen excess (G the
        // mean of R and B): α and
        // α F come back (specs/ops.md, "key").
        for alpha in [0.0f32, 0.25, 0.5, 0.9, 1.0] {
            let f = [0.3f32, 0.35, 0.4];
            let screen = green.screen;
            let c: [f32; 3] = std::array::from_fn(|k| alpha * f[k] + (1.0 - alpha) * screen[k]);
            let (colour, a) = green.pixel(c);
            assert!((a - alpha).abs() < 1e-5, "{a} for {alpha}");
            for k in 0..3 {
                assert!((colour[k] - alpha * f[k]).abs() < 1e-5, "{colour:?}");
            }
        }
    }

    #[test]
    fn clip_invert_and_despill_as_specified() {
        let mut k = key([0.0, 1.0, 0.0]);
        // excess 0.5 of the screen's 1: raw alpha 0.5, clipped to 0.25..0.75.
        k.clip = (0.25, 0.75);
        assert_eq!(k.pixel([0.0, 0.5, 0.0]).1, 0.5);
        assert_eq!(k.pixel([0.0, 0.8, 0.0]).1, 0.0);
        k.invert = true;
        assert_eq!(k.pixel([0.0, 0.8, 0.0]).1, 1.0);
        let mut k = key([0.0, 1.0, 0.0]);
        k.despill = true;
        // An opaque pixel with spill: green lowered to the others' mean.
        k.gain = 0.0;
        let (colour, alpha) = k.pixel([0.4, 0.7, 0.2]);
        assert_eq!((alpha, colour), (1.0, [0.4, 0.3, 0.2]));
        // No excess: untouched, bit for bit.
        assert_eq!(k.pixel([0.4, 0.1, 0.2]).0, [0.4, 0.1, 0.2]);
    }

    #[test]
    fn the_difference_matte_steps_or_smoothsteps_on_the_largest_difference() {
        let hard = DiffMatte {
            threshold: 0.1,
            softness: 0.0,
            invert: false,
        };
        assert_eq!(hard.alpha([0.5, 0.5, 0.5], [0.45, 0.5, 0.55]), 0.0);
        assert_eq!(hard.alpha([0.5, 0.5, 0.5], [0.5, 0.35, 0.5]), 1.0);
        let soft = DiffMatte {
            softness: 0.2,
            ..hard
        };
        // d = 0.2: half way through the ramp, smoothstep(0.5) = 0.5.
        assert!((soft.alpha([0.7, 0.0, 0.0], [0.5, 0.0, 0.0]) - 0.5).abs() < 1e-6);
        let t = 0.25f32;
        let d = 0.1 + 0.2 * t;
        let want = t * t * (3.0 - 2.0 * t);
        assert!((soft.alpha([d, 0.0, 0.0], [0.0, 0.0, 0.0]) - want).abs() < 1e-6);
        let inverted = DiffMatte {
            invert: true,
            ..soft
        };
        assert_eq!(inverted.alpha([1.0, 0.0, 0.0], [0.0, 0.0, 0.0]), 0.0);
    }

    #[test]
    fn triangulation_recovers_colour_and_alpha_from_two_backgrounds() {
        let (ba, bb) = ([0.0f32, 0.0, 1.0], [0.0f32, 1.0, 0.0]);
        for (f, alpha) in [
            ([0.2f32, 0.1, 0.3], 0.5f32),
            ([0.0; 3], 0.0),
            ([0.7, 0.6, 0.5], 1.0),
        ] {
            let over =
                |b: [f32; 3]| -> [f32; 3] { std::array::from_fn(|k| f[k] + (1.0 - alpha) * b[k]) };
            let (colour, a) = triangulate(over(ba), ba, over(bb), bb);
            assert!((a - alpha).abs() < 1e-6, "{a} for {alpha}");
            for k in 0..3 {
                assert!((colour[k] - f[k]).abs() < 1e-6, "{colour:?} for {f:?}");
            }
        }
        // Backgrounds alike: opaque, the mean of the two.
        let (c, a) = triangulate([0.2; 3], [0.5; 3], [0.4; 3], [0.5; 3]);
        assert_eq!((c, a), ([0.3f32; 3].map(|v| v), 1.0));
    }
}
