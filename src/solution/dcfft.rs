//! Stresses of surface tractions given on a grid of uniform rectangular cells, summed from the
//! cells' exact influence coefficients ([`super::patch`]): directly, at any point, or by the
//! discrete convolution and fast Fourier transform (DC-FFT) of Liu, Wang & Liu (2000) at the
//! cell centres of whole depth layers.
//!
//! Layout: traction and stress arrays are indexed `[row, column] = [y, x]`; a layer of stresses
//! is `[component, y, x]` with the components in the order of [`COMPONENTS`].
//!
//! The grid is either isolated (zero traction beyond it) or one period of tractions that repeat
//! in x and y ([`Periodicity`]; the stress under a periodic rough contact).
//!
//! ## Periodic tractions
//! Tractions `t` repeating with the periods `Lx = nx dx`, `Ly = ny dy` are split into their mean
//! `t̄` and the zero-mean rest `t - t̄`. A uniform traction on the whole surface of a half-space
//! stresses it uniformly: `σzz = -p̄`, `τxz = -q̄x`, `τyz = -q̄y`, the other components zero
//! (this state satisfies equilibrium and the surface conditions, so it is the solution). The
//! rest carries no net force, so the stress of its periodic images falls off with their
//! distance faster than that of single cells: the images within the window
//! `|offset| <= (M + 1/2) L` (per axis, with `M = PERIODIC_IMAGES`, halved weights on the
//! window's edge so that it stays symmetric) are summed exactly, cell by cell, and the others
//! are left out. The coefficients `C_per(a, b) = Σ C(a + m nx, b + n ny)` over the window are
//! a circular convolution kernel; written into the offsets `0 <= a < nx` of the DC-FFT's
//! wrap-around layout (their mirror `-a` holds `C_per(nx - a)`, which the parity gives, since
//! the window is symmetric), the linear convolution computes the circular one. The tests
//! compare with a window of twelve images each way and with the closed form of a sinusoidal
//! pressure.
//!
//! Threads: everything here runs on the calling thread. The work of a layer splits into
//! independent pieces, blocks of influence-coefficient rows ([`DcFft::influence_blocks`]) and
//! the six stress components ([`DcFft::component_into`]), and layers are independent of each
//! other; `crate::field` runs them in parallel.

use std::sync::Arc;

use ndarray::{Array2, Array3, ArrayViewMut2, ArrayViewMut3, Axis};
use realfft::{ComplexToReal, RealFftPlanner, RealToComplex};
use rustfft::num_complex::Complex;
use rustfft::{Fft, FftPlanner};

use super::patch::{uniform_patch, uniform_patch_offset_rows, PatchStresses, Rectangle};
use crate::operator::elastic::Periodicity;
use crate::stress::Stress;

/// Periodic tractions: the images of each cell summed exactly in each direction, on each side
/// (the window `|offset| <= (M + 1/2) L`; module doc).
pub const PERIODIC_IMAGES: usize = 2;

/// The weight of the offset of `s` cells along an axis of `n` cells in the symmetric window of
/// `images` periods on each side: 1 inside, 1/2 on its edge, 0 beyond.
fn window_weight(s: usize, n: usize, images: usize) -> f64 {
    let (twice, limit) = (2 * s, (2 * images + 1) * n);
    match twice.cmp(&limit) {
        std::cmp::Ordering::Less => 1.0,
        std::cmp::Ordering::Equal => 0.5,
        std::cmp::Ordering::Greater => 0.0,
    }
}

/// The offsets `(s, weight)` of the periodic images of the offset `d` along an axis of period
/// `period`: the window of `images` periods on each side of the point (module doc).
fn image_offsets(d: f64, period: f64, images: usize) -> Vec<(f64, f64)> {
    let centred = d - period * (d / period).round();
    let half = (images as f64 + 0.5) * period;
    let reach = images as i64 + 1;
    (-reach..=reach)
        .filter_map(|n| {
            let s = centred + n as f64 * period;
            let excess = (s.abs() - half) / period;
            if excess < -1e-9 {
                Some((s, 1.0))
            } else if excess <= 1e-9 {
                Some((s, 0.5))
            } else {
                None
            }
        })
        .collect()
}

/// The nearest periodic image of the offset `d` along an axis of period `period`, as
/// `(offset, weight)`: one in `(-period/2, period/2)`, or both `±period/2` with weight 1/2.
fn centred_offsets(d: f64, period: f64) -> Vec<(f64, f64)> {
    let centred = d - period * (d / period).round();
    if ((centred.abs() - 0.5 * period) / period).abs() <= 1e-9 {
        vec![(-0.5 * period, 0.5), (0.5 * period, 0.5)]
    } else {
        vec![(centred, 1.0)]
    }
}

/// The images beyond the window, spread over the plane: minus the stress at offset `d` of
/// the window rectangle `|x| <= (M + 1/2) Lx`, `|y| <= (M + 1/2) Ly` loaded uniformly with
/// the cell's traction times `dx dy / (Lx Ly)` (module doc).
fn far_images(
    d: [f64; 2],
    z: f64,
    cell: [f64; 2],
    periods: [f64; 2],
    images: usize,
    nu: f64,
) -> PatchStresses {
    let half = images as f64 + 0.5;
    let window = Rectangle {
        x1: -half * periods[0],
        x2: half * periods[0],
        y1: -half * periods[1],
        y2: half * periods[1],
    };
    let density = -cell[0] * cell[1] / (periods[0] * periods[1]);
    let s = uniform_patch(d[0], d[1], z, window, nu);
    PatchStresses {
        pressure: s.pressure.scaled(density),
        shear_x: s.shear_x.scaled(density),
        shear_y: s.shear_y.scaled(density),
    }
}

/// The uniform stress of uniform tractions `[p, qx, qy]` on the whole surface, component `c`
/// in the order of [`COMPONENTS`].
fn uniform_stress(mean: [f64; 3], c: usize) -> f64 {
    let [p, qx, qy] = mean;
    [0.0, 0.0, -p, -qy, -qx, 0.0][c]
}

/// The order of the stress components in a layer: `xx, yy, zz, yz, xz, xy`.
pub const COMPONENTS: [&str; 6] = ["xx", "yy", "zz", "yz", "xz", "xy"];

/// The stress at cell `[row, column]` of a layer (`[component, y, x]`, components in the order
/// of [`COMPONENTS`]).
#[inline]
pub fn layer_stress(layer: &ndarray::ArrayView3<f64>, row: usize, column: usize) -> Stress {
    Stress {
        xx: layer[[0, row, column]],
        yy: layer[[1, row, column]],
        zz: layer[[2, row, column]],
        yz: layer[[3, row, column]],
        xz: layer[[4, row, column]],
        xy: layer[[5, row, column]],
    }
}

