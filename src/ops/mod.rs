//! Compositing operations, one family per file, as pure functions over strips.

pub mod over;
