//! Differential rendering step by step against whole-image references and
//! oiiotool; zmerge against its reference and oiiotool's --zover.

use crate::common::*;
use exr::prelude::LineOrder;
use std::path::{Path, PathBuf};
use std::process::Command;

fn write(dir: &Path, name: &str, img: &Img) -> PathBuf {
    let path = dir.join(name);
    write_image(&path, img, compression("zip"), LineOrder::Increasing);
    path
}

/// `base` with R, G, B replaced by `f(x_value, y_value)` of images x and y
/// (0 outside their windows), over the window `window_of` gives.
fn colour_step(
    base: &Img,
    x: &Img,
    y: &Img,
    window: (i32, i32, usize, usize),
    f: impl Fn(f32, f32) -> f32,
) -> Img {
    let (x0, y0, width, height) = window;
    let mut out = Img {
        x: x0,
        y: y0,
        width,
        height,
        display: base.display,
        channels: Default::default(),
    };
    let value = |img: &Img, name: &str, px: i32, py: i32| match img.index(px, py) {
        Some(i) => img.channels[name].get_f32(i),
        None => 0.0,
    };
    for (name, samples) in &base.channels {
        let mut channel = samples.zeros_like(width * height);
        for py in 0..height {
            for px in 0..width {
                let (ax, ay) = (x0 + px as i32, y0 + py as i32);
                let i = py * width + px;
                if ["R", "G", "B"].contains(&name.as_str()) {
                    channel.set_f32(i, f(value(x, name, ax, ay), value(y, name, ax, ay)));
                } else if let Some(j) = base.index(ax, ay) {
                    channel.copy_from(i, samples, j);
                }
            }
        }
        out.channels.insert(name.clone(), channel);
    }
    out
}

fn union(a: &Img, b: &Img) -> (i32, i32, usize, usize) {
    let (x0, y0) = (a.x.min(b.x), a.y.min(b.y));
    let x1 = (a.x + a.width as i32).max(b.x + b.width as i32);
    let y1 = (a.y + a.height as i32).max(b.y + b.height as i32);
    (x0, y0, (x1 - x0) as usize, (y1 - y0) as usize)
}

/// The four inputs: object, proxy, render with shadows, plate.
fn shot(d: &Path, same_window: bool) -> [(PathBuf, Img); 4] {
    // (x, y, width, height) per input; one window for all when asked.
    let windows = if same_window {
        [(0, 0, 32, 24); 4]
    } else {
        [
            (4, 2, 30, 24),
            (-2, 0, 34, 26),
            (0, -3, 33, 28),
            (-1, 1, 36, 27),
        ]
    };
    let images: Vec<Img> = windows
        .iter()
        .enumerate()
        .map(|(i, &(x, y, w, h))| random_rgba(91 + i as u64, x, y, w, h, Kind::Float, i == 3))
        .collect();
    let names = ["object.exr", "proxy.exr", "shadowed.exr", "plate.exr"];
    let paths: Vec<PathBuf> = names
        .iter()
        .zip(&images)
        .map(|(n, img)| write(d, n, img))
        .collect();
    let read: Vec<Img> = paths.iter().map(|p| read_image(p)).collect();
    std::array::from_fn(|i| (paths[i].clone(), read[i].clone()))
}

fn diffrender(shot: &[(PathBuf, Img); 4], out: &Path, args: &[&str]) -> Img {
    let mut command = vec![
        "diffrender",
        "--object",
        s(&shot[0].0),
        "--proxy",
        s(&shot[1].0),
        "--with-shadows",
        s(&shot[2].0),
        "--plate",
        s(&shot[3].0),
        "-o",
        s(out),
        "-q",
    ];
    command.extend_from_slice(args);
    let result = run(&command);
    assert!(result.status.success(), "{}", stderr(&result));
    read_image(out)
}

#[test]
fn diffrender_equals_its_four_steps_done_on_whole_images() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let shot = shot(d, false);
    let [(_, i1), (_, i2), (_, i3), (_, plate)] = &shot;
    let i4 = reference_over(i1, i2, false);
    let i5 = colour_step(&i4, &i4, i3, union(&i4, i3), |a, b| a - b);
    for gain in [1.0f32, 0.4] {
        let g = gain.to_string();
        let ours = diffrender(
            &shot,
            &d.join("out.exr"),
            &["--shadow-gain", &g, "--strip-rows", "5"],
        );
        let window = (plate.x, plate.y, plate.width, plate.height);
        let i6 = colour_step(plate, &i5, plate, window, |light, p| p - gain * light);
        assert_identical(&ours, &reference_over(i1, &i6, false));
    }
    let ours = diffrender(&shot, &d.join("i5.exr"), &["--shadow-only"]);
    assert_identical(
        &ours,
        &Img {
            display: plate.display,
            ..i5
        },
    );
}

