//! `transform` where the map puts every pixel centre on a pixel centre
//! (whole-pixel moves, flips, flops, quarter and half turns, and their
//! combinations): the input's samples moved, bit for bit, whatever the
//! filter, for half, float and u32 channels holding NaN payloads,
//! infinities, -0.0, denormals and ids past 2^24, against the samples moved
//! by index here and oiiotool's `--flip`, `--flop` and `--rotateN`; a
//! translation's chunks are the input's. Under a real turn or scale, u32
//! ids are the nearest input sample.

use crate::common::*;
use crate::passthrough::chunks;
use crate::passthrough_moved::assert_placed;
use exr::math::Vec2;
use exr::prelude::{Blocks, Compression, Encoding, LineOrder};
use half::f16;
use std::path::Path;

/// The display window: both sides even, so a quarter turn about its middle
/// puts centres on centres.
const DISPLAY: (i32, i32) = (30, 20);

const FILTERS: [&str; 6] = [
    "impulse", "box", "triangle", "gaussian", "mitchell", "lanczos3",
];

/// Every few samples one of these (as bits), the rest ordinary: NaNs with
/// payloads (quiet and signalling, either sign), infinities, -0.0,
/// denormals, the largest finite value; ids past 2^24 that f32 cannot hold.
const HALF: [u16; 9] = [
    0x7e01, 0x7d55, 0xfe33, 0x7c00, 0xfc00, 0x8000, 0x0001, 0x83ff, 0x7bff,
];
const FLOAT: [u32; 9] = [
    0x7fc0_1234,
    0x7f80_0001,
    0xffa0_0001,
    0x7f80_0000,
    0xff80_0000,
    0x8000_0000,
    0x0000_0001,
    0x807f_ffff,
    0x7f7f_ffff,
];
const IDS: [u32; 7] = [
    0,
    (1 << 24) + 1,
    (1 << 24) + 3,
    0xffff_fffe,
    0xffff_ffff,
    0x8000_0001,
    123_456_789,
];

/// A plate of `w` x `h` at (x, y) in `DISPLAY`: half RGBA and `diffuse.R`,
/// float Z and vectors `forward.u`, `forward.v`, u32 `id`, each channel's
/// special values placed at its own pixels, beside ordinary ones.
fn special_plate(seed: u64, (x, y): (i32, i32), (w, h): (usize, usize)) -> Img {
    let mut rng = Lcg(seed);
    let n = w * h;
    let mut channels = std::collections::BTreeMap::new();
    let special = |k: usize| (k * 7 + seed as usize).is_multiple_of(5);
    for (c, name) in ["A", "B", "G", "R", "diffuse.R"].iter().enumerate() {
        let values = (0..n)
            .map(|k| match special(k + c) {
                true => f16::from_bits(HALF[(k + c) % HALF.len()]),
                false => f16::from_f32(rng.next() * 4.0 - 1.0),
            })
            .collect();
        channels.insert(name.to_string(), Samples::F16(values));
    }
    for (c, name) in ["Z", "forward.u", "forward.v"].iter().enumerate() {
        let values = (0..n)
            .map(|k| match special(k + c) {
                true => f32::from_bits(FLOAT[(k + c) % FLOAT.len()]),
                false => rng.next() * 100.0 - 50.0,
            })
            .collect();
        channels.insert(name.to_string(), Samples::F32(values));
    }
    let ids = (0..n)
        .map(|k| match special(k) {
            true => IDS[k % IDS.len()],
            false => (1 << 24) + (rng.next() * 1e6) as u32 * 2 + 1,
        })
        .collect();
    channels.insert("id".into(), Samples::U32(ids));
    Img {
        x,
        y,
        width: w,
        height: h,
        display: (DISPLAY.0 as usize, DISPLAY.1 as usize),
        channels,
    }
}

/// `special_plate` written as ZIP scanlines to `in.exr` in `dir`.
fn special_file(dir: &Path, seed: u64) -> (std::path::PathBuf, Img) {
    let input = dir.join("in.exr");
    // Overscan on the left and below the display window.
    let img = special_plate(seed, (-2, 3), (27, 19));
    write_image(&input, &img, Compression::ZIP16, LineOrder::Increasing);
    (input, img)
}

