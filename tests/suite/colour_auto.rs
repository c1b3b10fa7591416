//! `from = "auto"` in a job file (the header that reaches the node, after
//! the conversions before it), and `--from auto` from OpenImageIO's
//! `oiio:ColorSpace` and a DPX's or Cineon's log transfer
//! (specs/colour-library.md, "Colour metadata"; PyPI's opencolorio 2.6 the
//! oracle of the values).

use crate::colour::python;
use crate::colour_metadata::{header, rec709, tagged, RULES, V4};
use crate::common::*;
use exr::meta::attribute::{AttributeValue, Text};
use exr::prelude::WritableImage;
use std::path::{Path, PathBuf};
use std::process::Command;

/// The studio config: the built-in one with ADX10 and ADX16.
const STUDIO: &str = "ocio://studio-config-v4.0.0_aces-v2.0_ocio-v2.5";

/// A job file at `dir/name`: read `input`, then colorconvert nodes of the
/// `(from, to)` given, in a chain, written to `output`; `config` for each.
fn job(dir: &Path, name: &str, input: &Path, steps: &[(&str, &str)], config: &str) -> PathBuf {
    let mut text = format!("[[node]]\nname = \"in\"\nread = \"{}\"\n", s(input));
    let mut last = "in".to_string();
    for (i, (from, to)) in steps.iter().enumerate() {
        text += &format!(
            "[[node]]\nname = \"cc{i}\"\nop = \"colorconvert\"\ninputs = [\"{last}\"]\n\
             from = \"{from}\"\nto = \"{to}\"\nconfig = \"{config}\"\n"
        );
        last = format!("cc{i}");
    }
    let output = dir.join(format!("{name}.exr"));
    text += &format!(
        "[[node]]\nname = \"out\"\nwrite = \"{}\"\ninputs = [\"{last}\"]\n",
        s(&output)
    );
    let path = dir.join(format!("{name}.toml"));
    std::fs::write(&path, text).unwrap();
    path
}

/// `path` with string attribute `name` = `value` added to its header.
fn with_text(path: &Path, name: &str, value: &str) {
    let mut image = exr::prelude::read_all_data_from_file(path).unwrap();
    (image.layer_data.first_mut().unwrap().attributes.other)
        .insert(Text::from(name), AttributeValue::Text(Text::from(value)));
    image.write().to_file(path).unwrap();
}

/// A string attribute of `path`'s header.
fn text(path: &Path, name: &str) -> Option<String> {
    let h = header(path);
    let own = h.own_attributes.other.iter();
    own.chain(&h.shared_attributes.other)
        .find_map(|(k, v)| match v {
            AttributeValue::Text(t) if k.bytes() == name.as_bytes() => Some(t.to_string()),
            _ => None,
        })
}

#[test]
fn a_job_nodes_from_auto_reads_the_header_that_reaches_it() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    // read -> colorconvert(from auto): the command line's bytes.
    let cg = d.join("cg.exr");
    tagged(&cg, None, Some("lin_ap1_scene"));
    let alone = job(d, "alone", &cg, &[("auto", "ACES2065-1")], V4);
    ok(&["run", s(&alone), "-q"]);
    let command = d.join("command.exr");
    let args = ["--from", "auto", "--to", "ACES2065-1", "--config", V4, "-q"];
    ok(&[&["colorconvert", s(&cg), "-o", s(&command)], &args[..]].concat());
    let read = |p: &Path| std::fs::read(p).unwrap();
    assert!(
        read(&d.join("alone.exr")) == read(&command),
        "job and command differ"
    );

    // read -> to ACEScct -> from auto: auto sees the ID the first wrote.
    let plain = d.join("plain.exr");
    tagged(&plain, Some(rec709()), None);
    let steps = [("ACEScg", "ACEScct"), ("auto", "ACEScg")];
    let chain = job(d, "chain", &plain, &steps, V4);
    let dry = run(&["run", s(&chain), "--dry-run"]);
    assert!(dry.status.success(), "{}", stderr(&dry));
    let said = stderr(&dry);
    assert!(
        said.contains("(node 'cc1'): --from auto: 'ACEScct'"),
        "{said}"
    );
    ok(&["run", s(&chain), "-q"]);
    let named = job(
        d,
        "named",
        &plain,
        &[("ACEScg", "ACEScct"), ("ACEScct", "ACEScg")],
        V4,
    );
    ok(&["run", s(&named), "-q"]);
    assert!(same_but_fingerprint(
        &d.join("chain.exr"),
        &d.join("named.exr")
    ));

    // Nothing resolvable: one line naming the job's node, the file, the frame.
    std::fs::write(d.join("rules.ocio"), RULES).unwrap();
    tagged(&d.join("comp.1001.exr"), Some(rec709()), None);
    let rules = d.join("rules.ocio");
    let comp = d.join("comp.####.exr");
    let bad = job(d, "bad.####", &comp, &[("auto", "lin")], s(&rules));
    let out = run(&["run", s(&bad)]);
    assert_eq!(out.status.code(), Some(3), "{}", stderr(&out));
    let message = stderr(&out);
    assert_eq!(message.lines().count(), 1, "{message}");
    for says in [
        "bad.####.toml:",
        "(node 'cc0')",
        "comp.1001.exr",
        "--from auto: no colorInteropID, chromaticities (0.64,0.33 ",
        "name one with --from",
    ] {
        assert!(message.contains(says), "{says}: {message}");
    }
}

