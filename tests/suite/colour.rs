//! The OpenColorIO commands on files (`colorconvert`, `ociodisplay`,
//! `ociolook`, `cdl`, `filetransform`): every command on a grid of values
//! against PyPI's opencolorio 2.6.0 (tests/peers/opencolorio_reference.py),
//! in float and half, with explicit built-in configs both libraries have and
//! LUT and CDL files written here; alpha, layers and the channels that pass;
//! the names' errors; job-file nodes; oiiotool 2.4 where it agrees.

use crate::common::*;
use exr::prelude::{Compression, LineOrder};
use half::f16;
use serde_json::{json, Value};
use std::path::{Path, PathBuf};
use std::process::Command;

const V4: &str = "ocio://cg-config-v4.0.0_aces-v2.0_ocio-v2.5";
const V1: &str = "ocio://cg-config-v1.0.0_aces-v1.3_ocio-v2.1";
const GAMUT: &str = "ACES 1.3 Reference Gamut Compression";
/// ACES 2.1 (PyPI's opencolorio 2.6 builds these in; the crate does not).
const V5: &str = "ocio://cg-config-v5.0.0_aces-v2.1_ocio-v2.6";
const STUDIO5: &str = "ocio://studio-config-v5.0.0_aces-v2.1_ocio-v2.6";
const STUDIO4: &str = "ocio://studio-config-v4.0.0_aces-v2.0_ocio-v2.5";

/// specs/colour-library.md's grid: 14 values per channel, every
/// combination (2744 pixels, as a 56 x 49 image).
const VALUES: [f32; 14] = [
    -0.1, 0.0, 0.002, 0.02, 0.1, 0.18, 0.35, 0.5, 0.75, 1.0, 1.5, 4.0, 16.0, 65.0,
];
const WIDTH: usize = 56;
const HEIGHT: usize = 49;

fn grid() -> Vec<[f32; 3]> {
    let mut pixels = Vec::new();
    for r in VALUES {
        for g in VALUES {
            for b in VALUES {
                pixels.push([r, g, b]);
            }
        }
    }
    pixels
}

/// The grid as R, G, B in `kind`, with a float Z and a u32 id that must pass
/// bit for bit (no alpha: alpha 1, so unpremultiplying changes nothing).
fn grid_image(kind: &Kind) -> Img {
    let pixels = grid();
    let mut channels = std::collections::BTreeMap::new();
    for (c, name) in ["R", "G", "B"].iter().enumerate() {
        let values = pixels.iter().map(|p| p[c]);
        let samples = match kind {
            Kind::Half => Samples::F16(values.map(f16::from_f32).collect()),
            Kind::Float => Samples::F32(values.collect()),
        };
        channels.insert(name.to_string(), samples);
    }
    let n = pixels.len();
    channels.insert(
        "Z".into(),
        Samples::F32((0..n).map(|i| i as f32 * 0.37 - 9.0).collect()),
    );
    channels.insert("id".into(), Samples::U32((0..n as u32).collect()));
    Img {
        x: 0,
        y: 0,
        width: WIDTH,
        height: HEIGHT,
        display: (WIDTH, HEIGHT),
        channels,
    }
}

pub fn python() -> Option<String> {
    let python = std::env::var("EXRCOMP_OCIO_PYTHON").unwrap_or_else(|_| "python3".into());
    let found = Command::new(&python)
        .args(["-c", "import PyOpenColorIO, numpy"])
        .output()
        .is_ok_and(|o| o.status.success());
    if !found {
        missing(&format!(
            "{python} cannot import PyPI's PyOpenColorIO and numpy"
        ));
    }
    found.then_some(python)
}

