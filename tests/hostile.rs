//! Hostile input: real files truncated at many offsets and with single bytes
//! of their headers and offset tables changed. Every case ends within a
//! bounded time, under a memory limit, with success or a one-line error
//! naming the file: never a panic, an abort or a hang.

mod common;
use common::*;
use std::path::Path;
use std::time::{Duration, Instant};

fn check(path: &Path, truncated: bool) {
    let started = Instant::now();
    let out = limited(&["info", path.to_str().unwrap()]);
    let message = stderr(&out);
    let code = out.status.code();
    assert!(
        started.elapsed() < Duration::from_secs(20),
        "{message}: took {:?}",
        started.elapsed()
    );
    assert!(!message.contains("panicked"), "{message}");
    if truncated {
        assert_eq!(code, Some(3), "a truncated file must be refused: {message}");
    } else {
        assert!(
            matches!(code, Some(0 | 3)),
            "exit {:?}: {message}",
            out.status
        );
    }
    if code == Some(3) {
        assert!(
            message.contains(path.file_name().unwrap().to_str().unwrap()),
            "{message}"
        );
        assert_eq!(message.lines().count(), 1, "{message}");
    }
}

fn sources() -> Vec<(String, Vec<u8>)> {
    [
        "ScanLines/Desk.exr",
        "Beachball/singlepart.0001.exr",
        "TestImages/WideFloatRange.exr",
        "DisplayWindow/t01.exr",
    ]
    .iter()
    .map(|name| {
        (
            name.replace('/', "_"),
            std::fs::read(shared_images().join(name)).unwrap(),
        )
    })
    .collect()
}

/// Where the offset table starts and where it ends (the first chunk
/// begins there, in files whose chunks follow the table in order).
fn offset_table(bytes: &[u8]) -> (usize, usize) {
    let meta = exr::meta::MetaData::read_from_buffered(bytes, false).unwrap();
    let count = meta.headers[0].chunk_count;
    let entry =
        |start: usize| u64::from_le_bytes(bytes[start..start + 8].try_into().unwrap()) as usize;
    // The first entry points just past the table.
    let start = (0..bytes.len() - 8 * count)
        .find(|&start| entry(start) == start + 8 * count)
        .unwrap();
    (start, start + 8 * count)
}

#[test]
fn truncations_at_many_offsets_are_refused() {
    let dir = tempfile::tempdir().unwrap();
    for (name, bytes) in sources() {
        let path = dir.path().join(&name);
        let len = bytes.len();
        let (table, chunks) = offset_table(&bytes);
        let mut offsets: Vec<usize> = (1..24).map(|i| len * i / 24).collect();
        offsets.extend([
            0,
            4,
            8,
            table - 1,
            table,
            table + 5,
            chunks - 1,
            chunks,
            chunks + 5,
            len - 1,
        ]);
        for cut in offsets {
            std::fs::write(&path, &bytes[..cut]).unwrap();
            check(&path, true);
        }
    }
}

#[test]
fn changed_header_and_offset_table_bytes_never_crash() {
    let dir = tempfile::tempdir().unwrap();
    let mut rng = Lcg(2024);
    for (name, bytes) in sources() {
        let path = dir.path().join(&name);
        let (_, table_end) = offset_table(&bytes);
        for _ in 0..40 {
            let mut damaged = bytes.clone();
            let at = (rng.next() * table_end as f32) as usize;
            damaged[at] = match (rng.next() * 3.0) as u32 {
                0 => 0xff,
                1 => 0x00,
                _ => damaged[at] ^ (1 << (rng.next() * 8.0) as u32),
            };
            std::fs::write(&path, &damaged).unwrap();
            check(&path, false);
            // Compositing it must behave too.
            let out = limited(&[
                "over",
                path.to_str().unwrap(),
                path.to_str().unwrap(),
                "-o",
                dir.path().join("o.exr").to_str().unwrap(),
                "-q",
            ]);
            assert!(
                matches!(out.status.code(), Some(0 | 3)),
                "{}: {:?} {}",
                name,
                out.status,
                stderr(&out)
            );
        }
    }
}

#[test]
fn fuzzer_findings_stay_fixed() {
    // Inputs that once broke exrcomp (fuzz/README.md), kept as regressions:
    // read (`info`), and run through the engine by every kind of command.
    let folder = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fuzz-regressions");
    let mut files: Vec<_> = std::fs::read_dir(&folder)
        .unwrap_or_else(|e| panic!("{}: {e}", folder.display()))
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_none_or(|e| e != "md"))
        .collect();
    files.sort();
    assert!(
        !files.is_empty(),
        "no regression inputs in {}",
        folder.display()
    );
    let dir = tempfile::tempdir().unwrap();
    let good = dir.path().join("good.exr");
    generate(&good, "bg", (64, 64), &[]);
    let oiiotool = peer("oiiotool");
    let mut wrong = Vec::new();
    for file in &files {
        check(file, false);
        for (command, args) in hostile_commands() {
            let work = dir.path().join("work");
            std::fs::create_dir(&work).unwrap();
            let out = work.join("out.exr");
            let args = args(s(file), s(&good), s(&out));
            if let (_, Some(w)) = hostile_run(file, &args, &work, &out, oiiotool.as_deref()) {
                wrong.push(format!("{}, {command}: {w}", file.display()));
            }
            std::fs::remove_dir_all(&work).unwrap();
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}

#[test]
fn a_chunk_claiming_more_bytes_than_the_file_holds_is_refused_before_reading() {
    let dir = tempfile::tempdir().unwrap();
    let bytes = std::fs::read(shared_images().join("ScanLines/Desk.exr")).unwrap();
    let (_, first) = offset_table(&bytes);
    let mut damaged = bytes.clone();
    // Scanline chunk: y (i32), then the data size (i32).
    damaged[first + 4..first + 8].copy_from_slice(&i32::MAX.to_le_bytes());
    let path = dir.path().join("huge-chunk.exr");
    std::fs::write(&path, &damaged).unwrap();
    let out = limited(&["info", path.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(3));
    assert!(
        stderr(&out).contains("declares 2147483647 bytes"),
        "{}",
        stderr(&out)
    );
}

#[test]
fn a_result_too_wide_to_hold_a_strip_of_is_refused_before_allocating() {
    // Two small, valid images 200 million pixels apart: their union is
    // too wide for one block of rows to fit in memory.
    let dir = tempfile::tempdir().unwrap();
    let (a, b) = (dir.path().join("a.exr"), dir.path().join("b.exr"));
    let near = random_rgba(1, 0, 0, 4, 4, Kind::Half, false);
    let far = random_rgba(2, 200_000_000, 0, 4, 4, Kind::Half, false);
    write_image(
        &a,
        &near,
        compression("zip"),
        exr::prelude::LineOrder::Increasing,
    );
    write_image(
        &b,
        &far,
        compression("zip"),
        exr::prelude::LineOrder::Increasing,
    );
    let out_path = dir.path().join("out");
    std::fs::create_dir(&out_path).unwrap();
    let out = limited(&["over", s(&a), s(&b), "-o", s(&out_path.join("o.exr")), "-q"]);
    let message = stderr(&out);
    assert_eq!(out.status.code(), Some(3), "{message}");
    assert!(
        message.contains("a.exr") && message.contains("over the"),
        "{message}"
    );
    assert_eq!(message.lines().count(), 1, "{message}");
    assert_eq!(
        std::fs::read_dir(&out_path).unwrap().count(),
        0,
        "nothing left"
    );
}
