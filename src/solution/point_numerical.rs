//! Point contact by numerical integration: surface tractions on a square grid of uniform cells,
//! their stresses summed from the cells' exact influence coefficients ([`super::patch`]):
//! directly at any point, or by DC-FFT over whole depth layers ([`super::dcfft`]).
//!
//! The Hertz sphere discretised this way is an independent route to the closed form of
//! [`super::sphere_hertz`] (a check of it, and the model for tractions without a closed form).

use ndarray::Array2;

use super::dcfft::{DcFft, DcFftError, TractionGrid, TractionGridError};
use crate::operator::elastic::Periodicity;
use crate::stress::Stress;

/// Errors building a numerical point contact.
#[derive(Debug, PartialEq, thiserror::Error)]
pub enum NumericalError {
    #[error(transparent)]
    Grid(#[from] TractionGridError),
    #[error(transparent)]
    Fft(#[from] DcFftError),
    #[error(transparent)]
    Contact(#[from] crate::contact::ContactError),
    #[error("a traction-grid scene without its grid (a bug: the scene validation loads it)")]
    MissingTractions,
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
    /// Tractions given on a grid (zero beyond it), for a body of Poisson ratio `poisson`.
    pub fn new(grid: TractionGrid, poisson: f64) -> Result<Self, NumericalError> {
        let fft = DcFft::new(&grid, poisson)?;
        Ok(Self { grid, fft, poisson })
    }

    /// Tractions of which the grid is one period, repeating in x and y (the stress under a
    /// periodic rough contact; see [`super::dcfft`]).
    pub fn periodic(grid: TractionGrid, poisson: f64) -> Result<Self, NumericalError> {
        let fft = DcFft::periodic(&grid, poisson)?;
        Ok(Self { grid, fft, poisson })
    }

    /// Whether the grid is one period of repeating tractions.
    pub fn is_periodic(&self) -> bool {
        self.fft.periodicity() == Periodicity::Periodic
    }

    /// Tractions given as functions of `(x, y)` (units of a and p0) on `cells x cells` cells
    /// covering `[-extent, extent] x [-extent stretch, extent stretch]` (`stretch = b/a` keeps
    /// the resolution relative to each semi-axis of an elliptical contact): each cell carries the mean of each function over it
    /// (Gauss–Legendre, 4 x 4 points; cells where the pressure's support ends inside the cell,
    /// at the contact edge where the pressure has its square-root edge, are split into 4 x 4
    /// sub-cells), so the discretisation keeps the load up to that quadrature.
    ///
    /// An odd `cells` puts a cell centre on the axis (x = y = 0), where sections are drawn.
    pub fn from_functions(
        cells: usize,
        extent: f64,
        stretch: f64,
        poisson: f64,
        pressure: impl Fn(f64, f64) -> f64,
        shear_x: Option<&dyn Fn(f64, f64) -> f64>,
    ) -> Result<Self, NumericalError> {
        let n = cells.max(1);
        let h = 2.0 * extent / n as f64;
        let k = h * stretch;
        let (origin_x, origin_y) = (-extent, -extent * stretch);
        // Mean over the cell [x0, x0 + w] x [y0, y0 + w stretch].
        let mean = |f: &dyn Fn(f64, f64) -> f64, x0: f64, y0: f64, w: f64| {
            let mut sum = 0.0;
            for (u, wu) in GAUSS_4 {
                for (v, wv) in GAUSS_4 {
                    sum +=
                        wu * wv * f(x0 + 0.5 * w * (1.0 + u), y0 + 0.5 * w * stretch * (1.0 + v));
                }
            }
            sum / 4.0
        };
        // Whether the pressure's support boundary crosses the cell: its corners and centre
        // disagree on being loaded.
        let crossed = |x0: f64, y0: f64| {
            let loaded = [(0.0, 0.0), (h, 0.0), (0.0, k), (h, k), (0.5 * h, 0.5 * k)]
                .map(|(dx, dy)| pressure(x0 + dx, y0 + dy) > 0.0);
            loaded.iter().any(|l| *l) && !loaded.iter().all(|l| *l)
        };
        let cell_mean = |f: &dyn Fn(f64, f64) -> f64, row: usize, column: usize| {
            let (x0, y0) = (origin_x + column as f64 * h, origin_y + row as f64 * k);
            if crossed(x0, y0) {
                let sub = h / 4.0;
                let mut sum = 0.0;
                for i in 0..4 {
                    for j in 0..4 {
                        let y = y0 + j as f64 * sub * stretch;
                        sum += mean(f, x0 + i as f64 * sub, y, sub);
                    }
                }
                sum / 16.0
            } else {
                mean(f, x0, y0, h)
            }
        };
        let p = Array2::from_shape_fn((n, n), |(row, column)| cell_mean(&pressure, row, column));
        let q = shear_x
            .map(|f| Array2::from_shape_fn((n, n), |(row, column)| cell_mean(f, row, column)));
        let grid = TractionGrid::new([origin_x, origin_y], [h, k], Some(p), q, None)?;
        Self::new(grid, poisson)
    }

    /// The sliding Hertz sphere, `p = sqrt(1 - r²)`, `q = mu p` in +x (Johnson 1985, §3.4 and
    /// ch. 7), as cell means (see [`PointTractions::from_functions`]).
    pub fn hertz_sphere(
        cells: usize,
        extent: f64,
        friction: f64,
        poisson: f64,
    ) -> Result<Self, NumericalError> {
        let pressure = |x: f64, y: f64| (1.0 - x * x - y * y).max(0.0).sqrt();
        let shear = move |x: f64, y: f64| friction * pressure(x, y);
        let shear: Option<&dyn Fn(f64, f64) -> f64> = (friction != 0.0).then_some(&shear);
        Self::from_functions(cells, extent, 1.0, poisson, pressure, shear)
    }

    /// A sliding elliptical Hertz contact with semi-axes `a` along x (the unit of length) and
    /// `b = b_over_a a` along y, on a grid covering `extent` semi-axes each way: `p = p0 sqrt(1 - x²/a² - y²/b²)`, `q = mu p` in +x
    /// ([`crate::contact::elliptic::pressure_over_p0`]; Johnson 1985, §4.2).
    pub fn hertz_ellipse(
        cells: usize,
        extent: f64,
        b_over_a: f64,
        friction: f64,
        poisson: f64,
    ) -> Result<Self, NumericalError> {
        let pressure =
            move |x: f64, y: f64| crate::contact::elliptic::pressure_over_p0(x, y / b_over_a);
        let shear = move |x: f64, y: f64| friction * pressure(x, y);
        let shear: Option<&dyn Fn(f64, f64) -> f64> = (friction != 0.0).then_some(&shear);
        Self::from_functions(cells, extent, b_over_a, poisson, pressure, shear)
    }

    /// Cattaneo–Mindlin partial slip of a Hertz sphere under a tangential force
    /// `Q = tangential_over_limit mu P` in +x: the Hertz pressure and the traction of
    /// [`crate::contact::partial_slip::CattaneoMindlin`] (stick circle of radius
    /// `c = a (1 - Q/(mu P))^(1/3)`).
    pub fn mindlin_sphere(
        cells: usize,
        extent: f64,
        slip: &crate::contact::partial_slip::CattaneoMindlin,
        poisson: f64,
    ) -> Result<Self, NumericalError> {
        let pressure = |x: f64, y: f64| (1.0 - x * x - y * y).max(0.0).sqrt();
        let shear = |x: f64, y: f64| slip.traction_over_p0(x, y);
        Self::from_functions(cells, extent, 1.0, poisson, pressure, Some(&shear))
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
    /// piecewise-constant tractions; one patch evaluation per loaded cell (periodic: per
    /// cell and image, [`TractionGrid::periodic_stress_at`]). On the surface exactly on a
    /// cell edge some components are infinite (see [`super::patch::uniform_patch`] and
    /// [`Self::finite_stress_over_p0`]).
    pub fn stress_over_p0(&self, x: f64, y: f64, z: f64) -> Stress {
        if self.is_periodic() {
            self.grid.periodic_stress_at(x, y, z, self.poisson)
        } else {
            self.grid.stress_at(x, y, z, self.poisson)
        }
    }

    /// [`Self::stress_over_p0`], made finite on the surface on the cell edges and corners,
    /// where the discretised tractions jump and some of the cells' stresses are
    /// logarithmically infinite: there the mean of the values at the centres of the cells
    /// meeting there (two across an edge, four at a corner; half a cell away), to which the
    /// continuous tractions' value is the limit as the grid is refined. Where the exact value
    /// is finite on an edge it is kept (the mean of the one-sided limits).
    pub fn finite_stress_over_p0(&self, x: f64, y: f64, z: f64) -> Stress {
        let stress = self.stress_over_p0(x, y, z);
        if z > 0.0 || stress.is_finite() {
            return stress;
        }
        let [dx, dy] = self.grid.cell();
        let [x0, y0] = self.grid.origin();
        let on_edge = |u: f64, origin: f64, h: f64| {
            let f = (u - origin) / h;
            (f - f.round()).abs() <= 1e-9 * f.abs().max(1.0)
        };
        let (on_x, on_y) = (on_edge(x, x0, dx), on_edge(y, y0, dy));
        // Neither found by the test (a rounding away from the edge): both.
        let (on_x, on_y) = (on_x || !on_y, on_y || !on_x);
        let xs: &[f64] = if on_x {
            &[x - 0.5 * dx, x + 0.5 * dx]
        } else {
            &[x]
        };
        let ys: &[f64] = if on_y {
            &[y - 0.5 * dy, y + 0.5 * dy]
        } else {
            &[y]
        };
        let around: Vec<Stress> = ys
            .iter()
            .flat_map(|&v| xs.iter().map(move |&u| (u, v)))
            .map(|(u, v)| self.stress_over_p0(u, v, z))
            .collect();
        Stress::mean(&around)
    }

    /// The tractions `(p, qx)` of the cell containing `(x, y)` (zero outside an isolated
    /// grid; a periodic grid repeats).
    pub fn traction_at(&self, x: f64, y: f64) -> (f64, f64) {
        let [ny, nx] = self.grid.shape();
        let [dx, dy] = self.grid.cell();
        let [x0, y0] = self.grid.origin();
        let (mut fx, mut fy) = ((x - x0) / dx, (y - y0) / dy);
        if self.is_periodic() && fx.is_finite() && fy.is_finite() {
            fx = fx.rem_euclid(nx as f64);
            fy = fy.rem_euclid(ny as f64);
        }
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

    /// Total normal and tangential (x) force of the cells.
    fn resultants(tractions: &PointTractions) -> (f64, f64) {
        let [ny, nx] = tractions.grid().shape();
        let [dx, dy] = tractions.grid().cell();
        let (mut p_sum, mut q_sum) = (0.0, 0.0);
        for row in 0..ny {
            for column in 0..nx {
                let (p, qx, _) = tractions.grid().traction(row, column);
                p_sum += p * dx * dy;
                q_sum += qx * dx * dy;
            }
        }
        (p_sum, q_sum)
    }

    #[test]
    fn ellipse_and_partial_slip_cells_carry_their_loads() {
        use crate::contact::partial_slip::CattaneoMindlin;
        let third = 2.0 * std::f64::consts::PI / 3.0;
        // Elliptical Hertz: P = (2/3) pi a b p0 (Johnson 1985 §4.2), here with b = 0.4a.
        let ellipse = PointTractions::hertz_ellipse(81, 1.2, 0.4, 0.25, 0.3).expect("grid");
        assert!((ellipse.grid().cell()[1] / ellipse.grid().cell()[0] - 0.4).abs() < 1e-15);
        let (p, q) = resultants(&ellipse);
        assert!((p / (0.4 * third) - 1.0).abs() < 1e-4, "{p}");
        assert!((q / (0.25 * 0.4 * third) - 1.0).abs() < 1e-4, "{q}");
        // Cattaneo-Mindlin: the traction carries Q = 0.6 mu P.
        let slip = CattaneoMindlin::new(0.5, 0.6).expect("valid");
        let partial = PointTractions::mindlin_sphere(81, 1.2, &slip, 0.3).expect("grid");
        let (p, q) = resultants(&partial);
        assert!((p / third - 1.0).abs() < 1e-4, "{p}");
        assert!((q / (0.6 * 0.5 * third) - 1.0).abs() < 1e-4, "{q}");
    }

    #[test]
    fn surface_values_on_cell_edges_are_finite_means_of_the_neighbouring_centres() {
        // 8 cells over ±2: edges at multiples of 0.5, a corner at the origin.
        let tractions = PointTractions::hertz_sphere(8, 2.0, 0.3, 0.3).expect("grid");
        let exact = |x: f64, y: f64| tractions.grid().stress_at(x, y, 0.0, 0.3);
        assert!(!tractions.stress_over_p0(0.0, 0.0, 0.0).is_finite());
        let corner = tractions.finite_stress_over_p0(0.0, 0.0, 0.0);
        assert!(corner.is_finite(), "{corner:?}");
        let four = Stress::mean(&[
            exact(-0.25, -0.25),
            exact(0.25, -0.25),
            exact(-0.25, 0.25),
            exact(0.25, 0.25),
        ]);
        assert_eq!(corner, four);
        // On an x edge away from the corners: the two cells either side.
        let edge = tractions.finite_stress_over_p0(0.5, 0.25, 0.0);
        assert!(edge.is_finite(), "{edge:?}");
        assert_eq!(edge, Stress::mean(&[exact(0.25, 0.25), exact(0.75, 0.25)]));
        // szz = -p on the surface: the mean of the four cells' pressures at the corner.
        let p: f64 = [(-0.25, -0.25), (0.25, -0.25), (-0.25, 0.25), (0.25, 0.25)]
            .iter()
            .map(|&(x, y)| tractions.traction_at(x, y).0)
            .sum::<f64>()
            / 4.0;
        assert!((corner.zz + p).abs() < 1e-12, "{} vs {p}", corner.zz);
        // Cell centres and points below the surface are untouched.
        assert_eq!(
            tractions.finite_stress_over_p0(0.25, 0.25, 0.0),
            exact(0.25, 0.25)
        );
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
