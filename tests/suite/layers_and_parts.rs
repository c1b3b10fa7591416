//! Layers (`--layer`, `--all-layers`), views (`--view`), parts
//! (`file.exr:PART`, `--part`) and data windows per operator, on real files
//! and on multi-part files written here.

use crate::common::*;
use std::path::{Path, PathBuf};

fn merge_ok(args: &[&str]) {
    let out = run(args);
    assert!(out.status.success(), "{args:?}: {}", stderr(&out));
}

#[test]
fn beachball_composites_by_layer_by_view_and_all_layers() {
    let Some(images) = shared_images() else {
        return;
    };
    let beachball = |frame: u32| images.join(format!("Beachball/singlepart.{frame:04}.exr"));
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let (a_path, b_path) = (beachball(2), beachball(1));
    let (a, b) = (read_image(&a_path), read_image(&b_path));
    let out = |name: &str| d.join(format!("{name}.exr"));
    let over = |name: &str, args: &[&str]| {
        let mut command = vec!["over", s(&a_path), s(&b_path), "-o"];
        let path = out(name);
        command.push(s(&path));
        command.extend_from_slice(args);
        command.push("-q");
        merge_ok(&command);
        read_image(&path)
    };
    let left = over("left", &["--layer", "left"]);
    assert_identical(
        &left,
        &reference_merge("over", &a, &b, false, 1.0, &["left."]),
    );
    let all = over("all", &["--all-layers"]);
    assert_identical(
        &all,
        &reference_merge("over", &a, &b, false, 1.0, &["", "left."]),
    );
    // The left view is the left.* channels; the right one (the file's
    // default view) the unnamed ones.
    assert_identical(&over("view-left", &["--view", "left"]), &left);
    let plain = over("plain", &[]);
    assert_identical(&over("view-right", &["--view", "right"]), &plain);
    assert_identical(&plain, &reference_merge("over", &a, &b, false, 1.0, &[""]));
    assert_peers_read(&out("all"));

    let missing = run(&[
        "over",
        s(&a_path),
        s(&b_path),
        "-o",
        s(&out("x")),
        "--layer",
        "diffuse",
    ]);
    assert_eq!(missing.status.code(), Some(3), "{}", stderr(&missing));
    let message = stderr(&missing);
    assert!(
        message.contains("layer 'diffuse' not found") && message.contains("left"),
        "{message}"
    );
}

#[test]
fn parts_are_chosen_by_name_index_view_and_option() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let fg_right = random_rgba(51, 0, 0, 24, 18, Kind::Half, false);
    let fg_left = random_rgba(52, 2, 1, 20, 18, Kind::Half, false);
    let bg_right = random_rgba(53, 0, 0, 24, 18, Kind::Half, true);
    let bg_left = random_rgba(54, -1, 0, 24, 20, Kind::Half, true);
    let (fg, bg) = (d.join("fg.exr"), d.join("bg.exr"));
    // Every part also lists both views in `multiView`: a part's own `view`
    // is the one it holds.
    let zip = zip_scanlines();
    write_parts_listing(
        &fg,
        &[
            ("right", "right", &fg_right, zip),
            ("left", "left", &fg_left, zip),
        ],
        true,
    );
    write_parts_listing(
        &bg,
        &[
            ("right", "right", &bg_right, zip),
            ("left", "left", &bg_left, zip),
        ],
        true,
    );
    // Every part of bg comes out: the chosen one composited, the other
    // exactly bg's, each in its place.
    let composite = |inputs: [String; 2], args: &[&str], name: &str, part: usize| {
        let path = d.join(format!("{name}.exr"));
        let mut command = vec![
            "over",
            inputs[0].as_str(),
            inputs[1].as_str(),
            "-o",
            s(&path),
            "-q",
        ];
        command.extend_from_slice(args);
        merge_ok(&command);
        assert_peers_read(&path);
        let mut parts = read_parts(&path);
        assert_eq!(parts.len(), 2, "{name}");
        assert_identical(&parts[1 - part], [&bg_right, &bg_left][1 - part]);
        parts.swap_remove(part)
    };
    let with = |suffix: &str| [format!("{}{suffix}", s(&fg)), format!("{}{suffix}", s(&bg))];
    let left = reference_over(&fg_left, &bg_left, false);
    assert_identical(&composite(with(":left"), &[], "by-name", 1), &left);
    assert_identical(&composite(with(":1"), &[], "by-index", 1), &left);
    assert_identical(
        &composite(with(""), &["--view", "left"], "by-view", 1),
        &left,
    );
    assert_identical(
        &composite(with(""), &["--part", "left"], "by-option", 1),
        &left,
    );
    let right = reference_over(&fg_right, &bg_right, false);
    assert_identical(&composite(with(""), &[], "first", 0), &right);

    let [f, b] = with(":nope");
    let out = run(&["over", &f, &b, "-o", s(&d.join("x.exr"))]);
    assert_eq!(out.status.code(), Some(3), "{}", stderr(&out));
    assert!(
        stderr(&out).contains("no part 'nope' (parts: 0 (right), 1 (left))"),
        "{}",
        stderr(&out)
    );
}

