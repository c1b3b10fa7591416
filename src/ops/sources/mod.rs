//! Nodes that make pixels rather than read them: generated plates and the
//! slate.

pub mod plate;
pub mod slate;
