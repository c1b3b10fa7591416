//! Job files (`exrcomp run JOB.toml`): a graph of read, operation and write
//! nodes, checked with errors that name the file's line, then built into one
//! streaming `Graph`. The format: specs/job-format.md.

use crate::cli::{parse_screen, parse_tile};
use crate::engine::graph::{Graph, Op};
use crate::error::{Error, Result};
use crate::ops::blur::{self, Filter};
use crate::ops::defocus::{Aperture, Defocus};
use crate::ops::diffrender;
use crate::ops::layers::Selection;
use crate::ops::matte::{DiffMatte, Key, Matte, Pull};
use crate::ops::merge::{push_stack, Merge, MergeOp};
use crate::ops::morphology::Morphology;
use crate::ops::premult::Premult;
use crate::ops::stereo::{Eye, Stereo};
use crate::ops::vblur::VectorBlur;
use crate::ops::zmerge::ZMerge;
use crate::params::*;
use clap::ValueEnum;
use exr::math::Vec2;
use exr::meta::attribute::{ChannelDescription, IntegerBounds};
use serde::Deserialize;
use std::collections::HashMap;
use std::ops::Range;
use std::path::Path;
use toml::Spanned;

use crate::engine::strip::{Rows, RowsMut};

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct JobFile {
    /// Frames, as `--frames` takes them; `--frames` wins.
    frames: Option<String>,
    #[serde(default)]
    node: Vec<Spanned<NodeSpec>>,
}

/// One `[[node]]` table: exactly one of `read`, `op` or `write` says what
/// it is; the other keys are that kind's parameters.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct NodeSpec {
    name: Spanned<String>,
    read: Option<String>,
    op: Option<Spanned<String>>,
    write: Option<String>,
    #[serde(default)]
    inputs: Vec<Spanned<String>>,
    part: Option<String>,
    operator: Option<Spanned<String>>,
    mix: Option<f32>,
    straight: Option<bool>,
    layers: Option<Vec<String>>,
    all_layers: Option<bool>,
    view: Option<String>,
    compression: Option<String>,
    all_parts: Option<bool>,
    tile: Option<Spanned<String>>,
    radius: Option<u32>,
    filter: Option<Spanned<String>>,
    focus: Option<f32>,
    scale: Option<f32>,
    max_radius: Option<u32>,
    aperture: Option<Spanned<String>>,
    z_channel: Option<String>,
    vectors: Option<Spanned<Vec<String>>>,
    max_displacement: Option<u32>,
    eye: Option<Spanned<String>>,
    disparity: Option<f32>,
    shadow_gain: Option<f32>,
    shadow_only: Option<bool>,
    screen: Option<Spanned<String>>,
    gain: Option<f32>,
    balance: Option<f32>,
    clip_black: Option<f32>,
    clip_white: Option<f32>,
    despill: Option<bool>,
    invert: Option<bool>,
    threshold: Option<f32>,
    softness: Option<f32>,
}

/// A job file turned into what the engine runs.
pub struct JobPlan {
    /// Per read node, in graph order: the file pattern and the part asked for.
    pub reads: Vec<(String, Option<String>)>,
    pub graph: Graph,
    /// The read whose header the output keeps (following B inputs down).
    pub header_from: usize,
    pub output: String,
    pub compression: Option<String>,
    /// The write node's `all_parts`: the graph on every part of its read.
    pub all_parts: bool,
    /// The write node's tile size (`--tile` wins).
    pub tile: Option<Vec2<usize>>,
    pub frames: Option<String>,
}

/// A file name in the job as a path: relative ones are relative to the job
/// file's folder, so a shot's job file travels with it.
fn beside(job: &Path, file: &str) -> String {
    match job.parent() {
        Some(dir) if Path::new(file).is_relative() => dir.join(file).to_string_lossy().into_owned(),
        _ => file.to_string(),
    }
}

