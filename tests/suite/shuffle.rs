//! `shuffle` and `copy` on files: whole images against references made
//! here (carried channels bit for bit), against oiiotool's `--ch` and
//! `--chappend`, errors that list the channels, and job-file nodes.

use crate::common::*;
use exr::prelude::{Compression, LineOrder};
use half::f16;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::Command;

/// Half RGBA with Z and id, plus a half `diffuse` layer (R, G, B, A) and a
/// float `spec` layer (R, G, B), in a shifted data window.
fn layered(seed: u64, x: i32, width: usize) -> Img {
    let mut img = random_rgba(seed, x, 1, width, 13, Kind::Half, true);
    let mut rng = Lcg(seed + 7);
    let n = width * 13;
    for c in ["R", "G", "B", "A"] {
        let values = (0..n).map(|_| f16::from_f32(rng.next() * 2.0)).collect();
        img.channels
            .insert(format!("diffuse.{c}"), Samples::F16(values));
    }
    for c in ["R", "G", "B"] {
        let values = (0..n).map(|_| rng.next() - 0.25).collect();
        img.channels
            .insert(format!("spec.{c}"), Samples::F32(values));
    }
    img
}

fn write(dir: &Path, name: &str, img: &Img) -> PathBuf {
    let path = dir.join(format!("{name}.exr"));
    write_image(&path, img, Compression::ZIP16, LineOrder::Increasing);
    path
}

/// `img` with the channels `(new, old)` (old from `from`) and constants.
fn shuffled(img: &Img, from: &Img, renames: &[(&str, &str)], constants: &[(&str, f32)]) -> Img {
    let mut channels: BTreeMap<String, Samples> = img.channels.clone();
    for (new, old) in renames {
        channels.insert(new.to_string(), from.channels[*old].clone());
    }
    for (name, value) in constants {
        let mut samples = Samples::F32(vec![*value; img.width * img.height]);
        if from.channels.values().all(|s| matches!(s, Samples::F16(_))) {
            samples = Samples::F16(vec![f16::from_f32(*value); img.width * img.height]);
        }
        channels.insert(name.to_string(), samples);
    }
    Img {
        channels,
        ..img.clone()
    }
}

fn only(img: &Img) -> Img {
    Img {
        channels: BTreeMap::new(),
        ..img.clone()
    }
}

#[test]
fn shuffle_renames_drops_and_adds_constants_bit_for_bit() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let img = layered(1, -2, 27);
    let input = write(d, "in", &img);
    let out = d.join("out.exr");
    ok(&[
        "shuffle",
        s(&input),
        "-o",
        s(&out),
        "-q",
        "--ch",
        "R=diffuse.R,G=diffuse.G,B=spec.B,A=1.0,Z,object=id,=0.25",
    ]);
    let expected = shuffled(
        &only(&img),
        &img,
        &[
            ("R", "diffuse.R"),
            ("G", "diffuse.G"),
            ("B", "spec.B"),
            ("Z", "Z"),
            ("object", "id"),
        ],
        &[("A", 1.0), ("channel6", 0.25)],
    );
    assert_identical(&read_image(&out), &expected);

    // The short form is the --ch list spelled out, byte for byte.
    let spelled = d.join("spelled.exr");
    ok(&[
        "shuffle",
        s(&input),
        "-o",
        s(&out),
        "-q",
        "--layer-to-rgba",
        "diffuse",
    ]);
    ok(&[
        "shuffle",
        s(&input),
        "-o",
        s(&spelled),
        "-q",
        "--ch",
        "R=diffuse.R,G=diffuse.G,B=diffuse.B,A=diffuse.A",
    ]);
    // Two spellings, two jobs: the same bytes but for the fingerprint.
    assert!(same_but_fingerprint(&out, &spelled));
    let expected = shuffled(
        &only(&img),
        &img,
        &[
            ("R", "diffuse.R"),
            ("G", "diffuse.G"),
            ("B", "diffuse.B"),
            ("A", "diffuse.A"),
        ],
        &[],
    );
    assert_identical(&read_image(&out), &expected);
    // A layer without alpha gives R, G, B; indices count in the file's order.
    ok(&[
        "shuffle",
        s(&input),
        "-o",
        s(&out),
        "-q",
        "--layer-to-rgba",
        "spec",
    ]);
    let expected = shuffled(
        &only(&img),
        &img,
        &[("R", "spec.R"), ("G", "spec.G"), ("B", "spec.B")],
        &[],
    );
    assert_identical(&read_image(&out), &expected);
    ok(&["shuffle", s(&input), "-o", s(&out), "-q", "--ch", "3,0"]);
    let expected = shuffled(&only(&img), &img, &[("R", "R"), ("A", "A")], &[]);
    assert_identical(&read_image(&out), &expected);
    assert_peers_read(&out);
}

