//! Refuses a run whose output would replace one of its inputs, however the
//! two are spelt (`./b.exr`, an absolute path, `../dir/b.exr`, a symlinked
//! folder, a hard link): files are compared by identity, not by name.

use crate::error::{Error, Result};
use std::collections::HashMap;
use std::os::unix::fs::MetadataExt;
use std::path::{Path, PathBuf};

/// What a path refers to: an existing file by device and inode (following
/// links), or a file still to be created by its folder's canonical path.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
enum Identity {
    File(u64, u64),
    New(PathBuf),
}

fn identity(path: &Path) -> Identity {
    if let Ok(meta) = std::fs::metadata(path) {
        return Identity::File(meta.dev(), meta.ino());
    }
    let name = path.file_name().map(PathBuf::from).unwrap_or_default();
    let folder = match path.parent() {
        Some(dir) if !dir.as_os_str().is_empty() => dir,
        _ => Path::new("."),
    };
    // A folder that does not exist yet cannot hold an input.
    let folder = std::fs::canonicalize(folder).unwrap_or_else(|_| folder.to_path_buf());
    Identity::New(folder.join(name))
}

/// Errors (a usage error, exit 2) if any of `outputs` is the same file as
/// any of `inputs`, naming both; before any work starts.
pub fn refuse_overwriting(
    inputs: impl IntoIterator<Item = PathBuf>,
    outputs: impl IntoIterator<Item = (Option<i64>, PathBuf)>,
) -> Result<()> {
    refuse_replacing(inputs, ("the input", "an input"), outputs)
}

/// As `refuse_overwriting`, for files that are something else to the
/// command, `what` naming one (a farm job's frames, which its template must
/// not replace: `("the frame", "a frame the job writes")`).
pub fn refuse_replacing(
    files: impl IntoIterator<Item = PathBuf>,
    what: (&str, &str),
    outputs: impl IntoIterator<Item = (Option<i64>, PathBuf)>,
) -> Result<()> {
    let files = FileSet::new(files);
    for (frame, output) in outputs {
        if let Some(file) = files.get(&output) {
            let frame = frame.map_or(String::new(), |f| format!(" (frame {f})"));
            return Err(Error::usage(format!(
                "the output {}{frame} is {} {}: refusing to overwrite {}",
                output.display(),
                what.0,
                file.display(),
                what.1
            )));
        }
    }
    Ok(())
}

/// Files by identity: whether a path is one of them, however spelt.
pub struct FileSet(HashMap<Identity, PathBuf>);

impl FileSet {
    pub fn new(paths: impl IntoIterator<Item = PathBuf>) -> Self {
        FileSet(
            paths
                .into_iter()
                .map(|path| (identity(&path), path))
                .collect(),
        )
    }

    /// The file of the set that `path` is, as the set spells it.
    pub fn get(&self, path: &Path) -> Option<&PathBuf> {
        self.0.get(&identity(path))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn other_spellings_of_an_input_are_refused() {
        let dir = tempfile::tempdir().unwrap();
        let input = dir.path().join("b.exr");
        std::fs::write(&input, b"plate").unwrap();
        std::fs::create_dir(dir.path().join("sub")).unwrap();
        std::os::unix::fs::symlink(dir.path(), dir.path().join("self")).unwrap();
        std::fs::hard_link(&input, dir.path().join("hard.exr")).unwrap();
        let refused = |output: PathBuf| refuse_overwriting([input.clone()], [(None, output)]);
        for spelling in ["b.exr", "./b.exr", "sub/../b.exr", "self/b.exr", "hard.exr"] {
            let err = refused(dir.path().join(spelling)).unwrap_err();
            assert!(err.message.contains("refusing to overwrite"), "{spelling}");
            assert!(err.message.contains(&input.display().to_string()));
        }
        // An input given through a link is the file it names.
        let linked = dir.path().join("self/link.exr");
        std::os::unix::fs::symlink(&input, &linked).unwrap();
        assert!(refuse_overwriting([linked], [(Some(7), input.clone())]).is_err());
        // New files are compared by their folder's real path.
        let new = dir.path().join("new.exr");
        assert!(
            refuse_overwriting([new.clone()], [(None, dir.path().join("self/new.exr"))]).is_err()
        );
        assert!(refused(dir.path().join("c.exr")).is_ok());
        assert!(refused(dir.path().join("missing/b.exr")).is_ok());
    }
}
