//! Tiled inputs: any tile size, partial tiles at the right and bottom, any
//! line order and lossless compression, read tile row by tile row into the
//! same strips as scanlines; mipmap and ripmap levels with `--level`.

use crate::common::*;
use exr::image::{AnyChannel, AnyChannels, Encoding, FlatSamples, Image, Layer, Levels, RipMaps};
use exr::math::{RoundingMode, Vec2};
use exr::prelude::{Blocks, LayerAttributes, LineOrder, WritableImage};
use std::path::Path;

fn tiles(size: usize, compression_name: &str, line_order: LineOrder) -> Encoding {
    Encoding {
        compression: compression(compression_name),
        blocks: Blocks::Tiles(Vec2(size, size)),
        line_order,
    }
}

/// `exrcomp ARGS`, which must succeed.

#[test]
fn tiled_inputs_transcode_to_their_exact_pixels() {
    let dir = tempfile::tempdir().unwrap();
    let (input, output) = (dir.path().join("in.exr"), dir.path().join("out.exr"));
    // (x, y, width, height, tile): partial tiles right and bottom, tiles
    // wider and taller than the image, whole tiles only.
    let shapes = [
        (0, 0, 97, 61, 32),
        (-3, 5, 130, 70, 64),
        (2, -1, 300, 20, 256),
        (0, 0, 128, 64, 64),
    ];
    let orders = [
        LineOrder::Increasing,
        LineOrder::Decreasing,
        LineOrder::Unspecified,
    ];
    for (seed, &(x, y, width, height, tile)) in shapes.iter().enumerate() {
        let img = random_rgba(seed as u64, x, y, width, height, Kind::Half, true);
        for c in ["none", "zip", "piz"] {
            for order in orders {
                write_encoded(&input, &img, tiles(tile, c, order));
                // Strips of 16 rows (tile rows carried over several strips),
                // and the default strips (several tile rows each).
                for strip in [&["--strip-rows", "16"][..], &[]] {
                    let mut args = vec!["transcode", s(&input), "-o", s(&output), "-q"];
                    args.extend_from_slice(strip);
                    ok(&args);
                    let what = format!("{width}x{height} in {tile}x{tile} tiles, {c}, {order:?}");
                    println!("{what} {strip:?}");
                    assert_identical(&read_image(&output), &img);
                }
            }
        }
    }
    assert_peers_read(&output);
}

#[test]
fn tiled_inputs_read_as_openexr_reads_them() {
    let (Some(oiiotool), Some(idiff)) = (peer("oiiotool"), peer("idiff")) else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let plate = d.join("plate.exr");
    generate(&plate, "bg", (97, 61), &[]);
    let output = d.join("out.exr");
    for (tile, c) in [("32", "zip"), ("64", "piz"), ("16", "none")] {
        let tiled = d.join(format!("tiled_{tile}_{c}.exr"));
        succeed(
            std::process::Command::new(&oiiotool)
                .arg(&plate)
                .args(["--tile", tile, tile, "--compression", c, "-o"])
                .arg(&tiled),
        );
        ok(&["transcode", s(&tiled), "-o", s(&output), "-q"]);
        assert_idiff_identical(&idiff, &tiled, &output);
    }
    // OpenEXR's own tiled images: PIZ 128x128 tiles, and level 0 of a mipmap.
    for name in [
        "Tiles/GoldenGate.exr",
        "MultiResolution/ColorCodedLevels.exr",
    ] {
        let Some(image) = public_image(name) else {
            continue;
        };
        ok(&["transcode", s(&image), "-o", s(&output), "-q"]);
        assert_idiff_identical(&idiff, &image, &output);
    }
}