/// Invalid traction grids.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum TractionGridError {
    #[error("a traction grid needs at least one of pressure, shear_x, shear_y")]
    NoTraction,
    #[error("a traction grid needs at least one cell, got shape {0:?}")]
    Empty([usize; 2]),
    #[error(
        "{name} has shape {got:?} but {first} has {expected:?}; give every traction as [ny, nx]"
    )]
    ShapeMismatch {
        name: &'static str,
        got: [usize; 2],
        first: &'static str,
        expected: [usize; 2],
    },
    #[error("the cell size must be positive and finite, got dx = {dx}, dy = {dy}")]
    CellSize { dx: f64, dy: f64 },
    #[error("the grid origin must be finite, got ({0}, {1})")]
    Origin(f64, f64),
    #[error("{name}[{row}, {column}] is not finite ({value})")]
    NotFinite {
        name: &'static str,
        row: usize,
        column: usize,
        value: f64,
    },
}

/// Failures of the FFT library (lengths are fixed at planning, so these indicate a bug).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("DC-FFT: the real FFT failed: {0}")]
pub struct DcFftError(String);

impl From<realfft::FftError> for DcFftError {
    fn from(error: realfft::FftError) -> Self {
        Self(error.to_string())
    }
}

/// The three kinds of surface traction (the discriminant indexes stored coefficients).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Load {
    Pressure = 0,
    ShearX = 1,
    ShearY = 2,
}

impl Load {
    fn stress(self, s: &PatchStresses) -> &Stress {
        match self {
            Load::Pressure => &s.pressure,
            Load::ShearX => &s.shear_x,
            Load::ShearY => &s.shear_y,
        }
    }

    /// Parity `(in x, in y)` of each component's influence coefficient about the loaded cell:
    /// the pressure is symmetric in x and y, so a component is odd in x when it has an odd
    /// number of x indices (`xz`, `xy`); `qx` reverses under x -> -x, `qy` under y -> -y.
    fn parity(self, component: usize) -> (f64, f64) {
        const PRESSURE: [(f64, f64); 6] = [
            (1.0, 1.0),
            (1.0, 1.0),
            (1.0, 1.0),
            (1.0, -1.0),
            (-1.0, 1.0),
            (-1.0, -1.0),
        ];
        let (x, y) = PRESSURE[component];
        match self {
            Load::Pressure => (x, y),
            Load::ShearX => (-x, y),
            Load::ShearY => (x, -y),
        }
    }
}

fn component(s: &Stress, index: usize) -> f64 {
    [s.xx, s.yy, s.zz, s.yz, s.xz, s.xy][index]
}

/// Surface tractions, uniform on each cell of a regular grid.
///
/// Cell `[j, i]` (row `j` along y, column `i` along x) covers
/// `x0 + i dx <= x <= x0 + (i + 1) dx`, `y0 + j dy <= y <= y0 + (j + 1) dy`. Each traction is
/// optional (absent means zero): the pressure `p` pushes on the body (+z), `shear_x` and
/// `shear_y` act on the body in +x and +y.
#[derive(Clone, Debug, PartialEq)]
pub struct TractionGrid {
    origin: [f64; 2],
    cell: [f64; 2],
    shape: [usize; 2],
    pressure: Option<Array2<f64>>,
    shear_x: Option<Array2<f64>>,
    shear_y: Option<Array2<f64>>,
}

