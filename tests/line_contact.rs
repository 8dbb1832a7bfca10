//! The closed-form line-contact solution checked against independent references: numerical
//! quadrature of the Flamant point-force solutions, literature values, and exact properties.

use proptest::prelude::*;
use quadrature::double_exponential;
use stressfield::solution::{line_hertz, Solution};
use stressfield::stress::{Quantity, Stress};
use stressfield::study::assess::{maximum, StressMaxima};

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
pub fn flamant_quadrature(x: f64, z: f64, mu: f64, nu: f64) -> Stress {
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
    Stress {
        xx,
        yy: nu * (xx + zz),
        zz,
        yz: 0.0,
        xz,
        xy: 0.0,
    }
}

fn assert_stress_close(a: &Stress, b: &Stress, tol: f64, context: &str) {
    for (name, u, v) in [
        ("sxx", a.xx, b.xx),
        ("syy", a.yy, b.yy),
        ("szz", a.zz, b.zz),
        ("sxz", a.xz, b.xz),
    ] {
        assert!(
            (u - v).abs() <= tol,
            "{context}: {name} closed form {u} vs quadrature {v}"
        );
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

#[test]
fn literature_maxima_frictionless() {
    let solution = Solution::LineHertz {
        friction: 0.0,
        poisson: 0.3,
    };
    // Johnson (1985) §4.2(b): tau_1 = 0.300 p0 at x = 0, z = 0.786a (printed to 3 digits).
    let tau1 = maximum(&solution, Quantity::Tau1, false);
    assert!((tau1.value_over_p0 - 0.300).abs() < 5e-4, "{tau1:?}");
    assert!((tau1.z_over_a - 0.786).abs() < 5e-4, "{tau1:?}");
    // Orthogonal shear, the reversing shear of rolling contact fatigue: exactly p0/4 at
    // x = ±(√3/2)a, z = a/2 (Johnson §4.2(b) quotes 0.25 p0 at x = ±0.87a, z = 0.5a).
    let ortho = maximum(&solution, Quantity::OrthogonalShear, false);
    assert!((ortho.value_over_p0 - 0.25).abs() < 1e-12, "{ortho:?}");
    assert!(
        (ortho.x_over_a.abs() - 3f64.sqrt() / 2.0).abs() < 1e-6,
        "{ortho:?}"
    );
    assert!((ortho.z_over_a - 0.5).abs() < 1e-6, "{ortho:?}");
    // Von Mises, nu = 0.3: first yield at p0 = 1.79 Y, at z = 0.70a (Johnson §6.2).
    let vm = maximum(&solution, Quantity::VonMises, false);
    assert!((1.0 / vm.value_over_p0 - 1.79).abs() < 5e-3, "{vm:?}");
    assert!((vm.z_over_a - 0.70).abs() < 5e-3, "{vm:?}");
    assert!(vm.x_over_a.abs() < 1e-6);
    // Tresca: first yield at p0 = 3.3 k = 1.67 Y (Johnson §6.2); k = Y/2 = tau_max.
    let tresca = maximum(&solution, Quantity::MaxShear, false);
    assert!(
        (0.5 / tresca.value_over_p0 - 1.67).abs() < 5e-3,
        "{tresca:?}"
    );
}

#[test]
fn friction_moves_the_von_mises_maximum_to_the_surface() {
    let mut previous_depth = f64::INFINITY;
    let mut reached_surface_at = None;
    for step in 0..=10 {
        let mu = 0.05 * f64::from(step);
        let solution = Solution::LineHertz {
            friction: mu,
            poisson: 0.3,
        };
        let maxima = StressMaxima::of(&solution);
        let depth = maxima.von_mises.z_over_a;
        assert!(
            depth <= previous_depth + 1e-9,
            "mu = {mu}: depth {depth} > {previous_depth}"
        );
        previous_depth = depth;
        if maxima.yield_starts_at_surface() && reached_surface_at.is_none() {
            reached_surface_at = Some(mu);
        }
    }
    // Johnson (1985) §7.2: the maximum reaches the surface for mu of about 0.3.
    let mu = reached_surface_at.expect("surface reached by mu = 0.5");
    assert!(
        (0.25..=0.35).contains(&mu),
        "reached the surface at mu = {mu}"
    );
}

/// Divergence of the stress by central differences: d sxx/dx + d sxz/dz and
/// d sxz/dx + d szz/dz (equilibrium without body force).
fn divergence(x: f64, z: f64, mu: f64) -> (f64, f64) {
    let h = 1e-4;
    let s = |x, z| line_hertz::stress_over_p0(x, z, mu, 0.3);
    let (xp, xm, zp, zm) = (s(x + h, z), s(x - h, z), s(x, z + h), s(x, z - h));
    (
        (xp.xx - xm.xx) / (2.0 * h) + (zp.xz - zm.xz) / (2.0 * h),
        (xp.xz - xm.xz) / (2.0 * h) + (zp.zz - zm.zz) / (2.0 * h),
    )
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]

    #[test]
    fn equilibrium_holds_inside_the_body(x in -4.0f64..4.0, z in 0.05f64..4.0, mu in 0.0f64..0.8) {
        let (fx, fz) = divergence(x, z, mu);
        // Truncation error h^2 * (third derivative) with h = 1e-4 and z >= 0.05: below 1e-5 p0/a.
        prop_assert!(fx.abs() < 1e-5 && fz.abs() < 1e-5, "x={} z={} mu={}: ({}, {})", x, z, mu, fx, fz);
    }

    #[test]
    fn surface_boundary_conditions(x in -5.0f64..5.0, mu in 0.0f64..0.8) {
        let s = line_hertz::stress_over_p0(x, 0.0, mu, 0.3);
        let p = if x.abs() < 1.0 { (1.0 - x * x).sqrt() } else { 0.0 };
        prop_assert!((s.zz + p).abs() < 1e-13);
        prop_assert!((s.xz + mu * p).abs() < 1e-13);
        if x.abs() <= 1.0 {
            prop_assert!((s.xx - (-p - 2.0 * mu * x)).abs() < 1e-13);
        }
    }

    #[test]
    fn frictionless_field_is_symmetric(x in 0.0f64..5.0, z in 0.0f64..5.0) {
        let right = line_hertz::stress_over_p0(x, z, 0.0, 0.3);
        let left = line_hertz::stress_over_p0(-x, z, 0.0, 0.3);
        prop_assert!((right.xx - left.xx).abs() < 1e-14);
        prop_assert!((right.zz - left.zz).abs() < 1e-14);
        prop_assert!((right.xz + left.xz).abs() < 1e-14);
    }

    #[test]
    fn linear_in_friction(x in -4.0f64..4.0, z in 0.0f64..4.0, mu in 0.0f64..1.0) {
        let s0 = line_hertz::stress_over_p0(x, z, 0.0, 0.3);
        let s1 = line_hertz::stress_over_p0(x, z, 1.0, 0.3);
        let s = line_hertz::stress_over_p0(x, z, mu, 0.3);
        for (v, a, b) in [(s.xx, s0.xx, s1.xx), (s.zz, s0.zz, s1.zz), (s.xz, s0.xz, s1.xz), (s.yy, s0.yy, s1.yy)] {
            prop_assert!((v - (a + mu * (b - a))).abs() < 1e-13);
        }
    }

    #[test]
    fn finite_everywhere(x in -1e6f64..1e6, z in 0.0f64..1e6, mu in 0.0f64..1.0) {
        let s = line_hertz::stress_over_p0(x, z, mu, 0.3);
        prop_assert!([s.xx, s.yy, s.zz, s.xz].iter().all(|v| v.is_finite()));
        prop_assert!(s.von_mises().is_finite());
    }
}

#[test]
fn contact_edges_and_neighbourhood_are_finite_and_continuous() {
    for edge in [-1.0f64, 1.0] {
        let at = line_hertz::stress_over_p0(edge, 0.0, 0.3, 0.3);
        for (dx, dz) in [
            (1e-9, 0.0),
            (-1e-9, 0.0),
            (0.0, 1e-9),
            (1e-9, 1e-9),
            (-1e-9, 1e-9),
        ] {
            let near = line_hertz::stress_over_p0(edge + dx, dz, 0.3, 0.3);
            // Stresses are continuous at the edge (their gradient is not): |ds| ~ sqrt(distance).
            assert!(
                (near.xx - at.xx).abs() < 1e-3
                    && (near.zz - at.zz).abs() < 1e-3
                    && (near.xz - at.xz).abs() < 1e-3,
                "edge {edge} + ({dx}, {dz})"
            );
        }
    }
}

/// Flamant kernels integrated numerically over a strip, for the strip influence coefficients.
fn strip_by_quadrature(x: f64, z: f64, s1: f64, s2: f64) -> ([f64; 3], [f64; 3]) {
    let integrate = |f: &dyn Fn(f64) -> f64| {
        let split = x.clamp(s1, s2);
        let mut total = 0.0;
        for (lo, hi) in [(s1, split), (split, s2)] {
            if hi > lo {
                total += double_exponential::integrate(f, lo, hi, 1e-14).integral;
            }
        }
        total
    };
    let kernel = |s: f64, which: usize| {
        let dx = x - s;
        let r2 = dx * dx + z * z;
        let f = -2.0 / std::f64::consts::PI / (r2 * r2);
        f * match which {
            0 => dx * dx * z,
            1 => z * z * z,
            2 => dx * z * z,
            _ => dx * dx * dx,
        }
    };
    let n = [0, 1, 2].map(|k| integrate(&|s| kernel(s, k)));
    let t = [3, 2, 0].map(|k| integrate(&|s| kernel(s, k)));
    (n, t)
}

#[test]
fn strip_influence_coefficients_match_flamant_quadrature() {
    use stressfield::solution::strip::uniform_strip;
    for (s1, s2) in [(-1.0, 1.0), (0.2, 0.25), (-3.0, -1.5)] {
        for x in [-4.0, -1.0, -0.3, 0.0, 0.22, 0.9, 2.5] {
            for z in [0.01, 0.1, 0.5, 2.0, 7.0] {
                let (normal, tangential) = uniform_strip(x, z, s1, s2);
                let (qn, qt) = strip_by_quadrature(x, z, s1, s2);
                for k in 0..3 {
                    assert!(
                        (normal[k] - qn[k]).abs() < 1e-10,
                        "normal {k} at ({x}, {z}) strip [{s1}, {s2}]: {} vs {}",
                        normal[k],
                        qn[k]
                    );
                    assert!(
                        (tangential[k] - qt[k]).abs() < 1e-10,
                        "tangential {k} at ({x}, {z}) strip [{s1}, {s2}]: {} vs {}",
                        tangential[k],
                        qt[k]
                    );
                }
            }
        }
    }
}