/// The LUT and CDL files of the cases, written into `dir`.
fn write_luts(dir: &Path) {
    let curve = |x: f32| x.clamp(0.0, 1.0).powf(0.6) * 0.9 + 0.05;
    // A 9^3 .cube (red fastest) and .spi3d (blue fastest) of a crosstalk.
    let n = 9;
    let at = |i: usize| i as f32 / (n - 1) as f32;
    let mix = |r: f32, g: f32, b: f32| {
        [
            curve(0.8 * r + 0.15 * g + 0.05 * b),
            curve(0.1 * r + 0.8 * g + 0.1 * b),
            curve(0.05 * r * g + 0.9 * b),
        ]
    };
    let mut cube = format!("TITLE \"exrcomp test\"\nLUT_3D_SIZE {n}\n");
    let mut spi3d = format!("SPILUT 1.0\n3 3\n{n} {n} {n}\n");
    for b in 0..n {
        for g in 0..n {
            for r in 0..n {
                let [x, y, z] = mix(at(r), at(g), at(b));
                cube += &format!("{x:.6} {y:.6} {z:.6}\n");
            }
        }
    }
    for r in 0..n {
        for g in 0..n {
            for b in 0..n {
                let [x, y, z] = mix(at(r), at(g), at(b));
                spi3d += &format!("{r} {g} {b} {x:.6} {y:.6} {z:.6}\n");
            }
        }
    }
    std::fs::write(dir.join("test.cube"), cube).unwrap();
    std::fs::write(dir.join("test.spi3d"), spi3d).unwrap();
    // A 1024-entry .spi1d over [-0.125, 1.125] (its inverse is tested too).
    let entries: Vec<String> = (0..1024)
        .map(|i| format!("{:.7}", curve(-0.125 + 1.25 * i as f32 / 1023.0)))
        .collect();
    std::fs::write(
        dir.join("test.spi1d"),
        format!(
            "Version 1\nFrom -0.125 1.125\nLength 1024\nComponents 1\n{{\n{}\n}}\n",
            entries.join("\n")
        ),
    )
    .unwrap();
    // A CLF: range, matrix, 1D LUT, tetrahedral 3D LUT (last: the 3D LUT's
    // last bits differ between PyPI's AVX kernels and the crate's SSE2 ones,
    // which a range after it would magnify).
    let lut3d: Vec<String> = (0..27)
        .map(|i| {
            let (r, g, b) = (i / 9, i / 3 % 3, i % 3);
            let [x, y, z] = mix(r as f32 / 2.0, g as f32 / 2.0, b as f32 / 2.0);
            format!("{x:.6} {y:.6} {z:.6}")
        })
        .collect();
    let clf = format!(
        r#"<?xml version="1.0" encoding="UTF-8"?>
<ProcessList compCLFversion="3" id="exrcomp-test">
  <Range inBitDepth="32f" outBitDepth="32f">
    <minInValue>0.05</minInValue><maxInValue>0.95</maxInValue>
    <minOutValue>0</minOutValue><maxOutValue>1</maxOutValue>
  </Range>
  <Matrix inBitDepth="32f" outBitDepth="32f">
    <Array dim="3 3">0.9 0.08 0.02 0.05 0.9 0.05 0.01 0.09 0.9</Array>
  </Matrix>
  <LUT1D inBitDepth="32f" outBitDepth="32f">
    <Array dim="5 1">0 0.3 0.55 0.8 1</Array>
  </LUT1D>
  <LUT3D inBitDepth="32f" outBitDepth="32f" interpolation="tetrahedral">
    <Array dim="3 3 3 3">{}</Array>
  </LUT3D>
</ProcessList>
"#,
        lut3d.join(" ")
    );
    std::fs::write(dir.join("test.clf"), clf).unwrap();
    let correction = |id: &str, slope: &str, sat: &str| {
        format!(
            "<ColorCorrection id=\"{id}\"><SOPNode><Slope>{slope}</Slope>\
             <Offset>0.01 0 -0.02</Offset><Power>1.2 1.0 0.9</Power></SOPNode>\
             <SatNode><Saturation>{sat}</Saturation></SatNode></ColorCorrection>"
        )
    };
    std::fs::write(
        dir.join("shot.cc"),
        correction("shot", "1.1 1.0 0.9", "0.8"),
    )
    .unwrap();
    std::fs::write(
        dir.join("shots.ccc"),
        format!(
            "<ColorCorrectionCollection xmlns=\"urn:ASC:CDL:v1.01\">{}{}</ColorCorrectionCollection>",
            correction("a010", "1.1 1.0 0.9", "0.8"),
            correction("b020", "0.7 1.3 1.05", "1.4")
        ),
    )
    .unwrap();
    std::fs::write(
        dir.join("shots.cdl"),
        format!(
            "<ColorDecisionList xmlns=\"urn:ASC:CDL:v1.01\"><ColorDecision>{}</ColorDecision>\
             <ColorDecision>{}</ColorDecision></ColorDecisionList>",
            correction("a010", "1.1 1.0 0.9", "0.8"),
            correction("b020", "0.7 1.3 1.05", "1.4")
        ),
    )
    .unwrap();
}

/// A case: exrcomp's arguments after `IN -o OUT`, and the same transform
/// for the peer.
struct Case {
    name: &'static str,
    args: Vec<String>,
    peer: Value,
}

fn case(name: &'static str, args: &[&str], peer: Value) -> Case {
    Case {
        name,
        args: args.iter().map(|a| a.to_string()).collect(),
        peer,
    }
}

