//! Job files (`exrcomp run JOB.toml`): a graph of read, operation and write
//! nodes, checked with errors that name the file's line, then built into one
//! streaming `Graph`. The format: specs/job-format.md.

use crate::engine::graph::{Graph, GraphBuilder, NodeId};
use crate::error::{Error, Result};
use crate::io::attributes::Edit;
use crate::io::sequence::{split_time, InputTime};
use crate::ops::declare::{Args, Measured, Operation, REPEATED};
use crate::ops::layers::Selection;
use crate::run::settings::{RunArgs, WriteArgs};
use clap::{Args as _, FromArgMatches as _};
use serde::Deserialize;
use std::collections::{BTreeMap, HashMap};
use std::path::Path;
use toml::{Spanned, Value};

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct JobToml {
    /// Frames, as `--frames` takes them; `--frames` wins.
    frames: Option<String>,
    #[serde(default)]
    node: Vec<Spanned<Table>>,
}

/// A `[[node]]` table, each key and value with where it is.
type Table = BTreeMap<Spanned<String>, Spanned<Value>>;

/// The keys every node or kind of node takes besides an operation's own.
pub const NODE_KEYS: &[&str] = &["name", "inputs"];
pub const READ_KEYS: &[&str] = &["read", "part", "offset", "hold"];
pub const LAYER_KEYS: &[&str] = &["layers", "all_layers", "view"];

/// A job file turned into what the engine runs.
pub struct JobFileContents {
    /// Per read node, in graph order: the file pattern (with its `offset`
    /// or `hold` as `@TIME`) and the part asked for.
    pub reads: Vec<(String, Option<String>)>,
    pub graph: Graph,
    /// The read whose header the output keeps (following B inputs down).
    pub header_from: usize,
    pub output: String,
    /// The job's frames, as `--frames` takes them (`--frames` wins).
    pub frames: Option<String>,
    /// The write node's keys, as the options of those names take them.
    pub write: WriteArgs,
}

/// What an op node that measures parameters (`from = "auto"`) is measured
/// on: the read whose header reaches it (following last inputs down, as
/// the write's header is found), and the attribute edits of the ops
/// between (`Op::attributes`: an upstream conversion's `colorInteropID`).
pub struct Reaching {
    /// The read's file as the command line names it (with `@TIME`), and
    /// its part.
    pub read: String,
    pub part: Option<String>,
    /// The job's output and frames, as its write node and `frames` say.
    pub output: String,
    pub frames: Option<String>,
    pub edits: Vec<Edit>,
    /// "job.toml:12 (node 'cc')", for its messages.
    pub place: String,
}

/// The first pass that measures an op node's parameters from the read
/// that reaches it (src/run/job_run.rs: `Operation::measure` on a job of
/// that read).
pub type FirstPass<'a> = dyn Fn(&'static Operation, &Args, &Reaching) -> Result<Measured> + 'a;

/// A file name in the job as a path: relative ones are relative to the job
/// file's folder, so a shot's job file travels with it; a URI
/// (`ocio://NAME`) is not a file name.
fn beside(job: &Path, file: &str) -> String {
    match job.parent() {
        Some(dir) if Path::new(file).is_relative() && !file.contains("://") => {
            dir.join(file).to_string_lossy().into_owned()
        }
        _ => file.to_string(),
    }
}

/// Where in the job file something is, for messages: "job.toml:12".
struct Source<'a> {
    path: &'a Path,
    /// `--proxy-scale`: the operations' lengths in pixels scaled by it.
    proxy: Option<f32>,
    /// Where each line after the first starts, for finding lines in
    /// logarithmic time (a job can have a hundred thousand nodes).
    line_starts: Vec<usize>,
}

impl<'a> Source<'a> {
    fn new(path: &'a Path, text: &str) -> Self {
        let line_starts = text.match_indices('\n').map(|(i, _)| i + 1).collect();
        Source {
            path,
            line_starts,
            proxy: None,
        }
    }

    fn line(&self, offset: usize) -> usize {
        self.line_starts.partition_point(|&start| start <= offset) + 1
    }

