//! Grades: `grade` (Nuke's Grade: a linear ramp, clamps and a gamma),
//! `exposure` (stops) and `saturation`. Pointwise on the colour channels of
//! the selected layers; alpha and every other channel are copied. Formulas:
//! specs/ops.md, "Grades".

use super::declare::{choice, input, params, Operation, Value};
use super::layers::Selection;
use crate::engine::graph::Op;
use crate::io::attributes::Edit;
use crate::io::rows::{Rows, RowsMut};
use crate::params::{
    Bound, BLACKPOINT, GAMMA, GRADE_GAIN, LIFT, MULTIPLY, OFFSET, SATURATION_FACTOR, STOPS,
    WHITEPOINT,
};
use exr::meta::attribute::{ChannelDescription, IntegerBounds};

const INPUT: &[super::declare::Input] =
    &[input("input", "Input file or sequence, `:PART` for a part")];

pub const GRADE: Operation = Operation {
    name: "grade",
    about: "Nuke's Grade: blackpoint and whitepoint become lift and gain, then multiply, \
            offset, clamps and gamma, per colour channel (one value, or R,G,B)",
    inputs: INPUT,
    repeats: false,
    params: GradeParams::PARAMS,
    layers: true,
    straight: false,
    header: Some(0),
    build: |args, graph, inputs| {
        let p = GradeParams::read(args)?;
        if (0..3).any(|c| p.blackpoint.0[c] == p.whitepoint.0[c]) {
            return Err("whitepoint must differ from blackpoint in each channel".into());
        }
        let grade = Grade::new(&p);
        Ok(graph.add(Colour::new(grade, p.unpremult, &args.layers), inputs))
    },
    measure: None,
};

pub const EXPOSURE: Operation = Operation {
    name: "exposure",
    about: "Exposure in stops: colour times 2^stops (one value, or R,G,B)",
    params: ExposureParams::PARAMS,
    build: |args, graph, inputs| {
        let p = ExposureParams::read(args)?;
        let gain = p.stops.0.map(f32::exp2);
        Ok(graph.add(Colour::new(Exposure(gain), false, &args.layers), inputs))
    },
    ..GRADE
};

pub const SATURATION: Operation = Operation {
    name: "saturation",
    about: "Saturation: each colour moved from the pixel's luminance by a factor \
            (0 grey, 1 unchanged), as Nuke's Saturation and oiiotool's --saturate",
    params: SaturationParams::PARAMS,
    build: |args, graph, inputs| {
        let p = SaturationParams::read(args)?;
        let op = Saturation {
            factor: p.saturation,
            weights: p.luminance.weights(),
        };
        Ok(graph.add(Colour::new(op, false, &args.layers), inputs))
    },
    ..GRADE
};

params! {
    pub struct GradeParams {
        /// Input level that becomes lift (one value, or R,G,B).
        blackpoint: Rgb [BLACKPOINT] = "0",
        /// Input level that becomes gain; must differ from blackpoint.
        whitepoint: Rgb [WHITEPOINT] = "1",
        /// What blackpoint becomes.
        lift: Rgb [LIFT] = "0",
        /// What whitepoint becomes.
        gain: Rgb [GRADE_GAIN] = "1",
        /// Multiplies the ramp.
        multiply: Rgb [MULTIPLY] = "1",
        /// Added after the ramp (raises black and white alike).
        offset: Rgb [OFFSET] = "0",
        /// Gamma applied last: x^(1/gamma) from 0 to 1, a line of slope
        /// 1/gamma above; 0 makes a step.
        gamma: Rgb [GAMMA] = "1",
        /// Undo the grade: the inverse gamma, then the inverse ramp.
        reverse: bool,
        /// Do not clamp values below 0 to 0 (Nuke's black clamp, on by default).
        no_black_clamp: bool,
        /// Clamp values above 1 to 1.
        white_clamp: bool,
        /// Grade colour divided by alpha, then multiply by alpha again.
        unpremult: bool,
    }
}

params! {
    pub struct ExposureParams {
        /// Stops: +1 doubles, -1 halves (one value, or R,G,B).
        stops: Rgb [STOPS],
    }
}

