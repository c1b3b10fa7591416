//! The command line.

use crate::params::*;
use clap::{Args, Parser, Subcommand, ValueHint};
use std::path::PathBuf;

#[derive(Parser)]
#[command(
    name = "exrcomp",
    version,
    about = "Streaming OpenEXR sequence compositor"
)]
pub struct Cli {
    /// Worker threads (default: one per core).
    #[arg(long, global = true, value_parser = crate::params::parse_threads)]
    pub threads: Option<usize>,
    #[command(subcommand)]
    pub command: Command,
}

#[derive(Subcommand)]
pub enum Command {
    /// Composite FG over BG: C = Cfg + (1 - Afg) Cbg (premultiplied).
    Over {
        /// Foreground: a file or a sequence (fg.####.exr, fg.%04d.exr), with
        /// `:PART` (name or index) to read one part of a multi-part file.
        #[arg(value_hint = ValueHint::FilePath)]
        fg: String,
        /// Background: its header, display window and other channels are kept.
        #[arg(value_hint = ValueHint::FilePath)]
        bg: String,
        #[command(flatten)]
        with: Composite,
    },
    /// Merge A (top) with B (bottom) by an operator, as Nuke's Merge does.
    Merge {
        #[arg(long, value_enum)]
        op: crate::ops::merge::MergeOp,
        /// Top input: a file or sequence, `:PART` for a part.
        #[arg(value_hint = ValueHint::FilePath)]
        a: String,
        /// Bottom input: its header, display window and other channels are kept.
        #[arg(value_hint = ValueHint::FilePath)]
        b: String,
        /// Blend the result with B: 0 gives B, 1 the result.
        #[arg(long, default_value_t = 1.0, value_parser = |t: &str| MIX.parse::<f32>(t))]
        mix: f32,
        #[command(flatten)]
        with: Composite,
    },
    /// Composite layers L1 over L2 over ... Ln in one pass (L1 on top).
    Stack {
        /// Two or more inputs, top first; the last one's header is kept.
        #[arg(value_hint = ValueHint::FilePath, required = true, num_args = 2..)]
        inputs: Vec<String>,
        #[command(flatten)]
        with: Composite,
    },
    /// Multiply colour by alpha.
    Premult(OneInput),
    /// Divide colour by alpha (colour unchanged where alpha is 0).
    Unpremult(OneInput),
    /// Blur with a separable Gaussian or box of radius R (edges clamp to the
    /// data window); `--radius R` is oiiotool's `--blur (2R+1)x(2R+1)`.
    Blur {
        #[command(flatten)]
        one: OneInput,
        #[arg(long, value_parser = |t: &str| BLUR_RADIUS.parse::<u32>(t))]
        radius: u32,
        #[arg(long, value_enum, default_value = "gaussian")]
        filter: crate::ops::blur::Filter,
    },
    /// Depth of field from a depth channel: each pixel spreads over an
    /// aperture whose radius grows with its distance from the focus plane.
    Defocus {
        #[command(flatten)]
        one: OneInput,
        /// Depth in focus.
        #[arg(long, value_parser = |t: &str| FOCUS.parse::<f32>(t))]
        focus: f32,
        /// Blur radius in pixels of what is far behind the focus plane:
        /// radius = scale * |1 - focus / Z|.
        #[arg(long, value_parser = |t: &str| DEFOCUS_SCALE.parse::<f32>(t))]
        scale: f32,
        /// Largest radius (the rows read above and below).
        #[arg(long, value_parser = |t: &str| MAX_RADIUS.parse::<u32>(t))]
        max_radius: u32,
        /// disc, hexagon, or N-gon (5-gon, 8-gon...).
        #[arg(long, default_value = "disc", value_parser = crate::ops::defocus::Aperture::parse)]
        aperture: crate::ops::defocus::Aperture,
        #[arg(long, default_value = "Z")]
        z_channel: String,
    },
    /// Motion blur from per-pixel displacement (pixels moved during the frame).
    Vblur {
        #[command(flatten)]
        one: OneInput,
        /// Scales the displacement: 0 for none, 1 as rendered.
        #[arg(long, default_value_t = 1.0, value_parser = |t: &str| VBLUR_SCALE.parse::<f32>(t))]
        scale: f32,
        /// The x and y displacement channels (y down, in pixels).
        #[arg(long, default_value = "forward.u,forward.v", value_parser = parse_pair)]
        vectors: (String, String),
        /// Rows a streak may reach; without it, a first pass over the vectors
        /// measures it. A longer streak is an error, never cut.
        #[arg(long, value_parser = |t: &str| MAX_DISPLACEMENT.parse::<u32>(t))]
        max_displacement: Option<u32>,
    },
    /// The other eye of a stereo pair from one view and its depth.
    Stereo {
        #[arg(value_hint = ValueHint::FilePath)]
        input: String,
        #[arg(value_hint = ValueHint::FilePath, short, long)]
        output: String,
        /// The eye to make: pixels move right for the left eye, left for the right.
        #[arg(long, value_enum)]
        eye: crate::ops::stereo::Eye,
        /// Shift in pixels at depth 1: a pixel at depth Z moves K / Z.
        #[arg(long, allow_hyphen_values = true, value_parser = |t: &str| DISPARITY.parse::<f32>(t))]
        disparity: f32,
        #[arg(long, default_value = "Z")]
        z_channel: String,
        #[command(flatten)]
        run: RunArgs,
    },
    /// Depth-aware merge: per pixel the nearer sample goes over the farther
    /// (alpha 0 never in front); Z becomes the nearer depth.
    Zmerge {
        /// Two or more inputs; the last one's header and other channels are kept.
        #[arg(value_hint = ValueHint::FilePath, required = true, num_args = 2..)]
        inputs: Vec<String>,
        #[arg(value_hint = ValueHint::FilePath, short, long)]
        output: String,
        #[arg(long, default_value = "Z")]
        z_channel: String,
        #[command(flatten)]
        run: RunArgs,
    },
    /// Differential rendering (Debevec): an object rendered into a plate
    /// with the shadows and light it casts on a proxy of the real scene.
    Diffrender {
        /// I1: the object alone.
        #[arg(value_hint = ValueHint::FilePath, long)]
        object: String,
        /// I2: the proxy of the scene, without the object.
        #[arg(value_hint = ValueHint::FilePath, long)]
        proxy: String,
        /// I3: the proxy with the object's shadows (and light) on it.
        #[arg(value_hint = ValueHint::FilePath, long)]
        with_shadows: String,
        /// P: the real plate; its header and other channels are kept.
        #[arg(value_hint = ValueHint::FilePath, long)]
        plate: String,
        #[arg(value_hint = ValueHint::FilePath, short, long)]
        output: String,
        /// G in P - G (I4 - I3).
        #[arg(long, default_value_t = 1.0, allow_hyphen_values = true, value_parser = |t: &str| SHADOW_GAIN.parse::<f32>(t))]
        shadow_gain: f32,
        /// Write I5 = (I1 over I2) - I3 instead, for grading.
        #[arg(long)]
        shadow_only: bool,
        #[command(flatten)]
        run: RunArgs,
    },
    /// Colour-difference keyer: alpha from how far the screen channel rises
    /// above the other two, the screen taken out of the colour.
    Key {
        #[arg(value_hint = ValueHint::FilePath)]
        input: String,
        #[arg(value_hint = ValueHint::FilePath, short, long)]
        output: String,
        /// green, blue, or the screen's colour as R,G,B.
        #[arg(long, default_value = "green", value_parser = parse_screen)]
        screen: [f32; 3],
        /// Scales the difference: above 1 more transparent.
        #[arg(long, default_value_t = 1.0, value_parser = |t: &str| GAIN.parse::<f32>(t))]
        gain: f32,
        /// Weight of the first other channel against the second (0..1).
        #[arg(long, default_value_t = 0.5, value_parser = |t: &str| BALANCE.parse::<f32>(t))]
        balance: f32,
        /// Alpha at or below this becomes 0.
        #[arg(long, default_value_t = 0.0, value_parser = |t: &str| CLIP.parse::<f32>(t))]
        clip_black: f32,
        /// Alpha at or above this becomes 1.
        #[arg(long, default_value_t = 1.0, value_parser = |t: &str| CLIP.parse::<f32>(t))]
        clip_white: f32,
        /// Limit the screen channel to the other two (spill suppression).
        #[arg(long)]
        despill: bool,
        /// 1 - alpha.
        #[arg(long)]
        invert: bool,
        #[command(flatten)]
        run: RunArgs,
    },
    /// Difference matte: alpha from the difference with a clean plate.
    Diffmatte {
        #[arg(value_hint = ValueHint::FilePath)]
        input: String,
        #[arg(value_hint = ValueHint::FilePath, long)]
        clean_plate: String,
        #[arg(value_hint = ValueHint::FilePath, short, long)]
        output: String,
        /// Differences up to this are background (alpha 0).
        #[arg(long, default_value_t = 0.05, value_parser = |t: &str| THRESHOLD.parse::<f32>(t))]
        threshold: f32,
        /// Alpha reaches 1 at threshold + softness.
        #[arg(long, default_value_t = 0.1, value_parser = |t: &str| SOFTNESS.parse::<f32>(t))]
        softness: f32,
        #[arg(long)]
        invert: bool,
        #[command(flatten)]
        run: RunArgs,
    },
    /// Triangulation matting: one foreground over two known backgrounds gives
    /// alpha and colour exactly.
    Triangulate {
        #[arg(value_hint = ValueHint::FilePath, long)]
        over_a: String,
        #[arg(value_hint = ValueHint::FilePath, long)]
        bg_a: String,
        #[arg(value_hint = ValueHint::FilePath, long)]
        over_b: String,
        #[arg(value_hint = ValueHint::FilePath, long)]
        bg_b: String,
        #[arg(value_hint = ValueHint::FilePath, short, long)]
        output: String,
        #[command(flatten)]
        run: RunArgs,
    },
    /// Shrink a matte: the smallest alpha within a disc of the radius.
    Erode(Morph),
    /// Grow a matte: the largest alpha within a disc of the radius.
    Dilate(Morph),
    /// Flatten a deep file: each pixel's samples composited front to back
    /// (any command reading a deep scanline input flattens it the same way).
    Flatten {
        #[arg(value_hint = ValueHint::FilePath)]
        input: String,
        #[arg(value_hint = ValueHint::FilePath, short, long)]
        output: String,
        #[command(flatten)]
        run: RunArgs,
    },
    /// Merge deep files by depth, sample by sample, then flatten.
    Deepmerge {
        /// Two or more deep files or sequences; the first one's header is kept.
        #[arg(value_hint = ValueHint::FilePath, required = true, num_args = 2..)]
        inputs: Vec<String>,
        #[arg(value_hint = ValueHint::FilePath, short, long)]
        output: String,
        #[command(flatten)]
        run: RunArgs,
    },
    /// Write a farm job that runs a command over frame chunks.
    Farm {
        #[command(subcommand)]
        farm: Farm,
    },
    /// Join band files written with --rows into one file, copying their
    /// compressed chunks (nothing is decoded or re-encoded).
    Stitch {
        #[arg(value_hint = ValueHint::FilePath, required = true, num_args = 2..)]
        bands: Vec<PathBuf>,
        #[arg(value_hint = ValueHint::FilePath, short, long)]
        output: PathBuf,
    },
    /// Run a job file: a graph of reads, operations and a write, streamed in
    /// one pass (specs/job-format.md).
    Run {
        #[arg(value_hint = ValueHint::FilePath)]
        job: PathBuf,
        /// Write here instead of the job's write node's file.
        #[arg(value_hint = ValueHint::FilePath, short, long)]
        output: Option<String>,
        #[command(flatten)]
        run: RunArgs,
    },
    /// Read and write a sequence unchanged but for compression (the codec floor).
    Transcode {
        #[arg(value_hint = ValueHint::FilePath)]
        input: String,
        #[arg(value_hint = ValueHint::FilePath, short, long)]
        output: String,
        /// Level of a mipmapped input (N), or a ripmapped one (X,Y), to
        /// write instead of the full resolution (level 0).
        #[arg(long, value_parser = parse_level)]
        level: Option<exr::math::Vec2<usize>>,
        #[command(flatten)]
        run: RunArgs,
    },
    /// Describe EXR files as exrheader does and check that every chunk decodes.
    Info {
        #[arg(value_hint = ValueHint::FilePath, required = true)]
        files: Vec<PathBuf>,
        /// One JSON object per file, on a line of its own, with the same facts.
        #[arg(long)]
        json: bool,
    },
    /// Generate a synthetic shot and composite it.
    Demo {
        /// Where the shot is written.
        #[arg(long, default_value = "demo-shot")]
        dir: PathBuf,
        /// Number of frames.
        #[arg(long, default_value_t = 24)]
        length: usize,
        #[arg(long, default_value_t = 1920)]
        width: usize,
        #[arg(long, default_value_t = 1080)]
        height: usize,
        #[command(flatten)]
        run: RunArgs,
    },
    /// Write synthetic test plates (a grainy background or a moving foreground).
    Generate {
        /// Output file or sequence.
        #[arg(value_hint = ValueHint::FilePath)]
        output: String,
        #[arg(long, value_enum, default_value = "bg")]
        kind: crate::generate::PlateKind,
        #[arg(long, default_value_t = 1920)]
        width: usize,
        #[arg(long, default_value_t = 1080)]
        height: usize,
        /// Data window origin, as X,Y (display window stays at 0,0).
        #[arg(long, value_parser = parse_origin, default_value = "0,0", allow_hyphen_values = true)]
        origin: (i32, i32),
        /// Sample type of the colour channels.
        #[arg(long, value_enum, default_value = "half")]
        pixel_type: crate::generate::PixelType,
        #[command(flatten)]
        run: RunArgs,
    },
}

