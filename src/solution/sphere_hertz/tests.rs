//! Tests of [`super`].

use super::*;
use approx::assert_relative_eq;

const NU: f64 = 0.3;

fn components(s: &Stress) -> [f64; 6] {
    [s.xx, s.yy, s.zz, s.yz, s.xz, s.xy]
}

/// Points on z = 0 at radius `r` and 12 angles.
fn circle(r: f64) -> impl Iterator<Item = (f64, f64)> {
    (0..12).map(move |k| {
        let angle = f64::from(k) * std::f64::consts::PI / 6.0 + 0.1;
        (r * angle.cos(), r * angle.sin())
    })
}

#[test]
fn axis_stresses_match_johnson_closed_form() {
    // Johnson (1985) §3.4(b), on r = 0: szz = -p0 a^2/(a^2 + z^2),
    // sr = stheta = -p0 (1 + nu)(1 - (z/a) atan(a/z)) + p0 a^2 / (2 (a^2 + z^2)).
    for nu in [0.0, 0.25, 0.3, 0.5] {
        for i in 0..=60 {
            let z = f64::from(i) * 0.05;
            let s = stress_over_p0(0.0, 0.0, z, 0.0, nu);
            let z_atan = if z > 0.0 { z * (1.0 / z).atan() } else { 0.0 };
            let radial = -(1.0 + nu) * (1.0 - z_atan) + 0.5 / (1.0 + z * z);
            assert_relative_eq!(s.zz, -1.0 / (1.0 + z * z), epsilon = 1e-14);
            assert_relative_eq!(s.xx, radial, epsilon = 1e-14);
            assert_relative_eq!(s.yy, radial, epsilon = 1e-14);
            assert_eq!([s.yz, s.xz, s.xy], [0.0; 3], "z = {z}");
        }
    }
}

#[test]
fn surface_stresses_match_johnson_closed_form() {
    // Johnson (1985) §3.4(b), z = 0, a = 1, p0 = 1. Inside, with c = sqrt(1 - r^2):
    // sr = (1-2nu)/3 (1 - c^3)/r^2 - c, stheta = -(1-2nu)/3 (1 - c^3)/r^2 - 2 nu c, sz = -c;
    // outside: sr = -stheta = (1-2nu)/(3 r^2). (1 - c^3)/r^2 = (1 + c + c^2)/(1 + c) exactly.
    for nu in [0.0, 0.3, 0.45] {
        let k = (1.0 - 2.0 * nu) / 3.0;
        for i in 1..=200 {
            let r = f64::from(i) * 0.015;
            let (sr, stheta, sz) = if r < 1.0 {
                let c = (1.0 - r * r).sqrt();
                let ratio = (1.0 + c + c * c) / (1.0 + c);
                (k * ratio - c, -k * ratio - 2.0 * nu * c, -c)
            } else {
                (k / (r * r), -k / (r * r), 0.0)
            };
            for (x, y) in circle(r) {
                let (cos, sin) = (x / r, y / r);
                let s = stress_over_p0(x, y, 0.0, 0.0, nu);
                let context = format!("nu = {nu}, (x, y) = ({x}, {y})");
                let expected_xx = sr * cos * cos + stheta * sin * sin;
                let expected_yy = sr * sin * sin + stheta * cos * cos;
                let expected_xy = (sr - stheta) * sin * cos;
                assert!(
                    (s.xx - expected_xx).abs() < 1e-13,
                    "{context}: sxx {}",
                    s.xx
                );
                assert!(
                    (s.yy - expected_yy).abs() < 1e-13,
                    "{context}: syy {}",
                    s.yy
                );
                assert!(
                    (s.xy - expected_xy).abs() < 1e-13,
                    "{context}: sxy {}",
                    s.xy
                );
                assert!((s.zz - sz).abs() < 1e-13, "{context}: szz {}", s.zz);
            }
        }
    }
}

