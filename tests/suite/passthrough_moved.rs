//! Output blocks copied from an input's chunks when the ops move its pixels
//! by whole blocks (`crop --cut`, a crop of other columns of tiles;
//! src/engine/passthrough.rs): those chunks are the input's bytes stored at
//! the output's coordinates, the pixels are the op's as computed (the same
//! run encoded) and oiiotool's.

use crate::common::*;
use crate::passthrough::{check_run, chunks, run_as_encoded, same_as_oiiotool};
use exr::block::chunk::CompressedBlock;
use exr::math::Vec2;
use exr::meta::BlockDescription;
use exr::prelude::{Blocks, Compression, Encoding, LineOrder};
use exrcomp::io::reader::ExrFile;
use std::path::Path;

/// Per chunk of `out`, the index of `input`'s chunk whose bytes it is.
fn sources(out: &Path, input: &Path) -> Vec<Option<usize>> {
    let theirs = chunks(input);
    chunks(out)
        .iter()
        .map(|o| theirs.iter().position(|t| t == o))
        .collect()
}

/// Every chunk of `path` stores the block its place in the offset table
/// says: a scanline block its first row, a tile its column and row.
pub fn assert_placed(path: &Path) {
    let file = ExrFile::open(path, None).unwrap();
    let header = file.header(0);
    let window = header.data_window();
    for k in 0..header.chunk_count {
        match (
            file.read_chunk(0, k).unwrap().compressed_block,
            header.blocks,
        ) {
            (CompressedBlock::ScanLine(block), BlockDescription::ScanLines) => {
                let lines = header.compression.scan_lines_per_block() as i32;
                assert_eq!(block.y_coordinate, window.position.y() + k as i32 * lines);
            }
            (CompressedBlock::Tile(tile), BlockDescription::Tiles(tiles)) => {
                let across = window.size.width().div_ceil(tiles.tile_size.x());
                let at = Vec2(k % across, k / across);
                assert_eq!(tile.coordinates.tile_index, at, "chunk {k}");
            }
            _ => panic!("flat chunks of the part's kind"),
        }
    }
}

/// `crop IN ARGS` (checked by `run_as_encoded`, its chunks' coordinates
/// too): per output chunk, the input's it copies.
fn crop(input: &Path, args: &[&str], theirs: &[&str]) -> Vec<Option<usize>> {
    let out = input.with_file_name("out.exr");
    run_as_encoded("crop", input, args, theirs, &out);
    assert_placed(&out);
    sources(&out, input)
}

#[test]
fn a_cut_on_the_block_grid_copies_the_chunks_it_keeps_whole() {
    let dir = tempfile::tempdir().unwrap();
    let b = dir.path().join("b.exr");
    // Rows 5..75 in chunks of 16 rows: 5..21, 21..37, 37..53, 53..69 and
    // 69..75; half RGBA, float Z and u32 ids.
    let img = random_rgba(21, 3, 5, 40, 70, Kind::Half, true);
    write_image(&b, &img, Compression::ZIP16, LineOrder::Increasing);
    for (region, expected) in [
        // Two whole chunks, moved 21 rows up.
        ("40x32+3+21", vec![Some(1), Some(2)]),
        // The last block cut short (8 rows of a 16-row chunk): encoded.
        ("40x40+3+21", vec![Some(1), Some(2), None]),
        // The input's last, short chunk is the output's last block.
        ("40x22+3+53", vec![Some(3), Some(4)]),
        // Black rows above the input, then two of its chunks.
        ("40x48+3-11", vec![None, Some(0), Some(1)]),
        // Off the grid, other columns, black columns beside: encoded.
        ("40x32+3+13", vec![None; 2]),
        ("39x32+4+21", vec![None; 2]),
        ("42x32+2+21", vec![None; 2]),
    ] {
        let got = crop(&b, &["--region", region, "--cut"], &["--cut", region]);
        assert_eq!(got, expected, "--cut {region}");
    }
}

