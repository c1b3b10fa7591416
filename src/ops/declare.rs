//! An operation declared once: its name, inputs and parameters (names, help,
//! defaults, bounds) and how it adds its nodes to a graph. The command line
//! (src/cli/mod.rs) and the job file's op node (src/run/job_file.rs) are both made from
//! the declaration, so the two cannot disagree. Recipe: specs/architecture.md,
//! "Adding an operation".

use super::layers::Selection;
use crate::engine::graph::{GraphBuilder, NodeId};
use crate::engine::plan::Job;
use crate::error::Result;
use crate::io::attributes::Edit;
use crate::params::Bound;
use std::collections::BTreeMap;

pub struct Operation {
    /// The subcommand and the job file's `op = "NAME"`.
    pub name: &'static str,
    /// One line for `--help` (longer text after a blank line).
    pub about: &'static str,
    /// The inputs in order; with `repeats`, the last one may be given again
    /// (two or more in all).
    pub inputs: &'static [Input],
    pub repeats: bool,
    pub params: &'static [Param],
    /// Takes `--layer`, `--all-layers`, `--view` (job keys `layers`,
    /// `all_layers`, `view`), and `--part`, `--level`.
    pub layers: bool,
    /// Takes `--straight` (job key `straight`).
    pub straight: bool,
    /// The input whose header, display window and other channels the
    /// command's output keeps (`None`: the last one).
    pub header: Option<usize>,
    /// Adds the operation's nodes reading `inputs` (one per declared input,
    /// or more when it repeats); the last node added is the result.
    pub build: fn(&Args, &mut GraphBuilder, &[NodeId]) -> std::result::Result<NodeId, String>,
    /// Before the graph is built: parameters measured from the inputs (by a
    /// first pass over `job`, an identity graph of them) where they were
    /// not given. A job file's node measures its input 0, the read whose
    /// header reaches it, with the attribute edits of the ops on the way
    /// (`Op::attributes`; none on the command line). In a dry run (the
    /// `bool`) it reads no pixels.
    pub measure: Option<Measure>,
}

/// Measures parameters from a first pass over the inputs.
pub type Measure = fn(&Args, &Job, &[Edit], bool) -> Result<Measured>;

/// Parameters measured: name and value as given on the command line, and
/// notes saying how, which a dry run prints.
#[derive(Debug, Default)]
pub struct Measured {
    pub values: Vec<(&'static str, String)>,
    pub notes: Vec<String>,
}

pub struct Input {
    /// The positional argument's name in `--help`, or the option (`--NAME`)
    /// when `named`.
    pub name: &'static str,
    pub help: &'static str,
    pub named: bool,
}

/// A positional input.
pub const fn input(name: &'static str, help: &'static str) -> Input {
    Input {
        name,
        help,
        named: false,
    }
}

/// An input given as `--NAME FILE`.
pub const fn named(name: &'static str, help: &'static str) -> Input {
    Input {
        name,
        help,
        named: true,
    }
}

impl Operation {
    /// Whether `count` inputs are what it takes.
    pub fn takes(&self, count: usize) -> bool {
        match self.repeats {
            true => count >= self.inputs.len().max(2),
            false => count == self.inputs.len(),
        }
    }

    /// "two inputs (a, b)", for messages.
    pub fn arity(&self) -> String {
        let names: Vec<&str> = self.inputs.iter().map(|i| i.name).collect();
        let count = ["no", "one", "two", "three", "four"]
            .get(self.inputs.len())
            .copied()
            .unwrap_or("several");
        match (self.repeats, self.inputs.len()) {
            (true, _) => "two or more inputs".to_string(),
            (false, 1) => "one input".to_string(),
            (false, _) => format!("{count} inputs ({})", names.join(", ")),
        }
    }

    pub fn param(&self, name: &str) -> Option<&'static Param> {
        self.params.iter().find(|p| p.name == name)
    }

