//! Channel shuffles: `shuffle` (oiiotool's `--ch`: select, rename, reorder,
//! add constant channels, drop the rest) and `copy` (Nuke's Copy: channels of
//! A into B). Channels carried are copied bit for bit in their own type.
//! Grammar and choices: specs/ops.md, "Channel shuffles".

use super::declare::{input, params, Operation};
use crate::engine::graph::{Carried, Op};
use crate::io::rows::{Rows, RowsMut};
use crate::io::text::Utf8Text;
use exr::meta::attribute::{ChannelDescription, SampleType, Text};

pub const SHUFFLE: Operation = Operation {
    name: "shuffle",
    about: "Select, rename, reorder and add channels as oiiotool's --ch does \
            (R=diffuse.R,G=diffuse.G,B=diffuse.B,A=1.0); channels not named are dropped",
    inputs: &[input("input", "Input file or sequence, `:PART` for a part")],
    repeats: false,
    params: ShuffleParams::PARAMS,
    layers: false,
    straight: false,
    header: Some(0),
    build: |args, graph, inputs| {
        let p = ShuffleParams::read(args)?;
        let items = match (p.ch, p.layer_to_rgba) {
            (Some(ch), None) => parse(&ch)?,
            (None, Some(layer)) => layer_to_rgba(&layer)?,
            _ => {
                let names = match args.job_file {
                    true => "ch or layer_to_rgba",
                    false => "--ch or --layer-to-rgba",
                };
                return Err(format!("{} takes {names}, one of them", args.op));
            }
        };
        Ok(graph.add(Shuffle { items, into: false }, inputs))
    },
    measure: None,
};

pub const COPY: Operation = Operation {
    name: "copy",
    about: "Nuke's Copy: channels of A into B (--ch NEW=OLD,... as shuffle's), B's other \
            channels and header kept",
    inputs: &[
        input(
            "a",
            "Where the channels come from: a file or sequence, `:PART` for a part",
        ),
        input(
            "b",
            "What they go into: its header, display window and other channels are kept",
        ),
    ],
    repeats: false,
    params: CopyParams::PARAMS,
    layers: false,
    straight: false,
    header: Some(1),
    build: |args, graph, inputs| {
        let items = parse(&CopyParams::read(args)?.ch)?;
        Ok(graph.add(Shuffle { items, into: true }, inputs))
    },
    measure: None,
};

params! {
    pub struct ShuffleParams {
        /// The output's channels, comma-separated: NAME (kept), NEW=OLD
        /// (renamed), NEW=VALUE or =VALUE (a constant), INDEX (by position).
        ch: Option<String>,
        /// Layer NAME's R, G, B, A become R, G, B, A (the rest dropped).
        layer_to_rgba: Option<String>,
    }
}

params! {
    pub struct CopyParams {
        /// A's channels to copy, as shuffle's --ch: Z (as it is), mask=A
        /// (renamed), NEW=VALUE (a constant).
        ch: String,
    }
}

/// Where an output channel's samples come from, as written.
#[derive(Clone, Debug, PartialEq)]
pub enum From {
    /// The channel at this position in the input's list.
    Index(usize),
    /// The channel of this name (else the first whose name differs only
    /// in case, as oiiotool).
    Name(String),
    Constant(f32),
}

/// One output channel of a `--ch` list.
#[derive(Clone, Debug, PartialEq)]
pub struct Item {
    /// The output's name; the source's when `None`.
    pub name: Option<String>,
    pub from: From,
    /// Left out, rather than an error, when the input lacks the channel.
    pub optional: bool,
}

/// The default names of unnamed constants by position: oiiotool's.
fn default_name(position: usize) -> String {
    match ["R", "G", "B", "A", "Z"].get(position) {
        Some(name) => name.to_string(),
        None => format!("channel{position}"),
    }
}

/// A constant: a finite number.
fn constant(text: &str) -> Option<f32> {
    text.parse::<f32>().ok().filter(|v| v.is_finite())
}