#[test]
fn unknown_and_doubled_channels_are_refused_naming_what_there_is() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let input = write(d, "in", &layered(2, 0, 9));
    let out = d.join("out.exr");
    for (args, code, words) in [
        (&["--ch", "R=difuse.R"][..], 3, "no channel 'difuse.R' (channels: A, B, G, R, Z, diffuse.A, diffuse.B, diffuse.G, diffuse.R, id, spec.B, spec.G, spec.R)"),
        (&["--ch", "R,R=G"], 3, "channel 'R' is given twice"),
        (&["--ch", "40"], 3, "no channel number 40: the input has 13"),
        (&["--layer-to-rgba", "nope"], 3, "none of the channels asked for is there"),
        (&["--ch", "R,,G"], 2, "an empty channel"),
        (&[], 2, "shuffle takes --ch or --layer-to-rgba, one of them"),
    ] {
        let mut command = vec!["shuffle", s(&input), "-o", s(&out), "-q"];
        command.extend_from_slice(args);
        let result = run(&command);
        let message = stderr(&result);
        assert_eq!(result.status.code(), Some(code), "{args:?}: {message}");
        assert!(message.contains(words), "{args:?}: {message}");
    }
    assert!(!out.exists());
}

#[test]
fn copy_puts_channels_of_a_into_b() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let a = layered(3, 2, 20);
    let b = random_rgba(4, -1, 1, 18, 13, Kind::Float, false);
    let (pa, pb) = (write(d, "a", &a), write(d, "b", &b));
    let out = d.join("out.exr");
    ok(&[
        "copy",
        s(&pa),
        s(&pb),
        "-o",
        s(&out),
        "-q",
        "--ch",
        "Z,mask=diffuse.A,G=spec.G,gain=2",
    ]);
    // The union of the windows (columns -1 .. 22); each channel where its
    // input has data, 0 elsewhere.
    let window = |img: &Img| (img.x, img.x + img.width as i32);
    let (x0, x1) = (
        window(&b).0.min(window(&a).0),
        window(&b).1.max(window(&a).1),
    );
    let width = (x1 - x0) as usize;
    let place = |img: &Img, name: &str| {
        let source = &img.channels[name];
        let mut samples = source.zeros_like(width * 13);
        for y in 1..14 {
            for x in x0..x1 {
                if let Some(j) = img.index(x, y) {
                    samples.copy_from((y - 1) as usize * width + (x - x0) as usize, source, j);
                }
            }
        }
        samples
    };
    let mut channels = BTreeMap::new();
    for name in ["A", "B", "R"] {
        channels.insert(name.to_string(), place(&b, name));
    }
    channels.insert("G".into(), place(&a, "spec.G"));
    channels.insert("Z".into(), place(&a, "Z"));
    channels.insert("mask".into(), place(&a, "diffuse.A"));
    let mut gain = Samples::F32(vec![0.0; width * 13]);
    for i in 0..width * 13 {
        let (x, y) = (x0 + (i % width) as i32, 1 + (i / width) as i32);
        if b.index(x, y).is_some() || a.index(x, y).is_some() {
            gain.set_f32(i, 2.0);
        }
    }
    channels.insert("gain".into(), gain);
    let expected = Img {
        x: x0,
        width,
        channels,
        ..b.clone()
    };
    assert_identical(&read_image(&out), &expected);
}