    /// `args` for the image scaled by `factor` (`--proxy-scale`): each pixel
    /// length, given or by default, scaled.
    pub fn scale_lengths(&self, args: &mut Args, factor: f64) -> std::result::Result<(), String> {
        for param in self.params {
            let Some(scale) = param.pixels else { continue };
            if let Some(text) = args
                .values
                .get(param.name)
                .map(String::as_str)
                .or(param.default)
            {
                let scaled = scale(text, factor).map_err(|m| format!("{}: {m}", param.name))?;
                args.values.insert(param.name, scaled);
            }
        }
        Ok(())
    }
}

/// A parameter: `--NAME` on the command line (with `-` for `_`), `NAME` in
/// a job file.
pub struct Param {
    pub name: &'static str,
    pub help: &'static str,
    /// The default, as it would be typed; `None`: required, unless optional.
    pub default: Option<&'static str>,
    /// An `Option`: absent means not given (no default).
    pub optional: bool,
    /// A switch: `--NAME` alone on the command line, `true`/`false` in jobs.
    pub flag: bool,
    /// The values it takes, for `--help`.
    pub choices: &'static [&'static str],
    /// A file name (`FileName`): in a job file, relative to its folder.
    pub file: bool,
    /// Given again for more (`--context A=1 --context B=2`; a job file's
    /// list of strings): the values as text, one a line (`REPEATED`).
    pub repeats: bool,
    /// Parses and checks a value (bounds included).
    pub check: fn(&str) -> std::result::Result<(), String>,
    /// A length in pixels (declared `{pixels}`): its value scaled by a
    /// factor, as text (`--proxy-scale`).
    pub pixels: Option<Scale>,
}

/// A value (as text) times a factor, as text.
pub type Scale = fn(&str, f64) -> std::result::Result<String, String>;

/// A parameter's type that can be a length in pixels: how its value scales
/// with the image (`--proxy-scale`).
pub trait Length: Value {
    fn scaled(text: &str, factor: f64) -> std::result::Result<String, String>;
}

impl Length for f32 {
    fn scaled(text: &str, factor: f64) -> std::result::Result<String, String> {
        Ok(format!("{}", f32::parse(text)? as f64 * factor))
    }
}

/// Counts of pixels (radii, reaches) round up: a proxy never cuts what the
/// full size reaches.
impl Length for u32 {
    fn scaled(text: &str, factor: f64) -> std::result::Result<String, String> {
        Ok(format!("{}", (u32::parse(text)? as f64 * factor).ceil()))
    }
}

impl<T: Length> Length for Option<T> {
    fn scaled(text: &str, factor: f64) -> std::result::Result<String, String> {
        T::scaled(text, factor)
    }
}

impl Param {
    pub fn required(&self) -> bool {
        self.default.is_none() && !self.optional && !self.flag
    }
}

/// A parameter's type: how a value is read from text (the command line's,
/// or a job file's value written as text).
pub trait Value: Sized {
    fn parse(text: &str) -> std::result::Result<Self, String>;
    /// Numbers: parsed and checked against `bound` (crate::params).
    fn bounded(text: &str, _bound: &Bound) -> std::result::Result<Self, String> {
        Self::parse(text)
    }
    /// The value when the parameter is not given and has no default.
    fn absent() -> Option<Self> {
        None
    }
    const FLAG: bool = false;
    const OPTIONAL: bool = false;
    const CHOICES: &'static [&'static str] = &[];
    const FILE: bool = false;
    const REPEATS: bool = false;
}

/// Between the values of a parameter that `repeats`, as `Args` holds them.
pub const REPEATED: char = '\n';

macro_rules! number {
    ($($t:ty),*) => {$(
        impl Value for $t {
            fn parse(text: &str) -> std::result::Result<Self, String> {
                text.trim()
                    .parse()
                    .map_err(|_| format!("expected a number, not '{text}'"))
            }
            fn bounded(text: &str, bound: &Bound) -> std::result::Result<Self, String> {
                bound.parse(text)
            }
        }
    )*};
}
number!(f32, f64, u32);

