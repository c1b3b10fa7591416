//! The colour a file says it is in: the `colorInteropID` and
//! `chromaticities` a conversion writes (its destination's, as the config
//! names it: PyPI's opencolorio 2.6 is the oracle), `--from auto` reading
//! them, and `--context` variables (specs/colour-library.md, "Colour
//! metadata").

use crate::colour::python;
use crate::common::*;
use exr::meta::attribute::{AttributeValue, Chromaticities, Text};
use exr::meta::header::Header;
use exr::prelude::WritableImage;
use std::collections::BTreeMap;
use std::path::Path;
use std::process::Command;

pub const V4: &str = "ocio://cg-config-v4.0.0_aces-v2.0_ocio-v2.5";
const V1: &str = "ocio://cg-config-v1.0.0_aces-v1.3_ocio-v2.1";

/// OpenEXR's Rec. 709 (ITU-R BT.709, D65), as files carry it.
pub fn rec709() -> Chromaticities {
    chromaticities([0.64, 0.33, 0.3, 0.6, 0.15, 0.06, 0.3127, 0.329])
}

fn chromaticities(v: [f32; 8]) -> Chromaticities {
    use exr::math::Vec2;
    Chromaticities {
        red: Vec2(v[0], v[1]),
        green: Vec2(v[2], v[3]),
        blue: Vec2(v[4], v[5]),
        white: Vec2(v[6], v[7]),
    }
}

/// A small RGBA float image, with a `diffuse` layer, at `path` with the colour attributes given.
pub fn tagged(path: &Path, chroma: Option<Chromaticities>, interop: Option<&str>) {
    let mut channels = BTreeMap::new();
    let names = ["A", "B", "G", "R", "diffuse.B", "diffuse.G", "diffuse.R"];
    for (c, name) in names.iter().enumerate() {
        let values = (0..16).map(|i| 0.05 * (i + c) as f32).collect();
        channels.insert(name.to_string(), Samples::F32(values));
    }
    write_flat(path, (4, 4), channels);
    let mut image = exr::prelude::read_all_data_from_file(path).unwrap();
    image.attributes.chromaticities = chroma;
    if let Some(id) = interop {
        let value = AttributeValue::Text(Text::from(id));
        (image.layer_data.first_mut().unwrap().attributes.other)
            .insert(Text::from("colorInteropID"), value);
    }
    image.write().to_file(path).unwrap();
}

pub fn header(path: &Path) -> Header {
    let meta = exr::meta::MetaData::read_from_file(path, false).unwrap();
    meta.headers.into_iter().next().unwrap()
}

/// The colour attributes of `path`'s first part.
fn colour(path: &Path) -> (Option<String>, Option<Chromaticities>) {
    let h = header(path);
    let id = h.own_attributes.other.iter().find_map(|(k, v)| match v {
        AttributeValue::Text(t) if k.bytes() == b"colorInteropID" => Some(t.to_string()),
        _ => None,
    });
    (id, h.shared_attributes.chromaticities)
}

/// PyPI's opencolorio: the interop ID of each colour space of `config`.
fn interop_ids(python: &str, config: &str, spaces: &[&str]) -> Vec<String> {
    let script = "import sys, PyOpenColorIO as o\n\
                  c = o.Config.CreateFromFile(sys.argv[1])\n\
                  for n in sys.argv[2:]: print(c.getColorSpace(n).getInteropID())";
    let out = succeed(
        Command::new(python)
            .args(["-c", script, config])
            .args(spaces),
    );
    let text = String::from_utf8(out.stdout).unwrap();
    text.lines().map(str::to_string).collect()
}

