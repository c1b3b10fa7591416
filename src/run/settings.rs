//! The run and write settings every job that writes files takes, declared
//! once: the command line's options are derived from them (clap), and the
//! job file's write keys are their names (src/run/job_file.rs).

pub use crate::io::header_text::CompressionName;
use crate::params::*;
use clap::Args;

/// The help's headings the run and write options are grouped under.
pub const FRAMES: &str = "Frames and sequences";
pub const LAYERS: &str = "Layers, views and parts";
pub const OUTPUT: &str = "Output";
pub const MEDIA: &str = "Review media and DPX (.png, .jpg, .tif, .mov, .mp4, .dpx outputs)";
pub const RUN_CONTROL: &str = "Run control";

/// Which layers, views and parts an operation works on.
#[derive(Args, Clone, Default)]
#[command(next_help_heading = LAYERS)]
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
    #[command(flatten)]
    pub part: PartArgs,
    /// Level of mipmapped inputs (N), or ripmapped ones (X,Y; N is N,N) to
    /// read instead of the full resolution (level 0).
    #[arg(long, value_parser = parse_level)]
    pub level: Option<exr::math::Vec2<usize>>,
}

/// The part of a multi-part input: every command reading EXR inputs takes
/// it, with or without layers.
#[derive(Args, Clone, Default)]
#[command(next_help_heading = LAYERS)]
pub struct PartArgs {
    /// Part (name or index) of inputs given without `:PART`.
    #[arg(long)]
    pub part: Option<String>,
}

/// Options every job that writes files takes.
#[derive(Args, Clone)]
pub struct RunArgs {
    /// Frames: A-B, A-B:STEP, or a comma list (default: those on disk).
    /// Frame numbers may be negative (`--frames -3-2`), so a value starting
    /// with `-` is the frames, not an option.
    #[arg(help_heading = FRAMES, long, allow_hyphen_values = true)]
    pub frames: Option<String>,
    /// Only the COUNT frames of --frames from FIRST on, FIRST a chunk's
    /// first frame: a farm task named by its first frame alone (OpenCue's
    /// #FRAME_START#, whose #FRAME_END# Cuebot before 1.0 gets wrong).
    #[arg(help_heading = FRAMES, long, value_name = "FIRST,COUNT", allow_hyphen_values = true, value_parser = parse_chunk_from)]
    pub chunk_from: Option<(i64, usize)>,
    /// What is written and how: the job file's write node takes these keys
    /// too.
    #[command(flatten)]
    pub write: WriteArgs,
    /// libdeflate's effort for ZIP and ZIPS output, 1 (fastest) to 12
    /// (smallest); noisy low-byte halves always take ISA-L's fastest level.
    /// The default 2 writes files within 2.5% of OpenEXR's size.
    #[arg(help_heading = OUTPUT, long, default_value_t = crate::io::deflate::DEFAULT_LEVEL, allow_negative_numbers = true, value_parser = clap::value_parser!(u8).range(1..=12))]
    pub zip_level: u8,
    /// DWAA and DWAB output's compression level, written as the file's
    /// `dwaCompressionLevel`: higher is smaller and coarser (default 45, as
    /// OpenEXR's).
    #[arg(help_heading = OUTPUT, long, allow_negative_numbers = true, value_parser = |t: &str| DWA_LEVEL.parse::<f32>(t))]
    pub dwa_level: Option<f32>,
    /// What a missing input frame does: error (before any work), skip the
    /// output frame, hold the nearest earlier frame, or black.
    #[arg(help_heading = FRAMES, long, value_enum, default_value = "error")]
    pub missing: crate::engine::sources::MissingPolicy,
    /// Skip frames whose output already exists and decodes completely.
    #[arg(help_heading = RUN_CONTROL, long)]
    pub resume: bool,
    /// Report a frame with bad input and go on with the others (the exit
    /// code is still non-zero).
    #[arg(help_heading = RUN_CONTROL, long)]
    pub keep_going: bool,
    /// No progress bar and no summary.
    #[arg(help_heading = RUN_CONTROL, long, short)]
    pub quiet: bool,
    /// Print a JSON summary on standard output at the end.
    #[arg(help_heading = RUN_CONTROL, long)]
    pub json: bool,
    /// Lines on standard output for a log or a farm: a line per frame
    /// (written, kept) by default when it is not a terminal (with --quiet
    /// too); openjd and deadline add their progress lines.
    #[arg(help_heading = RUN_CONTROL, long, value_enum, value_name = "FORMAT", conflicts_with = "json")]
    pub progress: Option<crate::run::report::FarmLog>,
    /// Check every frame's inputs and the outputs, print the files each
    /// output frame reads and writes (with --json as JSON), decode nothing
    /// and write nothing.
    #[arg(help_heading = RUN_CONTROL, long)]
    pub dry_run: bool,
    /// Write only rows Y0-Y1 of each frame (on the output's block grid): a
    /// band of a huge plate for one machine; `exrcomp stitch` joins them.
    #[arg(help_heading = FRAMES, long, allow_hyphen_values = true, value_parser = parse_rows)]
    pub rows: Option<(i32, i32)>,
    /// The most pixels an output frame may have (its data window); by
    /// default 64 times the largest input's (data or display window), at
    /// least 4096x4096, so that a typo's size is refused before it fills
    /// a volume. Generated plates have none.
    #[arg(help_heading = OUTPUT, long, value_name = "N", value_parser = clap::value_parser!(u64).range(1..))]
    pub max_output_pixels: Option<u64>,
    /// Run the whole graph at this fraction of the size (0.5: half), for
    /// previews: each input resized as it is read (resize's box filter),
    /// each operation's lengths in pixels (radii, regions, shifts) scaled.
    #[arg(help_heading = OUTPUT, long, allow_negative_numbers = true, value_parser = |t: &str| crate::params::PROXY_SCALE.parse::<f32>(t))]
    pub proxy_scale: Option<f32>,
    /// Rows per strip, rounded up to whole output blocks (for tests of strip
    /// boundaries; the default sizes strips by bytes).
    #[arg(long, hide = true)]
    pub strip_rows: Option<usize>,
    /// Told of each frame as it ends, for a front end's own progress (the
    /// Python package's): no option.
    #[arg(skip)]
    pub on_frame: Option<FrameHook>,
}