#[test]
fn radial_stress_at_the_contact_edge_is_the_maximum_tension() {
    // Johnson (1985) §3.4(b): sr = (1 - 2 nu) p0 / 3 at r = a, the greatest tension. Only
    // (±1, 0) and (0, ±1) lie exactly on the edge in floating point; a point one ulp off
    // it moves the stress by about 1e-8 (the stress is Hölder-continuous there).
    for nu in [0.0, 0.3, 0.45] {
        let k = (1.0 - 2.0 * nu) / 3.0;
        for mu in [0.0, 0.4] {
            for (x, y) in [(1.0, 0.0), (-1.0, 0.0), (0.0, 1.0), (0.0, -1.0)] {
                let s = stress_over_p0(x, y, 0.0, mu, nu);
                let radial = s.xx * x * x + s.yy * y * y + 2.0 * s.xy * x * y;
                let hoop = s.xx * y * y + s.yy * x * x - 2.0 * s.xy * x * y;
                assert_eq!([s.zz, s.xz, s.yz], [0.0; 3]);
                if mu == 0.0 {
                    assert_relative_eq!(radial, k, epsilon = 1e-15);
                    assert_relative_eq!(hoop, -k, epsilon = 1e-15);
                }
            }
        }
        for (x, y) in circle(1.0) {
            let s = stress_over_p0(x, y, 0.0, 0.0, nu);
            let radial = s.xx * x * x + s.yy * y * y + 2.0 * s.xy * x * y;
            assert!((radial - k).abs() < 1e-7, "({x}, {y}): {radial}");
        }
    }
}

#[test]
fn maximum_shear_on_the_axis_is_031_p0_at_048_a() {
    // Johnson (1985) §3.4(b): (s1 - s3)/2 = 0.31 p0 at z = 0.48 a for nu = 0.3.
    let (mut best_z, mut best) = (0.0, 0.0);
    for i in 0..=20_000 {
        let z = f64::from(i) * 1e-4;
        let shear = stress_over_p0(0.0, 0.0, z, 0.0, NU).max_shear();
        if shear > best {
            (best_z, best) = (z, shear);
        }
    }
    assert!(
        (best - 0.31).abs() < 5e-3,
        "max shear {best} at z = {best_z}"
    );
    assert!(
        (best_z - 0.48).abs() < 5e-3,
        "max shear {best} at z = {best_z}"
    );
}

#[test]
fn surface_boundary_conditions_hold_inside_and_outside() {
    for mu in [0.0, 0.1, 0.3, 0.8] {
        for i in 0..=160 {
            let r = f64::from(i) * 0.025;
            for (x, y) in circle(r) {
                let s = stress_over_p0(x, y, 0.0, mu, NU);
                let (p, q) = surface_traction_over_p0(x, y, mu);
                let context = format!("mu = {mu}, (x, y) = ({x}, {y})");
                assert!((s.zz + p).abs() < 1e-12, "{context}: szz {} p {p}", s.zz);
                assert!((s.xz + q).abs() < 1e-12, "{context}: sxz {} q {q}", s.xz);
                assert!(s.yz.abs() < 1e-12, "{context}: syz {}", s.yz);
            }
        }
    }
    for (x, y) in [(1.0, 0.0), (0.0, -1.0), (0.6, 0.8), (1e3, 2e3), (-7.0, 1e6)] {
        let s = stress_over_p0(x, y, 0.0, 0.5, NU);
        assert_eq!([s.zz, s.xz, s.yz], [0.0; 3], "({x}, {y})");
    }
}

