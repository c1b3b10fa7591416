//! `--from auto`: the source colour space read from the input's first
//! frame, before the graph is built (`Operation::measure`): its
//! `colorInteropID`, else its `chromaticities`, else the config's file
//! rules (specs/colour-library.md, "Colour metadata").

use super::metadata::{interop_id, named, INTEROP_ID};
use crate::engine::plan::{Job, Source};
use crate::error::{Error, Result};
use crate::io::parts::choose_part;
use crate::io::reader::ExrFile;
use crate::ops::declare::Measured;
use exr::meta::attribute::AttributeValue;
use exr::meta::header::Header;
use ocio::Config;

/// The word that asks for it.
pub const AUTO: &str = "auto";

/// `--from auto`, measured as the colour space of input 0's first frame
/// in `config` (`given`: what named it, for a config without a name), with
/// a note saying why for the dry run.
pub fn measure(config: &Config, given: &str, job: &Job) -> Result<Measured> {
    let at = job.frames.iter().find_map(|f| match f.inputs[0] {
        Source::Frame(at) => Some(at),
        Source::Black(_) => None,
    });
    let Some(at) = at else {
        return Err(Error::usage(
            "--from auto reads the input's colour attributes, and every frame of it is \
             missing: name the colour space with --from",
        ));
    };
    let file = ExrFile::open(&job.inputs[0].path(at), job.frame_label(at))?;
    let part = choose_part(&file, job.parts[0].as_deref(), job.view.as_deref())?;
    let path = file.path.to_string_lossy().into_owned();
    let (space, why) = source(config, file.header(part), &path).map_err(|found| {
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
    if !config.filepath_only_matches_default_rule(path) {
        let space = config.color_space_from_filepath(path);
        return Ok((space, "the config's file rules".to_string()));
    }
    let id = match id {
        Some(id) => format!("colorInteropID '{id}',"),
        None => "no colorInteropID,".to_string(),
    };
    let chromaticities = match chromaticities {
        Some(c) => format!(
            "chromaticities ({},{} {},{} {},{} white {},{})",
            c.red.0, c.red.1, c.green.0, c.green.1, c.blue.0, c.blue.1, c.white.0, c.white.1
        ),
        None => "no chromaticities".to_string(),
    };
    Err(format!(
        "{id} {chromaticities} and no file rule but the default"
    ))
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

/// A string attribute of `header`, wherever the crate keeps it.
fn text(header: &Header, name: &str) -> Option<String> {
    let (own, shared) = (
        &header.own_attributes.other,
        &header.shared_attributes.other,
    );
    own.iter()
        .chain(shared)
        .find_map(|(key, value)| match value {
            AttributeValue::Text(t) if key.bytes() == name.as_bytes() => Some(t.to_string()),
            _ => None,
        })
}
