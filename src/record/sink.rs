//! Where a recording goes: a file, standard output, or a Rerun viewer (started here, or one
//! already running), step by step as the steps are computed.
//!
//! A file is encoded here rather than by Rerun's own file sink, so that a failure names the
//! file and the system's reason ("No space left on device"), and so that it follows the policy
//! of every output ([`crate::io::output::target`]): a new path or a regular file is written
//! into a temporary file beside it (registered with [`crate::io::output::Pending`], so that an
//! interruption removes it) and renamed over it once complete; a link is followed; a character
//! device or a FIFO is written through; a directory, block device or socket is refused.

use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex, MutexGuard};

use rerun::external::re_log_encoding::{CrateVersion, EncodeError, Encoder, EncodingOptions};
use rerun::log::LogMsg;
use rerun::sink::{LogSink, SinkFlushError};
use rerun::RecordingStream;

use super::{RecordError, APPLICATION_ID};
use crate::io::output::{target, Pending, Target};

/// The address `--connect` uses when none is given: a viewer on this machine, default port.
pub const DEFAULT_VIEWER_URL: &str = rerun::DEFAULT_CONNECT_URL;

/// Where to send a recording.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Destination {
    /// A file (see the module doc for links, devices and FIFOs).
    File(PathBuf),
    /// Standard output (`-o -`), e.g. piped into `rerun -`.
    Stdout,
    /// A new viewer, started here (`rerun` must be on the PATH).
    Spawn,
    /// A running viewer at this gRPC address (e.g. [`DEFAULT_VIEWER_URL`]).
    Connect(String),
}

impl std::fmt::Display for Destination {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Destination::File(path) => write!(f, "{}", path.display()),
            Destination::Stdout => write!(f, "standard output"),
            Destination::Spawn => write!(f, "a new Rerun viewer"),
            Destination::Connect(url) => write!(f, "the Rerun viewer at {url}"),
        }
    }
}

/// The encoder of a file or standard output, and the first error it met.
struct Writer {
    encoder: Option<Encoder<Box<dyn Write + Send>>>,
    error: Option<std::io::Error>,
}

impl Writer {
    fn fail(&mut self, error: EncodeError) {
        if self.error.is_none() {
            self.error = Some(match error {
                EncodeError::Write(e) => e,
                other => std::io::Error::other(other.to_string()),
            });
        }
        // Nothing more is written after a failure.
        self.encoder = None;
    }
}

type SharedWriter = Arc<Mutex<Writer>>;

fn lock(writer: &SharedWriter) -> MutexGuard<'_, Writer> {
    writer
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner)
}

/// A Rerun log sink that encodes every message into a [`Writer`].
struct WriterSink(SharedWriter);

impl LogSink for WriterSink {
    fn send(&self, message: LogMsg) {
        let mut writer = lock(&self.0);
        if let Some(encoder) = writer.encoder.as_mut() {
            if let Err(e) = encoder.append(&message) {
                writer.fail(e);
            }
        }
    }

    fn flush_blocking(&self, _timeout: std::time::Duration) -> Result<(), SinkFlushError> {
        let mut writer = lock(&self.0);
        if let Some(encoder) = writer.encoder.as_mut() {
            if let Err(e) = encoder.flush_blocking() {
                writer.fail(e);
            }
        }
        match &writer.error {
            Some(e) => Err(SinkFlushError::failed(e.to_string())),
            None => Ok(()),
        }
    }
}

/// How an open recording is completed.
enum Completion {
    /// Rename the temporary file to `path`.
    Rename {
        temp: tempfile::TempPath,
        _pending: Pending,
        file: std::fs::File,
        path: PathBuf,
    },
    /// Written in place (a device, a FIFO).
    Through,
    Stdout,
    /// A viewer: nothing to complete.
    Viewer {
        url: String,
    },
}

/// Standard output, held back until the first [`Output::flush`]: the stream's opening (its
/// description and viewer layout, logged while the first step is prepared) then arrives in
/// one piece. The Rerun 0.36.3 viewer reading standard input (`rerun -`) stopped reading, and
/// so blocked this program, when the stream paused between its first message and its layout
/// (seen with pauses of a second or more; a pause after the layout did no harm).
struct HeldBack<W: Write> {
    inner: W,
    /// The bytes held back, until the gate opens.
    held: Vec<u8>,
    open: Arc<AtomicBool>,
}

impl<W: Write> HeldBack<W> {
    fn is_open(&self) -> bool {
        self.open.load(Ordering::Acquire)
    }

    /// Writes out what was held back, once the gate is open.
    fn release(&mut self) -> std::io::Result<()> {
        if self.is_open() && !self.held.is_empty() {
            self.inner.write_all(&self.held)?;
            self.held = Vec::new();
        }
        Ok(())
    }
}

