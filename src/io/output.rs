//! Writing files atomically: into a temporary file in the target directory, then a rename, so
//! a reader never sees a half-written output and a failure leaves nothing behind.
//!
//! One policy for every output path (figures, field archives, reports, `--heights`,
//! `--pressure`, `--update`d references, recordings), decided by [`target`]:
//! - a new path or a regular file: written into a temporary file beside it, then renamed over
//!   it once complete;
//! - a symbolic link: followed; its target is treated by these rules and the link stays;
//! - a character device or a FIFO (`/dev/null`, `/dev/full`, a named pipe): written through,
//!   as a shell's `>` would, so that its errors ("No space left on device") are reported;
//! - a directory, a block device or a socket: refused.
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
#[error("cannot write {}: {}\nhint: check that its directory exists and is writable, or write elsewhere (--out-dir, --rrd, --report)", path.display(), without_temporary_path(error))]
pub struct OutputError {
    pub path: PathBuf,
    /// Why (shown in the message, not chained again below it).
    pub error: std::io::Error,
}

/// The text of `error` without the temporary file's path that `tempfile` appends (` at path
/// "dir/.stressfield-XXXX.part"`): the message names the user's path instead.
fn without_temporary_path(error: &std::io::Error) -> String {
    let text = error.to_string();
    match text.find(" at path ") {
        Some(at) if text[at..].contains(".stressfield-") => text[..at].to_string(),
        _ => text,
    }
}

/// How an output path is written (see the module doc).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Target {
    /// Into a temporary file in the same directory, then renamed to this path.
    Replace(PathBuf),
    /// Opened and written in place (a character device or a FIFO).
    Through(PathBuf),
}

/// Decides how `path` is written, or says why it cannot be (see the module doc).
pub fn target(path: &Path) -> Result<Target, String> {
    let metadata = match std::fs::symlink_metadata(path) {
        Ok(metadata) => metadata,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
            return Ok(Target::Replace(path.to_path_buf()))
        }
        Err(e) => return Err(e.to_string()),
    };
    let kind = metadata.file_type();
    if kind.is_symlink() {
        let linked = std::fs::canonicalize(path)
            .map_err(|e| format!("it is a symbolic link whose target cannot be reached ({e})"))?;
        return target(&linked);
    }
    if kind.is_file() {
        return Ok(Target::Replace(path.to_path_buf()));
    }
    if kind.is_dir() {
        return Err("it is a directory".into());
    }
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        if kind.is_char_device() || kind.is_fifo() {
            return Ok(Target::Through(path.to_path_buf()));
        }
        if kind.is_block_device() {
            return Err(
                "it is a block device (a disk): an output is never written onto one".into(),
            );
        }
        if kind.is_socket() {
            return Err("it is a socket".into());
        }
    }
    Err("it is not a regular file".into())
}

/// Writes `bytes` to `path`: atomically (temporary file in the same directory, then rename) or
/// through a device, as [`target`] decides.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> Result<(), OutputError> {
    let wrap = |error| OutputError {
        path: path.to_path_buf(),
        error,
    };
    match target(path).map_err(|m| wrap(std::io::Error::other(m)))? {
        Target::Replace(real) => {
            let mut temp = temp_beside(&real, ".part").map_err(wrap)?;
            let _pending = Pending::new(temp.path());
            temp.write_all(bytes).map_err(wrap)?;
            temp.as_file().sync_all().map_err(wrap)?;
            temp.persist(&real).map_err(|e| wrap(e.error))?;
        }
        Target::Through(device) => write_through(&device, bytes).map_err(wrap)?,
    }
    Ok(())
}

/// Writes `bytes` into a device or FIFO, as a shell's `>` would.
fn write_through(device: &Path, bytes: &[u8]) -> std::io::Result<()> {
    let mut file = std::fs::OpenOptions::new().write(true).open(device)?;
    file.write_all(bytes)?;
    file.flush()
}

/// The directory a file is written in (`.` for a bare file name).
fn parent_dir(path: &Path) -> &Path {
    match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    }
}

/// A new temporary file in the directory of `path`, readable by all once renamed.
/// Whether the directory `dir` takes a file: a temporary one is created in it and removed. A
/// command checks its output directories with this before it computes anything (issue 50: an
/// unwritable `--out-dir` was found only after the whole computation); permissions alone do
/// not tell (root writes anywhere the file system lets it, a read-only mount refuses all).
pub fn probe_directory(dir: &Path) -> std::io::Result<()> {
    tempfile::Builder::new()
        .prefix(".stressfield-probe-")
        .tempfile_in(dir)
        .map(drop)
}

