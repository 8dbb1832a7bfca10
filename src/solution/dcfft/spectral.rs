//! Periodic tractions in Fourier space: the stress of each wave of the tractions at depth `z`
//! in closed form, so that a layer needs no influence coefficients, no periodic images and no
//! zero padding, only the six inverse transforms of the grid's own size.
//!
//! ## The stress of one wave
//! A traction wave `(p, qx, qy) exp(i k·x)` on the surface of a half-space (`k = |k| > 0`,
//! `n = k / k`, `t = (-n_y, n_x)`) is a plane-strain problem in the plane of `n` and `z`
//! (the pressure `p` and the shear along the wave, `q_s = n·q`) plus an anti-plane one (the
//! shear across it, `q_t = t·q`). With the Airy function `φ = (A + B z) e^(-kz) e^(iks)` of the
//! plane problem (`σss = ∂²φ/∂z²`, `σzz = ∂²φ/∂s²`, `σsz = -∂²φ/∂s∂z`), the surface conditions
//! `σzz = -p`, `σsz = -q_s` give, with `E = e^(-kz)`:
//!
//! ```text
//! σzz = -[p (1 + kz) - i q_s kz] E        σss = [-p (1 - kz) + i q_s (2 - kz)] E
//! σsz = [-q_s (1 - kz) + i p kz] E        σtt = ν (σss + σzz) = 2ν (-p + i q_s) E
//! σtz = -q_t E                            σst = i q_t E
//! ```
//!
//! (Johnson 1985, §2.8, for the plane problem's pressure wave `σxx = -p (1 - kz) E`,
//! `σzz = -p (1 + kz) E`; the anti-plane displacement `u_t ∝ E e^(iks)` is harmonic.) The
//! components in x and y follow by rotating the in-plane tensor from `(n, t)` to `(x, y)`.
//! Frérot, Bonnet, Anciaux & Molinari (2019) give the same half-space operator in Fourier
//! space for Tamaas's volume integrals.
//!
//! ## Cells of uniform traction
//! The grid's tractions are uniform over each cell, so each grid wavenumber `k` carries its
//! aliases `k + 2π (m / dx, n / dy)`, weighted by the cells' form factor
//! `sinc(kx dx / 2) sinc(ky dy / 2)`. At the cell centres the aliases add to the grid
//! wave's coefficient (their phases there cancel the cells' own), so the exact stress of the
//! cells at the centres of a layer is one inverse transform of
//! `T(k, z) = Σ_(m,n) sinc · σ̂(k_mn, z)` times the tractions' discrete transform. The aliases
//! decay as `exp(-|k_mn| z)` and their form factors as `1/m`: an alias whose form factor
//! times `exp(-|k_mn| z)` is below `e^3` times a relative [`ALIAS_TOLERANCE`] (the `e^3`
//! covering the factors `1 + kz` and `2 - kz` of the stresses) is left out, since
//! `|k_mn| z > ln(1 / tol) + 3 + ln |sinc_x| + ln |sinc_y|`; every alias beyond
//! `(2M + 1) π z / d >= ln(1 / tol) + 3` is, which needs `M <= 7` from half a cell down
//! ([`MIN_DEPTH_CELLS`]); shallower layers are computed from the cells' influence
//! coefficients instead ([`super::DcFft`]). For the Nyquist wavenumbers of an even grid the
//! set of aliases is taken symmetric (`m = -M - 1 ..= M`), so that their transforms stay real.
//!
//! ## Symmetries of the sums
//! Only the wavenumbers `kx >= 0` are stored (the real transform's half spectrum), and only the
//! rows `ky >= 0` are summed: those of `-ky` follow by the parity in y. On a square grid of
//! square cells under pressure alone, the kernel of `(kx, ky)` with `ky < kx` is that of
//! `(ky, kx)` turned about the plane `x = y` (σxx and σyy exchanged, τxz and τyz), so only the
//! sums with `kx <= ky` are formed: the same terms in another order, equal to rounding. An alias
//! column along x whose factor alone is beyond the reach is skipped whole.
//!
//! ## The mean traction
//! As for the cell-based layers (module doc of [`super`]): the mean traction stresses the
//! half-space uniformly, `σzz = -p̄`, `τxz = -q̄x`, `τyz = -q̄y`.
//!
//! ## References
//! - K. L. Johnson, *Contact Mechanics*, Cambridge University Press (1985), §2.8.
//! - L. Frérot, M. Bonnet, G. Anciaux, J.-F. Molinari, A Fourier-accelerated volume integral
//!   method for elastoplastic contact, *Comput. Methods Appl. Mech. Engrg.* 351 (2019) 951–976.

