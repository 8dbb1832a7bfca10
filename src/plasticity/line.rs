//! Elastic-plastic line contact in plane strain: a cylinder (or a rigid roller) pressed on an
//! elastic-plastic body 1, the fields independent of y, the total strain `ε_yy = 0`, on a 2-D
//! x–z volume of `nx` columns and `nz` layers; the semi-analytical load steps of
//! [`super::loading`] with a plane operator and a line contact solver.
//!
//! ## The eigenstrain operator
//! A y-independent eigenstrain is a sum of waves `ε*(z) exp(i kx x)` with `ky = 0`, and the
//! half-space's response to each is that of [`super::column`] at the wavevector `(kx, 0)`: the
//! plane-strain problem in `(x, z)` (`s = x`) and the anti-plane one along `t = y`. Nothing
//! varies along y, so `u_y` is the anti-plane displacement alone, driven only by `ε*_xy` and
//! `ε*_yz`, which J2 flow under in-plane loads never creates (the deviatoric stress has no such
//! components): `u_y = 0` and `ε_yy = 0`, and the column's `σ_yy = σ_tt` is the plane-strain
//! one, `σ_yy = ν (σ_xx + σ_zz) - E ε*_yy` (Hooke's law with `ε_yy = 0`; checked cell by cell in
//! the tests). The waves come from a real FFT of each layer in x, zero-padded to `2 nx` (the
//! contact isolated as DC-FFT isolates it: the images of the plastic zone lie a grid length
//! away); the Nyquist wave takes the mean of `±kx`, the mean wave the uniform layer.
//!
//! ## The contact's stress
//! The stress of the pressure and of `q = μ p` (on body 1 along +x) at the cell centres: the
//! discrete convolution of the cells' tractions with the closed-form stress of a uniform
//! strip ([`crate::solution::strip::uniform_strip`], Flamant's solutions integrated over the
//! cell; Johnson 1985 §2.2), `σ_yy = ν (σ_xx + σ_zz)` in plane strain, summed directly over
//! the cells in contact.
//!
//! ## The line contact
//! The pressure under the load per unit length `P` on the gap `g0 + u_p` (the undeformed gap
//! and the plastic strain's surface displacement, into body 1): the surface displacement of a
//! strip of uniform pressure on a half-plane, `u_z(x) = -(2/(π E*)) ∫ p(s) ln|x - s| ds + C`
//! (Johnson 1985, §2.2, both bodies' compliance in `E*`; the coupling of the tangential traction
//! into `u_z` is left out, as the point contact's solver leaves it), on the cells, and
//! Kalker's active set over a dense system (the cells in contact, and the approach closing the
//! load), as [`crate::contact::coated`] solves a coated line. The constant `C` of a plane
//! problem is absorbed by the approach, which the solver defines only up to it.
//!
//! ## The approach
//! A plane problem defines an approach only between points at a finite depth (the project's
//! Hertz line reports the approach of the cylinders' axes; a flat has none). Here it is the
//! approach of the two points on the contact's axis at the volume grid's depth `D` below each
//! body's surface: `δ = -∫_0^D ε_zz dz` along body 1's axis (its total strain: elastic from the
//! total stress with `σ_yy`, plus plastic), plus the same integral of body 2's elastic strain
//! under the contact's tractions when body 2 is elastic (`0` for a rigid roller), by the
//! midpoint rule over the depth cells. For Hertz's pressure on one elastic half-plane it is
//! `δ(D) = (p0/E) [(1 - ν²) a asinh(D/a) - ν(1 + ν)(D √(a² + D²) - D²)/a]` (the axis stresses
//! of McEwen's field integrated; derived here), which the tests compare.
//!
//! ## References
//! - K. L. Johnson, *Contact Mechanics*, Cambridge University Press (1985), §2.2 (Flamant's
//!   line loads, the surface displacement of a pressure on a half-plane), §4.2(b) (Hertz's line
//!   contact).
//! - J. J. Kalker, *Three-Dimensional Elastic Bodies in Rolling Contact*, Kluwer (1990), ch. 2.
//! - C. Jacq, D. Nélias, G. Lormand, D. Girodin (2002), and L. Frérot, M. Bonnet,
//!   J.-F. Molinari, G. Anciaux (2019), as in [`super::loading`].

