//! The stresses in a coated body under tractions given on a grid: all six components at any
//! depth, in the coating and in the substrate, from the layered response of each traction
//! wave ([`super::response`]).
//!
//! ## The tractions as waves
//! The pressure `p` and the shear `qx` are given at the centres of a `[ny, nx]` grid and taken
//! as the band-limited functions through their samples (Whittaker–Shannon: each sample a
//! `sinc` in x and y); each wavenumber is one surface wave, whose stress at depth `z` follows
//! in closed form. On the surface the samples come back exactly (`σzz = -p`, `σxz = -qx`,
//! `σyz = 0` at every centre, to round-off); the Nyquist waves, which a real grid cannot carry
//! with their sign, are left out. Unlike the cell-based layers of a homogeneous body, no
//! influence coefficients exist here in closed form: the waves are exact for the band-limited
//! tractions, which differ from uniform cells by the cells' form factor (a smoothing on the
//! scale of a cell).
//!
//! A **periodic** contact is its own period: the grid's discrete transform gives every wave,
//! and the mean traction stresses the body uniformly (`σzz = -p̄`, `τxz = -q̄x`, as for the
//! homogeneous layers of [`crate::solution::dcfft`]).
//!
//! ## An isolated contact
//! The field of isolated tractions is the integral over all wavenumbers,
//! `σ(x) = (1/4π²) ∫ G(k, z) P(k) e^(ik·x) d²k`. Summed on the grid zero-padded to
//! `[2ny, 2nx]` (the lattice of its discrete transform) it is the field of periodic images two
//! grid lengths apart, whose stresses fall only as `1/R²` at depth: at `z >= a` under a Hertz
//! contact on ±2a they took 3 to 9 % off the maxima. The images come from the low
//! wavenumbers, where `G` depends on the direction of `k` alone; so the spectrum is split by a
//! smooth window (as Ewald splits a lattice sum; the split is derived here):
//!
//! ```text
//! G = G (1 - w) + G w,     w = (1 + s) e^(-s),   s = (kx Lx / α)² + (ky Ly / α)²
//! ```
//!
//! (`Lx`, `Ly` the padded grid's sides, `α` = [`SPLIT`]).
//! - `G (1 - w)` is summed on the padded grid: `1 - w = s²/2 + ...` vanishes as `k⁴` at
//!   `k = 0`, so its real-space kernel is `K - K * g` with `g` (the transform of `w`) a bump of
//!   width `ℓ = 2L/α` whose second moments vanish: beyond `ℓ` it falls as `(ℓ/R)⁴` of `K`, and
//!   its images (at least half a padded grid, `L/2`, from any cell) weigh about `(4/α)⁴`
//!   (1e-3) of what the images of `K` did. The images of the tractions smoothed by `g` reach
//!   the grid by `(α/4)² e^(-α²/16)` (1e-14) of the pressure.
//! - `G w` is confined to `s < 36` (`w < 1e-14` beyond) and summed on a lattice
//!   [`REFINEMENT`] times finer, whose images lie `REFINEMENT` padded grids away (their error
//!   falls as `1/REFINEMENT³` on a square grid, whose `1/R²` terms cancel by symmetry): the
//!   tractions' transform `P(k)` at each point summed directly (rows, then columns), the
//!   waves summed directly at the points asked for. The mean wave stands for the lattice cell
//!   around `k = 0`: its factors are the waves' averaged over the disk of the cell's area and
//!   over direction (the in-plane stress `(σss + σtt)/2`, for a homogeneous body
//!   `-(1 + 2ν) p̄ / 2`).
//!
//! In practice the padded grid sums every wave (`G`, not `G (1 - w)`: one transform, as for a
//! periodic contact), and the correction `D = Σ_fine G w P e^(ik·x) - Σ_padded G w P e^(ik·x)`
//! (the fine lattice's points at multiples of [`REFINEMENT`] are the padded grid's, so `D` is
//! one sum over the fine lattice with those points weighed `1 - REFINEMENT²`) is added: along a
//! row at every cell; on a whole plane every sixteenth of the grid and interpolated between by
//! cubics (`D` is the low wavenumbers' field of the images, at least `L/2` away: smooth over
//! the grid). The cost over the periodic sum: the tractions' transform at the lattice points
//! once, and 30 000 more waves a depth (against 260 000 on the padded grid of 255² cells).
//! Influence coefficients tabulated in real space (a Hankel transform per depth and
//! component, then a transform of the padded grid each) would cost more per depth: this keeps
//! the padded grid's waves and adds a small lattice.
//!
//! Measured (`crate::coating` tests, `docs/coatings.md`): Hertz tractions (μ = 0.3) on 64²
//! cells over ±2a against the same centred in 192² cells over ±6a, B4C and a soft coating on
//! steel, depths to 2.5a: 7e-5 `p0` below the surface (2.2e-2 `p0` with the images), 1.4e-4
//! `p0` on it (the band-limited tractions' ripples near the Nyquist wavenumber, which do not
//! decay there); on equal moduli (μ = 0.2, 128² cells over ±2a) against Hamilton's closed form
//! within ±1.5a, z = 0.25a to 0.8a: 9.4e-4 `p0` (8.9e-3 with the images; 2.7e-4 on 256²
//! cells: the sampled pressure).

