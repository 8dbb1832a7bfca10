//! An independent reference for coated line contacts: a rigid cylinder (or a cylinder of
//! given compliance) pressed on a coated half-plane in plane strain, solved by Fourier
//! integrals and quadrature, with nothing of the grid, the influence coefficients or the
//! active-set solver of [`crate::contact::coated::solve_line`].
//!
//! ## The method
//! For a chosen half-width `b`, the pressure is sought as
//! `p(x) = Σ_(n=1..N) c_n (1 - x²/b²)^(n - 1/2)`, each term vanishing at the edges like the
//! Hertz pressure. A term's Fourier transform is (Poisson's integral for `J_n`, Abramowitz &
//! Stegun 9.1.20)
//!
//! ```text
//! P_n(k) = ∫_(-b)^(b) (1 - x²/b²)^(n - 1/2) e^(-ikx) dx = b √π Γ(n + 1/2) (2/(kb))^n J_n(kb),
//! ```
//!
//! and its surface displacement, relative to the centre (a plane problem has no absolute
//! displacement), is
//!
//! ```text
//! u_n(x) - u_n(0) = (1/π) ∫₀^∞ [C(kh) + 2 (1 - ν_b²)/E_b] P_n(k) (cos kx - 1) dk / k
//! ```
//!
//! with `C(kh) = k u_z / p` the layered compliance of [`super::response`] (the only thing shared
//! with the solver, and checked on its own). Inside the contact the surfaces follow the
//! cylinder: `Σ c_n [u_n(x) - u_n(0)] = -x² / (2R)`, collocated at `M > N` points of `(0, b)`
//! and solved for `c_n` by least squares, the residual saying how well the terms represent the
//! pressure. The load per unit length is `W = Σ c_n b √π Γ(n + 1/2) / n!`. On equal materials
//! the result is Hertz's (`c_1 = p0`, the rest zero), which the tests check.
//!
//! The quadrature runs in `s = kb` over panels of unit width with 8 Gauss–Legendre points to
//! `s = 3000` (the integrand falls as `s^(-5/2)`). `J_n(s)/s^n` is its power series below 12;
//! above, `J0` and `J1` come from Hankel's asymptotic expansion (A&S 9.2.5, the smallest term
//! below 1e-10 there) and the higher orders from the upward recurrence (A&S 9.1.27, stable for
//! `s > n`).
//!
//! ## References
//! - M. Abramowitz, I. A. Stegun, *Handbook of Mathematical Functions* (1964), ch. 9.
//! - I. N. Sneddon, *Fourier Transforms*, McGraw-Hill (1951).
//! - K. L. Johnson, *Contact Mechanics* (1985), §4.2 (Hertz's line contact, the check).

use std::f64::consts::PI;

use super::response::Layered;

/// `J_ν(x)` for `ν = 0, 1` and `x >= 12` by Hankel's asymptotic expansion (A&S 9.2.5).
fn bessel_asymptotic(order: usize, x: f64) -> f64 {
    let mu = 4.0 * (order * order) as f64;
    let (mut p, mut q) = (1.0, 0.0);
    let mut a = 1.0;
    let mut last = f64::INFINITY;
    for k in 1..60 {
        let odd = (2 * k - 1) as f64;
        a *= (mu - odd * odd) / (k as f64 * 8.0 * x);
        let term = a.abs();
        if term > last || term < 1e-18 {
            break;
        }
        last = term;
        // P = Σ (-1)^j a_2j / x^2j, Q = Σ (-1)^j a_(2j+1) / x^(2j+1).
        let sign = if (k / 2) % 2 == 0 { 1.0 } else { -1.0 };
        if k % 2 == 0 {
            p += sign * a;
        } else {
            q += sign * a;
        }
    }
    let phase = x - (0.5 * order as f64 + 0.25) * PI;
    (2.0 / (PI * x)).sqrt() * (p * phase.cos() - q * phase.sin())
}

/// `J_n(x) / x^n` for `n = 1..=count`, `x >= 0` (module doc).
pub fn bessel_over_power(x: f64, count: usize) -> Vec<f64> {
    let mut out = vec![0.0; count];
    if x < 12.0 {
        // J_n(x) / x^n = Σ_k (-1)^k (x²/4)^k / (2^n k! (n + k)!).
        let q = -0.25 * x * x;
        for (i, slot) in out.iter_mut().enumerate() {
            let n = i + 1;
            let mut term = 1.0;
            for j in 1..=n {
                term /= 2.0 * j as f64;
            }
            let mut sum = term;
            for k in 1..80 {
                term *= q / (k as f64 * (n + k) as f64);
                sum += term;
                if term.abs() < 1e-18 * sum.abs().max(1e-300) {
                    break;
                }
            }
            *slot = sum;
        }
    } else {
        let mut previous = bessel_asymptotic(0, x);
        let mut current = bessel_asymptotic(1, x);
        let mut power = x;
        for (i, slot) in out.iter_mut().enumerate() {
            *slot = current / power;
            let n = (i + 1) as f64;
            let next = 2.0 * n / x * current - previous;
            previous = current;
            current = next;
            power *= x;
        }
    }
    out
}

