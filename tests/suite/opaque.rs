//! Output blocks where the foreground hides the background
//! (src/engine/opaque.rs): under an opaque foreground (`over`) or any
//! foreground (`copy`), the pixels equal the whole composite, the blocks are
//! the foreground's chunks where its part is laid out as the output, the
//! background's chunks there are only checked (a damaged one is refused),
//! and a stack's layer hides the layers below it: its chunks are the
//! output's blocks where the layers above it are transparent.

use crate::common::*;
use crate::passthrough::{
    a_damaged_chunk_is_refused, check_run, chunks, job_file, same_as_oiiotool,
};
use exr::prelude::{Compression, LineOrder};
use std::path::{Path, PathBuf};

const WIDTH: usize = 40;
const HEIGHT: usize = 70;

/// A random half RGBA image, opaque (alpha 1) outside rows `mixed`, with
/// the colours of those rows as they are.
fn opaque_outside(seed: u64, mixed: std::ops::Range<usize>) -> Img {
    let mut img = random_rgba(seed, 0, 0, WIDTH, HEIGHT, Kind::Half, false);
    for y in (0..HEIGHT).filter(|y| !mixed.contains(y)) {
        for x in 0..WIDTH {
            let i = img.index(x as i32, y as i32).unwrap();
            img.channels.get_mut("A").unwrap().set_f32(i, 1.0);
            img.channels
                .get_mut("R")
                .unwrap()
                .set_f32(i, (x + y) as f32 * 0.25);
        }
    }
    img
}

fn write(dir: &Path, name: &str, img: &Img) -> PathBuf {
    let path = dir.join(name);
    write_image(&path, img, Compression::ZIP16, LineOrder::Increasing);
    path
}

/// Per chunk of `out`, whether its bytes are the same chunk of `input`.
fn copied(out: &Path, input: &Path) -> Vec<bool> {
    let theirs = chunks(input);
    chunks(out)
        .iter()
        .zip(&theirs)
        .map(|(o, t)| o == t)
        .collect()
}

/// `img` with an infinity and a NaN in R at every pixel of rows `rows`.
fn poisoned(img: &Img, rows: std::ops::Range<usize>) -> Img {
    let mut img = img.clone();
    for y in rows {
        for x in 0..WIDTH {
            let i = img.index(x as i32, y as i32).unwrap();
            let value = [f32::INFINITY, f32::NAN][x % 2];
            img.channels.get_mut("R").unwrap().set_f32(i, value);
        }
    }
    img
}

#[test]
fn blocks_under_an_opaque_foreground_are_the_foregrounds_chunks() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    // Blocks of 16 rows: 0..16 and 64..70 opaque, 16..32 and 48..64 mixed
    // (part opaque, part not), 32..48 not opaque anywhere.
    let fg = opaque_outside(1, 20..50);
    let bg = random_rgba(2, 0, 0, WIDTH, HEIGHT, Kind::Half, false);
    let a = write(d, "a.exr", &fg);
    let b = write(d, "b.exr", &bg);
    let reference = reference_merge("over", &fg, &bg, false, 1.0, &[""]);
    let out = d.join("out.exr");
    check_run(&["over", s(&a), s(&b), "-o", s(&out), "--strip-rows", "16"]);
    assert_identical(&read_image(&out), &reference);
    assert_peers_read(&out);
    assert_eq!(
        copied(&out, &a),
        [true, false, false, false, true],
        "which chunks are A's bytes"
    );
    // An infinity or NaN under the opaque blocks is not taken (0 · ∞).
    let poison = write(d, "poison.exr", &poisoned(&bg, 0..16));
    let hidden = d.join("hidden.exr");
    check_run(&["over", s(&a), s(&poison), "-o", s(&hidden)]);
    assert_eq!(
        chunks(&hidden),
        chunks(&out),
        "B's values under A are not read"
    );
    // The same merge as a job file node.
    let job = d.join("over.toml");
    std::fs::write(&job, job_file("over", &["a", "b"])).unwrap();
    check_run(&["run", s(&job)]);
    assert_eq!(
        chunks(&d.join("out.exr")),
        chunks(&out),
        "a job file writes the same"
    );

    // A channel from B alone (Z), another compression, a mix: the result is
    // not A's block, nothing of A passes, and the pixels are the composite's.
    let extra = random_rgba(2, 0, 0, WIDTH, HEIGHT, Kind::Half, true);
    let extra_path = write(d, "extra.exr", &extra);
    let with_z = d.join("z.exr");
    check_run(&["over", s(&a), s(&extra_path), "-o", s(&with_z)]);
    let reference_z = reference_merge("over", &fg, &extra, false, 1.0, &[""]);
    assert_identical(&read_image(&with_z), &reference_z);
    let piz = d.join("piz.exr");
    check_run(&["over", s(&a), s(&b), "-o", s(&piz), "--compression", "piz"]);
    assert_identical(&read_image(&piz), &reference);
    let mixed = d.join("mix.exr");
    check_run(&["over", s(&a), s(&b), "-o", s(&mixed), "--mix", "0.5"]);
    let reference_mix = reference_merge("over", &fg, &bg, false, 0.5, &[""]);
    assert_identical(&read_image(&mixed), &reference_mix);
    assert_eq!(copied(&mixed, &a), [false; 5]);
}