impl Value for bool {
    fn parse(text: &str) -> std::result::Result<Self, String> {
        match text {
            "true" => Ok(true),
            "false" => Ok(false),
            _ => Err(format!("expected true or false, not '{text}'")),
        }
    }
    fn absent() -> Option<Self> {
        Some(false)
    }
    const FLAG: bool = true;
}

impl Value for String {
    fn parse(text: &str) -> std::result::Result<Self, String> {
        Ok(text.to_string())
    }
}

/// A file a parameter names (a LUT, a config): relative to the working
/// folder on the command line, to the job file's folder in a job file, as a
/// read node's file is; a URI (`ocio://NAME`) as it is.
#[derive(Clone, Debug, PartialEq)]
pub struct FileName(pub String);

impl Value for FileName {
    fn parse(text: &str) -> std::result::Result<Self, String> {
        Ok(FileName(text.to_string()))
    }
    const FILE: bool = true;
}

impl<T: Value> Value for Option<T> {
    fn parse(text: &str) -> std::result::Result<Self, String> {
        T::parse(text).map(Some)
    }
    fn bounded(text: &str, bound: &Bound) -> std::result::Result<Self, String> {
        T::bounded(text, bound).map(Some)
    }
    fn absent() -> Option<Self> {
        Some(None)
    }
    const OPTIONAL: bool = true;
    const CHOICES: &'static [&'static str] = T::CHOICES;
    const FILE: bool = T::FILE;
}

/// A value that is one of a few names (an enum), case-insensitive.
pub fn choice<T: Copy>(
    text: &str,
    names: &[&str],
    values: &[T],
    what: &str,
) -> std::result::Result<T, String> {
    names
        .iter()
        .position(|n| n.eq_ignore_ascii_case(text.trim()))
        .map(|i| values[i])
        .ok_or_else(|| format!("unknown {what} '{text}' (one of: {})", names.join(", ")))
}

/// What an operation is built from: its parameters' values as text, from
/// the command line or a job file, and the shared options.
pub struct Args {
    /// "op 'blur'" or "blur", for messages.
    pub op: &'static str,
    pub values: BTreeMap<&'static str, String>,
    pub layers: Selection,
    pub straight: bool,
    /// Built for a job file, whose node's input may be another node's.
    pub job_file: bool,
}

impl Args {
    /// Parameter `name` parsed by `parse`, else its default, else its
    /// absent value; an error when it is required.
    pub fn get<T: Value>(
        &self,
        name: &str,
        default: Option<&str>,
        parse: fn(&str) -> std::result::Result<T, String>,
    ) -> std::result::Result<T, String> {
        match self.values.get(name).map(String::as_str).or(default) {
            Some(text) => parse(text),
            None => T::absent().ok_or_else(|| format!("op '{}' needs {name}", self.op)),
        }
    }
}

