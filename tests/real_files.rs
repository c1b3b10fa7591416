//! OpenEXR's public test images: every good one is read, every damaged one
//! gives a clear error quickly, and a real multi-layer sequence composites.
//! Without the shared set, the few shipped images (tests/images) are read.

mod common;
use common::*;
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
