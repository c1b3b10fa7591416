//! `--slate`: the frame before the shot's first, black with the job's
//! metadata in the built-in font; its pixels against a layout computed
//! here (scale, margins, line spacing) with each glyph from the font's
//! table; written once by a chunked run, kept by --resume, the same bytes
//! each run, listed by --dry-run, refused over an input.

use crate::common::{assert_peers_read, ok, read_image, run, s, stderr, write_image, Img, Samples};
use exr::prelude::{Compression, LineOrder};
use std::collections::BTreeMap;
use std::path::Path;

/// 480 rows: the font at twice its size.
const W: usize = 240;
const H: usize = 480;

/// Frames 5 to 7 of a grey plate, `in.####.exr` in `dir`.
fn inputs(dir: &Path) {
    for frame in 5..=7 {
        let mut channels = BTreeMap::new();
        for name in ["R", "G", "B"] {
            channels.insert(name.to_string(), Samples::F32(vec![0.18; W * H]));
        }
        let img = Img {
            x: 0,
            y: 0,
            width: W,
            height: H,
            display: (W, H),
            channels,
        };
        let path = dir.join(format!("in.{frame:04}.exr"));
        write_image(&path, &img, Compression::ZIP16, LineOrder::Increasing);
    }
}

/// Whether (x, y) of an image `height` rows tall is a lit pixel of `lines`
/// drawn from the top-left: font pixels of `height / 240` image pixels,
/// each line in a box of one font pixel round its 7-row glyphs (6 columns
/// a character), 2 font pixels from the edges, one between boxes.
fn lit(lines: &[&str], height: usize, x: usize, y: usize) -> bool {
    let scale = (height / 240).max(1);
    let (fx, fy) = (x / scale, y / scale);
    let Some(fy) = fy.checked_sub(2) else {
        return false;
    };
    let (line, row) = (fy / 10, fy % 10);
    let (Some(text), Some(gx), Some(gy)) = (
        lines.get(line),
        fx.checked_sub(3),
        row.checked_sub(1).filter(|&r| r < 7),
    ) else {
        return false;
    };
    let (c, column) = (gx / 6, gx % 6);
    text.chars()
        .nth(c)
        .is_some_and(|c| column < 5 && exrcomp::draw::font::lit(c, column, gy))
}

#[test]
fn the_slate_is_black_with_the_jobs_metadata_in_the_font() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    inputs(d);
    let out = d.join("out.####.exr");
    let input = d.join("in.####.exr");
    // The inputs' own `comments` gives way to the user's.
    let args = [
        "--slate",
        "--attrib",
        "shot=SH010",
        "--attrib",
        "comments=take 2",
        "-q",
    ];
    ok(&[&["transcode", s(&input), "-o", s(&out)][..], &args].concat());
    let slate = d.join("out.0004.exr");
    assert_peers_read(&slate);
    let img = read_image(&slate);
    assert_eq!((img.x, img.y, img.width, img.height), (0, 0, W, H));
    assert_eq!(img.display, (W, H));
    let lines = [
        "OUTPUT: out.####.exr",
        "FRAMES: 5-7",
        "INPUT: in.####.exr",
        "SHOT: SH010",
        "COMMENTS: take 2",
    ];
    let mut lit_pixels = 0;
    for y in 0..H {
        for x in 0..W {
            let i = y * W + x;
            let expected = if lit(&lines, H, x, y) { 1.0 } else { 0.0 };
            lit_pixels += expected as usize;
            for c in ["R", "G", "B"] {
                assert_eq!(img.channels[c].get_f32(i), expected, "{c} at ({x}, {y})");
            }
            assert_eq!(img.channels["A"].get_f32(i), 1.0, "A at ({x}, {y})");
        }
    }
    assert!(lit_pixels > 100, "{lit_pixels} lit pixels");
    // The run's own frames are there as ever.
    assert!((5..=7).all(|f| d.join(format!("out.{f:04}.exr")).exists()));
}

