//! Files: frame sequences, the EXR reader and writer.

pub mod reader;
pub mod sequence;
pub mod writer;
