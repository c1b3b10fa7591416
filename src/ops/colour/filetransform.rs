//! `filetransform`: a LUT or transform file (OCIO's FileTransform:
//! `.cube`, `.spi1d`, `.spi3d`, `.clf`, `.ctf`, `.3dl`, `.cc`...; oiiotool's
//! `--ociofiletransform`, Nuke's OCIOFileTransform), no config needed.

use super::super::declare::{choice, params, FileName, Operation, Value};
use super::colorconvert::COLORCONVERT;
use ocio::{Config, FileTransform, Interpolation, Transform};

pub const FILETRANSFORM: Operation = Operation {
    name: "filetransform",
    about: "OpenColorIO: apply a LUT or transform file (.cube, .spi1d, .spi3d, .clf...)",
    params: FiletransformParams::PARAMS,
    build: |args, graph, inputs| {
        let p = FiletransformParams::read(args)?;
        let mut transform = FileTransform::new(&file(&p.file)?);
        transform.direction = super::direction(p.inverse);
        transform.interpolation = p.interpolation.0;
        let processor = read(Transform::File(transform), &p.file)?;
        let warnings = interpolation_unused(&processor, p.interpolation.0, &p.file)
            .into_iter()
            .collect();
        // A file says nothing of the space it ends in.
        let map = (super::Ocio::new(&processor).warned(warnings))
            .writing(super::metadata::written(None, None));
        Ok(super::add(map, p.no_unpremult, args, graph, inputs))
    },
    ..COLORCONVERT
};

params! {
    pub struct FiletransformParams {
        /// The file (a LUT, CLF/CTF, or a CDL file).
        file: FileName,
        /// Apply the file's inverse.
        inverse: bool,
        /// LUT interpolation: default (the format's), nearest, linear,
        /// tetrahedral (3D LUTs), cubic (1D LUTs), best.
        interpolation: Interp = "default",
        /// Transform the colour as it is, not divided by alpha first.
        no_unpremult: bool,
    }
}

/// `file` as an absolute path (OCIO resolves relative ones against a
/// config's search path; a raw config has none), checked to be a regular
/// file: a device or FIFO would be read forever or block.
pub fn file(file: &FileName) -> Result<String, String> {
    let file = file.0.as_str();
    let path = std::path::absolute(file).map_err(|e| format!("file '{file}': {e}"))?;
    let kind = match std::fs::metadata(&path) {
        Ok(metadata) => metadata.file_type(),
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
            return Err(format!("no file '{file}' (the LUT or transform to apply)"))
        }
        Err(e) => return Err(format!("file '{file}': {e}")),
    };
    if let Some(what) = crate::io::reader::not_regular(kind) {
        return Err(format!(
            "'{file}' is {what}, not a regular file (the LUT or transform to apply)"
        ));
    }
    Ok(path.to_string_lossy().into_owned())
}

/// A file transform's processor, on a raw config: the file's own error,
/// named, when it does not read.
pub fn read(transform: Transform, file: &FileName) -> Result<ocio::Processor, String> {
    super::processor(&Config::create_raw(), transform)
        .map_err(|e| format!("cannot apply '{}': {e}", file.0))
}

/// OCIO's warning when no LUT of the file can take the interpolation asked
/// for (cubic on a 3D LUT, or on a 1D one: OCIO's 1D LUTs take nearest and
/// linear; tetrahedral on 1D LUTs only), which then interpolates as the
/// format does. None for a file without LUTs, as OCIO.
pub fn interpolation_unused(
    processor: &ocio::Processor,
    interpolation: Interpolation,
    file: &FileName,
) -> Option<String> {
    use Interpolation::*;
    let (mut luts, mut used) = (false, false);
    for op in processor.ops() {
        let three = match op.to_transform() {
            Some(Transform::Lut1D(_)) => false,
            Some(Transform::Lut3D(_)) => true,
            _ => continue,
        };
        luts = true;
        used |= matches!(interpolation, Best | Default | Linear | Nearest)
            || three && interpolation == Tetrahedral;
    }
    let name = Interp(interpolation).name();
    (luts && !used).then(|| {
        format!(
            "--interpolation {name} is not allowed with '{}' (OpenColorIO: \
             Interpolation specified by FileTransform '{name}' is not allowed with \
             the given file); its LUTs interpolate as the format does",
            file.0
        )
    })
}

/// OCIO's LUT interpolation, by name.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Interp(pub Interpolation);

impl Interp {
    const VALUES: [Interpolation; 6] = {
        use Interpolation::*;
        [Default, Nearest, Linear, Tetrahedral, Cubic, Best]
    };

    /// Its name, as `--interpolation` takes it.
    fn name(self) -> &'static str {
        let at = Self::VALUES.iter().position(|v| *v == self.0);
        at.map_or("unknown", |i| Self::CHOICES[i])
    }
}

impl Value for Interp {
    fn parse(text: &str) -> Result<Self, String> {
        choice(text, Self::CHOICES, &Self::VALUES, "interpolation").map(Interp)
    }
    const CHOICES: &'static [&'static str] = &[
        "default",
        "nearest",
        "linear",
        "tetrahedral",
        "cubic",
        "best",
    ];
}
