//! The command line.

use clap::{Args, Parser, Subcommand};
use std::path::PathBuf;

#[derive(Parser)]
#[command(
    name = "exrcomp",
    version,
    about = "Streaming OpenEXR sequence compositor"
)]
pub struct Cli {
    /// Worker threads (default: one per core).
    #[arg(long, global = true)]
    pub threads: Option<usize>,
    #[command(subcommand)]
    pub command: Command,
}

#[derive(Subcommand)]
pub enum Command {
    /// Composite FG over BG: C = Cfg + (1 - Afg) Cbg (premultiplied).
    Over {
        /// Foreground: a file or a sequence (fg.####.exr, fg.%04d.exr).
        fg: String,
        /// Background: its header, display window and other channels are kept.
        bg: String,
        /// Output file or sequence.
        #[arg(short, long)]
        output: String,
        /// Inputs are unpremultiplied (straight) colour.
        #[arg(long)]
        straight: bool,
        #[command(flatten)]
        run: RunArgs,
    },
    /// Read and write a sequence unchanged but for compression (the codec floor).
    Transcode {
        input: String,
        #[arg(short, long)]
        output: String,
        #[command(flatten)]
        run: RunArgs,
    },
    /// Describe EXR files and check that every chunk decodes.
    Info {
        #[arg(required = true)]
        files: Vec<PathBuf>,
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
    /// Rows per strip, rounded up to whole output blocks (for tests of strip
    /// boundaries; the default sizes strips by bytes).
    #[arg(long, hide = true)]
    pub strip_rows: Option<usize>,
}

fn parse_origin(text: &str) -> Result<(i32, i32), String> {
    let (x, y) = text.split_once(',').ok_or("expected X,Y")?;
    Ok((
        x.trim().parse().map_err(|_| "bad X")?,
        y.trim().parse().map_err(|_| "bad Y")?,
    ))
}