use std::f64::consts::PI;

use ndarray::{Array2, ArrayViewMut3, Axis};
use rustfft::num_complex::Complex;

use super::{DcFftError, Load, TractionGrid};
use crate::operator::transform::{signed_index, Fft2Work, RealFft2};

/// The largest neglected alias, relative to the tractions.
pub const ALIAS_TOLERANCE: f64 = 1e-8;

/// Layers at least this many cells deep (the smaller cell side) are computed spectrally: from
/// half a cell down the alias sums cost less than the cell-based layer's window of images
/// (measured on 512², one thread: 0.2 s at half a cell, 0.05 s at one cell, 0.23 s for any
/// cell-based layer), and shallower they cost more (0.66 s at a quarter of a cell).
pub const MIN_DEPTH_CELLS: f64 = 0.5;

/// The spectral layers of one period of tractions.
pub struct SpectralLayers {
    shape: [usize; 2],
    cell: [f64; 2],
    poisson: f64,
    plan: RealFft2,
    /// The transforms of the loads present, less their mean, `[kx, ky]`.
    loads: Vec<(Load, Array2<Complex<f64>>)>,
    /// The mean tractions `[p̄, q̄x, q̄y]`.
    mean: [f64; 3],
}

/// The working memory of one spectral layer: the six components' spectra (`96 (nx/2 + 1) ny`
/// bytes) and the transform's scratch.
pub struct SpectralWork {
    spectra: Vec<Array2<Complex<f64>>>,
    fft: Fft2Work,
}

impl SpectralLayers {
    /// Transforms the tractions of `grid`, one period.
    pub fn new(grid: &TractionGrid, poisson: f64) -> Result<Self, DcFftError> {
        // Layers run in parallel over depths, each on one thread.
        let plan = RealFft2::sequential(grid.shape);
        let mean = grid.mean_tractions();
        let mut work = plan.work();
        let mut loads = Vec::new();
        for (load, array) in grid.loads() {
            let shift = mean[load as usize];
            let centred = array.mapv(|t| t - shift);
            let mut spectrum = plan.new_spectrum();
            plan.forward(centred.view(), &mut spectrum, &mut work)?;
            loads.push((load, spectrum));
        }
        Ok(Self {
            shape: grid.shape,
            cell: grid.cell,
            poisson,
            plan,
            loads,
            mean,
        })
    }

    /// Whether depth `z` is computed here (at least [`MIN_DEPTH_CELLS`] of a cell deep).
    pub fn takes(&self, z: f64) -> bool {
        z >= MIN_DEPTH_CELLS * self.cell[0].min(self.cell[1])
    }

    /// Fresh working memory for [`SpectralLayers::layer_into`].
    pub fn work(&self) -> SpectralWork {
        SpectralWork {
            spectra: (0..6).map(|_| self.plan.new_spectrum()).collect(),
            fft: self.plan.work(),
        }
    }

    /// The aliases of each axis taken at depth `z`: `M` with `(2M + 1) π z / d` at least
    /// `ln(1 / tol) + 3` (module doc).
    fn aliases(&self, z: f64) -> [i64; 2] {
        let reach = (1.0 / ALIAS_TOLERANCE).ln() + 3.0;
        self.cell.map(|d| {
            let m = ((reach * d / (PI * z) - 1.0) / 2.0).ceil();
            m.clamp(0.0, 64.0) as i64
        })
    }

