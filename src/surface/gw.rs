//! The Greenwood–Williamson model of a rough surface on a rigid (or elastic) flat, and the
//! plasticity index.
//!
//! Summits of one radius `β`, density `η` per unit area and Gaussian heights (mean `zs`,
//! standard deviation `σs`) above the mean plane of the surface heights; the flat at a
//! separation `d` from that plane touches the summits higher than `d`, each a Hertz contact
//! with interference `z - d`. With `h = (d - zs)/σs` and the integrals
//! `F_n(h) = ∫_h^∞ (s - h)^n φ(s) ds` of the standard normal density `φ`, on a nominal area
//! `A0` (Greenwood & Williamson 1966, eqs. 4–6):
//!
//! ```text
//! contacts  n = η A0 F0(h)
//! real area A = π η A0 β σs F1(h)
//! load      P = (4/3) η A0 E* β^½ σs^(3/2) F_(3/2)(h)
//! ```
//!
//! `F0` and `F1` have closed forms, `F0(h) = 1 - Φ(h)` and `F1(h) = φ(h) - h F0(h)`; all three
//! are evaluated here by one Gauss–Legendre quadrature (with `s - h = u²`, which makes the
//! `n = 3/2` integrand smooth), tested against the closed forms and independent quadrature.
//!
//! The plasticity index `ψ = (E*/H) sqrt(σs/β)` (Greenwood & Williamson 1966) reads: below
//! 0.6 the asperities deform elastically under any practical load, above 1 plastically even
//! under light loads, between the two it depends on the load.
//!
//! ## Reference
//! J. A. Greenwood, J. B. P. Williamson, Contact of nominally flat surfaces, *Proc. R. Soc.
//! Lond. A* 295 (1966) 300–319.

use std::f64::consts::PI;

/// The summit statistics the model needs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GreenwoodWilliamson {
    pub density_per_m2: f64,
    pub radius_m: f64,
    pub height_std_m: f64,
    /// Mean summit height above the mean plane, m.
    pub mean_height_m: f64,
    /// Combined modulus, Pa.
    pub e_star_pa: f64,
}

/// One point of the model's curves at a separation.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct GwPoint {
    /// Separation of the flat from the mean plane of the heights, m.
    pub separation_m: f64,
    /// Contacts per unit nominal area, 1/m².
    pub contacts_per_m2: f64,
    /// Real area over nominal area.
    pub area_fraction: f64,
    /// Load over nominal area, Pa.
    pub pressure_pa: f64,
}

/// The standard normal density.
fn phi(s: f64) -> f64 {
    (-0.5 * s * s).exp() / (2.0 * PI).sqrt()
}

/// Nodes and weights of 20-point Gauss–Legendre quadrature on [-1, 1] (half of them; the rule
/// is symmetric), computed by Newton's method on the Legendre polynomial.
fn gauss_legendre() -> [(f64, f64); 20] {
    let n = 20;
    let mut out = [(0.0, 0.0); 20];
    for (k, slot) in out.iter_mut().enumerate() {
        let mut x = (PI * (k as f64 + 0.75) / (n as f64 + 0.5)).cos();
        for _ in 0..100 {
            let (mut p0, mut p1) = (1.0, x);
            for m in 2..=n {
                let p2 = ((2 * m - 1) as f64 * x * p1 - (m - 1) as f64 * p0) / m as f64;
                p0 = p1;
                p1 = p2;
            }
            let derivative = n as f64 * (x * p1 - p0) / (x * x - 1.0);
            let step = p1 / derivative;
            x -= step;
            if step.abs() < 1e-16 {
                let (mut q0, mut q1) = (1.0, x);
                for m in 2..=n {
                    let q2 = ((2 * m - 1) as f64 * x * q1 - (m - 1) as f64 * q0) / m as f64;
                    q0 = q1;
                    q1 = q2;
                }
                let d = n as f64 * (x * q1 - q0) / (x * x - 1.0);
                *slot = (x, 2.0 / ((1.0 - x * x) * d * d));
                break;
            }
        }
    }
    out
}

/// `F_n(h) = ∫_h^∞ (s - h)^n φ(s) ds` for `n` >= 0, by quadrature in `u = sqrt(s - h)` over
/// panels out to where `φ` is below 1e-30 of its peak.
pub fn f_n(n: f64, h: f64) -> f64 {
    let rule = gauss_legendre();
    // s runs from h to max(h, 0) + 12; u = sqrt(s - h).
    let top = (h.max(0.0) + 12.0 - h).max(0.0).sqrt();
    let panels = 64;
    let width = top / panels as f64;
    let mut sum = 0.0;
    for p in 0..panels {
        let (a, b) = (p as f64 * width, (p + 1) as f64 * width);
        let (mid, half) = (0.5 * (a + b), 0.5 * (b - a));
        for &(x, w) in &rule {
            let u = mid + half * x;
            // ds = 2u du; (s - h)^n = u^(2n).
            sum += w * half * 2.0 * u.powf(2.0 * n + 1.0) * phi(h + u * u);
        }
    }
    sum
}

impl GreenwoodWilliamson {
    /// The model at separation `d` (m) from the mean plane.
    pub fn at(&self, separation_m: f64) -> GwPoint {
        let h = (separation_m - self.mean_height_m) / self.height_std_m;
        let eta = self.density_per_m2;
        GwPoint {
            separation_m,
            contacts_per_m2: eta * f_n(0.0, h),
            area_fraction: PI * eta * self.radius_m * self.height_std_m * f_n(1.0, h),
            pressure_pa: 4.0 / 3.0
                * eta
                * self.e_star_pa
                * self.radius_m.sqrt()
                * self.height_std_m.powf(1.5)
                * f_n(1.5, h),
        }
    }

