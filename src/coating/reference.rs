//! An independent reference for coated contact: a rigid sphere pressed on a coated half-space,
//! solved as an axisymmetric problem by Hankel transforms and quadrature, with nothing of the
//! grid, the influence coefficients or the conjugate-gradient solver.
//!
//! ## The method
//! For a chosen contact radius `a`, the pressure is sought as
//! `p(r) = Σ_(n=1..N) c_n (1 - r²/a²)^(n - 1/2)`, each term vanishing at the edge like the
//! Hertz pressure (a smooth contact). A term's Hankel transform is (Sneddon 1951; the
//! Sonine integral)
//!
//! ```text
//! P_n(k) = 2π ∫₀ᵃ (1 - ρ²/a²)^μ J0(kρ) ρ dρ = 2π a² 2^μ Γ(μ + 1) J_(μ+1)(ka) / (ka)^(μ+1)
//!        = 2π a² 2^μ Γ(μ + 1) sqrt(2/π) j_n(ka) / (ka)^n,          μ = n - 1/2,
//! ```
//!
//! (`j_n` the spherical Bessel function), and its surface displacement is
//! `u_n(r) = (1/2π) ∫₀^∞ C(kh) P_n(k) J0(kr) dk` with `C(kh) = k u_z / p` the layered
//! compliance of [`super::response`]. The displacement must follow the sphere inside the
//! contact, `Σ c_n u_n(r) = δ - r² / (2R)`: collocated at `M > N + 1` radii and solved for
//! `c_n` and `δ` by least squares, the residual saying how well the terms represent the
//! pressure. The load is `P = Σ c_n 2π a² / (2n + 1)`. On equal materials the result is Hertz's
//! (`c_1 = p0`, the rest zero), which the tests check.
//!
//! The quadrature runs in `x = ka` over panels of unit width with 8 Gauss–Legendre points to
//! `x = 3000` (the integrand falls as `x^(-5/2)`). `J0` is its power series below 16 and its
//! Hankel asymptotic expansion above (Abramowitz & Stegun 9.1.10 and 9.2.5; the series'
//! cancellation and the expansion's smallest term both stay below 1e-10).
//!
//! ## References
//! - I. N. Sneddon, *Fourier Transforms*, McGraw-Hill (1951) (Hankel transforms, Sonine's
//!   integral).
//! - M. Abramowitz, I. A. Stegun, *Handbook of Mathematical Functions* (1964), ch. 9, 10.

use std::f64::consts::PI;

use super::response::Layered;

/// `J0(x)` (module doc).
pub fn bessel_j0(x: f64) -> f64 {
    let x = x.abs();
    if x < 16.0 {
        let q = -0.25 * x * x;
        let mut term = 1.0;
        let mut sum = 1.0;
        for k in 1..80 {
            term *= q / (k * k) as f64;
            sum += term;
            if term.abs() < 1e-18 * sum.abs().max(1e-300) {
                break;
            }
        }
        sum
    } else {
        // a_k = a_(k-1) (2k - 1)² / (8k); P = Σ (-1)^k a_2k / x^2k, Q = -Σ (-1)^k a_(2k+1) / x^(2k+1).
        let (mut p, mut q) = (1.0, 0.0);
        let mut a = 1.0;
        let mut last = f64::INFINITY;
        for k in 1..60 {
            a *= ((2 * k - 1) * (2 * k - 1)) as f64 / (8.0 * k as f64);
            let term = a / x.powi(k);
            if term > last || term < 1e-18 {
                break;
            }
            last = term;
            let sign = if (k / 2) % 2 == 0 { 1.0 } else { -1.0 };
            // For ν = 0, μ - 1 = -1 makes every term of Q change sign (A&S 9.2.10).
            if k % 2 == 0 {
                p += sign * term;
            } else {
                q -= sign * term;
            }
        }
        let phase = x - 0.25 * PI;
        (2.0 / (PI * x)).sqrt() * (p * phase.cos() - q * phase.sin())
    }
}

