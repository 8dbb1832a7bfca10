//! Two-dimensional real discrete Fourier transforms, planned once and run in parallel: the
//! transform driver shared by the surface generator, the surface statistics (spectra,
//! autocorrelation) and the rough-contact solver (its elastic convolution).
//!
//! ## Layout
//! A real grid is `[ny, nx]` (row = y). Its spectrum has `nx / 2 + 1` wavenumbers `kx >= 0`
//! (the others follow from `F(-k) = conj F(k)`) and `ny` wavenumbers `ky` in FFT order
//! (`0, 1, ..., ny/2, -(ny - 1)/2, ..., -1`), stored **transposed**, `[kx, ky]`, so that the
//! transforms along y run on contiguous memory. [`RealFft2::spectrum_shape`] gives
//! `[nx / 2 + 1, ny]`.
//!
//! The forward transform is unnormalised, `F(kx, ky) = Σ f(x, y) exp(-2πi (kx x / nx + ky y /
//! ny))`; the inverse divides by `nx ny`, so that inverse(forward(f)) = f.
//!
//! ## Zero padding
//! [`RealFft2::forward`] accepts a real input smaller than the planned grid and treats the
//! rest as zeros (rows beyond it are not transformed at all); [`RealFft2::inverse`] computes
//! only the output rows asked for. A linear (non-periodic) convolution of two `n`-sample grids
//! runs on a `2n` plan with `n`-sample inputs and outputs.
//!
//! ## Threads
//! Rows and columns are split into one block per rayon thread (as many as the pool had when
//! the plan was made); each block has its own scratch in [`Fft2Work`], so a transform
//! allocates nothing. With one thread everything runs on the calling thread.

use std::sync::Arc;

use ndarray::{Array2, ArrayView2, ArrayViewMut2, Axis};
use rayon::prelude::*;
use realfft::{ComplexToReal, RealFftPlanner, RealToComplex};
use rustfft::num_complex::Complex;
use rustfft::{Fft, FftPlanner};

/// Columns (or rows) gathered together in the transposes between the row and column passes.
const TILE: usize = 16;

/// A failure of the FFT library (lengths are fixed at planning, so this indicates a bug).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("2-D FFT failed: {0}")]
pub struct TransformError(String);

impl TransformError {
    /// An error with this message (a misuse of the transforms' buffers).
    pub fn new(message: &str) -> Self {
        Self(message.to_string())
    }
}

impl From<realfft::FftError> for TransformError {
    fn from(error: realfft::FftError) -> Self {
        Self(error.to_string())
    }
}

/// Plans of the 2-D real transform of one grid shape `[ny, nx]`.
pub struct RealFft2 {
    shape: [usize; 2],
    blocks: usize,
    row_forward: Arc<dyn RealToComplex<f64>>,
    row_inverse: Arc<dyn ComplexToReal<f64>>,
    column_forward: Arc<dyn Fft<f64>>,
    column_inverse: Arc<dyn Fft<f64>>,
}

/// Scratch of one block of rows or columns.
struct BlockScratch {
    line: Vec<f64>,
    real_scratch: Vec<Complex<f64>>,
    column_scratch: Vec<Complex<f64>>,
    /// The row spectra of one tile of output rows (`[TILE, nx / 2 + 1]`), for the inverse.
    tile: Vec<Complex<f64>>,
}

/// The working memory of [`RealFft2`] transforms: the row spectra `[ny, nx / 2 + 1]` of the
/// forward transform (allocated by the first one: an inverse needs only a tile of rows a
/// block) and one scratch per block. Make one per plan (and per thread that runs transforms
/// concurrently).
pub struct Fft2Work {
    rows: Vec<Complex<f64>>,
    blocks: Vec<BlockScratch>,
}

impl RealFft2 {
    /// Plans the transforms of a real `[ny, nx]` grid (both at least 1).
    pub fn new(shape: [usize; 2]) -> Self {
        Self::with_blocks(shape, rayon::current_num_threads())
    }

    /// As [`RealFft2::new`] with every transform on the calling thread: for callers that run
    /// many transforms in parallel themselves (a rayon task that splits would let its thread
    /// start another task, and its memory, while it waits).
    pub fn sequential(shape: [usize; 2]) -> Self {
        Self::with_blocks(shape, 1)
    }