impl<W: Write> Write for HeldBack<W> {
    fn write(&mut self, bytes: &[u8]) -> std::io::Result<usize> {
        if !self.is_open() {
            self.held.extend_from_slice(bytes);
            return Ok(bytes.len());
        }
        self.release()?;
        self.inner.write(bytes)
    }

    fn flush(&mut self) -> std::io::Result<()> {
        if !self.is_open() {
            return Ok(());
        }
        self.release()?;
        self.inner.flush()
    }
}

/// An open recording: its stream, and how to complete it.
pub struct Output {
    pub stream: RecordingStream,
    writer: Option<SharedWriter>,
    /// The gate of standard output ([`HeldBack`]), opened by the first flush.
    gate: Option<Arc<AtomicBool>>,
    completion: Completion,
    /// What the user asked for (for messages).
    destination: Destination,
}

fn builder(name: &str) -> rerun::RecordingStreamBuilder {
    rerun::RecordingStreamBuilder::new(APPLICATION_ID)
        .recording_name(name.to_string())
        .enabled(true)
}

impl Output {
    /// Opens `destination` for the recording named `name` (a file is created at once, a
    /// viewer started or connected to).
    pub fn open(destination: &Destination, name: &str) -> Result<Self, RecordError> {
        let output_error = |path: &Path, message: String| RecordError::Output {
            path: path.to_path_buf(),
            message,
        };
        let with_writer = |write: Box<dyn Write + Send>,
                           gate: Option<Arc<AtomicBool>>,
                           completion: Completion,
                           shown: &Path| {
            let encoder = Encoder::new_eager(
                CrateVersion::LOCAL,
                EncodingOptions::PROTOBUF_COMPRESSED,
                write,
            )
            .map_err(|e| output_error(shown, e.to_string()))?;
            let writer = Arc::new(Mutex::new(Writer {
                encoder: Some(encoder),
                error: None,
            }));
            let stream = builder(name).buffered()?;
            stream.set_sink(Box::new(WriterSink(Arc::clone(&writer))));
            Ok::<_, RecordError>(Self {
                stream,
                writer: Some(writer),
                gate,
                completion,
                destination: destination.clone(),
            })
        };
        match destination {
            Destination::File(path) => match target(path).map_err(|m| output_error(path, m))? {
                Target::Replace(target) => {
                    let dir = match target.parent() {
                        Some(p) if !p.as_os_str().is_empty() => p,
                        _ => Path::new("."),
                    };
                    let temp = tempfile::Builder::new()
                        .prefix(".stressfield-")
                        .suffix(".rrd.part")
                        .tempfile_in(dir)
                        .map_err(|e| output_error(path, e.to_string()))?;
                    let pending = Pending::new(temp.path());
                    let (file, temp) = temp.into_parts();
                    let write = file
                        .try_clone()
                        .map_err(|e| output_error(path, e.to_string()))?;
                    with_writer(
                        Box::new(std::io::BufWriter::new(write)),
                        None,
                        Completion::Rename {
                            temp,
                            _pending: pending,
                            file,
                            path: target,
                        },
                        path,
                    )
                }
                Target::Through(target) => {
                    let file = std::fs::OpenOptions::new()
                        .write(true)
                        .open(&target)
                        .map_err(|e| output_error(path, e.to_string()))?;
                    with_writer(
                        Box::new(std::io::BufWriter::new(file)),
                        None,
                        Completion::Through,
                        path,
                    )
                }
            },
            Destination::Stdout => {
                use std::io::IsTerminal;
                if std::io::stdout().is_terminal() {
                    return Err(RecordError::Terminal);
                }
                let gate = Arc::new(AtomicBool::new(false));
                with_writer(
                    Box::new(std::io::BufWriter::new(HeldBack {
                        inner: std::io::stdout(),
                        held: Vec::new(),
                        open: Arc::clone(&gate),
                    })),
                    Some(gate),
                    Completion::Stdout,
                    Path::new("standard output"),
                )
            }
            Destination::Spawn => {
                let stream = builder(name)
                    .spawn()
                    .map_err(|e| RecordError::Spawn(e.to_string()))?;
                Ok(Self {
                    stream,
                    writer: None,
                    gate: None,
                    completion: Completion::Viewer {
                        url: DEFAULT_VIEWER_URL.into(),
                    },
                    destination: destination.clone(),
                })
            }
            Destination::Connect(url) => {
                let stream = builder(name).connect_grpc_opts(url.clone()).map_err(|e| {
                    RecordError::Viewer {
                        url: url.clone(),
                        message: e.to_string(),
                    }
                })?;
                Ok(Self {
                    stream,
                    writer: None,
                    gate: None,
                    completion: Completion::Viewer { url: url.clone() },
                    destination: destination.clone(),
                })
            }
        }
    }

