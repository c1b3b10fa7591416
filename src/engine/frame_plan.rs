//! What one frame of a job needs: its open inputs, each node's channels and
//! data window, the output header, and the strip height.

use super::deep_input::DeepInput;
use super::fingerprint;
use super::graph::{grow, intersection, union, Display, Graph, Node};
use super::luminance_chroma;
use super::plan::{FrameSources, HeaderBase, Job, OutputBlocks, Review, Source, MAX_STRIP_BYTES};
use super::region::Regions;
use crate::error::{Error, Kind, Result};
use crate::io::header_text::box_text;
use crate::io::limits::MAX_BLOCK_BYTES;
use crate::io::parts::choose_part;
use crate::io::reader::ExrFile;
use crate::io::tiles::{self, Level};
use crate::io::writer::Parts;
use exr::math::RoundingMode;
use exr::math::Vec2;
use exr::meta::attribute::Text;
use exr::meta::attribute::{
    ChannelDescription, IntegerBounds, LevelMode, LineOrder, TileDescription,
};
use exr::meta::header::{Header, LayerAttributes};
use exr::meta::{compute_chunk_count, BlockDescription};
use std::path::PathBuf;
use std::sync::Arc;

/// Raw output bytes a strip aims for: big enough to amortise per-strip work
/// (each stage thread's hand-over and call into the pool: at 1 MiB about 3%
/// of a 4K frame's CPU, 1.5% at this size), small enough that the strips in
/// flight stay a few megabytes.
const STRIP_BYTES: usize = 2 << 20;

/// Bytes a strip may hold, every node's rows and the inputs' decoded chunks
/// together, before it is cut to fewer blocks (none under one).
const HELD_BYTES: usize = 32 << 20;

/// Most chunks an output may have. Its offset table, 8 bytes a chunk, is
/// held in memory while it is written: 64 MiB at this limit, 8 million rows
/// of ZIPS, 134 million of ZIP. A result that tall comes only of inputs far
/// apart (or a damaged header), and would write gigabytes of nothing.
pub const MAX_OUTPUT_CHUNKS: usize = 8 << 20;

pub struct FramePlan {
    pub frame: i64,
    pub label: Option<i64>,
    pub output: PathBuf,
    pub inputs: Vec<Arc<ExrFile>>,
    /// Per input, the part read.
    pub parts: Vec<usize>,
    /// Per input, the level of that part read (a scanline part's only one).
    pub levels: Vec<Level>,
    /// Per deep input, what flattens it as it is read.
    pub deep: Vec<Option<Arc<DeepInput>>>,
    /// Per input, the data window read (empty for a black input); `windows`
    /// is per graph node, whose indices are not the inputs' once converting
    /// nodes are inserted.
    pub read: Vec<IntegerBounds>,
    pub header: Header,
    /// Per node: channels and data window.
    pub channels: Vec<Vec<ChannelDescription>>,
    pub windows: Vec<IntegerBounds>,
    pub strip_rows: usize,
    /// The rows computed: the whole output window, or for a band the band
    /// and the halo rows around it, on the output's block grid.
    pub computed: IntegerBounds,
    /// The rows and columns each node streams in (`region.rs`).
    pub regions: Regions,
    /// The input whose other parts the output keeps, their chunks copied as
    /// they are: the header's input when it has several parts.
    pub carried: Option<usize>,
    /// With `carried`, that input's part headers with the user's attribute
    /// edits (`--attrib`... apply to every part written).
    pub carried_headers: Vec<Header>,
    /// With `--all-parts`, on the first part's plan: every part's output
    /// header, each part planned and streamed in turn (`plan_parts`).
    pub every_part: Option<Vec<Header>>,
    /// What made the frame (`fingerprint.rs`), written into every part.
    pub fingerprint: String,
    /// With `--all-parts`, why the operations cannot apply to this part (a
    /// blur of a part without colour): it is streamed through an identity
    /// graph instead, unchanged, as a part not worked on is.
    pub carried_as_is: Option<Error>,
}

impl FramePlan {
    /// The burn-in of this frame of `review`, its fields filled and placed.
    pub fn label(&self, review: &Review) -> Option<crate::io::burn_in::Label> {
        let burn_in = review.burn_in.as_ref()?;
        let fields = crate::io::burn_in::Fields {
            frame: self.frame,
            header: &self.header,
            file: self.inputs.first().map(|f| f.path.as_path()),
            output: &self.output,
        };
        let size = self.header.data_window().size;
        Some(burn_in.label(burn_in.text(&fields), (size.width(), size.height())))
    }

