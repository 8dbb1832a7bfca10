//! FFT plans and the workspaces of a layer's convolutions.

use std::sync::Arc;

use ndarray::ArrayViewMut2;
use realfft::{ComplexToReal, RealFftPlanner, RealToComplex};
use rustfft::num_complex::Complex;
use rustfft::{Fft, FftPlanner};

use super::*;

/// FFT plans for one grid size `[ny, nx]`: real-to-complex along rows of length `2 nx`,
/// complex along columns of length `2 ny`. Shareable between [`DcFft`]s of the same size.
pub struct FftPlans {
    pub(super) shape: [usize; 2],
    pub(super) row_forward: Arc<dyn RealToComplex<f64>>,
    pub(super) row_inverse: Arc<dyn ComplexToReal<f64>>,
    pub(super) column_forward: Arc<dyn Fft<f64>>,
    pub(super) column_inverse: Arc<dyn Fft<f64>>,
}

/// Columns of a spectrum transformed together, from gathering to the inverse transform, while
/// they stay in cache.
pub(super) const COLUMN_CHUNK: usize = 8;

/// The rows of a real `2ny x 2nx` grid beyond the `ny` given ones.
#[derive(Clone, Copy, Debug)]
pub(super) enum Rows {
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
    pub(super) fn spectrum_len(&self) -> usize {
        (self.shape[1] + 1) * 2 * self.shape[0]
    }

    /// Length of the row spectra of `ny` rows: `ny` rows of `nx + 1`.
    pub(super) fn rows_len(&self) -> usize {
        (self.shape[1] + 1) * self.shape[0]
    }

    pub(super) fn scratch_len(&self) -> usize {
        self.row_forward
            .get_scratch_len()
            .max(self.row_inverse.get_scratch_len())
            .max(self.column_forward.get_inplace_scratch_len())
            .max(self.column_inverse.get_inplace_scratch_len())
    }

    /// Real-to-complex transforms of the rows `r < ny` of a real `2ny x 2nx` grid, row `r`
    /// written into its argument by `fill_row(r, line)`, into `rows` (`ny` rows of `nx + 1`).
    pub(super) fn row_spectra(
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
    pub(super) fn column_chunk(
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
        // Gather (a transpose of a narrow band: whole cache lines read per row), with the
        // rows beyond ny.
        let zero = Complex::new(0.0, 0.0);
        match more {
            Rows::ZeroPadded => {
                for (r, row) in rows.chunks_exact(width).enumerate() {
                    for (t, value) in row[start..start + count].iter().enumerate() {
                        chunk[t * height + r] = *value;
                    }
                }
                for column in chunk.chunks_exact_mut(height) {
                    column[ny..].fill(zero);
                }
            }
            Rows::Mirrored { parity } => {
                for (r, row) in rows.chunks_exact(width).enumerate() {
                    let mirror = (height - r) % height;
                    for (t, value) in row[start..start + count].iter().enumerate() {
                        chunk[t * height + r] = *value;
                        chunk[t * height + mirror] = parity * value;
                    }
                }
                // Row ny; row 0 is its own mirror, written last with its own value.
                for column in chunk.chunks_exact_mut(height) {
                    column[ny] = zero;
                }
                for (t, value) in rows[start..start + count].iter().enumerate() {
                    chunk[t * height] = *value;
                }
            }
        }
        self.column_forward.process_with_scratch(chunk, scratch);
    }

    /// The full spectrum of a zero-padded real grid whose rows `r < ny` are written by
    /// `fill_row`, column-major (see [`FftPlans::spectrum_len`]).
    pub(super) fn spectrum(
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
    pub(super) fn inverse_column_chunk(
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
    pub(super) fn inverse_rows(
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
pub(super) struct FftBuffers {
    pub(super) line: Vec<f64>,
    pub(super) scratch: Vec<Complex<f64>>,
}

impl FftBuffers {
    pub(super) fn new(plans: &FftPlans) -> Self {
        Self {
            line: vec![0.0; 2 * plans.shape[1]],
            scratch: vec![Complex::new(0.0, 0.0); plans.scratch_len()],
        }
    }
}

/// The working memory of one depth layer (reused from layer to layer by one worker), each
/// part allocated when first needed: the influence coefficients of one quadrant of offsets
/// (`48 L nx ny` bytes for `L` loads) and a component's spectra ([`ComponentWorkspace`]) for
/// layers from the cells, or a spectrum and its transform's scratch for spectral layers.
pub struct Workspace {
    /// `[load][component][b][a]`: six arrays of `nx ny` per load present.
    pub(super) quadrant: Vec<f64>,
    pub(super) component: Option<ComponentWorkspace>,
    pub(super) spectral: Option<super::spectral::SpectralWork>,
}

/// Working memory of one stress component of a layer ([`DcFft::component_into`]).
pub struct ComponentWorkspace {
    /// The row spectra of the component's coefficients: one array for the pressure and the
    /// shear along x together (`Packed` in `components.rs`), else one per load present. The
    /// first array then receives the row spectra of the result, column chunk by column chunk
    /// (no array of its own: a 256² component's spectra then stay in a core's 1 MB cache).
    pub(super) rows: Vec<Vec<Complex<f64>>>,
    /// Spectra of a chunk of columns: one load's coefficients, and the sum over loads.
    pub(super) chunk: Vec<Complex<f64>>,
    pub(super) sum: Vec<Complex<f64>>,
    pub(super) buffers: FftBuffers,
}