    /// Sends what has been logged so far (after each step, so that a viewer shows it); the
    /// first flush opens standard output's gate ([`HeldBack`]).
    pub fn flush(&self) -> Result<(), RecordError> {
        if let Some(gate) = &self.gate {
            gate.store(true, Ordering::Release);
        }
        self.stream
            .flush_blocking()
            .map_err(|e| self.error(e.to_string()))
    }

    /// The error of this destination: the writer's system error if there was one.
    fn error(&self, fallback: String) -> RecordError {
        let system = self
            .writer
            .as_ref()
            .and_then(|w| lock(w).error.as_ref().map(ToString::to_string));
        match (&self.destination, &self.completion) {
            (_, Completion::Viewer { url }) => RecordError::Viewer {
                url: url.clone(),
                message: fallback,
            },
            (Destination::File(path), _) => RecordError::Output {
                path: path.clone(),
                message: system.unwrap_or(fallback),
            },
            (_, _) => RecordError::Stdout(system.unwrap_or(fallback)),
        }
    }

    /// Completes the recording: the footer written and the file renamed into place, or the
    /// viewer's stream flushed. Whatever fails, a temporary file is removed.
    pub fn finish(self) -> Result<(), RecordError> {
        self.flush()?;
        let Self {
            stream,
            writer,
            completion,
            destination,
            ..
        } = self;
        // Every message reaches the sink before the stream is gone.
        drop(stream);
        let viewer = match &completion {
            Completion::Viewer { url } => Some(url.clone()),
            _ => None,
        };
        let fail = |message: String| match (&destination, &viewer) {
            (Destination::File(path), _) => RecordError::Output {
                path: path.clone(),
                message,
            },
            (_, Some(url)) => RecordError::Viewer {
                url: url.clone(),
                message,
            },
            _ => RecordError::Stdout(message),
        };
        if let Some(writer) = writer {
            let mut writer = lock(&writer);
            if let Some(e) = &writer.error {
                return Err(fail(e.to_string()));
            }
            let mut encoder = writer
                .encoder
                .take()
                .ok_or_else(|| fail("the recording was closed early".into()))?;
            encoder
                .finish()
                .and_then(|()| encoder.flush_blocking())
                .map_err(|e| match e {
                    EncodeError::Write(e) => fail(e.to_string()),
                    other => fail(other.to_string()),
                })?;
        }
        match completion {
            Completion::Rename {
                temp,
                _pending,
                file,
                path: target,
            } => {
                file.sync_all().map_err(|e| fail(e.to_string()))?;
                #[cfg(unix)]
                {
                    use std::os::unix::fs::PermissionsExt;
                    std::fs::set_permissions(&temp, std::fs::Permissions::from_mode(0o644))
                        .map_err(|e| fail(e.to_string()))?;
                }
                temp.persist(&target)
                    .map_err(|e| fail(e.error.to_string()))?;
                Ok(())
            }
            Completion::Through | Completion::Stdout | Completion::Viewer { .. } => Ok(()),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn standard_output_is_held_back_until_the_first_flush() {
        let open = Arc::new(AtomicBool::new(false));
        let mut out = HeldBack {
            inner: Vec::new(),
            held: Vec::new(),
            open: Arc::clone(&open),
        };
        out.write_all(b"header ").expect("held");
        out.flush()
            .expect("a flush before the gate opens keeps the bytes");
        out.write_all(b"layout ").expect("held");
        assert!(out.inner.is_empty());
        open.store(true, Ordering::Release);
        out.flush().expect("released");
        assert_eq!(out.inner, b"header layout ");
        out.write_all(b"step").expect("written through");
        assert_eq!(out.inner, b"header layout step");
        assert!(out.held.is_empty());
    }

    /// A writer that fails as a full disk does.
    struct FullDisk;

    impl Write for FullDisk {
        fn write(&mut self, _: &[u8]) -> std::io::Result<usize> {
            Err(std::io::Error::from_raw_os_error(28))
        }
        fn flush(&mut self) -> std::io::Result<()> {
            Ok(())
        }
    }

    #[test]
    fn a_write_error_is_kept_and_reported_by_flush() {
        let writer = Arc::new(Mutex::new(Writer {
            encoder: None,
            error: None,
        }));
        // The header write fails at once, as on a full disk.
        let error = Encoder::new_eager(
            CrateVersion::LOCAL,
            EncodingOptions::PROTOBUF_COMPRESSED,
            Box::new(FullDisk) as Box<dyn Write + Send>,
        )
        .err()
        .expect("the header cannot be written");
        lock(&writer).fail(error);
        let sink = WriterSink(Arc::clone(&writer));
        let message = sink
            .flush_blocking(std::time::Duration::from_secs(1))
            .expect_err("the error is reported")
            .to_string();
        assert!(message.contains("No space left on device"), "{message}");
    }
}