/// Where in the job file something is, for messages: "job.toml:12".
struct Source<'a> {
    path: &'a Path,
    /// Where each line after the first starts, for finding lines in
    /// logarithmic time (a job can have a hundred thousand nodes).
    line_starts: Vec<usize>,
}

impl<'a> Source<'a> {
    fn new(path: &'a Path, text: &str) -> Self {
        let line_starts = text.match_indices('\n').map(|(i, _)| i + 1).collect();
        Source { path, line_starts }
    }

    fn line(&self, offset: usize) -> usize {
        self.line_starts.partition_point(|&start| start <= offset) + 1
    }

    /// `value` within `bound`, or the error at `span`.
    fn checked<T: Into<f64> + Copy + std::fmt::Display>(
        &self,
        span: Range<usize>,
        bound: &Bound,
        value: T,
    ) -> Result<T> {
        bound.check(value).or_else(|m| self.error(span, m))
    }

    fn error<T>(&self, span: std::ops::Range<usize>, message: impl std::fmt::Display) -> Result<T> {
        Err(Error::usage(format!(
            "{}:{}: {message}",
            self.path.display(),
            self.line(span.start)
        )))
    }
}

pub fn load(path: &Path) -> Result<JobPlan> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| Error::usage(format!("{}: cannot read the job file: {e}", path.display())))?;
    let at = Source::new(path, &text);
    let file: JobFile = toml::from_str(&text).map_err(|e| {
        let line = e.span().map(|s| at.line(s.start)).unwrap_or(0);
        Error::usage(format!("{}:{line}: {}", path.display(), e.message()))
    })?;
    build(&at, file)
}

enum Kind<'a> {
    Read(&'a str),
    Op,
    Write(&'a str),
}

fn kind<'a>(at: &Source, node: &'a Spanned<NodeSpec>) -> Result<Kind<'a>> {
    let spec = node.get_ref();
    match (&spec.read, &spec.op, &spec.write) {
        (Some(file), None, None) => Ok(Kind::Read(file)),
        (None, Some(_), None) => Ok(Kind::Op),
        (None, None, Some(file)) => Ok(Kind::Write(file)),
        _ => at.error(
            node.span(),
            format!(
                "node '{}' needs exactly one of read, op or write",
                spec.name.get_ref()
            ),
        ),
    }
}