use std::f64::consts::PI;
use std::sync::Arc;

use ndarray::{Array2, Array4};
use realfft::{ComplexToReal, RealFftPlanner, RealToComplex};

use super::column::{Column, ColumnWork, DepthCells, C64, XX, XZ, YY, ZZ};
use super::j2::Hardening;
use super::loading::{
    run, PlasticBody, PlasticContactError, PlasticContactSolution, Progress, StepState, Steps,
};
use crate::solution::strip::uniform_strip;

const ZERO: C64 = C64 { re: 0.0, im: 0.0 };

/// The x–z volume grid: `cells` columns of width `spacing_m` (a cell centred on the axis at
/// index `cells / 2`) over the depth cells.
#[derive(Clone, Debug, PartialEq)]
pub struct LineGrid {
    pub cells: usize,
    pub spacing_m: f64,
    pub depth: DepthCells,
}

impl LineGrid {
    /// `[nz, nx]`.
    pub fn dims(&self) -> [usize; 2] {
        [self.depth.count(), self.cells]
    }

    /// The cell centres' x (m, from the axis).
    pub fn x_m(&self) -> Vec<f64> {
        (0..self.cells)
            .map(|i| (i as f64 - (self.cells / 2) as f64) * self.spacing_m)
            .collect()
    }
}

/// The residual stress of a plane-strain eigenstrain and the contact's stress, on a
/// [`LineGrid`] (arrays `[nz, 6, 1, nx]`: the layout of [`super::loading`] with one row).
pub struct PlaneStrainSpace {
    grid: LineGrid,
    column: Column,
    poisson: f64,
    forward: Arc<dyn RealToComplex<f64>>,
    inverse: Arc<dyn ComplexToReal<f64>>,
    /// `[l][d]`: `(σxx, σzz, σxz)` at the centre of layer `l` of a unit pressure on the cell
    /// `d - (nx - 1)` cells to the left.
    pressure_kernels: Vec<Vec<[f64; 3]>>,
    /// The same of a unit shear along +x.
    shear_kernels: Vec<Vec<[f64; 3]>>,
}

impl PlaneStrainSpace {
    /// The operator of body 1 (Young's modulus, Poisson's ratio in (-1, 0.5)) on `grid`.
    pub fn new(grid: LineGrid, modulus_pa: f64, poisson: f64) -> Self {
        let shear_modulus = modulus_pa / (2.0 * (1.0 + poisson));
        let n = 2 * grid.cells;
        let mut planner = RealFftPlanner::<f64>::new();
        let forward = planner.plan_fft_forward(n);
        let inverse = planner.plan_fft_inverse(n);
        let (pressure_kernels, shear_kernels) = strip_kernels(&grid);
        Self {
            column: Column::new(shear_modulus, poisson),
            poisson,
            forward,
            inverse,
            pressure_kernels,
            shear_kernels,
            grid,
        }
    }

    pub fn grid(&self) -> &LineGrid {
        &self.grid
    }