/// Called with a frame, what became of it, and how many of the run's
/// frames have ended, of how many (a frame the engine thread finished).
pub type FrameHook =
    std::sync::Arc<dyn Fn(i64, crate::run::report::Outcome, usize, usize) + Send + Sync>;

/// How the output is written: the options of every job that writes files,
/// and the keys of a job file's write node, which are their names with `_`
/// (src/run/job_file.rs). The command line's win over the job file's.
#[derive(Args, Clone, Default)]
pub struct WriteArgs {
    /// Output compression (each command's help lists the names and says
    /// its default, `compression_default` in src/cli/mod.rs).
    #[arg(help_heading = OUTPUT, long, value_parser = CompressionName::parse)]
    pub compression: Option<CompressionName>,
    /// Write tiled files with tiles of WxH pixels (N: NxN), one level
    /// (default: tiles as the background's if it is tiled, else scanlines).
    #[arg(help_heading = OUTPUT, long, value_parser = parse_tile)]
    pub tile: Option<exr::math::Vec2<usize>>,
    /// Write scanline files even when the background is tiled.
    #[arg(help_heading = OUTPUT, long, conflicts_with = "tile")]
    pub scanline: bool,
    /// Run the operation on every part of a multi-part input instead of one,
    /// each part keeping its own channels, windows and attributes; for
    /// operations of one input (specs/file-format.md, "Parts").
    #[arg(help_heading = FRAMES, long, conflicts_with = "rows")]
    pub all_parts: bool,
    /// Set an attribute of the output's header: NAME=VALUE, typed as oiiotool
    /// types it (an integer is an int, another number a float, else a
    /// string) or as :TYPE says (string, int, float, double, v2i, v2f, v3i,
    /// v3f, box2i, box2f, m33f, m44f, rational, timecode, keycode; values
    /// of several numbers separated by commas). Repeatable.
    #[arg(help_heading = OUTPUT, long = "attrib", value_name = "NAME=VALUE[:TYPE]", value_parser = crate::io::attributes::parse_attrib)]
    pub attribs: Vec<crate::io::attributes::Attrib>,
    /// Erase the output header's attributes of this name, or matching this
    /// glob (`*`, `?`), before --attrib sets any. Repeatable.
    #[arg(help_heading = OUTPUT, long = "erase-attrib", value_name = "NAME|GLOB", value_parser = crate::io::attributes::parse_erase)]
    pub erase_attribs: Vec<String>,
    /// Write each frame's timeCode: HH:MM:SS:FF (HH:MM:SS;FF drop-frame) for
    /// the shot's first frame, or @FRAME's (01:00:00:00@1001), counted at
    /// the frame rate; or +N / -N to shift the input's own by N frames.
    #[arg(help_heading = OUTPUT, long, value_name = "TIMECODE[@FRAME]|+N|-N", allow_hyphen_values = true, value_parser = crate::io::timecode::parse_spec)]
    pub timecode: Option<crate::io::timecode::TimecodeSpec>,
    /// Frame rate, written as framesPerSecond: N, N/D (24000/1001) or an
    /// NTSC rate as 23.976 (default: the input's).
    #[arg(help_heading = OUTPUT, long, value_name = "RATE", allow_hyphen_values = true, value_parser = crate::io::attributes::parse_fps)]
    pub fps: Option<exr::meta::attribute::Rational>,
    /// JPEG output's quality, 1 to 100 (default 90).
    #[arg(help_heading = MEDIA, long, allow_negative_numbers = true, value_parser = clap::value_parser!(u8).range(1..=100))]
    pub quality: Option<u8>,
    /// Bits per sample: PNG 8 or 16, TIFF 8, 16 or float (scene-linear, as
    /// it is); JPEG 8 (default 8); DPX 10 (default) or 16.
    #[arg(help_heading = MEDIA, long, value_enum)]
    pub bits: Option<crate::io::media::Bits>,
    /// What turns linear pixels into 8 or 16-bit code values: srgb (the sRGB
    /// curve, clamped; the default) or none (pixels that are display code
    /// values already, after ociodisplay).
    #[arg(help_heading = MEDIA, long, value_enum)]
    pub transfer: Option<crate::io::media::Transfer>,
    /// Text drawn into a corner of each frame, white on black; fields:
    /// {frame}, {frame:4} (zero-padded), {timecode}, {file} (the first
    /// input's), {output}, {attr:NAME}.
    #[arg(help_heading = MEDIA, long, value_name = "TEXT")]
    pub burn_in: Option<String>,
    /// The burn-in's corner (default bottom-left).
    #[arg(help_heading = MEDIA, long, value_enum)]
    pub burn_in_corner: Option<crate::io::burn_in::Corner>,
    /// A review movie's codec: prores (ProRes 422 HQ, .mov's default),
    /// prores4444 (with alpha), dnxhr (DNxHR 444) or h264 (.mp4's).
    #[arg(help_heading = MEDIA, long, value_enum)]
    pub codec: Option<crate::io::movie::Codec>,
    /// Write a slate first: frame (the shot's first - 1), black, with the
    /// job's output, frames, inputs, timecode, fps and attributes in white;
    /// only by a run that starts at the shot's first frame.
    #[arg(help_heading = OUTPUT, long)]
    pub slate: bool,
}

