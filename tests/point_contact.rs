//! The closed-form point-contact (sphere) solution checked against independent references:
//! numerical quadrature of the Boussinesq and Cerruti point-force solutions over the Hertz
//! tractions, the point-force solutions themselves far away, and equilibrium.

use proptest::prelude::*;
use quadrature::double_exponential;
use stressfield::solution::sphere_hertz;
use stressfield::stress::Stress;

/// Stress at `(x, y, z)` of a unit normal force pressing on the surface at the origin
/// (Boussinesq) plus `mu` times a unit tangential force in +x (Cerruti), in the crate's
/// convention (tension positive, z into the body): [`crate::patch::point_forces`], whose doc
/// comment gives the formulas (Johnson, *Contact Mechanics* (1985), §3.2).
fn point_force(x: f64, y: f64, z: f64, mu: f64, nu: f64) -> [f64; 6] {
    let (normal, tangential) = crate::patch::point_forces(x, y, z, nu);
    std::array::from_fn(|i| normal[i] + mu * tangential[i])
}

fn components(s: &Stress) -> [f64; 6] {
    [s.xx, s.yy, s.zz, s.yz, s.xz, s.xy]
}

const NAMES: [&str; 6] = ["sxx", "syy", "szz", "syz", "sxz", "sxy"];

/// One stress component at `(x, y, z)` by quadrature of [`point_force`] over the Hertz
/// tractions `p = sqrt(1 - r^2)`, `q = mu p` on the unit disk (a = 1, p0 = 1).
///
/// Polar coordinates about the contact centre with `r = sin(t)`, so that
/// `p r dr = cos^2(t) sin(t) dt` has no square-root edge singularity. The kernel peaks where
/// the source lies under the field point, at `t = asin(r0)` and at the field point's azimuth;
/// both ranges are split there, so the peaks fall on the ends of parts, where tanh-sinh
/// clusters its nodes. The parts are also kept short (a quarter turn in angle, `pi/8` in
/// `t`): on one long part the integrator's convergence test was once fooled (it stopped
/// after 25 evaluations, 4e-8 off, claiming 1e-12).
fn quadrature_component(x: f64, y: f64, z: f64, mu: f64, nu: f64, which: usize) -> f64 {
    use std::f64::consts::FRAC_PI_2;
    let r0 = x.hypot(y);
    let azimuth = y.atan2(x);
    let ring = |t: f64| {
        let (r, cos_t) = (t.sin(), t.cos());
        let inner = |theta: f64| {
            let (sin, cos) = theta.sin_cos();
            point_force(x - r * cos, y - r * sin, z, mu, nu)[which]
        };
        let mut around = 0.0;
        for k in 0..4 {
            let from = azimuth + FRAC_PI_2 * f64::from(k);
            around += double_exponential::integrate(inner, from, from + FRAC_PI_2, 1e-13).integral;
        }
        around * cos_t * cos_t * r
    };
    let mut cuts: Vec<f64> = (0..=8).map(|k| FRAC_PI_2 * f64::from(k) / 8.0).collect();
    if r0 < 1.0 {
        cuts.push(r0.asin());
        cuts.sort_by(f64::total_cmp);
    }
    cuts.windows(2)
        .filter(|part| part[1] > part[0])
        .map(|part| double_exponential::integrate(ring, part[0], part[1], 1e-13).integral)
        .sum()
}

#[test]
fn closed_form_matches_boussinesq_cerruti_quadrature_to_1e9_p0() {
    let mut checked = 0;
    let mut worst = 0.0f64;
    // 128 points: z from 0.1 to 3, under the contact and outside its footprint, all
    // directions; friction and Poisson's ratio varied from point to point.
    for k in 0..128 {
        let f = f64::from(k);
        let r0 = 2.6 * (0.618_034 * f + 0.1).fract();
        let azimuth = std::f64::consts::TAU * (0.414_214 * f).fract();
        let z = 0.1 + 2.9 * (0.732_051 * f + 0.05).fract();
        let mu = [0.0, 0.2, 0.5, 1.0][k as usize % 4];
        let nu = [0.0, 0.3, 0.45, 0.5, 0.25][k as usize % 5];
        let (x, y) = (r0 * azimuth.cos(), r0 * azimuth.sin());
        let closed = components(&sphere_hertz::stress_over_p0(x, y, z, mu, nu));
        for (which, name) in NAMES.iter().enumerate() {
            let quad = quadrature_component(x, y, z, mu, nu, which);
            let difference = (closed[which] - quad).abs();
            worst = worst.max(difference);
            assert!(
                difference <= 1e-9,
                "({x}, {y}, {z}) mu={mu} nu={nu}: {name} closed form {} vs quadrature {quad}",
                closed[which]
            );
        }
        checked += 1;
    }
    assert_eq!(checked, 128);
    // The quadrature itself is good to about 1e-11; see the figure with --nocapture.
    eprintln!("closed form vs quadrature: max |difference| = {worst:.1e} p0");
}

