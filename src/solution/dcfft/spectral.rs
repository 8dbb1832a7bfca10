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
//! decay as `exp(-|k_mn| z)`: below a relative [`ALIAS_TOLERANCE`] those beyond
//! `(2M + 1) π z / d >= ln(1 / tol) + 3` are left out, which needs `M <= 3` from one cell
//! down ([`MIN_DEPTH_CELLS`]); shallower layers are computed from the cells' influence
//! coefficients instead ([`super::DcFft`]). For the Nyquist wavenumbers of an even grid the
//! set of aliases is taken symmetric (`m = -M - 1 ..= M`), so that their transforms stay real.
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

/// Layers at least this many cells deep (the smaller cell side) are computed spectrally.
pub const MIN_DEPTH_CELLS: f64 = 1.0;

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
        let pressure = self.loads.iter().find(|(l, _)| *l == Load::Pressure);
        let shear_x = self.loads.iter().find(|(l, _)| *l == Load::ShearX);
        let shear_y = self.loads.iter().find(|(l, _)| *l == Load::ShearY);
        let zero = Complex::new(0.0, 0.0);
        // Aliases whose decay exp(-|k| z) is below the tolerance are left out.
        let reach = (1.0 / ALIAS_TOLERANCE).ln() + 3.0;
        let [width, height] = self.plan.spectrum_shape();
        // Each axis's aliases of each wavenumber index, with their form factors: (k, sinc).
        let aliases = |count: usize, n: usize, period: f64, d: f64, m_max: i64| {
            (0..count)
                .map(|index| {
                    let s = signed_index(index, n);
                    let k = 2.0 * PI * s as f64 / period;
                    alias_range(s, n, m_max)
                        .map(|m| {
                            let km = k + 2.0 * PI * m as f64 / d;
                            (km, sinc(0.5 * km * d))
                        })
                        .collect::<Vec<(f64, f64)>>()
                })
                .collect::<Vec<_>>()
        };
        let along_x = aliases(width, nx, period_x, dx, mx);
        let along_y = aliases(height, ny, period_y, dy, my);
        let (reach_squared, z_squared) = (reach * reach, z * z);
        for (ix, x_aliases) in along_x.iter().enumerate() {
            for (iy, y_aliases) in along_y.iter().enumerate() {
                let load = |entry: Option<&(Load, Array2<Complex<f64>>)>| {
                    entry.map_or(zero, |(_, s)| s[[ix, iy]])
                };
                let (p, qx, qy) = (load(pressure), load(shear_x), load(shear_y));
                let mut sum = [zero; 6];
                if ix != 0 || iy != 0 {
                    for &(kx, form_x) in x_aliases {
                        for &(ky, form_y) in y_aliases {
                            let k_squared = kx * kx + ky * ky;
                            // The grid's own wavenumber always counts.
                            let own = kx.abs() <= PI / dx && ky.abs() <= PI / dy;
                            if !own && k_squared * z_squared > reach_squared {
                                continue;
                            }
                            let wave = wave_stress([kx, ky], k_squared.sqrt(), z, nu, p, qx, qy);
                            let form = form_x * form_y;
                            for (total, value) in sum.iter_mut().zip(wave) {
                                *total += form * value;
                            }
                        }
                    }
                }
                for (spectrum, value) in work.spectra.iter_mut().zip(sum) {
                    spectrum[[ix, iy]] = value;
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

/// `sin(u) / u`.
fn sinc(u: f64) -> f64 {
    if u.abs() < 1e-8 {
        1.0 - u * u / 6.0
    } else {
        u.sin() / u
    }
}

/// The stress at depth `z` of the traction wave `(p, qx, qy) exp(i k·x)` of wavevector
/// `k ≠ 0` of length `magnitude` (module doc), its components in the order of
/// [`super::COMPONENTS`].
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