    /// The graph this plan streams: the job's, or for a part carried as it
    /// is, an identity.
    pub fn graph<'a>(&self, job: &'a Job) -> &'a Graph {
        static IDENTITY: std::sync::OnceLock<Graph> = std::sync::OnceLock::new();
        match self.carried_as_is {
            Some(_) => IDENTITY.get_or_init(Graph::identity),
            None => &job.graph,
        }
    }

    /// The parts to write: the header's input's parts with the written part
    /// in its place, or the written part alone.
    pub fn output_parts(&self) -> Parts<'_> {
        if let Some(headers) = &self.every_part {
            return Parts {
                headers: headers.clone(),
                streamed: (0..headers.len()).collect(),
                carried: None,
            };
        }
        match self.carried {
            Some(i) => {
                let mut headers = self.carried_headers.clone();
                headers[self.parts[i]] = self.header.clone();
                Parts {
                    headers,
                    streamed: vec![self.parts[i]],
                    carried: Some(&self.inputs[i]),
                }
            }
            None => Parts::single(self.header.clone()),
        }
    }

    /// The window written (the band's, when there is one).
    pub fn window(&self) -> IntegerBounds {
        self.header.data_window()
    }

    /// The header of input `i`'s part read.
    pub fn header_of(&self, i: usize) -> &Header {
        self.inputs[i].header(self.parts[i])
    }

    pub fn pixels(&self) -> usize {
        self.window().size.area()
    }

    /// Per input, the rows decode has read of it once a strip ending at
    /// output row `end` is read: the rows down to `end`, but behind a resize
    /// or transform its region's span of them (every row of its region with
    /// the last strip); decode reads them from the top, or from the bottom
    /// for a zone read bottom-up (`Regions::upward`).
    pub fn input_spans(&self, graph: &Graph, end: i32) -> Vec<std::ops::Range<i32>> {
        let last = end >= self.computed.end().y();
        let spans = (!self.regions.shared() && !last)
            .then(|| self.regions.spans(graph, self.computed.position.y()..end));
        let top = self.computed.position.y();
        (0..self.inputs.len())
            .map(|i| match (graph.input_node(i), &spans) {
                (Some(n), _) if last => {
                    let rect = self.regions.rect(n);
                    rect.position.y()..rect.end().y()
                }
                (Some(n), Some(spans)) => self.regions.span(spans, n).clone(),
                _ => top..end,
            })
            .collect()
    }

    /// The row ranges of the strips, top to bottom.
    pub fn strips(&self) -> impl Iterator<Item = std::ops::Range<i32>> {
        let (top, bottom) = (self.computed.position.y(), self.computed.end().y());
        let step = self.strip_rows as i32;
        (top..bottom)
            .step_by(self.strip_rows)
            .map(move |y| y..(y + step).min(bottom))
    }
}

/// The plans of `sources.frame`: one, or with `--all-parts` one per part of
/// the input, in part order, the first holding every part's header. A part
/// that cannot be planned is an error naming it.
pub fn plan_parts(job: &Job, sources: &FrameSources) -> Result<Vec<FramePlan>> {
    if !job.all_parts {
        return Ok(vec![plan_frame(job, sources, None, &job.graph)?]);
    }
    // Opened once, for every part's plan.
    let file = job.input_file(0, sources)?;
    let headers = &file.meta.headers;
    let mut plans = (0..headers.len())
        .map(|part| {
            let forced = Forced { part, file: &file };
            let plan = plan_frame(job, sources, Some(forced), &job.graph);
            plan.map_err(|e| in_part(e, part, &headers[part]))
        })
        .collect::<Result<Vec<_>>>()?;
    // A part carried as it is keeps its display window: refused where the
    // others' change (a resize, `--proxy-scale`), as OpenEXR's parts share one.
    let display = |p: &FramePlan| p.header.shared_attributes.display_window;
    if let Some(p) = plans.iter().position(|p| p.carried_as_is.is_some()) {
        if plans
            .iter()
            .any(|other| display(other) != display(&plans[p]))
        {
            let refusal = plans.swap_remove(p).carried_as_is.expect("carried");
            return Err(in_part(refusal, p, &headers[p]));
        }
    }
    plans[0].every_part = Some(plans.iter().map(|p| p.header.clone()).collect());
    Ok(plans)
}

/// `error` of `--all-parts` on `part`, naming the part.
fn in_part(error: Error, part: usize, header: &Header) -> Error {
    let name = header
        .own_attributes
        .layer_name
        .as_ref()
        .map(|n| format!(" ('{n}')"))
        .unwrap_or_default();
    Error::new(error.kind, format!("part {part}{name}: {}", error.message))
}

/// With `--all-parts`, the part of input 0 a plan reads, and that input's
/// file, opened once for every part.
#[derive(Clone, Copy)]
struct Forced<'f> {
    part: usize,
    file: &'f Arc<ExrFile>,
}

/// Opens the inputs of `sources.frame` and plans its output through
/// `graph`; `part` forces the part of input 0 read (`--all-parts`), and a
/// part an operation refuses is then carried as it is (`carry_as_is`).
/// The steps, each a function below, in the order their refusals come.
fn plan_frame(
    job: &Job,
    sources: &FrameSources,
    part: Option<Forced>,
    graph: &Graph,
) -> Result<FramePlan> {
    let frame = sources.frame;
    let opened = Opened::open(job, sources, part)?;
    check_luminance(job, &opened, graph)?;
    let channels = node_channels(&opened, graph);
    if let Some(refusal) = refusal(&opened, graph, &channels) {
        return match part {
            Some(_) => carry_as_is(job, sources, part, refusal),
            None => Err(refusal),
        };
    }
    check_subsampled_nodes(&opened, graph, &channels)?;
    let geometry = Geometry::of(job, &opened, graph)?;
    let window = geometry.window;
    let (mut header, fingerprint) = output_header(job, &opened, graph, &channels, &geometry)?;
    let (carried, carried_headers) = carried_parts(job, &opened, &mut header, &fingerprint)?;
    check_layout(job, &opened, &header, carried)?;
    // The output's block rows: scanline blocks, or tile rows.
    let lines = output_grid(&header).block.y();
    let written = match job.rows {
        Some(rows) => band(&mut header, rows, frame)?,
        None => window,
    };
    let computed = computed(written, window, graph, &geometry.windows, lines);
    let block_bytes = check_block_sizes(job, &opened, &header, window, lines)?;
    let regions =
        Regions::new(graph, computed, &geometry.windows).map_err(|m| opened.located(m))?;
    if job.rows.is_some() && !regions.shared() {
        return Err(Error::usage(
            "--rows renders bands of graphs that keep the image's size only: a resize or \
             transform streams its input at another rate",
        ));
    }
    let cost = StripCost::new(&opened, graph, &channels, &regions, computed);
    let strip_rows = strip_rows(job, &opened, &cost, window, lines, block_bytes)?;
    let Opened {
        inputs,
        parts,
        deep,
        levels,
        ..
    } = opened;
    Ok(FramePlan {
        frame,
        label: job.frame_label(frame),
        output: job.output.path(frame),
        inputs,
        parts,
        levels,
        read: geometry.read,
        deep,
        header,
        channels,
        windows: geometry.windows,
        strip_rows,
        computed,
        regions,
        carried,
        carried_headers,
        every_part: None,
        fingerprint,
        carried_as_is: None,
    })
}