/// What every compositing command takes besides its inputs.
#[derive(Args)]
pub struct Composite {
    /// Output file or sequence.
    #[arg(value_hint = ValueHint::FilePath, short, long)]
    pub output: String,
    /// Inputs and output are unpremultiplied (straight) colour.
    #[arg(long)]
    pub straight: bool,
    #[command(flatten)]
    pub layers: LayerArgs,
    #[command(flatten)]
    pub run: RunArgs,
}

#[derive(Subcommand)]
pub enum Farm {
    /// An Open Job Description job template (`openjd check`, `openjd run`,
    /// AWS Deadline Cloud): one task per chunk, each `--frames CHUNK --resume`.
    Openjd(FarmJob),
    /// An OpenCue outline (JSON, as PyOutline loads it) with one chunked
    /// layer (frames A-B or A-B:STEP); see the README for submitting it.
    Opencue(FarmJob),
}

/// A local command to run on a farm, in frame chunks.
#[derive(Args)]
pub struct FarmJob {
    /// All the frames, as --frames takes them.
    #[arg(long)]
    pub frames: String,
    /// Frames per task.
    #[arg(long, default_value_t = 10)]
    pub chunk: usize,
    /// OpenJD: let the scheduler chunk the frames (a CHUNK[INT] task
    /// parameter, the TASK_CHUNKING extension) instead of listing the chunks.
    #[arg(long)]
    pub task_chunking: bool,
    /// OpenJD: chunks sized towards this runtime from the ones done
    /// (implies --task-chunking).
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..))]
    pub target_runtime: Option<u32>,
    /// Where the job is written.
    #[arg(value_hint = ValueHint::FilePath, short, long)]
    pub output: PathBuf,
    /// The exrcomp command to run, without --frames (after `--`).
    #[arg(required = true, trailing_var_arg = true, allow_hyphen_values = true)]
    pub command: Vec<String>,
}