    fn error<T>(&self, span: std::ops::Range<usize>, message: impl std::fmt::Display) -> Result<T> {
        Err(Error::usage(format!(
            "{}:{}: {message}",
            self.path.display(),
            self.line(span.start)
        )))
    }
}

/// The job file at `path` (or `text`, a job given as text by a front end:
/// `path` then names it in messages, and relative file names start from
/// its folder), its operations' lengths in pixels scaled by `proxy` when it
/// is given, its nodes' measured parameters by `measure`.
pub fn load(
    path: &Path,
    text: Option<&str>,
    proxy: Option<f32>,
    measure: &FirstPass,
) -> Result<JobFileContents> {
    let text = match text {
        Some(text) => text.to_string(),
        None => crate::io::reader::open_regular(path)
            .and_then(std::io::read_to_string)
            .map_err(|e| {
                Error::usage(format!("{}: cannot read the job file: {e}", path.display()))
            })?,
    };
    let at = Source {
        proxy,
        ..Source::new(path, &text)
    };
    let file: JobToml = toml::from_str(&text).map_err(|e| {
        let line = e.span().map(|s| at.line(s.start)).unwrap_or(0);
        Error::usage(format!("{}:{line}: {}", path.display(), e.message()))
    })?;
    let nodes: Vec<Node> = file
        .node
        .iter()
        .map(|n| Node::new(&at, n))
        .collect::<Result<_>>()?;
    build(&at, &nodes, file.frames, measure)
}

enum Kind {
    Read(String),
    Op(&'static Operation),
    Write(String),
}

/// A `[[node]]` with its kind, name and inputs read, and its other keys
/// checked against what that kind takes.
struct Node<'a> {
    name: String,
    kind: Kind,
    inputs: Vec<Spanned<String>>,
    span: std::ops::Range<usize>,
    keys: &'a Table,
}

impl<'a> Node<'a> {
    fn new(at: &Source, table: &'a Spanned<Table>) -> Result<Self> {
        let (keys, span) = (table.get_ref(), table.span());
        let get = |key: &str| {
            keys.iter()
                .find(|(k, _)| k.get_ref() == key)
                .map(|(_, v)| v)
        };
        let text =
            |key: &str| -> Result<Option<String>> { get(key).map(|v| string(at, v)).transpose() };
        let Some(name) = text("name")? else {
            return at.error(span, "a node needs a name");
        };
        let kind = match (text("read")?, get("op"), text("write")?) {
            (Some(file), None, None) => Kind::Read(file),
            (None, Some(op), None) => {
                let op_name = string(at, op)?;
                let Some(found) = crate::ops::find(&op_name) else {
                    let known: Vec<&str> = crate::ops::ALL.iter().map(|o| o.name).collect();
                    return at.error(
                        op.span(),
                        format!("unknown op '{op_name}' (one of: {})", known.join(", ")),
                    );
                };
                Kind::Op(found)
            }
            (None, None, Some(file)) => Kind::Write(file),
            _ => {
                return at.error(
                    span,
                    format!("node '{name}' needs exactly one of read, op or write"),
                )
            }
        };
        let inputs = match get("inputs") {
            None => Vec::new(),
            Some(list) => match list.get_ref() {
                // The items carry no span of their own: the list's.
                Value::Array(items) if items.iter().all(Value::is_str) => items
                    .iter()
                    .filter_map(|v| v.as_str())
                    .map(|n| Spanned::new(list.span(), n.to_string()))
                    .collect(),
                _ => return at.error(list.span(), "inputs is a list of node names"),
            },
        };
        if let (Kind::Read(_), Some(first)) = (&kind, inputs.first()) {
            return at.error(
                first.span(),
                format!("node '{name}' reads a file: a read node takes no inputs"),
            );
        }
        let node = Node {
            name,
            kind,
            inputs,
            span,
            keys,
        };
        node.check_keys(at)?;
        Ok(node)
    }