/// `--from auto` on `input` and `--from named` write the same file.
fn same_as(d: &Path, input: &Path, named: &str, config: &str, to: &str) {
    let (auto, by_name) = (d.join("auto.exr"), d.join("named.exr"));
    for (out, from) in [(&auto, "auto"), (&by_name, named)] {
        let args = ["--from", from, "--to", to, "--config", config, "-q"];
        ok(&[&["colorconvert", s(input), "-o", s(out)], &args[..]].concat());
    }
    assert_identical(&read_image(&auto), &read_image(&by_name));
}

#[test]
fn oiio_colour_space_is_read_and_written() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let srgb = "sRGB Encoded Rec.709 (sRGB)";
    // Before chromaticities: oiiotool's conversions keep the source's.
    for (value, space) in [
        ("sRGB", srgb),
        ("linear", "Linear Rec.709 (sRGB)"),
        ("Linear", "Linear Rec.709 (sRGB)"),
        ("ACEScct", "ACEScct"),
        ("lin_ap1_scene", "ACEScg"),
    ] {
        let input = d.join(format!("{value}.exr"));
        tagged(&input, Some(rec709()), None);
        with_text(&input, "oiio:ColorSpace", value);
        same_as(d, &input, space, V4, "ACES2065-1");
    }
    // A conversion writes its destination's name; a file transform, which
    // ends nowhere known, removes it.
    let input = d.join("sRGB.exr");
    let out = d.join("cc.exr");
    let args = ["--from", "auto", "--to", "ACEScct", "--config", V4, "-q"];
    ok(&[&["colorconvert", s(&input), "-o", s(&out)], &args[..]].concat());
    assert_eq!(text(&out, "oiio:ColorSpace").as_deref(), Some("ACEScct"));
    let spi = d.join("half.spi1d");
    std::fs::write(
        &spi,
        "Version 1\nFrom 0 1\nLength 2\nComponents 1\n{\n0\n0.5\n}\n",
    )
    .unwrap();
    ok(&[
        "filetransform",
        s(&input),
        "-o",
        s(&out),
        "--file",
        s(&spi),
        "-q",
    ]);
    assert_eq!(text(&out, "oiio:ColorSpace"), None);
}

/// A 10-bit DPX of a ramp (oiiotool writes it) with transfer `transfer`.
fn dpx(oiiotool: &Path, path: &Path, transfer: &str) {
    succeed(Command::new(oiiotool).args([
        "--pattern",
        "fill:top=0.05,0.3,0.6:bottom=0.4,0.7,0.95",
        "16x8",
        "3",
        "-d",
        "uint10",
        "--sattrib",
        "dpx:Transfer",
        transfer,
        "-o",
        s(path),
    ]));
}

