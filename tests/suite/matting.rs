//! Matting against ground truth the tests make: known foregrounds (soft
//! edges, partial alpha, hair-thin lines) composited over known screens and
//! backgrounds, then pulled back.

use crate::common::*;
use exr::prelude::LineOrder;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

const W: usize = 48;
const H: usize = 32;

/// A straight-colour foreground and its alpha: a soft disc, a partly
/// transparent band (motion-blur-like) and one-pixel "hairs".
fn foreground(seed: u64, colour: impl Fn(&mut Lcg) -> [f32; 3]) -> (Vec<[f32; 3]>, Vec<f32>) {
    let mut rng = Lcg(seed);
    let mut colours = Vec::with_capacity(W * H);
    let mut alphas = Vec::with_capacity(W * H);
    for y in 0..H {
        for x in 0..W {
            let d = ((x as f32 - 16.0).powi(2) + (y as f32 - 16.0).powi(2)).sqrt();
            let disc = (1.0 - (d - 9.0) / 3.0).clamp(0.0, 1.0);
            let band = if (30..40).contains(&x) {
                (x - 29) as f32 / 11.0
            } else {
                0.0
            };
            let hair = if x == 43 || y == 27 { 0.35 } else { 0.0 };
            alphas.push(disc.max(band).max(hair));
            colours.push(colour(&mut rng));
        }
    }
    (colours, alphas)
}

fn image(rgb: impl Fn(usize) -> [f32; 3], alpha: Option<&[f32]>) -> Img {
    let mut channels = BTreeMap::new();
    for (k, name) in ["R", "G", "B"].iter().enumerate() {
        channels.insert(
            name.to_string(),
            Samples::F32((0..W * H).map(|i| rgb(i)[k]).collect()),
        );
    }
    if let Some(a) = alpha {
        channels.insert("A".into(), Samples::F32(a.to_vec()));
    }
    Img {
        x: 0,
        y: 0,
        width: W,
        height: H,
        display: (W, H),
        channels,
    }
}

fn write(dir: &Path, name: &str, img: &Img) -> PathBuf {
    let path = dir.join(name);
    write_image(&path, img, compression("zip"), LineOrder::Increasing);
    path
}

fn get(img: &Img, name: &str, i: usize) -> f32 {
    img.channels[name].get_f32(i)
}

#[test]
fn triangulation_recovers_alpha_and_colour_to_float_rounding() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let (f, a) = foreground(1, |r| [r.next(), r.next(), r.next()]);
    let mut rng = Lcg(2);
    let ba: Vec<[f32; 3]> = (0..W * H)
        .map(|_| [rng.next(), rng.next(), rng.next()])
        .collect();
    // Background B: far from A, but equal to it on row 3 (no information).
    let bb: Vec<[f32; 3]> = (0..W * H)
        .map(|i| {
            if i / W == 3 {
                ba[i]
            } else {
                ba[i].map(|v| 1.0 - v)
            }
        })
        .collect();
    let over = |bg: &[[f32; 3]]| -> Img {
        image(
            |i| std::array::from_fn(|k| a[i] * f[i][k] + (1.0 - a[i]) * bg[i][k]),
            None,
        )
    };
    let paths = [
        write(d, "over_a.exr", &over(&ba)),
        write(d, "bg_a.exr", &image(|i| ba[i], None)),
        write(d, "over_b.exr", &over(&bb)),
        write(d, "bg_b.exr", &image(|i| bb[i], None)),
    ];
    let out = d.join("matte.exr");
    ok(&[
        "triangulate",
        "--over-a",
        s(&paths[0]),
        "--bg-a",
        s(&paths[1]),
        "--over-b",
        s(&paths[2]),
        "--bg-b",
        s(&paths[3]),
        "-o",
        s(&out),
        "-q",
        "--strip-rows",
        "5",
    ]);
    let ours = read_image(&out);
    for i in 0..W * H {
        if i / W == 3 {
            // Ill-conditioned: taken as opaque, colour the mean of the two.
            assert_eq!(get(&ours, "A", i), 1.0);
            continue;
        }
        assert!(
            (get(&ours, "A", i) - a[i]).abs() < 2e-6,
            "alpha at {i}: {} vs {}",
            get(&ours, "A", i),
            a[i]
        );
        for (k, name) in ["R", "G", "B"].iter().enumerate() {
            let want = a[i] * f[i][k];
            assert!((get(&ours, name, i) - want).abs() < 4e-6, "{name} at {i}");
        }
    }
}

/// The keyer's screen and a foreground whose green sits exactly at the
/// mean of red and blue (no green excess: what an ideal key assumes).
const SCREEN: [f32; 3] = [0.1, 0.8, 0.15];

fn key(d: &Path, plate: &Img, args: &[&str]) -> Img {
    let input = write(d, "plate.exr", plate);
    let out = d.join("keyed.exr");
    let mut command = vec![
        "key",
        s(&input),
        "-o",
        s(&out),
        "--screen",
        "0.1,0.8,0.15",
        "-q",
    ];
    command.extend_from_slice(args);
    ok(&command);
    read_image(&out)
}

