//! Reading what users give us (scene files, traction tables, probe points, height maps) with
//! limits on the size of a file and the length of a line, so that a wrong path (`/dev/zero`,
//! a disk image, a binary file) fails at once with the limit in the message instead of filling
//! the memory. Sizes are counted as the bytes are read, so devices and pipes, whose size is
//! not known beforehand, are limited too.

use std::io::{BufRead, Read};
use std::path::Path;

use crate::io::text;

/// The largest scene file: scenes are a few KiB of TOML.
pub const SCENE_FILE_LIMIT: u64 = 1 << 20;

/// The largest traction table (CSV): a 2048 x 2048 grid of `x,y,p,qx,qy` rows takes about
/// 200 MiB; the grid may have at most 4096 x 4096 nodes.
pub const TRACTION_FILE_LIMIT: u64 = 256 << 20;

/// The largest input of `probe` (file or standard input): about five million points.
pub const POINTS_LIMIT: u64 = 128 << 20;

/// The longest line of a table (traction CSV, probe points): a row of five numbers takes well
/// under 200 bytes.
pub const LINE_LIMIT: usize = 64 << 10;

/// The UTF-8 byte-order mark, dropped from the start of every text read.
const BOM: &[u8] = "\u{feff}".as_bytes();

/// Input that cannot be read or is beyond a limit. The caller names the file.
#[derive(Debug, thiserror::Error)]
pub enum InputError {
    #[error("{0}")]
    Io(#[from] std::io::Error),
    #[error("larger than the {} allowed{}", text::bytes(*limit), hint_for(*limit))]
    TooLarge { limit: u64 },
    #[error("line {line} is longer than the {} allowed for a line (is it the right file?)", text::bytes(*limit as u64))]
    LineTooLong { line: usize, limit: usize },
    #[error("line {line} is not text (UTF-8): is it the right file?")]
    NotText { line: usize },
}

fn hint_for(limit: u64) -> &'static str {
    if limit == SCENE_FILE_LIMIT {
        " for a scene (scenes are a few KiB of TOML): is it the right file?"
    } else {
        ": is it the right file?"
    }
}

/// Reads the whole of `path` as UTF-8 text (without a leading byte-order mark), failing as soon as more than `limit` bytes come.
pub fn read_to_string(path: &Path, limit: u64) -> Result<String, InputError> {
    let file = std::fs::File::open(path)?;
    // A regular file's size, when within the limit, sizes the buffer once (no doubling).
    let size = file.metadata().map_or(0, |m| m.len());
    let capacity = if size <= limit { size as usize + 1 } else { 0 };
    read_all_with_capacity(file, limit, capacity)
}

/// Largest grid (in bytes of stored values) that [`crate::field::evaluate`] accepts on any
/// machine; less when the machine has less memory available (see
/// [`crate::field::memory_limit_bytes`]). It lives here, at the bottom of the pipeline, so
/// that the input readers and the field evaluation (which re-exports it) see one number
/// without either reaching up to the other.
pub const MAX_FIELD_BYTES: usize = 4 << 30;

/// The largest reference file of a regression run (`render --compare`: a PNG or a field
/// archive): a quarter of the memory a figure may use, so the largest figure's field fits.
pub const REFERENCE_FILE_LIMIT: u64 = (MAX_FIELD_BYTES / 4) as u64;

/// Reads the whole of `path` as bytes, failing as soon as more than `limit` bytes come.
pub fn read_bytes(path: &Path, limit: u64) -> Result<Vec<u8>, InputError> {
    let file = std::fs::File::open(path)?;
    // A regular file's size is known: beyond the limit it fails before a byte is read.
    let size = file.metadata().map_or(0, |m| m.len());
    if size > limit {
        return Err(InputError::TooLarge { limit });
    }
    let mut bytes = Vec::with_capacity(size as usize + 1);
    file.take(limit.saturating_add(1)).read_to_end(&mut bytes)?;
    if bytes.len() as u64 > limit {
        return Err(InputError::TooLarge { limit });
    }
    Ok(bytes)
}

/// Reads all of `reader` as UTF-8 text, failing as soon as more than `limit` bytes come.
pub fn read_all(reader: impl Read, limit: u64) -> Result<String, InputError> {
    read_all_with_capacity(reader, limit, 0)
}

