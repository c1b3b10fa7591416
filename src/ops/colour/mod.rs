//! OpenColorIO's transforms (the `ocio` crate, specs/colour-library.md):
//! `colorconvert`, `ociodisplay`, `ociolook`, `cdl` and `filetransform`, one
//! file each. Each builds its processor once, when the graph is built, and
//! applies it to the colour of each band through grade's `Colour` node
//! (layers, alpha, half widened to f32 and back). This file: the config
//! (`--config`, `$OCIO`, the built-in one), names checked against it, and
//! the processor as a colour map. Semantics: specs/ops.md, "Colour (OpenColorIO)".

pub mod auto;
pub mod cdl;
pub mod colorconvert;
pub mod filetransform;
pub mod metadata;
pub mod ociodisplay;
pub mod ociolook;
#[cfg(test)]
mod vendored;

use super::declare::{Args, FileName, Measured, Value, REPEATED};
use super::grade::{Colour, ColourMap};
use crate::engine::graph::{GraphBuilder, NodeId};
use crate::engine::plan::Job;
use crate::io::attributes::Edit;
use crate::io::parts::unknown;
use ocio::config::NamedTransform;
use ocio::{
    ColorSpaceTransform, Config, Context, CpuProcessor, GroupTransform, Processor, Transform,
    TransformDirection, ViewType,
};

pub use super::BUILTIN_COLOUR_CONFIG as BUILTIN;

/// The config: `--config FILE|ocio://NAME`, else `$OCIO` when set and not
/// empty, else the built-in one (not the crate's `create_from_env`, which
/// gives a raw config without `$OCIO`).
pub fn config(given: Option<&FileName>) -> Result<Config, String> {
    let (source, from) = source(given);
    Config::create_from_file(&source).map_err(|e| {
        format!("cannot load the OCIO config '{source}' ({from}): {e}; give --config FILE or ocio://NAME")
    })
}

/// Where the config comes from, and what named it.
fn source(given: Option<&FileName>) -> (String, &'static str) {
    let env = std::env::var("OCIO").ok().filter(|v| !v.is_empty());
    match (given, env) {
        (Some(file), _) => (file.0.clone(), "--config"),
        (None, Some(file)) => (file, "$OCIO"),
        (None, None) => (BUILTIN.to_string(), "the built-in default"),
    }
}

/// The colour operations' measure: `--from auto` read from the first frame
/// of the input, `edits` applied to its header (`auto.rs`); nothing for
/// the others.
pub fn measure(
    args: &Args,
    job: &Job,
    edits: &[Edit],
    _dry_run: bool,
) -> crate::error::Result<Measured> {
    let Some(from) = args.values.get("from") else {
        return Ok(Measured::default());
    };
    if from != auto::AUTO {
        return Ok(Measured::default());
    }
    let given = args.values.get("config").map(|c| FileName(c.clone()));
    let config = config(given.as_ref()).map_err(crate::error::Error::usage)?;
    auto::measure(&config, &source(given.as_ref()).0, job, edits)
}

/// A colour space, role or alias as the config spells its canonical name;
/// an error listing the colour spaces when there is none of that name.
pub fn colour_space(config: &Config, name: &str) -> Result<String, String> {
    if let Some(space) = config.get_color_space(name) {
        return Ok(space.name().to_string());
    }
    if name == auto::AUTO {
        return Err(
            "'auto' is no colour space: --from auto reads the input's (--to names one)".into(),
        );
    }
    let spaces: Vec<String> = (0..config.num_color_spaces())
        .map(|i| config.color_space_name_by_index(i).to_string())
        .collect();
    let mut known = spaces.clone();
    for space in &spaces {
        if let Some(cs) = config.get_color_space(space) {
            known.extend(cs.aliases().iter().cloned());
        }
    }
    known.extend((0..config.num_roles()).map(|i| config.role_name(i).to_string()));
    Err(unknown("colour space", name, &spaces.join(", "), &known))
}

