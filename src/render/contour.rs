//! Isolines by marching squares on the original grid, joined into polylines, and the choice of
//! contour levels.
//!
//! Crossings are linearly interpolated along cell edges. A saddle cell (two diagonal corners on
//! each side of the level) is resolved by the mean of its four corners: when the centre lies on
//! the same side as a diagonal pair, that pair is joined through the cell. Lines that reach the
//! border of the grid stay open (no ring is closed along the border), and segments lying on the
//! border itself (a level equal to the border values, such as 0 on a traction-free surface)
//! are dropped.

use std::collections::BTreeMap;

use ndarray::ArrayView2;

use super::ticks::{multiples, nice_steps};
use super::Levels;
use crate::field::Axis;

/// One isoline in `[x, z]` coordinates. A closed line repeats its first point at the end.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Polyline {
    pub points: Vec<[f64; 2]>,
    pub closed: bool,
}

/// Isolines of `values` (`[nz, nx]`, row `iz` at `z.value(iz)`) at `level`, in the axes'
/// coordinates.
pub(crate) fn isolines_on(
    values: ArrayView2<'_, f64>,
    x: &Axis,
    z: &Axis,
    level: f64,
) -> Vec<Polyline> {
    let (x_step, z_step) = (step(x), step(z));
    let mut lines = isolines(values, level);
    for line in &mut lines {
        for p in &mut line.points {
            *p = [x.min + p[0] * x_step, z.min + p[1] * z_step];
        }
    }
    lines
}

fn step(axis: &Axis) -> f64 {
    if axis.count > 1 {
        axis.step()
    } else {
        0.0
    }
}

/// Isolines of `values` (`[rows, columns]`) at `level` in index coordinates `[column, row]`.
pub(crate) fn isolines(values: ArrayView2<'_, f64>, level: f64) -> Vec<Polyline> {
    let (rows, columns) = values.dim();
    if rows < 2 || columns < 2 || !level.is_finite() {
        return Vec::new();
    }
    let grid = Grid {
        values,
        level,
        rows,
        columns,
    };
    let mut points: BTreeMap<usize, [f64; 2]> = BTreeMap::new();
    let mut segments: Vec<[usize; 2]> = Vec::new();
    for row in 0..rows - 1 {
        for column in 0..columns - 1 {
            grid.cell(column, row, &mut points, &mut segments);
        }
    }
    segments.retain(|[a, b]| !on_same_border(points[a], points[b], columns, rows));
    join(&points, &segments)
}

/// Edges are numbered: horizontal edges `(i, j)-(i+1, j)` first, then vertical `(i, j)-(i, j+1)`.
struct Grid<'a> {
    values: ArrayView2<'a, f64>,
    level: f64,
    rows: usize,
    columns: usize,
}

impl Grid<'_> {
    fn value(&self, column: usize, row: usize) -> f64 {
        self.values[[row, column]]
    }

    fn above(&self, v: f64) -> bool {
        v >= self.level
    }

    fn horizontal(&self, column: usize, row: usize) -> usize {
        row * (self.columns - 1) + column
    }

    fn vertical(&self, column: usize, row: usize) -> usize {
        self.rows * (self.columns - 1) + row * self.columns + column
    }

    /// Where the level crosses the edge from `a` (value `va`) to `b` (value `vb`).
    fn crossing(&self, a: [f64; 2], b: [f64; 2], va: f64, vb: f64) -> [f64; 2] {
        let t = ((self.level - va) / (vb - va)).clamp(0.0, 1.0);
        [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])]
    }

    fn cell(
        &self,
        i: usize,
        j: usize,
        points: &mut BTreeMap<usize, [f64; 2]>,
        segments: &mut Vec<[usize; 2]>,
    ) {
        // Corners counter-clockwise in index space from (i, j).
        let corners = [(i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1)];
        let v = corners.map(|(c, r)| self.value(c, r));
        if v.iter().any(|x| !x.is_finite()) {
            return;
        }
        let above = v.map(|x| self.above(x));
        // Edge k joins corner k and corner k + 1.
        let ids = [
            self.horizontal(i, j),
            self.vertical(i + 1, j),
            self.horizontal(i, j + 1),
            self.vertical(i, j),
        ];
        let mut crossed = [false; 4];
        for k in 0..4 {
            let (a, b) = (k, (k + 1) % 4);
            if above[a] != above[b] {
                crossed[k] = true;
                let pa = [corners[a].0 as f64, corners[a].1 as f64];
                let pb = [corners[b].0 as f64, corners[b].1 as f64];
                points
                    .entry(ids[k])
                    .or_insert_with(|| self.crossing(pa, pb, v[a], v[b]));
            }
        }
        match crossed.iter().filter(|c| **c).count() {
            2 => {
                let mut edges = (0..4).filter(|k| crossed[*k]).map(|k| ids[k]);
                if let (Some(a), Some(b)) = (edges.next(), edges.next()) {
                    segments.push([a, b]);
                }
            }
            4 => {
                // Saddle: corners 0 and 2 on one side, 1 and 3 on the other.
                let centre_above = self.above(v.iter().sum::<f64>() / 4.0);
                if centre_above == above[0] {
                    // 0 and 2 joined through the centre: cut off corners 1 and 3.
                    segments.push([ids[0], ids[1]]);
                    segments.push([ids[2], ids[3]]);
                } else {
                    // Cut off corners 0 and 2.
                    segments.push([ids[3], ids[0]]);
                    segments.push([ids[1], ids[2]]);
                }
            }
            _ => {}
        }
    }
}