fn cases(dir: &Path) -> Vec<Case> {
    let file = |name: &str| s(&dir.join(name)).to_string();
    let (cube, spi1d, spi3d, clf) = (
        file("test.cube"),
        file("test.spi1d"),
        file("test.spi3d"),
        file("test.clf"),
    );
    let (cc, ccc, cdl) = (file("shot.cc"), file("shots.ccc"), file("shots.cdl"));
    let sdr = "ACES 2.0 - SDR 100 nits (Rec.709)";
    vec![
        case(
            "v4_aces_to_acescg",
            &[
                "colorconvert",
                "--config",
                V4,
                "--from",
                "ACES2065-1",
                "--to",
                "ACEScg",
            ],
            json!({"kind": "colorconvert", "config": V4, "from": "ACES2065-1", "to": "ACEScg"}),
        ),
        case(
            "v4_acescg_to_acescct_by_alias",
            &[
                "colorconvert",
                "--config",
                V4,
                "--from",
                "lin_ap1",
                "--to",
                "acescct_ap1",
            ],
            json!({"kind": "colorconvert", "config": V4, "from": "ACEScg", "to": "ACEScct"}),
        ),
        case(
            "v4_acescg_to_srgb_texture_by_role",
            &[
                "colorconvert",
                "--config",
                V4,
                "--from",
                "scene_linear",
                "--to",
                "srgb_tx",
            ],
            json!({"kind": "colorconvert", "config": V4, "from": "ACEScg",
                   "to": "sRGB Encoded Rec.709 (sRGB)"}),
        ),
        case(
            "v1_acescct_to_rec709_linear",
            &[
                "colorconvert",
                "--config",
                V1,
                "--from",
                "ACEScct",
                "--to",
                "Linear Rec.709 (sRGB)",
            ],
            json!({"kind": "colorconvert", "config": V1, "from": "ACEScct",
                   "to": "Linear Rec.709 (sRGB)"}),
        ),
        case(
            "studio_v4_named_transform_to_acescg",
            &[
                "colorconvert",
                "--config",
                STUDIO4,
                "--from",
                "ARRI LogC4 - Curve",
                "--to",
                "ACEScg",
            ],
            json!({"kind": "colorconvert", "config": STUDIO4, "from": "ARRI LogC4 - Curve",
                   "to": "ACEScg"}),
        ),
        case(
            "studio_v4_named_transform_to_named_transform",
            &[
                "colorconvert",
                "--config",
                STUDIO4,
                "--from",
                "S-Log3 - Curve",
                "--to",
                "ARRI LogC4 - Curve",
            ],
            json!({"kind": "colorconvert", "config": STUDIO4, "from": "S-Log3 - Curve",
                   "to": "ARRI LogC4 - Curve"}),
        ),
        case(
            "studio_v5_acescg_to_named_transform",
            &[
                "colorconvert",
                "--config",
                STUDIO5,
                "--from",
                "ACEScg",
                "--to",
                "V-Log - Curve",
            ],
            json!({"kind": "colorconvert", "config": STUDIO5, "from": "ACEScg",
                   "to": "V-Log - Curve"}),
        ),
        case(
            "v5_display_alias",
            &[
                "ociodisplay",
                "--config",
                V5,
                "--display",
                "P3-D65 - Display",
                "--display-view",
                "ACES 2.0 - SDR 100 nits (P3 D65)",
            ],
            json!({"kind": "display", "config": V5, "from": "ACEScg",
                   "display": "P3-D65 - Display", "view": "ACES 2.0 - SDR 100 nits (P3 D65)"}),
        ),
        case(
            "v5_display_defaults",
            &["ociodisplay", "--config", V5],
            json!({"kind": "display", "config": V5, "from": "ACEScg",
                   "display": "sRGB - Display", "view": sdr}),
        ),
        case(
            "v4_display_inverse_from_acescct",
            &[
                "ociodisplay",
                "--config",
                V4,
                "--from",
                "ACEScct",
                "--display",
                "Rec.1886 Rec.709 - Display",
                "--display-view",
                "Video (colorimetric)",
                "--inverse",
            ],
            json!({"kind": "display", "config": V4, "from": "ACEScct",
                   "display": "Rec.1886 Rec.709 - Display", "view": "Video (colorimetric)",
                   "inverse": true}),
        ),
        case(
            "v4_display_defaults",
            &["ociodisplay", "--config", V4],
            json!({"kind": "display", "config": V4, "from": "ACEScg",
                   "display": "sRGB - Display", "view": sdr}),
        ),
        case(
            "v4_display_pq_hdr",
            &[
                "ociodisplay",
                "--config",
                V4,
                "--display",
                "Rec.2100-PQ - Display",
                "--display-view",
                "ACES 2.0 - HDR 1000 nits (P3 D65)",
            ],
            json!({"kind": "display", "config": V4, "from": "ACEScg",
                   "display": "Rec.2100-PQ - Display", "view": "ACES 2.0 - HDR 1000 nits (P3 D65)"}),
        ),
        case(
            "v1_display_with_looks_from_acescct",
            &[
                "ociodisplay",
                "--config",
                V1,
                "--from",
                "ACEScct",
                "--display",
                "sRGB - Display",
                "--display-view",
                "ACES 1.0 - SDR Video",
                "--looks",
                GAMUT,
            ],
            json!({"kind": "display", "config": V1, "from": "ACEScct", "display": "sRGB - Display",
                   "view": "ACES 1.0 - SDR Video", "looks": GAMUT}),
        ),
        case(
            "v4_look",
            &["ociolook", "--config", V4, "--look", GAMUT],
            json!({"kind": "look", "config": V4, "from": "ACEScg", "to": "ACEScg", "looks": GAMUT}),
        ),
        case(
            "v1_look_inverse_to_acescct",
            &[
                "ociolook",
                "--config",
                V1,
                "--look",
                GAMUT,
                "--from",
                "ACES2065-1",
                "--to",
                "ACEScct",
                "--inverse",
            ],
            json!({"kind": "look", "config": V1, "from": "ACES2065-1", "to": "ACEScct",
                   "looks": GAMUT, "inverse": true}),
        ),
        case(
            "cdl_values",
            &[
                "cdl",
                "--slope",
                "1.1,1.0,0.9",
                "--offset",
                "0.01,0,-0.02",
                "--power",
                "1.2,1.0,0.9",
                "--saturation",
                "0.8",
            ],
            json!({"kind": "cdl", "slope": [1.1, 1.0, 0.9], "offset": [0.01, 0.0, -0.02],
                   "power": [1.2, 1.0, 0.9], "sat": 0.8}),
        ),
        case(
            "cdl_inverse_one_value",
            &["cdl", "--slope", "1.3", "--power", "0.8", "--inverse"],
            json!({"kind": "cdl", "slope": [1.3, 1.3, 1.3], "offset": [0.0, 0.0, 0.0],
                   "power": [0.8, 0.8, 0.8], "sat": 1.0, "inverse": true}),
        ),
        case(
            "cdl_cc",
            &["cdl", "--file", &cc],
            json!({"kind": "cdl", "file": cc}),
        ),
        case(
            "cdl_ccc_by_id",
            &["cdl", "--file", &ccc, "--id", "b020"],
            json!({"kind": "cdl", "file": ccc, "id": "b020"}),
        ),
        case(
            "cdl_cdl_by_id",
            &["cdl", "--file", &cdl, "--id", "b020"],
            json!({"kind": "cdl", "file": cdl, "id": "b020"}),
        ),
        case(
            "cube",
            &["filetransform", "--file", &cube],
            json!({"kind": "file", "file": cube}),
        ),
        case(
            "cube_tetrahedral",
            &[
                "filetransform",
                "--file",
                &cube,
                "--interpolation",
                "tetrahedral",
            ],
            json!({"kind": "file", "file": cube, "interpolation": "tetrahedral"}),
        ),
        case(
            "spi1d",
            &["filetransform", "--file", &spi1d],
            json!({"kind": "file", "file": spi1d}),
        ),
        case(
            "spi1d_inverse",
            &["filetransform", "--file", &spi1d, "--inverse"],
            json!({"kind": "file", "file": spi1d, "inverse": true}),
        ),
        case(
            "spi3d",
            &["filetransform", "--file", &spi3d],
            json!({"kind": "file", "file": spi3d}),
        ),
        case(
            "clf",
            &["filetransform", "--file", &clf],
            json!({"kind": "file", "file": clf}),
        ),
    ]
}

