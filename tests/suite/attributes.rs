//! Header attributes survive exactly, and the same job writes the same bytes:
//! an input carrying every kind of standard attribute (OpenEXR's exrstdattr)
//! and custom typed ones (oiiotool's --attrib), checked against exrheader's
//! own reading of the input.

use crate::common::*;
use std::path::{Path, PathBuf};
use std::process::Command;

/// exrheader's text of `path` without the lines exrcomp owns: the file
/// name, its provenance (`Software`, and `Exif:ImageHistory`, a string of
/// several lines) and the chunk count it declares.
fn header_text(exrheader: &Path, path: &Path) -> String {
    let out = Command::new(exrheader).arg(path).output().unwrap();
    assert!(
        out.status.success(),
        "exrheader cannot read {}",
        path.display()
    );
    let mut in_history = false;
    String::from_utf8_lossy(&out.stdout)
        .lines()
        .filter(|l| {
            in_history |= l.starts_with("Exif:ImageHistory ");
            let owned = in_history
                || ["file ", "Software ", "chunkCount ", "exrcomp:fingerprint "]
                    .iter()
                    .any(|p| l.starts_with(p));
            in_history &= !l.ends_with('"');
            !owned
        })
        .collect::<Vec<_>>()
        .join("\n")
}

/// `d/in.exr`, holding every standard attribute exrstdattr sets and custom
/// ones of many types; `None` without the peer tools that make it.
fn every_attribute_input(d: &Path) -> Option<PathBuf> {
    let (Some(exrstdattr), Some(oiiotool)) = (peer("exrstdattr"), peer("oiiotool")) else {
        return None;
    };
    generate(&d.join("plain.exr"), "bg", (40, 36), &[]);
    // Custom attributes of many types, as oiiotool and Nuke write them.
    let out = Command::new(oiiotool)
        .arg(d.join("plain.exr"))
        .args(["--attrib", "studio:float", "1.5"])
        .args(["--attrib", "studio:int", "7"])
        .args(["--attrib", "studio:string", "shot 010"])
        .args([
            "--attrib:type=matrix",
            "studio:m44",
            "1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1",
        ])
        .args(["--attrib:type=vector", "studio:v3", "1,2,3"])
        .args(["--attrib:type=float[2]", "studio:v2", "1,2"])
        .args(["--attrib:type=int[2]", "studio:v2i", "1,2"])
        .args(["--attrib:type=rational", "studio:rational", "1/3"])
        .args(["--attrib:type=box2i", "studio:box", "0,0,5,5"])
        .args(["--attrib:type=double", "studio:double", "2.5"])
        .arg("-o")
        .arg(d.join("custom.exr"))
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", stderr(&out));
    // Every standard attribute exrstdattr sets, keyCode among them.
    let input = d.join("in.exr");
    let out = Command::new(exrstdattr)
        .args(["-keyCode", "1", "2", "3", "4", "5", "4", "64"])
        .args(["-timeCode", "1", "2", "-framesPerSecond", "24", "1"])
        .args([
            "-chromaticities",
            "0.64",
            "0.33",
            "0.3",
            "0.6",
            "0.15",
            "0.06",
            "0.3127",
            "0.329",
        ])
        .args([
            "-whiteLuminance",
            "100",
            "-xDensity",
            "72",
            "-utcOffset",
            "3600",
        ])
        .args([
            "-longitude",
            "1",
            "-latitude",
            "2",
            "-altitude",
            "3",
            "-focus",
            "4",
        ])
        .args(["-expTime", "0.01", "-aperture", "2.8", "-isoSpeed", "100"])
        .args([
            "-envmap",
            "LATLONG",
            "-wrapmodes",
            "clamp",
            "-adoptedNeutral",
            "0.3",
            "0.3",
        ])
        .args([
            "-owner",
            "me",
            "-comments",
            "hello",
            "-capDate",
            "2026:01:01 10:00:00",
        ])
        .args(["-renderingTransform", "RT", "-lookModTransform", "LMT"])
        .arg(d.join("custom.exr"))
        .arg(&input)
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", stderr(&out));
    Some(input)
}

