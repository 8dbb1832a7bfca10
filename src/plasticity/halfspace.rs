//! The residual stress and surface displacement of a volume of plastic strain (eigenstrain) in
//! an elastic half-space, on a grid of cells, by a partial Fourier transform in x and y and the
//! exact response of each wave along depth ([`super::column`]); optionally with the stress of
//! the contact's surface tractions added in the same transforms.
//!
//! ## The grid
//! Cells `dx x dy` in x and y (the contact's grid, `[ny, nx]`) over the depth cells of a
//! [`DepthCells`] (uniform or graded); the eigenstrain is sampled at the cell centres and
//! taken uniform along depth in each cell. Arrays of a volume are `[depth, component, y, x]`
//! with the components in the order of [`crate::solution::dcfft::COMPONENTS`] (xx, yy, zz, yz,
//! xz, xy; tensor shears).
//!
//! ## Periodic or isolated
//! Periodic: the grid is one period; each layer's discrete Fourier transform gives the waves of
//! the period, and every wave is solved exactly (the mean by the uniform layer). Isolated: the
//! layers are zero-padded to twice the grid each way and solved as a period of twice the
//! grid, so the images of the plastic zone lie at least one grid length away (across the
//! padding) from any cell. Their stress falls off as the cube of the distance and their
//! surface displacement at least as its square (a nucleus of strain; its axisymmetric part as
//! the cube), so with the plastic zone in the middle third of the grid the images change the
//! stresses by about `(b / 2L)³` of the zone's own (`b` its size, `2L` the padded period);
//! `tests.rs` measures the change against a padding of four.
//!
//! ## The contact's stress in the same transforms
//! The stress of the surface tractions at each depth is the discrete convolution of the
//! tractions with the influence coefficients of a loaded cell ([`crate::solution::dcfft`]):
//! periodic, or isolated and exact on the zero-padded grid (DC-FFT). The coefficients'
//! transforms are kept (each real or imaginary by the parity of its component), so that a
//! total stress costs one product per wave and no transform of its own.
//!
//! ## The Nyquist waves
//! On an even grid the wave of index `n/2` stands for both `+π/d` and `-π/d`; its response is
//! the mean of the two (so that the fields stay real).

use std::sync::Mutex;

use ndarray::{Array2, ArrayView2, ArrayView4, ArrayViewMut2, ArrayViewMut4, Axis};

use super::column::{Column, ColumnWork, DepthCells, C64};
use crate::operator::elastic::Periodicity;
use crate::operator::layers::LayerTransforms;
use crate::operator::transform::{signed_index, RealFft2, TransformError};
use crate::solution::dcfft::{DcFft, DcFftError, TractionGrid};

const ZERO: C64 = C64 { re: 0.0, im: 0.0 };

/// The volume grid of the plastic strains.
#[derive(Clone, Debug, PartialEq)]
pub struct VolumeGrid {
    /// `[ny, nx]`: the contact's grid.
    pub shape: [usize; 2],
    /// `[dx, dy]`, m.
    pub spacing_m: [f64; 2],
    pub depth: DepthCells,
    pub periodicity: Periodicity,
}

impl VolumeGrid {
    /// Cells in a layer.
    pub fn layer_cells(&self) -> usize {
        self.shape[0] * self.shape[1]
    }

    /// `[nz, ny, nx]`.
    pub fn dims(&self) -> [usize; 3] {
        [self.depth.count(), self.shape[0], self.shape[1]]
    }

    /// The shape of the transforms: the grid (periodic) or twice it (isolated).
    pub fn plan_shape(&self) -> [usize; 2] {
        match self.periodicity {
            Periodicity::Periodic => self.shape,
            Periodicity::NonPeriodic => [2 * self.shape[0], 2 * self.shape[1]],
        }
    }

    /// The volume of cell layer `j`'s cells, m³.
    pub fn cell_volume_m3(&self, j: usize) -> f64 {
        self.spacing_m[0] * self.spacing_m[1] * self.depth.thickness_m(j)
    }
}

/// Why the operator cannot be built or applied.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum HalfSpaceError {
    #[error(transparent)]
    Transform(#[from] TransformError),
    #[error("the contact's influence coefficients: {0}")]
    Coefficients(String),
}

impl From<DcFftError> for HalfSpaceError {
    fn from(error: DcFftError) -> Self {
        Self::Coefficients(error.to_string())
    }
}

