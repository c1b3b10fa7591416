//! Deep scanline inputs: flattened as they are read, and merged by depth
//! before flattening, checked against OpenEXR's and OIIO's own
//! (`oiiotool --flatten`, `--deepmerge`) on the public deep passes.

use crate::common::*;
use std::path::{Path, PathBuf};
use std::process::Command;

/// A deep pass: Trunks is shipped, Balls only in the shared set.
fn pass(name: &str) -> Option<PathBuf> {
    public_image(&format!("v2/LowResLeftView/{name}.exr"))
}

/// `oiiotool ARGS --ch R,G,B,A -o OUT`.
fn oiiotool_rgba(oiio: &Path, args: &[&str], out: &Path) {
    let status = Command::new(oiio)
        .args(args)
        .args(["--ch", "R,G,B,A", "-o"])
        .arg(out)
        .status()
        .unwrap();
    assert!(status.success(), "oiiotool {args:?}");
}

#[test]
fn flatten_equals_oiiotool_flatten_and_does_not_depend_on_strips() {
    let (Some(oiio), Some(idiff)) = (peer("oiiotool"), peer("idiff")) else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    for name in ["Balls", "Trunks"] {
        let Some(input) = pass(name) else { continue };
        let ours = d.join(format!("{name}.exr"));
        ok(&["flatten", s(&input), "-o", s(&ours), "-q"]);
        assert_peers_read(&ours);
        let (ours_rgba, theirs) = (
            d.join(format!("{name}-rgba.exr")),
            d.join(format!("{name}-oiio.exr")),
        );
        oiiotool_rgba(&oiio, &[s(&ours)], &ours_rgba);
        oiiotool_rgba(&oiio, &[s(&input), "--flatten"], &theirs);
        assert_idiff_identical(&idiff, &ours_rgba, &theirs);
        let strips = d.join(format!("{name}-strips.exr"));
        ok(&[
            "flatten",
            s(&input),
            "-o",
            s(&strips),
            "-q",
            "--strip-rows",
            "7",
        ]);
        assert_identical(&read_image(&ours), &read_image(&strips));
    }
}

#[test]
fn deepmerge_matches_oiiotool_and_either_order() {
    let (Some(oiio), Some(idiff)) = (peer("oiiotool"), peer("idiff")) else {
        return;
    };
    let (Some(balls), Some(trunks)) = (pass("Balls"), pass("Trunks")) else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let (ab, ba) = (d.join("ab.exr"), d.join("ba.exr"));
    ok(&["deepmerge", s(&balls), s(&trunks), "-o", s(&ab), "-q"]);
    ok(&["deepmerge", s(&trunks), s(&balls), "-o", s(&ba), "-q"]);
    let (ours_rgba, theirs) = (d.join("ab-rgba.exr"), d.join("oiio.exr"));
    oiiotool_rgba(&oiio, &[s(&ab)], &ours_rgba);
    oiiotool_rgba(
        &oiio,
        &[s(&balls), s(&trunks), "--deepmerge", "--flatten"],
        &theirs,
    );
    // Two pixels of 445,000 differ by about 1e-3 (samples at equal depth).
    let out = Command::new(idiff)
        .args(["-fail", "0.002", "-failpercent", "0.001"])
        .arg(&ours_rgba)
        .arg(&theirs)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stdout)
    );
    let (x, y) = (read_image(&ab), read_image(&ba));
    for name in ["R", "G", "B", "A"] {
        for i in 0..x.channels[name].len() {
            let (p, q) = (x.channels[name].get_f32(i), y.channels[name].get_f32(i));
            assert!((p - q).abs() <= 1e-3, "{name}[{i}]: {p} vs {q}");
        }
    }
}