fn build(at: &Source, file: JobFile) -> Result<JobPlan> {
    let nodes = &file.node;
    let mut by_name: HashMap<&str, usize> = HashMap::new();
    for (i, node) in nodes.iter().enumerate() {
        let name = &node.get_ref().name;
        if by_name.insert(name.get_ref(), i).is_some() {
            return at.error(
                name.span(),
                format!("a second node named '{}'", name.get_ref()),
            );
        }
    }
    let kinds: Vec<Kind> = nodes.iter().map(|n| kind(at, n)).collect::<Result<_>>()?;
    let writes: Vec<usize> = (0..nodes.len())
        .filter(|&i| matches!(kinds[i], Kind::Write(_)))
        .collect();
    let write = match writes[..] {
        [w] => w,
        [] => {
            return Err(Error::usage(format!(
                "{}: the job has no write node",
                at.path.display()
            )))
        }
        [_, second, ..] => {
            return at.error(
                nodes[second].span(),
                "only one write node per job is supported",
            )
        }
    };
    // Each node's inputs by index, every name checked.
    let mut inputs: Vec<Vec<usize>> = Vec::with_capacity(nodes.len());
    for node in nodes {
        let mut list = Vec::new();
        for input in &node.get_ref().inputs {
            match by_name.get(input.get_ref().as_str()) {
                Some(&i) if matches!(kinds[i], Kind::Write(_)) => {
                    return at.error(
                        input.span(),
                        format!("'{}' is a write node", input.get_ref()),
                    )
                }
                Some(&i) => list.push(i),
                None => {
                    return at.error(input.span(), format!("unknown node '{}'", input.get_ref()))
                }
            }
        }
        inputs.push(list);
    }

    // Every operation checked (op, operator, input count) before the graph is.
    for (n, node) in nodes.iter().enumerate() {
        if matches!(kinds[n], Kind::Op) {
            let _checked = operation(at, node, inputs[n].len())?;
        }
    }
    // Depth first from the write: reads first, then operations so that each
    // comes after its inputs; a node met again while open closes a cycle.
    let mut order: Vec<usize> = Vec::new();
    let mut state = vec![0u8; nodes.len()]; // 0 new, 1 open, 2 done
    let root = match inputs[write][..] {
        [root] => root,
        _ => {
            return at.error(
                nodes[write].span(),
                "the write node needs exactly one input",
            )
        }
    };
    visit(at, nodes, &inputs, root, &mut state, &mut order)?;
    for (i, node) in nodes.iter().enumerate() {
        if i != write && state[i] == 0 {
            return at.error(
                node.span(),
                format!(
                    "node '{}' is not used by the write",
                    node.get_ref().name.get_ref()
                ),
            );
        }
    }
    let reads: Vec<usize> = order
        .iter()
        .copied()
        .filter(|&i| matches!(kinds[i], Kind::Read(_)))
        .collect();
    let ops: Vec<usize> = order
        .iter()
        .copied()
        .filter(|&i| matches!(kinds[i], Kind::Op))
        .collect();

    // Graph node of each job node: reads 0..r, then operations (a stack
    // node becomes a chain of merges; its graph node is the last).
    let mut graph_index: HashMap<usize, usize> = HashMap::new();
    for (g, &r) in reads.iter().enumerate() {
        graph_index.insert(r, g);
    }
    let mut graph_ops: Vec<(Box<dyn Op>, Vec<usize>)> = Vec::new();
    for &n in &ops {
        let args: Vec<usize> = inputs[n].iter().map(|i| graph_index[i]).collect();
        let place = format!(
            "{}:{} (node '{}')",
            at.path.display(),
            at.line(nodes[n].span().start),
            nodes[n].get_ref().name.get_ref()
        );
        let located = |op: Box<dyn Op>| -> Box<dyn Op> {
            Box::new(Located {
                op,
                at: place.clone(),
            })
        };
        match operation(at, &nodes[n], args.len())? {
            Recipe::One(make) => graph_ops.push((located(make()), args)),
            Recipe::Stack(make) => {
                push_stack(&mut graph_ops, reads.len(), &args, || located(make()))
            }
            Recipe::Diffrender(gain, shadow_only) => {
                let [object, proxy, shadowed, plate] = args[..] else {
                    unreachable!("checked: four inputs")
                };
                let mut steps = Vec::new();
                let base = reads.len() + graph_ops.len();
                diffrender::push_steps(
                    &mut steps,
                    base,
                    [object, proxy, shadowed, plate],
                    gain,
                    shadow_only,
                );
                graph_ops.extend(steps.into_iter().map(|(op, inputs)| (located(op), inputs)));
            }
            Recipe::Blur(filter, radius, layers) => {
                let next = reads.len() + graph_ops.len();
                for (op, inputs) in blur::passes(filter, radius, &layers, args[0], next) {
                    graph_ops.push((located(op), inputs));
                }
            }
        }
        graph_index.insert(n, reads.len() + graph_ops.len() - 1);
    }
    if ops.is_empty() && reads.len() != 1 {
        return at.error(
            nodes[write].span(),
            "a write of a read needs that read alone",
        );
    }

    // The header comes from the bottom-most input: follow the last input.
    let mut source = root;
    while let Some(&last) = inputs[source].last() {
        source = last;
    }
    let Kind::Write(output) = kinds[write] else {
        unreachable!("write is a write node")
    };
    Ok(JobPlan {
        reads: reads
            .iter()
            .map(|&r| {
                let Kind::Read(file) = kinds[r] else {
                    unreachable!("reads are read nodes")
                };
                (beside(at.path, file), nodes[r].get_ref().part.clone())
            })
            .collect(),
        header_from: reads.iter().position(|&r| r == source).unwrap_or(0),
        graph: Graph::chain(reads.len(), graph_ops),
        output: beside(at.path, output),
        compression: nodes[write].get_ref().compression.clone(),
        all_parts: nodes[write].get_ref().all_parts.unwrap_or(false),
        tile: match &nodes[write].get_ref().tile {
            Some(tile) => Some(parse_tile(tile.get_ref()).or_else(|m| at.error(tile.span(), m))?),
            None => None,
        },
        frames: file.frames,
    })
}

