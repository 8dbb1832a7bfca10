//! The points of `stressfield probe`: rows `x,y,z` in units of a, read within limits.

use std::io::BufRead;

/// A point that could not be read.
#[derive(Debug, thiserror::Error, PartialEq)]
pub enum ProbeError {
    #[error("line {line}: `{text}`: {reason}\nhint: each row is x,y,z in units of a (a header row `x,y,z` and # comments are allowed)")]
    BadRow {
        line: usize,
        text: String,
        reason: String,
    },
    #[error("line {line}: z = {} lies outside the body; z >= 0 points into the body", crate::io::text::number(*.z))]
    OutsideBody { line: usize, z: f64 },
    #[error("line {line}: the point ({}, {}, {}) lies {} a from the contact, farther than the {} a a probe reaches\nhint: beyond it every stress is below 1e-9 p0 (they fall as a/r for a line contact, (a/r)² for a point contact); probe nearer", crate::io::text::number(.point[0]), crate::io::text::number(.point[1]), crate::io::text::number(.point[2]), crate::io::text::number(*.distance), crate::io::text::compact(MAX_DISTANCE_OVER_A))]
    TooFar {
        line: usize,
        point: [f64; 3],
        distance: f64,
    },
    #[error("cannot read the points: {0}")]
    Read(String),
    #[error("no points given\nhint: give rows x,y,z, e.g. 0,0,0.786")]
    Empty,
}

/// How far from the contact's centre a probe point may lie, in units of a. The closed forms
/// keep their precision far beyond (they break down near 1e78 a, where squares of lengths
/// overflow); every stress there is below 1e-9 p0.
pub const MAX_DISTANCE_OVER_A: f64 = 1e9;

/// The longest echo of a bad row in a message, in characters.
const ECHO_CHARS: usize = 80;

/// Reads rows `x,y,z`; blank lines and `#` comments are skipped, and a first row `x,y,z` is
/// taken as a header. At most [`crate::io::input::POINTS_LIMIT`] bytes in all and
/// [`crate::io::input::LINE_LIMIT`] a line; points within [`MAX_DISTANCE_OVER_A`] of the origin.
pub fn read_points(input: impl BufRead) -> Result<Vec<[f64; 3]>, ProbeError> {
    let mut points = Vec::new();
    let mut seen_row = false;
    let lines = crate::io::input::lines(
        input,
        crate::io::input::POINTS_LIMIT,
        crate::io::input::LINE_LIMIT,
    );
    for line in lines {
        let (line_number, line) = line.map_err(|e| ProbeError::Read(e.to_string()))?;
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
            text: crate::io::text::cut(text, ECHO_CHARS),
            reason: reason.into(),
        };
        if fields.len() != 3 {
            return Err(bad(&format!("expected 3 fields, found {}", fields.len())));
        }
        let mut point = [0.0_f64; 3];
        for (value, field) in point.iter_mut().zip(&fields) {
            let shown = crate::io::text::cut(field, 30);
            *value = field
                .parse()
                .map_err(|_| bad(&format!("`{shown}` is not a number")))?;
            if !value.is_finite() {
                return Err(bad(&format!("`{shown}` is not finite")));
            }
        }
        if point[2] < 0.0 {
            return Err(ProbeError::OutsideBody {
                line: line_number,
                z: point[2],
            });
        }
        let distance = point.iter().map(|v| v.abs()).fold(0.0, f64::max);
        if distance > MAX_DISTANCE_OVER_A {
            return Err(ProbeError::TooFar {
                line: line_number,
                point,
                distance,
            });
        }
        points.push(point);
    }
    if points.is_empty() {
        return Err(ProbeError::Empty);
    }
    Ok(points)
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

    #[test]
    fn far_points_and_long_lines_are_refused_with_a_short_echo() {
        assert!(read_points("1e9,0,0\n0,-1e9,1e9\n".as_bytes()).is_ok());
        let error = read_points("0,0,1\n1e79,0,1\n".as_bytes()).expect_err("far");
        assert!(
            matches!(error, ProbeError::TooFar { line: 2, .. }),
            "{error}"
        );
        let text = error.to_string();
        assert!(text.contains("1e79") && text.contains("1e9 a"), "{text}");
        // A bad row of a megabyte is echoed in a few dozen characters.
        let row = format!("0,0,{}\n", "9".repeat(1 << 20));
        let error = read_points(row.as_bytes()).expect_err("long line");
        assert!(error.to_string().contains("64 KiB"), "{error}");
        let row = format!("0,0,{}x\n", "9".repeat(60_000));
        let error = read_points(row.as_bytes()).expect_err("bad number");
        assert!(error.to_string().len() < 500, "{error}");
        assert!(error.to_string().contains("60005 characters"), "{error}");
    }
}
