//! `crop` (oiiotool's `--crop` and `--cut`) and `pad`: windows as oiiotool
//! sets them, every pixel the input's bit for bit or black (a whole-image
//! reference), and the job nodes.

use crate::common::*;
use exr::meta::attribute::LineOrder;
use std::path::Path;

fn ours(input: &Path, output: &Path, command: &str, args: &[&str]) -> Img {
    let mut all = vec![command, s(input), "-o", s(output), "--quiet"];
    all.extend(args);
    let out = run(&all);
    assert!(out.status.success(), "{}", stderr(&out));
    read_image(output)
}

/// `img`'s pixels moved by (dx, dy) into the window `(x, y, w, h)`: the
/// input's sample bits where it has data, else zero.
fn reference(
    img: &Img,
    (x, y, w, h): (i32, i32, usize, usize),
    (dx, dy): (i32, i32),
    display: (usize, usize),
) -> Img {
    let mut out = Img {
        x,
        y,
        width: w,
        height: h,
        display,
        channels: Default::default(),
    };
    for (name, samples) in &img.channels {
        let mut plane = samples.zeros_like(w * h);
        for row in 0..h {
            for column in 0..w {
                let (sx, sy) = (x + column as i32 + dx, y + row as i32 + dy);
                if let Some(i) = img.index(sx, sy) {
                    plane.copy_from(row * w + column, samples, i);
                }
            }
        }
        out.channels.insert(name.clone(), plane);
    }
    out
}

fn input(dir: &Path) -> (std::path::PathBuf, Img) {
    let path = dir.join("in.exr");
    let img = random_rgba(11, 3, 2, 50, 40, Kind::Half, true);
    write_image(&path, &img, compression("zip"), LineOrder::Increasing);
    let img = read_image(&path);
    (path, img)
}

#[test]
fn crop_cut_and_pad_keep_every_pixel_bit_for_bit() {
    let dir = tempfile::tempdir().unwrap();
    let (path, img) = input(dir.path());
    let display = img.display;
    let out = dir.path().join("out.exr");
    // Inside, across the edge (padding with black), and with --display.
    let got = ours(&path, &out, "crop", &["--region", "20x10+5+7"]);
    assert_identical(&got, &reference(&img, (5, 7, 20, 10), (0, 0), display));
    let got = ours(
        &path,
        &out,
        "crop",
        &["--region", "-4,30,59,49", "--strip-rows", "3"],
    );
    assert_identical(&got, &reference(&img, (-4, 30, 64, 20), (0, 0), display));
    let got = ours(&path, &out, "crop", &["--region", "20x10+5+7", "--display"]);
    let mut expected = reference(&img, (5, 7, 20, 10), (0, 0), (25, 17));
    expected.display = got.display;
    assert_identical(&got, &expected);
    // A cut: the region at the origin, data and display window both.
    let got = ours(
        &path,
        &out,
        "crop",
        &["--region", "30x20+40+30", "--cut", "--strip-rows", "1"],
    );
    assert_identical(&got, &reference(&img, (0, 0, 30, 20), (40, 30), (30, 20)));
    // Pad: 8 on each side; then left, top, right, bottom.
    let got = ours(&path, &out, "pad", &["--by", "8"]);
    assert_identical(&got, &reference(&img, (-5, -6, 66, 56), (0, 0), display));
    let got = ours(&path, &out, "pad", &["--by", "1,2,3,4", "--display"]);
    let mut expected = reference(&img, (2, 0, 54, 46), (0, 0), display);
    expected.display = got.display;
    assert_identical(&got, &expected);
}

#[test]
fn crop_and_cut_set_the_windows_oiiotool_sets() {
    let Some(oiiotool) = peer("oiiotool") else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let (path, _) = input(dir.path());
    for (geometry, ours_args, theirs) in [
        ("20x10+5+7", vec![], "--crop"),
        ("80x60-8-6", vec![], "--crop"),
        ("20x10+5+7", vec!["--cut"], "--cut"),
    ] {
        let (a, b) = (dir.path().join("ours.exr"), dir.path().join("theirs.exr"));
        let mut args = vec!["--region", geometry];
        args.extend(ours_args);
        ours(&path, &a, "crop", &args);
        let status = std::process::Command::new(&oiiotool)
            .args([s(&path), theirs, geometry, "-o", s(&b)])
            .status()
            .unwrap();
        assert!(status.success());
        let windows = |p: &Path| {
            let h = &exr::meta::MetaData::read_from_file(p, false)
                .unwrap()
                .headers[0];
            (h.data_window(), h.shared_attributes.display_window)
        };
        assert_eq!(windows(&a), windows(&b), "{theirs} {geometry}");
        if let Some(idiff) = peer("idiff") {
            assert_idiff_identical(&idiff, &a, &b);
        }
    }
}

