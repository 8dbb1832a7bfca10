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
    /// How far the step may be from the true one because the coordinates were rounded
    /// (`[x, y]`, the rounding unit over the axis's extent); 0 where they were exact.
    pub step_uncertainty: [f64; 2],
}

/// The unit of the last digit written in a number (`0.0391` -> 1e-4, `3.906e-02` -> 1e-5,
/// `12` -> 1): how finely a coordinate was rounded when it was written. `None` for text that is
/// not a decimal number.
pub fn last_digit(text: &str) -> Option<f64> {
    let text = text.trim();
    let (mantissa, exponent) = match text.find(['e', 'E']) {
        Some(at) => (&text[..at], text[at + 1..].parse::<i32>().ok()?),
        None => (text, 0),
    };
    let decimals = match mantissa.find('.') {
        Some(at) => mantissa.len() - at - 1,
        None => 0,
    };
    let decimals = i32::try_from(decimals).ok()?;
    Some(10f64.powi(exponent.checked_sub(decimals)?))
}

/// Finds the grid of `points` (x, y): at least two distinct values along each axis, each within
/// 1e-6 of the step of its node (the first value plus a whole number of steps), and every node
/// exactly once.
///
/// `rounding` is `[x, y]`: the unit of the last digit the coordinates were written with
/// ([`last_digit`], the finest over the rows), or 0 if they are exact. Instruments export
/// coordinates rounded to a few decimals (0.0391 for 0.0390625): a value is within half a unit
/// of its node, the first value too, and the step taken from the first and last values is
/// within one unit over the whole axis, so a node is accepted within two units. The rounding is
/// allowed only where it is finer than a quarter of the step; coarser rounding could hide an
/// uneven grid, so such files must be exact.
pub fn assemble(points: &[[f64; 2]], rounding: [f64; 2]) -> Result<RegularGrid, String> {
    let axis = |k: usize, name: &str| -> Result<(f64, f64, usize, f64), String> {
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
        let unit = rounding[k];
        let rounded = unit > 0.0 && 2.0 * unit < 0.25 * step;
        let tolerance = 1e-6 * step + if rounded { 2.0 * unit } else { 0.0 };
        let node = |i: usize| values[0] + i as f64 * step;
        if let Some(i) = (1..values.len()).find(|&i| (values[i] - node(i)).abs() > tolerance) {
            let written = if rounded {
                format!(" (allowing for coordinates written to {unit:e})")
            } else {
                String::new()
            };
            return Err(format!(
                "the {name} values are not evenly spaced: {} follows {} where {} was expected (step {step}{written}); give the tractions at the centres of a regular grid",
                values[i],
                values[i - 1],
                node(i)
            ));
        }
        let uncertainty = if rounded {
            unit / (values.len() - 1) as f64
        } else {
            0.0
        };
        Ok((values[0], step, values.len(), uncertainty))
    };
    let (x0, dx, nx, ux) = axis(0, "x")?;
    let (y0, dy, ny, uy) = axis(1, "y")?;
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
        step_uncertainty: [ux, uy],
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_last_digit_written() {
        for (text, unit) in [
            ("0.0391", 1e-4),
            ("3.906e-02", 1e-5),
            ("12", 1.0),
            ("-1.5E3", 100.0),
            ("0.", 1.0),
        ] {
            let got = last_digit(text).expect(text);
            assert!((got / unit - 1.0).abs() < 1e-12, "{text}: {got}");
        }
        assert_eq!(last_digit("1e"), None);
    }

    /// Issue 24, class 17: coordinates of a grid of step 1/25.6 rounded to 4, 5 and 6 decimals
    /// (as instruments export them) are accepted, every node found once, the step within the
    /// rounding; an uneven grid written to the same decimals is still refused.
    #[test]
    fn rounded_coordinates_form_their_grid() {
        let step = 1.0 / 25.6;
        for decimals in [4, 5, 6] {
            let round = |v: f64| format!("{v:.decimals$}");
            let mut texts = Vec::new();
            for j in 0..7 {
                for i in 0..40 {
                    texts.push([round(i as f64 * step), round(j as f64 * 2.0 * step)]);
                }
            }
            let unit = |k: usize| {
                texts
                    .iter()
                    .filter_map(|t| last_digit(&t[k]))
                    .fold(f64::INFINITY, f64::min)
            };
            let points: Vec<[f64; 2]> = texts
                .iter()
                .map(|t| [t[0].parse().expect("x"), t[1].parse().expect("y")])
                .collect();
            assert!(
                assemble(&points, [0.0, 0.0]).is_err(),
                "{decimals} decimals pass as exact"
            );
            let grid = assemble(&points, [unit(0), unit(1)]).expect("rounded grid");
            assert_eq!(grid.shape, [7, 40]);
            let limit = 10f64.powi(-(decimals as i32));
            assert!((grid.step[0] - step).abs() <= limit / 39.0);
            assert!(grid.step_uncertainty[0] > 0.0);
            for (point, [j, i]) in points.iter().zip(&grid.nodes) {
                assert!((point[0] - *i as f64 * step).abs() <= limit);
                assert!((point[1] - *j as f64 * 2.0 * step).abs() <= limit);
            }
            // One node moved by a tenth of a step: uneven, whatever the rounding.
            let mut uneven = points.clone();
            for point in uneven.iter_mut().filter(|p| p[0] == points[20][0]) {
                point[0] += 0.1 * step;
            }
            let error = assemble(&uneven, [unit(0), unit(1)]).expect_err("uneven");
            assert!(error.contains("not evenly spaced"), "{error}");
        }
    }

    /// Integers are exact even though their last digit is a whole unit; the rounding allowance
    /// is not used where it would be a quarter of the step or more.
    #[test]
    fn coarse_rounding_is_not_an_allowance() {
        let points: Vec<[f64; 2]> = [0.0, 3.0, 6.0, 10.0]
            .iter()
            .flat_map(|&x| [[x, 0.0], [x, 1.0]])
            .collect();
        assert!(assemble(&points, [1.0, 1.0]).is_err());
        let exact: Vec<[f64; 2]> = (0..4)
            .flat_map(|i| [[i as f64, 0.0], [i as f64, 1.0]])
            .collect();
        let grid = assemble(&exact, [1.0, 1.0]).expect("integers");
        assert_eq!(grid.step, [1.0, 1.0]);
        assert_eq!(grid.step_uncertainty, [0.0, 0.0]);
    }
}