/// A frame's inputs, open: per input its file, the part and level read,
/// and what flattens it if it is deep.
struct Opened<'a> {
    frame: i64,
    sources: &'a FrameSources,
    inputs: Vec<Arc<ExrFile>>,
    parts: Vec<usize>,
    deep: Vec<Option<Arc<DeepInput>>>,
    levels: Vec<Level>,
}

impl<'a> Opened<'a> {
    /// Opens each input's frame (`Job::input_file`) and chooses its part
    /// (`forced` for input 0), its deep flattening and its level.
    fn open(job: &Job, sources: &'a FrameSources, forced: Option<Forced>) -> Result<Self> {
        let mut parts = Vec::new();
        let inputs: Vec<Arc<ExrFile>> = (0..job.inputs.len())
            .map(|i| {
                let (file, part) = match forced.filter(|_| i == 0) {
                    Some(Forced { part, file }) => (file.clone(), part),
                    None => {
                        let file = job.input_file(i, sources)?;
                        let part =
                            choose_part(&file, job.parts[i].as_deref(), job.view.as_deref())?;
                        (file, part)
                    }
                };
                file.check_codec(part)?;
                parts.push(part);
                Ok(file)
            })
            .collect::<Result<_>>()?;
        let deep: Vec<Option<Arc<DeepInput>>> = (0..inputs.len())
            .map(|i| deep_input(job, i, sources, &inputs[i], parts[i]))
            .collect::<Result<_>>()?;
        let levels = read_levels(job, &inputs, &parts)?;
        Ok(Opened {
            frame: sources.frame,
            sources,
            inputs,
            parts,
            deep,
            levels,
        })
    }

    fn header_of(&self, i: usize) -> &Header {
        self.inputs[i].header(self.parts[i])
    }

    fn black(&self, i: usize) -> bool {
        matches!(self.sources.inputs[i], Source::Black(_))
    }

    /// The data window read of input `i`. A black input has no data
    /// anywhere: an empty data window.
    fn input_window(&self, i: usize) -> IntegerBounds {
        match (self.sources.inputs[i], &self.deep[i]) {
            (Source::Black(_), _) => IntegerBounds::zero(),
            (_, Some(deep)) => deep.window,
            _ => self.levels[i].window(self.header_of(i)),
        }
    }

    /// An input error naming the frame and every input file.
    fn located(&self, message: String) -> Error {
        let files: Vec<String> = (self.inputs.iter())
            .map(|f| f.path.display().to_string())
            .collect();
        Error::new(
            Kind::Input,
            format!("frame {} ({}): {message}", self.frame, files.join(", ")),
        )
    }

    /// The file the output header comes from, for messages.
    fn header_file(&self, job: &Job) -> Option<&ExrFile> {
        match job.header_base {
            HeaderBase::Input(i) => Some(&self.inputs[i]),
            HeaderBase::New(_) => None,
        }
    }
}

/// The conversion to RGB is set up from the first frame (of each part,
/// with --all-parts: `commands::luminance_inputs`); a later frame that is
/// luminance where it was not would be read as its Y, RY, BY channels.
fn check_luminance(job: &Job, opened: &Opened, graph: &Graph) -> Result<()> {
    let luminance = (0..opened.inputs.len()).find(|&i| {
        opened.deep[i].is_none()
            && luminance_chroma::is_luminance(opened.header_of(i), job.view.as_deref())
            && graph.reads_unconverted(i)
    });
    match luminance {
        Some(i) => Err(opened.inputs[i].error(
            "is luminance-only or luminance/chroma (Y, RY, BY) but the sequence's first frame \
             is RGB, and the operations are set up from the first frame: make the frames alike, \
             or run this frame on its own",
        )),
        None => Ok(()),
    }
}

/// Per graph node, its channels.
fn node_channels(opened: &Opened, graph: &Graph) -> Vec<Vec<ChannelDescription>> {
    graph.evaluate(
        |i| match &opened.deep[i] {
            Some(deep) => deep.channels.clone(),
            None => opened.header_of(i).channels.list.to_vec(),
        },
        |op, args| {
            let lists: Vec<&[ChannelDescription]> = args.iter().map(Vec::as_slice).collect();
            op.channels(&lists)
        },
    )
}