/// Whether both ends of a segment lie on the same side of the grid's border.
fn on_same_border(a: [f64; 2], b: [f64; 2], columns: usize, rows: usize) -> bool {
    const TOLERANCE: f64 = 1e-6;
    let near = |u: f64, w: f64| (u - w).abs() < TOLERANCE;
    let last_column = (columns - 1) as f64;
    let last_row = (rows - 1) as f64;
    (near(a[1], 0.0) && near(b[1], 0.0))
        || (near(a[1], last_row) && near(b[1], last_row))
        || (near(a[0], 0.0) && near(b[0], 0.0))
        || (near(a[0], last_column) && near(b[0], last_column))
}

/// Joins segments sharing an edge crossing into polylines: open chains from their ends first
/// (in edge order, for determinism), then the remaining closed rings.
fn join(points: &BTreeMap<usize, [f64; 2]>, segments: &[[usize; 2]]) -> Vec<Polyline> {
    let mut incident: BTreeMap<usize, Vec<usize>> = BTreeMap::new();
    for (s, [a, b]) in segments.iter().enumerate() {
        incident.entry(*a).or_default().push(s);
        incident.entry(*b).or_default().push(s);
    }
    let mut used = vec![false; segments.len()];
    let mut lines = Vec::new();
    let ends: Vec<usize> = incident
        .iter()
        .filter(|(_, s)| s.len() == 1)
        .map(|(node, _)| *node)
        .collect();
    for start in ends {
        if let Some(line) = walk(start, points, segments, &incident, &mut used) {
            lines.push(line);
        }
    }
    for s in 0..segments.len() {
        if !used[s] {
            if let Some(line) = walk(segments[s][0], points, segments, &incident, &mut used) {
                lines.push(line);
            }
        }
    }
    lines
}

fn walk(
    start: usize,
    points: &BTreeMap<usize, [f64; 2]>,
    segments: &[[usize; 2]],
    incident: &BTreeMap<usize, Vec<usize>>,
    used: &mut [bool],
) -> Option<Polyline> {
    let next_unused = |node: usize, used: &[bool]| {
        incident
            .get(&node)
            .and_then(|s| s.iter().copied().find(|s| !used[*s]))
    };
    let mut segment = next_unused(start, used)?;
    let mut node = start;
    let mut line = vec![points[&start]];
    loop {
        used[segment] = true;
        let [a, b] = segments[segment];
        node = if a == node { b } else { a };
        line.push(points[&node]);
        if node == start {
            return Some(Polyline {
                points: line,
                closed: true,
            });
        }
        match next_unused(node, used) {
            Some(s) => segment = s,
            None => {
                return Some(Polyline {
                    points: line,
                    closed: false,
                })
            }
        }
    }
}

