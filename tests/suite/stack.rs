//! `stack L1 ... Ln`: one pass over n layers equals folding `over` from the
//! bottom up exactly, and from the top down within float rounding (alpha
//! composes associatively: a12 = a1 + (1 - a1) a2).

use crate::common::*;
use exr::prelude::{Compression, LineOrder};

/// Random layers: count, windows and alphas from `seed`.
fn layers(seed: u64, kind: fn() -> Kind) -> Vec<Img> {
    let mut rng = Lcg(seed);
    let n = 2 + (rng.next() * 5.0) as usize;
    (0..n)
        .map(|i| {
            let x = (rng.next() * 20.0) as i32 - 10;
            let y = (rng.next() * 20.0) as i32 - 10;
            let w = 10 + (rng.next() * 30.0) as usize;
            let h = 10 + (rng.next() * 30.0) as usize;
            // The bottom layer carries pass-through channels.
            random_rgba(seed * 100 + i as u64, x, y, w, h, kind(), i == n - 1)
        })
        .collect()
}

fn stack(dir: &std::path::Path, layers: &[Img], args: &[&str]) -> Img {
    let paths: Vec<_> = (0..layers.len())
        .map(|i| dir.join(format!("l{i}.exr")))
        .collect();
    for (img, path) in layers.iter().zip(&paths) {
        write_image(path, img, Compression::ZIP16, LineOrder::Increasing);
    }
    let out = dir.join("stack.exr");
    let mut command = vec!["stack"];
    command.extend(paths.iter().map(|p| s(p)));
    command.extend(["-o", s(&out), "-q"]);
    command.extend_from_slice(args);
    let result = run(&command);
    assert!(result.status.success(), "{}", stderr(&result));
    read_image(&out)
}

/// The layers as written, and L1 over (L2 over (... over Ln)): what a chain
/// of `over` runs through files gives.
fn bottom_up(dir: &std::path::Path, count: usize) -> (Vec<Img>, Img) {
    let read: Vec<Img> = (0..count)
        .map(|i| read_image(&dir.join(format!("l{i}.exr"))))
        .collect();
    let mut result = read.last().unwrap().clone();
    for layer in read.iter().rev().skip(1) {
        result = reference_over(layer, &result, false);
    }
    (read, result)
}

/// Every sample within `tolerance` relative (absolute below 1).
fn assert_close(a: &Img, b: &Img, tolerance: f32) {
    assert_eq!((a.x, a.y, a.width, a.height), (b.x, b.y, b.width, b.height));
    assert_eq!(
        a.channels.keys().collect::<Vec<_>>(),
        b.channels.keys().collect::<Vec<_>>()
    );
    for (name, sa) in &a.channels {
        let sb = &b.channels[name];
        for i in 0..sa.len() {
            let (x, y) = (sa.get_f32(i), sb.get_f32(i));
            assert!(
                (x - y).abs() <= tolerance * x.abs().max(1.0),
                "{name}[{i}]: {x} vs {y}"
            );
        }
    }
}

#[test]
fn stack_equals_over_folded_from_the_bottom_and_from_the_top() {
    let dir = tempfile::tempdir().unwrap();
    for seed in 1..=6 {
        let layers = layers(seed, || Kind::Float);
        let strip = (1 + seed % 3 * 7).to_string();
        let ours = stack(dir.path(), &layers, &["--strip-rows", &strip]);
        let (read, reference) = bottom_up(dir.path(), layers.len());
        assert_identical(&ours, &reference);
        // ((L1 over L2) over L3) ...: the same up to rounding.
        let mut top_down = read[0].clone();
        for layer in &read[1..] {
            top_down = reference_over(&top_down, layer, false);
        }
        assert_close(&ours, &top_down, 1e-5);
    }
}

#[test]
fn half_stack_equals_the_bottom_up_fold_and_is_readable_by_openexr() {
    let dir = tempfile::tempdir().unwrap();
    let layers = layers(9, || Kind::Half);
    let ours = stack(dir.path(), &layers, &[]);
    // Each intermediate result is rounded to half, in the stack's merges as
    // in a chain of files.
    let (_, reference) = bottom_up(dir.path(), layers.len());
    assert_identical(&ours, &reference);
    assert_peers_read(&dir.path().join("stack.exr"));
}
