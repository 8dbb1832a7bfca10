//! A figure's fields saved as NumPy arrays (`render --save-field`), and their comparison with
//! saved references (`render --compare`).
//!
//! ## Format
//! One `.npz` archive per scene (a zip of `.npy` files, float64, C order), loadable with
//! `numpy.load`. For panel `k` (0 = left):
//! - `values_k`: `[rows, columns]` in the figure's stress unit (p0, MPa, ...), row 0 at the
//!   first vertical sample (the top of a depth section, the bottom of an xy section);
//! - `horizontal_k`: the `columns` horizontal coordinates, in the figure's length unit (x/a or
//!   mm; y for a yz section);
//! - `vertical_k`: the `rows` vertical coordinates (the depth z, or y for an xy section).
//!
//! Encoding and decoding happen in memory; the caller writes the bytes (atomically).

use std::io::Cursor;

use ndarray::{Array1, Array2};
use ndarray_npy::NpzWriter;

use crate::io::archive::{self, Archive, ArchiveError, Limit, NpyArray};
use crate::regression::{FieldCheck, FieldDifference};
use crate::render::Figure;

/// An unreadable or unwritable field archive.
#[derive(Debug, thiserror::Error)]
pub enum FieldFileError {
    #[error("cannot write the field archive: {0}")]
    Write(String),
    #[error("not a field archive of stressfield: {0}")]
    Read(String),
}

/// One panel's samples.
#[derive(Clone, Debug, PartialEq)]
pub struct PanelField {
    pub horizontal: Array1<f64>,
    pub vertical: Array1<f64>,
    /// `[vertical.len(), horizontal.len()]`.
    pub values: Array2<f64>,
}

impl PanelField {
    /// The samples of every panel of `figure`.
    pub fn of_figure(figure: &Figure) -> Vec<PanelField> {
        figure
            .panels
            .iter()
            .map(|panel| PanelField {
                horizontal: panel.x.values().collect(),
                vertical: panel.z.values().collect(),
                values: panel.values.clone(),
            })
            .collect()
    }
}

/// The `.npz` bytes of `panels`.
pub fn encode(panels: &[PanelField]) -> Result<Vec<u8>, FieldFileError> {
    let error = |e: ndarray_npy::WriteNpzError| FieldFileError::Write(e.to_string());
    let mut npz = NpzWriter::new(Cursor::new(Vec::new()));
    for (k, panel) in panels.iter().enumerate() {
        npz.add_array(format!("values_{k}"), &panel.values)
            .map_err(error)?;
        npz.add_array(format!("horizontal_{k}"), &panel.horizontal)
            .map_err(error)?;
        npz.add_array(format!("vertical_{k}"), &panel.vertical)
            .map_err(error)?;
    }
    Ok(npz.finish().map_err(error)?.into_inner())
}

/// The panels of `.npz` bytes written by [`encode`], within a quarter of the memory allowed
/// for fields (as [`decode_within`]).
pub fn decode(bytes: &[u8]) -> Result<Vec<PanelField>, FieldFileError> {
    decode_within(bytes, crate::field::memory_limit_bytes() as u64 / 4)
}