#[test]
fn a_conversion_writes_its_destinations_colour_and_removes_what_is_not_known() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let input = d.join("in.exr");
    tagged(&input, Some(rec709()), Some("lin_rec709_scene"));
    let convert = |out: &str, extra: &[&str]| {
        let out = d.join(out);
        let mut args = vec!["colorconvert", s(&input), "-o", s(&out), "-q"];
        args.extend(extra);
        ok(&args);
        colour(&out)
    };
    let ap1 = chromaticities([0.713, 0.293, 0.165, 0.83, 0.128, 0.044, 0.32168, 0.33767]);
    let spaces = ["--from", "Linear Rec.709 (sRGB)", "--to", "ACEScg"];
    let cg = convert("cg.exr", &[&["--config", V4][..], &spaces].concat());
    assert_eq!(cg, (Some("lin_ap1_scene".into()), Some(ap1)));
    let to_709 = ["--from", "ACEScg", "--to", "sRGB Encoded Rec.709 (sRGB)"];
    let srgb = convert("srgb.exr", &[&["--config", V4][..], &to_709].concat());
    assert_eq!(srgb, (Some("srgb_rec709_scene".into()), Some(rec709())));
    if let Some(python) = python() {
        let ids = interop_ids(&python, V4, &["ACEScg", "sRGB Encoded Rec.709 (sRGB)"]);
        assert_eq!([cg.0.unwrap(), srgb.0.unwrap()].to_vec(), ids);
    }
    // A config without interop IDs (OCIO 2.1's): neither is known.
    let v1 = ["--config", V1, "--from", "ACES2065-1", "--to", "ACEScg"];
    assert_eq!(convert("v1.exr", &v1), (None, None));
    // A named layer's conversion leaves the unnamed layer's as they were.
    let layer = [&["--config", V4, "--layer", "diffuse"][..], &spaces].concat();
    assert_eq!(convert("layer.exr", &layer), colour(&input));
    // A display's view ends in the display's colour space.
    let out = d.join("display.exr");
    ok(&[
        "ociodisplay",
        s(&input),
        "-o",
        s(&out),
        "-q",
        "--config",
        V4,
    ]);
    assert_eq!(
        colour(&out),
        (Some("srgb_rec709_display".into()), Some(rec709()))
    );
    // A LUT file says nothing of where it ends: both removed.
    let lut = d.join("half.cube");
    std::fs::write(&lut, "LUT_1D_SIZE 2\n0 0 0\n0.5 0.5 0.5\n").unwrap();
    let out = d.join("lut.exr");
    ok(&[
        "filetransform",
        s(&input),
        "-o",
        s(&out),
        "-q",
        "--file",
        s(&lut),
    ]);
    assert_eq!(colour(&out), (None, None));
    // A grade in place changes no attribute.
    let out = d.join("cdl.exr");
    ok(&["cdl", s(&input), "-o", s(&out), "-q", "--slope", "1.1"]);
    assert_eq!(colour(&out), colour(&input));
    // exrheader reads what was written.
    if let Some(exrheader) = peer("exrheader") {
        let text = String::from_utf8(succeed(Command::new(exrheader).arg(d.join("cg.exr"))).stdout)
            .unwrap();
        assert!(
            text.contains("colorInteropID (type string): \"lin_ap1_scene\""),
            "{text}"
        );
        assert!(text.contains("white (0.32168 0.33767)"), "{text}");
    }
}

/// A config of three spaces whose file rules send `*plate*` files to `g22`.
pub const RULES: &str = r#"ocio_profile_version: 2
roles:
  default: raw
  scene_linear: lin
file_rules:
  - !<Rule> {name: plates, colorspace: g22, pattern: "*plate*", extension: "*"}
  - !<Rule> {name: Default, colorspace: raw}
displays:
  sRGB:
    - !<View> {name: Raw, colorspace: raw}
colorspaces:
  - !<ColorSpace> {name: raw, isdata: true}
  - !<ColorSpace> {name: lin}
  - !<ColorSpace> {name: g22, to_reference: !<ExponentTransform> {value: [2.2, 2.2, 2.2, 1]}}
"#;

#[test]
fn from_auto_reads_the_interop_id_the_chromaticities_or_the_file_rules() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    // The same conversion with the source named and with auto: the same file.
    let same = |input: &Path, named: &str, rest: &[&str]| {
        let (auto, by_name) = (d.join("auto.exr"), d.join("named.exr"));
        for (out, from) in [(&auto, "auto"), (&by_name, named)] {
            let mut args = vec!["colorconvert", s(input), "-o", s(out), "-q"];
            args.extend(["--from", from]);
            args.extend(rest);
            ok(&args);
        }
        assert_identical(&read_image(&auto), &read_image(&by_name));
    };
    let to_aces = ["--config", V4, "--to", "ACES2065-1"];
    let with_id = d.join("cg.exr");
    tagged(&with_id, None, Some("lin_ap1_scene"));
    same(&with_id, "ACEScg", &to_aces);
    let with_709 = d.join("709.exr");
    tagged(&with_709, Some(rec709()), None);
    same(&with_709, "Linear Rec.709 (sRGB)", &to_aces);
    let rules = d.join("rules.ocio");
    std::fs::write(&rules, RULES).unwrap();
    let plate = d.join("plate.exr");
    tagged(&plate, None, None);
    same(&plate, "g22", &["--config", s(&rules), "--to", "lin"]);
    // The dry run says what it chose, and why.
    let dry = run(&[
        "colorconvert",
        s(&with_id),
        "-o",
        s(&d.join("x.exr")),
        "--config",
        V4,
        "--from",
        "auto",
        "--to",
        "ACES2065-1",
        "--dry-run",
    ]);
    assert!(dry.status.success(), "{}", stderr(&dry));
    let said = stderr(&dry);
    assert!(said.contains("--from auto: 'ACEScg'"), "{said}");
    assert!(said.contains("colorInteropID 'lin_ap1_scene'"), "{said}");
    // Nothing fits: one line naming the file, its frame and what it has.
    let comp = d.join("comp.1001.exr");
    tagged(&comp, Some(rec709()), None);
    let out = run(&[
        "colorconvert",
        s(&d.join("comp.####.exr")),
        "-o",
        s(&d.join("o.####.exr")),
        "--config",
        s(&rules),
        "--from",
        "auto",
        "--to",
        "lin",
    ]);
    assert!(!out.status.success());
    let message = stderr(&out);
    assert_eq!(message.lines().count(), 1, "{message}");
    for says in [
        "comp.1001.exr",
        "1001",
        "--from auto: no colorInteropID, chromaticities (0.64,0.33 ",
        "match no colour space of config",
        "name one with --from",
    ] {
        assert!(message.contains(says), "{says}: {message}");
    }
}