/// `--from` to `--to` as OCIO's `getProcessor(src, dst)` takes them: colour
/// spaces (names, aliases, roles) or named transforms of the config. A
/// named source applies its forward transform and a named destination its
/// inverse; a colour space beside a named transform adds nothing, and the
/// same name twice changes nothing (measured with PyPI's opencolorio 2.6).
pub fn conversion(config: &Config, from: &str, to: &str) -> Result<Transform, String> {
    let named = |name: &str| match config.get_color_space(name) {
        Some(_) => None,
        None => config.get_named_transform(name),
    };
    let (src, dst) = (named(from), named(to));
    if src.is_none() && dst.is_none() {
        let (from, to) = (colour_space(config, from)?, colour_space(config, to)?);
        return Ok(Transform::ColorSpace(ColorSpaceTransform::new(&from, &to)));
    }
    for (name, nt) in [(from, src), (to, dst)] {
        if nt.is_none() {
            colour_space(config, name)?;
        }
    }
    let mut group = GroupTransform::default();
    if src.map(NamedTransform::name) != dst.map(NamedTransform::name) {
        for (nt, dir) in [(src, false), (dst, true)] {
            if let Some(nt) = nt {
                let t = NamedTransform::get_transform(nt, direction(dir));
                group.transforms.push(t.map_err(|e| e.to_string())?);
            }
        }
    }
    Ok(Transform::Group(group))
}

/// The config's displays, the active ones first (in the order
/// `active_displays` or `$OCIO_ACTIVE_DISPLAYS` gives), then the others:
/// OCIO builds an inactive display when it is named.
pub fn displays(config: &Config) -> Vec<String> {
    let mut names: Vec<String> = (0..config.num_displays())
        .map(|i| config.display(i))
        .collect();
    for i in 0..config.num_displays_all() {
        let name = config.display_all(i);
        if !names.iter().any(|n| n == name) {
            names.push(name.to_string());
        }
    }
    names
}

/// A display by name, or by an alias of the display colour space of a
/// display's name (OCIO 2.6's display aliases: `P3-D65 - Display` is
/// `Gamma 2.6 P3-D65 - Display` in the ACES 2.1 configs).
pub fn display(config: &Config, name: &str) -> Result<String, String> {
    let names = displays(config);
    let aliased = config.get_color_space(name).map(|cs| cs.name().to_string());
    match aliased.filter(|cs| names.iter().any(|n| n == cs)) {
        Some(display) if !names.iter().any(|n| n.eq_ignore_ascii_case(name)) => Ok(display),
        _ => one_of("display", name, names),
    }
}

/// A display's views, the active ones first, then the others (inactive
/// views are built when named, as OCIO does).
pub fn views(config: &Config, display: &str) -> Vec<String> {
    let mut names: Vec<String> = (0..config.num_views(display))
        .map(|i| config.view(display, i))
        .collect();
    for kind in [ViewType::DisplayDefined, ViewType::Shared] {
        for i in 0..config.num_views_by_type(kind, display) {
            let name = config.view_by_type(kind, display, i);
            if !names.iter().any(|n| n == name) {
                names.push(name.to_string());
            }
        }
    }
    names
}

/// `name` among `names` (OCIO compares display, view and look names
/// without case), as `names` spells it; else an error listing them.
pub fn one_of(what: &str, name: &str, names: Vec<String>) -> Result<String, String> {
    match names.iter().find(|n| n.eq_ignore_ascii_case(name)) {
        Some(found) => Ok(found.clone()),
        None => Err(unknown(what, name, &names.join(", "), &names)),
    }
}

