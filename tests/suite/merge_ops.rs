//! Every merge operator, premult and unpremult against the whole-image
//! reference (tests/suite/common) and against oiiotool where it has the operator.

use crate::common::*;
use exr::prelude::{Compression, LineOrder};
use half::f16;
use std::collections::BTreeMap;
use std::path::Path;
use std::process::Command;

/// `exrcomp merge --op OP A B -o OUT ARGS...`, which must succeed and be
/// readable by OpenEXR; returns the output read back.
fn merge(dir: &Path, op: &str, a: &Path, b: &Path, args: &[&str]) -> Img {
    let out_path = dir.join(format!("{op}.exr"));
    let mut command = vec!["merge", "--op", op, s(a), s(b), "-o", s(&out_path), "-q"];
    command.extend_from_slice(args);
    let out = run(&command);
    assert!(
        out.status.success(),
        "merge --op {op} failed: {}",
        stderr(&out)
    );
    read_image(&out_path)
}

fn write(dir: &Path, name: &str, img: &Img) -> std::path::PathBuf {
    let path = dir.join(name);
    write_image(&path, img, Compression::ZIP16, LineOrder::Increasing);
    path
}

#[test]
fn every_operator_equals_the_reference_premultiplied_straight_and_mixed() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    // Windows that overlap only in part, so union, intersection, A and B differ.
    for (kind, tag) in [(Kind::Float, "float"), (Kind::Half, "half")] {
        let a = random_rgba(11, 3, -2, 30, 20, kind, false);
        let b_kind = if tag == "float" {
            Kind::Float
        } else {
            Kind::Half
        };
        let b = random_rgba(12, -4, 5, 28, 22, b_kind, true);
        let (pa, pb) = (write(d, "a.exr", &a), write(d, "b.exr", &b));
        let (a, b) = (read_image(&pa), read_image(&pb));
        for op in MERGE_OPS {
            for (straight, mix) in [(false, 1.0), (true, 1.0), (false, 0.3), (true, 0.6)] {
                let mix_text = mix.to_string();
                let mut args = vec!["--mix", mix_text.as_str(), "--strip-rows", "7"];
                if straight {
                    args.push("--straight");
                }
                let ours = merge(d, op, &pa, &pb, &args);
                let reference = reference_merge(op, &a, &b, straight, mix, &[""]);
                assert_identical(&ours, &reference);
            }
        }
    }
}

#[test]
fn inputs_wider_than_the_result_are_cut_to_its_columns() {
    // Same rows, different columns: A's chunks are decoded straight into the
    // strips of the intersection, starting 5 columns into each line.
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    for compression in [Compression::ZIP16, Compression::ZIP1] {
        let a = random_rgba(31, 0, 0, 40, 37, Kind::Half, true);
        let b = random_rgba(32, 5, 0, 25, 37, Kind::Float, false);
        let (pa, pb) = (d.join("a.exr"), d.join("b.exr"));
        write_image(&pa, &a, compression, LineOrder::Increasing);
        write_image(&pb, &b, compression, LineOrder::Increasing);
        for op in ["in", "over", "copy"] {
            let ours = merge(d, op, &pa, &pb, &["--strip-rows", "16"]);
            assert_identical(&ours, &reference_merge(op, &a, &b, false, 1.0, &[""]));
        }
    }
}

#[test]
fn a_sparse_a_leaves_b_bit_for_bit_where_it_is_transparent_black() {
    // A visible only inside a disc and on one lone pixel, so rows have
    // transparent black on both sides, in the middle, and all along; B holds
    // -0, NaN and negatives, which only a bit-exact pass keeps.
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    for (kinds, tag) in [
        ((Kind::Half, Kind::Half), "half"),
        ((Kind::Float, Kind::Float), "float"),
    ] {
        let mut a = random_rgba(21, 0, 0, 70, 24, kinds.0, false);
        let mut b = random_rgba(22, 0, 0, 70, 24, kinds.1, true);
        for y in 0..24i32 {
            for x in 0..70i32 {
                let i = a.index(x, y).unwrap();
                let inside = (x - 30).pow(2) + (y - 10).pow(2) < 49 || (x, y) == (66, 20);
                for s in a.channels.values_mut().filter(|_| !inside) {
                    s.set_f32(i, 0.0);
                }
                let odd = [-0.0, f32::NAN, -2.5][(x + y) as usize % 3];
                b.channels.get_mut("G").unwrap().set_f32(i, odd);
            }
        }
        let (pa, pb) = (write(d, "a.exr", &a), write(d, "b.exr", &b));
        let (a, b) = (read_image(&pa), read_image(&pb));
        for op in ["over", "plus", "xor", "multiply"] {
            let ours = merge(d, op, &pa, &pb, &["--strip-rows", "5"]);
            let reference = reference_merge(op, &a, &b, false, 1.0, &[""]);
            assert_identical(&ours, &reference);
            if op == "over" {
                let g = &ours.channels["G"];
                let kept = (0..g.len()).filter(|&i| g.bits(i) == b.channels["G"].bits(i));
                assert!(
                    kept.count() > 70 * 24 / 2,
                    "{tag}: B passes outside the disc"
                );
            }
        }
    }
}