    /// The stresses at depth `z` (see [`SpectralLayers::takes`]) at every cell centre,
    /// `[component, y, x]`, components in the order of [`super::COMPONENTS`].
    ///
    /// # Panics
    /// If `out` is not `[6, ny, nx]`.
    pub fn layer_into(
        &self,
        z: f64,
        work: &mut SpectralWork,
        mut out: ArrayViewMut3<f64>,
    ) -> Result<(), DcFftError> {
        let [ny, nx] = self.shape;
        assert_eq!(out.shape(), [6, ny, nx], "layer output must be [6, ny, nx]");
        let [dx, dy] = self.cell;
        let [mx, my] = self.aliases(z);
        let (period_x, period_y) = (nx as f64 * dx, ny as f64 * dy);
        let nu = self.poisson;
        let zero = Complex::new(0.0, 0.0);
        // The loads present, each with its transform and the kernel of a unit load of its
        // kind ([`unit_kernel`]).
        let loads: Vec<(Load, &Array2<Complex<f64>>)> =
            self.loads.iter().map(|(load, s)| (*load, s)).collect();
        // Aliases whose decay exp(-|k| z) is below the tolerance are left out.
        let reach = (1.0 / ALIAS_TOLERANCE).ln() + 3.0;
        let [width, height] = self.plan.spectrum_shape();
        // Each axis's aliases of each wavenumber index, with their form factors and the
        // factors' logarithms: (k, sinc, ln |sinc|).
        let aliases = |count: usize, n: usize, period: f64, d: f64, m_max: i64| {
            (0..count)
                .map(|index| {
                    let s = signed_index(index, n);
                    let k = 2.0 * PI * s as f64 / period;
                    alias_range(s, n, m_max)
                        .map(|m| {
                            let km = k + 2.0 * PI * m as f64 / d;
                            let form = sinc(0.5 * km * d);
                            (km, form, form.abs().ln())
                        })
                        .collect::<Vec<(f64, f64, f64)>>()
                })
                .collect::<Vec<_>>()
        };
        let along_x = aliases(width, nx, period_x, dx, mx);
        let along_y = aliases(height, ny, period_y, dy, my);
        let z_squared = z * z;
        let (limit_x, limit_y) = (PI / dx, PI / dy);
        // The alias sums of the unit kernels, per load present: [load][component].
        let mut kernels = vec![[0.0; 6]; loads.len()];
        let pressure_only = matches!(loads.as_slice(), [(Load::Pressure, _)]);
        // On a square grid of square cells the aliases along x and y are the same sets, so
        // the pressure's kernel above the diagonal (kx < ky, both >= 0) is kept for the
        // wavenumbers below it.
        let mut turn =
            (pressure_only && nx == ny && dx == dy).then(|| vec![[0.0; 6]; width * width]);
        for (ix, x_aliases) in along_x.iter().enumerate() {
            // Only the rows of ky >= 0 are summed; those of -ky are their mirror images
            // (`mirror_index`), whose kernels differ by the parity in y ([`y_parity`]).
            for iy in (0..height).filter(|&iy| signed_index(iy, ny) >= 0) {
                for kernel in kernels.iter_mut() {
                    *kernel = [0.0; 6];
                }
                // A square grid's pressure: the kernel of (kx, ky) below the diagonal is that
                // of (ky, kx), computed before, turned ([`turned_pressure_kernel`]).
                let turned = turn
                    .as_ref()
                    .filter(|_| iy < ix)
                    .map(|kept| kept[iy * width + ix]);
                if let (Some(kernel), [only]) = (turned, kernels.as_mut_slice()) {
                    *only = turned_pressure_kernel(kernel);
                } else if ix != 0 || iy != 0 {
                    for &(kx, form_x, log_x) in x_aliases {
                        let own_x = kx.abs() <= limit_x;
                        // An alias along x beyond the reach by itself leaves out every alias
                        // of its column (|k| >= |kx| and ln |sinc_y| <= 0): skipped whole,
                        // the same terms as tested one by one below.
                        let reach_x = reach + log_x;
                        let kx_squared = kx * kx;
                        if !own_x && (reach_x <= 0.0 || kx_squared * z_squared > reach_x * reach_x)
                        {
                            continue;
                        }
                        for &(ky, form_y, log_y) in &along_y[iy] {
                            let k_squared = kx_squared + ky * ky;
                            // The grid's own wavenumber always counts; an alias only where
                            // its form factor times exp(-|k| z) can reach the tolerance.
                            let own = own_x && ky.abs() <= limit_y;
                            let alias_reach = reach_x + log_y;
                            if !own
                                && (alias_reach <= 0.0
                                    || k_squared * z_squared > alias_reach * alias_reach)
                            {
                                continue;
                            }
                            let form = form_x * form_y;
                            if let [kernel] = kernels.as_mut_slice() {
                                if pressure_only {
                                    // The common case (no friction), with the load known.
                                    let unit = unit_kernel(
                                        Load::Pressure,
                                        [kx, ky],
                                        k_squared.sqrt(),
                                        z,
                                        nu,
                                    );
                                    for (total, value) in kernel.iter_mut().zip(unit) {
                                        *total += form * value;
                                    }
                                    continue;
                                }
                            }
                            for ((load, _), kernel) in loads.iter().zip(kernels.iter_mut()) {
                                let unit = unit_kernel(*load, [kx, ky], k_squared.sqrt(), z, nu);
                                for (total, value) in kernel.iter_mut().zip(unit) {
                                    *total += form * value;
                                }
                            }
                        }
                    }
                }
                if let (Some(kept), [only]) = (turn.as_mut(), kernels.as_slice()) {
                    if ix < iy {
                        kept[ix * width + iy] = *only;
                    }
                }
                let mirror = mirror_index(iy, ny);
                for (target, parity) in [(Some(iy), false), (mirror, true)] {
                    let Some(target) = target else { continue };
                    let mut sum = [zero; 6];
                    for ((load, spectrum), kernel) in loads.iter().zip(&kernels) {
                        let traction = spectrum[[ix, target]];
                        for (c, total) in sum.iter_mut().enumerate() {
                            let mut value = kernel[c];
                            if parity && y_parity(*load, c) < 0.0 {
                                value = -value;
                            }
                            *total += if imaginary(*load, c) {
                                Complex::new(0.0, value) * traction
                            } else {
                                traction * value
                            };
                        }
                    }
                    for (spectrum, value) in work.spectra.iter_mut().zip(sum) {
                        spectrum[[ix, target]] = value;
                    }
                }
            }
        }
        for (c, spectrum) in work.spectra.iter_mut().enumerate() {
            self.plan
                .inverse(spectrum, out.index_axis_mut(Axis(0), c), &mut work.fft)?;
        }
        // The uniform state of the mean traction.
        let [p, qx, qy] = self.mean;
        for (c, shift) in [(2, -p), (3, -qy), (4, -qx)] {
            if shift != 0.0 {
                out.index_axis_mut(Axis(0), c).mapv_inplace(|s| s + shift);
            }
        }
        Ok(())
    }
}

