//! defocus, vblur and stereo against whole-image references written from
//! specs/ops.md (vblur and stereo exact: same formulas, same order of sums;
//! defocus's sums are made another way, so within half precision), across block
//! sizes, strips, windows off zero and images shorter than the halo; and the
//! properties the spec promises.

use crate::common::*;
use exr::prelude::LineOrder;
use std::f32::consts::PI;
use std::path::Path;

/// A float image with R, G, B, A random, Z from `depth`, and displacement
/// channels forward.u/v from `motion`.
fn scene(
    seed: u64,
    (x, y, width, height): (i32, i32, usize, usize),
    depth: impl Fn(usize) -> f32,
    motion: impl Fn(usize) -> (f32, f32),
) -> Img {
    let mut img = random_rgba(seed, x, y, width, height, Kind::Float, false);
    let n = width * height;
    img.channels
        .insert("Z".into(), Samples::F32((0..n).map(&depth).collect()));
    img.channels.insert(
        "forward.u".into(),
        Samples::F32((0..n).map(|i| motion(i).0).collect()),
    );
    img.channels.insert(
        "forward.v".into(),
        Samples::F32((0..n).map(|i| motion(i).1).collect()),
    );
    img
}

fn exrcomp_on(dir: &Path, img: &Img, codec: &str, command: &[&str]) -> Img {
    let (input, output) = (dir.join("in.exr"), dir.join("out.exr"));
    write_image(&input, img, compression(codec), LineOrder::Increasing);
    let mut args = vec![command[0], s(&input), "-o", s(&output), "-q"];
    args.extend_from_slice(&command[1..]);
    let out = run(&args);
    assert!(out.status.success(), "{args:?}: {}", stderr(&out));
    read_image(&output)
}

const COLOURS: [&str; 4] = ["R", "G", "B", "A"];

// ---- defocus -------------------------------------------------------------

/// The smallest radius of the aperture (0: the disc) that reaches (dx, dy).
fn need(aperture: u32, dx: f32, dy: f32) -> f32 {
    if aperture == 0 {
        return (dx * dx + dy * dy).sqrt();
    }
    let apothem = (PI / aperture as f32).cos();
    (0..aperture)
        .map(|k| {
            let angle = PI / 2.0 + 2.0 * PI * k as f32 / aperture as f32;
            dx * angle.cos() + dy * angle.sin()
        })
        .fold(f32::MIN, f32::max)
        / apothem
}

fn area(aperture: u32, r: f32) -> f32 {
    let a = if aperture == 0 {
        PI * r * r
    } else {
        0.5 * aperture as f32 * r * r * (2.0 * PI / aperture as f32).sin()
    };
    a.max(1.0)
}

/// specs/ops.md's defocus over the whole image; `aperture` 0 is the disc.
fn reference_defocus(img: &Img, focus: f32, scale: f32, max: usize, aperture: u32) -> Img {
    let (w, h) = (img.width as i64, img.height as i64);
    let z = |i: usize| img.channels["Z"].get_f32(i);
    let coc = |d: f32| {
        if d.is_nan() || d <= 0.0 {
            0.0
        } else {
            (scale * (1.0 - focus / d).abs()).min(max as f32)
        }
    };
    let mut out = img.clone();
    for name in COLOURS {
        let target = out.channels.get_mut(name).unwrap();
        for y in 0..h {
            for x in 0..w {
                let p = (y * w + x) as usize;
                let (zp, rp) = (z(p), coc(z(p)));
                let (mut sum, mut total) = (0.0f32, 0.0f32);
                for yq in (y - max as i64).max(0)..(y + max as i64 + 1).min(h) {
                    for xq in (x - max as i64).max(0)..(x + max as i64 + 1).min(w) {
                        let q = (yq * w + xq) as usize;
                        let (dx, dy) = ((x - xq) as f32, (y - yq) as f32);
                        let rq = coc(z(q));
                        let d = need(aperture, dx, dy);
                        if d > rq || (z(q) > zp && d > rp) {
                            continue;
                        }
                        let weight = 1.0 / area(aperture, rq);
                        total += weight;
                        sum += weight * img.channels[name].get_f32(q);
                    }
                }
                target.set_f32(p, sum / total);
            }
        }
    }
    out
}