#[test]
fn symmetric_in_y_for_any_friction_and_in_x_without() {
    for mu in [0.0, 0.2, 0.7] {
        for x in [-2.5, -1.0, -0.3, 0.0, 0.4, 1.0, 1.7, 9.0] {
            for y in [0.05, 0.5, 1.0, 1.3, 3.0, 8.0] {
                for z in [0.0, 0.1, 0.5, 1.0, 2.5, 7.0] {
                    let a = components(&stress_over_p0(x, y, z, mu, NU));
                    let b = components(&stress_over_p0(x, -y, z, mu, NU));
                    // xx, yy, zz, xz even in y; yz, xy odd.
                    for (k, sign) in [1.0, 1.0, 1.0, -1.0, 1.0, -1.0].into_iter().enumerate() {
                        assert!((a[k] - sign * b[k]).abs() < 1e-15, "y: {k} at {x},{y},{z}");
                    }
                    if mu == 0.0 {
                        let c = components(&stress_over_p0(-x, y, z, mu, NU));
                        // xx, yy, zz, yz even in x; xz, xy odd.
                        for (k, sign) in [1.0, 1.0, 1.0, 1.0, -1.0, -1.0].into_iter().enumerate() {
                            assert!((a[k] - sign * c[k]).abs() < 1e-15, "x: {k} at {x},{y},{z}");
                        }
                    }
                }
            }
        }
    }
}

#[test]
fn linear_in_friction() {
    for (x, y, z) in [
        (0.3, 0.2, 0.5),
        (-1.2, 0.7, 0.0),
        (2.0, -1.0, 1.5),
        (0.0, 0.0, 0.3),
        (9.0, 2.0, 1.0),
    ] {
        let s0 = components(&stress_over_p0(x, y, z, 0.0, NU));
        let s1 = components(&stress_over_p0(x, y, z, 1.0, NU));
        for mu in [0.1, 0.35, 0.9] {
            let s = components(&stress_over_p0(x, y, z, mu, NU));
            for k in 0..6 {
                assert_relative_eq!(s[k], s0[k] + mu * (s1[k] - s0[k]), epsilon = 1e-15);
            }
        }
    }
}

#[test]
fn finite_on_axis_surface_edge_and_far_away() {
    let mut points = vec![];
    for z in [
        0.0, 1e-300, 1e-12, 1e-6, 0.5, 1.0, 5.999, 6.0, 1e3, 1e6, 1e12, 1e50,
    ] {
        points.push((0.0, 0.0, z));
    }
    for r in [
        0.0,
        1e-12,
        0.5,
        1.0 - 1e-12,
        1.0,
        1.0 + 1e-12,
        1.5,
        6.0,
        1e6,
        1e50,
    ] {
        for (x, y) in circle(r) {
            for z in [0.0, 1e-12, 1e-6] {
                points.push((x, y, z));
            }
        }
    }
    points.extend([
        (1.0, 0.0, 0.0),
        (-1.0, 0.0, 0.0),
        (0.0, 1.0, 0.0),
        (1e-12, 0.0, 0.0),
    ]);
    points.extend([(1e6, 1e6, 1e6), (-1e6, 0.0, 1.0), (3.0, 4.0, 1e-300)]);
    for (x, y, z) in points {
        for mu in [0.0, 0.4] {
            let s = stress_over_p0(x, y, z, mu, NU);
            assert!(
                components(&s).iter().all(|v| v.is_finite()) && s.von_mises().is_finite(),
                "({x}, {y}, {z}) mu = {mu}: {s:?}"
            );
        }
    }
}

#[test]
fn continuous_at_the_contact_edge() {
    let at = components(&stress_over_p0(1.0, 0.0, 0.0, 0.4, NU));
    for (dx, dy, dz) in [
        (1e-12, 0.0, 0.0),
        (-1e-12, 0.0, 0.0),
        (0.0, 0.0, 1e-12),
        (-1e-12, 1e-6, 1e-12),
    ] {
        let near = components(&stress_over_p0(1.0 + dx, dy, dz, 0.4, NU));
        for k in 0..6 {
            // The stresses are Hölder-continuous (exponent 1/2) at the edge.
            assert!(
                (near[k] - at[k]).abs() < 1e-5,
                "{k}: {} vs {}",
                near[k],
                at[k]
            );
        }
    }
}

