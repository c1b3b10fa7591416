//! Writes one EXR file from compressed chunks arriving in order, under a
//! temporary name that is renamed into place only once the file is complete.
//!
//! The header is written here, not by the exr crate: its attributes in one
//! fixed order (sorted by name, as OpenEXR writes them; the crate follows a
//! hash map's order, so the same job wrote different bytes from run to run),
//! and `keyCode` with all seven of its fields (the crate writes six, and
//! OpenEXR then refuses the file).

use super::overwrite::FileSet;
use super::reader::ExrFile;
use crate::error::{Error, Result};
use crate::stage_time::{self, Stage};
use crossbeam_channel::{bounded, Receiver, Sender};
use exr::block::chunk::Chunk;
use exr::block::chunk::CompressedBlock;
use exr::meta::attribute::{AttributeValue, BlockType, KeyCode};
use exr::meta::header::Header;
use exr::meta::{MetaData, Requirements};
use std::fs::{self, File};
use std::io::{BufWriter, Write};
use std::os::fd::AsRawFd;
use std::os::unix::fs::FileExt;
use std::path::{Path, PathBuf};
use std::sync::Mutex;

/// A compressed block and its index in the output's offset table.
pub struct IndexedChunk {
    pub index: usize,
    pub chunk: Chunk,
}

/// Where a file is written before it is complete: hidden, in the same folder
/// (so the final rename stays on one file system), and unique to this
/// writer across threads, processes, PID namespaces and hosts: the PID
/// (which `remove_stale_temporaries` reads), the host's name, and 64 random
/// bits (two containers' processes can share a PID and a host name).
pub fn temporary_path(path: &Path) -> PathBuf {
    let name = path
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    path.with_file_name(format!(
        ".{name}.exrcomp-{}-{}-{:016x}.tmp",
        std::process::id(),
        host_name(),
        random_u64()
    ))
}

/// This host's name, made safe for a file name ("host" when unknown).
fn host_name() -> String {
    let mut buffer = [0u8; 256];
    // SAFETY: the buffer is writable for its length; gethostname writes
    // at most that many bytes.
    let ok = unsafe { libc::gethostname(buffer.as_mut_ptr().cast(), buffer.len()) } == 0;
    let name: String = buffer
        .iter()
        .take_while(|&&b| ok && b != 0)
        .map(|&b| match b {
            b'a'..=b'z' | b'A'..=b'Z' | b'0'..=b'9' | b'.' | b'_' => b as char,
            _ => '_',
        })
        .take(64)
        .collect();
    match name.is_empty() {
        true => "host".into(),
        false => name,
    }
}

/// 64 bits from the kernel's random source; should it fail, the time in
/// nanoseconds and a count of this process's calls, which still differ
/// between writers here.
fn random_u64() -> u64 {
    static CALLS: std::sync::atomic::AtomicU64 = std::sync::atomic::AtomicU64::new(0);
    let mut bytes = [0u8; 8];
    // SAFETY: the buffer is writable for its length.
    let got = unsafe { libc::getrandom(bytes.as_mut_ptr().cast(), bytes.len(), 0) };
    if got == bytes.len() as isize {
        return u64::from_ne_bytes(bytes);
    }
    let nanos = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| d.as_nanos() as u64);
    let calls = CALLS.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    nanos ^ calls.rotate_left(48) ^ u64::from(std::process::id()).rotate_left(24)
}

/// Writes a small file whole (a farm job, a bench record, a PNG) under its
/// temporary name, renamed into place when complete, its folder created:
/// as frames are, an output path never holds a partial file.
pub fn write_whole(path: &Path, bytes: &[u8]) -> Result<()> {
    write_in_place(path, None, |file| {
        file.write_all(bytes)
            .map_err(|e| Error::output(path, None, format!("cannot write: {e}")))
    })
}