    fn with_blocks(shape: [usize; 2], blocks: usize) -> Self {
        let [ny, nx] = shape;
        let mut real_planner = RealFftPlanner::<f64>::new();
        let mut planner = FftPlanner::<f64>::new();
        Self {
            shape,
            blocks: blocks.max(1),
            row_forward: real_planner.plan_fft_forward(nx.max(1)),
            row_inverse: real_planner.plan_fft_inverse(nx.max(1)),
            column_forward: planner.plan_fft_forward(ny.max(1)),
            column_inverse: planner.plan_fft_inverse(ny.max(1)),
        }
    }

    /// `[ny, nx]` of the real grid.
    pub fn shape(&self) -> [usize; 2] {
        self.shape
    }

    /// `[nx / 2 + 1, ny]`: the stored spectrum, `[kx, ky]`.
    pub fn spectrum_shape(&self) -> [usize; 2] {
        [self.shape[1] / 2 + 1, self.shape[0]]
    }

    /// A zeroed spectrum of this plan's shape.
    pub fn new_spectrum(&self) -> Array2<Complex<f64>> {
        let [kx, ky] = self.spectrum_shape();
        Array2::zeros((kx, ky))
    }

    /// The working memory of this plan's transforms.
    pub fn work(&self) -> Fft2Work {
        let [ny, nx] = self.shape;
        let real_scratch = self
            .row_forward
            .get_scratch_len()
            .max(self.row_inverse.get_scratch_len());
        let column_scratch = self
            .column_forward
            .get_inplace_scratch_len()
            .max(self.column_inverse.get_inplace_scratch_len());
        let zero = Complex::new(0.0, 0.0);
        let tile = TILE.min(ny) * (nx / 2 + 1);
        Fft2Work {
            rows: Vec::new(),
            blocks: (0..self.blocks)
                .map(|_| BlockScratch {
                    line: vec![0.0; nx],
                    real_scratch: vec![zero; real_scratch],
                    column_scratch: vec![zero; column_scratch],
                    tile: vec![zero; tile],
                })
                .collect(),
        }
    }

    /// Rows per block when `count` items are split into the plan's blocks.
    fn block_len(&self, count: usize) -> usize {
        count.div_ceil(self.blocks).max(1)
    }

    /// The spectrum of `input` (`[ry, rx]` with `ry <= ny`, `rx <= nx`; the rest of the grid
    /// is zero) into `spectrum` (`[nx / 2 + 1, ny]`, overwritten).
    ///
    /// # Panics
    /// If `input` is larger than the plan or `spectrum` has another shape (programming errors).
    pub fn forward(
        &self,
        input: ArrayView2<f64>,
        spectrum: &mut Array2<Complex<f64>>,
        work: &mut Fft2Work,
    ) -> Result<(), TransformError> {
        let [ny, nx] = self.shape;
        let (ry, rx) = input.dim();
        assert!(
            ry <= ny && rx <= nx,
            "input {ry}x{rx} exceeds the plan {ny}x{nx}"
        );
        assert_eq!(spectrum.dim(), (nx / 2 + 1, ny), "spectrum shape");
        let width = nx / 2 + 1;
        let block = self.block_len(ny);
        if work.rows.len() != ny * width {
            work.rows = vec![Complex::new(0.0, 0.0); ny * width];
        }
        // Rows: real-to-complex, one block of rows per thread.
        let rows_done: Result<(), TransformError> = work
            .rows
            .par_chunks_mut(block * width)
            .zip(work.blocks.par_iter_mut())
            .enumerate()
            .try_for_each(|(b, (rows, scratch))| {
                for (offset, row) in rows.chunks_exact_mut(width).enumerate() {
                    let r = b * block + offset;
                    if r >= ry {
                        row.fill(Complex::new(0.0, 0.0));
                        continue;
                    }
                    let source = input.row(r);
                    for (target, value) in scratch.line.iter_mut().zip(source.iter()) {
                        *target = *value;
                    }
                    scratch.line[rx..].fill(0.0);
                    self.row_forward.process_with_scratch(
                        &mut scratch.line,
                        row,
                        &mut scratch.real_scratch,
                    )?;
                }
                Ok(())
            });
        rows_done?;
        // Columns: gather each kx column (a transpose), then transform it in place.
        let rows = &work.rows;
        let column_block = self.block_len(width);
        let storage = spectrum
            .as_slice_mut()
            .ok_or_else(|| TransformError("spectrum is not contiguous".into()))?;
        storage
            .par_chunks_mut(column_block * ny)
            .zip(work.blocks.par_iter_mut())
            .enumerate()
            .for_each(|(b, (columns, scratch))| {
                // A tile of columns at a time, so that each row is read in runs of TILE.
                for (t, tile) in columns.chunks_mut(TILE * ny).enumerate() {
                    let kx0 = b * column_block + t * TILE;
                    let count = tile.len() / ny;
                    for r in 0..ny {
                        let start = r * width + kx0;
                        for (c, value) in rows[start..start + count].iter().enumerate() {
                            tile[c * ny + r] = *value;
                        }
                    }
                    for column in tile.chunks_exact_mut(ny) {
                        self.column_forward
                            .process_with_scratch(column, &mut scratch.column_scratch);
                    }
                }
            });
        Ok(())
    }