/// The parity (in x times in y) of each stress component's influence coefficient about a
/// cell loaded by a pressure: positive for xx, yy, zz, xy (their transforms are real),
/// negative for yz, xz (imaginary). A shear along x reverses every parity in x.
const PRESSURE_PARITY: [(f64, f64); 6] = [
    (1.0, 1.0),
    (1.0, 1.0),
    (1.0, 1.0),
    (1.0, -1.0),
    (-1.0, 1.0),
    (-1.0, -1.0),
];

/// The transforms of the stress at each depth of a unit traction on one cell: `[depth][c]`,
/// each the real or the imaginary part (by its parity) of the spectrum `[nx' / 2 + 1, ny']`.
struct TractionKernels {
    /// `(pressure, shear along x)`.
    pressure: Vec<[Array2<f64>; 6]>,
    shear_x: Option<Vec<[Array2<f64>; 6]>>,
}

/// The residual stress (and the contact's stress) of a volume of plastic strain.
pub struct HalfSpace {
    grid: VolumeGrid,
    column: Column,
    stack: LayerTransforms,
    /// `6 nz` stress spectra, then the surface displacement's, then the tractions'.
    spectra: Vec<Array2<C64>>,
    kernels: Option<TractionKernels>,
    /// Whether `spectra` hold a strain's residual stress (set by `set_strain`, consumed by
    /// `stress`).
    strain_kept: bool,
}

impl HalfSpace {
    /// Bytes of the operator's spectra for `grid` (with the contact's coefficients when
    /// `contact` is true, one set per traction in `loads`), for an estimate before building.
    pub fn memory_bytes(grid: &VolumeGrid, contact_loads: usize) -> usize {
        let [ny, nx] = grid.plan_shape();
        let spectrum = (nx / 2 + 1) * ny;
        let nz = grid.depth.count();
        spectrum * 16 * (6 * nz + 4) + spectrum * 8 * 6 * nz * contact_loads
    }

    /// The operator of a half-space of shear modulus `shear_modulus_pa` and Poisson's ratio
    /// `poisson` on `grid`.
    pub fn new(grid: VolumeGrid, shear_modulus_pa: f64, poisson: f64) -> Self {
        let stack = LayerTransforms::new(grid.plan_shape());
        let spectra = stack.spectra(6 * grid.depth.count() + 2);
        Self {
            column: Column::new(shear_modulus_pa, poisson),
            stack,
            spectra,
            grid,
            kernels: None,
            strain_kept: false,
        }
    }

    pub fn grid(&self) -> &VolumeGrid {
        &self.grid
    }

    pub fn shear_modulus_pa(&self) -> f64 {
        self.column.shear_modulus_pa()
    }

    /// Computes and keeps the transforms of the contact's influence coefficients at the
    /// centres of the depth cells: a pressure, and a shear along x when `with_shear`
    /// (Poisson's ratio `poisson`, the body's).
    pub fn with_contact(mut self, poisson: f64, with_shear: bool) -> Result<Self, HalfSpaceError> {
        let pressure = traction_kernels(&self.grid, poisson, Unit::Pressure)?;
        let shear_x = match with_shear {
            true => Some(traction_kernels(&self.grid, poisson, Unit::ShearX)?),
            false => None,
        };
        self.kernels = Some(TractionKernels { pressure, shear_x });
        Ok(self)
    }

    /// The stress at the cell centres (`[nz, 6, ny, nx]`, Pa) and the normal surface
    /// displacement (`[ny, nx]`, m, into the body) of the plastic strain `strain`
    /// (`[nz, 6, ny, nx]`), plus, when `tractions` are given, the contact's stress of the
    /// pressure (Pa, `[ny, nx]`) and the shear along x (`shear_per_pressure` times it):
    /// [`HalfSpace::set_strain`] then [`HalfSpace::stress`].
    ///
    /// # Panics
    /// As those two.
    pub fn apply(
        &mut self,
        strain: ArrayView4<f64>,
        tractions: Option<(ArrayView2<f64>, f64)>,
        stress: ArrayViewMut4<f64>,
        surface: ArrayViewMut2<f64>,
    ) -> Result<(), HalfSpaceError> {
        self.set_strain(strain, surface)?;
        self.stress(tractions, stress)
    }