/// A 4x1 float RGBA image with these R values and alphas (G = B = R).
fn row(values: [f32; 4], alphas: [f32; 4]) -> Img {
    let mut channels = BTreeMap::new();
    for name in ["R", "G", "B"] {
        channels.insert(name.to_string(), Samples::F32(values.to_vec()));
    }
    channels.insert("A".to_string(), Samples::F32(alphas.to_vec()));
    Img {
        x: 0,
        y: 0,
        width: 4,
        height: 1,
        display: (4, 1),
        channels,
    }
}

fn red(img: &Img) -> Vec<f32> {
    (0..img.width)
        .map(|i| img.channels["R"].get_f32(i))
        .collect()
}

#[test]
fn the_documented_choices_divide_by_zero_screen_above_one_straight_alpha_zero() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let a = write(
        d,
        "a.exr",
        &row([2.0, 1.0, 0.5, -1.0], [1.0, 1.0, 0.0, 0.5]),
    );
    let b = write(
        d,
        "b.exr",
        &row([3.0, 0.0, 0.25, 2.0], [1.0, 0.0, 0.0, 1.0]),
    );
    // divide: 0 where B is 0, never inf or NaN.
    assert_eq!(
        red(&merge(d, "divide", &a, &b, &[])),
        [2.0 / 3.0, 0.0, 2.0, -0.5]
    );
    // screen: the larger value where both exceed 1, else A + B - AB.
    assert_eq!(
        red(&merge(d, "screen", &a, &b, &[])),
        [3.0, 1.0, 0.625, 3.0]
    );
    // straight: where the result alpha is 0, colour 0 (no NaN from 0/0).
    let ours = merge(d, "in", &a, &b, &["--straight"]);
    assert_eq!(red(&ours), [2.0, 0.0, 0.0, -1.0]);
    // mix 0 is B exactly.
    assert_eq!(
        red(&merge(d, "multiply", &a, &b, &["--mix", "0"])),
        [3.0, 0.0, 0.25, 2.0]
    );
    // Out-of-range mix is a usage error.
    let out = run(&[
        "merge",
        "--op",
        "over",
        s(&a),
        s(&b),
        "-o",
        s(&d.join("x.exr")),
        "--mix",
        "2",
    ]);
    assert_eq!(out.status.code(), Some(2), "{}", stderr(&out));
}

/// oiiotool's name for each operator it shares with us.
const OIIOTOOL: [(&str, &str); 8] = [
    ("over", "--over"),
    ("plus", "--add"),
    ("minus", "--sub"),
    ("multiply", "--mul"),
    ("divide", "--div"),
    ("max", "--max"),
    ("min", "--min"),
    ("difference", "--absdiff"),
];

/// oiiotool with `args` (paths and flags), writing `out`.
fn oiiotool(oiiotool: &Path, args: &[&Path], flag: &str, out: &Path) {
    let status = Command::new(oiiotool)
        .args(args)
        .arg(flag)
        .arg("-o")
        .arg(out)
        .status()
        .unwrap();
    assert!(status.success(), "oiiotool {flag}");
}

