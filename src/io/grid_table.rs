//! Rows of a table that sample a regular grid, in any order: the grid they form (first node,
//! step and count along x and y) and the node of each row. Shared by the traction CSV reader
//! and the XYZ surface reader; errors are texts for the caller to prefix with its file.

/// The regular grid formed by the rows' coordinates.
#[derive(Clone, Debug, PartialEq)]
pub struct RegularGrid {
    /// The node with the smallest x and y.
    pub first: [f64; 2],
    /// `[dx, dy]`.
    pub step: [f64; 2],
    /// `[ny, nx]`.
    pub shape: [usize; 2],
    /// `[row, column] = [j, i]` of each point, in the order given.
    pub nodes: Vec<[usize; 2]>,
}

/// Finds the grid of `points` (x, y): at least two distinct values along each axis, evenly
/// spaced (to 1e-6 of the step), and every node exactly once.
pub fn assemble(points: &[[f64; 2]]) -> Result<RegularGrid, String> {
    let axis = |k: usize, name: &str| -> Result<(f64, f64, usize), String> {
        let mut values: Vec<f64> = points.iter().map(|r| r[k]).collect();
        values.sort_by(f64::total_cmp);
        values.dedup();
        if values.len() < 2 {
            return Err(format!(
                "the grid needs at least two distinct {name} values, got {}",
                values.len()
            ));
        }
        let step = (values[values.len() - 1] - values[0]) / (values.len() - 1) as f64;
        let tolerance = 1e-6 * step;
        if let Some(w) = values
            .windows(2)
            .find(|w| (w[1] - w[0] - step).abs() > tolerance)
        {
            return Err(format!(
                "the {name} values are not evenly spaced: {} follows {} (step {step}); give the tractions at the centres of a regular grid",
                w[1], w[0]
            ));
        }
        Ok((values[0], step, values.len()))
    };
    let (x0, dx, nx) = axis(0, "x")?;
    let (y0, dy, ny) = axis(1, "y")?;
    if points.len() != nx * ny {
        return Err(format!(
            "{} rows for a grid of {nx} x {ny} = {} nodes: every node must appear exactly once",
            points.len(),
            nx * ny
        ));
    }
    let mut seen = vec![false; nx * ny];
    let mut nodes = Vec::with_capacity(points.len());
    for point in points {
        let i = ((point[0] - x0) / dx).round() as usize;
        let j = ((point[1] - y0) / dy).round() as usize;
        if std::mem::replace(&mut seen[j * nx + i], true) {
            return Err(format!(
                "the node ({}, {}) appears twice; every node must appear exactly once",
                point[0], point[1]
            ));
        }
        nodes.push([j, i]);
    }
    Ok(RegularGrid {
        first: [x0, y0],
        step: [dx, dy],
        shape: [ny, nx],
        nodes,
    })
}
