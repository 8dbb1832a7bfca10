//! Reading measured surfaces: an ASCII height matrix, XYZ rows on a regular grid, or an
//! ISO 25178-72 `.x3p` file ([`super::x3p`]), chosen by the file's extension.
//!
//! ## ASCII height matrix (`.asc`, `.txt`, `.dat`, `.csv`, anything else)
//! One line per row of samples (row = y), values separated by spaces, tabs or commas. Lines
//! starting with `#` are comments, except the header lines of Gwyddion's "ASCII data matrix"
//! export, which give the size and the height unit:
//!
//! ```text
//! # Width: 100 um          (the map's extent along x, nx dx)
//! # Height: 100 um         (along y, ny dy)
//! # Value units: um        (the unit of the heights)
//! ```
//!
//! Without them the caller gives the spacing and the height unit ([`ReadOptions`]); given
//! both, they must agree.
//!
//! ## XYZ (`.xyz`)
//! Three numbers per line, x, y and z, the nodes of a regular grid in any order (as the
//! traction CSV reader takes them, [`crate::io::grid_table`]); x and y in the length unit and z in
//! the height unit of [`ReadOptions`] (both default to metres).
//!
//! ## NumPy (`.npy`)
//! A 2-D float64 array `[rows, columns]` (row = y), as `contact --pressure`, `surface --heights`
//! and `wear --heights-out` write them: heights in metres unless the caller gives a height
//! unit; the spacing is the caller's (the file holds none).
//!
//! ## Missing points
//! `NaN` (or any non-finite value) is refused with its row and column, unless the caller asks
//! for [`Fill::Interpolate`]: each missing height becomes the mean of its valid neighbours,
//! repeated (Gauss–Seidel relaxation of Laplace's equation with the valid heights fixed) until
//! the largest change is below 1e-9 of the height range.

use std::path::Path;

use ndarray::Array2;

pub use super::samples::{interpolate_missing, Fill, ReadError};
use super::HeightMap;
use crate::io::text::cut;
use crate::io::units::{self, Dimension};

/// What the file may not say itself.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct ReadOptions {
    /// `[dx, dy]` in m (ASCII without a size header); the unit of x and y of an XYZ file is
    /// taken as metres unless `xyz_length_unit_m` says otherwise.
    pub spacing_m: Option<[f64; 2]>,
    /// The unit of the heights in m (1e-6 for um), unless the file says it.
    pub height_unit_m: Option<f64>,
    /// XYZ files: the unit of x and y in m.
    pub xyz_length_unit_m: Option<f64>,
    pub fill: Fill,
}

/// The size in m of a length unit (`m`, `mm`, `um`, `µm`, `nm`, `pm`, ...: those of scenes,
/// [`units::factor`]).
pub fn length_unit_m(unit: &str) -> Option<f64> {
    units::factor(unit, Dimension::Length)
}

/// The largest file read, in bytes: a quarter of the memory this machine allows for fields,
/// at most 2 GiB (every 4 bytes of text may be one height of 8 bytes, plus the text itself).
pub fn file_size_limit() -> u64 {
    (crate::field::memory_limit_bytes() as u64 / 4).min(2 << 30)
}

fn read_text(path: &Path) -> Result<String, ReadError> {
    let name = path.display().to_string();
    let io = |source| ReadError::Io {
        path: name.clone(),
        source,
    };
    let size = std::fs::metadata(path).map_err(io)?.len();
    let limit = file_size_limit();
    if size > limit {
        return Err(ReadError::TooLarge {
            path: name,
            size_mib: size >> 20,
            limit_mib: limit >> 20,
            needed_mib: (size + size * 2) >> 20,
        });
    }
    // Counted as read too: a device or a pipe (`/dev/zero`) has no size beforehand.
    crate::io::input::read_to_string(path, limit).map_err(|e| match e {
        crate::io::input::InputError::Io(source) => io(source),
        crate::io::input::InputError::TooLarge { limit } => ReadError::TooLarge {
            path: name.clone(),
            size_mib: (limit >> 20) + 1,
            limit_mib: limit >> 20,
            needed_mib: (limit * 3) >> 20,
        },
        other => ReadError::Format {
            path: name.clone(),
            message: other.to_string(),
        },
    })
}