params! {
    pub struct SaturationParams {
        /// 0 grey, 1 unchanged, above 1 more saturated.
        saturation: f32 [SATURATION_FACTOR],
        /// The luminance weights, by colour space: rec709 (sRGB), rec2020,
        /// acescg (AP1), aces2065 (AP0), ccir601, average.
        luminance: Luminance = "rec709",
    }
}

/// One value for R, G and B, or three (`R,G,B`; a job file's list too).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Rgb(pub [f32; 3]);

/// Any finite value (every `Rgb` parameter has a bound of its own).
const FINITE: Bound = Bound {
    name: "value",
    min: f32::MIN as f64,
    max: f32::MAX as f64,
};

impl Value for Rgb {
    fn parse(text: &str) -> Result<Self, String> {
        Self::bounded(text, &FINITE)
    }
    fn bounded(text: &str, bound: &Bound) -> Result<Self, String> {
        match bound.parse_list::<f32>(text)?[..] {
            [v] => Ok(Rgb([v; 3])),
            [r, g, b] => Ok(Rgb([r, g, b])),
            _ => Err(format!(
                "{} takes one value or three (R,G,B), not '{text}'",
                bound.name
            )),
        }
    }
}

/// Luminance weights: the Y row of each space's RGB to XYZ matrix.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Luminance {
    Rec709,
    Rec2020,
    AcesCg,
    Aces2065,
    Ccir601,
    Average,
}

impl Luminance {
    pub fn weights(self) -> [f32; 3] {
        match self {
            Luminance::Rec709 => [0.2126, 0.7152, 0.0722],
            Luminance::Rec2020 => [0.2627, 0.6780, 0.0593],
            Luminance::AcesCg => [0.272_228_7, 0.674_081_8, 0.053_689_52],
            Luminance::Aces2065 => [0.343_966_45, 0.728_166_1, -0.072_132_55],
            Luminance::Ccir601 => [0.299, 0.587, 0.114],
            Luminance::Average => [1.0 / 3.0; 3],
        }
    }
}

impl Value for Luminance {
    fn parse(text: &str) -> Result<Self, String> {
        use Luminance::*;
        let values = [Rec709, Rec2020, AcesCg, Aces2065, Ccir601, Average];
        choice(text, Self::CHOICES, &values, "luminance")
    }
    const CHOICES: &'static [&'static str] = &[
        "rec709", "rec2020", "acescg", "aces2065", "ccir601", "average",
    ];
}

/// A change of each pixel's colour alone: R, G and B of a run of pixels.
pub trait ColourMap: Send + Sync + std::fmt::Debug + 'static {
    fn apply(&self, rgb: &mut [Vec<f32>; 3]);
    /// Divided by alpha, colour where alpha is 0 is kept as it was rather
    /// than multiplied by 0 (OCIO's maps: an overflow to Inf times 0 would
    /// be NaN; specs/ops.md, "Colour (OpenColorIO)").
    fn keeps_clear(&self) -> bool {
        false
    }
    /// Warnings the map owes the run (printed once, unless `--quiet`).
    fn warnings(&self) -> Vec<String> {
        Vec::new()
    }
    /// The attributes it writes on the output (`Op::attributes`): a colour
    /// conversion's destination.
    fn attributes(&self) -> Vec<Edit> {
        Vec::new()
    }
}

/// Nuke's Grade per channel: the ramp `x A + B`, the clamps, the gamma
/// (specs/ops.md, "Grades").
#[derive(Clone, Debug, PartialEq)]
pub struct Grade {
    pub a: [f32; 3],
    pub b: [f32; 3],
    pub gamma: [f32; 3],
    pub reverse: bool,
    pub black_clamp: bool,
    pub white_clamp: bool,
}

impl Grade {
    /// A = (gain − lift) / (whitepoint − blackpoint) · multiply and
    /// B = offset + lift − blackpoint · A, rounded in Nuke's order.
    pub fn new(p: &GradeParams) -> Self {
        let channel = |i: usize| {
            let a = (p.gain.0[i] - p.lift.0[i]) / (p.whitepoint.0[i] - p.blackpoint.0[i])
                * p.multiply.0[i];
            (a, p.offset.0[i] + p.lift.0[i] - p.blackpoint.0[i] * a)
        };
        let [(a0, b0), (a1, b1), (a2, b2)] = [0, 1, 2].map(channel);
        Grade {
            a: [a0, a1, a2],
            b: [b0, b1, b2],
            gamma: p.gamma.0,
            reverse: p.reverse,
            black_clamp: !p.no_black_clamp,
            white_clamp: p.white_clamp,
        }
    }