#[test]
fn every_attribute_survives_and_runs_write_identical_bytes() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let (Some(exrheader), Some(input)) = (peer("exrheader"), every_attribute_input(d)) else {
        return;
    };
    // And a two-part file of it (exrmultipart's), every attribute in each part.
    let parts = d.join("parts.exr");
    if let Some(exrmultipart) = peer("exrmultipart") {
        std::fs::copy(&input, d.join("second.exr")).unwrap();
        succeed(
            Command::new(exrmultipart)
                .args(["-combine", "-i"])
                .args([&input, &d.join("second.exr")])
                .arg("-o")
                .arg(&parts),
        );
    }
    let tiled = ["--tile", "32", "--compression", "piz"];
    for source in [&input, &parts].into_iter().filter(|p| p.exists()) {
        let expected = header_text(&exrheader, source);
        assert!(expected.contains("keyCode") && expected.contains("studio:m44"));
        // Each job three times: the same bytes each time, every attribute kept
        // (a composite keeps B's, a tiled output all but the tiles').
        for job in [
            vec!["transcode", s(source)],
            vec!["over", s(source), s(source)],
            [&["over", s(source), s(source)][..], &tiled].concat(),
        ] {
            let outputs: Vec<Vec<u8>> = (0..3)
                .map(|i| {
                    let output = d.join(format!("out{i}.exr"));
                    let args = [&job[..], &["-o", s(&output), "-q"]].concat();
                    let out = run(&args);
                    assert!(out.status.success(), "{args:?}: {}", stderr(&out));
                    // What --tile and --compression change, left out of both.
                    let retiled = |text: &str| match job.len() > 3 {
                        true => text
                            .lines()
                            .filter(|l| {
                                ![
                                    "compression ",
                                    "tiles ",
                                    "    single level",
                                    "    tile size",
                                    "type ",
                                ]
                                .iter()
                                .any(|p| l.starts_with(p))
                            })
                            .collect::<Vec<_>>()
                            .join("\n"),
                        false => text.to_string(),
                    };
                    let text = header_text(&exrheader, &output);
                    assert_eq!(retiled(&text), retiled(&expected), "{args:?}");
                    assert_eq!(text.contains("tile size 32 by 32"), job.len() > 3);
                    assert_peers_read(&output);
                    std::fs::read(&output).unwrap()
                })
                .collect();
            assert!(
                outputs.iter().all(|o| *o == outputs[0]),
                "runs of {job:?} differ"
            );
        }
    }
}

/// `bytes` of a single-part file with attribute `name` of type `kind`
/// holding `value(old value)`; the chunk offsets move with the header.
fn retyped(bytes: &[u8], name: &str, kind: &str, value: impl Fn(&[u8]) -> Vec<u8>) -> Vec<u8> {
    let text_end = |from: usize| from + bytes[from..].iter().position(|&b| b == 0).unwrap();
    let mut out = bytes[..8].to_vec();
    let mut at = 8;
    while bytes[at] != 0 {
        let name_end = text_end(at);
        let kind_end = text_end(name_end + 1);
        let size = i32::from_le_bytes(bytes[kind_end + 1..kind_end + 5].try_into().unwrap());
        let end = kind_end + 5 + size as usize;
        if &bytes[at..name_end] == name.as_bytes() {
            let new = value(&bytes[kind_end + 5..end]);
            for text in [name, kind] {
                out.extend_from_slice(text.as_bytes());
                out.push(0);
            }
            out.extend_from_slice(&(new.len() as i32).to_le_bytes());
            out.extend_from_slice(&new);
        } else {
            out.extend_from_slice(&bytes[at..end]);
        }
        at = end;
    }
    out.push(0);
    let table = at + 1;
    let moved = out.len() as i64 - table as i64;
    let first = u64::from_le_bytes(bytes[table..table + 8].try_into().unwrap()) as usize;
    for entry in bytes[table..first].chunks_exact(8) {
        let offset = u64::from_le_bytes(entry.try_into().unwrap()) as i64 + moved;
        out.extend_from_slice(&(offset as u64).to_le_bytes());
    }
    out.extend_from_slice(&bytes[first..]);
    out
}