#[test]
fn far_field_tends_to_the_point_force_solutions() {
    // Far away the Hertz tractions act as the forces P = 2 pi a^2 p0 / 3 and Q = mu P; the
    // relative difference is O((a/R)^2), about 1e-8 at R = 1e4 and 1e-12 at R = 1e6.
    let force = 2.0 * std::f64::consts::PI / 3.0;
    for distance in [1e4, 1e5, 1e6] {
        for k in 0..24 {
            let polar = 0.1 + 1.3 * (0.618_034 * f64::from(k)).fract(); // from the z axis
            let azimuth = std::f64::consts::TAU * (0.414_214 * f64::from(k)).fract();
            let x = distance * polar.sin() * azimuth.cos();
            let y = distance * polar.sin() * azimuth.sin();
            let z = distance * polar.cos();
            let mu = 0.3;
            let ours = components(&sphere_hertz::stress_over_p0(x, y, z, mu, 0.3));
            let theirs = point_force(x, y, z, mu, 0.3).map(|v| force * v);
            let scale = theirs.iter().fold(0.0f64, |m, v| m.max(v.abs()));
            for i in 0..6 {
                let context = format!("R = {distance:e}, ({x}, {y}, {z}), {}", NAMES[i]);
                assert!(
                    (ours[i] - theirs[i]).abs() <= 1e-7 * scale,
                    "{context}: {} vs {}",
                    ours[i],
                    theirs[i]
                );
                // Components that are not small by symmetry: 1e-6 relative each.
                if theirs[i].abs() > 0.05 * scale {
                    let relative = (ours[i] / theirs[i] - 1.0).abs();
                    assert!(
                        relative < 1e-6,
                        "{context}: relative difference {relative:e}"
                    );
                }
            }
        }
    }
    // On the surface far away: szz = sxz = syz = 0 exactly, and sr = (1 - 2nu)/(3 r^2) for the
    // pressure (Johnson 1985, §3.4(b)).
    for r in [1e3, 1e6] {
        let s = sphere_hertz::stress_over_p0(r, 0.0, 0.0, 0.0, 0.3);
        assert_eq!([s.zz, s.xz, s.yz], [0.0; 3]);
        let expected = 0.4 / (3.0 * r * r);
        assert!(
            (s.xx / expected - 1.0).abs() < 1e-12,
            "{} vs {expected}",
            s.xx
        );
        assert!(
            (s.yy / -expected - 1.0).abs() < 1e-12,
            "{} vs {}",
            s.yy,
            -expected
        );
    }
}

/// Divergence of the stress by central differences (equilibrium without body force).
fn divergence(x: f64, y: f64, z: f64, mu: f64, nu: f64) -> [f64; 3] {
    let h = 1e-4;
    let s = |x, y, z| sphere_hertz::stress_over_p0(x, y, z, mu, nu);
    let (xp, xm) = (s(x + h, y, z), s(x - h, y, z));
    let (yp, ym) = (s(x, y + h, z), s(x, y - h, z));
    let (zp, zm) = (s(x, y, z + h), s(x, y, z - h));
    let d = |plus: f64, minus: f64| (plus - minus) / (2.0 * h);
    [
        d(xp.xx, xm.xx) + d(yp.xy, ym.xy) + d(zp.xz, zm.xz),
        d(xp.xy, xm.xy) + d(yp.yy, ym.yy) + d(zp.yz, zm.yz),
        d(xp.xz, xm.xz) + d(yp.yz, ym.yz) + d(zp.zz, zm.zz),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(500))]

    #[test]
    fn equilibrium_holds_inside_the_body(
        x in -7.0f64..7.0,
        y in -7.0f64..7.0,
        z in 0.1f64..5.0,
        mu in 0.0f64..1.0,
        nu in 0.0f64..0.5,
    ) {
        let f = divergence(x, y, z, mu, nu);
        // Truncation h^2/6 times a third derivative (below ~1/z^4 for z >= 0.1) with h = 1e-4,
        // and rounding eps/h: together well below 1e-5 p0/a.
        prop_assert!(
            f.iter().all(|v| v.abs() < 1e-5),
            "({}, {}, {}) mu={} nu={}: {:?}", x, y, z, mu, nu, f
        );
    }

    #[test]
    fn equilibrium_holds_where_closed_form_and_far_field_meet(
        radius in 5.9f64..6.1,
        polar in 0.0f64..1.5,
        azimuth in 0.0f64..std::f64::consts::TAU,
        mu in 0.0f64..1.0,
    ) {
        let (x, y, z) = (
            radius * polar.sin() * azimuth.cos(),
            radius * polar.sin() * azimuth.sin(),
            radius * polar.cos(),
        );
        let f = divergence(x, y, z, mu, 0.3);
        prop_assert!(f.iter().all(|v| v.abs() < 1e-8), "({}, {}, {}): {:?}", x, y, z, f);
    }
}