    /// The residual stress (`[nz, 6, 1, nx]`, Pa, at the cell centres) and the normal surface
    /// displacement (m, into the body, one per column) of the plastic strain `strain`
    /// (`[nz, 6, 1, nx]`, tensor components).
    pub fn residual(
        &self,
        strain: &Array4<f64>,
        stress: &mut Array4<f64>,
        surface: &mut [f64],
    ) -> Result<(), PlasticContactError> {
        let [nz, nx] = self.grid.dims();
        let n = 2 * nx;
        let bins = nx + 1;
        let fft_error = |e: realfft::FftError| PlasticContactError::Transform(e.to_string());
        // spectra[l][c][bin]
        let mut spectra = vec![vec![vec![ZERO; bins]; 6]; nz];
        let mut input = vec![0.0; n];
        let mut scratch = self.forward.make_scratch_vec();
        for (l, layer) in spectra.iter_mut().enumerate() {
            for (c, spectrum) in layer.iter_mut().enumerate() {
                input.fill(0.0);
                for i in 0..nx {
                    input[i] = strain[[l, c, 0, i]];
                }
                if input.iter().all(|&v| v == 0.0) {
                    continue;
                }
                self.forward
                    .process_with_scratch(&mut input, spectrum, &mut scratch)
                    .map_err(fft_error)?;
            }
        }
        let period = n as f64 * self.grid.spacing_m;
        let mut work = ColumnWork::default();
        let mut column_strain = vec![[ZERO; 6]; nz];
        let mut column_stress = vec![[ZERO; 6]; nz];
        let mut sum = vec![[ZERO; 6]; nz];
        let mut surface_spectrum = vec![ZERO; bins];
        for (bin, surface_value) in surface_spectrum.iter_mut().enumerate() {
            for (l, cell) in column_strain.iter_mut().enumerate() {
                for c in 0..6 {
                    cell[c] = spectra[l][c][bin];
                }
            }
            let kx = 2.0 * PI * bin as f64 / period;
            let waves: &[f64] = if bin == nx { &[kx, -kx] } else { &[kx] };
            for cell in sum.iter_mut() {
                *cell = [ZERO; 6];
            }
            let weight = 1.0 / waves.len() as f64;
            let mut displacement = ZERO;
            for &k in waves {
                let mut at_surface = [ZERO; 3];
                self.column.apply(
                    [k, 0.0],
                    &self.grid.depth,
                    &column_strain,
                    &mut column_stress,
                    &mut at_surface,
                    &mut work,
                );
                for (s, cell) in sum.iter_mut().zip(&column_stress) {
                    for (value, add) in s.iter_mut().zip(cell) {
                        *value += *add * weight;
                    }
                }
                displacement += at_surface[2] * weight;
            }
            *surface_value = displacement;
            for (l, cell) in sum.iter().enumerate() {
                for c in 0..6 {
                    spectra[l][c][bin] = cell[c];
                }
            }
        }
        let mut output = vec![0.0; n];
        let mut scratch = self.inverse.make_scratch_vec();
        let scale = 1.0 / n as f64;
        let mut invert =
            |spectrum: &mut Vec<C64>, output: &mut Vec<f64>| -> Result<(), PlasticContactError> {
                // The mean's and the Nyquist wave's imaginary parts vanish for a real field.
                spectrum[0].im = 0.0;
                spectrum[bins - 1].im = 0.0;
                self.inverse
                    .process_with_scratch(spectrum, output, &mut scratch)
                    .map_err(fft_error)
            };
        for (l, layer) in spectra.iter_mut().enumerate() {
            for (c, spectrum) in layer.iter_mut().enumerate() {
                invert(spectrum, &mut output)?;
                for i in 0..nx {
                    stress[[l, c, 0, i]] = output[i] * scale;
                }
            }
        }
        invert(&mut surface_spectrum, &mut output)?;
        for (i, value) in surface.iter_mut().enumerate().take(nx) {
            *value = output[i] * scale;
        }
        Ok(())
    }

    /// Adds the contact's stress of the pressure `pressure_pa` (one per column) and the shear
    /// `friction` times it along +x on body 1 to `stress` (`[nz, 6, 1, nx]`).
    pub fn add_contact(&self, pressure_pa: &[f64], friction: f64, stress: &mut Array4<f64>) {
        let [nz, nx] = self.grid.dims();
        let loaded: Vec<(usize, f64)> = pressure_pa
            .iter()
            .enumerate()
            .filter(|(_, &p)| p > 0.0)
            .map(|(j, &p)| (j, p))
            .collect();
        for l in 0..nz {
            for i in 0..nx {
                let mut s = [0.0; 3];
                for &(j, p) in &loaded {
                    let d = i + nx - 1 - j;
                    let normal = self.pressure_kernels[l][d];
                    let shear = self.shear_kernels[l][d];
                    for c in 0..3 {
                        s[c] += p * (normal[c] + friction * shear[c]);
                    }
                }
                stress[[l, XX, 0, i]] += s[0];
                stress[[l, ZZ, 0, i]] += s[1];
                stress[[l, XZ, 0, i]] += s[2];
                stress[[l, YY, 0, i]] += self.poisson * (s[0] + s[1]);
            }
        }
    }