/// Where an input pixel goes.
type Map = Box<dyn Fn((i32, i32)) -> (i32, i32)>;

fn flip() -> Map {
    Box::new(|(i, j)| (i, DISPLAY.1 - 1 - j))
}

fn flop() -> Map {
    Box::new(|(i, j)| (DISPLAY.0 - 1 - i, j))
}

/// A quarter turn counter-clockwise (y up) about the display's middle.
fn turn() -> Map {
    let (cx, cy) = (DISPLAY.0 / 2, DISPLAY.1 / 2);
    Box::new(move |(i, j)| (j + cx - cy, cx + cy - 1 - i))
}

/// Nuke's translate: y up.
fn translate(tx: i32, ty: i32) -> Map {
    Box::new(move |(i, j)| (i + tx, j - ty))
}

/// `first`, then each of `then`.
fn then(first: Map, then: Vec<Map>) -> Map {
    Box::new(move |p| then.iter().fold(first(p), |p, m| m(p)))
}

/// `img` with each pixel's samples moved where `to` says, by index: its
/// data window the moved one's bounding box (every pixel of it hit once).
fn moved(img: &Img, to: &Map) -> Img {
    let (x1, y1) = (img.x + img.width as i32 - 1, img.y + img.height as i32 - 1);
    let corners = [(img.x, img.y), (x1, img.y), (img.x, y1), (x1, y1)].map(to);
    let (x, y) = (
        corners.iter().map(|c| c.0).min().unwrap(),
        corners.iter().map(|c| c.1).min().unwrap(),
    );
    let width = (corners.iter().map(|c| c.0).max().unwrap() - x + 1) as usize;
    let height = (corners.iter().map(|c| c.1).max().unwrap() - y + 1) as usize;
    let mut out = Img {
        x,
        y,
        width,
        height,
        channels: Default::default(),
        ..img.clone()
    };
    for (name, plane) in &img.channels {
        let mut samples = plane.zeros_like(width * height);
        for j in 0..img.height as i32 {
            for i in 0..img.width as i32 {
                let (from, (tx, ty)) = (
                    img.index(img.x + i, img.y + j).unwrap(),
                    to((img.x + i, img.y + j)),
                );
                samples.copy_from(out.index(tx, ty).unwrap(), plane, from);
            }
        }
        out.channels.insert(name.clone(), samples);
    }
    out
}

fn transform(input: &Path, output: &Path, args: &[&str]) {
    let mut all = vec!["transform", s(input), "-o", s(output), "--quiet"];
    all.extend(args);
    let out = run(&all);
    assert!(out.status.success(), "{args:?}: {}", stderr(&out));
}

/// The exact transforms: knobs, and where they move a pixel.
fn exact_cases() -> Vec<(Vec<&'static str>, Map)> {
    vec![
        (vec!["--translate", "7,3"], translate(7, 3)),
        (vec!["--translate", "-12,-5"], translate(-12, -5)),
        (vec!["--flip"], flip()),
        (vec!["--flop"], flop()),
        (vec!["--rotate", "180"], then(flip(), vec![flop()])),
        (vec!["--scale", "-1"], then(flip(), vec![flop()])),
        (vec!["--rotate", "90"], turn()),
        (vec!["--rotate", "270"], then(turn(), vec![turn(), turn()])),
        (vec!["--rotate", "-90"], then(turn(), vec![turn(), turn()])),
        (vec!["--flip", "--flop"], then(flip(), vec![flop()])),
        // Mirror, then turn, then move (Nuke's order).
        (
            vec!["--rotate", "90", "--flip", "--translate", "-3,4"],
            then(flip(), vec![turn(), translate(-3, 4)]),
        ),
        (
            vec!["--rotate", "450", "--flop", "--translate", "2,-1"],
            then(flop(), vec![turn(), translate(2, -1)]),
        ),
    ]
}