/// `j_n(x) / x^n` for `n = 1..=count` (module doc): the power series below 10, the upward
/// recurrence from `j0`, `j1` above (stable for `x > n`).
pub(super) fn spherical_over_power(x: f64, count: usize) -> Vec<f64> {
    let mut out = vec![0.0; count];
    if x < 10.0 {
        for (i, slot) in out.iter_mut().enumerate() {
            let n = i + 1;
            // (2n + 1)!!
            let mut double_factorial = 1.0;
            let mut m = 2 * n + 1;
            while m > 1 {
                double_factorial *= m as f64;
                m -= 2;
            }
            let q = -0.5 * x * x;
            let mut term = 1.0 / double_factorial;
            let mut sum = term;
            for k in 1..60 {
                term *= q / (k as f64 * (2 * n + 2 * k + 1) as f64);
                sum += term;
                if term.abs() < 1e-18 * sum.abs() {
                    break;
                }
            }
            *slot = sum;
        }
    } else {
        let (s, c) = x.sin_cos();
        let mut previous = s / x;
        let mut current = s / (x * x) - c / x;
        let mut power = x;
        for (i, slot) in out.iter_mut().enumerate() {
            *slot = current / power;
            let n = (i + 1) as f64;
            let next = (2.0 * n + 1.0) / x * current - previous;
            previous = current;
            current = next;
            power *= x;
        }
    }
    out
}

/// `Γ(n + 1/2)` for integer `n >= 0`.
pub(super) fn gamma_half(n: usize) -> f64 {
    let mut g = PI.sqrt();
    for k in 0..n {
        g *= k as f64 + 0.5;
    }
    g
}

/// A solved axisymmetric contact (module doc).
#[derive(Clone, Debug, PartialEq)]
pub struct AxisymmetricContact {
    pub radius_m: f64,
    pub load_n: f64,
    pub approach_m: f64,
    /// `c_n`, Pa.
    pub coefficients_pa: Vec<f64>,
    /// The largest pressure, Pa (searched on 2001 radii).
    pub max_pressure_pa: f64,
    /// The collocation's rms residual over the sphere's depth at the edge, `a² / 2R`.
    pub residual: f64,
}

impl AxisymmetricContact {
    /// The pressure at radius `r` (Pa).
    pub fn pressure_pa(&self, r_m: f64) -> f64 {
        let t = 1.0 - (r_m / self.radius_m).powi(2);
        if t <= 0.0 {
            return 0.0;
        }
        self.coefficients_pa
            .iter()
            .enumerate()
            .map(|(i, c)| c * t.powf(i as f64 + 0.5))
            .sum()
    }
}

