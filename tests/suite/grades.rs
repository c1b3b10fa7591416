//! `grade`, `exposure` and `saturation` on files: whole images against the
//! formulas computed here, against oiiotool's `--mulc`, `--addc`, `--clamp`,
//! `--powc` and `--saturate`, and as job-file nodes.

use crate::common::*;
use exr::prelude::{Compression, LineOrder};
use half::f16;
use std::path::{Path, PathBuf};
use std::process::Command;

/// A float RGBA image with a shifted data window, Z and id, and a half
/// `diffuse` layer, written to `dir/NAME.exr`.
fn plate(dir: &Path, name: &str, seed: u64) -> (PathBuf, Img) {
    let mut img = random_rgba(seed, -3, 2, 29, 17, Kind::Float, true);
    let mut rng = Lcg(seed + 1);
    for c in ["R", "G", "B"] {
        let values = (0..29 * 17)
            .map(|_| f16::from_f32(rng.next() * 3.0 - 0.5))
            .collect();
        img.channels
            .insert(format!("diffuse.{c}"), Samples::F16(values));
    }
    let path = dir.join(format!("{name}.exr"));
    write_image(&path, &img, Compression::ZIP16, LineOrder::Increasing);
    (path, img)
}

/// Nuke's Grade of one value (specs/ops.md, "Grades"), without reverse.
fn nuke_grade(p: [f32; 7], white_clamp: bool, x: f32) -> f32 {
    let [bp, wp, lift, gain, multiply, offset, gamma] = p;
    let a = multiply * (gain - lift) / (wp - bp);
    let v = (a * x + offset + lift - a * bp).max(0.0);
    let v = if white_clamp { v.min(1.0) } else { v };
    if v < 1.0 {
        v.powf(1.0 / gamma)
    } else {
        1.0 + (v - 1.0) / gamma
    }
}

/// `img` with `f` applied to each sample of `channels` (channel index
/// 0, 1, 2 for R, G, B of the layer, and the pixel's alpha).
fn reference(img: &Img, prefix: &str, f: impl Fn(usize, f32, f32) -> f32) -> Img {
    let mut out = img.clone();
    for (k, c) in ["R", "G", "B"].iter().enumerate() {
        let name = format!("{prefix}{c}");
        let samples = out.channels.get_mut(&name).unwrap();
        for i in 0..samples.len() {
            let alpha = img.channels["A"].get_f32(i);
            let v = f(k, samples.get_f32(i), alpha);
            samples.set_f32(i, v);
        }
    }
    out
}

/// Identical windows and channels; samples within `tolerance` (relative
/// above 1) of the reference's.
fn assert_close(ours: &Img, reference: &Img, tolerance: f32) {
    assert_eq!(
        (ours.x, ours.y, ours.width, ours.height),
        (reference.x, reference.y, reference.width, reference.height)
    );
    let names = |img: &Img| img.channels.keys().cloned().collect::<Vec<_>>();
    assert_eq!(names(ours), names(reference));
    for (name, samples) in &ours.channels {
        let other = &reference.channels[name];
        assert_eq!(
            std::mem::discriminant(samples),
            std::mem::discriminant(other),
            "{name}"
        );
        for i in 0..samples.len() {
            let (a, b) = (samples.get_f32(i), other.get_f32(i));
            assert!(
                a.to_bits() == b.to_bits() || (a - b).abs() <= tolerance * b.abs().max(1.0),
                "{name} sample {i}: {a} vs {b}"
            );
        }
    }
}

