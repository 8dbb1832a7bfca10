//! Thermal distortion: the normal displacement of the surface of a half-space heated by a flux
//! moving over it (quasi-static thermoelasticity, free surface), as influence coefficients of
//! uniformly heated cells.
//!
//! ## Frequency-response function
//! With the transform and `γ` of [`super::stress`] (`γ² = k² - i V ξ / κ`), the outward normal
//! displacement of the surface (towards the counter-surface, the sign of the heights) per unit
//! flux is
//!
//! ```text
//! ŵ = 2 (1 + ν) α q̂ / (K γ (γ + k))
//! ```
//!
//! (Liu & Wang 2001). It is Barber's volume integral `w = ((1 + ν) α / π) ∫ T z' / ρ³ dV`
//! written in the transform: `T̂ = q̂ e^(-γz) / (K γ)` times the Poisson kernel `e^(-kz)`,
//! integrated over depth, gives `1 / (K γ (γ + k))`. A test derives the same function
//! independently as `∫ ε_zz dz` from the stresses of [`super::stress::response`] and Hooke's law.
//! For a stationary source (`γ = k`) it is `(1 + ν) α q̂ / (K k²)`, the logarithmic potential
//! `w = -(1 + ν) α Q ln r / (2π K)` of a point source (Barber 1969), defined up to a constant: a
//! stationary heated half-space has no steady far field. A uniform disc of flux `q` then bulges
//! by `w(0) - w(a) = (1 + ν) α q a² / (4 K)` (Barber 1969), a Hertzian flux `q0 √(1 - r²/a²)` by
//! `(1 + ν) α q0 a² (4/3 - ln 2) / (3 K)` (the same Poisson equation integrated; both are tests).
//! A moving source has a finite far field: ahead of it the surface is at rest, behind it the
//! heated wake stays raised.
//!
//! ## Influence coefficients
//! The displacement at offset `(x, y)` from a cell of unit flux is the inverse transform of
//! `H S`, `S = dx dy sinc(ξ dx/2) sinc(η dy/2)`, `H = ŵ / ((1 + ν) α / K)`. With the window
//! `W = exp(-k²/kw²)` (`kw` of [`super::stress`]) and `H_s = 1/k²`:
//! - `(1 - W) H_s`: its inverse transform is `E1(kw² r² / 4) / (4π)` exactly; taken as the cell
//!   integral of `-ln r / (2π)` in closed form (corner sums of
//!   `L = [x y (ln(x² + y²) - 3) + x² atan(y/x) + y² atan(x/y)] / 2`, the antiderivative of
//!   `ln r`) minus the cell integral (4 x 4 Gauss points) of the smooth rest
//!   `(-ln r - E1(kw² r²/4)/2) / (2π)`;
//! - `W H`, integrable at `k = 0` for a moving source (its `1/k²` survives only in a cusp
//!   `|ξ| < k² κ / V` about the η axis), by the graded band rule of [`super::stress`];
//! - `(1 - W)(H - H_s)`, sampled on the oversampled periodic lattice with 3 aliases each way.
//!
//! A stationary source (`V = 0`) takes the closed-form log part alone: its constant is then
//! arbitrary, and only differences of the displacement (what a contact under a given load
//! feels) have a meaning.
//!
//! ## References
//! - S. Liu, Q. Wang, A three-dimensional thermomechanical model of contact between
//!   non-conforming rough surfaces, *ASME J. Tribol.* 123 (2001) 17–26.
//! - J. R. Barber, Thermoelastic displacements and stresses due to a heat source moving over the
//!   surface of a half plane, *ASME J. Appl. Mech.* 51 (1984) 636–640; and J. R. Barber, The
//!   influence of thermal expansion on the friction and wear process, *Wear* 10 (1967) 155–159
//!   (the stationary bulge), as summarised in Barber, *Elasticity*, 3rd ed. (2010), ch. 14.
//! - M. Abramowitz, I. A. Stegun, *Handbook of Mathematical Functions* (1964), 5.1 (`E1`).

use std::f64::consts::PI;

use ndarray::{Array2, Array3, ArrayView2, Axis};
use rustfft::num_complex::Complex;

use super::kernel::{CellGrid, Convolution};
use super::special::EULER_GAMMA;
use super::special::{
    exponential_integral_e1, exponential_integral_series, gauss_legendre, integrate,
};
use super::stress::{add_band, add_smooth, sinc};
use crate::operator::transform::TransformError;