impl TractionGrid {
    /// Checks the arrays (same shape `[ny, nx]`, at least one cell, finite values) and the
    /// geometry (`origin = [x0, y0]` finite, `cell = [dx, dy]` positive and finite).
    pub fn new(
        origin: [f64; 2],
        cell: [f64; 2],
        pressure: Option<Array2<f64>>,
        shear_x: Option<Array2<f64>>,
        shear_y: Option<Array2<f64>>,
    ) -> Result<Self, TractionGridError> {
        let [dx, dy] = cell;
        if !(dx > 0.0 && dy > 0.0 && dx.is_finite() && dy.is_finite()) {
            return Err(TractionGridError::CellSize { dx, dy });
        }
        if !(origin[0].is_finite() && origin[1].is_finite()) {
            return Err(TractionGridError::Origin(origin[0], origin[1]));
        }
        let named = [
            ("pressure", &pressure),
            ("shear_x", &shear_x),
            ("shear_y", &shear_y),
        ];
        let mut first: Option<(&'static str, [usize; 2])> = None;
        for (name, array) in named {
            let Some(array) = array else { continue };
            let got = [array.nrows(), array.ncols()];
            match first {
                None => first = Some((name, got)),
                Some((first_name, expected)) if expected != got => {
                    return Err(TractionGridError::ShapeMismatch {
                        name,
                        got,
                        first: first_name,
                        expected,
                    })
                }
                Some(_) => {}
            }
            if let Some(((row, column), &value)) =
                array.indexed_iter().find(|(_, v)| !v.is_finite())
            {
                return Err(TractionGridError::NotFinite {
                    name,
                    row,
                    column,
                    value,
                });
            }
        }
        let Some((_, shape)) = first else {
            return Err(TractionGridError::NoTraction);
        };
        if shape[0] == 0 || shape[1] == 0 {
            return Err(TractionGridError::Empty(shape));
        }
        Ok(Self {
            origin,
            cell,
            shape,
            pressure,
            shear_x,
            shear_y,
        })
    }

    /// `[ny, nx]`.
    pub fn shape(&self) -> [usize; 2] {
        self.shape
    }

    /// `[dx, dy]`.
    pub fn cell(&self) -> [f64; 2] {
        self.cell
    }

    /// `[x0, y0]`, the corner of cell `[0, 0]` with the smallest coordinates.
    pub fn origin(&self) -> [f64; 2] {
        self.origin
    }

    /// The centre `(x, y)` of cell `[row, column]`.
    pub fn cell_centre(&self, row: usize, column: usize) -> (f64, f64) {
        (
            self.origin[0] + (column as f64 + 0.5) * self.cell[0],
            self.origin[1] + (row as f64 + 0.5) * self.cell[1],
        )
    }

    /// The rectangle of cell `[row, column]`.
    pub fn cell_rectangle(&self, row: usize, column: usize) -> Rectangle {
        let [x0, y0] = self.origin;
        let [dx, dy] = self.cell;
        Rectangle {
            x1: x0 + column as f64 * dx,
            x2: x0 + (column + 1) as f64 * dx,
            y1: y0 + row as f64 * dy,
            y2: y0 + (row + 1) as f64 * dy,
        }
    }

    /// The tractions `(p, qx, qy)` of cell `[row, column]`.
    pub fn traction(&self, row: usize, column: usize) -> (f64, f64, f64) {
        let at = |array: &Option<Array2<f64>>| array.as_ref().map_or(0.0, |a| a[[row, column]]);
        (at(&self.pressure), at(&self.shear_x), at(&self.shear_y))
    }

    /// The present tractions, each with its kind.
    fn loads(&self) -> impl Iterator<Item = (Load, &Array2<f64>)> {
        [
            (Load::Pressure, &self.pressure),
            (Load::ShearX, &self.shear_x),
            (Load::ShearY, &self.shear_y),
        ]
        .into_iter()
        .filter_map(|(load, array)| array.as_ref().map(|a| (load, a)))
    }

    /// Stress at any point `(x, y, z)`, `z >= 0`, by direct summation over the cells of
    /// [`uniform_patch`] times each cell's tractions (cells without traction are skipped).
    ///
    /// Cost: one patch evaluation per loaded cell. Exact for the piecewise-constant tractions,
    /// up to rounding (see [`uniform_patch`] for the accuracy and for the surface `z = 0`).
    pub fn stress_at(&self, x: f64, y: f64, z: f64, nu: f64) -> Stress {
        let [ny, nx] = self.shape;
        let mut sum = Stress::default();
        for row in 0..ny {
            for column in 0..nx {
                let (p, qx, qy) = self.traction(row, column);
                if p == 0.0 && qx == 0.0 && qy == 0.0 {
                    continue;
                }
                let s = uniform_patch(x, y, z, self.cell_rectangle(row, column), nu);
                sum = sum + s.pressure.scaled(p) + s.shear_x.scaled(qx) + s.shear_y.scaled(qy);
            }
        }
        sum
    }

    /// Stresses at every cell centre at depth `z` by direct summation, `[component, y, x]`.
    ///
    /// `O((nx ny)²)`: for small grids and for checking [`DcFft`].
    pub fn direct_layer(&self, z: f64, nu: f64) -> Array3<f64> {
        self.direct_layer_with(z, |x, y| self.stress_at(x, y, z, nu))
    }

    fn direct_layer_with(&self, _z: f64, stress: impl Fn(f64, f64) -> Stress) -> Array3<f64> {
        let [ny, nx] = self.shape;
        let mut out = Array3::zeros((6, ny, nx));
        for row in 0..ny {
            for column in 0..nx {
                let (x, y) = self.cell_centre(row, column);
                let s = stress(x, y);
                for c in 0..6 {
                    out[[c, row, column]] = component(&s, c);
                }
            }
        }
        out
    }

    /// The mean tractions `[p̄, q̄x, q̄y]` over the grid.
    pub fn mean_tractions(&self) -> [f64; 3] {
        let cells = (self.shape[0] * self.shape[1]) as f64;
        let mean = |array: &Option<Array2<f64>>| array.as_ref().map_or(0.0, |a| a.sum() / cells);
        [
            mean(&self.pressure),
            mean(&self.shear_x),
            mean(&self.shear_y),
        ]
    }

    /// Stress at `(x, y, z)` when the grid is one period of tractions repeating in x and y, by
    /// direct summation over the cells and their images in the window of [`PERIODIC_IMAGES`]
    /// periods (module doc). Cost: `(2M + 1)²` patch evaluations per cell.
    pub fn periodic_stress_at(&self, x: f64, y: f64, z: f64, nu: f64) -> Stress {
        self.periodic_stress_with_images(x, y, z, nu, PERIODIC_IMAGES)
    }

    /// [`TractionGrid::periodic_stress_at`] with a window of `images` periods on each side.
    pub fn periodic_stress_with_images(
        &self,
        x: f64,
        y: f64,
        z: f64,
        nu: f64,
        images: usize,
    ) -> Stress {
        let [ny, nx] = self.shape;
        let [dx, dy] = self.cell;
        let (period_x, period_y) = (nx as f64 * dx, ny as f64 * dy);
        let mean = self.mean_tractions();
        let cell = Rectangle {
            x1: -0.5 * dx,
            x2: 0.5 * dx,
            y1: -0.5 * dy,
            y2: 0.5 * dy,
        };
        let mut sum = Stress::default();
        for row in 0..ny {
            for column in 0..nx {
                let (p, qx, qy) = self.traction(row, column);
                let (p, qx, qy) = (p - mean[0], qx - mean[1], qy - mean[2]);
                if p == 0.0 && qx == 0.0 && qy == 0.0 {
                    continue;
                }
                let (xc, yc) = self.cell_centre(row, column);
                let of = |s: &PatchStresses| {
                    s.pressure.scaled(p) + s.shear_x.scaled(qx) + s.shear_y.scaled(qy)
                };
                for (sy, wy) in image_offsets(y - yc, period_y, images) {
                    for (sx, wx) in image_offsets(x - xc, period_x, images) {
                        let s = uniform_patch(sx, sy, z, cell, nu);
                        sum = sum + of(&s).scaled(wx * wy);
                    }
                }
                for (sy, wy) in centred_offsets(y - yc, period_y) {
                    for (sx, wx) in centred_offsets(x - xc, period_x) {
                        let s =
                            far_images([sx, sy], z, self.cell, [period_x, period_y], images, nu);
                        sum = sum + of(&s).scaled(wx * wy);
                    }
                }
            }
        }
        Stress {
            zz: sum.zz + uniform_stress(mean, 2),
            yz: sum.yz + uniform_stress(mean, 3),
            xz: sum.xz + uniform_stress(mean, 4),
            ..sum
        }
    }

    /// [`TractionGrid::direct_layer`] for periodic tractions
    /// ([`TractionGrid::periodic_stress_at`]).
    pub fn periodic_direct_layer(&self, z: f64, nu: f64) -> Array3<f64> {
        self.direct_layer_with(z, |x, y| self.periodic_stress_at(x, y, z, nu))
    }
}

/// FFT plans for one grid size `[ny, nx]`: real-to-complex along rows of length `2 nx`,
/// complex along columns of length `2 ny`. Shareable between [`DcFft`]s of the same size.
pub struct FftPlans {
    shape: [usize; 2],
    row_forward: Arc<dyn RealToComplex<f64>>,
    row_inverse: Arc<dyn ComplexToReal<f64>>,
    column_forward: Arc<dyn Fft<f64>>,
    column_inverse: Arc<dyn Fft<f64>>,
}

/// Columns of a spectrum transformed together, from gathering to the inverse transform, while
/// they stay in cache.
const COLUMN_CHUNK: usize = 8;

/// The rows of a real `2ny x 2nx` grid beyond the `ny` given ones.
#[derive(Clone, Copy, Debug)]
enum Rows {
    /// Zero (zero-padded tractions).
    ZeroPadded,
    /// Row `ny` zero and row `2ny - r` = `parity` times row `r` (influence coefficients in
    /// wrap-around order), so their transforms are the given rows' times the parity.
    Mirrored { parity: f64 },
}

impl FftPlans {
    /// Plans the transforms of a `(2 ny) x (2 nx)` zero-padded grid.
    pub fn new(shape: [usize; 2]) -> Self {
        let [ny, nx] = shape;
        let mut real_planner = RealFftPlanner::<f64>::new();
        let mut planner = FftPlanner::<f64>::new();
        Self {
            shape,
            row_forward: real_planner.plan_fft_forward(2 * nx),
            row_inverse: real_planner.plan_fft_inverse(2 * nx),
            column_forward: planner.plan_fft_forward(2 * ny),
            column_inverse: planner.plan_fft_inverse(2 * ny),
        }
    }