    /// `(σxx, σzz)` of the contact's tractions at the centres of column `i`'s cells, the shear
    /// `friction` times the pressure along +x.
    fn contact_axis(&self, pressure_pa: &[f64], friction: f64, i: usize) -> Vec<[f64; 2]> {
        let [nz, nx] = self.grid.dims();
        (0..nz)
            .map(|l| {
                let mut s = [0.0; 2];
                for (j, &p) in pressure_pa.iter().enumerate() {
                    if p > 0.0 {
                        let d = i + nx - 1 - j;
                        let normal = self.pressure_kernels[l][d];
                        let shear = self.shear_kernels[l][d];
                        s[0] += p * (normal[0] + friction * shear[0]);
                        s[1] += p * (normal[1] + friction * shear[1]);
                    }
                }
                s
            })
            .collect()
    }
}

/// The strips' stresses at the layers' centres, per offset (see
/// [`PlaneStrainSpace::pressure_kernels`]).
#[allow(clippy::type_complexity)]
fn strip_kernels(grid: &LineGrid) -> (Vec<Vec<[f64; 3]>>, Vec<Vec<[f64; 3]>>) {
    let nx = grid.cells;
    let dx = grid.spacing_m;
    let mut pressure = Vec::with_capacity(grid.depth.count());
    let mut shear = Vec::with_capacity(grid.depth.count());
    for z in grid.depth.centres_m() {
        let (p, q): (Vec<[f64; 3]>, Vec<[f64; 3]>) = (0..2 * nx - 1)
            .map(|d| {
                let x = (d as f64 - (nx - 1) as f64) * dx;
                uniform_strip(x, z, -0.5 * dx, 0.5 * dx)
            })
            .unzip();
        pressure.push(p);
        shear.push(q);
    }
    (pressure, shear)
}

/// The line contact on a row of cells: the surface displacement of uniform pressure strips
/// (module doc) and Kalker's active set.
pub struct LineContactSolver {
    cells: usize,
    spacing_m: f64,
    /// `[d]`: the displacement into the bodies at a cell of a unit pressure on the cell
    /// `d - (nx - 1)` to its left, up to the plane problem's constant.
    influence: Vec<f64>,
}

impl LineContactSolver {
    /// The solver of `cells` cells of width `spacing_m` between bodies of combined modulus
    /// `e_star_pa`.
    pub fn new(cells: usize, spacing_m: f64, e_star_pa: f64) -> Self {
        // ∫ ln|X| dX = X ln|X| - X.
        let primitive = |x: f64| {
            if x == 0.0 {
                0.0
            } else {
                x * x.abs().ln() - x
            }
        };
        let factor = -2.0 / (PI * e_star_pa);
        let influence = (0..2 * cells - 1)
            .map(|d| {
                let x = (d as f64 - (cells - 1) as f64) * spacing_m;
                factor * (primitive(x + 0.5 * spacing_m) - primitive(x - 0.5 * spacing_m))
            })
            .collect();
        Self {
            cells,
            spacing_m,
            influence,
        }
    }

    fn coefficient(&self, i: usize, j: usize) -> f64 {
        self.influence[i + self.cells - 1 - j]
    }

