//! Tiled output (`--tile WxH`, a job's `tile` key): one level, increasing
//! line order, any tile size on any data window, the input's pixels exactly;
//! and a tiled background's tiles copied as they are where the foreground
//! is transparent, as scanline blocks are.

use crate::common::*;
use exr::block::chunk::CompressedBlock;
use exr::math::Vec2;
use exr::meta::attribute::{LevelMode, LineOrder};
use exr::meta::BlockDescription;
use exr::prelude::{Blocks, Encoding};
use exrcomp::io::reader::ExrFile;
use std::path::Path;

/// `path` is a single-level tiled file of `tile` tiles in increasing line
/// order, its chunks in the file in table order (row by row, left to right).
fn assert_tiled(path: &Path, tile: (usize, usize)) {
    let file = ExrFile::open(path, None).unwrap();
    let header = file.header(0);
    let BlockDescription::Tiles(tiles) = header.blocks else {
        panic!("{} is not tiled", path.display());
    };
    assert_eq!(tiles.tile_size, Vec2(tile.0, tile.1));
    assert_eq!(tiles.level_mode, LevelMode::Singular);
    assert_eq!(header.line_order, LineOrder::Increasing);
    let size = header.layer_size;
    let count = size.width().div_ceil(tile.0) * size.height().div_ceil(tile.1);
    assert_eq!(header.chunk_count, count, "one chunk per tile");
    let starts: Vec<u64> = (0..count).map(|k| file.chunk_range(0, k).start).collect();
    assert!(
        starts.windows(2).all(|w| w[0] < w[1]),
        "tiles written in table order"
    );
}

fn tiled(size: usize) -> Encoding {
    Encoding {
        compression: compression("zip"),
        blocks: Blocks::Tiles(Vec2(size, size)),
        line_order: LineOrder::Increasing,
    }
}

#[test]
fn tiled_output_holds_the_input_pixels() {
    let idiff = peer("idiff");
    let dir = tempfile::tempdir().unwrap();
    let (input, output) = (dir.path().join("in.exr"), dir.path().join("out.exr"));
    // (x, y, width, height): odd sizes, windows off the origin, one wider
    // than tall; tiles that divide nothing, thin ones, one larger than the
    // image, one pixel.
    let shapes = [(0, 0, 97, 61), (-3, 5, 130, 70), (2, -1, 300, 20)];
    let sizes = [(64, 64), (16, 16), (32, 8), (7, 50), (256, 256), (1, 1)];
    for (seed, &(x, y, width, height)) in shapes.iter().enumerate() {
        let img = random_rgba(seed as u64, x, y, width, height, Kind::Half, true);
        write_image(&input, &img, compression("zip"), LineOrder::Decreasing);
        for (w, h) in sizes {
            for c in ["zip", "piz", "none"] {
                let tile = format!("{w}x{h}");
                let args = ["transcode", s(&input), "-o", s(&output), "-q"];
                ok(&[&args[..], &["--tile", &tile, "--compression", c]].concat());
                println!("{width}x{height} at {x},{y} in {tile} tiles, {c}");
                assert_tiled(&output, (w, h));
                assert_identical(&read_image(&output), &img);
            }
            assert_peers_read(&output);
            if let Some(exrheader) = peer("exrheader") {
                let out = succeed(std::process::Command::new(exrheader).arg(&output));
                let text = String::from_utf8_lossy(&out.stdout);
                let tiles = format!("single level\n    tile size {w} by {h} pixels");
                assert!(text.contains(&tiles), "exrheader shows {text}");
            }
            if let Some(idiff) = &idiff {
                assert_idiff_identical(idiff, &input, &output);
            }
        }
    }
    // Strips of one tile row, and of rows that are not a tile row (rounded
    // up to whole tile rows); `N` is N x N.
    let img = random_rgba(9, 1, 2, 83, 77, Kind::Float, true);
    write_image(&input, &img, compression("piz"), LineOrder::Increasing);
    for strip in ["1", "20", "1000"] {
        ok(&[
            "transcode",
            s(&input),
            "-o",
            s(&output),
            "-q",
            "--tile",
            "20",
            "--strip-rows",
            strip,
        ]);
        assert_tiled(&output, (20, 20));
        assert_identical(&read_image(&output), &img);
    }
}