/// The aliases `m` of signed wavenumber index `s` on `n` samples, up to `m_max` each side:
/// none along an axis whose wavenumber is zero (their form factor `sinc(π m)` vanishes), and
/// a set symmetric about zero for the Nyquist wavenumber of an even grid (module doc).
fn alias_range(s: i64, n: usize, m_max: i64) -> std::ops::RangeInclusive<i64> {
    if s == 0 {
        0..=0
    } else if n.is_multiple_of(2) && s == (n / 2) as i64 {
        -m_max - 1..=m_max
    } else {
        -m_max..=m_max
    }
}

/// The row of wavenumber `-ky` for the row `iy` of `ky > 0` (`signed_index(iy) > 0`), on `n`
/// rows; `None` for `ky = 0` and the Nyquist row of an even grid, which are their own mirror
/// images (the Nyquist row's aliases are taken symmetric, [`alias_range`]).
fn mirror_index(iy: usize, n: usize) -> Option<usize> {
    let s = signed_index(iy, n);
    (s > 0 && !(n.is_multiple_of(2) && s == (n / 2) as i64)).then(|| n - iy)
}

/// The parity of component `c` (order of [`super::COMPONENTS`]) of the stress of load `load`
/// under the reflection `y -> -y`: the stress components change sign with the number of
/// their indices that are `y` (`yz`, `xy`), and a shear `qy` reverses with the reflection.
fn y_parity(load: Load, c: usize) -> f64 {
    let component = if matches!(c, 3 | 5) { -1.0 } else { 1.0 };
    let traction = if load == Load::ShearY { -1.0 } else { 1.0 };
    component * traction
}

