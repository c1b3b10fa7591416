//! Output blocks copied from the background's chunks where the foreground is
//! transparent black (src/engine/passthrough.rs): the pixels equal the whole
//! composite, those chunks are the background's bytes, and a damaged chunk
//! is still refused.

use crate::common::*;
use exr::block::chunk::CompressedBlock;
use exr::prelude::{Compression, LineOrder};
use exrcomp::io::reader::ExrFile;
use std::path::{Path, PathBuf};

const WIDTH: usize = 40;
const HEIGHT: usize = 70;

/// A random half RGBA image, transparent black outside rows `visible`.
fn sparse(seed: u64, visible: std::ops::Range<usize>) -> Img {
    let mut img = random_rgba(seed, 0, 0, WIDTH, HEIGHT, Kind::Half, false);
    for y in (0..HEIGHT).filter(|y| !visible.contains(y)) {
        for x in 0..WIDTH {
            let i = img.index(x as i32, y as i32).unwrap();
            img.channels.values_mut().for_each(|s| s.set_f32(i, 0.0));
        }
    }
    img
}

fn write(dir: &Path, name: &str, img: &Img) -> PathBuf {
    let path = dir.join(name);
    write_image(&path, img, Compression::ZIP16, LineOrder::Increasing);
    path
}

/// The compressed bytes of every chunk of `path`, in table order.
pub fn chunks(path: &Path) -> Vec<Vec<u8>> {
    let file = ExrFile::open(path, None).unwrap();
    (0..file.header(0).chunk_count)
        .map(|k| match file.read_chunk(0, k).unwrap().compressed_block {
            CompressedBlock::ScanLine(block) => block.compressed_pixels_le,
            CompressedBlock::Tile(tile) => tile.compressed_pixels_le,
            _ => panic!("flat chunks"),
        })
        .collect()
}

pub fn check_run(args: &[&str]) {
    let out = run(args);
    assert!(out.status.success(), "{args:?}: {}", stderr(&out));
}

#[test]
fn blocks_under_a_transparent_foreground_are_the_backgrounds_chunks() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    // Visible in rows 20..35: blocks 1 and 2 (rows 16..48) blend, blocks 0,
    // 3 and 4 (the last one 6 rows) pass.
    let a = write(d, "a.exr", &sparse(1, 20..35));
    let b = write(
        d,
        "b.exr",
        &random_rgba(2, 0, 0, WIDTH, HEIGHT, Kind::Half, true),
    );
    let out = d.join("out.exr");
    check_run(&["over", s(&a), s(&b), "-o", s(&out), "--strip-rows", "16"]);
    let reference = reference_merge("over", &read_image(&a), &read_image(&b), false, 1.0, &[""]);
    assert_identical(&read_image(&out), &reference);
    assert_peers_read(&out);
    let (ours, theirs) = (chunks(&out), chunks(&b));
    let same: Vec<bool> = ours.iter().zip(&theirs).map(|(o, t)| o == t).collect();
    assert_eq!(
        same,
        [true, false, false, true, true],
        "which chunks are B's bytes"
    );
    // The same merge as a job file node.
    let job = d.join("over.toml");
    std::fs::write(&job, job_file("over", &["a", "b"])).unwrap();
    check_run(&["run", s(&job)]);
    assert_eq!(chunks(&out), ours, "the job file writes the same bytes");

    // Another output compression, or a window other than B's: nothing
    // passes, and the pixels are the same.
    let piz = d.join("piz.exr");
    check_run(&["over", s(&a), s(&b), "-o", s(&piz), "--compression", "piz"]);
    assert_identical(&read_image(&piz), &reference);
    let shifted = d.join("shifted.exr");
    let moved = random_rgba(3, 2, 0, WIDTH, HEIGHT, Kind::Half, true);
    let moved_path = write(d, "moved.exr", &moved);
    check_run(&["over", s(&a), s(&moved_path), "-o", s(&shifted)]);
    let reference = reference_merge("over", &read_image(&a), &moved, false, 1.0, &[""]);
    assert_identical(&read_image(&shifted), &reference);
}

