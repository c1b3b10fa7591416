//! A file read as a stream (`Read + Seek`) of positioned reads, for the
//! decoders of compressed formats that pull their bytes (PNG, JPEG): it owns
//! a handle of its own, so that a decoder's state can outlive one call; and
//! that state kept between calls (`InOrder`).

use std::fs::File;
use std::io::{Read, Seek, SeekFrom};
use std::ops::Range;
use std::os::unix::fs::FileExt;
use std::sync::Mutex;

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

/// A decoder that gives rows in order only (PNG, JPEG), kept between a
/// reader's calls at the row it is at; rows asked again start it over.
pub struct InOrder<D> {
    state: Mutex<(Option<D>, usize)>,
}

impl<D> InOrder<D> {
    /// Holding `decoder`, at row 0, if one is already started.
    pub fn new(decoder: Option<D>) -> Self {
        InOrder {
            state: Mutex::new((decoder, 0)),
        }
    }

    /// Rows `rows` of an image `height` rows tall, `row_bytes` each: `start`
    /// gives a decoder at row 0, `next` decodes its next row into the slice
    /// given (none: a row before `rows`, decoded and dropped). A failure
    /// drops the decoder: the next read starts over rather than continue a
    /// broken stream.
    pub fn read(
        &self,
        rows: Range<usize>,
        (height, row_bytes): (usize, usize),
        start: impl FnOnce() -> Result<D, String>,
        mut next: impl FnMut(&mut D, Option<&mut [u8]>) -> Result<(), String>,
    ) -> Result<Vec<u8>, String> {
        if rows.start >= rows.end || rows.end > height {
            return Err(format!("rows {rows:?} are outside the image"));
        }
        let mut state = self.state.lock().unwrap_or_else(|e| e.into_inner());
        let (decoder, at) = &mut *state;
        let decode = || {
            if decoder.is_none() || rows.start < *at {
                *decoder = None;
                *decoder = Some(start()?);
                *at = 0;
            }
            let d = decoder.as_mut().expect("a decoder");
            let mut out = vec![0u8; rows.len() * row_bytes];
            while *at < rows.end {
                let k = at.wrapping_sub(rows.start);
                next(
                    d,
                    (*at >= rows.start).then(|| &mut out[k * row_bytes..(k + 1) * row_bytes]),
                )?;
                *at += 1;
            }
            Ok(out)
        };
        let decoded = decode();
        if decoded.is_err() {
            *decoder = None;
        }
        decoded
    }
}
