//! What made a frame (specs/overnight.md, "Which job made a frame"): a hash
//! of everything that decides the output's bytes, written into the frame,
//! so that `--resume` keeps a frame only when this job, on these inputs,
//! would write it again.

use super::graph::Node;
use super::plan::{FrameSources, Job};
use crate::io::media::{self, Format};
use crate::io::reader::ExrFile;
use exr::meta::attribute::{AttributeValue, Text};
use exr::meta::header::Header;
use std::fmt::Write;
use std::path::Path;
use xxhash_rust::xxh3::Xxh3;

/// The EXR header attribute (a string) and the review media's text field
/// holding it.
pub const ATTRIBUTE: &str = crate::io::attributes::FINGERPRINT;

/// What the same job writes changes with the program: a new version redoes
/// every frame, rather than keep frames whose bytes it would not write.
const WRITER: &str = concat!("exrcomp ", env!("CARGO_PKG_VERSION"));

/// The part of a frame's fingerprint that is the job's own, the same for
/// every frame: the graph (each operation's every parameter, after
/// defaults, measured ones included: `Op`'s `Debug`) and the write
/// settings. Not the paths (a plate is known by its content, wherever a
/// farm worker mounts it), nor what only changes how the work is done
/// (threads, strips, `--resume`, `--keep-going`), nor `--rows`: a band's
/// frames carry the whole image's fingerprint, which `stitch` compares.
fn recipe(job: &Job) -> String {
    let mut text = String::from(WRITER);
    for node in &job.graph.nodes {
        // `origin` (a job file's line) is left out: it names, not makes.
        let _ = match node {
            Node::Input(i) => write!(text, "\ninput {i}"),
            Node::Op { op, inputs, .. } => write!(text, "\n{op:?} <- {inputs:?}"),
        };
    }
    let _ = write!(
        text,
        "\noutput {}\ntimes {:?} parts {:?} view {:?} level {:?} merged {}\n\
         compression {:?} blocks {:?} header {:?} zip {} all_parts {}\nattributes {:?}\nmedia {:?}",
        job.graph.output(),
        job.times,
        job.parts,
        job.view,
        job.level,
        job.merged.iter().map(Vec::len).sum::<usize>(),
        job.compression,
        job.blocks,
        job.header_base,
        job.zip_level,
        job.all_parts,
        job.attributes,
        job.media,
    );
    text
}

/// Frame `sources.frame`'s fingerprint: the job's `recipe`, the frame, and
/// what each file read is (`ExrFile::identity`: the inputs, then the deep
/// files merged into them), as 32 hex digits. A review frame whose burn-in
/// may show its own name also takes the name.
pub fn of_frame<'a>(
    job: &Job,
    sources: &FrameSources,
    files: impl Iterator<Item = &'a ExrFile>,
) -> String {
    let mut hash = Xxh3::new();
    hash.update(recipe(job).as_bytes());
    hash.update(format!("\nframe {} {:?}", sources.frame, sources.inputs).as_bytes());
    for file in files {
        hash.update(&file.identity().to_le_bytes());
    }
    if job.media.as_ref().is_some_and(|m| m.burn_in.is_some()) {
        let output = job.output.path(sources.frame);
        hash.update(output.file_name().unwrap_or_default().as_encoded_bytes());
    }
    format!("{:032x}", hash.digest128())
}

/// Writes `print` into `header`.
pub fn stamp(header: &mut Header, print: &str) {
    let value = AttributeValue::Text(Text::from_slice_unchecked(print.as_bytes()));
    (header.own_attributes.other).insert(Text::from(ATTRIBUTE), value);
}

/// The fingerprint `header` holds, if any.
pub fn read(header: &Header) -> Option<String> {
    match header.own_attributes.other.get(&Text::from(ATTRIBUTE)) {
        Some(AttributeValue::Text(text)) => String::from_utf8(text.bytes().to_vec()).ok(),
        _ => None,
    }
}

/// Whether the file at `path` (an EXR, or review media of `media`'s format)
/// is one `print` made: `None` when there is nothing there; `false` when a
/// part has another fingerprint or none, or it cannot be read.
pub fn made_by(path: &Path, media: Option<Format>, print: &str) -> Option<bool> {
    std::fs::symlink_metadata(path).ok()?;
    let ours = |found: Option<String>| found.as_deref() == Some(print);
    Some(match media {
        Some(format) => ours(media::note(path, format, ATTRIBUTE)),
        None => ExrFile::open(path, None)
            .is_ok_and(|file| file.meta.headers.iter().all(|h| ours(read(h)))),
    })
}