#[test]
fn a_png_slate_is_the_output_size_and_the_same_bytes_each_run() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    inputs(d);
    let input = d.join("in.####.exr");
    for name in ["a", "b"] {
        let out = d.join(format!("{name}/out.####.png"));
        let args = ["--slate", "--erase-attrib", "comments", "-q"];
        ok(&[&["transcode", s(&input), "-o", s(&out)][..], &args].concat());
    }
    let read = |p: &str| std::fs::read(d.join(p)).unwrap();
    assert_eq!(read("a/out.0004.png"), read("b/out.0004.png"));
    // Decoded by OpenImageIO: the output's size, black but for the text.
    let exr = d.join("slate.exr");
    if let Some(oiiotool) = crate::common::peer("oiiotool") {
        let png = d.join("a/out.0004.png");
        let out = std::process::Command::new(oiiotool)
            .arg(&png)
            .args(["-d", "float", "-o"])
            .arg(&exr)
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        let img = read_image(&exr);
        assert_eq!((img.width, img.height), (W, H));
        let lines = ["OUTPUT: out.####.png", "FRAMES: 5-7", "INPUT: in.####.exr"];
        for y in 0..H {
            for x in 0..W {
                let expected = if lit(&lines, H, x, y) { 1.0 } else { 0.0 };
                let v = img.channels["R"].get_f32(y * W + x);
                assert_eq!(v, expected, "({x}, {y})");
            }
        }
    }
}

#[test]
fn a_chunked_run_writes_the_slate_once_and_resume_keeps_it() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    inputs(d);
    let input = d.join("in.####.exr");
    let out = d.join("out.####.exr");
    let chunk = |frames: &str| {
        let args = ["--frames", frames, "--resume", "--slate", "-q"];
        ok(&[&["transcode", s(&input), "-o", s(&out)][..], &args].concat());
    };
    let slate = d.join("out.0004.exr");
    // --dry-run lists it, for the chunk that starts the shot only.
    let dry = |frames: &str| {
        let args = ["--frames", frames, "--slate", "--dry-run"];
        let listing = run(&[&["transcode", s(&input), "-o", s(&out)][..], &args].concat());
        String::from_utf8_lossy(&listing.stdout).contains("out.0004.exr")
    };
    assert!(dry("5-6"));
    assert!(!dry("7"));
    assert!(!slate.exists());
    chunk("5-6");
    let first = std::fs::read(&slate).unwrap();
    std::fs::remove_file(&slate).unwrap();
    chunk("7");
    assert!(
        !slate.exists(),
        "a chunk after the shot's first wrote the slate"
    );
    // --resume keeps the slate it made, and redoes another job's file at
    // its name (here frame 5's, complete) and a cut one.
    chunk("5-6");
    let modified = |p: &Path| std::fs::metadata(p).unwrap().modified().unwrap();
    let made = modified(&slate);
    chunk("5-6");
    assert_eq!(modified(&slate), made, "a complete slate was written again");
    std::fs::copy(d.join("out.0005.exr"), &slate).unwrap();
    chunk("5-6");
    assert_eq!(std::fs::read(&slate).unwrap(), first);
    std::fs::write(&slate, &first[..first.len() / 2]).unwrap();
    chunk("5-6");
    assert_eq!(std::fs::read(&slate).unwrap(), first);
    // The job file's write node takes `slate = true`: the same bytes.
    let job = d.join("job.toml");
    std::fs::write(
        &job,
        "[[node]]\nname = \"in\"\nread = \"in.####.exr\"\n\n\
         [[node]]\nname = \"out\"\nwrite = \"job/out.####.exr\"\ninputs = [\"in\"]\nslate = true\n",
    )
    .unwrap();
    ok(&["run", s(&job), "-q"]);
    assert_eq!(std::fs::read(d.join("job/out.0004.exr")).unwrap(), first);
}

#[test]
fn a_slate_over_an_input_or_a_frame_of_the_run_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    inputs(d);
    let input = d.join("in.####.exr");
    let out = d.join("out.####.exr");
    // A file read by every frame, where the slate would go.
    std::fs::copy(d.join("in.0005.exr"), d.join("out.0004.exr")).unwrap();
    let bg = d.join("out.0004.exr");
    let refused = run(&["over", s(&input), s(&bg), "-o", s(&out), "--slate"]);
    assert_eq!(refused.status.code(), Some(2), "{}", stderr(&refused));
    assert!(stderr(&refused).contains("refusing to overwrite an input"));
    // Nothing was written.
    assert!(!d.join("out.0005.exr").exists());
    let one_file = d.join("one.exr");
    let refused = run(&[
        "transcode",
        s(&input),
        "-o",
        s(&one_file),
        "--frames",
        "5",
        "--slate",
    ]);
    assert_eq!(refused.status.code(), Some(2), "{}", stderr(&refused));
    assert!(stderr(&refused).contains("--slate"), "{}", stderr(&refused));
}