/// Mean absolute alpha error of keying `f` (straight) with alpha `a` over
/// the screen, with noise of this amplitude added to the plate.
fn key_error(d: &Path, f: &[[f32; 3]], a: &[f32], noise: f32) -> f32 {
    let mut rng = Lcg(3);
    let plate = image(
        |i| std::array::from_fn(|k| a[i] * f[i][k] + (1.0 - a[i]) * SCREEN[k]),
        None,
    );
    let mut noisy = plate.clone();
    for name in ["R", "G", "B"] {
        if let Some(Samples::F32(v)) = noisy.channels.get_mut(name) {
            v.iter_mut()
                .for_each(|x| *x += noise * (rng.next() - 0.5) * 2.0);
        }
    }
    let ours = key(d, &noisy, &[]);
    (0..W * H)
        .map(|i| (get(&ours, "A", i) - a[i]).abs())
        .sum::<f32>()
        / (W * H) as f32
}

#[test]
fn the_keyer_recovers_alpha_on_an_ideal_screen_and_degrades_gracefully() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let neutral = |r: &mut Lcg| {
        let (red, blue) = (r.next(), r.next());
        [red, 0.5 * (red + blue), blue]
    };
    let (f, a) = foreground(4, neutral);
    let plate = image(
        |i| std::array::from_fn(|k| a[i] * f[i][k] + (1.0 - a[i]) * SCREEN[k]),
        None,
    );
    let ours = key(d, &plate, &[]);
    for i in 0..W * H {
        assert!((get(&ours, "A", i) - a[i]).abs() < 1e-5, "alpha at {i}");
        for (k, name) in ["R", "G", "B"].iter().enumerate() {
            assert!(
                (get(&ours, name, i) - a[i] * f[i][k]).abs() < 1e-5,
                "{name} at {i}"
            );
        }
    }
    // Measured (specs/ops.md): noise of ±0.01 and ±0.05 on the plate, and a
    // foreground with up to 0.1 of green excess (spill).
    let noisy = key_error(d, &f, &a, 0.01);
    let very_noisy = key_error(d, &f, &a, 0.05);
    let spilled = |r: &mut Lcg| {
        let c = neutral(r);
        [c[0], c[1] + 0.1 * r.next(), c[2]]
    };
    let (fs, a2) = foreground(4, spilled);
    let spill = key_error(d, &fs, &a2, 0.0);
    eprintln!("keyer mean alpha error: noise 0.01 {noisy:.4}, noise 0.05 {very_noisy:.4}, spill 0.1 {spill:.4}");
    assert!(
        noisy < 0.01 && very_noisy < 0.05 && spill < 0.05,
        "{noisy} {very_noisy} {spill}"
    );
}

#[test]
fn despill_limits_the_screen_channel_and_leaves_other_colours_alone() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    // Opaque colours: half with a green excess (spill), half without.
    let mut rng = Lcg(5);
    let colours: Vec<[f32; 3]> = (0..W * H)
        .map(|i| {
            let (r, b) = (0.3 + 0.5 * rng.next(), 0.3 + 0.5 * rng.next());
            let g = if i % 2 == 0 {
                0.5 * (r + b) + 0.2
            } else {
                0.5 * (r + b) - 0.1 * rng.next()
            };
            [r, g, b]
        })
        .collect();
    let plate = image(|i| colours[i], None);
    let plain = key(d, &plate, &[]);
    let despilled = key(d, &plate, &["--despill"]);
    for i in 0..W * H {
        let c: [f32; 3] = std::array::from_fn(|k| get(&plain, ["R", "G", "B"][k], i));
        let mean = 0.5 * (c[0] + c[2]);
        let g = get(&despilled, "G", i);
        if c[1] > mean {
            assert!(
                (g - mean).abs() < 1e-6,
                "spill at {i}: G {g} not limited to {mean}"
            );
        } else {
            assert_eq!(g, c[1], "pixel {i} without spill changed");
        }
        assert_eq!(get(&despilled, "R", i), c[0]);
        assert_eq!(get(&despilled, "B", i), c[2]);
    }
}

#[test]
fn a_difference_matte_separates_the_foreground_from_its_clean_plate() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let (f, a) = foreground(6, |r| [0.9 * r.next(), 0.2, 0.9]);
    let mut rng = Lcg(7);
    let plate: Vec<[f32; 3]> = (0..W * H)
        .map(|_| [0.2 + 0.1 * rng.next(), 0.6, 0.1])
        .collect();
    let shot = write(
        d,
        "shot.exr",
        &image(
            |i| std::array::from_fn(|k| a[i] * f[i][k] + (1.0 - a[i]) * plate[i][k]),
            None,
        ),
    );
    let clean = write(d, "clean.exr", &image(|i| plate[i], None));
    let out = d.join("matte.exr");
    ok(&[
        "diffmatte",
        s(&shot),
        "--clean-plate",
        s(&clean),
        "-o",
        s(&out),
        "--threshold",
        "0.02",
        "--softness",
        "0.1",
        "-q",
    ]);
    let ours = read_image(&out);
    for (i, &truth) in a.iter().enumerate() {
        let alpha = get(&ours, "A", i);
        if truth == 0.0 {
            assert_eq!(alpha, 0.0, "background at {i}");
        }
        if truth == 1.0 {
            // |F - plate| ≥ 0.3 in blue: well past threshold + softness.
            assert_eq!(alpha, 1.0, "foreground at {i}");
        }
    }
}