#[test]
fn a_stack_passes_where_every_layer_above_the_bottom_is_transparent() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let l1 = write(d, "l1.exr", &sparse(4, 3..10));
    let l2 = write(d, "l2.exr", &sparse(5, 50..52));
    let bg = write(
        d,
        "bg.exr",
        &random_rgba(6, 0, 0, WIDTH, HEIGHT, Kind::Half, true),
    );
    let out = d.join("out.exr");
    check_run(&["stack", s(&l1), s(&l2), s(&bg), "-o", s(&out)]);
    let (i1, i2, ib) = (read_image(&l1), read_image(&l2), read_image(&bg));
    let below = reference_merge("over", &i2, &ib, false, 1.0, &[""]);
    assert_identical(
        &read_image(&out),
        &reference_merge("over", &i1, &below, false, 1.0, &[""]),
    );
    let same: Vec<bool> = chunks(&out)
        .iter()
        .zip(&chunks(&bg))
        .map(|(o, t)| o == t)
        .collect();
    assert_eq!(same, [false, true, true, false, true]);
}

#[test]
fn a_damaged_chunk_that_would_pass_is_refused_naming_file_and_frame() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let a = sparse(7, 20..35);
    let b = random_rgba(8, 0, 0, WIDTH, HEIGHT, Kind::Half, true);
    write(d, "a.0001.exr", &a);
    let bg = write(d, "b.0001.exr", &b);
    over_of_a_damaged_b_is_refused(d, &bg);
}

/// With `bg` (`d/b.0001.exr`) damaged inside chunk 0's deflate stream
/// (after its 8-byte header: the chunk still has its size, only
/// decompressing finds the damage), `over a.#### b.####` exits 3 naming the
/// file, frame and chunk, and writes nothing.
pub fn over_of_a_damaged_b_is_refused(d: &Path, bg: &Path) {
    let (a, b) = (d.join("a.####.exr"), d.join("b.####.exr"));
    a_damaged_chunk_is_refused(d, bg, 0, &["over", s(&a), s(&b)]);
}

/// Damages chunk `chunk` of frame 1 `damaged` (in `d`), then checks that
/// `command` writing out.####.exr in `d` is refused naming the file, the
/// frame and the chunk, writing nothing.
pub fn a_damaged_chunk_is_refused(d: &Path, damaged: &Path, chunk: usize, command: &[&str]) {
    let file = ExrFile::open(damaged, None).unwrap();
    let at = file.chunk_range(0, chunk);
    drop(file);
    let mut bytes = std::fs::read(damaged).unwrap();
    let middle = (at.start + 8 + (at.end - at.start - 8) / 2) as usize;
    bytes[middle] ^= 0x5a;
    std::fs::write(damaged, bytes).unwrap();
    let output = d.join("out.####.exr");
    let out = run(&[command, &["-o", s(&output)]].concat());
    assert_eq!(out.status.code(), Some(3), "{}", stderr(&out));
    let message = stderr(&out);
    let name = damaged.file_name().unwrap().to_str().unwrap();
    let named = [name, "(frame 1)", &format!("chunk {chunk}")]
        .iter()
        .all(|w| message.contains(w));
    assert!(named, "{message}");
    assert!(
        !d.join("out.0001.exr").exists(),
        "no output for a damaged input"
    );
}

/// A job file writing merge `op` of nodes `inputs` (reading NAME.exr) to
/// out.exr.
pub fn job_file(op: &str, inputs: &[&str]) -> String {
    let mut names = inputs.to_vec();
    names.dedup();
    let reads: String = names
        .iter()
        .map(|n| format!("[[node]]\nname = \"{n}\"\nread = \"{n}.exr\"\n\n"))
        .collect();
    format!(
        "{reads}[[node]]\nname = \"comp\"\nop = \"{op}\"\ninputs = [\"{}\", \"{}\"]\n\n\
         [[node]]\nname = \"out\"\nwrite = \"out.exr\"\ninputs = [\"comp\"]\n",
        inputs[0], inputs[1]
    )
}

#[test]
fn one_input_on_both_sides_of_a_merge_is_composited_not_passed() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let img = sparse(9, 20..35);
    write(d, "b.exr", &img);
    let job = d.join("self.toml");
    std::fs::write(&job, job_file("over", &["b", "b"])).unwrap();
    check_run(&["run", s(&job)]);
    let reference = reference_merge("over", &img, &img, false, 1.0, &[""]);
    assert_identical(&read_image(&d.join("out.exr")), &reference);
}