/// A render's AOVs as parts, scanline and tiled, differently compressed:
/// every command keeps every part, the one worked on in its place and the
/// others chunk for chunk (the same bytes as the input's chunks).
#[test]
fn every_part_is_kept_and_the_others_copied_as_they_are() {
    use exr::prelude::{Blocks, Compression, Encoding, LineOrder};
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let beauty = random_rgba(61, 0, 0, 37, 29, Kind::Half, true);
    let diffuse = random_rgba(62, 3, 2, 30, 21, Kind::Float, true);
    let specular = random_rgba(63, 0, 0, 37, 29, Kind::Half, true);
    let encoding = |compression, blocks| Encoding {
        compression,
        blocks,
        line_order: LineOrder::Increasing,
    };
    let input = d.join("render.exr");
    write_encoded_parts(
        &input,
        &[
            (
                "beauty",
                "main",
                &beauty,
                encoding(Compression::ZIP16, Blocks::ScanLines),
            ),
            (
                "diffuse",
                "main",
                &diffuse,
                encoding(Compression::PIZ, Blocks::Tiles(exr::math::Vec2(16, 8))),
            ),
            (
                "specular",
                "main",
                &specular,
                encoding(Compression::RLE, Blocks::ScanLines),
            ),
        ],
    );
    let parts_in = read_parts(&input);
    let run_ok = |args: &[&str], output: &Path| {
        let out = run(args);
        assert!(out.status.success(), "{args:?}: {}", stderr(&out));
        assert_peers_read(output);
        read_parts(output)
    };
    // transcode, blur and over, each on one part.
    let output = d.join("transcoded.exr");
    let parts = run_ok(&["transcode", s(&input), "-o", s(&output), "-q"], &output);
    assert_eq!(parts.len(), 3);
    (0..3).for_each(|p| assert_identical(&parts[p], &parts_in[p]));

    let output = d.join("over.exr");
    let specular_part = format!("{}:specular", s(&input));
    let parts = run_ok(
        &[
            "over",
            &specular_part,
            &specular_part,
            "-o",
            s(&output),
            "-q",
        ],
        &output,
    );
    assert_identical(&parts[2], &reference_over(&specular, &specular, false));
    (0..2).for_each(|p| assert_identical(&parts[p], &parts_in[p]));

    // The carried parts' chunks are the input's bytes: the tiled part's
    // offset table points at the same chunks, in the same order.
    assert_eq!(part_chunks(&output, 1), part_chunks(&input, 1));
    assert_eq!(part_chunks(&output, 0), part_chunks(&input, 0));

    // Bands of a multi-part file would lose the other parts: refused.
    let out = run(&[
        "transcode",
        s(&input),
        "-o",
        s(&d.join("band.exr")),
        "--rows",
        "0-16",
    ]);
    assert_eq!(out.status.code(), Some(3), "{}", stderr(&out));
    assert!(stderr(&out).contains("has 3 parts"), "{}", stderr(&out));
}

/// The display window (position and size) of `path`'s first part.
fn display_window(path: &Path) -> ((i32, i32), (usize, usize)) {
    let meta = exr::meta::MetaData::read_from_file(path, false).unwrap();
    let w = meta.headers[0].shared_attributes.display_window;
    (
        (w.position.x(), w.position.y()),
        (w.size.width(), w.size.height()),
    )
}