#[test]
fn crop_and_pad_job_nodes_and_bad_regions() {
    let dir = tempfile::tempdir().unwrap();
    let (path, _) = input(dir.path());
    let (a, b) = (dir.path().join("a.exr"), dir.path().join("b.exr"));
    let got = ours(&path, &a, "crop", &["--region", "30x20+40+30", "--cut"]);
    let job = dir.path().join("job.toml");
    std::fs::write(
        &job,
        format!(
            "[[node]]\nname = \"in\"\nread = \"{}\"\n\n[[node]]\nname = \"cut\"\nop = \"crop\"\nregion = \"30x20+40+30\"\ncut = true\ninputs = [\"in\"]\n\n[[node]]\nname = \"out\"\nwrite = \"{}\"\ninputs = [\"cut\"]\n",
            s(&path),
            s(&b)
        ),
    )
    .unwrap();
    let ran = run(&["run", s(&job), "--quiet"]);
    assert!(ran.status.success(), "{}", stderr(&ran));
    assert_identical(&read_image(&b), &got);
    for (command, args) in [
        ("crop", ["--region", "0x5+0+0"]),
        ("crop", ["--region", "5,5,4,9"]),
        ("pad", ["--by", "-2"]),
    ] {
        let out = dir.path().join("bad.exr");
        let mut all = vec![command, s(&path), "-o", s(&out)];
        all.extend(args);
        let result = run(&all);
        assert!(!result.status.success(), "{args:?} accepted");
        assert!(stderr(&result).contains("expected"), "{}", stderr(&result));
        assert!(!out.exists());
    }
}

/// A transparent element, 60x50 at the origin, written to `a.exr`.
fn clear_element(dir: &Path) -> (std::path::PathBuf, Img) {
    let mut clear = random_rgba(12, 0, 0, 60, 50, Kind::Half, false);
    clear
        .channels
        .values_mut()
        .for_each(|s| *s = s.zeros_like(60 * 50));
    let a = dir.join("a.exr");
    write_image(&a, &clear, compression("zip"), LineOrder::Increasing);
    (a, clear)
}

#[test]
fn a_crop_under_a_merge_is_black_outside_its_window() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let (path, img) = input(d);
    // A transparent element wider and taller than the crop: the merge's
    // window is the element's, the crop's pixels only inside its region.
    let (a, clear) = clear_element(d);
    let job = d.join("job.toml");
    let text = format!(
        "[[node]]\nname = \"a\"\nread = \"{}\"\n\n[[node]]\nname = \"b\"\nread = \"{}\"\n\n\
         [[node]]\nname = \"cropped\"\nop = \"crop\"\nregion = \"20x10+5+7\"\ninputs = [\"b\"]\n\n\
         [[node]]\nname = \"comp\"\nop = \"over\"\ninputs = [\"a\", \"cropped\"]\n\n\
         [[node]]\nname = \"out\"\nwrite = \"{}\"\ninputs = [\"comp\"]\ncompression = \"piz\"\n",
        s(&a),
        s(&path),
        s(&d.join("out.exr"))
    );
    std::fs::write(&job, text).unwrap();
    let ran = run(&["run", s(&job), "--quiet"]);
    assert!(ran.status.success(), "{}", stderr(&ran));
    let cropped = reference(&img, (5, 7, 20, 10), (0, 0), img.display);
    let expected = reference_merge("over", &clear, &cropped, false, 1.0, &[""]);
    assert_identical(&read_image(&d.join("out.exr")), &expected);
}

/// A job reading `input` through `chain` (TOML nodes from "in" to one named
/// "last"), then cropped by `crop` (region, cut) if given, into `out`.
fn crop_job(job: &Path, input: &Path, chain: &str, crop: Option<(&str, bool)>, out: &Path) {
    let (crop, last) = match crop {
        Some((region, cut)) => (
            format!(
                "[[node]]\nname = \"crop\"\nop = \"crop\"\nregion = \"{region}\"\ncut = {cut}\ninputs = [\"last\"]\n\n"
            ),
            "crop",
        ),
        None => (String::new(), "last"),
    };
    let text = format!(
        "[[node]]\nname = \"in\"\nread = \"{}\"\n\n{chain}\n{crop}[[node]]\nname = \"out\"\nwrite = \"{}\"\ninputs = [\"{last}\"]\n",
        s(input),
        s(out)
    );
    std::fs::write(job, text).unwrap();
}