    /// Length of one full spectrum: `nx + 1` columns (`kx`) of `2 ny` values (`ky`), stored
    /// column after column, so that column transforms run on contiguous memory.
    fn spectrum_len(&self) -> usize {
        (self.shape[1] + 1) * 2 * self.shape[0]
    }

    /// Length of the row spectra of `ny` rows: `ny` rows of `nx + 1`.
    fn rows_len(&self) -> usize {
        (self.shape[1] + 1) * self.shape[0]
    }

    fn scratch_len(&self) -> usize {
        self.row_forward
            .get_scratch_len()
            .max(self.row_inverse.get_scratch_len())
            .max(self.column_forward.get_inplace_scratch_len())
            .max(self.column_inverse.get_inplace_scratch_len())
    }

    /// Real-to-complex transforms of the rows `r < ny` of a real `2ny x 2nx` grid, row `r`
    /// written into its argument by `fill_row(r, line)`, into `rows` (`ny` rows of `nx + 1`).
    fn row_spectra(
        &self,
        mut fill_row: impl FnMut(usize, &mut [f64]),
        work: &mut FftBuffers,
        rows: &mut [Complex<f64>],
    ) -> Result<(), DcFftError> {
        for (r, row) in rows.chunks_exact_mut(self.shape[1] + 1).enumerate() {
            fill_row(r, &mut work.line);
            self.row_forward
                .process_with_scratch(&mut work.line, row, &mut work.scratch)?;
        }
        Ok(())
    }

    /// Forward transforms of the columns `start..start + count` of a grid whose row spectra
    /// are `rows` (completed as `more` says), into `chunk` (column after column, `2 ny` each).
    fn column_chunk(
        &self,
        rows: &[Complex<f64>],
        more: Rows,
        start: usize,
        chunk: &mut [Complex<f64>],
        scratch: &mut [Complex<f64>],
    ) {
        let [ny, nx] = self.shape;
        let (width, height) = (nx + 1, 2 * ny);
        let count = chunk.len() / height;
        // Gather (a transpose of a narrow band: whole cache lines read per row).
        for (r, row) in rows.chunks_exact(width).enumerate() {
            for (t, value) in row[start..start + count].iter().enumerate() {
                chunk[t * height + r] = *value;
            }
        }
        let zero = Complex::new(0.0, 0.0);
        for column in chunk.chunks_exact_mut(height) {
            let (upper, lower) = column.split_at_mut(ny);
            match more {
                Rows::ZeroPadded => lower.fill(zero),
                Rows::Mirrored { parity } => {
                    lower[0] = zero;
                    for (target, value) in lower[1..].iter_mut().rev().zip(&upper[1..]) {
                        *target = parity * value;
                    }
                }
            }
        }
        self.column_forward.process_with_scratch(chunk, scratch);
    }

    /// The full spectrum of a zero-padded real grid whose rows `r < ny` are written by
    /// `fill_row`, column-major (see [`FftPlans::spectrum_len`]).
    fn spectrum(
        &self,
        fill_row: impl FnMut(usize, &mut [f64]),
        work: &mut FftBuffers,
    ) -> Result<Vec<Complex<f64>>, DcFftError> {
        let height = 2 * self.shape[0];
        let mut rows = vec![Complex::new(0.0, 0.0); self.rows_len()];
        self.row_spectra(fill_row, work, &mut rows)?;
        let mut spectrum = vec![Complex::new(0.0, 0.0); self.spectrum_len()];
        for (index, chunk) in spectrum.chunks_mut(COLUMN_CHUNK * height).enumerate() {
            let start = index * COLUMN_CHUNK;
            self.column_chunk(&rows, Rows::ZeroPadded, start, chunk, &mut work.scratch);
        }
        Ok(spectrum)
    }

    /// Inverse transforms of the columns `start..` of a spectrum given as `chunk` (destroyed),
    /// keeping the first `ny` values of each, scattered into the row spectra `rows`.
    fn inverse_column_chunk(
        &self,
        chunk: &mut [Complex<f64>],
        start: usize,
        rows: &mut [Complex<f64>],
        scratch: &mut [Complex<f64>],
    ) {
        let [ny, nx] = self.shape;
        let (width, height) = (nx + 1, 2 * ny);
        self.column_inverse.process_with_scratch(chunk, scratch);
        let count = chunk.len() / height;
        for (r, row) in rows.chunks_exact_mut(width).enumerate() {
            for (t, value) in row[start..start + count].iter_mut().enumerate() {
                *value = chunk[t * height + r];
            }
        }
    }