#[test]
fn data_windows_follow_each_operator_rule_on_the_display_window_files() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    // A: data window (30, 40)-(429, 339); B: (0, 0)-(399, 299), display
    // window (1, 1)-(400, 300). RGB without alpha: opaque inside the window.
    let (Some(a_path), Some(b_path)) = (
        public_image("DisplayWindow/t08.exr"),
        public_image("DisplayWindow/t02.exr"),
    ) else {
        return;
    };
    let (a, b) = (read_image(&a_path), read_image(&b_path));
    for (op, window) in [
        ("over", (0, 0, 430, 340)),
        ("in", (30, 40, 370, 260)),
        ("copy", (30, 40, 400, 300)),
        ("stencil", (0, 0, 400, 300)),
        ("plus", (0, 0, 430, 340)),
    ] {
        let path = d.join(format!("{op}.exr"));
        merge_ok(&[
            "merge",
            "--op",
            op,
            s(&a_path),
            s(&b_path),
            "-o",
            s(&path),
            "-q",
        ]);
        let ours = read_image(&path);
        assert_eq!((ours.x, ours.y, ours.width, ours.height), window, "{op}");
        assert_identical(&ours, &reference_merge(op, &a, &b, false, 1.0, &[""]));
        assert_eq!(display_window(&path), display_window(&b_path), "{op}");
    }
}

/// Runs `over` of `input` over itself with `args`; its exit code and stderr.
fn over_itself(input: &str, output: &Path, args: &[&str]) -> (Option<i32>, String) {
    let mut command = vec!["over", input, input, "-o", s(output), "-q"];
    command.extend_from_slice(args);
    let out = run(&command);
    (out.status.code(), stderr(&out))
}

#[test]
fn unknown_views_and_parts_are_input_errors_listing_those_that_exist() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let out = d.join("out.exr");
    // Single-part stereo: left (the default view) unprefixed, right as right.*.
    let mut img = random_rgba(61, 0, 0, 16, 12, Kind::Half, false);
    let right = random_rgba(62, 0, 0, 16, 12, Kind::Half, false);
    for (name, samples) in right.channels.clone() {
        img.channels.insert(format!("right.{name}"), samples);
    }
    let stereo = d.join("stereo.exr");
    write_multi_view(&stereo, &img, &["left", "right"]);
    let stereo = s(&stereo);
    for view in ["left", "right"] {
        let (code, message) = over_itself(stereo, &out, &["--view", view]);
        assert_eq!(code, Some(0), "{view}: {message}");
    }
    let (code, message) = over_itself(stereo, &out, &["--view", "centre"]);
    assert_eq!(code, Some(3), "{message}");
    assert!(
        message.contains(&format!("{stereo}: no view 'centre' (views: left, right)")),
        "{message}"
    );
    let (code, message) = over_itself(stereo, &out, &["--view", "rihgt"]);
    assert_eq!(code, Some(3), "{message}");
    assert!(message.contains("did you mean 'right'?"), "{message}");

    // Multi-part stereo: one part per view.
    let parts = d.join("parts.exr");
    let left = random_rgba(63, 0, 0, 16, 12, Kind::Half, false);
    write_parts(
        &parts,
        &[("rgba", "left", &left), ("rgba_right", "right", &right)],
    );
    let parts = s(&parts);
    let (code, message) = over_itself(parts, &out, &["--view", "centre"]);
    assert_eq!(code, Some(3), "{message}");
    assert!(
        message.contains(&format!("{parts}: no view 'centre' (views: left, right)")),
        "{message}"
    );
    // Parts by name or index, from the file name, --part or a job file.
    let (code, message) = over_itself(parts, &out, &["--part", "rgba_rihgt"]);
    assert_eq!(code, Some(3), "{message}");
    assert!(
        message.contains(
            "no part 'rgba_rihgt' (parts: 0 (rgba), 1 (rgba_right)); did you mean 'rgba_right'?"
        ),
        "{message}"
    );
    let (code, message) = over_itself(&format!("{parts}:2"), &out, &[]);
    assert_eq!(code, Some(3), "{message}");
    assert!(
        message.contains("no part '2' (parts: 0 (rgba), 1 (rgba_right))"),
        "{message}"
    );
    let job = d.join("job.toml");
    std::fs::write(
        &job,
        "[[node]]\nname = \"in\"\nread = \"parts.exr\"\npart = \"beauty\"\n\n\
         [[node]]\nname = \"out\"\nwrite = \"out.exr\"\ninputs = [\"in\"]\n",
    )
    .unwrap();
    let ran = run(&["run", s(&job), "-q"]);
    assert_eq!(ran.status.code(), Some(3), "{}", stderr(&ran));
    assert!(
        stderr(&ran).contains("no part 'beauty' (parts: 0 (rgba), 1 (rgba_right))"),
        "{}",
        stderr(&ran)
    );

    // A file without views is the same in every view.
    let mono = d.join("mono.exr");
    write_image(
        &mono,
        &left,
        exr::prelude::Compression::ZIP16,
        exr::prelude::LineOrder::Increasing,
    );
    let (code, message) = over_itself(s(&mono), &out, &["--view", "left"]);
    assert_eq!(code, Some(0), "{message}");
}