/// What a graph reads beyond a crop is read as the whole image has it: a
/// blur's rows and columns (the crop's edges had been the blur's), a blur's
/// behind a resize (its second pass had read the first's columns shifted by
/// the blur's reach), the pixels stereo moves in from beyond the crop (lost:
/// it had no reach). The job's result is the crop of the whole result, bit
/// for bit, cut or not, whatever the strips.
#[test]
fn a_crop_of_a_result_is_the_whole_results_crop() {
    let dir = tempfile::tempdir().unwrap();
    let (path, _) = input(dir.path());
    let (job, out) = (dir.path().join("job.toml"), dir.path().join("out.exr"));
    let blur = "[[node]]\nname = \"last\"\nop = \"blur\"\nradius = 3\ninputs = [\"in\"]\n";
    let resized = "[[node]]\nname = \"soft\"\nop = \"blur\"\nradius = 4\ninputs = [\"in\"]\n\n[[node]]\nname = \"last\"\nop = \"resize\"\nsize = \"96x72\"\ninputs = [\"soft\"]\n";
    let stereo = "[[node]]\nname = \"last\"\nop = \"stereo\"\neye = \"left\"\ndisparity = 200\ninputs = [\"in\"]\n";
    for chain in [blur, resized, stereo] {
        crop_job(&job, &path, chain, None, &out);
        let ran = run(&["run", s(&job), "--quiet"]);
        assert!(ran.status.success(), "{}", stderr(&ran));
        let whole = read_image(&out);
        for (region, cut, strip) in [
            ("20x10+5+7", false, "64"),
            ("20x10+5+7", false, "1"),
            ("9x30+40+9", true, "4"),
        ] {
            crop_job(&job, &path, chain, Some((region, cut)), &out);
            let ran = run(&["run", s(&job), "--strip-rows", strip, "--quiet"]);
            assert!(ran.status.success(), "{}", stderr(&ran));
            let numbers: Vec<i32> = region
                .split(['x', '+'])
                .map(|v| v.parse().unwrap())
                .collect();
            let (w, h, x, y) = (numbers[0], numbers[1], numbers[2], numbers[3]);
            let expected = match cut {
                false => reference(
                    &whole,
                    (x, y, w as usize, h as usize),
                    (0, 0),
                    whole.display,
                ),
                true => reference(
                    &whole,
                    (0, 0, w as usize, h as usize),
                    (x, y),
                    (w as usize, h as usize),
                ),
            };
            assert_identical(&read_image(&out), &expected);
        }
    }
}

/// A cut's pixels are its region's only: a merge computing the columns
/// right of the cut window, or a pad around it, had the source pixels
/// beyond the region (the cut copied its input wherever it had data).
#[test]
fn a_cut_is_black_outside_its_region_under_a_merge_and_a_pad() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let (path, img) = input(d);
    let (a, clear) = clear_element(d);
    let cut = reference(&img, (0, 0, 20, 10), (5, 7), (20, 10));
    let (job, out) = (d.join("job.toml"), d.join("out.exr"));
    let node = "[[node]]\nname = \"cut\"\nop = \"crop\"\nregion = \"20x10+5+7\"\ncut = true\ninputs = [\"b\"]\n\n";
    for (after, expected) in [
        (
            format!("[[node]]\nname = \"a\"\nread = \"{}\"\n\n[[node]]\nname = \"last\"\nop = \"over\"\ninputs = [\"a\", \"cut\"]\n\n", s(&a)),
            reference_merge("over", &clear, &cut, false, 1.0, &[""]),
        ),
        (
            "[[node]]\nname = \"last\"\nop = \"pad\"\nby = 3\ninputs = [\"cut\"]\n\n".into(),
            reference(&cut, (-3, -3, 26, 16), (0, 0), (20, 10)),
        ),
    ] {
        let text = format!(
            "[[node]]\nname = \"b\"\nread = \"{}\"\n\n{node}{after}\
             [[node]]\nname = \"out\"\nwrite = \"{}\"\ninputs = [\"last\"]\n",
            s(&path),
            s(&out)
        );
        std::fs::write(&job, text).unwrap();
        let ran = run(&["run", s(&job), "--quiet"]);
        assert!(ran.status.success(), "{}", stderr(&ran));
        assert_identical(&read_image(&out), &expected);
    }
}