/// Reads a surface file (see the module doc for the formats).
pub fn read_surface(path: &Path, options: &ReadOptions) -> Result<HeightMap, ReadError> {
    let name = path.display().to_string();
    let extension = path
        .extension()
        .map(|e| e.to_string_lossy().to_ascii_lowercase())
        .unwrap_or_default();
    match extension.as_str() {
        "x3p" => {
            let size_limit = file_size_limit();
            let map = super::x3p::read(path, size_limit, options.fill)?;
            // x3p heights are in metres (the CZ increment scales them).
            agree(
                &map,
                options.spacing_m,
                options.height_unit_m.map(|u| (u, 1.0)),
                &name,
            )?;
            Ok(map)
        }
        "npy" => read_npy(path, &name, options),
        "xyz" => {
            let map = parse_xyz(&read_text(path)?, &name, options)?;
            agree(&map, options.spacing_m, None, &name)?;
            Ok(map)
        }
        _ => parse_ascii(&read_text(path)?, &name, options),
    }
}

/// Reads a `.npy` height matrix (module doc).
fn read_npy(path: &Path, name: &str, options: &ReadOptions) -> Result<HeightMap, ReadError> {
    let format = |message: String| ReadError::Format {
        path: name.to_string(),
        message,
    };
    let io = |source| ReadError::Io {
        path: name.to_string(),
        source,
    };
    let size = std::fs::metadata(path).map_err(io)?.len();
    let limit = file_size_limit();
    if size > limit {
        return Err(ReadError::TooLarge {
            path: name.to_string(),
            size_mib: size >> 20,
            limit_mib: limit >> 20,
            needed_mib: size >> 20,
        });
    }
    let bytes = std::fs::read(path).map_err(io)?;
    let array = crate::io::archive::npy_f64(&bytes).map_err(format)?;
    let [ny, nx] = match array.shape.as_slice() {
        &[ny, nx] => [ny, nx],
        other => {
            return Err(format(format!(
                "a height map is a 2-D array [rows, columns], this one has shape {other:?}"
            )))
        }
    };
    let Some(spacing) = options.spacing_m else {
        return Err(format(
            "an .npy file holds only heights: give its sample spacing (--spacing 1um, or spacing = \"1 um\" in the scene)".to_string(),
        ));
    };
    let unit = options.height_unit_m.unwrap_or(1.0);
    let mut heights = Array2::from_shape_vec((ny, nx), array.values)
        .map_err(|e| format(e.to_string()))?
        .mapv(|h| h * unit);
    if let Some(((row, column), _)) = heights.indexed_iter().find(|(_, v)| !v.is_finite()) {
        match options.fill {
            Fill::Refuse => {
                return Err(format(format!(
                    "row {row}, column {column} is missing (not finite); fill missing points with fill = \"interpolate\" (--fill interpolate) or repair the file"
                )))
            }
            Fill::Interpolate => interpolate_missing(&mut heights).map_err(format)?,
        }
    }
    HeightMap::new(heights, spacing).map_err(|source| ReadError::Surface {
        path: name.to_string(),
        source,
    })
}

/// A spacing or a height unit the caller gave (`--spacing`, `--height-unit`, or the scene's
/// `spacing`, `height_unit`) must agree with what an x3p or XYZ file says itself, as with an
/// ASCII file's header: a contradiction is refused, naming both values, never ignored.
/// `height_unit_m` is `(given, the file's)`.
fn agree(
    map: &HeightMap,
    spacing_m: Option<[f64; 2]>,
    height_unit_m: Option<(f64, f64)>,
    path: &str,
) -> Result<(), ReadError> {
    let close = |a: f64, b: f64| (a - b).abs() <= 1e-6 * a.abs().max(b.abs());
    let format = |message: String| ReadError::Format {
        path: path.to_string(),
        message,
    };
    let file = map.spacing_m();
    if let Some(given) = spacing_m {
        if !(close(file[0], given[0]) && close(file[1], given[1])) {
            return Err(format(format!(
                "the file's coordinates give a spacing of {:.6e} x {:.6e} m, but a spacing of {:.6e} x {:.6e} m was given (--spacing, or spacing in the scene); remove it, the file says its spacing",
                file[0], file[1], given[0], given[1]
            )));
        }
    }
    if let Some((given, own)) = height_unit_m {
        if !close(given, own) {
            return Err(format(format!(
                "the file's heights are in units of {own:e} m (an x3p's are in metres, scaled by its CZ increment), but {given:e} m was given (--height-unit, or height_unit in the scene); remove it"
            )));
        }
    }
    Ok(())
}

