//! Point contact by numerical integration: surface tractions on a square grid of uniform cells,
//! their stresses summed from the cells' exact influence coefficients ([`super::patch`]):
//! directly at any point, or by DC-FFT over whole depth layers ([`super::dcfft`]).
//!
//! The Hertz sphere discretised this way is an independent route to the closed form of
//! [`super::sphere_hertz`] (a check of it, and the model for tractions without a closed form).

use ndarray::Array2;

use super::dcfft::{DcFft, DcFftError, TractionGrid, TractionGridError};
use crate::stress::Stress;

/// Errors building a numerical point contact.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum NumericalError {
    #[error(transparent)]
    Grid(#[from] TractionGridError),
    #[error(transparent)]
    Fft(#[from] DcFftError),
}

/// Gauss–Legendre nodes and weights on `[-1, 1]`, 4 points (exact for cubics).
const GAUSS_4: [(f64, f64); 4] = [
    (-0.861_136_311_594_052_6, 0.347_854_845_137_453_9),
    (-0.339_981_043_584_856_3, 0.652_145_154_862_546_1),
    (0.339_981_043_584_856_3, 0.652_145_154_862_546_1),
    (0.861_136_311_594_052_6, 0.347_854_845_137_453_9),
];

/// Surface tractions on a grid (units of a and p0) with the DC-FFT prepared for one Poisson
/// ratio.
pub struct PointTractions {
    grid: TractionGrid,
    fft: DcFft,
    poisson: f64,
}

impl std::fmt::Debug for PointTractions {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("PointTractions")
            .field("shape", &self.grid.shape())
            .field("cell", &self.grid.cell())
            .field("origin", &self.grid.origin())
            .field("poisson", &self.poisson)
            .finish()
    }
}

impl PartialEq for PointTractions {
    /// Equal tractions and Poisson ratio (the FFT follows from them).
    fn eq(&self, other: &Self) -> bool {
        self.grid == other.grid && self.poisson == other.poisson
    }
}

impl PointTractions {
    /// Tractions given on a grid, for a body of Poisson ratio `poisson`.
    pub fn new(grid: TractionGrid, poisson: f64) -> Result<Self, NumericalError> {
        let fft = DcFft::new(&grid, poisson)?;
        Ok(Self { grid, fft, poisson })
    }

    /// The sliding Hertz sphere, `p = sqrt(1 - r²)`, `q = mu p` in +x, on `cells x cells`
    /// cells covering `[-extent, extent]²`. Each cell carries the mean of the pressure over it
    /// (Gauss–Legendre, 4 x 4 points on each of 4 x 4 sub-cells for cells the contact edge
    /// crosses, where the pressure has its square-root edge), so the discretisation conserves
    /// the load `2 pi / 3` up to the quadrature of the edge cells.
    ///
    /// An odd `cells` puts a cell centre on the axis (x = y = 0), where sections are drawn.
    pub fn hertz_sphere(
        cells: usize,
        extent: f64,
        friction: f64,
        poisson: f64,
    ) -> Result<Self, NumericalError> {
        let n = cells.max(1);
        let h = 2.0 * extent / n as f64;
        let origin = -extent;
        let pressure = |x: f64, y: f64| (1.0 - x * x - y * y).max(0.0).sqrt();
        let mean = |x0: f64, y0: f64, w: f64| {
            let mut sum = 0.0;
            for (u, wu) in GAUSS_4 {
                for (v, wv) in GAUSS_4 {
                    sum += wu * wv * pressure(x0 + 0.5 * w * (1.0 + u), y0 + 0.5 * w * (1.0 + v));
                }
            }
            sum / 4.0
        };
        let p = Array2::from_shape_fn((n, n), |(row, column)| {
            let (x0, y0) = (origin + column as f64 * h, origin + row as f64 * h);
            // Nearest and farthest corner distances decide whether the edge crosses the cell.
            let near = |lo: f64| {
                if lo > 0.0 {
                    lo
                } else if lo + h < 0.0 {
                    lo + h
                } else {
                    0.0
                }
            };
            let far = |lo: f64| lo.abs().max((lo + h).abs());
            let r_near = near(x0).hypot(near(y0));
            let r_far = far(x0).hypot(far(y0));
            if r_near >= 1.0 {
                0.0
            } else if r_far <= 1.0 {
                mean(x0, y0, h)
            } else {
                let sub = h / 4.0;
                let mut sum = 0.0;
                for i in 0..4 {
                    for j in 0..4 {
                        sum += mean(x0 + i as f64 * sub, y0 + j as f64 * sub, sub);
                    }
                }
                sum / 16.0
            }
        });
        let q = (friction != 0.0).then(|| p.mapv(|v| friction * v));
        let grid = TractionGrid::new([origin, origin], [h, h], Some(p), q, None)?;
        Self::new(grid, poisson)
    }

