//! `cdl`: the ASC CDL (OCIO's CDLTransform; Nuke's OCIOCDLTransform): slope,
//! offset, power and saturation given, or read from a `.cc`, `.ccc` or
//! `.cdl` file (a correction picked by `--id`).

use super::super::declare::{params, FileName, Operation};
use super::super::grade::Rgb;
use super::colorconvert::COLORCONVERT;
use super::filetransform::{file, read};
use crate::params::{CDL_POWER, CDL_SLOPE, OFFSET, SATURATION_FACTOR};
use ocio::{CdlTransform, FileTransform, Processor, Transform, TransformDirection};

pub const CDL: Operation = Operation {
    name: "cdl",
    about: "OpenColorIO: ASC CDL, out = (in * slope + offset)^power then saturation, \
            values given or read from a .cc, .ccc or .cdl file",
    params: CdlParams::PARAMS,
    build: |args, graph, inputs| {
        let p = CdlParams::read(args)?;
        let given =
            [p.slope, p.offset, p.power].iter().any(Option::is_some) || p.saturation.is_some();
        let direction = super::direction(p.inverse);
        let transform = match (&p.file, given) {
            (Some(_), true) => {
                return Err(
                    "cdl takes --file or slope, offset, power and saturation, not both".into(),
                )
            }
            (Some(name), false) => {
                let mut transform = FileTransform::new(&file(name)?);
                transform.ccc_id = p.id.clone().unwrap_or_default();
                transform.direction = direction;
                Transform::File(transform)
            }
            (None, _) if p.id.is_some() => {
                return Err("cdl's --id picks a correction of --file".into())
            }
            (None, _) => {
                let wide =
                    |v: Option<Rgb>, identity: f32| v.map_or([identity; 3], |v| v.0).map(f64::from);
                Transform::Cdl(CdlTransform {
                    direction,
                    slope: wide(p.slope, 1.0),
                    offset: wide(p.offset, 0.0),
                    power: wide(p.power, 1.0),
                    sat: f64::from(p.saturation.unwrap_or(1.0)),
                    ..CdlTransform::default()
                })
            }
        };
        let processor = match &p.file {
            Some(name) => read(transform, name)?,
            None => super::processor(&ocio::Config::create_raw(), transform)?,
        };
        let map = super::Ocio::new(&processor);
        Ok(super::add(map, p.no_unpremult, args, graph, inputs))
    },
    ..COLORCONVERT
};

params! {
    pub struct CdlParams {
        /// Slope (one value, or R,G,B; default 1).
        slope: Option<Rgb> [CDL_SLOPE],
        /// Offset (one value, or R,G,B; default 0).
        offset: Option<Rgb> [OFFSET],
        /// Power (one value, or R,G,B; default 1).
        power: Option<Rgb> [CDL_POWER],
        /// Saturation, with Rec.709 luma (default 1).
        saturation: Option<f32> [SATURATION_FACTOR],
        /// A .cc, .ccc or .cdl file instead of the values.
        file: Option<FileName>,
        /// The correction of a .ccc or .cdl file: its id, or its index
        /// (default: the first).
        id: Option<String>,
        /// Apply the inverse CDL.
        inverse: bool,
        /// Transform the colour as it is, not divided by alpha first.
        no_unpremult: bool,
    }
}

/// Refuses the inverse of a CDL that has none, as OCIO does ("Singular
/// Matrix can't be inverted."): a slope or the saturation of 0 maps many
/// colours to one. Any CDL of the processor (given, read from a file, or
/// in a look) is checked; the `ocio` crate would write values.
pub fn invertible(processor: &Processor) -> Result<(), String> {
    for op in processor.ops() {
        let Some(Transform::Cdl(cdl)) = op.to_transform() else {
            continue;
        };
        if cdl.direction != TransformDirection::Inverse {
            continue;
        }
        let zero = match (cdl.slope.contains(&0.0), cdl.sat == 0.0) {
            (true, _) => "a slope of 0",
            (false, true) => "a saturation of 0",
            (false, false) => continue,
        };
        let given = match zero {
            "a slope of 0" => "--slope",
            _ => "--saturation",
        };
        return Err(format!(
            "the CDL has {zero} ({given}), which has no inverse (OpenColorIO: \
             Singular Matrix can't be inverted); --inverse needs every slope and \
             the saturation above 0"
        ));
    }
    Ok(())
}
