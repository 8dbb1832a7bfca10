//! Rough surfaces: height maps read from instrument files or generated, levelled and
//! characterised (ISO 25178 parameters, spectra, summits, the Greenwood-Williamson model).
//!
//! Conventions: heights in metres point *out of the body*, towards the counter-surface, so the
//! highest point touches first. A map is indexed `[row, column] = [y, x]`; sample `[j, i]` sits
//! at `(i dx, j dy)`.
//!
//! Uses: [`crate::operator`] (FFT), [`crate::field`], [`crate::io`].

pub mod generate;
pub mod gw;
pub mod read;
pub mod samples;
pub mod stats;
pub mod x3p;

use ndarray::Array2;
use rayon::prelude::*;

/// Why a height map cannot be built.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SurfaceError {
    #[error("a height map needs at least 2 x 2 samples, got {rows} row(s) of {columns}")]
    TooSmall { rows: usize, columns: usize },
    #[error("the sample spacing must lie between {} m and {} m, got dx = {} m, dy = {} m", crate::io::text::compact(MIN_SPACING_M), crate::io::text::compact(MAX_SPACING_M), crate::io::text::number(*.dx), crate::io::text::number(*.dy))]
    Spacing { dx: f64, dy: f64 },
    #[error("the height at row {row}, column {column} is {} m, more than the {} m a surface's height may reach (are the height unit and the spacing right?)", crate::io::text::number(*.value), crate::io::text::compact(MAX_HEIGHT_M))]
    TooHigh {
        row: usize,
        column: usize,
        value: f64,
    },
    #[error("the height at row {row}, column {column} is not finite ({value})")]
    NotFinite {
        row: usize,
        column: usize,
        value: f64,
    },
}

/// The smallest sample spacing, m: an atomic spacing (an AFM scan).
pub const MIN_SPACING_M: f64 = 1e-10;
/// The largest sample spacing, m.
pub const MAX_SPACING_M: f64 = 1.0;
/// The largest height (in size), m: far beyond any roughness or form a contact sees, and far
/// from where the statistics' sums of squares and the contact solver's sums could overflow.
pub const MAX_HEIGHT_M: f64 = 1.0;

/// Checks what a [`HeightMap`] holds: at least 2 x 2 samples, every height finite (missing
/// points must have been refused or filled by the reader) and at most [`MAX_HEIGHT_M`] in
/// size, the spacing `[dx, dy]` within [`MIN_SPACING_M`] and [`MAX_SPACING_M`]. The Python
/// package checks a height array with it before solving on it without a copy.
pub fn check_samples(
    heights_m: ndarray::ArrayView2<f64>,
    spacing_m: [f64; 2],
) -> Result<(), SurfaceError> {
    let (rows, columns) = heights_m.dim();
    if rows < 2 || columns < 2 {
        return Err(SurfaceError::TooSmall { rows, columns });
    }
    let [dx, dy] = spacing_m;
    let spacing_ok = |d: f64| (MIN_SPACING_M..=MAX_SPACING_M).contains(&d);
    if !(spacing_ok(dx) && spacing_ok(dy)) {
        return Err(SurfaceError::Spacing { dx, dy });
    }
    if !heights_m.into_par_iter().all(|v| v.is_finite()) {
        if let Some(((row, column), &value)) =
            heights_m.indexed_iter().find(|(_, v)| !v.is_finite())
        {
            return Err(SurfaceError::NotFinite { row, column, value });
        }
    }
    if let Some(((row, column), &value)) = heights_m
        .indexed_iter()
        .find(|(_, v)| v.abs() > MAX_HEIGHT_M)
    {
        return Err(SurfaceError::TooHigh { row, column, value });
    }
    Ok(())
}

/// Heights of a surface sampled on a regular grid.
#[derive(Clone, Debug, PartialEq)]
pub struct HeightMap {
    heights_m: Array2<f64>,
    spacing_m: [f64; 2],
}

impl HeightMap {
    /// Checks the samples and the spacing ([`check_samples`]) and keeps them.
    pub fn new(heights_m: Array2<f64>, spacing_m: [f64; 2]) -> Result<Self, SurfaceError> {
        check_samples(heights_m.view(), spacing_m)?;
        Ok(Self {
            heights_m,
            spacing_m,
        })
    }

    /// Heights in m, `[ny, nx]`, row = y.
    pub fn heights_m(&self) -> &Array2<f64> {
        &self.heights_m
    }