#[test]
fn mistyped_standard_attributes_are_refused_as_openexr_refuses_them() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let plain = d.join("plain.exr");
    generate(&plain, "bg", (16, 12), &[]);
    let bytes = std::fs::read(&plain).unwrap();
    // The file is sound before it is patched.
    let same = d.join("same.exr");
    std::fs::write(
        &same,
        retyped(&bytes, "lineOrder", "lineOrder", <[u8]>::to_vec),
    )
    .unwrap();
    assert!(run(&["info", s(&same)]).status.success());
    // Attribute, type written, type OpenEXR requires, value from the old one.
    type Case = (
        &'static str,
        &'static str,
        &'static str,
        fn(&[u8]) -> Vec<u8>,
    );
    let cases: [Case; 5] = [
        ("lineOrder", "int", "lineOrder", |old| vec![old[0], 0, 0, 0]),
        ("dataWindow", "v2i", "box2i", |old| old.to_vec()),
        ("compression", "int", "compression", |old| {
            vec![old[0], 0, 0, 0]
        }),
        ("pixelAspectRatio", "double", "float", |_| {
            1f64.to_le_bytes().to_vec()
        }),
        ("channels", "string", "chlist", |old| old.to_vec()),
    ];
    for (name, kind, wanted, value) in cases {
        let path = d.join(format!("{name}.exr"));
        std::fs::write(&path, retyped(&bytes, name, kind, value)).unwrap();
        if let Some(exrheader) = peer("exrheader") {
            let out = Command::new(exrheader).arg(&path).output().unwrap();
            assert!(!out.status.success(), "OpenEXR reads {name} as {kind}");
        }
        let expected =
            format!("attribute '{name}' has type '{kind}' where OpenEXR requires '{wanted}'");
        for command in [
            vec!["info", s(&path)],
            vec!["transcode", s(&path), "-o", s(&d.join("out.exr")), "-q"],
        ] {
            let out = run(&command);
            assert_eq!(out.status.code(), Some(3), "{command:?}: {}", stderr(&out));
            assert!(
                stderr(&out).contains(&expected),
                "{command:?}: {}",
                stderr(&out)
            );
        }
    }
}

/// The string attribute `name` of `path`'s first part, if it has one.
fn string_attribute(path: &Path, name: &str) -> Option<String> {
    let meta = exr::meta::MetaData::read_from_file(path, false).unwrap();
    let value = meta.headers[0]
        .all_named_attributes()
        .find(|(n, _)| *n == name.as_bytes())
        .map(|(_, value)| match value {
            exr::meta::attribute::AttributeValue::Text(text) => text.to_string(),
            other => panic!("{name} is {other:?}"),
        });
    value
}

#[test]
fn outputs_say_who_wrote_them_and_keep_the_history_of_their_input() {
    let Some(oiiotool) = peer("oiiotool") else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let ours = concat!("exrcomp ", env!("CARGO_PKG_VERSION"));
    // oiiotool's convention: `Software` names the writer, `Exif:ImageHistory`
    // collects one line per step.
    let input = d.join("in.exr");
    let made = Command::new(&oiiotool)
        .args([
            "--pattern",
            "constant:color=0.5,0.2,0.1,1",
            "32x24",
            "4",
            // Set here: oiiotool 2.4 writes a history by default, 3.2 only
            // with --history.
            "--attrib",
            "Exif:ImageHistory",
            "oiiotool --pattern constant",
            "-o",
        ])
        .arg(&input)
        .output()
        .unwrap();
    assert!(made.status.success(), "{}", stderr(&made));
    let history = string_attribute(&input, "Exif:ImageHistory").unwrap();
    let output = d.join("out.exr");
    let out = run(&["transcode", s(&input), "-o", s(&output), "-q"]);
    assert!(out.status.success(), "{}", stderr(&out));
    assert_eq!(string_attribute(&output, "Software").as_deref(), Some(ours));
    assert_eq!(string_attribute(&output, "software"), None);
    assert_eq!(
        string_attribute(&output, "Exif:ImageHistory"),
        Some(format!("{history}\n{ours}"))
    );
    // Without a history, the input's writer starts it.
    let plain = d.join("plain.exr");
    let made = Command::new(&oiiotool)
        .arg(&input)
        .args(["--nosoftwareattrib", "--eraseattrib", "Exif:ImageHistory"])
        .args(["--attrib", "Software", "Renderer 7", "-o"])
        .arg(&plain)
        .output()
        .unwrap();
    assert!(made.status.success(), "{}", stderr(&made));
    assert_eq!(string_attribute(&plain, "Exif:ImageHistory"), None);
    let out = run(&["transcode", s(&plain), "-o", s(&output), "-q"]);
    assert!(out.status.success(), "{}", stderr(&out));
    assert_eq!(
        string_attribute(&output, "Exif:ImageHistory"),
        Some(format!("Renderer 7\n{ours}"))
    );
    assert_peers_read(&output);
}

