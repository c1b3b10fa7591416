//! `ociodisplay`: scene colour to a display through one of its views (OCIO's
//! DisplayViewTransform; oiiotool's `--ociodisplay`, Nuke's OCIODisplay);
//! `--looks` replaces the view's looks, as oiiotool's `looks=` does (OCIO's
//! LegacyViewingPipeline with its looks override).

use super::super::declare::{params, FileName, Operation};
use super::colorconvert::COLORCONVERT;
use ocio::apphelpers::legacy_viewing_pipeline::LegacyViewingPipeline;
use ocio::{DisplayViewTransform, Transform};

pub const OCIODISPLAY: Operation = Operation {
    name: "ociodisplay",
    about: "OpenColorIO: scene colour to a display through one of its views \
            (default: the config's default display and its default view)",
    params: OciodisplayParams::PARAMS,
    build: |args, graph, inputs| {
        let p = OciodisplayParams::read(args)?;
        let config = super::config(p.config.as_ref())?;
        let from = super::colour_space(&config, &p.from)?;
        let display = match &p.display {
            Some(name) => super::display(&config, name)?,
            None => config.default_display(),
        };
        let view = match &p.display_view {
            Some(name) => super::one_of("view", name, super::views(&config, &display))?,
            None => config.default_view(&display),
        };
        let mut transform = DisplayViewTransform::new(&from, &display, &view);
        transform.direction = super::direction(p.inverse);
        let processor = match &p.looks {
            None => super::processor_in(&config, &p.context, Transform::DisplayView(transform))?,
            // OCIO's LegacyViewingPipeline has no direction.
            Some(_) if p.inverse => {
                return Err("ociodisplay --inverse takes the view's own looks, not --looks".into())
            }
            Some(looks) => {
                let mut pipeline = LegacyViewingPipeline::new();
                pipeline.set_display_view_transform(Some(&transform));
                pipeline.set_looks_override_enabled(true);
                pipeline.set_looks_override(&super::looks(&config, looks)?);
                (pipeline.get_processor_with_context(&config, &p.context.context(&config)))
                    .map_err(|e| e.to_string())?
            }
        };
        let edits = match p.inverse {
            true => super::metadata::destination(&config, &from),
            false => {
                super::metadata::destination(&config, &display_space(&config, &display, &view))
            }
        };
        let map = super::Ocio::new(&processor).writing(edits);
        Ok(super::add(map, p.no_unpremult, args, graph, inputs))
    },
    ..COLORCONVERT
};

params! {
    pub struct OciodisplayParams {
        /// The input's colour space (a name, alias or role of the config;
        /// `auto`: read from the input, as colorconvert's).
        from: String = "scene_linear",
        /// The display (default: the config's default display).
        display: Option<String>,
        /// The display's view (default: the display's default view). `--view`
        /// is the stereo view, as for every operation.
        display_view: Option<String>,
        /// Looks applied instead of the view's own (a comma list, `-` for
        /// inverse).
        looks: Option<String>,
        /// The inverse: display colour of the view back to the `from`
        /// colour space.
        inverse: bool,
        /// OCIO config: a file (.ocio, .ocioz) or ocio://NAME; default $OCIO,
        /// else ocio://cg-config-latest.
        config: Option<FileName>,
        /// An OCIO context variable, KEY=VALUE (`$SHOT` in the config's
        /// search path or a file's name); give it again for more.
        context: super::Vars,
        /// Transform the colour as it is, not divided by alpha first.
        no_unpremult: bool,
    }
}

/// The colour space a display's view ends in: the view's, or the display's
/// own where the view says `<USE_DISPLAY_NAME>` (OCIO 2's shared views).
fn display_space(config: &ocio::Config, display: &str, view: &str) -> String {
    let space = config.display_view_color_space_name(display, view);
    match space.eq_ignore_ascii_case(ocio::types::OCIO_VIEW_USE_DISPLAY_NAME) {
        true => display.to_string(),
        false => space.to_string(),
    }
}
