//! Output blocks where the foreground hides the background
//! (src/engine/opaque.rs): under an opaque foreground (`over`) or any
//! foreground (`copy`), the pixels equal the whole composite, the blocks are
//! the foreground's chunks where its part is laid out as the output, the
//! background's chunks there are only checked (a damaged one is refused),
//! and a stack's top layer hides the layers below.

use crate::common::*;
use crate::passthrough::{check_run, chunks, job_file};
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