    /// One value of channel `c`.
    pub fn value(&self, c: usize, x: f32) -> f32 {
        let (a, b, g) = (self.a[c], self.b[c], self.gamma[c]);
        // Nuke skips an identity ramp (which would turn -0 into +0).
        let ramp = a != 1.0 || b != 0.0;
        if !self.reverse {
            let mut x = if ramp { x * a + b } else { x };
            if self.black_clamp {
                x = x.max(0.0);
            }
            if self.white_clamp {
                x = x.min(1.0);
            }
            if g <= 0.0 {
                // A step: nothing below 0, everything above 1 infinite.
                match x {
                    x if x < 0.0 => 0.0,
                    x if x > 1.0 => f32::INFINITY,
                    x => x,
                }
            } else if g == 1.0 || x < 0.0 {
                x
            } else {
                let inverse = 1.0 / g;
                if x < 1.0 {
                    x.powf(inverse)
                } else {
                    1.0 + (x - 1.0) * inverse
                }
            }
        } else {
            let x = match g {
                g if g <= 0.0 => f32::from(u8::from(x > 0.0)),
                g if g == 1.0 || x <= 0.0 => x,
                g if x < 1.0 => x.powf(g),
                g => 1.0 + (x - 1.0) * g,
            };
            let x = if ramp {
                // A flat ramp (A = 0) has no inverse: Nuke takes slope 1.
                let a = if a == 0.0 { 1.0 } else { 1.0 / a };
                x * a + -b * a
            } else {
                x
            };
            // As Nuke: the black clamp, else the white clamp, never both.
            match (self.black_clamp, self.white_clamp) {
                (true, _) => x.max(0.0),
                (false, true) => x.min(1.0),
                (false, false) => x,
            }
        }
    }

    /// `value` forward over a run of channel `c`'s samples, bit for bit: the
    /// ramp and each clamp a pass of its own over the run (which the
    /// compiler vectorises), the gamma's branches chosen once per run; only
    /// the power is per sample.
    fn forward(&self, c: usize, values: &mut [f32]) {
        let (a, b, g) = (self.a[c], self.b[c], self.gamma[c]);
        if a != 1.0 || b != 0.0 {
            values.iter_mut().for_each(|x| *x = *x * a + b);
        }
        if self.black_clamp {
            values.iter_mut().for_each(|x| *x = x.max(0.0));
        }
        if self.white_clamp {
            values.iter_mut().for_each(|x| *x = x.min(1.0));
        }
        if g <= 0.0 {
            for x in values {
                *x = match *x {
                    x if x < 0.0 => 0.0,
                    x if x > 1.0 => f32::INFINITY,
                    x => x,
                };
            }
        } else if g != 1.0 {
            let inverse = 1.0 / g;
            for x in values {
                *x = match *x {
                    x if x < 0.0 => x,
                    x if x < 1.0 => x.powf(inverse),
                    x => 1.0 + (x - 1.0) * inverse,
                };
            }
        }
    }
}

impl ColourMap for Grade {
    fn apply(&self, rgb: &mut [Vec<f32>; 3]) {
        for (c, values) in rgb.iter_mut().enumerate() {
            match self.reverse {
                false => self.forward(c, values),
                true => values.iter_mut().for_each(|v| *v = self.value(c, *v)),
            }
        }
    }
}

/// Colour times a gain per channel (2^stops).
#[derive(Debug)]
pub struct Exposure(pub [f32; 3]);

impl ColourMap for Exposure {
    fn apply(&self, rgb: &mut [Vec<f32>; 3]) {
        for (values, gain) in rgb.iter_mut().zip(self.0) {
            values.iter_mut().for_each(|v| *v *= gain);
        }
    }
}

/// (1 − s) Y + s C, Y the weighted sum of R, G, B: C exactly at s = 1, Y
/// at s = 0 (oiiotool's `--saturate`).
#[derive(Debug)]
pub struct Saturation {
    pub factor: f32,
    pub weights: [f32; 3],
}