#[test]
fn operators_and_premult_equal_oiiotool() {
    let (Some(oiio), Some(idiff)) = (peer("oiiotool"), peer("idiff")) else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    // RGBA only and one window: oiiotool applies arithmetic to every channel.
    let a = write(
        d,
        "a.exr",
        &random_rgba(21, 2, 3, 40, 30, Kind::Float, false),
    );
    let mut b_img = random_rgba(22, 2, 3, 40, 30, Kind::Float, false);
    // Colour where alpha is 0, which unpremult must leave alone.
    let alpha: Vec<f32> = (0..b_img.width * b_img.height)
        .map(|i| b_img.channels["A"].get_f32(i))
        .collect();
    if let Some(Samples::F32(r)) = b_img.channels.get_mut("R") {
        for (r, &a) in r.iter_mut().zip(&alpha) {
            if a == 0.0 {
                *r = 0.75;
            }
        }
    }
    let b = write(d, "b.exr", &b_img);
    for (op, flag) in OIIOTOOL {
        let ours = d.join(format!("{op}.exr"));
        merge(d, op, &a, &b, &[]);
        let theirs = d.join(format!("{op}-oiio.exr"));
        oiiotool(&oiio, &[&a, &b], flag, &theirs);
        assert_peers_read(&ours);
        assert_idiff_identical(&idiff, &ours, &theirs);
    }
    for (command, flag) in [("premult", "--premult"), ("unpremult", "--unpremult")] {
        let ours = d.join(format!("{command}.exr"));
        let out = run(&[command, s(&b), "-o", s(&ours), "-q"]);
        assert!(out.status.success(), "{}", stderr(&out));
        let theirs = d.join(format!("{command}-oiio.exr"));
        oiiotool(&oiio, &[&b], flag, &theirs);
        assert_idiff_identical(&idiff, &ours, &theirs);
    }
}

#[test]
fn premult_and_unpremult_follow_the_formula_and_keep_other_channels() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let img = random_rgba(31, -3, 2, 25, 17, Kind::Half, true);
    let input = write(d, "in.exr", &img);
    let img = read_image(&input);
    for (command, inverse) in [("premult", false), ("unpremult", true)] {
        let out_path = d.join(format!("{command}.exr"));
        let out = run(&[
            command,
            s(&input),
            "-o",
            s(&out_path),
            "-q",
            "--strip-rows",
            "3",
        ]);
        assert!(out.status.success(), "{}", stderr(&out));
        let ours = read_image(&out_path);
        let mut expected = img.clone();
        let alpha = img.channels["A"].clone();
        for name in ["R", "G", "B"] {
            if let (Samples::F16(c), Samples::F16(a)) =
                (expected.channels.get_mut(name).unwrap(), &alpha)
            {
                for (c, a) in c.iter_mut().zip(a) {
                    let (cv, av) = (c.to_f32(), a.to_f32());
                    *c = f16::from_f32(match (inverse, av == 0.0) {
                        (false, _) => cv * av,
                        (true, true) => cv,
                        (true, false) => cv / av,
                    });
                }
            }
        }
        assert_identical(&ours, &expected);
    }
}

#[test]
fn output_keeps_b_header_attributes_and_names_exrcomp_as_software() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let a = write(d, "a.exr", &random_rgba(41, 0, 0, 8, 8, Kind::Half, false));
    let b = write(d, "b.exr", &random_rgba(42, 0, 0, 8, 8, Kind::Half, false));
    merge(d, "plus", &a, &b, &[]);
    let meta = exr::meta::MetaData::read_from_file(d.join("plus.exr"), false).unwrap();
    let attrs = &meta.headers[0].own_attributes;
    assert_eq!(
        attrs.comments.as_ref().map(|c| c.to_string()).as_deref(),
        Some("written by the tests")
    );
    let software = match attrs
        .other
        .get(&exr::meta::attribute::Text::from("Software"))
    {
        Some(exr::meta::attribute::AttributeValue::Text(t)) => t.to_string(),
        other => panic!("Software: {other:?}"),
    };
    assert!(software.starts_with("exrcomp "), "Software: {software}");
}

/// Samples of `got` whose bits differ from `want`'s, over every channel.
fn differing_bits(got: &Img, want: &Img) -> usize {
    assert_eq!(
        got.channels.keys().collect::<Vec<_>>(),
        want.channels.keys().collect::<Vec<_>>()
    );
    got.channels
        .iter()
        .map(|(name, samples)| {
            let theirs = &want.channels[name];
            (0..samples.len())
                .filter(|&i| samples.bits(i) != theirs.bits(i))
                .count()
        })
        .sum()
}

/// An opaque top input gives itself bit for bit whatever is under it
/// (issue 31): every half value, infinities and the 2,046 NaNs (signalling
/// ones too) included, over, atop and in with itself and under itself.
#[test]
fn an_opaque_input_passes_every_half_value_bit_for_bit() {
    let Some(path) = public_image("TestImages/AllHalfValues.exr") else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let input = read_image(&path);
    for op in ["over", "under", "atop", "in"] {
        let out = merge(dir.path(), op, &path, &path, &[]);
        assert_eq!(
            differing_bits(&out, &input),
            0,
            "{op} of AllHalfValues with itself"
        );
    }
}