    /// Complex-to-real inverse transforms of the row spectra `rows` (destroyed), times
    /// `scale`, keeping the first `nx` values of each row, written into `out` `[y, x]`.
    fn inverse_rows(
        &self,
        rows: &mut [Complex<f64>],
        scale: f64,
        work: &mut FftBuffers,
        mut out: ArrayViewMut2<f64>,
    ) -> Result<(), DcFftError> {
        let nx = self.shape[1];
        for (r, row) in rows.chunks_exact_mut(nx + 1).enumerate() {
            // Each row's spectrum is that of a real row: its first and last values are real
            // up to rounding, and the real inverse transform requires them exactly real.
            row[0].im = 0.0;
            row[nx].im = 0.0;
            self.row_inverse
                .process_with_scratch(row, &mut work.line, &mut work.scratch)?;
            for (target, value) in out.row_mut(r).iter_mut().zip(&work.line) {
                *target = scale * value;
            }
        }
        Ok(())
    }
}

/// A real row and FFT scratch.
struct FftBuffers {
    line: Vec<f64>,
    scratch: Vec<Complex<f64>>,
}

impl FftBuffers {
    fn new(plans: &FftPlans) -> Self {
        Self {
            line: vec![0.0; 2 * plans.shape[1]],
            scratch: vec![Complex::new(0.0, 0.0); plans.scratch_len()],
        }
    }
}

/// The working memory of one depth layer (reused from layer to layer by one worker): the
/// influence coefficients of one quadrant of offsets (`144 nx ny` bytes), the row spectra of
/// one component for each load present and of the result (`16 nx ny` bytes each), and a few
/// columns' spectra.
pub struct Workspace {
    /// `[load][component][b][a]`: 18 arrays of `nx ny`.
    quadrant: Vec<f64>,
    component: ComponentWorkspace,
}

/// Working memory of one stress component of a layer ([`DcFft::component_into`]).
pub struct ComponentWorkspace {
    /// Row spectra of one component's coefficients, one per load present.
    rows: Vec<Vec<Complex<f64>>>,
    /// Row spectra of one component of the result.
    result_rows: Vec<Complex<f64>>,
    /// Spectra of a chunk of columns: one load's coefficients, and the sum over loads.
    chunk: Vec<Complex<f64>>,
    sum: Vec<Complex<f64>>,
    buffers: FftBuffers,
}

/// Stresses of a [`TractionGrid`] at its cell centres, layer by layer, by DC-FFT.
///
/// ## Method
/// The stress at cell centre `(i, j)` is the discrete convolution
/// `S(i, j) = Σ_(k,l) C(i - k, j - l) t(k, l)` of the cell tractions `t` with the influence
/// coefficients `C(a, b)`, the stress of [`uniform_patch`] at offset `(a dx, b dy)` from a unit
/// loaded cell. Following Liu, Wang & Liu (2000), the coefficients of the offsets
/// `-n < a < n` are laid out in wrap-around order on a `2n` grid (offset `a` at index `a` for
/// `a >= 0`, at `2n + a` for `a < 0`, zero at index `n`), the tractions are zero-padded to the
/// same `2n`, and their cyclic convolution, computed as a product of discrete Fourier
/// transforms, equals the linear one on the first `n` indices — exactly, not as a periodic
/// approximation. Per layer and per component the spectra of the loads present are multiplied
/// and summed, and one inverse transform gives the component.
///
/// The coefficients are evaluated on one quadrant `a, b >= 0` (from corner terms shared between
/// neighbouring cells, [`uniform_patch_offset_rows`]) and mirrored by their parity (each component
/// is even or odd in x and in y about the loaded cell); the mirrored rows' transforms are the
/// transformed rows times the parity. The tractions' spectra are computed once, in
/// [`DcFft::new`]; each layer then costs one forward transform per load and component and one
/// inverse per component, real-to-complex along rows (`realfft`) and complex along columns
/// (`rustfft`). The column pass runs on a few columns at a time, from gathering through the
/// products to the inverse transform, so that it works in cache.
///
/// The result equals direct summation ([`TractionGrid::direct_layer`]) up to rounding (the
/// tests ask 1e-9 of the largest traction); its accuracy as an approximation of smooth
/// tractions is that of their discretisation into uniform cells.
///
/// ## Reference
/// S. Liu, Q. Wang, G. Liu, A versatile method of discrete convolution and FFT (DC-FFT) for
/// contact analyses, *Wear* 243 (2000).
pub struct DcFft {
    shape: [usize; 2],
    cell: [f64; 2],
    poisson: f64,
    plans: Arc<FftPlans>,
    /// The spectra of the zero-padded tractions present (periodic: less their mean).
    tractions: Vec<(Load, Vec<Complex<f64>>)>,
    periodicity: Periodicity,
    /// Periodic: the mean tractions `[p̄, q̄x, q̄y]`, whose stress is uniform.
    mean: [f64; 3],
}

impl DcFft {
    /// Plans the transforms and transforms the tractions of an isolated grid.
    pub fn new(grid: &TractionGrid, poisson: f64) -> Result<Self, DcFftError> {
        Self::with_plans(grid, poisson, Arc::new(FftPlans::new(grid.shape)))
    }

    /// As [`DcFft::new`] for a grid that is one period of tractions repeating in x and y
    /// (module doc).
    pub fn periodic(grid: &TractionGrid, poisson: f64) -> Result<Self, DcFftError> {
        Self::build(
            grid,
            poisson,
            Arc::new(FftPlans::new(grid.shape)),
            Periodicity::Periodic,
        )
    }

    /// Isolated or periodic.
    pub fn periodicity(&self) -> Periodicity {
        self.periodicity
    }

    /// As [`DcFft::new`], reusing plans made for the same grid shape.
    ///
    /// # Panics
    /// If `plans` were made for another shape.
    pub fn with_plans(
        grid: &TractionGrid,
        poisson: f64,
        plans: Arc<FftPlans>,
    ) -> Result<Self, DcFftError> {
        Self::build(grid, poisson, plans, Periodicity::NonPeriodic)
    }

    fn build(
        grid: &TractionGrid,
        poisson: f64,
        plans: Arc<FftPlans>,
        periodicity: Periodicity,
    ) -> Result<Self, DcFftError> {
        assert_eq!(plans.shape, grid.shape, "FFT plans for another grid shape");
        let nx = grid.shape[1];
        let mean = match periodicity {
            Periodicity::Periodic => grid.mean_tractions(),
            Periodicity::NonPeriodic => [0.0; 3],
        };
        let mut buffers = FftBuffers::new(&plans);
        let mut tractions = Vec::new();
        for (load, array) in grid.loads() {
            let shift = mean[load as usize];
            let fill_row = |r: usize, line: &mut [f64]| {
                for (target, value) in line.iter_mut().zip(array.row(r)) {
                    *target = *value - shift;
                }
                line[nx..].fill(0.0);
            };
            tractions.push((load, plans.spectrum(fill_row, &mut buffers)?));
        }
        Ok(Self {
            shape: grid.shape,
            cell: grid.cell,
            poisson,
            plans,
            tractions,
            periodicity,
            mean,
        })
    }

    /// `[ny, nx]`.
    pub fn shape(&self) -> [usize; 2] {
        self.shape
    }

    /// The plans, to share with another [`DcFft`] of the same shape.
    pub fn plans(&self) -> Arc<FftPlans> {
        Arc::clone(&self.plans)
    }

    /// Fresh working memory for [`DcFft::layer_into`].
    pub fn workspace(&self) -> Workspace {
        let [ny, nx] = self.shape;
        Workspace {
            quadrant: vec![0.0; 18 * nx * ny],
            component: self.component_workspace(),
        }
    }

    /// Fresh working memory for [`DcFft::component_into`].
    pub fn component_workspace(&self) -> ComponentWorkspace {
        let [ny, _] = self.shape;
        let zero = Complex::new(0.0, 0.0);
        let rows = self.plans.rows_len();
        ComponentWorkspace {
            rows: vec![vec![zero; rows]; self.tractions.len()],
            result_rows: vec![zero; rows],
            chunk: vec![zero; COLUMN_CHUNK * 2 * ny],
            sum: vec![zero; COLUMN_CHUNK * 2 * ny],
            buffers: FftBuffers::new(&self.plans),
        }
    }

    /// The stresses at depth `z >= 0` at every cell centre, `[component, y, x]` (shape
    /// `[6, ny, nx]`), computed on the calling thread with `workspace`.
    ///
    /// # Panics
    /// If `out` is not `[6, ny, nx]`.
    pub fn layer_into(
        &self,
        z: f64,
        workspace: &mut Workspace,
        mut out: ArrayViewMut3<f64>,
    ) -> Result<(), DcFftError> {
        let [ny, nx] = self.shape;
        assert_eq!(out.shape(), [6, ny, nx], "layer output must be [6, ny, nx]");
        self.influence_into(z, &mut workspace.quadrant);
        for c in 0..6 {
            self.component_into(
                &workspace.quadrant,
                c,
                &mut workspace.component,
                out.index_axis_mut(Axis(0), c),
            )?;
        }
        Ok(())
    }