#[test]
fn any_command_flattens_deep_inputs_as_it_reads_them() {
    let (Some(deep_balls), Some(deep_trunks)) = (pass("Balls"), pass("Trunks")) else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let flat = |input: &Path, name: &str| {
        let out = d.join(format!("{name}-flat.exr"));
        ok(&["flatten", s(input), "-o", s(&out), "-q"]);
        out
    };
    let (balls, trunks) = (flat(&deep_balls, "Balls"), flat(&deep_trunks, "Trunks"));
    let (direct, via_files) = (d.join("direct.exr"), d.join("via.exr"));
    ok(&[
        "over",
        s(&deep_balls),
        s(&deep_trunks),
        "-o",
        s(&direct),
        "-q",
    ]);
    ok(&["over", s(&balls), s(&trunks), "-o", s(&via_files), "-q"]);
    assert_identical(&read_image(&direct), &read_image(&via_files));
    // A flat file cannot be deep-merged.
    let out = run(&[
        "deepmerge",
        s(&balls),
        s(&deep_trunks),
        "-o",
        s(&d.join("x.exr")),
    ]);
    assert_eq!(out.status.code(), Some(3), "{}", stderr(&out));
    assert!(stderr(&out).contains("is not deep"), "{}", stderr(&out));
}

/// `oiiotool INPUT ARGS -o OUT`.
fn oiiotool_write(oiio: &Path, input: &Path, args: &[&str], out: &Path) {
    let status = Command::new(oiio)
        .arg(input)
        .args(args)
        .arg("-o")
        .arg(out)
        .status()
        .unwrap();
    assert!(status.success(), "oiiotool {args:?}");
}

#[test]
fn deep_tiles_and_many_line_deep_blocks_flatten_as_one_line_blocks_of_the_same_samples() {
    let (Some(oiio), Some(idiff)) = (peer("oiiotool"), peer("idiff")) else {
        return;
    };
    let Some(input) = pass("Trunks") else { return };
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    // The data window starts at row 141: tiles straddle it, and 17x23 tiles
    // end cut short at the right and bottom.
    let forms: [(&str, &[&str]); 4] = [
        (
            "tiled-32-zip",
            &["--tile", "32", "32", "--compression", "zip"],
        ),
        (
            "tiled-17x23-rle",
            &["--tile", "17", "23", "--compression", "rle"],
        ),
        (
            "tiled-64-none",
            &["--tile", "64", "64", "--compression", "none"],
        ),
        ("scanline-zip", &["--compression", "zip"]),
    ];
    for (name, args) in forms {
        let deep = d.join(format!("{name}.exr"));
        oiiotool_write(&oiio, &input, args, &deep);
        ok(&["info", s(&deep)]);
        // The same samples in one-line ZIPS blocks, as oiiotool rewrites them.
        let lines = d.join(format!("{name}-zips.exr"));
        oiiotool_write(&oiio, &deep, &["--compression", "zips"], &lines);
        let (ours, reference) = (d.join(format!("{name}-flat.exr")), d.join("ref.exr"));
        ok(&[
            "flatten",
            s(&deep),
            "-o",
            s(&ours),
            "-q",
            "--strip-rows",
            "7",
        ]);
        ok(&["flatten", s(&lines), "-o", s(&reference), "-q"]);
        assert_identical(&read_image(&ours), &read_image(&reference));
        let (ours_rgba, theirs) = (d.join("ours-rgba.exr"), d.join("theirs.exr"));
        oiiotool_rgba(&oiio, &[s(&ours)], &ours_rgba);
        oiiotool_rgba(&oiio, &[s(&deep), "--flatten"], &theirs);
        assert_idiff_identical(&idiff, &ours_rgba, &theirs);
    }
}