/// Per chunk `k` of `out`, whether its bytes are chunk `k + shift` of
/// `input`.
fn copied(out: &Path, input: &Path, shift: isize) -> Vec<bool> {
    let theirs = chunks(input);
    chunks(out)
        .iter()
        .enumerate()
        .map(|(k, o)| theirs.get(k.wrapping_add_signed(shift)) == Some(o))
        .collect()
}

/// `oiiotool IN ARGS -o THEIRS` and `idiff -fail 0` against `ours`, when
/// both peers are there.
pub fn same_as_oiiotool(input: &Path, args: &[&str], ours: &Path) {
    let (Some(oiiotool), Some(idiff)) = (peer("oiiotool"), peer("idiff")) else {
        return;
    };
    let theirs = ours.with_extension("oiio.exr");
    let status = std::process::Command::new(oiiotool)
        .arg(input)
        .args(args)
        .arg("-o")
        .arg(&theirs)
        .status()
        .unwrap();
    assert!(status.success(), "oiiotool {args:?}");
    assert_idiff_identical(&idiff, ours, &theirs);
}

#[test]
fn a_rename_that_keeps_the_channel_order_copies_every_chunk() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let img = random_rgba(10, 0, 0, WIDTH, HEIGHT, Kind::Half, false);
    let b = write(d, "b.exr", &img);
    let out = d.join("out.exr");
    let renamed = |from: &str, to: &str| {
        let mut expected = img.clone();
        let samples = expected.channels.remove(from).unwrap();
        expected.channels.insert(to.to_string(), samples);
        expected
    };
    // (--ch, the pixels, whether the chunks are B's): a reorder and a
    // rename that keep the sorted order copy; a rename that moves a channel
    // in the list, or a drop, changes the block's layout and is encoded.
    let mut dropped = img.clone();
    dropped.channels.remove("A");
    for (ch, expected, copies) in [
        ("R,G,B,A", img.clone(), true),
        ("A,B,G,Y=R", renamed("R", "Y"), true),
        ("A,AA=R,B,G", renamed("R", "AA"), false),
        ("R,G,B", dropped, false),
    ] {
        check_run(&["shuffle", s(&b), "-o", s(&out), "--ch", ch]);
        assert_identical(&read_image(&out), &expected);
        assert_eq!(copied(&out, &b, 0), [copies; 5], "--ch {ch}");
        assert_peers_read(&out);
        same_as_oiiotool(&b, &["--ch", ch], &out);
    }
}

/// A window change: the command, its arguments, oiiotool's, the input's
/// chunk at the output's first (counted from it), and which output chunks
/// are the input's bytes.
type Case = (
    &'static str,
    &'static [&'static str],
    &'static [&'static str],
    isize,
    &'static [bool],
);

#[test]
fn crops_and_pads_on_the_block_grid_copy_the_chunks_they_keep_whole() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    // Chunks of 16 rows: 0..16, 16..32, 32..48, 48..64, 64..70.
    let b = write(
        d,
        "b.exr",
        &random_rgba(11, 0, 0, WIDTH, HEIGHT, Kind::Half, true),
    );
    let out = d.join("out.exr");
    let cases: [Case; 6] = [
        // Rows on the grid: 16..48; 16..56 (its last block cut short).
        (
            "crop",
            &["--region", "40x32+0+16"],
            &["--crop", "40x32+0+16"],
            1,
            &[true; 2],
        ),
        (
            "crop",
            &["--region", "40x40+0+16"],
            &["--crop", "40x40+0+16"],
            1,
            &[true, true, false],
        ),
        // Off the grid, or other columns: nothing is copied.
        (
            "crop",
            &["--region", "40x32+0+8"],
            &["--crop", "40x32+0+8"],
            0,
            &[false; 2],
        ),
        (
            "crop",
            &["--region", "39x32+1+16"],
            &["--crop", "39x32+1+16"],
            1,
            &[false; 2],
        ),
        // The display window alone.
        (
            "crop",
            &["--region", "40x70+0+0", "--display"],
            &["--crop", "40x70+0+0", "--fullsize", "40x70+0+0"],
            0,
            &[true; 5],
        ),
        // Overscan of 16 rows above and below: rows -16..86, the input's
        // whole blocks copied, its short last one (6 rows in a block of 16)
        // and the black ones encoded.
        (
            "pad",
            &["--by", "0,16,0,16"],
            &["--crop", "40x102+0-16"],
            -1,
            &[false, true, true, true, true, false, false],
        ),
    ];
    for (command, args, theirs, first, expected) in cases {
        run_as_encoded(command, &b, args, theirs, &out);
        let got = copied(&out, &b, first);
        assert_eq!(got, expected, "{command} {args:?}");
    }
}