/// The contour levels to draw for data spanning `[min, max]`.
///
/// `Count(n)`: multiples of the nice step whose number of levels strictly inside the range
/// (not within 1 % of either end) is closest to `n`; 0 is skipped when `skip_zero` (a
/// non-negative quantity, where 0 is its lower bound). `Values`: the finite values given,
/// sorted, without duplicates.
pub(crate) fn choose_levels(levels: &Levels, min: f64, max: f64, skip_zero: bool) -> Vec<f64> {
    match levels {
        Levels::Values(values) => {
            let mut values: Vec<f64> = values.iter().copied().filter(|v| v.is_finite()).collect();
            values.sort_by(f64::total_cmp);
            values.dedup();
            values
        }
        Levels::Count(0) => Vec::new(),
        Levels::Count(n) => {
            let span = max - min;
            if !(span.is_finite() && span > 0.0) {
                return Vec::new();
            }
            let inside = |step: f64| -> Vec<f64> {
                let margin = 0.01 * span;
                multiples(min + margin, max - margin, step)
                    .into_iter()
                    .filter(|v| !(skip_zero && v.abs() < 1e-9 * step))
                    .collect()
            };
            let mut best: Option<(usize, Vec<f64>)> = None;
            for step in nice_steps(span / (*n as f64) / 10.0).take(12) {
                let candidate = inside(step);
                if candidate.is_empty() {
                    break;
                }
                let miss = candidate.len().abs_diff(*n);
                if best.as_ref().is_none_or(|(m, _)| miss <= *m) {
                    best = Some((miss, candidate));
                }
            }
            best.map(|(_, levels)| levels).unwrap_or_default()
        }
    }
}

#[cfg(test)]
mod tests {
    use approx::assert_abs_diff_eq;
    use ndarray::Array2;

    use super::*;

    fn sample(x: &Axis, z: &Axis, f: impl Fn(f64, f64) -> f64) -> Array2<f64> {
        Array2::from_shape_fn((z.count, x.count), |(iz, ix)| f(x.value(ix), z.value(iz)))
    }

    #[test]
    fn circle_of_a_paraboloid() {
        let (x, z) = (Axis::new(-1.0, 1.0, 81), Axis::new(-1.0, 1.0, 61));
        let values = sample(&x, &z, |x, z| x * x + z * z);
        let lines = isolines_on(values.view(), &x, &z, 0.25);
        assert_eq!(lines.len(), 1);
        let line = &lines[0];
        assert!(line.closed);
        assert_eq!(line.points.first(), line.points.last());
        assert!(line.points.len() > 40);
        for p in &line.points {
            assert_abs_diff_eq!(p[0].hypot(p[1]), 0.5, epsilon = 1e-3);
        }
    }

    #[test]
    fn a_linear_field_gives_a_straight_open_line() {
        let (x, z) = (Axis::new(-2.0, 2.0, 41), Axis::new(0.0, 2.0, 21));
        let values = sample(&x, &z, |x, z| 2.0 * x - z + 0.3);
        let lines = isolines_on(values.view(), &x, &z, 0.5);
        assert_eq!(lines.len(), 1);
        assert!(!lines[0].closed);
        for p in &lines[0].points {
            assert_abs_diff_eq!(2.0 * p[0] - p[1] + 0.3, 0.5, epsilon = 1e-12);
        }
        // It runs from the top border to the bottom border.
        let mut ends = [
            lines[0].points[0][1],
            lines[0].points.last().map_or(f64::NAN, |p| p[1]),
        ];
        ends.sort_by(f64::total_cmp);
        assert_abs_diff_eq!(ends[0], 0.0, epsilon = 1e-12);
        assert_abs_diff_eq!(ends[1], 2.0, epsilon = 1e-12);
    }

    #[test]
    fn a_ring_cut_by_the_border_stays_open() {
        // A half disc under the surface z = 0: no line may run along the surface.
        let (x, z) = (Axis::new(-1.0, 1.0, 41), Axis::new(0.0, 1.0, 21));
        let values = sample(&x, &z, |x, z| x * x + z * z);
        let lines = isolines_on(values.view(), &x, &z, 0.25);
        assert_eq!(lines.len(), 1);
        let points = &lines[0].points;
        assert!(!lines[0].closed);
        assert_abs_diff_eq!(points[0][1], 0.0);
        assert_abs_diff_eq!(points[points.len() - 1][1], 0.0);
        for pair in points.windows(2) {
            assert!(
                pair[0][1] > 0.0 || pair[1][1] > 0.0,
                "segment along the surface: {pair:?}"
            );
        }
    }

