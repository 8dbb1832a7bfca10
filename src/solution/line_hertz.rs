//! Exact stresses under a sliding Hertzian line contact (plane strain).

use crate::stress::Stress;

/// Stress (in units of `p0`) at `(x, z)` (in units of `a`) in an elastic half-plane loaded by
/// the Hertz pressure `p(x) = p0 sqrt(1 - x^2/a^2)` and the sliding traction `q(x) = mu p(x)`,
/// which acts on the body's surface in +x.
///
/// Closed form of McEwen (1949) and Smith & Liu (1953), as set out in Johnson, *Contact
/// Mechanics* (1985), §7.2 (tangential part) and §4.2 (normal part). With `m >= 0` and `n`
/// having the sign of `x`, defined by
///
/// ```text
/// m^2 = ½ [ sqrt((a^2 - x^2 + z^2)^2 + 4 x^2 z^2) + (a^2 - x^2 + z^2) ]
/// n^2 = ½ [ sqrt((a^2 - x^2 + z^2)^2 + 4 x^2 z^2) - (a^2 - x^2 + z^2) ]
/// ```
///
/// i.e. `m - i n = sqrt(a^2 - (x + i z)^2)`, the stresses (a = 1, p0 = 1, D = m^2 + n^2) are
///
/// ```text
/// pressure: sxx = -[m (1 + (z^2 + n^2)/D) - 2z]    szz = -m (1 - (z^2 + n^2)/D)
///           sxz = -n (m^2 - z^2)/D
/// traction: sxx = mu [n (2 - (z^2 - m^2)/D) - 2x]  szz = -mu n (m^2 - z^2)/D
///           sxz = -mu [m (1 + (z^2 + n^2)/D) - 2z]
/// ```
///
/// with `syy = nu (sxx + szz)` (plane strain). The signs are those of this crate (tension
/// positive, z into the body, traction in +x); they were checked against quadrature of the
/// Flamant point-force solutions (see the tests).
///
/// ## Evaluation without cancellation
/// Far from the contact `m ~ z` and `n ~ x`, and the brackets above lose all their digits. They
/// are rewritten exactly in terms of `m - z` and `n - x`, which follow without cancellation from
/// `(m - z) - i (n - x) = a^2 / ((m + z) - i (n + x))` (because `(m - i n)^2 - (z - i x)^2 = a^2`):
///
/// ```text
/// m (1 + (z^2 + n^2)/D) - 2z      = (m - z) (m (m - z) + 2 n^2) / D
/// n (2 - (z^2 - m^2)/D) - 2x      = n (m - z) (m + z) / D + 2 (n - x)
/// ```
///
/// At the contact edges (`x = ±a, z = 0`) `D = 0`; every ratio there has a vanishing numerator
/// of higher order and its limit, zero, is used. The result is finite for all `z >= 0`
/// with `|x|, |z| < 1e150`.
///
/// ## References
/// - E. McEwen, Stresses in elastic cylinders in contact along a generatrix, *Phil. Mag.* 40
///   (1949) 454–459.
/// - J. O. Smith and C. K. Liu, Stresses due to tangential and normal loads on an elastic solid
///   with application to some contact stress problems, *J. Appl. Mech.* 20 (1953) 157–166.
/// - K. L. Johnson, *Contact Mechanics*, Cambridge University Press (1985), §4.2 and §7.2.
#[inline]
pub fn stress_over_p0(x: f64, z: f64, mu: f64, nu: f64) -> Stress {
    let (m, n) = m_and_n(x, z);
    // (m - z) - i (n - x) = 1 / ((m + z) - i (n + x))
    let sum_m = m + z;
    let sum_n = n + x;
    let inv_sum = 1.0 / (sum_m * sum_m + sum_n * sum_n);
    let dm = sum_m * inv_sum; // m - z >= 0
    let dn = -sum_n * inv_sum; // n - x
    let d = m * m + n * n;
    let inv_d = if d > 0.0 { 1.0 / d } else { 0.0 };

    let bracket_m = dm * (m * dm + 2.0 * n * n) * inv_d; // m (1 + (z²+n²)/D) - 2z
    let m2_minus_z2 = dm * sum_m * inv_d; // (m² - z²)/D

    let xx = -bracket_m + mu * (n * m2_minus_z2 + 2.0 * dn);
    let zz = -m * m2_minus_z2 - mu * n * m2_minus_z2;
    let xz = -n * m2_minus_z2 - mu * bracket_m;
    Stress::plane_strain(xx, zz, xz, nu)
}