#[test]
fn closed_form_and_far_field_quadrature_agree_where_they_meet() {
    // Both are valid near R = 6; the closed form's error grows like R^2 eps, the rule's
    // falls like (2R)^-16.
    for r in [5.0, 6.0, 8.0] {
        for k in 0..20 {
            let polar = 0.08 * f64::from(k);
            let azimuth = 0.7 * f64::from(k);
            let (x, y, z) = (
                r * polar.sin() * azimuth.cos(),
                r * polar.sin() * azimuth.sin(),
                r * polar.cos(),
            );
            let t = x * x + y * y;
            let near = PotentialDerivatives::closed_form(x, y, z).stress(x, y, z, t, 0.5, NU);
            let far = PotentialDerivatives::far_field(t, z).stress(x, y, z, t, 0.5, NU);
            let (near, far) = (components(&near), components(&far));
            let scale = near.iter().fold(0.0f64, |m, v| m.max(v.abs()));
            for i in 0..6 {
                assert!(
                    (near[i] - far[i]).abs() < 1e-12 * scale,
                    "R = {r}, {i}: {near:?} {far:?}"
                );
            }
        }
    }
}

#[test]
fn gauss_jacobi_rule_is_exact_to_degree_15() {
    // ∫_0^1 (1 - s^2) s^(2k) ds = 1/(2k+1) - 1/(2k+3).
    for k in 0..8 {
        let rule: f64 = GAUSS_JACOBI_NODES
            .iter()
            .zip(&GAUSS_JACOBI_WEIGHTS)
            .map(|(&s, &w)| w * s.powi(2 * k))
            .sum();
        let exact = 1.0 / f64::from(2 * k + 1) - 1.0 / f64::from(2 * k + 3);
        assert_relative_eq!(rule, exact, max_relative = 1e-15);
    }
}