/// Whether component `c` of the stress of a unit wave of `load` is imaginary (`i` times the
/// real value of [`unit_kernel`]); otherwise it is real. A pressure wave's normal stresses
/// and `τxy` are in phase with it and its `τyz`, `τxz` a quarter period off; a shear wave's
/// the other way round (module doc).
fn imaginary(load: Load, c: usize) -> bool {
    (load == Load::Pressure) == matches!(c, 3 | 4)
}

/// The stress at depth `z` of a unit traction wave `exp(i k·x)` of kind `load` (`k ≠ 0` of
/// length `magnitude`), each component's real amplitude: the stress is that amplitude, times
/// `i` where [`imaginary`] says so. The formulas of the module doc with `p = 1` or
/// `q_s = n·e_q`, `q_t = t·e_q` for the unit shear along `e_q`, rotated to x and y; written
/// out in real arithmetic, since this runs once per alias and wavenumber (inlined, so that a
/// call with a constant `load` keeps only its branch).
#[inline(always)]
fn unit_kernel(load: Load, k: [f64; 2], magnitude: f64, z: f64, nu: f64) -> [f64; 6] {
    let n = [k[0] / magnitude, k[1] / magnitude];
    let kz = magnitude * z;
    let e = (-kz).exp();
    if load == Load::Pressure {
        // Real amplitudes of σss, σtt, σzz (σst = σtz = 0); imaginary one of σsz.
        return rotated(
            n,
            -(1.0 - kz) * e,
            -2.0 * nu * e,
            0.0,
            -(1.0 + kz) * e,
            kz * e,
            0.0,
        );
    }
    let (q_s, q_t) = if load == Load::ShearX {
        (n[0], -n[1])
    } else {
        (n[1], n[0])
    };
    // Imaginary amplitudes of σss, σtt, σst, σzz; real ones of σsz, σtz.
    rotated(
        n,
        q_s * (2.0 - kz) * e,
        2.0 * nu * q_s * e,
        q_t * e,
        q_s * kz * e,
        -q_s * (1.0 - kz) * e,
        -q_t * e,
    )
}

/// The components in x and y (order of [`super::COMPONENTS`]) of a wave's stress given in the
/// frame of its direction `n` (`s` along it, `t = (-n_y, n_x)` across it): the in-plane tensor
/// rotated from `(n, t)` to `(x, y)`.
fn rotated(n: [f64; 2], ss: f64, tt: f64, st: f64, zz: f64, sz: f64, tz: f64) -> [f64; 6] {
    let [nx, ny] = n;
    [
        nx * nx * ss + ny * ny * tt - 2.0 * nx * ny * st,
        ny * ny * ss + nx * nx * tt + 2.0 * nx * ny * st,
        zz,
        ny * sz + nx * tz,
        nx * sz - ny * tz,
        nx * ny * (ss - tt) + (nx * nx - ny * ny) * st,
    ]
}

/// The pressure kernel of the wavevector `(ky, kx)` from that of `(kx, ky)`: the half-space
/// turned about the plane `x = y` exchanges x and y, so `σxx` and `σyy` exchange, and `τyz`
/// and `τxz`; `σzz` and `τxy` stay ([`unit_kernel`] with `n` turned: its in-plane stresses
/// depend on `n` through `n_x²`, `n_y²` and `n_x n_y`, its shears `τyz = n_y σsz` and `τxz =
/// n_x σsz`; the aliases' form factors are a product of the two axes' and so symmetric). The
/// sums of the two kernels run over the same terms in another order, so they agree to
/// rounding.
fn turned_pressure_kernel(kernel: [f64; 6]) -> [f64; 6] {
    [
        kernel[1], kernel[0], kernel[2], kernel[4], kernel[3], kernel[5],
    ]
}