fn temp_beside(path: &Path, suffix: &str) -> std::io::Result<tempfile::NamedTempFile> {
    let mut builder = tempfile::Builder::new();
    // A temporary file is private (0600); the output is an ordinary file, readable by all.
    #[cfg(unix)]
    builder.permissions(std::os::unix::fs::PermissionsExt::from_mode(0o644));
    builder
        .prefix(".stressfield-")
        .suffix(suffix)
        .tempfile_in(parent_dir(path))
}

/// The outputs of one unit of work (a scene's PNG, SVG, field archive and recording) written
/// all or none: each is prepared in a temporary file beside its target, and only
/// [`Staged::commit`] moves them into place. Dropped without a commit (an error, a panic), it
/// removes its temporary files and leaves the targets as they were.
///
/// Targets are decided by [`target`] when they are added: a link's target is replaced, and a
/// device or FIFO is written through before any file is moved into place (it cannot be put
/// back, so its failure must come while the files can still be left as they were).
#[derive(Default)]
pub struct Staged {
    /// (the path given, how it is written, the prepared file).
    files: Vec<(PathBuf, Target, tempfile::TempPath)>,
    /// The temporary files registered for removal on interruption.
    pending: Vec<Pending>,
}

impl Staged {
    pub fn new() -> Self {
        Self::default()
    }

    /// Prepares `bytes` for `path`.
    pub fn add(&mut self, path: &Path, bytes: &[u8]) -> Result<(), OutputError> {
        let reserved = self.reserve(path)?;
        std::fs::write(&reserved, bytes)
            .and_then(|()| std::fs::File::open(&reserved)?.sync_all())
            .map_err(|error| OutputError {
                path: path.to_path_buf(),
                error,
            })
    }

    /// Reserves a temporary file for `path` (beside it, or beside a link's target; for a
    /// device, in the system's temporary directory) for a writer that takes a path (it may
    /// write it, or replace it by renaming its own file over it); returns that temporary path,
    /// which [`Staged::commit`] then moves to (or writes into) the target.
    pub fn reserve(&mut self, path: &Path) -> Result<PathBuf, OutputError> {
        let wrap = |error| OutputError {
            path: path.to_path_buf(),
            error,
        };
        let target = target(path).map_err(|m| wrap(std::io::Error::other(m)))?;
        let beside = match &target {
            Target::Replace(real) => real.clone(),
            Target::Through(_) => std::env::temp_dir().join("device"),
        };
        let temp = temp_beside(&beside, ".part")
            .map_err(wrap)?
            .into_temp_path();
        let reserved = temp.to_path_buf();
        self.pending.push(Pending::new(&reserved));
        self.files.push((path.to_path_buf(), target, temp));
        Ok(reserved)
    }

    /// The targets as given, in the order they were added.
    pub fn targets(&self) -> impl Iterator<Item = &Path> {
        self.files.iter().map(|(path, _, _)| path.as_path())
    }

    /// Moves every prepared file to its target. Targets to replace must still be regular files
    /// or absent (a directory, link, device or pipe put there meanwhile is refused before
    /// anything moves). Devices and pipes are written first; then existing targets are renamed
    /// aside, and put back if any move fails, so a failure leaves every file target as it
    /// was; on success the old versions are deleted.
    pub fn commit(self) -> Result<(), OutputError> {
        for (path, target, _) in &self.files {
            let Target::Replace(real) = target else {
                continue;
            };
            match std::fs::symlink_metadata(real) {
                Ok(meta) if !meta.file_type().is_file() => {
                    return Err(OutputError {
                        path: path.clone(),
                        error: std::io::Error::other(
                            "it is not a regular file now (a directory, link, device or pipe was put there while the outputs were prepared)",
                        ),
                    })
                }
                Ok(_) => {}
                Err(e) if e.kind() == std::io::ErrorKind::NotFound => {}
                Err(error) => {
                    return Err(OutputError {
                        path: path.clone(),
                        error,
                    })
                }
            }
        }
        let mut replaced = Vec::new();
        let mut through = Vec::new();
        for (path, target, temp) in self.files {
            match target {
                Target::Replace(real) => replaced.push((path, real, temp)),
                Target::Through(device) => through.push((path, device, temp)),
            }
        }
        // Devices and pipes first: they cannot be put back, and their errors (a full device)
        // are the likely ones, so a failure there leaves every file target as it was (issue
        // 42, class 5).
        for (path, device, temp) in through {
            std::fs::read(&temp)
                .and_then(|bytes| write_through(&device, &bytes))
                .map_err(|error| OutputError { path, error })?;
        }
        // Old versions renamed aside: (target, where it is now).
        let mut aside: Vec<(PathBuf, tempfile::TempPath)> = Vec::new();
        let restore = |aside: Vec<(PathBuf, tempfile::TempPath)>| {
            for (target, old) in aside {
                // Best effort: the error being reported is the first one.
                let _ = std::fs::rename(&old, &target);
                // `old` no longer exists: nothing left to delete on drop.
                let _ = old.keep();
            }
        };
        for (_, target, _) in &replaced {
            if !target.exists() {
                continue;
            }
            let moved = temp_beside(target, ".old").and_then(|placeholder| {
                let placeholder = placeholder.into_temp_path();
                std::fs::rename(target, &placeholder)?;
                Ok(placeholder)
            });
            match moved {
                Ok(old) => aside.push((target.clone(), old)),
                Err(error) => {
                    restore(aside);
                    return Err(OutputError {
                        path: target.clone(),
                        error,
                    });
                }
            }
        }
        let mut placed: Vec<PathBuf> = Vec::new();
        for (path, target, temp) in replaced {
            if let Err(e) = temp.persist(&target) {
                // `e.path` (the temporary file) is deleted when `e` drops.
                for done in &placed {
                    let _ = std::fs::remove_file(done);
                }
                restore(aside);
                return Err(OutputError {
                    path,
                    error: e.error,
                });
            }
            placed.push(target);
        }
        // Dropping the old versions deletes them.
        drop(aside);
        Ok(())
    }
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

