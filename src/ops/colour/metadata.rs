//! The colour attributes of a file: the `colorInteropID` a conversion
//! writes (its destination's interop ID in the config) and the
//! `chromaticities` that ID's primaries are (specs/colour-library.md,
//! "Colour metadata").

use crate::io::attributes::Edit;
use exr::math::Vec2;
use exr::meta::attribute::{AttributeValue, Chromaticities, Text};
use ocio::Config;

/// OpenEXR's attribute naming a file's colour space by its interop ID.
pub const INTEROP_ID: &str = "colorInteropID";

/// OpenImageIO's attribute naming a file's colour space (what its readers
/// of TIFF, PNG and JPEG set, and what oiiotool's conversions write).
pub const OIIO_COLOUR_SPACE: &str = "oiio:ColorSpace";

/// The DPX and Cineon readers' transfer characteristic (src/io/foreign).
pub const TRANSFERS: [&str; 2] = ["dpx:Transfer", "cineon:Transfer"];

/// Primaries and white point as published (x, y of red, green, blue,
/// white), by the name the Color Interop Forum's IDs give them
/// (`lin_ap1_scene`: transfer, primaries, scene or display).
const PRIMARIES: [(&str, [f32; 8]); 6] = [
    // SMPTE ST 2065-1 (ACES white).
    (
        "ap0",
        [0.7347, 0.2653, 0.0, 1.0, 0.0001, -0.077, 0.32168, 0.33767],
    ),
    // AMPAS S-2014-004 (ACEScg), ACES white.
    (
        "ap1",
        [0.713, 0.293, 0.165, 0.83, 0.128, 0.044, 0.32168, 0.33767],
    ),
    // ITU-R BT.709, D65.
    ("rec709", [0.64, 0.33, 0.3, 0.6, 0.15, 0.06, 0.3127, 0.329]),
    // SMPTE EG 432-1 (Display P3), D65.
    (
        "p3d65",
        [0.68, 0.32, 0.265, 0.69, 0.15, 0.06, 0.3127, 0.329],
    ),
    // ITU-R BT.2020, D65.
    (
        "rec2020",
        [0.708, 0.292, 0.17, 0.797, 0.131, 0.046, 0.3127, 0.329],
    ),
    // Adobe RGB (1998), D65.
    (
        "adobergb",
        [0.64, 0.33, 0.21, 0.71, 0.15, 0.06, 0.3127, 0.329],
    ),
];

fn chromaticities(v: [f32; 8]) -> Chromaticities {
    Chromaticities {
        red: Vec2(v[0], v[1]),
        green: Vec2(v[2], v[3]),
        blue: Vec2(v[4], v[5]),
        white: Vec2(v[6], v[7]),
    }
}

/// The primaries an interop ID names (`[namespace:]transfer_primaries_
/// scene|display`), when they are in the table.
pub fn primaries(id: &str) -> Option<Chromaticities> {
    let id = id.rsplit(':').next().unwrap_or(id);
    let mut words = id.split('_');
    let (_transfer, name, state) = (words.next()?, words.next()?, words.next()?);
    if words.next().is_some() || !matches!(state, "scene" | "display") {
        return None;
    }
    let found = PRIMARIES.iter().find(|(n, _)| *n == name);
    found.map(|&(_, v)| chromaticities(v))
}

/// The table's entry whose values `c` are, within the 1e-4 a file's
/// rounding leaves: the primaries' name.
pub fn named(c: &Chromaticities) -> Option<&'static str> {
    let values = [
        c.red.0, c.red.1, c.green.0, c.green.1, c.blue.0, c.blue.1, c.white.0, c.white.1,
    ];
    let near = |v: &[f32; 8]| values.iter().zip(v).all(|(a, b)| (a - b).abs() < 1e-4);
    PRIMARIES.iter().find(|(_, v)| near(v)).map(|(n, _)| *n)
}

/// A colour space's interop ID in `config`, if it has one.
pub fn interop_id(config: &Config, space: &str) -> Option<String> {
    let id = config.get_color_space(space)?.interop_id().to_string();
    (!id.is_empty()).then_some(id)
}

/// What a conversion writes of its destination `space` of `config`.
pub fn destination(config: &Config, space: &str) -> Vec<Edit> {
    written(interop_id(config, space), Some(space))
}

/// What a conversion writes of a destination of interop ID `id` and
/// colour space `space` (`None`: not known, a file transform's): the ID,
/// the primaries it names and OpenImageIO's `oiio:ColorSpace` (the name);
/// what is not known is removed, never left as the source's, and so are
/// a DPX's or Cineon's transfer, which the pixels no longer have.
pub fn written(id: Option<String>, space: Option<&str>) -> Vec<Edit> {
    let text = |name: &'static str, value: &str| {
        Edit::Set(name, Box::new(AttributeValue::Text(Text::from(value))))
    };
    let space_edit = match space {
        Some(space) => text(OIIO_COLOUR_SPACE, space),
        None => Edit::Remove(OIIO_COLOUR_SPACE),
    };
    let primaries_edit = match id.as_deref().and_then(primaries) {
        Some(c) => Edit::Set(
            "chromaticities",
            Box::new(AttributeValue::Chromaticities(c)),
        ),
        None => Edit::Remove("chromaticities"),
    };
    let id_edit = match id {
        Some(id) => text(INTEROP_ID, &id),
        None => Edit::Remove(INTEROP_ID),
    };
    let transfers = TRANSFERS.iter().map(|&name| Edit::Remove(name));
    [id_edit, primaries_edit, space_edit]
        .into_iter()
        .chain(transfers)
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn interop_ids_name_their_primaries() {
        let ap1 = primaries("lin_ap1_scene").unwrap();
        assert_eq!((ap1.red.0, ap1.white.1), (0.713, 0.33767));
        assert_eq!(primaries("ocio:acescct_ap1_scene"), Some(ap1));
        assert_eq!(
            named(&primaries("srgb_rec709_display").unwrap()),
            Some("rec709")
        );
        for unknown in [
            "data",
            "ocio:lin_awg4_scene",
            "lin_rec709",
            "lin_rec709_scene_x",
        ] {
            assert_eq!(primaries(unknown), None, "{unknown}");
        }
    }
}