    /// Every key is one this kind of node takes.
    fn check_keys(&self, at: &Source) -> Result<()> {
        let write_keys = WriteArgs::keys();
        let mut allowed: Vec<&str> = NODE_KEYS.to_vec();
        match self.kind {
            Kind::Read(_) => allowed.extend(READ_KEYS),
            Kind::Write(_) => {
                allowed.push("write");
                allowed.extend(write_keys.iter().map(String::as_str));
            }
            Kind::Op(op) => {
                allowed.push("op");
                allowed.extend(op.params.iter().map(|p| p.name));
                if op.layers {
                    allowed.extend(LAYER_KEYS);
                }
                if op.straight {
                    allowed.push("straight");
                }
            }
        }
        for key in self.keys.keys() {
            let name = key.get_ref().as_str();
            if !allowed.contains(&name) {
                // One suggestion when a key is near; the list only when none is.
                let hint = allowed
                    .iter()
                    .min_by_key(|a| edit_distance(a, name))
                    .filter(|a| edit_distance(a, name) <= 2)
                    .map_or_else(
                        || format!(" (it takes: {})", allowed.join(", ")),
                        |a| format!(": did you mean `{a}`?"),
                    );
                return at.error(
                    key.span(),
                    format!("unknown field `{name}` for node '{}'{hint}", self.name),
                );
            }
        }
        Ok(())
    }

    /// A switch: absent is false.
    fn flag(&self, at: &Source, key: &str) -> Result<bool> {
        match self.get(key) {
            None => Ok(false),
            Some(v) => v
                .get_ref()
                .as_bool()
                .map_or_else(|| at.error(v.span(), format!("{key} is true or false")), Ok),
        }
    }

    fn get(&self, key: &str) -> Option<&'a Spanned<Value>> {
        self.keys
            .iter()
            .find(|(k, _)| k.get_ref() == key)
            .map(|(_, v)| v)
    }

    /// An operation's arguments: each parameter's value as text, checked
    /// (an error at its key's line), and the shared keys.
    fn args(&self, at: &Source, op: &'static Operation) -> Result<Args> {
        let mut values = BTreeMap::new();
        for param in op.params {
            if let Some(value) = self.get(param.name) {
                let text = match param.repeats {
                    true => repeated(value.get_ref()),
                    false => as_text(value.get_ref()),
                };
                let text = text.or_else(|m| at.error(value.span(), m))?;
                (param.check)(&text).or_else(|m| at.error(value.span(), m))?;
                let text = if param.file {
                    beside(at.path, &text)
                } else {
                    text
                };
                values.insert(param.name, text);
            }
        }
        let layers = match self.get("layers") {
            None => Vec::new(),
            Some(v) => match v.get_ref() {
                Value::Array(items) if items.iter().all(Value::is_str) => items
                    .iter()
                    .filter_map(|i| i.as_str().map(String::from))
                    .collect(),
                _ => return at.error(v.span(), "layers is a list of layer names"),
            },
        };
        Ok(Args {
            op: op.name,
            values,
            layers: Selection {
                layers,
                all: self.flag(at, "all_layers")?,
                view: self.get("view").map(|v| string(at, v)).transpose()?,
            },
            straight: self.flag(at, "straight")?,
            job_file: true,
        })
    }

    /// "job.toml:12 (node 'comp')", for errors found when frames are planned.
    fn place(&self, at: &Source) -> String {
        format!(
            "{}:{} (node '{}')",
            at.path.display(),
            at.line(self.span.start),
            self.name
        )
    }
}

/// A read's `part`: a name, or an index as `--part` takes it (`"1"` or 1).
fn part(at: &Source, value: &Spanned<Value>) -> Result<String> {
    match value.get_ref() {
        Value::Integer(index) if *index >= 0 => Ok(index.to_string()),
        Value::String(name) => Ok(name.clone()),
        _ => at.error(value.span(), "part is a part's name or index (0 or more)"),
    }
}

fn string(at: &Source, value: &Spanned<Value>) -> Result<String> {
    match value.get_ref().as_str() {
        Some(text) => Ok(text.to_string()),
        None => at.error(value.span(), "expected a string"),
    }
}

