//! OpenEXR's public test images: every good one is read, every damaged one
//! gives a clear error quickly, and a real multi-layer sequence composites.
//! Without the shared set, the few shipped images (tests/images) are read.

use crate::common::*;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::{Duration, Instant};

/// The files under `folder` of the shared set, or of the shipped images
/// when the shared set is absent.
fn files_under(folder: &str) -> Vec<PathBuf> {
    let root = shared_images().unwrap_or_else(shipped_images);
    let mut found = Vec::new();
    let mut stack = vec![root.join(folder)];
    while let Some(dir) = stack.pop() {
        for entry in std::fs::read_dir(&dir).unwrap_or_else(|e| panic!("{}: {e}", dir.display())) {
            let path = entry.unwrap().path();
            if path.is_dir() {
                stack.push(path);
            } else {
                found.push(path);
            }
        }
    }
    found.sort();
    found
}

/// Every good (not Damaged) image of the shipped set, the shared set and the
/// second shared set, by its path in the sets; a shared copy wins over the
/// shipped one.
fn good_images() -> Vec<(String, PathBuf)> {
    let mut roots = vec![shipped_images()];
    roots.extend(shared_images());
    roots.extend(shared_more_images());
    let mut found = std::collections::BTreeMap::new();
    for root in roots {
        let mut stack = vec![root.clone()];
        while let Some(dir) = stack.pop() {
            for entry in std::fs::read_dir(&dir).unwrap() {
                let path = entry.unwrap().path();
                let name = path
                    .strip_prefix(&root)
                    .unwrap()
                    .to_string_lossy()
                    .into_owned();
                if path.is_dir() && name != "Damaged" {
                    stack.push(path);
                } else if path.extension().is_some_and(|e| e == "exr") {
                    found.insert(name, path);
                }
            }
        }
    }
    found.into_iter().collect()
}

/// Each part's name, and whether the (first part of the) file is deep, has
/// levels, has colour (R, G, B) and alpha, from its headers.
fn describe(path: &Path) -> (Vec<String>, bool, bool, bool, bool) {
    let meta = exr::meta::MetaData::read_from_file(path, false).unwrap();
    let names = meta
        .headers
        .iter()
        .map(|h| {
            h.own_attributes
                .layer_name
                .as_ref()
                .map(|n| n.to_string())
                .unwrap_or_default()
        })
        .collect();
    let first = &meta.headers[0];
    let levels = matches!(first.blocks, exr::meta::BlockDescription::Tiles(t)
        if t.level_mode != exr::meta::attribute::LevelMode::Singular);
    let colour = ["R", "G", "B"]
        .iter()
        .all(|c| first.channels.list.iter().any(|d| d.name.eq(c)));
    let alpha = first.channels.list.iter().any(|d| d.name.eq("A"));
    (names, first.deep, levels, colour, alpha)
}

/// What is wrong with one image through `info`, `transcode` and `over`
/// with itself, checked against idiff and oiiotool where they read it.
fn check_image(
    path: &Path,
    dir: &Path,
    oiiotool: Option<&Path>,
    idiff: Option<&Path>,
) -> Result<(), String> {
    let out = run(&["info", s(path)]);
    let text = String::from_utf8_lossy(&out.stdout);
    if !out.status.success() {
        return Err(format!("info: {}", stderr(&out).trim()));
    }
    if !(text.contains("dataWindow (type box2i): (") && text.contains("channels (type chlist):")) {
        return Err(format!("info prints no window or channels:\n{text}"));
    }
    if !text.contains("pixels: all") {
        return Err(format!("info does not check every chunk:\n{text}"));
    }
    let transcoded = dir.join("transcoded.exr");
    let out = run(&["transcode", s(path), "-o", s(&transcoded), "-q"]);
    if !out.status.success() {
        return Err(format!("transcode: {}", stderr(&out).trim()));
    }
    let (names, deep, levels, colour, alpha) = describe(path);
    let (names_out, ..) = describe(&transcoded);
    if names != names_out {
        return Err(format!(
            "transcode: parts {names:?} came out as {names_out:?}"
        ));
    }
    let oiio = |args: &[&str], out: &Path| {
        let status = Command::new(oiiotool.unwrap())
            .args(args)
            .arg("-o")
            .arg(out)
            .output()
            .unwrap();
        status.status.success()
    };
    let differ = |a: &Path, b: &Path, all: bool| -> Option<String> {
        let mut command = Command::new(idiff?);
        command.args(["-fail", "0", "-warn", "0"]);
        if all {
            command.arg("-a");
        }
        let out = command.arg(a).arg(b).output().unwrap();
        // A file idiff cannot read (subsampled channels: tests/suite/luminance_chroma.rs
        // checks those) says so on stderr.
        (!out.status.success()).then(|| {
            String::from_utf8_lossy(&out.stdout).into_owned()
                + &String::from_utf8_lossy(&out.stderr)
        })
    };
    match (deep, oiiotool.is_some()) {
        // idiff compares no deep file with a flat one: against oiiotool's
        // flattening, on the channels both compute (Z differs on purpose).
        (true, true) => {
            let (ours, theirs) = (dir.join("ours.exr"), dir.join("theirs.exr"));
            if oiio(&[s(&transcoded), "--ch", "R,G,B,A"], &ours)
                && oiio(&[s(path), "--flatten", "--ch", "R,G,B,A"], &theirs)
            {
                if let Some(d) = differ(&ours, &theirs, false) {
                    return Err(format!("transcode differs from oiiotool --flatten:\n{d}"));
                }
            }
        }
        (true, false) => {}
        // A mipmap's level 0 is what is read: idiff's first level.
        (false, _) => {
            if let Some(d) = differ(path, &transcoded, !levels) {
                if !d.contains("Could not read") {
                    return Err(format!("transcode differs from the input:\n{d}"));
                }
            }
        }
    }
    if !colour {
        return Ok(());
    }
    let composited = dir.join("over.exr");
    let out = run(&["over", s(path), s(path), "-o", s(&composited), "-q"]);
    if !out.status.success() {
        return Err(format!("over: {}", stderr(&out).trim()));
    }
    if !alpha {
        // Opaque (specs/ops.md, "Alpha"): over itself is the input itself.
        // oiiotool refuses `--over` without alpha.
        if let Some(d) = differ(path, &composited, !levels) {
            return Err(format!("over of an opaque image differs from it:\n{d}"));
        }
    } else if oiiotool.is_some() {
        let (ours, theirs) = (dir.join("ours.exr"), dir.join("theirs.exr"));
        let rgba = ["--ch", "R,G,B,A"];
        if oiio(
            &[
                s(path),
                rgba[0],
                rgba[1],
                s(path),
                rgba[0],
                rgba[1],
                "--over",
            ],
            &theirs,
        ) && oiio(&[s(&composited), rgba[0], rgba[1]], &ours)
        {
            if let Some(d) = differ(&ours, &theirs, false) {
                return Err(format!("over differs from oiiotool --over:\n{d}"));
            }
        }
    }
    Ok(())
}