/// The contact of a rigid sphere of radius `sphere_radius_m` on `layered` with the contact
/// radius `radius_m`, from `terms` pressure terms (module doc).
pub fn rigid_sphere(
    layered: &Layered,
    sphere_radius_m: f64,
    radius_m: f64,
    terms: usize,
) -> AxisymmetricContact {
    let a = radius_m;
    let h = layered.thickness_m;
    let collocation = 3 * terms + 12;
    // Radii clustered towards the edge: r = a sin(π/2 (i + 1/2) / M).
    let radii: Vec<f64> = (0..collocation)
        .map(|i| a * (0.5 * PI * (i as f64 + 0.5) / collocation as f64).sin())
        .collect();
    // u_n(r_i) by quadrature in x = ka.
    let (nodes, weights) = crate::thermal::special::gauss_legendre(8);
    let mut u = vec![vec![0.0; terms]; collocation];
    let prefactor: Vec<f64> = (1..=terms)
        .map(|n| {
            let mu = n as f64 - 0.5;
            2.0 * PI * a * a * 2f64.powf(mu) * gamma_half(n) * (2.0 / PI).sqrt()
        })
        .collect();
    for panel in 0..3000 {
        for (t, w) in nodes.iter().zip(&weights) {
            let x = panel as f64 + 0.5 + 0.5 * t;
            let k = x / a;
            let weight = 0.5 * w / a; // dk = dx / a
            let compliance = layered.normal_compliance_times_k(k * h);
            let bessel = spherical_over_power(x, terms);
            for (i, r) in radii.iter().enumerate() {
                let j0 = bessel_j0(k * r);
                for n in 0..terms {
                    u[i][n] += weight * compliance * prefactor[n] * bessel[n] * j0 / (2.0 * PI);
                }
            }
        }
    }
    // Least squares for [c_1..c_N, δ]: Σ c_n u_n(r_i) - δ = -r_i² / 2R, scaled by a² / 2R.
    let scale = a * a / (2.0 * sphere_radius_m);
    let unknowns = terms + 1;
    let mut normal = vec![vec![0.0; unknowns]; unknowns];
    let mut rhs = vec![0.0; unknowns];
    let rows: Vec<(Vec<f64>, f64)> = radii
        .iter()
        .zip(&u)
        .map(|(r, row)| {
            let mut a_row: Vec<f64> = row.clone();
            a_row.push(-1.0);
            (a_row, -r * r / (2.0 * sphere_radius_m))
        })
        .collect();
    // Column scaling so that the normal equations stay well conditioned.
    let column_scale: Vec<f64> = (0..unknowns)
        .map(|j| {
            rows.iter()
                .map(|(r, _)| r[j] * r[j])
                .sum::<f64>()
                .sqrt()
                .max(1e-300)
        })
        .collect();
    for (row, b) in &rows {
        for i in 0..unknowns {
            rhs[i] += row[i] / column_scale[i] * b;
            for j in 0..unknowns {
                normal[i][j] += row[i] / column_scale[i] * row[j] / column_scale[j];
            }
        }
    }
    let solution = solve_dense(normal, rhs);
    let x: Vec<f64> = solution
        .iter()
        .zip(&column_scale)
        .map(|(v, s)| v / s)
        .collect();
    let coefficients: Vec<f64> = x[..terms].to_vec();
    let approach = x[terms];
    let residual = (rows
        .iter()
        .map(|(row, b)| {
            let fit: f64 = row.iter().zip(&x).map(|(r, v)| r * v).sum();
            (fit - b).powi(2)
        })
        .sum::<f64>()
        / collocation as f64)
        .sqrt()
        / scale;
    let load = coefficients
        .iter()
        .enumerate()
        .map(|(i, c)| c * 2.0 * PI * a * a / (2.0 * (i + 1) as f64 + 1.0))
        .sum();
    let mut contact = AxisymmetricContact {
        radius_m: a,
        load_n: load,
        approach_m: approach,
        coefficients_pa: coefficients,
        max_pressure_pa: 0.0,
        residual,
    };
    contact.max_pressure_pa = (0..=2000)
        .map(|i| contact.pressure_pa(a * i as f64 / 2000.0))
        .fold(0.0, f64::max);
    contact
}

/// The contact radius that carries `load_n` (secant iteration on `ln a`), from the coating's
/// Hertz radius.
pub fn rigid_sphere_under_load(
    layered: &Layered,
    sphere_radius_m: f64,
    load_n: f64,
    terms: usize,
) -> AxisymmetricContact {
    let e1 = super::response::plane_strain_modulus(&layered.coating);
    let mut a0 = (3.0 * load_n * sphere_radius_m / (4.0 * e1)).cbrt();
    let mut c0 = rigid_sphere(layered, sphere_radius_m, a0, terms);
    let mut a1 = a0 * (load_n / c0.load_n).cbrt();
    let mut c1 = rigid_sphere(layered, sphere_radius_m, a1, terms);
    for _ in 0..30 {
        let (f0, f1) = ((c0.load_n / load_n).ln(), (c1.load_n / load_n).ln());
        if f1.abs() < 1e-12 || f1 == f0 {
            break;
        }
        let next = (a1.ln() - f1 * (a1.ln() - a0.ln()) / (f1 - f0)).exp();
        (a0, c0) = (a1, c1);
        a1 = next;
        c1 = rigid_sphere(layered, sphere_radius_m, a1, terms);
    }
    c1
}