/// Declares an operation's parameters as one struct, each field with its
/// doc comment (the help), an optional bound (`[crate::params::BOUND]`),
/// `{pixels}` for a length in pixels (scaled with the image by `--proxy-scale`;
/// its type implements `Length`) and an optional default as it would be
/// typed (`= "1.0"`); a field without a
/// default is required unless it is an `Option` or a `bool` (a switch).
/// Makes `PARAMS` (the declaration) and `read` (the values from `Args`).
macro_rules! params {
    ($(#[doc = $sdoc:literal])* pub struct $name:ident {
        $($(#[doc = $doc:literal])* $field:ident : $ty:ty $([$bound:path])? $({$unit:ident})? $(= $default:literal)?),* $(,)?
    }) => {
        $(#[doc = $sdoc])*
        #[derive(Debug)]
        pub struct $name {
            $($(#[doc = $doc])* pub $field: $ty,)*
        }

        impl $name {
            pub const PARAMS: &'static [$crate::ops::declare::Param] = &[$(
                $crate::ops::declare::Param {
                    name: stringify!($field),
                    help: concat!($($doc),*),
                    default: params!(@default $($default)?),
                    optional: <$ty as $crate::ops::declare::Value>::OPTIONAL,
                    flag: <$ty as $crate::ops::declare::Value>::FLAG,
                    choices: <$ty as $crate::ops::declare::Value>::CHOICES,
                    file: <$ty as $crate::ops::declare::Value>::FILE,
                    repeats: <$ty as $crate::ops::declare::Value>::REPEATS,
                    check: |text| params!(@parse $ty, text $(, $bound)?).map(drop),
                    pixels: params!(@pixels $ty $(, $unit)?),
                },
            )*];

            pub fn read(args: &$crate::ops::declare::Args) -> std::result::Result<Self, String> {
                Ok($name {$(
                    $field: args.get(
                        stringify!($field),
                        params!(@default $($default)?),
                        |text| params!(@parse $ty, text $(, $bound)?),
                    )?,
                )*})
            }
        }
    };
    (@pixels $ty:ty) => { None };
    (@pixels $ty:ty, pixels) => {
        Some(<$ty as $crate::ops::declare::Length>::scaled as $crate::ops::declare::Scale)
    };
    (@default) => { None };
    (@default $default:literal) => { Some($default) };
    (@parse $ty:ty, $text:expr) => { <$ty as $crate::ops::declare::Value>::parse($text) };
    (@parse $ty:ty, $text:expr, $bound:path) => {
        <$ty as $crate::ops::declare::Value>::bounded($text, &$bound)
    };
}
pub(crate) use params;

#[cfg(test)]
mod tests {
    use super::*;
    use crate::params::MIX;

    params! {
        /// A test op's parameters.
        pub struct Example {
            /// A bounded number.
            mix: f32 [MIX] = "1",
            /// Required.
            radius: u32,
            /// Optional.
            reach: Option<u32>,
            /// A switch.
            invert: bool,
        }
    }

    fn args(values: &[(&'static str, &str)]) -> Args {
        Args {
            op: "example",
            values: values.iter().map(|&(k, v)| (k, v.to_string())).collect(),
            layers: Selection::default(),
            straight: false,
            job_file: false,
        }
    }

    #[test]
    fn one_declaration_gives_names_help_defaults_and_checks() {
        let names: Vec<&str> = Example::PARAMS.iter().map(|p| p.name).collect();
        assert_eq!(names, ["mix", "radius", "reach", "invert"]);
        let [mix, radius, reach, invert] = Example::PARAMS else {
            panic!("four")
        };
        assert_eq!(mix.help.trim(), "A bounded number.");
        assert_eq!(mix.default, Some("1"));
        assert!(radius.required() && !mix.required() && !reach.required());
        assert!(invert.flag && reach.optional);
        assert!((mix.check)("0.5").is_ok() && (mix.check)("2").is_err());
        assert!((radius.check)("x").is_err());
    }

    #[test]
    fn values_defaults_and_the_missing_ones() {
        let read = Example::read(&args(&[("radius", "3")])).unwrap();
        assert_eq!(
            (read.mix, read.radius, read.reach, read.invert),
            (1.0, 3, None, false)
        );
        let read = Example::read(&args(&[
            ("radius", "3"),
            ("mix", "0.25"),
            ("reach", "7"),
            ("invert", "true"),
        ]))
        .unwrap();
        assert_eq!(
            (read.mix, read.radius, read.reach, read.invert),
            (0.25, 3, Some(7), true)
        );
        let missing = Example::read(&args(&[])).err().unwrap();
        assert_eq!(missing, "op 'example' needs radius");
        let out_of_bounds = Example::read(&args(&[("radius", "3"), ("mix", "nan")]));
        assert!(out_of_bounds
            .err()
            .unwrap()
            .contains("mix must be a number from 0 to 1"));
    }
}