    /// Transforms the plastic strain `strain` (`[nz, 6, ny, nx]`), writes the normal surface
    /// displacement it causes (`[ny, nx]`, m, into the body) and keeps the transforms of its
    /// residual stress for [`HalfSpace::stress`].
    ///
    /// # Panics
    /// If a shape does not match the grid.
    pub fn set_strain(
        &mut self,
        strain: ArrayView4<f64>,
        surface: ArrayViewMut2<f64>,
    ) -> Result<(), HalfSpaceError> {
        let [nz, ny, nx] = self.grid.dims();
        assert_eq!(strain.shape(), [nz, 6, ny, nx], "strain shape");
        assert_eq!(surface.dim(), (ny, nx), "surface shape");
        let count = 6 * nz;
        let mut inputs: Vec<ArrayView2<f64>> = Vec::with_capacity(count);
        for l in 0..nz {
            for c in 0..6 {
                inputs.push(
                    strain
                        .view()
                        .index_axis_move(Axis(0), l)
                        .index_axis_move(Axis(0), c),
                );
            }
        }
        self.stack.forward(&inputs, &mut self.spectra[..count])?;
        self.pass()?;
        self.stack
            .inverse(&mut self.spectra[count..count + 1], vec![surface])?;
        self.strain_kept = true;
        Ok(())
    }

    /// The stress (`[nz, 6, ny, nx]`, Pa) at the cell centres: the residual stress of the
    /// plastic strain given to [`HalfSpace::set_strain`] (whose transforms this consumes),
    /// plus, when `tractions` are given, the contact's stress of the pressure (Pa,
    /// `[ny, nx]`) and of the shear along x (`shear_per_pressure` times it).
    ///
    /// # Panics
    /// If no strain is kept, a shape does not match the grid, or tractions are given to an
    /// operator built without [`HalfSpace::with_contact`] (or a shear to one without its
    /// shear).
    pub fn stress(
        &mut self,
        tractions: Option<(ArrayView2<f64>, f64)>,
        mut stress: ArrayViewMut4<f64>,
    ) -> Result<(), HalfSpaceError> {
        let [nz, ny, nx] = self.grid.dims();
        assert!(
            self.strain_kept,
            "HalfSpace::stress needs HalfSpace::set_strain first"
        );
        assert_eq!(stress.shape(), [nz, 6, ny, nx], "stress shape");
        let count = 6 * nz;
        if let Some((pressure, shear)) = &tractions {
            assert_eq!(pressure.dim(), (ny, nx), "pressure shape");
            let Some(kernels) = &self.kernels else {
                panic!("tractions need HalfSpace::with_contact")
            };
            assert!(
                *shear == 0.0 || kernels.shear_x.is_some(),
                "a shear needs the shear's coefficients"
            );
            let (stresses, rest) = self.spectra.split_at_mut(count);
            let traction = &mut rest[1];
            self.stack
                .forward(&[pressure.view()], std::slice::from_mut(traction))?;
            let traction = &*traction;
            // Each layer's components plus the kernels times the pressure's transform.
            for (index, spectrum) in stresses.iter_mut().enumerate() {
                let (l, c) = (index / 6, index % 6);
                add_kernel(spectrum, &kernels.pressure[l][c], c, 1.0, traction, 1.0);
                if let (Some(shear_kernels), true) = (&kernels.shear_x, *shear != 0.0) {
                    add_kernel(spectrum, &shear_kernels[l][c], c, -1.0, traction, *shear);
                }
            }
        }
        self.strain_kept = false;
        let mut flat = stress
            .view_mut()
            .into_shape_with_order((count, ny, nx))
            .map_err(|e| TransformError::new(&format!("the stress is not contiguous: {e}")))?;
        let outputs: Vec<ArrayViewMut2<f64>> = flat.axis_iter_mut(Axis(0)).collect();
        self.stack.inverse(&mut self.spectra[..count], outputs)?;
        Ok(())
    }