/// Erode and dilate.
#[derive(Args)]
pub struct Morph {
    #[command(flatten)]
    pub one: OneInput,
    #[arg(long, value_parser = |t: &str| MORPH_RADIUS.parse::<u32>(t))]
    pub radius: u32,
    /// 1 - alpha afterwards.
    #[arg(long)]
    pub invert: bool,
}

/// An operation on one input.
#[derive(Args)]
pub struct OneInput {
    #[arg(value_hint = ValueHint::FilePath)]
    pub input: String,
    #[arg(value_hint = ValueHint::FilePath, short, long)]
    pub output: String,
    #[command(flatten)]
    pub layers: LayerArgs,
    #[command(flatten)]
    pub run: RunArgs,
}

/// Which layers, views and parts an operation works on.
#[derive(Args, Clone, Default)]
pub struct LayerArgs {
    /// Layer to work on (`diffuse` for diffuse.R, G, B, A); repeatable.
    /// Default: the unnamed layer (R, G, B, A).
    #[arg(long = "layer")]
    pub layers: Vec<String>,
    /// Every layer with colour channels in all inputs.
    #[arg(long, conflicts_with_all = ["layers", "view"])]
    pub all_layers: bool,
    /// View of a stereo file: the part with this `view`, or in a single-part
    /// multi-view file the channels `VIEW.R` (`layer.VIEW.R`).
    #[arg(long)]
    pub view: Option<String>,
    /// Part (name or index) of inputs given without `:PART`.
    #[arg(long)]
    pub part: Option<String>,
    /// Level of mipmapped inputs (N), or ripmapped ones (X,Y; N is N,N) to
    /// read instead of the full resolution (level 0).
    #[arg(long, value_parser = parse_level)]
    pub level: Option<exr::math::Vec2<usize>>,
}