/// The panels of `.npz` bytes, whose members together may unpack to at most `budget` bytes.
/// Every member's declared size is checked against the budget, and every array's declared
/// shape against its member's size, before anything is allocated
/// ([`crate::io::archive`]); axes must be finite (values may hold NaN and infinities, as the
/// fields of numerical solutions do on strip edges; [`compare`] matches them only with the
/// same value).
pub fn decode_within(bytes: &[u8], budget: u64) -> Result<Vec<PanelField>, FieldFileError> {
    let fix = "write the reference again (render --compare DIR --update --save-field)";
    let read = |e: String| FieldFileError::Read(format!("{e}; {fix}"));
    let mut npz =
        Archive::new(Cursor::new(bytes), "the archive").map_err(|e| read(e.to_string()))?;
    let names = npz.names();
    let mut left = budget;
    let mut array = |name: &str| -> Result<NpyArray, FieldFileError> {
        // numpy.savez names members `name.npy`, and so does NpzWriter.
        let member = format!("{name}.npy");
        let bytes = npz
            .member(
                &member,
                Limit::AtMost(left, "a quarter of the memory allowed for fields"),
            )
            .map_err(|e| match e {
                ArchiveError::Member { message, .. } => read(format!("{member} {message}")),
                other => read(other.to_string()),
            })?;
        left -= bytes.len() as u64;
        archive::npy_f64(&bytes).map_err(|e| read(format!("{member}: {e}")))
    };
    let mut panels = Vec::new();
    while names
        .iter()
        .any(|n| n == &format!("values_{}.npy", panels.len()))
    {
        let k = panels.len();
        let values = array(&format!("values_{k}"))?;
        let mut axis = |name: String| -> Result<Array1<f64>, FieldFileError> {
            let axis = array(&name)?;
            if axis.shape.len() != 1 {
                return Err(read(format!(
                    "{name} has {} dimensions, an axis one",
                    axis.shape.len()
                )));
            }
            if let Some(at) = axis.values.iter().position(|v| !v.is_finite()) {
                return Err(read(format!(
                    "{name}[{at}] is {}: an axis holds finite coordinates",
                    axis.values[at]
                )));
            }
            Ok(Array1::from(axis.values))
        };
        let horizontal = axis(format!("horizontal_{k}"))?;
        let vertical = axis(format!("vertical_{k}"))?;
        let shape = (vertical.len(), horizontal.len());
        if values.shape != [shape.0, shape.1] {
            return Err(read(format!(
                "values_{k} has shape {:?} but its axes have {} x {} samples",
                values.shape, shape.0, shape.1
            )));
        }
        let values = Array2::from_shape_vec(shape, values.values)
            .map_err(|e| read(format!("values_{k}: {e}")))?;
        panels.push(PanelField {
            horizontal,
            vertical,
            values,
        });
    }
    if panels.is_empty() {
        return Err(read("it has no array values_0".into()));
    }
    Ok(panels)
}

/// Compares `actual` with `reference` value by value: the largest absolute difference, where it
/// is, and whether it is within `tolerance` (the figure's stress unit, named `unit`; `axes`
/// label the coordinates, e.g. `["x/a", "z/a"]`). Grids
/// must match (same panel count, shapes, and coordinates to 1e-9 of their span); NaN equals
/// NaN, and NaN against a number is an infinite difference.
pub fn compare(
    actual: &[PanelField],
    reference: &[PanelField],
    tolerance: f64,
    unit: &str,
    axes: [&str; 2],
) -> FieldCheck {
    let mut check = FieldCheck {
        tolerance,
        unit: unit.to_string(),
        axes: axes.map(str::to_string),
        largest: None,
        mismatch: None,
    };
    if actual.len() != reference.len() {
        check.mismatch = Some(format!(
            "{} panel(s), the reference has {}",
            actual.len(),
            reference.len()
        ));
        return check;
    }
    for (k, (a, r)) in actual.iter().zip(reference).enumerate() {
        if a.values.dim() != r.values.dim() {
            check.mismatch = Some(format!(
                "panel {k} has {} x {} samples, the reference {} x {}",
                a.values.nrows(),
                a.values.ncols(),
                r.values.nrows(),
                r.values.ncols()
            ));
            return check;
        }
        for (name, ours, theirs) in [
            ("horizontal", &a.horizontal, &r.horizontal),
            ("vertical", &a.vertical, &r.vertical),
        ] {
            let span = theirs
                .iter()
                .fold(0.0f64, |m, v| m.max(v.abs()))
                .max(f64::MIN_POSITIVE);
            // Written so that NaN (in either) is a difference, never a match.
            if ours
                .iter()
                .zip(theirs)
                .any(|(x, y)| (x - y).is_nan() || (x - y).abs() > 1e-9 * span)
            {
                check.mismatch = Some(format!(
                    "panel {k}: the {name} axis differs from the reference's (another range or resolution)"
                ));
                return check;
            }
        }
        for ((j, i), (x, y)) in a
            .values
            .indexed_iter()
            .zip(r.values.iter())
            .map(|((index, x), y)| (index, (x, y)))
        {
            let difference = match (x.is_nan(), y.is_nan()) {
                (true, true) => 0.0,
                (false, false) if x == y => 0.0,
                (false, false) => (x - y).abs(),
                _ => f64::INFINITY,
            };
            let larger = check
                .largest
                .as_ref()
                .is_none_or(|d| difference > d.largest);
            if larger {
                check.largest = Some(FieldDifference {
                    panel: k,
                    largest: difference,
                    at: (a.horizontal[i], a.vertical[j]),
                });
            }
        }
    }
    check
}

