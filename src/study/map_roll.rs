//! How a periodic map is shown: rolled by whole cells so that the place of interest sits at its
//! centre, away from the seam where the period repeats.
//!
//! A periodic surface's solution repeats with the map, so its left and right (bottom and top)
//! edges are one line of the torus: a contact across that seam is drawn split into the map's
//! sides or corners. Rolling the displayed map by whole cells moves the seam elsewhere without
//! interpolating anything: every value is shown once, each at its own cell, and the axes
//! continue the map's coordinates past its period (a map rolled by `c` columns of width `dx`
//! runs from `c·dx` to `(c + nx)·dx`, one piece). An isolated map is never rolled: beyond it
//! there is nothing.
//!
//! The rough sheet ([`super::rough_sheet`]) centres its periodic maps on the report's maximum
//! ([`centring`]); a recording of the same scene shows its maps in the same frame by calling
//! [`super::rough_sheet::display_roll`] and [`Roll::apply`] / [`Roll::axes`].

use ndarray::{Array2, ArrayView2};

use crate::field::Axis;
use crate::operator::elastic::Periodicity;

/// A map's display frame, rolled by whole cells: displayed column `k` shows the map's column
/// `(k + columns) mod nx` at `x = (k + columns + 1/2)·dx`, displayed row `j` the map's row
/// `(j + rows) mod ny` at `y = (j + rows + 1/2)·dy`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Roll {
    /// The first displayed column's place in the periodic lattice of cells (negative: left of
    /// the map's origin).
    pub columns: isize,
    /// The first displayed row's place in the periodic lattice of cells.
    pub rows: isize,
}

impl Roll {
    /// The map as stored: not rolled.
    pub const NONE: Self = Self {
        columns: 0,
        rows: 0,
    };

    /// Whether the map is shown as stored.
    pub fn is_none(&self) -> bool {
        *self == Self::NONE
    }

    /// `values` (`[ny, nx]`) as displayed: `out[j, i] = values[(j + rows) mod ny, (i + columns)
    /// mod nx]`, a permutation of the values.
    pub fn apply<T: Clone>(&self, values: ArrayView2<'_, T>) -> Array2<T> {
        let (ny, nx) = values.dim();
        if self.is_none() || nx == 0 || ny == 0 {
            return values.to_owned();
        }
        let wrap = |k: usize, shift: isize, n: usize| (k as isize + shift).rem_euclid(n as isize);
        Array2::from_shape_fn((ny, nx), |(j, i)| {
            values[[
                wrap(j, self.rows, ny) as usize,
                wrap(i, self.columns, nx) as usize,
            ]]
            .clone()
        })
    }

    /// The displayed axes `(x, y)` of the cell centres of an `[ny, nx]` map of cells
    /// `[dx, dy]` (`spacing`, in the axes' unit): x from `(columns + 1/2)·dx` to
    /// `(columns + nx − 1/2)·dx`, continuous, beyond the period where the roll takes it; each
    /// value equals the stored cell's centre modulo the period.
    pub fn axes(&self, shape: [usize; 2], spacing: [f64; 2]) -> (Axis, Axis) {
        let [ny, nx] = shape;
        let [dx, dy] = spacing;
        let axis = |first: isize, n: usize, d: f64| {
            let first = first as f64 + 0.5;
            Axis::new(first * d, (first + n as f64 - 1.0) * d, n)
        };
        (axis(self.columns, nx, dx), axis(self.rows, ny, dy))
    }
}

/// The cell of `n` cells `spacing` wide (from 0) whose centre is nearest to `u`, within the map.
pub fn cell_of(u: f64, spacing: f64, n: usize) -> usize {
    let f = (u / spacing - 0.5).round();
    if f.is_finite() && f > 0.0 {
        (f as usize).min(n.saturating_sub(1))
    } else {
        0
    }
}

