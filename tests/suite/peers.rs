//! Cross-checks with the peer tools: oiiotool computes the same `over`, and
//! OpenEXR's own library decodes every file we write.

use crate::common::*;
use std::path::Path;
use std::process::Command;

#[test]
fn over_equals_oiiotool_over_with_offset_data_windows() {
    let (Some(oiiotool), Some(idiff)) = (peer("oiiotool"), peer("idiff")) else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    for pixel_type in ["half", "float"] {
        generate(
            &d.join("fg.exr"),
            "fg",
            (200, 100),
            &["--origin", "13,-7", "--pixel-type", pixel_type],
        );
        generate(
            &d.join("bg.exr"),
            "bg",
            (180, 120),
            &["--origin", "-5,4", "--pixel-type", pixel_type],
        );
        let out = run(&[
            "over",
            d.join("fg.exr").to_str().unwrap(),
            d.join("bg.exr").to_str().unwrap(),
            "-o",
            d.join("ours.exr").to_str().unwrap(),
            "-q",
        ]);
        assert!(out.status.success(), "{}", stderr(&out));
        assert_peers_read(&d.join("ours.exr"));
        // oiiotool needs equal channel counts: compare the RGBA both compute.
        let status = Command::new(&oiiotool)
            .arg(d.join("fg.exr"))
            .args(["--ch", "R,G,B,A"])
            .arg(d.join("bg.exr"))
            .args(["--ch", "R,G,B,A", "--over", "-d", pixel_type, "-o"])
            .arg(d.join("theirs.exr"))
            .status()
            .unwrap();
        assert!(status.success());
        let status = Command::new(&oiiotool)
            .arg(d.join("ours.exr"))
            .args(["--ch", "R,G,B,A", "-d", pixel_type, "-o"])
            .arg(d.join("ours_rgba.exr"))
            .status()
            .unwrap();
        assert!(status.success());
        assert_idiff_identical(&idiff, &d.join("theirs.exr"), &d.join("ours_rgba.exr"));
    }
}

#[test]
fn every_output_compression_decodes_in_openexr() {
    let Some(idiff) = peer("idiff") else { return };
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    generate(&d.join("fg.exr"), "fg", (97, 61), &["--origin", "3,2"]);
    generate(&d.join("bg.exr"), "bg", (90, 70), &["--origin", "0,0"]);
    let over = |compression: &str, out: &Path| {
        let result = run(&[
            "over",
            d.join("fg.exr").to_str().unwrap(),
            d.join("bg.exr").to_str().unwrap(),
            "-o",
            out.to_str().unwrap(),
            "--compression",
            compression,
            "-q",
        ]);
        assert!(
            result.status.success(),
            "{compression}: {}",
            stderr(&result)
        );
        assert_peers_read(out);
    };
    over("none", &d.join("none.exr"));
    for c in [
        "rle", "zips", "zip", "piz", "pxr24", "b44", "b44a", "dwaa", "dwab",
    ] {
        let path = d.join(format!("{c}.exr"));
        over(c, &path);
        // Lossless codecs (pxr24 is lossy for the float Z): the pixels are
        // those of the uncompressed output.
        if ["rle", "zips", "zip", "piz"].contains(&c) {
            assert_idiff_identical(&idiff, &d.join("none.exr"), &path);
        }
    }
}

#[test]
fn transcoding_real_photographs_is_lossless_and_readable() {
    let Some(idiff) = peer("idiff") else { return };
    let dir = tempfile::tempdir().unwrap();
    for name in [
        "ScanLines/Desk.exr",
        "ScanLines/Cannon.exr",
        "Beachball/singlepart.0001.exr",
        "TestImages/AllHalfValues.exr",
    ] {
        let Some(source) = public_image(name) else {
            continue;
        };
        for c in ["zip", "zips", "piz"] {
            let out = dir.path().join(format!("{c}.exr"));
            let result = run(&[
                "transcode",
                source.to_str().unwrap(),
                "-o",
                out.to_str().unwrap(),
                "--compression",
                c,
                "-q",
            ]);
            assert!(result.status.success(), "{name}: {}", stderr(&result));
            assert_peers_read(&out);
            assert_idiff_identical(&idiff, &source, &out);
        }
    }
}