#[test]
fn a_preview_of_the_input_is_dropped() {
    use exr::prelude::*;
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let input = d.join("in.exr");
    let pixels = SpecificChannels::rgba(|_: Vec2<usize>| (0.5f32, 0.25f32, 0.125f32, 1.0f32));
    let preview = exr::meta::attribute::Preview {
        size: Vec2(2, 2),
        pixel_data: vec![255; 16].into_iter().map(|b: u8| b as i8).collect(),
    };
    let attributes = LayerAttributes {
        preview: Some(preview),
        ..LayerAttributes::named("rgba")
    };
    Image::from_layer(Layer::new(
        (8, 6),
        attributes,
        Encoding {
            compression: Compression::ZIP16,
            blocks: Blocks::ScanLines,
            line_order: LineOrder::Increasing,
        },
        pixels,
    ))
    .write()
    .to_file(&input)
    .unwrap();
    let has_preview = |path: &Path| {
        let meta = exr::meta::MetaData::read_from_file(path, false).unwrap();
        meta.headers[0].own_attributes.preview.is_some()
    };
    assert!(has_preview(&input));
    let output = d.join("out.exr");
    let out = run(&["transcode", s(&input), "-o", s(&output), "-q"]);
    assert!(out.status.success(), "{}", stderr(&out));
    assert!(!has_preview(&output));
}

/// `exrcomp info`'s text of `path`, less its first line (the file, which
/// exrheader names without the size) and its chunk checks (`pixels:`).
fn info_text(path: &Path) -> String {
    let out = run(&["info", s(path)]);
    assert!(out.status.success(), "{}", stderr(&out));
    String::from_utf8_lossy(&out.stdout)
        .lines()
        .filter(|l| !l.starts_with("file ") && !l.starts_with("pixels: "))
        .collect::<Vec<_>>()
        .join("\n")
}

/// exrheader's text of `path` less its first line.
fn exrheader_text(exrheader: &Path, path: &Path) -> String {
    let out = Command::new(exrheader).arg(path).output().unwrap();
    assert!(out.status.success(), "{}", stderr(&out));
    String::from_utf8_lossy(&out.stdout)
        .lines()
        .filter(|l| !l.starts_with("file "))
        .collect::<Vec<_>>()
        .join("\n")
}

#[test]
fn info_prints_what_exrheader_prints() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let (Some(exrheader), Some(input)) = (peer("exrheader"), every_attribute_input(d)) else {
        return;
    };
    // Every attribute type, in a file of ours (which declares its chunkCount
    // and type), in a multi-part file of the exr crate's, tiled, and deep.
    let output = d.join("out.exr");
    let out = run(&["transcode", s(&input), "-o", s(&output), "-q"]);
    assert!(out.status.success(), "{}", stderr(&out));
    let parts = d.join("parts.exr");
    let img = random_rgba(71, 2, 3, 12, 10, Kind::Float, true);
    write_parts(&parts, &[("rgba", "left", &img), ("other", "right", &img)]);
    let tiled = d.join("tiled.exr");
    if let Some(oiiotool) = peer("oiiotool") {
        let out = Command::new(oiiotool)
            .arg(&output)
            .args(["--tile", "16", "16", "-o"])
            .arg(&tiled)
            .output()
            .unwrap();
        assert!(out.status.success(), "{}", stderr(&out));
    }
    // And OpenEXR's deep scanline pass, whose type is not the crate's.
    let deep = shipped_images().join("v2/LowResLeftView/Trunks.exr");
    for path in [&output, &parts, &tiled, &deep] {
        if path.exists() {
            assert_eq!(
                info_text(path),
                exrheader_text(&exrheader, path),
                "{}",
                path.display()
            );
        }
    }
    let text = String::from_utf8_lossy(&run(&["info", s(&parts)]).stdout).into_owned();
    assert!(text.contains(" part 1:\n"), "{text}");
    assert!(text.contains("pixels: all 1 chunks decode"), "{text}");
}

