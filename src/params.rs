//! The bounds of every numeric parameter, and one rule for them wherever a
//! value comes in, the command line or a job file: a finite number within
//! its bounds. A bound keeps what a value drives (halo rows, streak lengths,
//! shifts) from asking for unbounded memory or time.

use std::fmt::Display;
use std::str::FromStr;

pub struct Bound {
    /// The name as both the command line (`--max-radius`) and job files
    /// (`max_radius`) spell it, with `_`.
    pub name: &'static str,
    pub min: f64,
    pub max: f64,
}

impl Bound {
    /// `value` if it is finite and within the bounds: the bounds as
    /// written or as an f32 holds them (0.01 as f32 is 0.0099999998, and
    /// `--proxy-scale 0.01` was refused as under 0.01).
    pub fn check<T: Into<f64> + Copy + Display>(&self, value: T) -> Result<T, String> {
        let v: f64 = value.into();
        let (min, max) = (self.min as f32 as f64, self.max as f32 as f64);
        if v.is_finite() && (self.min.min(min)..=self.max.max(max)).contains(&v) {
            Ok(value)
        } else {
            Err(self.refusal(value))
        }
    }

    fn refusal(&self, shown: impl Display) -> String {
        format!(
            "{} must be a number from {} to {}, not {shown}",
            self.name, self.min, self.max
        )
    }

    /// Parses and checks a command-line value.
    pub fn parse<T: FromStr + Into<f64> + Copy + Display>(&self, text: &str) -> Result<T, String> {
        let value = text.trim().parse::<T>().map_err(|_| self.refusal(text))?;
        self.check(value).map_err(|_| self.refusal(text))
    }

    /// Parses and checks each value of a comma-separated list (`R,G,B`).
    pub fn parse_list<T: FromStr + Into<f64> + Copy + Display>(
        &self,
        text: &str,
    ) -> Result<Vec<T>, String> {
        text.split(',').map(|v| self.parse(v)).collect()
    }
}

const fn bound(name: &'static str, min: f64, max: f64) -> Bound {
    Bound { name, min, max }
}

pub const THREADS_PER_CORE: usize = 8;
pub const MIX: Bound = bound("mix", 0.0, 1.0);
pub const RESIZE_SCALE: Bound = bound("scale", 1e-4, 1e4);
pub const PROXY_SCALE: Bound = bound("proxy_scale", 0.01, 1.0);
pub const TRANSLATE: Bound = bound("translate", -1048576.0, 1048576.0);
pub const CENTER: Bound = bound("center", -1048576.0, 1048576.0);
pub const ROTATE: Bound = bound("rotate", -1e6, 1e6);
pub const TRANSFORM_SCALE: Bound = bound("scale", -1e4, 1e4);
pub const SKEW: Bound = bound("skew", -100.0, 100.0);
pub const BLUR_RADIUS: Bound = bound("radius", 0.0, 4096.0);
pub const MORPH_RADIUS: Bound = bound("radius", 0.0, 1024.0);
pub const FOCUS: Bound = bound("focus", 0.0, 1e9);
pub const DEFOCUS_SCALE: Bound = bound("scale", 0.0, 1e6);
pub const MAX_RADIUS: Bound = bound("max_radius", 0.0, 512.0);
pub const VBLUR_SCALE: Bound = bound("scale", -1000.0, 1000.0);
pub const MAX_DISPLACEMENT: Bound = bound("max_displacement", 0.0, 16384.0);
pub const DISPARITY: Bound = bound("disparity", -1e6, 1e6);
pub const SHADOW_GAIN: Bound = bound("shadow_gain", -100.0, 100.0);
pub const SCREEN: Bound = bound("screen", 0.0, 1e6);
pub const GAIN: Bound = bound("gain", 0.0, 1000.0);
pub const BALANCE: Bound = bound("balance", 0.0, 1.0);
pub const CLIP: Bound = bound("clip", 0.0, 1.0);
pub const THRESHOLD: Bound = bound("threshold", 0.0, 1e6);
pub const SOFTNESS: Bound = bound("softness", 0.0, 1e6);
/// Grade's points and levels: any finite value means something.
pub const BLACKPOINT: Bound = bound("blackpoint", -1e6, 1e6);
pub const WHITEPOINT: Bound = bound("whitepoint", -1e6, 1e6);
pub const LIFT: Bound = bound("lift", -1e6, 1e6);
pub const GRADE_GAIN: Bound = bound("gain", -1e6, 1e6);
pub const MULTIPLY: Bound = bound("multiply", -1e6, 1e6);
pub const OFFSET: Bound = bound("offset", -1e6, 1e6);
/// 0 (or below, in Nuke) makes the gamma a step.
pub const GAMMA: Bound = bound("gamma", 0.0, 1e3);
/// 2^64 is still a finite f32.
pub const STOPS: Bound = bound("stops", -64.0, 64.0);
pub const SATURATION_FACTOR: Bound = bound("saturation", -1e3, 1e3);
pub const CDL_SLOPE: Bound = bound("slope", 0.0, 1e6);
pub const CDL_POWER: Bound = bound("power", 0.0, 1e3);
/// DWAA/DWAB's `dwaCompressionLevel`: its quantisation step is the level /
/// 100000 of a JPEG table step, so 100000 already flattens every block.
pub const DWA_LEVEL: Bound = bound("dwa_level", 0.0, 1e5);
/// OpenEXR's default DWA level (oiiotool's `dwaa` is `dwaa:45`).
pub const DEFAULT_DWA_LEVEL: f32 = 45.0;