#[test]
fn tiles_moved_by_whole_tiles_are_copied_by_a_cut_or_a_crop() {
    let dir = tempfile::tempdir().unwrap();
    let b = dir.path().join("b.exr");
    // 16x16 tiles of a 70x50 window at (3, 5): columns 3, 19, 35, 51, 67
    // (6 wide), rows 5, 21, 37, 53 (2 tall); tile (c, r) is chunk 5r + c.
    let img = random_rgba(22, 3, 5, 70, 50, Kind::Half, true);
    let encoding = Encoding {
        compression: Compression::ZIP16,
        blocks: Blocks::Tiles(Vec2(16, 16)),
        line_order: LineOrder::Increasing,
    };
    write_encoded(&b, &img, encoding);
    let cut = |region: &'static str| (vec!["--region", region, "--cut"], vec!["--cut", region]);
    let kept = |region: &'static str| (vec!["--region", region], vec!["--crop", region]);
    for ((args, theirs), expected) in [
        (
            cut("32x32+19+21"),
            vec![Some(6), Some(7), Some(11), Some(12)],
        ),
        // To the input's right and bottom edges: its short tiles too.
        (
            cut("38x34+35+21"),
            [7, 8, 9, 12, 13, 14, 17, 18, 19].map(Some).to_vec(),
        ),
        // A tile wider than the input's last (black beside), one shorter
        // than its row: encoded.
        (
            cut("40x20+51+5"),
            vec![Some(3), None, None, None, None, None],
        ),
        (cut("32x32+20+21"), vec![None; 4]),
        // A crop of other columns: the output's tiles count from its corner.
        (
            kept("32x32+19+21"),
            vec![Some(6), Some(7), Some(11), Some(12)],
        ),
        (
            kept("40x32+19+21"),
            vec![Some(6), Some(7), None, Some(11), Some(12), None],
        ),
    ] {
        let got = crop(&b, &args, &theirs);
        assert_eq!(got, expected, "{args:?}");
    }
}

#[test]
fn a_cut_of_a_shared_multi_channel_plate_copies_whole_rows_only() {
    let Some(images) = shared_images() else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    // 20 half channels, ZIPS (a chunk a row), data window (654, 245) to
    // (1564, 1120) in a 2048x1556 frame.
    let b = dir.path().join("beachball.exr");
    std::fs::copy(images.join("Beachball/singlepart.0001.exr"), &b).unwrap();
    let rows: Vec<Option<usize>> = (55..455).map(Some).collect();
    assert_eq!(
        crop(
            &b,
            &["--region", "911x400+654+300", "--cut"],
            &["--cut", "911x400+654+300"]
        ),
        rows
    );
    assert_eq!(
        crop(
            &b,
            &["--region", "900x400+660+300", "--cut"],
            &["--cut", "900x400+660+300"]
        ),
        vec![None; 400]
    );
}