#[test]
fn info_json_gives_the_same_facts_per_part() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let parts = d.join("parts.exr");
    let img = random_rgba(72, 2, 3, 12, 40, Kind::Half, false);
    write_parts(&parts, &[("rgba", "left", &img), ("other", "right", &img)]);
    let out = run(&["info", "--json", s(&parts)]);
    assert!(out.status.success(), "{}", stderr(&out));
    let facts: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(facts["file"], s(&parts));
    assert_eq!(facts["flags"], 0x1000);
    let part = &facts["parts"][1];
    assert_eq!(part["chunks"], 3);
    assert_eq!(part["checked"], "all 3 chunks decode");
    let attributes = &part["attributes"];
    assert_eq!(
        attributes["dataWindow"],
        serde_json::json!({"type": "box2i", "value": {"min": [2, 3], "max": [13, 42]}})
    );
    assert_eq!(attributes["compression"]["value"], "zip");
    assert_eq!(attributes["view"]["value"], "right");
    assert_eq!(
        attributes["channels"]["value"][1],
        serde_json::json!({"name": "B", "type": "half", "sampling": [1, 1], "plinear": false})
    );
}

/// OpenEXR's names and strings are bytes, UTF-8 in practice: a non-ASCII
/// channel name and string attribute are written as their UTF-8 bytes, found
/// by --ch, --layer and job files as typed, and shown as OpenEXR shows them
/// (they had been read as Latin-1: "Ü" shown as "Ã\u{9c}", and not found).
#[test]
fn non_ascii_names_and_strings_are_utf8_both_ways() {
    let dir = tempfile::tempdir().unwrap();
    let p = |n: &str| dir.path().join(n);
    generate(&p("plain.exr"), "fg", (8, 4), &[]);
    ok(&[
        "shuffle",
        s(&p("plain.exr")),
        "--ch",
        "R,G,B,Ü=A,日本.R=R",
        "--attrib",
        "note=värde",
        "-o",
        s(&p("u.exr")),
        "-q",
    ]);
    let bytes = std::fs::read(p("u.exr")).unwrap();
    let holds = |needle: &[u8]| bytes.windows(needle.len()).any(|w| w == needle);
    assert!(holds("Ü\0".as_bytes()) && holds("日本.R\0".as_bytes()));
    assert!(holds("note\0string\0".as_bytes()) && holds("värde".as_bytes()));
    // Found as typed: a channel, a layer, and in a job file.
    ok(&[
        "shuffle",
        s(&p("u.exr")),
        "--ch",
        "Ü,A=Ü",
        "-o",
        s(&p("a.exr")),
        "-q",
    ]);
    ok(&[
        "premult",
        s(&p("u.exr")),
        "--layer",
        "日本",
        "-o",
        s(&p("l.exr")),
        "-q",
    ]);
    let job = format!(
        "[[node]]\nname = \"in\"\nread = \"{}\"\n\n[[node]]\nname = \"s\"\nop = \"shuffle\"\nch = \"X=Ü\"\ninputs = [\"in\"]\n\n[[node]]\nname = \"out\"\nwrite = \"{}\"\ninputs = [\"s\"]\nattrib = [\"söt=ö\"]\n",
        s(&p("u.exr")),
        s(&p("j.exr"))
    );
    std::fs::write(p("job.toml"), job).unwrap();
    ok(&["run", s(&p("job.toml")), "-q"]);
    // X is Ü, which is the plate's A (the test's reader keys names as Latin-1).
    assert_eq!(
        read_image(&p("j.exr")).channels["X"],
        read_image(&p("plain.exr")).channels["A"]
    );
    // Shown as OpenEXR shows them.
    let out = run(&["info", s(&p("u.exr"))]);
    let text = String::from_utf8_lossy(&out.stdout).to_string();
    assert!(text.contains("    Ü, 16-bit floating-point"), "{text}");
    assert!(text.contains("note (type string): \"värde\""), "{text}");
    if let Some(exrheader) = peer("exrheader") {
        let theirs = succeed(std::process::Command::new(exrheader).arg(p("j.exr")));
        let theirs = String::from_utf8_lossy(&theirs.stdout).to_string();
        assert!(theirs.contains("söt (type string): \"ö\""), "{theirs}");
        let theirs =
            succeed(std::process::Command::new(peer("exrheader").unwrap()).arg(p("u.exr")));
        let theirs = String::from_utf8_lossy(&theirs.stdout).to_string();
        assert!(
            theirs.contains("    日本.R, 16-bit floating-point"),
            "{theirs}"
        );
    }
}