/// Little-endian f32 triples.
fn raw(pixels: impl Iterator<Item = f32>) -> Vec<u8> {
    pixels.flat_map(f32::to_le_bytes).collect()
}

fn unraw(bytes: &[u8]) -> Vec<f32> {
    bytes
        .chunks(4)
        .map(|b| f32::from_le_bytes(b.try_into().unwrap()))
        .collect()
}

/// The peer's result of every case on `pixels`, in case order.
fn reference(
    python: &str,
    dir: &Path,
    tag: &str,
    pixels: &[[f32; 3]],
    cases: &[Case],
) -> Vec<Vec<f32>> {
    let results = reference_or_refusal(python, dir, tag, pixels, cases);
    results.into_iter().map(Result::unwrap).collect()
}

/// `reference`, with OCIO's message where it refuses a case that may be
/// refused (`"may_refuse": true`).
fn reference_or_refusal(
    python: &str,
    dir: &Path,
    tag: &str,
    pixels: &[[f32; 3]],
    cases: &[Case],
) -> Vec<Result<Vec<f32>, String>> {
    let grid = dir.join(format!("grid_{tag}.raw"));
    std::fs::write(&grid, raw(pixels.iter().flatten().copied())).unwrap();
    let outs: Vec<PathBuf> = cases
        .iter()
        .map(|c| dir.join(format!("{}_{tag}.raw", c.name)))
        .collect();
    let spec = json!({
        "grid": s(&grid),
        "cases": cases.iter().zip(&outs).map(|(c, out)| {
            let mut peer = c.peer.clone();
            peer["out"] = json!(s(out));
            peer
        }).collect::<Vec<_>>(),
    });
    let spec_path = dir.join(format!("spec_{tag}.json"));
    std::fs::write(&spec_path, spec.to_string()).unwrap();
    let script = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/peers/opencolorio_reference.py");
    succeed(Command::new(python).arg(script).arg(&spec_path));
    outs.iter()
        .map(
            |o| match std::fs::read_to_string(format!("{}.refused", s(o))) {
                Ok(refusal) => Err(refusal),
                Err(_) => Ok(unraw(&std::fs::read(o).unwrap())),
            },
        )
        .collect()
}

/// exrcomp's R, G, B of `out` as triples.
fn rgb(img: &Img) -> Vec<[f32; 3]> {
    (0..img.width * img.height)
        .map(|i| ["R", "G", "B"].map(|c| img.channels[c].get_f32(i)))
        .collect()
}

/// Float: within 1e-5 relative (floor 1e-3, specs/colour-library.md); half:
/// within one half step of the reference (which may round to infinity
/// where half does). NaN matches NaN. Returns the worst error, relative in
/// float, in half steps in half.
fn compare(name: &str, ours: &[[f32; 3]], reference: &[f32], half: bool) -> f64 {
    let mut worst = 0.0f64;
    for (i, (&got, &want)) in ours.iter().flatten().zip(reference).enumerate() {
        let want = match half {
            true if f16::from_f32(want).is_infinite() => f16::from_f32(want).to_f32(),
            _ => want,
        };
        if got.is_nan() && want.is_nan() || got == want {
            continue;
        }
        let error = (f64::from(got) - f64::from(want)).abs();
        let unit = match half {
            true => {
                let h = f16::from_f32(want.abs());
                f64::from(f16::from_bits(h.to_bits() + 1).to_f32() - h.to_f32())
            }
            false => 1e-5 * f64::from(want.abs()).max(1e-3),
        };
        worst = worst.max(error / unit * if half { 1.0 } else { 1e-5 });
        assert!(
            error <= unit,
            "{name}: sample {i} (pixel {:?}) is {got}, PyPI opencolorio gives {want}",
            grid()[i / 3]
        );
    }
    worst
}

#[test]
fn every_command_matches_pypi_opencolorio_in_float_and_half() {
    let Some(python) = python() else { return };
    let dir = tempfile::tempdir().unwrap();
    write_luts(dir.path());
    let cases = cases(dir.path());
    let (float_in, half_in) = (
        dir.path().join("grid.exr"),
        dir.path().join("grid_half.exr"),
    );
    let (float_img, half_img) = (grid_image(&Kind::Float), grid_image(&Kind::Half));
    write_image(
        &float_in,
        &float_img,
        Compression::ZIP16,
        LineOrder::Increasing,
    );
    write_image(
        &half_in,
        &half_img,
        Compression::ZIP16,
        LineOrder::Increasing,
    );
    let float_ref = reference(&python, dir.path(), "float", &grid(), &cases);
    let half_ref = reference(&python, dir.path(), "half", &rgb(&half_img), &cases);
    for (k, c) in cases.iter().enumerate() {
        for (input, img, reference, half) in [
            (&float_in, &float_img, &float_ref[k], false),
            (&half_in, &half_img, &half_ref[k], true),
        ] {
            let out = dir.path().join(format!("{}_{half}.exr", c.name));
            let mut args = vec![c.args[0].as_str(), s(input), "-o", s(&out), "--quiet"];
            args.extend(c.args[1..].iter().map(String::as_str));
            let result = run(&args);
            assert!(result.status.success(), "{args:?}: {}", stderr(&result));
            // ACES 2.1's use_display_aliases is read, not warned about.
            assert!(stderr(&result).is_empty(), "{args:?}: {}", stderr(&result));
            let ours = read_image(&out);
            let worst = compare(c.name, &rgb(&ours), reference, half);
            let unit = ["relative", "half steps"][half as usize];
            eprintln!("{}: worst error {worst:.2e} {unit}", c.name);
            for name in ["Z", "id"] {
                assert_eq!(
                    ours.channels[name], img.channels[name],
                    "{}: {name} passes",
                    c.name
                );
            }
            assert_eq!(
                std::mem::discriminant(&ours.channels["R"]),
                std::mem::discriminant(&img.channels["R"]),
                "{}: colour keeps its type",
                c.name
            );
        }
    }
}