impl ColourMap for Saturation {
    fn apply(&self, rgb: &mut [Vec<f32>; 3]) {
        let [r, g, b] = rgb;
        let [wr, wg, wb] = self.weights;
        let s = self.factor;
        for ((r, g), b) in r.iter_mut().zip(g.iter_mut()).zip(b.iter_mut()) {
            let y = (1.0 - s) * (wr * *r + wg * *g + wb * *b);
            (*r, *g, *b) = (y + s * *r, y + s * *g, y + s * *b);
        }
    }
}

/// The node: a colour map over each selected layer's R, G, B (a missing one
/// reads as 0 and is not written) inside the data window; with `unpremult`,
/// on colour divided by alpha (where it is not 0), multiplied by it after
/// (so 0 where alpha is 0, or as it was for a map that `keeps_clear`), as
/// `unpremult`, the map and `premult` in turn.
#[derive(Debug)]
pub struct Colour<M> {
    map: M,
    unpremult: bool,
    layers: Selection,
}

impl<M: ColourMap> Colour<M> {
    pub fn new(map: M, unpremult: bool, layers: &Selection) -> Self {
        Colour {
            map,
            unpremult,
            layers: layers.clone(),
        }
    }
}

impl<M: ColourMap> Op for Colour<M> {
    fn check(&self, inputs: &[&[ChannelDescription]]) -> Result<(), String> {
        self.layers.check(inputs)
    }

    fn assumptions(
        &self,
        _names: &[String],
        _inputs: &[&[ChannelDescription]],
        _windows: &[IntegerBounds],
    ) -> Vec<String> {
        self.map.warnings()
    }

    /// The map's attributes when the colour it changes is the image's (the
    /// unnamed layer's, or every layer's): a named layer's leaves the
    /// header describing the unnamed one as it was.
    fn attributes(&self) -> Vec<Edit> {
        match self.layers.layers.is_empty() || self.layers.all {
            true => self.map.attributes(),
            false => Vec::new(),
        }
    }

