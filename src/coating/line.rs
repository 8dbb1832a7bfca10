//! Line contacts on a coated body (plane strain): the influence coefficients of strips of
//! uniform pressure on the layered half-plane, and the six stress components at any depth under
//! tractions given on a 1-D grid.
//!
//! A line contact's tractions `p(x)`, `q(x)` are uniform along `y`: each of their Fourier waves
//! `e^(ikx)` is the plane problem of [`super::response`] with the wave vector along `x`, so the
//! same constants serve (`σyy = ν (σxx + σzz)`, plane strain; no anti-plane part).
//!
//! ## The influence coefficients
//! The surface compliance `u_z / p = C(|k|h) / |k|` ([`super::response::Layered::
//! normal_compliance_times_k`]) plus the counter-body's `2 (1 - ν_b²) / (E_b |k|)` is split as
//! in [`super::kernel`]:
//!
//! ```text
//! 2/(E*top |k|)  +  (2/|k|)(1/E2' - 1/E1') e^(-|k|h)  +  R(|k|)
//! ```
//!
//! In one dimension the transform pairs are `(1/2π) ∫ (2/|k|) e^(ikx) dk = -(2/π) ln|x| + const`
//! and `(1/2π) ∫ (2/|k|) e^(-|k|c) e^(ikx) dk = -(1/2π) ln(x² + c²) · 2 + const` (from
//! `∫₀^∞ (e^(-ak) - e^(-bk)) cos(kx) / k dk = ½ ln((b² + x²)/(a² + x²))`, Gradshteyn & Ryzhik
//! 3.951.2's special case, checked here by differentiation in `x`). Integrated over a strip of
//! width `d` centred at the origin they give, at `x`,
//!
//! ```text
//! -(2/π) top [F(x + d/2) - F(x - d/2)],                 F(t) = t ln|t| - t
//! -(1/π)(1/E2' - 1/E1') [H(x + d/2) - H(x - d/2)],     H(t) = t ln(t² + c²) - 2t + 2c atan(t/c)
//! ```
//!
//! (`H' = ln(t² + c²)`, derived here; `H -> 2F` as `c -> 0`). The remainder `R` is finite at
//! `k = 0` and decays as `e^(-kh)`; it is sampled with the strip's form factor `sinc(kd/2)` on a
//! grid eight times the cells' and transformed back, as in two dimensions. The kernels are
//! defined up to one additive constant (a plane problem has no absolute displacement), which
//! the contact's approach absorbs: the pressure does not depend on it.
//!
//! ## The stresses
//! The tractions, zero-padded to a period of at least sixteen times the grid, are the
//! band-limited functions through their samples; every wave of the padded transform gives its
//! stress at depth in closed form and one inverse transform per component the field at the
//! cell centres. The mean wave stands for the wavenumbers within half a step of zero,
//! `|k| < π/L` (`L` the period), where the tractions' transform is nearly their resultant: its
//! factors are the waves' averaged over that band (16 Gauss–Legendre points; for a homogeneous
//! body `σzz = σxx = -p̄`, `σxz = -q̄`). The band average matters for a layer thicker than the
//! period's scale, whose waves change from the substrate's to the coating's inside the band:
//! the `k -> 0` limit alone put 0.3 % into the surface von Mises stress of a coating 220 b
//! thick. The periodic images sixteen grid lengths apart change the stress under the contact
//! by about `(a/L)² p0` (Flamant's field of the images; below 1e-3 p0 here), which the check
//! against McEwen's closed form measures ([`super::tests`], `docs/coatings.md`).
//!
//! ## References
//! - I. S. Gradshteyn, I. M. Ryzhik, *Table of Integrals, Series, and Products* (Frullani-type
//!   integrals); K. L. Johnson, *Contact Mechanics* (1985), §2.8 (the plane waves) and §5.9
//!   (influence coefficients of strips).
//! - M. J. O'Sullivan, R. B. King, *ASME J. Tribol.* 110 (1988) 235–240 (the layered waves).