/// A job file in `d`, `over.toml`: a.exr over b.exr into job.exr, whose
/// write node also holds `write_key`.
fn over_job(d: &Path, write_key: &str) -> std::path::PathBuf {
    let job = d.join("over.toml");
    let text = format!(
        "[[node]]\nname = \"a\"\nread = \"a.exr\"\n\n[[node]]\nname = \"b\"\nread = \"b.exr\"\n\n\
         [[node]]\nname = \"comp\"\nop = \"over\"\ninputs = [\"a\", \"b\"]\n\n\
         [[node]]\nname = \"out\"\nwrite = \"job.exr\"\ninputs = [\"comp\"]\n{write_key}\n"
    );
    std::fs::write(&job, text).unwrap();
    job
}

/// The compressed bytes of every tile of `path`, in table order.
fn tiles(path: &Path) -> Vec<Vec<u8>> {
    let file = ExrFile::open(path, None).unwrap();
    (0..file.header(0).chunk_count)
        .map(|k| match file.read_chunk(0, k).unwrap().compressed_block {
            CompressedBlock::Tile(tile) => tile.compressed_pixels_le,
            _ => panic!("tiles"),
        })
        .collect()
}

#[test]
fn tiles_under_a_transparent_foreground_are_the_backgrounds_tiles() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let (width, height) = (80, 70);
    // Visible in rows 20..35 and columns 10..25 only: with 16x16 tiles, the
    // tiles of columns 0 and 1 in rows 1 and 2 blend, all others pass.
    let sparse = |top: i32| {
        let mut fg = random_rgba(1, 0, top, width, height, Kind::Half, false);
        for y in top..top + height as i32 {
            for x in 0..width as i32 {
                if !((20..35).contains(&y) && (10..25).contains(&x)) {
                    let i = fg.index(x, y).unwrap();
                    fg.channels.values_mut().for_each(|c| c.set_f32(i, 0.0));
                }
            }
        }
        fg
    };
    let fg = sparse(0);
    let bg = random_rgba(2, 0, 0, width, height, Kind::Half, false);
    let (a, b, out) = (d.join("a.exr"), d.join("b.exr"), d.join("out.exr"));
    write_encoded(&a, &fg, tiled(16));
    write_encoded(&b, &bg, tiled(16));
    let reference = reference_merge("over", &fg, &bg, false, 1.0, &[""]);
    let across = width.div_ceil(16);
    let blending = |k: usize| (1..=2).contains(&(k / across)) && k % across <= 1;
    let mut written = None;
    for strip in ["16", "40"] {
        let args = ["over", s(&a), s(&b), "-o", s(&out), "-q", "--tile", "16"];
        ok(&[&args[..], &["--strip-rows", strip]].concat());
        assert_identical(&read_image(&out), &reference);
        let (ours, theirs) = (tiles(&out), tiles(&b));
        let same: Vec<bool> = ours.iter().zip(&theirs).map(|(o, t)| o == t).collect();
        let expected: Vec<bool> = (0..theirs.len()).map(|k| !blending(k)).collect();
        assert_eq!(same, expected, "which tiles are B's bytes");
        written = Some(ours);
    }
    assert_peers_read(&out);
    // The job file's `tile` key writes the same file.
    let job = over_job(d, "tile = \"16x16\"");
    ok(&["run", s(&job), "-q"]);
    let written = written.unwrap();
    assert_eq!(tiles(&d.join("job.exr")), written);
    // Without --tile the output is tiled as B is: the same file.
    ok(&["over", s(&a), s(&b), "-o", s(&out), "-q"]);
    assert_eq!(tiles(&out), written, "B's tiling followed");
    // A foreground window a tile row above B's: the output's tile rows are
    // B's one row down, its tiles renumbered.
    let taller = sparse(-16);
    write_encoded(&a, &taller, tiled(16));
    ok(&["over", s(&a), s(&b), "-o", s(&out), "-q", "--tile", "16"]);
    assert_identical(
        &read_image(&out),
        &reference_merge("over", &taller, &bg, false, 1.0, &[""]),
    );
    let (ours, theirs) = (tiles(&out), tiles(&b));
    assert_eq!(ours.len(), theirs.len() + across, "one more tile row");
    let same: Vec<bool> = ours[across..]
        .iter()
        .zip(&theirs)
        .map(|(o, t)| o == t)
        .collect();
    let expected: Vec<bool> = (0..theirs.len()).map(|k| !blending(k)).collect();
    assert_eq!(same, expected, "B's tiles, one row down");
    assert_peers_read(&out);
    write_encoded(&a, &fg, tiled(16));
    // Other tiles than B's, or scanlines into tiles: nothing passes, and the
    // pixels are the same.
    for (input, tile) in [(&b, "32"), (&b, "16x32")] {
        ok(&["over", s(&a), s(input), "-o", s(&out), "-q", "--tile", tile]);
        assert_identical(&read_image(&out), &reference);
    }
    let scanlines = d.join("scanlines.exr");
    write_image(&scanlines, &bg, compression("zip"), LineOrder::Increasing);
    ok(&[
        "over",
        s(&a),
        s(&scanlines),
        "-o",
        s(&out),
        "-q",
        "--tile",
        "16",
    ]);
    assert_identical(&read_image(&out), &reference);
    assert!(tiles(&out).iter().zip(tiles(&b)).all(|(o, t)| *o != t));
}