    /// The pressure (Pa, one per cell) carrying `load_n_per_m` on the gap `gap_m` (m, one per
    /// cell, the bodies' separation before their elastic displacement), starting from the
    /// cells where `warm` is positive (if any).
    pub fn solve(
        &self,
        gap_m: &[f64],
        load_n_per_m: f64,
        warm: Option<&[f64]>,
    ) -> Result<Vec<f64>, String> {
        let n = self.cells;
        if gap_m.len() != n {
            return Err(format!("{} gaps for {n} cells", gap_m.len()));
        }
        let mut active: Vec<bool> = match warm {
            Some(p) if p.iter().any(|&v| v > 0.0) => p.iter().map(|&v| v > 0.0).collect(),
            _ => {
                let lowest = gap_m
                    .iter()
                    .enumerate()
                    .fold(
                        (0, f64::INFINITY),
                        |b, (i, &g)| if g < b.1 { (i, g) } else { b },
                    );
                (0..n).map(|i| i == lowest.0).collect()
            }
        };
        let scale = gap_m
            .iter()
            .fold(0.0f64, |m, &g| m.max(g.abs()))
            .max(1e-300);
        for _ in 0..MAX_ACTIVE_SET_ITERATIONS {
            let cells: Vec<usize> = (0..n).filter(|&i| active[i]).collect();
            let m = cells.len();
            // [K_AA  -1] [p]   [-g_A]
            // [dx ... 0] [δ] = [ P  ]
            let mut matrix = vec![vec![0.0; m + 1]; m + 1];
            let mut rhs = vec![0.0; m + 1];
            for (r, &i) in cells.iter().enumerate() {
                for (c, &j) in cells.iter().enumerate() {
                    matrix[r][c] = self.coefficient(i, j);
                }
                matrix[r][m] = -1.0;
                rhs[r] = -gap_m[i];
            }
            matrix[m][..m].fill(self.spacing_m);
            rhs[m] = load_n_per_m;
            let solution = solve_dense(matrix, rhs)
                .ok_or_else(|| "the contact's system is singular".to_string())?;
            let approach = solution[m];
            let mut pressure = vec![0.0; n];
            for (r, &i) in cells.iter().enumerate() {
                pressure[i] = solution[r];
            }
            let negative: Vec<usize> = cells
                .iter()
                .copied()
                .filter(|&i| pressure[i] < 0.0)
                .collect();
            if !negative.is_empty() && negative.len() < m {
                for i in negative {
                    active[i] = false;
                }
                continue;
            }
            // The cells outside that the bodies would interpenetrate.
            let mut added = false;
            let outside: Vec<usize> = (0..n).filter(|&i| !active[i]).collect();
            for i in outside {
                let displacement: f64 = cells
                    .iter()
                    .map(|&j| self.coefficient(i, j) * pressure[j])
                    .sum();
                if gap_m[i] + displacement - approach < -1e-12 * scale {
                    active[i] = true;
                    added = true;
                }
            }
            if !added {
                if !negative.is_empty() {
                    return Err("the active set has no cell of positive pressure".into());
                }
                return Ok(pressure);
            }
        }
        Err(format!(
            "the active set did not settle in {MAX_ACTIVE_SET_ITERATIONS} iterations"
        ))
    }
}

/// Active-set iterations allowed in one line contact solve.
const MAX_ACTIVE_SET_ITERATIONS: usize = 200;

/// Gaussian elimination with partial pivoting; `None` if singular.
fn solve_dense(mut a: Vec<Vec<f64>>, mut b: Vec<f64>) -> Option<Vec<f64>> {
    let n = b.len();
    for k in 0..n {
        let pivot = (k..n).max_by(|&i, &j| a[i][k].abs().total_cmp(&a[j][k].abs()))?;
        if a[pivot][k] == 0.0 {
            return None;
        }
        a.swap(k, pivot);
        b.swap(k, pivot);
        let (upper, lower) = a.split_at_mut(k + 1);
        let pivot_row = &upper[k];
        for (offset, row) in lower.iter_mut().enumerate() {
            let factor = row[k] / pivot_row[k];
            if factor != 0.0 {
                for (value, p) in row[k..].iter_mut().zip(&pivot_row[k..]) {
                    *value -= factor * p;
                }
                b[k + 1 + offset] -= factor * b[k];
            }
        }
    }
    let mut x = vec![0.0; n];
    for k in (0..n).rev() {
        let sum: f64 = (k + 1..n).map(|j| a[k][j] * x[j]).sum();
        x[k] = (b[k] - sum) / a[k][k];
    }
    Some(x)
}