/// Creates the temporary file `path`, new (never another writer's, which
/// truncating would destroy), and holds an exclusive lock on it while it is
/// open, which tells every other exrcomp (another host's, over NFS, or
/// another PID namespace's, where the name's PID says nothing) that it is
/// being written. Another run's clean-up may remove the file between its
/// creation and the lock (it was unlocked then): the file locked must still
/// be the one at `path`, else it is made again under that name.
pub(crate) fn create_locked(path: &Path) -> std::io::Result<File> {
    use std::os::unix::fs::MetadataExt;
    loop {
        let file = fs::OpenOptions::new()
            .write(true)
            .create_new(true)
            .open(path)?;
        // Only a clean-up can hold it (the name is this writer's): for the
        // moment it takes to remove it, after which the check below sees it gone.
        file.lock()?;
        let locked = file.metadata()?;
        match fs::symlink_metadata(path) {
            Ok(now) if (now.dev(), now.ino()) == (locked.dev(), locked.ino()) => return Ok(file),
            Ok(_) => {
                return Err(std::io::Error::other(
                    "another writer took the temporary name",
                ))
            }
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => continue,
            Err(e) => return Err(e),
        }
    }
}

/// Removes temporary files in `dir` left by exrcomp runs that no longer exist
/// (killed with SIGKILL, or a machine that lost power): a file whose PID
/// runs no process here and whose lock (`create_locked`) nobody holds. A
/// file of a live writer, here or on another host, is left alone, and so
/// is any of the run's `inputs`, whatever its name.
pub fn remove_stale_temporaries(dir: &Path, inputs: &FileSet) {
    let dir = if dir.as_os_str().is_empty() {
        Path::new(".")
    } else {
        dir
    };
    let Ok(entries) = fs::read_dir(dir) else {
        return;
    };
    for entry in entries.flatten() {
        let name = entry.file_name().to_string_lossy().into_owned();
        let pid = name
            .strip_prefix('.')
            .and_then(|n| n.strip_suffix(".tmp"))
            .and_then(|n| n.rsplit_once(".exrcomp-"))
            .and_then(|(_, id)| id.split('-').next()?.parse::<u32>().ok());
        let Some(pid) = pid else {
            continue;
        };
        let path = entry.path();
        if Path::new(&format!("/proc/{pid}")).exists() || inputs.get(&path).is_some() {
            continue;
        }
        // Unlocked: its writer is gone (a lock is held until the rename).
        // Only a regular file (opening a FIFO of that name would block).
        if let Ok(file) = super::reader::open_regular(&path) {
            if file.try_lock().is_ok() {
                let _ = fs::remove_file(&path);
            }
        }
    }
}

/// The parts of a file to write: the parts `streamed` are those whose
/// chunks arrive through `next`, one part after the other in this order;
/// every other part is copied chunk for chunk, decoding nothing, from the
/// same part of `carried` (the input whose other parts the output keeps).
pub struct Parts<'a> {
    pub headers: Vec<Header>,
    pub streamed: Vec<usize>,
    pub carried: Option<&'a ExrFile>,
}

impl Parts<'_> {
    pub fn single(header: Header) -> Self {
        Parts {
            headers: vec![header],
            streamed: vec![0],
            carried: None,
        }
    }
}