use std::f64::consts::PI;

use ndarray::Array2;
use realfft::RealFftPlanner;
use rustfft::num_complex::Complex;

use super::kernel::remainder;
use super::response::{plane_strain_modulus, Layered, Side, WaveResponse};
use crate::operator::transform::TransformError;

/// How many times the grid the remainder `R` is sampled over (its periodic images lie at least
/// seven grid lengths away from any offset used).
const REMAINDER_PERIODS: usize = 8;

/// The smallest padded period of the stresses, in grid lengths (module doc).
const STRESS_PERIODS: usize = 16;

fn sinc(x: f64) -> f64 {
    if x.abs() < 1e-8 {
        1.0 - x * x / 6.0
    } else {
        x.sin() / x
    }
}

/// `F(t) = t ln|t| - t` (0 at 0).
fn log_strip(t: f64) -> f64 {
    if t == 0.0 {
        0.0
    } else {
        t * t.abs().ln() - t
    }
}

/// `H(t) = t ln(t² + c²) - 2t + 2c atan(t/c)` (module doc), `c > 0`.
fn smoothed_log_strip(t: f64, c: f64) -> f64 {
    t * (t * t + c * c).ln() - 2.0 * t + 2.0 * c * (t / c).atan()
}

/// The influence coefficients (m/Pa) of a coated body (and the counter-body of compliance
/// `counter_per_pa`, `(1 - ν_b²)/E_b`, 0 when rigid) on strips of width `spacing_m`: the normal
/// surface displacement at offsets `0, d, ..., (cells - 1) d` from a strip of unit pressure,
/// up to one common constant (module doc).
pub fn line_kernel(
    layered: &Layered,
    counter_per_pa: f64,
    cells: usize,
    spacing_m: f64,
) -> Result<Vec<f64>, TransformError> {
    let d = spacing_m;
    let h = layered.thickness_m;
    let e1 = plane_strain_modulus(&layered.coating);
    let e2 = plane_strain_modulus(&layered.substrate);
    let top = 1.0 / e1 + counter_per_pa;
    let far = 1.0 / e2 - 1.0 / e1;
    // The remainder on a period of REMAINDER_PERIODS grids.
    let length = REMAINDER_PERIODS * cells.max(1);
    let mut planner = RealFftPlanner::<f64>::new();
    let inverse = planner.plan_fft_inverse(length);
    let period_m = length as f64 * d;
    let mut spectrum: Vec<Complex<f64>> = (0..=length / 2)
        .map(|m| {
            let k = 2.0 * PI * m as f64 / period_m;
            Complex::new(remainder(layered, k) * sinc(0.5 * k * d), 0.0)
        })
        .collect();
    if length.is_multiple_of(2) {
        // The Nyquist wave is real: its cosine alone.
        let last = spectrum.len() - 1;
        spectrum[last].im = 0.0;
    }
    let mut rest = vec![0.0; length];
    inverse.process(&mut spectrum, &mut rest)?;
    Ok((0..cells)
        .map(|j| {
            let x = j as f64 * d;
            let love = -(2.0 / PI) * top * (log_strip(x + 0.5 * d) - log_strip(x - 0.5 * d));
            let smooth = -(1.0 / PI)
                * far
                * (smoothed_log_strip(x + 0.5 * d, h) - smoothed_log_strip(x - 0.5 * d, h));
            love + smooth + rest[j] / length as f64
        })
        .collect())
}

/// The stresses of a coated body under line tractions on a 1-D grid (module doc).
pub struct LineStress {
    layered: Layered,
    cells: usize,
    period: usize,
    period_m: f64,
    /// `(load, spectrum)`: load 0 the pressure, 1 `qx`; only the loads present.
    loads: Vec<(usize, Vec<Complex<f64>>)>,
    /// Per wave `m >= 1` below the Nyquist: `k` (1/m) and the wave's constants.
    waves: Vec<(f64, WaveResponse)>,
}