/// A look list (`A, +B, -C`, OCIO's grammar: `,` or `:` between looks, `+`
/// forward, `-` inverse) with each look checked against the config.
pub fn looks(config: &Config, text: &str) -> Result<String, String> {
    let names: Vec<String> = (0..config.num_looks())
        .map(|i| config.look_name_by_index(i).to_string())
        .collect();
    let mut checked = Vec::new();
    for look in text.split([',', ':']).map(str::trim) {
        let (sign, name) = match look.strip_prefix(['+', '-']) {
            Some(rest) => (&look[..1], rest.trim()),
            None => ("", look),
        };
        checked.push(format!("{sign}{}", one_of("look", name, names.clone())?));
    }
    Ok(checked.join(", "))
}

/// The forward or inverse direction.
pub fn direction(inverse: bool) -> TransformDirection {
    match inverse {
        true => TransformDirection::Inverse,
        false => TransformDirection::Forward,
    }
}

/// A transform's processor in a config (a raw one for files and CDLs).
pub fn processor(config: &Config, transform: Transform) -> Result<Processor, String> {
    processor_in(config, &Vars::default(), transform)
}

/// `processor`, with the config's context variables `vars` set over its
/// own (`--context`).
pub fn processor_in(
    config: &Config,
    vars: &Vars,
    transform: Transform,
) -> Result<Processor, String> {
    let context = vars.context(config);
    let processor = config
        .get_processor_with_context(&context, &transform, TransformDirection::Forward)
        .map_err(|e| e.to_string())?;
    cdl::invertible(&processor)?;
    Ok(processor)
}

/// `--context KEY=VALUE`, given again for more: OCIO's context variables
/// (`$SHOT` in a config's search path or a file transform's `src`); a job
/// file's list of `"KEY=VALUE"` strings.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Vars(pub Vec<(String, String)>);

impl Vars {
    /// The config's current context with these variables set.
    pub fn context(&self, config: &Config) -> Context {
        let mut context = config.current_context().clone();
        for (key, value) in &self.0 {
            context.set_string_var(key, Some(value));
        }
        context
    }
}

impl Value for Vars {
    fn parse(text: &str) -> Result<Self, String> {
        let lines = text.split(REPEATED).filter(|l| !l.is_empty());
        let pairs = lines.map(|line| match line.split_once('=') {
            Some((key, value)) if !key.trim().is_empty() => {
                Ok((key.trim().to_string(), value.to_string()))
            }
            _ => Err(format!(
                "'{line}': a context variable is KEY=VALUE (SHOT=sh010)"
            )),
        });
        pairs.collect::<Result<_, _>>().map(Vars)
    }
    fn absent() -> Option<Self> {
        Some(Vars::default())
    }
    const OPTIONAL: bool = true;
    const REPEATS: bool = true;
}

/// An OCIO CPU processor as a colour map: built once per command, shared by
/// every band of the node (the engine runs them on the pool at once), with
/// the warnings its building owes the run and the attributes it writes.
pub struct Ocio {
    cpu: CpuProcessor,
    id: String,
    warnings: Vec<String>,
    edits: Vec<Edit>,
}

impl Ocio {
    pub fn new(processor: &Processor) -> Self {
        Ocio {
            cpu: processor.default_cpu_processor(),
            id: processor.cache_id(),
            warnings: Vec::new(),
            edits: Vec::new(),
        }
    }

    /// With warnings for the run to print once.
    pub fn warned(self, warnings: Vec<String>) -> Self {
        Ocio { warnings, ..self }
    }

    /// Writing the destination's colour attributes (`metadata.rs`).
    pub fn writing(self, edits: Vec<Edit>) -> Self {
        Ocio { edits, ..self }
    }
}

/// A processor's maths, as its cache id (a hash of its ops and their
/// values), and the attributes written: what a frame's fingerprint
/// records, so that a config with the same names and other maths makes
/// other frames.
impl std::fmt::Debug for Ocio {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "Ocio({})", self.id)?;
        match self.edits.is_empty() {
            true => Ok(()),
            false => write!(f, " writing {:?}", self.edits),
        }
    }
}

impl ColourMap for Ocio {
    fn keeps_clear(&self) -> bool {
        true
    }

    fn warnings(&self) -> Vec<String> {
        self.warnings.clone()
    }