#[test]
fn exact_transforms_move_every_sample_bit_for_bit_whatever_the_filter() {
    let dir = tempfile::tempdir().unwrap();
    let ((input, img), out) = (special_file(dir.path(), 3), dir.path().join("out.exr"));
    for (args, to) in exact_cases() {
        let expected = moved(&img, &to);
        for filter in FILTERS {
            let strips: &[&str] = match filter {
                "lanczos3" => &["1", "7", "64"],
                _ => &["64"],
            };
            for strip in strips {
                let all = [&args[..], &["--filter", filter, "--strip-rows", strip]].concat();
                transform(&input, &out, &all);
                let got = read_image(&out);
                assert_eq!(
                    (got.x, got.y, got.width, got.height),
                    (expected.x, expected.y, expected.width, expected.height),
                    "{all:?}: the data window"
                );
                assert_identical(&got, &expected);
            }
        }
        assert_peers_read(&out);
    }
}

/// oiiotool 2.4 flips, flops and turns by copying; it reads u32 channels as
/// normalised float (measured: an id of 2^24 + 1 comes out 0.0039), so
/// they are left out, and it writes half channels beside float ones as
/// float: each sample is compared widened to f32, NaN against NaN (the
/// payloads are checked against the moved samples above). Its quarter
/// turns turn the display window too (to H x W at the origin; Nuke's, and
/// ours, is kept), which moves its image by `((W - H) / 2, (H - W) / 2)`
/// from ours.
#[test]
fn flips_flops_and_quarter_turns_equal_oiiotools() {
    let Some(oiiotool) = peer("oiiotool") else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let ((input, _), ours) = (special_file(dir.path(), 4), dir.path().join("ours.exr"));
    let quarter = ((DISPLAY.0 - DISPLAY.1) / 2, (DISPLAY.1 - DISPLAY.0) / 2);
    for (args, flag, offset) in [
        (&["--flip"][..], "--flip", (0, 0)),
        (&["--flop"], "--flop", (0, 0)),
        (&["--rotate", "-90"], "--rotate90", quarter),
        (&["--rotate", "180"], "--rotate180", (0, 0)),
        (&["--rotate", "90"], "--rotate270", quarter),
    ] {
        transform(&input, &ours, &[args, &["--filter", "lanczos3"]].concat());
        assert_same_as_oiiotool(&oiiotool, &input, &[flag], &ours, offset);
    }
}

/// oiiotool's `IN --ch (all but id) ARGS` has `ours`'s data window moved by
/// `(dx, dy)` and its samples, each widened to f32, NaN against NaN.
fn assert_same_as_oiiotool(
    oiiotool: &Path,
    input: &Path,
    args: &[&str],
    ours: &Path,
    (dx, dy): (i32, i32),
) {
    let theirs = ours.with_extension("oiio.exr");
    succeed(
        std::process::Command::new(oiiotool)
            .arg(input)
            .args(["--ch", "A,B,G,R,Z,diffuse.R,forward.u,forward.v"])
            .args(args)
            .arg("-o")
            .arg(&theirs),
    );
    let (got, expected) = (read_image(ours), read_image(&theirs));
    assert_eq!(
        (got.x, got.y, got.width, got.height),
        (
            expected.x + dx,
            expected.y + dy,
            expected.width,
            expected.height
        ),
        "{args:?}: the data window"
    );
    assert_eq!(expected.channels.len(), 8, "{args:?}");
    for (name, e) in &expected.channels {
        let g = &got.channels[name];
        for i in 0..e.len() {
            let (a, b) = (g.get_f32(i), e.get_f32(i));
            assert!(
                a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan()),
                "{args:?}: {name} sample {i}: {a:e} ({:#x}) against {b:e} ({:#x})",
                a.to_bits(),
                b.to_bits()
            );
        }
    }
}