/// Options every job that writes files takes.
#[derive(Args, Clone)]
pub struct RunArgs {
    /// Frames: A-B, A-B:STEP, or a comma list (default: those on disk).
    #[arg(long)]
    pub frames: Option<String>,
    /// Output compression: none, rle, zips, zip, piz, pxr24, b44, b44a, dwaa, dwab
    /// (default: the background's).
    #[arg(long)]
    pub compression: Option<String>,
    /// libdeflate's effort for ZIP and ZIPS output, 1 (fastest) to 12
    /// (smallest); noisy low-byte halves always take ISA-L's fastest level.
    /// The default 2 writes files within 2.5% of OpenEXR's size.
    #[arg(long, default_value_t = crate::io::zip::DEFAULT_LEVEL, value_parser = clap::value_parser!(u8).range(1..=12))]
    pub zip_level: u8,
    /// DWAA and DWAB output's compression level, written as the file's
    /// `dwaCompressionLevel`: higher is smaller and coarser (default 45, as
    /// OpenEXR's).
    #[arg(long, value_parser = |t: &str| DWA_LEVEL.parse::<f32>(t))]
    pub dwa_level: Option<f32>,
    /// Write tiled files with tiles of WxH pixels (N: NxN), one level,
    /// instead of scanlines.
    #[arg(long, value_parser = parse_tile)]
    pub tile: Option<exr::math::Vec2<usize>>,
    /// What a missing input frame does: error (before any work), skip the
    /// output frame, hold the nearest earlier frame, or black.
    #[arg(long, value_enum, default_value = "error")]
    pub missing: crate::engine::sources::MissingPolicy,
    /// Skip frames whose output already exists and decodes completely.
    #[arg(long)]
    pub resume: bool,
    /// Report a frame with bad input and go on with the others (the exit
    /// code is still non-zero).
    #[arg(long)]
    pub keep_going: bool,
    /// No progress bar and no summary.
    #[arg(long, short)]
    pub quiet: bool,
    /// Print a JSON summary on standard output at the end.
    #[arg(long)]
    pub json: bool,
    /// Check every frame's inputs and the outputs, print what would be
    /// written, and write nothing.
    #[arg(long)]
    pub dry_run: bool,
    /// Write only rows Y0-Y1 of each frame (on the output's block grid): a
    /// band of a huge plate for one machine; `exrcomp stitch` joins them.
    #[arg(long, value_parser = parse_rows)]
    pub rows: Option<(i32, i32)>,
    /// Run the operation on every part of a multi-part input instead of one,
    /// each part keeping its own channels, windows and attributes; for
    /// operations of one input (specs/file-format.md, "Parts").
    #[arg(long, conflicts_with = "rows")]
    pub all_parts: bool,
    /// Rows per strip, rounded up to whole output blocks (for tests of strip
    /// boundaries; the default sizes strips by bytes).
    #[arg(long, hide = true)]
    pub strip_rows: Option<usize>,
}