/// The first operation that refuses its inputs' channels (a blur of no
/// colour), located.
fn refusal(opened: &Opened, graph: &Graph, channels: &[Vec<ChannelDescription>]) -> Option<Error> {
    graph.nodes.iter().find_map(|node| {
        let Node::Op {
            op, inputs: args, ..
        } = node
        else {
            return None;
        };
        let lists: Vec<&[ChannelDescription]> =
            args.iter().map(|&n| channels[n].as_slice()).collect();
        let message = op.check(&lists).err()?;
        Some(opened.located(node.locate(message)))
    })
}

/// Subsampled channels are carried, or turned into RGB first
/// (`luminance_chroma`); an operation never reads them as they are.
fn check_subsampled_nodes(
    opened: &Opened,
    graph: &Graph,
    channels: &[Vec<ChannelDescription>],
) -> Result<()> {
    for (n, node) in graph.nodes.iter().enumerate() {
        let subsampled = channels[n].iter().find(|c| c.sampling != Vec2(1, 1));
        if let (Node::Op { .. }, Some(c)) = (node, subsampled) {
            return Err(opened.located(format!(
                "channel {} is subsampled and reaches an operation unconverted: a sequence's \
                 frames must be all luminance/chroma or all RGB, as its first frame decides",
                c.name
            )));
        }
    }
    Ok(())
}

/// Where the frame's pixels are: per input the window read, per node its
/// data window, the output's, and its display window if an op changed it.
struct Geometry {
    read: Vec<IntegerBounds>,
    windows: Vec<IntegerBounds>,
    window: IntegerBounds,
    /// The output's display window and pixel aspect, and whether an
    /// operation changed them.
    display: Display,
    resized: bool,
}

impl Geometry {
    /// The windows, the result's refused where it is empty, beyond OpenEXR's
    /// coordinates or over the output-size limit.
    fn of(job: &Job, opened: &Opened, graph: &Graph) -> Result<Self> {
        let frame = opened.frame;
        let inputs = opened.inputs.len();
        // Display windows first: an op whose geometry follows them (a resize's
        // scale) learns them before it is asked for data windows and regions.
        let displays = graph.display_windows(|i| Display::of(opened.header_of(i)));
        let (display, resized) = displays[graph.output()]
            .clone()
            .map_err(|m| opened.located(m))?;
        let read: Vec<IntegerBounds> = (0..inputs).map(|i| opened.input_window(i)).collect();
        let mut windows = graph.evaluate(|i| read[i], |op, args| op.data_window(args));
        // A result of black inputs alone (`--missing black` on its only input)
        // is a transparent black frame shaped as their nearest frames are, as a
        // missing frame is black over its format in Nuke, not a frame left out.
        if windows[graph.output()].size.area() == 0 && (0..inputs).any(|i| opened.black(i)) {
            let shaped = |i: usize| match opened.black(i) {
                true => opened.levels[i].window(opened.header_of(i)),
                false => read[i],
            };
            windows = graph.evaluate(shaped, |op, args| op.data_window(args));
        }
        let window = windows[graph.output()];
        if window.size.area() == 0 {
            return Err(Error::new(
                Kind::Input,
                format!("frame {frame}: the result's data window is empty (inputs black or not overlapping): nothing to write"),
            ));
        }
        check_coordinates(opened, window)?;
        // Pixels over the limit: a typo's size, refused before anything is sized from it.
        let largest = (0..inputs)
            .map(|i| {
                let display = opened.header_of(i).shared_attributes.display_window;
                read[i].size.area().max(display.size.area()) as u64
            })
            .max();
        // Inputs so far apart that they span it are an input problem, which
        // the limits below (`too_big`) name; an operation's size is a usage error.
        let spread = read.iter().copied().fold(IntegerBounds::zero(), union);
        if let Some(message) = super::output_limit::check(job.max_output_pixels, largest, window)
            .filter(|_| spread.size.area() < window.size.area())
        {
            // Named by the output it would be: the size is the job's, not an input's.
            let output = job.output.path(frame);
            return Err(Error::usage(format!(
                "frame {frame} ({}): {message}",
                output.display()
            )));
        }
        Ok(Geometry {
            read,
            windows,
            window,
            display,
            resized,
        })
    }
}

/// OpenEXR's coordinates (ImfHeader.cpp's sanity check; the exr crate's,
/// which the writer applies, holds the end past the last pixel below the
/// limit): an input far out, resized or moved, can leave them.
fn check_coordinates(opened: &Opened, window: IntegerBounds) -> Result<()> {
    let limit = i64::from(i32::MAX / 2);
    let (x0, y0) = (
        i64::from(window.position.x()),
        i64::from(window.position.y()),
    );
    let (x1, y1) = (
        x0 + window.size.width() as i64 - 1,
        y0 + window.size.height() as i64 - 1,
    );
    if [x0, y0].iter().any(|&v| v <= -limit) || [x1, y1].iter().any(|&v| v + 1 >= limit) {
        return Err(opened.located(format!(
            "the result's data window ({x0} {y0}) - ({x1} {y1}) would not fit OpenEXR's 32-bit \
             coordinates (pixels from {} to {})",
            1 - limit,
            limit - 2
        )));
    }
    Ok(())
}