pub(super) fn solve_dense(mut matrix: Vec<Vec<f64>>, mut rhs: Vec<f64>) -> Vec<f64> {
    let n = rhs.len();
    for column in 0..n {
        let pivot = (column..n)
            .max_by(|&a, &b| matrix[a][column].abs().total_cmp(&matrix[b][column].abs()))
            .unwrap_or(column);
        matrix.swap(column, pivot);
        rhs.swap(column, pivot);
        let pivot_row = matrix[column].clone();
        for row in column + 1..n {
            let factor = matrix[row][column] / pivot_row[column];
            for (target, source) in matrix[row][column..].iter_mut().zip(&pivot_row[column..]) {
                *target -= factor * source;
            }
            rhs[row] -= factor * rhs[column];
        }
    }
    let mut x = vec![0.0; n];
    for row in (0..n).rev() {
        let sum: f64 = (row + 1..n).map(|j| matrix[row][j] * x[j]).sum();
        x[row] = (rhs[row] - sum) / matrix[row][row];
    }
    x
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contact::material::Material;

    #[test]
    fn bessel_functions_against_tabulated_values() {
        // Abramowitz & Stegun table 9.1: J0(1) = 0.765197686557967, J0(10) =
        // -0.245935764451348, J0(20) = 0.167024664340583 (to the digits printed).
        for (x, want) in [
            (1.0, 0.765_197_686_557_967),
            (10.0, -0.245_935_764_451_348),
            (20.0, 0.167_024_664_340_583),
        ] {
            assert!((bessel_j0(x) - want).abs() < 1e-13, "J0({x})");
        }
        // Continuity where the methods change, and j_n from its closed forms.
        assert!((bessel_j0(16.0 - 1e-12) - bessel_j0(16.0 + 1e-12)).abs() < 1e-11);
        for x in [0.5, 3.0, 9.999, 10.001, 40.0] {
            let (s, c) = f64::sin_cos(x);
            let j1 = s / (x * x) - c / x;
            let j2 = (3.0 / (x * x) - 1.0) * s / x - 3.0 * c / (x * x);
            let got = spherical_over_power(x, 2);
            assert!(
                (got[0] - j1 / x).abs() < 1e-12 * (1.0 + (j1 / x).abs()),
                "{x}"
            );
            assert!(
                (got[1] - j2 / (x * x)).abs() < 1e-12 * (1.0 + (j2 / x / x).abs()),
                "{x}"
            );
        }
    }

    #[test]
    fn equal_materials_give_hertz() {
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
        let (radius, a) = (5e-3, 50e-6);
        let contact = rigid_sphere(&layered, radius, a, 4);
        let e = 210e9 / 0.91;
        let load = 4.0 * e * a.powi(3) / (3.0 * radius);
        let p0 = 3.0 * load / (2.0 * PI * a * a);
        eprintln!(
            "measured: Hankel reference, equal moduli: load {:.1e}, p0 {:.1e}, approach {:.1e}, residual {:.1e}",
            contact.load_n / load - 1.0,
            contact.max_pressure_pa / p0 - 1.0,
            contact.approach_m / (a * a / radius) - 1.0,
            contact.residual
        );
        // The quadrature's truncation at ka = 3000 leaves a few parts in a million.
        assert!((contact.load_n / load - 1.0).abs() < 2e-5);
        assert!((contact.max_pressure_pa / p0 - 1.0).abs() < 2e-5);
        assert!((contact.approach_m / (a * a / radius) - 1.0).abs() < 2e-5);
        for i in 0..=100 {
            let r = a * i as f64 / 100.0;
            let hertz = p0 * (1.0 - (r / a).powi(2)).max(0.0).sqrt();
            assert!(
                (contact.pressure_pa(r) - hertz).abs() < 2e-5 * p0,
                "r = {r}"
            );
        }
    }
}
