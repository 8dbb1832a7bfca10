//! Writing files atomically: into a temporary file in the target directory, then a rename, so
//! a reader never sees a half-written output and a failure leaves nothing behind.
//!
//! Temporary files are registered while they are written ([`Pending`]); the binary installs
//! [`remove_pending_on_interrupt`], so that an interruption (Ctrl-C, `kill`) removes them too
//! before the process ends.

use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::{Mutex, MutexGuard};

/// Temporary files being written: an interruption removes them.
static PENDING: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

fn pending() -> MutexGuard<'static, Vec<PathBuf>> {
    // A panic while the list was held leaves it usable: it is only a list of paths.
    PENDING
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner)
}

/// A temporary file registered for removal on interruption while this guard lives (drop it
/// once the file is renamed to its final name or removed).
#[derive(Debug)]
pub struct Pending {
    path: PathBuf,
}

impl Pending {
    pub fn new(path: &Path) -> Self {
        pending().push(path.to_path_buf());
        Self {
            path: path.to_path_buf(),
        }
    }
}

impl Drop for Pending {
    fn drop(&mut self) {
        let mut list = pending();
        if let Some(index) = list.iter().position(|p| *p == self.path) {
            list.swap_remove(index);
        }
    }
}

/// Removes every registered temporary file; returns those removed.
fn remove_pending(list: &[PathBuf]) -> Vec<PathBuf> {
    list.iter()
        .filter(|path| std::fs::remove_file(path).is_ok())
        .cloned()
        .collect()
}

/// Handles SIGINT, SIGTERM and SIGHUP: removes the registered temporary files, says so on
/// standard error and ends the process with status 128 + the signal's number (130 for
/// Ctrl-C), as a shell reports a process killed by it.
#[cfg(unix)]
pub fn remove_pending_on_interrupt() -> std::io::Result<()> {
    use signal_hook::consts::{SIGHUP, SIGINT, SIGTERM};
    let mut signals = signal_hook::iterator::Signals::new([SIGINT, SIGTERM, SIGHUP])?;
    std::thread::Builder::new()
        .name("interrupt".into())
        .spawn(move || {
            if let Some(signal) = signals.forever().next() {
                // Held until the process ends: no temporary file is renamed or added meanwhile.
                let list = pending();
                let removed = remove_pending(&list);
                let name = match signal {
                    SIGINT => "SIGINT",
                    SIGTERM => "SIGTERM",
                    _ => "SIGHUP",
                };
                if removed.is_empty() {
                    eprintln!("interrupted ({name})");
                } else {
                    let names: Vec<String> =
                        removed.iter().map(|p| p.display().to_string()).collect();
                    eprintln!(
                        "interrupted ({name}): removed the unfinished {}",
                        names.join(", ")
                    );
                }
                std::process::exit(128 + signal);
            }
        })?;
    Ok(())
}

/// Elsewhere interruptions end the process as they would (temporary files may be left).
#[cfg(not(unix))]
pub fn remove_pending_on_interrupt() -> std::io::Result<()> {
    Ok(())
}

/// An output that could not be written.
#[derive(Debug, thiserror::Error)]
#[error("cannot write {path}: {source}\nhint: check that the directory exists and is writable, or choose another with --out-dir")]
pub struct OutputError {
    pub path: PathBuf,
    #[source]
    pub source: std::io::Error,
}

/// Writes `bytes` to `path` atomically (temporary file in the same directory, then rename).
pub fn write_atomic(path: &Path, bytes: &[u8]) -> Result<(), OutputError> {
    let wrap = |source| OutputError {
        path: path.to_path_buf(),
        source,
    };
    let dir = match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    };
    let mut builder = tempfile::Builder::new();
    // A temporary file is private (0600); the output is an ordinary file, readable by all.
    #[cfg(unix)]
    builder.permissions(std::os::unix::fs::PermissionsExt::from_mode(0o644));
    let mut temp = builder
        .prefix(".stressfield-")
        .suffix(".part")
        .tempfile_in(dir)
        .map_err(wrap)?;
    let _pending = Pending::new(temp.path());
    temp.write_all(bytes).map_err(wrap)?;
    temp.as_file().sync_all().map_err(wrap)?;
    temp.persist(path).map_err(|e| wrap(e.error))?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn writes_and_replaces() {
        let dir = tempfile::tempdir().expect("temp dir");
        let path = dir.path().join("a.txt");
        write_atomic(&path, b"one").expect("write");
        write_atomic(&path, b"two").expect("rewrite");
        assert_eq!(std::fs::read(&path).expect("read"), b"two");
        #[cfg(unix)]
        {
            use std::os::unix::fs::PermissionsExt;
            let mode = std::fs::metadata(&path).expect("meta").permissions().mode();
            assert_eq!(
                mode & 0o044,
                0o044,
                "readable by group and others: {mode:o}"
            );
        }
        assert_eq!(
            std::fs::read_dir(dir.path()).expect("list").count(),
            1,
            "no temporary left"
        );
    }

    #[test]
    fn pending_files_are_listed_while_their_guard_lives() {
        let dir = tempfile::tempdir().expect("temp dir");
        let path = dir.path().join(".x.part");
        std::fs::write(&path, b"x").expect("write");
        {
            let _guard = Pending::new(&path);
            assert!(pending().contains(&path));
        }
        assert!(!pending().contains(&path));
        assert_eq!(
            remove_pending(std::slice::from_ref(&path)),
            vec![path.clone()]
        );
        assert!(!path.exists());
    }

    #[test]
    fn missing_directory_fails_without_leftovers() {
        let dir = tempfile::tempdir().expect("temp dir");
        let path = dir.path().join("missing").join("a.png");
        let err = write_atomic(&path, b"x").expect_err("no directory");
        assert!(err.to_string().contains("cannot write"), "{err}");
        assert_eq!(std::fs::read_dir(dir.path()).expect("list").count(), 0);
    }
}