#[test]
fn a_higher_dwa_level_writes_smaller_files_that_record_it() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let input = d.join("in.exr");
    generate(&input, "bg", (256, 192), &[]);
    let level = |path: &Path| {
        let meta = exr::meta::MetaData::read_from_file(path, false).unwrap();
        match meta.headers[0].compression {
            exr::prelude::Compression::DWAA(level) | exr::prelude::Compression::DWAB(level) => {
                level
            }
            other => panic!("{other:?}"),
        }
    };
    for compression in ["dwaa", "dwab"] {
        let sizes: Vec<u64> = ["5", "45", "500"]
            .iter()
            .map(|n| {
                let out = d.join(format!("{compression}-{n}.exr"));
                let result = run(&[
                    "transcode",
                    s(&input),
                    "-o",
                    s(&out),
                    "--compression",
                    compression,
                    "--dwa-level",
                    n,
                    "-q",
                ]);
                assert!(result.status.success(), "{}", stderr(&result));
                assert_eq!(level(&out), Some(n.parse().unwrap()));
                assert_peers_read(&out);
                std::fs::metadata(&out).unwrap().len()
            })
            .collect();
        assert!(
            sizes[0] > sizes[1] && sizes[1] > sizes[2],
            "{compression}: {sizes:?}"
        );
    }
    let out = d.join("x.exr");
    for (args, message) in [
        (
            vec!["--compression", "dwaa", "--dwa-level=-1"],
            "dwa_level must be a number from 0 to",
        ),
        (
            vec!["--compression", "dwaa", "--dwa-level", "nan"],
            "dwa_level must be a number from 0 to",
        ),
        (
            vec!["--compression", "zip", "--dwa-level", "45"],
            "--dwa-level applies to dwaa and dwab",
        ),
    ] {
        let mut command = vec!["transcode", s(&input), "-o", s(&out)];
        command.extend_from_slice(&args);
        let result = run(&command);
        assert_eq!(result.status.code(), Some(2), "{args:?}");
        assert!(
            stderr(&result).contains(message),
            "{args:?}: {}",
            stderr(&result)
        );
    }
}

/// OpenEXR 3.5 (PyPI's) writes what OpenEXR 3.1 cannot: HTJ2K (3.4) and
/// ZSTD (3.5). Read, they are refused in one line naming the file and the
/// compression; an HTJ2K part beside the part worked on is carried as it is,
/// and OpenEXR 3.5 reads it back.
#[test]
fn newer_compressions_are_refused_clearly_and_an_htj2k_part_is_carried() {
    let Some(python) = openexr_python() else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let script = r#"
import OpenEXR, numpy, sys
rgb = numpy.random.default_rng(1).random((24, 32, 3)).astype("f2")
def header(c):
    return {"compression": c, "type": OpenEXR.scanlineimage}
for name, c in [("htj2k", OpenEXR.HTJ2K32_COMPRESSION), ("zstd", OpenEXR.ZSTD_COMPRESSION)]:
    OpenEXR.File(header(c), {"RGB": rgb}).write(f"{name}.exr")
OpenEXR.File([
    OpenEXR.Part(header(OpenEXR.ZIP_COMPRESSION), {"RGB": rgb}, "flat"),
    OpenEXR.Part(header(OpenEXR.HTJ2K256_COMPRESSION), {"RGB": rgb}, "jpeg"),
]).write("two.exr")
"#;
    succeed(Command::new(&python).args(["-c", script]).current_dir(d));
    let out = d.join("out.exr");
    for (name, message) in [
        ("htj2k", "HTJ2K compression is not supported"),
        ("zstd", "compression code 13 is not supported"),
        ("two", "HTJ2K compression is not supported"),
    ] {
        let input = d.join(format!("{name}.exr"));
        // The HTJ2K part: the second of two.
        let part = format!("{}:{}", s(&input), usize::from(name == "two"));
        let mut commands = vec![
            vec!["info", s(&input)],
            vec!["over", &part, &part, "-o", s(&out)],
        ];
        if name != "two" {
            commands.push(vec!["transcode", s(&input), "-o", s(&out)]);
        }
        for args in commands {
            let result = run(&args);
            let text = stderr(&result);
            assert_eq!(result.status.code(), Some(3), "{args:?}: {text}");
            assert!(
                text.contains(s(&input)) && text.contains(message),
                "{args:?}: {text}"
            );
            assert_eq!(text.trim().lines().count(), 1, "{text}");
        }
    }
    let two = d.join("two.exr");
    let result = run(&[
        "transcode",
        s(&two),
        "-o",
        s(&out),
        "-q",
        "--compression",
        "piz",
    ]);
    assert!(result.status.success(), "{}", stderr(&result));
    assert_eq!(part_chunks(&out, 1), part_chunks(&two, 1));
    let same = r#"
import OpenEXR, numpy, sys
a, b = (OpenEXR.File(p, separate_channels=True) for p in sys.argv[1:])
assert len(b.parts) == 2 and b.parts[1].header["compression"] == OpenEXR.HTJ2K256_COMPRESSION
for pa, pb in zip(a.parts, b.parts):
    for name, channel in pa.channels.items():
        assert numpy.array_equal(channel.pixels, pb.channels[name].pixels), name
"#;
    succeed(Command::new(&python).args(["-c", same]).arg(&two).arg(&out));
}