/// A number of a height file: NaN or an infinity written as such (`nan`, `-inf`) is a missing
/// point, but a number too large for a float (`1e400`) is an error, never a missing point.
fn value(field: &str) -> Result<f64, String> {
    let shown = cut(field, 40);
    let value: f64 = field
        .parse()
        .map_err(|_| format!("`{shown}` is not a number"))?;
    let spelled = field
        .trim_start_matches(['+', '-'])
        .to_ascii_lowercase()
        .starts_with("inf");
    if value.is_infinite() && !spelled {
        return Err(format!(
            "`{shown}` is out of range (at most 1.8e308 in size); repair the file (a missing point is written NaN)"
        ));
    }
    Ok(value)
}

/// A field of a line: its text and its column (1-based, in characters).
fn fields(line: &str) -> impl Iterator<Item = (usize, &str)> {
    let mut start = None;
    let mut out = Vec::new();
    for (offset, c) in line.char_indices() {
        let separator = c == ',' || c == ';' || c.is_whitespace();
        match (separator, start) {
            (false, None) => start = Some(offset),
            (true, Some(s)) => {
                out.push((s, &line[s..offset]));
                start = None;
            }
            _ => {}
        }
    }
    if let Some(s) = start {
        out.push((s, &line[s..]));
    }
    out.into_iter()
        .map(move |(s, text)| (line[..s].chars().count() + 1, text))
}

/// Parses an ASCII height matrix.
pub fn parse_ascii(text: &str, path: &str, options: &ReadOptions) -> Result<HeightMap, ReadError> {
    let at = |line: usize, column: usize, message: String| ReadError::At {
        path: path.to_string(),
        line,
        column,
        message,
    };
    let format = |message: String| ReadError::Format {
        path: path.to_string(),
        message,
    };
    let (mut width, mut height, mut unit) = (None, None, None);
    let mut rows: Vec<Vec<f64>> = Vec::new();
    // (line, column) of each missing value, in order.
    let mut missing: Vec<(usize, usize, usize, usize)> = Vec::new();
    let mut first_line = 0;
    for (index, line) in crate::io::text::lines(text).enumerate() {
        let number = index + 1;
        let trimmed = line.trim();
        if trimmed.is_empty() {
            continue;
        }
        if let Some(comment) = trimmed.strip_prefix('#') {
            if let Some((key, value)) = comment.split_once(':') {
                let key = key.trim().to_ascii_lowercase();
                let header = |what: &str, reason: String| {
                    at(
                        number,
                        1,
                        format!("cannot read the {what}: {reason}; write e.g. `# {key}: 100 um`"),
                    )
                };
                let length = |what: &str| {
                    units::parse(value, Dimension::Length).map_err(|reason| header(what, reason))
                };
                match key.as_str() {
                    "width" => width = Some(length("width")?),
                    "height" => height = Some(length("height")?),
                    "value units" => {
                        unit = Some(length_unit_m(value).ok_or_else(|| {
                            at(
                                number,
                                1,
                                format!(
                                    "unknown height unit `{}`; use one of: {}",
                                    cut(value.trim(), 40),
                                    Dimension::Length.unit_list()
                                ),
                            )
                        })?)
                    }
                    _ => {}
                }
            }
            continue;
        }
        let mut row = Vec::new();
        for (column, field) in fields(line) {
            let value = value(field).map_err(|m| at(number, column, m))?;
            if !value.is_finite() {
                missing.push((number, column, rows.len(), row.len()));
            }
            row.push(value);
        }
        if let Some(first) = rows.first() {
            if row.len() != first.len() {
                return Err(at(
                    number,
                    1,
                    format!(
                        "this row has {} values, the first (line {first_line}) has {}: every row of the matrix needs the same number",
                        row.len(),
                        first.len()
                    ),
                ));
            }
        } else {
            first_line = number;
        }
        rows.push(row);
    }
    let (ny, nx) = (rows.len(), rows.first().map_or(0, Vec::len));
    if ny < 2 || nx < 2 {
        return Err(format(format!(
            "a height map needs at least 2 rows of 2 values, got {ny} row(s) of {nx}"
        )));
    }
    let from_header = match (width, height) {
        (Some(w), Some(h)) => Some([w / nx as f64, h / ny as f64]),
        (Some(w), None) => Some([w / nx as f64, w / nx as f64]),
        (None, Some(h)) => Some([h / ny as f64, h / ny as f64]),
        (None, None) => None,
    };
    let spacing = match (from_header, options.spacing_m) {
        (Some(header), Some(given)) => {
            let close = |a: f64, b: f64| (a - b).abs() <= 1e-6 * a.abs().max(b.abs());
            if !(close(header[0], given[0]) && close(header[1], given[1])) {
                return Err(format(format!(
                    "the header's size gives a spacing of {:.6e} x {:.6e} m, but {:.6e} x {:.6e} m was given; remove one of them",
                    header[0], header[1], given[0], given[1]
                )));
            }
            header
        }
        (Some(header), None) => header,
        (None, Some(given)) => given,
        (None, None) => {
            return Err(format(
                "the file does not say its sample spacing: give it (--spacing 1um, or spacing = \"1 um\" in the scene), or add a header line `# Width: 100 um`".to_string(),
            ))
        }
    };
    let unit = match (unit, options.height_unit_m) {
        (Some(header), Some(given)) if (header - given).abs() > 1e-12 * header => {
            return Err(format(format!(
                "the header says the heights are in units of {header:e} m, but {given:e} m was given; remove one of them"
            )))
        }
        (Some(u), _) | (None, Some(u)) => u,
        (None, None) => {
            return Err(format(
                "the file does not say the unit of its heights: give it (--height-unit um, or height_unit = \"um\"), or add a header line `# Value units: um`".to_string(),
            ))
        }
    };
    let mut heights = Array2::from_shape_fn((ny, nx), |(j, i)| rows[j][i] * unit);
    if let Some(&(line, column, row, col)) = missing.first() {
        match options.fill {
            Fill::Refuse => {
                return Err(at(
                    line,
                    column,
                    format!(
                        "row {row}, column {col} is missing ({} missing point(s) in all); fill them with fill = \"interpolate\" (--fill interpolate) or repair the file",
                        missing.len()
                    ),
                ))
            }
            Fill::Interpolate => interpolate_missing(&mut heights).map_err(format)?,
        }
    }
    HeightMap::new(heights, spacing).map_err(|source| ReadError::Surface {
        path: path.to_string(),
        source,
    })
}