    pub fn grid(&self) -> &TractionGrid {
        &self.grid
    }

    pub fn dcfft(&self) -> &DcFft {
        &self.fft
    }

    pub fn poisson(&self) -> f64 {
        self.poisson
    }

    /// Stress (units of p0) at `(x, y, z)` by direct summation over the cells: exact for the
    /// piecewise-constant tractions; one patch evaluation per loaded cell.
    pub fn stress_over_p0(&self, x: f64, y: f64, z: f64) -> Stress {
        self.grid.stress_at(x, y, z, self.poisson)
    }

    /// The tractions `(p, qx)` of the cell containing `(x, y)` (zero outside the grid).
    pub fn traction_at(&self, x: f64, y: f64) -> (f64, f64) {
        let [ny, nx] = self.grid.shape();
        let [dx, dy] = self.grid.cell();
        let [x0, y0] = self.grid.origin();
        let (fx, fy) = ((x - x0) / dx, (y - y0) / dy);
        if !(fx >= 0.0 && fy >= 0.0 && fx < nx as f64 && fy < ny as f64) {
            return (0.0, 0.0);
        }
        let (p, qx, _) = self.grid.traction(fy as usize, fx as usize);
        (p, qx)
    }

    /// The index of the cell centre nearest to `u` along x (`axis = 0`) or y (`axis = 1`),
    /// clamped to the grid.
    pub fn nearest_centre(&self, u: f64, axis: usize) -> usize {
        let shape = self.grid.shape();
        let n = if axis == 0 { shape[1] } else { shape[0] };
        let f = (u - self.grid.origin()[axis]) / self.grid.cell()[axis] - 0.5;
        (f.round().max(0.0) as usize).min(n - 1)
    }

    /// The coordinate of cell centre `index` along x (`axis = 0`) or y (`axis = 1`).
    pub fn centre(&self, index: usize, axis: usize) -> f64 {
        self.grid.origin()[axis] + (index as f64 + 0.5) * self.grid.cell()[axis]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hertz_cells_carry_the_load() {
        // Load of the Hertz pressure over the unit circle: 2 pi / 3 (p0 = 1, a = 1).
        let tractions = PointTractions::hertz_sphere(63, 1.5, 0.2, 0.3).expect("grid");
        let [ny, nx] = tractions.grid().shape();
        let [dx, dy] = tractions.grid().cell();
        let mut load = 0.0;
        let mut shear = 0.0;
        for row in 0..ny {
            for column in 0..nx {
                let (p, qx, qy) = tractions.grid().traction(row, column);
                load += p * dx * dy;
                shear += qx * dx * dy;
                assert_eq!(qy, 0.0);
            }
        }
        let exact = 2.0 * std::f64::consts::PI / 3.0;
        assert!((load / exact - 1.0).abs() < 1e-5, "{load} vs {exact}");
        assert!((shear / (0.2 * exact) - 1.0).abs() < 1e-5);
        // The odd grid has a centre on the axis.
        let i = tractions.nearest_centre(0.0, 0);
        assert!(tractions.centre(i, 0).abs() < 1e-15);
        assert_eq!(tractions.traction_at(5.0, 0.0), (0.0, 0.0));
        assert!((tractions.traction_at(0.0, 0.0).0 - 1.0).abs() < 1e-3);
    }

    #[test]
    fn far_below_the_grid_acts_as_boussinesq() {
        // szz of a normal point force W = 2 pi / 3 at depth z on the axis: -3W/(2 pi z²).
        let tractions = PointTractions::hertz_sphere(31, 1.2, 0.0, 0.3).expect("grid");
        let z = 40.0;
        let szz = tractions.stress_over_p0(0.0, 0.0, z).zz;
        let expected =
            -3.0 * (2.0 * std::f64::consts::PI / 3.0) / (2.0 * std::f64::consts::PI * z * z);
        assert!((szz / expected - 1.0).abs() < 1e-3, "{szz} vs {expected}");
    }
}