/// The colours within half precision (2^-11 relative) of the reference's,
/// which sums in another order; the other channels and the rest identical.
fn assert_within_half_precision(ours: &Img, reference: &Img) {
    let mut exact = reference.clone();
    for name in COLOURS {
        let (a, b) = (&ours.channels[name], &reference.channels[name]);
        for i in 0..b.len() {
            let (a, b) = (a.get_f32(i), b.get_f32(i));
            assert!(
                (a - b).abs() <= b.abs() / 2048.0,
                "{name} at sample {i}: {a} vs {b}"
            );
        }
        exact
            .channels
            .insert(name.into(), ours.channels[name].clone());
    }
    assert_identical(ours, &exact);
}

#[test]
fn defocus_equals_the_reference_for_apertures_blocks_strips_and_short_images() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    for (codec, window, aperture, name) in [
        ("zips", (-3, 4, 19, 23), 0, "disc"),
        ("zip", (5, -2, 17, 37), 6, "hexagon"),
        ("piz", (0, 0, 21, 40), 5, "5-gon"),
        ("none", (2, 3, 15, 4), 0, "disc"),
    ] {
        let mut rng = Lcg(window.2 as u64);
        let depths: Vec<f32> = (0..window.2 * window.3)
            .map(|_| 2.0 + 20.0 * rng.next())
            .collect();
        let img = scene(81, window, |i| depths[i], |_| (0.0, 0.0));
        for strip in ["1", "7", "64"] {
            let args = [
                "defocus",
                "--focus",
                "6",
                "--scale",
                "9",
                "--max-radius",
                "5",
                "--aperture",
                name,
                "--strip-rows",
                strip,
            ];
            let ours = exrcomp_on(d, &img, codec, &args);
            assert_within_half_precision(&ours, &reference_defocus(&img, 6.0, 9.0, 5, aperture));
        }
    }
}

#[test]
fn a_point_in_focus_stays_a_point_in_front_of_a_blurred_background() {
    let dir = tempfile::tempdir().unwrap();
    let (width, height, at) = (31, 29, 15 * 31 + 14);
    let mut img = scene(
        82,
        (0, 0, width, height),
        |i| if i == at { 10.0 } else { 100.0 },
        |_| (0.0, 0.0),
    );
    for name in COLOURS {
        let v: Vec<f32> = (0..width * height)
            .map(|i| if i == at { 4.0 } else { 0.25 })
            .collect();
        img.channels.insert(name.into(), Samples::F32(v));
    }
    let args = [
        "defocus",
        "--focus",
        "10",
        "--scale",
        "8",
        "--max-radius",
        "8",
    ];
    let ours = exrcomp_on(dir.path(), &img, "zip", &args);
    for i in 0..width * height {
        let v = ours.channels["R"].get_f32(i);
        if i == at {
            assert_eq!(v, 4.0, "the point keeps its value");
        } else {
            assert!((v - 0.25).abs() < 1e-6, "pixel {i}: {v}: the point spread");
        }
    }
}

// ---- vblur ---------------------------------------------------------------

/// specs/ops.md's vblur over the whole image: each pixel's value split over
/// n = max(1, round(|S d|)) samples at t = k/n, rounded to pixels.
fn reference_vblur(img: &Img, scale: f32) -> Img {
    let (w, h) = (img.width as i64, img.height as i64);
    let mut out = img.clone();
    for name in COLOURS {
        let mut sums = vec![0.0f32; (w * h) as usize];
        for y in 0..h {
            for x in 0..w {
                let i = (y * w + x) as usize;
                let (dx, dy) = (
                    scale * img.channels["forward.u"].get_f32(i),
                    scale * img.channels["forward.v"].get_f32(i),
                );
                let n = ((dx * dx + dy * dy).sqrt().round() as usize).max(1);
                for k in 0..n {
                    let t = k as f32 / n as f32;
                    let (tx, ty) = (x + (t * dx).round() as i64, y + (t * dy).round() as i64);
                    if tx >= 0 && tx < w && ty >= 0 && ty < h {
                        sums[(ty * w + tx) as usize] +=
                            (1.0 / n as f32) * img.channels[name].get_f32(i);
                    }
                }
            }
        }
        let target = out.channels.get_mut(name).unwrap();
        for (i, v) in sums.iter().enumerate() {
            target.set_f32(i, *v);
        }
    }
    out
}