fn oiiotool(tool: &Path, args: &[&str]) {
    succeed(Command::new(tool).args(args));
}

#[test]
fn shuffle_and_copy_equal_oiiotools_ch_and_chappend() {
    let Some(tool) = peer("oiiotool") else {
        return;
    };
    let Some(idiff) = peer("idiff") else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let img = layered(5, 0, 31);
    let input = write(d, "in", &img);
    let (ours, theirs) = (d.join("ours.exr"), d.join("theirs.exr"));
    for spec in [
        "R=diffuse.R,G=diffuse.G,B=diffuse.B,A=1.0",
        "R=spec.B,G,B=diffuse.r,A=diffuse.A,depth=Z,=0.5",
        "Z,spec.R,A",
    ] {
        ok(&["shuffle", s(&input), "-o", s(&ours), "-q", "--ch", spec]);
        oiiotool(&tool, &[s(&input), "--ch", spec, "-o", s(&theirs)]);
        assert_idiff_identical(&idiff, &ours, &theirs);
        let names = |p: &Path| read_image(p).channels.keys().cloned().collect::<Vec<_>>();
        assert_eq!(names(&ours), names(&theirs), "{spec}");
    }
    // copy: B's channels, then A's shuffled, appended (same windows).
    let b = random_rgba(6, 0, 1, 31, 13, Kind::Half, false);
    let pb = write(d, "b", &b);
    ok(&[
        "copy",
        s(&input),
        s(&pb),
        "-o",
        s(&ours),
        "-q",
        "--ch",
        "Z,mask=diffuse.A",
    ]);
    oiiotool(
        &tool,
        &[
            s(&pb),
            s(&input),
            "--ch",
            "Z,mask=diffuse.A",
            "--chappend",
            "-o",
            s(&theirs),
        ],
    );
    assert_idiff_identical(&idiff, &ours, &theirs);
}

#[test]
fn shuffle_and_copy_nodes_in_a_job_write_what_the_commands_write() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    for frame in 1..=2 {
        write(d, &format!("a.{frame:04}"), &layered(10 + frame, 0, 16));
        write(
            d,
            &format!("b.{frame:04}"),
            &random_rgba(20 + frame, 0, 1, 16, 13, Kind::Half, false),
        );
    }
    let job = "[[node]]\nname = \"a\"\nread = \"a.####.exr\"\n\n\
        [[node]]\nname = \"b\"\nread = \"b.####.exr\"\n\n\
        [[node]]\nname = \"s\"\nop = \"shuffle\"\nlayer_to_rgba = \"diffuse\"\ninputs = [\"a\"]\n\n\
        [[node]]\nname = \"c\"\nop = \"copy\"\nch = \"mask=A,Z=0.5\"\ninputs = [\"s\", \"b\"]\n\n\
        [[node]]\nname = \"out\"\nwrite = \"job.####.exr\"\ninputs = [\"c\"]\n";
    std::fs::write(d.join("job.toml"), job).unwrap();
    ok(&["run", s(&d.join("job.toml")), "-q"]);
    let p = |n: &str| d.join(format!("{n}.####.exr"));
    ok(&[
        "shuffle",
        s(&p("a")),
        "-o",
        s(&p("s1")),
        "-q",
        "--layer-to-rgba",
        "diffuse",
    ]);
    ok(&[
        "copy",
        s(&p("s1")),
        s(&p("b")),
        "-o",
        s(&p("s2")),
        "-q",
        "--ch",
        "mask=A,Z=0.5",
    ]);
    for frame in 1..=2 {
        let name = |n: &str| d.join(format!("{n}.{frame:04}.exr"));
        // Two jobs: the same bytes but for which job each file names.
        let same = same_but_fingerprint(&name("job"), &name("s2"));
        assert!(
            same,
            "frame {frame}: the job's file differs from the commands'"
        );
    }
}
