//! TIFF inputs (specs/file-format.md, "TIFF"): files oiiotool writes in
//! every listed variant (8/16-bit integer and 32-bit float; strips and
//! tiles; none, LZW, Deflate, PackBits; contiguous and planar; grey, RGB,
//! RGBA associated and unassociated) and the shared libtiff pictures, read
//! as oiiotool reads them (`idiff -fail 0`); the classes not read and
//! damaged files refused in one line with nothing written.

use crate::common::{peer, stderr};
use crate::foreign_inputs::{assert_as_oiiotool, assert_refused, foreign_images, transcode};
use std::path::Path;
use std::process::Command;

const PATTERN: &str =
    "fill:topleft=0,0,0,0:topright=1,0.2,0.5,0.3:bottomleft=0.3,1,0.7,1:bottomright=1,1,1,0.6";

/// `oiiotool --pattern ... 67x45 4 --ch CHANNELS ARGS -o PATH`.
fn make(oiiotool: &Path, path: &Path, channels: &str, args: &[&str]) {
    let made = Command::new(oiiotool)
        .args(["--pattern", PATTERN, "67x45", "4", "--ch", channels])
        .args(args)
        .arg("-o")
        .arg(path)
        .output()
        .unwrap();
    assert!(made.status.success(), "{}", stderr(&made));
}

#[test]
fn every_listed_variant_reads_as_oiiotool_reads_it() {
    let Some(oiiotool) = peer("oiiotool") else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let mut k = 0;
    for depth in ["uint8", "uint16", "float"] {
        for compression in ["none", "lzw", "zip", "packbits"] {
            for layout in [
                &[][..],
                &["--tile", "16", "16"],
                &["--planarconfig", "separate"],
            ] {
                for channels in ["0", "0,1,2", "0,1,2,3"] {
                    k += 1;
                    let input = dir.path().join(format!("v{k}.tif"));
                    let mut args = vec!["-d", depth, "--compression", compression];
                    args.extend(layout);
                    make(&oiiotool, &input, channels, &args);
                    let output = input.with_extension("exr");
                    transcode(&input, &output, &[]);
                    assert_as_oiiotool(&input, &output, depth != "uint8");
                }
            }
        }
    }
    for depth in ["uint8", "uint16"] {
        let input = dir.path().join(format!("unassociated-{depth}.tif"));
        let unassociated = ["--attrib", "oiio:UnassociatedAlpha", "1", "-d", depth];
        make(&oiiotool, &input, "0,1,2,3", &unassociated);
        let output = input.with_extension("exr");
        transcode(&input, &output, &[]);
        assert_as_oiiotool(&input, &output, depth != "uint8");
    }
}

#[test]
fn shared_tiffs_read_as_oiiotool_reads_them() {
    let Some(root) = foreign_images() else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    // White-is-zero grey, a palette, 32-bit unsigned samples, old-style LZW
    // codes, tiles placed by the strips' tags (the SGI library's) and of
    // samples of format "void" among them.
    let read = [
        ("checker.tif", false),
        ("grid.tif", false),
        ("libtiffpic/ladoga.tif", true),
        ("libtiffpic/cramps.tif", false),
        ("libtiffpic/cramps-tile.tif", false),
        ("libtiffpic/quad-lzw.tif", false),
        ("libtiffpic/quad-tile.tif", false),
        ("libtiffpic/depth/flower-minisblack-08.tif", false),
        ("libtiffpic/depth/flower-minisblack-16.tif", true),
        ("libtiffpic/depth/flower-palette-08.tif", false),
        ("libtiffpic/depth/flower-rgb-contig-08.tif", false),
        ("libtiffpic/depth/flower-rgb-contig-16.tif", true),
        ("libtiffpic/depth/flower-rgb-contig-32.tif", true),
        ("libtiffpic/depth/flower-rgb-planar-08.tif", false),
        ("libtiffpic/depth/flower-rgb-planar-16.tif", true),
    ];
    for (file, float) in read {
        let input = root.join(file);
        let output = dir
            .path()
            .join(Path::new(file).with_extension("exr").file_name().unwrap());
        transcode(&input, &output, &[]);
        assert_as_oiiotool(&input, &output, float);
    }
}

#[test]
fn damaged_tiffs_are_refused_in_one_line_and_nothing_is_written() {
    let Some(oiiotool) = peer("oiiotool") else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let good = dir.path().join("good.tif");
    make(
        &oiiotool,
        &good,
        "0,1,2",
        &["-d", "uint16", "--compression", "lzw"],
    );
    let good = std::fs::read(good).unwrap();
    let cases: Vec<(&str, Vec<u8>, &str)> = vec![
        ("cut", good[..good.len() / 3].to_vec(), "does not decode"),
        ("header", good[..6].to_vec(), "not a readable TIFF"),
    ];
    assert_refused(dir.path(), "tif", cases);
}