    /// The influence coefficients of depth `z` for [`DcFft::component_into`]: fills
    /// `quadrant`, of the length of [`Workspace`]'s (`18 nx ny`).
    pub fn influence_into(&self, z: f64, quadrant: &mut Vec<f64>) {
        for block in self.influence_blocks(quadrant, 1) {
            self.fill_influence(z, block);
        }
    }

    /// One stress component (`c` in the order of [`COMPONENTS`]) of a layer whose influence
    /// coefficients are in `quadrant` ([`DcFft::influence_into`]), `[y, x]`. The six
    /// components of a layer are independent, so callers may compute them on different
    /// threads, each with its own [`ComponentWorkspace`].
    ///
    /// # Panics
    /// If `out` is not `[ny, nx]` or `c >= 6`.
    pub fn component_into(
        &self,
        quadrant: &[f64],
        c: usize,
        workspace: &mut ComponentWorkspace,
        mut out: ArrayViewMut2<f64>,
    ) -> Result<(), DcFftError> {
        let [ny, nx] = self.shape;
        assert!(c < 6, "stress component index {c} out of 0..6");
        assert_eq!(out.shape(), [ny, nx], "component output must be [ny, nx]");
        let ComponentWorkspace {
            rows,
            result_rows,
            chunk,
            sum,
            buffers,
        } = workspace;
        let scale = 1.0 / (4 * nx * ny) as f64;
        let (cells, height) = (nx * ny, 2 * ny);
        // Row transforms of this component's coefficients, for each load.
        let periodic = self.periodicity == Periodicity::Periodic;
        for ((load, _), load_rows) in self.tractions.iter().zip(rows.iter_mut()) {
            let (parity_x, parity_y) = load.parity(c);
            let offset = (*load as usize * 6 + c) * cells;
            let coefficients = &quadrant[offset..offset + cells];
            // Row b of the wrap-around grid: offsets 0..nx, a zero, then the mirror.
            let fill_row = |b: usize, line: &mut [f64]| {
                // Periodic rows beyond ny/2 are the mirror of row ny - b.
                let (b, sign) = if periodic && 2 * b > ny {
                    (ny - b, parity_y)
                } else {
                    (b, 1.0)
                };
                let source = &coefficients[b * nx..(b + 1) * nx];
                for (target, value) in line[..nx].iter_mut().zip(source) {
                    *target = sign * value;
                }
                line[nx] = 0.0;
                for (target, value) in line[nx + 1..].iter_mut().rev().zip(&source[1..]) {
                    *target = sign * parity_x * value;
                }
            };
            self.plans.row_spectra(fill_row, buffers, load_rows)?;
        }
        // Column by column chunk: forward transforms, products with the tractions'
        // spectra summed over the loads, inverse transforms.
        for start in (0..=nx).step_by(COLUMN_CHUNK) {
            let length = COLUMN_CHUNK.min(nx + 1 - start) * height;
            let (chunk, sum) = (&mut chunk[..length], &mut sum[..length]);
            sum.fill(Complex::new(0.0, 0.0));
            for ((load, traction), load_rows) in self.tractions.iter().zip(rows.iter()) {
                let more = Rows::Mirrored {
                    parity: load.parity(c).1,
                };
                let scratch = &mut buffers.scratch;
                self.plans
                    .column_chunk(load_rows, more, start, chunk, scratch);
                let traction = &traction[start * height..start * height + length];
                for ((total, coefficient), t) in sum.iter_mut().zip(&*chunk).zip(traction) {
                    *total += coefficient * t;
                }
            }
            self.plans
                .inverse_column_chunk(sum, start, result_rows, &mut buffers.scratch);
        }
        self.plans
            .inverse_rows(result_rows, scale, buffers, out.view_mut())?;
        let uniform = uniform_stress(self.mean, c);
        if uniform != 0.0 {
            out.mapv_inplace(|v| v + uniform);
        }
        Ok(())
    }

    /// The stresses of one layer, `[component, y, x]`, on the calling thread.
    pub fn layer(&self, z: f64) -> Result<Array3<f64>, DcFftError> {
        let [ny, nx] = self.shape;
        let mut out = Array3::zeros((6, ny, nx));
        self.layer_into(z, &mut self.workspace(), out.view_mut())?;
        Ok(out)
    }

    /// Splits `quadrant` (resized to the length of [`Workspace`]'s, `18 nx ny`) into at most
    /// `blocks` blocks of consecutive offset rows, to be filled by
    /// [`DcFft::fill_influence`], possibly on different threads; together they make the
    /// influence coefficients that [`DcFft::influence_into`] computes in one piece.
    pub fn influence_blocks<'q>(
        &self,
        quadrant: &'q mut Vec<f64>,
        blocks: usize,
    ) -> Vec<InfluenceBlock<'q>> {
        let [ny, nx] = self.shape;
        quadrant.resize(18 * nx * ny, 0.0);
        // Periodic coefficients are needed on the rows b <= ny/2 only: the others are their
        // mirror (C_per(a, ny - b) = C_per(a, -b)), read so by `component_into`.
        let filled = match self.periodicity {
            Periodicity::NonPeriodic => ny,
            Periodicity::Periodic => ny / 2 + 1,
        };
        let rows_per_block = filled.div_ceil(blocks.clamp(1, filled.max(1)));
        let mut out: Vec<InfluenceBlock<'q>> = (0..filled.div_ceil(rows_per_block))
            .map(|k| InfluenceBlock {
                rows: k * rows_per_block..((k + 1) * rows_per_block).min(filled),
                arrays: Vec::with_capacity(18),
            })
            .collect();
        for array in quadrant.chunks_exact_mut(nx * ny) {
            let array = &mut array[..filled * nx];
            for (block, rows) in out.iter_mut().zip(array.chunks_mut(rows_per_block * nx)) {
                block.arrays.push(rows);
            }
        }
        out
    }

    /// Fills one block of [`DcFft::influence_blocks`] with the coefficients of depth `z`: the
    /// stresses at offsets `(a dx, b dy)`, `0 <= a < nx`, `b` in the block's rows, as 18 arrays
    /// `[load][component][b][a]` (those of absent loads are left alone).
    pub fn fill_influence(&self, z: f64, block: InfluenceBlock<'_>) {
        let nx = self.shape[1];
        let present = |load: Load| self.tractions.iter().any(|(l, _)| *l == load);
        let loads: Vec<Load> = [Load::Pressure, Load::ShearX, Load::ShearY]
            .into_iter()
            .filter(|&load| present(load))
            .collect();
        if self.periodicity == Periodicity::Periodic {
            self.fill_periodic_influence(z, block, &loads);
            return;
        }
        let InfluenceBlock { rows, mut arrays } = block;
        let first_row = rows.start;
        uniform_patch_offset_rows(self.cell, z, nx, rows, self.poisson, |a, b, s| {
            let index = (b - first_row) * nx + a;
            for &load in &loads {
                let stress = load.stress(s);
                let first = load as usize * 6;
                let values = [
                    stress.xx, stress.yy, stress.zz, stress.yz, stress.xz, stress.xy,
                ];
                for (array, value) in arrays[first..first + 6].iter_mut().zip(values) {
                    array[index] = value;
                }
            }
        });
    }
}