    /// The heights in m, `[ny, nx]`, moved out of the map (the Python package hands them to
    /// NumPy without a copy).
    pub fn into_heights_m(self) -> Array2<f64> {
        self.heights_m
    }

    /// `[dx, dy]` in m.
    pub fn spacing_m(&self) -> [f64; 2] {
        self.spacing_m
    }

    /// `[ny, nx]`.
    pub fn shape(&self) -> [usize; 2] {
        let (ny, nx) = self.heights_m.dim();
        [ny, nx]
    }

    /// The steps at the seams of the map repeated periodically, against the steps between
    /// neighbouring samples: `[(seam, neighbours) along x, (seam, neighbours) along y]`, each the
    /// rms of the height differences (m) between the last and the first column (row), and
    /// between neighbouring columns (rows) inside the map. A map that tiles has seam steps like
    /// its neighbours'; a measured map's opposite edges are unrelated samples, a seam step about
    /// √2 Sq.
    pub fn seam_steps_m(&self) -> [(f64, f64); 2] {
        seam_steps_m(self.heights_m.view())
    }

    /// The sampled extent `[nx dx, ny dy]` in m (the period of a periodic surface).
    pub fn size_m(&self) -> [f64; 2] {
        let [ny, nx] = self.shape();
        [nx as f64 * self.spacing_m[0], ny as f64 * self.spacing_m[1]]
    }
}

/// [`HeightMap::seam_steps_m`] of heights given as an array (`[rows = y, columns = x]`, at
/// least 2 x 2).
pub fn seam_steps_m(h: ndarray::ArrayView2<f64>) -> [(f64, f64); 2] {
    let (ny, nx) = h.dim();
    let rms = |sum: f64, n: usize| (sum / n.max(1) as f64).sqrt();
    let (mut seam_x, mut inner_x, mut seam_y, mut inner_y) = (0.0, 0.0, 0.0, 0.0);
    for j in 0..ny {
        seam_x += (h[[j, 0]] - h[[j, nx - 1]]).powi(2);
        for i in 1..nx {
            inner_x += (h[[j, i]] - h[[j, i - 1]]).powi(2);
        }
    }
    for i in 0..nx {
        seam_y += (h[[0, i]] - h[[ny - 1, i]]).powi(2);
    }
    for j in 1..ny {
        for i in 0..nx {
            inner_y += (h[[j, i]] - h[[j - 1, i]]).powi(2);
        }
    }
    [
        (rms(seam_x, ny), rms(inner_x, ny * (nx - 1))),
        (rms(seam_y, nx), rms(inner_y, (ny - 1) * nx)),
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn refuses_small_maps_bad_spacing_and_non_finite_heights() {
        let ok = Array2::zeros((2, 3));
        assert!(HeightMap::new(ok.clone(), [1e-6, 1e-6]).is_ok());
        assert_eq!(
            HeightMap::new(Array2::zeros((1, 5)), [1e-6, 1e-6]),
            Err(SurfaceError::TooSmall {
                rows: 1,
                columns: 5
            })
        );
        assert!(matches!(
            HeightMap::new(ok.clone(), [0.0, 1e-6]),
            Err(SurfaceError::Spacing { .. })
        ));
        // Issue 13: spacings and heights a surface cannot mean are refused, not overflowed.
        for spacing in [[1e-300, 1e-6], [1e-6, 1e300], [f64::INFINITY, 1e-6]] {
            assert!(matches!(
                HeightMap::new(ok.clone(), spacing),
                Err(SurfaceError::Spacing { .. })
            ));
        }
        assert!(HeightMap::new(ok.clone(), [MIN_SPACING_M, MAX_SPACING_M]).is_ok());
        let mut high = ok.clone();
        high[[0, 1]] = -1e300;
        let error = HeightMap::new(high, [1e-6, 1e-6]).expect_err("too high");
        assert!(matches!(
            error,
            SurfaceError::TooHigh {
                row: 0,
                column: 1,
                ..
            }
        ));
        assert!(error.to_string().contains("-1e300 m"), "{error}");
        let mut bad = ok;
        bad[[1, 2]] = f64::NAN;
        assert!(matches!(
            HeightMap::new(bad, [1e-6, 1e-6]),
            Err(SurfaceError::NotFinite {
                row: 1,
                column: 2,
                ..
            })
        ));
    }
}
