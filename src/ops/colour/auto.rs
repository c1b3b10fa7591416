//! `--from auto`: the source colour space read from the input's first
//! frame, before the graph is built (`Operation::measure`), from its
//! header after the attribute edits of the ops before the node (a job
//! file's): its `colorInteropID`, else its `oiio:ColorSpace`, else its
//! `chromaticities`, else a DPX's or Cineon's log transfer, else the
//! config's file rules (specs/colour-library.md, "Colour metadata").

use super::metadata::{interop_id, named, INTEROP_ID, OIIO_COLOUR_SPACE, TRANSFERS};
use crate::engine::plan::{Job, Source};
use crate::error::{Error, Result};
use crate::io::attributes::Edit;
use crate::io::parts::choose_part;
use crate::ops::declare::Measured;
use exr::meta::attribute::AttributeValue;
use exr::meta::header::Header;
use ocio::Config;

/// The word that asks for it.
pub const AUTO: &str = "auto";

/// `--from auto`, measured as the colour space of input 0's first frame
/// in `config` (`given`: what named it, for a config without a name),
/// `edits` applied to its header, with a note saying why for the dry run.
pub fn measure(config: &Config, given: &str, job: &Job, edits: &[Edit]) -> Result<Measured> {
    let first = (job.frames.iter()).find(|f| matches!(f.inputs[0], Source::Frame(_)));
    let Some(first) = first else {
        return Err(Error::usage(
            "--from auto reads the input's colour attributes, and every frame of it is \
             missing: name the colour space with --from",
        ));
    };
    let file = job.input_file(0, first)?;
    let part = choose_part(&file, job.parts[0].as_deref(), job.view.as_deref())?;
    let path = file.path.to_string_lossy().into_owned();
    let mut header = file.header(part).clone();
    edits.iter().for_each(|edit| edit.apply(&mut header));
    let (space, why) = source(config, &header, &path).map_err(|found| {
        let name = match config.name() {
            "" => given,
            name => name,
        };
        file.error(format!(
            "--from auto: {found} match no colour space of config '{name}'; name one \
             with --from"
        ))
    })?;
    Ok(Measured {
        values: vec![("from", space.clone())],
        notes: vec![format!(
            "--from auto: '{space}' ({}: {why})",
            file.path.display()
        )],
    })
}

/// The colour space a file is in, and why; else what was found, for the
/// error.
fn source(
    config: &Config,
    header: &Header,
    path: &str,
) -> std::result::Result<(String, String), String> {
    let id = text(header, INTEROP_ID);
    if let Some(id) = &id {
        if let Some(space) = with_interop_id(config, id) {
            return Ok((space, format!("its colorInteropID '{id}'")));
        }
    }
    let oiio = text(header, OIIO_COLOUR_SPACE);
    if let Some(name) = &oiio {
        if let Some(space) = oiio_space(config, name) {
            return Ok((space, format!("its {OIIO_COLOUR_SPACE} '{name}'")));
        }
    }
    let chromaticities = header.shared_attributes.chromaticities;
    if let Some(primaries) = chromaticities.as_ref().and_then(named) {
        let linear = format!("lin_{primaries}_scene");
        if let Some(space) = with_interop_id(config, &linear) {
            return Ok((
                space,
                format!("its chromaticities are {primaries}'s, taken as linear"),
            ));
        }
    }
    let transfer = TRANSFERS
        .iter()
        .find_map(|&name| text(header, name).map(|t| (name, t)));
    if let Some((name, value)) = &transfer {
        if let Some(space) = log_space(config, header, value) {
            return Ok((space, format!("its {name} '{value}'")));
        }
    }
    if !config.filepath_only_matches_default_rule(path) {
        let space = config.color_space_from_filepath(path);
        return Ok((space, "the config's file rules".to_string()));
    }
    let mut found = vec![match id {
        Some(id) => format!("colorInteropID '{id}'"),
        None => "no colorInteropID".to_string(),
    }];
    found.extend(oiio.map(|name| format!("{OIIO_COLOUR_SPACE} '{name}'")));
    found.push(match chromaticities {
        Some(c) => format!(
            "chromaticities ({},{} {},{} {},{} white {},{})",
            c.red.0, c.red.1, c.green.0, c.green.1, c.blue.0, c.blue.1, c.white.0, c.white.1
        ),
        None => "no chromaticities".to_string(),
    });
    found.extend(transfer.map(|(name, value)| format!("{name} '{value}'")));
    Err(format!(
        "{} and no file rule but the default",
        found.join(", ")
    ))
}

/// The colour space OpenImageIO's `oiio:ColorSpace` names: `sRGB` the
/// sRGB-encoded Rec.709 texture space, `linear` scene-linear Rec.709 (as
/// its readers mean them), else a colour space's interop ID, name or alias.
fn oiio_space(config: &Config, name: &str) -> Option<String> {
    let meant = match name {
        "sRGB" => Some("srgb_rec709_scene"),
        "linear" | "Linear" => Some("lin_rec709_scene"),
        _ => None,
    };
    let by_meaning = meant.and_then(|id| with_interop_id(config, id));
    by_meaning.or_else(|| with_interop_id(config, name))
}

/// The config's ADX space for a DPX's or Cineon's `transfer`, when it is a
/// log one (printing density, logarithmic, ADX): ADX16 for 16-bit ADX
/// samples, else ADX10 (Cineon's and 10-bit DPX's codes, 95 black).
fn log_space(config: &Config, header: &Header, transfer: &str) -> Option<String> {
    if !matches!(transfer, "Printing density" | "Logarithmic" | "ADX") {
        return None;
    }
    let bits = attribute(header, "dpx:BitsPerSample");
    let (id, name) = match (transfer, bits) {
        ("ADX", Some(AttributeValue::I32(16))) => ("ocio:adx16_apd_scene", "ADX16"),
        _ => ("ocio:adx10_apd_scene", "ADX10"),
    };
    with_interop_id(config, id).or_else(|| with_interop_id(config, name))
}

/// The colour space whose interop ID is `id` (with or without its
/// namespace), else whose name or alias is.
fn with_interop_id(config: &Config, id: &str) -> Option<String> {
    let bare = |s: &str| s.rsplit(':').next().unwrap_or(s).to_string();
    let spaces = (0..config.num_color_spaces()).map(|i| config.color_space_name_by_index(i));
    for space in spaces {
        if interop_id(config, space).is_some_and(|own| own == id || bare(&own) == bare(id)) {
            return Some(space.to_string());
        }
    }
    config.get_color_space(id).map(|cs| cs.name().to_string())
}

/// Attribute `name` of `header`, wherever the crate keeps it.
fn attribute<'h>(header: &'h Header, name: &str) -> Option<&'h AttributeValue> {
    let (own, shared) = (
        &header.own_attributes.other,
        &header.shared_attributes.other,
    );
    own.iter()
        .chain(shared)
        .find_map(|(key, value)| (key.bytes() == name.as_bytes()).then_some(value))
}

/// A string attribute of `header`.
fn text(header: &Header, name: &str) -> Option<String> {
    match attribute(header, name)? {
        AttributeValue::Text(t) => Some(t.to_string()),
        _ => None,
    }
}