    /// One pass over the waves: the residual stresses of the strain's transforms in their
    /// place, and the surface displacement's transform.
    fn pass(&mut self) -> Result<(), HalfSpaceError> {
        let nz = self.grid.depth.count();
        let count = 6 * nz;
        let [plan_y, plan_x] = self.grid.plan_shape();
        let [dx, dy] = self.grid.spacing_m;
        let (period_x, period_y) = (plan_x as f64 * dx, plan_y as f64 * dy);
        let nyquist_x = (plan_x % 2 == 0).then_some(plan_x / 2);
        let nyquist_y = (plan_y % 2 == 0).then_some(plan_y / 2);
        let column = &self.column;
        let depth = &self.grid.depth;
        self.stack.for_each_column(
            &mut self.spectra,
            || Buffers::new(nz),
            |buffers, kx_index, columns| {
                let kx = 2.0 * std::f64::consts::PI * kx_index as f64 / period_x;
                let xs: &[f64] = if Some(kx_index) == nyquist_x {
                    &[kx, -kx]
                } else {
                    &[kx]
                };
                // A chunk of wavevectors at a time: each spectrum's values of the chunk are
                // read (and written) in one run, the chunk's columns of cells stay in cache.
                for first in (0..plan_y).step_by(CHUNK) {
                    let size = CHUNK.min(plan_y - first);
                    for (index, spectrum) in columns[..count].iter().enumerate() {
                        let (l, c) = (index / 6, index % 6);
                        for (w, value) in spectrum[first..first + size].iter().enumerate() {
                            buffers.strain[w * nz + l][c] = *value;
                        }
                    }
                    for w in 0..size {
                        let ky_index = first + w;
                        let ky = 2.0 * std::f64::consts::PI * signed_index(ky_index, plan_y) as f64
                            / period_y;
                        let ys: &[f64] = if Some(ky_index) == nyquist_y {
                            &[ky, -ky]
                        } else {
                            &[ky]
                        };
                        let strain = &buffers.strain[w * nz..(w + 1) * nz];
                        let out = &mut buffers.sum[w * nz..(w + 1) * nz];
                        if xs.len() * ys.len() == 1 {
                            let mut surface = [ZERO; 3];
                            column.apply(
                                [kx, ys[0]],
                                depth,
                                strain,
                                out,
                                &mut surface,
                                &mut buffers.work,
                            );
                            buffers.surface[w] = surface[2];
                            continue;
                        }
                        out.fill([ZERO; 6]);
                        let mut displacement = ZERO;
                        let weight = 1.0 / (xs.len() * ys.len()) as f64;
                        for &kx in xs {
                            for &ky in ys {
                                let mut surface = [ZERO; 3];
                                column.apply(
                                    [kx, ky],
                                    depth,
                                    strain,
                                    &mut buffers.stress,
                                    &mut surface,
                                    &mut buffers.work,
                                );
                                for (sum, cell) in out.iter_mut().zip(&buffers.stress) {
                                    for (s, v) in sum.iter_mut().zip(cell) {
                                        *s += *v * weight;
                                    }
                                }
                                displacement += surface[2] * weight;
                            }
                        }
                        buffers.surface[w] = displacement;
                    }
                    for (index, spectrum) in columns[..count].iter_mut().enumerate() {
                        let (l, c) = (index / 6, index % 6);
                        for (w, value) in spectrum[first..first + size].iter_mut().enumerate() {
                            *value = buffers.sum[w * nz + l][c];
                        }
                    }
                    columns[count][first..first + size].copy_from_slice(&buffers.surface[..size]);
                }
            },
        )?;
        Ok(())
    }
}

/// Wavevectors of a column handled together by [`HalfSpace::pass`].
const CHUNK: usize = 16;

/// The working memory of one thread's columns: a chunk of wavevectors' columns of cells.
struct Buffers {
    strain: Vec<[C64; 6]>,
    stress: Vec<[C64; 6]>,
    sum: Vec<[C64; 6]>,
    surface: Vec<C64>,
    work: ColumnWork,
}

impl Buffers {
    fn new(nz: usize) -> Self {
        Self {
            strain: vec![[ZERO; 6]; CHUNK * nz],
            stress: vec![[ZERO; 6]; nz],
            sum: vec![[ZERO; 6]; CHUNK * nz],
            surface: vec![ZERO; CHUNK],
            work: ColumnWork::default(),
        }
    }
}

/// `spectrum += factor kernel traction`, the kernel of component `c` real, or imaginary when
/// the component's parity (times `x_sign` for a shear along x, which reverses it in x) is
/// odd.
fn add_kernel(
    spectrum: &mut Array2<C64>,
    kernel: &Array2<f64>,
    c: usize,
    x_sign: f64,
    traction: &Array2<C64>,
    factor: f64,
) {
    let (px, py) = PRESSURE_PARITY[c];
    let real = px * py * x_sign > 0.0;
    ndarray::Zip::from(spectrum)
        .and(kernel)
        .and(traction)
        .for_each(|value, &k, &t| {
            let k = k * factor;
            if real {
                *value += t * k;
            } else {
                // i k t
                *value += C64::new(-t.im * k, t.re * k);
            }
        });
}