/// oiiotool's `--ch` list: `NAME`, `NEW=OLD`, `NEW=VALUE`, `=VALUE`, `INDEX`
/// (`RGB` and `RGBA` alone stand for `R,G,B` and `R,G,B,A`).
pub fn parse(text: &str) -> Result<Vec<Item>, String> {
    let text = match text.trim() {
        "RGB" => "R,G,B",
        "RGBA" => "R,G,B,A",
        other => other,
    };
    text.split(',')
        .enumerate()
        .map(|(position, part)| {
            let part = part.trim();
            let item = |name: Option<String>, from| Item {
                name,
                from,
                optional: false,
            };
            if let Ok(index) = part.parse::<usize>() {
                return Ok(item(None, From::Index(index)));
            }
            match part.split_once('=').map(|(n, o)| (n.trim(), o.trim())) {
                None if part.is_empty() => Err(format!("an empty channel in '{text}'")),
                None => Ok(item(None, From::Name(part.to_string()))),
                Some((new, old)) => match (new, constant(old)) {
                    ("", Some(v)) => Ok(item(Some(default_name(position)), From::Constant(v))),
                    (_, Some(v)) => Ok(item(Some(new.to_string()), From::Constant(v))),
                    ("", None) => Err(format!("'{part}': a name goes before '='")),
                    (_, None) if old.is_empty() => {
                        Err(format!("'{part}': a channel or a number goes after '='"))
                    }
                    (_, None) => Ok(item(Some(new.to_string()), From::Name(old.to_string()))),
                },
            }
        })
        .collect()
}

/// `R=L.R,G=L.G,B=L.B,A=L.A`, each of them only if the layer has it.
pub fn layer_to_rgba(layer: &str) -> Result<Vec<Item>, String> {
    let layer = layer.trim().trim_end_matches('.');
    if layer.is_empty() {
        return Err("layer_to_rgba needs a layer name".into());
    }
    Ok(["R", "G", "B", "A"]
        .iter()
        .map(|c| Item {
            name: Some(c.to_string()),
            from: From::Name(format!("{layer}.{c}")),
            optional: true,
        })
        .collect())
}

/// The node: the output's channels from its first input (and with `into`,
/// every channel of the second it does not replace).
#[derive(Debug)]
pub struct Shuffle {
    pub items: Vec<Item>,
    pub into: bool,
}

/// An output channel: its description and where its samples come from.
struct Output {
    channel: ChannelDescription,
    /// (input, channel index), or a constant.
    source: Result<(usize, usize), f32>,
}

fn names(list: &[ChannelDescription]) -> String {
    let names: Vec<String> = list.iter().map(|c| c.name.utf8()).collect();
    match names.is_empty() {
        true => "none".into(),
        false => names.join(", "),
    }
}

impl Shuffle {
    /// The output channels, sorted by name as OpenEXR stores them.
    fn resolve(&self, inputs: &[&[ChannelDescription]]) -> Result<Vec<Output>, String> {
        let from = inputs[0];
        // A constant is half when the image it goes into is all half.
        let base = inputs[inputs.len() - 1];
        let constant_type = match base.iter().all(|c| c.sample_type == SampleType::F16) {
            true => SampleType::F16,
            false => SampleType::F32,
        };
        let mut outputs = Vec::new();
        for item in &self.items {
            let source = match &item.from {
                From::Constant(v) => Err(*v),
                From::Index(i) if *i < from.len() => Ok(*i),
                From::Index(i) => {
                    return Err(format!(
                        "no channel number {i}: the input has {} (from 0: {})",
                        from.len(),
                        names(from)
                    ))
                }
                From::Name(name) => {
                    let lower = name.to_lowercase();
                    let found = from.iter().position(|c| c.name.is(name)).or_else(|| {
                        from.iter()
                            .position(|c| c.name.utf8().to_lowercase() == lower)
                    });
                    match found {
                        Some(i) => Ok(i),
                        None if item.optional => continue,
                        None => {
                            return Err(format!("no channel '{name}' (channels: {})", names(from)))
                        }
                    }
                }
            };
            let channel = match (source, &item.name) {
                (Ok(i), None) => from[i].clone(),
                (Ok(i), Some(name)) => ChannelDescription {
                    name: text(name)?,
                    ..from[i].clone()
                },
                (Err(_), name) => {
                    let name = name.as_deref().expect("constants are named");
                    ChannelDescription::named(text(name)?, constant_type)
                }
            };
            outputs.push(Output {
                channel,
                source: source.map(|i| (0, i)),
            });
        }
        if outputs.is_empty() {
            return Err(format!(
                "none of the channels asked for is there (channels: {})",
                names(from)
            ));
        }
        for (i, output) in outputs.iter().enumerate() {
            if outputs[..i]
                .iter()
                .any(|o| o.channel.name == output.channel.name)
            {
                return Err(format!("channel '{}' is given twice", output.channel.name));
            }
        }
        if self.into {
            for (i, c) in inputs[1].iter().enumerate() {
                if !outputs.iter().any(|o| o.channel.name == c.name) {
                    outputs.push(Output {
                        channel: c.clone(),
                        source: Ok((1, i)),
                    });
                }
            }
        }
        outputs.sort_by(|a, b| a.channel.name.bytes().cmp(b.channel.name.bytes()));
        Ok(outputs)
    }
}