/// `img`'s R, G, B with `alpha` (premultiplied) divided out where it is not 0.
fn straight(img: &Img, prefix: &str) -> Vec<[f32; 3]> {
    (0..img.width * img.height)
        .map(|i| {
            let a = img.channels["A"].get_f32(i);
            ["R", "G", "B"].map(|c| {
                let v = img.channels[&format!("{prefix}{c}")].get_f32(i);
                if a == 0.0 {
                    v
                } else {
                    v / a
                }
            })
        })
        .collect()
}

fn assert_close(name: &str, got: f32, want: f32) {
    let ok = got == want || (got - want).abs() <= 1e-5 * want.abs().max(1e-3);
    assert!(ok, "{name}: {got}, the reference {want}");
}

#[test]
fn alpha_layers_job_nodes_and_the_ocio_variable() {
    let Some(python) = python() else { return };
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    // Premultiplied float RGBA (alpha 0 and 1 among others), Z, id, and a
    // half `diffuse` layer.
    let mut img = random_rgba(5, -2, 3, 23, 11, Kind::Float, true);
    let mut rng = Lcg(9);
    for c in ["R", "G", "B"] {
        let values = (0..23 * 11)
            .map(|_| f16::from_f32(rng.next() * 3.0))
            .collect();
        img.channels
            .insert(format!("diffuse.{c}"), Samples::F16(values));
    }
    let input = d.join("in.exr");
    write_image(&input, &img, Compression::ZIP16, LineOrder::Increasing);
    let convert = json!({"kind": "colorconvert", "config": V1, "from": "ACEScg", "to": "ACEScct"});
    let case = |name| case(name, &[], convert.clone());
    let refs = reference(&python, d, "alpha", &straight(&img, ""), &[case("rgb")]);
    let plain = reference(&python, d, "plain", &rgb(&img), &[case("plain")]);
    let diffuse = reference(
        &python,
        d,
        "diffuse",
        &straight(&img, "diffuse."),
        &[case("layer")],
    );
    let command = |out: &Path, extra: &[&str]| {
        let mut args = vec!["colorconvert", s(&input), "-o", s(out), "-q"];
        args.extend(["--from", "ACEScg", "--to", "ACEScct"]);
        args.extend(extra);
        let result = run(&args);
        assert!(result.status.success(), "{args:?}: {}", stderr(&result));
        read_image(out)
    };
    let ours = command(&d.join("rgb.exr"), &["--config", V1]);
    let as_is = command(&d.join("as_is.exr"), &["--config", V1, "--no-unpremult"]);
    let layer = command(
        &d.join("layer.exr"),
        &["--config", V1, "--layer", "diffuse"],
    );
    for i in 0..23 * 11 {
        let a = img.channels["A"].get_f32(i);
        for (k, c) in ["R", "G", "B"].into_iter().enumerate() {
            // Unpremultiplied, converted, premultiplied; where alpha is 0
            // kept as it was (0, premultiplied).
            let want = match a {
                0.0 => img.channels[c].get_f32(i),
                _ => refs[0][3 * i + k] * a,
            };
            assert_close(c, ours.channels[c].get_f32(i), want);
            assert_close(c, as_is.channels[c].get_f32(i), plain[0][3 * i + k]);
            let name = format!("diffuse.{c}");
            let want = match a {
                0.0 => img.channels[&name].get_f32(i),
                _ => f16::from_f32(diffuse[0][3 * i + k] * a).to_f32(),
            };
            let got = layer.channels[&name].get_f32(i);
            assert!(
                (got - want).abs() <= 1e-3 * want.abs().max(1e-3),
                "{name}: {got} vs {want}"
            );
        }
    }
    for (out, kept) in [
        (&ours, &["A", "Z", "id", "diffuse.R"][..]),
        (&layer, &["A", "R", "G", "B", "Z", "id"]),
    ] {
        for name in kept {
            assert_eq!(
                out.channels[*name], img.channels[*name],
                "{name} passes bit for bit"
            );
        }
    }
    // $OCIO names the config when --config does not.
    let by_env = d.join("env.exr");
    let mut call = exrcomp();
    call.args(["colorconvert", s(&input), "-o", s(&by_env), "-q"]);
    call.args(["--from", "ACEScg", "--to", "ACEScct"]);
    succeed(call.env("OCIO", V1));
    assert_identical(&read_image(&by_env), &ours);
    let out = call.env("OCIO", d.join("missing.ocio")).output().unwrap();
    assert_eq!(out.status.code(), Some(2));
    let message = stderr(&out);
    assert!(message.contains("missing.ocio' ($OCIO)"), "{message}");
    assert_eq!(message.lines().count(), 1, "{message}");
    // The same node in a job file.
    let job = d.join("job.toml");
    std::fs::write(
        &job,
        format!(
            "[[node]]\nname = \"in\"\nread = \"in.exr\"\n\n[[node]]\nname = \"cc\"\n\
             op = \"colorconvert\"\nconfig = \"{V1}\"\nfrom = \"ACEScg\"\nto = \"ACEScct\"\n\
             layers = [\"diffuse\"]\ninputs = [\"in\"]\n\n[[node]]\nname = \"out\"\n\
             write = \"job.exr\"\ninputs = [\"cc\"]\n"
        ),
    )
    .unwrap();
    succeed(exrcomp().args(["run", s(&job), "-q"]));
    assert_identical(&read_image(&d.join("job.exr")), &layer);
    // A job's file names are relative to its folder, wherever it runs.
    write_luts(d);
    let lut = d.join("lut.toml");
    std::fs::write(
        &lut,
        "[[node]]\nname = \"in\"\nread = \"in.exr\"\n\n[[node]]\nname = \"lut\"\n\
         op = \"filetransform\"\nfile = \"test.cube\"\ninputs = [\"in\"]\n\n[[node]]\n\
         name = \"out\"\nwrite = \"lut.exr\"\ninputs = [\"lut\"]\n",
    )
    .unwrap();
    succeed(exrcomp().args(["run", s(&lut), "-q"]).current_dir("/"));
    let by_command = d.join("lut_command.exr");
    let cube = d.join("test.cube");
    succeed(exrcomp().args([
        "filetransform",
        s(&input),
        "-o",
        s(&by_command),
        "-q",
        "--file",
        s(&cube),
    ]));
    assert_identical(&read_image(&d.join("lut.exr")), &read_image(&by_command));
    // An unknown name: exit 2 before any frame, one line, a near miss.
    let out = run(&[
        "ociolook",
        s(&input),
        "-o",
        s(&d.join("x.exr")),
        "--look",
        "ACES 1.3 Reference Gamut Compresion",
    ]);
    assert_eq!(out.status.code(), Some(2));
    let message = stderr(&out);
    assert!(
        message.contains("did you mean 'ACES 1.3 Reference Gamut Compression'?"),
        "{message}"
    );
    assert_eq!(message.lines().count(), 1, "{message}");
    assert!(!d.join("x.exr").exists());
}