#[test]
fn copy_is_the_foregrounds_chunks_wherever_it_holds_the_block() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let fg = random_rgba(3, 0, 0, WIDTH, HEIGHT, Kind::Half, false);
    let bg = random_rgba(4, 0, 0, WIDTH, HEIGHT, Kind::Half, false);
    let (a, b) = (write(d, "a.exr", &fg), write(d, "b.exr", &bg));
    let out = d.join("out.exr");
    check_run(&["merge", "--op", "copy", s(&a), s(&b), "-o", s(&out)]);
    assert_identical(
        &read_image(&out),
        &reference_merge("copy", &fg, &bg, false, 1.0, &[""]),
    );
    assert_eq!(copied(&out, &a), [true; 5]);
}

#[test]
fn a_stacks_opaque_top_layer_hides_the_layers_below() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let (i1, i2) = (opaque_outside(5, 16..70), opaque_outside(6, 0..40));
    let ib = random_rgba(7, 0, 0, WIDTH, HEIGHT, Kind::Half, false);
    let (l1, l2, bg) = (
        write(d, "l1.exr", &i1),
        write(d, "l2.exr", &i2),
        write(d, "bg.exr", &poisoned(&ib, 0..16)),
    );
    let out = d.join("out.exr");
    check_run(&["stack", s(&l1), s(&l2), s(&bg), "-o", s(&out)]);
    let below = reference_merge("over", &i2, &ib, false, 1.0, &[""]);
    let reference = reference_merge("over", &i1, &below, false, 1.0, &[""]);
    assert_identical(&read_image(&out), &reference);
    // L1 is opaque over block 0 only; L2's opacity lower down is not L1's.
    assert_eq!(copied(&out, &l1), [true, false, false, false, false]);
}

#[test]
fn a_damaged_background_chunk_under_an_opaque_block_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write(d, "a.0001.exr", &opaque_outside(8, 20..50));
    let bg = write(
        d,
        "b.0001.exr",
        &random_rgba(9, 0, 0, WIDTH, HEIGHT, Kind::Half, false),
    );
    // Damaged under A's opaque block 0.
    crate::passthrough::over_of_a_damaged_b_is_refused(d, &bg);
}

/// How a row of a test layer is made.
#[derive(Clone, Copy)]
enum Row {
    /// Transparent black.
    Clear,
    /// Random colours, alpha 1.
    Opaque,
    /// As `random_rgba` makes it.
    Random,
}

/// A random RGBA image whose row y is made as `row(y)` says.
fn layer(seed: u64, kind: fn() -> Kind, row: impl Fn(usize) -> Row) -> Img {
    let mut img = random_rgba(seed, 0, 0, WIDTH, HEIGHT, kind(), false);
    for y in 0..HEIGHT {
        for x in 0..WIDTH {
            let i = img.index(x as i32, y as i32).unwrap();
            match row(y) {
                Row::Clear => img.channels.values_mut().for_each(|s| s.set_f32(i, 0.0)),
                Row::Opaque => img.channels.get_mut("A").unwrap().set_f32(i, 1.0),
                Row::Random => {}
            }
        }
    }
    img
}