    fn compute(&self, _frame: i64, inputs: &[&Rows], out: &mut RowsMut) -> Result<(), String> {
        let input = inputs[0];
        let layers = self.layers.resolve(&[input.channels.as_slice()]);
        let found: Vec<[Option<usize>; 3]> = layers
            .iter()
            .map(|layer| {
                let mut names = layer.colours();
                [(); 3].map(|()| names.next().and_then(|n| input.channel_index(&n)))
            })
            .collect();
        // The channels the map writes; the others are copied as they are.
        let copied: Vec<usize> = (0..input.channels.len())
            .filter(|c| !found.iter().flatten().any(|f| *f == Some(*c)))
            .collect();
        let columns = out.valid_columns();
        let mut rgb: [Vec<f32>; 3] = Default::default();
        let keep = self.unpremult && self.map.keeps_clear();
        let mut before: [Vec<f32>; 3] = Default::default();
        let mut alpha = vec![0.0f32; columns.len()];
        for y in out.valid_rows() {
            let (to, from) = (out.row_range(y), input.row_range(y));
            for &c in &copied {
                out.planes[c]
                    .bytes_mut(to.clone())
                    .copy_from_slice(input.planes[c].bytes(from.clone()));
            }
            let at = |start: usize| start + columns.start..start + columns.end;
            let (src, dst) = (at(from.start), at(to.start));
            for (layer, found) in layers.iter().zip(&found) {
                for (values, c) in rgb.iter_mut().zip(found) {
                    values.clear();
                    values.resize(columns.len(), 0.0);
                    if let Some(c) = c {
                        input.planes[*c].read_f32(src.clone(), values);
                    }
                }
                if self.unpremult {
                    layer.read_alpha(input, y, columns.start, &mut alpha);
                    for values in &mut rgb {
                        // Divided everywhere, kept where alpha is 0: a
                        // select the compiler vectorises.
                        for (v, &a) in values.iter_mut().zip(&alpha) {
                            let divided = *v / a;
                            *v = if a != 0.0 { divided } else { *v };
                        }
                    }
                }
                if keep {
                    before.clone_from(&rgb);
                }
                self.map.apply(&mut rgb);
                for ((values, c), kept) in rgb.iter_mut().zip(found).zip(&before) {
                    if keep {
                        for ((v, &a), &was) in values.iter_mut().zip(&alpha).zip(kept) {
                            *v = if a != 0.0 { *v * a } else { was };
                        }
                    } else if self.unpremult {
                        values.iter_mut().zip(&alpha).for_each(|(v, &a)| *v *= a);
                    }
                    if let Some(c) = c {
                        out.planes[*c].write_f32(dst.clone(), values);
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
    use crate::ops::premult::Premult;
    use exr::meta::attribute::{IntegerBounds, SampleType};

    fn rgb(text: &str) -> Rgb {
        Rgb::parse(text).unwrap()
    }

    /// Grade parameters: blackpoint, whitepoint, lift, gain, multiply,
    /// offset, gamma (one value each), with the clamps and reverse.
    fn grade(values: [f32; 7], black_clamp: bool, white_clamp: bool, reverse: bool) -> Grade {
        let [blackpoint, whitepoint, lift, gain, multiply, offset, gamma] =
            values.map(|v| Rgb([v; 3]));
        Grade::new(&GradeParams {
            blackpoint,
            whitepoint,
            lift,
            gain,
            multiply,
            offset,
            gamma,
            reverse,
            no_black_clamp: !black_clamp,
            white_clamp,
            unpremult: false,
        })
    }

    /// Nuke's documented Grade, in f64: A = multiply (gain − lift) /
    /// (whitepoint − blackpoint), B = offset + lift − A blackpoint,
    /// pow(A x + B, 1/gamma) from 0 to 1, the tangent line above it.
    fn nuke(values: [f32; 7], black_clamp: bool, white_clamp: bool, x: f32) -> f64 {
        let [bp, wp, lift, gain, multiply, offset, gamma] = values.map(f64::from);
        let a = multiply * (gain - lift) / (wp - bp);
        let mut v = a * f64::from(x) + offset + lift - a * bp;
        if black_clamp {
            v = v.max(0.0);
        }
        if white_clamp {
            v = v.min(1.0);
        }
        match v {
            _ if gamma == 0.0 && v > 1.0 => f64::INFINITY,
            _ if gamma == 0.0 => v.max(0.0),
            v if v < 0.0 => v,
            v if v < 1.0 => v.powf(1.0 / gamma),
            v => 1.0 + (v - 1.0) / gamma,
        }
    }

    const CASES: [[f32; 7]; 6] = [
        [0.0, 1.0, 0.0, 1.0, 1.0, 0.0, 1.0],
        [0.05, 0.9, -0.1, 1.3, 0.8, 0.02, 2.2],
        [-0.2, 2.0, 0.1, 0.7, 1.5, -0.05, 0.45],
        [0.0, 1.0, 0.0, 1.0, 2.0, 0.1, 1.0],
        [0.1, 0.5, 0.3, -0.4, 1.0, 0.0, 3.0],
        [0.0, 1.0, 0.0, 1.0, 1.0, 0.0, 0.0],
    ];
    const XS: [f32; 9] = [-0.5, -0.01, 0.0, 0.001, 0.18, 0.5, 0.99, 1.0, 7.5];

    #[test]
    fn grade_follows_nukes_formula_with_every_clamp() {
        for values in CASES {
            for (black, white) in [(true, false), (false, false), (true, true), (false, true)] {
                let g = grade(values, black, white, false);
                for x in XS {
                    let (ours, reference) = (g.value(1, x), nuke(values, black, white, x));
                    let tolerance = 2e-6 * reference.abs().max(1.0);
                    assert!(
                        (f64::from(ours) - reference).abs() <= tolerance
                            || f64::from(ours) == reference,
                        "{values:?} clamps {black} {white} x {x}: {ours} vs {reference}"
                    );
                }
            }
        }
    }

    #[test]
    fn a_run_is_graded_as_each_value_is_bit_for_bit() {
        let mut xs: Vec<f32> = XS.to_vec();
        xs.extend([-0.0, 1e-30, 0.999_999, 1.000_001, 65504.0, f32::INFINITY]);
        xs.extend([f32::NEG_INFINITY, f32::NAN, -f32::NAN, f32::MIN_POSITIVE]);
        let gammas = [0.0, -1.0, 1.0, 0.45, 2.2];
        for values in CASES {
            for (black, white) in [(true, false), (false, false), (true, true), (false, true)] {
                for gamma in gammas {
                    let mut g = grade(values, black, white, false);
                    g.gamma = [gamma, values[6], 1.0];
                    let mut rgb = [xs.clone(), xs.clone(), xs.clone()];
                    g.apply(&mut rgb);
                    for (c, run) in rgb.iter().enumerate() {
                        for (x, got) in xs.iter().zip(run) {
                            let want = g.value(c, *x);
                            assert_eq!(
                                got.to_bits(),
                                want.to_bits(),
                                "{values:?} clamps {black} {white} gamma {gamma} channel {c} x {x}"
                            );
                        }
                    }
                }
            }
        }
    }

    #[test]
    fn reverse_is_the_inverse_where_nothing_was_clamped() {
        for values in CASES.into_iter().filter(|v| v[6] > 0.0) {
            let (forward, back) = (
                grade(values, false, false, false),
                grade(values, false, false, true),
            );
            for x in XS {
                let y = forward.value(0, x);
                let again = back.value(0, y);
                assert!(
                    (again - x).abs() <= 1e-5 * x.abs().max(1.0),
                    "{values:?}: {x} graded {y} reversed {again}"
                );
            }
        }
        // Reverse clamps what it gives: black first, as Nuke.
        let back = grade(CASES[1], true, true, true);
        assert_eq!(back.value(0, -1.0), 0.0);
        assert!(back.value(0, 4.0) > 1.0);
        let back = grade(CASES[1], false, true, true);
        assert_eq!(back.value(0, 4.0), 1.0);
        // A step gamma reversed: 1 above 0, 0 elsewhere.
        let step = grade(CASES[5], false, false, true);
        assert_eq!(
            [-1.0, 0.0, 0.5, 3.0].map(|x| step.value(0, x)),
            [0.0, 0.0, 1.0, 1.0]
        );
    }

    #[test]
    fn values_are_one_or_three_and_bounded() {
        assert_eq!(rgb("0.5"), Rgb([0.5; 3]));
        assert_eq!(rgb("-0.1,0,2"), Rgb([-0.1, 0.0, 2.0]));
        assert!(Rgb::parse("1,2").is_err());
        assert!(Rgb::parse("1,nan,2").is_err());
        let message = Rgb::bounded("100", &STOPS).unwrap_err();
        assert!(message.contains("stops must be a number"), "{message}");
    }

    #[test]
    fn exposure_and_saturation_against_their_formulas() {
        let mut values = [
            vec![0.25f32, -1.0, 3.0],
            vec![0.5, 0.0, 1.0],
            vec![0.75, 2.0, 0.1],
        ];
        let before = values.clone();
        Exposure([2.0f32.exp2(), 1.0, (-1.0f32).exp2()]).apply(&mut values);
        assert_eq!(
            values[0],
            before[0].iter().map(|v| v * 4.0).collect::<Vec<_>>()
        );
        assert_eq!(values[1], before[1]);
        assert_eq!(
            values[2],
            before[2].iter().map(|v| v / 2.0).collect::<Vec<_>>()
        );

        for luminance in [Luminance::Rec709, Luminance::AcesCg, Luminance::Aces2065] {
            let w = luminance.weights();
            assert!((w.iter().sum::<f32>() - 1.0).abs() < 1e-6, "{luminance:?}");
            for s in [0.0f32, 0.5, 1.0, 1.7] {
                let mut values = before.clone();
                Saturation {
                    factor: s,
                    weights: w,
                }
                .apply(&mut values);
                for i in 0..3 {
                    let c = [0, 1, 2].map(|k| f64::from(before[k][i]));
                    let y: f64 = (0..3).map(|k| f64::from(w[k]) * c[k]).sum();
                    for k in 0..3 {
                        let reference = y + f64::from(s) * (c[k] - y);
                        let ours = f64::from(values[k][i]);
                        assert!((ours - reference).abs() < 1e-6, "{s} {ours} vs {reference}");
                    }
                }
                if s == 1.0 {
                    assert_eq!(values, before, "1 leaves colour exactly");
                }
                if s == 0.0 {
                    assert!((0..3)
                        .all(|i| values[0][i] == values[1][i] && values[1][i] == values[2][i]));
                }
            }
        }
    }

    /// Rows 0..3 of columns -1..5, valid over columns 0..4: half colours
    /// and alpha (0 among them) of the unnamed and the `diffuse` layer,
    /// and a float Z.
    fn frame() -> Rows {
        let names = [
            "A",
            "B",
            "G",
            "R",
            "Z",
            "diffuse.B",
            "diffuse.G",
            "diffuse.R",
        ];
        let channels: Vec<ChannelDescription> = names
            .iter()
            .map(|&n| {
                let kind = if n == "Z" {
                    SampleType::F32
                } else {
                    SampleType::F16
                };
                ChannelDescription::new(n, kind, n != "Z")
            })
            .collect();
        let valid = IntegerBounds::new((0, 0), (4, 3));
        let mut rows = Rows::zeros(-1, 0, 6, 3, channels, valid);
        for y in 0..3 {
            let range = rows.row_range(y);
            for (c, name) in names.into_iter().enumerate() {
                let values: Vec<f32> = (0..6)
                    .map(|x| match (x, name) {
                        (0 | 5, _) => 0.0,
                        (_, "A") => [0.0, 0.5, 1.0, 0.25][x - 1],
                        (_, "Z") => 10.0 + x as f32,
                        _ => 0.1 * (c + x) as f32 - 0.15 * y as f32,
                    })
                    .collect();
                rows.planes[c].write_f32(range.clone(), &values);
            }
        }
        rows
    }

    fn compute(op: &dyn Op, input: &Rows) -> Rows {
        let mut out = Rows::zeros(
            input.x,
            0,
            input.width,
            3,
            input.channels.clone(),
            input.valid,
        );
        for mut band in out.bands(0, 2) {
            op.compute(1, &[input], &mut band).unwrap();
        }
        out
    }

    fn samples(rows: &Rows, name: &str) -> Vec<f32> {
        let c = rows.channel_index(name).unwrap();
        let mut values = vec![0.0; rows.width * rows.height];
        rows.planes[c].read_f32(0..values.len(), &mut values);
        values
    }

    #[test]
    fn the_node_grades_the_selected_colours_inside_the_data_window_only() {
        let input = frame();
        let g = grade(CASES[2], true, false, false);
        let layers = Selection {
            layers: vec!["diffuse".into()],
            ..Default::default()
        };
        let out = compute(&Colour::new(g.clone(), false, &layers), &input);
        for name in ["A", "B", "G", "R", "Z"] {
            let c = input.channel_index(name).unwrap();
            assert_eq!(out.planes[c], input.planes[c], "{name} passes bit for bit");
        }
        for (k, name) in ["diffuse.R", "diffuse.G", "diffuse.B"]
            .into_iter()
            .enumerate()
        {
            let (before, after) = (samples(&input, name), samples(&out, name));
            for (i, (x, v)) in before.iter().zip(&after).enumerate() {
                let column = i % 6;
                let expected = if (1..5).contains(&column) {
                    half::f16::from_f32(g.value(k, *x)).to_f32()
                } else {
                    0.0
                };
                assert_eq!(*v, expected, "{name} sample {i}");
            }
        }
    }

    #[test]
    fn unpremult_is_unpremult_grade_premult_in_turn() {
        let input = frame();
        let g = grade(CASES[1], true, false, false);
        let all = Selection::default();
        let ours = compute(&Colour::new(g.clone(), true, &all), &input);
        let chain = [
            &Premult {
                inverse: true,
                layers: all.clone(),
            } as &dyn Op,
            &Colour::new(g, false, &all),
            &Premult {
                inverse: false,
                layers: all.clone(),
            },
        ]
        .iter()
        .fold(input.clone(), |rows, op| compute(*op, &rows));
        for name in ["R", "G", "B", "A", "Z"] {
            let c = input.channel_index(name).unwrap();
            // The chain rounds to half between its steps; the node does not.
            let (a, b) = (samples(&ours, name), samples(&chain, name));
            for (x, y) in a.iter().zip(&b) {
                assert!(
                    (x - y).abs() <= 2e-3 * y.abs().max(1.0),
                    "{name}: {x} vs {y}"
                );
            }
            if name == "A" || name == "Z" {
                assert_eq!(ours.planes[c], input.planes[c]);
            }
        }
        // Where alpha is 0 (column 1) the colour is 0, lifted or not.
        let r = samples(&ours, "R");
        assert_eq!([r[1], r[7], r[13]], [0.0; 3]);
    }
}
