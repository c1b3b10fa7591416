//! The streaming engine: a graph of nodes evaluated strip by strip.

pub mod assumptions;
pub mod compose;
pub mod decode;
pub mod deep_input;
pub mod encode;
pub mod fingerprint;
pub mod frame_plan;
pub mod graph;
pub mod interrupt;
pub mod luminance_chroma;
pub mod memory_bound;
pub mod opaque;
pub mod output_limit;
pub mod passthrough;
pub mod pipeline;
pub mod plan;
pub mod prepass;
pub mod provenance;
pub mod region;
pub mod sources;
