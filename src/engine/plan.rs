//! A job: input sequences through a graph into an output sequence, what
//! each output frame reads, and how it is written. What one frame needs is
//! planned from it in `frame_plan.rs`.

use super::graph::Graph;
use crate::error::Result;
use crate::io::attributes::Edits;
use crate::io::reader::ExrFile;
use crate::io::sequence::{FramePattern, InputTime};
use exr::math::Vec2;
use exr::meta::attribute::IntegerBounds;
use exr::prelude::Compression;
use std::path::PathBuf;
use std::sync::Arc;

/// Most bytes one strip may take, every node's rows together: a few strips
/// are in flight at once (decoded, composed, encoded), so this keeps a frame
/// within a gigabyte or so. One block of rows over it is refused: only a
/// data window millions of pixels wide (a damaged header, or inputs far
/// apart) comes near it; real frames take a few megabytes per block.
pub const MAX_STRIP_BYTES: usize = 256 << 20;

/// How the output's pixels are laid out in blocks.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum OutputBlocks {
    /// As the part the header comes from: tiles of its size (one level) if
    /// it is tiled, else scanlines; as oiiotool keeps an input's tiling, and
    /// so that a tiled input's untouched tiles can be copied.
    FollowInput,
    /// Scanlines (`--scanline`).
    Scanlines,
    /// Tiles of this size, one level (`--tile`).
    Tiles(Vec2<usize>),
}

/// A job: input sequences through a graph into an output sequence.
pub struct Job {
    pub inputs: Vec<FramePattern>,
    /// Per input, which of its frames each output frame reads (`FILE@+10`);
    /// `frames` holds the result, missing frames resolved.
    pub times: Vec<InputTime>,
    /// Per input, the part asked for (`file.exr:PART` or `--part`).
    pub parts: Vec<Option<String>>,
    /// The view asked for: picks the part of that view in multi-part files.
    pub view: Option<String>,
    /// The level read of mipmapped and ripmapped inputs (x, y; a mipmap's
    /// level n is (n, n)); `None` reads level 0.
    pub level: Option<Vec2<usize>>,
    /// Per input, more deep files whose samples merge with its own before
    /// they are flattened (`deepmerge`); empty for most.
    pub merged: Vec<Vec<FramePattern>>,
    pub output: FramePattern,
    /// Per output frame, where each input comes from.
    pub frames: Vec<FrameSources>,
    pub graph: Graph,
    /// Output compression; `None` keeps that of the input the header comes from.
    pub compression: Option<Compression>,
    /// Scanlines or tiles for the output.
    pub blocks: OutputBlocks,
    pub header_base: HeaderBase,
    /// Rows per strip (rounded up to whole blocks); `None` sizes by bytes.
    pub strip_rows: Option<usize>,
    /// libdeflate level for ZIP and ZIPS output.
    pub zip_level: u8,
    /// Skip frames whose output exists and decodes completely.
    pub resume: bool,
    /// A frame whose input is bad is reported and the run goes on.
    pub keep_going: bool,
    /// Write only rows `y0..y1` of each frame (a band, for `stitch`).
    pub rows: Option<(i32, i32)>,
    /// `--max-output-pixels`: the most pixels an output frame may have
    /// (`None`: the default, `output_limit::limit`).
    pub max_output_pixels: Option<u64>,
    /// Run the graph on every part of the one input, one after the other,
    /// into the parts of one output (`--all-parts`).
    pub all_parts: bool,
    /// The user's edits of the output's attributes (`--attrib`, `--timecode`...).
    pub attributes: Edits,
    /// Review media (PNG, JPEG, TIFF, a movie) instead of EXR: how they are written.
    pub media: Option<Review>,
    /// The slate this run writes before its frames (`--slate`), if any.
    pub slate: Option<SlateFrame>,
    /// Per input, its first file read, opened as the job was made
    /// (`run::first_files`); empty for a job of no inputs.
    pub first_files: Vec<Option<FirstFile>>,
}

/// An input's first file read (its first frame not made black), opened
/// before the run for what is read of it then (luminance, warnings): the
/// plan of `frame`, the first output frame reading it, reads it rather than
/// opening it again, so that each input frame is opened once a run.
pub struct FirstFile {
    /// The output frame reading it.
    pub frame: i64,
    /// The input's frame it is.
    pub read: i64,
    pub file: Arc<ExrFile>,
}

/// A review media output: its format's options, and a burn-in.
#[derive(Clone, Debug)]
pub struct Review {
    pub media: crate::io::media::Media,
    pub burn_in: Option<crate::io::burn_in::BurnIn>,
    /// The movie every frame goes into, for a movie output (.mov, .mp4).
    pub movie: Option<Arc<crate::io::movie::Movie>>,
}

/// One output frame and, per input, the frame it reads.
#[derive(Clone, Debug, PartialEq)]
pub struct FrameSources {
    pub frame: i64,
    pub inputs: Vec<Source>,
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Source {
    /// This frame of the input sequence.
    Frame(i64),
    /// Transparent black, shaped like this frame of the input (its header,
    /// channels and display window).
    Black(i64),
}

impl Source {
    pub fn file_frame(self) -> i64 {
        match self {
            Source::Frame(f) | Source::Black(f) => f,
        }
    }
}

/// Where the output header's attributes come from.
#[derive(Debug)]
pub enum HeaderBase {
    /// The header of this input (the background, for merges).
    Input(usize),
    /// A new header with this display window (for generated images).
    New(IntegerBounds),
}

impl Job {
    /// Every file the job reads, and every file it writes with its frame.
    pub fn files(&self) -> (Vec<PathBuf>, Vec<(Option<i64>, PathBuf)>) {
        let mut reads = Vec::new();
        let mut writes = Vec::new();
        for sources in &self.frames {
            for (input, source) in self.inputs.iter().zip(&sources.inputs) {
                reads.push(input.path(source.file_frame()));
            }
            for merged in self.merged.iter().flatten() {
                reads.push(merged.path(sources.frame));
            }
            let frame = self.frame_label(sources.frame);
            writes.push((frame, self.output.path(sources.frame)));
        }
        (reads, writes)
    }

    pub fn frame_label(&self, frame: i64) -> Option<i64> {
        frame_label(&self.output, &self.inputs, frame)
    }

    /// Input `i`'s file for output frame `sources`: its first file, opened
    /// already, if this is the frame reading it (`FirstFile`), else opened
    /// now.
    pub fn input_file(&self, i: usize, sources: &FrameSources) -> Result<Arc<ExrFile>> {
        let source = sources.inputs[i];
        if let Some(Some(first)) = self.first_files.get(i) {
            if first.frame == sources.frame && source == Source::Frame(first.read) {
                return Ok(first.file.clone());
            }
        }
        let at = source.file_frame();
        let file = ExrFile::open(&self.inputs[i].path(at), self.frame_label(at))?;
        Ok(Arc::new(file))
    }
}

/// Frame numbers appear in messages only for sequences (of `output` or
/// `inputs`).
pub fn frame_label(output: &FramePattern, inputs: &[FramePattern], frame: i64) -> Option<i64> {
    let sequence = output.is_sequence() || inputs.iter().any(|p| p.is_sequence());
    sequence.then_some(frame)
}

/// Which frame is the slate (`--slate`) and the shot's frames it introduces.
#[derive(Clone, Debug, PartialEq)]
pub struct SlateFrame {
    pub frame: i64,
    /// The shot's frames, as `--frames` takes them (`1001-1100`).
    pub range: String,
}