fn read_all_with_capacity(
    reader: impl Read,
    limit: u64,
    capacity: usize,
) -> Result<String, InputError> {
    let mut bytes = Vec::with_capacity(capacity);
    reader
        .take(limit.saturating_add(1))
        .read_to_end(&mut bytes)?;
    if bytes.len() as u64 > limit {
        return Err(InputError::TooLarge { limit });
    }
    // A byte-order mark (editors on Windows write one) is no part of the text.
    if bytes.starts_with(BOM) {
        bytes.drain(..BOM.len());
    }
    String::from_utf8(bytes).map_err(|e| {
        let valid = &e.as_bytes()[..e.utf8_error().valid_up_to()];
        InputError::NotText {
            line: valid.iter().filter(|b| **b == b'\n').count() + 1,
        }
    })
}

/// The lines of `reader` (without their line ending: `\n`, `\r\n` or a lone `\r`, and without a
/// leading byte-order mark), numbered from 1, at most `line_limit` bytes each and
/// `total_limit` bytes in all; the first error ends the iteration.
pub fn lines<R: BufRead>(reader: R, total_limit: u64, line_limit: usize) -> Lines<R> {
    Lines {
        reader,
        total_limit,
        line_limit,
        read: 0,
        line: 0,
        done: false,
    }
}

/// The iterator of [`lines`].
pub struct Lines<R> {
    reader: R,
    total_limit: u64,
    line_limit: usize,
    read: u64,
    line: usize,
    done: bool,
}

impl<R: BufRead> Iterator for Lines<R> {
    type Item = Result<(usize, String), InputError>;

    fn next(&mut self) -> Option<Self::Item> {
        if self.done {
            return None;
        }
        self.line += 1;
        let mut buffer = Vec::new();
        let (read, _) = match read_line(&mut self.reader, &mut buffer, self.line_limit) {
            Ok(result) => result,
            Err(e) => {
                self.done = true;
                return Some(Err(InputError::Io(e)));
            }
        };
        if read == 0 {
            self.done = true;
            return None;
        }
        self.read += read as u64;
        let error = if self.read > self.total_limit {
            Some(InputError::TooLarge {
                limit: self.total_limit,
            })
        } else if buffer.len() > self.line_limit {
            Some(InputError::LineTooLong {
                line: self.line,
                limit: self.line_limit,
            })
        } else {
            None
        };
        if let Some(error) = error {
            self.done = true;
            return Some(Err(error));
        }
        if self.line == 1 && buffer.starts_with(BOM) {
            buffer.drain(..BOM.len());
        }
        match String::from_utf8(buffer) {
            Ok(text) => Some(Ok((self.line, text))),
            Err(_) => {
                self.done = true;
                Some(Err(InputError::NotText { line: self.line }))
            }
        }
    }
}

