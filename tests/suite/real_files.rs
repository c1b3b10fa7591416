//! OpenEXR's public test images: every good one is read, every damaged one
//! gives a clear error quickly, and a real multi-layer sequence composites.
//! Without the shared set, the few shipped images (tests/images) are read.

use crate::common::*;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::{Duration, Instant};

/// The files under `folder` of the shared set, or of the shipped images
/// when the shared set is absent.
fn files_under(folder: &str) -> Vec<PathBuf> {
    let root = shared_images().unwrap_or_else(shipped_images);
    let mut found = Vec::new();
    let mut stack = vec![root.join(folder)];
    while let Some(dir) = stack.pop() {
        for entry in std::fs::read_dir(&dir).unwrap_or_else(|e| panic!("{}: {e}", dir.display())) {
            let path = entry.unwrap().path();
            if path.is_dir() {
                stack.push(path);
            } else {
                found.push(path);
            }
        }
    }
    found.sort();
    found
}

/// Every good (not Damaged) image of the shipped set, the shared set and the
/// second shared set, by its path in the sets; a shared copy wins over the
/// shipped one.
fn good_images() -> Vec<(String, PathBuf)> {
    let mut roots = vec![shipped_images()];
    roots.extend(shared_images());
    roots.extend(shared_more_images());
    let mut found = std::collections::BTreeMap::new();
    for root in roots {
        let mut stack = vec![root.clone()];
        while let Some(dir) = stack.pop() {
            for entry in std::fs::read_dir(&dir).unwrap() {
                let path = entry.unwrap().path();
                let name = path
                    .strip_prefix(&root)
                    .unwrap()
                    .to_string_lossy()
                    .into_owned();
                if path.is_dir() && name != "Damaged" {
                    stack.push(path);
                } else if path.extension().is_some_and(|e| e == "exr") {
                    found.insert(name, path);
                }
            }
        }
    }
    found.into_iter().collect()
}

/// What the sweep needs to know of one part of a file, from its header.
struct PartFacts {
    name: String,
    deep: bool,
    /// Mipmap or ripmap levels.
    levels: bool,
    ripmap: bool,
    /// R, G and B, or luminance (Y: composited as RGB, specs/file-format.md).
    colour: bool,
    /// Y and no R, G, B (oiiotool reads it as Y).
    luminance: bool,
    alpha: bool,
    subsampled: bool,
    /// oiiotool's name of the colour channels' sample type.
    colour_type: &'static str,
}

fn describe(path: &Path) -> Vec<PartFacts> {
    use exr::meta::attribute::LevelMode;
    let meta = exr::meta::MetaData::read_from_file(path, false).unwrap();
    meta.headers
        .iter()
        .map(|h| {
            let has = |name: &str| h.channels.list.iter().any(|c| c.name.eq(name));
            let mode = match h.blocks {
                exr::meta::BlockDescription::Tiles(t) => t.level_mode,
                exr::meta::BlockDescription::ScanLines => LevelMode::Singular,
            };
            let rgb = ["R", "G", "B"].iter().all(|c| has(c));
            let colour_type = match h
                .channels
                .list
                .iter()
                .find(|c| c.name.eq("R") || c.name.eq("Y"))
            {
                Some(c) if c.sample_type == exr::meta::attribute::SampleType::F32 => "float",
                Some(c) if c.sample_type == exr::meta::attribute::SampleType::U32 => "uint",
                _ => "half",
            };
            PartFacts {
                name: h
                    .own_attributes
                    .layer_name
                    .as_ref()
                    .map(|n| n.to_string())
                    .unwrap_or_default(),
                deep: h.deep,
                levels: mode != LevelMode::Singular,
                ripmap: mode == LevelMode::RipMap,
                colour: rgb || has("Y"),
                luminance: !rgb && has("Y"),
                alpha: has("A"),
                subsampled: h
                    .channels
                    .list
                    .iter()
                    .any(|c| c.sampling != exr::math::Vec2(1, 1)),
                colour_type,
            }
        })
        .collect()
}

/// The peers the sweep compares with.
struct Peers {
    oiiotool: Option<PathBuf>,
    idiff: Option<PathBuf>,
    exrmultipart: Option<PathBuf>,
}