/// An elastic-plastic line contact loaded step by step.
#[derive(Clone, Debug)]
pub struct LinePlasticProblem {
    /// The undeformed gap between the bodies (m, one per column, `x² / 2R` for cylinders).
    pub gap_m: Vec<f64>,
    pub grid: LineGrid,
    /// Body 1's Young's modulus and Poisson's ratio.
    pub modulus_pa: f64,
    pub poisson: f64,
    /// Body 2's, or `None` when rigid (for the approach).
    pub counter: Option<(f64, f64)>,
    /// The contact's combined modulus.
    pub e_star_pa: f64,
    pub hardening: Hardening,
    /// `q = μ p` on body 1 along +x.
    pub friction: f64,
    /// The load per unit length of each step (N/m): loading, then unloading.
    pub loads_n_per_m: Vec<f64>,
    /// The steps after which the whole state is kept.
    pub snapshots: Vec<usize>,
    pub tolerance: f64,
    pub max_iterations: usize,
    pub acceleration: usize,
}

/// Bytes the solve of `grid` takes besides the snapshots (the strains, stresses, spectra and
/// kernels).
pub fn memory_bytes(grid: &LineGrid) -> usize {
    let [nz, nx] = grid.dims();
    nz * nx * 8 * (6 * 5 + 2) + nz * (nx + 1) * 16 * 6 + 2 * nz * 2 * nx * 24 + nx * nx * 8
}

/// The plane-strain body of the load-step loop ([`super::loading::run`]): the operator, the
/// residual stress of the last plastic strain, and the line contact on the gap.
struct PlaneBody<'a> {
    problem: &'a LinePlasticProblem,
    operator: PlaneStrainSpace,
    contact: LineContactSolver,
    residual_stress: Array4<f64>,
    surface: Vec<f64>,
    gap: Vec<f64>,
}

impl PlasticBody for PlaneBody<'_> {
    fn set_strain(
        &mut self,
        strain: &Array4<f64>,
        displacement: &mut Array2<f64>,
    ) -> Result<(), PlasticContactError> {
        self.operator
            .residual(strain, &mut self.residual_stress, &mut self.surface)?;
        for (u, &value) in displacement.iter_mut().zip(&self.surface) {
            *u = value;
        }
        Ok(())
    }

    fn stress(
        &mut self,
        pressure_pa: &Array2<f64>,
        friction: f64,
        stress: &mut Array4<f64>,
    ) -> Result<(), PlasticContactError> {
        stress.assign(&self.residual_stress);
        let pressure: Vec<f64> = pressure_pa.iter().copied().collect();
        self.operator.add_contact(&pressure, friction, stress);
        Ok(())
    }

    fn contact(
        &mut self,
        step: usize,
        load: f64,
        displacement: &Array2<f64>,
        previous: &Array2<f64>,
    ) -> Result<(Array2<f64>, f64), PlasticContactError> {
        for ((g, &g0), &u) in self
            .gap
            .iter_mut()
            .zip(&self.problem.gap_m)
            .zip(displacement.iter())
        {
            *g = g0 + u;
        }
        let warm: Vec<f64> = previous.iter().copied().collect();
        let pressure = self
            .contact
            .solve(&self.gap, load, Some(&warm))
            .map_err(|message| PlasticContactError::LineContact {
                step,
                load_n_per_m: load,
                message,
            })?;
        let nx = pressure.len();
        let pressure = Array2::from_shape_vec((1, nx), pressure)
            .map_err(|e| PlasticContactError::Parameter(e.to_string()))?;
        // The dense solver's approach is defined up to the plane problem's constant: the
        // reported one is the final state's (PlasticBody::approach_m).
        Ok((pressure, 0.0))
    }

    fn approach_needs_stress(&self) -> bool {
        true
    }

    fn approach_m(
        &self,
        _contact_m: f64,
        stress: &Array4<f64>,
        strain: &Array4<f64>,
        pressure_pa: &Array2<f64>,
    ) -> f64 {
        let pressure: Vec<f64> = pressure_pa.iter().copied().collect();
        approach_m(
            &self.operator,
            stress,
            strain,
            &pressure,
            [self.problem.modulus_pa, self.problem.poisson],
            self.problem.counter,
            self.problem.friction,
        )
    }
}