#[test]
fn a_damaged_deep_tiled_file_is_refused_in_one_line() {
    let Some(oiio) = peer("oiiotool") else { return };
    let Some(input) = pass("Trunks") else { return };
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let deep = d.join("tiled.exr");
    oiiotool_write(
        &oiio,
        &input,
        &["--tile", "32", "32", "--compression", "zip"],
        &deep,
    );
    let bytes = std::fs::read(&deep).unwrap();
    let out_dir = d.join("out");
    std::fs::create_dir(&out_dir).unwrap();
    // Bytes flipped across the chunk area (sizes, tables, samples), and
    // the file cut short.
    let mut damaged = Vec::new();
    for at in [55, 70, 85, 99] {
        let mut flipped = bytes.clone();
        let from = bytes.len() * at / 100;
        for b in &mut flipped[from..from + 16] {
            *b ^= 0x5a;
        }
        damaged.push((format!("flipped-{at}.exr"), flipped));
    }
    damaged.push(("cut.exr".into(), bytes[..bytes.len() * 3 / 4].to_vec()));
    for (name, data) in damaged {
        let path = d.join(&name);
        std::fs::write(&path, data).unwrap();
        for command in ["info", "flatten"] {
            let mut args = vec![command, s(&path)];
            let out_path = out_dir.join("o.exr");
            if command == "flatten" {
                args.extend(["-o", s(&out_path), "-q"]);
            }
            let out = limited(&args);
            let message = stderr(&out);
            assert_eq!(out.status.code(), Some(3), "{name} {command}: {message}");
            assert_eq!(message.lines().count(), 1, "{name} {command}: {message}");
            assert!(message.contains(&name), "{name} {command}: {message}");
            assert_eq!(std::fs::read_dir(&out_dir).unwrap().count(), 0);
        }
    }
}

#[test]
fn a_deep_part_is_carried_whole_and_flattened_with_all_parts() {
    let (Some(oiio), Some(idiff), Some(multipart)) =
        (peer("oiiotool"), peer("idiff"), peer("exrmultipart"))
    else {
        return;
    };
    let Some(input) = pass("Trunks") else { return };
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    // oiiotool writes no mixed deep and flat file: exrmultipart joins them.
    let (flat, deep, both) = (d.join("flat.exr"), d.join("deep.exr"), d.join("both.exr"));
    generate(&flat, "bg", (1024, 576), &[]);
    oiiotool_write(
        &oiio,
        &input,
        &["--tile", "32", "32", "--compression", "zip"],
        &deep,
    );
    let status = Command::new(multipart)
        .args(["-combine", "-i"])
        .args([&flat, &deep])
        .arg("-o")
        .arg(&both)
        .status()
        .unwrap();
    assert!(status.success());
    // The flat part worked on, the deep one carried: OpenEXR reads it back,
    // the same samples.
    let carried = d.join("carried.exr");
    let part = format!("{}:0", s(&both));
    ok(&[
        "transcode",
        &part,
        "-o",
        s(&carried),
        "-q",
        "--compression",
        "piz",
    ]);
    // info's version flags are the file's, as exrheader prints them (a deep
    // part in a multi-part file sets the non-image bit: 0x1800).
    for file in [&both, &carried] {
        let ours = run(&["info", s(file)]);
        assert!(ours.status.success(), "{}", stderr(&ours));
        let version = |text: &[u8]| {
            String::from_utf8_lossy(text)
                .lines()
                .find(|l| l.starts_with("file format version"))
                .map(str::to_string)
        };
        assert_eq!(
            version(&ours.stdout).as_deref(),
            Some("file format version: 2, flags 0x1800")
        );
        if let Some(exrheader) = peer("exrheader") {
            let theirs = succeed(Command::new(exrheader).arg(file));
            assert_eq!(version(&ours.stdout), version(&theirs.stdout));
        }
    }
    let flattened = |file: &Path, name: &str| {
        let out = d.join(name);
        oiiotool_write(&oiio, file, &["--subimage", "1", "--flatten"], &out);
        out
    };
    assert_idiff_identical(
        &idiff,
        &flattened(&both, "in.exr"),
        &flattened(&carried, "out.exr"),
    );
    // With --all-parts the deep part comes out flattened, as `flatten` makes it.
    let (all, alone) = (d.join("all.exr"), d.join("alone.exr"));
    ok(&["transcode", s(&both), "-o", s(&all), "-q", "--all-parts"]);
    ok(&["flatten", s(&deep), "-o", s(&alone), "-q"]);
    let parts = read_parts(&all);
    assert_eq!(parts.len(), 2);
    assert_identical(&parts[1], &read_image(&alone));
}
