//! Files: frame sequences, the EXR reader and writer, review media.

pub mod attributes;
pub mod b44;
pub mod burn_in;
pub mod deep;
pub mod deflate;
pub mod media;
pub mod overwrite;
pub mod parts;
pub mod png;
pub mod reader;
pub mod sequence;
pub mod standard_attributes;
pub mod stitch;
pub mod subsampling;
pub mod text;
pub mod tiles;
pub mod timecode;
pub mod writer;
pub mod zip;