type C64 = Complex<f64>;

/// Aliases each way of the smooth part on the surface.
const ALIASES: i64 = 3;
/// Oversampling in x of the smooth part's periodic lattice (the wake behind is long).
const OVERSAMPLING: usize = 4;

/// `H = 2 / (γ (γ + k))`: the outward surface displacement per `(1 + ν) α q̂ / K` (module doc);
/// `two_u = V / κ`. `k` must be positive.
pub fn response(xi: f64, eta: f64, two_u: f64) -> C64 {
    let k = xi.hypot(eta);
    let gamma = C64::new(k * k, -two_u * xi).sqrt();
    2.0 / (gamma * (gamma + k))
}

/// The antiderivative `L(x, y)` of `ln √(x² + y²)` in x and y.
fn log_corner(x: f64, y: f64) -> f64 {
    let r2 = x * x + y * y;
    if r2 == 0.0 {
        return 0.0;
    }
    let mut value = if x == 0.0 || y == 0.0 {
        0.0
    } else {
        x * y * (r2.ln() - 3.0)
    };
    if x != 0.0 {
        value += x * x * (y / x).atan();
    }
    if y != 0.0 {
        value += y * y * (x / y).atan();
    }
    0.5 * value
}

/// `∫∫ -ln r / (2π)` over `[x0, x1] x [y0, y1]`: the stationary displacement of a uniformly
/// heated cell per `(1 + ν) α q / K`, up to the arbitrary constant (times the area).
pub fn stationary_rectangle(x0: f64, x1: f64, y0: f64, y1: f64) -> f64 {
    -(log_corner(x1, y1) - log_corner(x1, y0) - log_corner(x0, y1) + log_corner(x0, y0))
        / (2.0 * PI)
}

/// `-ln r - E1(kw² r² / 4) / 2`, smooth in `r` (its series has no logarithm).
fn regular_log(r: f64, kw: f64) -> f64 {
    let x = 0.25 * (kw * r).powi(2);
    if x <= 1.0 {
        0.5 * (EULER_GAMMA + (0.25 * kw * kw).ln()) + 0.5 * exponential_integral_series(x)
    } else {
        -r.ln() - 0.5 * exponential_integral_e1(x)
    }
}