impl DcFft {
    /// [`DcFft::fill_influence`] of periodic tractions: the coefficients `C_per(a, b)` of the
    /// circular offsets `0 <= a < nx`, `b` in the block's rows (`b <= ny/2`: the others are
    /// their mirror, see [`DcFft::influence_blocks`]), each the sum of the cell's
    /// coefficients over the images in the window (module doc). Every offset `s` of the window
    /// along y with `s mod ny` in the block is evaluated for all `|a'|` of the window along x
    /// and folded: `a'` onto `a' mod nx`, and `-a'` (by the parity in x) onto `-a' mod nx`.
    fn fill_periodic_influence(&self, z: f64, block: InfluenceBlock<'_>, loads: &[Load]) {
        let [ny, nx] = self.shape;
        let images = PERIODIC_IMAGES;
        let InfluenceBlock { rows, mut arrays } = block;
        for &load in loads {
            for array in &mut arrays[load as usize * 6..load as usize * 6 + 6] {
                array.fill(0.0);
            }
        }
        let reach_x = (2 * images + 1) * nx / 2;
        let reach_y = (2 * images + 1) * ny / 2;
        let reach = images as i64 + 1;
        for n in -reach..=reach {
            // The offsets s = b + n ny of the block's rows b, as |s| (a contiguous range):
            // n >= 0 gives s >= 0; n < 0 gives s < 0, mirrored by the parity in y.
            let (start, end, mirrored) = if n >= 0 {
                let shift = n as usize * ny;
                (rows.start + shift, rows.end + shift, false)
            } else {
                let shift = (-n) as usize * ny;
                (shift + 1 - rows.end, shift + 1 - rows.start, true)
            };
            let end = end.min(reach_y + 1);
            if start >= end {
                continue;
            }
            let row_of = |s: usize| -> usize {
                if mirrored {
                    (-n) as usize * ny - s
                } else {
                    s - n as usize * ny
                }
            };
            uniform_patch_offset_rows(
                self.cell,
                z,
                reach_x + 1,
                start..end,
                self.poisson,
                |a, s, stresses| {
                    let weight = window_weight(a, nx, images) * window_weight(s, ny, images);
                    if weight == 0.0 {
                        return;
                    }
                    let row = row_of(s) - rows.start;
                    let plus = row * nx + a % nx;
                    let minus = row * nx + (nx - a % nx) % nx;
                    for &load in loads {
                        let stress = load.stress(stresses);
                        let first = load as usize * 6;
                        for c in 0..6 {
                            let (parity_x, parity_y) = load.parity(c);
                            let sign = if mirrored { parity_y } else { 1.0 };
                            let value = weight * sign * component(stress, c);
                            let array = &mut arrays[first + c];
                            array[plus] += value;
                            if a > 0 {
                                array[minus] += parity_x * value;
                            }
                        }
                    }
                },
            );
        }
        // The images beyond the window, seen from the cell's nearest image.
        let [dx, dy] = self.cell;
        let periods = [nx as f64 * dx, ny as f64 * dy];
        for b in rows.clone() {
            for a in 0..nx {
                let index = (b - rows.start) * nx + a;
                for (sy, wy) in centred_offsets(b as f64 * dy, periods[1]) {
                    for (sx, wx) in centred_offsets(a as f64 * dx, periods[0]) {
                        let far = far_images([sx, sy], z, self.cell, periods, images, self.poisson);
                        for &load in loads {
                            let stress = load.stress(&far);
                            for c in 0..6 {
                                arrays[load as usize * 6 + c][index] +=
                                    wx * wy * component(stress, c);
                            }
                        }
                    }
                }
            }
        }
    }
}

/// A block of rows of the influence coefficients of a layer ([`DcFft::influence_blocks`]):
/// the rows `b` of each of the 18 arrays `[load][component]`.
pub struct InfluenceBlock<'q> {
    rows: std::ops::Range<usize>,
    arrays: Vec<&'q mut [f64]>,
}

#[cfg(test)]
mod tests {
    use super::*;

    fn grid(shape: [usize; 2], loads: [bool; 3]) -> TractionGrid {
        let [ny, nx] = shape;
        let field = |seed: f64| {
            Array2::from_shape_fn((ny, nx), |(j, i)| {
                let (x, y) = (i as f64 / nx as f64, j as f64 / ny as f64);
                (seed * x + 2.1 * y + seed * x * y).sin() + 0.3 * (7.0 * x * seed).cos()
            })
        };
        TractionGrid::new(
            [-0.4, 0.3],
            [0.1, 0.07],
            loads[0].then(|| field(1.3)),
            loads[1].then(|| field(2.9)),
            loads[2].then(|| field(-1.7)),
        )
        .expect("valid grid")
    }

    fn assert_layers_agree(grid: &TractionGrid, depths: &[f64], nu: f64) {
        let fft = DcFft::new(grid, nu).expect("planned");
        for &z in depths {
            let direct = grid.direct_layer(z, nu);
            let difference = (&fft.layer(z).expect("transformed") - &direct)
                .iter()
                .fold(0.0f64, |m, v| m.max(v.abs()));
            assert!(
                difference < 1e-9,
                "z = {z}: max |FFT - direct| = {difference:e}"
            );
            let shape = grid.shape();
            eprintln!("{shape:?}, z = {z}: max |FFT - direct| = {difference:.1e}");
        }
    }

    #[test]
    fn fft_equals_direct_summation_on_small_grids() {
        // Tractions of order one; 16 x 12 and 20 x 20; the surface, tiny and larger depths.
        assert_layers_agree(
            &grid([12, 16], [true, true, true]),
            &[0.0, 1e-6, 0.03, 0.7],
            0.3,
        );
        assert_layers_agree(&grid([20, 20], [true, true, false]), &[0.0, 0.01, 2.0], 0.5);
        assert_layers_agree(&grid([7, 5], [false, false, true]), &[0.0, 0.2], 0.0);
        // Degenerate shapes: one cell, one row, one column.
        assert_layers_agree(&grid([1, 1], [true, true, true]), &[0.0, 0.5], 0.3);
        assert_layers_agree(&grid([1, 6], [true, false, false]), &[0.1], 0.3);
        assert_layers_agree(&grid([5, 1], [false, true, false]), &[0.1], 0.3);
    }

