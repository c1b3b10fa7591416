//! Files: frame sequences, the EXR reader and writer, review media, and the
//! rows of pixels in memory they are decoded into (`rows`). Nothing here
//! imports the engine or the front ends.

pub mod attributes;
pub mod b44;
pub mod burn_in;
pub mod deep;
pub mod deflate;
pub mod dpx_out;
pub mod foreign;
pub mod header_text;
pub mod jpeg_out;
pub mod limits;
pub mod media;
pub mod movie;
pub mod overwrite;
pub mod parts;
pub mod positioned;
pub mod reader;
pub mod rows;
pub mod sequence;
pub mod standard_attributes;
pub mod stitch;
pub mod subsampling;
pub mod text;
pub mod tiles;
pub mod timecode;
pub mod writer;
pub mod zip;