#[test]
fn a_merge_under_or_over_a_cut_passes_where_its_foreground_is_transparent() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    // A visible in rows 36..40 only: in B's chunk 2 (rows 32..48).
    let mut a = random_rgba(23, 0, 0, 40, 70, Kind::Half, false);
    for y in (0..70).filter(|y| !(36..40).contains(y)) {
        for x in 0..40 {
            let i = a.index(x, y).unwrap();
            a.channels.values_mut().for_each(|s| s.set_f32(i, 0.0));
        }
    }
    let b = random_rgba(24, 0, 0, 40, 70, Kind::Half, false);
    for (name, img) in [("a.exr", &a), ("b.exr", &b)] {
        write_image(
            &d.join(name),
            img,
            Compression::ZIP16,
            LineOrder::Increasing,
        );
    }
    let read = "[[node]]\nname = \"a\"\nread = \"a.exr\"\n\n\
                [[node]]\nname = \"b\"\nread = \"b.exr\"\n\n";
    let cut = |input: &str| {
        format!(
            "[[node]]\nname = \"cut\"\nop = \"crop\"\nregion = \"40x48+0+16\"\ncut = true\n\
             inputs = [\"{input}\"]\n\n"
        )
    };
    let over = |bottom: &str| {
        format!("[[node]]\nname = \"comp\"\nop = \"over\"\ninputs = [\"a\", \"{bottom}\"]\n\n")
    };
    let write = |top: &str| {
        format!("[[node]]\nname = \"out\"\nwrite = \"out.exr\"\ninputs = [\"{top}\"]\n")
    };
    // The cut of the composite: output rows 0..48 are its rows 16..64.
    let cut_over = format!("{read}{}{}{}", over("b"), cut("comp"), write("cut"));
    let whole = reference_merge("over", &a, &b, false, 1.0, &[""]);
    let out = d.join("out.exr");
    let job = d.join("job.toml");
    std::fs::write(&job, cut_over).unwrap();
    check_run(&["run", s(&job)]);
    let reference = d.join("reference.exr");
    write_image(
        &reference,
        &whole,
        Compression::ZIP16,
        LineOrder::Increasing,
    );
    let expected = d.join("expected.exr");
    check_run(&[
        "crop",
        s(&reference),
        "-o",
        s(&expected),
        "--region",
        "40x48+0+16",
        "--cut",
    ]);
    assert_identical(&read_image(&out), &read_image(&expected));
    same_as_oiiotool(&reference, &["--cut", "40x48+0+16"], &out);
    assert_eq!(sources(&out, &d.join("b.exr")), [Some(1), None, Some(3)]);
    assert_placed(&out);

    // A over the cut B: A's rows 32..48 (output block 2) hide B's rows 48..64.
    let over_cut = format!("{read}{}{}{}", cut("b"), over("cut"), write("comp"));
    std::fs::write(&job, over_cut).unwrap();
    check_run(&["run", s(&job)]);
    let cut_b = d.join("cut_b.exr");
    check_run(&[
        "crop",
        s(&d.join("b.exr")),
        "-o",
        s(&cut_b),
        "--region",
        "40x48+0+16",
        "--cut",
    ]);
    let reference = reference_merge("over", &a, &read_image(&cut_b), false, 1.0, &[""]);
    assert_identical(&read_image(&out), &reference);
    // Rows 48..70 are A's alone, beyond the cut.
    assert_eq!(
        sources(&out, &d.join("b.exr")),
        [Some(1), Some(2), None, None, None]
    );
    assert_placed(&out);
}

/// `reformat` at the same size is a placement: every chunk is the input's,
/// stored at the output's coordinates, scanline or tiled, its data window
/// the display window (as oiiotool's --fit, which drops the data window's
/// offset, is compared) or offset in it; at another size none is.
#[test]
fn a_reformat_that_keeps_the_size_copies_every_chunk() {
    let dir = tempfile::tempdir().unwrap();
    let b = dir.path().join("b.exr");
    let full = random_rgba(25, 0, 0, 70, 50, Kind::Half, true);
    let mut offset = random_rgba(26, 3, 5, 70, 50, Kind::Half, true);
    offset.display = (76, 60);
    let tiles = Encoding {
        compression: Compression::ZIP16,
        blocks: Blocks::Tiles(Vec2(16, 16)),
        line_order: LineOrder::Increasing,
    };
    let out = dir.path().join("out.exr");
    for (encoding, count) in [(zip_scanlines(), 4), (tiles, 20)] {
        let all: Vec<Option<usize>> = (0..count).map(Some).collect();
        let mut full = full.clone();
        full.display = (70, 50);
        write_encoded(&b, &full, encoding);
        // Centred in a format as tall or as wide: 4 columns right, 3 rows
        // down.
        for format in ["70x50", "78x50", "70x56"] {
            let args = ["--format", format, "--fit", "fit", "--center"];
            run_as_encoded("reformat", &b, &args, &["--fit", format], &out);
            assert_placed(&out);
            assert_eq!(sources(&out, &b), all, "{format}");
        }
        let half = ["--format", "35x25", "--fit", "fit", "--quiet"];
        check_run(&[&["reformat", s(&b), "-o", s(&out)][..], &half].concat());
        assert!(sources(&out, &b).iter().all(Option::is_none));
        write_encoded(&b, &offset, encoding);
        let centred = ["--format", "76x66", "--fit", "width", "--center", "--quiet"];
        check_run(&[&["reformat", s(&b), "-o", s(&out)][..], &centred].concat());
        let mut expected = offset.clone();
        (expected.x, expected.y, expected.display) = (3, 8, (76, 66));
        assert_identical(&read_image(&out), &expected);
        assert_placed(&out);
        assert_eq!(sources(&out, &b), all, "offset");
    }
}
