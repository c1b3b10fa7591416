//! Compositing operations, one family per file, as pure functions over strips.

pub mod blur;
pub mod defocus;
pub mod diffrender;
pub mod layers;
pub mod matte;
pub mod merge;
pub mod morphology;
pub mod premult;
pub mod stereo;
pub mod vblur;
pub mod zmerge;