impl Peers {
    /// `oiiotool ARGS -o OUT`; false when oiiotool fails (or is missing).
    fn oiio(&self, args: &[&str], out: &Path) -> bool {
        let Some(oiiotool) = &self.oiiotool else {
            return false;
        };
        Command::new(oiiotool)
            .args(args)
            .arg("-o")
            .arg(out)
            .output()
            .unwrap()
            .status
            .success()
    }

    /// What `idiff -fail 0` (`-a`: every part and level) reports when `a`
    /// and `b` differ, or when it cannot read them.
    fn differ(&self, a: &Path, b: &Path, all: bool) -> Option<String> {
        let mut command = Command::new(self.idiff.as_ref()?);
        command.args(["-fail", "0", "-warn", "0"]);
        if all {
            command.arg("-a");
        }
        let out = command.arg(a).arg(b).output().unwrap();
        (!out.status.success()).then(|| {
            String::from_utf8_lossy(&out.stdout).into_owned()
                + &String::from_utf8_lossy(&out.stderr)
        })
    }
}

/// oiiotool arguments reading part `k` of `path` as flat R, G, B (and A,
/// when `alpha`), its first level: `deep` flattened, `luminance` (Y) as grey.
/// (Written in the type of `part`'s colour: oiiotool would write float
/// where other channels are.)
fn rgba_of(path: &Path, k: usize, part: &PartFacts, deep: bool, luminance: bool) -> Vec<String> {
    let mut args = vec![s(path).to_string(), "--subimage".into(), k.to_string()];
    if deep {
        args.push("--flatten".into());
    }
    let rgb = if luminance { "R=Y,G=Y,B=Y" } else { "R,G,B" };
    let channels = format!("{rgb}{}", if part.alpha { ",A" } else { "" });
    args.extend(["--unmip".into(), "--ch".into(), channels]);
    args.extend(["-d".into(), part.colour_type.into()]);
    args
}

/// Every chunk of every part of `input` but `except` is in `output`
/// byte for byte (carried, not decoded).
fn carried(input: &Path, output: &Path, parts: usize, except: usize) -> Result<(), String> {
    for k in (0..parts).filter(|&k| k != except) {
        if part_chunks(input, k) != part_chunks(output, k) {
            return Err(format!("part {k} is not the input's chunks"));
        }
    }
    Ok(())
}

