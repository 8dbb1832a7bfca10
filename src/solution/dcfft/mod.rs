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
//! Threads: everything here runs on the calling thread but [`DcFft::influence_in_parallel`].
//! The work of a layer splits into its influence coefficients (in parallel there, or in
//! blocks of rows, [`DcFft::influence_blocks`]) and the six stress components
//! ([`DcFft::component_into`]), and layers are independent of each other; `crate::field`
//! runs them in parallel.

mod components;
mod grid;
mod images;
mod periodic_turned;
mod plans;
pub mod spectral;
mod turned;

pub use grid::*;
pub use images::*;
pub use plans::*;

use std::sync::Arc;

use ndarray::{Array3, ArrayViewMut3, Axis};
use rustfft::num_complex::Complex;

use super::patch::{offset_sums, uniform_patch_offset_rows};
use crate::operator::elastic::Periodicity;

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
/// neighbouring cells, [`offset_sums`]) and mirrored by their parity (each component is even or
/// odd in x and in y about the loaded cell); the mirrored rows' transforms are the transformed
/// rows times the parity. On an isolated square grid of square cells only the half `a >= b` of
/// the quadrant is evaluated, the rest turned about the diagonal
/// ([`DcFft::fill_turned_influence`]); on a periodic one only `b <= a <= n/2` is summed over
/// the images ([`DcFft::fill_periodic_turned_influence`]). The tractions' spectra are computed
/// once, in [`DcFft::new`]; each layer then costs one forward transform per load and
/// component (one for the pressure and the shear along x together, `Packed` in
/// `components.rs`) and one inverse per component, real-to-complex along rows (`realfft`) and
/// complex along columns (`rustfft`) ([`DcFft::component_into`]). The column pass runs on a
/// few columns at a time, from gathering through the products to the inverse transform, so
/// that it works in cache, and writes the result's row spectra over the coefficients' columns
/// it has read.
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
    /// Periodic: the layers from half a cell down, in Fourier space ([`spectral`]).
    spectral: Option<spectral::SpectralLayers>,
}

impl DcFft {
    /// Plans the transforms and transforms the tractions of an isolated grid.
    pub fn new(grid: &TractionGrid, poisson: f64) -> Result<Self, DcFftError> {
        Self::with_plans(grid, poisson, Arc::new(FftPlans::new(grid.shape)))
    }

    /// As [`DcFft::new`] for a grid that is one period of tractions repeating in x and y:
    /// layers from half a cell down in Fourier space ([`spectral`]), the shallower ones from
    /// the cells' periodic influence coefficients (module doc).
    pub fn periodic(grid: &TractionGrid, poisson: f64) -> Result<Self, DcFftError> {
        let mut fft = Self::periodic_by_cells(grid, poisson)?;
        fft.spectral = Some(spectral::SpectralLayers::new(grid, poisson)?);
        Ok(fft)
    }

    /// As [`DcFft::periodic`] with every layer from the cells' periodic influence
    /// coefficients (the window of images, module doc): the reference of the spectral layers.
    pub fn periodic_by_cells(grid: &TractionGrid, poisson: f64) -> Result<Self, DcFftError> {
        Self::build(
            grid,
            poisson,
            Arc::new(FftPlans::new(grid.shape)),
            Periodicity::Periodic,
        )
    }

    /// Whether the layer at depth `z` is computed in Fourier space ([`spectral`]).
    pub fn is_spectral(&self, z: f64) -> bool {
        self.spectral.as_ref().is_some_and(|s| s.takes(z))
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
            spectral: None,
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
        // Each kind of layer frees the other's memory (the search runs them in depth order).
        if let Some(layers) = self.spectral.as_ref().filter(|s| s.takes(z)) {
            workspace.quadrant = Vec::new();
            workspace.component = None;
            let work = workspace.spectral.get_or_insert_with(|| layers.work());
            return layers.layer_into(z, work, out);
        }
        workspace.spectral = None;
        self.influence_into(z, &mut workspace.quadrant);
        let component = workspace
            .component
            .get_or_insert_with(|| self.component_workspace());
        for (c, out) in out.axis_iter_mut(Axis(0)).enumerate() {
            self.component_into(&workspace.quadrant, c, component, out)?;
        }
        Ok(())
    }

    /// The influence coefficients of depth `z` for [`DcFft::component_into`]: fills
    /// `quadrant`, of the length of [`Workspace`]'s (`6 L nx ny` for the `L` loads present).
    pub fn influence_into(&self, z: f64, quadrant: &mut Vec<f64>) {
        if self.turns_about_diagonal() {
            self.fill_turned_influence(z, quadrant, 1);
            return;
        }
        if self.periodic_turns_about_diagonal() {
            self.fill_periodic_turned_influence(z, quadrant, 1);
            return;
        }
        for block in self.influence_blocks(quadrant, 1) {
            self.fill_influence(z, block);
        }
    }

    /// [`DcFft::influence_into`] split over `threads` threads of the rayon pool (for one layer
    /// at a time): the same coefficients to the last bit. A grid that [turns about its
    /// diagonal](DcFft::turns_about_diagonal) is filled band by band, its rows in parallel and
    /// then their turned values; a periodic one that
    /// [does](DcFft::periodic_turns_about_diagonal) in blocks of rows of equal work, then
    /// turned; others in blocks of rows, a few per thread, so that uneven blocks still
    /// balance.
    pub fn influence_in_parallel(&self, z: f64, quadrant: &mut Vec<f64>, threads: usize) {
        use rayon::prelude::*;
        if self.turns_about_diagonal() {
            self.fill_turned_influence(z, quadrant, threads.max(1));
            return;
        }
        if self.periodic_turns_about_diagonal() {
            self.fill_periodic_turned_influence(z, quadrant, threads.max(1));
            return;
        }
        self.influence_blocks(quadrant, 4 * threads.max(1))
            .into_par_iter()
            .for_each(|block| self.fill_influence(z, block));
    }

