//! Hostile input: real files truncated at many offsets (before or while they
//! are read), with single bytes of their headers and offset tables changed, or
//! with sizes that would make us allocate far more than the file holds. Every
//! case ends within a bounded time, under a memory limit, with success or a
//! one-line error naming the file: never a panic, an abort, a signal or a hang.

mod common;
use common::*;
use exrcomp::io::reader::ExrFile;
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

/// The sources that are here: the last two are shipped, the others only in
/// the shared set.
fn sources() -> Vec<(String, Vec<u8>)> {
    [
        "ScanLines/Desk.exr",
        "Beachball/singlepart.0001.exr",
        "TestImages/WideFloatRange.exr",
        "DisplayWindow/t01.exr",
    ]
    .iter()
    .filter_map(|name| {
        Some((
            name.replace('/', "_"),
            std::fs::read(public_image(name)?).unwrap(),
        ))
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
    // Inputs the fuzzer (fuzz/) once broke exrcomp with, kept as regressions.
    let folder = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fuzz-regressions");
    let Ok(entries) = std::fs::read_dir(&folder) else {
        return;
    };
    for entry in entries {
        check(&entry.unwrap().path(), false);
    }
}

#[test]
fn a_chunk_claiming_more_bytes_than_the_file_holds_is_refused_before_reading() {
    let Some(path) = public_image("DisplayWindow/t01.exr") else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let bytes = std::fs::read(path).unwrap();
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
fn an_input_cut_short_while_it_is_read_is_an_input_error() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("plate.exr");
    generate(&path, "bg", (512, 256), &["--compression", "zip"]);
    let file = ExrFile::open(&path, Some(7)).unwrap();
    let count = file.header(0).chunk_count;
    // Another process rewrites the file after we opened it.
    let len = std::fs::metadata(&path).unwrap().len();
    let cut = std::fs::OpenOptions::new().write(true).open(&path).unwrap();
    cut.set_len(len / 4).unwrap();
    let named = |e: exrcomp::error::Error| {
        assert_eq!(e.kind, exrcomp::error::Kind::Input, "{e}");
        assert!(e.message.contains("plate.exr (frame 7)"), "{e}");
    };
    for k in count / 2..count {
        named(file.decode_chunk(0, k).unwrap_err());
        named(file.checked_zip_chunk(0, k).unwrap_err());
        named(file.unpack_zip_chunk(0, k, |_| ()).unwrap_err());
        named(file.read_chunk(0, k).unwrap_err());
    }
    named(file.check_part(0).unwrap_err());
}

/// A small ZIP file whose data window claims `width` columns: its chunks
/// hold a few kilobytes but would decompress to hundreds of megabytes.
fn far_too_wide(path: &Path, width: i32) {
    generate(path, "bg", (128, 256), &["--compression", "zip"]);
    let mut bytes = std::fs::read(path).unwrap();
    let key = b"dataWindow\0box2i\0";
    let at = bytes.windows(key.len()).position(|w| w == key).unwrap() + key.len() + 4;
    let x0 = i32::from_le_bytes(bytes[at..at + 4].try_into().unwrap());
    bytes[at + 8..at + 12].copy_from_slice(&(x0 + width - 1).to_le_bytes());
    std::fs::write(path, bytes).unwrap();
}

#[test]
fn a_data_window_wider_than_the_file_could_hold_is_refused_at_any_thread_count() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let bad = d.join("wide.exr");
    far_too_wide(&bad, 1 << 21);
    let good = d.join("good.exr");
    generate(&good, "bg", (128, 256), &["--compression", "zip"]);
    let out = d.join("out.exr");
    for threads in ["2", "8"] {
        for args in [
            vec!["transcode", s(&bad)],
            vec!["over", s(&bad), s(&good)],
            vec!["over", s(&good), s(&bad)],
        ] {
            let mut args = args.clone();
            args.extend(["-o", s(&out), "--threads", threads, "-q"]);
            // Under the 4 GiB limit: blocks sized from the window would not fit.
            let result = limited(&args);
            let message = stderr(&result);
            assert_eq!(result.status.code(), Some(3), "{args:?}: {message}");
            assert!(message.contains("wide.exr"), "{message}");
            assert_eq!(message.lines().count(), 1, "{message}");
            assert!(!out.exists());
            assert_eq!(
                std::fs::read_dir(d).unwrap().count(),
                2,
                "no temporary left"
            );
        }
    }
}

#[test]
fn a_chunk_too_small_for_its_block_is_refused_before_it_is_inflated() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("small-chunk.exr");
    // ZIP blocks of 16 lines x 128 pixels x 12 bytes: 24576 bytes, more
    // than deflate can make of the 8 bytes chunk 0 is then said to hold.
    generate(&path, "bg", (128, 64), &["--compression", "zip"]);
    let mut bytes = std::fs::read(&path).unwrap();
    let (_, first) = offset_table(&bytes);
    bytes[first + 4..first + 8].copy_from_slice(&8i32.to_le_bytes());
    std::fs::write(&path, &bytes).unwrap();
    let out = limited(&["info", s(&path)]);
    let message = stderr(&out);
    assert_eq!(out.status.code(), Some(3), "{message}");
    assert!(
        message.contains("small-chunk.exr: chunk 0")
            && message.contains("8 bytes cannot hold the block's 24576 bytes"),
        "{message}"
    );
}

#[test]
fn inputs_so_far_apart_that_the_result_could_not_be_read_back_are_refused() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let near = d.join("near.exr");
    let far = d.join("far.exr");
    generate(&near, "bg", (128, 64), &["--compression", "zip"]);
    generate(
        &far,
        "bg",
        (128, 64),
        &["--compression", "zip", "--origin", "3000000,0"],
    );
    let out = d.join("out.exr");
    // 3 million columns x 16 lines x 12 bytes: blocks over the 512 MiB limit.
    let result = limited(&["over", s(&near), s(&far), "-o", s(&out), "--threads", "8"]);
    let message = stderr(&result);
    assert_eq!(result.status.code(), Some(3), "{message}");
    assert!(
        message.contains("near.exr, ") && message.contains("far.exr): the result's data window"),
        "{message}"
    );
    assert!(!out.exists());
}