/// The part names, compressions and data windows of `path`, as OpenEXR
/// headers give them.
fn part_headers(path: &Path) -> Vec<(String, String, String)> {
    let meta = exr::meta::MetaData::read_from_file(path, false).unwrap();
    meta.headers
        .iter()
        .map(|h| {
            let name = h.own_attributes.layer_name.as_ref().map(|n| n.to_string());
            let window = h.data_window();
            (
                name.unwrap_or_default(),
                format!("{:?}", h.compression),
                format!("{:?} {:?}", window.position, window.size),
            )
        })
        .collect()
}

#[test]
fn all_parts_runs_a_one_input_operation_on_every_part() {
    use exr::prelude::{Blocks, Compression, Encoding, LineOrder};
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let encoding = |compression, blocks| Encoding {
        compression,
        blocks,
        line_order: LineOrder::Increasing,
    };
    let parts_in = [
        random_rgba(71, 0, 0, 37, 29, Kind::Half, true),
        random_rgba(72, 3, 2, 30, 21, Kind::Float, false),
        random_rgba(73, 0, 5, 37, 20, Kind::Half, true),
    ];
    let encodings = [
        encoding(Compression::ZIP16, Blocks::ScanLines),
        encoding(Compression::PIZ, Blocks::Tiles(exr::math::Vec2(16, 8))),
        encoding(Compression::RLE, Blocks::ScanLines),
    ];
    let names = ["beauty", "diffuse", "specular"];
    let input = d.join("render.exr");
    let list: Vec<_> = (0..3)
        .map(|p| (names[p], "main", &parts_in[p], encodings[p]))
        .collect();
    write_encoded_parts(&input, &list);
    let ok = |args: &[&str]| {
        let out = run(args);
        assert!(out.status.success(), "{args:?}: {}", stderr(&out));
    };

    // Per part, the reference: the operation on that part alone, a
    // single-part file of the same pixels and encoding.
    for op in [&["premult"][..], &["blur", "--radius", "2"], &["transcode"]] {
        let output = d.join(format!("{}-all.exr", op[0]));
        let mut args = op.to_vec();
        args.extend([s(&input), "-o", s(&output), "-q", "--all-parts"]);
        args.extend(["--compression", "zips"]);
        ok(&args);
        assert_peers_read(&output);
        let parts = read_parts(&output);
        assert_eq!(parts.len(), 3, "{op:?}");
        let headers = part_headers(&output);
        let headers_in = part_headers(&input);
        for p in 0..3 {
            let single = d.join(format!("part{p}.exr"));
            write_encoded_parts(&single, &[list[p]]);
            let reference = d.join(format!("{}-{p}.exr", op[0]));
            let mut args = op.to_vec();
            args.extend([s(&single), "-o", s(&reference), "-q"]);
            ok(&args);
            assert_identical(&parts[p], &read_image(&reference));
            // Its own name and window; every part written as asked.
            assert_eq!(headers[p].0, headers_in[p].0);
            assert_eq!(headers[p].2, headers_in[p].2);
            assert_eq!(headers[p].1, "ZIP1", "{op:?} part {p}");
        }
        if op[0] == "transcode" {
            (0..3).for_each(|p| {
                assert_identical(&parts[p], &read_image(&d.join(format!("part{p}.exr"))))
            });
            if let Some(idiff) = peer("idiff") {
                let out = std::process::Command::new(idiff)
                    .args(["-a", "-fail", "0"])
                    .arg(&input)
                    .arg(&output)
                    .output()
                    .unwrap();
                assert!(
                    out.status.success(),
                    "{}",
                    String::from_utf8_lossy(&out.stdout)
                );
            }
        }
    }

    // A multi-part file made by oiiotool from two of the parts; the
    // references are its parts as oiiotool extracts them.
    if let Some(oiio) = peer("oiiotool") {
        let oiiotool = |args: &[&str]| {
            let status = std::process::Command::new(&oiio)
                .args(args)
                .status()
                .unwrap();
            assert!(status.success(), "oiiotool {args:?}");
        };
        let (made, output) = (d.join("oiio.exr"), d.join("oiio-all.exr"));
        let (part0, part2) = (d.join("part0.exr"), d.join("part2.exr"));
        oiiotool(&[s(&part0), s(&part2), "--siappendall", "-o", s(&made)]);
        ok(&[
            "blur",
            s(&made),
            "-o",
            s(&output),
            "-q",
            "--all-parts",
            "--radius",
            "1",
        ]);
        let parts = read_parts(&output);
        assert_eq!(parts.len(), 2);
        for (p, part) in parts.iter().enumerate() {
            let (single, reference) = (d.join("single.exr"), d.join("reference.exr"));
            oiiotool(&[s(&made), "--subimage", &p.to_string(), "-o", s(&single)]);
            ok(&[
                "blur",
                s(&single),
                "-o",
                s(&reference),
                "-q",
                "--radius",
                "1",
            ]);
            assert_identical(part, &read_image(&reference));
        }
    }

    // The job file's write node takes `all_parts`: the same bytes.
    let job = d.join("job.toml");
    std::fs::write(
        &job,
        "[[node]]\nname = \"in\"\nread = \"render.exr\"\n\n[[node]]\nname = \"p\"\nop = \"premult\"\n\
         inputs = [\"in\"]\n\n[[node]]\nname = \"out\"\nwrite = \"job-all.exr\"\ninputs = [\"p\"]\n\
         compression = \"zips\"\nall_parts = true\n",
    )
    .unwrap();
    ok(&["run", s(&job), "-q"]);
    assert_eq!(
        std::fs::read(d.join("job-all.exr")).unwrap(),
        std::fs::read(d.join("premult-all.exr")).unwrap()
    );
}

