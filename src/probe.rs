//! Stresses at individual points: CSV in (`x,y,z` in units of a), CSV out (units of p0).

use std::io::{BufRead, Write};

use crate::solution::Solution;

/// Header of the probe output.
pub const HEADER: &str = "x,y,z,sxx,syy,szz,syz,sxz,sxy,s1,s2,s3,von_mises,max_shear";

/// A point that could not be read.
#[derive(Debug, thiserror::Error, PartialEq)]
pub enum ProbeError {
    #[error("line {line}: `{text}`: {reason}\nhint: each row is x,y,z in units of a (a header row `x,y,z` and # comments are allowed)")]
    BadRow {
        line: usize,
        text: String,
        reason: String,
    },
    #[error("line {line}: z = {z} lies outside the body; z >= 0 points into the body")]
    OutsideBody { line: usize, z: f64 },
    #[error("cannot read the points: {0}")]
    Read(String),
    #[error("no points given\nhint: give rows x,y,z, e.g. 0,0,0.786")]
    Empty,
}

/// Reads rows `x,y,z`; blank lines and `#` comments are skipped, and a first row `x,y,z` is
/// taken as a header.
pub fn read_points(input: impl BufRead) -> Result<Vec<[f64; 3]>, ProbeError> {
    let mut points = Vec::new();
    let mut seen_row = false;
    for (index, line) in input.lines().enumerate() {
        let line_number = index + 1;
        let line = line.map_err(|e| ProbeError::Read(e.to_string()))?;
        let text = line.trim();
        if text.is_empty() || text.starts_with('#') {
            continue;
        }
        let fields: Vec<&str> = text.split(',').map(str::trim).collect();
        if !seen_row
            && fields
                .iter()
                .map(|f| f.to_ascii_lowercase())
                .eq(["x", "y", "z"])
        {
            seen_row = true;
            continue;
        }
        seen_row = true;
        let bad = |reason: &str| ProbeError::BadRow {
            line: line_number,
            text: text.to_string(),
            reason: reason.into(),
        };
        if fields.len() != 3 {
            return Err(bad(&format!("expected 3 fields, found {}", fields.len())));
        }
        let mut point = [0.0_f64; 3];
        for (value, field) in point.iter_mut().zip(&fields) {
            *value = field
                .parse()
                .map_err(|_| bad(&format!("`{field}` is not a number")))?;
            if !value.is_finite() {
                return Err(bad(&format!("`{field}` is not finite")));
            }
        }
        if point[2] < 0.0 {
            return Err(ProbeError::OutsideBody {
                line: line_number,
                z: point[2],
            });
        }
        points.push(point);
    }
    if points.is_empty() {
        return Err(ProbeError::Empty);
    }
    Ok(points)
}

/// Writes the header and one row per point, every value in shortest round-trip form (17
/// significant digits at most, exact to the last bit).
pub fn write_csv(
    out: &mut impl Write,
    solution: &Solution,
    points: &[[f64; 3]],
) -> std::io::Result<()> {
    writeln!(out, "{HEADER}")?;
    for &[x, y, z] in points {
        let s = solution.stress_over_p0(x, y, z);
        let [s1, s2, s3] = s.principal();
        writeln!(
            out,
            "{x},{y},{z},{},{},{},{},{},{},{s1},{s2},{s3},{},{}",
            s.xx,
            s.yy,
            s.zz,
            s.yz,
            s.xz,
            s.xy,
            s.von_mises(),
            s.max_shear()
        )?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_header_comments_and_rows() {
        let text = "# points\nx, y, z\n0,0,0.786\n\n1.5,0,0\n";
        assert_eq!(
            read_points(text.as_bytes()).expect("valid"),
            vec![[0.0, 0.0, 0.786], [1.5, 0.0, 0.0]]
        );
    }

    #[test]
    fn rejects_bad_rows_with_line_numbers() {
        assert!(matches!(
            read_points("0,0\n".as_bytes()),
            Err(ProbeError::BadRow { line: 1, .. })
        ));
        assert!(matches!(
            read_points("0,0,0\n0,abc,1\n".as_bytes()),
            Err(ProbeError::BadRow { line: 2, .. })
        ));
        assert_eq!(
            read_points("0,0,-0.1\n".as_bytes()),
            Err(ProbeError::OutsideBody { line: 1, z: -0.1 })
        );
        assert_eq!(
            read_points("# nothing\n".as_bytes()),
            Err(ProbeError::Empty)
        );
        assert!(matches!(
            read_points("0,0,NaN\n".as_bytes()),
            Err(ProbeError::BadRow { .. })
        ));
    }
}
