//! `reformat`: an image into a format, as Nuke's Reformat: resized to the
//! format's width or height (aspect kept), to fit inside it or fill it, or
//! distorted to it (`resize`'s passes), then placed at the format's corner or
//! centred (`crop`'s placement); the display window is the format, and the
//! pixel aspect ratio the format's (the picture keeps its shape across
//! them). At scale 1 the image is copied and moved, so its chunks pass
//! through. Formats by Nuke's names or WxH[:RATIO]. Rules: specs/ops.md,
//! "reformat".

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
        /// A format by Nuke's name (HD_1080, UHD_4K, 2K_DCP, 4K_DCP...) or WxH pixels,
        /// square or of a pixel aspect ratio after a colon (1828x1556:2).
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
/// (sources: specs/ops.md, "reformat").
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

/// A format: a name from `FORMATS` (any case), or WxH with square pixels
/// or `WxH:RATIO`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Format {
    pub size: Size,
    pub pixel_aspect: f32,
}

impl Value for Format {
    fn parse(text: &str) -> Result<Self, String> {
        let named = FORMATS
            .iter()
            .find(|f| f.0.eq_ignore_ascii_case(text.trim()));
        if let Some(&(_, width, height, pixel_aspect)) = named {
            let size = Size { width, height };
            return Ok(Format { size, pixel_aspect });
        }
        let (size, ratio) = text.split_once(':').unwrap_or((text, "1"));
        let pixel_aspect = ratio
            .trim()
            .parse::<f32>()
            .ok()
            .filter(|r| (0.01..=100.0).contains(r));
        match (Size::parse(size), pixel_aspect) {
            (Ok(size), Some(pixel_aspect)) => Ok(Format { size, pixel_aspect }),
            (Ok(_), None) => Err(format!(
                "format '{text}': the pixel aspect ratio after ':' must be a number from 0.01 \
                 to 100 (1828x1556:2)"
            )),
            (Err(_), _) => {
                let names: Vec<&str> = FORMATS.iter().map(|f| f.0).collect();
                Err(format!(
                    "unknown format '{text}': expected WxH, WxH:RATIO or one of {}",
                    names.join(", ")
                ))
            }
        }
    }
}

/// A format's size scaled as a WxH one, its ratio kept.
impl Length for Format {
    fn scaled(text: &str, factor: f64) -> Result<String, String> {
        let Format { size, pixel_aspect } = Format::parse(text)?;
        let size = Size::scaled(&format!("{}x{}", size.width, size.height), factor)?;
        Ok(format!("{size}:{pixel_aspect}"))
    }
}

fn build(args: &Args, graph: &mut GraphBuilder, inputs: &[NodeId]) -> Result<NodeId, String> {
    let p = Params::read(args)?;
    let Format { size, pixel_aspect } = p.format;
    let target = Target::Fit(size, pixel_aspect, p.fit);
    let resized = passes(target, p.filter, inputs[0], graph);
    let format = IntegerBounds::new((0, 0), (size.width, size.height));
    Ok(graph.add(Crop::place(format, p.center), &[resized]))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn formats_by_name_or_size() {
        let format = |width, height, pixel_aspect| {
            Ok(Format {
                size: Size { width, height },
                pixel_aspect,
            })
        };
        assert_eq!(Format::parse("2K_DCP"), format(2048, 1080, 1.0));
        assert_eq!(Format::parse("uhd_4k"), format(3840, 2160, 1.0));
        assert_eq!(Format::parse("1000x500"), format(1000, 500, 1.0));
        assert_eq!(Format::parse("1828x1556:2"), format(1828, 1556, 2.0));
        assert!(Format::parse("HD_1081").unwrap_err().contains("HD_1080"));
        for bad in ["1000x500:0", "1000x500:x", "1000x500:1e9"] {
            assert!(Format::parse(bad).unwrap_err().contains("0.01"), "{bad}");
        }
        assert_eq!(Format::parse("hd"), format(1920, 1080, 1.0));
        assert_eq!(Format::parse("2K_Cinemascope"), format(1828, 1556, 2.0));
        assert_eq!(Format::parse("PAL_16:9"), format(720, 576, 1.46));
        // Nuke's ratios, as its Python guide prints them (0.91, 1.09) and
        // its anamorphic formats have them.
        let ratio = |name: &str| Format::parse(name).unwrap().pixel_aspect;
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
        // Under a proxy, a named format is scaled with its ratio kept.
        assert_eq!(
            Format::scaled("2K_Cinemascope", 0.5).as_deref(),
            Ok("914x778:2")
        );
    }
}