use std::f64::consts::PI;

use ndarray::{Array2, Array3, ArrayView2, Axis};
use rustfft::num_complex::Complex;

use super::response::{Layered, Side, WaveResponse, WaveStress};
use crate::operator::transform::{signed_index, RealFft2, TransformError};

/// `α` of the split (module doc): the window's width `k_w = α / L`.
pub const SPLIT: f64 = 24.0;

/// How many times finer the low wavenumbers' lattice is than the padded grid's.
pub const REFINEMENT: usize = 6;

/// The largest `s` kept: beyond, `w = (1 + s) e^(-s) < 1e-14`.
const CUTOFF: f64 = 36.0;

/// The nodes per grid side at which [`LayeredStress::layer`] sums the image correction.
const PLANE_NODES: usize = 16;

/// One point of the low wavenumbers' lattice.
struct LowPoint {
    /// The column (`kx` index, `>= 0`).
    column: usize,
    /// `(kx, ky, |k|)` and the wave's constants; `None` for the mean (`k = 0`).
    wave: Option<([f64; 3], WaveResponse)>,
    /// `ky`, 1/m.
    ky: f64,
    /// The tractions' transforms times `w`, the point's weight in the correction (module doc)
    /// and 2 off the column `kx = 0` (whose conjugate points the real field adds), per load
    /// (0 pressure, 1 `qx`).
    tractions: [Complex<f64>; 2],
}

/// The correction of an isolated contact's periodic sum (module doc).
struct Correction {
    /// `kx` of each column, 1/m.
    kx: Vec<f64>,
    points: Vec<LowPoint>,
    /// The radius of the disk of the fine lattice cell's area, 1/m.
    mean_radius: f64,
}

/// The stress layers of one set of tractions on a coated body.
pub struct LayeredStress {
    layered: Layered,
    shape: [usize; 2],
    spacing_m: [f64; 2],
    plan: RealFft2,
    /// `(load, spectrum)`: load 0 the pressure, 1 `qx`; only the loads present.
    loads: Vec<(usize, Array2<Complex<f64>>)>,
    /// Per spectrum entry `[kx, ky]`: the wave vector `(kx, ky)`, `|k|` and the wave's
    /// constants (`None` for the mean and the Nyquist waves).
    waves: Array2<Option<([f64; 3], WaveResponse)>>,
    /// The correction of an isolated contact; `None` for a periodic one.
    correction: Option<Correction>,
}

