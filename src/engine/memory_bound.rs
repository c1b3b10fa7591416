//! The most memory one frame's run holds at once, from its plan: the bound
//! of specs/architecture.md ("Memory bound", and "Regions of interest" for
//! nodes that stream at another size), which a farm job asks of its workers.

use super::frame_plan::{output_grid, FramePlan};
use super::graph::{Band, Graph, Node};
use super::plan::Job;
use super::region::Regions;
use exr::meta::attribute::IntegerBounds;
use exr::prelude::Compression;

/// Program, thread stacks and allocator.
const PROGRAM: u64 = 10 << 20;

/// Samples below which a band is not worth a task of its own.
const MIN_BAND_SAMPLES: usize = 16 << 10;

/// Rows per band for `rows` rows `width` wide: a few bands per thread, so
/// that uneven bands even out, none smaller than `MIN_BAND_SAMPLES`.
pub fn band_rows(rows: usize, width: usize) -> usize {
    let bands = 4 * rayon::current_num_threads();
    let floor = MIN_BAND_SAMPLES.div_ceil(width.max(1));
    rows.div_ceil(bands).max(floor).max(1)
}

/// Bytes at most resident while `plan` runs through its job's graph:
///
/// ```text
/// Σ_inputs D_i + max_inputs Z_i
///     + max_live Σ W_n (S_n + 2 h_n) b_n + (4 + c_o + 2 B) S W b_o
///     + max_n T scratch_n + T codec + Σ_inputs D_i + J + 10 MiB
/// ```
///
/// with, for a ZIP input, `D_i = max(2 A_i W_i + a_i (A_i + 2 L_i) R_i,
/// a_i (F_i + 2 L_i) R_i) b_i` (the strip being built and the one in the
/// channel; chunks decoded apart from the strip, `a_i` 1 unless they
/// inflate straight into it, `decode::direct`) and `Z_i = (min(T L_i,
/// F_i + 2 L_i) + (1 - a_i) (A_i + 2 L_i)) R_i b_i` (its chunks read, at most T
/// over all inputs, and a strip's chunks the heap keeps: `DecodeTerms`);
/// for other codecs `D_i = max(3 (A_i + 2 L_i) R_i + 2 A_i W_i, (F_i + 2
/// L_i + 2 min(T L_i, F_i + 2 L_i)) R_i) b_i` and `Z_i = 0`. `W` and `S`
/// are the output's width and strip rows (at most the rows computed: a
/// strip never holds more), `W_n` a node's region's width (`W_i` an
/// input's) and `S_n` the most rows of its region a strip spans (`S` where
/// nothing resamples), `R_i` the width an input is decoded over (its data
/// window read, its chunks' width: none for a black input), `F_i` the rows
/// its first strip reads (its span, which its window then holds) and `A_i`
/// the most a later one reads (what its span gained: `S` where nothing
/// resamples), `T` the threads, and `B` the batches of chunks the writer
/// lets wait (`writer::IN_FLIGHT`), each with its bytes laid out. An input
/// read whole (its span its whole region: a turn near 90 degrees, readers
/// that disagree) is decoded once: its chunks decoded apart, the strip
/// built of them and `c_i min(T L_i, S_i + 2 L_i) R_i b_i` in flight.
/// `scratch_n` is a band's own buffers (`Op::scratch`), the nodes computed
/// one after another; `codec` each thread's ZIP buffers
/// (`codec_per_thread`), which hold what a ZIP input inflates and a ZIP
/// output transforms: `c_i` is 1 for a ZIP input (2 otherwise), `c_o` 0
/// for a ZIP output (1 otherwise). `D_i` is what a foreign input's row
/// reader holds (`ExrFile::decoder_bytes`: a TIFF's strip, a PNG's
/// inflate state and row; 0 for EXR, DPX and Cineon). `J` is a JPEG
/// output's bands waiting to be encoded and written (`jpeg_out::resident`;
/// 0 for other outputs).
pub fn memory_bound(plan: &FramePlan, job: &Job) -> u64 {
    let graph = plan.graph(job);
    let s = plan.strip_rows.min(plan.computed.size.height()) as u64;
    let threads = rayon::current_num_threads() as u64;
    let spans = spanned_rows(graph, &plan.regions, plan.computed, plan.strip_rows);
    let bytes = |channels: &[exr::meta::attribute::ChannelDescription]| {
        channels
            .iter()
            .map(|c| c.sample_type.bytes_per_sample() as u64)
            .sum::<u64>()
    };
    let reads = read_rows(plan, graph);
    // At most T chunks are in flight over all inputs (one pool, the inputs
    // of a strip decoded together or one after another): the largest
    // input's share is counted once.
    let (held, shared) = (0..plan.inputs.len())
        .map(|i| {
            let b = bytes(&plan.header_of(i).channels.list);
            let terms = decode_bytes(plan, graph, &spans, i, reads[i]);
            (terms.held * b, terms.shared * b)
        })
        .fold((0, 0), |(held, shared), (h, f)| (held + h, shared.max(f)));
    let decode = held + shared;
    let held = window_rows(graph, &spans);
    let windows = graph.peak(|n| {
        let width = plan.regions.rect(n).size.width();
        width * held[n] * bytes(&plan.channels[n]) as usize
    });
    let width = plan.computed.size.width() as u64;
    let waiting = 2 * crate::io::writer::IN_FLIGHT as u64;
    // A ZIP block's transform is in the threads' codec buffers.
    let strips = 5 + waiting - deflates(plan, job) as u64;
    let encode = strips * s * width * bytes(&plan.header.channels.list);
    let scratch = scratch(plan, graph, &spans) * threads;
    let codec = codec_per_thread(plan, job) * threads;
    // A foreign input's row reader (io::foreign::Rows::resident).
    let readers: u64 = plan.inputs.iter().map(|f| f.decoder_bytes()).sum();
    let jpeg = match &job.media {
        Some(review) if review.media.format == crate::io::media::Format::Jpeg => {
            crate::io::jpeg_out::resident(width as usize, review.media.quality, s as usize)
        }
        _ => 0,
    };
    decode + windows as u64 + encode + scratch + codec + readers + jpeg + PROGRAM
}