/// A parameter's value as the command line would give it: numbers and
/// switches written out, a list as `A,B`.
fn as_text(value: &Value) -> std::result::Result<String, String> {
    Ok(match value {
        Value::String(text) => text.clone(),
        Value::Integer(n) => n.to_string(),
        Value::Float(x) => x.to_string(),
        Value::Boolean(b) => b.to_string(),
        Value::Array(items) => items
            .iter()
            .map(as_text)
            .collect::<std::result::Result<Vec<_>, _>>()?
            .join(","),
        _ => return Err("expected a string, a number, true or false, or a list".into()),
    })
}

/// A repeated parameter's values (a list of strings, or one) as `Args`
/// holds them: one a line.
fn repeated(value: &Value) -> std::result::Result<String, String> {
    match value {
        Value::String(text) => Ok(text.clone()),
        Value::Array(items) if items.iter().all(Value::is_str) => Ok(items
            .iter()
            .filter_map(Value::as_str)
            .collect::<Vec<_>>()
            .join(&REPEATED.to_string())),
        _ => Err("expected a string or a list of strings".into()),
    }
}

/// Levenshtein distance, for "did you mean".
fn edit_distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut diagonal = row[0];
        row[0] = i + 1;
        for (j, &cb) in b.iter().enumerate() {
            let next = (diagonal + usize::from(ca != cb))
                .min(row[j] + 1)
                .min(row[j + 1] + 1);
            diagonal = row[j + 1];
            row[j + 1] = next;
        }
    }
    row[b.len()]
}