impl LayeredStress {
    /// Transforms the tractions (Pa, `[ny, nx]`, cells `spacing_m`): `pressure`, and `shear_x`
    /// (`qx`, acting in +x on the body) when given.
    pub fn new<'a>(
        layered: Layered,
        pressure: ArrayView2<'a, f64>,
        shear_x: Option<ArrayView2<'a, f64>>,
        spacing_m: [f64; 2],
        periodic: bool,
    ) -> Result<Self, TransformError> {
        let (ny, nx) = pressure.dim();
        let plan_shape = if periodic { [ny, nx] } else { [2 * ny, 2 * nx] };
        let plan = RealFft2::new(plan_shape);
        let mut work = plan.work();
        let present: Vec<(usize, ArrayView2<f64>)> = [(0, Some(pressure)), (1, shear_x)]
            .into_iter()
            .filter_map(|(load, array)| array.map(|a| (load, a)))
            .collect();
        let mut loads = Vec::new();
        for (load, array) in &present {
            let mut spectrum = plan.new_spectrum();
            plan.forward(*array, &mut spectrum, &mut work)?;
            loads.push((*load, spectrum));
        }
        let [py, px] = plan_shape;
        let (lx, ly) = (px as f64 * spacing_m[0], py as f64 * spacing_m[1]);
        let [width, height] = plan.spectrum_shape();
        let h = layered.thickness_m;
        let waves = Array2::from_shape_fn((width, height), |(ix, iy)| {
            let (sx, sy) = (signed_index(ix, px), signed_index(iy, py));
            let nyquist =
                (px % 2 == 0 && sx == (px / 2) as i64) || (py % 2 == 0 && sy == (py / 2) as i64);
            if (sx == 0 && sy == 0) || nyquist {
                return None;
            }
            let (kx, ky) = (2.0 * PI * sx as f64 / lx, 2.0 * PI * sy as f64 / ly);
            let k = kx.hypot(ky);
            Some(([kx, ky, k], layered.wave(k * h)))
        });
        let correction = (!periodic).then(|| correction(&layered, &present, spacing_m, [lx, ly]));
        Ok(Self {
            layered,
            shape: [ny, nx],
            spacing_m,
            plan,
            loads,
            waves,
            correction,
        })
    }

    /// The coated body.
    pub fn layered(&self) -> &Layered {
        &self.layered
    }

    /// The tractions' grid `[ny, nx]`.
    pub fn shape(&self) -> [usize; 2] {
        self.shape
    }

    /// The stresses (Pa) at depth `z_m` along grid row `row` (e.g. the centre row, the plane of
    /// symmetry of a contact centred on the grid), `[component, x]` at the `nx` cell centres:
    /// each component's waves summed over `ky` with the row's phase, then one transform along
    /// `x` (no 2-D transforms: a row costs `O(nx ny)`); an isolated contact's correction
    /// summed at every cell (module doc).
    pub fn row(&self, row: usize, z_m: f64, side: Side) -> Array2<f64> {
        let nx = self.shape[1];
        let [width, height] = self.plan.spectrum_shape();
        let [py, px] = self.plan.shape();
        let mut columns = vec![[Complex::new(0.0, 0.0); 6]; width];
        for ix in 0..width {
            for iy in 0..height {
                let Some(([kx, ky, k], response)) = &self.waves[[ix, iy]] else {
                    continue;
                };
                let at = response.at(k * z_m, side, &self.layered);
                let factors = at.stress([kx / k, ky / k]);
                let angle = 2.0 * PI * (signed_index(iy, py) * row as i64) as f64 / py as f64;
                let phase = Complex::from_polar(1.0, angle);
                for (c, column) in columns[ix].iter_mut().enumerate() {
                    for (load, traction) in &self.loads {
                        let [re, im] = factors[c][*load];
                        *column += Complex::new(re, im) * traction[[ix, iy]] * phase;
                    }
                }
            }
        }
        if self.correction.is_none() {
            self.add_periodic_mean(|c, value| columns[0][c] += value);
        }
        let mut planner = realfft::RealFftPlanner::<f64>::new();
        let inverse = planner.plan_fft_inverse(px);
        let mut out = Array2::zeros((6, nx));
        let mut line = vec![0.0; px];
        for c in 0..6 {
            let mut spectrum: Vec<Complex<f64>> = columns.iter().map(|v| v[c]).collect();
            // The mean's and (zeroed) Nyquist's imaginary parts are rounding: a real grid.
            spectrum[0].im = 0.0;
            if px % 2 == 0 {
                spectrum[width - 1].im = 0.0;
            }
            if inverse.process(&mut spectrum, &mut line).is_err() {
                // Lengths are fixed above; a failure here is a bug in the layout.
                continue;
            }
            let scale = 1.0 / (px * py) as f64;
            for i in 0..nx {
                out[[c, i]] = line[i] * scale;
            }
        }
        if let Some(correction) = &self.correction {
            let x: Vec<f64> = (0..nx).map(|i| i as f64 * self.spacing_m[0]).collect();
            let y = row as f64 * self.spacing_m[1];
            let columns = self.correction_columns(correction, z_m, side, &[y]);
            out += &correction_values(correction, &columns, 1, &x).index_axis(Axis(1), 0);
        }
        out
    }

    /// The mean traction of a periodic contact: `σzz = -p̄`, `τxz = -q̄x`; `add(component,
    /// value)` adds to the mean wave of a component.
    fn add_periodic_mean(&self, mut add: impl FnMut(usize, Complex<f64>)) {
        for (load, traction) in &self.loads {
            let mean = traction[[0, 0]];
            if *load == 0 {
                add(2, -mean);
            } else {
                add(4, -mean);
            }
        }
    }

    /// The factors of an isolated contact's mean wave at depth `z` (module doc): the waves'
    /// averaged over the disk of radius `radius` (4 Gauss points in `k²`) and over 8
    /// directions (exact for the factors' trigonometric polynomials, of degree up to 4).
    fn mean_factors(&self, radius: f64, z_m: f64, side: Side) -> WaveStress {
        let h = self.layered.thickness_m;
        let (nodes, weights) = crate::thermal::special::gauss_legendre(4);
        let mut out = [[[0.0; 2]; 3]; 6];
        for (t, w) in nodes.iter().zip(&weights) {
            // u = k² / radius² on [0, 1]: the disk's area element.
            let k = radius * (0.5 * (t + 1.0)).sqrt();
            let at = self.layered.wave(k * h).at(k * z_m, side, &self.layered);
            for j in 0..8 {
                let angle = (j as f64 + 0.5) * PI / 4.0;
                let factors = at.stress([angle.cos(), angle.sin()]);
                for (o, f) in out.iter_mut().flatten().zip(factors.iter().flatten()) {
                    o[0] += w / 16.0 * f[0];
                }
            }
        }
        out
    }

    /// The correction's waves summed over `ky` at each `y` of `y_m`:
    /// `[column][y][component]`.
    fn correction_columns(
        &self,
        correction: &Correction,
        z_m: f64,
        side: Side,
        y_m: &[f64],
    ) -> Vec<Vec<[Complex<f64>; 6]>> {
        let zero = Complex::new(0.0, 0.0);
        let mut columns = vec![vec![[zero; 6]; y_m.len()]; correction.kx.len()];
        let mean = self.mean_factors(correction.mean_radius, z_m, side);
        let loads: Vec<usize> = self.loads.iter().map(|(load, _)| *load).collect();
        let mut phases = vec![zero; y_m.len()];
        for point in &correction.points {
            let factors = match &point.wave {
                Some(([kx, ky, k], response)) => response
                    .at(k * z_m, side, &self.layered)
                    .stress([kx / k, ky / k]),
                None => mean,
            };
            let mut weighted = [zero; 6];
            for (c, value) in weighted.iter_mut().enumerate() {
                for &load in &loads {
                    let [re, im] = factors[c][load];
                    *value += Complex::new(re, im) * point.tractions[load];
                }
            }
            for (phase, &y) in phases.iter_mut().zip(y_m) {
                *phase = Complex::from_polar(1.0, point.ky * y);
            }
            for (slot, phase) in columns[point.column].iter_mut().zip(&phases) {
                for (s, w) in slot.iter_mut().zip(&weighted) {
                    *s += w * phase;
                }
            }
        }
        columns
    }

    /// The stresses (Pa) at depth `z_m` at every cell centre, `[component, y, x]` with the
    /// components `[xx, yy, zz, yz, xz, xy]`; at `z = h`, those of `side`. An isolated
    /// contact's correction is summed at [`PLANE_NODES`] nodes a side and interpolated
    /// between by cubics (module doc).
    pub fn layer(&self, z_m: f64, side: Side) -> Result<Array3<f64>, TransformError> {
        let [ny, nx] = self.shape;
        let mut spectra: Vec<Array2<Complex<f64>>> =
            (0..6).map(|_| self.plan.new_spectrum()).collect();
        for ((ix, iy), wave) in self.waves.indexed_iter() {
            let Some(([kx, ky, k], response)) = wave else {
                continue;
            };
            let at = response.at(k * z_m, side, &self.layered);
            let factors = at.stress([kx / k, ky / k]);
            for (c, spectrum) in spectra.iter_mut().enumerate() {
                let mut sum = Complex::new(0.0, 0.0);
                for (load, traction) in &self.loads {
                    let [re, im] = factors[c][*load];
                    sum += Complex::new(re, im) * traction[[ix, iy]];
                }
                spectrum[[ix, iy]] = sum;
            }
        }
        if self.correction.is_none() {
            self.add_periodic_mean(|c, value| spectra[c][[0, 0]] += value);
        }
        let mut out = Array3::zeros((6, ny, nx));
        let mut work = self.plan.work();
        for (c, spectrum) in spectra.iter_mut().enumerate() {
            self.plan
                .inverse(spectrum, out.index_axis_mut(Axis(0), c), &mut work)?;
        }
        if let Some(correction) = &self.correction {
            out += &self.correction_plane(correction, z_m, side);
        }
        Ok(out)
    }

    /// The correction on the whole grid, `[component, y, x]`: summed every `stride` cells
    /// (and one stride beyond the grid each way) and interpolated between by cubic Lagrange
    /// polynomials, first along x, then along y.
    fn correction_plane(&self, correction: &Correction, z_m: f64, side: Side) -> Array3<f64> {
        let [ny, nx] = self.shape;
        let [dx, dy] = self.spacing_m;
        let (sx, sy) = (stride(nx), stride(ny));
        let nodes = |n: usize, stride: usize| -> Vec<f64> {
            if stride == 1 {
                (0..n).map(|i| i as f64).collect()
            } else {
                let count = (n - 1 + stride) / stride + 3;
                (0..count)
                    .map(|t| (t as f64 - 1.0) * stride as f64)
                    .collect()
            }
        };
        let (cx, cy) = (nodes(nx, sx), nodes(ny, sy));
        let x: Vec<f64> = cx.iter().map(|i| i * dx).collect();
        let y: Vec<f64> = cy.iter().map(|j| j * dy).collect();
        let columns = self.correction_columns(correction, z_m, side, &y);
        let values = correction_values(correction, &columns, y.len(), &x);
        let along_x = Array3::from_shape_fn((6, cy.len(), nx), |(c, j, i)| {
            interpolate(sx, i, |t| values[[c, j, t]])
        });
        Array3::from_shape_fn((6, ny, nx), |(c, j, i)| {
            interpolate(sy, j, |t| along_x[[c, t, i]])
        })
    }
}

