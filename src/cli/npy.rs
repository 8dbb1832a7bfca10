//! `.npy` outputs of the subcommands (`--pressure`, `--temperature`, heights).

use std::path::Path;

use anyhow::{bail, Context, Result};
use stressfield::io::output::write_atomic;

/// Refuses an output path that does not end in `.npy`.
pub(crate) fn npy_path(flag: &str, path: &Path) -> Result<()> {
    if path.extension().is_none_or(|e| e != "npy") {
        bail!(
            "{flag} writes a NumPy file: give a path ending in .npy, got {}",
            path.display()
        );
    }
    Ok(())
}

/// `array` as a NumPy .npy file at `path`, written atomically.
pub(crate) fn write_npy(path: &Path, array: &ndarray::Array2<f64>, what: &str) -> Result<()> {
    let mut bytes = Vec::new();
    ndarray_npy::WriteNpyExt::write_npy(array, &mut bytes)
        .with_context(|| format!("encoding the {what} as .npy"))?;
    write_atomic(path, &bytes)?;
    Ok(())
}