/// Parses XYZ rows.
pub fn parse_xyz(text: &str, path: &str, options: &ReadOptions) -> Result<HeightMap, ReadError> {
    let at = |line: usize, column: usize, message: String| ReadError::At {
        path: path.to_string(),
        line,
        column,
        message,
    };
    let format = |message: String| ReadError::Format {
        path: path.to_string(),
        message,
    };
    let mut points = Vec::new();
    let mut values = Vec::new();
    let mut missing = None;
    // The finest digit the coordinates were written to: instruments round them (see
    // `grid_table::assemble`).
    let mut rounding = [f64::INFINITY; 2];
    for (index, line) in crate::io::text::lines(text).enumerate() {
        let number = index + 1;
        let trimmed = line.trim();
        if trimmed.is_empty() || trimmed.starts_with('#') {
            continue;
        }
        let row: Vec<(usize, &str)> = fields(line).collect();
        if row.len() != 3 {
            return Err(at(
                number,
                1,
                format!("expected three values x, y, z, got {}", row.len()),
            ));
        }
        let mut xyz = [0.0f64; 3];
        for (k, (_, field)) in row.iter().take(2).enumerate() {
            if let Some(unit) = crate::io::grid_table::last_digit(field) {
                rounding[k] = rounding[k].min(unit);
            }
        }
        for (k, (column, field)) in row.iter().enumerate() {
            xyz[k] = value(field).map_err(|m| at(number, *column, m))?;
            if !xyz[k].is_finite() && (k < 2 || missing.is_none()) {
                if k < 2 {
                    return Err(at(number, *column, "x and y must be finite".to_string()));
                }
                missing = Some((number, *column));
            }
        }
        points.push([xyz[0], xyz[1]]);
        values.push(xyz[2]);
    }
    let rounding = rounding.map(|unit| if unit.is_finite() { unit } else { 0.0 });
    let grid = crate::io::grid_table::assemble(&points, rounding).map_err(|m| {
        format(m.replace(
            "give the tractions at the centres of a regular grid",
            "give the heights on a regular grid",
        ))
    })?;
    let length = options.xyz_length_unit_m.unwrap_or(1.0);
    let unit = options.height_unit_m.unwrap_or(1.0);
    let [ny, nx] = grid.shape;
    let mut heights = Array2::zeros((ny, nx));
    for (value, [j, i]) in values.iter().zip(&grid.nodes) {
        heights[[*j, *i]] = value * unit;
    }
    if let Some((line, column)) = missing {
        match options.fill {
            Fill::Refuse => {
                return Err(at(
                    line,
                    column,
                    "the height is missing; fill missing points with fill = \"interpolate\" (--fill interpolate) or repair the file".to_string(),
                ))
            }
            Fill::Interpolate => interpolate_missing(&mut heights).map_err(format)?,
        }
    }
    // A spacing given for rounded coordinates is the finer value where the file's agrees with
    // it to its rounding; otherwise the file's stands, and `agree` refuses the contradiction.
    let mut spacing = [grid.step[0] * length, grid.step[1] * length];
    if let Some(given) = options.spacing_m {
        for k in 0..2 {
            let allowed = grid.step_uncertainty[k] * length;
            if allowed > 0.0 && (given[k] - spacing[k]).abs() <= allowed {
                spacing[k] = given[k];
            }
        }
    }
    HeightMap::new(heights, spacing).map_err(|source| ReadError::Surface {
        path: path.to_string(),
        source,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ascii(text: &str, options: ReadOptions) -> Result<HeightMap, ReadError> {
        parse_ascii(text, "s.asc", &options)
    }

    #[test]
    fn reads_a_gwyddion_matrix_with_its_header() {
        let text =
            "# Channel: Height\n# Width: 3 um\n# Height: 1 um\n# Value units: nm\n1 2\t3\n4,5,6\n";
        let map = ascii(text, ReadOptions::default()).expect("valid");
        assert_eq!(map.shape(), [2, 3]);
        let [dx, dy] = map.spacing_m();
        assert!((dx - 1e-6).abs() < 1e-18 && (dy - 0.5e-6).abs() < 1e-18);
        assert!((map.heights_m()[[1, 2]] - 6e-9).abs() < 1e-21);
        // Without a header, from the options; the header and options must agree.
        let bare = "1 2\n3 4\n";
        let options = ReadOptions {
            spacing_m: Some([2e-6, 2e-6]),
            height_unit_m: Some(1e-6),
            ..ReadOptions::default()
        };
        let map = ascii(bare, options).expect("valid");
        assert_eq!(map.heights_m()[[1, 0]], 3e-6);
        let error = ascii(text, options).expect_err("conflict");
        assert!(error.to_string().contains("remove one"), "{error}");
    }

    #[test]
    fn bad_matrices_name_the_line_and_column() {
        let options = ReadOptions {
            spacing_m: Some([1e-6, 1e-6]),
            height_unit_m: Some(1e-6),
            ..ReadOptions::default()
        };
        let cases = [
            ("1 2 3\n4 5\n", "line 2, column 1", "same number"),
            ("1 2\n3 x4\n", "line 2, column 3", "`x4` is not a number"),
            (
                "1 2\n3 NaN\n",
                "line 2, column 3",
                "row 1, column 1 is missing",
            ),
            ("1 2 3\n", "", "at least 2 rows"),
            (
                "# Width: 10 furlongs\n1 2\n3 4\n",
                "line 1",
                "cannot read the width",
            ),
        ];
        for (text, place, fragment) in cases {
            let error = ascii(text, options).expect_err(text).to_string();
            assert!(
                error.contains(place) && error.contains(fragment),
                "{text:?}: {error}"
            );
        }
        let no_spacing = ReadOptions {
            height_unit_m: Some(1e-6),
            ..ReadOptions::default()
        };
        assert!(ascii("1 2\n3 4\n", no_spacing)
            .expect_err("spacing")
            .to_string()
            .contains("--spacing"));
        let zero = ReadOptions {
            spacing_m: Some([0.0, 1e-6]),
            ..options
        };
        assert!(ascii("1 2\n3 4\n", zero)
            .expect_err("zero")
            .to_string()
            .contains("spacing must lie between"));
    }

    #[test]
    fn missing_points_are_interpolated_on_request() {
        let options = ReadOptions {
            spacing_m: Some([1e-6, 1e-6]),
            height_unit_m: Some(1e-6),
            fill: Fill::Interpolate,
            ..ReadOptions::default()
        };
        // A plane z = x + 2y (um) with two holes: harmonic interpolation restores it exactly.
        let text = "0 1 2 3\n2 nan 4 5\n4 5 NaN 7\n6 7 8 9\n";
        let map = ascii(text, options).expect("filled");
        assert!((map.heights_m()[[1, 1]] - 3e-6).abs() < 1e-13);
        assert!((map.heights_m()[[2, 2]] - 6e-6).abs() < 1e-13);
        let all = ReadOptions { ..options };
        assert!(ascii("nan nan\nnan nan\n", all).is_err());
    }

    #[test]
    fn xyz_rows_in_any_order() {
        let text = "# x y z\n1e-6 0 3\n0 0 1\n0 2e-6 5\n1e-6 2e-6 7\n";
        let options = ReadOptions {
            height_unit_m: Some(1e-9),
            ..ReadOptions::default()
        };
        let map = parse_xyz(text, "s.xyz", &options).expect("valid");
        assert_eq!(map.shape(), [2, 2]);
        assert_eq!(map.spacing_m(), [1e-6, 2e-6]);
        assert!((map.heights_m()[[1, 1]] - 7e-9).abs() < 1e-20);
        let error = parse_xyz("0 0 1\n1 0 2\n0 1 3\n0 1 4\n", "s.xyz", &options)
            .expect_err("twice")
            .to_string();
        assert!(
            error.contains("appears twice") || error.contains("every node"),
            "{error}"
        );
        let error = parse_xyz("0 0 1\n1 0\n", "s.xyz", &options)
            .expect_err("short")
            .to_string();
        assert!(
            error.contains("line 2") && error.contains("three values"),
            "{error}"
        );
    }

    /// Issue 24, class 8: an x3p says its spacing and its heights' unit (metres) itself: a
    /// `--spacing` or `--height-unit` that contradicts it is refused naming both values; one
    /// that agrees is accepted.
    #[test]
    fn flags_contradicting_an_x3p_are_refused() {
        let heights = Array2::from_shape_fn((6, 8), |(j, i)| (i as f64 - j as f64) * 1e-8);
        let map = HeightMap::new(heights, [1e-6, 2e-6]).expect("map");
        let dir = tempfile::tempdir().expect("dir");
        let path = dir.path().join("s.x3p");
        std::fs::write(&path, super::super::x3p::write(&map).expect("x3p")).expect("write");
        let read = |options: ReadOptions| read_surface(&path, &options);
        assert_eq!(read(ReadOptions::default()).expect("plain"), map);
        let agreeing = ReadOptions {
            spacing_m: Some([1e-6, 2e-6]),
            height_unit_m: Some(1.0),
            ..ReadOptions::default()
        };
        assert_eq!(read(agreeing).expect("agreeing"), map);
        let error = read(ReadOptions {
            height_unit_m: Some(1e-6),
            ..ReadOptions::default()
        })
        .expect_err("a height unit of um")
        .to_string();
        assert!(
            error.contains("1e-6 m was given (--height-unit") && error.contains("metres"),
            "{error}"
        );
        let error = read(ReadOptions {
            spacing_m: Some([1e-6, 1e-6]),
            ..ReadOptions::default()
        })
        .expect_err("another spacing")
        .to_string();
        assert!(
            error.contains("2.000000e-6") && error.contains("was given (--spacing"),
            "{error}"
        );
    }

    /// Issue 24, class 17: an XYZ export with coordinates rounded to 4 decimals (µm, step
    /// 0.0390625 µm written 0.0391, 0.0781, ...) is read; a --spacing that agrees to the
    /// rounding is taken as the finer value, one that does not is refused.
    #[test]
    fn xyz_coordinates_rounded_as_instruments_write_them() {
        let step = 0.0390625;
        let mut text = String::from("# x (um) y (um) z (nm)\n");
        for j in 0..9 {
            for i in 0..33 {
                let z = (i * j) as f64;
                text += &format!("{:.4}\t{:.4}\t{z}\n", i as f64 * step, j as f64 * step);
            }
        }
        let options = ReadOptions {
            xyz_length_unit_m: Some(1e-6),
            height_unit_m: Some(1e-9),
            ..ReadOptions::default()
        };
        let map = parse_xyz(&text, "s.xyz", &options).expect("rounded coordinates");
        assert_eq!(map.shape(), [9, 33]);
        let [dx, dy] = map.spacing_m();
        assert!((dx / (step * 1e-6) - 1.0).abs() < 1e-4, "{dx}");
        assert!((dy / (step * 1e-6) - 1.0).abs() < 1e-3, "{dy}");
        assert!((map.heights_m()[[8, 32]] - 256e-9).abs() < 1e-18);
        let given = ReadOptions {
            spacing_m: Some([step * 1e-6, step * 1e-6]),
            ..options
        };
        let map = parse_xyz(&text, "s.xyz", &given).expect("agreeing spacing");
        assert_eq!(map.spacing_m(), [step * 1e-6, step * 1e-6]);
        let wrong = ReadOptions {
            spacing_m: Some([0.04e-6, 0.04e-6]),
            ..options
        };
        let map = parse_xyz(&text, "s.xyz", &wrong).expect("parsed");
        let error = agree(&map, wrong.spacing_m, None, "s.xyz").expect_err("contradiction");
        assert!(
            error.to_string().contains("was given (--spacing"),
            "{error}"
        );
    }

    /// Issue 24, class 7: an overflowing number is an error naming its line and column, never
    /// a missing point (not even with interpolation asked for).
    #[test]
    fn an_overflowing_number_is_an_error_not_a_missing_point() {
        let options = ReadOptions {
            spacing_m: Some([1e-6, 1e-6]),
            height_unit_m: Some(1e-6),
            fill: Fill::Interpolate,
            ..ReadOptions::default()
        };
        let error = ascii("1 2\n3 1e400\n", options)
            .expect_err("overflow")
            .to_string();
        assert!(
            error.contains("line 2, column 3") && error.contains("`1e400` is out of range"),
            "{error}"
        );
        let error = parse_xyz("0 0 1\n1 0 -1e999\n0 1 3\n1 1 4\n", "s.xyz", &options)
            .expect_err("overflow")
            .to_string();
        assert!(
            error.contains("line 2, column 5") && error.contains("out of range"),
            "{error}"
        );
        // Spelled infinities and NaN stay missing points.
        assert!(ascii("1 2 0\n3 -inf 0\n0 0 0\n", options).is_ok());
    }

    /// Issue 24, classes 9, 10 and 16: exponents in headers, a byte-order mark, lone CR line
    /// endings, and long header values echoed cut.
    #[test]
    fn headers_take_exponents_marks_and_old_mac_endings() {
        let text = "# Width: 1.6e-5 m\r# Height: 8e-6m\r# Value units: μm\r1 2\r3 4\r";
        let map = ascii(text, ReadOptions::default()).expect("valid");
        assert_eq!(map.shape(), [2, 2]);
        let [dx, dy] = map.spacing_m();
        assert!((dx - 8e-6).abs() < 1e-18 && (dy - 4e-6).abs() < 1e-18);
        assert!((map.heights_m()[[1, 1]] - 4e-6).abs() < 1e-18);
        let dir = tempfile::tempdir().expect("dir");
        let path = dir.path().join("bom.asc");
        std::fs::write(&path, format!("\u{feff}{text}")).expect("write");
        assert_eq!(
            read_surface(&path, &ReadOptions::default()).expect("bom"),
            map
        );
        let long = format!("# Width: {}\n1 2\n3 4\n", "9".repeat(100_000));
        let error = ascii(&long, ReadOptions::default())
            .expect_err("long")
            .to_string();
        assert!(
            error.contains("line 1") && error.len() < 500,
            "{} characters",
            error.len()
        );
    }

    /// Issue 24, class 8: a spacing that contradicts an XYZ file's coordinates is refused as
    /// an ASCII header's is, naming both; one that agrees is accepted.
    #[test]
    fn a_spacing_contradicting_an_xyz_file_is_refused() {
        let dir = tempfile::tempdir().expect("dir");
        let path = dir.path().join("grid.xyz");
        let rows: String = (0..4)
            .flat_map(|j| (0..4).map(move |i| format!("{}e-6 {}e-6 {}e-9\n", i, j, i * j)))
            .collect();
        std::fs::write(&path, rows).expect("file");
        let with = |spacing: f64| ReadOptions {
            spacing_m: Some([spacing, spacing]),
            ..ReadOptions::default()
        };
        read_surface(&path, &with(1e-6)).expect("agrees");
        let error = read_surface(&path, &with(2e-6)).expect_err("conflict");
        assert!(
            error.to_string().contains("was given (--spacing"),
            "{error}"
        );
    }
}
