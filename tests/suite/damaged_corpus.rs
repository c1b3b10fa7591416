//! OpenEXR's own collection of damaged files (shared/exr-images/Damaged:
//! fuzzed, truncated, oversized) through every kind of command, as foreground
//! and as background, each in a child process under a 4 GiB address-space
//! limit and a time limit. Each run either succeeds with an output that
//! OpenEXR decodes, or refuses the file in one line naming it (exit 3); never a
//! panic, an abort, a signal, a hang, or anything left in the output folder.

use crate::common::*;
use std::collections::BTreeMap;
use std::path::PathBuf;

#[test]
fn every_damaged_file_is_refused_or_processed_by_every_command() {
    let Some(folder) = shared_images().map(|root| root.join("Damaged")) else {
        return;
    };
    let mut files: Vec<PathBuf> = std::fs::read_dir(&folder)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_none_or(|e| e != "rst"))
        .collect();
    files.sort();
    assert!(!files.is_empty(), "{} is empty", folder.display());
    let dir = tempfile::tempdir().unwrap();
    let good = dir.path().join("good.exr");
    generate(&good, "bg", (64, 64), &[]);
    let oiiotool = peer("oiiotool");
    let commands = hostile_commands();

    // Two workers: the runs are short, single processes, mostly refused at
    // the header.
    let workers = 2;
    let results: Vec<(String, &str, Option<i32>, Option<String>)> = std::thread::scope(|scope| {
        let handles: Vec<_> = (0..workers)
            .map(|w| {
                let (files, commands, dir) = (&files, &commands, dir.path());
                let (good, oiiotool) = (&good, oiiotool.as_deref());
                scope.spawn(move || {
                    let mut results = Vec::new();
                    for file in files.iter().skip(w).step_by(workers) {
                        let name = file.file_name().unwrap().to_string_lossy().into_owned();
                        for (command, args) in commands {
                            let work = dir.join(format!("work{w}"));
                            std::fs::create_dir(&work).unwrap();
                            let out = work.join("out.exr");
                            let args = args(s(file), s(good), s(&out));
                            let (code, wrong) = hostile_run(file, &args, &work, &out, oiiotool);
                            std::fs::remove_dir_all(&work).unwrap();
                            results.push((name.clone(), *command, code, wrong));
                        }
                    }
                    results
                })
            })
            .collect();
        handles
            .into_iter()
            .flat_map(|h| h.join().unwrap())
            .collect()
    });

    let mut counts: BTreeMap<(&str, Option<i32>), usize> = BTreeMap::new();
    for (_, command, code, _) in &results {
        *counts.entry((command, *code)).or_default() += 1;
    }
    eprintln!("{} files; exit codes per command: {counts:?}", files.len());
    let wrong: Vec<String> = results
        .iter()
        .filter_map(|(name, command, _, wrong)| {
            wrong.as_ref().map(|w| format!("{name}, {command}: {w}"))
        })
        .collect();
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}