/// oiiotool with these arguments; panics if it fails.
fn oiiotool(oiio: &Path, args: &[&str]) {
    let out = Command::new(oiio).args(args).output().unwrap();
    assert!(
        out.status.success(),
        "oiiotool {args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
}

#[test]
fn diffrender_equals_the_same_steps_in_oiiotool() {
    let (Some(oiio), Some(idiff)) = (peer("oiiotool"), peer("idiff")) else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    // One window for all: oiiotool's --sub works on every channel of the union.
    let shot = shot(d, true);
    let [o, p, w, plate] = [0, 1, 2, 3].map(|i| s(&shot[i].0).to_string());
    let t = |n: &str| s(&d.join(n)).to_string();
    // I5 = (I1 over I2) - I3 in R, G, B.
    oiiotool(
        &oiio,
        &[
            &o,
            &p,
            "--over",
            &w,
            "--sub",
            "--ch",
            "R,G,B",
            "-o",
            &t("i5.exr"),
        ],
    );
    // I6 = P - I5 in R, G, B, with P's alpha; then I1 over I6.
    oiiotool(
        &oiio,
        &[
            &plate,
            "--ch",
            "R,G,B",
            &t("i5.exr"),
            "--sub",
            &plate,
            "--ch",
            "A",
            "--chappend",
            "-o",
            &t("i6.exr"),
        ],
    );
    oiiotool(&oiio, &[&o, &t("i6.exr"), "--over", "-o", &t("theirs.exr")]);
    diffrender(&shot, &d.join("ours.exr"), &[]);
    oiiotool(
        &oiio,
        &[&t("ours.exr"), "--ch", "R,G,B,A", "-o", &t("ours_rgba.exr")],
    );
    assert_idiff_identical(&idiff, &d.join("ours_rgba.exr"), &d.join("theirs.exr"));
    diffrender(&shot, &d.join("ours_i5.exr"), &["--shadow-only"]);
    oiiotool(
        &oiio,
        &[
            &t("ours_i5.exr"),
            "--ch",
            "R,G,B",
            "-o",
            &t("ours_i5_rgb.exr"),
        ],
    );
    assert_idiff_identical(&idiff, &d.join("ours_i5_rgb.exr"), &d.join("i5.exr"));
}

// ---- zmerge --------------------------------------------------------------

/// Premultiplied RGBA with depth; alpha 0 where `hole(i)`.
fn layer(seed: u64, window: (i32, i32, usize, usize), depth: impl Fn(usize) -> f32) -> Img {
    let (x, y, w, h) = window;
    let mut img = random_rgba(seed, x, y, w, h, Kind::Float, false);
    img.channels
        .insert("Z".into(), Samples::F32((0..w * h).map(depth).collect()));
    img
}

/// specs/ops.md's zmerge over the whole image.
fn reference_zmerge(inputs: &[Img]) -> Img {
    let x0 = inputs.iter().map(|i| i.x).min().unwrap();
    let y0 = inputs.iter().map(|i| i.y).min().unwrap();
    let x1 = inputs.iter().map(|i| i.x + i.width as i32).max().unwrap();
    let y1 = inputs.iter().map(|i| i.y + i.height as i32).max().unwrap();
    let (width, height) = ((x1 - x0) as usize, (y1 - y0) as usize);
    let last = inputs.last().unwrap();
    let mut out = Img {
        x: x0,
        y: y0,
        width,
        height,
        display: last.display,
        channels: Default::default(),
    };
    for (name, samples) in &last.channels {
        out.channels
            .insert(name.clone(), samples.zeros_like(width * height));
    }
    for py in 0..height {
        for px in 0..width {
            let (ax, ay) = (x0 + px as i32, y0 + py as i32);
            let at = |img: &Img, name: &str| {
                img.index(ax, ay)
                    .map_or(0.0, |i| img.channels[name].get_f32(i))
            };
            let depth = |img: &Img| {
                img.index(ax, ay)
                    .map_or(f32::INFINITY, |i| img.channels["Z"].get_f32(i))
            };
            let mut order: Vec<usize> = (0..inputs.len()).collect();
            order.sort_by(|&i, &j| {
                let key = |k: usize| (at(&inputs[k], "A") == 0.0, depth(&inputs[k]));
                let (a, b) = (key(i), key(j));
                a.0.cmp(&b.0).then(a.1.total_cmp(&b.1))
            });
            let (mut c, mut coverage) = ([0.0f32; 3], 0.0f32);
            for &i in &order {
                for (k, name) in ["R", "G", "B"].iter().enumerate() {
                    c[k] += (1.0 - coverage) * at(&inputs[i], name);
                }
                coverage += (1.0 - coverage) * at(&inputs[i], "A");
            }
            let i = py * width + px;
            for (k, name) in ["R", "G", "B"].iter().enumerate() {
                out.channels.get_mut(*name).unwrap().set_f32(i, c[k]);
            }
            out.channels.get_mut("A").unwrap().set_f32(i, coverage);
            let front = order[0];
            let z = if at(&inputs[front], "A") != 0.0 {
                depth(&inputs[front])
            } else {
                depth(last)
            };
            out.channels.get_mut("Z").unwrap().set_f32(i, z);
        }
    }
    out
}

fn zmerge(paths: &[PathBuf], out: &Path) -> Img {
    let mut command = vec!["zmerge"];
    command.extend(paths.iter().map(|p| s(p)));
    command.extend(["-o", s(out), "-q", "--strip-rows", "3"]);
    let result = run(&command);
    assert!(result.status.success(), "{}", stderr(&result));
    read_image(out)
}

#[test]
fn zmerge_puts_the_nearer_sample_over_and_transparent_ones_never_win() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let mut rng = Lcg(7);
    let depths: Vec<Vec<f32>> = (0..3)
        .map(|_| (0..40 * 40).map(|_| 1.0 + 9.0 * rng.next()).collect())
        .collect();
    let inputs = [
        layer(101, (0, 0, 31, 25), |i| depths[0][i]),
        layer(102, (-3, 4, 28, 30), |i| depths[1][i]),
        layer(103, (2, -2, 33, 29), |i| depths[2][i]),
    ];
    let paths: Vec<PathBuf> = inputs
        .iter()
        .enumerate()
        .map(|(i, img)| write(d, &format!("l{i}.exr"), img))
        .collect();
    let read: Vec<Img> = paths.iter().map(|p| read_image(p)).collect();
    assert_identical(
        &zmerge(&paths[..2], &d.join("two.exr")),
        &reference_zmerge(&read[..2]),
    );
    assert_identical(
        &zmerge(&paths, &d.join("three.exr")),
        &reference_zmerge(&read),
    );
    // A transparent sample in front: what is behind shows, with its depth.
    let front = layer(104, (0, 0, 4, 4), |_| 1.0);
    let mut clear = front.clone();
    for name in ["R", "G", "B", "A"] {
        clear
            .channels
            .insert(name.into(), Samples::F32(vec![0.0; 16]));
    }
    let back = layer(105, (0, 0, 4, 4), |_| 9.0);
    let (pc, pb) = (write(d, "clear.exr", &clear), write(d, "back.exr", &back));
    let ours = zmerge(&[pc, pb.clone()], &d.join("clear_over.exr"));
    assert_identical(&ours, &read_image(&pb));
}