impl WriteArgs {
    /// These settings, the command line's, over `job`'s: an option given
    /// wins over the job's key, the lists follow the job's, and `--tile`
    /// wins over the job's `scanline`.
    pub fn over(self, job: WriteArgs) -> WriteArgs {
        WriteArgs {
            compression: self.compression.or(job.compression),
            all_parts: self.all_parts || job.all_parts,
            scanline: self.scanline || (self.tile.is_none() && job.scanline),
            tile: self.tile.or(job.tile),
            attribs: job.attribs.into_iter().chain(self.attribs).collect(),
            erase_attribs: job
                .erase_attribs
                .into_iter()
                .chain(self.erase_attribs)
                .collect(),
            timecode: self.timecode.or(job.timecode),
            fps: self.fps.or(job.fps),
            quality: self.quality.or(job.quality),
            bits: self.bits.or(job.bits),
            transfer: self.transfer.or(job.transfer),
            burn_in: self.burn_in.or(job.burn_in),
            burn_in_corner: self.burn_in_corner.or(job.burn_in_corner),
            codec: self.codec.or(job.codec),
            slate: self.slate || job.slate,
        }
    }

    /// The job file's write keys: the options' names with `_`.
    pub fn keys() -> Vec<String> {
        WriteArgs::augment_args(clap::Command::new("write"))
            .get_arguments()
            .filter_map(|arg| arg.get_long())
            .map(|long| long.replace('-', "_"))
            .collect()
    }
}

