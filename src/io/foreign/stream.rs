//! A file read as a stream (`Read + Seek`) of positioned reads, for the
//! decoders of compressed formats that pull their bytes (PNG): it owns a
//! handle of its own, so that a decoder's state can outlive one call.

use std::fs::File;
use std::io::{Read, Seek, SeekFrom};
use std::os::unix::fs::FileExt;

/// `file` from byte `at` on; a stream never moves the handle's own offset.
pub struct Stream {
    file: File,
    at: u64,
}

impl Stream {
    /// A stream of `file` from its start, on a handle of its own.
    pub fn new(file: &File) -> Result<Stream, String> {
        let file = file
            .try_clone()
            .map_err(|e| format!("cannot read it again: {e}"))?;
        Ok(Stream { file, at: 0 })
    }
}

impl Read for Stream {
    fn read(&mut self, buf: &mut [u8]) -> std::io::Result<usize> {
        let n = self.file.read_at(buf, self.at)?;
        self.at += n as u64;
        Ok(n)
    }
}

impl Seek for Stream {
    fn seek(&mut self, to: SeekFrom) -> std::io::Result<u64> {
        let target = match to {
            SeekFrom::Start(at) => Some(at),
            SeekFrom::Current(by) => self.at.checked_add_signed(by),
            SeekFrom::End(by) => self.file.metadata()?.len().checked_add_signed(by),
        };
        self.at = target.ok_or_else(|| {
            std::io::Error::new(std::io::ErrorKind::InvalidInput, "seek before the start")
        })?;
        Ok(self.at)
    }
}