#[test]
fn vblur_equals_the_reference_with_and_without_a_given_reach() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    for (codec, window) in [
        ("zips", (-4, 3, 25, 30)),
        ("zip", (0, -5, 20, 41)),
        ("piz", (3, 0, 22, 6)),
    ] {
        let mut rng = Lcg(window.3 as u64);
        let motion: Vec<(f32, f32)> = (0..window.2 * window.3)
            .map(|_| (12.0 * rng.next() - 6.0, 14.0 * rng.next() - 7.0))
            .collect();
        let img = scene(83, window, |_| 1.0, |i| motion[i]);
        for (strip, reach) in [("1", None), ("9", Some("8")), ("64", None)] {
            let mut args = vec!["vblur", "--scale", "1.5", "--strip-rows", strip];
            if let Some(r) = reach {
                args.extend(["--max-displacement", r]);
            }
            // 1.5 x 7 rows: reach 8 is not enough for every pixel; the
            // measured reach always is.
            let (input, output) = (d.join("in.exr"), d.join("out.exr"));
            write_image(&input, &img, compression(codec), LineOrder::Increasing);
            let mut command = vec![args[0], s(&input), "-o", s(&output), "-q"];
            command.extend_from_slice(&args[1..]);
            let result = run(&command);
            if reach.is_some() && result.status.code() == Some(3) {
                assert!(
                    stderr(&result).contains("beyond the 8 the blur reaches"),
                    "{}",
                    stderr(&result)
                );
                continue;
            }
            assert!(result.status.success(), "{}", stderr(&result));
            assert_identical(&read_image(&output), &reference_vblur(&img, 1.5));
        }
    }
}

#[test]
fn a_moving_pixel_becomes_a_streak_of_length_scale_times_displacement() {
    let dir = tempfile::tempdir().unwrap();
    let (width, height, at) = (40, 9, 4 * 40 + 5);
    let mut img = scene(
        84,
        (0, 0, width, height),
        |_| 1.0,
        |i| if i == at { (6.0, 0.0) } else { (0.0, 0.0) },
    );
    for name in COLOURS {
        let v: Vec<f32> = (0..width * height)
            .map(|i| if i == at { 3.0 } else { 0.0 })
            .collect();
        img.channels.insert(name.into(), Samples::F32(v));
    }
    for (scale, length) in [("1", 6), ("2.5", 15), ("0", 1)] {
        let ours = exrcomp_on(dir.path(), &img, "zip", &["vblur", "--scale", scale]);
        let lit: Vec<usize> = (0..width * height)
            .filter(|&i| ours.channels["R"].get_f32(i) != 0.0)
            .collect();
        assert_eq!(lit, (at..at + length).collect::<Vec<_>>(), "scale {scale}");
        let sum: f32 = lit.iter().map(|&i| ours.channels["R"].get_f32(i)).sum();
        assert!(
            (sum - 3.0).abs() < 1e-5,
            "scale {scale}: the streak holds {sum}"
        );
    }
}

// ---- stereo --------------------------------------------------------------

/// specs/ops.md's stereo over the whole image: per row, each pixel moves by
/// round(K / Z) (right for the left eye), the nearer (then the first) wins,
/// and holes take the farther of the nearest moved pixels on either side.
fn reference_stereo(img: &Img, disparity: f32, left: bool) -> Img {
    let (w, h) = (img.width, img.height);
    let mut out = img.clone();
    for y in 0..h {
        let z = |x: usize| img.channels["Z"].get_f32(y * w + x);
        let mut source: Vec<Option<(usize, f32)>> = vec![None; w];
        for x in 0..w {
            let shift = if z(x) > 0.0 {
                (disparity / z(x)).round() as i64
            } else {
                0
            };
            let to = x as i64 + if left { shift } else { -shift };
            if to < 0 || to >= w as i64 {
                continue;
            }
            if source[to as usize].is_none_or(|(_, d)| z(x) < d) {
                source[to as usize] = Some((x, z(x)));
            }
        }
        let moved = source.clone();
        for (x, slot) in source.iter_mut().enumerate() {
            if slot.is_none() {
                let l = moved[..x].iter().rev().flatten().next();
                let r = moved[x + 1..].iter().flatten().next();
                *slot = match (l, r) {
                    (Some(&l), Some(&r)) => Some(if r.1 > l.1 { r } else { l }),
                    (l, r) => l.or(r).copied(),
                };
            }
        }
        for (name, samples) in out.channels.iter_mut() {
            for (x, slot) in source.iter().enumerate() {
                let from = slot.map_or(y * w + x, |(sx, _)| y * w + sx);
                samples.copy_from(y * w + x, &img.channels[name], from);
            }
        }
    }
    out
}