/// A channel name OpenEXR can store.
fn text(name: &str) -> Result<Text, String> {
    (!name.is_empty() && name.len() < 256)
        .then(|| crate::io::text::text(name))
        .ok_or_else(|| format!("'{name}' is not a channel name a file can hold"))
}

impl Op for Shuffle {
    fn channels(&self, inputs: &[&[ChannelDescription]]) -> Vec<ChannelDescription> {
        match self.resolve(inputs) {
            Ok(outputs) => outputs.into_iter().map(|o| o.channel).collect(),
            // `check` says why.
            Err(_) => inputs[inputs.len() - 1].to_vec(),
        }
    }

    fn check(&self, inputs: &[&[ChannelDescription]]) -> Result<(), String> {
        self.resolve(inputs).map(drop)
    }

    /// `shuffle` without constants; never `copy`, whose blocks hold A's
    /// channels, which B's chunks lack.
    fn carries(&self, inputs: &[&[ChannelDescription]]) -> Option<Carried> {
        if self.into {
            return None;
        }
        let outputs = self.resolve(inputs).ok()?;
        let channels = outputs
            .iter()
            .map(|o| o.source.ok().map(|(_, i)| i))
            .collect::<Option<_>>()?;
        Some(Carried {
            input: 0,
            channels,
            shift: (0, 0),
        })
    }