/// What is wrong with one image through `info`, `transcode` and `over`
/// of each part with itself, checked against idiff and oiiotool (which
/// must read every part with colour but subsampled ones); the other parts
/// must come out chunk for chunk.
fn check_image(path: &Path, dir: &Path, peers: &Peers) -> Result<(), String> {
    let out = run(&["info", s(path)]);
    let text = String::from_utf8_lossy(&out.stdout);
    if !out.status.success() {
        return Err(format!("info: {}", stderr(&out).trim()));
    }
    if !(text.contains("dataWindow (type box2i): (") && text.contains("channels (type chlist):")) {
        return Err(format!("info prints no window or channels:\n{text}"));
    }
    if !text.contains("pixels: all") {
        return Err(format!("info does not check every chunk:\n{text}"));
    }
    let transcoded = dir.join("transcoded.exr");
    let out = run(&["transcode", s(path), "-o", s(&transcoded), "-q"]);
    if !out.status.success() {
        return Err(format!("transcode: {}", stderr(&out).trim()));
    }
    let parts = describe(path);
    let names = |parts: &[PartFacts]| parts.iter().map(|p| p.name.clone()).collect::<Vec<_>>();
    let names_out = names(&describe(&transcoded));
    if names(&parts) != names_out {
        return Err(format!(
            "transcode: parts {:?} came out as {names_out:?}",
            names(&parts)
        ));
    }
    carried(path, &transcoded, parts.len(), 0).map_err(|e| format!("transcode: {e}"))?;
    let first = &parts[0];
    if first.deep {
        // idiff compares no deep file with a flat one: against oiiotool's
        // flattening, on the channels both compute (Z differs on purpose).
        let (ours, theirs) = (dir.join("ours.exr"), dir.join("theirs.exr"));
        let rgba = ["--ch", "R,G,B,A"];
        if peers.oiio(&[&[s(path), "--flatten"][..], &rgba].concat(), &theirs) {
            if !peers.oiio(&[&[s(&transcoded)][..], &rgba].concat(), &ours) {
                return Err("oiiotool cannot read the transcoded file".into());
            }
            if let Some(d) = peers.differ(&ours, &theirs, false) {
                return Err(format!("transcode differs from oiiotool --flatten:\n{d}"));
            }
        }
    } else if !first.subsampled {
        // Every part and level (a mipmap's level 0 is what is read of the
        // first part, idiff's first level; oiiotool 2.4 misreads ripmaps'
        // levels, even of a file against itself, so their carried chunks
        // are compared above).
        let all = !first.levels && !parts.iter().any(|p| p.ripmap);
        if let Some(d) = peers.differ(path, &transcoded, all) {
            return Err(format!("transcode differs from the input:\n{d}"));
        }
    }
    for (k, part) in parts.iter().enumerate().filter(|(_, p)| p.colour) {
        let composited = dir.join("over.exr");
        let input = format!("{}:{k}", s(path));
        let out = run(&["over", &input, &input, "-o", s(&composited), "-q"]);
        if !out.status.success() {
            return Err(format!("over of part {k}: {}", stderr(&out).trim()));
        }
        carried(path, &composited, parts.len(), k).map_err(|e| format!("over of part {k}: {e}"))?;
        // oiiotool reads no subsampled channels (tests/suite/luminance_chroma.rs
        // checks those against OpenEXR's formulas).
        if part.subsampled || peers.oiiotool.is_none() {
            continue;
        }
        // The reference: the part alone as a file (a flattened deep part
        // rounded to its channels' type, as exrcomp reads it), over itself.
        // oiiotool 2.4 misreads a deep part of a multi-part file: OpenEXR's
        // exrmultipart takes it out first.
        let (alone, ours, theirs) = (
            dir.join("alone.exr"),
            dir.join("ours.exr"),
            dir.join("theirs.exr"),
        );
        let (source, index) = match (part.deep && parts.len() > 1, &peers.exrmultipart) {
            (true, Some(exrmultipart)) => {
                succeed(
                    Command::new(exrmultipart)
                        .args(["-separate", "-i", s(path), "-o"])
                        .arg(dir.join("separate")),
                );
                (dir.join(format!("separate.{}.exr", k + 1)), 0)
            }
            (true, None) => continue,
            (false, _) => (path.to_path_buf(), k),
        };
        let read = rgba_of(&source, index, part, part.deep, part.luminance);
        let read: Vec<&str> = read.iter().map(String::as_str).collect();
        if !peers.oiio(&read, &alone) {
            return Err(format!("oiiotool cannot read part {k}"));
        }
        // Without alpha the part is opaque (specs/ops.md, "Alpha"): over
        // itself is the part itself (oiiotool refuses `--over` without alpha).
        let reference = match part.alpha {
            true => vec![s(&alone), s(&alone), "--over", "-d", part.colour_type],
            false => vec![s(&alone)],
        };
        if !peers.oiio(&reference, &theirs) {
            return Err(format!("oiiotool cannot composite part {k}"));
        }
        let read = rgba_of(&composited, k, part, false, false);
        let read: Vec<&str> = read.iter().map(String::as_str).collect();
        if !peers.oiio(&read, &ours) {
            return Err(format!("oiiotool cannot read over of part {k}"));
        }
        if let Some(d) = peers.differ(&ours, &theirs, false) {
            return Err(format!("over of part {k} differs from oiiotool:\n{d}"));
        }
    }
    Ok(())
}

/// Runs `check_image` on each of `images`; the failures, one a line.
fn sweep(images: &[(String, PathBuf)]) -> Vec<String> {
    let peers = Peers {
        oiiotool: peer("oiiotool"),
        idiff: peer("idiff"),
        exrmultipart: peer("exrmultipart"),
    };
    let dir = tempfile::tempdir().unwrap();
    let failures: Vec<String> = images
        .iter()
        .filter_map(|(name, path)| {
            check_image(path, dir.path(), &peers)
                .err()
                .map(|e| format!("{name}: {e}"))
        })
        .collect();
    eprintln!("{} images checked", images.len());
    failures
}