#[test]
fn stereo_equals_the_reference_for_random_depths_and_block_sizes() {
    let dir = tempfile::tempdir().unwrap();
    for (codec, window, eye) in [
        ("zips", (-2, 3, 37, 11), "left"),
        ("zip", (4, 0, 29, 20), "right"),
        ("piz", (0, -6, 33, 40), "left"),
    ] {
        let mut rng = Lcg(window.2 as u64);
        let depths: Vec<f32> = (0..window.2 * window.3)
            .map(|_| {
                if rng.next() < 0.1 {
                    0.0
                } else {
                    1.0 + 9.0 * rng.next()
                }
            })
            .collect();
        let img = scene(88, window, |i| depths[i], |_| (0.0, 0.0));
        let ours = exrcomp_on(
            dir.path(),
            &img,
            codec,
            &[
                "stereo",
                "--eye",
                eye,
                "--disparity",
                "20",
                "--strip-rows",
                "3",
            ],
        );
        assert_identical(&ours, &reference_stereo(&img, 20.0, eye == "left"));
    }
}

#[test]
fn stereo_with_constant_depth_is_a_pure_shift_and_nearer_pixels_win() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let (width, height) = (30, 12);
    let img = scene(85, (2, -1, width, height), |_| 4.0, |_| (0.0, 0.0));
    // K / Z = 12 / 4: three columns right for the left eye.
    let ours = exrcomp_on(
        d,
        &img,
        "zips",
        &[
            "stereo",
            "--eye",
            "left",
            "--disparity",
            "12",
            "--strip-rows",
            "5",
        ],
    );
    for (name, samples) in &img.channels {
        for y in 0..height {
            for x in 0..width {
                let from = x.saturating_sub(3);
                let (got, want) = (
                    ours.channels[name].bits(y * width + x),
                    samples.bits(y * width + from),
                );
                assert_eq!(got, want, "{name} ({x}, {y})");
            }
        }
    }
    // One near pixel (Z 1: 12 columns left for the right eye) lands where a
    // far one (Z 12: one column left) does: the near one wins.
    let mut depths = vec![12.0f32; width * height];
    depths[20] = 1.0;
    let img = scene(86, (0, 0, width, height), |i| depths[i], |_| (0.0, 0.0));
    let ours = exrcomp_on(
        d,
        &img,
        "zip",
        &["stereo", "--eye", "right", "--disparity", "12"],
    );
    assert_eq!(ours.channels["R"].bits(8), img.channels["R"].bits(20));
    assert_eq!(ours.channels["Z"].get_f32(8), 1.0);
    // Where the near pixel left (column 19 after the far ones' shift), the
    // hole takes the farther neighbour.
    assert_eq!(ours.channels["Z"].get_f32(19), 12.0);
}

#[test]
fn missing_depth_or_vector_channels_name_the_channel() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let input = d.join("in.exr");
    let img = random_rgba(87, 0, 0, 8, 8, Kind::Half, false);
    write_image(&input, &img, compression("zip"), LineOrder::Increasing);
    for (args, channel) in [
        (
            vec![
                "defocus",
                "--focus",
                "1",
                "--scale",
                "1",
                "--max-radius",
                "2",
            ],
            "'Z'",
        ),
        (vec!["vblur", "--max-displacement", "3"], "'forward.u'"),
        (vec!["vblur"], "'forward.u'"),
        (
            vec![
                "stereo",
                "--eye",
                "left",
                "--disparity",
                "3",
                "--z-channel",
                "depth",
            ],
            "'depth'",
        ),
    ] {
        let out_path = d.join("out.exr");
        let mut command = vec![args[0], s(&input), "-o", s(&out_path)];
        command.extend_from_slice(&args[1..]);
        let out = run(&command);
        assert_eq!(out.status.code(), Some(3), "{args:?}: {}", stderr(&out));
        assert!(stderr(&out).contains(channel), "{args:?}: {}", stderr(&out));
        assert!(!out_path.exists());
    }
}
