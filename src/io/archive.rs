//! Bounded reading of archives: the members of a zip archive (an x3p surface, an npz field)
//! and NumPy `.npy` arrays.
//!
//! Every size a file declares is checked before anything is allocated: against what the file
//! can hold (a stored member is as large as it is packed, a deflated one at most
//! [`DEFLATE_MAX_RATIO`] times larger; an array's shape must fill its `.npy` exactly), against
//! what the metadata leads to expect (an x3p's matrix size) and against the memory budget the
//! caller gives. Members are unpacked through `take(limit + 1)`, so a member that inflates
//! beyond what it declared (a zip bomb) is refused after at most `limit + 1` bytes.
//!
//! ## Reference
//! NumPy Enhancement Proposal 1, *A simple file format for NumPy arrays* (the `.npy` header).

use std::io::{Read, Seek};

use crate::io::text;

/// Deflate's largest ratio of unpacked to packed bytes: a match of 258 bytes coded in as few as
/// two bits gives 1032 (zlib's technical details); a member declaring more is damaged.
pub const DEFLATE_MAX_RATIO: u64 = 1032;

/// An archive, or one of its members, that cannot be read within its bounds. Messages name the
/// file, the member and the fix.
#[derive(Debug, thiserror::Error)]
pub enum ArchiveError {
    #[error("{path}: not a zip archive ({reason}): is it the right file?")]
    NotZip { path: String, reason: String },
    #[error("{path}: the archive has no member {member}")]
    Missing { path: String, member: String },
    #[error("{path}: member {member}: {message}")]
    Member {
        path: String,
        member: String,
        message: String,
    },
}

/// A member the zip reader cannot open for its compression or encryption.
const UNSUPPORTED: &str = "uses a compression or encryption stressfield does not read: export the file again, unencrypted, with Deflate";

/// The name of a zip compression method, by its number in the zip specification (APPNOTE
/// 4.4.5): the crate built without them shows bzip2 and LZMA as numbers.
fn method_name(method: zip::CompressionMethod) -> String {
    #[allow(deprecated)]
    match method.to_u16() {
        12 => "bzip2".into(),
        14 => "LZMA".into(),
        93 => "Zstandard".into(),
        95 => "XZ".into(),
        99 => "AES encryption".into(),
        code => format!("method {code}"),
    }
}

