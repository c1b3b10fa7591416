//! Every file of the shared foreign image set (../shared/foreign-images,
//! whatever it holds: a file added there is covered) is read as oiiotool
//! reads it (`oiiotool FILE -d half|float`, the type exrcomp reads it as,
//! compared with `idiff -fail 0`), or refused in one line naming it, exit
//! code 3, nothing written, saying which class is not read (a file that
//! fails to decode is not refused: oiiotool read it). specs/file-format.md,
//! "Foreign inputs".

use crate::common::{limited, read_image, s, stderr, Samples};
use crate::foreign_inputs::{assert_as_oiiotool, foreign_images};
use std::path::{Path, PathBuf};

/// The image files under `dir`, sorted (not the licences and READMEs).
fn images(dir: &Path, into: &mut Vec<PathBuf>) {
    let mut entries: Vec<PathBuf> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .collect();
    entries.sort();
    for path in entries {
        let ext = path.extension().and_then(|e| e.to_str()).unwrap_or("");
        if path.is_dir() {
            images(&path, into);
        } else if !ext.is_empty() && !["md", "txt"].contains(&ext) {
            into.push(path);
        }
    }
}

#[test]
fn every_shared_foreign_image_reads_as_oiiotool_or_is_refused_in_one_line() {
    let Some(root) = foreign_images() else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let mut files = Vec::new();
    images(&root, &mut files);
    assert!(
        files.len() >= 20,
        "{} files in {}",
        files.len(),
        root.display()
    );
    let (mut read, mut refused) = (Vec::new(), Vec::new());
    for (k, input) in files.iter().enumerate() {
        let output = dir.path().join(format!("{k}.exr"));
        let out = limited(&["transcode", s(input), "-o", s(&output), "-q"]);
        let said = stderr(&out);
        if out.status.success() {
            let float = read_image(&output)
                .channels
                .values()
                .all(|c| matches!(c, Samples::F32(_)));
            assert_as_oiiotool(input, &output, float);
            read.push(input);
        } else {
            assert_eq!(out.status.code(), Some(3), "{}: {said}", input.display());
            assert_eq!(said.trim_end().lines().count(), 1, "{said}");
            assert!(said.contains(s(input)), "{said}");
            assert!(
                !output.exists(),
                "{}: an output was written",
                input.display()
            );
            // A class not read, said as such: not a file that fails to
            // decode, which oiiotool read.
            assert!(said.contains(" not read"), "{said}");
            refused.push(input);
        }
    }
    eprintln!(
        "{} read as oiiotool reads them, refused: {refused:?}",
        read.len()
    );
}