impl LineStress {
    /// Transforms the tractions (Pa, at the centres of `pressure.len()` strips `spacing_m`
    /// wide): `pressure`, and `shear_x` (`qx` in +x on the body) when given.
    pub fn new(
        layered: Layered,
        pressure: &[f64],
        shear_x: Option<&[f64]>,
        spacing_m: f64,
    ) -> Result<Self, TransformError> {
        let cells = pressure.len();
        let period = (STRESS_PERIODS * cells.max(1)).next_power_of_two();
        let mut planner = RealFftPlanner::<f64>::new();
        let forward = planner.plan_fft_forward(period);
        let mut loads = Vec::new();
        for (load, values) in [(0, Some(pressure)), (1, shear_x)] {
            let Some(values) = values else { continue };
            let mut line = vec![0.0; period];
            line[..cells].copy_from_slice(values);
            let mut spectrum = forward.make_output_vec();
            forward.process(&mut line, &mut spectrum)?;
            loads.push((load, spectrum));
        }
        let period_m = period as f64 * spacing_m;
        let h = layered.thickness_m;
        let waves = (1..period / 2)
            .map(|m| {
                let k = 2.0 * PI * m as f64 / period_m;
                (k, layered.wave(k * h))
            })
            .collect();
        Ok(Self {
            layered,
            cells,
            period,
            period_m,
            loads,
            waves,
        })
    }

    /// The coated body.
    pub fn layered(&self) -> &Layered {
        &self.layered
    }