/// A whole-pixel move alone is a data window move: every output chunk is
/// the input's, stored at the output's coordinates, scanline and tiled; the
/// pixels those of the same move encoded (PIZ), and of oiiotool's
/// `--origin`.
#[test]
fn a_whole_pixel_translation_copies_every_chunk() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let img = special_plate(5, (3, -4), (40, 70));
    let input = d.join("in.exr");
    let (out, encoded) = (d.join("out.exr"), d.join("piz.exr"));
    let tiles = Encoding {
        compression: Compression::ZIP1,
        blocks: Blocks::Tiles(Vec2(16, 16)),
        line_order: LineOrder::Increasing,
    };
    for encoding in [zip_scanlines(), tiles] {
        write_encoded(&input, &img, encoding);
        for (tx, ty) in [(7, 3), (-12, -5), (0, 33)] {
            let by = format!("{tx},{ty}");
            transform(&input, &out, &["--translate", &by]);
            let expected = moved(&img, &translate(tx, ty));
            assert_identical(&read_image(&out), &expected);
            let (ours, theirs) = (chunks(&out), chunks(&input));
            assert!(
                ours.len() == theirs.len() && ours.iter().zip(&theirs).all(|(o, t)| o == t),
                "--translate {by}: which chunks are the input's, in order: {:?}",
                ours.iter()
                    .zip(&theirs)
                    .map(|(o, t)| o == t)
                    .collect::<Vec<_>>()
            );
            assert_placed(&out);
            assert_peers_read(&out);
            transform(
                &input,
                &encoded,
                &["--translate", &by, "--compression", "piz"],
            );
            assert_identical(&read_image(&encoded), &expected);
        }
    }
    // Half a pixel is filtered: nothing is the input's.
    transform(&input, &out, &["--translate", "7.5,3"]);
    let theirs = chunks(&input);
    assert!(chunks(&out).iter().all(|c| !theirs.contains(c)));
    // oiiotool's --origin moves the data window: the same pixels.
    let Some(oiiotool) = peer("oiiotool") else {
        return;
    };
    transform(&input, &out, &["--translate", "-12,-5"]);
    assert_same_as_oiiotool(&oiiotool, &input, &["--origin", "-9+1"], &out, (0, 0));
}

/// Under a 2 degree turn and a scale (lanczos3), each u32 sample is the
/// input's at the pixel holding the inverse-mapped centre, or 0 outside the
/// data window: never a weighted sum of ids.
#[test]
fn ids_take_the_nearest_sample_under_a_real_turn_or_scale() {
    let dir = tempfile::tempdir().unwrap();
    let ((input, img), out) = (special_file(dir.path(), 6), dir.path().join("out.exr"));
    let Samples::U32(ids) = &img.channels["id"] else {
        unreachable!()
    };
    let (w, h) = (DISPLAY.0 as f64, DISPLAY.1 as f64);
    for (angle, scale) in [(2.0f64, 1.0f64), (0.0, 1.37), (-33.0, 0.8)] {
        let args = [
            "--rotate",
            &angle.to_string(),
            "--scale",
            &scale.to_string(),
            "--filter",
            "lanczos3",
        ]
        .map(String::from);
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        transform(&input, &out, &args);
        let got = read_image(&out);
        let Samples::U32(out_ids) = &got.channels["id"] else {
            panic!("id stays u32")
        };
        let (sin, cos) = angle.to_radians().sin_cos();
        let (mut checked, mut kept) = (0, 0);
        for (k, &id) in out_ids.iter().enumerate() {
            let (x, y) = (
                got.x + (k % got.width) as i32,
                got.y + (k / got.width) as i32,
            );
            // The inverse map, y up about the display's middle.
            let (px, py) = (x as f64 + 0.5 - w / 2.0, h - y as f64 - 0.5 - h / 2.0);
            let (ux, uy) = (
                (cos * px + sin * py) / scale,
                (-sin * px + cos * py) / scale,
            );
            let (u, v) = (ux + w / 2.0, h - (uy + h / 2.0));
            let near_edge = |t: f64| (t - t.round()).abs() < 1e-6;
            if near_edge(u) || near_edge(v) {
                continue;
            }
            let expected = img
                .index(u.floor() as i32, v.floor() as i32)
                .map_or(0, |i| ids[i]);
            assert_eq!(id, expected, "{args:?}: id at ({x}, {y})");
            checked += 1;
            kept += (id > 1 << 24) as usize;
        }
        assert!(checked > 400 && kept > 300, "{args:?}: {checked} {kept}");
        assert_peers_read(&out);
    }
}