/// The output's header, flat, of the output node's channels and window,
/// with its blocks, compression, the user's attribute edits and the
/// frame's fingerprint (returned too, for the other parts).
fn output_header(
    job: &Job,
    opened: &Opened,
    graph: &Graph,
    channels: &[Vec<ChannelDescription>],
    geometry: &Geometry,
) -> Result<(Header, String)> {
    let frame = opened.frame;
    let mut header = match job.header_base {
        HeaderBase::Input(i) => opened.header_of(i).clone(),
        HeaderBase::New(display) => {
            Header::new(Text::from("image"), display.size, Default::default())
                .with_display_window(display)
                .with_attributes(LayerAttributes::default())
        }
    };
    let mut output_channels = channels[graph.output()].clone();
    output_channels.sort_by(|a, b| a.name.bytes().cmp(b.name.bytes()));
    header.channels = exr::meta::attribute::ChannelList::new(output_channels.into());
    if geometry.resized {
        header.shared_attributes.display_window = geometry.display.window;
        header.shared_attributes.pixel_aspect = geometry.display.pixel_aspect;
    }
    // The ops' own edits (a colour conversion's destination), under the user's.
    if let HeaderBase::Input(i) = job.header_base {
        graph
            .edits(i)
            .iter()
            .for_each(|edit| edit.apply(&mut header));
    }
    header.deep = false;
    header.deep_data_version = None;
    header.max_samples_per_pixel = None;
    let header_file = (opened.header_file(job))
        .map(|f| format!(" ({})", f.path.display()))
        .unwrap_or_default();
    // Erased before the stamp, so that an input's history can be dropped
    // (as oiiotool's --eraseattrib does), then set over it.
    job.attributes.erase(&mut header);
    super::provenance::stamp(&mut header);
    crate::io::stitch::erase_band_record(&mut header);
    (job.attributes.set(&mut header, frame))
        .map_err(|m| Error::usage(format!("frame {frame}{header_file}: {m}")))?;
    let merged = (opened.deep.iter().flatten()).flat_map(|d| d.files[1..].iter());
    let files = (opened.inputs.iter().map(Arc::as_ref)).chain(merged.map(|(f, _)| f.as_ref()));
    let fingerprint = fingerprint::of_frame(job, opened.sources, files);
    fingerprint::stamp(&mut header, &fingerprint);
    let foreign = (opened.header_file(job)).is_some_and(|f| f.format().is_some());
    match job.compression {
        Some(compression) => header.compression = compression,
        // A DPX or Cineon header input is uncompressed: written as ZIP, as
        // oiiotool writes it, not as an uncompressed EXR larger than it.
        None if foreign => header.compression = exr::prelude::Compression::ZIP16,
        None => {}
    }
    header.blocks = output_blocks(job, &header);
    header.line_order = LineOrder::Increasing;
    let window = geometry.window;
    header.layer_size = window.size;
    header.own_attributes.layer_position = window.position;
    header.chunk_count = compute_chunk_count(header.compression, window.size, header.blocks);
    Ok((header, fingerprint))
}

/// The output's blocks: tiles asked for, or those of the header's input
/// (not for bands, which `stitch` joins as scanline blocks), else scanlines.
fn output_blocks(job: &Job, header: &Header) -> BlockDescription {
    // A new header (generate, demo) has the exr crate's default blocks.
    let input_blocks = match job.header_base {
        HeaderBase::Input(_) => header.blocks,
        HeaderBase::New(_) => BlockDescription::ScanLines,
    };
    let tile_size = match (job.blocks, input_blocks, job.rows) {
        (OutputBlocks::Tiles(size), _, _) => Some(size),
        // Bands for `stitch` join scanline blocks.
        (OutputBlocks::FollowInput, BlockDescription::Tiles(tiles), None) => Some(tiles.tile_size),
        _ => None,
    };
    match tile_size {
        Some(tile_size) => BlockDescription::Tiles(TileDescription {
            tile_size,
            level_mode: LevelMode::Singular,
            rounding_mode: RoundingMode::Down,
        }),
        None => BlockDescription::ScanLines,
    }
}

/// The input whose other parts the output carries (`FramePlan::carried`),
/// and its part headers with the user's edits and the fingerprint. The
/// exr crate writes one `chromaticities` for every part: where the written
/// part's are not the others' (a colour conversion's), no part has any.
fn carried_parts(
    job: &Job,
    opened: &Opened,
    header: &mut Header,
    fingerprint: &str,
) -> Result<(Option<usize>, Vec<Header>)> {
    let carried = match job.header_base {
        HeaderBase::Input(i)
            if opened.inputs[i].meta.headers.len() > 1 && !opened.black(i) && !job.all_parts =>
        {
            Some(i)
        }
        _ => None,
    };
    let Some(i) = carried else {
        return Ok((None, Vec::new()));
    };
    let mut carried_headers: Vec<Header> = (opened.inputs[i].meta.headers.iter())
        .map(|part| {
            let mut part = part.clone();
            job.attributes.carry(&mut part, header);
            fingerprint::stamp(&mut part, fingerprint);
            part
        })
        .collect();
    let chromaticities = |h: &Header| h.shared_attributes.chromaticities;
    if (carried_headers.iter().enumerate())
        .any(|(p, h)| p != opened.parts[i] && chromaticities(h) != chromaticities(header))
    {
        for part in carried_headers.iter_mut().chain([&mut *header]) {
            part.shared_attributes.chromaticities = None;
        }
    }
    check_shared_display(opened, i, header, &carried_headers)?;
    Ok((carried, carried_headers))
}