fn is_zip(compression: Compression) -> bool {
    matches!(compression, Compression::ZIP1 | Compression::ZIP16)
}

/// Whether the output's blocks are deflated here (`zip::compress`).
fn deflates(plan: &FramePlan, job: &Job) -> bool {
    job.media.is_none() && is_zip(plan.header.compression)
}

/// Whether input `i`'s chunks are inflated here (`zip::unpack`).
fn inflates(plan: &FramePlan, i: usize) -> bool {
    plan.deep[i].is_none() && is_zip(plan.header_of(i).compression)
}

/// Bytes each pool thread keeps all run once it has inflated or deflated a
/// ZIP block (the thread-locals of `zip.rs` and `deflate.rs`, reused and
/// never freed, so on every thread however few blocks a strip has): the
/// largest block inflated or transformed, the deflate data of a block read
/// with its padding, the deflate output and the compressors.
fn codec_per_thread(plan: &FramePlan, job: &Job) -> u64 {
    let block_bytes = |block: exr::math::Vec2<usize>, header: &exr::meta::header::Header| {
        (block.x() * block.y() * header.channels.bytes_per_pixel) as u64
    };
    let read = (0..plan.inputs.len())
        .filter(|&i| inflates(plan, i))
        .map(|i| block_bytes(plan.levels[i].block, plan.header_of(i)))
        .max()
        .unwrap_or(0);
    let written = match deflates(plan, job) {
        true => block_bytes(output_grid(&plan.header).block, &plan.header),
        false => 0,
    };
    let padded = match read {
        0 => 0,
        _ => read + crate::io::zip::PADDING as u64,
    };
    let deflated = match written {
        0 => 0,
        _ => written + written / 512 + crate::io::deflate::state_bytes(job.zip_level) as u64,
    };
    read.max(written) + padded + deflated
}