/// The influence-coefficient lattice (`[2 ny, 2 nx]`, wrap-around order) of the outward surface
/// displacement per `(1 + ν) α / K` for `u = V / (2κ)` (module doc).
pub fn influence_lattice(grid: &CellGrid, u: f64) -> Array2<f64> {
    let [ny, nx] = grid.shape;
    let [dx, dy] = grid.spacing_m;
    let stationary = grid.offset_lattice(|i, j| {
        let (x, y) = (i as f64 * dx, j as f64 * dy);
        stationary_rectangle(x - 0.5 * dx, x + 0.5 * dx, y - 0.5 * dy, y + 0.5 * dy)
    });
    if u == 0.0 {
        return stationary;
    }
    let kw = 8.0 * PI / (2.0 * nx as f64 * dx).min(2.0 * ny as f64 * dy);
    let (nodes, weights) = gauss_legendre(4);
    let smooth = grid.offset_lattice(|i, j| {
        let (x, y) = (i as f64 * dx, j as f64 * dy);
        let mut sum = 0.0;
        for (a, wa) in nodes.iter().zip(&weights) {
            for (b, wb) in nodes.iter().zip(&weights) {
                let r = (x + 0.5 * dx * a).hypot(y + 0.5 * dy * b);
                sum += wa * wb * regular_log(r, kw);
            }
        }
        sum * 0.25 * dx * dy / (2.0 * PI)
    });
    let mut out = Array3::zeros((1, 2 * ny, 2 * nx));
    out.index_axis_mut(Axis(0), 0)
        .assign(&(&stationary - &smooth));
    let two_u = 2.0 * u;
    let window = |k: f64| (-(k / kw).powi(2)).exp();
    let cell = |xi: f64, eta: f64| dx * dy * sinc(0.5 * xi * dx) * sinc(0.5 * eta * dy);
    add_band(&mut out, grid, kw * 5.0, [1.0], &|xi, eta| {
        [response(xi, eta, two_u) * window(xi.hypot(eta)) * cell(xi, eta)]
    });
    // The lattice's wavenumber steps (those of `add_smooth`).
    let d_xi = 2.0 * PI / ((2 * nx * OVERSAMPLING) as f64 * dx);
    let d_eta = 2.0 * PI / ((2 * ny) as f64 * dy);
    let smooth = |xi: f64, eta: f64| {
        let k = xi.hypot(eta);
        if k == 0.0 {
            return C64::new(0.0, 0.0);
        }
        (response(xi, eta, two_u) - 1.0 / (k * k)) * (1.0 - window(k)) * cell(xi, eta)
    };
    // Near the η axis `H` keeps `1/k²` in a cusp `|ξ| < k²/(2u)` narrower than the lattice's
    // step: there the samples are replaced by their means over the lattice cell in ξ (over the
    // whole cell at k = 0), so that the sum integrates the cusp instead of hitting or missing it.
    let eta_cusp = 4.0 * (u * d_xi).sqrt() + d_eta;
    let mean_in_xi = |xi: f64, eta: f64| {
        let (a, b) = (xi - 0.5 * d_xi, xi + 0.5 * d_xi);
        let part = |lo: f64, hi: f64, im: bool| {
            integrate(
                |t| {
                    let v = smooth(t, eta);
                    if im {
                        v.im
                    } else {
                        v.re
                    }
                },
                lo,
                hi,
                1e-13 * dx * dy * d_xi,
            )
        };
        let pieces = if a < 0.0 && b > 0.0 {
            vec![(a, 0.0), (0.0, b)]
        } else {
            vec![(a, b)]
        };
        let (mut re, mut im) = (0.0, 0.0);
        for (lo, hi) in pieces {
            re += part(lo, hi, false);
            im += part(lo, hi, true);
        }
        C64::new(re, im) / d_xi
    };
    add_smooth(
        &mut out,
        grid,
        ALIASES,
        OVERSAMPLING,
        [1.0],
        &|xi, eta, _| {
            if xi.abs() < 3.5 * d_xi && eta.abs() < eta_cusp {
                if eta == 0.0 {
                    // The whole cell about k = 0, halves in η (the cusp closes at η = 0).
                    let half = 0.5 * d_eta;
                    let (nodes, weights) = gauss_legendre(12);
                    let mut sum = C64::new(0.0, 0.0);
                    for (t, w) in nodes.iter().zip(&weights) {
                        // Graded towards η = 0: η = half s², s in (0, 1).
                        let s = 0.5 * (t + 1.0);
                        let e = half * s * s;
                        let jacobian = half * 2.0 * s * 0.5;
                        sum += (mean_in_xi(xi, e) + mean_in_xi(xi, -e)) * (w * jacobian);
                    }
                    return [sum / d_eta];
                }
                return [mean_in_xi(xi, eta)];
            }
            [smooth(xi, eta)]
        },
    );
    out.index_axis_move(Axis(0), 0)
}

/// The outward surface displacement (m) of a body under a gridded flux, by DC-FFT.
pub struct DisplacementOperator {
    convolution: Convolution,
    scale: f64,
}

impl DisplacementOperator {
    /// For `u = V / (2κ)` (1/m) and `(1 + ν) α / K` (m/W).
    pub fn new(
        grid: &CellGrid,
        u: f64,
        poisson_expansion_over_conductivity: f64,
    ) -> Result<Self, TransformError> {
        let lattice = influence_lattice(grid, u);
        Ok(Self {
            convolution: Convolution::new(grid.shape, lattice.view())?,
            scale: poisson_expansion_over_conductivity,
        })
    }

    /// Bytes held for a grid of `shape`.
    pub fn memory_bytes(shape: [usize; 2]) -> usize {
        Convolution::memory_bytes(shape)
    }