/// Depth first from `root`, with an explicit stack (a chain of a hundred
/// thousand nodes must not overflow the call stack): each node is pushed to
/// `order` after its inputs; a node met again while open closes a cycle.
fn visit(
    at: &Source,
    nodes: &[Spanned<NodeSpec>],
    inputs: &[Vec<usize>],
    root: usize,
    state: &mut [u8],
    order: &mut Vec<usize>,
) -> Result<()> {
    // (node, how many of its inputs have been visited)
    let mut stack = vec![(root, 0)];
    state[root] = 1;
    while let Some((n, next)) = stack.last_mut() {
        let n = *n;
        let Some(&i) = inputs[n].get(*next) else {
            state[n] = 2;
            order.push(n);
            stack.pop();
            continue;
        };
        *next += 1;
        match state[i] {
            0 => {
                state[i] = 1;
                stack.push((i, 0));
            }
            1 => {
                return at.error(
                    nodes[i].span(),
                    format!(
                        "node '{}' is part of a cycle",
                        nodes[i].get_ref().name.get_ref()
                    ),
                )
            }
            _ => {}
        }
    }
    Ok(())
}

type Make = Box<dyn Fn() -> Box<dyn Op>>;

/// A recipe of one operation, made by `make` for each graph node.
fn one<O: Op + 'static>(make: impl Fn() -> O + 'static) -> Recipe {
    Recipe::One(Box::new(move || Box::new(make())))
}

/// How an op node becomes graph operations.
enum Recipe {
    One(Make),
    /// `over` merges, bottom up.
    Stack(Make),
    /// The two passes of a blur.
    Blur(Filter, usize, Selection),
    /// Differential rendering's merges and shadow steps: gain, shadow only.
    Diffrender(f32, bool),
}