/// PyPI's opencolorio: `input`'s RGB (as exrcomp reads it, transcoded to
/// `exr`) from `from` to `to` of `config`.
fn reference(python: &str, exr: &Path, from: &str, to: &str, config: &str) -> Vec<f32> {
    let img = read_image(exr);
    let values: Vec<String> = (0..img.width * img.height)
        .flat_map(|i| ["R", "G", "B"].map(|c| img.channels[c].get_f32(i).to_string()))
        .collect();
    let script = "import sys, PyOpenColorIO as o\n\
                  c = o.Config.CreateFromFile(sys.argv[1])\n\
                  p = c.getProcessor(sys.argv[2], sys.argv[3]).getDefaultCPUProcessor()\n\
                  v = [float(x) for x in sys.argv[4:]]\n\
                  print(' '.join(repr(x) for x in p.applyRGB(v)))";
    let out = succeed(
        Command::new(python)
            .args(["-c", script, config, from, to])
            .args(&values),
    );
    let text = String::from_utf8(out.stdout).unwrap();
    text.split_whitespace()
        .map(|x| x.parse().unwrap())
        .collect()
}

#[test]
fn a_dpx_or_cineon_log_transfer_is_adx() {
    let (Some(oiiotool), Some(python)) = (peer("oiiotool"), python()) else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let log = d.join("log.dpx");
    dpx(&oiiotool, &log, "Printing density");
    let out = d.join("cg.exr");
    let args = ["--from", "auto", "--to", "ACEScg", "--config", STUDIO];
    let dry = run(&[
        &["colorconvert", s(&log), "-o", s(&out), "--dry-run"],
        &args[..],
    ]
    .concat());
    let said = stderr(&dry);
    assert!(
        said.contains("'ADX10' ") && said.contains("dpx:Transfer 'Printing density'"),
        "{said}"
    );
    ok(&[&["colorconvert", s(&log), "-o", s(&out), "-q"], &args[..]].concat());
    // The values: OCIO's ADX10 to ACEScg of the samples as read.
    let read = d.join("read.exr");
    ok(&["transcode", s(&log), "-o", s(&read), "-q"]);
    let expected = reference(&python, &read, "ADX10", "ACEScg", STUDIO);
    let img = read_image(&out);
    for i in 0..img.width * img.height {
        for (c, name) in ["R", "G", "B"].iter().enumerate() {
            let (got, want) = (img.channels[*name].get_f32(i), expected[3 * i + c]);
            // Written as half, as the 10-bit input is read.
            let step = half::f16::from_f32(want).to_f32() - want;
            assert!(
                (got - want).abs() <= step.abs() + want.abs() * 1e-3,
                "{i} {name}: {got} {want}"
            );
        }
    }
    assert_eq!(
        text(&out, "dpx:Transfer"),
        None,
        "a conversion drops the transfer"
    );
    // A config without ADX: one line naming the transfer found.
    let fail = run(&[
        "colorconvert",
        s(&log),
        "-o",
        s(&out),
        "--from",
        "auto",
        "--to",
        "ACEScg",
    ]);
    let message = stderr(&fail);
    assert_eq!(fail.status.code(), Some(3), "{message}");
    assert_eq!(message.lines().count(), 1, "{message}");
    assert!(
        message.contains("dpx:Transfer 'Printing density'"),
        "{message}"
    );
    // A linear DPX is not log: the file rules decide (the studio config's
    // default only: refused).
    let linear = d.join("linear.dpx");
    dpx(&oiiotool, &linear, "Linear");
    let args = ["--from", "auto", "--to", "ACEScg", "--config", STUDIO];
    let refused = run(&[&["colorconvert", s(&linear), "-o", s(&out)], &args[..]].concat());
    assert!(!refused.status.success(), "{}", stderr(&refused));
    // Cineon is printing density.
    let Some(foreign) = crate::foreign_inputs::foreign_images() else {
        return;
    };
    let cineon = foreign.join("cineon/checker.cin");
    let args = [
        "--from",
        "auto",
        "--to",
        "ACEScg",
        "--config",
        STUDIO,
        "--dry-run",
    ];
    let dry = run(&[&["colorconvert", s(&cineon), "-o", s(&out)], &args[..]].concat());
    let said = stderr(&dry);
    assert!(
        said.contains("'ADX10' ") && said.contains("cineon:Transfer"),
        "{said}"
    );
}