    fn compute(&self, _frame: i64, inputs: &[&Rows], out: &mut RowsMut) -> Result<(), String> {
        let lists: Vec<&[ChannelDescription]> =
            inputs.iter().map(|r| r.channels.as_slice()).collect();
        let outputs = self.resolve(&lists)?;
        let columns = out.valid_columns();
        for y in out.valid_rows() {
            let range = out.row_range(y);
            for (c, output) in outputs.iter().enumerate() {
                debug_assert!(out.channels[c].name == output.channel.name);
                match output.source {
                    Ok((input, s)) => {
                        let rows = inputs[input];
                        out.planes[c]
                            .bytes_mut(range.clone())
                            .copy_from_slice(rows.planes[s].bytes(rows.row_range(y)));
                    }
                    Err(value) => {
                        let dst = range.start + columns.start..range.start + columns.end;
                        out.planes[c].write_f32(dst, &vec![value; columns.len()]);
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
    use exr::meta::attribute::IntegerBounds;

    fn item(name: Option<&str>, from: From) -> Item {
        Item {
            name: name.map(str::to_string),
            from,
            optional: false,
        }
    }

    #[test]
    fn the_grammar_is_oiiotools() {
        let name = |n: &str| From::Name(n.into());
        assert_eq!(
            parse("R=diffuse.R, G ,B=0.5,=1,2,Z=depth,=0").unwrap(),
            [
                item(Some("R"), name("diffuse.R")),
                item(None, name("G")),
                item(Some("B"), From::Constant(0.5)),
                item(Some("A"), From::Constant(1.0)),
                item(None, From::Index(2)),
                item(Some("Z"), name("depth")),
                item(Some("channel6"), From::Constant(0.0)),
            ]
        );
        assert_eq!(parse("RGBA").unwrap().len(), 4);
        assert_eq!(
            parse("A=1.0").unwrap(),
            [item(Some("A"), From::Constant(1.0))]
        );
        for bad in ["R,,G", "=G", "R=", ""] {
            assert!(parse(bad).is_err(), "{bad}");
        }
        // A name that is not a number stays a name, even "nan" after '='.
        assert_eq!(parse("A=nan").unwrap(), [item(Some("A"), name("nan"))]);
    }

    fn list(channels: &[(&str, SampleType)]) -> Vec<ChannelDescription> {
        channels
            .iter()
            .map(|&(n, t)| ChannelDescription::new(n, t, false))
            .collect()
    }

    fn resolved(
        items: Vec<Item>,
        into: bool,
        inputs: &[&[ChannelDescription]],
    ) -> Result<Vec<(String, SampleType)>, String> {
        let op = Shuffle { items, into };
        op.check(inputs)?;
        Ok(op
            .channels(inputs)
            .iter()
            .map(|c| (c.name.utf8(), c.sample_type))
            .collect())
    }

    #[test]
    fn outputs_are_sorted_typed_and_errors_list_the_channels() {
        use SampleType::*;
        let input = list(&[
            ("A", F16),
            ("B", F16),
            ("G", F16),
            ("R", F16),
            ("Z", F32),
            ("diffuse.R", F32),
            ("id", U32),
        ]);
        let got = resolved(
            parse("R=diffuse.R,G,b,A=1,object=id,0").unwrap(),
            false,
            &[&input],
        );
        let expected = [
            ("A", F32),
            ("B", F16),
            ("G", F16),
            ("R", F32),
            ("object", U32),
        ];
        // `0` is A (by position) and A is also given as a constant.
        assert_eq!(got.unwrap_err(), "channel 'A' is given twice");
        let got = resolved(
            parse("R=diffuse.R,G,b,A=1,object=id").unwrap(),
            false,
            &[&input],
        )
        .unwrap();
        let expected: Vec<_> = expected.iter().map(|&(n, t)| (n.to_string(), t)).collect();
        assert_eq!(
            got, expected,
            "b found case-insensitively; the constant is float"
        );
        let halves = list(&[("B", F16), ("G", F16), ("R", F16)]);
        let got = resolved(parse("R,G,B,A=1").unwrap(), false, &[&halves]).unwrap();
        assert_eq!(
            got[0],
            ("A".to_string(), F16),
            "a constant into a half image is half"
        );
        let message = resolved(parse("R=diffuse.X").unwrap(), false, &[&input]).unwrap_err();
        assert_eq!(
            message,
            "no channel 'diffuse.X' (channels: A, B, G, R, Z, diffuse.R, id)"
        );
        let message = resolved(parse("9").unwrap(), false, &[&input]).unwrap_err();
        assert!(
            message.starts_with("no channel number 9: the input has 7"),
            "{message}"
        );
        let message = resolved(layer_to_rgba("specular").unwrap(), false, &[&input]).unwrap_err();
        assert!(
            message.starts_with("none of the channels asked for"),
            "{message}"
        );
        let got = resolved(layer_to_rgba("diffuse").unwrap(), false, &[&input]).unwrap();
        assert_eq!(got, [("R".to_string(), F32)]);
        // Into B: B's channels, one replaced and one added.
        let b = list(&[("B", F32), ("G", F32), ("R", F32), ("Z", F16)]);
        let got = resolved(parse("Z,mask=A").unwrap(), true, &[&input, &b]).unwrap();
        let names: Vec<_> = got.iter().map(|(n, t)| format!("{n}:{t:?}")).collect();
        assert_eq!(names, ["B:F32", "G:F32", "R:F32", "Z:F32", "mask:F16"]);
    }

    #[test]
    fn carried_channels_are_bit_for_bit_and_constants_fill_the_data_window() {
        use SampleType::*;
        let channels = list(&[("A", F16), ("Z", F32), ("id", U32)]);
        let valid = IntegerBounds::new((0, 1), (3, 2));
        let mut a = Rows::zeros(-1, 0, 5, 4, channels, valid);
        for y in 1..3 {
            let range = a.row_range(y);
            for (c, plane) in a.planes.iter_mut().enumerate() {
                let values: Vec<f32> = (0..5)
                    .map(|x| {
                        if (1..4).contains(&x) {
                            (c * 100 + x) as f32 + 0.3
                        } else {
                            0.0
                        }
                    })
                    .collect();
                plane.write_f32(range.clone(), &values);
            }
        }
        let b = Rows::zeros(-1, 0, 5, 4, list(&[("R", F16)]), valid);
        let op = Shuffle {
            items: parse("alpha=A,id,Z=7.5").unwrap(),
            into: true,
        };
        let lists = [a.channels.as_slice(), b.channels.as_slice()];
        let mut out = Rows::zeros(-1, 0, 5, 4, op.channels(&lists), valid);
        for mut band in out.bands(0, 3) {
            op.compute(1, &[&a, &b], &mut band).unwrap();
        }
        let names: Vec<String> = out.channels.iter().map(|c| c.name.utf8()).collect();
        assert_eq!(names, ["R", "Z", "alpha", "id"]);
        assert_eq!(out.planes[2], a.planes[0], "alpha is A, bit for bit");
        assert_eq!(out.planes[3], a.planes[2], "id is carried");
        let mut z = vec![0.0; 20];
        out.planes[1].read_f32(0..20, &mut z);
        for (i, v) in z.iter().enumerate() {
            let (x, y) = (i % 5, i / 5);
            let inside = (1..4).contains(&x) && (1..3).contains(&y);
            assert_eq!(*v, if inside { 7.5 } else { 0.0 }, "Z at {x}, {y}");
        }
    }
}