/// The stride (cells) of [`LayeredStress::layer`]'s nodes on a side of `cells`.
fn stride(cells: usize) -> usize {
    (cells / PLANE_NODES).max(1)
}

/// The value at fine index `i` from nodes `value(t)` at `(t - 1) stride` (cubic Lagrange
/// through the four nodes around it; `stride = 1` takes the node itself).
fn interpolate(stride: usize, i: usize, value: impl Fn(usize) -> f64) -> f64 {
    if stride == 1 {
        return value(i);
    }
    let position = i as f64 / stride as f64 + 1.0;
    let first = position.floor() as usize - 1;
    let u = position - first as f64;
    let weights = [
        -(u - 1.0) * (u - 2.0) * (u - 3.0) / 6.0,
        u * (u - 2.0) * (u - 3.0) / 2.0,
        -u * (u - 1.0) * (u - 3.0) / 2.0,
        u * (u - 1.0) * (u - 2.0) / 6.0,
    ];
    weights
        .iter()
        .enumerate()
        .map(|(j, w)| w * value(first + j))
        .sum()
}

/// The real field of the correction's columns at the points `x_m` of each of `rows`:
/// `[component, row, x]`.
fn correction_values(
    correction: &Correction,
    columns: &[Vec<[Complex<f64>; 6]>],
    rows: usize,
    x_m: &[f64],
) -> Array3<f64> {
    let mut out = Array3::zeros((6, rows, x_m.len()));
    for (kx, column) in correction.kx.iter().zip(columns) {
        for (i, &x) in x_m.iter().enumerate() {
            let phase = Complex::from_polar(1.0, kx * x);
            for (r, slot) in column.iter().enumerate() {
                for (c, value) in slot.iter().enumerate() {
                    out[[c, r, i]] += (value * phase).re;
                }
            }
        }
    }
    out
}

