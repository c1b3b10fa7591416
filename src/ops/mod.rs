//! Compositing operations, one family per file, as pure functions over
//! strips, each declared once (`declare::Operation`) and listed in `ALL`.

/// The colour config without `--config` or `$OCIO`: OCIO's ACES CG config as
/// the ocio crate embeds it (v4.0.0, ACES 2.0; PyPI's 2.6 names v5.0.0 so).
/// Outside `colour` so that a build without that feature (the fuzz crate)
/// still names it to farm workers.
pub const BUILTIN_COLOUR_CONFIG: &str = "ocio://cg-config-latest";

pub mod blur;
#[cfg(feature = "colour")]
pub mod colour;
pub mod crop;
pub mod declare;
pub mod defocus;
pub mod diffrender;
pub mod grade;
pub mod layers;
pub mod matte;
pub mod merge;
pub mod morphology;
pub mod premult;
pub mod reformat;
pub mod resize;
pub mod shuffle;
pub mod sources;
pub mod stereo;
#[cfg(test)]
pub mod testing;
pub mod transform;
pub mod vblur;
pub mod warp;
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
    #[cfg(feature = "colour")]
    &colour::colorconvert::COLORCONVERT,
    #[cfg(feature = "colour")]
    &colour::ociodisplay::OCIODISPLAY,
    #[cfg(feature = "colour")]
    &colour::ociolook::OCIOLOOK,
    #[cfg(feature = "colour")]
    &colour::cdl::CDL,
    #[cfg(feature = "colour")]
    &colour::filetransform::FILETRANSFORM,
    &resize::RESIZE,
    &crop::CROP,
    &crop::PAD,
    &reformat::REFORMAT,
    &transform::TRANSFORM,
];

pub fn find(name: &str) -> Option<&'static Operation> {
    ALL.iter().copied().find(|op| op.name == name)
}

#[cfg(test)]
mod tests {
    /// A parameter is a length in pixels (`{pixels}`, scaled by `--proxy-scale`)
    /// exactly when its help says it is in pixels: an op whose radius or
    /// shift is not declared one fails here, not in a proxy render.
    #[test]
    fn every_length_in_pixels_is_declared_one() {
        for op in super::ALL {
            for param in op.params {
                let says = param.help.to_lowercase().contains("pixel");
                assert_eq!(
                    says,
                    param.pixels.is_some(),
                    "op '{}' parameter '{}': its help {} pixels but it is {}declared {{pixels}}",
                    op.name,
                    param.name,
                    if says {
                        "speaks of"
                    } else {
                        "does not speak of"
                    },
                    if param.pixels.is_some() { "" } else { "not " },
                );
            }
        }
    }

    /// Each kind of length scales as specs/ops.md ("--proxy-scale") says.
    #[test]
    fn lengths_scale_by_their_kind() {
        let scaled = |op: &str, name: &str, text: &str, factor: f64| {
            let param = super::find(op).unwrap().param(name).unwrap();
            (param.pixels.unwrap())(text, factor).unwrap()
        };
        assert_eq!(scaled("blur", "radius", "5", 0.5), "3");
        assert_eq!(scaled("stereo", "disparity", "5", 0.5), "2.5");
        assert_eq!(scaled("crop", "region", "41x30+3-5", 0.5), "1,-3,21,12");
        assert_eq!(scaled("pad", "by", "1,2,3,4", 0.5), "1,1,2,2");
        assert_eq!(scaled("resize", "size", "1920x1081", 0.5), "960x541");
        assert_eq!(scaled("reformat", "format", "HD_1080", 0.25), "480x270:1");
        assert_eq!(
            scaled("reformat", "format", "2K_Cinemascope", 0.5),
            "914x778:2"
        );
        assert_eq!(scaled("transform", "translate", "3,-1", 0.5), "1.5,-0.5");
    }

    /// specs/job-format.md's table of op nodes lists every operation and each
    /// of its parameters (a row saying "as merge" shares merge's keys).
    #[test]
    fn the_job_format_lists_every_operation_and_parameter() {
        let spec = include_str!("../../specs/job-format.md");
        let row = |name: &str| {
            spec.lines()
                .find(|l| l.starts_with("| `op = ") && l.contains(&format!("\"{name}\"")))
        };
        for op in super::ALL {
            let Some(mut line) = row(op.name) else {
                panic!("specs/job-format.md has no row for op '{}'", op.name)
            };
            if line.contains("as merge") {
                line = row("merge").expect("merge's row");
            }
            for param in op.params {
                let (plain, valued) = (format!("`{}`", param.name), format!("`{} = ", param.name));
                assert!(
                    line.contains(&plain) || line.contains(&valued),
                    "specs/job-format.md's row for '{}' lacks `{}`",
                    op.name,
                    param.name
                );
            }
        }
    }
}