/// Input `i`'s decode terms, in samples (times its bytes per pixel: the
/// bound's first two terms).
struct DecodeTerms {
    /// What it holds whatever the other inputs do: its strips and the
    /// chunks decoded apart from them.
    held: u64,
    /// What the inputs' decodes share, counted for the largest (ZIP only;
    /// other codecs' are in `held`): its chunks being read and inflated,
    /// at most one per thread over all inputs, and where they inflate
    /// straight into the strip, a strip's chunks more: the heap keeps
    /// freed chunk and strip buffers (one arena, untrimmed), and without
    /// them a 4K noise blur at 8 threads peaked at 119.8 MiB over a bound
    /// of 116.
    shared: u64,
}

/// Input `i`'s decode terms beside its window (`read`: the rows its first
/// strip reads and the most a later one does). Chunks are as wide as the
/// input's data window (`R_i`), strips as its region (`W_i`: a crop's
/// narrower, a small input's wider).
fn decode_bytes(
    plan: &FramePlan,
    graph: &Graph,
    spans: &[usize],
    i: usize,
    read: (u64, u64),
) -> DecodeTerms {
    let width = plan.read[i].size.width() as u64;
    let strip_width = graph
        .input_node(i)
        .map_or(plan.computed, |n| plan.regions.rect(n))
        .size
        .width() as u64;
    let threads = rayon::current_num_threads() as u64;
    let s = plan.strip_rows.min(plan.computed.size.height()) as u64;
    let rows = graph.input_node(i).map_or(s, |n| spans[n] as u64);
    let lines = plan.levels[i].block.y() as u64;
    let whole = !plan.regions.shared()
        && graph
            .input_node(i)
            .is_some_and(|n| spans[n] >= plan.regions.rect(n).size.height());
    // Chunks decoded apart from the strip (all but ZIP's: `decode::direct`),
    // which becomes the input's window.
    let direct = decodes_direct(plan, graph, i);
    let apart = |rows: u64| {
        if direct {
            0
        } else {
            (rows + 2 * lines) * width
        }
    };
    // A chunk's bytes read and inflated per thread; ZIP inflates into the
    // thread's own buffer (`codec_per_thread`).
    let zip = inflates(plan, i);
    let copies = 2 - zip as u64;
    let in_flight = |rows: u64| copies * (threads * lines).min(rows + 2 * lines) * width;
    let (held, shared) = match whole {
        // Decoded once: its chunks, the strip built of them (unless they
        // were decoded into it), and the chunks in flight.
        true if direct => (0, in_flight(rows)),
        true => (apart(rows) + rows * strip_width, in_flight(rows)),
        // The first strip reads the rows of its span (the window then
        // holds them); each later one only those its span gained: its
        // chunks decoded apart, the strip built of them and the one in the
        // channel; ZIP chunks read one per thread at most, freed once
        // inflated. (A strip's rows at least where spans are strips: the
        // last strip may be shorter, the bound is the steady state's.)
        false => {
            let (first, later) = read;
            let later = later.max(s.min(first));
            let strips = 2 * later * strip_width;
            match zip {
                true => (
                    (apart(later) + strips).max(apart(first)),
                    in_flight(first.max(later)) + direct as u64 * (later + 2 * lines) * width,
                ),
                // Other codecs' intermediates (PIZ's Huffman tables) are
                // not counted apart: all of a strip's chunks read and
                // decompressed, on this input's account.
                false => (
                    ((1 + copies) * (later + 2 * lines) * width + strips)
                        .max(apart(first) + in_flight(first)),
                    0,
                ),
            }
        }
    };
    match zip {
        true => DecodeTerms { held, shared },
        false => DecodeTerms {
            held: held + shared,
            shared: 0,
        },
    }
}

/// Whether input `i`'s chunks decode straight into its strips (as
/// `decode::direct` finds when it reads them): ZIP, no subsampling, flat,
/// its region inside its data window from a block's first row.
fn decodes_direct(plan: &FramePlan, graph: &Graph, i: usize) -> bool {
    let header = plan.header_of(i);
    let window = plan.read[i];
    let region = graph
        .input_node(i)
        .map_or(plan.computed, |n| plan.regions.rect(n));
    let lines = plan.levels[i].block.y() as i32;
    plan.deep[i].is_none()
        && !crate::io::subsampling::any(header)
        && matches!(header.compression, Compression::ZIP1 | Compression::ZIP16)
        && window.position.x() <= region.position.x()
        && window.end().x() >= region.end().x()
        && window.position.y() <= region.position.y()
        && (region.position.y() - window.position.y()) % lines == 0
}