#[test]
fn tiled_foreground_over_scanline_background_equals_reference() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let (fg_path, bg_path, out) = (d.join("fg.exr"), d.join("bg.exr"), d.join("out.exr"));
    let fg = random_rgba(7, 3, -5, 97, 61, Kind::Float, false);
    let bg = random_rgba(8, -4, 0, 90, 70, Kind::Float, true);
    write_encoded(&fg_path, &fg, tiles(32, "zip", LineOrder::Decreasing));
    write_image(&bg_path, &bg, compression("zip"), LineOrder::Increasing);
    let reference = reference_over(&fg, &bg, false);
    for strip in ["1", "20", "100"] {
        ok(&[
            "over",
            s(&fg_path),
            s(&bg_path),
            "-o",
            s(&out),
            "-q",
            "--strip-rows",
            strip,
        ]);
        assert_identical(&read_image(&out), &reference);
    }
    // And the other way round: a scanline fg over a tiled bg. Below the fg's
    // window a ZIP bg's blocks would pass through if it were scanlines: its
    // tiles pass only into tiles of their size (tests/suite/tiled_output.rs).
    for c in ["zip", "piz"] {
        write_image(&fg_path, &fg, compression(c), LineOrder::Increasing);
        write_encoded(&bg_path, &bg, tiles(64, c, LineOrder::Unspecified));
        ok(&["over", s(&fg_path), s(&bg_path), "-o", s(&out), "-q"]);
        assert_identical(&read_image(&out), &reference);
        assert_peers_read(&out);
    }
}

/// Random half RGBA of each level size given (display window: level 0's).
fn level_images(sizes: &[Vec2<usize>], seed: u64) -> Vec<Img> {
    sizes
        .iter()
        .enumerate()
        .map(|(i, size)| {
            let mut img = random_rgba(seed + i as u64, 0, 0, size.x(), size.y(), Kind::Half, false);
            img.display = (97, 61);
            img
        })
        .collect()
}

/// Writes `levels` (level 0 first) as a mipmap or ripmap, 32x32 ZIP tiles.
fn write_levels(
    path: &Path,
    levels: &[Img],
    rounding_mode: RoundingMode,
    rip: Option<Vec2<usize>>,
) {
    let names: Vec<&String> = levels[0].channels.keys().collect();
    let channels: Vec<AnyChannel<Levels<FlatSamples>>> = names
        .iter()
        .map(|&name| {
            let data: Vec<FlatSamples> = levels
                .iter()
                .map(|level| match &level.channels[name] {
                    Samples::F16(v) => FlatSamples::F16(v.clone()),
                    _ => unreachable!("half levels"),
                })
                .collect();
            let samples = match rip {
                None => Levels::Mip {
                    rounding_mode,
                    level_data: data,
                },
                Some(level_count) => Levels::Rip {
                    rounding_mode,
                    level_data: RipMaps {
                        map_data: data,
                        level_count,
                    },
                },
            };
            AnyChannel::new(name.as_str(), samples)
        })
        .collect();
    let layer = Layer::new(
        (levels[0].width, levels[0].height),
        LayerAttributes::default(),
        tiles(32, "zip", LineOrder::Increasing),
        AnyChannels::sort(channels.into()),
    );
    Image::from_layer(layer).write().to_file(path).unwrap();
}

