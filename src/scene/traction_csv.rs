//! Surface tractions given by the user as a CSV grid: rows `x,y,p[,qx][,qy]` at the centres of
//! a regular grid of cells, in the units the scene states.

use ndarray::Array2;

/// The most nodes along x or along y.
pub const MAX_NODES_PER_SIDE: usize = 4096;

/// The largest traction of a table, where it was read.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Largest {
    /// `|value|`, in the file's unit.
    pub magnitude: f64,
    pub line: usize,
    /// The column: `p`, `qx` or `qy`.
    pub column: &'static str,
}

/// Tractions read from a CSV file, still in the file's units.
#[derive(Clone, Debug, PartialEq)]
pub struct TractionTable {
    /// Centre of cell `[0, 0]` (smallest x and y).
    pub first_centre: [f64; 2],
    /// `[dx, dy]`.
    pub cell: [f64; 2],
    /// `[y, x]` arrays; absent columns are `None`.
    pub pressure: Array2<f64>,
    pub shear_x: Option<Array2<f64>>,
    pub shear_y: Option<Array2<f64>>,
    /// The largest `|p|`, `|qx|` or `|qy|` (for the caller's check after unit conversion).
    pub largest: Largest,
}

/// Reads the table. The header names the columns (`x`, `y`, `p`, and optionally `qx`, `qy`, in
/// any order); `#` comments and blank lines are skipped; the rows may come in any order but must
/// cover every node of a regular grid (at least 2 x 2) exactly once. `p >= 0` (compressive
/// contact pressure). Lines are at most [`crate::io::input::LINE_LIMIT`] bytes, and the grid at
/// most [`MAX_NODES_PER_SIDE`] nodes along each side. Errors name the line and the fix.
pub fn read(text: &str) -> Result<TractionTable, String> {
    if let Some((number, _)) = crate::io::text::lines(text)
        .enumerate()
        .find(|(_, l)| l.len() > crate::io::input::LINE_LIMIT)
    {
        return Err(format!(
            "line {}: longer than the {} allowed for a line: is it the right file?",
            number + 1,
            crate::io::text::bytes(crate::io::input::LINE_LIMIT as u64)
        ));
    }
    let mut lines = crate::io::text::lines(text)
        .enumerate()
        .map(|(i, l)| (i + 1, l.trim()))
        .filter(|(_, l)| !l.is_empty() && !l.starts_with('#'));
    let (header_line, header) = lines.next().ok_or(
        "the file has no header row; the first row must name the columns: x,y,p[,qx][,qy]",
    )?;
    let names: Vec<&str> = header.split(',').map(str::trim).collect();
    let column = |name: &str| names.iter().position(|n| *n == name);
    let (Some(ix), Some(iy), Some(ip)) = (column("x"), column("y"), column("p")) else {
        return Err(format!(
            "line {header_line}: the header must name the columns x, y and p (and optionally qx, qy), got `{}`",
            crate::io::text::cut(header, 60)
        ));
    };
    if let Some(unknown) = names
        .iter()
        .find(|n| !["x", "y", "p", "qx", "qy"].contains(n))
    {
        return Err(format!(
            "line {header_line}: unknown column `{}`; the columns are x, y, p, qx, qy",
            crate::io::text::cut(unknown, 40)
        ));
    }
    if let Some((second, name)) = names
        .iter()
        .enumerate()
        .find(|(i, n)| names[..*i].contains(n))
    {
        return Err(format!(
            "line {header_line}: the column `{name}` is named twice (columns {} and {}); each of x, y, p, qx, qy may appear once",
            column(name).map_or(0, |first| first + 1),
            second + 1
        ));
    }
    let (iqx, iqy) = (column("qx"), column("qy"));
    let max_rows = MAX_NODES_PER_SIDE * MAX_NODES_PER_SIDE;
    let mut rows: Vec<[f64; 5]> = Vec::new();
    // The finest digit the coordinates were written to (see `grid_table::assemble`).
    let mut rounding = [f64::INFINITY; 2];
    let mut largest = Largest {
        magnitude: 0.0,
        line: header_line,
        column: "p",
    };
    for (number, line) in lines {
        if rows.len() == max_rows {
            return Err(format!(
                "line {number}: more than {max_rows} rows; a grid has at most {MAX_NODES_PER_SIDE} x {MAX_NODES_PER_SIDE} nodes"
            ));
        }
        let fields: Vec<&str> = line.split(',').map(str::trim).collect();
        if fields.len() != names.len() {
            return Err(format!(
                "line {number}: expected {} fields like the header, got {}",
                names.len(),
                fields.len()
            ));
        }
        let value = |index: Option<usize>, name: &str| -> Result<f64, String> {
            let Some(index) = index else { return Ok(0.0) };
            let v: f64 = fields[index].parse().map_err(|_| {
                format!(
                    "line {number}: {name} = `{}` is not a number",
                    crate::io::text::cut(fields[index], 40)
                )
            })?;
            if !v.is_finite() {
                return Err(format!("line {number}: {name} must be finite, got {v}"));
            }
            Ok(v)
        };
        for (k, index) in [ix, iy].into_iter().enumerate() {
            if let Some(unit) = crate::io::grid_table::last_digit(fields[index]) {
                rounding[k] = rounding[k].min(unit);
            }
        }
        let row = [
            value(Some(ix), "x")?,
            value(Some(iy), "y")?,
            value(Some(ip), "p")?,
            value(iqx, "qx")?,
            value(iqy, "qy")?,
        ];
        if row[2] < 0.0 {
            return Err(format!(
                "line {number}: p = {} is negative; a contact pressure pushes on the surface (p >= 0)",
                row[2]
            ));
        }
        for (value, column) in row[2..].iter().zip(["p", "qx", "qy"]) {
            if value.abs() > largest.magnitude {
                largest = Largest {
                    magnitude: value.abs(),
                    line: number,
                    column,
                };
            }
        }
        rows.push(row);
    }
    let points: Vec<[f64; 2]> = rows.iter().map(|r| [r[0], r[1]]).collect();
    let rounding = rounding.map(|unit| if unit.is_finite() { unit } else { 0.0 });
    let grid = crate::io::grid_table::assemble(&points, rounding)?;
    let [ny, nx] = grid.shape;
    if nx > MAX_NODES_PER_SIDE || ny > MAX_NODES_PER_SIDE {
        return Err(format!(
            "a grid of {nx} x {ny} nodes (x by y) has more than {MAX_NODES_PER_SIDE} nodes along {}",
            if nx > MAX_NODES_PER_SIDE { "x" } else { "y" }
        ));
    }
    let mut arrays = [
        Array2::zeros((ny, nx)),
        Array2::zeros((ny, nx)),
        Array2::zeros((ny, nx)),
    ];
    for (row, [j, i]) in rows.iter().zip(&grid.nodes) {
        for (array, value) in arrays.iter_mut().zip(&row[2..]) {
            array[[*j, *i]] = *value;
        }
    }
    let [pressure, shear_x, shear_y] = arrays;
    Ok(TractionTable {
        first_centre: grid.first,
        cell: grid.step,
        pressure,
        shear_x: iqx.map(|_| shear_x),
        shear_y: iqy.map(|_| shear_y),
        largest,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_a_grid_in_any_order() {
        let text = "# two by three\nx, y, qx, p\n0.5,1,0.1,2\n0.0,1,0,1\n0,0,0,0\n0.5,0,0,3\n0,2,0,4\n0.5,2,0.2,5\n";
        let table = read(text).expect("valid");
        assert_eq!(table.first_centre, [0.0, 0.0]);
        assert_eq!(table.cell, [0.5, 1.0]);
        assert_eq!(table.pressure[[1, 1]], 2.0);
        assert_eq!(table.pressure[[2, 0]], 4.0);
        assert_eq!(table.shear_x.as_ref().expect("qx")[[2, 1]], 0.2);
        assert!(table.shear_y.is_none());
    }

    #[test]
    fn bad_tables_say_what_is_wrong() {
        let cases = [
            ("", "no header"),
            ("x,y\n0,0\n", "x, y and p"),
            ("x,y,p,q\n0,0,1,0\n", "unknown column `q`"),
            ("x,y,p\n0,0,1\n1,0\n", "line 3: expected 3 fields"),
            ("x,y,p\n0,0,one\n", "line 2: p = `one`"),
            ("x,y,p\n0,0,-1\n", "negative"),
            (
                "x,y,p\n0,0,1\n1,0,1\n3,0,1\n0,1,1\n1,1,1\n3,1,1\n",
                "evenly spaced",
            ),
            ("x,y,p\n0,0,1\n1,0,1\n0,1,1\n", "every node"),
            ("x,y,p\n0,0,1\n1,0,1\n0,1,1\n0,1,1\n", "appears twice"),
            ("x,y,p\n0,0,1\n0,1,1\n", "two distinct x"),
            ("x,y,p,p\n0,0,1,1\n", "`p` is named twice (columns 3 and 4)"),
            ("x,x,y,p\n0,0,0,1\n", "`x` is named twice (columns 1 and 2)"),
        ];
        for (text, fragment) in cases {
            let error = read(text).expect_err(text);
            assert!(error.contains(fragment), "{text:?}: {error}");
        }
    }
}