/// Per input, the rows its first strip reads and the most any later strip
/// reads (the pipeline's reads: each strip the rows of its input's span not
/// read yet, `plan::input_spans`).
fn read_rows(plan: &FramePlan, graph: &Graph) -> Vec<(u64, u64)> {
    let mut done: Vec<std::ops::Range<i32>> = (0..plan.inputs.len())
        .map(|i| {
            let first = match graph.input_node(i) {
                Some(n) if plan.regions.upward(n) => plan.regions.rect(n).end().y(),
                Some(n) => plan.regions.rect(n).position.y(),
                None => plan.computed.position.y(),
            };
            first..first
        })
        .collect();
    let mut reads = vec![(0, 0); plan.inputs.len()];
    for (k, rows) in plan.strips().enumerate() {
        for (i, span) in plan.input_spans(graph, rows.end).into_iter().enumerate() {
            let upward = graph.input_node(i).is_some_and(|n| plan.regions.upward(n));
            let done = &mut done[i];
            let read = match upward {
                true => span.start.min(done.start)..done.start,
                false => done.end..span.end.max(done.end),
            };
            *done = done.start.min(read.start)..done.end.max(read.end);
            let (first, later) = &mut reads[i];
            match k {
                0 => *first = read.len() as u64,
                _ => *later = (*later).max(read.len() as u64),
            }
        }
    }
    reads
}

/// The most scratch one band of a node holds (`Op::scratch`), over the
/// nodes: a band of the most rows a node computes at once, a strip's span
/// and the rows its own halo trailed by (a halo op's last strip).
fn scratch(plan: &FramePlan, graph: &Graph, spans: &[usize]) -> u64 {
    let width = |n: usize| plan.regions.rect(n).size.width();
    graph
        .nodes
        .iter()
        .enumerate()
        .map(|(n, node)| match node {
            Node::Op { op, inputs, .. } => {
                let rows = band_rows(spans[n] + op.halo(), width(n));
                let channels: Vec<&[_]> = inputs.iter().map(|&i| &plan.channels[i][..]).collect();
                let widths: Vec<usize> = inputs.iter().map(|&i| width(i)).collect();
                op.scratch(&Band {
                    rows,
                    width: width(n),
                    inputs: &channels,
                    widths: &widths,
                }) as u64
            }
            Node::Input(_) => 0,
        })
        .max()
        .unwrap_or(0)
}

/// Per node, the most rows its compose window holds at once: the most rows
/// of its region one strip spans (`spanned_rows`) and its consumers' halo
/// above and below. Compose makes room for them before a window first
/// grows, so that it never grows by moving (a Vec doubling: its new buffer
/// twice the rows, the old one left resident in the heap).
pub fn window_rows(graph: &Graph, spans: &[usize]) -> Vec<usize> {
    let mut halo = vec![0; graph.nodes.len()];
    for node in &graph.nodes {
        if let Node::Op { op, inputs, .. } = node {
            for &i in inputs {
                halo[i] = halo[i].max(op.halo());
            }
        }
    }
    (0..graph.nodes.len())
        .map(|n| spans[n] + 2 * halo[n])
        .collect()
}

/// Per node, the most rows of its region one strip of `strip_rows` rows of
/// `computed` spans: the strip's own where nothing resamples; behind a
/// resize or transform, the most its zone's span takes over the frame's
/// strips (the whole region for a zone read whole, a turn near 90 degrees).
pub fn spanned_rows(
    graph: &Graph,
    regions: &Regions,
    computed: IntegerBounds,
    strip_rows: usize,
) -> Vec<usize> {
    let s = strip_rows.clamp(1, computed.size.height().max(1));
    let mut most = vec![s; graph.nodes.len()];
    if regions.shared() {
        return most;
    }
    most.fill(0);
    let (top, bottom) = (computed.position.y(), computed.end().y());
    for start in (top..bottom).step_by(s) {
        let spans = regions.spans(graph, start..bottom.min(start + s as i32));
        for (n, most) in most.iter_mut().enumerate() {
            *most = (*most).max(regions.span(&spans, n).len());
        }
    }
    most
}