#[cfg(test)]
mod tests {
    use super::*;

    fn panel(shift: f64) -> PanelField {
        let horizontal: Array1<f64> = Array1::linspace(-2.0, 2.0, 9);
        let vertical: Array1<f64> = Array1::linspace(0.0, 1.0, 5);
        let values = Array2::from_shape_fn((5, 9), |(j, i)| {
            (horizontal[i] * vertical[j]).sin() + if (j, i) == (3, 6) { shift } else { 0.0 }
        });
        PanelField {
            horizontal,
            vertical,
            values,
        }
    }

    const AXES: [&str; 2] = ["x/a", "z/a"];

    #[test]
    fn round_trip_through_npz_bytes() {
        let panels = vec![panel(0.0), panel(0.5)];
        let bytes = encode(&panels).expect("encodes");
        assert_eq!(decode(&bytes).expect("decodes"), panels);
        // A zip archive: the local file header signature.
        assert_eq!(&bytes[..4], b"PK\x03\x04");
    }

    #[test]
    fn finds_a_change_of_1e_3_and_where_it_is() {
        let reference = vec![panel(0.0), panel(0.0)];
        let same = compare(&reference.clone(), &reference, 1e-4, "p0", AXES);
        assert!(same.passed(), "{}", same.summary());
        assert_eq!(same.largest.as_ref().map(|d| d.largest), Some(0.0));
        let changed = vec![panel(0.0), panel(1e-3)];
        let check = compare(&changed, &reference, 1e-4, "p0", AXES);
        assert!(!check.passed());
        let largest = check.largest.expect("largest");
        assert_eq!(largest.panel, 1);
        assert!((largest.largest - 1e-3).abs() < 1e-15);
        assert_eq!(largest.at, (1.0, 0.75));
        assert!(compare(&changed, &reference, 2e-3, "p0", AXES).passed());
    }

    #[test]
    fn other_grids_are_mismatches_not_differences() {
        let reference = vec![panel(0.0)];
        let two = compare(&[panel(0.0), panel(0.0)], &reference, 1.0, "p0", AXES);
        assert!(!two.passed() && two.mismatch.is_some());
        let mut moved = panel(0.0);
        moved.horizontal[2] += 0.01;
        let check = compare(&[moved], &reference, 1.0, "p0", AXES);
        assert!(check
            .mismatch
            .as_deref()
            .is_some_and(|m| m.contains("horizontal")));
        let mut nan = panel(0.0);
        nan.values[[0, 0]] = f64::NAN;
        assert!(!compare(&[nan.clone()], &reference, 1.0, "p0", AXES).passed());
        assert!(compare(&[nan.clone()], &[nan], 0.0, "p0", AXES).passed());
    }

    #[test]
    fn refuses_other_archives() {
        assert!(decode(b"not a zip").is_err());
        let mut npz = NpzWriter::new(Cursor::new(Vec::new()));
        npz.add_array("pressure", &Array2::<f64>::zeros((2, 2)))
            .expect("add");
        let bytes = npz.finish().expect("finish").into_inner();
        let error = decode(&bytes).expect_err("no values_0");
        assert!(error.to_string().contains("values_0"), "{error}");
    }