    #[test]
    fn a_level_equal_to_the_border_values_draws_nothing_on_the_border() {
        let (x, z) = (Axis::new(-1.0, 1.0, 11), Axis::new(0.0, 1.0, 11));
        // Zero on the surface (with rounding noise), negative below.
        let values = sample(
            &x,
            &z,
            |x, z| if z == 0.0 { 1e-17 * x.signum() } else { -z },
        );
        assert!(isolines_on(values.view(), &x, &z, 0.0).is_empty());
    }

    #[test]
    fn saddles_follow_the_cell_centre() {
        // Corners: (0,0) = 1, (1,0) = 0, (0,1) = 0, (1,1) = 1; the centre is 0.5.
        let values = Array2::from_shape_vec((2, 2), vec![1.0, 0.0, 0.0, 1.0]).expect("shape");
        // Centre above 0.4: the high corners are joined, the low corners cut off.
        let mut lines = isolines(values.view(), 0.4);
        assert_eq!(lines.len(), 2);
        lines.sort_by(|a, b| a.points[0][0].total_cmp(&b.points[0][0]));
        let corner_of = |line: &Polyline| {
            let mid = [
                (line.points[0][0] + line.points[1][0]) / 2.0,
                (line.points[0][1] + line.points[1][1]) / 2.0,
            ];
            [mid[0].round(), mid[1].round()]
        };
        let mut corners: Vec<[f64; 2]> = lines.iter().map(corner_of).collect();
        corners.sort_by(|a, b| a[0].total_cmp(&b[0]));
        assert_eq!(corners, vec![[0.0, 1.0], [1.0, 0.0]]);
        // Centre below 0.6: the high corners are cut off instead.
        let lines = isolines(values.view(), 0.6);
        let mut corners: Vec<[f64; 2]> = lines.iter().map(corner_of).collect();
        corners.sort_by(|a, b| a[0].total_cmp(&b[0]));
        assert_eq!(corners, vec![[0.0, 0.0], [1.0, 1.0]]);
    }

    #[test]
    fn segments_are_joined_into_long_lines() {
        let (x, z) = (Axis::new(-1.0, 1.0, 201), Axis::new(0.0, 1.0, 101));
        let values = sample(&x, &z, |x, z| 0.3 * (3.0 * x).sin() + z);
        let lines = isolines_on(values.view(), &x, &z, 0.5);
        assert_eq!(lines.len(), 1, "one continuous line");
        assert!(lines[0].points.len() > 100);
    }

    #[test]
    fn levels_by_count_are_nice_and_inside() {
        let levels = choose_levels(&Levels::Count(10), 0.0, 0.3004, true);
        // Steps of 0.02 give 14 levels, of 0.05 only 5: 14 is closer to 10.
        assert_eq!(levels.len(), 14, "{levels:?}");
        assert_abs_diff_eq!(levels[0], 0.02, epsilon = 1e-12);
        assert_abs_diff_eq!(levels[13], 0.28, epsilon = 1e-12);
        let levels = choose_levels(&Levels::Count(5), 0.0, 0.3004, true);
        assert_eq!(levels.len(), 5, "{levels:?}");
        assert_abs_diff_eq!(levels[0], 0.05, epsilon = 1e-12);
        let signed = choose_levels(&Levels::Count(8), -1.0, 0.6, false);
        assert!(
            signed.iter().any(|l| l.abs() < 1e-12),
            "0 kept for signed maps: {signed:?}"
        );
        assert!(signed.iter().all(|l| *l > -1.0 && *l < 0.6));
        let given = choose_levels(
            &Levels::Values(vec![0.2, 0.1, f64::NAN, 0.2]),
            0.0,
            1.0,
            true,
        );
        assert_eq!(given, vec![0.1, 0.2]);
        assert!(choose_levels(&Levels::Count(0), 0.0, 1.0, true).is_empty());
        assert!(choose_levels(&Levels::Count(5), 1.0, 1.0, true).is_empty());
    }
}
