//! A TIFF file's first image file directory (classic or BigTIFF, either
//! byte order): its tags, whose values are read from the file when asked,
//! each within the file's length.

use crate::io::positioned::read_at;
use std::collections::BTreeMap;
use std::fs::File;

/// Tags: where each value is and how it is stored.
pub struct Ifd {
    pub big_endian: bool,
    file: File,
    len: u64,
    entries: BTreeMap<u16, Entry>,
}

struct Entry {
    kind: u16,
    count: u64,
    /// The value's bytes when they fit in the entry, else its offset.
    inline: Option<Vec<u8>>,
    offset: u64,
}

/// Bytes one value of a TIFF field type takes (0: a type not read).
fn type_size(kind: u16) -> u64 {
    match kind {
        1 | 2 | 6 | 7 => 1,
        3 | 8 => 2,
        4 | 9 | 11 | 13 => 4,
        5 | 10 | 12 | 16 | 17 | 18 => 8,
        _ => 0,
    }
}

/// Most entries a directory may have (a real one has a few dozen).
const MOST_ENTRIES: u64 = 4096;

impl Ifd {
    /// The first directory of `file` (`len` bytes).
    pub fn first(file: &File, len: u64) -> Result<Ifd, String> {
        let head = read_at(file, 0, len.min(16) as usize)?;
        let big_endian = match head.get(..2) {
            Some(b"MM") => true,
            Some(b"II") => false,
            _ => return Err("not a readable TIFF: no byte order mark".into()),
        };
        let file = file
            .try_clone()
            .map_err(|e| format!("cannot read it again: {e}"))?;
        let mut ifd = Ifd {
            big_endian,
            file,
            len,
            entries: BTreeMap::new(),
        };
        let short = || "not a readable TIFF: its header is cut short".to_string();
        let (big, at) = match ifd.uint(head.get(2..4).ok_or_else(short)?) {
            42 => (false, ifd.uint(head.get(4..8).ok_or_else(short)?)),
            43 => (true, ifd.uint(head.get(8..16).ok_or_else(short)?)),
            v => return Err(format!("not a readable TIFF: version {v}")),
        };
        let (count_size, entry_size, inline_size) = if big { (8, 20, 8) } else { (2, 12, 4) };
        let unreadable = |e: String| format!("not a readable TIFF: its directory's {e}");
        let count = ifd.uint(&ifd.bytes(at, count_size).map_err(unreadable)?);
        if count == 0 || count > MOST_ENTRIES {
            return Err(format!(
                "not a readable TIFF: its directory has {count} entries"
            ));
        }
        let table = ifd
            .bytes(at + count_size, count * entry_size)
            .map_err(unreadable)?;
        for e in table.chunks_exact(entry_size as usize) {
            let (tag, kind) = (ifd.uint(&e[0..2]) as u16, ifd.uint(&e[2..4]) as u16);
            let (count, value) = match big {
                true => (ifd.uint(&e[4..12]), &e[12..20]),
                false => (ifd.uint(&e[4..8]), &e[8..12]),
            };
            let size = type_size(kind).saturating_mul(count);
            let entry = Entry {
                kind,
                count,
                inline: (size <= inline_size).then(|| value[..size as usize].to_vec()),
                offset: ifd.uint(value),
            };
            ifd.entries.entry(tag).or_insert(entry);
        }
        Ok(ifd)
    }

    /// An unsigned integer of 1, 2, 4 or 8 bytes in the file's byte order.
    pub fn uint(&self, b: &[u8]) -> u64 {
        let mut v = 0u64;
        for k in 0..b.len() {
            let byte = if self.big_endian {
                b[k]
            } else {
                b[b.len() - 1 - k]
            };
            v = v << 8 | byte as u64;
        }
        v
    }

    /// `size` bytes of the file from `at`, refused past its end.
    pub fn bytes(&self, at: u64, size: u64) -> Result<Vec<u8>, String> {
        if at.checked_add(size).is_none_or(|end| end > self.len) {
            return Err(format!(
                "bytes {at}..+{size} are past its end ({} bytes)",
                self.len
            ));
        }
        read_at(&self.file, at, size as usize)
    }

    /// Tag `tag`'s values as unsigned integers (an integer type's), `None`
    /// when the file does not have it.
    pub fn unsigned(&self, tag: u16) -> Result<Option<Vec<u64>>, String> {
        let Some(e) = self.entries.get(&tag) else {
            return Ok(None);
        };
        let size = match e.kind {
            1 | 3 | 4 | 13 | 16 | 18 => type_size(e.kind),
            kind => return Err(format!("its tag {tag} is of type {kind}, not an integer")),
        };
        let bytes = self.value(e).map_err(|m| format!("its tag {tag}: {m}"))?;
        Ok(Some(
            bytes
                .chunks_exact(size as usize)
                .map(|b| self.uint(b))
                .collect(),
        ))
    }

    /// Tag `tag`'s first value as an unsigned integer.
    pub fn first_unsigned(&self, tag: u16) -> Result<Option<u64>, String> {
        Ok(self.unsigned(tag)?.and_then(|v| v.first().copied()))
    }

    /// Tag `tag`'s text (an ASCII value, up to its first NUL).
    pub fn text(&self, tag: u16) -> Option<String> {
        let e = self.entries.get(&tag).filter(|e| e.kind == 2)?;
        let bytes = self.value(e).ok()?;
        let end = bytes.iter().position(|&b| b == 0).unwrap_or(bytes.len());
        Some(String::from_utf8_lossy(&bytes[..end]).into_owned())
    }

    /// Tag `tag`'s first value as a number (a rational's quotient).
    pub fn rational(&self, tag: u16) -> Option<f32> {
        let e = self.entries.get(&tag).filter(|e| e.kind == 5)?;
        let bytes = self.value(e).ok()?;
        let (n, d) = (self.uint(bytes.get(..4)?), self.uint(bytes.get(4..8)?));
        (d > 0).then(|| n as f32 / d as f32)
    }

    fn value(&self, e: &Entry) -> Result<Vec<u8>, String> {
        match &e.inline {
            Some(bytes) => Ok(bytes.clone()),
            None => self.bytes(e.offset, type_size(e.kind).saturating_mul(e.count)),
        }
    }
}