/// How many bytes a member may unpack to.
#[derive(Clone, Copy, Debug)]
pub enum Limit<'a> {
    /// Exactly this many, as the metadata says (the text says why, e.g. "24 x 16 values of
    /// type D").
    Exactly(u64, &'a str),
    /// At most this many (the text says why, e.g. "main.xml describes the axes in a few KiB").
    AtMost(u64, &'a str),
}

/// A zip archive whose members are read within bounds (module doc).
pub struct Archive<R> {
    zip: zip::ZipArchive<R>,
    path: String,
}

impl<R: Read + Seek> Archive<R> {
    /// Opens the archive `reader`; `path` names it in messages.
    pub fn new(reader: R, path: &str) -> Result<Self, ArchiveError> {
        let zip = zip::ZipArchive::new(reader).map_err(|e| ArchiveError::NotZip {
            path: path.to_string(),
            reason: text::cut(&e.to_string(), 120),
        })?;
        Ok(Self {
            zip,
            path: path.to_string(),
        })
    }

    /// The names of the members, in the archive's order.
    pub fn names(&self) -> Vec<String> {
        self.zip.file_names().map(str::to_string).collect()
    }

    /// The unpacked bytes of `member`, refused before anything is allocated when its declared
    /// size breaks `limit` or cannot be (module doc), and after at most `limit + 1` bytes when
    /// it unpacks to more than it declared.
    pub fn member(&mut self, member: &str, limit: Limit) -> Result<Vec<u8>, ArchiveError> {
        let fail = |message: String| ArchiveError::Member {
            path: self.path.clone(),
            member: text::cut(member, 80),
            message,
        };
        // What the member is packed with, read before it is opened: an encrypted member or
        // a compression this build does not unpack is named as such, never "damaged".
        let raw = self
            .zip
            .index_for_name(member)
            .and_then(|i| self.zip.by_index_raw(i).ok())
            .map(|raw| (raw.encrypted(), raw.compression()));
        match raw {
            Some((true, _)) => return Err(fail("is encrypted, which stressfield does not read: export the file again without a password".to_string())),
            Some((false, method)) if !matches!(method, zip::CompressionMethod::Stored | zip::CompressionMethod::Deflated) => {
                return Err(fail(format!("is compressed with {}, which stressfield does not unpack (it reads members stored or compressed with Deflate): export the file again with Deflate", method_name(method))))
            }
            _ => {}
        }
        let mut entry = match self.zip.by_name(member) {
            Ok(entry) => entry,
            Err(zip::result::ZipError::FileNotFound) => {
                return Err(ArchiveError::Missing {
                    path: self.path.clone(),
                    member: text::cut(member, 80),
                })
            }
            Err(zip::result::ZipError::UnsupportedArchive(_)) => {
                return Err(fail(UNSUPPORTED.to_string()))
            }
            Err(e) => {
                return Err(fail(format!(
                    "cannot be read ({e}): the archive is damaged"
                )))
            }
        };
        let declared = entry.size();
        let packed = entry.compressed_size();
        let most = match limit {
            Limit::Exactly(expected, why) if declared != expected => {
                return Err(fail(format!(
                    "declares {declared} bytes unpacked, but {why} take {expected} bytes: the archive is damaged or not what its metadata says; export it again"
                )))
            }
            Limit::AtMost(most, why) if declared > most => {
                return Err(fail(format!(
                    "declares {} unpacked, more than the {} allowed ({why}): is it the right file?",
                    text::bytes(declared),
                    text::bytes(most)
                )))
            }
            Limit::Exactly(most, _) | Limit::AtMost(most, _) => most,
        };
        let possible = match entry.compression() {
            zip::CompressionMethod::Stored => packed,
            _ => packed
                .saturating_mul(DEFLATE_MAX_RATIO)
                .saturating_add(1024),
        };
        if declared > possible {
            return Err(fail(format!(
                "declares {declared} bytes unpacked from {packed} packed, more than compression can give: the archive is damaged; export it again"
            )));
        }
        // Within the limit, so the buffer is allocated once and no larger than allowed.
        let mut bytes = Vec::with_capacity(declared as usize);
        (&mut entry)
            .take(most.saturating_add(1))
            .read_to_end(&mut bytes)
            .map_err(|e| fail(format!("cannot be unpacked ({e}): the archive is damaged")))?;
        let read = bytes.len() as u64;
        if read > most {
            return Err(fail(format!(
                "unpacks to more than the {most} bytes it may have (stopped there): a damaged archive or a zip bomb; export it again"
            )));
        }
        if read != declared {
            return Err(fail(format!(
                "unpacks to {read} bytes, {declared} declared: the archive is damaged; export it again"
            )));
        }
        Ok(bytes)
    }
}

/// A NumPy array of float64 read from `.npy` bytes: its shape and its values in C order.
#[derive(Clone, Debug, PartialEq)]
pub struct NpyArray {
    pub shape: Vec<usize>,
    pub values: Vec<f64>,
}

/// Reads `.npy` bytes of float64 (little- or big-endian, C or Fortran order). The shape the
/// header declares must fill the bytes after it exactly (checked before the values are
/// allocated, with overflow-safe products), so a damaged or hostile header cannot ask for
/// more memory than the file's own size.
pub fn npy_f64(bytes: &[u8]) -> Result<NpyArray, String> {
    let damaged = |what: &str| format!("{what}: not a NumPy .npy array, or a damaged one");
    if bytes.len() < 10 || &bytes[..6] != b"\x93NUMPY" {
        return Err(damaged("no .npy magic number"));
    }
    let (length, start) = match bytes[6] {
        1 => (u64::from(u16::from_le_bytes([bytes[8], bytes[9]])), 10),
        2 | 3 if bytes.len() >= 12 => (
            u64::from(u32::from_le_bytes([
                bytes[8], bytes[9], bytes[10], bytes[11],
            ])),
            12,
        ),
        version => return Err(damaged(&format!(".npy version {version}"))),
    };
    let end = start as u64 + length;
    if end > bytes.len() as u64 {
        return Err(damaged(&format!(
            "a header of {length} bytes in {} bytes",
            bytes.len()
        )));
    }
    let header = String::from_utf8_lossy(&bytes[start..end as usize]);
    let value = |key: &str| -> Result<&str, String> {
        ["'", "\""]
            .iter()
            .find_map(|q| {
                header
                    .find(&format!("{q}{key}{q}"))
                    .map(|at| at + key.len() + 2)
            })
            .and_then(|at| header[at..].trim_start().strip_prefix(':'))
            .map(str::trim_start)
            .ok_or_else(|| damaged(&format!("no `{key}` in the header")))
    };
    let descr = value("descr")?;
    let descr = descr
        .get(1..)
        .and_then(|rest| rest.split(['\'', '"']).next())
        .unwrap_or("");
    let big_endian = match descr {
        "<f8" => false,
        ">f8" => true,
        other => {
            return Err(format!(
                "values of type `{}`; a field archive holds float64 (`<f8`)",
                text::cut(other, 20)
            ))
        }
    };
    let fortran = value("fortran_order")?.starts_with("True");
    let shape_text = value("shape")?;
    let shape_text = shape_text
        .strip_prefix('(')
        .and_then(|s| s.split(')').next())
        .ok_or_else(|| damaged("no shape tuple"))?;
    let mut shape = Vec::new();
    for dimension in shape_text
        .split(',')
        .map(str::trim)
        .filter(|d| !d.is_empty())
    {
        let n: u64 = dimension
            .parse()
            .map_err(|_| damaged(&format!("shape entry `{}`", text::cut(dimension, 20))))?;
        shape.push(n);
    }
    let shown = format!(
        "({})",
        shape
            .iter()
            .map(u64::to_string)
            .collect::<Vec<_>>()
            .join(", ")
    );
    let data = bytes.len() as u64 - end;
    let needed = shape
        .iter()
        .try_fold(8u64, |product, &n| product.checked_mul(n));
    if needed != Some(data) {
        let needed = needed.map_or("more than 2^64".to_string(), |n| n.to_string());
        return Err(format!(
            "declares shape {shown}, {needed} bytes of float64, but holds {data} bytes: a damaged or another file"
        ));
    }
    let shape: Vec<usize> = shape.iter().map(|&n| n as usize).collect();
    let mut values: Vec<f64> = bytes[end as usize..]
        .chunks_exact(8)
        .map(|b| {
            let b = [b[0], b[1], b[2], b[3], b[4], b[5], b[6], b[7]];
            if big_endian {
                f64::from_be_bytes(b)
            } else {
                f64::from_le_bytes(b)
            }
        })
        .collect();
    if fortran && shape.len() > 1 {
        values = fortran_to_c(&values, &shape);
    }
    Ok(NpyArray { shape, values })
}

/// `values` of `shape` in Fortran order (first index fastest), reordered to C order.
fn fortran_to_c(values: &[f64], shape: &[usize]) -> Vec<f64> {
    let mut out = vec![0.0; values.len()];
    let mut index = vec![0usize; shape.len()];
    for &value in values {
        // The C offset of the current index.
        let offset = index.iter().zip(shape).fold(0, |o, (i, n)| o * n + i);
        out[offset] = value;
        for (i, n) in index.iter_mut().zip(shape) {
            *i += 1;
            if *i < *n {
                break;
            }
            *i = 0;
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use std::io::{Cursor, Write};

    use super::*;

    fn npy(header: &str, data: &[u8]) -> Vec<u8> {
        let mut bytes = b"\x93NUMPY\x01\x00".to_vec();
        bytes.extend_from_slice(&(header.len() as u16).to_le_bytes());
        bytes.extend_from_slice(header.as_bytes());
        bytes.extend_from_slice(data);
        bytes
    }

    fn zip_of(members: &[(&str, &[u8])], method: zip::CompressionMethod) -> Vec<u8> {
        let mut bytes = Vec::new();
        {
            let mut zip = zip::ZipWriter::new(Cursor::new(&mut bytes));
            let options = zip::write::SimpleFileOptions::default().compression_method(method);
            for (name, data) in members {
                zip.start_file(*name, options).expect("entry");
                zip.write_all(data).expect("data");
            }
            zip.finish().expect("zip");
        }
        bytes
    }

    /// Issue 24, class 12: a member packed with bzip2, or encrypted, is named as such, not
    /// "missing" or "damaged". The archive is written stored, then its headers patched: the
    /// method at offset 8 of the local header and 10 of the central one, the encryption flag
    /// (bit 0 of the flags) at 6 and 8.
    #[test]
    fn unsupported_compression_and_encryption_are_named() {
        let stored = zip_of(&[("main.xml", b"<x/>")], zip::CompressionMethod::Stored);
        let patch = |method: Option<u16>, encrypted: bool| {
            let mut bytes = stored.clone();
            for (signature, flags) in [(b"PK\x03\x04", 6), (b"PK\x01\x02", 8)] {
                let at = bytes
                    .windows(4)
                    .position(|w| w == signature)
                    .expect("header");
                if let Some(method) = method {
                    bytes[at + flags + 2..at + flags + 4].copy_from_slice(&method.to_le_bytes());
                }
                if encrypted {
                    bytes[at + flags] |= 1;
                }
            }
            let mut archive = Archive::new(Cursor::new(bytes), "s.x3p").expect("zip");
            archive
                .member("main.xml", Limit::AtMost(1024, "test"))
                .expect_err("unsupported")
                .to_string()
        };
        let bzip2 = patch(Some(12), false);
        assert!(
            bzip2.contains("compressed with bzip2") && bzip2.contains("Deflate"),
            "{bzip2}"
        );
        let encrypted = patch(None, true);
        assert!(encrypted.contains("is encrypted"), "{encrypted}");
    }

    #[test]
    fn npy_arrays_read_in_c_order() {
        let data: Vec<u8> = [1.0f64, 2.0, 3.0, 4.0, 5.0, 6.0]
            .iter()
            .flat_map(|v| v.to_le_bytes())
            .collect();
        let c = npy(
            "{'descr': '<f8', 'fortran_order': False, 'shape': (2, 3), }",
            &data,
        );
        let array = npy_f64(&c).expect("valid");
        assert_eq!(array.shape, vec![2, 3]);
        assert_eq!(array.values, vec![1.0, 2.0, 3.0, 4.0, 5.0, 6.0]);
        // Fortran order: the first index runs fastest.
        let f = npy(
            "{'descr': '<f8', 'fortran_order': True, 'shape': (2, 3), }",
            &data,
        );
        assert_eq!(
            npy_f64(&f).expect("valid").values,
            vec![1.0, 3.0, 5.0, 2.0, 4.0, 6.0]
        );
        let one = npy(
            "{'descr': '<f8', 'fortran_order': False, 'shape': (6,), }",
            &data,
        );
        assert_eq!(npy_f64(&one).expect("valid").shape, vec![6]);
    }

    /// Issue 24, class 1: a header declaring (100000, 100000) or (3000000000, 1) over a few
    /// bytes is refused by its size, before the values are allocated (the test would abort
    /// the process otherwise).
    #[test]
    fn a_declared_shape_must_fill_the_array() {
        for shape in [
            "(100000, 100000)",
            "(3000000000, 1)",
            "(4294967296, 4294967296)",
        ] {
            let bytes = npy(
                &format!("{{'descr': '<f8', 'fortran_order': False, 'shape': {shape}, }}"),
                &[0; 16],
            );
            let error = npy_f64(&bytes).expect_err(shape);
            assert!(
                error.contains(&format!("declares shape {shape}"))
                    && error.contains("holds 16 bytes"),
                "{error}"
            );
        }
        let int = npy(
            "{'descr': '<i8', 'fortran_order': False, 'shape': (2,), }",
            &[0; 16],
        );
        assert!(npy_f64(&int).expect_err("int").contains("float64"));
        assert!(npy_f64(b"\x93NUMPY\x01\x00\xff\xff{").is_err());
        assert!(npy_f64(b"PK").is_err());
    }

    /// Issue 24, class 2: a member that declares more than it may, or inflates beyond what it
    /// declared, is refused; at most `limit + 1` bytes are unpacked.
    #[test]
    fn members_are_read_within_their_limit() {
        let zeros = vec![0u8; 1 << 20];
        let bytes = zip_of(
            &[("main.xml", b"<x/>"), ("data.bin", &zeros)],
            zip::CompressionMethod::Deflated,
        );
        let mut archive = Archive::new(Cursor::new(bytes), "s.x3p").expect("zip");
        assert_eq!(archive.names(), vec!["main.xml", "data.bin"]);
        assert_eq!(
            archive
                .member("main.xml", Limit::AtMost(4, "small"))
                .expect("fits"),
            b"<x/>"
        );
        let error = archive
            .member("data.bin", Limit::Exactly(3072, "24 x 16 values of type D"))
            .expect_err("bomb")
            .to_string();
        assert!(
            error.starts_with("s.x3p: member data.bin: declares 1048576 bytes")
                && error.contains("24 x 16 values of type D take 3072"),
            "{error}"
        );
        let error = archive
            .member("data.bin", Limit::AtMost(1000, "a few KiB"))
            .expect_err("large")
            .to_string();
        assert!(
            error.contains("more than the 1000 bytes allowed"),
            "{error}"
        );
        assert!(matches!(
            archive.member("other", Limit::AtMost(1, "")),
            Err(ArchiveError::Missing { .. })
        ));
        assert!(Archive::new(Cursor::new(b"not a zip".to_vec()), "f").is_err());
    }

    /// A member whose header understates its size (a crafted bomb) stops at the limit.
    #[test]
    fn a_member_that_inflates_beyond_its_declared_size_stops_at_the_limit() {
        let zeros = vec![0u8; 1 << 20];
        let mut bytes = zip_of(&[("data.bin", &zeros)], zip::CompressionMethod::Deflated);
        // Rewrite the declared size (1 MiB, at offset 22 of the local header and 24 of the
        // central directory entry) to 3072.
        let declared = (1u32 << 20).to_le_bytes();
        let positions: Vec<usize> = bytes
            .windows(4)
            .enumerate()
            .filter(|(_, w)| *w == declared)
            .map(|(at, _)| at)
            .collect();
        assert!(!positions.is_empty());
        for at in positions {
            bytes[at..at + 4].copy_from_slice(&3072u32.to_le_bytes());
        }
        let mut archive = Archive::new(Cursor::new(bytes), "s.x3p").expect("zip");
        let error = archive
            .member("data.bin", Limit::Exactly(3072, "24 x 16 values of type D"))
            .expect_err("bomb")
            .to_string();
        assert!(
            error.contains("more than the 3072 bytes") || error.contains("damaged"),
            "{error}"
        );
    }
}