/// Issue 14's "done means": every good image of OpenEXR's public test
/// collection we have passes `info`, `transcode` (pixels equal by `idiff
/// -fail 0`, every part kept by name) and, with colour, `over` with itself
/// (equal to `oiiotool --over`).
#[test]
fn every_good_image_passes_info_transcode_and_over_with_itself() {
    let images = good_images();
    assert!(!images.is_empty());
    let failures = sweep(&images);
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// Files of each class made by OpenEXR's and OIIO's own tools from a
/// generated plate (RGBA half, Z and vectors float), a shipped RGB image
/// with a display window and the shipped deep pass: tiles of 32, 64 and
/// 256, mipmaps and ripmaps rounded down and up, and multi-part files
/// mixing scanline, tiled, mipmapped, ripmapped and deep parts; with PyPI's
/// OpenEXR, luminance/chroma files (Y, RY, BY at sampling 2 2, with and
/// without A) in B44 and B44A. `None` without the tools.
pub fn made_images(d: &Path) -> Option<Vec<(String, PathBuf)>> {
    let (oiiotool, maketiled, multipart) = (
        peer("oiiotool")?,
        peer("exrmaketiled")?,
        peer("exrmultipart")?,
    );
    let file = |name: &str| d.join(format!("{name}.exr"));
    let plate = file("plate");
    generate(&plate, "fg", (97, 61), &[]);
    let rgb = shipped_images().join("DisplayWindow/t01.exr");
    let deep = shipped_images().join("v2/LowResLeftView/Trunks.exr");
    let mut made = Vec::new();
    // `program ARGS`, with `OUT` the made file `name`.
    let mut make = |name: &str, program: &Path, args: &[&Path]| {
        let out = file(name);
        let args = args
            .iter()
            .map(|&a| if a == Path::new("OUT") { &out } else { a });
        succeed(Command::new(program).args(args));
        made.push((name.to_string(), out));
    };
    let p = Path::new;
    // oiiotool 2.4 writes a plate of mixed types as float, or as `-d`.
    for (tile, c, format) in [
        ("32", "zip", "float"),
        ("64", "piz", "half"),
        ("256", "none", "float"),
    ] {
        let args = [
            &plate,
            p("--tile"),
            p(tile),
            p(tile),
            p("--compression"),
            p(c),
            p("-d"),
            p(format),
            p("-o"),
            p("OUT"),
        ];
        make(&format!("tiled-{tile}-{c}-{format}"), &oiiotool, &args);
    }
    let args = [
        &rgb,
        p("--tile"),
        p("16"),
        p("16"),
        p("--compression"),
        p("rle"),
        p("-o"),
        p("OUT"),
    ];
    make("tiled-rgb-16-rle", &oiiotool, &args);
    for (name, source, options) in [
        ("mip-down-32-zip", &plate, "-m -t 32 32 -z zip"),
        ("mip-up-16-rle", &plate, "-m -u -t 16 16 -z rle"),
        ("rip-down-32-piz", &plate, "-r -t 32 32 -z piz"),
        ("rip-up-64-zip-rgb", &rgb, "-r -u -z zip"),
    ] {
        let mut args: Vec<&Path> = options.split(' ').map(p).collect();
        args.extend([source.as_path(), p("OUT")]);
        make(name, &maketiled, &args);
    }
    for (name, parts) in [
        (
            "parts-scanline-first",
            [
                &plate,
                &file("tiled-32-zip-float"),
                &file("mip-down-32-zip"),
                &file("rip-down-32-piz"),
                &deep,
            ]
            .to_vec(),
        ),
        (
            "parts-mipmap-first",
            vec![
                &file("mip-down-32-zip"),
                &plate,
                &file("rip-up-64-zip-rgb"),
                &file("tiled-32-zip-float"),
            ],
        ),
        (
            "parts-deep-first",
            vec![&deep, &file("tiled-32-zip-float"), &rgb],
        ),
    ] {
        let mut args = vec![p("-combine"), p("-override"), p("1"), p("-i")];
        args.extend(parts.iter().map(|f| f.as_path()));
        args.extend([p("-o"), p("OUT")]);
        make(name, &multipart, &args);
    }
    made.extend(luminance_chroma_b44(d));
    Some(made)
}

/// B44 and B44A luminance/chroma files written by OpenEXR (PyPI's
/// OpenEXR, tests/peers/openexr_subsampled.py), none without it.
fn luminance_chroma_b44(d: &Path) -> Vec<(String, PathBuf)> {
    let Some(python) = openexr_python() else {
        return Vec::new();
    };
    let script = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/peers/openexr_subsampled.py");
    let folder = d.join("luminance-chroma");
    std::fs::create_dir_all(&folder).unwrap();
    succeed(Command::new(python).arg(script).arg("write").arg(&folder));
    ["yc_b44", "yc_b44a", "yca_b44", "yca_b44a"]
        .map(|name| (name.to_string(), folder.join(format!("{name}.exr"))))
        .to_vec()
}

/// The same sweep over files of every class made here by the peers.
#[test]
fn files_of_every_class_made_by_the_peers_pass_info_transcode_and_over() {
    let dir = tempfile::tempdir().unwrap();
    let Some(images) = made_images(dir.path()) else {
        return;
    };
    let failures = sweep(&images);
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn info_rejects_every_damaged_file_quickly_and_cleanly() {
    let damaged = files_under("Damaged");
    assert!(!damaged.is_empty());
    for path in damaged {
        let started = Instant::now();
        let out = limited(&["info", path.to_str().unwrap()]);
        let message = stderr(&out);
        assert_eq!(
            out.status.code(),
            Some(3),
            "{}: exit {:?}, {message}",
            path.display(),
            out.status
        );
        assert!(
            message.contains(path.file_name().unwrap().to_str().unwrap()),
            "error must name the file: {message}"
        );
        assert_eq!(
            message.lines().count(),
            1,
            "one line, no panic trace: {message}"
        );
        assert!(!message.contains("panicked"), "{message}");
        assert!(
            started.elapsed() < Duration::from_secs(10),
            "{} took {:?}",
            path.display(),
            started.elapsed()
        );
    }
}

#[test]
fn two_frames_of_the_beachball_sequence_composite_like_the_reference() {
    // fg frame N is Beachball frame N + 1, over Beachball frame N: a real
    // multi-layer sequence whose many extra channels pass through from bg.
    let Some(images) = shared_images() else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let beachball = images.join("Beachball");
    for frame in 1..=2 {
        let source = beachball.join(format!("singlepart.{:04}.exr", frame + 1));
        std::fs::copy(&source, dir.path().join(format!("fg.{frame:04}.exr"))).unwrap();
    }
    let fg = dir.path().join("fg.####.exr");
    let bg = beachball.join("singlepart.####.exr");
    let out = dir.path().join("comp.####.exr");
    let result = run(&[
        "over",
        fg.to_str().unwrap(),
        bg.to_str().unwrap(),
        "-o",
        out.to_str().unwrap(),
        "--frames",
        "1-2",
        "-q",
    ]);
    assert!(result.status.success(), "{}", stderr(&result));
    for frame in 1..=2 {
        let ours = read_image(&dir.path().join(format!("comp.{frame:04}.exr")));
        let reference = reference_over(
            &read_image(&dir.path().join(format!("fg.{frame:04}.exr"))),
            &read_image(&beachball.join(format!("singlepart.{frame:04}.exr"))),
            false,
        );
        assert!(ours.channels.len() > 4, "extra channels pass through");
        assert_identical(&ours, &reference);
        assert_peers_read(&dir.path().join(format!("comp.{frame:04}.exr")));
    }
}

#[test]
fn mipmapped_tiled_input_composites_at_level_0() {
    let Some(path) = public_image("MultiResolution/ColorCodedLevels.exr") else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out.exr");
    let result = run(&["over", s(&path), s(&path), "-o", s(&out), "-q"]);
    assert!(result.status.success(), "{}", stderr(&result));
    let level0 = read_image(&path);
    assert_identical(&read_image(&out), &reference_over(&level0, &level0, false));
    assert_peers_read(&out);
}