#[test]
fn zmerge_colours_equal_oiiotool_zover_and_its_depth_is_the_nearer() {
    let (Some(oiio), Some(idiff)) = (peer("oiiotool"), peer("idiff")) else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let mut rng = Lcg(8);
    let (za, zb): (Vec<f32>, Vec<f32>) = (0..30 * 20)
        .map(|_| (1.0 + 9.0 * rng.next(), 1.0 + 9.0 * rng.next()))
        .unzip();
    let a = write(d, "a.exr", &layer(106, (0, 0, 30, 20), |i| za[i]));
    let b = write(d, "b.exr", &layer(107, (0, 0, 30, 20), |i| zb[i]));
    let ours = zmerge(&[a.clone(), b.clone()], &d.join("ours.exr"));
    let t = |n: &str| s(&d.join(n)).to_string();
    oiiotool(&oiio, &[s(&a), s(&b), "--zover", "-o", &t("theirs.exr")]);
    oiiotool(
        &oiio,
        &[&t("ours.exr"), "--ch", "R,G,B,A", "-o", &t("ours_rgba.exr")],
    );
    oiiotool(
        &oiio,
        &[
            &t("theirs.exr"),
            "--ch",
            "R,G,B,A",
            "-o",
            &t("theirs_rgba.exr"),
        ],
    );
    assert_idiff_identical(&idiff, &d.join("ours_rgba.exr"), &d.join("theirs_rgba.exr"));
    // Where they differ (specs/ops.md): our Z is the nearer visible depth.
    let (ra, rb) = (read_image(&a), read_image(&b));
    for i in 0..30 * 20 {
        let shows = |img: &Img| img.channels["A"].get_f32(i) != 0.0;
        let expected = match (shows(&ra), shows(&rb)) {
            (true, true) => za[i].min(zb[i]),
            (true, false) => za[i],
            _ => zb[i],
        };
        assert_eq!(ours.channels["Z"].get_f32(i), expected, "pixel {i}");
    }
}