/// Blocks of 16 rows. L1: clear but rows 20..40 (blended) and 64..70
/// (opaque); L2: opaque but rows 40..60 (blended).
fn stack_layers(kind: fn() -> Kind) -> [Img; 4] {
    let l1 = layer(10, kind, |y| match y {
        20..=39 => Row::Random,
        64.. => Row::Opaque,
        _ => Row::Clear,
    });
    let l2 = layer(11, kind, |y| match y {
        40..=59 => Row::Random,
        _ => Row::Opaque,
    });
    let random = |seed| random_rgba(seed, 0, 0, WIDTH, HEIGHT, kind(), false);
    [l1, l2, random(12), random(13)]
}

#[test]
fn a_stacks_opaque_middle_layer_hides_the_layers_below_it() {
    stack_with_an_opaque_middle_layer(|| Kind::Half);
    stack_with_an_opaque_middle_layer(|| Kind::Float);
}

fn stack_with_an_opaque_middle_layer(kind: fn() -> Kind) {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let layers = stack_layers(kind);
    let paths: Vec<PathBuf> = (0..4)
        .map(|i| write(d, &format!("l{}.exr", i + 1), &layers[i]))
        .collect();
    let names: Vec<&str> = paths.iter().map(|p| s(p)).collect();
    let out = d.join("out.exr");
    check_run(&[&["stack"], &names[..], &["-o", s(&out)]].concat());
    let reference = layers[..3]
        .iter()
        .rev()
        .fold(layers[3].clone(), |below, l| {
            reference_merge("over", l, &below, false, 1.0, &[""])
        });
    assert_identical(&read_image(&out), &reference);
    assert_peers_read(&out);
    // Block 0: L1 clear over L2 opaque, L2's chunk; block 4: L1 opaque, L1's
    // (the top layer hiding first); block 1: L1 blended over L2 opaque.
    assert_eq!(copied(&out, &paths[1]), [true, false, false, false, false]);
    assert_eq!(copied(&out, &paths[0]), [false, false, false, false, true]);
    // oiiotool keeps each --over's result in the inputs' type: half
    // layers' differ from the float composite where two blend.
    if matches!(kind(), Kind::Float) {
        let over = ["--over"; 3];
        same_as_oiiotool(&paths[0], &[&names[1..], &over[..]].concat(), &out);
    }
    // An infinity or NaN in L3 under L2's opaque blocks 0 and 1 is not taken.
    let poison = write(d, "poison.exr", &poisoned(&layers[2], 0..32));
    let hidden = d.join("hidden.exr");
    let mut poisoned_names = names.clone();
    poisoned_names[2] = s(&poison);
    check_run(&[&["stack"], &poisoned_names[..], &["-o", s(&hidden)]].concat());
    assert_eq!(
        chunks(&hidden),
        chunks(&out),
        "L3's values under L2 are not read"
    );
}

#[test]
fn a_damaged_chunk_under_a_stacks_opaque_middle_layer_is_refused() {
    // Chunk 0 of L3 lies under L2's block that passes, chunk 1 under L2's
    // block that L1 blends over.
    for chunk in [0, 1] {
        let dir = tempfile::tempdir().unwrap();
        let d = dir.path();
        let layers = stack_layers(|| Kind::Half);
        let paths: Vec<PathBuf> = (0..3)
            .map(|i| write(d, &format!("l{}.0001.exr", i + 1), &layers[i]))
            .collect();
        let sequence = |i: usize| d.join(format!("l{}.####.exr", i + 1));
        let (l1, l2, l3) = (sequence(0), sequence(1), sequence(2));
        a_damaged_chunk_is_refused(d, &paths[2], chunk, &["stack", s(&l1), s(&l2), s(&l3)]);
    }
}