/// One layer's six kernels, or why its transform failed.
type LayerKernels = Result<[Array2<f64>; 6], TransformError>;

/// A unit traction on one cell.
#[derive(Clone, Copy, PartialEq)]
enum Unit {
    Pressure,
    ShearX,
}

/// The transforms of the stresses of a unit traction on cell `[0, 0]` at the centres of the
/// depth cells (module doc), each kept as its real or imaginary part.
fn traction_kernels(
    grid: &VolumeGrid,
    poisson: f64,
    unit: Unit,
) -> Result<Vec<[Array2<f64>; 6]>, HalfSpaceError> {
    let [ny, nx] = grid.shape;
    let mut load = Array2::zeros((ny, nx));
    load[[0, 0]] = 1.0;
    let (pressure, shear) = match unit {
        Unit::Pressure => (Some(load), None),
        Unit::ShearX => (None, Some(load)),
    };
    let tractions = TractionGrid::new([0.0, 0.0], grid.spacing_m, pressure, shear, None)
        .map_err(|e| HalfSpaceError::Coefficients(e.to_string()))?;
    let fft = match grid.periodicity {
        Periodicity::NonPeriodic => DcFft::new(&tractions, poisson)?,
        Periodicity::Periodic => DcFft::periodic(&tractions, poisson)?,
    };
    let depths = grid.depth.centres_m();
    let plan = RealFft2::sequential(grid.plan_shape());
    let x_sign = match unit {
        Unit::Pressure => 1.0,
        Unit::ShearX => -1.0,
    };
    let kept: Mutex<Vec<Option<LayerKernels>>> =
        Mutex::new((0..depths.len()).map(|_| None).collect());
    crate::field::for_each_dcfft_layer(&fft, &depths, |index, _, layer| {
        let mut work = plan.work();
        let mut spectrum = plan.new_spectrum();
        let result = (|| {
            let mut parts: Vec<Array2<f64>> = Vec::with_capacity(6);
            for (c, &parity) in PRESSURE_PARITY.iter().enumerate() {
                let coefficients = layer.index_axis(Axis(0), c);
                let grid_of = wrap_around(coefficients, grid.periodicity, parity, x_sign);
                plan.forward(grid_of.view(), &mut spectrum, &mut work)?;
                let (px, py) = parity;
                let real = px * py * x_sign > 0.0;
                parts.push(spectrum.mapv(|v| if real { v.re } else { v.im }));
            }
            let array: [Array2<f64>; 6] = parts
                .try_into()
                .map_err(|_| TransformError::new("six components"))?;
            Ok(array)
        })();
        if let Ok(mut slots) = kept.lock() {
            slots[index] = Some(result);
        }
    })?;
    let slots = kept
        .into_inner()
        .map_err(|_| HalfSpaceError::Coefficients("a worker panicked".into()))?;
    slots
        .into_iter()
        .map(|slot| match slot {
            Some(Ok(array)) => Ok(array),
            Some(Err(e)) => Err(HalfSpaceError::Transform(e)),
            None => Err(HalfSpaceError::Coefficients(
                "a layer was not computed".into(),
            )),
        })
        .collect()
}

/// The coefficients of offsets `(i, j) >= 0` (the layer of a unit load on cell `[0, 0]`)
/// laid out for the convolution: as they are on a periodic grid (circular offsets), or in
/// wrap-around order on the padded grid with the negative offsets from the parity.
fn wrap_around(
    coefficients: ArrayView2<f64>,
    periodicity: Periodicity,
    parity: (f64, f64),
    x_sign: f64,
) -> Array2<f64> {
    if periodicity == Periodicity::Periodic {
        return coefficients.to_owned();
    }
    let (ny, nx) = coefficients.dim();
    let (px, py) = (parity.0 * x_sign, parity.1);
    let mut out = Array2::zeros((2 * ny, 2 * nx));
    for ((j, i), &value) in coefficients.indexed_iter() {
        let (jm, im) = ((2 * ny - j) % (2 * ny), (2 * nx - i) % (2 * nx));
        out[[j, i]] = value;
        if i > 0 {
            out[[j, im]] = px * value;
        }
        if j > 0 {
            out[[jm, i]] = py * value;
        }
        if i > 0 && j > 0 {
            out[[jm, im]] = px * py * value;
        }
    }
    out
}

#[cfg(test)]
mod tests;