/// Whether `path`'s first part is scanlines.
fn is_scanlines(path: &Path) -> bool {
    let file = ExrFile::open(path, None).unwrap();
    matches!(file.header(0).blocks, BlockDescription::ScanLines)
}

#[test]
fn the_output_is_tiled_as_the_background_is_unless_told() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let (fg, bg) = (
        random_rgba(4, 0, 0, 45, 33, Kind::Half, false),
        random_rgba(5, 0, 0, 45, 33, Kind::Half, false),
    );
    let (a, b, out) = (d.join("a.exr"), d.join("b.exr"), d.join("out.exr"));
    write_encoded(&a, &fg, tiled(8));
    write_encoded(&b, &bg, tiled(16));
    let reference = reference_merge("over", &fg, &bg, false, 1.0, &[""]);
    // B's tiles, not A's; and a transcode keeps its input's.
    ok(&["over", s(&a), s(&b), "-o", s(&out), "-q"]);
    assert_tiled(&out, (16, 16));
    assert_identical(&read_image(&out), &reference);
    ok(&["transcode", s(&a), "-o", s(&out), "-q"]);
    assert_tiled(&out, (8, 8));
    // A scanline B gives scanlines under a tiled A.
    let scanlines = d.join("scanlines.exr");
    write_image(&scanlines, &bg, compression("zip"), LineOrder::Increasing);
    ok(&["over", s(&a), s(&scanlines), "-o", s(&out), "-q"]);
    assert!(is_scanlines(&out));
    // --scanline and the job file's `scanline = true` write scanlines;
    // --tile wins over the job's key.
    ok(&["over", s(&a), s(&b), "-o", s(&out), "-q", "--scanline"]);
    assert!(is_scanlines(&out));
    assert_identical(&read_image(&out), &reference);
    let job = over_job(d, "scanline = true");
    ok(&["run", s(&job), "-q"]);
    assert!(is_scanlines(&d.join("job.exr")));
    ok(&["run", s(&job), "-q", "--tile", "4"]);
    assert_tiled(&d.join("job.exr"), (4, 4));
    let both = run(&[
        "over",
        s(&a),
        s(&b),
        "-o",
        s(&out),
        "--scanline",
        "--tile",
        "4",
    ]);
    assert_eq!(both.status.code(), Some(2), "--scanline with --tile");
    // A mipmapped B: one level of its tile size.
    if let Some(maketiled) = peer("exrmaketiled") {
        let mip = d.join("mip.exr");
        let args = [s(&scanlines), s(&mip)];
        succeed(
            std::process::Command::new(maketiled)
                .args(["-m", "-t", "16", "16"])
                .args(args),
        );
        ok(&["over", s(&a), s(&mip), "-o", s(&out), "-q"]);
        assert_tiled(&out, (16, 16));
        assert_identical(&read_image(&out), &reference);
    }
}

