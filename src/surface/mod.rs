//! Rough surfaces: height maps read from instrument files or generated, levelled and
//! characterised (ISO 25178 parameters, spectra, summits, the Greenwood-Williamson model).
//!
//! Conventions: heights in metres point *out of the body*, towards the counter-surface, so the
//! highest point touches first. A map is indexed `[row, column] = [y, x]`; sample `[j, i]` sits
//! at `(i dx, j dy)`.

pub mod generate;
pub mod gw;
pub mod read;
pub mod stats;
pub mod x3p;

use ndarray::Array2;
use rayon::prelude::*;

/// Why a height map cannot be built.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SurfaceError {
    #[error("a height map needs at least 2 x 2 samples, got {rows} row(s) of {columns}")]
    TooSmall { rows: usize, columns: usize },
    #[error("the sample spacing must be positive and finite, got dx = {dx} m, dy = {dy} m")]
    Spacing { dx: f64, dy: f64 },
    #[error("the height at row {row}, column {column} is not finite ({value})")]
    NotFinite {
        row: usize,
        column: usize,
        value: f64,
    },
}

/// Heights of a surface sampled on a regular grid.
#[derive(Clone, Debug, PartialEq)]
pub struct HeightMap {
    heights_m: Array2<f64>,
    spacing_m: [f64; 2],
}

impl HeightMap {
    /// Checks the samples (at least 2 x 2, every height finite: missing points must have been
    /// refused or filled by the reader) and the spacing `[dx, dy]` (positive, finite).
    pub fn new(heights_m: Array2<f64>, spacing_m: [f64; 2]) -> Result<Self, SurfaceError> {
        let (rows, columns) = heights_m.dim();
        if rows < 2 || columns < 2 {
            return Err(SurfaceError::TooSmall { rows, columns });
        }
        let [dx, dy] = spacing_m;
        if !(dx > 0.0 && dy > 0.0 && dx.is_finite() && dy.is_finite()) {
            return Err(SurfaceError::Spacing { dx, dy });
        }
        if !heights_m.par_iter().all(|v| v.is_finite()) {
            if let Some(((row, column), &value)) =
                heights_m.indexed_iter().find(|(_, v)| !v.is_finite())
            {
                return Err(SurfaceError::NotFinite { row, column, value });
            }
        }
        Ok(Self {
            heights_m,
            spacing_m,
        })
    }

    /// Heights in m, `[ny, nx]`, row = y.
    pub fn heights_m(&self) -> &Array2<f64> {
        &self.heights_m
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

    /// The sampled extent `[nx dx, ny dy]` in m (the period of a periodic surface).
    pub fn size_m(&self) -> [f64; 2] {
        let [ny, nx] = self.shape();
        [nx as f64 * self.spacing_m[0], ny as f64 * self.spacing_m[1]]
    }

    /// The heights, consumed.
    pub fn into_heights_m(self) -> Array2<f64> {
        self.heights_m
    }
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