    /// The curves from `d = zs + 4σs` (a few contacts) down to `zs - 1σs` (heavy load), in
    /// `count` steps.
    pub fn curves(&self, count: usize) -> Vec<GwPoint> {
        let (top, bottom) = (
            self.mean_height_m + 4.0 * self.height_std_m,
            self.mean_height_m - self.height_std_m,
        );
        (0..count)
            .map(|k| self.at(top + (bottom - top) * k as f64 / (count - 1).max(1) as f64))
            .collect()
    }

    /// The real area fraction carrying the mean pressure `pressure_pa` (the separation found by
    /// bisection; the load decreases monotonically with the separation).
    pub fn area_at_pressure(&self, pressure_pa: f64) -> GwPoint {
        let (mut low, mut high) = (
            self.mean_height_m - 10.0 * self.height_std_m,
            self.mean_height_m + 12.0 * self.height_std_m,
        );
        for _ in 0..200 {
            let mid = 0.5 * (low + high);
            if self.at(mid).pressure_pa > pressure_pa {
                low = mid;
            } else {
                high = mid;
            }
        }
        self.at(0.5 * (low + high))
    }
}

/// The plasticity index `ψ = (E*/H) sqrt(σs/β)` and its reading.
pub fn plasticity_index(
    e_star_pa: f64,
    hardness_pa: f64,
    height_std_m: f64,
    radius_m: f64,
) -> (f64, &'static str) {
    let psi = e_star_pa / hardness_pa * (height_std_m / radius_m).sqrt();
    (psi, plasticity_reading(psi))
}

/// The reading of a plasticity index (Greenwood & Williamson 1966).
pub fn plasticity_reading(psi: f64) -> &'static str {
    if psi < 0.6 {
        "elastic: the asperities deform elastically under any practical load (ψ < 0.6)"
    } else if psi > 1.0 {
        "plastic: most asperity contacts flow plastically even under light loads (ψ > 1)"
    } else {
        "mixed: elastic or plastic depending on the load (0.6 <= ψ <= 1)"
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// 1 - Φ(h), independent of the quadrature: Φ(h) = 1/2 + φ(h) Σ h^(2k+1)/(2k+1)!! for
    /// |h| < 5 (the series converges everywhere), and the continued fraction
    /// φ(h) / (h + 1/(h + 2/(h + ...))) beyond.
    fn upper_tail(h: f64) -> f64 {
        if h.abs() < 5.0 {
            let (mut term, mut sum) = (h, h);
            for k in 1..200 {
                term *= h * h / (2 * k + 1) as f64;
                sum += term;
            }
            return 0.5 - phi(h) * sum;
        }
        if h < 0.0 {
            return 1.0 - upper_tail(-h);
        }
        let mut fraction = h;
        for k in (1..200).rev() {
            fraction = h + k as f64 / fraction;
        }
        phi(h) / fraction
    }

    #[test]
    fn f0_and_f1_have_their_closed_forms() {
        for h in [-3.0, -1.0, -0.2, 0.5, 1.0, 2.5, 4.0] {
            let f0 = f_n(0.0, h);
            let tail = upper_tail(h);
            assert!(
                (f0 - tail).abs() < 1e-12 * tail.max(1e-300) + 1e-15,
                "F0({h}) {f0} vs {tail}"
            );
            let f1 = f_n(1.0, h);
            let closed = phi(h) - h * tail;
            assert!(
                (f1 - closed).abs() < 1e-11 * closed,
                "F1({h}) {f1} vs {closed}"
            );
        }
        assert!((f_n(0.0, 0.0) - 0.5).abs() < 1e-14);
    }

    #[test]
    fn f_three_halves_against_independent_quadrature() {
        use quadrature::double_exponential::integrate;
        for h in [-2.0, 0.0, 1.0, 3.0] {
            let reference =
                integrate(|s| (s - h).max(0.0).powf(1.5) * phi(s), h, h + 40.0, 1e-14).integral;
            let ours = f_n(1.5, h);
            assert!(
                (ours / reference - 1.0).abs() < 1e-9,
                "F3/2({h}) {ours} vs {reference}"
            );
        }
    }

    #[test]
    fn the_model_is_monotone_and_the_plasticity_index_reads_right() {
        let gw = GreenwoodWilliamson {
            density_per_m2: 1e10,
            radius_m: 20e-6,
            height_std_m: 0.1e-6,
            mean_height_m: 0.05e-6,
            e_star_pa: 1.15e11,
        };
        let curves = gw.curves(30);
        for pair in curves.windows(2) {
            assert!(pair[1].pressure_pa > pair[0].pressure_pa);
            assert!(pair[1].area_fraction > pair[0].area_fraction);
        }
        let point = gw.area_at_pressure(1e6);
        assert!((point.pressure_pa / 1e6 - 1.0).abs() < 1e-9);
        // Far above every summit nothing touches.
        assert!(gw.at(2e-6).contacts_per_m2 < 1e-10 * gw.density_per_m2);
        let (psi, reading) = plasticity_index(1.15e11, 3e9, 0.1e-6, 20e-6);
        assert!((psi - 1.15e11 / 3e9 * (0.1f64 / 20.0).sqrt()).abs() < 1e-12);
        assert!(reading.starts_with("plastic"));
        assert!(plasticity_index(1e9, 3e9, 1e-6, 1e-4)
            .1
            .starts_with("elastic"));
    }
}