/// OpenEXR requires every part of a file to share its display window and
/// pixel aspect ratio (ImfMultiPartOutputFile refuses the file else): a
/// geometry op on one part of input `i` cannot leave the others as they are.
fn check_shared_display(
    opened: &Opened,
    i: usize,
    header: &Header,
    carried_headers: &[Header],
) -> Result<()> {
    let shown = |h: &Header| {
        let a = &h.shared_attributes;
        (a.display_window, a.pixel_aspect.to_bits())
    };
    let mismatch = (carried_headers.iter().enumerate())
        .find(|&(p, h)| p != opened.parts[i] && shown(h) != shown(header));
    let Some((_, other)) = mismatch else {
        return Ok(());
    };
    let describe = |h: &Header| {
        let a = &h.shared_attributes;
        format!(
            "{} at pixel aspect {}",
            box_text(a.display_window),
            a.pixel_aspect
        )
    };
    Err(Error::usage(format!(
        "frame {}: {} has {} parts, which OpenEXR requires to share one display \
         window and pixel aspect ratio: the result's, {}, is not its other parts', {}: \
         give --all-parts to apply the operations to every part",
        opened.frame,
        opened.inputs[i].path.display(),
        carried_headers.len(),
        describe(header),
        describe(other),
    )))
}

/// What the output's layout allows: bands of single-part scanline files,
/// and subsampled channels in scanline parts of the compressions that
/// keep them.
fn check_layout(job: &Job, opened: &Opened, header: &Header, carried: Option<usize>) -> Result<()> {
    if let (OutputBlocks::Tiles(_), Some(_)) = (job.blocks, job.rows) {
        return Err(Error::usage(
            "--rows writes bands of scanline files only (stitch joins scanline blocks): drop --tile",
        ));
    }
    if let (Some(i), Some(_)) = (carried, job.rows) {
        return Err(opened.inputs[i].error(format!(
            "has {} parts: --rows renders bands of single-part outputs only, and the other parts \
             would be lost",
            opened.inputs[i].meta.headers.len()
        )));
    }
    // OpenEXR allows subsampled channels in scanline parts only.
    let tiled = header.blocks.has_tiles().then(|| {
        "OpenEXR allows them in scanline parts only, so the output cannot be tiled: drop --tile \
         (or the write node's tile)"
            .to_string()
    });
    if let Some(message) = crate::io::subsampling::any(header)
        .then_some(tiled)
        .flatten()
    {
        let source = match opened.header_file(job) {
            Some(file) => file.path.display().to_string(),
            None => "the result".into(),
        };
        return Err(Error::usage(format!(
            "frame {}: {source} has subsampled channels for the output: {message}",
            opened.frame
        )));
    }
    Ok(())
}

/// Never write a file the reader would refuse, nor allocate for it: the
/// output's blocks (of `lines` rows), tiles and chunk count checked against
/// the reader's limits. Returns the bytes of one block of rows.
fn check_block_sizes(
    job: &Job,
    opened: &Opened,
    header: &Header,
    window: IntegerBounds,
    lines: usize,
) -> Result<usize> {
    // From inputs, a result far wider or taller than any of them (inputs far
    // apart) is an input problem; a generated image asked that wide, a usage error.
    let too_big = |message: String| match opened.inputs.is_empty() {
        true => Error::usage(format!("frame {}: {message}", opened.frame)),
        false => opened.located(message),
    };
    let block_bytes = window
        .size
        .width()
        .saturating_mul(lines)
        .saturating_mul(header.channels.bytes_per_pixel);
    if block_bytes > MAX_BLOCK_BYTES {
        let message = format!(
            "the result's data window is {} pixels wide: its blocks of {lines} lines would take \
             {block_bytes} bytes, over the {MAX_BLOCK_BYTES}-byte limit",
            window.size.width()
        );
        return Err(too_big(message));
    }
    let size = (window.size.width(), window.size.height());
    if let Some(message) = job.media.as_ref().and_then(|r| r.media.too_large(size)) {
        return Err(too_big(message));
    }
    // Tiles asked of a size whose blocks the reader would refuse.
    if let BlockDescription::Tiles(tiles) = header.blocks {
        let tile_bytes = tiles
            .tile_size
            .area()
            .saturating_mul(header.channels.bytes_per_pixel);
        if tile_bytes > MAX_BLOCK_BYTES {
            return Err(Error::usage(format!(
                "frame {}: tiles of {}x{} pixels would take {tile_bytes} bytes each, over \
                 the {MAX_BLOCK_BYTES}-byte limit of a block: give a smaller --tile",
                opened.frame,
                tiles.tile_size.width(),
                tiles.tile_size.height()
            )));
        }
    }
    // Its offset table is held while it is written, 8 bytes a chunk: the
    // one thing that grows with its height.
    let chunks = output_grid(header).blocks;
    let chunks = chunks.x().saturating_mul(chunks.y());
    if chunks > MAX_OUTPUT_CHUNKS {
        let message = format!(
            "the result's data window is {} x {} pixels: it would take {chunks} chunks, over the \
             {MAX_OUTPUT_CHUNKS}-chunk limit",
            window.size.width(),
            window.size.height()
        );
        return Err(too_big(message));
    }
    Ok(block_bytes)
}