    fn attributes(&self) -> Vec<Edit> {
        self.edits.clone()
    }

    fn apply(&self, rgb: &mut [Vec<f32>; 3]) {
        // OCIO's pixels are packed RGBA: alpha 1, as PyPI's applyRGB has it
        // (the node's alpha, if any, passes untouched).
        // Through a buffer on the stack, a run at a time: no allocation
        // per row. The runs are the processor's own chunks (1024 pixels:
        // `CpuProcessor::apply_pixels`), so the ops see what they saw with
        // the row whole.
        const RUN: usize = 1024;
        let [r, g, b] = rgb;
        let mut pixels = [[0.0f32; 4]; RUN];
        for start in (0..r.len()).step_by(RUN) {
            let end = (start + RUN).min(r.len());
            let run = &mut pixels[..end - start];
            for (i, p) in (start..end).zip(run.iter_mut()) {
                *p = [r[i], g[i], b[i], 1.0];
            }
            self.cpu.apply_pixels(run);
            for (i, &[pr, pg, pb, _]) in (start..end).zip(run.iter()) {
                (r[i], g[i], b[i]) = (pr, pg, pb);
            }
        }
    }
}

/// The node applying `map` to the selected layers' colour, divided by
/// alpha first and multiplied again after unless `no_unpremult`.
pub fn add(
    map: Ocio,
    no_unpremult: bool,
    args: &Args,
    graph: &mut GraphBuilder,
    inputs: &[NodeId],
) -> NodeId {
    graph.add(Colour::new(map, !no_unpremult, &args.layers), inputs)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::engine::graph::{Node, Op};
    use crate::io::text::Utf8Text;
    use crate::ops::declare::Operation;
    use crate::ops::layers::Selection;
    use crate::ops::testing::{compute, image, sample};

    /// Operation `op` built from its declared parameters, as a job file or
    /// the command line would give them: its one node.
    pub fn built(
        op: &Operation,
        values: &[(&'static str, &str)],
        layers: &[&str],
    ) -> Result<Box<dyn Op>, String> {
        let args = Args {
            op: op.name,
            values: values.iter().map(|&(k, v)| (k, v.to_string())).collect(),
            layers: Selection {
                layers: layers.iter().map(|l| l.to_string()).collect(),
                ..Default::default()
            },
            straight: false,
            job_file: false,
        };
        let (mut graph, inputs) = GraphBuilder::with_inputs(1);
        (op.build)(&args, &mut graph, &inputs)?;
        match graph.finish().nodes.pop() {
            Some(Node::Op { op, .. }) => Ok(op),
            _ => panic!("{} adds a node", op.name),
        }
    }

    const GAMUT_LOOK: &str = "ACES 1.3 Reference Gamut Compression";

    /// RGBA (alpha 0, 0.25, 0.5, 1 by column), Z and a `diffuse` layer.
    fn rgba() -> crate::io::rows::Rows {
        let alpha = |x: i32, _| [0.0, 0.25, 0.5, 1.0][x as usize % 4];
        let colour = |k: f32| move |x: i32, y: i32| (0.07 * (x + 2 * y) as f32 - 0.1) * k;
        image(
            8,
            3,
            &[
                ("A", &alpha),
                ("B", &colour(0.5)),
                ("G", &colour(1.0)),
                ("R", &colour(1.5)),
                ("Z", &|x, y| 100.0 + (x * y) as f32),
                ("diffuse.B", &colour(0.2)),
                ("diffuse.G", &colour(0.3)),
                ("diffuse.R", &colour(0.4)),
            ],
        )
    }

    #[test]
    fn colour_is_unpremultiplied_converted_and_premultiplied_again() {
        let input = rgba();
        let cpu = v1()
            .get_processor("ACEScg", "ACEScct")
            .unwrap()
            .default_cpu_processor();
        let values = [
            ("config", "ocio://cg-config-v1.0.0_aces-v1.3_ocio-v2.1"),
            ("from", "ACEScg"),
            ("to", "ACEScct"),
        ];
        let op = built(&colorconvert::COLORCONVERT, &values, &[]).unwrap();
        let out = compute(op.as_ref(), &[&input]).unwrap();
        let plain = [values.to_vec(), vec![("no_unpremult", "true")]].concat();
        let as_is = compute(
            built(&colorconvert::COLORCONVERT, &plain, &[])
                .unwrap()
                .as_ref(),
            &[&input],
        )
        .unwrap();
        for y in 0..3 {
            for x in 0..8 {
                let at = |rows: &crate::io::rows::Rows, c: &str| sample(rows, c, x, y).unwrap();
                let a = at(&input, "A");
                let c = ["R", "G", "B"].map(|n| at(&input, n));
                let mut straight = c.map(|v| if a == 0.0 { v } else { v / a });
                cpu.apply_rgb(&mut straight);
                let mut plain = c;
                cpu.apply_rgb(&mut plain);
                for (k, n) in ["R", "G", "B"].into_iter().enumerate() {
                    // Alpha 0: kept as it was (specs/ops.md).
                    let want = if a == 0.0 { c[k] } else { straight[k] * a };
                    assert_eq!(at(&out, n), want, "{n} at {x},{y}");
                    assert_eq!(at(&as_is, n), plain[k], "{n} at {x},{y} as is");
                }
                for n in ["A", "Z", "diffuse.R", "diffuse.G", "diffuse.B"] {
                    assert_eq!(at(&out, n).to_bits(), at(&input, n).to_bits(), "{n} passes");
                }
            }
        }
    }

    #[test]
    fn an_overflow_where_alpha_is_0_is_not_nan() {
        // ACEScct 100 is 2^(100 x 17.52 - 9.72) in ACEScg: Inf. Times alpha
        // 0 it was NaN; the colour there is kept as it was.
        let alpha = |x: i32, _| [0.0, 0.5][x as usize];
        let input = image(
            2,
            1,
            &[
                ("A", &alpha),
                ("B", &|_, _| 100.0),
                ("G", &|_, _| 0.5),
                ("R", &|_, _| 100.0),
            ],
        );
        let values = [
            ("config", "ocio://cg-config-v1.0.0_aces-v1.3_ocio-v2.1"),
            ("from", "ACEScct"),
            ("to", "ACEScg"),
        ];
        let op = built(&colorconvert::COLORCONVERT, &values, &[]).unwrap();
        let out = compute(op.as_ref(), &[&input]).unwrap();
        for n in ["R", "G", "B"] {
            let (clear, half) = (sample(&out, n, 0, 0).unwrap(), sample(&out, n, 1, 0));
            assert_eq!(
                clear,
                sample(&input, n, 0, 0).unwrap(),
                "{n} where alpha is 0"
            );
            assert!(!half.unwrap().is_nan(), "{n} where alpha is 0.5");
        }
        assert!(sample(&out, "R", 1, 0).unwrap().is_infinite());
    }

    #[test]
    fn the_inverse_of_a_cdl_without_one_is_refused_as_ocio_refuses_it() {
        let error = |values: &[(&'static str, &str)]| built(&cdl::CDL, values, &[]).err();
        for (values, says) in [
            (
                vec![("saturation", "0")],
                "a saturation of 0 (--saturation)",
            ),
            (vec![("slope", "0")], "a slope of 0 (--slope)"),
            (vec![("slope", "1,0,1"), ("saturation", "0.5")], "(--slope)"),
        ] {
            assert!(error(&values).is_none(), "{values:?} forward");
            let inverse = [values.clone(), vec![("inverse", "true")]].concat();
            let message = error(&inverse).expect("refused");
            assert!(message.contains(says), "{message}");
            assert!(message.contains("Singular Matrix can't be inverted"));
            assert_eq!(message.lines().count(), 1);
        }
        // Read from a file, the same.
        let dir = tempfile::tempdir().unwrap();
        let cc = dir.path().join("flat.cc");
        std::fs::write(
            &cc,
            "<ColorCorrection id=\"flat\"><SOPNode><Slope>1 1 1</Slope><Offset>0 0 0</Offset>\
             <Power>1 1 1</Power></SOPNode><SatNode><Saturation>0</Saturation></SatNode>\
             </ColorCorrection>",
        )
        .unwrap();
        let file = cc.to_str().unwrap();
        assert!(error(&[("file", file)]).is_none());
        let message = error(&[("file", file), ("inverse", "true")]).expect("refused");
        assert!(message.contains("a saturation of 0"), "{message}");
        assert!(error(&[("slope", "1e-6"), ("inverse", "true")]).is_none());
    }

    /// A 1D LUT whose entries are infinite (OCIO's
    /// lut3by1d_nan_infinity_example.clf): OCIO clamps them to +-FLT_MAX
    /// and its SIMD renderer interpolates `(high - low) t + low`, so
    /// between FLT_MAX and -FLT_MAX the difference overflows to -Inf and
    /// the result is -Inf (PyPI's opencolorio 2.6 gives it); exactly on an
    /// entry 0 x Inf is NaN.
    #[test]
    fn a_lut_with_infinite_entries_gives_ocios_infinities() {
        let dir = tempfile::tempdir().unwrap();
        let clf = dir.path().join("inf.clf");
        std::fs::write(
            &clf,
            r#"<?xml version="1.0" encoding="UTF-8"?>
<ProcessList id="inf" compCLFversion="3.0">
  <LUT1D inBitDepth="32f" outBitDepth="32f">
    <Array dim="4 3">0 0 0  0 0 inf  0 0 -inf  0 0 0</Array>
  </LUT1D>
</ProcessList>
"#,
        )
        .unwrap();
        let blue = [0.4f32, 0.5, 1.0 / 3.0, 2.0 / 3.0, 0.2];
        let input = image(5, 1, &[("B", &|x, _| blue[x as usize])]);
        let values = [("file", clf.to_str().unwrap())];
        let op = built(&filetransform::FILETRANSFORM, &values, &[]).unwrap();
        let out = compute(op.as_ref(), &[&input]).unwrap();
        let b: Vec<f32> = (0..5).map(|x| sample(&out, "B", x, 0).unwrap()).collect();
        assert_eq!(b[0], f32::NEG_INFINITY, "{b:?}");
        assert_eq!(b[1], f32::NEG_INFINITY, "{b:?}");
        assert!(b[2].is_nan(), "{b:?}");
        assert_eq!(b[3], -f32::MAX, "{b:?}");
        // Between 0 and FLT_MAX: finite, as OCIO's.
        assert!(b[4].is_finite() && b[4] > 1e38, "{b:?}");
    }

    #[test]
    fn a_layer_is_converted_and_the_rest_passes() {
        let input = rgba();
        let values = [
            ("config", "ocio://cg-config-v1.0.0_aces-v1.3_ocio-v2.1"),
            ("from", "ACES2065-1"),
            ("to", "ACEScg"),
        ];
        let op = built(&colorconvert::COLORCONVERT, &values, &["diffuse"]).unwrap();
        let out = compute(op.as_ref(), &[&input]).unwrap();
        for (c, before) in out.channels.iter().zip(&input.channels) {
            let (plane_out, plane_in) = (
                &out.planes[out.channel_index(&c.name.utf8()).unwrap()],
                &input.planes[input.channel_index(&before.name.utf8()).unwrap()],
            );
            let changed = plane_out != plane_in;
            assert_eq!(changed, c.name.utf8().starts_with("diffuse."), "{}", c.name);
        }
    }

    /// ASC CDL in f64 with OCIO's no-clamp style: power only above 0,
    /// saturation about Rec.709 luma.
    fn asc(
        rgb: [f64; 3],
        slope: [f64; 3],
        offset: [f64; 3],
        power: [f64; 3],
        sat: f64,
    ) -> [f64; 3] {
        let v: Vec<f64> = (0..3)
            .map(|i| {
                let v = rgb[i] * slope[i] + offset[i];
                if v > 0.0 {
                    v.powf(power[i])
                } else {
                    v
                }
            })
            .collect();
        let luma = 0.2126 * v[0] + 0.7152 * v[1] + 0.0722 * v[2];
        [0, 1, 2].map(|i| luma + sat * (v[i] - luma))
    }

    #[test]
    fn cdl_values_follow_the_asc_formula() {
        let input = rgba();
        let values = [
            ("slope", "1.2,1,0.8"),
            ("offset", "0.02,0,-0.01"),
            ("power", "1.4,1,0.7"),
            ("saturation", "0.6"),
            ("no_unpremult", "true"),
        ];
        let out = compute(built(&cdl::CDL, &values, &[]).unwrap().as_ref(), &[&input]).unwrap();
        for y in 0..3 {
            for x in 0..8 {
                let c = ["R", "G", "B"].map(|n| f64::from(sample(&input, n, x, y).unwrap()));
                let want = asc(c, [1.2, 1.0, 0.8], [0.02, 0.0, -0.01], [1.4, 1.0, 0.7], 0.6);
                for (k, n) in ["R", "G", "B"].into_iter().enumerate() {
                    let got = f64::from(sample(&out, n, x, y).unwrap());
                    // OCIO's CPU renderer takes its fast pow (specs/ops.md).
                    assert!(
                        (got - want[k]).abs() <= 1e-3 * want[k].abs().max(1e-2),
                        "{n} at {x},{y}: {got} vs {}",
                        want[k]
                    );
                }
            }
        }
    }

    #[test]
    fn each_operation_refuses_what_it_cannot_do_in_one_line() {
        let v4 = ("config", "ocio://cg-config-v4.0.0_aces-v2.0_ocio-v2.5");
        let error =
            |op, values: &[(&'static str, &str)]| built(op, values, &[]).expect_err("an error");
        let message = error(
            &ociodisplay::OCIODISPLAY,
            &[v4, ("display", "sRGB - Dislpay")],
        );
        assert!(
            message.starts_with("no display 'sRGB - Dislpay' (displays: sRGB - Display, "),
            "{message}"
        );
        assert!(
            message.ends_with("did you mean 'sRGB - Display'?"),
            "{message}"
        );
        let message = error(
            &ociodisplay::OCIODISPLAY,
            &[v4, ("display_view", "ACES 2.0 - SDR 100 nits")],
        );
        assert!(
            message.contains("(views: ACES 2.0 - SDR 100 nits (Rec.709), Un-tone-mapped"),
            "{message}"
        );
        let message = error(
            &ociodisplay::OCIODISPLAY,
            &[v4, ("looks", GAMUT_LOOK), ("inverse", "true")],
        );
        assert!(message.contains("not --looks"), "{message}");
        let message = error(&ociolook::OCIOLOOK, &[v4, ("look", "grade")]);
        assert!(
            message.starts_with("no look 'grade' (looks: ACES 1.3 Reference Gamut Compression)"),
            "{message}"
        );
        let message = error(
            &colorconvert::COLORCONVERT,
            &[v4, ("from", "ACEScg"), ("to", "sRGB")],
        );
        assert!(
            message.starts_with("no colour space 'sRGB' (colour spaces: sRGB - Display, "),
            "{message}"
        );
        let message = error(&cdl::CDL, &[("file", "x.cc"), ("slope", "2")]);
        assert!(message.contains("not both"), "{message}");
        assert!(error(&cdl::CDL, &[("id", "a")]).contains("picks a correction of --file"));
        let message = error(
            &filetransform::FILETRANSFORM,
            &[("file", "/nowhere/grade.cube")],
        );
        assert_eq!(
            message,
            "no file '/nowhere/grade.cube' (the LUT or transform to apply)"
        );
        assert!(message.lines().count() == 1);
        // A file that is there but not a regular one says what it is.
        for (file, what) in [("/dev/zero", "a character device"), ("/", "a directory")] {
            for op in [&filetransform::FILETRANSFORM, &cdl::CDL] {
                let message = error(op, &[("file", file)]);
                let says = format!("'{file}' is {what}, not a regular file");
                assert!(message.starts_with(&says), "{message}");
            }
        }
    }

    fn v1() -> Config {
        config(Some(&FileName(
            "ocio://cg-config-v1.0.0_aces-v1.3_ocio-v2.1".into(),
        )))
        .unwrap()
    }

    #[test]
    fn names_aliases_and_roles_become_the_configs_spelling() {
        let config = v1();
        assert_eq!(colour_space(&config, "ACEScg").unwrap(), "ACEScg");
        assert_eq!(colour_space(&config, "acescg").unwrap(), "ACEScg");
        assert_eq!(colour_space(&config, "ACES - ACEScg").unwrap(), "ACEScg");
        assert_eq!(colour_space(&config, "scene_linear").unwrap(), "ACEScg");
    }

    #[test]
    fn an_unknown_name_lists_the_ones_there_are_and_suggests_a_near_miss() {
        let config = v1();
        let message = colour_space(&config, "ACEScgg").unwrap_err();
        assert!(message.starts_with("no colour space 'ACEScgg' (colour spaces: "));
        assert!(
            message.contains("ACES2065-1, ACEScc, ACEScct, ACEScg"),
            "{message}"
        );
        assert!(message.ends_with("; did you mean 'ACEScg'?"), "{message}");
        assert!(!colour_space(&config, "Rec.2020 Nothing")
            .unwrap_err()
            .contains("did you mean"));
        let message = looks(&config, "+ACES 1.3 Reference Gamut Compresion").unwrap_err();
        assert!(message.contains("did you mean 'ACES 1.3 Reference Gamut Compression'"));
        assert_eq!(
            looks(&config, "-aces 1.3 reference gamut compression").unwrap(),
            "-ACES 1.3 Reference Gamut Compression"
        );
    }

    #[test]
    fn the_config_comes_from_the_option_else_ocio_else_the_builtin() {
        let message = config(Some(&FileName("/nowhere/config.ocio".into())))
            .err()
            .unwrap();
        assert!(
            message.starts_with("cannot load the OCIO config '/nowhere/config.ocio' (--config)")
        );
        let message = config(Some(&FileName("ocio://no-such-config".into())))
            .err()
            .unwrap();
        assert!(message.contains("no-such-config"), "{message}");
        // $OCIO is read by the process; the suite's colour module tests it.
        assert!(config(Some(&FileName(BUILTIN.into()))).is_ok());
    }

    #[test]
    fn the_map_is_the_processor_on_each_pixel() {
        let config = v1();
        let cpu = config
            .get_processor("ACEScg", "ACEScct")
            .unwrap()
            .default_cpu_processor();
        let mut rgb = [
            vec![0.18f32, 0.0, 4.0],
            vec![0.5, 1.0, -0.1],
            vec![0.02, 2.0, 0.0],
        ];
        let before = rgb.clone();
        let processor = config.get_processor("ACEScg", "ACEScct").unwrap();
        Ocio::new(&processor).apply(&mut rgb);
        for i in 0..3 {
            let mut pixel = [before[0][i], before[1][i], before[2][i]];
            cpu.apply_rgb(&mut pixel);
            assert_eq!([rgb[0][i], rgb[1][i], rgb[2][i]], pixel);
        }
        // ACEScct of 0.18 (the ACES spec: (log2(x) + 9.72) / 17.52).
        let expected = (0.18f32.log2() + 9.72) / 17.52;
        assert!((rgb[0][0] - expected).abs() < 1e-5, "{}", rgb[0][0]);
    }
}
