//! Compositing operations, one family per file, as pure functions over
//! strips, each declared once (`declare::Operation`) and listed in `ALL`.

pub mod blur;
pub mod declare;
pub mod defocus;
pub mod diffrender;
pub mod grade;
pub mod layers;
pub mod matte;
pub mod merge;
pub mod morphology;
pub mod premult;
pub mod shuffle;
pub mod stereo;
pub mod vblur;
pub mod zmerge;

use declare::Operation;

/// Every operation, as the command line lists them: adding an operation is
/// its file and one line here.
pub const ALL: &[&Operation] = &[
    &merge::OVER,
    &merge::MERGE,
    &merge::STACK,
    &premult::PREMULT,
    &premult::UNPREMULT,
    &blur::BLUR,
    &defocus::DEFOCUS,
    &vblur::VBLUR,
    &stereo::STEREO,
    &zmerge::ZMERGE,
    &diffrender::DIFFRENDER,
    &matte::KEY,
    &matte::DIFFMATTE,
    &matte::TRIANGULATE,
    &morphology::ERODE,
    &morphology::DILATE,
    &grade::GRADE,
    &grade::EXPOSURE,
    &grade::SATURATION,
    &shuffle::SHUFFLE,
    &shuffle::COPY,
];

pub fn find(name: &str) -> Option<&'static Operation> {
    ALL.iter().copied().find(|op| op.name == name)
}
