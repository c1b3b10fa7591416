//! Who wrote an output and what was done to its input, as oiiotool records
//! it (specs/file-format.md, "Provenance").

use exr::meta::attribute::{AttributeValue, Text};
use exr::meta::header::Header;

/// What names the writer of a file: OpenImageIO's `Software`, a string.
/// OpenEXR has no standard attribute for it; the exr crate's `software` is
/// its own name, which other tools do not read.
const SOFTWARE: &str = "Software";

/// One line per tool that wrote the image, oldest first (oiiotool's).
const HISTORY: &str = "Exif:ImageHistory";

/// This program, as `Software` and history lines name it.
const WRITER: &str = concat!("exrcomp ", env!("CARGO_PKG_VERSION"));

/// Marks `header`, made from an input's, as written by exrcomp: `Software`
/// names it, and `Exif:ImageHistory` gains a line for it after the input's
/// history (without one, after the input's writer). The input's preview
/// goes: its pixels are the input's, not the output's.
pub fn stamp(header: &mut Header) {
    let attributes = &mut header.own_attributes;
    let text = |value: Option<&AttributeValue>| match value {
        Some(AttributeValue::Text(text)) => Some(text.bytes().to_vec()),
        _ => None,
    };
    let earlier = text(attributes.other.get(&Text::from(HISTORY)))
        .or_else(|| text(attributes.other.get(&Text::from(SOFTWARE))))
        .or_else(|| {
            attributes
                .software_name
                .as_ref()
                .map(|t| t.bytes().to_vec())
        });
    let mut history = match earlier {
        Some(mut lines) => {
            lines.push(b'\n');
            lines
        }
        None => Vec::new(),
    };
    history.extend_from_slice(WRITER.as_bytes());
    attributes.software_name = None;
    attributes.preview = None;
    for (name, value) in [(SOFTWARE, WRITER.as_bytes()), (HISTORY, &history)] {
        let value = AttributeValue::Text(Text::from_slice_unchecked(value));
        attributes.other.insert(Text::from(name), value);
    }
}
