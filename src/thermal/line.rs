//! Line contacts (plane problems): the steady temperature rise of a half-space under a band
//! source moving over it, from Jaeger's moving line source integrated over uniformly heated
//! strips.
//!
//! A line source of `q'` W per metre of length moving at speed `V` in +x over the adiabatic
//! surface raises the temperature, in its frame, by (Carslaw & Jaeger 1959, §10.7; Jaeger
//! 1942)
//!
//! ```text
//! θ(x, z) = q' / (π K) · exp(-u x) K0(u r),   r = √(x² + z²),   u = V / (2κ),
//! ```
//!
//! written `exp(-u (x + r)) · [e^(u r) K0(u r)]` so that neither factor overflows. A stationary
//! band (`u = 0`) has no steady temperature in a plane problem (it grows like the logarithm of
//! time), so the speed of a line contact over each heated body must be positive.
//!
//! A strip of width `h` with unit flux gives `K θ = (1/π) ∫ exp(-u s) K0(u √(s² + z²)) ds` over
//! the strip's offsets `s` from the point; the logarithmic singularity at `s = 0` on the
//! surface is integrated by adaptive Gauss–Kronrod bisection. The strips are few (a line
//! contact's grid is one row), so the convolution is summed directly.
//!
//! ## References
//! - H. S. Carslaw, J. C. Jaeger, *Conduction of Heat in Solids*, 2nd ed., Oxford (1959).
//! - J. C. Jaeger, *Proc. R. Soc. N. S. W.* 76 (1942).

use std::f64::consts::PI;

use rayon::prelude::*;

use super::special::{bessel_k0_scaled, integrate};

/// `K θ` at depth `z` under the centre of the strip offset by `offset` strips of width `h`
/// from a strip of unit flux moving with `u = V / (2κ) > 0`.
pub fn strip_temperature(offset: i64, h: f64, z: f64, u: f64) -> f64 {
    let x = offset as f64 * h;
    let (a, b) = (x - 0.5 * h, x + 0.5 * h);
    let f = |s: f64| {
        let r = s.hypot(z);
        if r == 0.0 {
            return 0.0;
        }
        (-u * (s + r)).exp() * bessel_k0_scaled(u * r)
    };
    // The scale of the integrand near the source, for an absolute tolerance.
    let tolerance = 1e-11 * h * (1.0 + bessel_k0_scaled(u * h.max(z)).abs());
    let value = if a < 0.0 && b > 0.0 {
        integrate(f, a, 0.0, tolerance) + integrate(f, 0.0, b, tolerance)
    } else {
        integrate(f, a, b, tolerance)
    };
    value / PI
}

/// The temperature rise at one depth of a half-space under a flux on a row of strips.
pub struct LineTemperature {
    /// `K θ` for the offsets `-(n - 1)..n`, index `offset + n - 1`.
    kernel: Vec<f64>,
    n: usize,
    scale: f64,
}

impl LineTemperature {
    /// For `n` strips of width `h` (m) at depth `z`, `u = V / (2κ) > 0` and conductivity `K`.
    pub fn new(n: usize, h: f64, z: f64, u: f64, conductivity_w_per_m_k: f64) -> Self {
        let kernel = (0..(2 * n).saturating_sub(1))
            .into_par_iter()
            .map(|k| strip_temperature(k as i64 - n as i64 + 1, h, z, u))
            .collect();
        Self {
            kernel,
            n,
            scale: 1.0 / conductivity_w_per_m_k,
        }
    }

    /// The temperature rise (K) at the strips' centres under `flux` (W/m², `n` values).
    pub fn apply(&self, flux: &[f64]) -> Vec<f64> {
        let n = self.n;
        (0..n)
            .into_par_iter()
            .map(|i| {
                let sum: f64 = flux
                    .iter()
                    .enumerate()
                    .map(|(j, q)| q * self.kernel[i + n - 1 - j])
                    .sum();
                sum * self.scale
            })
            .collect()
    }
}
