//! `reformat`: an image into a format, as Nuke's Reformat: resized to the
//! format's width or height (aspect kept), to fit inside it or fill it, or
//! distorted to it (`resize`'s passes), then placed at the format's corner or
//! centred (`crop`'s placement); the display window is the format. At scale
//! 1 the image is copied and moved, so its chunks pass through. Formats by
//! Nuke's names or WxH. Rules: specs/ops.md, "reformat".

use super::crop::Crop;
use super::declare::{input, params, Args, Length, Operation, Value};
use super::resize::{passes, Filter, Fit, Size, Target};
use crate::engine::graph::{GraphBuilder, NodeId};
use exr::meta::attribute::IntegerBounds;

pub const REFORMAT: Operation = Operation {
    name: "reformat",
    about: "Resize into a format (Nuke's Reformat): --format HD_1080|UHD_4K|2K_DCP|...|WxH \
            becomes the display window, the image scaled by --fit and placed at its corner or \
            --center",
    inputs: &[input("input", "Input file or sequence, `:PART` for a part")],
    repeats: false,
    params: Params::PARAMS,
    layers: false,
    straight: false,
    header: Some(0),
    build,
    measure: None,
};

params! {
    pub struct Params {
        /// A format by Nuke's name (HD_1080, UHD_4K, 2K_DCP, 4K_DCP...) or WxH pixels.
        format: Format {pixels},
        /// width, height (aspect kept), fit (inside), fill (covering) or distort.
        fit: Fit = "width",
        /// Centre the image in the format (else at its top left corner).
        center: bool,
        /// box, triangle, gaussian, mitchell or lanczos3.
        filter: Filter = "mitchell",
    }
}

/// Nuke's built-in formats: name, width, height and pixel aspect ratio
/// (sources: specs/ops.md, "reformat"). The ratio is not applied to the
/// resize nor written to the header (`--attrib pixelAspectRatio=R` writes it).
pub const FORMATS: &[(&str, usize, usize, f32)] = &[
    ("PC_Video", 640, 480, 1.0),
    ("NTSC", 720, 486, 0.91),
    ("PAL", 720, 576, 1.09),
    ("NTSC_16:9", 720, 486, 1.21),
    ("PAL_16:9", 720, 576, 1.46),
    ("HD_720", 1280, 720, 1.0),
    ("HD_1080", 1920, 1080, 1.0),
    // Nuke 7's name for HD_1080.
    ("HD", 1920, 1080, 1.0),
    ("UHD_4K", 3840, 2160, 1.0),
    ("1K_Super_35(full-ap)", 1024, 778, 1.0),
    ("1K_Cinemascope", 914, 778, 2.0),
    ("2K_Super_35(full-ap)", 2048, 1556, 1.0),
    ("2K_Cinemascope", 1828, 1556, 2.0),
    ("2K_DCP", 2048, 1080, 1.0),
    ("4K_Super_35(full-ap)", 4096, 3112, 1.0),
    ("4K_Cinemascope", 3656, 3112, 2.0),
    ("4K_DCP", 4096, 2160, 1.0),
    ("square_256", 256, 256, 1.0),
    ("square_512", 512, 512, 1.0),
    ("square_1K", 1024, 1024, 1.0),
    ("square_2K", 2048, 2048, 1.0),
];

/// A format's size: a name from `FORMATS` (any case) or WxH.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Format(pub Size);

impl Value for Format {
    fn parse(text: &str) -> Result<Self, String> {
        let named = FORMATS
            .iter()
            .find(|f| f.0.eq_ignore_ascii_case(text.trim()));
        match named {
            Some(&(_, width, height, _)) => Ok(Format(Size { width, height })),
            None => Size::parse(text).map(Format).map_err(|_| {
                let names: Vec<&str> = FORMATS.iter().map(|f| f.0).collect();
                format!(
                    "unknown format '{text}': expected WxH or one of {}",
                    names.join(", ")
                )
            }),
        }
    }
}

/// A named format's size scaled as a WxH one.
impl Length for Format {
    fn scaled(text: &str, factor: f64) -> Result<String, String> {
        let Format(size) = Format::parse(text)?;
        Size::scaled(&format!("{}x{}", size.width, size.height), factor)
    }
}

fn build(args: &Args, graph: &mut GraphBuilder, inputs: &[NodeId]) -> Result<NodeId, String> {
    let p = Params::read(args)?;
    let size = p.format.0;
    let resized = passes(Target::Fit(size, p.fit), p.filter, inputs[0], graph);
    let format = IntegerBounds::new((0, 0), (size.width, size.height));
    Ok(graph.add(Crop::place(format, p.center), &[resized]))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn formats_by_name_or_size() {
        let size = |w, h| {
            Ok(Format(Size {
                width: w,
                height: h,
            }))
        };
        assert_eq!(Format::parse("2K_DCP"), size(2048, 1080));
        assert_eq!(Format::parse("uhd_4k"), size(3840, 2160));
        assert_eq!(Format::parse("1000x500"), size(1000, 500));
        assert!(Format::parse("HD_1081").unwrap_err().contains("HD_1080"));
        assert_eq!(Format::parse("hd"), size(1920, 1080));
        assert_eq!(Format::parse("2K_Cinemascope"), size(1828, 1556));
        assert_eq!(Format::parse("PAL_16:9"), size(720, 576));
        // Nuke's ratios, as its Python guide prints them (0.91, 1.09) and
        // its anamorphic formats have them.
        let ratio = |name: &str| FORMATS.iter().find(|f| f.0 == name).unwrap().3;
        assert_eq!(
            [
                "NTSC",
                "PAL",
                "NTSC_16:9",
                "PAL_16:9",
                "4K_Cinemascope",
                "HD_1080"
            ]
            .map(ratio),
            [0.91, 1.09, 1.21, 1.46, 2.0, 1.0]
        );
    }
}