/// `--threads`: at least one, at most `THREADS_PER_CORE` per core the
/// machine has (more only costs memory and start-up).
/// Most threads a farm task may ask for: a farm worker's cores, not the
/// submitting machine's (the largest cloud hosts have 896 vCPUs).
pub const FARM_THREADS: usize = 1024;

/// `--threads` as parsed: at least one, at most `FARM_THREADS`; a local run
/// is held to `parse_threads`'s bound once the command is known.
pub fn parse_farm_threads(text: &str) -> Result<usize, String> {
    match text.trim().parse::<usize>() {
        Ok(n) if (1..=FARM_THREADS).contains(&n) => Ok(n),
        _ => Err(format!(
            "threads must be a whole number from 1 to {FARM_THREADS} (a farm worker's cores), not '{text}'"
        )),
    }
}

pub fn parse_threads(text: &str) -> Result<usize, String> {
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    let most = cores * THREADS_PER_CORE;
    match text.trim().parse::<usize>() {
        Ok(n) if (1..=most).contains(&n) => Ok(n),
        _ => Err(format!(
            "threads must be a whole number from 1 to {most} ({THREADS_PER_CORE} per core), not '{text}'"
        )),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_rule_for_every_number() {
        for text in ["NaN", "nan", "inf", "-inf", "1e30", "-0.5", "1.5", "x", ""] {
            assert!(MIX.parse::<f32>(text).is_err(), "{text}");
        }
        assert_eq!(MIX.parse::<f32>("0.25"), Ok(0.25));
        assert_eq!(MAX_RADIUS.parse::<u32>("512"), Ok(512));
        assert!(MAX_RADIUS.parse::<u32>("513").is_err());
        assert!(VBLUR_SCALE.check(f32::NAN).is_err());
        assert!(VBLUR_SCALE.check(f32::INFINITY).is_err());
        assert_eq!(VBLUR_SCALE.check(-2.0f32), Ok(-2.0));
        // The bounds themselves, as an f32 holds them, are within.
        assert_eq!(PROXY_SCALE.parse::<f32>("0.01"), Ok(0.01));
        assert_eq!(RESIZE_SCALE.parse::<f32>("0.0001"), Ok(0.0001));
        assert!(PROXY_SCALE.parse::<f32>("0.0099").is_err());
        assert!(RESIZE_SCALE.parse::<f64>("0.000099999").is_err());
        let message = DISPARITY.parse::<f32>("1e30").unwrap_err();
        assert!(
            message.contains("disparity must be a number from"),
            "{message}"
        );
    }

    #[test]
    fn threads_are_bounded_by_the_machine() {
        assert!(parse_threads("0").is_err());
        assert!(parse_threads("100000").is_err());
        assert!(parse_threads("-1").is_err());
        assert_eq!(parse_threads("1"), Ok(1));
        assert_eq!(
            parse_threads(&THREADS_PER_CORE.to_string()),
            Ok(THREADS_PER_CORE)
        );
    }
}