/// Solves the steps ([`super::loading::run`] on the plane-strain body); `progress` after every
/// iteration. The results' loads and arrays: N/m, one row in y (`[nz, 6, 1, nx]`,
/// `[nz, 1, nx]`, `[1, nx]`).
pub fn solve(
    problem: &LinePlasticProblem,
    progress: &mut dyn FnMut(Progress),
    observe: Option<&mut dyn FnMut(&StepState)>,
) -> Result<PlasticContactSolution, PlasticContactError> {
    let grid = &problem.grid;
    let [nz, nx] = grid.dims();
    if problem.gap_m.len() != nx {
        return Err(PlasticContactError::Parameter(format!(
            "{} gaps for {nx} columns",
            problem.gap_m.len()
        )));
    }
    let steps = Steps {
        dims: [nz, 1, nx],
        modulus_pa: problem.modulus_pa,
        poisson: problem.poisson,
        hardening: problem.hardening,
        friction: problem.friction,
        loads: &problem.loads_n_per_m,
        snapshots: &problem.snapshots,
        axis_cell: [0, nx / 2],
        tolerance: problem.tolerance,
        max_iterations: problem.max_iterations,
        acceleration: problem.acceleration,
    };
    steps.validate("half-plane")?;
    let mut body = PlaneBody {
        problem,
        operator: PlaneStrainSpace::new(grid.clone(), problem.modulus_pa, problem.poisson),
        contact: LineContactSolver::new(nx, grid.spacing_m, problem.e_star_pa),
        residual_stress: Array4::zeros((nz, 6, 1, nx)),
        surface: vec![0.0; nx],
        gap: vec![0.0; nx],
    };
    run(&mut body, &steps, progress, observe)
}

/// The approach of the points at the grid's depth below each surface on the axis (module
/// doc): body 1's `-∫ ε_zz dz` from its total stress and plastic strain, plus body 2's elastic
/// one under the contact's tractions (`counter` its modulus and Poisson's ratio; its shear is
/// `-μ p`), by the midpoint rule over the depth cells.
fn approach_m(
    operator: &PlaneStrainSpace,
    stress: &Array4<f64>,
    strain: &Array4<f64>,
    pressure_pa: &[f64],
    body1: [f64; 2],
    counter: Option<(f64, f64)>,
    friction: f64,
) -> f64 {
    let grid = operator.grid();
    let axis = grid.cells / 2;
    let [modulus, nu] = body1;
    let mut approach = 0.0;
    for l in 0..grid.depth.count() {
        let s = |c: usize| stress[[l, c, 0, axis]];
        let elastic = (s(ZZ) - nu * (s(XX) + s(YY))) / modulus;
        let total = elastic + strain[[l, ZZ, 0, axis]];
        approach -= total * grid.depth.thickness_m(l);
    }
    if let Some((modulus2, nu2)) = counter {
        let along = operator.contact_axis(pressure_pa, -friction, axis);
        for (l, [sxx, szz]) in along.iter().enumerate() {
            let strain_zz = ((1.0 - nu2 * nu2) * szz - nu2 * (1.0 + nu2) * sxx) / modulus2;
            approach -= strain_zz * grid.depth.thickness_m(l);
        }
    }
    approach
}

#[cfg(test)]
#[path = "line_tests.rs"]
mod tests;
