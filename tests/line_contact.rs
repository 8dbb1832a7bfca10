//! The closed-form line-contact solution checked against independent references: numerical
//! quadrature of the Flamant point-force solutions, literature values, and exact properties.

use approx::assert_relative_eq;
use proptest::prelude::*;
use quadrature::double_exponential;
use stressfield::solution::line_hertz;
use stressfield::stress::Stress;

/// Stress at `(x, z)` by quadrature of the Flamant solutions over the Hertz tractions
/// `p = sqrt(1 - s^2)`, `q = mu p` (a = 1, p0 = 1).
///
/// Flamant (1892), see Johnson, Contact Mechanics (1985), §2.2: a normal force P per unit
/// length pressing on the surface at the origin gives
/// `sxx = -(2P/pi) x^2 z / r^4`, `szz = -(2P/pi) z^3 / r^4`, `sxz = -(2P/pi) x z^2 / r^4`,
/// and a tangential force Q in +x gives
/// `sxx = -(2Q/pi) x^3 / r^4`, `szz = -(2Q/pi) x z^2 / r^4`, `sxz = -(2Q/pi) x^2 z / r^4`.
///
/// The substitution `s = sin(t)` removes the square-root end singularities; the integral is
/// split at the field point, where the kernel peaks, and each part integrated with tanh-sinh,
/// which clusters its nodes at the ends of each part.
fn flamant_quadrature(x: f64, z: f64, mu: f64, nu: f64) -> Stress {
    let component = |which: usize| {
        let integrand = |t: f64| {
            let s = t.sin();
            let p = t.cos(); // sqrt(1 - s^2)
            let ds = t.cos();
            let dx = x - s;
            let r2 = dx * dx + z * z;
            let f = -2.0 / std::f64::consts::PI / (r2 * r2);
            let (normal, tangential) = match which {
                0 => (dx * dx * z, dx * dx * dx),
                1 => (z * z * z, dx * z * z),
                _ => (dx * z * z, dx * dx * z),
            };
            f * p * (normal + mu * tangential) * ds
        };
        let half_pi = std::f64::consts::FRAC_PI_2;
        let split = x.clamp(-1.0, 1.0).asin();
        let mut total = 0.0;
        for (lo, hi) in [(-half_pi, split), (split, half_pi)] {
            if hi > lo {
                total += double_exponential::integrate(integrand, lo, hi, 1e-13).integral;
            }
        }
        total
    };
    let xx = component(0);
    let zz = component(1);
    let xz = component(2);
    Stress { xx, yy: nu * (xx + zz), zz, yz: 0.0, xz, xy: 0.0 }
}

fn assert_stress_close(a: &Stress, b: &Stress, tol: f64, context: &str) {
    for (name, u, v) in [
        ("sxx", a.xx, b.xx),
        ("syy", a.yy, b.yy),
        ("szz", a.zz, b.zz),
        ("sxz", a.xz, b.xz),
    ] {
        assert!((u - v).abs() <= tol, "{context}: {name} closed form {u} vs quadrature {v}");
    }
}

#[test]
fn closed_form_matches_flamant_quadrature_to_1e8_p0() {
    let mut checked = 0;
    for mu in [0.0, 0.25, 0.6] {
        for ix in 0..=24 {
            let x = -3.0 + 0.25 * f64::from(ix);
            for z in [0.02, 0.05, 0.1, 0.3, 0.5, 0.786, 1.0, 1.7, 3.0, 6.0] {
                let closed = line_hertz::stress_over_p0(x, z, mu, 0.3);
                let quad = flamant_quadrature(x, z, mu, 0.3);
                assert_stress_close(&closed, &quad, 1e-8, &format!("x={x} z={z} mu={mu}"));
                checked += 1;
            }
        }
    }
    assert_eq!(checked, 3 * 25 * 10);
}
