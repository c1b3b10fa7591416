//! Hostile input: real files truncated at many offsets (before or while they
//! are read), with single bytes of their headers and offset tables changed, or
//! with sizes that would make us allocate far more than the file holds. Every
//! case ends within a bounded time, under a memory limit, with success or a
//! one-line error naming the file: never a panic, an abort, a signal or a hang.

use crate::common;
use crate::common::*;
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

/// Two tiny inputs a billion rows apart: a result whose offset table alone
/// would take half a gigabyte, gigabytes of nothing written, is refused at
/// once, nothing left in the output folder.
#[test]
fn inputs_so_far_apart_vertically_that_the_result_is_absurdly_tall_are_refused() {
    let dir = tempfile::tempdir().unwrap();
    let (a, b) = (dir.path().join("near.exr"), dir.path().join("far.exr"));
    let near = random_rgba(1, 0, 0, 8, 4, Kind::Half, false);
    let far = random_rgba(2, 0, 1_073_741_000, 8, 4, Kind::Half, false);
    for (path, img) in [(&a, &near), (&b, &far)] {
        write_image(
            path,
            img,
            compression("zip"),
            exr::prelude::LineOrder::Increasing,
        );
    }
    let out_path = dir.path().join("out");
    std::fs::create_dir(&out_path).unwrap();
    let out = limited(&["over", s(&b), s(&a), "-o", s(&out_path.join("o.exr")), "-q"]);
    assert_refused(&out, ["far.exr", "chunk limit"], &out_path);
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
    assert_refused(&out, ["a.exr", "over the"], &out_path);
}

/// EXR's ZIP predictor and byte split (the inverse of what readers undo),
/// then zlib.
fn zip_pack(raw: &[u8]) -> Vec<u8> {
    let mut split: Vec<u8> = Vec::with_capacity(raw.len());
    split.extend(raw.iter().step_by(2));
    split.extend(raw.iter().skip(1).step_by(2));
    let mut previous = 0u8;
    let predicted: Vec<u8> = split
        .iter()
        .enumerate()
        .map(|(i, &b)| {
            let d = if i == 0 {
                b
            } else {
                b.wrapping_sub(previous).wrapping_add(128)
            };
            previous = b;
            d
        })
        .collect();
    let mut compressor = libdeflater::Compressor::new(libdeflater::CompressionLvl::best());
    let mut out = vec![0; compressor.zlib_compress_bound(predicted.len())];
    let len = compressor.zlib_compress(&predicted, &mut out).unwrap();
    out.truncate(len);
    out
}

/// An EXR file from its attributes (name, type, value; sorted, as
/// written) and its chunks (each with its header), one part.
fn exr_file(deep: bool, attributes: &[(&str, &str, Vec<u8>)], chunks: &[Vec<u8>]) -> Vec<u8> {
    let mut file = vec![0x76, 0x2f, 0x31, 0x01];
    file.extend((2u32 | if deep { 0x800 } else { 0 }).to_le_bytes());
    common::put_attributes(&mut file, attributes);
    let mut offset = (file.len() + 8 * chunks.len()) as u64;
    for chunk in chunks {
        file.extend(offset.to_le_bytes());
        offset += chunk.len() as u64;
    }
    chunks.iter().for_each(|c| file.extend(c));
    file
}

/// The attributes of a scanline file with `channels` (name, pixel type:
/// 1 half, 2 float) and data window (x0, y0, x1, y1), ZIPS.
fn zips_attributes(
    channels: &[(&str, i32)],
    window: [i32; 4],
    deep: bool,
) -> Vec<(&'static str, &'static str, Vec<u8>)> {
    let mut list = Vec::new();
    for (name, kind) in channels {
        list.extend(name.as_bytes());
        list.push(0);
        list.extend(kind.to_le_bytes());
        list.extend([0, 0, 0, 0]);
        list.extend(1i32.to_le_bytes());
        list.extend(1i32.to_le_bytes());
    }
    list.push(0);
    let window: Vec<u8> = window.iter().flat_map(|v| v.to_le_bytes()).collect();
    let mut attributes = vec![
        ("channels", "chlist", list),
        ("compression", "compression", vec![2]),
        ("dataWindow", "box2i", window.clone()),
        ("displayWindow", "box2i", window),
        ("lineOrder", "lineOrder", vec![0]),
        ("pixelAspectRatio", "float", 1f32.to_le_bytes().to_vec()),
        ("screenWindowCenter", "v2f", vec![0; 8]),
        ("screenWindowWidth", "float", 1f32.to_le_bytes().to_vec()),
    ];
    if deep {
        attributes.push(("type", "string", b"deepscanline".to_vec()));
        attributes.push(("version", "int", 1i32.to_le_bytes().to_vec()));
    }
    attributes
}

/// A one-line deep ZIPS file `width` pixels wide (channels A half, Z float)
/// whose last pixel holds `samples` samples, all zero: a few hundred
/// kilobytes of zlib for hundreds of megabytes of samples.
fn crowded_deep_file(width: usize, samples: usize) -> Vec<u8> {
    let attributes = zips_attributes(&[("A", 1), ("Z", 2)], [0, 0, width as i32 - 1, 0], true);
    let mut counts = vec![0u8; 4 * width];
    counts[4 * (width - 1)..].copy_from_slice(&(samples as i32).to_le_bytes());
    let table = zip_pack(&counts);
    let data = zip_pack(&vec![0; samples * 6]);
    let mut chunk = 0i32.to_le_bytes().to_vec();
    for size in [table.len(), data.len(), samples * 6] {
        chunk.extend((size as u64).to_le_bytes());
    }
    chunk.extend(table);
    chunk.extend(data);
    exr_file(true, &attributes, &[chunk])
}