/// Writes the headers of `parts`, then the chunks `next` yields (`Ok(None)`
/// ends them), then the carried parts' chunks. An error from `next` abandons
/// the file and is returned as is.
///
/// The chunks get their places in the file here, in order, and each batch
/// is written there by a task on the pool (`Batches`).
pub fn write_file(
    path: &Path,
    frame: Option<i64>,
    parts: Parts,
    mut next: impl FnMut() -> Result<Option<Vec<IndexedChunk>>>,
) -> Result<()> {
    let fail = |e: &dyn std::fmt::Display| Error::output(path, frame, e);
    place(path, frame, |file| {
        let headers = &parts.headers;
        let count = headers.len();
        let bytes = header_bytes(headers).map_err(|e| fail(&e))?;
        file.write_all_at(&bytes, 0).map_err(|e| fail(&e))?;
        // The offset tables, written once the chunks' places are known.
        let tables = bytes.len() as u64;
        let total: usize = headers.iter().map(|h| h.chunk_count).sum();
        let mut position = tables + total as u64 * 8;
        let mut offsets: Vec<Vec<u64>> = headers
            .iter()
            .map(|h| Vec::with_capacity(h.chunk_count))
            .collect();
        let batches = Batches::new(file, count);
        rayon::in_place_scope(|scope| {
            let streamed = &parts.streamed;
            // The streamed part being written: the first not yet complete.
            let mut current = 0;
            while let Some(chunks) = next()? {
                let at = position;
                let mut batch = Vec::with_capacity(chunks.len());
                for mut c in chunks {
                    while streamed
                        .get(current)
                        .is_some_and(|&p| offsets[p].len() == headers[p].chunk_count)
                    {
                        current += 1;
                    }
                    let Some(&part) = streamed.get(current) else {
                        return Err(Error::internal("a chunk arrived after the last part's"));
                    };
                    let done = &mut offsets[part];
                    if c.index != done.len() {
                        return Err(Error::internal(format!(
                            "chunk {} of part {part} arrived where chunk {} was due",
                            c.index,
                            done.len()
                        )));
                    }
                    done.push(position);
                    c.chunk.layer_index = part;
                    position += chunk_size(&c.chunk, count);
                    batch.push(c.chunk);
                }
                batches.spawn(scope, batch, at).map_err(|e| fail(&e))?;
            }
            for &part in streamed {
                let chunk_count = headers[part].chunk_count;
                if offsets[part].len() != chunk_count {
                    return Err(Error::internal(format!(
                        "{} of part {part}'s {chunk_count} chunks were written",
                        offsets[part].len()
                    )));
                }
            }
            let Some(source) = parts.carried else {
                return Ok(());
            };
            let (mut at, mut batch) = (position, Vec::new());
            for (part, done) in offsets.iter_mut().enumerate() {
                if streamed.contains(&part) {
                    continue;
                }
                for index in 0..headers[part].chunk_count {
                    let mut chunk = source.read_chunk(part, index)?;
                    chunk.layer_index = part;
                    done.push(position);
                    position += chunk_size(&chunk, count);
                    batch.push(chunk);
                    if position - at >= CARRIED_BATCH {
                        let full = std::mem::take(&mut batch);
                        batches.spawn(scope, full, at).map_err(|e| fail(&e))?;
                        at = position;
                    }
                }
            }
            if !batch.is_empty() {
                batches.spawn(scope, batch, at).map_err(|e| fail(&e))?;
            }
            Ok(())
        })?;
        batches.check().map_err(|e| fail(&e))?;
        let table_bytes: Vec<u8> = offsets
            .iter()
            .flatten()
            .flat_map(|o| o.to_le_bytes())
            .collect();
        if table_bytes.len() != total * 8 {
            return Err(Error::internal("a carried part was not copied whole"));
        }
        file.write_all_at(&table_bytes, tables)
            .map_err(|e| fail(&e))
    })
}

/// Bytes of carried chunks gathered before a batch is written.
const CARRIED_BATCH: u64 = 4 << 20;

/// Batches of chunks waiting to be written; more wait on the writer thread.
pub const IN_FLIGHT: usize = 2;

/// Writes batches of placed chunks (`pwrite`) as tasks on the pool: the
/// kernel's copy into the page cache, the writer's largest cost, runs
/// beside the other stages' tasks instead of on one thread, and the writes
/// of frames in flight overlap. At most `IN_FLIGHT` batches wait, so memory
/// stays bounded by the channels'.
struct Batches<'f> {
    file: &'f File,
    /// Parts in the file: a multi-part file's chunks begin with their part.
    parts: usize,
    /// The first write that failed.
    failed: Mutex<Option<std::io::Error>>,
    slots: (Sender<()>, Receiver<()>),
}

impl<'f> Batches<'f> {
    fn new(file: &'f File, parts: usize) -> Self {
        Batches {
            file,
            parts,
            failed: Mutex::new(None),
            slots: bounded(IN_FLIGHT),
        }
    }