/// A config whose `shot` space is a LUT named by `$SHOT` (default `a`) in
/// its search path.
const SHOTS: &str = r#"ocio_profile_version: 2
search_path: luts
environment:
  SHOT: a
roles:
  default: raw
  scene_linear: lin
displays:
  sRGB:
    - !<View> {name: Raw, colorspace: raw}
colorspaces:
  - !<ColorSpace> {name: raw, isdata: true}
  - !<ColorSpace> {name: lin}
  - !<ColorSpace> {name: shot, to_reference: !<FileTransform> {src: "$SHOT.spi1d", interpolation: linear}}
"#;

/// PyPI's opencolorio: `values` (R, G, B triples) from `shot` to `lin`
/// with context variable SHOT set to `shot`.
fn shot_reference(python: &str, config: &Path, shot: &str, values: &[[f32; 3]]) -> Vec<f32> {
    let script = "import sys, json, PyOpenColorIO as o\n\
                  c = o.Config.CreateFromFile(sys.argv[1])\n\
                  x = c.getCurrentContext()\n\
                  x.setStringVar('SHOT', sys.argv[2])\n\
                  p = c.getProcessor(x, 'shot', 'lin').getDefaultCPUProcessor()\n\
                  print(json.dumps([v for rgb in json.loads(sys.argv[3]) for v in p.applyRGB(rgb)]))";
    let values = serde_json::to_string(values).unwrap();
    let out = succeed(Command::new(python).args(["-c", script, s(config), shot, &values]));
    serde_json::from_slice(&out.stdout).unwrap()
}

#[test]
fn context_variables_choose_the_files_a_config_reads() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    std::fs::create_dir(d.join("luts")).unwrap();
    for (shot, top) in [("a", "0.5"), ("b", "2.0"), ("sh010", "0.25")] {
        let lut =
            format!("Version 1\nFrom 0.0 1.0\nLength 3\nComponents 1\n{{\n0.0\n0.1\n{top}\n}}\n");
        std::fs::write(d.join("luts").join(format!("{shot}.spi1d")), lut).unwrap();
    }
    let config = d.join("shots.ocio");
    std::fs::write(&config, SHOTS).unwrap();
    let input = d.join("in.exr");
    tagged(&input, None, None);
    let convert = |out: &Path, context: &[&str]| {
        let mut args = vec!["colorconvert", s(&input), "-o", s(out), "-q", "--config"];
        args.extend([
            s(&config),
            "--from",
            "shot",
            "--to",
            "lin",
            "--no-unpremult",
        ]);
        for c in context {
            args.extend(["--context", c]);
        }
        ok(&args);
        read_image(out)
    };
    let rgb = |img: &Img| -> Vec<[f32; 3]> {
        (0..16)
            .map(|i| ["R", "G", "B"].map(|c| img.channels[c].get_f32(i)))
            .collect()
    };
    let values = rgb(&read_image(&input));
    let python = python();
    for (shot, context) in [
        ("a", vec![]),
        ("b", vec!["SHOT=b"]),
        ("sh010", vec!["OTHER=x", "SHOT=sh010"]),
    ] {
        let got = rgb(&convert(&d.join(format!("{shot}.exr")), &context));
        if let Some(python) = &python {
            let want = shot_reference(python, &config, shot, &values);
            for (g, w) in got.iter().flatten().zip(&want) {
                assert!((g - w).abs() <= 1e-6 + 1e-5 * w.abs(), "{shot}: {g} vs {w}");
            }
        }
    }
    // --resume redoes the frames a context other than theirs made.
    let out = d.join("seq.exr");
    let a = convert(&out, &["SHOT=a"]);
    let mut args = vec!["colorconvert", s(&input), "-o", s(&out), "-q", "--resume"];
    args.extend([
        "--config",
        s(&config),
        "--from",
        "shot",
        "--to",
        "lin",
        "--no-unpremult",
    ]);
    ok(&[&args[..], &["--context", "SHOT=b"]].concat());
    let b = read_image(&out);
    assert_identical(&b, &read_image(&d.join("b.exr")));
    assert_ne!(rgb(&a), rgb(&b));
    // A job file's node takes the same as a list.
    let keys = format!(
        "op = \"colorconvert\"\nconfig = \"{}\"\nfrom = \"shot\"\nto = \"lin\"\nno_unpremult = true\n\
         context = [\"SHOT=b\"]",
        s(&config)
    );
    assert_identical(&read_image(&one_op_job(d, &input, &keys)), &b);
}
