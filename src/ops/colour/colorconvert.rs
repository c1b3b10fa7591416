//! `colorconvert`: from one colour space of the config to another (OCIO's
//! ColorSpaceTransform; oiiotool's `--colorconvert`, Nuke's OCIOColorSpace).

use super::super::declare::{input, params, FileName, Operation};

pub const COLORCONVERT: Operation = Operation {
    name: "colorconvert",
    about: "OpenColorIO: colour from one colour space of the config to another \
            (names, aliases or roles), on colour divided by alpha unless --no-unpremult",
    inputs: &[input("input", "Input file or sequence, `:PART` for a part")],
    repeats: false,
    params: ColorconvertParams::PARAMS,
    layers: true,
    straight: false,
    header: Some(0),
    build: |args, graph, inputs| {
        let p = ColorconvertParams::read(args)?;
        let config = super::config(p.config.as_ref())?;
        let transform = super::conversion(&config, &p.from, &p.to)?;
        let processor = super::processor_in(&config, &p.context, transform)?;
        // A named transform's destination is no colour space of the config.
        let to = config
            .get_color_space(&p.to)
            .map(|cs| cs.name().to_string());
        let edits = match to {
            Some(to) => super::metadata::destination(&config, &to),
            None => super::metadata::written(None, None),
        };
        let map = super::Ocio::new(&processor).writing(edits);
        Ok(super::add(map, p.no_unpremult, args, graph, inputs))
    },
    measure: Some(super::measure),
};

params! {
    pub struct ColorconvertParams {
        /// The input's colour space (a name, alias or role of the config),
        /// or a named transform of the config (its forward transform);
        /// `auto`: read from the input's colorInteropID, chromaticities, or
        /// the config's file rules.
        from: String,
        /// The output's colour space, or a named transform (its inverse).
        to: String,
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