#[test]
fn grade_exposure_and_saturation_equal_their_formulas_on_whole_images() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let (input, img) = plate(d, "in", 3);
    let out = d.join("out.exr");
    // Per-channel values, a negative lift list, the white clamp.
    ok(&[
        "grade",
        s(&input),
        "-o",
        s(&out),
        "-q",
        "--blackpoint",
        "0.02,0,0.05",
        "--whitepoint",
        "0.9",
        "--lift",
        "-0.1,0,0.05",
        "--gain",
        "1.2,1,0.8",
        "--multiply",
        "1.1",
        "--offset",
        "0.01",
        "--gamma",
        "2.2,1,0.6",
        "--white-clamp",
    ]);
    let per = |k: usize| {
        [
            [0.02, 0.9, -0.1, 1.2, 1.1, 0.01, 2.2],
            [0.0, 0.9, 0.0, 1.0, 1.1, 0.01, 1.0],
            [0.05, 0.9, 0.05, 0.8, 1.1, 0.01, 0.6],
        ][k]
    };
    let expected = reference(&img, "", |k, x, _| nuke_grade(per(k), true, x));
    assert_close(&read_image(&out), &expected, 2e-6);

    // A layer, on colour unpremultiplied: the unnamed colours pass bit for bit.
    ok(&[
        "grade",
        s(&input),
        "-o",
        s(&out),
        "-q",
        "--layer",
        "diffuse",
        "--gamma",
        "1.8",
        "--offset",
        "0.1",
        "--unpremult",
    ]);
    let p = [0.0, 1.0, 0.0, 1.0, 1.0, 0.1, 1.8];
    let expected = reference(&img, "diffuse.", |_, x, a| {
        let x = if a == 0.0 { x } else { x / a };
        nuke_grade(p, false, x) * a
    });
    assert_close(&read_image(&out), &expected, 1e-3);

    ok(&[
        "exposure",
        s(&input),
        "-o",
        s(&out),
        "-q",
        "--stops",
        "1.5,-1,0",
    ]);
    let gains = [1.5f32.exp2(), 0.5, 1.0];
    let expected = reference(&img, "", |k, x, _| x * gains[k]);
    assert_close(&read_image(&out), &expected, 0.0);

    ok(&[
        "saturation",
        s(&input),
        "-o",
        s(&out),
        "-q",
        "--saturation",
        "0.3",
        "--luminance",
        "acescg",
    ]);
    let w = [0.2722287f32, 0.6740818, 0.0536895];
    let expected = {
        let mut out = img.clone();
        let get = |c: &str, i: usize| img.channels[c].get_f32(i);
        for i in 0..img.width * img.height {
            let y = w[0] * get("R", i) + w[1] * get("G", i) + w[2] * get("B", i);
            for c in ["R", "G", "B"] {
                let v = y + 0.3 * (get(c, i) - y);
                out.channels.get_mut(c).unwrap().set_f32(i, v);
            }
        }
        out
    };
    assert_close(&read_image(&out), &expected, 1e-6);
    assert_peers_read(&out);
}

#[test]
fn grades_are_refused_with_a_usage_error_naming_the_value() {
    let dir = tempfile::tempdir().unwrap();
    let (input, _) = plate(dir.path(), "in", 4);
    let out = dir.path().join("out.exr");
    for (args, words) in [
        (
            &["--whitepoint", "0.2", "--blackpoint", "0.2"][..],
            "whitepoint must differ",
        ),
        (&["--gamma", "-1"], "gamma must be a number"),
        (&["--lift", "0,1"], "lift takes one value or three"),
        (&["--gain", "nan"], "gain must be a number"),
    ] {
        let mut command = vec!["grade", s(&input), "-o", s(&out), "-q"];
        command.extend_from_slice(args);
        let result = run(&command);
        assert_eq!(
            result.status.code(),
            Some(2),
            "{args:?}: {}",
            stderr(&result)
        );
        assert!(
            stderr(&result).contains(words),
            "{args:?}: {}",
            stderr(&result)
        );
    }
    assert!(!out.exists());
}

fn oiiotool(tool: &Path, args: &[&str]) {
    succeed(Command::new(tool).args(args));
}