#[test]
fn level_option_reads_mipmap_and_ripmap_levels() {
    let dir = tempfile::tempdir().unwrap();
    let (input, output) = (dir.path().join("mip.exr"), dir.path().join("out.exr"));
    let size = Vec2(97, 61);
    // `transcode --level LEVEL` of the input gives `expected` exactly.
    let level_is = |level: &str, expected: &Img| {
        ok(&[
            "transcode",
            s(&input),
            "-o",
            s(&output),
            "-q",
            "--level",
            level,
        ]);
        assert_identical(&read_image(&output), expected);
    };
    for (rounding, seed) in [(RoundingMode::Down, 10), (RoundingMode::Up, 20)] {
        let sizes: Vec<Vec2<usize>> = exr::meta::mip_map_levels(rounding, size)
            .map(|(_, s)| s)
            .collect();
        let levels = level_images(&sizes, seed);
        write_levels(&input, &levels, rounding, None);
        for (n, level) in levels.iter().enumerate() {
            level_is(&n.to_string(), level);
        }
        // Level 0 by default, and no level past the last.
        ok(&["transcode", s(&input), "-o", s(&output), "-q"]);
        assert_identical(&read_image(&output), &levels[0]);
        let past = sizes.len().to_string();
        let out = run(&["transcode", s(&input), "-o", s(&output), "--level", &past]);
        assert!(!out.status.success());
        assert!(stderr(&out).contains("has no level"), "{}", stderr(&out));
    }

    let rounding = RoundingMode::Down;
    let indexed: Vec<(Vec2<usize>, Vec2<usize>)> =
        exr::meta::rip_map_levels(rounding, size).collect();
    let sizes: Vec<Vec2<usize>> = indexed.iter().map(|&(_, s)| s).collect();
    let count = Vec2(
        indexed.iter().map(|(i, _)| i.x()).max().unwrap() + 1,
        indexed.iter().map(|(i, _)| i.y()).max().unwrap() + 1,
    );
    let levels = level_images(&sizes, 30);
    write_levels(&input, &levels, rounding, Some(count));
    for (at, (index, _)) in indexed.iter().enumerate() {
        level_is(&format!("{},{}", index.x(), index.y()), &levels[at]);
    }

    // A composite at level 1 takes the level from every input with levels.
    let bg = random_rgba(40, 0, 0, 48, 30, Kind::Half, false);
    let bg_path = dir.path().join("bg.exr");
    write_image(&bg_path, &bg, compression("zip"), LineOrder::Increasing);
    let sizes: Vec<Vec2<usize>> = exr::meta::mip_map_levels(rounding, size)
        .map(|(_, s)| s)
        .collect();
    let levels = level_images(&sizes, 50);
    write_levels(&input, &levels, rounding, None);
    let args = ["over", s(&input), s(&bg_path), "-o", s(&output), "-q"];
    ok(&[&args[..], &["--level", "1"]].concat());
    assert_identical(
        &read_image(&output),
        &reference_over(&levels[1], &bg, false),
    );
}

#[test]
fn levels_of_openexrs_mipmap_read_as_openexr_reads_them() {
    let (Some(oiiotool), Some(idiff)) = (peer("oiiotool"), peer("idiff")) else {
        return;
    };
    let Some(image) = public_image("MultiResolution/ColorCodedLevels.exr") else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let (ours, theirs) = (dir.path().join("ours.exr"), dir.path().join("theirs.exr"));
    for level in ["1", "4", "9"] {
        ok(&[
            "transcode",
            s(&image),
            "-o",
            s(&ours),
            "-q",
            "--level",
            level,
        ]);
        succeed(
            std::process::Command::new(&oiiotool)
                .arg(&image)
                .args(["--selectmip", level, "-o"])
                .arg(&theirs),
        );
        assert_idiff_identical(&idiff, &theirs, &ours);
    }
}

#[test]
fn tiled_inputs_clipped_to_the_result_equal_reference() {
    // `in` keeps the windows' intersection: each ZIP tiled input is wider
    // than the result on one side, so its tiles are cut at the result's
    // columns (straight into the strip, with default strips of whole tile
    // rows; through the carried tiles with strips of 16 rows).
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let (a_path, b_path, out) = (d.join("a.exr"), d.join("b.exr"), d.join("out.exr"));
    let a = random_rgba(11, -7, 0, 90, 64, Kind::Half, false);
    let b = random_rgba(12, 5, 0, 101, 64, Kind::Half, false);
    write_encoded(&a_path, &a, tiles(32, "zip", LineOrder::Increasing));
    write_encoded(&b_path, &b, tiles(16, "zip", LineOrder::Increasing));
    let reference = reference_merge("in", &a, &b, false, 1.0, &[""]);
    for strip in [&["--strip-rows", "16"][..], &[]] {
        let args = [
            "merge",
            "--op",
            "in",
            s(&a_path),
            s(&b_path),
            "-o",
            s(&out),
            "-q",
        ];
        ok(&[&args[..], strip].concat());
        assert_identical(&read_image(&out), &reference);
    }
}