    /// The real grid of `spectrum` (destroyed), divided by `nx ny`, into `output` (`[oy, ox]`
    /// with `oy <= ny`, `ox <= nx`: the first rows and columns of the grid).
    ///
    /// # Panics
    /// If the shapes do not fit the plan (programming errors).
    pub fn inverse(
        &self,
        spectrum: &mut Array2<Complex<f64>>,
        output: ArrayViewMut2<f64>,
        work: &mut Fft2Work,
    ) -> Result<(), TransformError> {
        self.inverse_with(spectrum, output, work, |mut row, line, scale| {
            for (target, value) in row.iter_mut().zip(line) {
                *target = scale * value;
            }
        })
    }

    /// As [`RealFft2::inverse`], adding to each `output` column `j` the grid's column
    /// `columns[j]` (each `< nx`; `output` has `columns.len()` columns and at most `ny`
    /// rows): the lattice of a longer periodic grid cropped to its offsets, without the
    /// periodic grid itself.
    ///
    /// # Panics
    /// As [`RealFft2::inverse`], or if `columns` does not match `output` or exceeds the plan.
    pub fn inverse_add_columns(
        &self,
        spectrum: &mut Array2<Complex<f64>>,
        output: ArrayViewMut2<f64>,
        columns: &[usize],
        work: &mut Fft2Work,
    ) -> Result<(), TransformError> {
        assert_eq!(output.ncols(), columns.len(), "output columns");
        assert!(
            columns.iter().all(|&c| c < self.shape[1]),
            "a column exceeds the plan"
        );
        self.inverse_with(spectrum, output, work, |mut row, line, scale| {
            for (target, &column) in row.iter_mut().zip(columns) {
                *target += scale * line[column];
            }
        })
    }