    fn max_difference(a: &Array3<f64>, b: &Array3<f64>) -> f64 {
        (a - b).iter().fold(0.0f64, |m, v| m.max(v.abs()))
    }

    #[test]
    fn periodic_fft_equals_periodic_direct_summation() {
        // Even and odd sizes (the window's edge falls on a cell for even ones), one row.
        for (shape, loads, nu) in [
            ([6, 8], [true, true, true], 0.3),
            ([5, 7], [true, true, false], 0.25),
            ([1, 6], [true, false, true], 0.3),
            ([4, 1], [false, true, false], 0.0),
        ] {
            let grid = grid(shape, loads);
            let fft = DcFft::periodic(&grid, nu).expect("planned");
            for z in [0.0, 0.02, 0.3, 1.5] {
                let difference = max_difference(
                    &fft.layer(z).expect("transformed"),
                    &grid.periodic_direct_layer(z, nu),
                );
                assert!(difference < 1e-9, "{shape:?}, z = {z}: {difference:e}");
            }
        }
    }

    #[test]
    fn periodic_images_beyond_the_window_are_negligible() {
        // Zero-mean tractions carry no net force: with the far images spread over the plane,
        // the window of two periods each way is within 1e-3 of the largest traction of the
        // window of twelve (measured: 4.8e-4).
        let grid = grid([6, 8], [true, true, true]);
        let largest = grid
            .loads()
            .flat_map(|(_, a)| a.iter().map(|v| v.abs()))
            .fold(0.0, f64::max);
        let mut worst = 0.0f64;
        for (x, y) in [(0.05, 0.6), (-0.35, 0.33), (0.35, 0.0)] {
            for z in [0.0, 0.1, 0.4, 1.0] {
                let near = grid.periodic_stress_at(x, y, z, 0.3);
                let far = grid.periodic_stress_with_images(x, y, z, 0.3, 12);
                let difference = (0..6)
                    .map(|c| (component(&near, c) - component(&far, c)).abs())
                    .fold(0.0, f64::max);
                worst = worst.max(difference / largest);
            }
        }
        eprintln!("periodic images: window 2 vs 12, largest difference {worst:.1e} of the largest traction");
        assert!(worst < 1e-3, "{worst:e}");
    }

    #[test]
    fn uniform_periodic_tractions_stress_the_body_uniformly() {
        let [ny, nx] = [5, 6];
        let uniform = |v: f64| Some(Array2::from_elem((ny, nx), v));
        let grid = TractionGrid::new(
            [0.3, -1.0],
            [0.2, 0.3],
            uniform(1.5),
            uniform(0.4),
            uniform(-0.2),
        )
        .expect("valid");
        let fft = DcFft::periodic(&grid, 0.3).expect("planned");
        for z in [0.0, 0.1, 3.0] {
            let layer = fft.layer(z).expect("transformed");
            for (c, expected) in [0.0, 0.0, -1.5, 0.2, -0.4, 0.0].into_iter().enumerate() {
                for value in layer.index_axis(Axis(0), c) {
                    assert!(
                        (value - expected).abs() < 1e-12,
                        "c = {c}, z = {z}: {value}"
                    );
                }
            }
        }
    }

    #[test]
    fn a_sinusoidal_pressure_gives_the_closed_form() {
        // p = p̄ + p1 cos(kx), uniform in y: plane strain. Its stress, from the Airy function
        // (A + A kz) e^(-kz) cos kx with A = p1/k² (derived here): σxx = -p1 (1 - kz) e^(-kz) cos kx,
        // σzz = -p̄ - p1 (1 + kz) e^(-kz) cos kx, τxz = -p1 kz e^(-kz) sin kx,
        // σyy = ν (σxx + σzz) + (uniform part 0). The cells carry the cell means of the
        // pressure, whose fundamental has the amplitude p1 sinc²(k dx/2); the harmonics of the
        // steps fall as e^(-2π z/dx), about 3e-6 p1 at z = 2 dx. The images beyond the window
        // leave up to 5e-5 (measured; 1e-4 asked).
        let (nx, ny, dx, nu) = (32, 3, 1.0 / 32.0, 0.3);
        let k = 2.0 * std::f64::consts::PI;
        let (mean, p1) = (1.0, 0.6);
        let half = 0.5 * k * dx;
        let sinc = half.sin() / half;
        let pressure = Array2::from_shape_fn((ny, nx), |(_, i)| {
            let x = (i as f64 + 0.5) * dx;
            mean + p1 * k.recip() / dx * ((k * (x + 0.5 * dx)).sin() - (k * (x - 0.5 * dx)).sin())
        });
        let grid =
            TractionGrid::new([0.0, 0.0], [dx, 0.5], Some(pressure), None, None).expect("valid");
        let fft = DcFft::periodic(&grid, nu).expect("planned");
        let amplitude = p1 * sinc * sinc;
        for z in [2.0 * dx, 0.1, 0.3] {
            let layer = fft.layer(z).expect("transformed");
            let decay = (-k * z).exp();
            for i in 0..nx {
                let x = (i as f64 + 0.5) * dx;
                let (c, s) = ((k * x).cos(), (k * x).sin());
                let sxx = -amplitude * (1.0 - k * z) * decay * c;
                let szz = -mean - amplitude * (1.0 + k * z) * decay * c;
                let sxz = -amplitude * k * z * decay * s;
                let syy = nu * (sxx + szz + mean);
                for (component, expected) in [(0, sxx), (1, syy), (2, szz), (4, sxz)] {
                    let got = layer[[component, 1, i]];
                    assert!(
                        (got - expected).abs() < 1e-4,
                        "z = {z}, x = {x}, component {component}: {got} vs {expected}"
                    );
                }
                for component in [3, 5] {
                    assert!(layer[[component, 1, i]].abs() < 1e-12);
                }
            }
        }
    }

    #[test]
    fn shape_mismatch_and_missing_tractions_are_reported() {
        let a = Array2::zeros((3, 4));
        let b = Array2::zeros((4, 3));
        assert_eq!(
            TractionGrid::new([0.0; 2], [1.0; 2], Some(a.clone()), None, Some(b)),
            Err(TractionGridError::ShapeMismatch {
                name: "shear_y",
                got: [4, 3],
                first: "pressure",
                expected: [3, 4],
            })
        );
        assert_eq!(
            TractionGrid::new([0.0; 2], [1.0; 2], None, None, None),
            Err(TractionGridError::NoTraction)
        );
        assert!(matches!(
            TractionGrid::new([0.0; 2], [0.0, 1.0], Some(a), None, None),
            Err(TractionGridError::CellSize { .. })
        ));
    }
}