/// specs/examples/conversion.toml: a LogC4 plate, ten frames on, shuffled
/// and converted to ACEScg with timecode, against PyPI's opencolorio.
#[test]
fn the_conversion_example_runs_in_one_pass() {
    let Some(python) = python() else { return };
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let examples = Path::new(env!("CARGO_MANIFEST_DIR")).join("specs/examples");
    std::fs::copy(examples.join("conversion.toml"), d.join("conversion.toml")).unwrap();
    let plate = |frame: u64| {
        let mut img = random_rgba(frame, 0, 0, 16, 9, Kind::Half, false);
        for c in ["R", "G", "B"] {
            let samples = img.channels.remove(c).unwrap();
            img.channels.insert(format!("camera.{c}"), samples);
        }
        img.channels.remove("A");
        img
    };
    for frame in 1011..=1014 {
        let path = d.join(format!("plate.{frame}.exr"));
        write_image(
            &path,
            &plate(frame),
            Compression::ZIP16,
            LineOrder::Increasing,
        );
    }
    succeed(exrcomp().args(["run", s(&d.join("conversion.toml")), "-q"]));
    let studio = "ocio://studio-config-v4.0.0_aces-v2.0_ocio-v2.5";
    let logc =
        json!({"kind": "colorconvert", "config": studio, "from": "ARRI LogC4", "to": "ACEScg"});
    let source = plate(1012);
    let camera: Vec<[f32; 3]> = (0..16 * 9)
        .map(|i| ["R", "G", "B"].map(|c| source.channels[&format!("camera.{c}")].get_f32(i)))
        .collect();
    let reference = reference(&python, d, "logc", &camera, &[case("logc", &[], logc)]);
    let out = read_image(&d.join("plate_acescg.1002.exr"));
    assert_eq!(
        out.channels.keys().collect::<Vec<_>>(),
        ["A", "B", "G", "R"]
    );
    compare("conversion", &rgb(&out), &reference[0], true);
    assert!((0..16 * 9).all(|i| out.channels["A"].get_f32(i) == 1.0));
    if let Some(exrheader) = crate::common::peer("exrheader") {
        let text = String::from_utf8_lossy(
            &succeed(Command::new(exrheader).arg(d.join("plate_acescg.1002.exr"))).stdout,
        )
        .to_string();
        assert!(text.contains("01:00:00:01"), "{text}");
        assert!(text.contains("\"ACEScg\""), "{text}");
    }
}