impl RunArgs {
    /// The options of a command line that gives none.
    pub fn none() -> Self {
        use clap::FromArgMatches;
        let command = Self::augment_args(clap::Command::new("run").no_binary_name(true));
        let matches = command.get_matches_from(std::iter::empty::<String>());
        Self::from_arg_matches(&matches).expect("no options parse")
    }

    /// The output's block layout these options ask for.
    pub fn blocks(&self) -> crate::engine::plan::OutputBlocks {
        use crate::engine::plan::OutputBlocks;
        match (self.write.tile, self.write.scanline) {
            (Some(size), _) => OutputBlocks::Tiles(size),
            (None, true) => OutputBlocks::Scanlines,
            (None, false) => OutputBlocks::FollowInput,
        }
    }
}

/// `FIRST,COUNT`: a chunk's first frame and its size (at least 1).
pub fn parse_chunk_from(text: &str) -> Result<(i64, usize), String> {
    let bad = || format!("expected FIRST,COUNT (a chunk's first frame, its frames), not '{text}'");
    let (first, count) = text.split_once(',').ok_or_else(bad)?;
    match (first.trim().parse(), count.trim().parse()) {
        (Ok(first), Ok(count)) if count >= 1 => Ok((first, count)),
        _ => Err(bad()),
    }
}

pub fn parse_rows(text: &str) -> Result<(i32, i32), String> {
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

pub fn parse_level(text: &str) -> Result<exr::math::Vec2<usize>, String> {
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_job_files_write_keys_are_the_write_options_names() {
        let keys = WriteArgs::keys();
        let expected = [
            "compression",
            "tile",
            "scanline",
            "all_parts",
            "attrib",
            "erase_attrib",
            "timecode",
            "fps",
            "quality",
            "bits",
            "transfer",
            "burn_in",
            "burn_in_corner",
            "codec",
            "slate",
        ];
        assert_eq!(keys, expected);
    }

    #[test]
    fn the_command_lines_write_settings_win_and_lists_follow_the_jobs() {
        let job = WriteArgs {
            compression: Some(CompressionName::Piz),
            scanline: true,
            erase_attribs: vec!["a".into()],
            ..WriteArgs::default()
        };
        let given = WriteArgs {
            compression: Some(CompressionName::Zip),
            tile: Some(exr::math::Vec2(32, 32)),
            erase_attribs: vec!["b".into()],
            ..WriteArgs::default()
        };
        let run = given.over(job);
        assert_eq!(run.compression, Some(CompressionName::Zip));
        assert!(!run.scanline, "--tile wins over the job's scanline");
        assert_eq!(run.erase_attribs, ["a", "b"]);
    }
}
