//! Feeds arbitrary bytes to exrcomp's DPX, Cineon, PNG, TIFF and JPEG readers as a file.
//!
//! The input's first byte picks a magic number (DPX big- or little-endian,
//! Cineon big- or little-endian, PNG, TIFF either way, JPEG), which replaces its first four bytes, so
//! that every input reaches a foreign reader's header checks rather than
//! the EXR reader's. As `read_exr`: the file is opened with
//! `ExrFile::open`, every row decoded (`check_part`), then `info` runs on
//! it; errors are expected, panics, aborts, timeouts and OOMs are bugs.
#![no_main]

use exrcomp::io::reader::ExrFile;
use libfuzzer_sys::fuzz_target;
use std::path::PathBuf;
use std::sync::OnceLock;

/// One scratch file per fuzzing process (libFuzzer may run several jobs).
fn scratch() -> &'static PathBuf {
    static PATH: OnceLock<PathBuf> = OnceLock::new();
    PATH.get_or_init(|| {
        let shm = std::path::Path::new("/dev/shm");
        let dir = if shm.is_dir() { shm.to_path_buf() } else { std::env::temp_dir() };
        dir.join(format!("exrcomp-fuzz-foreign-{}", std::process::id()))
    })
}

const MAGIC: [[u8; 4]; 9] = [
    *b"SDPX",
    *b"XPDS",
    [0x80, 0x2a, 0x5f, 0xd7],
    [0xd7, 0x5f, 0x2a, 0x80],
    [0x89, b'P', b'N', b'G'],
    [b'I', b'I', 42, 0],
    [b'M', b'M', 0, 42],
    [0xff, 0xd8, 0xff, 0xe0],
    [0xff, 0xd8, 0xff, 0xdb],
];

fuzz_target!(|data: &[u8]| {
    let mut bytes = data.to_vec();
    if bytes.len() >= 4 {
        // A seed keeps its own magic when it has one.
        if !MAGIC.contains(&bytes[..4].try_into().expect("4 bytes")) {
            let magic = MAGIC[bytes[0] as usize % MAGIC.len()];
            bytes[..4].copy_from_slice(&magic);
        }
    }
    let path = scratch();
    std::fs::write(path, &bytes).expect("write scratch file");
    if let Ok(file) = ExrFile::open(path, None) {
        let _ = file.check_part(0);
    }
    let _ = exrcomp::tools::info::describe(path);
});