/// Hamilton's (1983) explicit equations for `a = 1`, `p0 = 1`, in the form of the
/// ContactMechanics package (`ReferenceSolutions/Hertz.py`), off the axis only.
fn hamilton_explicit(x: f64, y: f64, z: f64, mu: f64, nu: f64) -> [f64; 6] {
    let (x2, y2, z2) = (x * x, y * y, z * z);
    let r2 = x2 + y2;
    let r4 = r2 * r2;
    let a = r2 + z2 - 1.0;
    let s = (a * a + 4.0 * z2).sqrt();
    let m = ((s + a) / 2.0).sqrt();
    let n = ((s - a) / 2.0).sqrt();
    let phi = (1.0 / m).atan();
    let g = m * m - n * n + z * m - n;
    let h = 2.0 * m * n + m + z * n;
    let c = 1.0 - 2.0 * nu;

    let bracket = (1.0 - nu) * n * z2 - c / 3.0 * (n * s + 2.0 * a * n + 1.0) - nu * m * z;
    let pressure = [
        (1.0 + nu) * z * phi
            + ((y2 - x2) / r2 * bracket - n * (x2 + 2.0 * nu * y2) - m * x2 * z / s) / r2,
        (1.0 + nu) * z * phi
            + ((x2 - y2) / r2 * bracket - n * (y2 + 2.0 * nu * x2) - m * y2 * z / s) / r2,
        -n + z * m / s,
        -z * (y * n / s - y * z * h / (g * g + h * h)),
        -z * (x * n / s - x * z * h / (g * g + h * h)),
        x * y * c / r4 * (-n * r2 + 2.0 / 3.0 * n * (s + 2.0 * a) - z * (z * n + m) + 2.0 / 3.0)
            + x * y * z / r4 * (-m * r2 / s - z * n + m),
    ];

    let fx = 1.5 - 2.0 * x2 / r2;
    let hx = 0.5 - 2.0 * x2 / r2;
    let hy = 0.5 - 2.0 * y2 / r2;
    let traction = [
        -x * (nu / 4.0 + 1.0) * phi
            + x * m / r4
                * (fx * (s * nu - 2.0 * a * nu + z2) + x2 * z2 / s + 1.75 * nu * r2
                    - 2.0 * nu * x2
                    + r2)
            + x * z * n / r4
                * (fx * (-s / 6.0 * c - a / 3.0 * c - (z2 + 3.0) / 2.0) + x2 / s
                    - nu * r2 / 4.0
                    - 1.75 * r2)
            + 4.0 * x * z / (3.0 * r4) * fx * c,
        -0.75 * nu * x * phi
            + x * m / r4 * (hy * (nu * (s - 2.0 * a + r2) + z2) + y2 * z2 / s + 0.75 * nu * r2)
            + z * x * n / r4
                * (hy * (-s / 6.0 * c - a / 3.0 * c - z2 / 2.0 - 1.5) + y2 / s
                    - 0.75 * nu * r2
                    - r2 / 4.0)
            + 4.0 / 3.0 * z * x / r4 * hy * c,
        z * x * n / (2.0 * r2) * (1.0 - (r2 + z2 + 1.0) / s),
        x * y * z / (2.0 * r4)
            * (m * (0.5 + (z2 / 2.0 - 1.5 - r2 / 2.0) / s)
                + z * n / 2.0 * (-3.0 + (5.0 + z2 + r2) / s)),
        1.5 * z * phi
            + z * m / r2 * (1.0 + x2 / r2 - x2 / s)
            + n / r2 * (-0.75 * (s + 2.0 * a) + z2 - 0.75 - r2 / 4.0 + z2 / 2.0 * hx),
        y / 2.0 * (nu / 2.0 - 1.0) * phi
            + y * m / r4
                * (x2 * z2 / s
                    + nu * ((s - 2.0 * a) * hx - 2.0 * x2 + r2 / 4.0)
                    + r2 / 2.0
                    + z2 * hx)
            + y * z * n / r4
                * (hx * ((2.0 * nu - 1.0) * (s / 6.0 + a / 3.0) - z2 / 2.0 - 1.5 - r2 / 2.0)
                    + r2 * nu / 4.0
                    + x2 / s
                    - y2 / 2.0
                    - 1.5 * x2)
            + 4.0 * y * z / (3.0 * r4) * hx * c,
    ];
    std::array::from_fn(|k| pressure[k] + mu * traction[k])
}

#[test]
fn agrees_with_hamiltons_explicit_equations_off_the_axis() {
    let mut worst = 0.0f64;
    for (i, mu) in [0.0, 0.25, 1.0].into_iter().enumerate() {
        for nu in [0.0, 0.3, 0.5] {
            for k in 0..150 {
                // A deterministic scatter over 0.3 <= r <= 3, 0.02 <= z <= 3.
                let f = f64::from(k + 150 * i as i32);
                let r = 0.3 + 2.7 * (0.618_034 * f).fract();
                let angle = std::f64::consts::TAU * (0.414_214 * f).fract();
                let z = 0.02 + 2.98 * (0.732_051 * f).fract();
                let (x, y) = (r * angle.cos(), r * angle.sin());
                let ours = components(&stress_over_p0(x, y, z, mu, nu));
                let theirs = hamilton_explicit(x, y, z, mu, nu);
                for c in 0..6 {
                    let difference = (ours[c] - theirs[c]).abs();
                    worst = worst.max(difference);
                    assert!(
                        difference < 1e-12,
                        "({x}, {y}, {z}) mu {mu} nu {nu} component {c}: {} vs {}",
                        ours[c],
                        theirs[c]
                    );
                }
            }
        }
    }
    assert!(worst > 0.0);
    eprintln!("closed form vs Hamilton's explicit equations: max |difference| = {worst:.1e}");
}