/// The bytes a strip of some rows holds. The nodes hold the strip's rows
/// (their region's span of them: the output's rows, but behind a resize)
/// across their region's width (those alive at once, `Graph::peak`); a flat
/// input's chunks are decoded across its own width (wider than the result's
/// when it is clipped), whole blocks covering the strip's rows. (A deep
/// input's chunks are decoded in batches of their own size.)
struct StripCost<'a> {
    graph: &'a Graph,
    regions: &'a Regions,
    top: i32,
    /// Per node, the bytes of a pixel.
    pixel_bytes: Vec<usize>,
    /// Per flat input: its node, the bytes of a row decoded, its block's rows.
    decoded: Vec<(Option<usize>, usize, usize)>,
}

impl<'a> StripCost<'a> {
    fn new(
        opened: &Opened,
        graph: &'a Graph,
        channels: &[Vec<ChannelDescription>],
        regions: &'a Regions,
        computed: IntegerBounds,
    ) -> Self {
        let pixel_bytes: Vec<usize> = channels
            .iter()
            .map(|list| list.iter().map(|c| c.sample_type.bytes_per_sample()).sum())
            .collect();
        let decoded: Vec<(Option<usize>, usize, usize)> = (0..opened.inputs.len())
            .filter(|&i| opened.deep[i].is_none())
            .map(|i| {
                let header = opened.header_of(i);
                let row = header.channels.bytes_per_pixel * opened.input_window(i).size.width();
                (graph.input_node(i), row, opened.levels[i].block.y())
            })
            .collect();
        StripCost {
            graph,
            regions,
            top: computed.position.y(),
            pixel_bytes,
            decoded,
        }
    }

    /// The bytes a strip of `rows` rows from the top holds.
    fn bytes(&self, rows: usize) -> usize {
        let (graph, regions) = (self.graph, self.regions);
        let spans = regions.spans(graph, self.top..self.top.saturating_add(rows as i32));
        // Decode reads a zone from its top to its span's end, or from its
        // bottom to its span's start when it reads it bottom-up (a flip):
        // the span, but where readers disagree or a turn near 90 degrees
        // asks whole columns, the whole input.
        let held = |n: Option<usize>| {
            n.map_or(rows, |n| {
                let (span, rect) = (regions.span(&spans, n), regions.rect(n));
                let rows = match regions.upward(n) {
                    true => rect.end().y() - span.start,
                    false => span.end - rect.position.y(),
                };
                rows.max(0) as usize
            })
        };
        let nodes = graph.peak(|n| {
            self.pixel_bytes[n]
                .saturating_mul(regions.rect(n).size.width())
                .saturating_mul(held(Some(n)))
        });
        (self.decoded.iter())
            .map(|&(node, row, lines)| row.saturating_mul(held(node) + lines))
            .fold(nodes, usize::saturating_add)
    }
}

/// The rows of a strip: whole blocks of `lines` rows, about `STRIP_BYTES`
/// of output, all it holds within `HELD_BYTES`; a frame whose one block of
/// rows is over `MAX_STRIP_BYTES` is refused.
fn strip_rows(
    job: &Job,
    opened: &Opened,
    cost: &StripCost,
    window: IntegerBounds,
    lines: usize,
    block_bytes: usize,
) -> Result<usize> {
    let smallest = cost.bytes(lines);
    if smallest > MAX_STRIP_BYTES {
        let message = format!(
            "the result would be {} x {} pixels: a strip of one {lines}-row block, decoded and \
             composited, would take {smallest} bytes, over the {MAX_STRIP_BYTES}-byte limit \
             (is a data window damaged? a turn near 90 or 270 degrees holds its whole \
             input, and a resize that shrinks the height many times over holds as many \
             input rows per output row: resize in steps)",
            window.size.width(),
            window.size.height(),
        );
        // Blame the widest input (the first of the widest): its data window
        // makes the strips that wide, or inputs far apart do.
        let widest = (0..opened.inputs.len())
            .rev()
            .max_by_key(|&i| opened.input_window(i).size.width());
        return Err(match widest {
            Some(i) => opened.inputs[i].error(message),
            None => Error::usage(message),
        });
    }
    // Strips of whole tile rows of the tiled inputs too, when that stays
    // small: their tiles then decode straight into the strip, none carried.
    let grain = (0..opened.inputs.len())
        .filter(|&i| opened.deep[i].is_none() && opened.header_of(i).blocks.has_tiles())
        .map(|i| opened.levels[i].block.y())
        .fold(lines, lcm);
    let grain = match cost.bytes(grain) <= HELD_BYTES {
        true => grain,
        false => lines,
    };
    let mut blocks = STRIP_BYTES
        .div_ceil(block_bytes.max(1))
        .max(rayon::current_num_threads())
        .next_multiple_of(grain / lines);
    // Behind a reduction (a 16K plate resized to 4K) a strip holds far more
    // input than output: all it holds is kept within `HELD_BYTES` then,
    // down to one block.
    while blocks > 1 && cost.bytes(blocks * lines) > HELD_BYTES {
        blocks = (blocks / 2).max(1);
    }
    // Asked for (tests of strip boundaries), within the same memory bound.
    if let Some(rows) = job.strip_rows {
        blocks = blocks.min(rows.div_ceil(lines).max(1));
    }
    Ok(blocks * lines)
}

/// `--all-parts` on a part the operations refuse (`refusal`: no colour to
/// blur, no vectors): the part planned through an identity graph, so it is
/// written unchanged, as the parts a one-part run does not work on are.
fn carry_as_is(
    job: &Job,
    sources: &FrameSources,
    part: Option<Forced>,
    refusal: Error,
) -> Result<FramePlan> {
    let mut plan = plan_frame(job, sources, part, &Graph::identity())?;
    plan.carried_as_is = Some(refusal);
    Ok(plan)
}