/// `sin(u) / u`.
fn sinc(u: f64) -> f64 {
    if u.abs() < 1e-8 {
        1.0 - u * u / 6.0
    } else {
        u.sin() / u
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The stress at depth `z` of the traction wave `(p, qx, qy) exp(i k·x)` of wavevector
    /// `k ≠ 0` of length `magnitude` in the complex formulas of the module doc, its components
    /// in the order of [`super::COMPONENTS`]: the reference of [`unit_kernel`].
    fn wave_stress(
        k: [f64; 2],
        magnitude: f64,
        z: f64,
        nu: f64,
        p: Complex<f64>,
        qx: Complex<f64>,
        qy: Complex<f64>,
    ) -> [Complex<f64>; 6] {
        let (nx, ny) = (k[0] / magnitude, k[1] / magnitude);
        let kz = magnitude * z;
        let e = (-kz).exp();
        let i = Complex::new(0.0, 1.0);
        let q_s = nx * qx + ny * qy;
        let q_t = -ny * qx + nx * qy;
        let zz = -(p * (1.0 + kz) - i * q_s * kz) * e;
        let sz = (-q_s * (1.0 - kz) + i * p * kz) * e;
        let tz = -q_t * e;
        let ss = (-p * (1.0 - kz) + i * q_s * (2.0 - kz)) * e;
        let tt = 2.0 * nu * (-p + i * q_s) * e;
        let st = i * q_t * e;
        [
            nx * nx * ss + ny * ny * tt - 2.0 * nx * ny * st,
            ny * ny * ss + nx * nx * tt + 2.0 * nx * ny * st,
            zz,
            ny * sz + nx * tz,
            nx * sz - ny * tz,
            nx * ny * (ss - tt) + (nx * nx - ny * ny) * st,
        ]
    }

    #[test]
    fn unit_kernels_are_the_waves_stresses() {
        // The real-arithmetic kernels against the complex formulas of the module doc, for
        // each load alone, at wavevectors of every direction and at several depths; and the
        // parity in y against the wave of the reflected wavevector.
        let nu = 0.27;
        let one = Complex::new(1.0, 0.0);
        let none = Complex::new(0.0, 0.0);
        for (load, [p, qx, qy]) in [
            (Load::Pressure, [one, none, none]),
            (Load::ShearX, [none, one, none]),
            (Load::ShearY, [none, none, one]),
        ] {
            for k in [
                [1.0, 0.0],
                [0.3, -2.0],
                [-1.7, 0.4],
                [0.0, 3.0],
                [-2.0, -2.5],
            ] {
                let magnitude: f64 = f64::hypot(k[0], k[1]);
                for z in [0.0, 0.1, 0.8, 2.5] {
                    let wave = wave_stress(k, magnitude, z, nu, p, qx, qy);
                    let unit = unit_kernel(load, k, magnitude, z, nu);
                    let mirrored = unit_kernel(load, [k[0], -k[1]], magnitude, z, nu);
                    for c in 0..6 {
                        let expected = if imaginary(load, c) {
                            Complex::new(0.0, unit[c])
                        } else {
                            Complex::new(unit[c], 0.0)
                        };
                        assert!(
                            (wave[c] - expected).norm() <= 1e-14,
                            "{load:?}, k = {k:?}, z = {z}, c = {c}: {} vs {expected}",
                            wave[c]
                        );
                        assert!(
                            (mirrored[c] - y_parity(load, c) * unit[c]).abs() <= 1e-14,
                            "{load:?}, k = {k:?}, z = {z}, c = {c}: parity"
                        );
                    }
                }
            }
        }
    }

    #[test]
    fn the_turned_pressure_kernel_is_that_of_the_exchanged_wavevector() {
        for k in [[1.0, 0.0], [0.3, 2.0], [-1.7, 0.4], [2.0, -2.5]] {
            let magnitude: f64 = f64::hypot(k[0], k[1]);
            for z in [0.0, 0.1, 0.8, 2.5] {
                let turned =
                    turned_pressure_kernel(unit_kernel(Load::Pressure, k, magnitude, z, 0.3));
                let direct = unit_kernel(Load::Pressure, [k[1], k[0]], magnitude, z, 0.3);
                for c in 0..6 {
                    assert!(
                        (turned[c] - direct[c]).abs() <= 1e-15,
                        "k = {k:?}, z = {z}, c = {c}: {} vs {}",
                        turned[c],
                        direct[c]
                    );
                }
            }
        }
    }

    #[test]
    fn mirror_rows_pair_the_signed_wavenumbers() {
        assert_eq!(
            (0..6).map(|i| mirror_index(i, 6)).collect::<Vec<_>>(),
            [None, Some(5), Some(4), None, None, None]
        );
        assert_eq!(
            (0..5).map(|i| mirror_index(i, 5)).collect::<Vec<_>>(),
            [None, Some(4), Some(3), None, None]
        );
    }
}