    fn names(dir: &Path) -> Vec<String> {
        let mut names: Vec<String> = std::fs::read_dir(dir)
            .expect("list")
            .map(|e| e.expect("entry").file_name().to_string_lossy().into_owned())
            .collect();
        names.sort();
        names
    }

    #[test]
    fn staged_files_appear_together_on_commit() {
        let dir = tempfile::tempdir().expect("temp dir");
        let (a, b) = (dir.path().join("a.png"), dir.path().join("b.svg"));
        std::fs::write(&a, b"old a").expect("write");
        let mut staged = Staged::new();
        staged.add(&a, b"new a").expect("stage a");
        staged.add(&b, b"new b").expect("stage b");
        // Nothing visible before the commit.
        assert_eq!(std::fs::read(&a).expect("read"), b"old a");
        assert!(!b.exists());
        staged.commit().expect("commit");
        assert_eq!(std::fs::read(&a).expect("read"), b"new a");
        assert_eq!(std::fs::read(&b).expect("read"), b"new b");
        assert_eq!(names(dir.path()), ["a.png", "b.svg"], "no temporary left");
    }

    #[test]
    fn staged_files_dropped_without_commit_leave_nothing() {
        let dir = tempfile::tempdir().expect("temp dir");
        let mut staged = Staged::new();
        staged.add(&dir.path().join("a.png"), b"a").expect("stage");
        let reserved = staged.reserve(&dir.path().join("r.rrd")).expect("reserve");
        assert!(reserved.exists());
        drop(staged);
        assert!(names(dir.path()).is_empty(), "{:?}", names(dir.path()));
    }

    #[test]
    fn a_target_that_is_a_directory_stops_the_commit_before_anything_moves() {
        let dir = tempfile::tempdir().expect("temp dir");
        let (a, b) = (dir.path().join("a.png"), dir.path().join("b.svg"));
        std::fs::write(&a, b"old a").expect("write");
        let mut staged = Staged::new();
        staged.add(&a, b"new a").expect("stage a");
        staged.add(&b, b"new b").expect("stage b");
        // A directory put where b goes while the outputs were prepared.
        std::fs::create_dir(&b).expect("mkdir");
        let error = staged.commit().expect_err("b is a directory");
        assert!(error.to_string().contains("b.svg"), "{error}");
        assert!(error.to_string().contains("not a regular file"), "{error}");
        assert_eq!(std::fs::read(&a).expect("read"), b"old a");
        assert_eq!(names(dir.path()), ["a.png", "b.svg"], "no temporary left");
        // Known from the start, it is refused when it is added.
        let error = Staged::new().add(&b, b"new b").expect_err("a directory");
        assert!(error.to_string().contains("it is a directory"), "{error}");
        assert!(write_atomic(&b, b"x")
            .expect_err("a directory")
            .to_string()
            .contains("it is a directory"));
    }