#[test]
fn bad_tile_sizes_are_usage_errors() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let input = d.join("in.exr");
    let img = random_rgba(3, 0, 0, 20, 20, Kind::Half, false);
    write_image(&input, &img, compression("zip"), LineOrder::Increasing);
    let out = d.join("out.exr");
    for tile in ["0", "64x", "x64", "64x0", "65537", "big"] {
        let result = run(&["transcode", s(&input), "-o", s(&out), "--tile", tile]);
        assert_eq!(result.status.code(), Some(2), "--tile {tile}");
        assert!(stderr(&result).contains("tile size"), "{}", stderr(&result));
    }
    // Tiles whose blocks no reader takes (ours refuses blocks over 512 MiB,
    // OpenEXR tiles over 2 GiB): 8193 x 8193 half RGBA is 537 MB.
    for tile in ["8193", "16384x16384"] {
        let result = run(&["transcode", s(&input), "-o", s(&out), "--tile", tile]);
        assert_eq!(result.status.code(), Some(2), "--tile {tile}");
        assert!(
            stderr(&result).contains("give a smaller --tile"),
            "{}",
            stderr(&result)
        );
        assert!(!out.exists());
    }
    // Bands are scanline blocks for `stitch`: not with tiles.
    let result = run(&[
        "transcode",
        s(&input),
        "-o",
        s(&out),
        "--tile",
        "16",
        "--rows",
        "0-16",
    ]);
    assert_eq!(result.status.code(), Some(2));
    assert!(stderr(&result).contains("--rows"), "{}", stderr(&result));
    assert!(!out.exists());
    // Nor does stitch join tiled files: rows 0-16 in tiles, 16-20 in
    // scanlines, of one 20x20 image.
    let (top, bottom) = (d.join("top.exr"), d.join("bottom.exr"));
    ok(&[
        "transcode",
        s(&input),
        "-o",
        s(&top),
        "-q",
        "--rows",
        "0-16",
    ]);
    let tiled = d.join("tiled.exr");
    ok(&["transcode", s(&top), "-o", s(&tiled), "-q", "--tile", "16"]);
    ok(&[
        "transcode",
        s(&input),
        "-o",
        s(&bottom),
        "-q",
        "--rows",
        "16-20",
    ]);
    let result = run(&["stitch", s(&tiled), s(&bottom), "-o", s(&out)]);
    assert_eq!(result.status.code(), Some(3));
    assert!(stderr(&result).contains("tiled.exr"), "{}", stderr(&result));
    assert!(!out.exists());
    // A job file's bad tile names its line.
    let job = d.join("job.toml");
    std::fs::write(
        &job,
        "[[node]]\nname = \"a\"\nread = \"in.exr\"\n\n\
         [[node]]\nname = \"out\"\nwrite = \"out.exr\"\ninputs = [\"a\"]\ntile = \"16y16\"\n",
    )
    .unwrap();
    let result = run(&["run", s(&job)]);
    assert_eq!(result.status.code(), Some(2));
    assert!(
        stderr(&result).contains("job.toml:9"),
        "{}",
        stderr(&result)
    );
}