    /// Writes `batch`, placed from `at`, on the pool once a slot is free;
    /// an earlier batch's failure is returned instead.
    fn spawn<'s>(
        &'s self,
        scope: &rayon::Scope<'s>,
        batch: Vec<Chunk>,
        at: u64,
    ) -> std::io::Result<()> {
        self.check()?;
        stage_time::wait(Stage::Write, || self.slots.0.send(()))
            .map_err(|_| std::io::Error::other("the writer's slots closed"))?;
        scope.spawn(move |_| {
            let _slot = Slot(&self.slots.1);
            if let Err(e) = stage_time::task(Stage::Write, || self.write(&batch, at)) {
                self.lock().get_or_insert(e);
            }
        });
        Ok(())
    }

    fn write(&self, batch: &[Chunk], at: u64) -> std::io::Result<()> {
        let size: u64 = batch.iter().map(|c| chunk_size(c, self.parts)).sum();
        let mut bytes = Vec::with_capacity(size as usize);
        for chunk in batch {
            chunk
                .write(&mut bytes, self.parts)
                .map_err(std::io::Error::other)?;
        }
        if bytes.len() as u64 != size {
            return Err(std::io::Error::other("a chunk's size was miscounted"));
        }
        self.file.write_all_at(&bytes, at)?;
        // Starts the batch's write-back here, on the pool, so that the sync
        // before the rename finds little left to do on the writer thread.
        // Only a hint: the sync reports any error.
        // SAFETY: plain system call on an open descriptor.
        unsafe {
            libc::sync_file_range(
                self.file.as_raw_fd(),
                at as libc::off64_t,
                bytes.len() as libc::off64_t,
                libc::SYNC_FILE_RANGE_WRITE,
            )
        };
        Ok(())
    }

    fn lock(&self) -> std::sync::MutexGuard<'_, Option<std::io::Error>> {
        self.failed.lock().unwrap_or_else(|e| e.into_inner())
    }

    /// The first failure so far (all of them, once the scope has ended).
    fn check(&self) -> std::io::Result<()> {
        match self.lock().take() {
            Some(e) => Err(e),
            None => Ok(()),
        }
    }
}

/// A batch's slot, freed when its task ends, even by a panic (which reaches
/// the writer once the scope ends): a slot lost would stall the writer.
struct Slot<'a>(&'a Receiver<()>);

impl Drop for Slot<'_> {
    fn drop(&mut self) {
        let _ = self.0.recv();
    }
}

/// The bytes `chunk` takes in a file of `parts` parts.
fn chunk_size(chunk: &Chunk, parts: usize) -> u64 {
    let part = if parts > 1 { 4 } else { 0 };
    let block = match &chunk.compressed_block {
        CompressedBlock::ScanLine(b) => 8 + b.compressed_pixels_le.len(),
        CompressedBlock::Tile(b) => 20 + b.compressed_pixels_le.len(),
        CompressedBlock::DeepScanLine(b) => {
            28 + b.compressed_pixel_offset_table.len() + b.compressed_sample_data_le.len()
        }
        CompressedBlock::DeepTile(b) => {
            40 + b.compressed_pixel_offset_table.len() + b.compressed_sample_data_le.len()
        }
    };
    (part + block) as u64
}

/// Creates `path`'s folder, runs `write` on a buffered file at
/// `path`'s temporary name, then flushes it, syncs it to disk and renames
/// it into place; on any error the temporary file is removed and the
/// error returned as it is.
pub fn write_in_place(
    path: &Path,
    frame: Option<i64>,
    write: impl FnOnce(&mut BufWriter<&File>) -> Result<()>,
) -> Result<()> {
    place(path, frame, |file| {
        let mut buffered = BufWriter::with_capacity(1 << 20, file);
        write(&mut buffered)?;
        buffered.flush().map_err(|e| Error::output(path, frame, e))
    })
}

/// Creates `path`'s folder, runs `write` on the file at `path`'s
/// temporary name, then syncs it to disk and renames it into place; on any
/// error, or a panic, the temporary file is removed (and the error returned
/// as it is).
fn place(path: &Path, frame: Option<i64>, write: impl FnOnce(&File) -> Result<()>) -> Result<()> {
    let fail = |e: &dyn std::fmt::Display| Error::output(path, frame, e);
    if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
        fs::create_dir_all(dir).map_err(|e| fail(&format!("cannot create folder: {e}")))?;
    }
    let mut temporary = Temporary {
        path: temporary_path(path),
        placed: false,
    };
    let file = create_locked(&temporary.path).map_err(|e| fail(&format!("cannot create: {e}")))?;
    write(&file)?;
    file.sync_all().map_err(|e| fail(&e))?;
    fs::rename(&temporary.path, path)
        .map_err(|e| fail(&format!("cannot rename into place: {e}")))?;
    temporary.placed = true;
    Ok(())
}

/// A temporary file, removed when dropped before it is renamed into place
/// (on an error, or a panic, while it is written).
struct Temporary {
    path: PathBuf,
    placed: bool,
}

impl Drop for Temporary {
    fn drop(&mut self) {
        if !self.placed {
            let _ = fs::remove_file(&self.path);
        }
    }
}