    /// `[ny, nx]` outward displacement (m) under `flux` (W/m²).
    pub fn apply(&mut self, flux: ArrayView2<f64>) -> Result<Array2<f64>, TransformError> {
        let mut out = Array2::zeros(self.convolution.shape());
        self.convolution.apply(flux, out.view_mut())?;
        out.mapv_inplace(|w| w * self.scale);
        Ok(out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn log_cell_integral_matches_quadrature() {
        // The corner sums against adaptive quadrature of -ln r / (2π): a cell away from the
        // origin and the singular cell itself (tolerance 1e-10).
        for (x0, x1, y0, y1) in [
            (2.5, 3.5, 1.5, 2.5),
            (-0.3, 0.7, -0.45, 0.55),
            (0.1, 2.0, -1.0, 0.5),
        ] {
            let reference = integrate(
                |x| integrate(|y| -(x * x + y * y).sqrt().ln() / (2.0 * PI), y0, y1, 1e-13),
                x0,
                x1,
                1e-12,
            );
            let value = stationary_rectangle(x0, x1, y0, y1);
            assert!((value - reference).abs() < 1e-10, "{value} vs {reference}");
        }
    }

    #[test]
    fn displacement_response_is_the_depth_integral_of_the_normal_strain() {
        // w = ∫ ε_zz dz with ε_zz = (σzz - ν(σxx + σyy)) / E + α T from the stress response
        // (per E α) and T̂ = e^(-γz)/γ: an independent derivation of 2(1+ν)/(γ(γ+k))
        // (tolerance 1e-7 relative; measured below).
        let nu = 0.3;
        let mut worst: f64 = 0.0;
        for (xi, eta, two_u) in [
            (1.0, 0.5, 0.0),
            (0.7, -1.2, 2.0),
            (-2.0, 0.3, 10.0),
            (0.05, 1.0, 40.0),
        ] {
            let k: f64 = f64::hypot(xi, eta);
            let gamma = C64::new(k * k, -two_u * xi).sqrt();
            let strain = |z: f64| {
                let s = super::super::stress::response(xi, eta, z, two_u, nu);
                s[2] - nu * (s[0] + s[1]) + (-gamma * z).exp() / gamma
            };
            let end = 60.0 / k;
            let re = integrate(|z| strain(z).re, 0.0, end, 1e-14);
            let im = integrate(|z| strain(z).im, 0.0, end, 1e-14);
            let expected = (1.0 + nu) * response(xi, eta, two_u);
            let error = (C64::new(re, im) - expected).norm() / expected.norm();
            worst = worst.max(error);
        }
        eprintln!("measured: displacement FRF vs ∫ε_zz dz: {worst:.1e}");
        assert!(worst < 1e-7);
    }

    /// A grid of `n` (odd) cells of `d` each way, centred on the origin, and a flux on it (each
    /// cell the mean of 8 x 8 samples).
    fn centred(n: usize, d: f64, q: impl Fn(f64, f64) -> f64) -> (CellGrid, Array2<f64>) {
        let c = (n / 2) as f64;
        let flux = Array2::from_shape_fn((n, n), |(row, column)| {
            let mut sum = 0.0;
            for a in 0..8 {
                for b in 0..8 {
                    let x = (column as f64 - c - 0.5 + (a as f64 + 0.5) / 8.0) * d;
                    let y = (row as f64 - c - 0.5 + (b as f64 + 0.5) / 8.0) * d;
                    sum += q(x, y);
                }
            }
            sum / 64.0
        });
        (
            CellGrid {
                shape: [n, n],
                spacing_m: [d, d],
            },
            flux,
        )
    }

    #[test]
    fn stationary_bulges_match_barber() {
        // Uniform disc: w(0) - w(a) = (1+ν) α q a² / (4K) (Barber); Hertzian flux:
        // (1+ν) α q0 a² (4/3 - ln 2) / (3K). Cells of a/20 (tolerance 2e-3; measured below).
        let (a, n) = (1.0, 81);
        let d = a / 20.0;
        let centre = n / 2;
        for (name, q, expected) in [
            (
                "uniform disc",
                &(|x: f64, y: f64| if x * x + y * y < 1.0 { 1.0 } else { 0.0 })
                    as &dyn Fn(f64, f64) -> f64,
                0.25,
            ),
            (
                "Hertzian flux",
                &|x: f64, y: f64| (1.0 - x * x - y * y).max(0.0).sqrt(),
                (4.0 / 3.0 - 2f64.ln()) / 3.0,
            ),
        ] {
            let (grid, flux) = centred(n, d, q);
            let w = DisplacementOperator::new(&grid, 0.0, 1.0)
                .expect("operator")
                .apply(flux.view())
                .expect("apply");
            // w(a) averaged over the four points at r = a on the axes.
            let edge = 0.25
                * (w[[centre, centre + 20]]
                    + w[[centre, centre - 20]]
                    + w[[centre + 20, centre]]
                    + w[[centre - 20, centre]]);
            let bulge = w[[centre, centre]] - edge;
            let error = (bulge - expected) / expected;
            eprintln!("measured: stationary bulge, {name}: {error:.1e}");
            assert!(error.abs() < 2e-3, "{name}: {bulge} vs {expected}");
        }
    }

    /// A product rule on `[0, limit]`: 8-point Gauss–Legendre panels, halving towards 0 down to
    /// `limit * 1e-9`, then 24 uniform panels.
    fn graded_rule(limit: f64) -> Vec<(f64, f64)> {
        let (nodes, weights) = gauss_legendre(8);
        let mut edges = vec![0.0];
        let mut edge = limit * 1e-9;
        while edge < limit / 24.0 {
            edges.push(edge);
            edge *= 2.0;
        }
        for k in 1..=24 {
            edges.push(limit * k as f64 / 24.0);
        }
        let mut rule = Vec::new();
        for pair in edges.windows(2) {
            for (t, w) in nodes.iter().zip(&weights) {
                rule.push((
                    0.5 * (pair[0] + pair[1]) + 0.5 * (pair[1] - pair[0]) * t,
                    0.5 * (pair[1] - pair[0]) * w,
                ));
            }
        }
        rule
    }

    /// `w(x, y)` per (1+ν)α/K under `exp(-r²/s²)` moving at `u`: the inverse transform of
    /// `H q̂`, `q̂ = π s² exp(-k² s²/4)`, by a product rule graded towards both axes (no window,
    /// no lattice: independent of the operator's splitting; agrees with nested adaptive
    /// quadrature to 7e-6 of the centre value).
    fn gaussian_reference(points: &[(f64, f64)], s: f64, u: f64) -> Vec<f64> {
        let rule = graded_rule(12.0 / s);
        let mut sums = vec![0.0; points.len()];
        for &(xi, wx) in &rule {
            for &(eta_abs, we) in &rule {
                for eta in [eta_abs, -eta_abs] {
                    let k2 = xi * xi + eta * eta;
                    let h = response(xi, eta, 2.0 * u) * (PI * s * s * (-k2 * s * s / 4.0).exp());
                    for (sum, &(x, y)) in sums.iter_mut().zip(points) {
                        *sum += wx * we * (h * C64::from_polar(1.0, xi * x + eta * y)).re;
                    }
                }
            }
        }
        sums.iter().map(|v| 2.0 * v / (4.0 * PI * PI)).collect()
    }

    #[test]
    fn moving_displacement_matches_the_inverse_transform_of_a_gaussian_flux() {
        // Gaussian flux of width s on 97² cells over ±6 s, u s = 0.3 and 3: the operator
        // against adaptive quadrature at points ahead, at the centre, behind and aside
        // (tolerance 0.5 % of the largest; measured below).
        let (s, n) = (1.0, 97);
        let d = 12.0 * s / n as f64;
        let (grid, flux) = centred(n, d, |x, y| (-(x * x + y * y) / (s * s)).exp());
        let c = n / 2;
        for u in [0.3, 3.0] {
            let w = DisplacementOperator::new(&grid, u, 1.0)
                .expect("operator")
                .apply(flux.view())
                .expect("apply");
            let offsets = [
                (0i64, 0i64),
                (16, 0),
                (-16, 0),
                (-40, 0),
                (0, 16),
                (-24, 12),
            ];
            let points: Vec<(f64, f64)> = offsets
                .iter()
                .map(|&(dc, dr)| (dc as f64 * d, dr as f64 * d))
                .collect();
            let references = gaussian_reference(&points, s, u);
            let mut worst: f64 = 0.0;
            let mut largest: f64 = 0.0;
            for (&(dc, dr), reference) in offsets.iter().zip(references) {
                let (row, column) = ((c as i64 + dr) as usize, (c as i64 + dc) as usize);
                worst = worst.max((w[[row, column]] - reference).abs());
                largest = largest.max(reference.abs());
            }
            eprintln!(
                "measured: moving displacement, Gaussian, u s = {u}: {:.1e}",
                worst / largest
            );
            assert!(worst < 5e-3 * largest, "u {u}: {worst} of {largest}");
        }
    }
}
