//! Positioned reads (`pread`) of exactly the bytes asked, for every reader.

use std::fs::File;
use std::os::unix::fs::FileExt;

/// `len` bytes of `file` from byte `at`. Readers check their offsets against
/// the file's length when they open it, so a short read means that it
/// shrank since.
pub fn read_at(file: &File, at: u64, len: usize) -> Result<Vec<u8>, String> {
    let mut bytes = vec![0; len];
    file.read_exact_at(&mut bytes, at).map_err(|e| {
        let end = at + len as u64;
        match e.kind() {
            std::io::ErrorKind::UnexpectedEof => {
                format!("the file was cut short while it was read (bytes {at}..{end} are gone)")
            }
            _ => format!("cannot read bytes {at}..{end}: {e}"),
        }
    })?;
    Ok(bytes)
}