/// The output's grid of blocks (scanline blocks or tiles) and their place
/// in its offset table.
pub fn output_grid(header: &Header) -> Level {
    tiles::levels(header)[0]
}

fn lcm(a: usize, b: usize) -> usize {
    let gcd = |mut a: usize, mut b: usize| {
        while b != 0 {
            (a, b) = (b, a % b);
        }
        a
    };
    a / gcd(a, b) * b
}

/// The level each input reads (`input_level`); a level asked that no input
/// has is an error.
fn read_levels(job: &Job, inputs: &[Arc<ExrFile>], parts: &[usize]) -> Result<Vec<Level>> {
    let levels = inputs
        .iter()
        .zip(parts)
        .map(|(file, &part)| input_level(job, file, part))
        .collect::<Result<Vec<Level>>>()?;
    if let Some(asked) = job.level.filter(|&l| l != Vec2(0, 0)) {
        if !levels.iter().any(|l| l.index == asked) {
            return Err(Error::usage(format!(
                "--level {}: no input is mipmapped or ripmapped",
                tiles::name(asked)
            )));
        }
    }
    Ok(levels)
}

/// The level of `part` of `file` read: `job.level` if it has levels
/// (mipmaps and ripmaps), else its only one.
pub fn input_level(job: &Job, file: &ExrFile, part: usize) -> Result<Level> {
    let header = file.header(part);
    let layered = tiles::levels(header).len() > 1;
    tiles::level(header, job.level.filter(|_| layered))
        .map_err(|m| file.error(format!("--level: {m}")))
}

/// Narrows `header` to the band of rows `y0..y1` (on its block grid),
/// recording the whole window and `frame` it is a band of (for `stitch`),
/// and returns the band.
fn band(header: &mut Header, (y0, y1): (i32, i32), frame: i64) -> Result<IntegerBounds> {
    let window = header.data_window();
    let (top, bottom) = (window.position.y(), window.end().y());
    let lines = header.compression.scan_lines_per_block() as i32;
    let on_grid = |y: i32| (y - top) % lines == 0 || y == bottom;
    if y0 < top || y0 >= y1 || y1 > bottom || !on_grid(y0) || !on_grid(y1) {
        return Err(Error::usage(format!(
            "--rows {y0}-{y1}: a band must lie in rows {top}-{bottom} and start and end on \
             {lines}-line block boundaries counted from row {top}"
        )));
    }
    crate::io::stitch::mark_band(header, window, frame);
    header.own_attributes.layer_position = exr::math::Vec2(window.position.x(), y0);
    header.layer_size = exr::math::Vec2(window.size.width(), (y1 - y0) as usize);
    header.chunk_count = ((y1 - y0) as usize).div_ceil(lines as usize);
    Ok(IntegerBounds::new(
        (window.position.x(), y0),
        (window.size.width(), (y1 - y0) as usize),
    ))
}

/// The rows and columns computed to write `written` (the output's `window`,
/// or a band of it): it and, around it, as far as the graph's halos reach
/// (`Graph::reach`), where some node has data. So a node behind a crop, or
/// behind a band's edge, reads the rows and columns beyond it as the whole
/// image would have it (a crop of a blur is the blur's crop). The top is on
/// the output's block grid, counted from the window's top, so that the
/// written rows come in whole blocks.
fn computed(
    written: IntegerBounds,
    window: IntegerBounds,
    graph: &Graph,
    windows: &[IntegerBounds],
    lines: usize,
) -> IntegerBounds {
    let data = windows.iter().copied().fold(written, union);
    let rect = intersection(grow(written, graph.reach()), data);
    let (lines, origin) = (lines as i32, window.position.y());
    let top = origin + (rect.position.y() - origin).div_euclid(lines) * lines;
    IntegerBounds::new(
        (rect.position.x(), top),
        (rect.size.width(), (rect.end().y() - top) as usize),
    )
}

/// Input `i`'s flattening, if it is deep: its own file and those merged
/// with it (the same frame), each checked.
fn deep_input(
    job: &Job,
    i: usize,
    sources: &FrameSources,
    file: &Arc<ExrFile>,
    part: usize,
) -> Result<Option<Arc<DeepInput>>> {
    let merged = job.merged.get(i).map_or(&[][..], Vec::as_slice);
    if matches!(sources.inputs[i], Source::Black(_)) {
        return Ok(None);
    }
    if !file.header(part).deep {
        if let Some(other) = merged.first() {
            return Err(file.error(format!(
                "is not deep, so it cannot be deep-merged with {}",
                other.display()
            )));
        }
        return Ok(None);
    }
    let at = sources.inputs[i].file_frame();
    let mut files = vec![(file.clone(), part)];
    let mut levels = vec![input_level(job, file, part)?];
    for pattern in merged {
        let other = Arc::new(ExrFile::open(&pattern.path(at), job.frame_label(at))?);
        let part = choose_part(&other, None, job.view.as_deref())?;
        other.check_codec(part)?;
        if !other.header(part).deep {
            return Err(other.error("is not deep: deepmerge takes deep files only"));
        }
        levels.push(input_level(job, &other, part)?);
        files.push((other, part));
    }
    Ok(Some(Arc::new(DeepInput::new(files, levels))))
}