/// In `d`: render.exr, parts "beauty" (RGBA, Z) and "depth" (Z) of random
/// pixels from `seed`, an empty folder for the output, and the output's path.
fn beauty_and_depth(d: &Path, seed: u64) -> (PathBuf, PathBuf, PathBuf) {
    let beauty = random_rgba(seed, 0, 0, 24, 16, Kind::Half, true);
    let mut depth = beauty.clone();
    depth.channels.retain(|name, _| name == "Z");
    let input = d.join("render.exr");
    write_parts(
        &input,
        &[("beauty", "main", &beauty), ("depth", "main", &depth)],
    );
    let out_dir = d.join("out");
    std::fs::create_dir(&out_dir).unwrap();
    let output = out_dir.join("o.exr");
    (input, out_dir, output)
}

#[test]
fn all_parts_names_a_part_it_cannot_process_and_refuses_two_input_operations() {
    let dir = tempfile::tempdir().unwrap();
    let (input, _, output) = beauty_and_depth(dir.path(), 81);
    // premult of a part without colour: the part is named in a warning and
    // written unchanged (it had failed the frame, issue 31).
    let out = run(&["premult", s(&input), "-o", s(&output), "--all-parts"]);
    let message = stderr(&out);
    assert_eq!(out.status.code(), Some(0), "{message}");
    assert!(
        message.contains("warning: part 1 ('depth') is written unchanged"),
        "{message}"
    );
    assert_identical(&read_parts(&output)[1], &read_parts(&input)[1]);
    std::fs::remove_file(&output).unwrap();
    // transcode takes it, every part kept.
    let out = run(&[
        "transcode",
        s(&input),
        "-o",
        s(&output),
        "--all-parts",
        "-q",
    ]);
    assert!(out.status.success(), "{}", stderr(&out));
    assert_eq!(read_parts(&output).len(), 2);
    // Operations of two inputs, a part chosen as well, a band: usage errors.
    let input_part = format!("{}:depth", s(&input));
    let refused: [&[&str]; 4] = [
        &["over", s(&input), s(&input)],
        &["deepmerge", s(&input), s(&input)],
        &["transcode", &input_part],
        &["transcode", s(&input), "--rows", "0-16"],
    ];
    for args in refused {
        let mut args = args.to_vec();
        args.extend(["-o", s(&output), "--all-parts"]);
        let out = run(&args);
        let message = stderr(&out);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {message}");
        assert!(message.contains("all-parts"), "{args:?}: {message}");
    }
    // A job file's read with its own `part` key likewise (the key was applied
    // after the job was made, so the part went unchecked: exit 0).
    let job = dir.path().join("part.toml");
    let text = format!(
        "[[node]]\nname = \"in\"\nread = \"{}\"\npart = \"depth\"\n\n\
         [[node]]\nname = \"out\"\nwrite = \"{}\"\ninputs = [\"in\"]\nall_parts = true\n",
        s(&input),
        s(&output)
    );
    std::fs::write(&job, text).unwrap();
    let out = run(&["run", s(&job)]);
    let message = stderr(&out);
    assert_eq!(out.status.code(), Some(2), "{message}");
    assert!(message.contains("all-parts"), "{message}");
}