    /// The inverse transform, each output row written by `emit(row, grid_row, 1 / (nx ny))`
    /// from the grid's row (unscaled).
    fn inverse_with(
        &self,
        spectrum: &mut Array2<Complex<f64>>,
        mut output: ArrayViewMut2<f64>,
        work: &mut Fft2Work,
        emit: impl Fn(ndarray::ArrayViewMut1<f64>, &[f64], f64) + Sync,
    ) -> Result<(), TransformError> {
        let [ny, nx] = self.shape;
        let (oy, ox) = output.dim();
        assert!(
            oy <= ny && ox <= nx,
            "output {oy}x{ox} exceeds the plan {ny}x{nx}"
        );
        assert_eq!(spectrum.dim(), (nx / 2 + 1, ny), "spectrum shape");
        let width = nx / 2 + 1;
        let column_block = self.block_len(width);
        let storage = spectrum
            .as_slice_mut()
            .ok_or_else(|| TransformError("spectrum is not contiguous".into()))?;
        storage
            .par_chunks_mut(column_block * ny)
            .zip(work.blocks.par_iter_mut())
            .for_each(|(columns, scratch)| {
                for column in columns.chunks_exact_mut(ny) {
                    self.column_inverse
                        .process_with_scratch(column, &mut scratch.column_scratch);
                }
            });
        let spectrum: &[Complex<f64>] = storage;
        let scale = 1.0 / (nx as f64 * ny as f64);
        let block = self.block_len(oy);
        let nyquist = (nx % 2 == 0).then_some(nx / 2);
        output
            .axis_chunks_iter_mut(Axis(0), block)
            .into_par_iter()
            .zip(work.blocks.par_iter_mut())
            .enumerate()
            .try_for_each(|(b, (mut out_rows, scratch))| {
                let rows_here = out_rows.nrows();
                // Gather a tile of rows at a time, so that each column is read in runs of
                // TILE.
                for t0 in (0..rows_here).step_by(TILE) {
                    let count = TILE.min(rows_here - t0);
                    let r0 = b * block + t0;
                    for kx in 0..width {
                        let start = kx * ny + r0;
                        for (t, value) in spectrum[start..start + count].iter().enumerate() {
                            scratch.tile[t * width + kx] = *value;
                        }
                    }
                    for t in 0..count {
                        let row = &mut scratch.tile[t * width..(t + 1) * width];
                        // The spectrum of a real row has real values at kx = 0 (and nx / 2);
                        // the real inverse transform requires them exactly real.
                        row[0].im = 0.0;
                        if let Some(k) = nyquist {
                            row[k].im = 0.0;
                        }
                        self.row_inverse.process_with_scratch(
                            row,
                            &mut scratch.line,
                            &mut scratch.real_scratch,
                        )?;
                        emit(out_rows.row_mut(t0 + t), &scratch.line, scale);
                    }
                }
                Ok::<(), TransformError>(())
            })
    }
}

