//! The lattice of influence coefficients of a grid of uniformly heated rectangular cells, and
//! its linear convolution with a gridded flux by DC-FFT (Liu, Wang & Liu 2000): the kernel for
//! the offsets `-n <= i < n` in wrap-around order on a `2n` grid, the flux zero-padded to it,
//! the first `n` values of the cyclic convolution kept. Thermal kernels are not even in x (the
//! heat is swept behind the contact), so their spectra are complex.

use ndarray::{Array2, ArrayView2, ArrayViewMut2};
use rayon::prelude::*;
use rustfft::num_complex::Complex;

use crate::operator::transform::{Fft2Work, RealFft2, TransformError};

/// A grid of `[ny, nx]` rectangular cells `dx x dy` (row = y); cell `(0, 0)` is centred at the
/// grid's origin, offsets are counted in cells.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CellGrid {
    /// `[ny, nx]`.
    pub shape: [usize; 2],
    /// `[dx, dy]`, m.
    pub spacing_m: [f64; 2],
}

impl CellGrid {
    /// The lattice of `value(i, j)` for the offsets `-nx <= i < nx`, `-ny <= j < ny` (cells),
    /// in wrap-around order on `[2 ny, 2 nx]`, rows evaluated in parallel.
    pub fn offset_lattice(&self, value: impl Fn(i64, i64) -> f64 + Sync) -> Array2<f64> {
        let [ny, nx] = self.shape;
        let mut lattice = Array2::zeros((2 * ny, 2 * nx));
        lattice
            .axis_iter_mut(ndarray::Axis(0))
            .into_par_iter()
            .enumerate()
            .for_each(|(row, mut line)| {
                let j = signed(row, 2 * ny);
                for (column, slot) in line.iter_mut().enumerate() {
                    *slot = value(signed(column, 2 * nx), j);
                }
            });
        lattice
    }

    /// `value(i, j)` for the column offsets `-nx < i < nx` (column `i + nx - 1`) and the row
    /// offsets `rows` (one row each, in their order), rows evaluated in parallel: the
    /// coefficients that one row of a convolution needs.
    pub fn offset_rows(&self, rows: &[i64], value: impl Fn(i64, i64) -> f64 + Sync) -> Array2<f64> {
        let nx = self.shape[1] as i64;
        let mut lattice = Array2::zeros((rows.len(), (2 * nx - 1).max(0) as usize));
        lattice
            .axis_iter_mut(ndarray::Axis(0))
            .into_par_iter()
            .zip(rows.par_iter())
            .for_each(|(mut line, &j)| {
                for (column, slot) in line.iter_mut().enumerate() {
                    *slot = value(column as i64 - nx + 1, j);
                }
            });
        lattice
    }
}

/// The signed offset stored at `index` of a wrap-around axis of length `n` (`n` even).
pub fn signed(index: usize, n: usize) -> i64 {
    if index < n / 2 {
        index as i64
    } else {
        index as i64 - n as i64
    }
}

/// A real kernel on the offsets of a [`CellGrid`], applied by DC-FFT.
pub struct Convolution {
    shape: [usize; 2],
    plan: RealFft2,
    kernel: Array2<Complex<f64>>,
    spectrum: Array2<Complex<f64>>,
    work: Fft2Work,
}

impl Convolution {
    /// The convolution with `lattice` (`[2 ny, 2 nx]`, wrap-around order, see
    /// [`CellGrid::offset_lattice`]) on a grid of `shape`.
    pub fn new(shape: [usize; 2], lattice: ArrayView2<f64>) -> Result<Self, TransformError> {
        let plan = RealFft2::new([2 * shape[0], 2 * shape[1]]);
        let mut work = plan.work();
        let mut kernel = plan.new_spectrum();
        plan.forward(lattice, &mut kernel, &mut work)?;
        let spectrum = plan.new_spectrum();
        Ok(Self {
            shape,
            plan,
            kernel,
            spectrum,
            work,
        })
    }

    /// Bytes held for a grid of `shape` (kernel and input spectra, FFT row buffers).
    pub fn memory_bytes(shape: [usize; 2]) -> usize {
        let half = (shape[1] + 1) * 2 * shape[0];
        half * 16 * 3
    }

    pub fn shape(&self) -> [usize; 2] {
        self.shape
    }

    /// The zero-padded spectrum of `input` (`[ny, nx]`), for [`Self::apply_transformed`]: one
    /// transform of a flux serves every kernel of the same grid.
    pub fn transform(
        &mut self,
        input: ArrayView2<f64>,
    ) -> Result<Array2<Complex<f64>>, TransformError> {
        let mut spectrum = self.plan.new_spectrum();
        self.plan.forward(input, &mut spectrum, &mut self.work)?;
        Ok(spectrum)
    }

    /// `output = kernel * input` from the input's spectrum ([`Self::transform`], of a
    /// convolution of the same grid).
    pub fn apply_transformed(
        &mut self,
        input_spectrum: &Array2<Complex<f64>>,
        output: ArrayViewMut2<f64>,
    ) -> Result<(), TransformError> {
        self.spectrum.assign(input_spectrum);
        self.spectrum
            .zip_mut_with(&self.kernel, |value, &k| *value *= k);
        self.plan
            .inverse(&mut self.spectrum, output, &mut self.work)
    }

    /// `output = kernel * input` (linear convolution), both `[ny, nx]`.
    pub fn apply(
        &mut self,
        input: ArrayView2<f64>,
        output: ArrayViewMut2<f64>,
    ) -> Result<(), TransformError> {
        self.plan
            .forward(input, &mut self.spectrum, &mut self.work)?;
        self.spectrum
            .zip_mut_with(&self.kernel, |value, &k| *value *= k);
        self.plan
            .inverse(&mut self.spectrum, output, &mut self.work)
    }
}