/// A job's read takes a part by index as `--part` does (`part = 1` had been
/// refused: "expected a string"), and `--dry-run` names the part each read
/// takes, the one `--view` picks too (it had named the file only).
#[test]
fn a_jobs_part_index_and_the_dry_runs_part() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let left = random_rgba(1, 0, 0, 16, 8, Kind::Half, false);
    let right = random_rgba(2, 0, 0, 16, 8, Kind::Half, false);
    let input = d.join("stereo.exr");
    write_parts(&input, &[("l", "left", &left), ("r", "right", &right)]);
    let job = d.join("job.toml");
    let output = d.join("out.exr");
    std::fs::write(
        &job,
        format!(
            "[[node]]\nname = \"in\"\nread = \"{}\"\npart = 1\n\n[[node]]\nname = \"out\"\nwrite = \"{}\"\ninputs = [\"in\"]\n",
            s(&input),
            s(&output)
        ),
    )
    .unwrap();
    ok(&["run", s(&job), "-q"]);
    let reference = d.join("reference.exr");
    let second = format!("{}:1", s(&input));
    ok(&["transcode", &second, "-o", s(&reference), "-q"]);
    assert_identical(&read_parts(&output)[1], &read_parts(&reference)[1]);
    let first = format!("{}:l", s(&input));
    for (args, listed) in [
        (&[s(&input), "--view", "right"][..], "(part 1 'r')"),
        (&[&first], "(part 0 'l')"),
        (
            &[s(&input), "--view", "right", "--json"],
            "\"part\":\"part 1 'r'\"",
        ),
    ] {
        let mut all = vec!["premult", "-o", s(&output), "--dry-run"];
        all.extend(args);
        let out = succeed(exrcomp().args(&all));
        let listing = String::from_utf8_lossy(&out.stdout);
        assert!(listing.contains(listed), "{args:?}: {listing}");
    }
}

/// OpenEXR requires every part of a file to share its display window and
/// pixel aspect ratio: a geometry operation on one part of a multi-part file
/// is refused, naming the file and what to give, nothing written (it wrote a
/// file OpenEXR refuses, exit 0); `--all-parts` applies it to every part,
/// and what keeps the display window still carries the other parts.
#[test]
fn a_geometry_change_to_one_part_of_many_is_refused_or_made_to_every_part() {
    let dir = tempfile::tempdir().unwrap();
    let (input, out_dir, output) = beauty_and_depth(dir.path(), 82);
    let depth_part = format!("{}:depth", s(&input));
    let refused: [&[&str]; 5] = [
        &["resize", s(&input), "--scale", "0.5"],
        &["resize", &depth_part, "--scale", "0.5"],
        &["reformat", s(&input), "--format", "2K_Cinemascope"],
        &["crop", s(&input), "--region", "8x8+0+0", "--cut"],
        &["transcode", s(&input), "--proxy-scale", "0.5"],
    ];
    for args in refused {
        let out = run(&[args, &["-o", s(&output)]].concat());
        let message = stderr(&out);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {message}");
        assert!(
            message.contains("render.exr has 2 parts") && message.contains("--all-parts"),
            "{args:?}: {message}"
        );
        assert_eq!(message.lines().count(), 1, "{message}");
        assert_eq!(std::fs::read_dir(&out_dir).unwrap().count(), 0);
    }
    let windows = |path: &Path| -> Vec<_> {
        let meta = exr::meta::MetaData::read_from_file(path, false).unwrap();
        let shown = |h: &exr::meta::header::Header| {
            let a = &h.shared_attributes;
            (a.display_window, a.pixel_aspect)
        };
        meta.headers.iter().map(shown).collect()
    };
    for args in [
        &["resize", s(&input), "--scale", "0.5", "--all-parts"][..],
        &[
            "reformat",
            s(&input),
            "--format",
            "2K_Cinemascope",
            "--all-parts",
        ],
        &["grade", s(&input), "--gain", "2"],
    ] {
        ok(&[args, &["-o", s(&output), "-q"]].concat());
        let shown = windows(&output);
        assert_eq!(shown.len(), 2, "{args:?}");
        assert_eq!(shown[0], shown[1], "{args:?}");
        if let Some(oiiotool) = peer("oiiotool") {
            succeed(
                std::process::Command::new(oiiotool)
                    .arg("--stats")
                    .arg(&output),
            );
        }
    }
}