    /// Whether the coefficients of the offsets `a < b` are those of `(b, a)` turned about the
    /// diagonal `x = y`: an isolated square grid of square cells. Its coefficients are then
    /// filled by [`DcFft::influence_into`] in one piece, in half the work of the blocks of
    /// [`DcFft::influence_blocks`], which callers should not use instead: the layers would
    /// differ in the last bits.
    pub fn turns_about_diagonal(&self) -> bool {
        let ([ny, nx], [dx, dy]) = (self.shape, self.cell);
        self.periodicity == Periodicity::NonPeriodic && nx == ny && dx == dy
    }

    /// The stresses of one layer, `[component, y, x]`, on the calling thread.
    pub fn layer(&self, z: f64) -> Result<Array3<f64>, DcFftError> {
        let [ny, nx] = self.shape;
        let mut out = Array3::zeros((6, ny, nx));
        self.layer_into(z, &mut self.workspace(), out.view_mut())?;
        Ok(out)
    }

    /// Splits `quadrant` (resized to the length of [`Workspace`]'s, `6 L nx ny`) into at most
    /// `blocks` blocks of consecutive offset rows, to be filled by
    /// [`DcFft::fill_influence`], possibly on different threads; together they make the
    /// influence coefficients that [`DcFft::influence_into`] computes in one piece.
    pub fn influence_blocks<'q>(
        &self,
        quadrant: &'q mut Vec<f64>,
        blocks: usize,
    ) -> Vec<InfluenceBlock<'q>> {
        let [ny, nx] = self.shape;
        quadrant.resize(6 * self.tractions.len() * nx * ny, 0.0);
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
                arrays: Vec::with_capacity(6 * self.tractions.len()),
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
    /// stresses at offsets `(a dx, b dy)`, `0 <= a < nx`, `b` in the block's rows, as six
    /// arrays per load present, `[load][component][b][a]` with the loads in the order of their
    /// transforms: only the loads present take memory (at 2048², six arrays of coefficients
    /// are 200 MB for each worker).
    pub fn fill_influence(&self, z: f64, block: InfluenceBlock<'_>) {
        let nx = self.shape[1];
        // The loads present, in the order of their transforms and coefficients.
        let loads: Vec<Load> = self.tractions.iter().map(|(load, _)| *load).collect();
        if self.periodicity == Periodicity::Periodic {
            self.fill_periodic_influence(z, block, &loads);
            return;
        }
        let InfluenceBlock { rows, mut arrays } = block;
        let first_row = rows.start;
        offset_sums(self.cell, z, nx, rows, false, |b, sums| {
            let row = (b - first_row) * nx..(b - first_row + 1) * nx;
            for (slot, &load) in loads.iter().enumerate() {
                for c in 0..6 {
                    sums.component(
                        load,
                        c,
                        self.poisson,
                        &mut arrays[slot * 6 + c][row.clone()],
                    );
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
        for array in &mut arrays[..6 * loads.len()] {
            array.fill(0.0);
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
                    for (slot, &load) in loads.iter().enumerate() {
                        let stress = load.stress(stresses);
                        let first = slot * 6;
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
        self.add_far_images(z, rows, &mut arrays, loads, |_| 0..nx);
    }

    /// Adds to the periodic coefficients of the block's `rows` (rows of `nx` values, six
    /// arrays a load of `loads`) the images beyond the window, seen from the cell's nearest
    /// image, at the columns `columns(b)` of each row `b`.
    fn add_far_images(
        &self,
        z: f64,
        rows: std::ops::Range<usize>,
        arrays: &mut [&mut [f64]],
        loads: &[Load],
        columns: impl Fn(usize) -> std::ops::Range<usize>,
    ) {
        let [ny, nx] = self.shape;
        let [dx, dy] = self.cell;
        let periods = [nx as f64 * dx, ny as f64 * dy];
        for b in rows.clone() {
            for a in columns(b) {
                let index = (b - rows.start) * nx + a;
                for (sy, wy) in centred_offsets(b as f64 * dy, periods[1]) {
                    for (sx, wx) in centred_offsets(a as f64 * dx, periods[0]) {
                        let far = far_images(
                            [sx, sy],
                            z,
                            self.cell,
                            periods,
                            PERIODIC_IMAGES,
                            self.poisson,
                        );
                        for (slot, &load) in loads.iter().enumerate() {
                            let stress = load.stress(&far);
                            for c in 0..6 {
                                arrays[slot * 6 + c][index] += wx * wy * component(stress, c);
                            }
                        }
                    }
                }
            }
        }
    }
}

/// A block of rows of the influence coefficients of a layer ([`DcFft::influence_blocks`]):
/// the rows `b` of each of the six arrays `[component]` of each load present.
pub struct InfluenceBlock<'q> {
    rows: std::ops::Range<usize>,
    arrays: Vec<&'q mut [f64]>,
}

#[cfg(test)]
mod tests;
