//! Writes one EXR file from compressed chunks arriving in order, under a
//! temporary name that is renamed into place only once the file is complete.

use crate::engine::encode::IndexedChunk;
use crate::error::{Error, Result};
use exr::block::writer::ChunksWriter;
use exr::meta::header::Header;
use std::fs::{self, File};
use std::io::BufWriter;
use std::path::{Path, PathBuf};

/// Where a file is written before it is complete: hidden, in the same folder
/// (so the final rename stays on one file system), unique to this process.
pub fn temporary_path(path: &Path) -> PathBuf {
    let name = path
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    path.with_file_name(format!(".{name}.exrcomp-{}.tmp", std::process::id()))
}

/// Removes temporary files in `dir` left by exrcomp runs that no longer exist
/// (killed with SIGKILL, or a machine that lost power). A file of a process
/// that is still running, another exrcomp writing there, is left alone.
pub fn remove_stale_temporaries(dir: &Path) {
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
            .and_then(|(_, pid)| pid.parse::<u32>().ok());
        if let Some(pid) = pid {
            if !Path::new(&format!("/proc/{pid}")).exists() {
                let _ = fs::remove_file(entry.path());
            }
        }
    }
}

/// Writes `header` and then the chunks `next` yields (`Ok(None)` ends the
/// file). An error from `next` abandons the file and is returned as is.
pub fn write_file(
    path: &Path,
    frame: Option<i64>,
    header: Header,
    mut next: impl FnMut() -> Result<Option<Vec<IndexedChunk>>>,
) -> Result<()> {
    let fail = |e: &dyn std::fmt::Display| Error::output(path, frame, e);
    if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
        fs::create_dir_all(dir).map_err(|e| fail(&format!("cannot create folder: {e}")))?;
    }
    let temporary = temporary_path(path);
    let result = (|| {
        let file = File::create(&temporary).map_err(|e| fail(&format!("cannot create: {e}")))?;
        let mut out = BufWriter::with_capacity(1 << 20, file);
        let mut upstream: Option<Error> = None;
        let mut expected = 0;
        let written = exr::block::write(&mut out, smallvec(header), false, |_, writer| loop {
            match next() {
                Ok(Some(chunks)) => {
                    for c in chunks {
                        if c.index != expected {
                            upstream = Some(Error::internal(format!(
                                "chunk {} arrived where chunk {expected} was due",
                                c.index
                            )));
                            return Err(exr::error::Error::Aborted);
                        }
                        writer.write_chunk(c.index, c.chunk)?;
                        expected += 1;
                    }
                }
                Ok(None) => return Ok(()),
                Err(e) => {
                    upstream = Some(e);
                    return Err(exr::error::Error::Aborted);
                }
            }
        });
        if let Some(e) = upstream {
            return Err(e);
        }
        written.map_err(|e| fail(&e))?;
        let file = out.into_inner().map_err(|e| fail(&e.error()))?;
        file.sync_all().map_err(|e| fail(&e))?;
        fs::rename(&temporary, path).map_err(|e| fail(&format!("cannot rename into place: {e}")))
    })();
    if result.is_err() {
        let _ = fs::remove_file(&temporary);
    }
    result
}

fn smallvec(header: Header) -> exr::meta::Headers {
    let mut headers = exr::meta::Headers::new();
    headers.push(header);
    headers
}