/// The job's one write node and each node's inputs by index, every name
/// checked.
fn links(at: &Source, nodes: &[Node]) -> Result<(usize, Vec<Vec<usize>>)> {
    let mut by_name: HashMap<&str, usize> = HashMap::new();
    for (i, node) in nodes.iter().enumerate() {
        if by_name.insert(&node.name, i).is_some() {
            return at.error(
                node.span.clone(),
                format!("a second node named '{}'", node.name),
            );
        }
    }
    let writes: Vec<usize> = (0..nodes.len())
        .filter(|&i| matches!(nodes[i].kind, Kind::Write(_)))
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
                nodes[second].span.clone(),
                "only one write node per job is supported",
            )
        }
    };
    // Each node's inputs by index, every name checked.
    let mut inputs: Vec<Vec<usize>> = Vec::with_capacity(nodes.len());
    for node in nodes {
        let mut list = Vec::new();
        for input in &node.inputs {
            match by_name.get(input.get_ref().as_str()) {
                Some(&i) if matches!(nodes[i].kind, Kind::Write(_)) => {
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

    Ok((write, inputs))
}

fn build(
    at: &Source,
    nodes: &[Node],
    frames: Option<String>,
    measure: &FirstPass,
) -> Result<JobFileContents> {
    let (write, inputs) = links(at, nodes)?;

    // Every operation checked (parameters, input count) before the graph is:
    // built once on inputs of its own (those that measure, their parameters
    // only: they are built when the files have been read).
    for (n, node) in nodes.iter().enumerate() {
        match node.kind {
            Kind::Op(op) if op.measure.is_none() => {
                let (mut scratch, ids) = GraphBuilder::with_inputs(inputs[n].len());
                operation(at, node, op, &mut scratch, &ids, Vec::new())?;
            }
            Kind::Op(op) => {
                node.args(at, op)?;
            }
            _ => {}
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
                nodes[write].span.clone(),
                "the write node needs exactly one input",
            )
        }
    };
    visit(at, nodes, &inputs, root, &mut state, &mut order)?;
    for (i, node) in nodes.iter().enumerate() {
        if i != write && state[i] == 0 {
            return at.error(
                node.span.clone(),
                format!("node '{}' is not used by the write", node.name),
            );
        }
    }
    let reads: Vec<usize> = order
        .iter()
        .copied()
        .filter(|&i| matches!(nodes[i].kind, Kind::Read(_)))
        .collect();

    // The reads are the graph's inputs 0..r, then each operation's nodes.
    let mut graph = GraphBuilder::default();
    let mut built: HashMap<usize, NodeId> = HashMap::new();
    for (g, &r) in reads.iter().enumerate() {
        built.insert(r, graph.input(g));
    }
    let Kind::Write(output) = &nodes[write].kind else {
        unreachable!("write is a write node")
    };
    for &n in &order {
        if let Kind::Op(op) = nodes[n].kind {
            let args: Vec<NodeId> = inputs[n].iter().map(|i| built[i]).collect();
            // Measured on the header the node's input brings (none: the
            // op's own error, of its input count, follows).
            // Followed down only for ops that measure: a chain of a hundred
            // thousand premults must not walk it at each node.
            let read = match op.measure {
                Some(_) => header_source(&inputs, n),
                None => n,
            };
            let measured = match (op.measure, args.last(), &nodes[read].kind) {
                (Some(_), Some(&last), Kind::Read(_)) => {
                    let input = reads.iter().position(|&r| r == read).unwrap_or(0);
                    let reaching = Reaching {
                        output: beside(at.path, output),
                        frames: frames.clone(),
                        edits: graph.edits(input, last),
                        place: nodes[n].place(at),
                        ..read_of(at, &nodes[read])?
                    };
                    measure(op, &nodes[n].args(at, op)?, &reaching)?.values
                }
                _ => Vec::new(),
            };
            graph.locate(Some(nodes[n].place(at)));
            let id = operation(at, &nodes[n], op, &mut graph, &args, measured)?;
            built.insert(n, id);
        }
    }
    if built.len() == reads.len() && reads.len() != 1 {
        return at.error(
            nodes[write].span.clone(),
            "a write of a read needs that read alone",
        );
    }

    // The header comes from the bottom-most input: follow the last input.
    let source = header_source(&inputs, root);
    let out = &nodes[write];
    Ok(JobFileContents {
        reads: reads
            .iter()
            .map(|&r| read_of(at, &nodes[r]).map(|read| (read.read, read.part)))
            .collect::<Result<_>>()?,
        header_from: reads.iter().position(|&r| r == source).unwrap_or(0),
        graph: graph.finish(),
        output: beside(at.path, output),
        frames,
        write: write_settings(at, out)?,
    })
}

/// The read whose header node `n`'s result keeps: its last input's, down
/// to a read.
fn header_source(inputs: &[Vec<usize>], n: usize) -> usize {
    let mut source = n;
    while let Some(&last) = inputs[source].last() {
        source = last;
    }
    source
}

/// Read node `node`'s file, as the command line names it, and part (the
/// rest of `Reaching` empty).
fn read_of(at: &Source, node: &Node) -> Result<Reaching> {
    let Kind::Read(file) = &node.kind else {
        unreachable!("reads are read nodes")
    };
    Ok(Reaching {
        read: read_file(at, node, beside(at.path, file))?,
        part: node.get("part").map(|v| part(at, v)).transpose()?,
        output: String::new(),
        frames: None,
        edits: Vec::new(),
        place: String::new(),
    })
}

/// The write node's settings: each key parsed as the command-line option
/// of that name parses its value (src/run/settings.rs), so that the two
/// cannot differ; an error names the key's place.
fn write_settings(at: &Source, node: &Node) -> Result<WriteArgs> {
    let mut words = Vec::new();
    for (key, value) in node.keys {
        let key = key.get_ref();
        if key == "write" || NODE_KEYS.contains(&key.as_str()) {
            continue;
        }
        let option = format!("--{}", key.replace('_', "-"));
        let given = match value.get_ref() {
            Value::Boolean(true) => vec![option],
            Value::Boolean(false) => Vec::new(),
            Value::Array(items) => items
                .iter()
                .map(|item| as_text(item).map(|text| format!("{option}={text}")))
                .collect::<std::result::Result<_, _>>()
                .or_else(|m| at.error(value.span(), m))?,
            other => {
                let text = as_text(other).or_else(|m| at.error(value.span(), m))?;
                vec![format!("{option}={text}")]
            }
        };
        // Each key alone first, so that its error names its place (and the
        // key, where clap's reason does not).
        write_matches(&given).or_else(|m| match m.contains(key.as_str()) {
            true => at.error(value.span(), m),
            false => at.error(value.span(), format!("{key}: {m}")),
        })?;
        words.extend(given);
    }
    let matches = write_matches(&words).or_else(|m| at.error(node.span.clone(), m))?;
    let run = RunArgs::from_arg_matches(&matches).map_err(|e| Error::usage(e.to_string()))?;
    Ok(run.write)
}

/// `words` parsed as the run options of a command line, or clap's reason.
fn write_matches(words: &[String]) -> std::result::Result<clap::ArgMatches, String> {
    RunArgs::augment_args(clap::Command::new("write").no_binary_name(true))
        .try_get_matches_from(words)
        .map_err(|e| {
            use std::error::Error as _;
            match e.source() {
                Some(reason) => reason.to_string(),
                None => e
                    .to_string()
                    .lines()
                    .next()
                    .unwrap_or_default()
                    .trim_start_matches("error: ")
                    .to_string(),
            }
        })
}

/// A read node's file with its `offset` or `hold` key as the `@TIME` the
/// command line writes after a file name (one of the three ways only).
fn read_file(at: &Source, node: &Node, file: String) -> Result<String> {
    let time = match (node.get("offset"), node.get("hold")) {
        (None, None) => return Ok(file),
        (Some(_), Some(hold)) => {
            return at.error(hold.span(), "a read takes offset or hold, not both")
        }
        (Some(offset), None) => match offset.get_ref().as_integer() {
            Some(n) => InputTime::parse(&format!("{n:+}")),
            None => Err("offset is a number of frames (offset = 10)".to_string()),
        }
        .or_else(|m| at.error(offset.span(), m))?,
        (None, Some(hold)) => match hold.get_ref() {
            Value::Boolean(true) => InputTime::Hold(None),
            Value::Integer(f) => {
                InputTime::parse(&f.to_string()).or_else(|m| at.error(hold.span(), m))?
            }
            _ => {
                return at.error(
                    hold.span(),
                    "hold is true (the first frame on disk) or a frame number (hold = 1001)",
                )
            }
        },
    };
    let key = node
        .get("offset")
        .or(node.get("hold"))
        .expect("one is given");
    match split_time(&file) {
        Ok((_, InputTime::Offset(0))) => Ok(format!("{file}{}", time.suffix())),
        _ => at.error(
            key.span(),
            format!("'{file}' gives its frames with @ already: give offset/hold or @, not both"),
        ),
    }
}

/// Op node `node`'s nodes added to `graph` on `inputs`, its input count
/// and every parameter checked, with the values `measured` for it.
fn operation(
    at: &Source,
    node: &Node,
    op: &'static Operation,
    graph: &mut GraphBuilder,
    inputs: &[NodeId],
    measured: Vec<(&'static str, String)>,
) -> Result<NodeId> {
    if !op.takes(inputs.len()) {
        return at.error(
            node.span.clone(),
            format!(
                "op '{}' takes {}, not {}",
                op.name,
                op.arity(),
                inputs.len()
            ),
        );
    }
    let mut args = node.args(at, op)?;
    args.values.extend(measured);
    if let Some(factor) = at.proxy {
        op.scale_lengths(&mut args, factor as f64)
            .or_else(|m| at.error(node.span.clone(), format!("--proxy-scale: {m}")))?;
    }
    (op.build)(&args, graph, inputs).or_else(|m| at.error(node.span.clone(), m))
}

/// Depth first from `root`, with an explicit stack (a chain of a hundred
/// thousand nodes must not overflow the call stack): each node is pushed to
/// `order` after its inputs; a node met again while open closes a cycle.
fn visit(
    at: &Source,
    nodes: &[Node],
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
                    nodes[i].span.clone(),
                    format!("node '{}' is part of a cycle", nodes[i].name),
                )
            }
            _ => {}
        }
    }
    Ok(())
}