/// The fine lattice of the correction (module doc) and the tractions' transforms there.
fn correction(
    layered: &Layered,
    loads: &[(usize, ArrayView2<f64>)],
    spacing_m: [f64; 2],
    padded_m: [f64; 2],
) -> Correction {
    let [dx, dy] = spacing_m;
    let [lx, ly] = padded_m;
    let nyquist = [loads[0].1.dim().1 as i64, loads[0].1.dim().0 as i64];
    let fine = REFINEMENT as i64;
    let f = fine as f64;
    // Lattice index m: kx = 2π m / (F Lx), so s = (2π m / (F α))² + (2π n / (F α))².
    let reach = (CUTOFF.sqrt() * SPLIT * f / (2.0 * PI)).floor() as i64;
    let kx: Vec<f64> = (0..=reach)
        .map(|m| 2.0 * PI * m as f64 / (f * lx))
        .collect();
    let ky: Vec<f64> = (-reach..=reach)
        .map(|n| 2.0 * PI * n as f64 / (f * ly))
        .collect();
    // dkx dky / 4π² times the cell area (P(k) = dx dy Σ p e^(-ik·x)).
    let weight = dx * dy / (f * f * lx * ly);
    let inside = |m: i64, n: i64| {
        let s = (2.0 * PI / (f * SPLIT)).powi(2) * (m * m + n * n) as f64;
        (s <= CUTOFF).then(|| (1.0 + s) * (-s).exp())
    };
    // Each load's transform along x for every row, then along y at each lattice point.
    let transforms: Vec<(usize, Array2<Complex<f64>>)> = loads
        .iter()
        .map(|(load, array)| {
            let (rows, cells) = array.dim();
            let mut along_x = Array2::from_elem((kx.len(), rows), Complex::new(0.0, 0.0));
            for (m, k) in kx.iter().enumerate() {
                let twiddles: Vec<Complex<f64>> = (0..cells)
                    .map(|i| Complex::from_polar(1.0, -k * i as f64 * dx))
                    .collect();
                for (j, row) in array.outer_iter().enumerate() {
                    along_x[[m, j]] = row.iter().zip(&twiddles).map(|(p, t)| t * p).sum();
                }
            }
            let mut both = Array2::from_elem((kx.len(), ky.len()), Complex::new(0.0, 0.0));
            for (n, k) in ky.iter().enumerate() {
                let twiddles: Vec<Complex<f64>> = (0..rows)
                    .map(|j| Complex::from_polar(1.0, -k * j as f64 * dy))
                    .collect();
                for m in 0..kx.len() {
                    if inside(m as i64, n as i64 - reach).is_some() {
                        both[[m, n]] = along_x
                            .row(m)
                            .iter()
                            .zip(&twiddles)
                            .map(|(a, t)| a * t)
                            .sum();
                    }
                }
            }
            (*load, both)
        })
        .collect();
    let h = layered.thickness_m;
    let mut points = Vec::new();
    for (m, &kx_m) in kx.iter().enumerate() {
        for (n, &ky_n) in ky.iter().enumerate() {
            let (mi, ni) = (m as i64, n as i64 - reach);
            let Some(w) = inside(mi, ni) else {
                continue;
            };
            // The padded grid's own points are subtracted from the fine lattice's sum (but for
            // the mean and the Nyquist waves, which the padded grid leaves out).
            let padded = mi % fine == 0
                && ni % fine == 0
                && (mi, ni) != (0, 0)
                && mi / fine != nyquist[0]
                && ni.abs() / fine != nyquist[1];
            let share = if padded { 1.0 - f * f } else { 1.0 };
            let factor = weight * w * share * if m == 0 { 1.0 } else { 2.0 };
            let mut tractions = [Complex::new(0.0, 0.0); 2];
            for (load, transform) in &transforms {
                tractions[*load] = transform[[m, n]] * factor;
            }
            let k = kx_m.hypot(ky_n);
            let wave = (k > 0.0).then(|| ([kx_m, ky_n, k], layered.wave(k * h)));
            points.push(LowPoint {
                column: m,
                wave,
                ky: ky_n,
                tractions,
            });
        }
    }
    let cell = (2.0 * PI / (f * lx)) * (2.0 * PI / (f * ly));
    Correction {
        kx,
        points,
        mean_radius: (cell / PI).sqrt(),
    }
}