/// Op node `node`'s recipe, given its input count, every parameter checked.
fn operation(at: &Source, node: &Spanned<NodeSpec>, count: usize) -> Result<Recipe> {
    let spec = node.get_ref();
    let op = spec.op.as_ref().expect("an op node");
    let layers = Selection {
        layers: spec.layers.clone().unwrap_or_default(),
        all: spec.all_layers.unwrap_or(false),
        view: spec.view.clone(),
    };
    let straight = spec.straight.unwrap_or(false);
    // The command line's bounds, one rule for both (crate::params).
    let number = |bound: &Bound, value| at.checked(node.span(), bound, value);
    let want = |counts: std::ops::RangeInclusive<usize>, what: &str| -> Result<()> {
        if counts.contains(&count) {
            Ok(())
        } else {
            at.error(
                node.span(),
                format!("op '{}' takes {what}, not {count}", op.get_ref()),
            )
        }
    };
    let selection = layers.clone();
    let merge = move |op: MergeOp, mix: f32| -> Make {
        let layers = selection.clone();
        Box::new(move || {
            Box::new(Merge {
                op,
                straight,
                mix,
                layers: layers.clone(),
            })
        })
    };
    Ok(match op.get_ref().as_str() {
        "merge" | "over" => {
            want(2..=2, "two inputs (A, B)")?;
            let operator = match (&spec.operator, op.get_ref().as_str()) {
                (None, "over") => MergeOp::Over,
                (None, _) => return at.error(node.span(), "op 'merge' needs an operator"),
                (Some(name), _) => MergeOp::from_str(name.get_ref(), true).or_else(|_| {
                    at.error(
                        name.span(),
                        format!("unknown operator '{}'", name.get_ref()),
                    )
                })?,
            };
            Recipe::One(merge(operator, number(&MIX, spec.mix.unwrap_or(1.0))?))
        }
        "stack" => {
            want(2..=usize::MAX, "two or more inputs")?;
            Recipe::Stack(merge(MergeOp::Over, 1.0))
        }
        "blur" => {
            want(1..=1, "one input")?;
            let filter = match &spec.filter {
                None => Filter::Gaussian,
                Some(name) => Filter::from_str(name.get_ref(), true).or_else(|_| {
                    at.error(name.span(), format!("unknown filter '{}'", name.get_ref()))
                })?,
            };
            let Some(radius) = spec.radius else {
                return at.error(node.span(), "op 'blur' needs a radius");
            };
            Recipe::Blur(
                filter,
                at.checked(node.span(), &BLUR_RADIUS, radius)? as usize,
                layers,
            )
        }
        "premult" | "unpremult" => {
            want(1..=1, "one input")?;
            let inverse = op.get_ref() == "unpremult";
            one(move || Premult {
                inverse,
                layers: layers.clone(),
            })
        }
        "defocus" => {
            want(1..=1, "one input")?;
            let aperture = match &spec.aperture {
                None => Aperture::Disc,
                Some(text) => {
                    Aperture::parse(text.get_ref()).or_else(|m| at.error(text.span(), m))?
                }
            };
            let (Some(focus), Some(scale), Some(max_radius)) =
                (spec.focus, spec.scale, spec.max_radius)
            else {
                return at.error(
                    node.span(),
                    "op 'defocus' needs focus, scale and max_radius",
                );
            };
            let (focus, scale) = (number(&FOCUS, focus)?, number(&DEFOCUS_SCALE, scale)?);
            let max_radius = at.checked(node.span(), &MAX_RADIUS, max_radius)?;
            let z_channel = spec.z_channel.clone().unwrap_or_else(|| "Z".into());
            one(move || Defocus {
                focus,
                scale,
                max_radius: max_radius as usize,
                aperture,
                z_channel: z_channel.clone(),
                layers: layers.clone(),
            })
        }
        "vblur" => {
            want(1..=1, "one input")?;
            // A job's input can be any node: no first pass, the reach is given.
            let Some(reach) = spec.max_displacement else {
                return at.error(
                    node.span(),
                    "op 'vblur' needs max_displacement in a job file",
                );
            };
            let vectors = match &spec.vectors {
                None => ["forward.u".to_string(), "forward.v".to_string()],
                Some(v) => match &v.get_ref()[..] {
                    [x, y] => [x.clone(), y.clone()],
                    _ => {
                        return at.error(v.span(), "vectors are two channel names: [\"u\", \"v\"]")
                    }
                },
            };
            let scale = number(&VBLUR_SCALE, spec.scale.unwrap_or(1.0))?;
            let reach = at.checked(node.span(), &MAX_DISPLACEMENT, reach)?;
            one(move || VectorBlur {
                scale,
                vectors: vectors.clone(),
                reach: reach as usize,
                layers: layers.clone(),
            })
        }
        "stereo" => {
            want(1..=1, "one input")?;
            let (Some(eye), Some(disparity)) = (&spec.eye, spec.disparity) else {
                return at.error(node.span(), "op 'stereo' needs eye and disparity");
            };
            let eye = Eye::from_str(eye.get_ref(), true).or_else(|_| {
                at.error(
                    eye.span(),
                    format!("eye is left or right, not '{}'", eye.get_ref()),
                )
            })?;
            let disparity = number(&DISPARITY, disparity)?;
            let z_channel = spec.z_channel.clone().unwrap_or_else(|| "Z".into());
            one(move || Stereo {
                eye,
                disparity,
                z_channel: z_channel.clone(),
            })
        }
        "key" => {
            want(1..=1, "one input")?;
            let screen = match &spec.screen {
                None => [0.0, 1.0, 0.0],
                Some(text) => parse_screen(text.get_ref()).or_else(|m| at.error(text.span(), m))?,
            };
            let clip = (
                number(&CLIP, spec.clip_black.unwrap_or(0.0))?,
                number(&CLIP, spec.clip_white.unwrap_or(1.0))?,
            );
            if clip.1 <= clip.0 {
                return at.error(node.span(), "clip_white must be above clip_black");
            }
            let gain = number(&GAIN, spec.gain.unwrap_or(1.0))?;
            let balance = number(&BALANCE, spec.balance.unwrap_or(0.5))?;
            let (despill, invert) = (spec.despill.unwrap_or(false), spec.invert.unwrap_or(false));
            one(move || {
                Matte(Pull::Key(Key {
                    screen,
                    gain,
                    balance,
                    clip,
                    despill,
                    invert,
                }))
            })
        }
        "diffmatte" => {
            want(2..=2, "two inputs (footage, clean plate)")?;
            let threshold = number(&THRESHOLD, spec.threshold.unwrap_or(0.05))?;
            let softness = number(&SOFTNESS, spec.softness.unwrap_or(0.1))?;
            let invert = spec.invert.unwrap_or(false);
            one(move || {
                Matte(Pull::Difference(DiffMatte {
                    threshold,
                    softness,
                    invert,
                }))
            })
        }
        "triangulate" => {
            want(
                4..=4,
                "four inputs (over A, background A, over B, background B)",
            )?;
            one(|| Matte(Pull::Triangulation))
        }
        "erode" | "dilate" => {
            want(1..=1, "one input")?;
            let Some(radius) = spec.radius else {
                return at.error(node.span(), format!("op '{}' needs a radius", op.get_ref()));
            };
            let radius = at.checked(node.span(), &MORPH_RADIUS, radius)? as usize;
            let (dilate, invert) = (op.get_ref() == "dilate", spec.invert.unwrap_or(false));
            one(move || Morphology {
                radius,
                dilate,
                invert,
                layers: layers.clone(),
            })
        }
        "zmerge" => {
            want(2..=usize::MAX, "two or more inputs")?;
            let z_channel = spec.z_channel.clone().unwrap_or_else(|| "Z".into());
            one(move || ZMerge {
                z_channel: z_channel.clone(),
            })
        }
        "diffrender" => {
            want(4..=4, "four inputs (object, proxy, with_shadows, plate)")?;
            Recipe::Diffrender(
                number(&SHADOW_GAIN, spec.shadow_gain.unwrap_or(1.0))?,
                spec.shadow_only.unwrap_or(false),
            )
        }
        other => return at.error(op.span(), format!("unknown op '{other}'")),
    })
}

/// An operation that names its job-file node in its errors.
struct Located {
    op: Box<dyn Op>,
    at: String,
}

impl Op for Located {
    fn halo(&self) -> usize {
        self.op.halo()
    }
    fn channels(&self, inputs: &[&[ChannelDescription]]) -> Vec<ChannelDescription> {
        self.op.channels(inputs)
    }
    fn check(&self, inputs: &[&[ChannelDescription]]) -> std::result::Result<(), String> {
        self.op
            .check(inputs)
            .map_err(|m| format!("{}: {m}", self.at))
    }
    fn data_window(&self, inputs: &[IntegerBounds]) -> IntegerBounds {
        self.op.data_window(inputs)
    }
    fn passes_second(&self) -> bool {
        self.op.passes_second()
    }
    fn hides_nothing(&self, first: &Rows, second: &[ChannelDescription], rows: Range<i32>) -> bool {
        self.op.hides_nothing(first, second, rows)
    }
    fn compute(
        &self,
        frame: i64,
        inputs: &[&Rows],
        out: &mut RowsMut,
    ) -> std::result::Result<(), String> {
        self.op.compute(frame, inputs, out)
    }
}