/// Real and imaginary parts of `sqrt(1 - (x + i z)^2) = m - i n`, with `m >= 0` and `n` of the
/// sign of `x`, computed without cancellation (the `m`, `n` of Johnson 1985, §7.2).
#[inline(always)]
fn m_and_n(x: f64, z: f64) -> (f64, f64) {
    let s = 1.0 - x * x + z * z;
    let xz = x * z;
    let r = (s * s + 4.0 * xz * xz).sqrt();
    // The larger of m, |n| from the sum (no cancellation), the smaller from m |n| = |x z|.
    // Written with selects instead of branches so that rows vectorise.
    let large = (0.5 * (r + s.abs())).sqrt();
    let small = xz.abs() / large.max(f64::MIN_POSITIVE);
    let (m, n_abs) = if s >= 0.0 {
        (large, small)
    } else {
        (small, large)
    };
    (m, n_abs.copysign(x))
}

/// Surface tractions of the Hertz line contact: `(p/p0, q/p0)` at `x/a`.
pub fn surface_traction_over_p0(x: f64, mu: f64) -> (f64, f64) {
    let p = if x.abs() < 1.0 {
        (1.0 - x * x).sqrt()
    } else {
        0.0
    };
    (p, mu * p)
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    #[test]
    fn surface_inside_contact_is_exact() {
        for mu in [0.0, 0.2, 0.5] {
            for i in 0..=40 {
                let x = -1.0 + 2.0 * f64::from(i) / 40.0;
                let s = stress_over_p0(x, 0.0, mu, 0.3);
                let (p, q) = surface_traction_over_p0(x, mu);
                assert_relative_eq!(s.zz, -p, epsilon = 1e-14);
                assert_relative_eq!(s.xz, -q, epsilon = 1e-14);
                assert_relative_eq!(s.xx, -p - 2.0 * mu * x, epsilon = 1e-14);
            }
        }
    }

    #[test]
    fn trailing_edge_tension_is_two_mu_p0() {
        let s = stress_over_p0(-1.0, 0.0, 0.3, 0.3);
        assert_relative_eq!(s.xx, 0.6, epsilon = 1e-15);
        let s = stress_over_p0(1.0, 0.0, 0.3, 0.3);
        assert_relative_eq!(s.xx, -0.6, epsilon = 1e-15);
    }

    #[test]
    fn surface_outside_contact_is_traction_free() {
        for x in [1.0 + 1e-12, 1.5, 3.0, -2.0, 1e6] {
            let s = stress_over_p0(x, 0.0, 0.4, 0.3);
            assert_eq!(s.zz, 0.0);
            assert_eq!(s.xz, 0.0);
            // Outside, only the traction contributes: sxx = 2 mu (n - x), n = sign(x) sqrt(x²-1).
            let expected = 2.0 * 0.4 * (x.signum() * (x * x - 1.0).sqrt() - x);
            assert_relative_eq!(s.xx, expected, epsilon = 1e-9, max_relative = 1e-9);
        }
    }

    #[test]
    fn axis_stresses_match_johnson_closed_form() {
        // On x = 0 with mu = 0 (Johnson 1985, §4.2(b)): sxx = -(p0/a)[(a²+2z²)/sqrt(a²+z²) - 2z],
        // szz = -p0 a / sqrt(a² + z²), sxz = 0.
        for i in 0..=50 {
            let z = f64::from(i) * 0.1;
            let s = stress_over_p0(0.0, z, 0.0, 0.3);
            let root = (1.0 + z * z).sqrt();
            assert_relative_eq!(s.zz, -1.0 / root, epsilon = 1e-14);
            assert_relative_eq!(
                s.xx,
                -((1.0 + 2.0 * z * z) / root - 2.0 * z),
                epsilon = 1e-14
            );
            assert_eq!(s.xz, 0.0);
        }
    }

    #[test]
    fn far_field_is_finite_and_decays_like_flamant() {
        // Far away the contact acts as a point force P = pi a p0 / 2 (and Q = mu P):
        // Flamant gives szz = -(2P/pi) z^3 / rho^4 = -p0 a z^3 / rho^4 for the normal part.
        let (x, z) = (3.0e4, 4.0e4);
        let s = stress_over_p0(x, z, 0.0, 0.3);
        let rho2 = x * x + z * z;
        assert_relative_eq!(s.zz, -z.powi(3) / (rho2 * rho2), max_relative = 1e-7);
        assert_relative_eq!(s.xx, -x * x * z / (rho2 * rho2), max_relative = 1e-7);
        assert_relative_eq!(s.xz, -x * z * z / (rho2 * rho2), max_relative = 1e-7);
    }
}