/// `Γ(n + 1/2)` for integer `n >= 0`.
fn gamma_half(n: usize) -> f64 {
    let mut g = PI.sqrt();
    for k in 0..n {
        g *= k as f64 + 0.5;
    }
    g
}

fn factorial(n: usize) -> f64 {
    (1..=n).map(|k| k as f64).product()
}

/// A solved plane-strain contact (module doc).
#[derive(Clone, Debug, PartialEq)]
pub struct PlaneContact {
    pub half_width_m: f64,
    /// Load per unit length, N/m.
    pub load_n_per_m: f64,
    /// `c_n`, Pa.
    pub coefficients_pa: Vec<f64>,
    /// The largest pressure, Pa (searched on 2001 points).
    pub max_pressure_pa: f64,
    /// The collocation's rms residual over the cylinder's depth at the edge, `b² / 2R`.
    pub residual: f64,
}

impl PlaneContact {
    /// The pressure at `x` (Pa).
    pub fn pressure_pa(&self, x_m: f64) -> f64 {
        let t = 1.0 - (x_m / self.half_width_m).powi(2);
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

/// The contact of a cylinder of radius `radius_m` (the pair's effective radius) on `layered`
/// with the half-width `half_width_m`, the cylinder's compliance `counter_per_pa`
/// (`(1 - ν_b²)/E_b`, 0 when rigid), from `terms` pressure terms (module doc).
pub fn cylinder(
    layered: &Layered,
    counter_per_pa: f64,
    radius_m: f64,
    half_width_m: f64,
    terms: usize,
) -> PlaneContact {
    let b = half_width_m;
    let h = layered.thickness_m;
    let collocation = 3 * terms + 12;
    let points: Vec<f64> = (0..collocation)
        .map(|i| b * (0.5 * PI * (i as f64 + 0.5) / collocation as f64).sin())
        .collect();
    let prefactor: Vec<f64> = (1..=terms)
        .map(|n| b * PI.sqrt() * gamma_half(n) * 2f64.powi(n as i32))
        .collect();
    let (nodes, weights) = crate::thermal::special::gauss_legendre(8);
    let mut relative = vec![vec![0.0; terms]; collocation];
    for panel in 0..3000 {
        for (t, w) in nodes.iter().zip(&weights) {
            let s = panel as f64 + 0.5 + 0.5 * t;
            let k = s / b;
            let weight = 0.5 * w / b; // dk = ds / b
            let compliance = layered.normal_compliance_times_k(k * h) + 2.0 * counter_per_pa;
            // P_n(k) = prefactor_n J_n(s) / s^n.
            let bessel = bessel_over_power(s, terms);
            for (i, x) in points.iter().enumerate() {
                let factor = weight * compliance / (PI * k) * ((k * x).cos() - 1.0);
                for n in 0..terms {
                    relative[i][n] += factor * prefactor[n] * bessel[n];
                }
            }
        }
    }
    // Least squares for c_n: Σ c_n D_n(x_i) = -x_i² / 2R, columns scaled.
    let rows: Vec<(Vec<f64>, f64)> = points
        .iter()
        .zip(&relative)
        .map(|(x, row)| (row.clone(), -x * x / (2.0 * radius_m)))
        .collect();
    let column_scale: Vec<f64> = (0..terms)
        .map(|j| {
            rows.iter()
                .map(|(r, _)| r[j] * r[j])
                .sum::<f64>()
                .sqrt()
                .max(1e-300)
        })
        .collect();
    let mut normal = vec![vec![0.0; terms]; terms];
    let mut rhs = vec![0.0; terms];
    for (row, target) in &rows {
        for i in 0..terms {
            rhs[i] += row[i] / column_scale[i] * target;
            for j in 0..terms {
                normal[i][j] += row[i] / column_scale[i] * row[j] / column_scale[j];
            }
        }
    }
    let solution = super::reference::solve_dense(normal, rhs);
    let coefficients: Vec<f64> = solution
        .iter()
        .zip(&column_scale)
        .map(|(v, s)| v / s)
        .collect();
    let scale = b * b / (2.0 * radius_m);
    let residual = (rows
        .iter()
        .map(|(row, target)| {
            let fit: f64 = row.iter().zip(&coefficients).map(|(r, c)| r * c).sum();
            (fit - target).powi(2)
        })
        .sum::<f64>()
        / collocation as f64)
        .sqrt()
        / scale;
    let load = coefficients
        .iter()
        .enumerate()
        .map(|(i, c)| c * b * PI.sqrt() * gamma_half(i + 1) / factorial(i + 1))
        .sum();
    let mut contact = PlaneContact {
        half_width_m: b,
        load_n_per_m: load,
        coefficients_pa: coefficients,
        max_pressure_pa: 0.0,
        residual,
    };
    contact.max_pressure_pa = (0..=2000)
        .map(|i| contact.pressure_pa(b * i as f64 / 2000.0))
        .fold(0.0, f64::max);
    contact
}

/// The half-width that carries `load_n_per_m` (secant iteration on `ln b`), from the coating's
/// Hertz half-width.
pub fn cylinder_under_load(
    layered: &Layered,
    counter_per_pa: f64,
    radius_m: f64,
    load_n_per_m: f64,
    terms: usize,
) -> PlaneContact {
    let e1 = super::response::plane_strain_modulus(&layered.coating);
    let top = 1.0 / (1.0 / e1 + counter_per_pa);
    let mut b0 = (4.0 * load_n_per_m * radius_m / (PI * top)).sqrt();
    let mut c0 = cylinder(layered, counter_per_pa, radius_m, b0, terms);
    let mut b1 = b0 * (load_n_per_m / c0.load_n_per_m).sqrt();
    let mut c1 = cylinder(layered, counter_per_pa, radius_m, b1, terms);
    for _ in 0..30 {
        let (f0, f1) = (
            (c0.load_n_per_m / load_n_per_m).ln(),
            (c1.load_n_per_m / load_n_per_m).ln(),
        );
        if f1.abs() < 1e-12 || f1 == f0 {
            break;
        }
        let next = (b1.ln() - f1 * (b1.ln() - b0.ln()) / (f1 - f0)).exp();
        (b0, c0) = (b1, c1);
        b1 = next;
        c1 = cylinder(layered, counter_per_pa, radius_m, b1, terms);
    }
    c1
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::coating::response::plane_strain_modulus;
    use crate::contact::material::Material;

    #[test]
    fn bessel_functions_against_tabulated_values() {
        // Values of mpmath.besselj to 17 digits.
        let mut worst: f64 = 0.0;
        for (n, x, value) in [
            (1, 1.0, 0.440_050_585_744_933_5),
            (1, 12.5, -0.165_483_804_614_759_72),
            (1, 40.0, 0.126_038_318_037_585),
            (3, 10.0, 0.058_379_379_305_186_812),
            (8, 20.0, -0.073_868_928_840_750_34),
            (5, 2.0, 0.007_039_629_755_871_686),
            (2, 11.9, -0.063_534_021_474_702_93),
            (6, 13.0, -0.118_030_672_130_236_36),
        ] {
            let computed = bessel_over_power(x, n)[n - 1] * x.powi(n as i32);
            worst = worst.max((computed - value).abs());
        }
        assert!(worst < 1e-10, "{worst}");
        assert!((bessel_asymptotic(0, 20.0) - 0.167_024_664_340_583_15).abs() < 1e-12);
    }

    #[test]
    fn equal_materials_give_hertz() {
        // Johnson §4.2: b² = 4WR/(πE*), p = p0 sqrt(1 - x²/b²), p0 = 2W/(πb).
        let steel = Material {
            modulus_pa: 210e9,
            poisson: 0.3,
        };
        let layered = Layered {
            coating: steel,
            substrate: steel,
            thickness_m: 30e-6,
            under: crate::coating::Interlayers::NONE,
        };
        let (radius, b) = (10e-3, 100e-6);
        let counter = 0.91 / 210e9;
        let contact = cylinder(&layered, counter, radius, b, 6);
        let e_star = 1.0 / (1.0 / plane_strain_modulus(&steel) + counter);
        let load = PI * e_star * b * b / (4.0 * radius);
        let p0 = 2.0 * load / (PI * b);
        // The terms are nearly dependent (their coefficients trade off at 4e-3 p0 with no
        // effect on the sum): the pressure profile is compared, not each c_n.
        let profile = (0..=200)
            .map(|i| {
                let x = b * i as f64 / 200.0;
                (contact.pressure_pa(x) - p0 * (1.0 - (x / b).powi(2)).sqrt()).abs() / p0
            })
            .fold(0.0, f64::max);
        let worst = [
            (contact.load_n_per_m / load - 1.0).abs(),
            (contact.max_pressure_pa / p0 - 1.0).abs(),
            profile,
        ]
        .into_iter()
        .fold(0.0, f64::max);
        eprintln!(
            "measured: the plane-strain reference on equal moduli against Hertz: {worst:.1e} (residual {:.1e})",
            contact.residual
        );
        assert!(worst < 2e-5, "{worst}");
    }
}