#[test]
fn a_deep_pixel_of_millions_of_samples_is_refused_before_flattening() {
    // 350 KB unpacking to 360 MB of samples in one pixel: decoded to f32 and
    // sorted, it took over 4 GiB.
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("crowded.exr");
    std::fs::write(&path, crowded_deep_file(65536, 60_000_000)).unwrap();
    // The file itself is well-formed: `info` accepts it.
    let out = limited(&["info", s(&path)]);
    assert!(out.status.success(), "{}", stderr(&out));
    let folder = dir.path().join("out");
    std::fs::create_dir(&folder).unwrap();
    let out = limited(&[
        "flatten",
        s(&path),
        "-o",
        s(&folder.join("flat.exr")),
        "-q",
        "--threads",
        "8",
    ]);
    assert_refused(&out, ["crowded.exr", "deep chunk 0"], &folder);
}

#[test]
fn an_input_far_wider_than_the_result_is_refused_before_decoding() {
    // 4 MB of ZIPS, 8 million transparent pixels wide, 64 rows, to the left
    // of a 64x64 plate: `stencil` keeps the plate's window, and a strip of
    // the input's chunks, decoded across its own width, took over 4 GiB.
    let dir = tempfile::tempdir().unwrap();
    let (wide, plate) = (dir.path().join("wide.exr"), dir.path().join("plate.exr"));
    let width = 8_000_000;
    let window = [32 - width as i32, 0, 31, 63];
    let channels = [("A", 1), ("B", 1), ("G", 1), ("R", 1)];
    let data = zip_pack(&vec![0; width * 8]);
    let chunks: Vec<Vec<u8>> = (0..64i32)
        .map(|y| {
            let mut chunk = y.to_le_bytes().to_vec();
            chunk.extend((data.len() as i32).to_le_bytes());
            chunk.extend(&data);
            chunk
        })
        .collect();
    std::fs::write(
        &wide,
        exr_file(false, &zips_attributes(&channels, window, false), &chunks),
    )
    .unwrap();
    generate(&plate, "bg", (64, 64), &[]);
    let folder = dir.path().join("out");
    std::fs::create_dir(&folder).unwrap();
    let out = limited(&[
        "merge",
        "--op",
        "stencil",
        s(&wide),
        s(&plate),
        "-o",
        s(&folder.join("o.exr")),
        "-q",
        "--threads",
        "8",
    ]);
    assert_refused(&out, ["wide.exr", "over the"], &folder);
}

/// A one-line input error (exit 3) holding `words`, and nothing left in
/// `folder`, the output's.
fn assert_refused(out: &std::process::Output, words: [&str; 2], folder: &Path) {
    let message = stderr(out);
    assert_eq!(out.status.code(), Some(3), "{message}");
    assert!(words.iter().all(|w| message.contains(w)), "{message}");
    assert_eq!(message.lines().count(), 1, "{message}");
    assert_eq!(
        std::fs::read_dir(folder).unwrap().count(),
        0,
        "nothing left"
    );
}

/// What is not a regular file (a FIFO, a character device, a directory) is
/// refused at once, as an input or as one frame of a sequence, whatever the
/// command: never opened for a read that would wait for a writer or never
/// end.
#[test]
fn inputs_that_are_not_regular_files_are_refused_without_blocking() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let fifo = d.join("fifo.exr");
    let made = std::process::Command::new("mkfifo").arg(&fifo).status();
    assert!(made.is_ok_and(|s| s.success()), "mkfifo");
    write_sequence(d, "a", [1, 3], 7);
    let frame = d.join("a.0002.exr");
    std::process::Command::new("mkfifo")
        .arg(&frame)
        .status()
        .unwrap();
    std::fs::create_dir(d.join("dir.exr")).unwrap();
    let paths = ["o.exr", "a.####.exr", "o.####.exr", "dir.exr"].map(|p| d.join(p));
    let [out, seq, outs, dir_exr] = [0, 1, 2, 3].map(|i| s(&paths[i]));
    let f = s(&fifo);
    let cases: [(&[&str], String); 6] = [
        (
            &["transcode", f, "-o", out],
            format!("{f}: cannot open: not a regular file (a FIFO)"),
        ),
        (
            &["transcode", f, "-o", out, "--dry-run"],
            format!("{f}: cannot open: not a regular file (a FIFO)"),
        ),
        (
            &["info", f],
            format!("{f}: cannot open: not a regular file (a FIFO)"),
        ),
        (
            &["info", "/dev/zero"],
            "/dev/zero: cannot open: not a regular file (a character device)".into(),
        ),
        (
            &["info", dir_exr],
            format!("{dir_exr}: cannot open: not a regular file (a directory)"),
        ),
        (
            &["transcode", seq, "-o", outs],
            "a.0002.exr (frame 2): cannot open: not a regular file (a FIFO)".into(),
        ),
    ];
    for (args, message) in cases {
        let ended = limited_within(args, Duration::from_secs(20));
        assert!(!ended.timed_out, "{args:?} blocked");
        assert_eq!(ended.code, Some(3), "{args:?}: {}", ended.stderr);
        assert_eq!(
            ended.stderr.lines().count(),
            1,
            "{args:?}: {}",
            ended.stderr
        );
        assert!(
            ended.stderr.contains(&message),
            "{args:?}: {}",
            ended.stderr
        );
    }
    // The sequence's good frames are written; nothing is at the FIFO frame's output.
    assert!(!d.join("o.exr").exists() && !d.join("o.0002.exr").exists());
}