/// The roll that shows cell `[row, column]` of a map of `shape` `[ny, nx]` at its centre
/// cell `[ny/2, nx/2]` (rounded down) if the map is periodic: by at most half a period each way,
/// so that whatever lies within half a period of that cell is drawn whole. An isolated map is
/// not rolled ([`Roll::NONE`]).
pub fn centring(periodicity: Periodicity, cell: [usize; 2], shape: [usize; 2]) -> Roll {
    match periodicity {
        Periodicity::NonPeriodic => Roll::NONE,
        Periodicity::Periodic => Roll {
            columns: cell[1] as isize - (shape[1] / 2) as isize,
            rows: cell[0] as isize - (shape[0] / 2) as isize,
        },
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn numbered(ny: usize, nx: usize) -> Array2<f64> {
        Array2::from_shape_fn((ny, nx), |(j, i)| (j * nx + i) as f64)
    }

    #[test]
    fn a_roll_is_a_permutation_and_none_changes_nothing() {
        let values = numbered(5, 7);
        for roll in [
            Roll {
                columns: 3,
                rows: -2,
            },
            Roll {
                columns: -10,
                rows: 9,
            },
        ] {
            let rolled = roll.apply(values.view());
            let mut seen: Vec<f64> = rolled.iter().copied().collect();
            seen.sort_by(f64::total_cmp);
            let all: Vec<f64> = (0..35).map(|k| k as f64).collect();
            assert_eq!(seen, all, "{roll:?}");
            // Rolled back, the map is the stored one.
            let back = Roll {
                columns: -roll.columns,
                rows: -roll.rows,
            };
            assert_eq!(back.apply(rolled.view()), values);
        }
        assert_eq!(Roll::NONE.apply(values.view()), values);
    }

    #[test]
    fn centring_puts_the_cell_at_the_centre_of_a_periodic_map_only() {
        for (cell, shape) in [
            ([0, 0], [8, 8]),
            ([7, 0], [8, 9]),
            ([3, 126], [128, 128]),
            ([4, 4], [9, 9]),
        ] {
            let roll = centring(Periodicity::Periodic, cell, shape);
            let marker = Array2::from_shape_fn((shape[0], shape[1]), |at| {
                if [at.0, at.1] == cell {
                    1.0
                } else {
                    0.0
                }
            });
            let rolled = roll.apply(marker.view());
            assert_eq!(
                rolled[[shape[0] / 2, shape[1] / 2]],
                1.0,
                "{cell:?} {shape:?}"
            );
            assert!(
                roll.columns.unsigned_abs() <= shape[1] / 2
                    && roll.rows.unsigned_abs() <= shape[0] / 2
            );
            assert!(centring(Periodicity::NonPeriodic, cell, shape).is_none());
        }
    }

    #[test]
    fn rolled_axes_run_on_past_the_period_and_agree_with_the_cells_modulo_it() {
        let (nx, ny, dx, dy) = (6, 4, 0.5, 2.0);
        let roll = Roll {
            columns: 4,
            rows: -3,
        };
        let (x, y) = roll.axes([ny, nx], [dx, dy]);
        assert_eq!((x.min, x.max, x.count), (2.25, 4.75, 6));
        assert_eq!((y.min, y.max, y.count), (-5.0, 1.0, 4));
        let period = nx as f64 * dx;
        for k in 0..nx {
            let stored = (k as isize + roll.columns).rem_euclid(nx as isize) as f64;
            let offset = (x.value(k) - (stored + 0.5) * dx) / period;
            assert!((offset - offset.round()).abs() < 1e-12, "{k}");
        }
        assert_eq!(
            Roll::NONE.axes([ny, nx], [dx, dy]).0,
            Axis::new(0.25, 2.75, 6)
        );
    }

    #[test]
    fn the_cell_of_a_coordinate_is_the_nearest_centre_within_the_map() {
        assert_eq!(cell_of(0.25, 0.5, 6), 0);
        assert_eq!(cell_of(109.5, 1.0, 128), 109);
        assert_eq!(cell_of(-3.0, 1.0, 128), 0);
        assert_eq!(cell_of(500.0, 1.0, 128), 127);
        assert_eq!(cell_of(f64::NAN, 1.0, 128), 0);
    }
}