/// Issue 14's "done means": every good image of OpenEXR's public test
/// collection we have passes `info`, `transcode` (pixels equal by `idiff
/// -fail 0`, every part kept by name) and, with colour, `over` with itself
/// (equal to `oiiotool --over`).
#[test]
fn every_good_image_passes_info_transcode_and_over_with_itself() {
    let (oiiotool, idiff) = (peer("oiiotool"), peer("idiff"));
    let dir = tempfile::tempdir().unwrap();
    let images = good_images();
    assert!(!images.is_empty());
    let mut failures = Vec::new();
    for (name, path) in &images {
        let result = check_image(path, dir.path(), oiiotool.as_deref(), idiff.as_deref());
        if let Err(e) = result {
            failures.push(format!("{name}: {e}"));
        }
    }
    eprintln!("{} images checked", images.len());
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn info_rejects_every_damaged_file_quickly_and_cleanly() {
    let damaged = files_under("Damaged");
    assert!(!damaged.is_empty());
    for path in damaged {
        let started = Instant::now();
        let out = limited(&["info", path.to_str().unwrap()]);
        let message = stderr(&out);
        assert_eq!(
            out.status.code(),
            Some(3),
            "{}: exit {:?}, {message}",
            path.display(),
            out.status
        );
        assert!(
            message.contains(path.file_name().unwrap().to_str().unwrap()),
            "error must name the file: {message}"
        );
        assert_eq!(
            message.lines().count(),
            1,
            "one line, no panic trace: {message}"
        );
        assert!(!message.contains("panicked"), "{message}");
        assert!(
            started.elapsed() < Duration::from_secs(10),
            "{} took {:?}",
            path.display(),
            started.elapsed()
        );
    }
}

#[test]
fn two_frames_of_the_beachball_sequence_composite_like_the_reference() {
    // fg frame N is Beachball frame N + 1, over Beachball frame N: a real
    // multi-layer sequence whose many extra channels pass through from bg.
    let Some(images) = shared_images() else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let beachball = images.join("Beachball");
    for frame in 1..=2 {
        let source = beachball.join(format!("singlepart.{:04}.exr", frame + 1));
        std::fs::copy(&source, dir.path().join(format!("fg.{frame:04}.exr"))).unwrap();
    }
    let fg = dir.path().join("fg.####.exr");
    let bg = beachball.join("singlepart.####.exr");
    let out = dir.path().join("comp.####.exr");
    let result = run(&[
        "over",
        fg.to_str().unwrap(),
        bg.to_str().unwrap(),
        "-o",
        out.to_str().unwrap(),
        "--frames",
        "1-2",
        "-q",
    ]);
    assert!(result.status.success(), "{}", stderr(&result));
    for frame in 1..=2 {
        let ours = read_image(&dir.path().join(format!("comp.{frame:04}.exr")));
        let reference = reference_over(
            &read_image(&dir.path().join(format!("fg.{frame:04}.exr"))),
            &read_image(&beachball.join(format!("singlepart.{frame:04}.exr"))),
            false,
        );
        assert!(ours.channels.len() > 4, "extra channels pass through");
        assert_identical(&ours, &reference);
        assert_peers_read(&dir.path().join(format!("comp.{frame:04}.exr")));
    }
}

#[test]
fn mipmapped_tiled_input_composites_at_level_0() {
    let Some(path) = public_image("MultiResolution/ColorCodedLevels.exr") else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out.exr");
    let result = run(&["over", s(&path), s(&path), "-o", s(&out), "-q"]);
    assert!(result.status.success(), "{}", stderr(&result));
    let level0 = read_image(&path);
    assert_identical(&read_image(&out), &reference_over(&level0, &level0, false));
    assert_peers_read(&out);
}