/// oiiotool 2.4 runs Debian's OpenColorIO 2.1.2 (specs/colour-library.md),
/// which has no built-in configs: both read the ACES 1.3 CG config as PyPI
/// serializes it. Where 2.1.2 computes what 2.6 does (matrices, ACEScct, the
/// gamut compression look, LUT files) the two agree to 1e-5; its CDL and
/// ACES 1.0 output transform are older code (measured 9.5e-4 and 5.3e-3
/// apart). oiiotool's `--ociofiletransform` interpolates with OCIO's "best"
/// (tetrahedral in a 3D LUT), exrcomp with the format's default (trilinear
/// for `.cube`) unless `--interpolation` says otherwise.
#[test]
fn oiiotool_agrees_where_its_opencolorio_2_1_does() {
    let (Some(python), Some(oiiotool)) = (python(), crate::common::peer("oiiotool")) else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write_luts(d);
    let config = d.join("aces13.ocio");
    let serialize = format!("import PyOpenColorIO as o; open(r'{}', 'w').write(o.Config.CreateFromFile('{V1}').serialize())", s(&config));
    succeed(Command::new(&python).args(["-c", &serialize]));
    let mut img = grid_image(&Kind::Float);
    img.channels
        .retain(|name, _| ["R", "G", "B"].contains(&name.as_str()));
    let input = d.join("grid.exr");
    write_image(&input, &img, Compression::ZIP16, LineOrder::Increasing);
    let file = |name: &str| s(&d.join(name)).to_string();
    let (cube, spi1d, cc) = (file("test.cube"), file("test.spi1d"), file("shot.cc"));
    let cfg = s(&config);
    let sdr = [
        "--display",
        "sRGB - Display",
        "--display-view",
        "ACES 1.0 - SDR Video",
    ];
    let cases: [(&str, Vec<&str>, Vec<&str>, f32); 7] = [
        (
            "matrix",
            vec![
                "colorconvert",
                "--config",
                cfg,
                "--from",
                "ACES2065-1",
                "--to",
                "ACEScg",
            ],
            vec!["--colorconvert", "ACES2065-1", "ACEScg"],
            1e-5,
        ),
        (
            "acescct",
            vec![
                "colorconvert",
                "--config",
                cfg,
                "--from",
                "ACEScg",
                "--to",
                "ACEScct",
            ],
            vec!["--colorconvert", "ACEScg", "ACEScct"],
            1e-5,
        ),
        (
            "look",
            vec!["ociolook", "--config", cfg, "--look", GAMUT],
            vec!["--ociolook:from=ACEScg:to=ACEScg", GAMUT],
            1e-5,
        ),
        (
            "cube",
            vec!["filetransform", "--file", &cube, "--interpolation", "best"],
            vec!["--ociofiletransform", &cube],
            1e-5,
        ),
        (
            "spi1d",
            vec!["filetransform", "--file", &spi1d],
            vec!["--ociofiletransform", &spi1d],
            1e-5,
        ),
        (
            "cdl",
            vec!["cdl", "--file", &cc],
            vec!["--ociofiletransform", &cc],
            1e-3,
        ),
        (
            "display",
            [vec!["ociodisplay", "--config", cfg], sdr.to_vec()].concat(),
            vec![
                "--ociodisplay:from=ACEScg",
                "sRGB - Display",
                "ACES 1.0 - SDR Video",
            ],
            1e-2,
        ),
    ];
    for (name, ours, theirs, tolerance) in cases {
        let (a, b) = (
            d.join(format!("{name}_ours.exr")),
            d.join(format!("{name}_oiio.exr")),
        );
        let mut args = vec![ours[0], s(&input), "-o", s(&a), "-q"];
        args.extend(&ours[1..]);
        let out = run(&args);
        assert!(out.status.success(), "{args:?}: {}", stderr(&out));
        succeed(
            Command::new(&oiiotool)
                .args(["--colorconfig", cfg, s(&input)])
                .args(&theirs)
                .args(["-d", "float", "-o", s(&b)]),
        );
        let (ours, theirs) = (rgb(&read_image(&a)), rgb(&read_image(&b)));
        let mut worst = 0.0f32;
        for (x, y) in ours.iter().flatten().zip(theirs.iter().flatten()) {
            if x != y {
                worst = worst.max((x - y).abs() / y.abs().max(1e-3));
            }
        }
        eprintln!("{name}: oiiotool 2.4 (OCIO 2.1.2) differs by {worst:.2e} relative");
        assert!(worst <= tolerance, "{name}: {worst} over {tolerance}");
    }
}

/// The sweep's values per channel: the grid's range with the extremes a
/// file can hold (half's largest, infinities), every combination.
const SWEEP: [f32; 17] = [
    f32::NEG_INFINITY,
    -65504.0,
    -1.0,
    -0.1,
    0.0,
    0.002,
    0.02,
    0.18,
    0.5,
    1.0,
    1.5,
    4.0,
    16.0,
    65.0,
    1000.0,
    65504.0,
    f32::INFINITY,
];

/// Equal (infinities of the same sign), both NaN, or within 1e-5 relative
/// or 2e-6 absolute.
fn matches(got: f32, want: f32) -> bool {
    let error = (f64::from(got) - f64::from(want)).abs();
    got == want
        || got.is_nan() && want.is_nan()
        || got.is_finite()
            && want.is_finite()
            && error <= 2e-6_f64.max(1e-5 * f64::from(want.abs()))
}

/// OpenColorIO's own test files (../shared/ocio-test-files: its LUTs,
/// transforms and CDLs, some malformed on purpose), each through
/// `filetransform`, forward and `--inverse`, against PyPI's opencolorio
/// 2.6 on every combination of `SWEEP`: the same files load and are
/// refused, and every loaded case matches (infinities with OCIO's sign).
#[test]
fn every_ocio_test_file_loads_or_is_refused_and_computes_as_pypi_does() {
    let Some(files) = ocio_test_files() else {
        return;
    };
    let Some(python) = python() else { return };
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let mut pixels = Vec::new();
    for r in SWEEP {
        for g in SWEEP {
            for b in SWEEP {
                pixels.push([r, g, b]);
            }
        }
    }
    let (width, height) = (SWEEP.len() * SWEEP.len(), SWEEP.len());
    let mut channels = std::collections::BTreeMap::new();
    for (c, name) in ["R", "G", "B"].iter().enumerate() {
        let values = pixels.iter().map(|p| p[c]).collect();
        channels.insert(name.to_string(), Samples::F32(values));
    }
    let input = d.join("sweep.exr");
    write_flat(&input, (width, height), channels);
    let mut names: Vec<PathBuf> = std::fs::read_dir(&files)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.is_file())
        .filter(|p| !["LICENSE", "README.md"].iter().any(|n| p.ends_with(n)))
        .collect();
    names.sort();
    let mut cases = Vec::new();
    for (k, file) in names.iter().enumerate() {
        for inverse in [false, true] {
            let name: &'static str = Box::leak(format!("sweep{k}_{inverse}").into_boxed_str());
            let mut args = vec!["filetransform", "--file", s(file)];
            args.extend(inverse.then_some("--inverse"));
            let peer = json!({"kind": "file", "file": s(file), "inverse": inverse,
                              "may_refuse": true});
            cases.push(case(name, &args, peer));
        }
    }
    let references = reference_or_refusal(&python, d, "sweep", &pixels, &cases);
    let (mut loaded, mut refused, mut wrong) = (0, 0, Vec::new());
    for (c, reference) in cases.iter().zip(&references) {
        let out = d.join(format!("{}.exr", c.name));
        let mut args = vec![c.args[0].as_str(), s(&input), "-o", s(&out), "--quiet"];
        args.extend(c.args[1..].iter().map(String::as_str));
        let result = run(&args);
        let what = c.args[2..].join(" ");
        match (reference, result.status.success()) {
            (Err(_), false) => refused += 1,
            (Err(ocio), true) => wrong.push(format!("{what}: loads; OCIO refuses: {ocio}")),
            (Ok(_), false) => wrong.push(format!("{what}: refused: {}", stderr(&result))),
            (Ok(want), true) => {
                loaded += 1;
                let ours = rgb(&read_image(&out));
                let bad: Vec<usize> = (0..want.len())
                    .filter(|&i| !matches(ours[i / 3][i % 3], want[i]))
                    .collect();
                if let Some(&i) = bad.first() {
                    wrong.push(format!(
                        "{what}: {} samples differ, first of pixel {:?}: {} where OCIO gives {}",
                        bad.len(),
                        pixels[i / 3],
                        ours[i / 3][i % 3],
                        want[i]
                    ));
                }
            }
        }
    }
    eprintln!(
        "{} files: {loaded} cases loaded by both, {refused} refused by both",
        names.len()
    );
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
    assert!(
        loaded > 100 && refused > 10,
        "{loaded} loaded, {refused} refused"
    );
}

