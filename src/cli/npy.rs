//! `.npy` outputs of the subcommands (`--pressure`, `--temperature`, heights), and the output
//! policy they share with figures: a path's extension is read in any case, and a device or
//! FIFO (`/dev/null`, a named pipe) is written through whatever its name
//! ([`stressfield::io::output::target`]).

use std::path::Path;

use anyhow::{bail, Context, Result};
use stressfield::io::output::{target, Staged, Target};

/// Whether `path` ends in `.extension`, in any case (`F.PNG` is a PNG).
pub(crate) fn has_extension(path: &Path, extension: &str) -> bool {
    path.extension()
        .and_then(|e| e.to_str())
        .is_some_and(|e| e.eq_ignore_ascii_case(extension))
}

/// Whether `path` is written through (a character device or a FIFO): its name says nothing of
/// its format.
pub(crate) fn is_device(path: &Path) -> bool {
    matches!(target(path), Ok(Target::Through(_)))
}

/// Refuses an output path that does not end in `.npy` (any case), unless it is a device or a
/// FIFO, which is written through.
pub(crate) fn npy_path(flag: &str, path: &Path) -> Result<()> {
    if !has_extension(path, "npy") && !is_device(path) {
        bail!(
            "{flag} writes a NumPy file: give a path ending in .npy, got {}",
            path.display()
        );
    }
    Ok(())
}

/// `array` as the bytes of a NumPy .npy file.
pub(crate) fn npy_bytes(array: &ndarray::Array2<f64>, what: &str) -> Result<Vec<u8>> {
    let mut bytes = Vec::new();
    ndarray_npy::WriteNpyExt::write_npy(array, &mut bytes)
        .with_context(|| format!("encoding the {what} as .npy"))?;
    Ok(bytes)
}

/// An output of a command reserved before anything is computed (its directory exists and
/// takes a file, or it is a device), filled afterwards and moved into place with the
/// command's other outputs by [`Staged::commit`]: all or none.
pub(crate) struct Reserved<'a> {
    /// The path as given.
    pub(crate) path: &'a Path,
    /// The temporary file prepared for it.
    file: std::path::PathBuf,
}

impl<'a> Reserved<'a> {
    /// Reserves `path` in `staged`.
    pub(crate) fn new(staged: &mut Staged, path: &'a Path) -> Result<Self> {
        let file = staged.reserve(path)?;
        Ok(Self { path, file })
    }

    /// Writes `bytes` into the reserved file.
    pub(crate) fn fill(&self, bytes: &[u8]) -> Result<()> {
        std::fs::write(&self.file, bytes)
            .with_context(|| format!("cannot write {}", self.path.display()))
    }
}

/// `array` as a NumPy .npy file at `path`, written atomically (or through a device).
pub(crate) fn write_npy(path: &Path, array: &ndarray::Array2<f64>, what: &str) -> Result<()> {
    stressfield::io::output::write_atomic(path, &npy_bytes(array, what)?)?;
    Ok(())
}