/// Whole-image min or max of alpha over a disc of radius r (clamped to the image).
fn reference_morphology(img: &Img, r: i64, dilate: bool) -> Vec<f32> {
    let (w, h) = (img.width as i64, img.height as i64);
    let mut out = Vec::new();
    for y in 0..h {
        for x in 0..w {
            let mut best = if dilate { f32::MIN } else { f32::MAX };
            for dy in -r..=r {
                let span = (((r * r - dy * dy) as f32).sqrt().floor()) as i64;
                for dx in -span..=span {
                    let (xx, yy) = (x + dx, y + dy);
                    if xx >= 0 && xx < w && yy >= 0 && yy < h {
                        let v = img.channels["A"].get_f32((yy * w + xx) as usize);
                        best = if dilate { best.max(v) } else { best.min(v) };
                    }
                }
            }
            out.push(best);
        }
    }
    out
}

#[test]
fn erode_and_dilate_equal_the_reference_and_undo_each_other_on_a_point() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let (_, a) = foreground(8, |_| [0.5, 0.5, 0.5]);
    let matte = image(|_| [0.5, 0.5, 0.5], Some(&a));
    let input = write(d, "matte.exr", &matte);
    for (command, dilate) in [("erode", false), ("dilate", true)] {
        let out = d.join(format!("{command}.exr"));
        ok(&[
            command,
            s(&input),
            "-o",
            s(&out),
            "--radius",
            "3",
            "-q",
            "--strip-rows",
            "2",
        ]);
        let ours = read_image(&out);
        let want = reference_morphology(&matte, 3, dilate);
        for (i, w) in want.iter().enumerate() {
            assert_eq!(get(&ours, "A", i), *w, "{command} at {i}");
            assert_eq!(get(&ours, "R", i), 0.5, "{command} changed colour");
        }
    }
    // One lit pixel: dilate by 2 makes the 13-pixel disc, erode takes it back.
    let mut point = vec![0.0f32; W * H];
    point[10 * W + 20] = 1.0;
    let p = write(d, "point.exr", &image(|_| [0.0; 3], Some(&point)));
    let (grown, back) = (d.join("grown.exr"), d.join("back.exr"));
    ok(&["dilate", s(&p), "-o", s(&grown), "--radius", "2", "-q"]);
    ok(&["erode", s(&grown), "-o", s(&back), "--radius", "2", "-q"]);
    let lit = |img: &Img| (0..W * H).filter(|&i| get(img, "A", i) > 0.0).count();
    assert_eq!(lit(&read_image(&grown)), 13);
    assert_eq!(
        (0..W * H)
            .map(|i| get(&read_image(&back), "A", i))
            .collect::<Vec<_>>(),
        point
    );
}

#[test]
fn key_then_over_a_new_background_is_one_pass_in_a_job() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let (f, a) = foreground(9, |r| {
        let (red, blue) = (r.next(), r.next());
        [red, 0.5 * (red + blue), blue]
    });
    let plate = image(
        |i| std::array::from_fn(|k| a[i] * f[i][k] + (1.0 - a[i]) * SCREEN[k]),
        None,
    );
    write(d, "plate.exr", &plate);
    write(
        d,
        "bg.exr",
        &random_rgba(10, 0, 0, W, H, Kind::Float, false),
    );
    let job = "[[node]]\nname = \"plate\"\nread = \"plate.exr\"\n\n[[node]]\nname = \"bg\"\nread = \"bg.exr\"\n\n\
        [[node]]\nname = \"keyed\"\nop = \"key\"\nscreen = \"0.1,0.8,0.15\"\ndespill = true\ninputs = [\"plate\"]\n\n\
        [[node]]\nname = \"comp\"\nop = \"over\"\ninputs = [\"keyed\", \"bg\"]\n\n\
        [[node]]\nname = \"out\"\nwrite = \"comp.exr\"\ninputs = [\"comp\"]\n";
    std::fs::write(d.join("job.toml"), job).unwrap();
    ok(&["run", s(&d.join("job.toml")), "-q"]);
    let p = |n: &str| d.join(n);
    ok(&[
        "key",
        s(&p("plate.exr")),
        "-o",
        s(&p("k.exr")),
        "--screen",
        "0.1,0.8,0.15",
        "--despill",
        "-q",
    ]);
    ok(&[
        "over",
        s(&p("k.exr")),
        s(&p("bg.exr")),
        "-o",
        s(&p("steps.exr")),
        "-q",
    ]);
    assert_identical(&read_image(&p("comp.exr")), &read_image(&p("steps.exr")));
    assert_peers_read(&p("comp.exr"));
}
