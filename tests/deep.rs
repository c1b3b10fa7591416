//! Deep scanline inputs: flattened as they are read, and merged by depth
//! before flattening, checked against OpenEXR's and OIIO's own
//! (`oiiotool --flatten`, `--deepmerge`) on the public deep passes.

mod common;
use common::*;
use std::path::{Path, PathBuf};
use std::process::Command;

/// A deep pass: Trunks is shipped, Balls only in the shared set.
fn pass(name: &str) -> Option<PathBuf> {
    public_image(&format!("v2/LowResLeftView/{name}.exr"))
}

fn ok(args: &[&str]) {
    let out = run(args);
    assert!(out.status.success(), "{args:?}: {}", stderr(&out));
}

/// `oiiotool ARGS --ch R,G,B,A -o OUT`.
fn oiiotool_rgba(oiio: &Path, args: &[&str], out: &Path) {
    let status = Command::new(oiio)
        .args(args)
        .args(["--ch", "R,G,B,A", "-o"])
        .arg(out)
        .status()
        .unwrap();
    assert!(status.success(), "oiiotool {args:?}");
}

#[test]
fn flatten_equals_oiiotool_flatten_and_does_not_depend_on_strips() {
    let (Some(oiio), Some(idiff)) = (peer("oiiotool"), peer("idiff")) else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    for name in ["Balls", "Trunks"] {
        let Some(input) = pass(name) else { continue };
        let ours = d.join(format!("{name}.exr"));
        ok(&["flatten", s(&input), "-o", s(&ours), "-q"]);
        assert_peers_read(&ours);
        let (ours_rgba, theirs) = (
            d.join(format!("{name}-rgba.exr")),
            d.join(format!("{name}-oiio.exr")),
        );
        oiiotool_rgba(&oiio, &[s(&ours)], &ours_rgba);
        oiiotool_rgba(&oiio, &[s(&input), "--flatten"], &theirs);
        assert_idiff_identical(&idiff, &ours_rgba, &theirs);
        let strips = d.join(format!("{name}-strips.exr"));
        ok(&[
            "flatten",
            s(&input),
            "-o",
            s(&strips),
            "-q",
            "--strip-rows",
            "7",
        ]);
        assert_identical(&read_image(&ours), &read_image(&strips));
    }
}

#[test]
fn deepmerge_matches_oiiotool_and_either_order() {
    let (Some(oiio), Some(idiff)) = (peer("oiiotool"), peer("idiff")) else {
        return;
    };
    let (Some(balls), Some(trunks)) = (pass("Balls"), pass("Trunks")) else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let (ab, ba) = (d.join("ab.exr"), d.join("ba.exr"));
    ok(&["deepmerge", s(&balls), s(&trunks), "-o", s(&ab), "-q"]);
    ok(&["deepmerge", s(&trunks), s(&balls), "-o", s(&ba), "-q"]);
    let (ours_rgba, theirs) = (d.join("ab-rgba.exr"), d.join("oiio.exr"));
    oiiotool_rgba(&oiio, &[s(&ab)], &ours_rgba);
    oiiotool_rgba(
        &oiio,
        &[s(&balls), s(&trunks), "--deepmerge", "--flatten"],
        &theirs,
    );
    // Two pixels of 445,000 differ by about 1e-3 (samples at equal depth).
    let out = Command::new(idiff)
        .args(["-fail", "0.002", "-failpercent", "0.001"])
        .arg(&ours_rgba)
        .arg(&theirs)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stdout)
    );
    let (x, y) = (read_image(&ab), read_image(&ba));
    for name in ["R", "G", "B", "A"] {
        for i in 0..x.channels[name].len() {
            let (p, q) = (x.channels[name].get_f32(i), y.channels[name].get_f32(i));
            assert!((p - q).abs() <= 1e-3, "{name}[{i}]: {p} vs {q}");
        }
    }
}

#[test]
fn any_command_flattens_deep_inputs_as_it_reads_them() {
    let (Some(deep_balls), Some(deep_trunks)) = (pass("Balls"), pass("Trunks")) else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let flat = |input: &Path, name: &str| {
        let out = d.join(format!("{name}-flat.exr"));
        ok(&["flatten", s(input), "-o", s(&out), "-q"]);
        out
    };
    let (balls, trunks) = (flat(&deep_balls, "Balls"), flat(&deep_trunks, "Trunks"));
    let (direct, via_files) = (d.join("direct.exr"), d.join("via.exr"));
    ok(&[
        "over",
        s(&deep_balls),
        s(&deep_trunks),
        "-o",
        s(&direct),
        "-q",
    ]);
    ok(&["over", s(&balls), s(&trunks), "-o", s(&via_files), "-q"]);
    assert_identical(&read_image(&direct), &read_image(&via_files));
    // A flat file cannot be deep-merged.
    let out = run(&[
        "deepmerge",
        s(&balls),
        s(&deep_trunks),
        "-o",
        s(&d.join("x.exr")),
    ]);
    assert_eq!(out.status.code(), Some(3), "{}", stderr(&out));
    assert!(stderr(&out).contains("is not deep"), "{}", stderr(&out));
}
