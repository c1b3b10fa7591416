//! Feeds arbitrary bytes to exrcomp's EXR reader as a file.
//!
//! `ExrFile::open` takes a path (it memory-maps the file), so each input is
//! written to a per-process temporary file first. Errors are expected and
//! ignored; only panics, aborts, timeouts and OOMs are bugs. Panics that
//! exrcomp itself catches around the exr crate (src/guard.rs) become errors,
//! as they would in the real program.
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
        dir.join(format!("exrcomp-fuzz-{}.exr", std::process::id()))
    })
}

fuzz_target!(|data: &[u8]| {
    let path = scratch();
    std::fs::write(path, data).expect("write scratch file");

    // Open (header + offset tables), then decode every chunk of every part.
    if let Ok(file) = ExrFile::open(path, None) {
        for part in 0..file.meta.headers.len() {
            let _ = file.check_part(part);
        }
    }
    // The `info` command: the same reading plus formatting.
    let _ = exrcomp::tools::info::describe(path);
});