    /// The stresses (Pa) at depth `z_m` at the strips' centres, `[component, x]` with the
    /// components `[xx, yy, zz, yz, xz, xy]` (`yz = xy = 0`); at `z = h`, those of `side`.
    pub fn at_depth(&self, z_m: f64, side: Side) -> Result<Array2<f64>, TransformError> {
        let width = self.period / 2 + 1;
        let mut columns = vec![[Complex::new(0.0, 0.0); 6]; width];
        for (m, (k, response)) in self.waves.iter().enumerate() {
            let index = m + 1;
            let factors = response.at(k * z_m, side, &self.layered).stress([1.0, 0.0]);
            for (c, column) in columns[index].iter_mut().enumerate() {
                for (load, traction) in &self.loads {
                    let [re, im] = factors[c][*load];
                    *column += Complex::new(re, im) * traction[index];
                }
            }
        }
        // The mean wave: the waves averaged over the band |k| < π/L it stands for (module doc).
        let (nodes, weights) = crate::thermal::special::gauss_legendre(16);
        let band = PI / self.period_m;
        let h = self.layered.thickness_m;
        let mut average = [[0.0; 3]; 6];
        for (t, w) in nodes.iter().zip(&weights) {
            let k = 0.5 * band * (1.0 + t);
            let factors = self
                .layered
                .wave(k * h)
                .at(k * z_m, side, &self.layered)
                .stress([1.0, 0.0]);
            for (c, row) in average.iter_mut().enumerate() {
                for (load, slot) in row.iter_mut().enumerate() {
                    *slot += 0.5 * w * factors[c][load][0];
                }
            }
        }
        for (load, traction) in &self.loads {
            let mean = traction[0].re;
            for (c, column) in columns[0].iter_mut().enumerate() {
                // Only the real factors survive for a real mean (the imaginary ones are odd in
                // k): σxx, σyy, σzz of p, σxz of q.
                *column += Complex::new(average[c][*load] * mean, 0.0);
            }
        }
        let mut planner = RealFftPlanner::<f64>::new();
        let inverse = planner.plan_fft_inverse(self.period);
        let mut out = Array2::zeros((6, self.cells));
        let mut line = vec![0.0; self.period];
        let scale = 1.0 / self.period as f64;
        for c in 0..6 {
            let mut spectrum: Vec<Complex<f64>> = columns.iter().map(|v| v[c]).collect();
            spectrum[0].im = 0.0;
            if self.period.is_multiple_of(2) {
                spectrum[width - 1] = Complex::new(0.0, 0.0);
            }
            inverse.process(&mut spectrum, &mut line)?;
            for i in 0..self.cells {
                out[[c, i]] = line[i] * scale;
            }
        }
        Ok(out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contact::material::Material;

    #[test]
    fn the_strip_integrals_are_those_of_their_kernels() {
        // Gauss-Legendre quadrature of ln|x - s| and ln((x - s)² + c²) over a strip, away from
        // the singular point, against F and H.
        let (nodes, weights) = crate::thermal::special::gauss_legendre(40);
        let mut worst: f64 = 0.0;
        for &(x, c) in &[(1.7, 0.5), (-3.2, 2.0), (6.0, 0.1), (2.5, 4.0)] {
            let (mut plain, mut smooth) = (0.0, 0.0);
            for (t, w) in nodes.iter().zip(&weights) {
                let s = 0.5 * t; // strip of width 1
                plain += 0.5 * w * (x - s).abs().ln();
                smooth += 0.5 * w * ((x - s) * (x - s) + c * c).ln();
            }
            let closed_plain = log_strip(x + 0.5) - log_strip(x - 0.5);
            let closed_smooth = smoothed_log_strip(x + 0.5, c) - smoothed_log_strip(x - 0.5, c);
            worst = worst
                .max((closed_plain - plain).abs())
                .max((closed_smooth - smooth).abs());
        }
        assert!(worst < 1e-12, "{worst}");
        // c -> 0: H -> 2F.
        assert!((smoothed_log_strip(0.8, 1e-12) - 2.0 * log_strip(0.8)).abs() < 1e-10);
    }

    #[test]
    fn equal_materials_give_the_homogeneous_strips_up_to_a_constant() {
        // Johnson §5.9 (strip of uniform pressure on a half-plane):
        // u(x) = -(2/(π E*)) [F(x + d/2) - F(x - d/2)] + const.
        let steel = Material {
            modulus_pa: 210e9,
            poisson: 0.3,
        };
        let layered = Layered {
            coating: steel,
            substrate: steel,
            thickness_m: 5e-6,
            under: crate::coating::Interlayers::NONE,
        };
        let d = 1e-6;
        let counter = 0.91 / 210e9;
        let kernel = line_kernel(&layered, counter, 64, d).expect("kernel");
        let e_star = 210e9 / (2.0 * 0.91);
        let exact =
            |x: f64| -(2.0 / (PI * e_star)) * (log_strip(x + 0.5 * d) - log_strip(x - 0.5 * d));
        let offset = kernel[0] - exact(0.0);
        let scale = exact(0.0).abs();
        let worst = (0..64)
            .map(|j| (kernel[j] - offset - exact(j as f64 * d)).abs() / scale)
            .fold(0.0, f64::max);
        eprintln!("measured: equal moduli, line influence coefficients against the homogeneous strips: {worst:.1e}");
        assert!(worst < 1e-12, "{worst}");
    }

    /// Hertz's pressure and `q = μp` (p0 = 1 Pa, b = 1 m) at the centres of `cells` strips over
    /// ±`extent`.
    fn hertz_tractions(cells: usize, extent: f64, mu: f64) -> (Vec<f64>, Vec<f64>, Vec<f64>, f64) {
        let d = 2.0 * extent / cells as f64;
        let x: Vec<f64> = (0..cells).map(|i| -extent + (i as f64 + 0.5) * d).collect();
        let p: Vec<f64> = x.iter().map(|x| (1.0 - x * x).max(0.0).sqrt()).collect();
        let q = p.iter().map(|p| mu * p).collect();
        (x, p, q, d)
    }

    #[test]
    fn equal_moduli_give_mcewens_field() {
        // McEwen's sliding line contact (crate::solution::line_hertz), μ = 0.2, ν = 0.3, from
        // Hertz's pressure sampled on 400 strips over ±2b.
        let steel = Material {
            modulus_pa: 210e9,
            poisson: 0.3,
        };
        let layered = Layered {
            coating: steel,
            substrate: steel,
            thickness_m: 0.3,
            under: crate::coating::Interlayers::NONE,
        };
        let (x, p, q, d) = hertz_tractions(400, 2.0, 0.2);
        let field = LineStress::new(layered, &p, Some(&q), d).expect("stress");
        let mut worst: f64 = 0.0;
        let mut surface: f64 = 0.0;
        let mut in_plane: f64 = 0.0;
        for z in [0.0, 0.25, 0.5, 0.78, 1.0] {
            let side = if z <= 0.3 {
                Side::Coating
            } else {
                Side::Substrate
            };
            let rows = field.at_depth(z, side).expect("row");
            for (i, &xi) in x.iter().enumerate() {
                if z == 0.0 {
                    surface = surface
                        .max((rows[[2, i]] + p[i]).abs())
                        .max((rows[[4, i]] + q[i]).abs());
                    if xi.abs() < 0.9 {
                        let exact = crate::solution::line_hertz::stress_over_p0(xi, 0.0, 0.2, 0.3);
                        in_plane = in_plane
                            .max((rows[[0, i]] - exact.xx).abs())
                            .max((rows[[1, i]] - exact.yy).abs());
                    }
                    continue;
                }
                if xi.abs() > 1.5 {
                    continue;
                }
                let exact = crate::solution::line_hertz::stress_over_p0(xi, z, 0.2, 0.3);
                for (c, e) in [exact.xx, exact.yy, exact.zz, exact.yz, exact.xz, exact.xy]
                    .iter()
                    .enumerate()
                {
                    worst = worst.max((rows[[c, i]] - e).abs());
                }
            }
        }
        eprintln!("measured: equal moduli, the line field against McEwen's (μ = 0.2, 400 strips over ±2b, |x| <= 1.5b, z = 0.25b to b): {worst:.1e} p0; free surface {surface:.1e} p0; surface σxx, σyy (|x| < 0.9b) {in_plane:.1e} p0");
        assert!(worst < 2e-3, "{worst}");
        assert!(surface < 1e-12, "{surface}");
    }

    #[test]
    fn the_line_field_honours_the_interface() {
        // B4C on steel and a soft layer on steel: σzz, σxz continuous across z = h, σxx jumps.
        let steel = Material {
            modulus_pa: 210e9,
            poisson: 0.3,
        };
        let mut worst: f64 = 0.0;
        for coating in [
            Material {
                modulus_pa: 450e9,
                poisson: 0.17,
            },
            Material {
                modulus_pa: 70e9,
                poisson: 0.35,
            },
        ] {
            let layered = Layered {
                coating,
                substrate: steel,
                thickness_m: 0.2,
                under: crate::coating::Interlayers::NONE,
            };
            let (_, p, q, d) = hertz_tractions(200, 2.0, 0.3);
            let field = LineStress::new(layered, &p, Some(&q), d).expect("stress");
            let above = field.at_depth(0.2, Side::Coating).expect("row");
            let below = field.at_depth(0.2, Side::Substrate).expect("row");
            let mut jump: f64 = 0.0;
            for i in 0..200 {
                worst = worst
                    .max((above[[2, i]] - below[[2, i]]).abs())
                    .max((above[[4, i]] - below[[4, i]]).abs());
                jump = jump.max((above[[0, i]] - below[[0, i]]).abs());
            }
            eprintln!("measured: line interface, σzz σxz continuous to {worst:.1e} p0; σxx jumps by up to {jump:.2} p0");
            assert!(jump > 0.05, "{jump}");
        }
        assert!(worst < 1e-12, "{worst}");
    }
}