#[test]
fn grades_match_oiiotool_where_it_has_the_same_operation() {
    let Some(tool) = peer("oiiotool") else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    // RGBA alone: oiiotool's constants go to every channel.
    let img = random_rgba(5, 2, -1, 31, 19, Kind::Float, false);
    let input = d.join("in.exr");
    write_image(&input, &img, Compression::ZIP16, LineOrder::Increasing);
    let (ours, theirs) = (d.join("ours.exr"), d.join("theirs.exr"));
    let compare =
        |tolerance: f32| assert_close(&read_image(&ours), &read_image(&theirs), tolerance);

    ok(&[
        "exposure",
        s(&input),
        "-o",
        s(&ours),
        "-q",
        "--stops",
        "1.5,-1,0.25",
    ]);
    let gains = [1.5f32, -1.0, 0.25].map(|s| s.exp2().to_string()).join(",");
    oiiotool(
        &tool,
        &[s(&input), "--mulc", &format!("{gains},1"), "-o", s(&theirs)],
    );
    compare(0.0);

    ok(&[
        "saturation",
        s(&input),
        "-o",
        s(&ours),
        "-q",
        "--saturation",
        "0.4",
    ]);
    oiiotool(&tool, &[s(&input), "--saturate", "0.4", "-o", s(&theirs)]);
    compare(1e-6);

    // multiply, offset, clamps, gamma: in 0..1 the gamma is a power.
    ok(&[
        "grade",
        s(&input),
        "-o",
        s(&ours),
        "-q",
        "--multiply",
        "0.8",
        "--offset",
        "-0.05",
        "--gamma",
        "2.2",
        "--white-clamp",
    ]);
    let power = (1.0f32 / 2.2).to_string();
    oiiotool(
        &tool,
        &[
            s(&input),
            "--mulc",
            "0.8,0.8,0.8,1",
            "--addc",
            "-0.05,-0.05,-0.05,0",
            "--clamp:min=0:max=1",
            "--powc",
            &format!("{power},{power},{power},1"),
            "-o",
            s(&theirs),
        ],
    );
    compare(1e-6);
}

#[test]
fn grade_nodes_in_a_job_write_what_the_commands_write() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    for frame in 1..=2 {
        let img = random_rgba(frame, 0, 0, 24, 20, Kind::Half, true);
        let path = d.join(format!("in.{frame:04}.exr"));
        write_image(&path, &img, Compression::ZIP16, LineOrder::Increasing);
    }
    let read = "[[node]]\nname = \"in\"\nread = \"in.####.exr\"\n\n\
        [[node]]\nname = \"g\"\nop = \"grade\"\nlift = [-0.1, 0, 0.05]\ngamma = 1.7\nwhite_clamp = true\ninputs = [\"in\"]\n\n";
    let job = format!(
        "{read}[[node]]\nname = \"e\"\nop = \"exposure\"\nstops = -0.5\ninputs = [\"g\"]\n\n\
        [[node]]\nname = \"s\"\nop = \"saturation\"\nsaturation = 1.4\nluminance = \"rec2020\"\ninputs = [\"e\"]\n\n\
        [[node]]\nname = \"out\"\nwrite = \"job.####.exr\"\ninputs = [\"s\"]\n"
    );
    std::fs::write(d.join("job.toml"), job).unwrap();
    ok(&["run", s(&d.join("job.toml")), "-q"]);
    let p = |n: &str| d.join(format!("{n}.####.exr"));
    // One node: the command's file, byte for byte.
    let one =
        format!("{read}[[node]]\nname = \"out\"\nwrite = \"one.####.exr\"\ninputs = [\"g\"]\n");
    std::fs::write(d.join("one.toml"), one).unwrap();
    ok(&["run", s(&d.join("one.toml")), "-q"]);
    ok(&[
        "grade",
        s(&p("in")),
        "-o",
        s(&p("direct")),
        "-q",
        "--lift",
        "-0.1,0,0.05",
        "--gamma",
        "1.7",
        "--white-clamp",
    ]);
    for frame in 1..=2 {
        let name = |n: &str| d.join(format!("{n}.{frame:04}.exr"));
        let same = std::fs::read(name("one")).unwrap() == std::fs::read(name("direct")).unwrap();
        assert!(
            same,
            "frame {frame}: the job's file differs from the command's"
        );
    }
    // The chain equals its steps run one by one, so nothing is rounded between the steps.
    ok(&[
        "grade",
        s(&p("in")),
        "-o",
        s(&p("s1")),
        "-q",
        "--lift",
        "-0.1,0,0.05",
        "--gamma",
        "1.7",
        "--white-clamp",
    ]);
    ok(&[
        "exposure",
        s(&p("s1")),
        "-o",
        s(&p("s2")),
        "-q",
        "--stops",
        "-0.5",
    ]);
    ok(&[
        "saturation",
        s(&p("s2")),
        "-o",
        s(&p("s3")),
        "-q",
        "--saturation",
        "1.4",
        "--luminance",
        "rec2020",
    ]);
    for frame in 1..=2 {
        let name = |n: &str| d.join(format!("{n}.{frame:04}.exr"));
        // The steps round to half between them; the job does not.
        assert_close(&read_image(&name("job")), &read_image(&name("s3")), 2e-3);
    }
}