/// The signed wavenumber index of FFT position `index` on `n` samples: `0, 1, ..., n/2,
/// -(n - 1)/2, ..., -1` (for even `n`, `n / 2` counts as positive).
pub fn signed_index(index: usize, n: usize) -> i64 {
    if index <= n / 2 {
        index as i64
    } else {
        index as i64 - n as i64
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rustfft::num_complex::Complex64;

    fn grid(ny: usize, nx: usize) -> Array2<f64> {
        Array2::from_shape_fn((ny, nx), |(j, i)| {
            ((0.37 * i as f64 + 1.3 * j as f64).sin() + 0.01 * (i * j) as f64).cos()
        })
    }

    /// The direct DFT at `(kx, ky)`.
    fn dft(f: &Array2<f64>, shape: [usize; 2], kx: usize, ky: usize) -> Complex64 {
        let [ny, nx] = shape;
        let mut sum = Complex64::new(0.0, 0.0);
        for ((j, i), v) in f.indexed_iter() {
            let phase = -2.0
                * std::f64::consts::PI
                * (kx as f64 * i as f64 / nx as f64 + ky as f64 * j as f64 / ny as f64);
            sum += Complex64::from_polar(*v, phase);
        }
        sum
    }

    fn check_forward_against_direct(shape: [usize; 2], input: &Array2<f64>) {
        let plan = RealFft2::new(shape);
        let mut work = plan.work();
        let mut spectrum = plan.new_spectrum();
        plan.forward(input.view(), &mut spectrum, &mut work)
            .expect("forward");
        let [kxs, kys] = plan.spectrum_shape();
        for kx in 0..kxs {
            for ky in 0..kys {
                let expected = dft(input, shape, kx, ky);
                let got = spectrum[[kx, ky]];
                assert!(
                    (got - expected).norm() < 1e-10 * (1.0 + expected.norm()),
                    "{shape:?} ({kx}, {ky}): {got} vs {expected}"
                );
            }
        }
    }

    #[test]
    fn forward_equals_the_direct_dft_for_odd_even_and_padded_grids() {
        // [34, 70]: more columns and rows than a transpose tile, with a partial tile.
        for shape in [[8, 8], [5, 7], [6, 9], [1, 4], [3, 1], [34, 70]] {
            check_forward_against_direct(shape, &grid(shape[0], shape[1]));
        }
        // A 4x5 input zero-padded into 8x10.
        check_forward_against_direct([8, 10], &grid(4, 5));
    }

    #[test]
    fn inverse_restores_the_input_on_several_threads() {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(3)
            .build()
            .expect("pool");
        pool.install(|| {
            for shape in [[16, 16], [7, 10], [9, 5], [2, 2], [100, 130]] {
                let input = grid(shape[0], shape[1]);
                let plan = RealFft2::new(shape);
                let mut work = plan.work();
                let mut spectrum = plan.new_spectrum();
                plan.forward(input.view(), &mut spectrum, &mut work)
                    .expect("forward");
                let mut output = Array2::zeros((shape[0], shape[1]));
                plan.inverse(&mut spectrum, output.view_mut(), &mut work)
                    .expect("inverse");
                for (a, b) in input.iter().zip(&output) {
                    assert!((a - b).abs() < 1e-12, "{shape:?}: {a} vs {b}");
                }
            }
        });
    }

    /// The cropped inverse adds, to the bit, what the whole inverse writes in those columns
    /// (the smooth part of the thermal stress lattices relies on it).
    #[test]
    fn inverse_add_columns_adds_the_whole_inverse_columns_to_the_bit() {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(3)
            .build()
            .expect("pool");
        pool.install(|| {
            let shape = [34, 40];
            let plan = RealFft2::new(shape);
            let mut work = plan.work();
            let mut spectrum = plan.new_spectrum();
            plan.forward(grid(34, 40).view(), &mut spectrum, &mut work)
                .expect("forward");
            let mut copy = spectrum.clone();
            let mut whole = Array2::zeros((34, 40));
            plan.inverse(&mut copy, whole.view_mut(), &mut work)
                .expect("inverse");
            let columns = [0, 1, 2, 3, 36, 37, 38, 39, 17];
            let start = Array2::from_shape_fn((34, columns.len()), |(j, i)| 0.1 * (j + i) as f64);
            let mut added = start.clone();
            // A fresh work: the inverse needs no row spectra of a forward transform.
            plan.inverse_add_columns(&mut spectrum, added.view_mut(), &columns, &mut plan.work())
                .expect("inverse");
            for ((j, i), value) in added.indexed_iter() {
                assert_eq!(
                    value.to_bits(),
                    (start[[j, i]] + whole[[j, columns[i]]]).to_bits(),
                    "({j}, {i})"
                );
            }
        });
    }

    #[test]
    fn padded_product_is_the_linear_convolution() {
        // f (3x4) convolved with g (3x4) on a 6x8 plan: the first 3x4 outputs equal the direct
        // linear sum Σ f(k) g(i - k) over k <= i.
        let f = grid(3, 4);
        let g = Array2::from_shape_fn((3, 4), |(j, i)| 1.0 / (1.0 + (i + 2 * j) as f64));
        let plan = RealFft2::new([6, 8]);
        let mut work = plan.work();
        let mut a = plan.new_spectrum();
        let mut b = plan.new_spectrum();
        plan.forward(f.view(), &mut a, &mut work).expect("f");
        plan.forward(g.view(), &mut b, &mut work).expect("g");
        a.zip_mut_with(&b, |x, y| *x *= *y);
        let mut out = Array2::zeros((3, 4));
        plan.inverse(&mut a, out.view_mut(), &mut work)
            .expect("inverse");
        for j in 0..3 {
            for i in 0..4 {
                let mut sum = 0.0;
                for l in 0..=j {
                    for k in 0..=i {
                        sum += f[[l, k]] * g[[j - l, i - k]];
                    }
                }
                assert!((out[[j, i]] - sum).abs() < 1e-12, "({j}, {i})");
            }
        }
    }

    #[test]
    fn signed_indices_follow_fft_order() {
        let even: Vec<_> = (0..6).map(|i| signed_index(i, 6)).collect();
        assert_eq!(even, [0, 1, 2, 3, -2, -1]);
        let odd: Vec<_> = (0..5).map(|i| signed_index(i, 5)).collect();
        assert_eq!(odd, [0, 1, 2, -2, -1]);
    }
}