    /// Issue 24, class 13: every output follows one policy ([`target`]). A link is followed
    /// (its target replaced, the link kept), a character device is written through so that its
    /// error is reported (a link to /dev/full fails with "No space left on device" instead of
    /// succeeding by replacing the link), a directory is refused, by `write_atomic` and by
    /// `Staged` alike.
    #[cfg(unix)]
    #[test]
    fn links_and_devices_follow_one_policy() {
        let dir = tempfile::tempdir().expect("temp dir");
        let real = dir.path().join("real.csv");
        std::fs::write(&real, b"old").expect("write");
        let link = dir.path().join("link.csv");
        std::os::unix::fs::symlink(&real, &link).expect("symlink");
        let canonical = std::fs::canonicalize(&real).expect("canonical");
        assert_eq!(target(&link), Ok(Target::Replace(canonical)));
        write_atomic(&link, b"new").expect("through the link");
        assert!(std::fs::symlink_metadata(&link)
            .expect("link")
            .file_type()
            .is_symlink());
        assert_eq!(std::fs::read(&real).expect("read"), b"new");
        let mut staged = Staged::new();
        staged.add(&link, b"staged").expect("stage");
        staged.commit().expect("commit");
        assert!(std::fs::symlink_metadata(&link)
            .expect("link")
            .file_type()
            .is_symlink());
        assert_eq!(std::fs::read(&real).expect("read"), b"staged");
        assert_eq!(
            names(dir.path()),
            ["link.csv", "real.csv"],
            "no temporary left"
        );

        let dangling = dir.path().join("dangling.csv");
        std::os::unix::fs::symlink(dir.path().join("missing/x.csv"), &dangling).expect("symlink");
        assert!(target(&dangling)
            .expect_err("dangling")
            .contains("symbolic link"));

        let full = Path::new("/dev/full");
        if full.exists() {
            let to_full = dir.path().join("full.csv");
            std::os::unix::fs::symlink(full, &to_full).expect("symlink");
            assert_eq!(target(&to_full), Ok(Target::Through(full.to_path_buf())));
            let error = write_atomic(&to_full, b"x").expect_err("a full device");
            assert!(error.to_string().contains("No space left"), "{error}");
            let mut staged = Staged::new();
            staged.add(&to_full, b"x").expect("stage");
            let error = staged.commit().expect_err("a full device");
            assert!(error.to_string().contains("No space left"), "{error}");
            assert!(std::fs::symlink_metadata(&to_full)
                .expect("link")
                .file_type()
                .is_symlink());
        }
        let null = Path::new("/dev/null");
        if null.exists() {
            write_atomic(null, b"x").expect("written through");
            let mut staged = Staged::new();
            staged.add(null, b"x").expect("stage");
            staged.commit().expect("written through");
        }
    }

    #[test]
    fn a_move_that_fails_puts_every_old_version_back() {
        let dir = tempfile::tempdir().expect("temp dir");
        let (a, b, c) = (
            dir.path().join("a.png"),
            dir.path().join("b.rrd"),
            dir.path().join("c.npz"),
        );
        std::fs::write(&a, b"old a").expect("write");
        std::fs::write(&b, b"old b").expect("write");
        let mut staged = Staged::new();
        staged.add(&a, b"new a").expect("stage a");
        staged.add(&c, b"new c").expect("stage c");
        // A writer given the reserved path that replaces it, then a writer that lost its file:
        // the move of b fails after a and c were placed.
        let reserved = staged.reserve(&b).expect("reserve");
        std::fs::remove_file(&reserved).expect("remove");
        assert!(staged.commit().is_err());
        assert_eq!(std::fs::read(&a).expect("read"), b"old a");
        assert_eq!(std::fs::read(&b).expect("read"), b"old b");
        assert!(!c.exists(), "a new file is removed again");
        assert_eq!(names(dir.path()), ["a.png", "b.rrd"], "no temporary left");
        // A writer that renames its own file over the reserved path.
        let mut staged = Staged::new();
        let reserved = staged.reserve(&b).expect("reserve");
        let own = dir.path().join("writer.tmp");
        std::fs::write(&own, b"new b").expect("write");
        std::fs::rename(&own, &reserved).expect("rename");
        staged.commit().expect("commit");
        assert_eq!(std::fs::read(&b).expect("read"), b"new b");
        assert_eq!(names(dir.path()), ["a.png", "b.rrd"]);
    }

    #[test]
    fn staged_files_are_removed_on_interruption_until_committed() {
        let dir = tempfile::tempdir().expect("temp dir");
        let in_dir = |list: &[PathBuf]| {
            list.iter()
                .filter(|p| p.starts_with(dir.path()))
                .cloned()
                .collect::<Vec<_>>()
        };
        let mut staged = Staged::new();
        staged.add(&dir.path().join("a.png"), b"a").expect("stage");
        staged.reserve(&dir.path().join("b.rrd")).expect("reserve");
        // Both temporary files are registered: an interruption now would remove them.
        let registered = in_dir(&pending());
        assert_eq!(registered.len(), 2, "{registered:?}");
        assert!(registered.iter().all(|p| p.exists()));
        staged.commit().expect("commit");
        assert!(in_dir(&pending()).is_empty());
        assert_eq!(names(dir.path()), ["a.png", "b.rrd"]);
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
        // Issue 24, class 16: the message names the user's path, not the temporary one.
        let text = err.to_string();
        assert!(
            text.contains(&path.display().to_string()) && !text.contains(".part"),
            "{text}"
        );
        let mut staged = Staged::new();
        let text = staged
            .add(&path, b"x")
            .expect_err("no directory")
            .to_string();
        assert!(!text.contains(".part"), "{text}");
    }
}