/// A screen colour: `green`, `blue` or R,G,B.
pub fn parse_screen(text: &str) -> Result<[f32; 3], String> {
    match text.to_ascii_lowercase().as_str() {
        "green" => return Ok([0.0, 1.0, 0.0]),
        "blue" => return Ok([0.0, 0.0, 1.0]),
        _ => {}
    }
    let values: Vec<f32> = text
        .split(',')
        .map(|v| SCREEN.parse::<f32>(v))
        .collect::<Result<_, _>>()
        .map_err(|m| format!("expected green, blue or R,G,B: {m}"))?;
    match values[..] {
        [r, g, b] if r.max(g).max(b) > r.min(g).min(b) => Ok([r, g, b]),
        [_, _, _] => Err("a screen colour needs one channel above the others".into()),
        _ => Err("expected green, blue or R,G,B".into()),
    }
}

fn parse_rows(text: &str) -> Result<(i32, i32), String> {
    let bad = || "expected Y0-Y1 (rows Y0 to Y1, Y1 excluded)".to_string();
    let (a, b) = text.rsplit_once('-').ok_or_else(bad)?;
    Ok((
        a.trim().parse().map_err(|_| bad())?,
        b.trim().parse().map_err(|_| bad())?,
    ))
}

/// A tile size: `WxH`, or `N` for N x N, each 1 to 65536 pixels.
pub fn parse_tile(text: &str) -> Result<exr::math::Vec2<usize>, String> {
    let bad = || format!("tile size '{text}': expected WxH or N, 1 to 65536 pixels each");
    let number = |t: &str| {
        t.trim()
            .parse::<usize>()
            .ok()
            .filter(|n| (1..=65536).contains(n))
            .ok_or_else(bad)
    };
    match text.split_once(['x', 'X']) {
        Some((w, h)) => Ok(exr::math::Vec2(number(w)?, number(h)?)),
        None => number(text).map(|n| exr::math::Vec2(n, n)),
    }
}

fn parse_level(text: &str) -> Result<exr::math::Vec2<usize>, String> {
    let number = |t: &str| {
        t.trim()
            .parse::<usize>()
            .map_err(|_| "expected N (a mipmap level) or X,Y (a ripmap level)".to_string())
    };
    match text.split_once(',') {
        Some((x, y)) => Ok(exr::math::Vec2(number(x)?, number(y)?)),
        None => number(text).map(|n| exr::math::Vec2(n, n)),
    }
}

fn parse_pair(text: &str) -> Result<(String, String), String> {
    let (x, y) = text.split_once(',').ok_or("expected X,Y")?;
    Ok((x.trim().to_string(), y.trim().to_string()))
}

fn parse_origin(text: &str) -> Result<(i32, i32), String> {
    let (x, y) = text.split_once(',').ok_or("expected X,Y")?;
    Ok((
        x.trim().parse().map_err(|_| "bad X")?,
        y.trim().parse().map_err(|_| "bad Y")?,
    ))
}