/// A display or view that is not active (`active_displays` and
/// `active_views` of the config, `$OCIO_ACTIVE_DISPLAYS` and
/// `$OCIO_ACTIVE_VIEWS`) is built when named, as OCIO and oiiotool build
/// it: the same pixels as with every display active.
#[test]
fn inactive_displays_and_views_are_built_when_named() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let input = d.join("grid.exr");
    write_image(
        &input,
        &grid_image(&Kind::Float),
        Compression::ZIP16,
        LineOrder::Increasing,
    );
    let builtin = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("vendor/ocio/src/builtins/configs/cg-config-v4.0.0_aces-v2.0_ocio-v2.5.ocio");
    let text: String = std::fs::read_to_string(builtin)
        .unwrap()
        .lines()
        .map(|line| match line {
            l if l.starts_with("active_displays:") => "active_displays: [sRGB - Display]",
            l if l.starts_with("active_views:") => "active_views: [Raw]",
            l => l,
        })
        .collect::<Vec<_>>()
        .join("\n");
    let narrow = d.join("narrow.ocio");
    std::fs::write(&narrow, text).unwrap();
    let (display, view) = (
        "Rec.1886 Rec.709 - Display",
        "ACES 2.0 - SDR 100 nits (Rec.709)",
    );
    let command = |out: &str, config: &Path, env: &[(&str, &str)]| {
        let out = d.join(out);
        let mut call = exrcomp();
        call.args(["ociodisplay", s(&input), "-o", s(&out), "-q", "--config"]);
        call.args([s(config), "--display", display, "--display-view", view]);
        call.envs(env.iter().copied());
        succeed(&mut call);
        read_image(&out)
    };
    let all = command("all.exr", Path::new(V4), &[]);
    assert_identical(&command("narrow.exr", &narrow, &[]), &all);
    let env = [
        ("OCIO_ACTIVE_DISPLAYS", "sRGB - Display"),
        ("OCIO_ACTIVE_VIEWS", "Raw"),
    ];
    assert_identical(&command("env.exr", Path::new(V4), &env), &all);
    // A name that is nowhere is still refused, listing the active first.
    let out = run(&[
        "ociodisplay",
        s(&input),
        "-o",
        s(&d.join("x.exr")),
        "--config",
        s(&narrow),
        "--display",
        "Rec.1886 Rec.709 - Dislpay",
    ]);
    assert_eq!(out.status.code(), Some(2));
    let message = stderr(&out);
    assert!(message.contains("(displays: sRGB - Display, "), "{message}");
    assert!(
        message.contains("did you mean 'Rec.1886 Rec.709 - Display'"),
        "{message}"
    );
}

/// An interpolation no LUT of the file takes (cubic on a 3D LUT,
/// tetrahedral on a 1D one) is OCIO's warning, once per run however many
/// frames, and the format's interpolation; one it takes says nothing.
#[test]
fn an_interpolation_a_lut_cannot_take_warns_once() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write_luts(d);
    write_sequence(d, "plate", 1..=3, 7);
    let pattern = d.join("plate.####.exr");
    let command = |file: &str, interpolation: &str, out: &str| {
        let out = d.join(out);
        let lut = d.join(file);
        let result = run(&[
            "filetransform",
            s(&pattern),
            "-o",
            s(&out),
            "--file",
            s(&lut),
            "--interpolation",
            interpolation,
        ]);
        assert!(result.status.success(), "{}", stderr(&result));
        let warnings: Vec<String> = stderr(&result)
            .lines()
            .filter(|l| l.contains("warning"))
            .map(str::to_string)
            .collect();
        (warnings, out)
    };
    for (file, interpolation) in [("test.spi3d", "cubic"), ("test.spi1d", "tetrahedral")] {
        let (warnings, out) = command(file, interpolation, &format!("{file}.####.exr"));
        assert_eq!(warnings.len(), 1, "{file}: {warnings:?}");
        let says = format!("'{interpolation}' is not allowed with the given file");
        assert!(warnings[0].contains(&says), "{}", warnings[0]);
        // The format's own interpolation, as with none asked for.
        let (none, default) = command(file, "default", &format!("{file}_default.####.exr"));
        assert!(none.is_empty(), "{none:?}");
        for frame in 1..=3 {
            let name = |p: &Path| PathBuf::from(s(p).replace("####", &format!("{frame:04}")));
            assert_identical(&read_image(&name(&out)), &read_image(&name(&default)));
        }
    }
    let (warnings, _) = command("test.spi3d", "tetrahedral", "tetra.####.exr");
    assert!(warnings.is_empty(), "{warnings:?}");
}
