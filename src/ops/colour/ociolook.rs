//! `ociolook`: a look of the config (OCIO's LookTransform; oiiotool's
//! `--ociolook`, Nuke's OCIOLookTransform), from a colour space to another
//! through the look's process space.

use super::super::declare::{params, FileName, Operation};
use super::colorconvert::COLORCONVERT;
use ocio::{LookTransform, Transform};

pub const OCIOLOOK: Operation = Operation {
    name: "ociolook",
    about: "OpenColorIO: apply looks of the config (default from and to: scene_linear)",
    params: OciolookParams::PARAMS,
    build: |args, graph, inputs| {
        let p = OciolookParams::read(args)?;
        let config = super::config(p.config.as_ref())?;
        let from = super::colour_space(&config, &p.from)?;
        let to = match &p.to {
            Some(to) => super::colour_space(&config, to)?,
            None => from.clone(),
        };
        let mut transform = LookTransform::new(&from, &to, &super::looks(&config, &p.look)?);
        transform.direction = super::direction(p.inverse);
        let processor = super::processor_in(&config, &p.context, Transform::Look(transform))?;
        let written = if p.inverse { &from } else { &to };
        let map =
            super::Ocio::new(&processor).writing(super::metadata::destination(&config, written));
        Ok(super::add(map, p.no_unpremult, args, graph, inputs))
    },
    ..COLORCONVERT
};

params! {
    pub struct OciolookParams {
        /// The looks (a comma list, `-` before a look for its inverse).
        look: String,
        /// The input's colour space (a name, alias or role of the config;
        /// `auto`: read from the input, as colorconvert's).
        from: String = "scene_linear",
        /// The output's colour space (default: from).
        to: Option<String>,
        /// The inverse: from `to` back to `from` through the looks undone.
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