/// `COMMAND INPUT ARGS -o OUT`, its pixels checked against the same run
/// encoded (PIZ: nothing copied, the pixels as the ops compute them), read by
/// the peers and compared with oiiotool's `INPUT THEIRS`.
pub fn run_as_encoded(command: &str, input: &Path, args: &[&str], theirs: &[&str], out: &Path) {
    let encoded = out.with_extension("piz.exr");
    let mut all = vec![command, s(input), "-o", s(out)];
    all.extend(args);
    check_run(&all);
    all[3] = s(&encoded);
    all.extend(["--compression", "piz"]);
    check_run(&all);
    assert_identical(&read_image(out), &read_image(&encoded));
    assert_peers_read(out);
    same_as_oiiotool(input, theirs, out);
}

#[test]
fn a_merge_over_a_crop_passes_only_where_the_crop_keeps_the_pixels() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let a = sparse(12, 20..35);
    write(d, "a.exr", &a);
    let b = write(
        d,
        "b.exr",
        &random_rgba(13, 0, 0, WIDTH, HEIGHT, Kind::Half, true),
    );
    for (region, expected) in [
        // Rows 16..70: the blocks without the element (visible in rows
        // 20..35) and inside the crop pass.
        ("40x54+0+16", [false, false, false, true, true]),
        // Columns 0..30: the merge's window is A's 40, the crop's black
        // beside B's pixels: nothing passes.
        ("30x70+0+0", [false; 5]),
    ] {
        let job = d.join("job.toml");
        let text = format!(
            "[[node]]\nname = \"a\"\nread = \"a.exr\"\n\n\
             [[node]]\nname = \"b\"\nread = \"b.exr\"\n\n\
             [[node]]\nname = \"cropped\"\nop = \"crop\"\nregion = \"{region}\"\n\
             inputs = [\"b\"]\n\n\
             [[node]]\nname = \"comp\"\nop = \"over\"\ninputs = [\"a\", \"cropped\"]\n\n\
             [[node]]\nname = \"out\"\nwrite = \"out.exr\"\ninputs = [\"comp\"]\n"
        );
        std::fs::write(&job, text).unwrap();
        check_run(&["run", s(&job)]);
        let cropped = d.join("cropped.exr");
        check_run(&["crop", s(&b), "-o", s(&cropped), "--region", region]);
        let reference = reference_merge("over", &a, &read_image(&cropped), false, 1.0, &[""]);
        let out = d.join("out.exr");
        assert_identical(&read_image(&out), &reference);
        assert_eq!(copied(&out, &b, 0), expected, "crop {region}");
    }
}

#[test]
fn a_rename_after_a_merge_still_passes_the_backgrounds_chunks() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let a = sparse(14, 20..35);
    write(d, "a.exr", &a);
    let img = random_rgba(15, 0, 0, WIDTH, HEIGHT, Kind::Half, false);
    let b = write(d, "b.exr", &img);
    let job = d.join("job.toml");
    let text = job_file("over", &["a", "b"]).replace(
        "inputs = [\"comp\"]",
        "inputs = [\"renamed\"]",
    ) + "\n[[node]]\nname = \"renamed\"\nop = \"shuffle\"\nch = \"A,B,G,Y=R\"\ninputs = [\"comp\"]\n";
    std::fs::write(&job, text).unwrap();
    check_run(&["run", s(&job)]);
    let out = d.join("out.exr");
    let mut expected = reference_merge("over", &a, &img, false, 1.0, &[""]);
    let red = expected.channels.remove("R").unwrap();
    expected.channels.insert("Y".into(), red);
    assert_identical(&read_image(&out), &expected);
    assert_eq!(copied(&out, &b, 0), [true, false, false, true, true]);
}