/// A surface stress at the edges of a contact along a row of cells, where its peak lies
/// between the cells: `x_m` the cell centres (uniform spacing), `pressure` the row's
/// pressure, `values` the stress at the centres. At each edge (a loaded cell next to an
/// unloaded one) returns `(x, value)`: the edge placed where the square of the pressure,
/// extended linearly from the last two loaded cells, reaches 0 (a pressure falling as
/// `√(a - r)`, as Hertz's and every smooth elastic contact's does at its edge (Johnson 1985,
/// §3.4 and §4.1: the pressure of a contact of non-conforming smooth bodies); kept between the
/// last loaded centre and the first unloaded one), and the stress there extrapolated by the
/// parabola through the first three unloaded centres. Outside the contact the surface is
/// free and the stress smooth; inside it falls off as `√(a - r)` (a kink at the edge that
/// no sampling resolves), so the edge's value is its limit from outside. (Beyond the trailing
/// edge of a sliding line contact the friction's part rises as `√` to the edge, McEwen's
/// `2μp0 (|x|/b - √(x²/b² - 1))` (Johnson 1985, §7.1): the parabola stays 1.6 % below
/// `2μp0` at 200 strips on the contact; a fit with that `√` term overshot by 13 %, the
/// samples' noise amplified.)
pub fn surface_edge_values(x_m: &[f64], pressure: &[f64], values: &[f64]) -> Vec<(f64, f64)> {
    let n = x_m.len().min(pressure.len()).min(values.len());
    if n < 2 {
        return Vec::new();
    }
    let dx = x_m[1] - x_m[0];
    let mut out = Vec::new();
    // `dir` +1: the loaded cell `i`, the free cells `i + 1, i + 2, i + 3`; -1 mirrored.
    for i in 0..n {
        for dir in [1i64, -1] {
            let at = |k: i64| -> Option<usize> {
                let j = i as i64 + dir * k;
                (0..n as i64).contains(&j).then_some(j as usize)
            };
            let (Some(free0), Some(free1), Some(free2)) = (at(1), at(2), at(3)) else {
                continue;
            };
            if pressure[i] <= 0.0 || pressure[free0] > 0.0 {
                continue;
            }
            if pressure[free1] > 0.0 || pressure[free2] > 0.0 {
                continue;
            }
            let beyond = match at(-1) {
                Some(inner) if pressure[inner] > pressure[i] => {
                    let (p0, p1) = (pressure[i].powi(2), pressure[inner].powi(2));
                    (p0 / (p1 - p0)).clamp(0.0, 1.0)
                }
                _ => 0.5,
            };
            // The edge at `t` cells before the first free centre (0 < t <= 1); the parabola
            // through the free centres at 0, 1, 2 evaluated at -t.
            let t = 1.0 - beyond;
            let [f0, f1, f2] = [values[free0], values[free1], values[free2]];
            let value =
                f0 * (1.0 + t) * (2.0 + t) / 2.0 - f1 * t * (2.0 + t) + f2 * t * (1.0 + t) / 2.0;
            out.push((x_m[i] + dir as f64 * beyond * dx.abs(), value));
        }
    }
    out
}