    /// Issue 24, class 1: a member declaring shape (100000, 100000) or (3000000000, 1) is
    /// refused by its size (the test process would abort allocating 80 GB otherwise).
    #[test]
    fn a_huge_declared_shape_is_refused_before_allocating() {
        let bytes = encode(&[panel(0.0)]).expect("encodes");
        for shape in ["(100000, 100000)", "(3000000000, 1)"] {
            let mut forged = Vec::new();
            {
                let mut npz = zip::ZipWriter::new(Cursor::new(&mut forged));
                let options = zip::write::SimpleFileOptions::default();
                let mut header = b"\x93NUMPY\x01\x00".to_vec();
                let dict =
                    format!("{{'descr': '<f8', 'fortran_order': False, 'shape': {shape}, }}");
                header.extend_from_slice(&(dict.len() as u16).to_le_bytes());
                header.extend_from_slice(dict.as_bytes());
                header.extend_from_slice(&[0; 16]);
                for name in ["values_0.npy", "horizontal_0.npy", "vertical_0.npy"] {
                    use std::io::Write;
                    npz.start_file(name, options).expect("entry");
                    npz.write_all(&header).expect("write");
                }
                npz.finish().expect("finish");
            }
            assert!(forged.len() < 1024, "{} bytes", forged.len());
            let error = decode(&forged).expect_err(shape).to_string();
            assert!(
                error.contains(&format!("values_0.npy: declares shape {shape}"))
                    && error.contains("--update"),
                "{error}"
            );
        }
        // Members beyond the budget are refused by their declared size.
        let error = decode_within(&bytes, 100).expect_err("budget").to_string();
        assert!(error.contains("more than the 100 bytes allowed"), "{error}");
    }

    /// Issue 24, class 14: a NaN axis in a reference is refused, not a match.
    #[test]
    fn non_finite_axes_are_refused() {
        let mut nan = panel(0.0);
        nan.vertical[1] = f64::NAN;
        let bytes = encode(&[nan.clone()]).expect("encodes");
        let error = decode(&bytes).expect_err("nan axis").to_string();
        assert!(error.contains("vertical_0[1] is NaN"), "{error}");
        // Compared directly, a NaN axis is a mismatch too.
        let check = compare(&[panel(0.0)], &[nan], 1.0, "p0", AXES);
        assert!(check.mismatch.is_some(), "{}", check.summary());
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig {
            cases: 256,
            rng_seed: proptest::test_runner::RngSeed::Fixed(24),
            failure_persistence: None,
            ..proptest::prelude::ProptestConfig::default()
        })]

        /// Issue 24: the mutation test of scenes, extended to reference files. A reference
        /// `.npz` with bytes overwritten (in its zip headers, `.npy` headers or data) or cut
        /// short is refused with a reason or read as a consistent field; never a panic or an
        /// allocation beyond its budget; a field read back compares without panicking, and
        /// its axes are finite.
        #[test]
        fn mutated_reference_files_are_refused_or_consistent(
            edits in proptest::collection::vec((0usize..4096, proptest::prelude::any::<u8>()), 1..6),
            cut in proptest::prelude::any::<proptest::sample::Index>(),
            truncate in proptest::prelude::any::<bool>(),
        ) {
            let panels = vec![panel(0.0), panel(0.25)];
            let mut bytes = encode(&panels).expect("encodes");
            for (at, byte) in edits {
                let at = at % bytes.len();
                bytes[at] = byte;
            }
            if truncate {
                bytes.truncate(cut.index(bytes.len()));
            }
            match decode_within(&bytes, 1 << 20) {
                Err(error) => {
                    let text = error.to_string();
                    proptest::prop_assert!(text.contains("--update"), "{}", text);
                }
                Ok(read) => {
                    for field in &read {
                        proptest::prop_assert_eq!(
                            field.values.dim(),
                            (field.vertical.len(), field.horizontal.len())
                        );
                        proptest::prop_assert!(field.horizontal.iter().all(|v| v.is_finite()));
                        proptest::prop_assert!(field.vertical.iter().all(|v| v.is_finite()));
                    }
                    let check = compare(&panels, &read, 1e-6, "p0", AXES);
                    if read == panels {
                        proptest::prop_assert!(check.mismatch.is_none());
                    }
                }
            }
        }
    }
}
