//! The black-box suites, one test binary: each module runs the built exrcomp
//! (and the peers) on real files; the maths of each operation is tested in
//! memory beside it in src/.

mod attributes;
mod bench;
mod bench_report;
mod blur;
#[cfg(feature = "colour")]
mod colour;
mod colour_auto;
mod colour_metadata;
mod common;
mod crop;
mod damaged_corpus;
mod deep;
mod depth_and_motion;
mod diffrender_and_zmerge;
mod dpx_output;
mod farm;
mod first_run;
mod foreign_inputs;
mod foreign_jpeg;
mod foreign_png;
mod foreign_tiff;
mod grades;
mod hostile;
mod input_opens;
mod job_files;
mod layers_and_parts;
mod luminance_chroma;
mod matting;
mod memory;
mod merge_ops;
mod metadata_and_time;
mod movie;
mod opaque;
mod over_reference;
mod overnight;
mod passthrough;
mod passthrough_moved;
mod peers;
mod proxy;
mod real_files;
mod resize;
mod resize_same;
mod review_media;
mod sequences_and_errors;
mod shuffle;
mod slate;
mod stack;
mod stage_times;
mod stale_frames;
mod tiled;
mod tiled_output;
mod transform;
mod transform_exact;
mod views_and_parts;
