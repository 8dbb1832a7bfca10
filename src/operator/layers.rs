//! Stacks of 2-D real transforms of one shape, for fields given layer by layer (a volume of
//! cells): the layers' transforms run in parallel over the stack, each on one thread
//! ([`RealFft2::sequential`]), and a pass over the wavevectors hands each column of
//! wavenumbers `kx` of every spectrum of the stack to one thread, so that an operator acting
//! along the stack at each wavevector (the depth of a half-space) runs in parallel too.
//!
//! The spectra have [`RealFft2`]'s layout (`[nx / 2 + 1, ny]`, each `kx` column contiguous).

use ndarray::{Array2, ArrayView2, ArrayViewMut2};
use rayon::prelude::*;
use rustfft::num_complex::Complex;

use crate::operator::transform::{RealFft2, TransformError};

/// The transforms of a stack of layers of one plan shape.
pub struct LayerTransforms {
    plan: RealFft2,
}

impl LayerTransforms {
    /// Plans the transforms of real `[ny, nx]` layers (inputs and outputs may be smaller: the
    /// rest of the grid is zero, as [`RealFft2::forward`] reads them).
    pub fn new(shape: [usize; 2]) -> Self {
        Self {
            plan: RealFft2::sequential(shape),
        }
    }

    pub fn shape(&self) -> [usize; 2] {
        self.plan.shape()
    }

    /// `[nx / 2 + 1, ny]`.
    pub fn spectrum_shape(&self) -> [usize; 2] {
        self.plan.spectrum_shape()
    }

    /// `count` zeroed spectra.
    pub fn spectra(&self, count: usize) -> Vec<Array2<Complex<f64>>> {
        (0..count).map(|_| self.plan.new_spectrum()).collect()
    }

    /// The spectrum of each input into the spectrum beside it, in parallel.
    ///
    /// # Panics
    /// If the counts differ or a shape does not fit the plan.
    pub fn forward(
        &self,
        inputs: &[ArrayView2<f64>],
        spectra: &mut [Array2<Complex<f64>>],
    ) -> Result<(), TransformError> {
        assert_eq!(inputs.len(), spectra.len(), "one spectrum per input");
        inputs
            .par_iter()
            .zip(spectra.par_iter_mut())
            .map_init(
                || self.plan.work(),
                |work, (input, spectrum)| self.plan.forward(input.view(), spectrum, work),
            )
            .collect()
    }

    /// The real layer of each spectrum (destroyed) into the output beside it, in parallel.
    ///
    /// # Panics
    /// If the counts differ or a shape does not fit the plan.
    pub fn inverse(
        &self,
        spectra: &mut [Array2<Complex<f64>>],
        outputs: Vec<ArrayViewMut2<f64>>,
    ) -> Result<(), TransformError> {
        assert_eq!(outputs.len(), spectra.len(), "one output per spectrum");
        spectra
            .par_iter_mut()
            .zip(outputs.into_par_iter())
            .map_init(
                || self.plan.work(),
                |work, (spectrum, output)| self.plan.inverse(spectrum, output, work),
            )
            .collect()
    }

    /// Calls `visit(work, kx, columns)` for each wavenumber index `kx` (in parallel), with
    /// `columns[s]` the column `kx` of `spectra[s]` (its `ny` values of `ky` in FFT order);
    /// `work` is made by `init` once per thread.
    pub fn for_each_column<W, I, F>(
        &self,
        spectra: &mut [Array2<Complex<f64>>],
        init: I,
        visit: F,
    ) -> Result<(), TransformError>
    where
        I: Fn() -> W + Sync + Send,
        F: Fn(&mut W, usize, &mut [&mut [Complex<f64>]]) + Sync + Send,
    {
        let [width, ny] = self.spectrum_shape();
        let mut columns: Vec<Vec<&mut [Complex<f64>]>> = (0..width)
            .map(|_| Vec::with_capacity(spectra.len()))
            .collect();
        for spectrum in spectra.iter_mut() {
            let storage = spectrum
                .as_slice_mut()
                .ok_or_else(|| TransformError::new("a spectrum is not contiguous"))?;
            for (kx, column) in storage.chunks_exact_mut(ny).enumerate() {
                columns[kx].push(column);
            }
        }
        columns
            .into_par_iter()
            .enumerate()
            .for_each_init(init, |work, (kx, mut column)| visit(work, kx, &mut column));
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_stack_round_trips_and_columns_see_every_spectrum() {
        let shape = [6, 10];
        let stack = LayerTransforms::new(shape);
        let layers: Vec<Array2<f64>> = (0..5)
            .map(|l| Array2::from_shape_fn((4, 7), |(j, i)| ((l * 31 + j * 7 + i) as f64).sin()))
            .collect();
        let views: Vec<ArrayView2<f64>> = layers.iter().map(|a| a.view()).collect();
        let mut spectra = stack.spectra(5);
        stack.forward(&views, &mut spectra).expect("forward");
        // Doubling every value through the columns doubles the layers.
        stack
            .for_each_column(
                &mut spectra,
                || (),
                |_, _, columns| {
                    assert_eq!(columns.len(), 5);
                    for column in columns.iter_mut() {
                        for value in column.iter_mut() {
                            *value *= 2.0;
                        }
                    }
                },
            )
            .expect("columns");
        let mut outputs: Vec<Array2<f64>> = (0..5).map(|_| Array2::zeros((4, 7))).collect();
        stack
            .inverse(
                &mut spectra,
                outputs.iter_mut().map(|o| o.view_mut()).collect(),
            )
            .expect("inverse");
        for (input, output) in layers.iter().zip(&outputs) {
            for (a, b) in input.iter().zip(output) {
                assert!((2.0 * a - b).abs() < 1e-12);
            }
        }
    }
}