/// Reads one line into `buffer` without its ending (`\n`, `\r\n`, or a lone `\r` as old Mac
/// files have), at most `line_limit + 1` bytes of it (one more tells a line that is too long);
/// returns the bytes consumed and whether a line ending was found.
fn read_line(
    reader: &mut impl BufRead,
    buffer: &mut Vec<u8>,
    line_limit: usize,
) -> std::io::Result<(usize, bool)> {
    let mut consumed = 0;
    loop {
        let available = match reader.fill_buf() {
            Ok(bytes) => bytes,
            Err(e) if e.kind() == std::io::ErrorKind::Interrupted => continue,
            Err(e) => return Err(e),
        };
        if available.is_empty() {
            return Ok((consumed, false));
        }
        let room = line_limit + 1 - buffer.len();
        match available.iter().position(|b| *b == b'\n' || *b == b'\r') {
            Some(at) if at <= room => {
                buffer.extend_from_slice(&available[..at]);
                let carriage_return = available[at] == b'\r';
                reader.consume(at + 1);
                consumed += at + 1;
                if carriage_return {
                    // `\r\n` is one ending.
                    let next = loop {
                        match reader.fill_buf() {
                            Ok(bytes) => break bytes.first().copied(),
                            Err(e) if e.kind() == std::io::ErrorKind::Interrupted => continue,
                            Err(e) => return Err(e),
                        }
                    };
                    if next == Some(b'\n') {
                        reader.consume(1);
                        consumed += 1;
                    }
                }
                return Ok((consumed, true));
            }
            _ => {
                let take = available.len().min(room);
                buffer.extend_from_slice(&available[..take]);
                reader.consume(take);
                consumed += take;
                if buffer.len() > line_limit {
                    return Ok((consumed, false));
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn whole_reads_stop_at_the_limit() {
        assert_eq!(read_all("abc".as_bytes(), 3).expect("fits"), "abc");
        let error = read_all(std::io::repeat(0).take(1 << 30), 1024).expect_err("endless");
        assert!(error.to_string().contains("1 KiB"), "{error}");
        let error = read_all(&b"ok\n\xff\n"[..], 100).expect_err("binary");
        assert!(error.to_string().contains("line 2"), "{error}");
    }

    #[cfg(unix)]
    #[test]
    fn byte_reads_stop_at_the_limit() {
        let error = read_bytes(Path::new("/dev/zero"), 4096).expect_err("endless");
        assert!(
            matches!(error, InputError::TooLarge { limit: 4096 }),
            "{error}"
        );
        let dir = tempfile::tempdir().expect("temp dir");
        let path = dir.path().join("f");
        std::fs::write(&path, b"\x89PNG").expect("write");
        assert_eq!(read_bytes(&path, 4).expect("fits"), b"\x89PNG");
        assert!(read_bytes(&path, 3).is_err());
        // A large (sparse) file fails by its size, before it is read.
        let file = std::fs::File::create(&path).expect("create");
        file.set_len(1 << 40).expect("sparse");
        assert!(matches!(
            read_bytes(&path, 1 << 20),
            Err(InputError::TooLarge { .. })
        ));
    }

    #[test]
    fn lines_are_numbered_and_limited() {
        let text = "a\r\nbb\n\nccc";
        let read: Vec<(usize, String)> = lines(text.as_bytes(), 100, 10)
            .collect::<Result<_, _>>()
            .expect("valid");
        assert_eq!(
            read,
            vec![
                (1, "a".into()),
                (2, "bb".into()),
                (3, String::new()),
                (4, "ccc".into())
            ]
        );
        // A line of exactly the limit passes; one byte more does not.
        assert!(lines("12345\n".as_bytes(), 100, 5).all(|l| l.is_ok()));
        let mut long = lines("ok\n123456\nnever\n".as_bytes(), 100, 5);
        assert!(long.next().expect("first").is_ok());
        let error = long.next().expect("second").expect_err("too long");
        assert!(
            matches!(error, InputError::LineTooLong { line: 2, .. }),
            "{error}"
        );
        assert!(long.next().is_none(), "the first error ends the lines");
        // An endless line without a newline ends at the line limit, not the memory.
        let mut zeros = lines(std::io::BufReader::new(std::io::repeat(0)), 1 << 40, 64);
        assert!(matches!(
            zeros.next().expect("one"),
            Err(InputError::LineTooLong { line: 1, .. })
        ));
        let mut many = lines(std::io::BufReader::new(std::io::repeat(b'\n')), 1000, 64);
        assert!(matches!(
            many.find(Result::is_err).expect("stops"),
            Err(InputError::TooLarge { limit: 1000 })
        ));
    }

    /// Issue 24, classes 10 and 16: a byte-order mark is dropped and a lone CR ends a line.
    #[test]
    fn byte_order_marks_and_lone_carriage_returns() {
        let text = "\u{feff}# x,y,z\r1,2,3\r\n4,5,6\r\r7,8,9";
        assert_eq!(
            read_all(text.as_bytes(), 100).expect("text"),
            text.trim_start_matches('\u{feff}')
        );
        let read: Vec<(usize, String)> = lines(text.as_bytes(), 100, 10)
            .collect::<Result<_, _>>()
            .expect("valid");
        assert_eq!(
            read,
            vec![
                (1, "# x,y,z".into()),
                (2, "1,2,3".into()),
                (3, "4,5,6".into()),
                (4, String::new()),
                (5, "7,8,9".into())
            ]
        );
        // Through a reader that hands out one byte at a time (a CR at a buffer's end).
        let slow = std::io::BufReader::with_capacity(1, text.as_bytes());
        assert_eq!(lines(slow, 100, 10).count(), 5);
    }
}