/// The magic number, version and flags, and each header's attributes
/// sorted by name; checked as the exr crate checks what it writes.
pub fn header_bytes(headers: &[Header]) -> exr::error::Result<Vec<u8>> {
    // The crate's validation refuses subsampled channels; their rules were
    // checked where they were read (`subsampling::restore`).
    let requirements = requirements(&super::subsampling::unsampled(headers))?;
    let mut bytes = exr::meta::magic_number::BYTES.to_vec();
    requirements.write(&mut bytes)?;
    for header in headers {
        let mut attributes: Vec<_> = header.all_named_attributes().collect();
        attributes.sort_by(|a, b| a.0.cmp(b.0));
        for (name, value) in &attributes {
            match value {
                AttributeValue::KeyCode(code) => write_key_code(name, code, &mut bytes),
                // The crate names a deep part's type as a flat one's.
                AttributeValue::BlockType(_) if header.deep => {
                    let deep = match header.blocks.has_tiles() {
                        true => BlockType::DeepTile,
                        false => BlockType::DeepScanLine,
                    };
                    exr::meta::attribute::write(name, &AttributeValue::BlockType(deep), &mut bytes)?
                }
                value => exr::meta::attribute::write(name, value, &mut bytes)?,
            }
        }
        bytes.push(0);
    }
    // A multi-part file's header list ends with an empty header.
    if requirements.has_multiple_layers {
        bytes.push(0);
    }
    Ok(bytes)
}

/// The version flags `headers` need, once checked. The crate's
/// `MetaData::validate` refuses deep parts outright; a file carrying one (a
/// deep part of the input, copied) gets the per-header checks, as the reader
/// gives such files, and the deep flag.
fn requirements(headers: &[Header]) -> exr::error::Result<Requirements> {
    if !headers.iter().any(|h| h.deep) {
        let mut requirements = MetaData::validate(headers, false)?;
        requirements.file_format_version = 2;
        return Ok(requirements);
    }
    let multipart = headers.len() > 1;
    let mut long_names = false;
    for header in headers {
        header.validate(multipart, &mut long_names, false)?;
    }
    Ok(Requirements {
        file_format_version: 2,
        is_single_layer_and_tiled: false,
        has_long_names: long_names,
        has_deep_data: true,
        has_multiple_layers: multipart,
    })
}

/// `keyCode` as OpenEXR lays it out: seven little-endian ints.
fn write_key_code(name: &[u8], code: &KeyCode, bytes: &mut Vec<u8>) {
    let fields = [
        code.film_manufacturer_code,
        code.film_type,
        code.film_roll_prefix,
        code.count,
        code.perforation_offset,
        code.perforations_per_frame,
        code.perforations_per_count,
    ];
    for text in [name, b"keycode"] {
        bytes.extend_from_slice(text);
        bytes.push(0);
    }
    bytes.extend_from_slice(&(fields.len() as i32 * 4).to_le_bytes());
    fields
        .iter()
        .for_each(|f| bytes.extend_from_slice(&f.to_le_bytes()));
}

#[cfg(test)]
mod tests {
    use super::*;
    use exr::block::chunk::CompressedScanLineBlock;
    use std::time::Duration;

    #[test]
    fn a_batch_whose_write_panics_frees_its_slot_and_the_panic_reaches_the_writer() {
        let (done, ended) = crossbeam_channel::bounded(1);
        std::thread::spawn(move || {
            let file = tempfile::tempfile().unwrap();
            let batches = Batches::new(&file, 1);
            // A second part's chunk in a one-part file: the crate asserts.
            let bad = || Chunk {
                layer_index: 1,
                compressed_block: CompressedBlock::ScanLine(CompressedScanLineBlock {
                    y_coordinate: 0,
                    compressed_pixels_le: vec![0; 8],
                }),
            };
            let caught = crate::guard::catch(|| {
                rayon::in_place_scope(|scope| {
                    for _ in 0..2 * IN_FLIGHT {
                        batches.spawn(scope, vec![bad()], 0).unwrap();
                    }
                })
            });
            let _ = done.send(caught.map_err(|p| p.message));
        });
        let caught = ended.recv_timeout(Duration::from_secs(20));
        let message = caught.expect("the writer stalled").unwrap_err();
        assert!(message.contains("invalid header index"), "{message}");
    }
}
